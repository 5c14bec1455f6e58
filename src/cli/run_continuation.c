/* The `continuation` analysis on the command line: the library's run, its tables and summary.json,
 * the picture (continuation_plot.c) and a few lines on stdout. */
#include "cli.h"

#include <stdio.h>

static int progress(void *user, int done, int planned)
{
    const cli_case_args *a = user;
    if (!a->quiet)
        fprintf(stderr, "geardyn: continuation: %d of %d branches\n", done, planned);
    return 0;
}

static void report(const char *dir, const gd_contin_result *res)
{
    printf("%s: continuation in %s from %.10g (period %d%s): %d branches, %ld corrections, %.2f Newton iterations "
           "per correction, %.2f s CPU\n", dir, res->parameter, res->start_value, res->nper_start,
           res->period_found ? ", found" : "", res->nbranches, res->corrections,
           res->corrections ? (double)res->newton_iterations / (double)res->corrections : 0.0, res->cpu_s);
    for (int b = 0; b < res->nbranches; b++) {
        const gd_branch *br = &res->branch[b].br;
        printf("  branch %d, period %d, %s: %d points to %.10g (%s)\n", b, res->branch[b].nper,
               res->branch[b].direction > 0 ? "up" : "down", br->npoints,
               gd_contin_value(res, br->pt[br->npoints - 1].orbit.p), br->end_reason);
        for (int i = 0; i < br->nbif; i++)
            printf("    %s%s%s at %.10g\n", gd_bif_kind_name(br->bif[i].kind), br->bif[i].clearance >= 0 ? " of " : "",
                   br->bif[i].clearance >= 0 ? res->clear_name[br->bif[i].clearance] : "",
                   gd_contin_value(res, br->bif[i].p));
    }
    for (int i = 0; i < res->nnotes; i++)
        printf("  note: %s\n", res->notes[i]);
}

int run_continuation(const cli_case_args *a, gd_case *c, const char *dir)
{
    gd_error err = {0};
    gd_contin_result res;
    if (gd_contin_run(c, progress, (void *)a, &res, &err) != GD_OK)
        return cli_fail(&err);
    const char *files[8] = {"branch.csv", "bifurcations.csv"};
    int nfiles = 2;
    gd_status st = gd_mkdir_p(dir, &err);
    if (st == GD_OK)
        st = gd_contin_write_tables(dir, c, &res, &err);
    const char *note = NULL;
    if (st == GD_OK && gd_gnuplot_wanted(c->plots, &note)) {
        gd_error perr = {0};
        gd_status pst = cli_continuation_draw(dir, c, &res, &perr);
        static const char *pics[] = {"continuation.png", "continuation.svg"};
        gd_gnuplot_drawn(pst, &perr, pics, 2, files, &nfiles);
    }
    if (st == GD_OK)
        st = gd_contin_write_summary(dir, c, &res, files, nfiles, &err);
    if (st == GD_OK && !a->quiet) {
        if (note)
            fprintf(stderr, "geardyn: note: %s\n", note);
        report(dir, &res);
    }
    gd_contin_result_free(&res);
    return st == GD_OK ? 0 : cli_fail(&err);
}
