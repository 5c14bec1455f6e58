/* The comparison of optimisers (docs/optimisation.md section 7): every algorithm the same budget,
 * seeds and problem instances; final values (best, quartiles, median), success rate to a target,
 * evaluations to reach it and the expected running time, runtime distributions over a ladder of
 * targets in the manner of COCO/BBOB, and the convergence quartiles against evaluations. */
#include "opt_internal.h"
#include "../core/gsl_quiet.h"
#include "../core/clock.h"

#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

GD_API void gd_opt_compare_result_free(gd_opt_compare_result *r)
{
    if (!r)
        return;
    if (r->run)
        for (int i = 0; i < r->nalgs * r->runs; i++) {
            free(r->run[i].y);
            free(r->run[i].hits);
            free(r->run[i].best_history);
        }
    free(r->run);
    free(r->stats);
    free(r->targets);
    memset(r, 0, sizeof *r);
}

/* The first evaluation (1-based) whose best is within prec of f_ref, or -1. */
static long first_hit(const gd_opt_compare_run *u, long n, double f_ref, double prec)
{
    if (!(u->best_history[n - 1] - f_ref <= prec))
        return -1;
    long lo = 0, hi = n - 1; /* best_history is non-increasing: bisection */
    while (lo < hi) {
        long mid = lo + (hi - lo) / 2;
        if (u->best_history[mid] - f_ref <= prec)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo + 1;
}

/* The settings make a comparison: counts, targets, known algorithms, one dimension. */
static gd_status compare_check(const gd_opt_problem *const *problems, const gd_opt_compare_settings *s,
                               gd_error *err)
{
    if (s->nalgs < 1 || s->nalgs > GD_OPT_NALGORITHMS || s->runs < 1 || s->budget < 1)
        return gd_error_set(err, GD_ERR_INPUT, "comparison: %d algorithms, %d runs, budget %ld (valid: >= 1 each)",
                            s->nalgs, s->runs, s->budget);
    if (!(s->target > 0) || s->ntargets < 1 || !(s->target_loosest >= s->target) ||
        (s->ntargets > 1 && !(s->target_loosest > s->target)))
        return gd_error_set(err, GD_ERR_INPUT, "comparison: targets %g .. %g, %d of them (valid: 0 < target < "
                            "target_loosest, at least one)", s->target, s->target_loosest, s->ntargets);
    for (int a = 0; a < s->nalgs; a++)
        if (!gd_opt_algorithm_name(s->algs[a]))
            return gd_error_set(err, GD_ERR_INPUT, "comparison: unknown algorithm %d", s->algs[a]);
    int dim = problems[0]->dim;
    for (int k = 1; k < s->runs; k++)
        if (problems[k]->dim != dim)
            return gd_error_set(err, GD_ERR_INPUT, "comparison: instances of different dimensions");
    return GD_OK;
}

/* The result's arrays and every run's algorithm, instance and seed. */
static gd_status compare_alloc(const gd_opt_compare_settings *s, int dim, gd_opt_compare_result *r, gd_error *err)
{
    r->nalgs = s->nalgs;
    r->runs = s->runs;
    r->dim = dim;
    r->budget = s->budget;
    r->target = s->target;
    r->ntargets = s->ntargets;
    int ntask = s->nalgs * s->runs;
    r->run = calloc((size_t)ntask, sizeof *r->run);
    r->stats = calloc((size_t)s->nalgs, sizeof *r->stats);
    r->targets = malloc(sizeof(double) * (size_t)s->ntargets);
    int ok = r->run && r->stats && r->targets;
    for (int i = 0; i < ntask && ok; i++) {
        gd_opt_compare_run *u = &r->run[i];
        u->alg = s->algs[i / s->runs];
        u->run = i % s->runs;
        u->seed = s->seed + (unsigned long)u->run;
        u->y = malloc(sizeof(double) * (size_t)dim);
        u->hits = malloc(sizeof(long) * (size_t)s->ntargets);
        u->best_history = malloc(sizeof(double) * (size_t)s->budget);
        ok = u->y && u->hits && u->best_history;
    }
    if (!ok) {
        gd_opt_compare_result_free(r);
        return gd_error_set(err, GD_ERR_NOMEM, "comparison: out of memory for %d runs of %ld evaluations", ntask,
                            s->budget);
    }
    return GD_OK;
}

/* Every run (algorithm x instance), in parallel; the first failing run in task order is
 * the error. */
static gd_status compare_runs(const gd_opt_problem *const *problems, const gd_opt_compare_settings *s,
                              gd_opt_compare_result *r, gd_error *err)
{
    int dim = r->dim;
    int ntask = s->nalgs * s->runs;
    int nt = opt_threads(s->threads);
    if (nt > ntask)
        nt = ntask;
    opt_first_failure bad;
    opt_first_failure_init(&bad, ntask);
#pragma omp parallel for schedule(dynamic, 1) num_threads(nt)
    for (int i = 0; i < ntask; i++) {
        gd_opt_compare_run *u = &r->run[i];
        gd_opt_settings os;
        gd_opt_settings_default(&os);
        os.algorithm = u->alg;
        os.budget = s->budget;
        os.seed = u->seed;
        os.population = s->population;
        os.threads = 1; /* the runs are the parallel units */
        if (s->local_xtol > 0)
            os.local_xtol = s->local_xtol;
        if (s->local_step > 0)
            os.local_step = s->local_step;
        os.keep_history = 1;
        os.stop = s->stop;
        os.hv_ref[0] = s->hv_ref[0];
        os.hv_ref[1] = s->hv_ref[1];
        if (s->archive > 0)
            os.archive = s->archive;
        if (s->scalar_algorithm > 0)
            os.scalar_algorithm = s->scalar_algorithm;
        if (s->scalar_grid > 0)
            os.scalar_grid = s->scalar_grid;
        gd_opt_result res;
        gd_error e = {0};
        gd_status st = gd_opt_run(problems[u->run], &os, &res, &e);
        if (st != GD_OK) {
            opt_first_failure_note(&bad, i, st, &e);
            continue;
        }
        u->f = res.f;
        memcpy(u->y, res.y, sizeof(double) * (size_t)dim);
        u->evaluations = res.evaluations;
        memcpy(u->best_history, res.best_history, sizeof(double) * (size_t)res.evaluations);
        if (res.nobj == 2) { /* the hypervolume shortfall; the point of the front with the least f1 */
            const double box = s->hv_ref[0] * s->hv_ref[1];
            u->f = box - res.hv;
            for (long k = 0; k < res.evaluations; k++)
                u->best_history[k] = box - res.hv_history[k];
            u->f = u->best_history[res.evaluations - 1]; /* the history's own sum, to the last bit */
            if (res.nfront > 0)
                memcpy(u->y, res.front_y, sizeof(double) * (size_t)dim);
        }
        for (long k = res.evaluations; k < s->budget; k++)
            u->best_history[k] = res.f;
        u->starts = res.starts;
        u->wall_s = res.wall_s;
        gd_opt_result_free(&res);
    }
    opt_first_failure_destroy(&bad);
    if (bad.st != GD_OK) {
        const gd_opt_compare_run *u = &r->run[bad.index];
        if (err)
            *err = bad.err;
        gd_error_prefix(err, "comparison, %s run %d", gd_opt_algorithm_name(u->alg), u->run + 1);
        return bad.st; /* recorded by another thread: this thread's last status is not it */
    }
    return GD_OK;
}

/* The reference value (given, or the best of all runs), the ladder of targets and the
 * evaluations each run took to reach each. */
static void compare_targets(const gd_opt_compare_settings *s, gd_opt_compare_result *r)
{
    int ntask = s->nalgs * s->runs;
    r->f_ref_known = isfinite(s->f_ref);
    r->f_ref = s->f_ref;
    if (!r->f_ref_known) {
        r->f_ref = INFINITY;
        for (int i = 0; i < ntask; i++)
            r->f_ref = fmin(r->f_ref, r->run[i].f);
    }
    for (int k = 0; k < s->ntargets; k++)
        r->targets[k] = s->ntargets == 1 ? s->target
                        : s->target_loosest * pow(s->target / s->target_loosest, (double)k / (s->ntargets - 1));
    r->targets[s->ntargets - 1] = s->target;
    for (int i = 0; i < ntask; i++) {
        gd_opt_compare_run *u = &r->run[i];
        u->evals_to_target = first_hit(u, s->budget, r->f_ref, s->target);
        for (int k = 0; k < s->ntargets; k++)
            u->hits[k] = first_hit(u, s->budget, r->f_ref, r->targets[k]);
    }
}

/* The statistics of algorithm a over its runs; v, w: scratch of s->runs values each. */
static void compare_alg_stats(const gd_opt_compare_settings *s, gd_opt_compare_result *r, int a, double *v,
                              double *w)
{
    gd_opt_alg_stats *S = &r->stats[a];
    const gd_opt_compare_run *U = r->run + (size_t)a * (size_t)s->runs;
    S->alg = s->algs[a];
    int ns = 0;
    double spent = 0;
    for (int k = 0; k < s->runs; k++) {
        v[k] = U[k].f;
        S->wall_total_s += U[k].wall_s;
        if (U[k].evals_to_target > 0) {
            w[ns++] = (double)U[k].evals_to_target;
            spent += (double)U[k].evals_to_target;
        } else {
            spent += (double)U[k].evaluations;
        }
    }
    gsl_sort(v, 1, (size_t)s->runs);
    S->best = v[0];
    S->worst = v[s->runs - 1];
    S->q1 = gsl_stats_quantile_from_sorted_data(v, 1, (size_t)s->runs, 0.25);
    S->median = gsl_stats_median_from_sorted_data(v, 1, (size_t)s->runs);
    S->q3 = gsl_stats_quantile_from_sorted_data(v, 1, (size_t)s->runs, 0.75);
    S->mean = gsl_stats_mean(v, 1, (size_t)s->runs);
    S->successes = ns;
    S->success_rate = (double)ns / s->runs;
    if (ns) {
        gsl_sort(w, 1, (size_t)ns);
        S->evals_to_target_median = gsl_stats_median_from_sorted_data(w, 1, (size_t)ns);
        S->ert = spent / ns;
    } else {
        S->evals_to_target_median = NAN;
        S->ert = NAN;
    }
    S->wall_mean_s = S->wall_total_s / s->runs;
}

GD_API gd_status gd_opt_compare(const gd_opt_problem *const *problems, const gd_opt_compare_settings *s,
                                gd_opt_compare_result *r, gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    memset(r, 0, sizeof *r);
    gd_status st = compare_check(problems, s, err);
    if (st != GD_OK)
        return st;
    double t0 = gd_clock_wall_s();
    if ((st = compare_alloc(s, problems[0]->dim, r, err)) != GD_OK)
        return st;
    if ((st = compare_runs(problems, s, r, err)) != GD_OK) {
        gd_opt_compare_result_free(r);
        return st;
    }
    compare_targets(s, r);
    /* statistics per algorithm */
    double *v = malloc(sizeof(double) * (size_t)s->runs * 2);
    if (!v) {
        gd_opt_compare_result_free(r);
        return gd_error_set(err, GD_ERR_NOMEM, "comparison: out of memory");
    }
    for (int a = 0; a < s->nalgs; a++)
        compare_alg_stats(s, r, a, v, v + s->runs);
    free(v);
    r->wall_s = gd_clock_wall_s() - t0;
    return GD_OK;
}

GD_API void gd_opt_compare_quartiles(const gd_opt_compare_result *r, int a, long evals, double q[3])
{
    q[0] = q[1] = q[2] = NAN;
    if (a < 0 || a >= r->nalgs || evals < 1 || r->runs < 1)
        return;
    if (evals > r->budget)
        evals = r->budget;
    double *v = malloc(sizeof(double) * (size_t)r->runs);
    if (!v)
        return;
    for (int k = 0; k < r->runs; k++)
        v[k] = r->run[(size_t)a * (size_t)r->runs + (size_t)k].best_history[evals - 1] - r->f_ref;
    gsl_sort(v, 1, (size_t)r->runs);
    q[0] = gsl_stats_quantile_from_sorted_data(v, 1, (size_t)r->runs, 0.25);
    q[1] = gsl_stats_median_from_sorted_data(v, 1, (size_t)r->runs);
    q[2] = gsl_stats_quantile_from_sorted_data(v, 1, (size_t)r->runs, 0.75);
    free(v);
}

GD_API double gd_opt_compare_ecdf(const gd_opt_compare_result *const *rs, int nres, int a, long evals)
{
    long hit = 0, all = 0;
    for (int j = 0; j < nres; j++) {
        const gd_opt_compare_result *r = rs[j];
        if (a < 0 || a >= r->nalgs)
            continue;
        for (int k = 0; k < r->runs; k++) {
            const gd_opt_compare_run *u = &r->run[(size_t)a * (size_t)r->runs + (size_t)k];
            for (int t = 0; t < r->ntargets; t++)
                hit += u->hits[t] > 0 && u->hits[t] <= evals;
            all += r->ntargets;
        }
    }
    return all ? (double)hit / (double)all : NAN;
}
