/* The `compare-optimizers` analysis on the command line (docs/optimisation.md section 7): the
 * statistics of each problem as it finishes, the convergence and runtime-distribution pictures,
 * the summary line. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *obj_name(const gd_compare_entry *q) { return gd_opt_objective_name(q->objective); }

/* The progress report of one problem: the statistics of each optimiser. */
void cli_compare_problem(void *user, const gd_compare_entry *q, const gd_opt_compare_settings *s)
{
    const cli_progress *o = user;
    if (o->quiet)
        return;
    if (q->nobj == 2) { /* the hypervolume of each run's front: the reference box less its shortfall */
        const double box = q->hv_ref[0] * q->hv_ref[1];
        printf("%s, d = %d: %d optimisers x %d runs x %ld evaluations in %.1f s; the hypervolume within (%g, %g), "
               "%.8g for %s\n", obj_name(q), q->dim, s->nalgs, s->runs, s->budget, q->res.wall_s, q->hv_ref[0],
               q->hv_ref[1], box - q->res.f_ref, q->res.f_ref_known ? "the true front" : "the best run");
        printf("  %-14s %12s %12s %12s %12s %8s %10s %10s\n", "optimizer", "best HV", "median HV", "IQR", "worst HV",
               "success", "ERT evals", "wall s");
        for (int k = 0; k < s->nalgs; k++) {
            const gd_opt_alg_stats *S = &q->res.stats[k];
            printf("  %-14s %12.6g %12.6g %12.4g %12.6g %7.0f%% %10.4g %10.3g\n", gd_opt_algorithm_name(S->alg),
                   box - S->best, box - S->median, S->q3 - S->q1, box - S->worst, 100 * S->success_rate, S->ert,
                   S->wall_mean_s);
        }
        fflush(stdout);
        return;
    }
    printf("%s, d = %d%s: %d optimisers x %d runs x %ld evaluations in %.1f s; f_ref %.8g (%s)\n", obj_name(q),
           q->dim, q->shift > 0 ? " (shifted)" : "", s->nalgs, s->runs, s->budget, q->res.wall_s, q->res.f_ref,
           q->res.f_ref_known ? "the minimum" : "best found");
    printf("  %-12s %12s %12s %12s %12s %8s %10s %10s\n", "optimizer", "best", "median", "IQR", "worst",
           "success", "ERT evals", "wall s");
    for (int k = 0; k < s->nalgs; k++) {
        const gd_opt_alg_stats *S = &q->res.stats[k];
        printf("  %-12s %12.6g %12.6g %12.4g %12.6g %7.0f%% %10.4g %10.3g\n", gd_opt_algorithm_name(S->alg),
               S->best, S->median, S->q3 - S->q1, S->worst, 100 * S->success_rate, S->ert, S->wall_mean_s);
    }
    fflush(stdout);
}

void cli_compare_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    (void)c;
    const gd_compare_outcome *C = result;
    if (!a->quiet)
        printf("%s: %d problem%s compared in %.1f s on %d thread%s\n", dir, C->n, C->n == 1 ? "" : "s", C->wall_s,
               C->threads, C->threads == 1 ? "" : "s");
}
