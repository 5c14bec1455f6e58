/* The work-precision analysis itself (gd_workprec.h, docs/accuracy.md).
 *
 * 1. A small grid on the torsional model with impacts (4000 rpm, double-sided): every run of
 *    the grid is there, finished, with finite errors; the reference has converged (its check
 *    by an independent method differs by less than workprecision.reference_max_error); the
 *    errors fall as the steps shrink or the tolerance tightens; the cheapest setting for a
 *    target meets it.
 * 2. The measured convergence order of classical RK4 on a smooth case (permanent contact, no
 *    event at all) is 4 within 0.3, with root finding on and off alike.
 * 3. Event location restores the order on an impacting case: RK4 at fixed steps measures
 *    order 4 (within 0.4) with root finding on and less than 3 with it off (the steps then
 *    straddle the kinks of the dead zone: about 2); the same for the 5th-order table.
 * 4. The Poincare error metric on known input.
 * 5. The linear stability of a fixed step (gd_sim_step_stability): on the undamped oscillator
 *    y'' = -w^2 y its amplification is the closed form |R(i h w)| of RK4 (1 - x^2/2 + x^4/24 +
 *    i (x - x^3/6)) and of a two-stage second-order table (1 + i x - x^2/2), RK4 turns unstable at
 *    h w = 2 sqrt 2 and the fewest stable steps are ceil(w T / 2 sqrt 2); on the paper's pair (bta,
 *    2000 rpm) the fewest stable RK4 steps agree with the undamped modal analysis's highest
 *    frequency (GSL's symmetric eigensolver, an independent computation) and its 2 sqrt 2 bound,
 *    and a work-precision grid there reports RK4 at 32 steps per period (blown up to an RMS of
 *    1e7 m/s^2) as unstable and 64 as ok. */
#include "geardyn/geardyn.h"
#include "tap.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static void set_all(gd_case *c, const char *const *sets)
{
    gd_error e = {0};
    for (int i = 0; sets[i]; i++)
        if (gd_case_set(c, sets[i], i, &e) != GD_OK) {
            printf("Bail out! %s: %s\n", sets[i], e.msg);
            exit(1);
        }
}

/* y'' = -w^2 y as y = (x, v) */
static const double W_OSC = 3.0;
static void osc_rhs(double t, const double *y, double *yd, void *ctx)
{
    (void)t, (void)ctx;
    yd[0] = y[1];
    yd[1] = -W_OSC * W_OSC * y[0];
}
static void osc_tangent(double t, const double *y, const double *v, double *out, void *ctx)
{
    (void)y;
    osc_rhs(t, v, out, ctx);
}
static void osc_jacobian(double t, const double *y, double *J, void *ctx)
{
    (void)t, (void)y, (void)ctx;
    J[0] = 0, J[1] = 1, J[2] = -W_OSC * W_OSC, J[3] = 0;
}

static void step_stability_tests(void)
{
    gd_custom_system sys = {2, osc_rhs, osc_tangent, osc_jacobian, NULL};
    gd_model m;
    memset(&m, 0, sizeof m);
    gd_model_custom(&m, &sys, 2.0 * M_PI);
    double y[2] = {1, 0};
    gd_modes md;
    memset(&md, 0, sizeof md);
    gd_solver_opts o = gd_solver_opts_defaults();
    gd_error e = {0};
    double worst_rk4 = 0, worst_erk2 = 0;
    int flag_ok = 1;
    for (int N = 3; N <= 40; N++) {
        double x = W_OSC * m.period / N;
        gd_step_stability sb;
        o.method = GD_METHOD_RK4;
        o.steps_per_period = N;
        if (gd_sim_step_stability(&m, &o, y, &md, &sb, &e) != GD_OK) {
            tap_ok(0, "step stability: %s", e.msg);
            return;
        }
        double complex r4 = 1 - x * x / 2 + x * x * x * x / 24 + I * (x - x * x * x / 6);
        worst_rk4 = fmax(worst_rk4, fabs(sb.amplification - cabs(r4)));
        flag_ok &= sb.unstable == (x > 2.0 * M_SQRT2);
        o.method = GD_METHOD_ERK;
        o.order = 2;
        o.table[0] = '\0';
        o.fixed_step = 1;
        if (gd_sim_step_stability(&m, &o, y, &md, &sb, &e) != GD_OK) {
            tap_ok(0, "step stability: %s", e.msg);
            return;
        }
        worst_erk2 = fmax(worst_erk2, fabs(sb.amplification - sqrt(1 + x * x * x * x / 4)));
    }
    TAP_CLOSE(worst_rk4, 0.0, 1e-12, "step stability: |R(i h w)| of RK4 in closed form, h w from 0.47 to 6.3");
    TAP_CLOSE(worst_erk2, 0.0, 1e-12, "step stability: |R(i h w)| of the 2-stage order-2 table, sqrt(1 + x^4/4)");
    tap_ok(flag_ok, "step stability: RK4 unstable exactly beyond h w = 2 sqrt 2");
    o.method = GD_METHOD_RK4;
    o.steps_per_period = 10;
    gd_step_stability sb;
    gd_sim_step_stability(&m, &o, y, &md, &sb, &e);
    long want = (long)ceil(W_OSC * m.period / (2.0 * M_SQRT2));
    tap_ok(sb.min_steps_per_period == want, "step stability: fewest stable RK4 steps %ld = ceil(w T / 2 sqrt 2) = %ld",
           sb.min_steps_per_period, want);
    o.method = GD_METHOD_ERK;
    o.fixed_step = 0;
    gd_sim_step_stability(&m, &o, y, &md, &sb, &e);
    tap_ok(isnan(sb.amplification) && !sb.unstable, "step stability: an adaptive step is not judged");
}

/* The paper's pair (bta, 2000 rpm): the fewest stable RK4 steps against the undamped modal
 * analysis, and the work-precision statuses either side. */
static void paper_pair_stability(void)
{
    const char *sets[] = {"scene.analysis=work-precision", "scene.model=bta", "operating.speed_rpm=2000",
                          "clearance.backlash_um=10", "clearance.bearing_clearance_um=5", "excitation.stiffness=harmonic",
                          "excitation.stiffness_harmonics=0.1", "excitation.ste_amplitude_um=10",
                          "run.transient_periods=300", "run.record_periods=20", "workprecision.horizon_periods=5",
                          "workprecision.families=rk4", "workprecision.root_finding_off=off",
                          "workprecision.rk4_steps_min=32", "workprecision.rk4_steps_max=64",
                          "workprecision.order_study=off", "workprecision.lyapunov=off", NULL};
    gd_case c;
    gd_error e = {0};
    gd_case_init(&c, &e);
    c.speed_rpm = 4000, c.torque_nm = 500;
    set_all(&c, sets);
    gd_model m;
    if (gd_case_resolve(&c, &e) != GD_OK || gd_model_build(&c, &m, &e) != GD_OK) {
        printf("Bail out! %s\n", e.msg);
        exit(1);
    }
    gd_modes md;
    double y0[GD_MAX_STATE];
    gd_modal ma;
    if (gd_initial_state(&c, &m, y0, &md, &e) != GD_OK || gd_modal_analyse(&m, &md, NULL, &ma, &e) != GD_OK) {
        printf("Bail out! %s\n", e.msg);
        exit(1);
    }
    gd_solver_opts o = gd_solver_opts_defaults();
    o.method = GD_METHOD_RK4;
    o.steps_per_period = 32;
    gd_step_stability sb;
    if (gd_sim_step_stability(&m, &o, y0, &md, &sb, &e) != GD_OK) {
        printf("Bail out! %s\n", e.msg);
        exit(1);
    }
    double fmax_hz = ma.freq_hz[ma.nmodes - 1];
    double undamped = 2.0 * M_PI * fmax_hz / m.mesh_freq_hz / (2.0 * M_SQRT2);
    printf("# bta 2000 rpm: highest mode %.6g Hz (modal), %.6g Hz (Jacobian, damping ratio %.3g); RK4 stable from %ld "
           "steps per period, undamped bound %.4g; |R| at 32 steps %.4g\n",
           fmax_hz, sb.freq_hz, sb.damping_ratio, sb.min_steps_per_period, undamped, sb.amplification);
    tap_ok(labs(sb.min_steps_per_period - (long)ceil(undamped)) <= 1,
           "paper's pair: fewest stable RK4 steps %ld within 1 of the modal bound %.4g", sb.min_steps_per_period,
           undamped);
    gd_wp_result r;
    if (gd_workprec_run(&c, &m, NULL, NULL, &r, &e) != GD_OK) {
        printf("Bail out! %s\n", e.msg);
        exit(1);
    }
    int unst = 0, ok = 0;
    for (int i = 0; i < r.nruns; i++) {
        const gd_wp_run *u = &r.runs[i];
        printf("# %s: %s, RMS %.4g m/s^2: %s\n", u->label, gd_wp_status_name(u->status), u->rms_accel_mps2,
               u->message);
        unst += u->steps_per_period == 32 && u->status == GD_WP_UNSTABLE;
        ok += u->steps_per_period == 64 && u->status == GD_WP_OK;
    }
    tap_ok(r.nruns == 2 && unst == 1 && ok == 1, "paper's pair at 2000 rpm: RK4 at 32 steps unstable, at 64 ok");
    tap_ok(gd_workprec_cheapest(&r, 1e-3, 0) < 0 || r.runs[gd_workprec_cheapest(&r, 1e-3, 0)].status == GD_WP_OK,
           "paper's pair: the cheapest setting is never an unstable one");
    gd_workprec_free(&r);
    gd_case_free(&c);
}

static void run(const char *const *base, const char *const *extra, gd_wp_result *res)
{
    gd_case c;
    gd_error e = {0};
    gd_case_init(&c, &e);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    set_all(&c, base);
    if (extra)
        set_all(&c, extra);
    gd_model m;
    if (gd_case_resolve(&c, &e) != GD_OK || gd_model_build(&c, &m, &e) != GD_OK ||
        gd_workprec_run(&c, &m, NULL, NULL, res, &e) != GD_OK) {
        printf("Bail out! %s\n", e.msg);
        exit(1);
    }
    gd_case_free(&c);
}

static const gd_wp_order *order_of(const gd_wp_result *r, const char *family)
{
    for (int i = 0; i < r->norders; i++)
        if (strcmp(r->families[r->orders[i].family].name, family) == 0)
            return &r->orders[i];
    return NULL;
}

static void show_order(const gd_wp_order *o, const char *name)
{
    printf("# %s:", name);
    for (int l = 0; l < o->nlevels; l++)
        printf(" N=%d %.3g", o->steps[l], o->err[l]);
    printf("\n");
}

int main(void)
{
    const char *impacting[] = {"scene.analysis=work-precision", "scene.model=torsional", "run.transient_periods=300",
                               "run.record_periods=20", "workprecision.horizon_periods=5", NULL};

    /* 1. the grid */
    {
        const char *grid[] = {"workprecision.families=rk4,erk5", "workprecision.rk4_steps_min=32",
                              "workprecision.rk4_steps_max=256", "workprecision.rtol_loosest=1e-4",
                              "workprecision.rtol_tightest=1e-8", "workprecision.order_study=off", NULL};
        gd_wp_result r;
        run(impacting, grid, &r);
        tap_ok(r.nfamilies == 4, "families: rk4, rk4-noroot, erk5, erk5-noroot (%d)", r.nfamilies);
        tap_ok(r.nruns == 2 * 4 + 2 * 5, "grid: 4 step counts and 5 tolerances, with and without root finding (%d runs)",
               r.nruns);
        int fin = 1, ok = 1;
        for (int i = 0; i < r.nruns; i++) {
            const gd_wp_run *u = &r.runs[i];
            ok &= u->status == GD_WP_OK;
            fin &= isfinite(u->err_poincare) && isfinite(u->err_rms) && isfinite(u->err_events) &&
                   isfinite(u->err_short) && u->cpu_s > 0 && u->rhs_evals > 0 && u->steps > 0 && u->events > 0;
        }
        tap_ok(ok, "every run finished");
        tap_ok(fin, "every run has finite errors, a wall time, RHS evaluations, steps and events");
        tap_ok(r.ref.converged && r.ref.check_poincare < 1e-9, "reference converged: differs from its check by %.3g",
               r.ref.check_poincare);
        tap_ok(strcmp(r.ref.motion, "period-1") == 0 && !r.ref.chaotic, "scene: %s", r.ref.motion);
        tap_ok(r.ref.events == 80, "reference: 4 events per mesh period over 20 periods (%ld)", r.ref.events);
        /* errors fall along each family (rk4 by 2^4 per doubling, adaptive by at least 10 over 4 decades) */
        const gd_wp_run *a = &r.runs[0], *b = &r.runs[3];
        tap_ok(b->err_poincare < a->err_poincare / 1000, "rk4: Poincare error %.3g at N=32, %.3g at N=256",
               a->err_poincare, b->err_poincare);
        tap_ok(b->err_events < a->err_events / 100, "rk4: event time error %.3g at N=32, %.3g at N=256", a->err_events,
               b->err_events);
        const gd_wp_run *c0 = &r.runs[8], *c1 = &r.runs[12];
        tap_ok(strcmp(c0->label, "erk5 rtol=1e-04") == 0 && strcmp(c1->label, "erk5 rtol=1e-08") == 0, "labels: %s, %s",
               c0->label, c1->label);
        tap_ok(c1->err_poincare < c0->err_poincare / 100, "erk5: Poincare error %.3g at rtol 1e-4, %.3g at 1e-8",
               c0->err_poincare, c1->err_poincare);
        tap_ok(c1->err_events < 1e-6 && r.runs[17].err_events > 1e-4,
               "event times: %.3g located (erk5 1e-8), %.3g at step ends (root finding off)", c1->err_events,
               r.runs[17].err_events);
        int k = gd_workprec_cheapest(&r, 1e-6, 0);
        tap_ok(k >= 0 && r.runs[k].err_poincare <= 1e-6 && r.runs[k].err_rms <= 1e-6,
               "cheapest at 1e-6: %s (Poincare %.3g, RMS %.3g)", k >= 0 ? r.runs[k].label : "none",
               k >= 0 ? r.runs[k].err_poincare : NAN, k >= 0 ? r.runs[k].err_rms : NAN);
        k = gd_workprec_cheapest(&r, 1e-6, 1);
        tap_ok(k >= 0 && r.runs[k].err_events <= 1e-6 && r.families[r.runs[k].family].root_finding,
               "cheapest at 1e-6 with the event times too: %s (located events, event time error %.3g)",
               k >= 0 ? r.runs[k].label : "none", k >= 0 ? r.runs[k].err_events : NAN);
        gd_workprec_free(&r);
    }

    /* 2. smooth: permanent contact, no events */
    {
        const char *smooth[] = {"scene.analysis=work-precision", "scene.model=torsional", "clearance.backlash_um=0",
                                "operating.torque_nm=20000", "excitation.stiffness_harmonics=0.2",
                                "run.transient_periods=0", "run.record_periods=5", "workprecision.horizon_periods=5",
                                "workprecision.families=rk4", "workprecision.rk4_steps_min=16",
                                "workprecision.rk4_steps_max=16", "workprecision.order_steps_min=8",
                                "workprecision.order_steps_max=256", NULL};
        gd_wp_result r;
        run(smooth, NULL, &r);
        tap_ok(r.ref.events == 0, "smooth case: no events (%ld)", r.ref.events);
        const gd_wp_order *on = order_of(&r, "rk4"), *off = order_of(&r, "rk4-noroot");
        if (on && off) {
            show_order(on, "rk4");
            TAP_CLOSE(on->order, 4.0, 0.3, "smooth: measured order of RK4, root finding on");
            TAP_CLOSE(off->order, 4.0, 0.3, "smooth: measured order of RK4, root finding off");
        } else {
            tap_ok(0, "order study present");
        }
        gd_workprec_free(&r);
    }

    /* 3. impacting: event location restores the order */
    {
        const char *study[] = {"workprecision.families=rk4,erk5", "workprecision.rk4_steps_min=16",
                               "workprecision.rk4_steps_max=16", "workprecision.rtol_loosest=1e-4",
                               "workprecision.rtol_tightest=1e-4", "workprecision.order_steps_min=16",
                               "workprecision.order_steps_max=512", NULL};
        gd_wp_result r;
        run(impacting, study, &r);
        const gd_wp_order *on = order_of(&r, "rk4"), *off = order_of(&r, "rk4-noroot");
        const gd_wp_order *on5 = order_of(&r, "erk5"), *off5 = order_of(&r, "erk5-noroot");
        if (on && off && on5 && off5) {
            show_order(on, "rk4");
            show_order(off, "rk4-noroot");
            show_order(on5, "erk5");
            show_order(off5, "erk5-noroot");
            TAP_CLOSE(on->order, 4.0, 0.4, "impacts: measured order of RK4 with event location");
            tap_ok(off->order < 3.0, "impacts: RK4 without event location drops to order %.2f (below 3)", off->order);
            TAP_CLOSE(on5->order, 5.0, 0.5, "impacts: measured order of the 5th-order table with event location");
            tap_ok(off5->order < 3.0, "impacts: 5th-order table without event location drops to order %.2f",
                   off5->order);
        } else {
            tap_ok(0, "order study present");
        }
        gd_workprec_free(&r);
    }

    /* 4. the metric */
    {
        double a[6] = {1, 10, 2, 20, 3, 30}, b[6] = {1, 10, 2, 20, 3, 30};
        TAP_CLOSE(gd_workprec_poincare_error(a, b, 3, 2), 0.0, 0.0, "metric: equal points");
        a[4] = 3.4; /* component 0 scale 1 + 3 = 4: 0.4 / 4 */
        TAP_CLOSE(gd_workprec_poincare_error(a, b, 3, 2), 0.1, 1e-15, "metric: scaled by 1 + max |p|");
        a[1] = NAN;
        tap_ok(isinf(gd_workprec_poincare_error(a, b, 3, 2)), "metric: NaN is an infinite error");
    }

    /* 5. the stability of a fixed step */
    step_stability_tests();
    paper_pair_stability();
    return tap_done();
}
