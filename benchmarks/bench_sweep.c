/* Benchmark: the paper's speed sweep (Figs. 18-20) with the bta model, 100 to 8000 rpm, 300
 * transient and 200 recorded mesh periods, rtol 1e-8, events on, continuation up and down
 * (one chain per direction) or independent points, with and without the largest Lyapunov
 * exponent, on a chosen number of threads. Prints the wall time of each configuration.
 *
 * Usage: bench_sweep POINTS [MODE] CONFIG...
 *   MODE: both (continuation, up and down: 2 x POINTS runs; default), up, independent
 *   CONFIG: THREADS:MLE, e.g. 2:0 (2 threads, no exponent) 2:1 (2 threads, the exponent)
 *   any further argument section.key=value is a case setting applied to every configuration
 *   (e.g. solver.order=8, solver.vector_kernels=sundials) */
#include "geardyn/geardyn.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

/* CPU time of all threads of the process (less sensitive than the wall time to other load) */
static double cpu(void)
{
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return (double)u.ru_utime.tv_sec + 1e-6 * (double)u.ru_utime.tv_usec + (double)u.ru_stime.tv_sec +
           1e-6 * (double)u.ru_stime.tv_usec;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv)
{
    int points = argc > 1 ? atoi(argv[1]) : 400;
    int a = 2;
    const char *mode = "both";
    if (argc > 2 && strchr(argv[2], ':') == NULL) {
        mode = argv[2];
        a = 3;
    }
    const char *dflt[] = {"2:0", "2:1"};
    const char *confs[16], *extra[16];
    int nconf = 0, nextra = 0;
    for (int i = a; i < argc; i++) {
        if (strchr(argv[i], '=') && nextra < 16)
            extra[nextra++] = argv[i];
        else if (nconf < 16)
            confs[nconf++] = argv[i];
    }
    if (nconf == 0)
        confs[nconf++] = dflt[0], confs[nconf++] = dflt[1];
    printf("speed sweep 100-8000 rpm, bta, 300 + 200 mesh periods, rtol 1e-8, %d points, %s", points, mode);
    for (int i = 0; i < nextra; i++)
        printf(", %s", extra[i]);
    printf("\n");
    printf("%-8s %-4s %10s %10s %8s %14s %12s %12s\n", "threads", "MLE", "wall_s", "cpu_s", "runs", "cpu_s_per_run",
           "steps", "rhs_evals");
    for (int k = 0; k < nconf; k++) {
        const char *conf = confs[k];
        int threads = atoi(conf), mle = atoi(strchr(conf, ':') ? strchr(conf, ':') + 1 : "0");
        gd_case c;
        gd_error err = {0};
        gd_case_init(&c, &err);
        char sets[32][96];
        int n = 0;
        snprintf(sets[n++], 96, "scene.analysis=sweep");
        snprintf(sets[n++], 96, "scene.model=bta");
        snprintf(sets[n++], 96, "operating.torque_nm=500");
        snprintf(sets[n++], 96, "clearance.backlash_um=10");
        snprintf(sets[n++], 96, "clearance.bearing_clearance_um=5");
        snprintf(sets[n++], 96, "excitation.ste_amplitude_um=10");
        snprintf(sets[n++], 96, "damping.mesh_damping_ratio=0.02");
        snprintf(sets[n++], 96, "solver.rtol=1e-8");
        snprintf(sets[n++], 96, "run.transient_periods=300");
        snprintf(sets[n++], 96, "run.record_periods=200");
        snprintf(sets[n++], 96, "run.lyapunov_exponents=%d", mle);
        snprintf(sets[n++], 96, "sweep.parameter=operating.speed_rpm");
        snprintf(sets[n++], 96, "sweep.from=100");
        snprintf(sets[n++], 96, "sweep.to=8000");
        snprintf(sets[n++], 96, "sweep.points=%d", points);
        if (strcmp(mode, "independent") == 0)
            snprintf(sets[n++], 96, "sweep.mode=independent");
        else
            snprintf(sets[n++], 96, "sweep.direction=%s", mode);
        for (int i = 0; i < nextra && n < 32; i++)
            snprintf(sets[n++], 96, "%s", extra[i]);
        for (int i = 0; i < n; i++)
            if (gd_case_set(&c, sets[i], i, &err) != GD_OK) {
                fprintf(stderr, "%s\n", err.msg);
                return 1;
            }
        gd_sweep_plan p;
        gd_sweep_point *pts;
        if (gd_case_resolve(&c, &err) != GD_OK || gd_sweep_plan_create(&c, &p, &err) != GD_OK ||
            gd_sweep_points_create(&p, &pts, &err) != GD_OK) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
        gd_sweep_opts o;
        gd_sweep_opts_default(&o);
        o.threads = threads;
        double t0 = now(), c0 = cpu();
        if (gd_sweep_run(&c, &p, pts, &o, &err) != GD_OK) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
        double wall = now() - t0, cput = cpu() - c0;
        long steps = 0, rhs = 0;
        for (int s = 0; s < p.nslots; s++) {
            steps += pts[s].steps;
            rhs += pts[s].rhs_evals;
        }
        printf("%-8d %-4s %10.1f %10.1f %8d %14.3f %12ld %12ld\n", threads, mle ? "on" : "off", wall, cput, p.nslots,
               cput / p.nslots, steps, rhs);
        fflush(stdout);
        gd_sweep_points_free(&p, pts);
        gd_sweep_plan_free(&p);
        gd_case_free(&c);
    }
    return 0;
}
