/* The geardyn command line: shared helpers of the subcommands. */
#ifndef GD_CLI_H
#define GD_CLI_H

#include <stdio.h>

#include "geardyn/geardyn.h"
#include "gnuplot.h"

#define CLI_MAX_SETS 256

typedef struct cli_case_args {
    const char *case_path;
    const char *sets[CLI_MAX_SETS];
    int nsets;
    const char *out_dir;
    int quiet;
    int resume;              /* run: --resume (sweeps) */
    int threads;             /* run: --threads N (0: the OpenMP default) */
    int check_only;          /* geardyn check: no LTCA, no integration (gd_case.ltca_deferred) */
    gd_run_cost cost;        /* estimated by cli_load_case */
    char dir[GD_PATH_MAX];   /* run: the output directory (--out, output.directory, results/NAME) */
} cli_case_args;

/* Parse CASE [--set s.k=v ...] [--out DIR] [--quiet]; returns 0 or the exit status. */
int cli_parse_case_args(int argc, char **argv, cli_case_args *a, int allow_out);
/* Load, apply --set, resolve, build the model and estimate the run's cost (a->cost), refusing a
 * run above output.max_bytes; prints the error and returns the exit status on failure. For a run,
 * the LTCA of the resolution asks the signals (cli_should_stop): a signal caught meanwhile ends it
 * with the line of an interrupted run and 128 + the signal. */
int cli_load_case(cli_case_args *a, gd_case *c);
/* Parse the arguments of `run` (allow_out) or `check` and load the case they name: 0 with *c loaded
 * (the caller frees it), else the exit status with nothing left to free. */
int cli_open_case(int argc, char **argv, int allow_out, cli_case_args *a, gd_case *c);
int cli_fail(const gd_error *err);
/* The physical values a resolved case takes from the schema's defaults (gd_case_defaulted_keys), one
 * line per section, every line starting with prefix; nothing when there are none. */
void cli_print_defaulted(FILE *f, const gd_case *c, const char *prefix);
/* geardyn check's section of natural frequencies, resonance speeds and strain-energy shares of the
 * case's model m (check_modes.c). */
void cli_check_modes(const gd_case *c, const gd_model *m);
void cli_check_step(const gd_case *c, const gd_run_cost *k);
/* The threads a run uses for --threads N: N when positive, else the OpenMP default (1 without
 * OpenMP). */
int cli_threads(int requested);

/* Signals during a run (signals.c): catch SIGINT, SIGTERM and SIGHUP; the signal caught (0: none);
 * should_stop of gd_run_env; the line and exit status (128 + signal) of an interrupted run. */
void cli_signals_catch(void);
int cli_signal_caught(void);
const char *cli_signal_name(int sig);
int cli_should_stop(void *user);
int cli_interrupted(const char *dir);

/* Progress on stderr while an analysis runs (the user of gd_run_env). */
typedef struct cli_progress {
    int quiet, tty;
    long last_pct;
    const cli_case_args *args;
    char note[GD_ERROR_MSG_MAX]; /* for the end of the run: why there are no pictures ("": none) */
    double t0, last;             /* optimize: the first evaluation's time and the last line's (monotonic s) */
} cli_progress;

/* The command line's part of an analysis of the library's table: what it prints before the run
 * and after it (the progress line's end), its lines on stdout. Any may be NULL. (The pictures are
 * the library's, drawn by the command line's drawer, cli_gnuplot_drawer.) */
typedef struct cli_row {
    int analysis;
    void (*announce)(const char *dir, const gd_case *c);
    void (*after_run)(const cli_progress *p, gd_status st);
    void (*report)(const cli_case_args *a, const char *dir, const gd_case *c, const void *result);
    /* an analysis whose run needs more of the command line (the sweep), which then calls
     * gd_analysis_run_in itself */
    int (*own)(const cli_case_args *a, gd_case *c, const char *dir);
} cli_row;

/* The environment of a run: *p (its user) from the arguments, the command line's hooks of every
 * analysis (progress, the drawer of the pictures and the notes, the lines at the end). */
void cli_run_env(cli_progress *p, const cli_case_args *a, gd_run_env *env);
/* The notes of a run (gd_run_env.note, user a cli_progress): pictures not drawn at once on stderr,
 * no pictures at all kept for the end of the run (printed unless --quiet). */
void cli_note(void *user, int kind, const char *text);
/* Unless quiet, the note that DIR received its files one by one, not in one step, and why
 * (gd_run_dir_fallback, docs/robustness.md). */
void cli_publish_note(const cli_case_args *a, const gd_run_dir *out);

int cli_response_progress(void *user, long done, long total);
void cli_response_after_run(const cli_progress *p, gd_status st);
void cli_response_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result);
void cli_tca_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result);
void cli_ltca_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result);

int cli_workprec_start(void *user, const char *what, const char *label, int index, int total);
int cli_workprec_done(void *user, const char *what, const gd_wp_run *r, const gd_wp_result *res);
void cli_workprec_announce(const char *dir, const gd_case *c);
void cli_workprec_after_run(const cli_progress *p, gd_status st);
void cli_workprec_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result);

void cli_optimize_run(void *user, int run, int runs, unsigned long seed, const gd_opt_result *r);
void cli_optimize_progress(void *user, long done, long total);
void cli_optimize_after_run(const cli_progress *p, gd_status st);
void cli_optimize_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result);
/* after an optimisation over load and speed: bta, the ranking, the Harris map's least (run_optpost.c) */
void cli_optpost_report(const gd_case *c, const gd_optimize_outcome *o);
void cli_optimize_robust_report(const gd_case *c, const gd_optimize_outcome *o);
void cli_optimize_pareto_report(const char *dir, const gd_case *c, const gd_optimize_outcome *o);
void cli_compare_problem(void *user, const gd_compare_entry *q, const gd_opt_compare_settings *s);
void cli_compare_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result);

/* The sweep: the journal and --resume, signals, the progress line and MPI ranks around the row's
 * run (src/cli/run_sweep.c); dir: the output directory. */
int run_sweep(const cli_case_args *a, gd_case *c, const char *dir);

int cmd_run(int argc, char **argv);
/* The continuation: its lines on stdout (run_continuation.c). */
void cli_continuation_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result);
int cli_continuation_progress(void *user, int branches_done, int branches_planned);
/* The basins: progress, signals and MPI ranks around the row's run (run_basins.c) and its lines on
 * stdout. */
int run_basins(const cli_case_args *a, gd_case *c, const char *dir);
void cli_basins_after_run(const cli_progress *p, gd_status st);
void cli_basins_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result);
int cmd_check(int argc, char **argv);
int cmd_events(int argc, char **argv);
int cmd_keys(int argc, char **argv);

#endif
