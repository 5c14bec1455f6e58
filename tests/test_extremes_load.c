/* Extremes of load and damping (suite 'extremes', docs/accuracy.md): 10 kW and 2000 kW, a step
 * of the torque, zero load (the teeth separate for good: the run must stop with a clear status
 * and message), zero damping and a damping ratio of 0.2. The paper's pair and bta model at 4000
 * rpm (quickstart data) unless stated; each scene at rtol 1e-7 and 1e-9 (extremes_util.h):
 * completes, no NaN/inf, events bounded, the two runs agree within the stated tolerances. */
#include "extremes_util.h"
#include "geardyn/gd_analysis.h"
#include "geardyn/gd_scene.h"

#define S(...) ((const char *const[]){__VA_ARGS__, NULL})

/* A step of the torque: 200 periods at 500 N m, then from that state 200 periods at `after`.
 * Returns the run after the step (caller frees). */
static void stepped(double after, double rtol, ex_run *out)
{
    gd_case c;
    gd_error e = {0};
    gd_case_init(&c, &e);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    const char *sets[] = {"run.transient_periods=200", "run.record_periods=1", "run.lyapunov_exponents=0", NULL};
    for (int i = 0; sets[i]; i++)
        gd_case_set(&c, sets[i], i, &e);
    gd_case_set_number(&c, "solver.rtol", rtol, &e);
    gd_case_set_number(&c, "solver.atol", rtol / 100, &e);
    gd_model m;
    gd_response_result r;
    if (gd_case_resolve(&c, &e) != GD_OK || gd_model_build(&c, &m, &e) != GD_OK ||
        gd_response_run(&c, &m, NULL, NULL, NULL, &r, &e) != GD_OK) {
        printf("Bail out! before the step: %s\n", e.msg);
        exit(1);
    }
    gd_case_free(&c);
    /* after: the same state and contact modes, the new load */
    memset(out, 0, sizeof *out);
    out->finite = 1;
    gd_case_init(&c, &e);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    gd_case_set_number(&c, "operating.torque_nm", after, &e);
    gd_case_set_number(&c, "solver.rtol", rtol, &e);
    gd_case_set_number(&c, "solver.atol", rtol / 100, &e);
    gd_case_set_number(&c, "run.transient_periods", 0, &e);
    gd_case_set_number(&c, "run.record_periods", 200, &e);
    gd_case_set_number(&c, "run.lyapunov_exponents", 0, &e);
    if (gd_case_resolve(&c, &e) != GD_OK || gd_model_build(&c, &m, &e) != GD_OK) {
        printf("Bail out! %s\n", e.msg);
        exit(1);
    }
    out->n = m.n;
    out->periods = 200;
    out->tail = 100;
    out->pts = calloc(201 * (size_t)m.n, sizeof(double));
    gd_response_opts o;
    gd_response_opts_default(&o);
    o.y0 = r.y_final;
    o.md0 = &r.md_final;
    gd_response_hooks h = {ex_on_sample, ex_on_poincare, NULL, NULL};
    double t0 = ex_now();
    out->st = gd_response_run(&c, &m, &o, &h, out, &out->res, &e);
    out->wall_s = ex_now() - t0;
    snprintf(out->msg, sizeof out->msg, "%s", out->st == GD_OK ? "" : e.msg);
    out->rms_tail = out->count ? sqrt(out->sum2 / (double)out->count) : NAN;
    snprintf(out->motion, sizeof out->motion, "%s", out->res.motion);
    gd_case_free(&c);
}

static void torque_step(double after, double tol_tail)
{
    ex_run a, b;
    stepped(after, 1e-7, &a);
    stepped(after, 1e-9, &b);
    char label[80];
    snprintf(label, sizeof label, "bta, torque step 500 -> %g N m", after);
    ex_describe(label, "rtol 1e-7", &a);
    ex_describe(label, "rtol 1e-9", &b);
    tap_ok(a.st == GD_OK && b.st == GD_OK, "%s: completes at both tolerances%s%s", label,
           a.st != GD_OK || b.st != GD_OK ? ": " : "", a.st != GD_OK ? a.msg : b.msg);
    if (a.st == GD_OK && b.st == GD_OK) {
        tap_ok(a.finite && b.finite && isfinite(a.rms_tail) && isfinite(b.rms_tail), "%s: no NaN or inf", label);
        double epp = (double)b.res.stats.events / 200.0;
        tap_ok(epp <= 60, "%s: events bounded: %.2f per mesh period (at most 60)", label, epp);
        double d = gd_workprec_poincare_error(a.pts, b.pts, 21, a.n);
        tap_ok(d <= 1e-5, "%s: trajectories after the step agree over 20 periods: %.3g (tol 1e-5)", label, d);
        d = gd_workprec_poincare_error(a.pts + 100 * a.n, b.pts + 100 * b.n, 101, a.n);
        tap_ok(d <= tol_tail, "%s: Poincare points of the last 100 periods agree: %.3g (tol %g)", label, d, tol_tail);
        d = fabs(a.rms_tail - b.rms_tail) / b.rms_tail;
        tap_ok(d <= 1e-6, "%s: RMS of the last 100 periods agrees: %.6g and %.6g m/s^2 (relative %.3g, tol 1e-6)",
               label, a.rms_tail, b.rms_tail, d);
        /* the step settles on the response a run at the new load reaches by itself */
        ex_run direct;
        char tq[64];
        snprintf(tq, sizeof tq, "operating.torque_nm=%g", after);
        ex_run_case(S(tq), NULL, 1e-9, 400, 100, &direct);
        d = fabs(direct.rms_tail - b.rms_tail) / b.rms_tail;
        tap_ok(direct.st == GD_OK && d <= 1e-4,
               "%s: settles on the response of a run started at %g N m: RMS %.6g vs %.6g m/s^2 (relative %.3g, tol 1e-4)",
               label, after, b.rms_tail, direct.rms_tail, d);
        ex_free(&direct);
    }
    ex_free(&a);
    ex_free(&b);
}

/* Zero load, no transmission error, started at rest inside the backlash: nothing ever brings
 * the teeth together again. The run must stop with GD_ERR_PHYSICS and say why. */
static void zero_load(const char *model)
{
    gd_case c;
    gd_error e = {0};
    gd_case_init(&c, &e);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    char mdl[64];
    snprintf(mdl, sizeof mdl, "scene.model=%s", model);
    const char *sets[] = {mdl, "operating.torque_nm=0", "scene.error_excitation=off", "run.initial_condition=zero",
                          "run.transient_periods=3000", "run.record_periods=10", "run.lyapunov_exponents=0", NULL};
    for (int i = 0; sets[i]; i++)
        gd_case_set(&c, sets[i], i, &e);
    gd_model m;
    gd_response_result r;
    if (gd_case_resolve(&c, &e) != GD_OK || gd_model_build(&c, &m, &e) != GD_OK) {
        printf("Bail out! %s\n", e.msg);
        exit(1);
    }
    gd_status st = gd_response_run(&c, &m, NULL, NULL, NULL, &r, &e);
    printf("# zero load (%s): %s: %s\n", model, gd_status_name(st), e.msg);
    tap_ok(st == GD_ERR_PHYSICS, "%s at zero load: the run stops with the physics status (%s)", model,
           gd_status_name(st));
    tap_ok(strstr(e.msg, "separated") && strstr(e.msg, "load"),
           "%s at zero load: the message says the teeth stay separated and why", model);
    gd_case_free(&c);
}

int main(void)
{
    ex_spec p10 = {"bta, 10 kW (23.9 N m)", 300, 20, 1e-5, 100, 1e-5, 1e-6, 60, 0, 0};
    ex_check(&p10, S("operating.power_kw=10"), NULL);
    ex_spec p2000 = {"bta, 2000 kW (4775 N m)", 300, 20, 1e-5, 100, 1e-5, 1e-6, 60, 0, 0};
    ex_check(&p2000, S("operating.power_kw=2000"), NULL);
    torque_step(50, 1e-5);
    zero_load("torsional");
    zero_load("bta");
    /* zero damping everywhere (mesh, supports, groove shafts): weakly chaotic (largest exponent
     * about +0.05 per period); trajectories agree to 1e-6 over 20 periods */
    ex_spec z0 = {"bta, zero damping", 300, 20, 1e-4, 100, 0, 1e-4, 60, 0, 0};
    ex_check(&z0, S("damping.mesh_damping_ratio=0", "damping.support_damping_ratio=0",
                    "damping.shaft_damping_ratio=0"), NULL);
    ex_spec z02 = {"bta, mesh damping ratio 0.2", 300, 20, 1e-5, 100, 1e-5, 1e-6, 60, 0, 0};
    ex_check(&z02, S("damping.mesh_damping_ratio=0.2"), NULL);
    return tap_done();
}
