/* The robust variant of the gear objectives from the case's [optimize] keys (docs/optimisation.md
 * section 12): the settings of its Monte Carlo sample, and the checks the keys' ranges do not make. */
#include "opt_internal.h"
#include "../case/case_keys.h"

#include <stdio.h>
#include <string.h>

void gd_opt_case_robust(const gd_case *c, gd_opt_robust *rb)
{
    memset(rb, 0, sizeof *rb);
    if (!c->opt_robust)
        return;
    rb->samples = c->opt_robust_samples;
    /* the stream of the problem instance of run 1: apart from the optimisers' seeds, and unused by the
     * gear problem, which has no instances */
    rb->seed = gd_opt_instance_seed(c, 0);
    rb->quantile = c->opt_robust_quantile;
    rb->tilt_arcmin = c->opt_robust_tilt_arcmin;
    rb->centre_distance_mm = c->opt_robust_centre_distance_mm;
    rb->amount_um = c->opt_robust_amount_um;
    rb->length_mm = c->opt_robust_length_mm;
}

gd_status gd_opt_resolve_robust(const gd_case *c, int compare, int gear, gd_error *err)
{
    if (!c->opt_robust)
        return GD_OK;
    char w[GD_PATH_MAX + 32];
    gd_case_key_where(c, "optimize", "robust", w, sizeof w);
    if (compare)
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.robust: on for compare-optimizers (valid: off; the "
                            "robust variant is an objective of optimize)", w);
    if (!gear)
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.robust: on for the test function %s (valid: off, or a "
                            "gear objective: gear-lte, gear-lte-range, gear-dynamic; the sample deviates a flank)", w,
                            c->opt_objective);
    return GD_OK;
}
