/* Continuation of the paper's bta model in the speed (cases/paper/sweep-speed.ini: LTCA stiffness,
 * mesh-in impact, bearings with clearance; gd_model_at_case_key on operating.speed_rpm, the model
 * built again at every speed), the period-1 orbit from 3000 rpm up to 5500 rpm with the default
 * steps and tolerances (gd_cont_opts_default: the arclength scaled by the state's size and the
 * range, dp_max a fiftieth of the range, 50 rpm; the tolerances derived from rtol 1e-8).
 *
 * 1. The branch reaches the bound, 5500 rpm, every point converged (the residual below the derived
 *    shooting tolerance), and no step changed the speed by more than 50 rpm.
 * 2. Stable points (every third, at most eight) against plain simulation: from the Poincare point
 *    moved by 1e-4 in every component, integrated until |mu_max|^N < 1e-9, the state at mesh phase
 *    0 agrees with the branch point to 1e-6.
 * 3. Every located bifurcation against an independent computation at a hundred times finer
 *    integration tolerance (rtol 1e-10), 0.5 rpm either side of it, by Newton shooting at the fixed
 *    speed from its state: a period doubling has a real multiplier that passes -1 between the two
 *    sides, a Neimark-Sacker point a complex pair (at the located angle, to 1e-2) whose modulus
 *    passes 1, a contact change an extremum of its clearance coordinate whose distance to a boundary
 *    changes sign and event counts that differ; the speed where the multiplier, the modulus or the
 *    distance reaches its critical value on the parabola through the two sides and the located speed
 *    itself (shot there too) lies within 1e-3 rpm of the located one.
 *    Every change of stability between two branch points is bracketed by a located period doubling
 *    or Neimark-Sacker point, and each location took at most 12 corrected points. */
#include "analysis_util.h"
#include "tap.h"
#include "geardyn/gd_periodic.h"
#include "geardyn/gd_scene.h"

#include <string.h>

/* the orbit of one period at p from y, with the fine options */
static void shoot(gd_case_param *cp, const gd_solver_opts *of, double p, const double *y, gd_po *orbit)
{
    gd_error e = {0};
    gd_model m;
    gd_po_opts po;
    gd_po_opts_default(&po);
    if (gd_model_at_case_key(p, &m, cp, &e) != GD_OK || gd_po_solve(&m, of, &po, y, orbit, &e) != GD_OK)
        au_die(&e);
}

/* the value of the bifurcation's kind on an orbit: PD 1 + mu for the real multiplier nearest -1; NS
 * |mu| - 1 for the complex multiplier nearest the angle th; contact change the signed distance of the
 * extremum of clearance clr nearest (kind, phase) to the boundary bnd (from gd_sim_orbit_gaps) */
static double value(const gd_bifurcation *b, const gd_po *q, gd_case_param *cp, const gd_solver_opts *of, int kind,
                    double phase, double bnd)
{
    gd_error e = {0};
    int best = -1;
    if (b->kind == GD_BIF_PERIOD_DOUBLING) {
        for (int i = 0; i < q->n; i++)
            if (q->mu_im[i] == 0 && (best < 0 || fabs(q->mu_re[i] + 1) < fabs(q->mu_re[best] + 1)))
                best = i;
        return 1.0 + q->mu_re[best];
    }
    if (b->kind == GD_BIF_NEIMARK_SACKER) {
        double th = atan2(b->mu_im, b->mu_re);
        for (int i = 0; i < q->n; i++)
            if (q->mu_im[i] > 0 && (best < 0 || fabs(atan2(q->mu_im[i], q->mu_re[i]) - th) <
                                                    fabs(atan2(q->mu_im[best], q->mu_re[best]) - th)))
                best = i;
        if (fabs(atan2(q->mu_im[best], q->mu_re[best]) - th) > 1e-2)
            return NAN;
        return hypot(q->mu_re[best], q->mu_im[best]) - 1.0;
    }
    gd_model m;
    gd_gap_extrema g;
    if (gd_model_at_case_key(q->p, &m, cp, &e) != GD_OK || gd_sim_orbit_gaps(&m, of, q->y[0], 1, &g, &e) != GD_OK)
        au_die(&e);
    double dbest = INFINITY;
    for (int i = 0; i < g.n[b->clearance]; i++) {
        double d = fabs(g.t[b->clearance][i] / m.period - phase);
        d = fmin(d - floor(d), 1.0 - (d - floor(d)));
        if (g.kind[b->clearance][i] == kind && d < dbest)
            best = i, dbest = d;
    }
    return best < 0 ? NAN : g.x[b->clearance][best] - bnd;
}

/* for a contact change: the extremum (kind, phase, boundary) of its clearance whose distance changes
 * sign between the orbits lo and hi; 0 when none */
static int crossing(const gd_bifurcation *b, const gd_po *lo, const gd_po *hi, gd_case_param *cp,
                    const gd_solver_opts *of, int *kind, double *phase, double *bnd)
{
    gd_error e = {0};
    gd_model m;
    gd_gap_extrema g;
    if (gd_model_at_case_key(lo->p, &m, cp, &e) != GD_OK || gd_sim_orbit_gaps(&m, of, lo->y[0], 1, &g, &e) != GD_OK)
        au_die(&e);
    const int c = b->clearance;
    for (int i = 0; i < g.n[c]; i++)
        for (int s = 0; s < 2; s++) {
            *kind = g.kind[c][i];
            *phase = g.t[c][i] / m.period;
            *bnd = s ? -g.h[c] : g.h[c];
            double a = g.x[c][i] - *bnd, z = value(b, hi, cp, of, *kind, *phase, *bnd);
            if (isfinite(z) && (a > 0) != (z > 0))
                return 1;
        }
    return 0;
}

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
    printf("# scales: state %.6g, parameter %.6g; shooting tolerance %.3g, locate_tol %.3g\n", br.y_scale, br.p_scale,
           br.tol, br.locate_tol);
    double rmax = 0, dpmax = 0;
    for (int i = 0; i < br.npoints; i++) {
        const gd_po *q = &br.pt[i].orbit;
        rmax = fmax(rmax, q->residual);
        if (i > 0)
            dpmax = fmax(dpmax, fabs(q->p - br.pt[i - 1].orbit.p) * cp.scale);
    }
    for (int i = 0; i < br.nbif; i++)
        printf("#   %s%s%s at %.6f rpm (bracket %.6f .. %.6f), multiplier %.6f%+.6fi, %d corrections, %s\n",
               gd_bif_kind_name(br.bif[i].kind), br.bif[i].clearance >= 0 ? " of " : "",
               br.bif[i].clearance >= 0 ? m.clear[br.bif[i].clearance].name : "", br.bif[i].p * cp.scale,
               br.bif[i].p_lo * cp.scale, br.bif[i].p_hi * cp.scale, br.bif[i].mu_re, br.bif[i].mu_im,
               br.bif[i].corrections, gd_bif_location_name(br.bif[i].location));
    double last = br.pt[br.npoints - 1].orbit.p * cp.scale;
    tap_ok(br.end == GD_END_BOUND && fabs(last - 5500.0) < 1e-6 && rmax < br.tol,
           "from 3000 rpm to the bound 5500 rpm (last point %.6f rpm, %s), largest residual %.3g (tolerance %.3g)",
           last, br.end_reason, rmax, br.tol);
    tap_ok(dpmax < 50.0 * (1.0 + 1e-6), "no step longer than a fiftieth of the range, 50 rpm (longest %.4f rpm)",
           dpmax);

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
        dmax = fmax(dmax, d);
        count++;
    }
    char label[160];
    snprintf(label, sizeof label, "%d stable points against settled simulation, max |y - y_sim|", count);
    tap_ok(count >= 4, "at least 4 stable points checked (%d)", count);
    TAP_CLOSE(dmax, 0.0, 1e-6, label);

    /* 3. each bifurcation against shooting at fixed speeds either side, at rtol 1e-10 */
    gd_solver_opts of = o;
    of.rtol = 1e-10;
    of.atol = 1e-12;
    const double delta = 0.5 / cp.scale;
    int bad = 0, corr = 0, checked[5] = {0};
    double worst = 0;
    for (int i = 0; i < br.nbif; i++) {
        const gd_bifurcation *b = &br.bif[i];
        corr = b->corrections > corr ? b->corrections : corr;
        if (b->kind != GD_BIF_PERIOD_DOUBLING && b->kind != GD_BIF_NEIMARK_SACKER && b->kind != GD_BIF_CONTACT_CHANGE)
            continue;
        gd_po lo, mid, hi;
        shoot(&cp, &of, b->p - delta, b->y, &lo);
        shoot(&cp, &of, b->p, b->y, &mid);
        shoot(&cp, &of, b->p + delta, b->y, &hi);
        int kind = 0, events_differ = 1;
        double phase = 0, bnd = 0;
        if (b->kind == GD_BIF_CONTACT_CHANGE) {
            events_differ = lo.events[b->clearance] != hi.events[b->clearance];
            if (!crossing(b, &lo, &hi, &cp, &of, &kind, &phase, &bnd))
                phase = NAN;
        }
        double fl = value(b, &lo, &cp, &of, kind, phase, bnd), fh = value(b, &hi, &cp, &of, kind, phase, bnd);
        double fc = value(b, &mid, &cp, &of, kind, phase, bnd);
        /* the zero of the parabola through the three, nearest the middle (Newton from its secant's) */
        double c1 = (fh - fl) / (2.0 * delta), c2 = (fh - 2.0 * fc + fl) / (2.0 * delta * delta), x = -fc / c1;
        for (int it = 0; it < 20; it++)
            x -= (fc + c1 * x + c2 * x * x) / (c1 + 2.0 * c2 * x);
        double ps = (b->p + x) * cp.scale, d = fabs(ps - b->p * cp.scale);
        int ok = isfinite(fl) && isfinite(fh) && isfinite(fc) && (fl > 0) != (fh > 0) && d < 1e-3 && events_differ;
        printf("#   %s at %.6f rpm: at +-0.5 rpm and rtol 1e-10 %.4g and %.4g, zero at %.6f rpm (%.2g from it)%s\n",
               gd_bif_kind_name(b->kind), b->p * cp.scale, fl, fh, ps, d,
               events_differ ? "" : ", the event counts equal");
        bad += !ok;
        worst = isfinite(d) ? fmax(worst, d) : INFINITY;
        checked[b->kind]++;
    }
    tap_ok(checked[GD_BIF_PERIOD_DOUBLING] == 2 && checked[GD_BIF_NEIMARK_SACKER] == 9 &&
               checked[GD_BIF_CONTACT_CHANGE] == 8 && bad == 0,
           "%d period doublings, %d Neimark-Sacker points and %d contact changes, each confirmed by shooting at fixed "
           "speeds either side at rtol 1e-10 (%d not; the farthest %.3g rpm from the located speed)",
           checked[GD_BIF_PERIOD_DOUBLING], checked[GD_BIF_NEIMARK_SACKER], checked[GD_BIF_CONTACT_CHANGE], bad, worst);
    int unbracketed = 0;
    for (int i = 1; i < br.npoints; i++) {
        if (br.pt[i].orbit.stable == br.pt[i - 1].orbit.stable)
            continue;
        int found = 0;
        for (int k = 0; k < br.nbif; k++)
            found |= br.bif[k].after == i &&
                     (br.bif[k].kind == GD_BIF_PERIOD_DOUBLING || br.bif[k].kind == GD_BIF_NEIMARK_SACKER);
        unbracketed += !found;
    }
    tap_ok(unbracketed == 0, "every change of stability between two points holds a located period doubling or "
           "Neimark-Sacker point (%d do not)", unbracketed);
    tap_ok(corr > 0 && corr <= 12, "at most 12 corrected points per bifurcation located (%d)", corr);
    gd_branch_free(&br);
    gd_case_free(&c);
    return tap_done();
}
