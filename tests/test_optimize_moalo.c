/* Two objectives (docs/optimisation.md section 12): the hypervolume and the non-dominated filter
 * against hand-computed values; the front the wrapper keeps is the non-dominated set of every
 * evaluation and its hypervolume history grows; MOALO on ZDT1 and ZDT2 (Zitzler, Deb & Thiele 2000)
 * in 5 variables with 50 ants and 401 iterations (20 100 evaluations) reaches, in the median over
 * seeds 1 .. 20, a hypervolume within 1 % of the true front's; the same run with 1 and 2 threads
 * evaluates the same points; the scalarisations spend the budget exactly; an algorithm is refused on
 * a problem with the other number of objectives. TAP output. */
#include "geardyn/geardyn.h"
#include "tap.h"

#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static gd_opt_result run(int fn, int dim, int alg, long budget, int pop, unsigned long seed, int threads,
                         gd_status *st, gd_error *e)
{
    gd_opt_testfn t;
    gd_opt_testfn_init(&t, fn, dim, 0, 1, e);
    gd_opt_problem p;
    gd_opt_testfn_problem(&t, &p);
    gd_opt_settings s;
    gd_opt_settings_default(&s);
    s.algorithm = alg;
    s.budget = budget;
    s.population = pop;
    s.seed = seed;
    s.threads = threads;
    s.keep_history = 1;
    s.hv_ref[0] = s.hv_ref[1] = 1.1;
    gd_opt_result r;
    *st = gd_opt_run(&p, &s, &r, e);
    gd_opt_testfn_free(&t);
    return r;
}

int main(void)
{
    /* ---- the hypervolume of a few points, by hand ------------------------------------------- */
    {
        /* (1, 3), (2, 2), (3, 1) and the dominated (2.5, 2.5), the duplicate (2, 2), within (4, 4):
         * 3 x 1 + 2 x 1 + 1 x 1 + ... the staircase: (4-1)(4-3) + (4-2)(3-2) + (4-3)(2-1) = 3 + 2 + 1 */
        double f[] = {2.5, 2.5, 3, 1, 1, 3, 2, 2, 2, 2};
        double ref[2] = {4, 4};
        TAP_CLOSE(gd_opt_hypervolume(f, 5, ref), 6.0, 1e-15, "hypervolume of a staircase");
        int idx[5];
        int m = gd_opt_nondominated(f, 5, idx);
        tap_ok(m == 3 && idx[0] == 2 && idx[1] == 3 && idx[2] == 1, "non-dominated: 3 points, f1 increasing "
               "(%d: %d %d %d)", m, idx[0], idx[1], idx[2]);
        double ref2[2] = {2.5, 4}; /* (3, 1) lies beyond r1: it adds nothing */
        TAP_CLOSE(gd_opt_hypervolume(f, 5, ref2), 1.5 * 1 + 0.5 * 1, 1e-15, "points beyond the reference add nothing");
        double t1 = gd_opt_zdt_front_hv(GD_OBJ_ZDT1, (double[]){1.1, 1.1});
        double t2 = gd_opt_zdt_front_hv(GD_OBJ_ZDT2, (double[]){1.1, 1.1});
        /* the true fronts sampled at 100001 points: the staircase converges to the area from below */
        enum { NS = 100001 };
        double *g = malloc(sizeof(double) * 2 * NS);
        for (int zi = 0; zi < 2; zi++) {
            for (int k = 0; k < NS; k++) {
                double x = (double)k / (NS - 1);
                g[2 * k] = x;
                g[2 * k + 1] = zi ? 1 - x * x : 1 - sqrt(x);
            }
            double h = gd_opt_hypervolume(g, NS, (double[]){1.1, 1.1});
            TAP_CLOSE(h, zi ? t2 : t1, 2e-5, zi ? "ZDT2's true front: 1.21 - 2/3 against 1e5 points"
                                                : "ZDT1's true front: 1.21 - 1/3 against 1e5 points");
        }
        free(g);
    }

    /* ---- the wrapper's front, its hypervolume history, the budget ------------------------------ */
    const int algs[] = {GD_OPT_MOALO, GD_OPT_RANDOM, GD_OPT_WEIGHTED_SUM, GD_OPT_EPS_CONSTRAINT};
    for (size_t a = 0; a < sizeof algs / sizeof algs[0]; a++) {
        gd_error e = {0};
        gd_status st;
        const long budget = 1237;
        gd_opt_result r = run(GD_OBJ_ZDT1, 5, algs[a], budget, 20, 3, 1, &st, &e);
        const char *an = gd_opt_algorithm_name(algs[a]);
        if (st != GD_OK) {
            tap_ok(0, "%s on ZDT1: %s", an, e.msg);
            continue;
        }
        long expect = algs[a] == GD_OPT_MOALO ? 20 * (gd_alo_iterations(budget, 20) + 1) : budget; /* N (T + 1) */
        tap_ok(r.evaluations == expect, "%s: %ld evaluations of a budget of %ld (expected %ld)", an, r.evaluations,
               budget, expect);
        int *idx = malloc(sizeof(int) * (size_t)budget);
        double *f = malloc(sizeof(double) * 2 * (size_t)budget);
        for (long k = 0; k < r.evaluations; k++) {
            f[2 * k] = r.fv_history[2 * k];
            f[2 * k + 1] = r.fv_history[2 * k + 1];
        }
        int m = gd_opt_nondominated(f, (int)r.evaluations, idx);
        int same = m == r.nfront;
        for (int k = 0; same && k < m; k++)
            same = f[2 * idx[k]] == r.front_f[2 * k] && f[2 * idx[k] + 1] == r.front_f[2 * k + 1];
        /* and each front point's own objectives are those of its variables */
        for (int k = 0; same && k < m; k++) {
            double v[2];
            gd_opt_zdt_value(GD_OBJ_ZDT1, 5, r.front_y + 5 * k, v);
            same = v[0] == r.front_f[2 * k] && v[1] == r.front_f[2 * k + 1];
        }
        tap_ok(same, "%s: the front is the non-dominated set of every evaluation (%d points), each point's "
               "values its own", an, r.nfront);
        int mono = 1;
        for (long k = 1; k < r.evaluations; k++)
            mono = mono && r.hv_history[k] >= r.hv_history[k - 1];
        double hv = gd_opt_hypervolume(f, (int)r.evaluations, (double[]){1.1, 1.1});
        tap_ok(mono && r.hv == hv && fabs(r.hv_history[r.evaluations - 1] - hv) <= 1e-12 * hv, "%s: the hypervolume "
               "after each evaluation (a running sum) never falls and ends at the front's, %.9g (running %.9g)", an, hv,
               r.hv_history[r.evaluations - 1]);
        free(idx);
        free(f);
        gd_opt_result_free(&r);
    }

    /* ---- MOALO on ZDT1 and ZDT2: within 1 % of the true front's hypervolume ------------------- */
    for (int zi = 0; zi < 2; zi++) {
        int fn = zi ? GD_OBJ_ZDT2 : GD_OBJ_ZDT1;
        double hv_true = gd_opt_zdt_front_hv(fn, (double[]){1.1, 1.1});
        double loss[20], arch[20];
        int ok = 1;
        for (int s = 0; s < 20; s++) {
            gd_error e = {0};
            gd_status st;
            gd_opt_result r = run(fn, 5, GD_OPT_MOALO, 20100, 50, (unsigned long)s + 1, 1, &st, &e);
            ok = ok && st == GD_OK && r.evaluations == 20100 && r.iterations == 401;
            loss[s] = st == GD_OK ? 1.0 - r.hv / hv_true : 1.0;
            arch[s] = st == GD_OK ? 1.0 - r.archive_hv / hv_true : 1.0;
            gd_opt_result_free(&r);
        }
        gsl_sort(loss, 1, 20);
        gsl_sort(arch, 1, 20);
        double med = gsl_stats_median_from_sorted_data(loss, 1, 20);
        double amed = gsl_stats_median_from_sorted_data(arch, 1, 20);
        tap_ok(ok && med <= 0.01, "MOALO on %s (5 variables, 50 ants, 401 iterations, 20 seeds): the median "
               "hypervolume is %.3f %% below the true front's (quartiles %.3f, %.3f %%; tolerance 1 %%); its archive "
               "of 100 alone: median %.2f %% below", zi ? "ZDT2" : "ZDT1", 100 * med,
               100 * gsl_stats_quantile_from_sorted_data(loss, 1, 20, 0.25),
               100 * gsl_stats_quantile_from_sorted_data(loss, 1, 20, 0.75), 100 * amed);
    }

    /* ---- threads: the same points with 1 and 2 ------------------------------------------------- */
    {
        gd_error e = {0};
        gd_status s1, s2;
        gd_opt_result a = run(GD_OBJ_ZDT2, 5, GD_OPT_MOALO, 1020, 20, 7, 1, &s1, &e);
        gd_opt_result b = run(GD_OBJ_ZDT2, 5, GD_OPT_MOALO, 1020, 20, 7, 2, &s2, &e);
        int same = s1 == GD_OK && s2 == GD_OK && a.evaluations == b.evaluations && a.narchive == b.narchive &&
                   memcmp(a.fv_history, b.fv_history, sizeof(double) * 2 * (size_t)a.evaluations) == 0 &&
                   memcmp(a.archive_f, b.archive_f, sizeof(double) * 2 * (size_t)a.narchive) == 0;
        tap_ok(same, "MOALO with 1 and 2 threads: every evaluation and the archive bit for bit");
        gd_opt_result_free(&a);
        gd_opt_result_free(&b);
    }

    /* ---- refusals ------------------------------------------------------------------------------ */
    {
        gd_error e = {0};
        gd_status st;
        gd_opt_result r = run(GD_OBJ_ZDT1, 5, GD_OPT_ALO, 100, 10, 1, 1, &st, &e);
        tap_ok(st == GD_ERR_INPUT, "ALO on two objectives is refused (%s)", e.msg);
        gd_opt_testfn t;
        gd_opt_testfn_init(&t, GD_OBJ_SPHERE, 3, 0, 1, &e);
        gd_opt_problem p;
        gd_opt_testfn_problem(&t, &p);
        gd_opt_settings s;
        gd_opt_settings_default(&s);
        s.algorithm = GD_OPT_MOALO;
        s.budget = 100;
        s.population = 10;
        s.hv_ref[0] = s.hv_ref[1] = 1;
        st = gd_opt_run(&p, &s, &r, &e);
        tap_ok(st == GD_ERR_INPUT, "MOALO on one objective is refused (%s)", e.msg);
        gd_opt_testfn_free(&t);
    }
    return tap_done();
}
