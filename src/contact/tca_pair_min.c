/* The exact minimum of the gap of one tooth pair over the pinion flank, from its best grid node
 * (formulation (b), docs/tca.md section 5): the minimum over z of the slice minimum, by a
 * safeguarded Newton iteration on its slope in a bracket walked from the grid slices, and, for a
 * flat minimum (line contact), every edge of the pair. */
#include "tca_internal.h"

#include <math.h>
#include <string.h>

/* ---- one tooth pair --------------------------------------------------------------------------- */

static void add_tie(tca_pair_out *po, const tca_cand *c)
{
    if (c->ok && c->bits && po->ntie < 8) {
        po->tie_g[po->ntie] = c->g;
        po->tie_b[po->ntie] = c->bits;
        po->ntie++;
    }
}

/* A bracket of the minimum of the slice minimum m(z): from grid slice j0 (slope mp0, candidate c0)
 * walk slice by slice downhill until the slope changes sign or the face ends. (za, ma, ca): the
 * last slice walked with the starting sign; (zb, mb, cb): the first with the other sign, zb NaN
 * when the walk ended without one. */
typedef struct z_bracket {
    double za, ma;
    tca_cand ca;
    double zb, mb;
    tca_cand cb;
} z_bracket;

static gd_status bracket_downhill(gd_tca *t, int half, const tca_pose *P, const double *gv, const unsigned char *fv,
                                  int j0, double mp0, const tca_cand *c0, double flat, tca_pair_out *po, z_bracket *br,
                                  int *iters, gd_error *err)
{
    int np = t->nprof, nz = t->nface;
    int dir = mp0 > 0 ? -1 : 1;
    int j = j0;
    br->za = t->z[j0];
    br->ma = mp0;
    br->ca = *c0;
    br->zb = NAN;
    br->mb = NAN;
    br->cb = (tca_cand){0};
    while (1) {
        int jn = j + dir;
        if (jn < 0 || jn >= nz)
            break; /* the face end is the minimum of m: ca */
        tca_cand cn;
        double mpn;
        gd_status st = tca_slice_min_z(t, half, P, t->z[jn], gv + (size_t)jn * np, fv + (size_t)jn * np, -1, &cn, &mpn,
                                       NULL, iters, err);
        if (st != GD_OK)
            return st;
        if (!cn.ok)
            break;
        tca_keep_best(&po->best, &cn);
        if (dir * mpn >= 0 || fabs(mpn) <= flat) {
            br->zb = t->z[jn];
            br->mb = mpn;
            br->cb = cn;
            break;
        }
        j = jn;
        br->za = t->z[jn];
        br->ma = mpn;
        br->ca = cn;
    }
    return GD_OK;
}

/* Safeguarded Newton on m'(z) in the bracket [lo, hi] with m'(lo) < 0 < m'(hi); the last iterate's
 * candidate in *cz. */
static gd_status newton_on_slope(gd_tca *t, int half, const tca_pose *P, const double *gv, const unsigned char *fv,
                                 const z_bracket *br, double flat, tca_pair_out *po, tca_cand *cz_out, int *iters,
                                 gd_error *err)
{
    int nz = t->nface;
    const double rb1 = t->h[half].f1.rb;
    double lo = br->za, hi = br->zb, mlo = br->ma, mhi = br->mb;
    tca_cand clo = br->ca, chi = br->cb;
    if (lo > hi) {
        double tz = lo; lo = hi; hi = tz;
        double tm = mlo; mlo = mhi; mhi = tm;
        tca_cand tc = clo; clo = chi; chi = tc;
    }
    (void)mhi;
    double z = fabs(mlo) < fabs(br->mb) ? lo : hi;
    double mz = z == lo ? mlo : mhi, mzz = NAN, zprev = NAN, mprev = NAN;
    tca_cand cz = z == lo ? clo : chi;
    for (int it = 0; it < 60 && hi - lo > 1e-12; it++) {
        double zn;
        if (isfinite(mzz) && mzz > 0)
            zn = z - mz / mzz;
        else if (isfinite(mprev) && mz != mprev)
            zn = z - mz * (z - zprev) / (mz - mprev);
        else
            zn = 0.5 * (lo + hi);
        if (!(zn > lo && zn < hi))
            zn = 0.5 * (lo + hi);
        double step = fabs(zn - z);
        zprev = z;
        mprev = mz;
        tca_cand cn;
        double mpn, mppn;
        int jh = nz > 1 ? (int)lround((zn - t->z[0]) / (t->z[1] - t->z[0])) : 0;
        jh = jh < 0 ? 0 : jh >= nz ? nz - 1 : jh;
        gd_status st = tca_slice_min_hint(t, half, P, zn, NULL, NULL, -1, gv, fv, jh, cz.u * rb1, &cn, &mpn, &mppn,
                                          iters, err);
        if (st != GD_OK)
            return st;
        if (!cn.ok || !isfinite(mpn))
            break;
        z = zn;
        mz = mpn;
        mzz = mppn;
        cz = cn;
        tca_keep_best(&po->best, &cn);
        if (mz < 0)
            lo = z;
        else
            hi = z;
        if (step < 1e-12 || fabs(mz) <= flat)
            break;
    }
    *cz_out = cz;
    return GD_OK;
}

/* Every edge of a flat minimum: the face ends, the tip and root edges, the gear boundaries. */
static gd_status examine_edges(gd_tca *t, int half, const tca_pose *P, const double *gv, const unsigned char *fv,
                               tca_pair_out *po, int *iters, gd_error *err)
{
    int np = t->nprof, nz = t->nface;
    gd_status st;
    tca_cand c;
    for (int e = 0; e < 2; e++) {
        int j = e == 0 ? 0 : nz - 1;
        st = tca_slice_min(t, half, P, j, -1, gv, fv, &c, iters, err);
        if (st != GD_OK)
            return st;
        tca_keep_best(&po->best, &c);
        add_tie(po, &c);
    }
    for (int e = 0; e < 2; e++) {
        int i = e == 0 ? np - 1 : 0;
        int jb = -1;
        for (int j = 0; j < nz; j++)
            if (fv[(size_t)j * np + i] == 0 && (jb < 0 || gv[(size_t)j * np + i] < gv[(size_t)jb * np + i]))
                jb = j;
        if (jb < 0)
            continue;
        st = tca_along_min(t, half, P, t->rho[i], t->z[jb], &c, iters, err);
        if (st != GD_OK)
            return st;
        tca_keep_best(&po->best, &c);
        add_tie(po, &c);
    }
    for (int k = TCA_C_G_ROOT; k <= TCA_C_G_HI; k++) {
        int best_n = -1;
        for (int j = 0; j < nz; j++)
            for (int i = 0; i < np; i++) {
                size_t n = (size_t)j * np + i;
                if (fv[n] != 0)
                    continue;
                int adj = (i > 0 && fv[n - 1] == 1 + k) || (i < np - 1 && fv[n + 1] == 1 + k);
                if (adj && (best_n < 0 || gv[n] < gv[best_n]))
                    best_n = (int)n;
            }
        if (best_n < 0)
            continue;
        st = tca_lagrange_min(t, half, P, k, t->rho[best_n % np], t->z[best_n / np], &c, iters, err);
        if (st != GD_OK)
            return st;
        tca_keep_best(&po->best, &c);
        add_tie(po, &c);
    }
    return GD_OK;
}

/* The minimum along z of the slice minimum from grid slice j0 (slope mp0, candidate c0): the
 * bracket, then Newton in it; *line_like when m is flat at j0 (line contact). */
static gd_status refine_along_face(gd_tca *t, int half, const tca_pose *P, const double *gv, const unsigned char *fv,
                                   int j0, double mp0, const tca_cand *c0, double flat, tca_pair_out *po,
                                   int *line_like, int *iters, gd_error *err)
{
    *line_like = 0;
    if (fabs(mp0) <= flat) {
        *line_like = 1;
        return GD_OK;
    }
    z_bracket br;
    gd_status st = bracket_downhill(t, half, P, gv, fv, j0, mp0, c0, flat, po, &br, iters, err);
    if (st != GD_OK)
        return st;
    if (isfinite(br.zb)) {
        tca_cand cz;
        st = newton_on_slope(t, half, P, gv, fv, &br, flat, po, &cz, iters, err);
        if (st != GD_OK)
            return st;
        tca_keep_best(&po->best, &cz);
        add_tie(po, &cz);
    } else {
        tca_keep_best(&po->best, &br.ca);
        add_tie(po, &br.ca);
    }
    return GD_OK;
}

/* The exact minimum of one pair from its best grid node (i0, j0). The pair's minimum is the
 * minimum over z of the slice minimum m(z) = min over rho of g(rho, z), each slice exact over its
 * feasible rho interval (so that the pinion tip and root edges and the gear boundaries are part of
 * it) and the face ends the ends of the z interval: a one-dimensional problem, solved by a
 * safeguarded Newton iteration on m'(z) = 0 in a bracket found from the grid slices. When m is
 * flat (line contact) every edge of the pair is also examined so that edges touched together
 * with the flank are reported. */
gd_status tca_refine_from_grid(gd_tca *t, int half, const tca_pose *P, const double *gv, const unsigned char *fv,
                               int i0, int j0, int all_edges, const tca_cand *pre, double pre_mp, tca_pair_out *po,
                               int *iters, gd_error *err)
{
    int np = t->nprof, nz = t->nface;
    memset(po, 0, sizeof *po);
    tca_cand c0;
    double mp0, mpp0;
    gd_status st = GD_OK;
    if (pre) {
        c0 = *pre;
        mp0 = pre_mp;
    } else {
        st = tca_slice_min_z(t, half, P, t->z[j0], gv + (size_t)j0 * np, fv + (size_t)j0 * np, i0, &c0, &mp0, &mpp0,
                             iters, err);
        if (st != GD_OK)
            return st;
    }
    tca_keep_best(&po->best, &c0);
    add_tie(po, &c0);
    if (t->refine && c0.ok) {
        /* flatness scale: a slope below this over the face is rounding (line contact) */
        double face = t->z[nz - 1] - t->z[0];
        double flat = 1e-13 / (t->h[half].f2.rb * face);
        int line_like;
        st = refine_along_face(t, half, P, gv, fv, j0, mp0, &c0, flat, po, &line_like, iters, err);
        if (st != GD_OK)
            return st;
        if (line_like || all_edges) {
            st = examine_edges(t, half, P, gv, fv, po, iters, err);
            if (st != GD_OK)
                return st;
        }
    }
    for (int i = 0; i < po->ntie; i++)
        if (po->tie_g[i] <= po->best.g + t->tol_edge)
            po->tie_bits |= po->tie_b[i];
    if (po->best.ok)
        po->tie_bits |= po->best.bits;
    return GD_OK;
}
