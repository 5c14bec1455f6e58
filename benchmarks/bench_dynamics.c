/* Benchmark: the bta model at 4000 rpm, rtol 1e-8, events on (the quickstart case):
 * steps per second, RHS evaluations per mesh period, wall time per mesh period.
 * Also the torsional and torsional-lr levels, root finding off, and the cost of the largest
 * Lyapunov exponent by either method, for comparison.
 * Usage: bench_dynamics [repeats [only [section.key=value ...]]]  (best of the repeats is
 * reported; only: run the configurations whose label contains this string; the settings are
 * applied to every run). CPU time (getrusage) is the figure to quote on a shared machine. */
#include "geardyn/geardyn.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

/* CPU time of the process: the machine is shared, CPU time is the reliable figure */
static double cpu(void)
{
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return (double)u.ru_utime.tv_sec + 1e-6 * (double)u.ru_utime.tv_usec + (double)u.ru_stime.tv_sec +
           1e-6 * (double)u.ru_stime.tv_usec;
}

static const char *only;          /* run only the configurations whose label contains this */
static const char *extra[16];     /* further settings for every run (section.key=value) */
static int nextra;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int run(const char *label, const char *const *sets, int nsets, int repeats)
{
    if (only && !strstr(label, only))
        return 0;
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
    for (int i = 0; i < nextra; i++)
        if (gd_case_set(&c, extra[i], 9 + nsets + i, &err) != GD_OK) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
    if (gd_case_resolve(&c, &err) != GD_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    gd_model m;
    gd_model_build(&c, &m, &err);
    double best = 1e300, best_wall = 1e300;
    gd_response_result r;
    for (int k = 0; k < repeats; k++) {
        double t0 = now(), c0 = cpu();
        if (gd_response_run(&c, &m, NULL, NULL, NULL, &r, &err) != GD_OK) {
            fprintf(stderr, "%s: %s\n", label, err.msg);
            return 1;
        }
        double t = cpu() - c0, w = now() - t0;
        if (t < best)
            best = t;
        if (w < best_wall)
            best_wall = w;
    }
    long periods = (long)c.transient_periods + c.record_periods;
    printf("%-36s cpu %7.3f s  wall %7.3f s  %8.0f steps/s  %6.1f steps/period  %7.1f RHS/period  "
           "%5.2f RHS/step  %6.1f us/period  %6ld events  rms %.10g  %s\n",
           label, best, best_wall, r.stats.steps / best, (double)r.stats.steps / periods,
           (double)r.stats.rhs_evals / periods, (double)r.stats.rhs_evals / (double)r.stats.steps,
           1e6 * best / periods, r.stats.events, r.rms_accel_mps2[2], r.motion);
    gd_case_free(&c);
    return 0;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 3;
    if (argc > 2 && argv[2][0])
        only = argv[2];
    for (int i = 3; i < argc && nextra < 16; i++)
        extra[nextra++] = argv[i];
    printf("geardyn %s, 500 mesh periods per run, best of %d (CPU time of the process, getrusage)\n",
           GD_VERSION_STRING, repeats);
    const char *bta[] = {"scene.model=bta"};
    const char *bta_off[] = {"scene.model=bta", "solver.root_finding=off"};
    const char *bta_mle[] = {"scene.model=bta", "run.lyapunov_exponents=1"};
    const char *bta_mle2[] = {"scene.model=bta", "run.lyapunov_exponents=1", "run.lyapunov_method=two-trajectory"};
    const char *bta_rk4[] = {"scene.model=bta", "solver.method=rk4", "solver.steps_per_period=512"};
    const char *bta_dirk[] = {"scene.model=bta", "solver.method=dirk"};
    const char *lr[] = {"scene.model=torsional-lr"};
    const char *tor[] = {"scene.model=torsional"};
    int rc = 0;
    rc |= run("bta erk8 rtol 1e-8 events on", bta, 1, repeats);
    rc |= run("bta erk8 rtol 1e-8 events off", bta_off, 2, repeats);
    rc |= run("bta erk8 events on + MLE (tangent)", bta_mle, 2, repeats);
    rc |= run("bta erk8 events on + MLE (two traj.)", bta_mle2, 3, repeats);
    rc |= run("bta rk4 512/period events on", bta_rk4, 3, repeats);
    rc |= run("bta dirk4 rtol 1e-8 events on", bta_dirk, 2, 1);
    rc |= run("torsional-lr erk8 rtol 1e-8", lr, 1, repeats);
    rc |= run("torsional erk8 rtol 1e-8", tor, 1, repeats);
    return rc;
}
