/* The `tca` analysis on the command line: the summary lines (the pictures are the library's:
 * src/plot/plot_tca.c). */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *half_name[2] = {"left", "right"};

void cli_tca_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    const gd_tca_result *r = result;
    if (a->quiet)
        return;
    printf("%s: TCA, %d positions per half, GTE peak-to-peak", dir, r->npos);
    for (int h = 0; h < r->halves; h++)
        printf(" %s %.6g arcsec%s", half_name[h], r->gte_pp_arcsec[h], h + 1 < r->halves ? "," : "");
    printf("; edge contact");
    for (int h = 0; h < r->halves; h++)
        printf(" %s %s", half_name[h], r->edge_kinds[h] ? "yes" : "no");
    printf("\n  operating pressure angle %.6g deg, %ld Newton iterations, %.3f s\n", r->alpha_op_mean * 180 / M_PI,
           r->iterations, r->wall_s);
    if (c->tca_formulation == GD_TCA_BOTH)
        printf("  formulations (a) and (b): %d of %d positions compared, largest difference %.3g arcsec\n",
               r->compared, r->npos * r->halves, r->max_diff_arcsec);
}
