/* The exact minimum of the gap of one tooth pair along a line of the pinion flank (formulation
 * (b), docs/tca.md section 5): over the profile in a transverse slice (within the feasible run of
 * profile nodes), along a pinion profile edge (the tip or root), and on a gear boundary crossing
 * the flank (Lagrange); Newton by GSL hybridsj with analytic Jacobians. */
#include "tca_internal.h"

#include <math.h>
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

/* Evaluate a point as a candidate: feasible (tolerance 1e-9 m), with the boundaries it lies on. */
static void make_cand(gd_tca *t, int half, const tca_pose *P, double u, double z, tca_cand *c)
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

/* feasibility (0, or 1 + the violated constraint) and gap of profile node i at axial position z */
static int node_at(gd_tca *t, int half, const tca_pose *P, int i, double z, double *g)
{
    tca_local L;
    tca_local_eval(t, half, P, t->rho[i] / t->h[half].f1.rb, z, 0, &L);
    int f = tca_feasible(t, half, &L, 1e-12);
    *g = f ? NAN : L.g;
    return f;
}

gd_status tca_slice_min_z(gd_tca *t, int half, const tca_pose *P, double z, const double *gv,
                          const unsigned char *fv, int i0, tca_cand *out, double *mp, double *mpp, int *iters,
                          gd_error *err)
{
    return tca_slice_min_hint(t, half, P, z, gv, fv, i0, NULL, NULL, -1, NAN, out, mp, mpp, iters, err);
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
static void slice_slopes(gd_tca *t, int half, const tca_pose *P, double z, const tca_cand *best, double *mp,
                         double *mpp)
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

/* As tca_slice_min_z; at an axial position z between grid slices (gv == NULL) the feasible run is
 * taken from grid slice jh of the pair's node arrays (gp, fp) and corrected by evaluating only the
 * nodes at its ends, and Newton starts from rho_hint (the slice minimum of a neighbouring z). */
gd_status tca_slice_min_hint(gd_tca *t, int half, const tca_pose *P, double z, const double *gv,
                             const unsigned char *fv, int i0, const double *gp, const unsigned char *fp, int jh,
                             double rho_hint, tca_cand *out, double *mp, double *mpp, int *iters, gd_error *err)
{
    int np = t->nprof;
    const double *rho = t->rho;
    const double rb1 = t->h[half].f1.rb;
    slice_run r = {0, 0, 0, 0, 0};
    if (!gv && gp && jh >= 0) {
        if (!run_from_hint(t, half, P, z, gp, fp, jh, rho_hint, &r)) {
            tca_cand none = {0};
            *out = none;
            return GD_OK;
        }
    } else if (!run_from_slice(t, half, P, z, gv, fv, i0, &r)) {
        tca_cand none = {0};
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
    tca_cand best = {0}, c;
    if (mp)
        *mp = NAN;
    if (mpp)
        *mpp = NAN;
    make_cand(t, half, P, rlo / rb1, z, &c);
    tca_keep_best(&best, &c);
    make_cand(t, half, P, rhi / rb1, z, &c);
    tca_keep_best(&best, &c);
    make_cand(t, half, P, rstart / rb1, z, &c);
    tca_keep_best(&best, &c);
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
            tca_keep_best(&best, &c);
        }
    }
    *out = best;
    if (best.ok && (mp || mpp))
        slice_slopes(t, half, P, z, &best, mp, mpp);
    return GD_OK;
}

/* Exact minimum in grid slice j from node i0 (the pair's node values gv, fv). */
gd_status tca_slice_min(gd_tca *t, int half, const tca_pose *P, int j, int i0, const double *gv,
                        const unsigned char *fv, tca_cand *out, int *iters, gd_error *err)
{
    size_t off = (size_t)j * t->nprof;
    return tca_slice_min_z(t, half, P, t->z[j], gv + off, fv + off, i0, out, NULL, NULL, iters, err);
}

/* Exact minimum along a pinion profile line rho = const (the tip or root edge), starting at z0. */
gd_status tca_along_min(gd_tca *t, int half, const tca_pose *P, double rho, double z0, tca_cand *out, int *iters,
                        gd_error *err)
{
    const gd_flank *f1 = &t->h[half].f1;
    const double rb1 = f1->rb;
    tca_cand best = {0}, c;
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
        tca_keep_best(&best, &c);
    }
    make_cand(t, half, P, rho / rb1, z0, &c);
    tca_keep_best(&best, &c);
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
            tca_keep_best(&best, &c);
        }
    }
    *out = best;
    return GD_OK;
}

/* Exact minimum on the gear boundary k (tip, root or end face) crossing the pinion flank. */
gd_status tca_lagrange_min(gd_tca *t, int half, const tca_pose *P, int k, double rho0, double z0, tca_cand *out,
                           int *iters, gd_error *err)
{
    tca_cand c = {0};
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
