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

/* Two objectives: the front of the best run, its hypervolume, its ends, and for the gear the unmodified
 * flank and the case's own beside it. */
void cli_optimize_pareto_report(const char *dir, const gd_case *c, const gd_optimize_outcome *o)
{
    const gd_opt_pareto_report *P = o->pareto;
    const gd_opt_result *b = &P->res[P->best];
    printf("%s: %s on %s%s%s, %d variable%s, %d run%s of %ld evaluations (%.1f s, %d thread%s): %d non-dominated "
           "points, hypervolume %.8g within (%g, %g)\n", dir, gd_opt_algorithm_name(c->opt_algorithm),
           gd_opt_objective_name(P->objective), P->gear ? " and " : "",
           P->gear ? gd_opt_objective_name(P->objective2) : "", o->dim, o->dim == 1 ? "" : "s", P->runs,
           P->runs == 1 ? "" : "s", b->evaluations, o->wall_s, o->threads, o->threads == 1 ? "" : "s", b->nfront,
           b->hv, P->hv_ref[0], P->hv_ref[1]);
    if (b->nfront > 0)
        printf("  the front from %s %.6g, %s %.6g to %s %.6g, %s %.6g (pareto.csv)\n", P->column[0], b->front_f[0],
               P->column[1], b->front_f[1], P->column[0], b->front_f[2 * (b->nfront - 1)], P->column[1],
               b->front_f[2 * (b->nfront - 1) + 1]);
    if (P->gear)
        for (int j = 0; j < 2; j++)
            printf("  %s: %s %.6g, %s %.6g\n", j ? "the case's modification" : "unmodified", P->column[0],
                   P->flank_f[j][0], P->column[1], P->flank_f[j][1]);
    else
        printf("  the true front's hypervolume %.8g: %.3g %% short\n", P->true_front_hv,
               100 * (P->true_front_hv - b->hv) / P->true_front_hv);
}
