/* Benchmark: the bta model at 4000 rpm, rtol 1e-8, events on (the quickstart case):
 * steps per second, RHS evaluations per mesh period, wall time per mesh period.
 * Also the torsional and torsional-lr levels, root finding off, and the cost of the largest
 * Lyapunov exponent by either method, for comparison.
 * Usage: bench_dynamics [repeats]  (best of the repeats is reported) */
#include "geardyn/geardyn.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int run(const char *label, const char *const *sets, int nsets, int repeats)
{
    gd_case c;
    gd_error err = {0};
    gd_case_init(&c, &err);
    const char *base[] = {"operating.speed_rpm=4000", "operating.torque_nm=500", "clearance.backlash_um=10",
                          "clearance.bearing_clearance_um=5", "excitation.ste_amplitude_um=10", "solver.rtol=1e-8",
                          "run.transient_periods=300", "run.record_periods=200", "run.lyapunov_exponents=0"};
    for (int i = 0; i < 9; i++)
        gd_case_set(&c, base[i], i, &err);
    for (int i = 0; i < nsets; i++)
        if (gd_case_set(&c, sets[i], 9 + i, &err) != GD_OK) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
    if (gd_case_resolve(&c, &err) != GD_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    gd_model m;
    gd_model_build(&c, &m, &err);
    double best = 1e300;
    gd_response_result r;
    for (int k = 0; k < repeats; k++) {
        double t0 = now();
        if (gd_response_run(&c, &m, NULL, NULL, NULL, &r, &err) != GD_OK) {
            fprintf(stderr, "%s: %s\n", label, err.msg);
            return 1;
        }
        double t = now() - t0;
        if (t < best)
            best = t;
    }
    long periods = (long)c.transient_periods + c.record_periods;
    printf("%-34s %8.3f s  %9.0f steps/s  %7.1f steps/period  %8.1f RHS/period  %6.1f us/period  %7ld events  %s\n",
           label, best, r.stats.steps / best, (double)r.stats.steps / periods, (double)r.stats.rhs_evals / periods,
           1e6 * best / periods, r.stats.events, r.motion);
    gd_case_free(&c);
    return 0;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 3;
    printf("geardyn %s, 500 mesh periods per run, best of %d\n", GD_VERSION_STRING, repeats);
    const char *bta[] = {"scene.model=bta"};
    const char *bta_off[] = {"scene.model=bta", "solver.root_finding=off"};
    const char *bta_mle[] = {"scene.model=bta", "run.lyapunov_exponents=1"};
    const char *bta_mle2[] = {"scene.model=bta", "run.lyapunov_exponents=1", "run.lyapunov_method=two-trajectory"};
    const char *bta_rk4[] = {"scene.model=bta", "solver.method=rk4", "solver.steps_per_period=512"};
    const char *bta_dirk[] = {"scene.model=bta", "solver.method=dirk"};
    const char *lr[] = {"scene.model=torsional-lr"};
    const char *tor[] = {"scene.model=torsional"};
    int rc = 0;
    rc |= run("bta erk5 rtol 1e-8 events on", bta, 1, repeats);
    rc |= run("bta erk5 rtol 1e-8 events off", bta_off, 2, repeats);
    rc |= run("bta erk5 events on + MLE (tangent)", bta_mle, 2, repeats);
    rc |= run("bta erk5 events on + MLE (two traj.)", bta_mle2, 3, repeats);
    rc |= run("bta rk4 512/period events on", bta_rk4, 3, repeats);
    rc |= run("bta dirk4 rtol 1e-8 events on", bta_dirk, 2, 1);
    rc |= run("torsional-lr erk5 rtol 1e-8", lr, 1, repeats);
    rc |= run("torsional erk5 rtol 1e-8", tor, 1, repeats);
    return rc;
}
