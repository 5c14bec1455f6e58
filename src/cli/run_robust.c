/* The robust variant of an optimize run on the command line (docs/optimisation.md section 12): the
 * robust and the nominal objective of the unmodified flank, the case's own and the optimum. */
#include "cli.h"

#include <stdio.h>

void cli_optimize_robust_report(const gd_case *c, const gd_optimize_outcome *o)
{
    const gd_opt_robust_report *r = o->robust;
    if (!r)
        return;
    const char *unit = o->objective != GD_OBJ_GEAR_DYNAMIC ? "arcsec"
                       : c->opt_dynamic_response == GD_DYN_DTE_PP ? "um" : "m/s^2";
    printf("  robust %s: the %g quantile over %d samples (tilt +-%g arcmin, centre distance +-%g mm, design "
           "+-%g um / +-%g mm; robust.csv)\n", gd_opt_objective_name(o->objective), r->settings.quantile,
           r->settings.samples, r->settings.tilt_arcmin, r->settings.centre_distance_mm, r->settings.amount_um,
           r->settings.length_mm);
    printf("    robust:  unmodified %.6g, the case's modification %.6g, optimum %.6g %s\n", r->robust[0], r->robust[1],
           r->robust[2], unit);
    printf("    nominal: unmodified %.6g, the case's modification %.6g, optimum %.6g %s\n", r->nominal[0],
           r->nominal[1], r->nominal[2], unit);
}
