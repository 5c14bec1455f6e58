/* geardyn run: load the case, find its analysis in the library's table (gd_analysis.h), run it,
 * write its tables, draw its pictures, write summary.json and print what it found. The command
 * line's part of each analysis (progress, the lines on stdout) is its row in rows[]; the pictures are
 * the library's, drawn by gnuplot through the drawer the command line gives (cli_gnuplot_drawer). */
#include "cli.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

static const cli_row rows[] = {
    { GD_ANALYSIS_RESPONSE, NULL, cli_response_after_run, cli_response_report, NULL },
    { GD_ANALYSIS_SWEEP, NULL, NULL, NULL, run_sweep },
    { GD_ANALYSIS_TCA, NULL, NULL, cli_tca_report, NULL },
    { GD_ANALYSIS_LTCA, NULL, NULL, cli_ltca_report, NULL },
    { GD_ANALYSIS_OPTIMIZE, NULL, cli_optimize_after_run, cli_optimize_report, NULL },
    { GD_ANALYSIS_COMPARE_OPTIMIZERS, NULL, NULL, cli_compare_report, NULL },
    { GD_ANALYSIS_WORK_PRECISION, cli_workprec_announce, cli_workprec_after_run, cli_workprec_report, NULL },
    { GD_ANALYSIS_CONTINUATION, NULL, NULL, cli_continuation_report, NULL },
    { GD_ANALYSIS_BASINS, NULL, cli_basins_after_run, cli_basins_report, run_basins },
};

static const cli_row *cli_row_for(int analysis)
{
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++)
        if (rows[i].analysis == analysis)
            return &rows[i];
    return NULL;
}

/* The hooks of gd_run_env: each finds the command line's row of the analysis it is called for
 * (an analysis may run another one inside it: optimize runs ltca and tca). */
static void on_ran(void *user, const gd_case *c, gd_status st)
{
    const cli_row *r = cli_row_for(c->analysis);
    if (r && r->after_run)
        r->after_run(user, st);
}

void cli_note(void *user, int kind, const char *text)
{
    cli_progress *p = user;
    if (kind == GD_NOTE_NO_PICTURES)
        snprintf(p->note, sizeof p->note, "%s", text);
    else
        fprintf(stderr, "geardyn: note: %s\n", text);
}

static void on_done(void *user, const gd_case *c, const void *result, gd_run_dir *out)
{
    cli_progress *p = user;
    const cli_row *r = cli_row_for(c->analysis);
    if (p->note[0] && !p->args->quiet)
        fprintf(stderr, "geardyn: note: %s\n", p->note);
    cli_publish_note(p->args, out);
    if (r && r->report)
        r->report(p->args, gd_run_dir_path(out), c, result);
}

void cli_publish_note(const cli_case_args *a, const gd_run_dir *out)
{
    const char *why = gd_run_dir_fallback(out);
    if (why && !a->quiet)
        fprintf(stderr, "geardyn: note: %s: files moved in one by one, not published in one step: %s\n",
                gd_run_dir_path(out), why);
}

void cli_run_env(cli_progress *p, const cli_case_args *a, gd_run_env *env)
{
    *p = (cli_progress){a->quiet, !a->quiet && isatty(2), -1, a, "", 0, 0};
    memset(env, 0, sizeof *env);
    env->user = p;
    env->threads = a->threads;
    env->progress = cli_response_progress;
    env->should_stop = cli_should_stop;
    env->workprec.start = cli_workprec_start;
    env->workprec.done = cli_workprec_done;
    env->optimize_run = cli_optimize_run;
    env->optimize_progress = cli_optimize_progress;
    env->compare_problem = cli_compare_problem;
    env->continuation_branch = cli_continuation_progress;
    env->draw = cli_gnuplot_drawer;
    env->note = cli_note;
    env->ran = on_ran;
    env->done = on_done;
}

/* Run the analysis of a resolved case through its row of the library's table. */
static int run_row(const cli_case_args *a, const gd_case *c, const gd_analysis_type *t, const cli_row *r,
                   const char *dir)
{
    gd_error err = {0};
    cli_progress p;
    gd_run_env env;
    cli_run_env(&p, a, &env);
    if (r->announce && !a->quiet)
        r->announce(dir, c);
    gd_status st = gd_analysis_run_in(t, c, &env, dir, &err);
    if (st != GD_OK && cli_signal_caught())
        return cli_interrupted(dir);
    return st == GD_OK ? 0 : cli_fail(&err);
}

int cmd_run(int argc, char **argv)
{
    cli_case_args a;
    gd_case c;
    cli_signals_catch(); /* from the start: the case's resolution may run an LTCA */
    int rc = cli_open_case(argc, argv, 1, &a, &c);
    if (rc)
        return rc;
    const char *dir = a.dir;
    if (!a.quiet)
        cli_print_defaulted(stderr, &c, "geardyn: ");
    if (a.cost.seconds > 60 && !a.quiet) { /* a long run says so before it starts */
        char est[200];
        gd_run_cost_format(&a.cost, est, sizeof est);
        fprintf(stderr, "geardyn: this run is estimated at %s (limit run.max_time_s = %.4g s)\n", est, c.max_time_s);
    }
    const gd_analysis_type *t = gd_analysis_find(c.analysis); /* gd_case_resolve refused a case without one */
    static const cli_row plain = {0}; /* an analysis the command line has no pictures or lines for */
    const cli_row *r = cli_row_for(c.analysis);
    if (r && r->own)
        rc = r->own(&a, &c, dir);
    else
        rc = run_row(&a, &c, t, r ? r : &plain, dir);
    gd_case_free(&c);
    return rc;
}
