/* The `continuation` analysis on the command line: progress per branch and the branches,
 * bifurcations and curves found, on stdout (the pictures are the library's: src/plot/). */
#include "cli.h"

#include <stdio.h>

int cli_continuation_progress(void *user, int done, int planned)
{
    const cli_progress *p = user;
    if (!p->quiet)
        fprintf(stderr, "geardyn: continuation: %d of %d branches\n", done, planned);
    return 0;
}

void cli_continuation_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    (void)c;
    const gd_contin_result *res = result;
    if (a->quiet)
        return;
    printf("%s: continuation in %s from %.10g (period %d%s%s%s): %d branches, %ld corrections, %.2f Newton "
           "iterations per correction, %.2f s CPU\n", dir, res->parameter, res->start_value, res->nper_start,
           res->period_found ? ", found" : "", res->start_source[0] ? ", the point of " : "", res->start_source,
           res->nbranches, res->corrections,
           res->corrections ? (double)res->newton_iterations / (double)res->corrections : 0.0, res->cpu_s);
    for (int b = 0; b < res->nbranches; b++) {
        const gd_branch *br = &res->branch[b].br;
        printf("  branch %d, period %d, %s: %d points to %.10g (%s)\n", b, res->branch[b].nper,
               res->branch[b].direction > 0 ? "up" : "down", br->npoints,
               gd_contin_value(res, br->pt[br->npoints - 1].orbit.p), res->branch[b].end_reason);
        for (int i = 0; i < br->nbif; i++)
            printf("    %s%s%s at %.10g%s%s%s\n", gd_bif_kind_name(br->bif[i].kind),
                   br->bif[i].clearance >= 0 ? " of " : "",
                   br->bif[i].clearance >= 0 ? res->clear_name[br->bif[i].clearance] : "",
                   gd_contin_value(res, br->bif[i].p), br->bif[i].location != GD_LOC_LOCATED ? " (location: " : "",
                   br->bif[i].location != GD_LOC_LOCATED ? gd_bif_location_name(br->bif[i].location) : "",
                   br->bif[i].location != GD_LOC_LOCATED ? ")" : "");
    }
    for (int i = 0; i < res->ncurves; i++) {
        const gd_curve *cv = &res->curve[i].cv;
        const gd_curve_point *z = &cv->pt[cv->npoints - 1];
        char from[GD_PATH_MAX + 112];
        if (res->curve[i].branch >= 0)
            snprintf(from, sizeof from, "branch %d", res->curve[i].branch);
        else
            snprintf(from, sizeof from, "%s", res->curve_start);
        printf("  curve %d, %s%s%s, period %d, from %s, %s in %s: %d points to (%.10g, %.10g) (%s)\n", i,
               gd_curve_kind_name(cv->kind), cv->clearance >= 0 ? " of " : "",
               cv->clearance >= 0 ? res->clear_name[cv->clearance] : "", cv->nper, from,
               res->curve[i].direction > 0 ? "up" : "down", res->parameter2, cv->npoints, gd_contin_value(res, z->orbit.p),
               z->p2 * res->scale2, cv->end_reason);
    }
    for (int i = 0; i < res->nnotes; i++)
        printf("  note: %s\n", res->notes[i]);
}
