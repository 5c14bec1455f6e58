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
