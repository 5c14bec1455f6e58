/* Curves of folds, period doublings and grazings of periodic orbits in two parameters
 * (gd_curve_follow, gd_envelope.h; docs/continuation.md section 8) on the Kahraman & Singh oscillator
 * with constant stiffness: zeta 0.05, F_m 0.1, in the plane of the mesh frequency Omega and the
 * excitation amplitude F_a (operating.speed_rpm and excitation.ste_amplitude_um through
 * gd_model_at_case_keys), started from the bifurcations of the one-parameter branch in Omega at
 * F_a 0.1 (Omega 0.5 .. 1.5), F_a 0.05 .. 0.2.
 *
 * 1. Closed form: the grazing curve of the non-impacting orbit is where its linear amplitude
 *    F_a Omega^2 / |1 - Omega^2 + 2 i zeta Omega| reaches F_m: at every point of both directions
 *    |F_a Omega^2 - F_m sqrt((1 - Omega^2)^2 + (2 zeta Omega)^2)| < 1e-8.
 * 2. Liouville: for one degree of freedom det M = exp(-2 zeta 2 pi / Omega) (the saltation matrices of
 *    the continuous dead-zone force are the identity), so on a fold curve tr M = 1 + det M and on a
 *    period-doubling curve tr M = -(1 + det M): at every point of the two fold curves and the
 *    period-doubling curve, both directions, to 1e-8; the critical multiplier is +1 (-1) to 1e-8.
 * 3. Consistency: one-parameter continuations in Omega at F_a 0.05, 0.08, 0.12, 0.14 and 0.16 find the
 *    grazing, the two folds and (from F_a 0.09 on) the period doubling where the curves, followed from
 *    F_a 0.1 to a bound at that F_a (the curve's point on the bound is corrected there), cross it: to
 *    1e-8 relative in Omega.
 * 4. No curve ends on a change of its orbit's contact events inside the box: the lower fold curve runs
 *    down to F_a 0.05 (an event that crosses the start of the orbit rotates the order of its events
 *    and is no contact change; a fingerprint of the events in their order would end it at F_a 0.051).
 * 5. Neimark-Sacker, on a system whose multipliers are known: y' = [[s, -w], [w, s]] y + (1e-3 cos t, 0)
 *    with s = p1 - p2^2, w = 0.2 + 0.5 p2 (period 2 pi) has the multipliers exp(2 pi (s +- i w)), so
 *    its Neimark-Sacker curve is p1 = p2^2 with kappa = cos(2 pi w). Followed from p2 = 0.05 both ways
 *    in p2 0 .. 0.7: p1 = p2^2 and kappa to 1e-8 at every point, and the strong resonances 1:4
 *    (w = 1/4, p2 = 0.1) and 1:3 (w = 1/3, p2 = 0.2667) located there to 1e-8. (At w = 1/2, p2 = 0.6,
 *    the pair of this rotation touches -1 and leaves it again, kappa's minimum: no 1:2 point, and the
 *    curve runs on to the bound.)
 * 6. Admissibility (below).
 * 7. A jump of the model in the second parameter ends the curve there, named (below). */
#include "analysis_util.h"
#include "tap.h"
#include "geardyn/gd_envelope.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double ZETA = 0.05, FM = 0.1, FA0 = 0.1;
static const char *SETS[] = {"excitation.ste_phase_deg=90", "solver.rtol=1e-10", "solver.atol=1e-12", NULL};

/* the one-parameter branch from the attractor at Omega 0.5, F_a = fa, up to 1.5 */
static void branch_at(double fa, gd_branch *br)
{
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    gd_error e = {0};
    au_ks_case(&c, &m, 0.0, ZETA, FM, fa, 0.5, SETS);
    gd_solver_opts_from_case(&c, &o);
    double y[GD_MAX_STATE];
    gd_modes md;
    if (gd_initial_state(&c, &m, y, &md, &e) != GD_OK || gd_sim_period_map(&m, &o, y, 300, y, NULL, NULL, &e) != GD_OK)
        au_die(&e);
    gd_cont_opts co;
    gd_cont_opts_default(&co);
    co.p_min = 0.5;
    co.p_max = 1.5;
    co.ds_max = 0.05;
    gd_po start;
    if (gd_po_solve(&m, &o, &co.po, y, &start, &e) != GD_OK ||
        gd_continue(gd_model_at_mesh_frequency, &m, &o, &co, &start, br, &e) != GD_OK)
        au_die(&e);
    gd_case_free(&c);
}

/* the bifurcations of a branch by name: grazing (the first contact change), upper fold (above it),
 * lower fold (below it), period doubling (the highest in Omega: from F_a 0.16 on the branch has a
 * second one near Omega 0.63, on another curve); NULL when absent */
typedef struct named {
    const gd_bifurcation *b[4];
} named;
enum { GRAZE = 0, FOLD_HI = 1, FOLD_LO = 2, PD = 3 };
static const char *NAME[] = {"grazing", "upper fold", "lower fold", "period doubling"};

static named name_bifs(const gd_branch *br)
{
    named nb = {{NULL, NULL, NULL, NULL}};
    for (int i = 0; i < br->nbif; i++) {
        const gd_bifurcation *b = &br->bif[i];
        if (b->kind == GD_BIF_CONTACT_CHANGE && !nb.b[GRAZE])
            nb.b[GRAZE] = b;
        else if (b->kind == GD_BIF_PERIOD_DOUBLING && (!nb.b[PD] || b->p > nb.b[PD]->p))
            nb.b[PD] = b;
    }
    for (int i = 0; i < br->nbif && nb.b[GRAZE]; i++) {
        const gd_bifurcation *b = &br->bif[i];
        if (b->kind == GD_BIF_FOLD && b->p > nb.b[GRAZE]->p && !nb.b[FOLD_HI])
            nb.b[FOLD_HI] = b;
        else if (b->kind == GD_BIF_FOLD && b->p < nb.b[GRAZE]->p && !nb.b[FOLD_LO])
            nb.b[FOLD_LO] = b;
    }
    return nb;
}

static const int CURVE_OF[4] = {GD_CURVE_GRAZING, GD_CURVE_FOLD, GD_CURVE_FOLD, GD_CURVE_PERIOD_DOUBLING};

/* the curve of bifurcation b (of branch br at F_a 0.1) in direction dir, F_a in [lo, hi] */
static void follow(gd_case_param2 *pp, const gd_solver_opts *o, const gd_bifurcation *b, int kind, int dir, double lo,
                   double hi, gd_curve *cv)
{
    gd_error e = {0};
    gd_curve_opts co;
    gd_curve_opts_default(&co);
    co.p_min[0] = 0.5;
    co.p_max[0] = 1.5;
    co.p_min[1] = lo;
    co.p_max[1] = hi;
    co.direction = dir;
    gd_curve_start s;
    memset(&s, 0, sizeof s);
    s.kind = kind;
    s.nper = 1;
    s.clearance = kind == GD_CURVE_GRAZING ? b->clearance : -1;
    s.p1 = b->p;
    s.p2 = FA0;
    memcpy(s.y, b->y, sizeof s.y);
    if (gd_curve_follow(gd_model_at_case_keys, pp, o, &co, &s, cv, &e) != GD_OK)
        au_die(&e);
}

/* check 5: the linear rotation with known multipliers */
typedef struct rot {
    double p1, p2;
    gd_custom_system sys;
} rot;
static double rot_s(const rot *R) { return R->p1 - R->p2 * R->p2; }
static double rot_w(double p2) { return 0.2 + 0.5 * p2; }
static void rot_rhs(double t, const double *y, double *yd, void *ctx)
{
    const rot *R = ctx;
    double s = rot_s(R), w = rot_w(R->p2);
    yd[0] = s * y[0] - w * y[1] + 1e-3 * cos(t);
    yd[1] = w * y[0] + s * y[1];
}
static void rot_tangent(double t, const double *y, const double *v, double *out, void *ctx)
{
    (void)t;
    (void)y;
    const rot *R = ctx;
    double s = rot_s(R), w = rot_w(R->p2);
    out[0] = s * v[0] - w * v[1];
    out[1] = w * v[0] + s * v[1];
}
static gd_status rot_at(double p1, double p2, gd_model *m, void *ctx, gd_error *err)
{
    (void)err;
    rot *R = ctx;
    R->p1 = p1;
    R->p2 = p2;
    gd_model_custom(m, &R->sys, 2.0 * M_PI);
    return GD_OK;
}

static void neimark_sacker(void)
{
    rot R;
    memset(&R, 0, sizeof R);
    R.sys.n = 2;
    R.sys.rhs = rot_rhs;
    R.sys.tangent = rot_tangent;
    R.sys.ctx = &R;
    gd_solver_opts o;
    au_smooth_opts(&o);
    gd_curve_opts co;
    gd_curve_opts_default(&co);
    co.p_min[0] = -0.5;
    co.p_max[0] = 1.0;
    co.p_min[1] = 0.0;
    co.p_max[1] = 0.7;
    gd_curve_start s;
    memset(&s, 0, sizeof s);
    s.kind = GD_CURVE_NEIMARK_SACKER;
    s.nper = 1;
    s.clearance = -1;
    s.p1 = 0.0025;
    s.p2 = 0.05;
    for (int dir = -1; dir <= 1; dir += 2) {
        gd_error e = {0};
        gd_curve cv;
        co.direction = dir;
        if (gd_curve_follow(rot_at, &R, &o, &co, &s, &cv, &e) != GD_OK)
            au_die(&e);
        double w1 = 0, wk = 0;
        for (int i = 0; i < cv.npoints; i++) {
            double p1 = cv.pt[i].orbit.p, p2 = cv.pt[i].p2;
            w1 = fmax(w1, fabs(p1 - p2 * p2));
            wk = fmax(wk, fabs(cv.pt[i].kappa - cos(2.0 * M_PI * rot_w(p2))));
        }
        printf("# Neimark-Sacker curve %s: %d points, %ld corrections, %ld Newton iterations: %s\n",
               dir > 0 ? "up" : "down", cv.npoints, cv.corrections, cv.newton_iterations, cv.end_reason);
        for (int i = 0; i < cv.nc2; i++)
            printf("#   %s at (%.10f, %.10f), kappa %.10f, location %s\n", gd_codim2_kind_name(cv.c2[i].kind),
                   cv.c2[i].p1, cv.c2[i].p2, cv.c2[i].kappa, gd_bif_location_name(cv.c2[i].location));
        double top = dir > 0 ? 0.7 : 0.0;
        tap_ok(cv.end == GD_CEND_BOUND && fabs(cv.pt[cv.npoints - 1].p2 - top) < 1e-12,
               "Neimark-Sacker curve %s: to the bound p2 = %g (%s)", dir > 0 ? "up" : "down", top, cv.end_reason);
        tap_ok(w1 < 1e-8 && wk < 1e-8, "Neimark-Sacker curve %s: p1 = p2^2 to %.2g, kappa = cos(2 pi w) to %.2g at "
               "every point", dir > 0 ? "up" : "down", w1, wk);
        if (dir > 0) {
            const double want[2] = {0.1, 0.8 / 3.0};
            const int kind[2] = {GD_C2_R4, GD_C2_R3};
            int found = 0;
            for (int j = 0; j < 2; j++)
                for (int i = 0; i < cv.nc2; i++)
                    if (cv.c2[i].kind == kind[j] && fabs(cv.c2[i].p2 - want[j]) < 1e-8 &&
                        fabs(cv.c2[i].p1 - want[j] * want[j]) < 1e-8)
                        found++;
            tap_ok(found == 2 && cv.nc2 == 2, "the strong resonances 1:4 at p2 = 0.1 and 1:3 at p2 = 0.2667 located "
                   "to 1e-8, and no other codimension-two point (%d found, %d of them right)", cv.nc2, found);
        } else {
            tap_ok(cv.nc2 == 0, "no codimension-two point below p2 = 0.05 (%d)", cv.nc2);
        }
        gd_curve_free(&cv);
    }
}

/* check 6: admissibility of a grazing curve. A second harmonic a2 cos(2 Omega t + DELTA2) of the
 * transmission error (a2 in units of the half backlash, the curve's second parameter; the first is F_a,
 * Omega held at the grazing of the branch at F_a 0.1). The in-contact orbit is linear,
 * x = 1 + F_m + A1 cos(phi) + A2 cos(2 phi + delta): along the grazing curve (its minimum at the
 * boundary x = 1) a2 grows with F_a, and with delta near 0 (DELTA2 2.72 at Omega 0.709) x'' at the
 * touch, A1 - 4 A2 cos(delta), falls to zero: a degenerate grazing, where two new minima are born at
 * the touch. Beyond it the defining system still has solutions (the touch a local maximum at the
 * boundary between two minima past it, inside the held window, where no event is located), but no
 * orbit of the model is such: the curve must end there ("inadmissible"; without the check it runs on
 * to F_a 0.2 over 22 more points). Each point of the curve is checked by an ordinary run of the hybrid
 * model from its state (events everywhere, no held window): no minimum of x below the boundary by
 * more than 1e-7. */
static const double DELTA2 = 2.72;
static gd_status harm2_at(double p1, double p2, gd_model *m, void *ctx, gd_error *err)
{
    gd_status st = gd_model_at_case_keys(p1, p2, m, ctx, err); /* (p2 scales to the mean error 0) */
    double e[8];
    for (int i = 0; i < 8; i++)
        e[i] = p2 * m->bc_m * cos(2.0 * (2.0 * M_PI * i / 8.0) + DELTA2);
    for (int j = 0; j < m->nmesh && st == GD_OK; j++)
        st = gd_model_set_error_table(m, j, e, 8, err);
    return st;
}

static void admissibility(gd_case *c, const gd_solver_opts *o, double om, const gd_bifurcation *graze)
{
    gd_error e = {0};
    if (gd_case_set_number(c, "operating.speed_rpm", graze->p / om, &e) != GD_OK)
        au_die(&e);
    gd_case_param2 pp = {c, "excitation.ste_amplitude_um", "excitation.ste_mean_um", 1.0, 0.0};
    gd_curve_opts co;
    gd_curve_opts_default(&co);
    co.p_min[0] = 0.01;
    co.p_max[0] = 0.3;
    co.p_min[1] = 0.0;
    co.p_max[1] = 0.1;
    co.direction = 1;
    gd_curve_start s;
    memset(&s, 0, sizeof s);
    s.kind = GD_CURVE_GRAZING;
    s.nper = 1;
    s.clearance = graze->clearance;
    s.p1 = FA0;
    s.p2 = 0.0;
    memcpy(s.y, graze->y, sizeof s.y);
    gd_curve cv;
    if (gd_curve_follow(harm2_at, &pp, o, &co, &s, &cv, &e) != GD_OK)
        au_die(&e);
    const gd_curve_point *z = &cv.pt[cv.npoints - 1];
    printf("# grazing curve in (F_a, a2) at Omega %.10f: %d points to (%.10f, %.10f), %ld corrections: %s\n",
           graze->p, cv.npoints, z->orbit.p, z->p2, cv.corrections, cv.end_reason);
    tap_ok(cv.end == GD_CEND_INADMISSIBLE && strstr(cv.end_reason, "not admissible") &&
           strstr(cv.end_reason, "curvature"), "admissibility: the grazing curve ends where its touch turns "
           "degenerate (%s: %s)", gd_curve_end_name(cv.end), cv.end_reason);
    /* every point: the model's own orbit from its state keeps x >= 1 (its minima on or above the boundary) */
    double below = 0;
    const int cl = graze->clearance;
    for (int i = 0; i < cv.npoints; i++) {
        gd_model m;
        gd_gap_extrema g;
        if (harm2_at(cv.pt[i].orbit.p, cv.pt[i].p2, &m, &pp, &e) != GD_OK ||
            gd_sim_orbit_gaps(&m, o, cv.pt[i].orbit.y[0], 1, &g, &e) != GD_OK)
            au_die(&e);
        for (int j = 0; j < g.n[cl]; j++)
            if (g.kind[cl][j] < 0)
                below = fmax(below, g.h[cl] - g.x[cl][j]);
    }
    tap_ok(below < 1e-7, "admissibility: at each of the %d points no minimum of the model's orbit lies below the "
           "boundary by more than 1e-7 (%.2g)", cv.npoints, below);
    tap_ok(z->p2 > 0.01 && z->orbit.p > FA0, "admissibility: the curve ran to a2 %.6f, F_a %.6f before it ended",
           z->p2, z->orbit.p);
    gd_curve_free(&cv);
}

/* check 7: a model that jumps in the second parameter. The excitation amplitude of the model is F_a for
 * F_a >= 0.08 and F_a - 0.01 below (a step of the model, as the mesh-in impact of an LTCA excitation
 * when its first touch moves from one point of the flank to another). The grazing curve followed down
 * from F_a 0.1 reaches the step (Omega 0.7477); below it the model's grazing curve lies elsewhere (at F_a
 * higher by 0.01), so no point across the step continues the curve: the curve must end at the step with
 * its cause named ("discontinuous", not "no convergence at the smallest step"), its last point within
 * 1e-3 above it, and not crawl towards it at the smallest step. */
static const double JUMP_AT = 0.08;
static double JUMP_BY = -0.01;
static gd_status jump_at(double p1, double p2, gd_model *m, void *ctx, gd_error *err)
{
    return gd_model_at_case_keys(p1, p2 < JUMP_AT ? p2 + JUMP_BY : p2, m, ctx, err);
}

/* The box, direction and start of the grazing curve followed down to the model's step (checks 7, 7b). */
static void jump_curve(const gd_bifurcation *graze, gd_curve_opts *co, gd_curve_start *s)
{
    gd_curve_opts_default(co);
    co->p_min[0] = 0.5;
    co->p_max[0] = 1.5;
    co->p_min[1] = 0.05;
    co->p_max[1] = 0.2;
    co->direction = -1;
    memset(s, 0, sizeof *s);
    s->kind = GD_CURVE_GRAZING;
    s->nper = 1;
    s->clearance = graze->clearance;
    s->p1 = graze->p;
    s->p2 = FA0;
    memcpy(s->y, graze->y, sizeof s->y);
}

/* check 7b: a small step of the model (F_a - 0.002 below 0.08): the grazing curve's corrector converges
 * across it in one step, onto the model's other grazing curve (shifted by 0.002 in F_a); a step over the
 * jump is found (the corrector's differences saw it, the residual bisected) and the curve ends at the jump,
 * not on the box at F_a 0.05 having changed curves unseen. */
static void model_small_jump(gd_case_param2 *pp, const gd_solver_opts *o, const gd_bifurcation *graze)
{
    gd_error e = {0};
    gd_curve_opts co;
    gd_curve_start s;
    jump_curve(graze, &co, &s);
    JUMP_BY = -0.002;
    gd_curve cv;
    if (gd_curve_follow(jump_at, pp, o, &co, &s, &cv, &e) != GD_OK)
        au_die(&e);
    JUMP_BY = -0.01;
    const gd_curve_point *z = &cv.pt[cv.npoints - 1];
    double below = INFINITY;
    for (int i = 0; i < cv.npoints; i++)
        below = fmin(below, cv.pt[i].p2);
    printf("# grazing curve down to a small step of the model at F_a %.3f: %d points to (%.10f, %.10f), %ld "
           "corrections: %s: %s\n", JUMP_AT, cv.npoints, z->orbit.p, z->p2, cv.corrections, gd_curve_end_name(cv.end),
           cv.end_reason);
    tap_ok(cv.end == GD_CEND_DISCONTINUOUS && below >= JUMP_AT && z->p2 - JUMP_AT < 1e-4, "small model step: no "
           "point below F_a %.3f (lowest %.10f), the curve ends discontinuous within 1e-4 above it (%s)", JUMP_AT,
           below, gd_curve_end_name(cv.end));
    gd_curve_free(&cv);
}

static void model_jump(gd_case_param2 *pp, const gd_solver_opts *o, const gd_bifurcation *graze)
{
    gd_error e = {0};
    gd_curve_opts co;
    gd_curve_start s;
    jump_curve(graze, &co, &s);
    co.words.key[1] = "excitation.ste_amplitude_um";
    co.words.unit[1] = "um";
    gd_curve cv;
    if (gd_curve_follow(jump_at, pp, o, &co, &s, &cv, &e) != GD_OK)
        au_die(&e);
    const gd_curve_point *z = &cv.pt[cv.npoints - 1];
    int small = 0;
    for (int i = 0; i < cv.npoints; i++)
        small += cv.pt[i].ds > 0 && cv.pt[i].ds < 2.0 * co.ds_min;
    printf("# grazing curve down to a step of the model at F_a %.3f: %d points (%d at the smallest step) to "
           "(%.10f, %.10f), %ld corrections: %s: %s\n", JUMP_AT, cv.npoints, small, z->orbit.p, z->p2, cv.corrections,
           gd_curve_end_name(cv.end), cv.end_reason);
    tap_ok(cv.end == GD_CEND_DISCONTINUOUS && strstr(cv.end_reason, "excitation.ste_amplitude_um") &&
           strstr(cv.end_reason, "discontinuous"), "model step: the curve ends on the model's discontinuity, named "
           "(%s: %s)", gd_curve_end_name(cv.end), cv.end_reason);
    tap_ok(z->p2 >= JUMP_AT && z->p2 - JUMP_AT < 1e-3, "model step: its last point at F_a %.10f, within 1e-3 above "
           "the step at %.3f", z->p2, JUMP_AT);
    tap_ok(small <= 5, "model step: %d of its %d points at the smallest step (at most 5: no crawl)", small, cv.npoints);
    /* the jump is located from the first step whose corrector fails next to it (its differences saw the jump),
     * not by halving that step down to ds_min, a failed corrector at each of some eighteen halvings */
    tap_ok(cv.corrections <= cv.npoints + 4, "model step: named at the first failed step: %ld corrections for %d "
           "points", cv.corrections, cv.npoints);
    const char *at = strstr(cv.end_reason, " at ");
    const double pj = at ? atof(at + 4) : NAN;
    tap_ok(fabs(pj - JUMP_AT) < 1e-6 && z->p2 > pj && z->p2 - JUMP_AT < 1e-4, "model step: located at F_a %.10g "
           "(within 1e-6 of %.3f), the last point %.3g above it", pj, JUMP_AT, z->p2 - pj);
    gd_curve_free(&cv);
}

int main(void)
{
    neimark_sacker();
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    au_ks_case(&c, &m, 0.0, ZETA, FM, FA0, 0.5, SETS);
    gd_solver_opts_from_case(&c, &o);
    const double om = m.Omega / c.speed_rpm; /* Omega per rpm */
    gd_case_param2 pp = {&c, "operating.speed_rpm", "excitation.ste_amplitude_um", 1.0 / om, 1.0};
    gd_branch br;
    branch_at(FA0, &br);
    named nb = name_bifs(&br);
    tap_ok(nb.b[GRAZE] && nb.b[FOLD_HI] && nb.b[FOLD_LO] && nb.b[PD],
           "the branch at F_a 0.1 has a grazing, two folds and a period doubling (%d bifurcations)", br.nbif);
    if (!(nb.b[GRAZE] && nb.b[FOLD_HI] && nb.b[FOLD_LO] && nb.b[PD]))
        return tap_done();
    admissibility(&c, &o, om, nb.b[GRAZE]);
    model_jump(&pp, &o, nb.b[GRAZE]);
    model_small_jump(&pp, &o, nb.b[GRAZE]);

    /* 1 and 2: every point of every curve, both directions over the whole box */
    for (int k = 0; k < 4; k++)
        for (int dir = -1; dir <= 1; dir += 2) {
            gd_curve cv;
            follow(&pp, &o, nb.b[k], CURVE_OF[k], dir, 0.05, 0.2, &cv);
            double worst = 0, worst_det = 0, worst_mu = 0;
            for (int i = 0; i < cv.npoints; i++) {
                const gd_po *q = &cv.pt[i].orbit;
                double Om = q->p, fa = cv.pt[i].p2;
                if (k == GRAZE) {
                    double r = fa * Om * Om - FM * sqrt(pow(1 - Om * Om, 2) + pow(2 * ZETA * Om, 2));
                    worst = fmax(worst, fabs(r));
                    continue;
                }
                double tr = q->M[0] + q->M[3], det = q->M[0] * q->M[3] - q->M[1] * q->M[2];
                double s = CURVE_OF[k] == GD_CURVE_FOLD ? 1.0 : -1.0;
                worst = fmax(worst, fabs(tr - s * (1.0 + det)));
                worst_det = fmax(worst_det, fabs(det - exp(-2.0 * ZETA * 2.0 * M_PI / Om)));
                double dmu = INFINITY; /* the multiplier nearest s */
                for (int j = 0; j < q->n; j++)
                    dmu = fmin(dmu, hypot(q->mu_re[j] - s, q->mu_im[j]));
                worst_mu = fmax(worst_mu, dmu);
            }
            const gd_curve_point *z = &cv.pt[cv.npoints - 1];
            printf("# %s curve %s: %d points to (%.8f, %.8f), %ld corrections, %ld Newton iterations: %s\n", NAME[k],
                   dir > 0 ? "up" : "down", cv.npoints, z->orbit.p, z->p2, cv.corrections, cv.newton_iterations,
                   cv.end_reason);
            tap_ok(cv.end != GD_CEND_CONTACT, "%s curve %s: no contact change ends it (%s)", NAME[k],
                   dir > 0 ? "up" : "down", gd_curve_end_name(cv.end));
            tap_ok(cv.npoints >= 10, "%s curve %s: %d points (%s)", NAME[k], dir > 0 ? "up" : "down", cv.npoints,
                   gd_curve_end_name(cv.end));
            if (k == GRAZE) {
                TAP_CLOSE(worst, 0.0, 1e-8, "grazing curve: F_a Omega^2 - F_m sqrt((1 - Omega^2)^2 + (2 zeta Omega)^2) "
                          "at every point");
            } else {
                tap_ok(worst < 1e-8, "%s curve %s: tr M %s (1 + det M) to %.2g at every point (Liouville)", NAME[k],
                       dir > 0 ? "up" : "down", CURVE_OF[k] == GD_CURVE_FOLD ? "=" : "= -", worst);
                tap_ok(worst_det < 1e-8, "%s curve %s: det M = exp(-4 pi zeta / Omega) to %.2g", NAME[k],
                       dir > 0 ? "up" : "down", worst_det);
                tap_ok(worst_mu < 1e-8, "%s curve %s: a multiplier at %s1 to %.2g at every point", NAME[k],
                       dir > 0 ? "up" : "down", CURVE_OF[k] == GD_CURVE_FOLD ? "+" : "-", worst_mu);
            }
            gd_curve_free(&cv);
        }

    /* 3: one-parameter runs at five values of F_a against the curves' points on the bound F_a */
    const double fas[] = {0.05, 0.08, 0.12, 0.14, 0.16};
    for (int f = 0; f < 5; f++) {
        gd_branch b2;
        branch_at(fas[f], &b2);
        named n2 = name_bifs(&b2);
        for (int k = 0; k < 4; k++) {
            if (k == PD && fas[f] < 0.09)
                continue; /* the period doubling leaves Omega 1.5 below F_a 0.081 */
            if (!n2.b[k]) {
                tap_ok(0, "F_a %.2f: the one-parameter branch has its %s", fas[f], NAME[k]);
                continue;
            }
            gd_curve cv;
            int dir = fas[f] > FA0 ? 1 : -1;
            follow(&pp, &o, nb.b[k], CURVE_OF[k], dir, dir > 0 ? 0.05 : fas[f], dir > 0 ? fas[f] : 0.2, &cv);
            const gd_curve_point *z = &cv.pt[cv.npoints - 1];
            double rel = fabs(z->orbit.p - n2.b[k]->p) / n2.b[k]->p;
            tap_ok(cv.end == GD_CEND_BOUND && fabs(z->p2 - fas[f]) < 1e-12 && rel < 1e-8,
                   "F_a %.2f: the %s of the one-parameter run at Omega %.10f, the curve's %.10f (rel %.2g; %s)", fas[f],
                   NAME[k], n2.b[k]->p, z->orbit.p, rel, cv.end_reason);
            gd_curve_free(&cv);
        }
        gd_branch_free(&b2);
    }
    gd_branch_free(&br);
    gd_case_free(&c);
    return tap_done();
}
