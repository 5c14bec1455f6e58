/* geardyn run: load the case and run the analysis its scene names, through the command line's
 * row of that analysis (each row: the library's analysis, its files and pictures). */
#include "cli.h"

#include <stdio.h>
#include <string.h>

typedef int (*cli_runner)(const cli_case_args *a, gd_case *c, const char *dir);

/* One row per analysis of the library's table (gd_analysis.h). */
static const struct {
    int analysis;
    cli_runner run;
} runners[] = {
    { GD_ANALYSIS_RESPONSE, run_response },
    { GD_ANALYSIS_SWEEP, run_sweep },
    { GD_ANALYSIS_TCA, run_tca },
    { GD_ANALYSIS_LTCA, run_ltca },
    { GD_ANALYSIS_OPTIMIZE, run_optimize },
    { GD_ANALYSIS_COMPARE_OPTIMIZERS, run_compare },
    { GD_ANALYSIS_WORK_PRECISION, run_work_precision },
    { GD_ANALYSIS_CONTINUATION, run_continuation },
};

/* The runner of a resolved case's analysis (gd_case_resolve refused any other). */
static cli_runner cli_runner_for(int analysis)
{
    for (size_t i = 0; i < sizeof runners / sizeof runners[0]; i++)
        if (runners[i].analysis == analysis)
            return runners[i].run;
    return run_response;
}

static void default_out_dir(const char *case_path, char *out, size_t len)
{
    const char *base = strrchr(case_path, '/');
    base = base ? base + 1 : case_path;
    size_t l = strlen(base);
    if (l > 4 && strcmp(base + l - 4, ".ini") == 0)
        l -= 4;
    snprintf(out, len, "results/%.*s", (int)l, base);
}

int cmd_run(int argc, char **argv)
{
    cli_case_args a;
    gd_case c;
    int rc = cli_open_case(argc, argv, 1, &a, &c);
    if (rc)
        return rc;
    char dir[GD_PATH_MAX];
    if (a.out_dir)
        snprintf(dir, sizeof dir, "%s", a.out_dir);
    else if (c.directory[0])
        snprintf(dir, sizeof dir, "%s", c.directory);
    else
        default_out_dir(a.case_path, dir, sizeof dir);
    rc = cli_runner_for(c.analysis)(&a, &c, dir);
    gd_case_free(&c);
    return rc;
}
