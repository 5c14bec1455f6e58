/* geardyn: the command-line tool. Dispatches to the subcommands. */
#include "cli.h"
#include "help.h"
#include "sweep_mpi.h"

#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The commands; their text is in help.c. */
static const struct {
    const char *name;
    int (*fn)(int argc, char **argv);
} commands[] = {
    {"run", cmd_run}, {"check", cmd_check}, {"events", cmd_events}, {"keys", cmd_keys}, {"help", cmd_help},
};

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
        cli_help_usage(stderr);
        return 2;
    }
    const char *cmd = argv[1];
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0) {
        cli_help_usage(stdout);
        return 0;
    }
    if (strcmp(cmd, "--version") == 0) {
        printf("geardyn %s (OpenMP %s, MPI %s)\n%s\n", GD_VERSION_STRING, GD_HAVE_OPENMP ? "on" : "off",
               GD_HAVE_MPI ? "on" : "off", GD_SUNDIALS_BUILD);
        return 0;
    }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        if (strcmp(cmd, commands[i].name) != 0)
            continue;
        if (argc > 2 && (strcmp(argv[2], "--help") == 0 || strcmp(argv[2], "-h") == 0)) {
            cli_help_print(stdout, cli_help_find(cmd));
            return 0;
        }
        return commands[i].fn(argc - 1, argv + 1);
    }
    fprintf(stderr, "geardyn: unknown command '%s'\n\n", cmd);
    cli_help_usage(stderr);
    return 2;
}
