/* 10^5 mesh periods (suite 'extremes', docs/accuracy.md): no drift of the Poincare points of a
 * periodic response. The torsional model at 4000 rpm (period-1, double-sided impacts, 4 located
 * events per period), default solver (ERK order 8, rtol 1e-8), integrated for 100 000 mesh
 * periods (4 x 10^5 events, 3000 time shifts of the integrator's clock). Checked: the Poincare
 * points of the last 1000 periods stay as close to the point after 10^3 periods as those of periods
 * 1000-2000 do, and their mean equals the mean of those (the orbit is attracting, so a drift would
 * come from the clock: the excitation phase Omega t and the root tolerance grow with |t| unless
 * the time is shifted; with adaptive steps each period's map differs by about rtol, which is the
 * noise, not a drift); the absolute time after N periods is N times the period to rounding;
 * every period has the same 4 events; and the fixed point agrees with one computed at rtol 1e-10. */
#include "extremes_util.h"
#include "geardyn/gd_analysis.h"
#include "geardyn/gd_scene.h"

/* Poincare points of two windows of 1000 periods, [1000, 2000) and the last 1000: their mean and
 * their largest distance from the point at 1000 (the noise of the adaptive step sequence). */
static double mean_early[GD_MAX_STATE], mean_late[GD_MAX_STATE], dev_early, dev_late;

static void fixed_point(double rtol, long periods, double *p1000, double *pend, long *events_last, double *t_end,
                        long *bad_periods, double *wall, const gd_model **mout)
{
    static gd_model m;
    gd_case c;
    gd_error e = {0};
    gd_case_init(&c, &e);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    gd_case_set(&c, "scene.model=torsional", 0, &e);
    gd_case_set_number(&c, "solver.rtol", rtol, &e);
    gd_case_set_number(&c, "solver.atol", rtol / 100, &e);
    if (gd_case_resolve(&c, &e) != GD_OK || gd_model_build(&c, &m, &e) != GD_OK) {
        printf("Bail out! %s\n", e.msg);
        exit(1);
    }
    double y[GD_MAX_STATE];
    gd_modes md;
    gd_initial_state(&c, &m, y, &md, &e);
    gd_solver_opts o;
    gd_solver_opts_from_case(&c, &o);
    gd_sim *s;
    if (gd_sim_create(&m, &o, y, &md, &s, &e) != GD_OK) {
        printf("Bail out! %s\n", e.msg);
        exit(1);
    }
    double t0 = ex_now();
    long prev = 0;
    *bad_periods = 0;
    for (long k = 1; k <= periods; k++) {
        if (gd_sim_period(s, &e) != GD_OK) {
            printf("Bail out! period %ld: %s\n", k, e.msg);
            exit(1);
        }
        if (k == 1000)
            memcpy(p1000, gd_sim_state(s), sizeof(double) * (size_t)m.n);
        if (k >= 1000 && (k < 2000 || k > periods - 1000)) {
            int early = k < 2000;
            const double *y1 = gd_sim_state(s);
            double d = gd_workprec_poincare_error(y1, p1000, 1, m.n);
            double *mean = early ? mean_early : mean_late;
            for (int i = 0; i < m.n; i++)
                mean[i] += y1[i] / 1000.0;
            if (early)
                dev_early = fmax(dev_early, d);
            else
                dev_late = fmax(dev_late, d);
        }
        if (k >= 1000) {
            gd_sim_stats st;
            gd_sim_get_stats(s, &st);
            if (k > 1000 && st.events - prev != 4)
                (*bad_periods)++;
            prev = st.events;
        }
    }
    *wall = ex_now() - t0;
    memcpy(pend, gd_sim_state(s), sizeof(double) * (size_t)m.n);
    gd_sim_stats st;
    gd_sim_get_stats(s, &st);
    *events_last = st.events;
    *t_end = gd_sim_time(s);
    gd_sim_free(s);
    gd_case_free(&c);
    *mout = &m;
}

int main(void)
{
    const long N = 100000;
    double a1000[GD_MAX_STATE], aend[GD_MAX_STATE], b1000[GD_MAX_STATE], bend[GD_MAX_STATE];
    long ev, evb, bad, badb;
    double tend, tendb, wall, wallb;
    const gd_model *m;
    fixed_point(1e-8, N, a1000, aend, &ev, &tend, &bad, &wall, &m);
    printf("# 1e5 periods at rtol 1e-8: %.2f s, %ld events, %.2f us per period\n", wall, ev, 1e6 * wall / (double)N);
    double d = gd_workprec_poincare_error(aend, a1000, 1, m->n);
    printf("# distance from the Poincare point at period 1000: largest %.3g over periods 1000-2000, %.3g over the last "
           "1000, %.3g at the end (the noise of the adaptive steps, about rtol)\n", dev_early, dev_late, d);
    tap_ok(dev_late <= 1e-7 && dev_early <= 1e-7,
           "no drift: every Poincare point of the last 1000 periods within %.3g of the one at period 1000 (tol 1e-7, "
           "10 rtol; periods 1000-2000: %.3g)", dev_late, dev_early);
    double dm = gd_workprec_poincare_error(mean_late, mean_early, 1, m->n);
    tap_ok(dm <= 1e-8, "no drift: mean Poincare point of the last 1000 periods against periods 1000-2000: %.3g "
           "(tol 1e-8)", dm);
    printf("# q = %.15g um, q' = %.15g (period 1000); %.15g, %.15g (period 100000)\n", a1000[0], a1000[1], aend[0],
           aend[1]);
    TAP_REL(tend, (double)N * m->period, 4e-16 * 64, "absolute time after 1e5 periods is 1e5 periods");
    tap_ok(bad == 0, "every one of the last %ld periods has exactly 4 events (%ld do not)", N - 1000, bad);
    tap_ok(ev >= 4 * (N - 1000) && ev <= 4 * N + 8, "events bounded: %ld in %ld periods", ev, N);
    fixed_point(1e-10, 2000, b1000, bend, &evb, &tendb, &badb, &wallb, &m);
    d = gd_workprec_poincare_error(a1000, b1000, 1, m->n);
    tap_ok(d <= 1e-6, "the fixed point agrees with rtol 1e-10: %.3g (tol 1e-6)", d);
    return tap_done();
}
