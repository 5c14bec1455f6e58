/* Continuation of systems whose Floquet multipliers are known exactly (gd_model_custom, period
 * T = 2 pi): the monodromy of y' = A(p) y + f(t) is exp(A T), so the multipliers are exp(lambda T)
 * for the eigenvalues lambda of A(p), whatever the forcing f (which only places the orbit).
 *
 * 1. Two complex pairs crossing the unit circle in one step: A = diag(B(p - 0.30, 0.7),
 *    B(p - 0.31, 1.1)) with B(s, w) = [[s, -w], [w, s]], so a pair crosses at p = 0.30 and another at
 *    p = 0.31; continued from 0 to 1 with steps of 0.05 in p, so that one step holds both. Both
 *    Neimark-Sacker points are located, each to 1e-7 of its place, with its multiplier on the unit
 *    circle (to 1e-6) at the angle w T (mod 2 pi) to 1e-6; none elsewhere. (A product over the
 *    multipliers, the bialternate product, changes sign twice in that step and finds neither.)
 * 2. A neutral saddle: A = diag(1 + p/2, -1 + p/2), real multipliers exp((+-1 + p/2) T) whose
 *    product exp(p T) passes 1 at p = 0 with neither on the unit circle: no Neimark-Sacker point from
 *    -0.5 to 0.5, and no note.
 * 3. A branch point: x' = p x - x^3 (one state), the orbit x = 0 from p = -0.5 to 0.5 meets the branch
 *    x^2 = p at p = 0, where its multiplier exp(p T) passes 1 while the branch stays straight (the
 *    tangent's parameter part keeps its sign: no fold). The branch-point test locates it at 0 to
 *    1e-7, reported as a branch point, and the branch goes on to the bound.
 * 4. A test function that jumps: x' = a x with a = -0.1 below p = 0.3 and 0.1 above: the multiplier
 *    jumps across 1, the branch-point test changes sign without a zero; the location closes on the
 *    jump at 0.3 and reports it as a jump.
 * 5. A location whose trial points fail: system 1 with no model in (0.3, 0.30002): the
 *    Neimark-Sacker point there is the end of the bracket reached nearer the crossing (within 1e-4 of
 *    it, with its own multiplier on the circle to 1e-3), keeps that bracket, and reports it as a
 *    bracket.
 * 6. The period-doubling test where det(M + I) = prod (1 + mu) overflows (multipliers of 1e200): finite,
 *    with the product's sign. */
#include "analysis/cont_internal.h"
#include "analysis_util.h"
#include "tap.h"
#include "geardyn/gd_periodic.h"

#include <string.h>

typedef struct lin {
    int kind;                /* 1: two rotations, 2: neutral saddle, 3: pitchfork, 4: a jump */
    double p;
    double fail_lo, fail_hi; /* model_at fails for p in (fail_lo, fail_hi) */
    gd_custom_system sys;
} lin;

static void rhs(double t, const double *y, double *ydot, void *ctx)
{
    const lin *L = ctx;
    const double p = L->p, f = 1e-3 * cos(t);
    switch (L->kind) {
    case 1:
        ydot[0] = (p - 0.30) * y[0] - 0.7 * y[1] + f;
        ydot[1] = 0.7 * y[0] + (p - 0.30) * y[1];
        ydot[2] = (p - 0.31) * y[2] - 1.1 * y[3] + f;
        ydot[3] = 1.1 * y[2] + (p - 0.31) * y[3];
        break;
    case 2:
        ydot[0] = (1.0 + 0.5 * p) * y[0] + f;
        ydot[1] = (-1.0 + 0.5 * p) * y[1] + f;
        break;
    case 3:
        ydot[0] = p * y[0] - y[0] * y[0] * y[0];
        break;
    default:
        ydot[0] = (p < 0.3 ? -0.1 : 0.1) * y[0];
    }
}

static void tangent(double t, const double *y, const double *v, double *out, void *ctx)
{
    (void)t;
    const lin *L = ctx;
    const double p = L->p;
    switch (L->kind) {
    case 1:
        out[0] = (p - 0.30) * v[0] - 0.7 * v[1];
        out[1] = 0.7 * v[0] + (p - 0.30) * v[1];
        out[2] = (p - 0.31) * v[2] - 1.1 * v[3];
        out[3] = 1.1 * v[2] + (p - 0.31) * v[3];
        break;
    case 2:
        out[0] = (1.0 + 0.5 * p) * v[0];
        out[1] = (-1.0 + 0.5 * p) * v[1];
        break;
    case 3:
        out[0] = (p - 3.0 * y[0] * y[0]) * v[0];
        break;
    default:
        out[0] = (p < 0.3 ? -0.1 : 0.1) * v[0];
    }
}

static gd_status model_at(double p, gd_model *m, void *ctx, gd_error *err)
{
    lin *L = ctx;
    if (p > L->fail_lo && p < L->fail_hi)
        return gd_error_set(err, GD_ERR_SOLVER, "no model at p = %g (the test's gap)", p);
    L->p = p;
    gd_model_custom(m, &L->sys, 2.0 * M_PI);
    return GD_OK;
}

/* the branch of system `kind` (state size n) from the orbit near 0 at p0, in [lo, hi], steps of dp in p */
static void branch(lin *L, int n, double p0, double lo, double hi, double dp, gd_branch *br)
{
    gd_error e = {0};
    gd_solver_opts o;
    au_smooth_opts(&o);
    gd_model m;
    model_at(p0, &m, L, &e);
    double y[GD_MAX_STATE] = {0};
    gd_cont_opts co;
    gd_cont_opts_default(&co);
    co.p_min = lo;
    co.p_max = hi;
    co.ds = co.ds_min = co.ds_max = dp / (hi - lo);
    co.dp_max = 2.0 * dp;
    gd_po start;
    if (gd_po_solve(&m, &o, &co.po, y, &start, &e) != GD_OK)
        au_die(&e);
    start.p = p0;
    (void)n;
    if (gd_continue(model_at, L, &o, &co, &start, br, &e) != GD_OK)
        au_die(&e);
    printf("# system %d: %d points, end: %s\n", L->kind, br->npoints, br->end_reason);
    for (int i = 0; i < br->nbif; i++)
        printf("#   %s at p = %.10f (bracket %.10f .. %.10f), multiplier %.9f%+.9fi, %s\n",
               gd_bif_kind_name(br->bif[i].kind), br->bif[i].p, br->bif[i].p_lo, br->bif[i].p_hi, br->bif[i].mu_re,
               br->bif[i].mu_im, gd_bif_location_name(br->bif[i].location));
    for (int i = 0; i < br->nnotes; i++)
        printf("#   note: %s\n", br->notes[i]);
}

int main(void)
{
    /* 1. two pairs in one step */
    lin L = {.kind = 1, .sys = {4, rhs, tangent, NULL, NULL}};
    L.sys.ctx = &L;
    gd_branch br;
    branch(&L, 4, 0.0, 0.0, 1.0, 0.05, &br);
    int both = 0;
    for (int i = 1; i < br.npoints; i++)
        if (br.pt[i - 1].orbit.p < 0.30 && br.pt[i].orbit.p > 0.31)
            both = 1;
    tap_ok(both, "two pairs: one step holds both crossings (0.30 and 0.31)");
    int nns = 0, ok1 = 0, ok2 = 0;
    for (int i = 0; i < br.nbif; i++) {
        const gd_bifurcation *b = &br.bif[i];
        if (b->kind != GD_BIF_NEIMARK_SACKER)
            continue;
        nns++;
        double r = hypot(b->mu_re, b->mu_im), th = atan2(b->mu_im, b->mu_re);
        for (int k = 0; k < 2; k++) {
            double at = k ? 0.31 : 0.30, w = k ? 1.1 : 0.7, want = remainder(w * 2.0 * M_PI, 2.0 * M_PI);
            if (fabs(b->p - at) < 1e-7 && fabs(r - 1.0) < 1e-6 && fabs(remainder(fabs(th) - fabs(want), 2.0 * M_PI)) < 1e-6
                && b->location == GD_LOC_LOCATED)
                *(k ? &ok2 : &ok1) = 1;
        }
    }
    tap_ok(nns == 2 && ok1 && ok2, "two pairs: both Neimark-Sacker points located, at 0.30 and 0.31 to 1e-7, each "
           "multiplier on the unit circle at the angle of its rotation (%d found)", nns);
    gd_branch_free(&br);

    /* 2. a neutral saddle */
    lin S = {.kind = 2, .sys = {2, rhs, tangent, NULL, NULL}};
    S.sys.ctx = &S;
    branch(&S, 2, -0.5, -0.5, 0.5, 0.05, &br);
    int ns = 0;
    for (int i = 0; i < br.nbif; i++)
        ns += br.bif[i].kind == GD_BIF_NEIMARK_SACKER;
    double p_first = br.pt[0].orbit.p, p_last = br.pt[br.npoints - 1].orbit.p;
    tap_ok(br.end == GD_END_BOUND && p_first < 0 && p_last > 0 && ns == 0 && br.nnotes == 0,
           "neutral saddle: from %.2f to %.2f, %d Neimark-Sacker points, %d notes", p_first, p_last, ns, br.nnotes);
    gd_branch_free(&br);

    /* 3. a branch point */
    lin P = {.kind = 3, .sys = {1, rhs, tangent, NULL, NULL}};
    P.sys.ctx = &P;
    branch(&P, 1, -0.5, -0.5, 0.5, 0.05, &br);
    const gd_bifurcation *bp = NULL;
    int folds = 0;
    for (int i = 0; i < br.nbif; i++) {
        if (br.bif[i].kind == GD_BIF_BRANCH_POINT)
            bp = &br.bif[i];
        folds += br.bif[i].kind == GD_BIF_FOLD;
    }
    tap_ok(br.end == GD_END_BOUND && br.nbif == 1 && bp && fabs(bp->p) < 1e-7 && folds == 0 &&
               bp->location == GD_LOC_LOCATED,
           "branch point: the orbit x = 0 meets x^2 = p at p = %.3g, located as a branch point (%d bifurcations, "
           "%d folds), the branch on to the bound", bp ? bp->p : NAN, br.nbif, folds);
    gd_branch_free(&br);

    /* 4. a test function that jumps: x' = a x with a = -0.1 below p = 0.3 and 0.1 above, so the
     * multiplier exp(a T) jumps across 1 and the branch-point test changes sign there without a zero.
     * Brent closes a bracket on the jump; the location says so (jump), it does not report a zero. */
    lin J = {.kind = 4, .sys = {1, rhs, tangent, NULL, NULL}};
    J.sys.ctx = &J;
    branch(&J, 1, 0.0, 0.0, 1.0, 0.05, &br);
    const gd_bifurcation *jb = br.nbif == 1 ? &br.bif[0] : NULL;
    tap_ok(jb && jb->kind == GD_BIF_BRANCH_POINT && jb->location == GD_LOC_JUMP && fabs(jb->p - 0.3) < 1e-6,
           "a jump of the test function at p = 0.3: bracketed there (%.9f) and reported as a jump, not a zero (%s)",
           jb ? jb->p : NAN, jb ? gd_bif_location_name(jb->location) : "none");
    gd_branch_free(&br);

    /* 5. a location whose trial points find no model in (0.3, 0.30002), just beyond the crossing at
     * 0.30 (system 1): the Neimark-Sacker point is the end of the bracket reached nearer the crossing
     * (its own orbit, its multiplier on the circle to 1e-3), the bracket the one reached, and it says
     * so (bracket) */
    L.fail_lo = 0.3;
    L.fail_hi = 0.30002;
    branch(&L, 4, 0.0, 0.0, 1.0, 0.05, &br);
    const gd_bifurcation *nb = NULL;
    for (int i = 0; i < br.nbif; i++)
        if (br.bif[i].kind == GD_BIF_NEIMARK_SACKER && fabs(br.bif[i].p - 0.30) < 5e-3)
            nb = &br.bif[i];
    double lo = nb ? fmin(nb->p_lo, nb->p_hi) : NAN, hi = nb ? fmax(nb->p_lo, nb->p_hi) : NAN;
    tap_ok(nb && nb->location == GD_LOC_BRACKET && lo <= 0.3 && hi >= 0.30002 && fabs(nb->p - 0.3) < 1e-4 &&
               fabs(hypot(nb->mu_re, nb->mu_im) - 1.0) < 1e-3,
           "a location whose trial points fail just beyond 0.30: at %.7f (|mu| %.6f), the bracket reached %.6f .. "
           "%.6f, reported as %s", nb ? nb->p : NAN, nb ? hypot(nb->mu_re, nb->mu_im) : NAN, lo, hi,
           nb ? gd_bif_location_name(nb->location) : "none");
    gd_branch_free(&br);

    /* 6. the period-doubling test of multipliers whose product overflows: 1e200, 1e200, 0.5 +- 0.5i, -0.5
     * and -3e200 (det(M + I) about -1.5e600 < 0), and with 1e200 in place of -3e200 (> 0): the test
     * function is finite with the sign of the product (the product itself, formed factor by factor,
     * becomes inf * 0 = NaN) */
    gd_po q;
    memset(&q, 0, sizeof q);
    q.n = 6;
    const double re[6] = {-3e200, 1e200, 1e200, 0.5, 0.5, -0.5}, im[6] = {0, 0, 0, 0.5, -0.5, 0};
    memcpy(q.mu_re, re, sizeof re);
    memcpy(q.mu_im, im, sizeof im);
    double neg = cont_pd_test(&q);
    q.mu_re[0] = 1e200;
    double pos = cont_pd_test(&q);
    tap_ok(isfinite(neg) && neg < 0 && isfinite(pos) && pos > 0, "the period-doubling test where det(M + I) "
           "overflows: %.3g and %.3g, finite, with the product's signs (- and +)", neg, pos);
    return tap_done();
}
