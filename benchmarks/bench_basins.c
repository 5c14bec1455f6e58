/* Benchmark: the basins of the shipped cases (docs/basins.md section 9), wall clock and the process's
 * CPU time of gd_basins_run on OpenMP threads:
 *
 *   ks-picture    cases/basins/ks-hysteresis.ini, the 200 x 200 picture alone (samples 0)
 *   ks-fractions  the same case, 10 000 random states alone (picture off)
 *   paper         cases/basins/paper-4750rpm.ini, the 100 x 100 picture alone (the bta model; its LTCA,
 *                 computed when the case is resolved, timed apart)
 *
 * Reported: the mesh periods integrated, per initial state, the wall and CPU seconds and the CPU
 * microseconds per mesh period, and the attractors with their share.
 *
 * Usage: bench_basins [threads [which ...]]   (default: 2 threads, all three; GEARDYN_SOURCE the tree) */
#include "geardyn/geardyn.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int run(const char *what, const char *file, const char *const *sets, int threads)
{
    const char *src = getenv("GEARDYN_SOURCE");
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", src ? src : ".", file);
    gd_case c;
    gd_error e = {0};
    gd_case_init(&c, &e);
    if (gd_case_load(&c, path, &e) != GD_OK) {
        fprintf(stderr, "%s\n", e.msg);
        return 1;
    }
    for (int i = 0; sets[i]; i++)
        if (gd_case_set(&c, sets[i], i, &e) != GD_OK) {
            fprintf(stderr, "%s: %s\n", sets[i], e.msg);
            return 1;
        }
    double t0 = now();
    if (gd_case_resolve(&c, &e) != GD_OK) {
        fprintf(stderr, "%s\n", e.msg);
        return 1;
    }
    double t_resolve = now() - t0;
    gd_basins_hooks h = {0};
    h.threads = threads;
    gd_basins_result res;
    clock_t c0 = clock();
    t0 = now();
    if (gd_basins_run(&c, NULL, &h, &res, &e) != GD_OK) {
        fprintf(stderr, "%s\n", e.msg);
        return 1;
    }
    double wall = now() - t0, cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    const gd_basins_point *p = &res.pt[0];
    long states = (long)res.nx * res.ny + c.bas_samples;
    printf("%-13s %ld initial states, %ld mesh periods (%.1f per state): %.2f s wall, %.2f s CPU on %d threads, "
           "%.1f us CPU per mesh period (case resolved in %.2f s)\n", what, states, p->periods,
           (double)p->periods / (double)states, wall, cpu, res.threads, 1e6 * cpu / (double)p->periods, t_resolve);
    for (int a = 0; a < p->natt; a++) {
        long cells = 0;
        for (long k = 0; res.grid && k < (long)res.nx * res.ny; k++)
            cells += res.grid[k] == a;
        printf("    attractor %d: %s, %s: %s %.4f\n", a, p->att[a].name,
               p->att[a].impact_regime >= 0 ? gd_impact_regime_name(p->att[a].impact_regime) : "-",
               res.grid ? "share of the picture" : "fraction", res.grid ? (double)cells / (double)(res.nx * res.ny)
                                                                        : (double)p->count[a] / (double)p->samples);
    }
    gd_basins_result_free(&res);
    gd_case_free(&c);
    return 0;
}

int main(int argc, char **argv)
{
    int threads = argc > 1 ? atoi(argv[1]) : 2;
    printf("geardyn %s on %s: basins, %d threads\n", GD_VERSION_STRING, GD_SUNDIALS_BUILD, threads);
    static const char *picture[] = {"basins.samples=0", NULL};
    static const char *fractions[] = {"basins.picture=off", "basins.samples=10000", NULL};
    static const char *paper[] = {"basins.samples=0", NULL};
    int rc = 0;
    for (int i = argc > 2 ? 2 : 0; i < (argc > 2 ? argc : 3); i++) {
        const char *w = argc > 2 ? argv[i] : (const char *[]){"ks-picture", "ks-fractions", "paper"}[i];
        if (strcmp(w, "ks-picture") == 0)
            rc |= run(w, "cases/basins/ks-hysteresis.ini", picture, threads);
        else if (strcmp(w, "ks-fractions") == 0)
            rc |= run(w, "cases/basins/ks-hysteresis.ini", fractions, threads);
        else if (strcmp(w, "paper") == 0)
            rc |= run(w, "cases/basins/paper-4750rpm.ini", paper, threads);
        else {
            fprintf(stderr, "unknown benchmark %s (ks-picture, ks-fractions, paper)\n", w);
            rc = 1;
        }
    }
    return rc;
}
