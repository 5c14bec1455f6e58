/* The `ltca` analysis on the command line: pictures of the load distribution on the unrolled
 * flank and of the LTE, GTE and mesh stiffness, and the summary lines (docs/ltca.md). */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *half_name[2] = {"left", "right"};

void cli_ltca_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    const gd_ltca_result *r = result;
    if (a->quiet)
        return;
    /* ISO 6336-1's mean mesh stiffness of one mesh, beside LTCA's (the same as check's default) */
    double iso = NAN;
    gd_geometry g;
    gd_error e = {0};
    const gd_pair pair = gd_pair_from_case(c);
    if (gd_geometry_compute(&pair, &g, &e) == GD_OK)
        iso = gd_iso6336_mesh_stiffness(&pair, &g);
    printf("%s: LTCA, %d positions, %d slices per half, %s pinion, %.6g N m: LTE %.6g arcsec p-p\n", dir, r->npos,
           r->nslices, r->floating ? "floating" : "fixed", r->torque_nm, r->lte_pp_arcsec);
    for (int h = 0; h < r->halves; h++) {
        printf("  %-5s mean mesh stiffness %.6g N/m (%.4g .. %.4g; ISO 6336-1 %.4g), load share %.4f, max pressure "
               "%.0f MPa, edge loading %s", half_name[h], r->stiffness_mean[h], r->stiffness_min[h],
               r->stiffness_max[h], iso, r->load_share[h], r->pressure_max[h] * 1e-6, r->edge_positions[h] ? "yes" : "no");
        if (r->edge_positions[h])
            printf(" at %d of %d positions (face-end line load up to %.3g x its line's mean)", r->edge_positions[h],
                   r->npos, r->edge_ratio_max[h]);
        if (r->tip_positions[h])
            printf(", tip contact at %d of %d positions", r->tip_positions[h], r->npos);
        printf("\n");
    }
    printf("  %ld active-set iterations, largest residual %.3g m, %.3f s\n", r->iterations, r->max_residual,
           r->wall_s);
}
