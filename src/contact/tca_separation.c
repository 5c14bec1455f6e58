/* Formulation (b), surface separation, at one pinion position (docs/tca.md, section 5): at every
 * node of a grid on the pinion flank the gear rotation that closes the gap there (closed form for
 * the involute gear flank), the least over the nodes and tooth pairs, the exact minimum of each
 * pair within reach (tca_pair_min.c), the pairs in contact and the edges touched, and the
 * topography of the separation. */
#include "tca_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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
    tca_cand best;
    int best_pair, iters;
    double pair_g[MAX_PAIRS], lb[MAX_PAIRS], mp0[MAX_PAIRS];
    unsigned pair_bits[MAX_PAIRS];
    tca_cand c0s[MAX_PAIRS];
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
        gd_status st = tca_slice_min_z(t, S->half, &P, t->z[j0], gv + (size_t)j0 * t->nprof, fv + (size_t)j0 * t->nprof,
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
        tca_pair_out po;
        gd_status st = tca_refine_from_grid(t, S->half, &P, gv, fv, S->ps[q].best % t->nprof, S->ps[q].best / t->nprof,
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

gd_status tca_scan(gd_tca *t, int half, double phi1, int accumulate, gd_tca_contact *out,
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
    S.best = (tca_cand){0};
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
    return tca_scan(t, half, phi1, 1, out, NULL, err);
}
