/* Pseudo-arclength continuation of the Kahraman & Singh oscillator in the mesh frequency
 * (gd_continue with gd_model_at_mesh_frequency): zeta 0.05, F_m 0.1, F_a 0.1, Omega 0.5 .. 1.5,
 * time-invariant stiffness (alpha 0) and the modulation of cases/validation/kahraman-singh.ini
 * (alpha 0.2).
 *
 * 1. The branch from Omega 0.5 upwards ends on the bound 1.5 with the bifurcations expected of a
 *    softening impact oscillator: the grazing where the non-impacting orbit first touches the
 *    boundary (a contact change; for alpha 0 at Omega = 1/sqrt(1.99), where the linear amplitude
 *    F_a Omega^2 / |1 - Omega^2 + 2 i zeta Omega| reaches F_m, located to 1e-9 on the distance of
 *    the orbit's smallest mesh deflection to the boundary), a fold above it where the branch turns
 *    back (the jump of an up sweep), a fold below it where the unstable branch turns into the
 *    stable impacting one (the jump of a down sweep), and for alpha 0 a period doubling; each
 *    located to an arclength bracket of 1e-8 in at most 12 corrected points (Brent's method; a
 *    bisection would take 22 or more).
 * 2. Both directions: from the attractor at Omega 1.0 continued down and up, the same bifurcations
 *    to 1e-8 in the parameter.
 * 3. Every stable branch point whose largest multiplier is below 0.9 is the attractor of plain
 *    simulation: from the orbit's Poincare point moved by 1e-3 in every component, integrated
 *    until |mu_max|^N < 1e-10, the state at mesh phase 0 agrees with the branch point to 1e-6.
 * 4. Brute force on both sides of each bifurcation, 0.01 away in Omega, from the branch point
 *    nearest it: on the side where the branch exists the simulation stays on the orbit shooting
 *    finds there (to 1e-6); on the other side it leaves (by more than 1e-2), and beyond the
 *    period doubling it settles on a period-2 orbit (P(y) - y > 1e-3, P^2(y) - y < 1e-6).
 * 5. Branch switching at the period doubling (alpha 0): the period-2 orbit found 0.01 beyond it is
 *    stable and is the attractor of simulation there (to 1e-6); its branch, continued to 1.5, has
 *    every stable point with |mu_max| < 0.9 against settled simulation to 1e-6.
 * 6. A brute-force sweep up and down in steps of 0.005 jumps once each way, in the grid interval
 *    that contains the upper fold (up) and the lower fold (down): the hysteresis interval of the
 *    sweep is bounded by the two folds.
 * 7. The located values converge as the integration tolerance tightens (alpha 0, rtol 1e-6, 1e-8,
 *    1e-10, 1e-12, atol 100 times smaller, locate_tol 1e-8): the grazing within 1e-9 of 1/sqrt(1.99)
 *    from rtol 1e-8 on and within 1e-8 at 1e-6, the folds within 1e-8 and the period doubling within
 *    5e-8 of their values at rtol 1e-12.
 * 8. The extrema the grazing is located on (gd_sim_orbit_gaps): on the non-impacting orbit at
 *    Omega 0.6 (alpha 0) the mesh coordinate has one maximum and one minimum per period, at
 *    1 + F_m +- F_a Omega^2 / |1 - Omega^2 + 2 i zeta Omega| (the closed form of
 *    tests/test_periodic_orbit.c) to 1e-9, half a period apart to 1e-6. A pair of extrema inside one
 *    integration step: with a third stiffness harmonic at Omega 0.2 the coordinate has 8 extrema per
 *    period, two of them 0.041 periods apart; with 12 fixed steps per period the gap watch finds the 8
 *    of an adaptive run at rtol 1e-10 (to 1e-3 in phase, 1e-4 in the coordinate).
 * 9. A bifurcation in the last step before a bound is located: the branch from 0.5 to a bound 1e-6
 *    beyond the grazing, or beyond the period doubling, has it at its place to 1e-8.
 * 10. The period-2 branch by single shooting (one segment of two periods) has the bifurcations of
 *    multiple shooting to 1e-8 and as many points within 25 %, and the parameter part of its unit
 *    tangent at the start within 20 % of multiple shooting's (the arclength's state part is averaged
 *    over the segments).
 * 11. The event-count fallback of a contact change (gd_cont_opts.contact_by_events): the grazing of
 *    alpha 0 bisected on the event count lies within 1e-6 above its place, on the side where the
 *    orbit penetrates, and is reported as located on the event count.
 * 12. Branch switching accepts only the orbit born at the doubling: offered the period-1 orbit at
 *    Omega 1.3 as a period doubling (none is there; the stable period-2 orbit born at 1.2267 coexists),
 *    gd_po_period_doubled refuses; at the real doubling it finds the period-2 orbit. */
#include "analysis_util.h"
#include "tap.h"
#include "geardyn/gd_periodic.h"
#include "geardyn/gd_scene.h"

#include <string.h>

static double dist(const double *a, const double *b, int n)
{
    double d = 0;
    for (int i = 0; i < n; i++)
        d = fmax(d, fabs(a[i] - b[i]));
    return d;
}

/* the branch from the attractor reached after 300 periods from the case's start at Omega0 (po_tol,
 * locate_tol: the shooting's and the location's tolerances, 0 for the default: derived) */
static void branch(const gd_case *c, const gd_model *m, const gd_solver_opts *o, int direction, double po_tol,
                   double locate_tol, gd_branch *br)
{
    gd_error e = {0};
    double y[GD_MAX_STATE];
    gd_modes md;
    if (gd_initial_state(c, m, y, &md, &e) != GD_OK || gd_sim_period_map(m, o, y, 300, y, NULL, NULL, &e) != GD_OK)
        au_die(&e);
    gd_cont_opts co;
    gd_cont_opts_default(&co);
    co.p_min = 0.5;
    co.p_max = 1.5;
    co.ds_max = 0.05;
    co.direction = direction;
    co.po.tol = po_tol;
    co.locate_tol = locate_tol;
    gd_po start;
    if (gd_po_solve(m, o, &co.po, y, &start, &e) != GD_OK || gd_continue(gd_model_at_mesh_frequency, (void *)m, o, &co,
                                                                           &start, br, &e) != GD_OK)
        au_die(&e);
    long it = br->newton_iterations;
    printf("# from Omega %.3g, direction %+d: %d points, %ld corrections, %ld Newton iterations (%.2f per "
           "correction), %ld chord iterations, end: %s\n", m->Omega, direction, br->npoints, br->corrections, it,
           (double)it / (double)br->corrections, br->chord_iterations, br->end_reason);
    for (int i = 0; i < br->nbif; i++)
        printf("#   %s at Omega %.10f (bracket %.10f .. %.10f), multiplier %.6f%+.6fi, %d corrections\n",
               gd_bif_kind_name(br->bif[i].kind), br->bif[i].p, br->bif[i].p_lo, br->bif[i].p_hi, br->bif[i].mu_re,
               br->bif[i].mu_im, br->bif[i].corrections);
}

/* check 3: stable points against settled simulation */
static void stable_points(const char *name, const gd_model *m, const gd_solver_opts *o, const gd_branch *br)
{
    gd_error e = {0};
    double dmax = 0;
    int count = 0;
    for (int i = 0; i < br->npoints; i++) {
        const gd_po *q = &br->pt[i].orbit;
        if (!(q->mu_max < 0.9))
            continue;
        gd_model mq;
        double y[GD_MAX_STATE];
        if (gd_model_at_mesh_frequency(q->p, &mq, (void *)m, &e) != GD_OK)
            au_die(&e);
        for (int j = 0; j < m->n; j++)
            y[j] = q->y[0][j] + 1e-3;
        int N = (int)ceil(log(1e-10) / log(q->mu_max)) * q->nper; /* whole orbit periods: back to y[0] */
        if (gd_sim_period_map(&mq, o, y, N, y, NULL, NULL, &e) != GD_OK)
            au_die(&e);
        dmax = fmax(dmax, dist(y, q->y[0], m->n));
        count++;
    }
    char label[200];
    snprintf(label, sizeof label, "%s: %d stable points against settled simulation, max |y - y_sim|", name, count);
    TAP_CLOSE(dmax, 0.0, 1e-6, label);
}

/* the branch point nearest parameter p */
static const gd_po *nearest(const gd_branch *br, double p, int after)
{
    const gd_po *best = NULL;
    for (int i = after - 1; i <= after && i < br->npoints; i++)
        if (i >= 0 && (!best || fabs(br->pt[i].orbit.p - p) < fabs(best->p - p)))
            best = &br->pt[i].orbit;
    return best;
}

/* check 4 at bifurcation b: `exists` is the side (+1 above, -1 below) where the orbit exists and is
 * stable; brute force there stays, on the other side it leaves */
static void both_sides(const char *name, const gd_model *m, const gd_solver_opts *o, const gd_branch *br,
                       const gd_bifurcation *b, int exists)
{
    gd_error e = {0};
    const int n = m->n;
    const gd_po *q = nearest(br, b->p, b->after);
    gd_model mq;
    double y[GD_MAX_STATE], y1[GD_MAX_STATE], y2[GD_MAX_STATE];
    /* the side where the orbit exists: shoot there from the stable branch point nearest it, simulate from
     * it moved by 1e-4 */
    double p_in = b->p + 0.01 * exists, p_out = b->p - 0.01 * exists;
    const gd_po *qi = NULL;
    for (int i = 0; i < br->npoints; i++)
        if (br->pt[i].orbit.stable && (!qi || fabs(br->pt[i].orbit.p - p_in) < fabs(qi->p - p_in)))
            qi = &br->pt[i].orbit;
    gd_po_opts po;
    gd_po_opts_default(&po);
    gd_po orbit;
    if (gd_model_at_mesh_frequency(p_in, &mq, (void *)m, &e) != GD_OK || gd_po_solve(&mq, o, &po, qi->y[0], &orbit, &e))
        au_die(&e);
    for (int j = 0; j < n; j++)
        y[j] = orbit.y[0][j] + 1e-4;
    if (gd_sim_period_map(&mq, o, y, 3000, y, NULL, NULL, &e) != GD_OK)
        au_die(&e);
    double d_in = dist(y, orbit.y[0], n);
    /* the other side: from the nearest point the simulation goes elsewhere */
    if (gd_model_at_mesh_frequency(p_out, &mq, (void *)m, &e) != GD_OK)
        au_die(&e);
    memcpy(y, q->y[0], sizeof y);
    if (gd_sim_period_map(&mq, o, y, 3000, y, NULL, NULL, &e) != GD_OK ||
        gd_sim_period_map(&mq, o, y, 1, y1, NULL, NULL, &e) != GD_OK ||
        gd_sim_period_map(&mq, o, y1, 1, y2, NULL, NULL, &e) != GD_OK)
        au_die(&e);
    double d_out = dist(y, q->y[0], n);
    tap_ok(d_in < 1e-6, "%s %s at %.6f: 0.01 on the side of the orbit, simulation stays on it (%.3g)", name,
           gd_bif_kind_name(b->kind), b->p, d_in);
    if (b->kind == GD_BIF_PERIOD_DOUBLING) {
        double d1 = dist(y1, y, n), d2 = dist(y2, y, n);
        tap_ok(d1 > 1e-3 && d2 < 1e-6, "%s period doubling at %.6f: 0.01 beyond, a period-2 orbit (|P y - y| %.3g, "
               "|P^2 y - y| %.3g)", name, b->p, d1, d2);
    } else {
        tap_ok(d_out > 1e-2, "%s fold at %.6f: 0.01 beyond, simulation leaves the branch (%.3g)", name, b->p, d_out);
    }
}

/* the bifurcations of kind `kind` of a branch, in branch order */
static int of_kind(const gd_branch *br, int kind, const gd_bifurcation **out, int max)
{
    int k = 0;
    for (int i = 0; i < br->nbif; i++)
        if (br->bif[i].kind == kind && k < max)
            out[k++] = &br->bif[i];
    return k;
}

/* the largest parameter difference between bifurcations of the same kind in two branches (in
 * opposite order when reversed); -1 when their numbers differ */
static double same_bifurcations(const gd_branch *a, const gd_branch *b, int reversed)
{
    double d = 0;
    for (int kind = 0; kind <= GD_BIF_CONTACT_CHANGE; kind++) {
        const gd_bifurcation *x[8], *y[8];
        int nx = of_kind(a, kind, x, 8), ny = of_kind(b, kind, y, 8);
        if (nx != ny)
            return -1;
        for (int i = 0; i < nx; i++)
            d = fmax(d, fabs(x[i]->p - y[reversed ? nx - 1 - i : i]->p));
    }
    return d;
}

/* 5. branch switching at the period doubling b: the period-2 orbit 0.01 beyond it against settled
 * simulation (either of its two Poincare points), and its branch continued to 1.5 */
static void period_two(const char *name, const gd_model *m, const gd_solver_opts *o, const gd_bifurcation *b)
{
    gd_error e = {0};
    gd_po_opts po;
    gd_po_opts_default(&po);
    gd_po p2;
    if (gd_po_period_doubled(gd_model_at_mesh_frequency, (void *)m, o, &po, b, 0.01, 0.05, &p2, &e) != GD_OK)
        au_die(&e);
    gd_model mq;
    double y[GD_MAX_STATE];
    memcpy(y, b->y, sizeof y);
    if (gd_model_at_mesh_frequency(p2.p, &mq, (void *)m, &e) != GD_OK ||
        gd_sim_period_map(&mq, o, y, 3000, y, NULL, NULL, &e) != GD_OK)
        au_die(&e);
    double d = fmin(dist(y, p2.y[0], m->n), dist(y, p2.y[1], m->n));
    printf("# period-2 orbit at Omega %.6f: mu_max %.6f, Newton %d, events %ld\n", p2.p, p2.mu_max, p2.iterations,
           p2.events[0]);
    tap_ok(p2.nper == 2 && p2.stable && d < 1e-6 && dist(p2.y[0], p2.y[1], m->n) > 1e-3,
           "%s: the period-2 orbit switched to at Omega %.6f is stable (%.6f) and the attractor of simulation "
           "(%.3g)", name, p2.p, p2.mu_max, d);
    gd_cont_opts co;
    gd_cont_opts_default(&co);
    co.po.nper = 2;
    co.p_min = 0.5;
    co.p_max = 1.5;
    co.ds_max = 0.05;
    gd_branch br;
    if (gd_continue(gd_model_at_mesh_frequency, (void *)m, o, &co, &p2, &br, &e) != GD_OK)
        au_die(&e);
    printf("# the period-2 branch from Omega %.6f: %d points, %d bifurcations, end: %s\n", p2.p, br.npoints, br.nbif,
           br.end_reason);
    for (int i = 0; i < br.nbif; i++)
        printf("#   %s at Omega %.10f, multiplier %.6f%+.6fi\n", gd_bif_kind_name(br.bif[i].kind), br.bif[i].p,
               br.bif[i].mu_re, br.bif[i].mu_im);
    char label[200];
    snprintf(label, sizeof label, "%s, period 2", name);
    stable_points(label, m, o, &br);
    /* 10. the same branch by single shooting (one segment of two periods): the same bifurcations, and
     * about as many points (the arclength's state part is averaged over the segments) */
    gd_branch bs;
    co.po.multiple = 0;
    if (gd_continue(gd_model_at_mesh_frequency, (void *)m, o, &co, &p2, &bs, &e) != GD_OK)
        au_die(&e);
    double dp = same_bifurcations(&br, &bs, 0), ratio = (double)bs.npoints / br.npoints;
    printf("# single shooting: %d points, %d bifurcations, end: %s; tangent_p at the start %.6f (multiple %.6f)\n",
           bs.npoints, bs.nbif, bs.end_reason, bs.pt[0].tangent_p, br.pt[0].tangent_p);
    tap_ok(bs.end == GD_END_BOUND && dp >= 0 && dp < 1e-8 && ratio > 0.8 && ratio < 1.25,
           "%s, period 2 by single shooting: to the bound, the bifurcations of multiple shooting (max |dp| %.3g), "
           "%d points against %d", name, dp, bs.npoints, br.npoints);
    double tr = bs.pt[0].tangent_p / br.pt[0].tangent_p;
    tap_ok(fabs(tr - 1.0) < 0.2, "%s, period 2: the parameter part of the unit tangent at the start, single over "
           "multiple shooting, %.4f (within 20 %% of 1: a step of the arclength moves p alike)", name, tr);
    gd_branch_free(&bs);
    gd_branch_free(&br);
}

/* 6. A brute-force sweep up and down (Omega 0.55 .. 0.80 by 0.005, each point 400 periods from the
 * state the previous one ended in): the grid interval where the settled Poincare point jumps (by
 * more than 0.05) contains the fold that ends the branch being followed: the upper fold going up,
 * the lower fold going down. */
static void sweep_jumps(const char *name, const gd_case *c, const gd_model *m, const gd_solver_opts *o,
                        double fold_hi, double fold_lo)
{
    gd_error e = {0};
    for (int dir = 1; dir >= -1; dir -= 2) {
        double y[GD_MAX_STATE], prev[GD_MAX_STATE], jump_lo = NAN, jump_hi = NAN;
        gd_modes md;
        int jumps = 0;
        if (gd_initial_state(c, m, y, &md, &e) != GD_OK)
            au_die(&e);
        for (int k = 0; k <= 50; k++) {
            double Om = dir > 0 ? 0.55 + 0.005 * k : 0.80 - 0.005 * k;
            gd_model mq;
            if (gd_model_at_mesh_frequency(Om, &mq, (void *)m, &e) != GD_OK ||
                gd_sim_period_map(&mq, o, y, 400, y, NULL, NULL, &e) != GD_OK)
                au_die(&e);
            if (k > 0 && dist(y, prev, m->n) > 0.05) {
                jumps++;
                jump_lo = Om - 0.005 * dir;
                jump_hi = Om;
            }
            memcpy(prev, y, sizeof prev);
        }
        double fold = dir > 0 ? fold_hi : fold_lo;
        tap_ok(jumps == 1 && (fold - jump_lo) * (fold - jump_hi) < 0,
               "%s: the sweep %s jumps once (%d), between Omega %.3f and %.3f, around the fold at %.6f", name,
               dir > 0 ? "up" : "down", jumps, jump_lo, jump_hi, fold);
    }
}

/* check 9: a bifurcation in the last step before a bound is located as anywhere else: the branch from
 * 0.5 up to a bound 1e-6 beyond the bifurcation b (a step of the branch is of order 1e-2, so the
 * bifurcation lies in the step that crosses the bound) has it, at its place to 1e-8 */
static void bound_step(const char *name, const gd_case *c, const gd_model *m, const gd_solver_opts *o,
                       const gd_bifurcation *b)
{
    gd_error e = {0};
    double y[GD_MAX_STATE];
    gd_modes md;
    if (gd_initial_state(c, m, y, &md, &e) != GD_OK || gd_sim_period_map(m, o, y, 300, y, NULL, NULL, &e) != GD_OK)
        au_die(&e);
    gd_cont_opts co;
    gd_cont_opts_default(&co);
    co.p_min = 0.5;
    co.p_max = b->p + 1e-6;
    co.ds_max = 0.05;
    gd_po start;
    gd_branch br;
    if (gd_po_solve(m, o, &co.po, y, &start, &e) != GD_OK ||
        gd_continue(gd_model_at_mesh_frequency, (void *)m, o, &co, &start, &br, &e) != GD_OK)
        au_die(&e);
    const gd_bifurcation *f = NULL;
    for (int i = 0; i < br.nbif; i++)
        if (br.bif[i].kind == b->kind && fabs(br.bif[i].p - b->p) < 1e-8)
            f = &br.bif[i];
    double last_inside = br.npoints > 1 ? br.pt[br.npoints - 2].orbit.p : NAN;
    tap_ok(br.end == GD_END_BOUND && f != NULL && last_inside < b->p,
           "%s: the %s at %.10f, in the step from the last point inside (%.6f) to the bound %.6f, is located (%s)",
           name, gd_bif_kind_name(b->kind), b->p, last_inside, co.p_max, f ? "found" : "missing");
    gd_branch_free(&br);
}

/* check 12: branch switching accepts only the orbit born at the doubling. Given a period doubling
 * that is not one (the period-1 orbit of alpha 0 at Omega 1.3, past the real doubling at 1.2267, where
 * the stable period-2 orbit born there coexists 0.07 away), gd_po_period_doubled finds no orbit born
 * there: the period-2 orbit it reaches keeps its amplitude when the distance to the "doubling" is
 * quartered. At the real doubling it finds the one born there. */
static void switching_check(const gd_model *m, const gd_solver_opts *o, const gd_branch *up, const gd_bifurcation *pd)
{
    gd_error e = {0};
    const gd_po *q = NULL;
    for (int i = 0; i < up->npoints; i++)
        if (up->pt[i].orbit.p > 1.25 && (!q || fabs(up->pt[i].orbit.p - 1.3) < fabs(q->p - 1.3)))
            q = &up->pt[i].orbit;
    gd_model mq;
    gd_po_opts po;
    gd_po_opts_default(&po);
    gd_po at, p2;
    if (gd_model_at_mesh_frequency(1.3, &mq, (void *)m, &e) != GD_OK || gd_po_solve(&mq, o, &po, q->y[0], &at, &e) != GD_OK)
        au_die(&e);
    gd_bifurcation fake = *pd;
    fake.p = 1.3;
    memcpy(fake.y, at.y[0], sizeof fake.y);
    gd_status st = gd_po_period_doubled(gd_model_at_mesh_frequency, (void *)m, o, &po, &fake, 0.01, 0.05, &p2, &e);
    printf("# switching at a period doubling that is none (Omega 1.3, |mu| %.4f): %s\n", at.mu_max,
           st == GD_OK ? "an orbit accepted" : e.msg);
    tap_ok(st == GD_ERR_SOLVER, "branch switching at Omega 1.3 on the period-1 orbit, no doubling there: no orbit of "
           "twice the period accepted (%s)", st == GD_OK ? "one accepted" : "refused");
    gd_error_clear(&e);
    st = gd_po_period_doubled(gd_model_at_mesh_frequency, (void *)m, o, &po, pd, 0.01, 0.05, &p2, &e);
    tap_ok(st == GD_OK && p2.nper == 2, "branch switching at the real doubling at %.6f: the period-2 orbit born there "
           "(%s)", pd->p, st == GD_OK ? "found" : e.msg);
}

static void ks(double alpha, const char *name, int expect_pd, double grazing)
{
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    const char *sets[] = {"excitation.ste_phase_deg=90", "solver.rtol=1e-10", "solver.atol=1e-12", NULL};
    au_ks_case(&c, &m, alpha, 0.05, 0.1, 0.1, 0.5, sets);
    gd_solver_opts_from_case(&c, &o);
    gd_branch up;
    branch(&c, &m, &o, 1, 0.0, 0.0, &up);
    /* 1. the bifurcations in order */
    const gd_bifurcation *fold[4], *pd[4], *cc[4];
    int nf = of_kind(&up, GD_BIF_FOLD, fold, 4), npd = of_kind(&up, GD_BIF_PERIOD_DOUBLING, pd, 4);
    int ncc = of_kind(&up, GD_BIF_CONTACT_CHANGE, cc, 4);
    tap_ok(up.end == GD_END_BOUND && fabs(up.pt[up.npoints - 1].orbit.p - 1.5) < 1e-12 && nf == 2 &&
               npd == expect_pd && ncc == 1 && cc[0] == &up.bif[0] && fold[0] == &up.bif[1] &&
               fold[0]->p > cc[0]->p && fold[1]->p < cc[0]->p,
           "%s: from 0.5 to the bound 1.5 (%s): grazing of the mesh, fold above it, fold below it%s (%d "
           "bifurcations)", name, up.end_reason, expect_pd ? ", period doubling" : "", up.nbif);
    double bw = 0;
    int corr = 0;
    for (int i = 0; i < up.nbif; i++) {
        bw = fmax(bw, fabs(up.bif[i].p_hi - up.bif[i].p_lo));
        corr = up.bif[i].corrections > corr ? up.bif[i].corrections : corr;
    }
    TAP_CLOSE(bw, 0.0, 1e-7, "largest parameter bracket of a located bifurcation");
    tap_ok(corr > 0 && corr <= 12, "%s: at most 12 corrected points per bifurcation located (%d)", name, corr);
    if (grazing > 0 && ncc == 1)
        TAP_CLOSE(cc[0]->p, grazing, 1e-9, "the grazing of the non-impacting orbit at Omega = 1/sqrt(1.99)");
    /* 2. both directions from the attractor at Omega 1 */
    gd_case c1;
    gd_model m1;
    au_ks_case(&c1, &m1, alpha, 0.05, 0.1, 0.1, 1.0, sets);
    gd_branch down, up1;
    branch(&c1, &m1, &o, -1, 0.0, 0.0, &down);
    branch(&c1, &m1, &o, 1, 0.0, 0.0, &up1);
    /* the branch from 0.5 up is the one from 1 down, reversed, then the one from 1 up */
    gd_branch joined = down;
    joined.nbif = 0;
    gd_bifurcation all[16];
    joined.bif = all;
    for (int i = down.nbif - 1; i >= 0 && joined.nbif < 16; i--)
        all[joined.nbif++] = down.bif[i];
    for (int i = 0; i < up1.nbif && joined.nbif < 16; i++)
        all[joined.nbif++] = up1.bif[i];
    double dp = same_bifurcations(&up, &joined, 0);
    tap_ok(dp >= 0 && dp < 1e-8, "%s: from Omega 1 down (%s) and up (%s): the same bifurcations (max |dp| %.3g)",
           name, down.end_reason, up1.end_reason, dp);
    /* 3. and 4. */
    stable_points(name, &m, &o, &up);
    if (nf == 2) {
        both_sides(name, &m, &o, &up, fold[0], -1); /* the upper fold: the branch is stable below it */
        both_sides(name, &m, &o, &up, fold[1], +1); /* the lower fold: the impacting branch is stable above */
        sweep_jumps(name, &c, &m, &o, fold[0]->p, fold[1]->p);
    }
    if (expect_pd && npd == 1) {
        both_sides(name, &m, &o, &up, pd[0], -1);
        period_two(name, &m, &o, pd[0]);
        bound_step(name, &c, &m, &o, pd[0]);
        switching_check(&m, &o, &up, pd[0]);
    }
    if (ncc == 1)
        bound_step(name, &c, &m, &o, cc[0]);
    gd_branch_free(&up);
    gd_branch_free(&up1);
    gd_branch_free(&down);
    gd_case_free(&c);
    gd_case_free(&c1);
}

/* check 11: the event-count fallback of a contact change (gd_cont_opts.contact_by_events), on the
 * grazing of alpha 0: bisected to where the event detection first sees the contact, reported as such
 * (location event-count), within 1e-6 of the grazing on the extremum's distance and on the side where
 * the orbit penetrates */
static void events_fallback(void)
{
    const char *sets[] = {"excitation.ste_phase_deg=90", "solver.rtol=1e-10", "solver.atol=1e-12", NULL};
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    gd_error e = {0};
    au_ks_case(&c, &m, 0.0, 0.05, 0.1, 0.1, 0.5, sets);
    gd_solver_opts_from_case(&c, &o);
    double y[GD_MAX_STATE], graze = 1.0 / sqrt(1.99);
    gd_modes md;
    if (gd_initial_state(&c, &m, y, &md, &e) != GD_OK || gd_sim_period_map(&m, &o, y, 300, y, NULL, NULL, &e) != GD_OK)
        au_die(&e);
    gd_cont_opts co;
    gd_cont_opts_default(&co);
    co.p_min = 0.5;
    co.p_max = 0.72;
    co.ds_max = 0.05;
    co.contact_by_events = 1;
    gd_po start;
    gd_branch br;
    if (gd_po_solve(&m, &o, &co.po, y, &start, &e) != GD_OK ||
        gd_continue(gd_model_at_mesh_frequency, (void *)&m, &o, &co, &start, &br, &e) != GD_OK)
        au_die(&e);
    const gd_bifurcation *b = br.nbif == 1 ? &br.bif[0] : NULL;
    printf("# contact change by the event count: %d bifurcations; at Omega %.10f (bracket %.10f .. %.10f), %s, %d "
           "corrections\n", br.nbif, b ? b->p : NAN, b ? b->p_lo : NAN, b ? b->p_hi : NAN,
           b ? gd_bif_location_name(b->location) : "-", b ? b->corrections : 0);
    tap_ok(b && b->kind == GD_BIF_CONTACT_CHANGE && b->location == GD_LOC_EVENTS && b->p >= graze &&
               b->p - graze < 1e-6,
           "the grazing by bisection of the event count: at %.10f, %.3g above 1/sqrt(1.99), reported as %s", b ? b->p : NAN,
           b ? b->p - graze : NAN, b ? gd_bif_location_name(b->location) : "-");
    gd_branch_free(&br);
    gd_case_free(&c);
}

/* check 7: the located values against the integration tolerance */
static void tolerances(void)
{
    const double rtol[] = {1e-6, 1e-8, 1e-10, 1e-12}, graze = 1.0 / sqrt(1.99);
    double ref[4] = {0}, got[4][4];
    int nb[4];
    for (int k = 3; k >= 0; k--) {
        char r[64], a[64];
        snprintf(r, sizeof r, "solver.rtol=%g", rtol[k]);
        snprintf(a, sizeof a, "solver.atol=%g", rtol[k] / 100);
        const char *sets[] = {"excitation.ste_phase_deg=90", r, a, NULL};
        gd_case c;
        gd_model m;
        gd_solver_opts o;
        au_ks_case(&c, &m, 0.0, 0.05, 0.1, 0.1, 0.5, sets);
        gd_solver_opts_from_case(&c, &o);
        gd_branch br;
        branch(&c, &m, &o, 1, fmax(1e-9, 0.1 * rtol[k]), 1e-8, &br);
        nb[k] = br.nbif;
        for (int i = 0; i < 4; i++)
            got[k][i] = i < br.nbif ? br.bif[i].p : NAN;
        if (k == 3)
            memcpy(ref, got[3], sizeof ref);
        printf("# rtol %-6g: grazing %.10f, folds %.10f %.10f, period doubling %.10f\n", rtol[k], got[k][0],
               got[k][1], got[k][2], got[k][3]);
        gd_branch_free(&br);
        gd_case_free(&c);
    }
    double dg = 0, df = 0, dpd = 0, dg6 = fabs(got[0][0] - graze);
    int n_ok = 1;
    for (int k = 0; k < 4; k++) {
        n_ok &= nb[k] == 4;
        if (k > 0) /* from rtol 1e-8 on; at 1e-6, dg6 */
            dg = fmax(dg, fabs(got[k][0] - graze));
        df = fmax(df, fmax(fabs(got[k][1] - ref[1]), fabs(got[k][2] - ref[2])));
        dpd = fmax(dpd, fabs(got[k][3] - ref[3]));
    }
    tap_ok(n_ok && dg < 1e-9 && dg6 < 1e-8 && df < 1e-8 && dpd < 5e-8, "K&S alpha 0 at rtol 1e-6 to 1e-12: 4 "
           "bifurcations each; the grazing within %.2g of 1/sqrt(1.99) from rtol 1e-8 on (%.2g at 1e-6), the folds "
           "within %.2g and the period doubling within %.2g of rtol 1e-12's", dg, dg6, df, dpd);
}

/* check 8: the gap watch's extrema against the closed-form linear orbit */
static void gap_extrema(void)
{
    const double Om = 0.6, zeta = 0.05, Fm = 0.1, Fa = 0.1;
    const char *sets[] = {"excitation.ste_phase_deg=90", "solver.rtol=1e-10", "solver.atol=1e-12", NULL};
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    gd_error e = {0};
    au_ks_case(&c, &m, 0.0, zeta, Fm, Fa, Om, sets);
    gd_solver_opts_from_case(&c, &o);
    double y[GD_MAX_STATE];
    gd_modes md;
    gd_po_opts po;
    gd_po_opts_default(&po);
    gd_po orbit;
    gd_gap_extrema g;
    if (gd_initial_state(&c, &m, y, &md, &e) != GD_OK || gd_sim_period_map(&m, &o, y, 300, y, NULL, NULL, &e) != GD_OK ||
        gd_po_solve(&m, &o, &po, y, &orbit, &e) != GD_OK || gd_sim_orbit_gaps(&m, &o, orbit.y[0], 1, &g, &e) != GD_OK)
        au_die(&e);
    double A = Fa * Om * Om / hypot(1.0 - Om * Om, 2.0 * zeta * Om), xmax = NAN, xmin = NAN, tmax = 0, tmin = 0;
    for (int i = 0; i < g.n[0]; i++) {
        if (g.kind[0][i] > 0)
            xmax = g.x[0][i], tmax = g.t[0][i];
        else
            xmin = g.x[0][i], tmin = g.t[0][i];
    }
    double dt = fabs(fabs(tmax - tmin) - 0.5 * m.period);
    printf("# gap extrema at Omega 0.6: %d, max %.12f, min %.12f, h %.3g; closed form %.12f, %.12f\n", g.n[0], xmax,
           xmin, g.h[0], 1.0 + Fm + A, 1.0 + Fm - A);
    tap_ok(g.n[0] == 2 && g.dropped == 0 && fabs(xmax - (1.0 + Fm + A)) < 1e-9 && fabs(xmin - (1.0 + Fm - A)) < 1e-9 &&
               dt < 1e-6 * m.period && fabs(g.h[0] - 1.0) < 1e-12,
           "gap watch on the linear orbit at Omega 0.6: %d extrema, max and min to %.2g and %.2g of 1 + F_m +- A, "
           "half a period apart to %.2g periods", g.n[0], fabs(xmax - (1.0 + Fm + A)), fabs(xmin - (1.0 + Fm - A)),
           dt / m.period);
    gd_case_free(&c);
}

/* check 8b: a pair of extrema inside one integration step. Alpha 0.2 with a third stiffness harmonic
 * (stiffness_harmonics 0.05, 0.05, 0.3), backlash 200 um (no contact), Omega 0.2: the mesh coordinate
 * has 8 extrema per period, two of them 0.041 periods apart. Integrated with 12 fixed steps per
 * period (a step of 0.083 periods holds that pair, and the rate has the same sign at both its ends),
 * the gap watch finds the 8 extrema of an adaptive run at rtol 1e-10, to 1e-3 in phase and 1e-4 in
 * the coordinate. */
static void gap_pair(void)
{
    const char *sets[] = {"excitation.stiffness_harmonics=0.05,0.05,0.3", "solver.rtol=1e-10", "solver.atol=1e-12",
                          "clearance.backlash_um=200", NULL};
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    gd_error e = {0};
    au_ks_case(&c, &m, 0.2, 0.05, 0.1, 0.1, 0.2, sets);
    gd_solver_opts_from_case(&c, &o);
    double y[GD_MAX_STATE];
    gd_modes md;
    if (gd_initial_state(&c, &m, y, &md, &e) != GD_OK || gd_sim_period_map(&m, &o, y, 300, y, NULL, NULL, &e) != GD_OK)
        au_die(&e);
    gd_gap_extrema fine, coarse;
    gd_solver_opts oc = o;
    oc.fixed_step = 1;
    oc.steps_per_period = 12;
    if (gd_sim_orbit_gaps(&m, &o, y, 1, &fine, &e) != GD_OK || gd_sim_orbit_gaps(&m, &oc, y, 1, &coarse, &e) != GD_OK)
        au_die(&e);
    double dt = 0, dx = 0, closest = INFINITY;
    for (int i = 0; i < fine.n[0]; i++) {
        if (i > 0)
            closest = fmin(closest, (fine.t[0][i] - fine.t[0][i - 1]) / m.period);
        if (i < coarse.n[0] && coarse.kind[0][i] == fine.kind[0][i]) {
            dt = fmax(dt, fabs(coarse.t[0][i] - fine.t[0][i]) / m.period);
            dx = fmax(dx, fabs(coarse.x[0][i] - fine.x[0][i]));
        } else {
            dt = dx = INFINITY;
        }
    }
    printf("# extrema at Omega 0.2: %d (adaptive), %d (12 fixed steps), the closest two %.4f periods apart\n",
           fine.n[0], coarse.n[0], closest);
    tap_ok(fine.n[0] == 8 && coarse.n[0] == 8 && closest < 1.0 / 12 && dt < 1e-3 && dx < 1e-4,
           "gap watch with 12 steps per period: the %d extrema of the adaptive run (%d found), a pair %.3f periods "
           "apart among them, to %.2g periods and %.2g", fine.n[0], coarse.n[0], closest, dt, dx);
    gd_case_free(&c);
}

int main(void)
{
    ks(0.0, "K&S alpha 0", 1, 1.0 / sqrt(1.99));
    ks(0.2, "K&S alpha 0.2", 0, 0.0);
    tolerances();
    gap_extrema();
    gap_pair();
    events_fallback();
    return tap_done();
}
