/* The text of every command of the command line, once: printed by `geardyn help COMMAND` and
 * `geardyn COMMAND --help`, and rendered as the man page geardyn(1) by `geardyn help --man`. */
#ifndef GD_CLI_HELP_H
#define GD_CLI_HELP_H

#include <stdio.h>

typedef struct cli_option {
    const char *flags;       /* "--out DIR" */
    const char *text;        /* one paragraph */
} cli_option;

#define CLI_MAX_OPTIONS 8

typedef struct cli_help {
    const char *name;        /* "run" */
    const char *synopsis;    /* the arguments after the name */
    const char *summary;     /* one line */
    const char *description; /* paragraphs separated by an empty line */
    cli_option options[CLI_MAX_OPTIONS];
} cli_help;

/* The text of one command, or NULL. */
const cli_help *cli_help_find(const char *name);
/* The usage of every command (`geardyn --help`). */
void cli_help_usage(FILE *f);
/* One command in full (`geardyn help COMMAND`). */
void cli_help_print(FILE *f, const cli_help *h);
/* The man page geardyn(1) in roff. */
void cli_help_man(FILE *f);
/* geardyn help [COMMAND | --man] */
int cmd_help(int argc, char **argv);

#endif
