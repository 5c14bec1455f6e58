/* geardyn run: load the case and run the analysis its scene names. */
#include "cli.h"

#include <stdio.h>
#include <string.h>

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
    int rc = cli_parse_case_args(argc, argv, &a, 1);
    if (rc)
        return rc;
    gd_case c;
    rc = cli_load_case(&a, &c);
    if (rc) {
        gd_case_free(&c);
        return rc;
    }
    char dir[GD_PATH_MAX];
    if (a.out_dir)
        snprintf(dir, sizeof dir, "%s", a.out_dir);
    else if (c.directory[0])
        snprintf(dir, sizeof dir, "%s", c.directory);
    else
        default_out_dir(a.case_path, dir, sizeof dir);
    switch (c.analysis) {
    case GD_ANALYSIS_SWEEP: rc = run_sweep(&a, &c, dir); break;
    case GD_ANALYSIS_TCA: rc = run_tca(&a, &c, dir); break;
    case GD_ANALYSIS_LTCA: rc = run_ltca(&a, &c, dir); break;
    case GD_ANALYSIS_WORK_PRECISION: rc = run_work_precision(&a, &c, dir); break;
    case GD_ANALYSIS_OPTIMIZE: rc = run_optimize(&a, &c, dir); break;
    case GD_ANALYSIS_COMPARE_OPTIMIZERS: rc = run_compare(&a, &c, dir); break;
    case GD_ANALYSIS_RESPONSE:
    default:
        rc = run_response(&a, &c, dir);
        break;
    }
    gd_case_free(&c);
    return rc;
}
