/* Formulation (b), surface separation (docs/tca.md, section 5): at every node of a grid on the
 * pinion flank the gear rotation that closes the gap there (closed form for the involute gear
 * flank), the least over the nodes and tooth pairs, then the exact minimum of the flank, its edges
 * and corners by Newton (GSL hybridsj, analytic Jacobians), and the topography of the separation. */
#include "tca_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- the Newton systems ------------------------------------------------------------------- */

typedef struct sys_ctx {
    gd_tca *t;
    int half;
    const tca_pose *P;
    double rho, z;   /* the fixed coordinate of 1-D systems */
    int k;           /* constraint of the Lagrange system */
} sys_ctx;

static double rb1_of(const sys_ctx *c) { return c->t->h[c->half].f1.rb; }

/* one transverse slice: dg/drho = 0 at fixed z */
static int sys_slice(const double *x, void *p, double *f, double *J)
{
    sys_ctx *c = p;
    tca_local L;
    tca_local_eval(c->t, c->half, c->P, x[0] / rb1_of(c), c->z, 2, &L);
    if (!L.ok)
        return 1;
    f[0] = L.g_r;
    J[0] = L.g_rr;
    return 0;
}

/* along a pinion profile line (tip or root edge): dg/dz = 0 at fixed rho */
static int sys_along(const double *x, void *p, double *f, double *J)
{
    sys_ctx *c = p;
    tca_local L;
    tca_local_eval(c->t, c->half, c->P, c->rho / rb1_of(c), x[0], 2, &L);
    if (!L.ok)
        return 1;
    f[0] = L.g_z;
    J[0] = L.g_zz;
    return 0;
}

/* on the boundary h_k = 0: h = 0 and grad g parallel to grad h (Lagrange) */
static int sys_lagrange(const double *x, void *p, double *f, double *J)
{
    sys_ctx *c = p;
    tca_local L;
    tca_local_eval(c->t, c->half, c->P, x[0] / rb1_of(c), x[1], 2, &L);
    if (!L.ok)
        return 1;
    double h, hr, hz, hrr, hrz, hzz;
    tca_constraint(c->t, c->half, &L, c->k, &h, &hr, &hz, &hrr, &hrz, &hzz);
    f[0] = h;
    f[1] = L.g_r * hz - L.g_z * hr;
    J[0] = hr;
    J[1] = hz;
    J[2] = L.g_rr * hz + L.g_r * hrz - L.g_rz * hr - L.g_z * hrr;
    J[3] = L.g_rz * hz + L.g_r * hzz - L.g_zz * hr - L.g_z * hrz;
    return 0;
}

#define XTOL 1e-13
#define MAXIT 60

/* ---- candidates ----------------------------------------------------------------------------- */

typedef struct cand {
    double u, z, g;
    unsigned bits;
    int ok;
} cand;

/* Evaluate a point as a candidate: feasible (tolerance 1e-9 m), with the boundaries it lies on. */
static void make_cand(gd_tca *t, int half, const tca_pose *P, double u, double z, cand *c)
{
    tca_local L;
    tca_local_eval(t, half, P, u, z, 0, &L);
    c->ok = L.ok && tca_feasible(t, half, &L, 1e-9) == 0;
    c->u = u;
    c->z = z;
    c->g = L.g;
    c->bits = 0;
    if (!c->ok)
        return;
    for (int k = 0; k < TCA_NC; k++) {
        double h, a, b, d, e, f;
        tca_constraint(t, half, &L, k, &h, &a, &b, &d, &e, &f);
        if (fabs(h) <= 1e-9)
            c->bits |= tca_edge_bit(k);
    }
}

static void keep_best(cand *best, const cand *c)
{
    if (c->ok && (!best->ok || c->g < best->g))
        *best = *c;
}

/* Value of constraint k at (rho, z) (order 0 quantities only). */
static double h_at(gd_tca *t, int half, const tca_pose *P, int k, double rho, double z)
{
    tca_local L;
    const gd_flank *f1 = &t->h[half].f1;
    tca_local_eval(t, half, P, rho / f1->rb, z, 0, &L);
    double h, a, b, d, e, f;
    if (!L.ok)
        return k == TCA_C_G_ROOT ? -1.0 : NAN;
    tca_constraint(t, half, &L, k, &h, &a, &b, &d, &e, &f);
    return h;
}

/* Root of constraint k between a feasible point a (h >= 0) and an infeasible point b along a
 * segment s in [0, 1] of (rho, z): Illinois regula falsi to 1e-13 m in the arc. */
static double boundary_between(gd_tca *t, int half, const tca_pose *P, int k, const double a[2], const double b[2])
{
    double s0 = 0, s1 = 1;
    double f0 = h_at(t, half, P, k, a[0], a[1]);
    double f1 = h_at(t, half, P, k, b[0], b[1]);
    if (!isfinite(f1))
        f1 = -fabs(f0) - 1e-6;
    double len = hypot(b[0] - a[0], b[1] - a[1]);
    if (!(f0 >= 0) || !(f1 < 0))
        return 0;
    int side = 0;
    for (int it = 0; it < 100 && (s1 - s0) * len > 1e-13; it++) {
        double s = s1 - f1 * (s1 - s0) / (f1 - f0);
        if (!(s > s0 && s < s1))
            s = 0.5 * (s0 + s1);
        double fs = h_at(t, half, P, k, a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]));
        if (!isfinite(fs))
            fs = -1e-6;
        if (fs >= 0) {
            s0 = s;
            f0 = fs;
            if (side == -1)
                f1 *= 0.5;
            side = -1;
        } else {
            s1 = s;
            f1 = fs;
            if (side == 1)
                f0 *= 0.5;
            side = 1;
        }
    }
    return s0;
}

/* Exact minimum over rho in the transverse slice z, within the feasible run of profile nodes that
 * holds node i0 (or the least node when i0 < 0). gv/fv: the pair's node values in this slice when
 * z is a grid slice, else NULL (computed here). Also the slope m' = dm/dz of the slice minimum
 * m(z) there (envelope theorem; along the boundary when the minimum sits on one) and, when the
 * minimum is interior or on a pinion profile edge, its curvature m'' (else NaN). */
static gd_status slice_min_hint(gd_tca *t, int half, const tca_pose *P, double z, const double *gv,
                                const unsigned char *fv, int i0, const double *gp, const unsigned char *fp, int jh,
                                double rho_hint, cand *out, double *mp, double *mpp, int *iters, gd_error *err);

/* feasibility (0, or 1 + the violated constraint) and gap of profile node i at axial position z */
static int node_at(gd_tca *t, int half, const tca_pose *P, int i, double z, double *g)
{
    tca_local L;
    tca_local_eval(t, half, P, t->rho[i] / t->h[half].f1.rb, z, 0, &L);
    int f = tca_feasible(t, half, &L, 1e-12);
    *g = f ? NAN : L.g;
    return f;
}

static gd_status slice_min_z(gd_tca *t, int half, const tca_pose *P, double z, const double *gv,
                             const unsigned char *fv, int i0, cand *out, double *mp, double *mpp, int *iters,
                             gd_error *err)
{
    return slice_min_hint(t, half, P, z, gv, fv, i0, NULL, NULL, -1, NAN, out, mp, mpp, iters, err);
}

/* The feasible run of profile nodes [lo, hi] a slice minimum is sought in, its least node imin
 * and the violated constraints just outside its ends (1 + constraint, 0 at the flank's edge). */
typedef struct slice_run {
    int lo, hi, imin, flo, fhi;
} slice_run;

/* The run of grid slice jh nearest to the hint, its ends checked at z; 0 when there is none. */
static int run_from_hint(gd_tca *t, int half, const tca_pose *P, double z, const double *gp, const unsigned char *fp,
                         int jh, double rho_hint, slice_run *r)
{
    int np = t->nprof;
    const double *rho = t->rho;
    int lo, hi;
    const unsigned char *fj = fp + (size_t)jh * np;
    int start = -1;
    double dbest = INFINITY;
    for (int i = 0; i < np; i++)
        if (fj[i] == 0) {
            double d = isfinite(rho_hint) ? fabs(rho[i] - rho_hint) : gp[(size_t)jh * np + i];
            if (d < dbest) {
                dbest = d;
                start = i;
            }
        }
    if (start < 0)
        return 0;
    lo = hi = start;
    while (lo > 0 && fj[lo - 1] == 0)
        lo--;
    while (hi < np - 1 && fj[hi + 1] == 0)
        hi++;
    double gg;
    /* move the ends to where the nodes are feasible at z */
    while (lo <= hi && node_at(t, half, P, lo, z, &gg))
        lo++;
    while (hi >= lo && node_at(t, half, P, hi, z, &gg))
        hi--;
    if (lo > hi)
        return 0;
    while (lo > 0 && (r->flo = node_at(t, half, P, lo - 1, z, &gg)) == 0)
        lo--;
    while (hi < np - 1 && (r->fhi = node_at(t, half, P, hi + 1, z, &gg)) == 0)
        hi++;
    int imin = -1;
    if (isfinite(rho_hint)) {
        imin = lo;
        for (int i = lo; i <= hi; i++)
            if (fabs(rho[i] - rho_hint) < fabs(rho[imin] - rho_hint))
                imin = i;
    } else {
        imin = start < lo ? lo : start > hi ? hi : start;
    }
    r->lo = lo;
    r->hi = hi;
    r->imin = imin;
    return 1;
}

/* The run of the slice's node values (gv, fv; computed here when NULL) that holds node i0, or the
 * least node when i0 is not feasible; 0 when no node of the slice is feasible. */
static int run_from_slice(gd_tca *t, int half, const tca_pose *P, double z, const double *gv,
                          const unsigned char *fv, int i0, slice_run *r)
{
    int np = t->nprof;
    int lo, hi;
    if (!gv) {
        for (int i = 0; i < np; i++)
            t->sf[i] = (unsigned char)node_at(t, half, P, i, z, &t->sg[i]);
        gv = t->sg;
        fv = t->sf;
    }
    if (i0 < 0 || fv[i0] != 0) {
        i0 = -1;
        for (int i = 0; i < np; i++)
            if (fv[i] == 0 && (i0 < 0 || gv[i] < gv[i0]))
                i0 = i;
        if (i0 < 0)
            return 0;
    }
    lo = hi = i0;
    while (lo > 0 && fv[lo - 1] == 0)
        lo--;
    while (hi < np - 1 && fv[hi + 1] == 0)
        hi++;
    int imin = lo;
    for (int i = lo; i <= hi; i++)
        if (gv[i] < gv[imin])
            imin = i;
    if (lo > 0)
        r->flo = fv[lo - 1];
    if (hi < np - 1)
        r->fhi = fv[hi + 1];
    r->lo = lo;
    r->hi = hi;
    r->imin = imin;
    return 1;
}

/* The slope m' of the slice minimum (along the gear boundary when it sits on one) and its
 * curvature m'' when the minimum is interior or on a pinion profile edge. */
static void slice_slopes(gd_tca *t, int half, const tca_pose *P, double z, const cand *best, double *mp, double *mpp)
{
    tca_local L;
    tca_local_eval(t, half, P, best->u, z, 2, &L);
    unsigned gear = best->bits & (tca_edge_bit(TCA_C_G_ROOT) | tca_edge_bit(TCA_C_G_TIP) | tca_edge_bit(TCA_C_G_LO) |
                                  tca_edge_bit(TCA_C_G_HI));
    unsigned prof = best->bits & (tca_edge_bit(TCA_C_P_ROOT) | tca_edge_bit(TCA_C_P_TIP));
    double d1 = L.g_z, d2 = NAN;
    if (gear) {
        int k = 0;
        while (!(gear & tca_edge_bit(k)))
            k++;
        double h, hr, hz, hrr, hrz, hzz;
        tca_constraint(t, half, &L, k, &h, &hr, &hz, &hrr, &hrz, &hzz);
        if (fabs(hr) > 0)
            d1 = L.g_z - L.g_r * hz / hr;
    } else if (prof) {
        d2 = L.g_zz;
    } else if (L.g_rr > 0) {
        d2 = L.g_zz - L.g_rz * L.g_rz / L.g_rr;
    }
    if (mp)
        *mp = d1;
    if (mpp)
        *mpp = d2;
}

/* As slice_min_z; at an axial position z between grid slices (gv == NULL) the feasible run is
 * taken from grid slice jh of the pair's node arrays (gp, fp) and corrected by evaluating only the
 * nodes at its ends, and Newton starts from rho_hint (the slice minimum of a neighbouring z). */
static gd_status slice_min_hint(gd_tca *t, int half, const tca_pose *P, double z, const double *gv,
                                const unsigned char *fv, int i0, const double *gp, const unsigned char *fp, int jh,
                                double rho_hint, cand *out, double *mp, double *mpp, int *iters, gd_error *err)
{
    int np = t->nprof;
    const double *rho = t->rho;
    const double rb1 = t->h[half].f1.rb;
    slice_run r = {0, 0, 0, 0, 0};
    if (!gv && gp && jh >= 0) {
        if (!run_from_hint(t, half, P, z, gp, fp, jh, rho_hint, &r)) {
            cand none = {0};
            *out = none;
            return GD_OK;
        }
    } else if (!run_from_slice(t, half, P, z, gv, fv, i0, &r)) {
        cand none = {0};
        *out = none;
        if (mp)
            *mp = NAN;
        if (mpp)
            *mpp = NAN;
        return GD_OK;
    }
    const int lo = r.lo, hi = r.hi;
    double rlo = rho[lo], rhi = rho[hi];
    if (lo > 0) {
        double a[2] = {rho[lo], z}, b[2] = {rho[lo - 1], z};
        rlo = rho[lo] + boundary_between(t, half, P, r.flo - 1, a, b) * (rho[lo - 1] - rho[lo]);
    }
    if (hi < np - 1) {
        double a[2] = {rho[hi], z}, b[2] = {rho[hi + 1], z};
        rhi = rho[hi] + boundary_between(t, half, P, r.fhi - 1, a, b) * (rho[hi + 1] - rho[hi]);
    }
    double rstart = isfinite(rho_hint) ? fmin(fmax(rho_hint, rlo), rhi) : rho[r.imin];
    cand best = {0}, c;
    if (mp)
        *mp = NAN;
    if (mpp)
        *mpp = NAN;
    make_cand(t, half, P, rlo / rb1, z, &c);
    keep_best(&best, &c);
    make_cand(t, half, P, rhi / rb1, z, &c);
    keep_best(&best, &c);
    make_cand(t, half, P, rstart / rb1, z, &c);
    keep_best(&best, &c);
    if (t->refine) {
        sys_ctx ctx = {t, half, P, 0, z, 0};
        double x[1] = {rstart};
        int conv, it;
        gd_status st = tca_newton(t, 1, sys_slice, &ctx, x, XTOL, MAXIT, &conv, &it, err);
        if (st != GD_OK)
            return st;
        *iters += it;
        if (conv && x[0] >= rlo - 1e-12 && x[0] <= rhi + 1e-12) {
            make_cand(t, half, P, x[0] / rb1, z, &c);
            keep_best(&best, &c);
        }
    }
    *out = best;
    if (best.ok && (mp || mpp))
        slice_slopes(t, half, P, z, &best, mp, mpp);
    return GD_OK;
}

/* Exact minimum in grid slice j from node i0 (the pair's node values gv, fv). */
static gd_status slice_min(gd_tca *t, int half, const tca_pose *P, int j, int i0, const double *gv,
                           const unsigned char *fv, cand *out, int *iters, gd_error *err)
{
    size_t off = (size_t)j * t->nprof;
    return slice_min_z(t, half, P, t->z[j], gv + off, fv + off, i0, out, NULL, NULL, iters, err);
}

/* Exact minimum along a pinion profile line rho = const (the tip or root edge), starting at z0. */
static gd_status along_min(gd_tca *t, int half, const tca_pose *P, double rho, double z0, cand *out, int *iters,
                           gd_error *err)
{
    const gd_flank *f1 = &t->h[half].f1;
    const double rb1 = f1->rb;
    cand best = {0}, c;
    /* the feasible interval of z along the line around z0, from the face ends and the gear bounds */
    tca_local L;
    tca_local_eval(t, half, P, rho / rb1, z0, 0, &L);
    int bad0 = tca_feasible(t, half, &L, 1e-9);
    if (bad0) {
        *out = best;
        return GD_OK;
    }
    double ends[2];
    double zend[2] = {f1->z_min, f1->z_max};
    for (int s = 0; s < 2; s++) {
        /* walk toward the face end; stop at the first gear bound */
        int n = 16;
        double zprev = z0, zz = z0;
        ends[s] = zend[s];
        for (int i = 1; i <= n; i++) {
            zz = z0 + (zend[s] - z0) * i / n;
            tca_local_eval(t, half, P, rho / rb1, zz, 0, &L);
            int bad = tca_feasible(t, half, &L, 1e-9);
            if (bad) {
                double a[2] = {rho, zprev}, b[2] = {rho, zz};
                ends[s] = zprev + boundary_between(t, half, P, bad - 1, a, b) * (zz - zprev);
                break;
            }
            zprev = zz;
        }
        make_cand(t, half, P, rho / rb1, ends[s], &c);
        keep_best(&best, &c);
    }
    make_cand(t, half, P, rho / rb1, z0, &c);
    keep_best(&best, &c);
    if (t->refine) {
        sys_ctx ctx = {t, half, P, rho, 0, 0};
        double x[1] = {z0};
        int conv, it;
        gd_status st = tca_newton(t, 1, sys_along, &ctx, x, XTOL, MAXIT, &conv, &it, err);
        if (st != GD_OK)
            return st;
        *iters += it;
        if (conv && x[0] >= ends[0] - 1e-12 && x[0] <= ends[1] + 1e-12) {
            make_cand(t, half, P, rho / rb1, x[0], &c);
            keep_best(&best, &c);
        }
    }
    *out = best;
    return GD_OK;
}

/* Exact minimum on the gear boundary k (tip, root or end face) crossing the pinion flank. */
static gd_status lagrange_min(gd_tca *t, int half, const tca_pose *P, int k, double rho0, double z0, cand *out,
                              int *iters, gd_error *err)
{
    cand c = {0};
    *out = c;
    if (!t->refine)
        return GD_OK;
    sys_ctx ctx = {t, half, P, 0, 0, k};
    double x[2] = {rho0, z0};
    int conv, it;
    gd_status st = tca_newton(t, 2, sys_lagrange, &ctx, x, XTOL, MAXIT, &conv, &it, err);
    if (st != GD_OK)
        return st;
    *iters += it;
    if (conv)
        make_cand(t, half, P, x[0] / t->h[half].f1.rb, x[1], out);
    return GD_OK;
}

/* ---- one tooth pair --------------------------------------------------------------------------- */

typedef struct pair_out {
    cand best;
    unsigned tie_bits;       /* boundary bits of candidates within tol_edge of the pair minimum */
    double tie_g[8];
    unsigned tie_b[8];
    int ntie;
} pair_out;

static void add_tie(pair_out *po, const cand *c)
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
    cand ca;
    double zb, mb;
    cand cb;
} z_bracket;

static gd_status bracket_downhill(gd_tca *t, int half, const tca_pose *P, const double *gv, const unsigned char *fv,
                                  int j0, double mp0, const cand *c0, double flat, pair_out *po, z_bracket *br,
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
    br->cb = (cand){0};
    while (1) {
        int jn = j + dir;
        if (jn < 0 || jn >= nz)
            break; /* the face end is the minimum of m: ca */
        cand cn;
        double mpn;
        gd_status st = slice_min_z(t, half, P, t->z[jn], gv + (size_t)jn * np, fv + (size_t)jn * np, -1, &cn, &mpn,
                                   NULL, iters, err);
        if (st != GD_OK)
            return st;
        if (!cn.ok)
            break;
        keep_best(&po->best, &cn);
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
                                 const z_bracket *br, double flat, pair_out *po, cand *cz_out, int *iters,
                                 gd_error *err)
{
    int nz = t->nface;
    const double rb1 = t->h[half].f1.rb;
    double lo = br->za, hi = br->zb, mlo = br->ma, mhi = br->mb;
    cand clo = br->ca, chi = br->cb;
    if (lo > hi) {
        double tz = lo; lo = hi; hi = tz;
        double tm = mlo; mlo = mhi; mhi = tm;
        cand tc = clo; clo = chi; chi = tc;
    }
    (void)mhi;
    double z = fabs(mlo) < fabs(br->mb) ? lo : hi;
    double mz = z == lo ? mlo : mhi, mzz = NAN, zprev = NAN, mprev = NAN;
    cand cz = z == lo ? clo : chi;
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
        cand cn;
        double mpn, mppn;
        int jh = nz > 1 ? (int)lround((zn - t->z[0]) / (t->z[1] - t->z[0])) : 0;
        jh = jh < 0 ? 0 : jh >= nz ? nz - 1 : jh;
        gd_status st = slice_min_hint(t, half, P, zn, NULL, NULL, -1, gv, fv, jh, cz.u * rb1, &cn, &mpn, &mppn, iters,
                                      err);
        if (st != GD_OK)
            return st;
        if (!cn.ok || !isfinite(mpn))
            break;
        z = zn;
        mz = mpn;
        mzz = mppn;
        cz = cn;
        keep_best(&po->best, &cn);
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
                               pair_out *po, int *iters, gd_error *err)
{
    int np = t->nprof, nz = t->nface;
    gd_status st;
    cand c;
    for (int e = 0; e < 2; e++) {
        int j = e == 0 ? 0 : nz - 1;
        st = slice_min(t, half, P, j, -1, gv, fv, &c, iters, err);
        if (st != GD_OK)
            return st;
        keep_best(&po->best, &c);
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
        st = along_min(t, half, P, t->rho[i], t->z[jb], &c, iters, err);
        if (st != GD_OK)
            return st;
        keep_best(&po->best, &c);
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
        st = lagrange_min(t, half, P, k, t->rho[best_n % np], t->z[best_n / np], &c, iters, err);
        if (st != GD_OK)
            return st;
        keep_best(&po->best, &c);
        add_tie(po, &c);
    }
    return GD_OK;
}

/* The minimum along z of the slice minimum from grid slice j0 (slope mp0, candidate c0): the
 * bracket, then Newton in it; *line_like when m is flat at j0 (line contact). */
static gd_status refine_along_face(gd_tca *t, int half, const tca_pose *P, const double *gv, const unsigned char *fv,
                                   int j0, double mp0, const cand *c0, double flat, pair_out *po, int *line_like,
                                   int *iters, gd_error *err)
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
        cand cz;
        st = newton_on_slope(t, half, P, gv, fv, &br, flat, po, &cz, iters, err);
        if (st != GD_OK)
            return st;
        keep_best(&po->best, &cz);
        add_tie(po, &cz);
    } else {
        keep_best(&po->best, &br.ca);
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
static gd_status refine_from_grid(gd_tca *t, int half, const tca_pose *P, const double *gv, const unsigned char *fv,
                                  int i0, int j0, int all_edges, const cand *pre, double pre_mp, pair_out *po,
                                  int *iters, gd_error *err)
{
    int np = t->nprof, nz = t->nface;
    memset(po, 0, sizeof *po);
    cand c0;
    double mp0, mpp0;
    gd_status st = GD_OK;
    if (pre) {
        c0 = *pre;
        mp0 = pre_mp;
    } else {
        st = slice_min_z(t, half, P, t->z[j0], gv + (size_t)j0 * np, fv + (size_t)j0 * np, i0, &c0, &mp0, &mpp0,
                         iters, err);
        if (st != GD_OK)
            return st;
    }
    keep_best(&po->best, &c0);
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

/* ---- grid --------------------------------------------------------------------------------- */

/* Gap at every node for one pair; returns the index of the least feasible node or -1. */
static int grid_pair(gd_tca *t, int half, const tca_pose *P, double *gv, unsigned char *fv)
{
    const tca_half *H = &t->h[half];
    const gd_flank *f2 = &H->f2;
    const double rb = f2->rb, rb2sq = rb * rb;
    const double rlo = rb * sqrt(1 + f2->u_min * f2->u_min), rhi = rb * sqrt(1 + f2->u_max * f2->u_max);
    const double rlo2 = rlo * rlo, rhi2 = rhi * rhi;
    const double zlo = f2->z_min - 1e-12, zhi = f2->z_max + 1e-12;
    const double *A = P->A, *c = P->c;
    const double eta = f2->eta_b, k2 = f2->k;
    int nn = t->nprof * t->nface, best = -1;
    double gbest = INFINITY;
    for (int n = 0; n < nn; n++) {
        const double *x = H->x1 + 3 * n;
        double Q0 = A[0] * x[0] + A[1] * x[1] + A[2] * x[2] + c[0];
        double Q1 = A[3] * x[0] + A[4] * x[1] + A[5] * x[2] + c[1];
        double Q2 = A[6] * x[0] + A[7] * x[1] + A[8] * x[2] + c[2];
        double r2 = Q0 * Q0 + Q1 * Q1;
        unsigned char bad = 0;
        if (r2 < rlo2)
            bad = 1 + TCA_C_G_ROOT;
        else if (r2 > rhi2)
            bad = 1 + TCA_C_G_TIP;
        else if (Q2 < zlo)
            bad = 1 + TCA_C_G_LO;
        else if (Q2 > zhi)
            bad = 1 + TCA_C_G_HI;
        fv[n] = bad;
        if (bad) {
            gv[n] = NAN;
            continue;
        }
        double s = sqrt(r2 - rb2sq);
        double g = atan2(Q1 * rb - Q0 * s, Q0 * rb + Q1 * s) + s / rb + eta - k2 * Q2;
        gv[n] = g;
        if (g < gbest) {
            gbest = g;
            best = n;
        }
    }
    return best;
}

void tca_fill_contact(const gd_tca *t, int half, double phi1, int pair, double u1, double z1, double te,
                      gd_tca_contact *out)
{
    const tca_half *H = &t->h[half];
    gd_flank_eval e;
    gd_flank_eval_at(&H->f1, u1, z1, 1, &e);
    double n[3];
    gd_flank_normal(&e, n);
    out->phi1 = phi1;
    out->te = te;
    out->pair = pair;
    out->u1 = u1;
    out->z1 = z1;
    tca_fixed_point(t, half, phi1, pair, e.r, out->pos);
    tca_fixed_vector(t, phi1, pair, n, out->normal);
    out->alpha_op = atan2(out->normal[0], out->normal[1]);
    tca_pose P;
    tca_pose_at(t, half, phi1, tca_phi2_nominal(t, phi1), pair, &P);
    tca_local L;
    tca_local_eval(t, half, &P, u1, z1, 0, &L);
    double rb2 = H->f2.rb;
    out->u2 = L.R > rb2 ? sqrt(L.R * L.R - rb2 * rb2) / rb2 : 0;
    out->z2 = L.Z;
}

/* Per-position scratch of the pairs. */
typedef struct pair_scan {
    int pair, best;
    double gmin;
} pair_scan;

#define MAX_PAIRS 64

/* The state of one position through its phases: the grid of every pair, the estimates, the
 * refined minimum of each pair and the least of them. */
typedef struct scan_state {
    int half, lo, hi, nn;
    double phi1, phi2;
    pair_scan ps[MAX_PAIRS];
    int np_;
    double gridmin;
    double hz;               /* slice spacing */
    double gstar;
    cand best;
    int best_pair, iters;
    double pair_g[MAX_PAIRS], lb[MAX_PAIRS], mp0[MAX_PAIRS];
    unsigned pair_bits[MAX_PAIRS];
    cand c0s[MAX_PAIRS];
    int order[MAX_PAIRS], nord;
} scan_state;

/* Gap at every node of every candidate pair; the pairs that meet, with their least node. */
static gd_status scan_grid(gd_tca *t, scan_state *S, gd_error *err)
{
    S->np_ = 0;
    S->gridmin = INFINITY;
    for (int m = S->lo; m <= S->hi; m++) {
        tca_pose P;
        tca_pose_at(t, S->half, S->phi1, S->phi2, m, &P);
        double *gv = t->gbuf + (size_t)(m - S->lo) * S->nn;
        unsigned char *fv = t->fbuf + (size_t)(m - S->lo) * S->nn;
        int b = grid_pair(t, S->half, &P, gv, fv);
        if (b < 0)
            continue;
        S->ps[S->np_].pair = m;
        S->ps[S->np_].best = b;
        S->ps[S->np_].gmin = gv[b];
        if (gv[b] < S->gridmin)
            S->gridmin = gv[b];
        S->np_++;
    }
    if (S->np_ == 0)
        return gd_error_set(err, GD_ERR_INTERNAL, "TCA: no tooth pair meets at phi1 = %.6g rad (half %d)", S->phi1,
                            S->half);
    return GD_OK;
}

/* The exact minimum in the best node's slice of each pair within the window; the pairs are then
 * refined in the order of that estimate (each one fully: the slice of the grid's least node need
 * not be the slice nearest the pair's minimum, so no pair is skipped on its estimate). */
static gd_status estimate_pairs(gd_tca *t, scan_state *S, double window, gd_error *err)
{
    S->nord = 0;
    for (int q = 0; q < S->np_; q++) {
        S->pair_g[q] = INFINITY;
        S->pair_bits[q] = 0;
        S->lb[q] = INFINITY;
        if (S->ps[q].gmin > S->gridmin + window)
            continue;
        if (!t->refine) {
            S->lb[q] = S->ps[q].gmin;
            S->order[S->nord++] = q;
            continue;
        }
        int m = S->ps[q].pair, j0 = S->ps[q].best / t->nprof;
        tca_pose P;
        tca_pose_at(t, S->half, S->phi1, S->phi2, m, &P);
        const double *gv = t->gbuf + (size_t)(m - S->lo) * S->nn;
        const unsigned char *fv = t->fbuf + (size_t)(m - S->lo) * S->nn;
        double mpp;
        gd_status st = slice_min_z(t, S->half, &P, t->z[j0], gv + (size_t)j0 * t->nprof, fv + (size_t)j0 * t->nprof,
                                   S->ps[q].best % t->nprof, &S->c0s[q], &S->mp0[q], &mpp, &S->iters, err);
        if (st != GD_OK)
            return st;
        if (!S->c0s[q].ok)
            continue;
        S->lb[q] = S->c0s[q].g - (isfinite(S->mp0[q]) ? fabs(S->mp0[q]) * S->hz : 0);
        S->order[S->nord++] = q;
    }
    for (int a = 1; a < S->nord; a++)
        for (int b = a; b > 0 && S->lb[S->order[b]] < S->lb[S->order[b - 1]]; b--) {
            int tmp = S->order[b];
            S->order[b] = S->order[b - 1];
            S->order[b - 1] = tmp;
        }
    return GD_OK;
}

/* Refine the estimated pairs in order; the least of their minima. */
static gd_status refine_pairs(gd_tca *t, scan_state *S, gd_error *err)
{
    for (int oq = 0; oq < S->nord; oq++) {
        int q = S->order[oq];
        int m = S->ps[q].pair;
        tca_pose P;
        tca_pose_at(t, S->half, S->phi1, S->phi2, m, &P);
        const double *gv = t->gbuf + (size_t)(m - S->lo) * S->nn;
        const unsigned char *fv = t->fbuf + (size_t)(m - S->lo) * S->nn;
        pair_out po;
        gd_status st = refine_from_grid(t, S->half, &P, gv, fv, S->ps[q].best % t->nprof, S->ps[q].best / t->nprof,
                                        0, t->refine ? &S->c0s[q] : NULL, t->refine ? S->mp0[q] : 0, &po, &S->iters,
                                        err);
        if (st != GD_OK)
            return st;
        if (!po.best.ok)
            continue;
        S->pair_g[q] = po.best.g;
        S->pair_bits[q] = po.tie_bits;
        if (po.best.g < S->gstar) {
            S->gstar = po.best.g;
            S->best = po.best;
            S->best_pair = m;
        }
    }
    if (!S->best.ok) {
        /* no refinement succeeded: the grid minimum */
        for (int q = 0; q < S->np_; q++)
            if (S->ps[q].gmin <= S->gridmin) {
                S->best_pair = S->ps[q].pair;
                int n = S->ps[q].best;
                S->best.u = t->rho[n % t->nprof] / t->h[S->half].f1.rb;
                S->best.z = t->z[n / t->nprof];
                S->best.g = S->ps[q].gmin;
                S->best.ok = 1;
                S->gstar = S->best.g;
            }
    }
    return GD_OK;
}

/* Pairs in contact and edge contact (ties within the tolerances); without refinement the grid
 * definition: a least node on the boundary of the flank or of the feasible set. */
static unsigned contact_edges(const gd_tca *t, const scan_state *S, int *in_contact)
{
    unsigned edge = 0;
    *in_contact = 0;
    for (int q = 0; q < S->np_; q++) {
        if (S->pair_g[q] <= S->gstar + t->tol_contact) {
            (*in_contact)++;
            if (S->pair_g[q] <= S->gstar + t->tol_edge)
                edge |= S->pair_bits[q];
        }
    }
    if (!t->refine) {
        edge = 0;
        for (int q = 0; q < S->np_; q++) {
            if (S->ps[q].gmin > S->gstar + t->tol_edge)
                continue;
            int n = S->ps[q].best, i = n % t->nprof, j = n / t->nprof;
            const unsigned char *fv = t->fbuf + (size_t)(S->ps[q].pair - S->lo) * S->nn;
            if (i == 0) edge |= tca_edge_bit(TCA_C_P_ROOT);
            if (i == t->nprof - 1) edge |= tca_edge_bit(TCA_C_P_TIP);
            if (j == 0) edge |= tca_edge_bit(TCA_C_P_LO);
            if (j == t->nface - 1) edge |= tca_edge_bit(TCA_C_P_HI);
            if (i > 0 && fv[n - 1]) edge |= tca_edge_bit(fv[n - 1] - 1);
            if (i < t->nprof - 1 && fv[n + 1]) edge |= tca_edge_bit(fv[n + 1] - 1);
        }
    }
    return edge;
}

/* The topography: least separation and ease-off of every node over the positions. */
static void accumulate_topography(gd_tca *t, const scan_state *S)
{
    tca_half *H = &t->h[S->half];
    double s = H->f2.rb * H->f2.cos_bb;
    for (int q = 0; q < S->np_; q++) {
        int m = S->ps[q].pair;
        const double *gv = t->gbuf + (size_t)(m - S->lo) * S->nn;
        const unsigned char *fv = t->fbuf + (size_t)(m - S->lo) * S->nn;
        for (int n = 0; n < S->nn; n++) {
            if (fv[n])
                continue;
            double sep = (gv[n] - S->gstar) * s, ease = gv[n] * s;
            if (!(H->sep[n] <= sep))
                H->sep[n] = sep;
            if (!(H->ease[n] <= ease))
                H->ease[n] = ease;
        }
    }
}

static gd_status scan_and_refine(gd_tca *t, int half, double phi1, int accumulate, gd_tca_contact *out,
                                 double *gstar_out, gd_error *err)
{
    tca_half *H = &t->h[half];
    scan_state S;
    S.half = half;
    S.phi1 = phi1;
    S.nn = t->nprof * t->nface;
    S.phi2 = tca_phi2_nominal(t, phi1);
    tca_pair_range(t, half, phi1, &S.lo, &S.hi);
    if (S.hi - S.lo + 1 > t->maxpairs)
        S.hi = S.lo + t->maxpairs - 1;
    gd_status st = scan_grid(t, &S, err);
    if (st != GD_OK)
        return st;
    /* refine the pairs whose grid minimum may hide the least gap: within the grid resolution of
     * the least one (the gap a node half a cell away from a line contact can show) */
    const gd_flank *f1 = &H->f1;
    double hr = t->nprof > 1 ? (t->rho[1] - t->rho[0]) : 0;
    double hz = t->nface > 1 ? (t->z[1] - t->z[0]) : 0;
    double kap = 1.0 / (f1->rb * f1->u_min) + 1.0 / (H->f2.rb * H->f2.u_min);
    double scale = 1.0 / (H->f2.rb * H->f2.cos_bb);
    double window = scale * (0.5 * kap * (0.36 * hr * hr + 0.36 * hz * hz * f1->sin_bb * f1->sin_bb) + 2e-6);
    S.hz = hz;
    S.gstar = INFINITY;
    S.best = (cand){0};
    S.best_pair = 0;
    S.iters = 0;
    st = estimate_pairs(t, &S, window, err);
    if (st != GD_OK)
        return st;
    st = refine_pairs(t, &S, err);
    if (st != GD_OK)
        return st;
    int in_contact;
    unsigned edge = contact_edges(t, &S, &in_contact);
    if (accumulate)
        accumulate_topography(t, &S);
    if (out) {
        tca_fill_contact(t, half, phi1, S.best_pair, S.best.u, S.best.z, -S.gstar, out);
        out->edge = edge;
        out->pairs_in_contact = in_contact;
        out->iterations = S.iters;
        out->converged = 1;
    }
    if (gstar_out)
        *gstar_out = S.gstar;
    return GD_OK;
}

gd_status tca_separation(gd_tca *t, int half, double phi1, gd_tca_contact *out, gd_error *err)
{
    return scan_and_refine(t, half, phi1, 1, out, NULL, err);
}

/* Contact lines: per pair and slice, the exact slice minimum. */
gd_status tca_lines(gd_tca *t, int half, double phi1, double max_gap, gd_error *err)
{
    double gstar;
    gd_status st = scan_and_refine(t, half, phi1, 0, NULL, &gstar, err);
    if (st != GD_OK)
        return st;
    /* the grid buffers now hold the pairs of this position (scan_and_refine filled them) */
    const tca_half *H = &t->h[half];
    int nn = t->nprof * t->nface, np = t->nprof;
    double phi2 = tca_phi2_nominal(t, phi1);
    double phi2_actual = phi2 - gstar;
    double s = H->f2.rb * H->f2.cos_bb;
    int lo, hi;
    tca_pair_range(t, half, phi1, &lo, &hi);
    if (hi - lo + 1 > t->maxpairs)
        hi = lo + t->maxpairs - 1;
    t->nlines = 0;
    int iters = 0;
    for (int m = lo; m <= hi; m++) {
        tca_pose P;
        tca_pose_at(t, half, phi1, phi2, m, &P);
        const double *gv = t->gbuf + (size_t)(m - lo) * nn;
        const unsigned char *fv = t->fbuf + (size_t)(m - lo) * nn;
        for (int j = 0; j < t->nface; j++) {
            int ib = -1;
            for (int i = 0; i < np; i++)
                if (fv[(size_t)j * np + i] == 0 && (ib < 0 || gv[(size_t)j * np + i] < gv[(size_t)j * np + ib]))
                    ib = i;
            if (ib < 0)
                continue;
            if ((gv[(size_t)j * np + ib] - gstar) * s > max_gap + 50e-6)
                continue;
            cand c;
            st = slice_min(t, half, &P, j, ib, gv, fv, &c, &iters, err);
            if (st != GD_OK)
                return st;
            if (!c.ok || (c.g - gstar) * s > max_gap)
                continue;
            if (t->nlines == t->cap_lines) {
                int cap = t->cap_lines ? 2 * t->cap_lines : 256;
                gd_tca_line_point *nl = realloc(t->lines, (size_t)cap * sizeof *nl);
                if (!nl)
                    return gd_error_set(err, GD_ERR_NOMEM, "TCA: out of memory for the contact lines");
                t->lines = nl;
                t->cap_lines = cap;
            }
            gd_tca_line_point *lp = &t->lines[t->nlines++];
            memset(lp, 0, sizeof *lp);
            lp->pair = m;
            lp->slice = j;
            lp->u1 = c.u;
            lp->z1 = c.z;
            lp->gap = (c.g - gstar) * s;
            lp->gap_nominal = c.g * s;
            lp->edge = c.bits;
            gd_flank_eval e;
            gd_flank_eval_at(&H->f1, c.u, c.z, 2, &e);
            double n[3], k[2], dir[2][3];
            gd_flank_normal(&e, n);
            gd_flank_curvature(&e, k, dir);
            tca_fixed_point(t, half, phi1, m, e.r, lp->pos);
            tca_fixed_vector(t, phi1, m, n, lp->normal);
            for (int a = 0; a < 2; a++) {
                lp->k1[a] = k[a];
                tca_fixed_vector(t, phi1, m, dir[a], lp->dir1[a]);
            }
            tca_local L;
            tca_local_eval(t, half, &P, c.u, c.z, 0, &L);
            double rb2 = H->f2.rb;
            lp->u2 = sqrt(fmax(L.R * L.R - rb2 * rb2, 0)) / rb2;
            lp->z2 = L.Z;
            gd_flank_eval e2;
            gd_flank_eval_at(&H->f2, lp->u2, lp->z2, 2, &e2);
            gd_flank_curvature(&e2, k, dir);
            for (int a = 0; a < 2; a++) {
                lp->k2[a] = k[a];
                tca_gear_to_fixed(t, half, phi2_actual, m, dir[a], 0, lp->dir2[a]);
            }
        }
    }
    return GD_OK;
}
