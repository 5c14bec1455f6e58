/* The geardyn command line: shared helpers of the subcommands. */
#ifndef GD_CLI_H
#define GD_CLI_H

#include "geardyn/geardyn.h"

#define CLI_MAX_SETS 256

typedef struct cli_case_args {
    const char *case_path;
    const char *sets[CLI_MAX_SETS];
    int nsets;
    const char *out_dir;
    int quiet;
} cli_case_args;

/* Parse CASE [--set s.k=v ...] [--out DIR] [--quiet]; returns 0 or the exit status. */
int cli_parse_case_args(int argc, char **argv, cli_case_args *a, int allow_out);
/* Load, apply --set, resolve; prints the error and returns the exit status on failure. */
int cli_load_case(const cli_case_args *a, gd_case *c);
int cli_fail(const gd_error *err);

int cmd_run(int argc, char **argv);
/* The analyses behind `run`, one file each (dir: the output directory, not yet created). */
int run_response(const cli_case_args *a, gd_case *c, const char *dir);
int cmd_check(int argc, char **argv);
int cmd_events(int argc, char **argv);

#endif
