/* The text of every command, and its two renderings: the terminal and the man page. */
#include "help.h"

#include <stdio.h>
#include <string.h>

static const cli_help commands[] = {
    {"run", "CASE [--set section.key=value ...] [--out DIR] [--quiet] [--threads N] [--resume]",
     "run the analysis of a case file and write its tables and pictures",
     "Reads CASE, applies the --set assignments in order, checks every key and runs the analysis "
     "named by [scene] analysis: response, sweep, tca, ltca, optimize, compare-optimizers, "
     "work-precision, continuation or basins. The results go to DIR: --out, else [output] directory, else "
     "results/<case name>.\n\n"
     "The run locks DIR (a second run into it is refused), writes its files into a stage beside "
     "it (.NAME.geardyn-stage in DIR's parent) and exchanges the stage and DIR in one step when "
     "the whole run has succeeded (file by file, with a note saying why, where DIR cannot be "
     "exchanged: --out ., a mount point), keeping the other files of DIR; a failed or interrupted run "
     "(SIGINT, SIGTERM, SIGHUP: exit 130, 143, 129) leaves DIR as it was. "
     "Pictures are drawn with gnuplot when it is installed.\n\n"
     "A sweep started by mpirun -n N geardyn run CASE (geardyn built with -Dmpi=enabled) spreads "
     "its points over the N ranks, and basins over a parameter its values; rank 0 writes the same "
     "files as a serial run.",
     {{"--set section.key=value", "override one key of the case (repeatable; -s is the short form)"},
      {"--out DIR", "the output directory"},
      {"--quiet", "print nothing but errors"},
      {"--threads N", "OpenMP threads of a sweep, basins, an optimisation or an optimiser comparison "
                      "(default: all cores); 1 or N threads give identical files"},
      {"--resume", "finish an interrupted sweep: only the points missing from DIR/.sweep.journal run"}}},
    {"check", "CASE [--set section.key=value ...]",
     "validate a case and print every resolved key with its unit and source",
     "Prints every key of the schema with its value, its unit and where the value came from: "
     "'file line N' (written in CASE), '--set #N' (the Nth --set), 'default' (the schema's "
     "default) or 'derived' (computed from other keys, such as the masses from the geometry). "
     "Then the derived geometry (ISO 21771: radii, contact ratios, centre distance) and the model "
     "scales (natural and mesh frequency, static mesh force and deflection), then the modes of the "
     "model linearised at its static operating point: natural frequencies, the pinion speeds of their "
     "main and superharmonic (1/2, 1/3, 1/4) resonances, the share of each mesh and support in each "
     "mode's strain energy. Nothing is written.",
     {{"--set section.key=value", "override one key of the case (repeatable)"}}},
    {"events", "FILE [--from S] [--to S] [--clearance NAME] [--kind KIND] [--recorded] [--csv OUT]",
     "summarise, filter and export an event log (events.csv of a response run)",
     "Prints the number of events per clearance and kind, the impact regime (no impact, single-sided, "
     "double-sided) and the statistics of the relative velocity at contact, for the rows that pass "
     "the filters.",
     {{"--from S", "only events at or after time S (seconds)"},
      {"--to S", "only events at or before time S (seconds)"},
      {"--clearance NAME", "only one clearance, as named in the log: mesh (torsional), mesh-L, mesh-R, bearing-1L, bearing-1R, bearing-2L, bearing-2R"},
      {"--kind KIND", "only one kind: contact, separation, back-contact or back-separation"},
      {"--recorded", "only the recorded window (no transient)"},
      {"--csv OUT", "also write the selected rows to OUT"}}},
    {"keys", "[--markdown]",
     "print every key of a case file: section, unit, type, valid range, default, meaning",
     "The table comes from the schema the case reader uses, so it is complete and current. "
     "docs/case-keys.md is its --markdown form.",
     {{"--markdown", "print a Markdown table"}}},
    {"help", "[COMMAND | --man]",
     "print the text of one command, or the man page",
     "Without an argument, the usage of every command. geardyn COMMAND --help prints the same "
     "text as geardyn help COMMAND.",
     {{"--man", "print the man page geardyn(1) in roff"}}},
};

static const size_t ncommands = sizeof commands / sizeof commands[0];

static const char *exit_status =
    "0 success; 2 bad input (case file, option or value: one message naming file, line, key and "
    "valid range, nothing written); 1 any other failure (solver failure, chattering, endless "
    "tooth separation).";

const cli_help *cli_help_find(const char *name)
{
    for (size_t i = 0; i < ncommands; i++)
        if (strcmp(commands[i].name, name) == 0)
            return &commands[i];
    return NULL;
}

/* Print text folded at width columns, each line starting with indent spaces. */
static void fold(FILE *f, const char *text, int indent, int width)
{
    const char *p = text;
    while (*p) {
        if (*p == '\n') { /* an empty line between paragraphs */
            fputc('\n', f);
            p++;
            continue;
        }
        int col = indent;
        fprintf(f, "%*s", indent, "");
        int first = 1;
        while (*p && *p != '\n') {
            size_t w = strcspn(p, " \n");
            if (!first && col + 1 + (int)w > width)
                break;
            fprintf(f, "%s%.*s", first ? "" : " ", (int)w, p);
            col += (first ? 0 : 1) + (int)w;
            first = 0;
            p += w;
            while (*p == ' ')
                p++;
        }
        fputc('\n', f);
        if (*p == '\n')
            p++;
    }
}

void cli_help_usage(FILE *f)
{
    fputs("usage: geardyn COMMAND [ARGS]\n\n", f);
    for (size_t i = 0; i < ncommands; i++) {
        fprintf(f, "  geardyn %s %s\n", commands[i].name, commands[i].synopsis);
        fold(f, commands[i].summary, 8, 96);
    }
    fputs("  geardyn --version\n\n"
          "geardyn help COMMAND (or geardyn COMMAND --help) explains one command.\n\n",
          f);
    fputs("Exit status:\n", f);
    fold(f, exit_status, 2, 96);
}

void cli_help_print(FILE *f, const cli_help *h)
{
    fprintf(f, "usage: geardyn %s %s\n\n", h->name, h->synopsis);
    fold(f, h->summary, 0, 96);
    fputc('\n', f);
    fold(f, h->description, 0, 96);
    if (h->options[0].flags) {
        fputs("\noptions:\n", f);
        for (int i = 0; i < CLI_MAX_OPTIONS && h->options[i].flags; i++) {
            fprintf(f, "  %s\n", h->options[i].flags);
            fold(f, h->options[i].text, 8, 96);
        }
    }
    fputs("\nexit status:\n", f);
    fold(f, exit_status, 2, 96);
}

/* Text in roff: a hyphen is \-, and a line never starts with a dot or an apostrophe. */
static void roff(FILE *f, const char *text)
{
    int bol = 1;
    for (const char *p = text; *p; p++) {
        if (bol && (*p == '.' || *p == '\''))
            fputs("\\&", f);
        if (*p == '-')
            fputs("\\-", f);
        else if (*p == '\\')
            fputs("\\e", f);
        else if (*p == '\n' && p[1] == '\n') {
            fputs("\n.PP\n", f);
            p++;
            bol = 1;
            continue;
        } else
            fputc(*p, f);
        bol = *p == '\n';
    }
    fputc('\n', f);
}

void cli_help_man(FILE *f)
{
    fputs(".TH GEARDYN 1 \"\" \"geardyn\" \"User Commands\"\n"
          ".SH NAME\ngeardyn \\- nonlinear dynamics of gear pairs\n.SH SYNOPSIS\n",
          f);
    for (size_t i = 0; i < ncommands; i++) {
        fprintf(f, "%s.B geardyn %s\n", i ? ".br\n" : "", commands[i].name);
        roff(f, commands[i].synopsis);
    }
    fputs(".SH DESCRIPTION\n", f);
    roff(f, "geardyn reads a case file (INI: sections of keys, each with its unit) describing a gear "
            "pair and an analysis, and writes tables, an event log, summary.json and pictures. "
            "geardyn keys lists every key; the user guide is docs/guide.md of the source tree.");
    fputs(".SH COMMANDS\n", f);
    for (size_t i = 0; i < ncommands; i++) {
        const cli_help *h = &commands[i];
        fprintf(f, ".SS \"%s\"\n.B geardyn %s\n", h->name, h->name);
        roff(f, h->synopsis);
        fputs(".PP\n", f);
        roff(f, h->summary);
        fputs(".PP\n", f);
        roff(f, h->description);
        for (int j = 0; j < CLI_MAX_OPTIONS && h->options[j].flags; j++) {
            fputs(".TP\n.B ", f);
            roff(f, h->options[j].flags);
            roff(f, h->options[j].text);
        }
    }
    fputs(".SH EXIT STATUS\n", f);
    roff(f, exit_status);
}

int cmd_help(int argc, char **argv)
{
    if (argc < 2) {
        cli_help_usage(stdout);
        return 0;
    }
    if (strcmp(argv[1], "--man") == 0) {
        cli_help_man(stdout);
        return 0;
    }
    const cli_help *h = cli_help_find(argv[1]);
    if (!h) {
        fprintf(stderr, "geardyn: help: unknown command '%s'\n\n", argv[1]);
        cli_help_usage(stderr);
        return 2;
    }
    cli_help_print(stdout, h);
    return 0;
}
