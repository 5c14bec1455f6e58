/* The geardyn command line: shared helpers of the subcommands. */
#ifndef GD_CLI_H
#define GD_CLI_H

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
} cli_case_args;

/* Parse CASE [--set s.k=v ...] [--out DIR] [--quiet]; returns 0 or the exit status. */
int cli_parse_case_args(int argc, char **argv, cli_case_args *a, int allow_out);
/* Load, apply --set, resolve; prints the error and returns the exit status on failure. */
int cli_load_case(const cli_case_args *a, gd_case *c);
/* Parse the arguments of `run` (allow_out) or `check` and load the case they name: 0 with *c loaded
 * (the caller frees it), else the exit status with nothing left to free. */
int cli_open_case(int argc, char **argv, int allow_out, cli_case_args *a, gd_case *c);
int cli_fail(const gd_error *err);
/* The threads a run uses for --threads N: N when positive, else the OpenMP default (1 without
 * OpenMP). */
int cli_threads(int requested);

/* The response variable of the local analysis ([output] response_variable). */
typedef struct cli_variable {
    int kind, index;
    char name[32];
} cli_variable;

typedef struct cli_local {
    cli_variable var;
    double *t, *x, *xd;      /* uniform samples: s, um, m/s */
    size_t n, cap;
    double *px, *pxd;        /* Poincare points */
    size_t np, pcap;
    double spec_amax;        /* largest spectral amplitude (for the plot's floor) */
} cli_local;

int cli_variable_resolve(const gd_case *c, const gd_model *m, cli_variable *v, gd_error *err);
void cli_variable_value(const gd_model *m, const cli_variable *v, double t, const double *y, double *x, double *xdot);
int cli_local_add_sample(cli_local *L, double t_s, double x, double xdot);
int cli_local_add_poincare(cli_local *L, double x, double xdot);
void cli_local_free(cli_local *L);
gd_status cli_local_write(const char *dir, const gd_case *c, const gd_model *m, const gd_response_result *r,
                          cli_local *L, const char **files, int *nfiles, int draw, gd_error *err);

int cmd_run(int argc, char **argv);
/* The analyses behind `run`, one file each (dir: the output directory, not yet created). */
int run_response(const cli_case_args *a, gd_case *c, const char *dir);
int run_tca(const cli_case_args *a, gd_case *c, const char *dir);
int run_ltca(const cli_case_args *a, gd_case *c, const char *dir);
int run_sweep(const cli_case_args *a, gd_case *c, const char *dir);
int run_work_precision(const cli_case_args *a, gd_case *c, const char *dir);
int run_optimize(const cli_case_args *a, gd_case *c, const char *dir);
int run_compare(const cli_case_args *a, gd_case *c, const char *dir);
int run_continuation(const cli_case_args *a, gd_case *c, const char *dir);
/* continuation.png and .svg into dir (continuation_plot.c). */
gd_status cli_continuation_draw(const char *dir, const gd_case *c, const gd_contin_result *res, gd_error *err);
int cmd_check(int argc, char **argv);
int cmd_events(int argc, char **argv);
int cmd_keys(int argc, char **argv);

#endif
