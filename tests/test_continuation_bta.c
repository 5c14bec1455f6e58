/* Continuation of the paper's bta model in the speed (cases/paper/sweep-speed.ini: LTCA stiffness,
 * mesh-in impact, bearings with clearance; gd_model_at_case_key on operating.speed_rpm, the model
 * built again at every speed), the period-1 orbit from 3000 rpm up to 5500 rpm.
 *
 * 1. The branch reaches the bound, 5500 rpm, every point converged (the residual below the
 *    shooting tolerance 1e-8), and no step changed the speed by more than dp_max (50 rpm).
 * 2. Stable points (every third, at most eight) against plain simulation: from the Poincare point
 *    moved by 1e-4 in every component, integrated until |mu_max|^N < 1e-9, the state at mesh phase
 *    0 agrees with the branch point to 1e-6.
 * 3. Every bifurcation located lies between the two branch points that bracket it, its kind's test
 *    function having changed sign there; a period doubling has its multiplier within 1e-4 of -1;
 *    each took at most 12 corrected points (Brent's method on a continuous test function, the
 *    contact changes too: a bisection to locate_tol 1e-6 from steps of up to 20 would take 20 or
 *    more). */
#include "analysis_util.h"
#include "tap.h"
#include "geardyn/gd_periodic.h"
#include "geardyn/gd_scene.h"

#include <string.h>

int main(void)
{
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    gd_error e = {0};
    const char *src = getenv("GEARDYN_SOURCE");
    char path[2048];
    snprintf(path, sizeof path, "%s/cases/paper/sweep-speed.ini", src ? src : ".");
    if (gd_case_init(&c, &e) != GD_OK || gd_case_load(&c, path, &e) != GD_OK ||
        gd_case_set_number(&c, "operating.speed_rpm", 3000.0, &e) != GD_OK || gd_case_resolve(&c, &e) != GD_OK ||
        gd_model_build(&c, &m, &e) != GD_OK)
        au_die(&e);
    gd_solver_opts_from_case(&c, &o);
    gd_case_param cp = {&c, "operating.speed_rpm", 3000.0 / m.Omega};
    double y[GD_MAX_STATE];
    gd_modes md;
    if (gd_initial_state(&c, &m, y, &md, &e) != GD_OK || gd_sim_period_map(&m, &o, y, 500, y, NULL, NULL, &e) != GD_OK)
        au_die(&e);
    gd_cont_opts co;
    gd_cont_opts_default(&co);
    co.po.tol = 1e-8;
    co.ds = 1.0;
    co.ds_max = 20.0; /* the states change far faster with Omega than Omega itself (section 6 of the doc) */
    co.locate_tol = 1e-6;
    co.dp_max = 50.0 / cp.scale; /* 50 rpm */
    co.p_min = 3000.0 / cp.scale;
    co.p_max = 5500.0 / cp.scale;
    gd_po start;
    gd_branch br;
    if (gd_po_solve(&m, &o, &co.po, y, &start, &e) != GD_OK ||
        gd_continue(gd_model_at_case_key, &cp, &o, &co, &start, &br, &e) != GD_OK)
        au_die(&e);
    printf("# %d points, %ld corrections, %ld Newton iterations (%.2f per correction), %ld chord iterations, end: %s\n",
           br.npoints, br.corrections, br.newton_iterations, (double)br.newton_iterations / (double)br.corrections,
           br.chord_iterations, br.end_reason);
    double rmax = 0, dpmax = 0;
    for (int i = 0; i < br.npoints; i++) {
        const gd_po *q = &br.pt[i].orbit;
        rmax = fmax(rmax, q->residual);
        if (i > 0)
            dpmax = fmax(dpmax, fabs(q->p - br.pt[i - 1].orbit.p) * cp.scale);
        printf("#   %8.2f rpm  |mu| %.5f %s  Newton %d  events/clearance %ld %ld %ld %ld %ld %ld\n", q->p * cp.scale,
               q->mu_max, q->stable ? "stable  " : "unstable", q->iterations, q->events[0], q->events[1],
               q->events[2], q->events[3], q->events[4], q->events[5]);
    }
    for (int i = 0; i < br.nbif; i++)
        printf("#   %s%s%s at %.4f rpm (bracket %.4f .. %.4f), multiplier %.6f%+.6fi, %d corrections\n",
               gd_bif_kind_name(br.bif[i].kind), br.bif[i].clearance >= 0 ? " of " : "",
               br.bif[i].clearance >= 0 ? m.clear[br.bif[i].clearance].name : "", br.bif[i].p * cp.scale,
               br.bif[i].p_lo * cp.scale, br.bif[i].p_hi * cp.scale, br.bif[i].mu_re, br.bif[i].mu_im,
               br.bif[i].corrections);
    double last = br.pt[br.npoints - 1].orbit.p * cp.scale;
    tap_ok(br.end == GD_END_BOUND && fabs(last - 5500.0) < 1e-6 && rmax < co.po.tol,
           "from 3000 rpm to the bound 5500 rpm (last point %.6f rpm, %s), largest residual %.3g", last,
           br.end_reason, rmax);
    tap_ok(dpmax < 50.0 * (1.0 + 1e-6), "no step longer than dp_max, 50 rpm (longest %.4f rpm)", dpmax);

    /* 2. stable points against simulation */
    double dmax = 0;
    int count = 0, seen = 0;
    for (int i = 0; i < br.npoints && count < 8; i++) {
        const gd_po *q = &br.pt[i].orbit;
        if (!(q->mu_max < 0.99) || seen++ % 3)
            continue;
        gd_model mq;
        double ys[GD_MAX_STATE];
        if (gd_model_at_case_key(q->p, &mq, &cp, &e) != GD_OK)
            au_die(&e);
        for (int j = 0; j < m.n; j++)
            ys[j] = q->y[0][j] + 1e-4;
        int N = (int)ceil(log(1e-9) / log(q->mu_max));
        if (gd_sim_period_map(&mq, &o, ys, N, ys, NULL, NULL, &e) != GD_OK)
            au_die(&e);
        double d = 0;
        for (int j = 0; j < m.n; j++)
            d = fmax(d, fabs(ys[j] - q->y[0][j]));
        printf("#   %8.2f rpm: %d periods of simulation, |y - y_sim| %.3g\n", q->p * cp.scale, N, d);
        dmax = fmax(dmax, d);
        count++;
    }
    char label[160];
    snprintf(label, sizeof label, "%d stable points against settled simulation, max |y - y_sim|", count);
    tap_ok(count >= 4, "at least 4 stable points checked (%d)", count);
    TAP_CLOSE(dmax, 0.0, 1e-6, label);

    /* 3. the bifurcations lie where their test functions changed sign */
    int bad = 0, corr = 0;
    for (int i = 0; i < br.nbif; i++) {
        const gd_bifurcation *b = &br.bif[i];
        corr = b->corrections > corr ? b->corrections : corr;
        const gd_po *a = &br.pt[b->after - 1].orbit, *z = &br.pt[b->after].orbit;
        int inside = (b->p - a->p) * (b->p - z->p) <= 0;
        int sign = 1;
        if (b->kind == GD_BIF_CONTACT_CHANGE)
            sign = a->events[b->clearance] != z->events[b->clearance];
        if (b->kind == GD_BIF_PERIOD_DOUBLING)
            sign = fabs(b->mu_re + 1.0) < 1e-4 && fabs(b->mu_im) < 1e-4;
        if (!inside || !sign)
            bad++;
    }
    tap_ok(br.nbif > 0 && bad == 0, "%d bifurcations, each between the branch points around it with its test "
           "function changed (%d not)", br.nbif, bad);
    tap_ok(corr > 0 && corr <= 12, "at most 12 corrected points per bifurcation located (%d)", corr);
    gd_branch_free(&br);
    gd_case_free(&c);
    return tap_done();
}
