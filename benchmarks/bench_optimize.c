/* Benchmark: the optimisation of the paper's gear problem (docs/optimisation.md, docs/performance.md).
 *  1. One evaluation of the gear objective (LTE amplitude of the Table 2 modification, 32 positions,
 *     21 slices, floating pinion, 500 N m, delta 0.5', dE 0.1 mm): its LTCA workspace creation
 *     (gd_ltca_create: TCA workspace with the modified flank, tooth tables) and the 32 positions,
 *     best of the repeats.
 *  2. The cost of ALO itself (random walks, sorting; no objective): ALO on the sphere, d = 6, 30 ants,
 *     100 iterations, per evaluation.
 *  3. With "full": the paper's ALO run (30 ants, 100 iterations, 3030 evaluations) on the gear
 *     problem with 1 and 2 threads.
 * Usage: bench_optimize [repeats] [full] */
#include "geardyn/geardyn.h"

#include <gsl/gsl_errno.h>
#include <math.h>
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

static int make(gd_case *c, gd_error *err)
{
    gd_case_init(c, err);
    const char *base[] = {"scene.analysis=optimize", "misalignment.axis_in_plane_arcmin=-0.35355339",
                          "misalignment.axis_cross_plane_arcmin=0.35355339", "misalignment.centre_distance_error_mm=0.1",
                          "operating.torque_nm=500", "optimize.iterations=100", "optimize.population=30"};
    for (int i = 0; i < 7; i++)
        if (gd_case_set(c, base[i], i, err) != GD_OK)
            return 1;
    return gd_case_resolve(c, err) != GD_OK;
}

static gd_status sphere(void *state, const double *y, double *f, gd_error *err)
{
    (void)state;
    (void)err;
    double s = 0;
    for (int i = 0; i < 6; i++)
        s += y[i] * y[i];
    *f = s;
    return GD_OK;
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    int repeats = argc > 1 ? atoi(argv[1]) : 5;
    int full = argc > 2 && strcmp(argv[2], "full") == 0;
    if (repeats < 1)
        repeats = 1;
    gd_case c;
    gd_error err = {0};
    if (make(&c, &err)) {
        fprintf(stderr, "case: %s\n", err.msg);
        return 1;
    }
    gd_pair t = gd_pair_from_case(&c);
    const gd_ltca_settings set = gd_ltca_settings_from_case(&c);
    gd_opt_gear_table2(&t);
    double best_create = 1e300, best_eval = 1e300, f = 0;
    for (int r = 0; r < repeats; r++) {
        double t0 = now();
        gd_ltca *w;
        if (gd_ltca_create(&t, &set, &w, &err) != GD_OK) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
        double t1 = now();
        gd_ltca_free(w);
        best_create = fmin(best_create, t1 - t0);
        t0 = now();
        if (gd_opt_gear_lte_pp(&t, &set, &f, &err) != GD_OK) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
        best_eval = fmin(best_eval, now() - t0);
    }
    printf("gear objective (Table 2, %d positions, %d slices): %.2f ms per evaluation, of which %.2f ms "
           "gd_ltca_create (%.0f %%); LTE %.6f arcsec\n", c.ltca_positions_per_cycle, c.ltca_face_slices,
           best_eval * 1e3, best_create * 1e3, 100 * best_create / best_eval, f);

    /* ALO's own cost */
    double lo[6] = {-1, -1, -1, -1, -1, -1}, hi[6] = {1, 1, 1, 1, 1, 1};
    gd_opt_problem p = {0};
    p.dim = 6;
    p.lower = lo;
    p.upper = hi;
    p.eval = sphere;
    gd_opt_settings s;
    gd_opt_settings_default(&s);
    s.algorithm = GD_OPT_ALO;
    s.population = 30;
    s.budget = 30 * 101;
    s.threads = 1;
    double best_alo = 1e300;
    for (int r = 0; r < repeats; r++) {
        gd_opt_result res;
        s.seed = (unsigned long)r + 1;
        if (gd_opt_run(&p, &s, &res, &err) != GD_OK) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
        best_alo = fmin(best_alo, res.wall_s);
        gd_opt_result_free(&res);
    }
    printf("ALO itself (sphere d = 6, 30 ants, 100 iterations): %.3f ms per run, %.2f us per evaluation\n",
           best_alo * 1e3, best_alo / 3030 * 1e6);

    if (full) {
        gd_opt_gear *g;
        const gd_pair pair = gd_pair_from_case(&c);
        double lower[GD_OPT_GEAR_NVARS], upper[GD_OPT_GEAR_NVARS];
        gd_opt_gear_vars v;
        gd_opt_gear_vars_paper(&v);
        gd_opt_gear_bounds(&c, &v, lower, upper);
        if (gd_opt_gear_create(&pair, &set, &v, lower, upper, &g, &err) != GD_OK) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
        gd_opt_gear_problem(g, &p);
        for (int th = 1; th <= 2; th++) {
            gd_opt_result res;
            s.seed = 1;
            s.threads = th;
            if (gd_opt_run(&p, &s, &res, &err) != GD_OK) {
                fprintf(stderr, "%s\n", err.msg);
                return 1;
            }
            printf("ALO on the gear problem (30 ants, 100 iterations, %ld evaluations), %d thread%s: %.1f s "
                   "(%.2f ms per evaluation), best %.6f arcsec\n", res.evaluations, th, th > 1 ? "s" : "", res.wall_s,
                   res.wall_s / res.evaluations * 1e3, res.f);
            gd_opt_result_free(&res);
        }
        gd_opt_gear_free(g);
    }
    gd_case_free(&c);
    return 0;
}
