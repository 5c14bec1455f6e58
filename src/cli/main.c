/* geardyn: the command-line tool. Dispatches to the subcommands. */
#include "cli.h"
#include "sweep_mpi.h"

#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *usage =
    "usage: geardyn COMMAND [ARGS]\n"
    "\n"
    "  geardyn run CASE [--set section.key=value ...] [--out DIR] [--quiet]\n"
    "                   [--threads N] [--resume]\n"
    "        run the scene of a case file; results, tables and pictures go to DIR\n"
    "        (default: [output] directory, else results/<case name>)\n"
    "        sweeps: --threads N OpenMP threads (default: all), --resume finishes an\n"
    "        interrupted sweep; mpirun -n N geardyn run ... spreads one over N ranks\n"
    "  geardyn check CASE [--set section.key=value ...]\n"
    "        validate a case and print every resolved parameter with its unit and source\n"
    "  geardyn events FILE [--from S] [--to S] [--clearance NAME] [--kind KIND]\n"
    "                      [--recorded] [--csv OUT]\n"
    "        summarise an event log (events.csv): counts per clearance and kind, impact\n"
    "        regime, impact velocities; filter by time window, clearance and kind\n"
    "  geardyn --help | --version\n"
    "\n"
    "Exit status: 0 success, 2 bad input (case file, option, value), 1 any other failure.\n";

int cli_fail(const gd_error *err)
{
    if (cli_mpi_rank() > 0 && (err->code == GD_ERR_INPUT || err->code == GD_ERR_GEOMETRY))
        return gd_status_exit_code(err->code); /* every rank reads the same case: rank 0 says it */
    fprintf(stderr, "geardyn: %s\n", err->msg);
    return gd_status_exit_code(err->code);
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
#if GD_HAVE_MPI
    if (cli_mpi_init(&argc, &argv) != 0) /* only when started by mpirun */
        return 1;
    atexit(cli_mpi_finalize);
#endif
    if (argc < 2) {
        fputs(usage, stderr);
        return 2;
    }
    const char *cmd = argv[1];
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
        fputs(usage, stdout);
        return 0;
    }
    if (strcmp(cmd, "--version") == 0) {
        printf("geardyn %s (OpenMP %s, MPI %s)\n%s\n", GD_VERSION_STRING, GD_HAVE_OPENMP ? "on" : "off",
               GD_HAVE_MPI ? "on" : "off", GD_SUNDIALS_BUILD);
        return 0;
    }
    if (strcmp(cmd, "run") == 0)
        return cmd_run(argc - 1, argv + 1);
    if (strcmp(cmd, "check") == 0)
        return cmd_check(argc - 1, argv + 1);
    if (strcmp(cmd, "events") == 0)
        return cmd_events(argc - 1, argv + 1);
    fprintf(stderr, "geardyn: unknown command '%s'\n\n%s", cmd, usage);
    return 2;
}
