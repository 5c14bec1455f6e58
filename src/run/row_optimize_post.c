/* The optimize row's report after an optimisation over load and speed (gear-lte-range,
 * gear-dynamic; include/geardyn/gd_optpost.h, docs/optimisation.md section 12): the three flanks
 * exactly as the objective saw them, handed to gd_optpost_compute. */
#include "rows.h"
#include "geardyn/gd_optpost.h"
#include "geardyn/gd_scene.h"
#include "../optimisation/opt_internal.h"

#include <stdlib.h>

gd_pair gd_row_optimize_flank(const gd_case *c, const gd_optimize_outcome *o, int j)
{
    gd_pair t = gd_pair_from_case(c);
    if (j == 0) {
        t.root_relief_amount_um = t.root_relief_length_mm = t.tip_relief_amount_um = t.tip_relief_length_mm = 0;
        t.lead_relief_inner_um = t.lead_relief_outer_um = t.lead_unmodified_length_mm = 0;
        t.lead_unmodified_centre_mm = t.helix_slope_um = 0;
    } else if (j == 2) {
        gd_opt_gear_apply(&o->vars, &t, o->res[o->best].y);
    } else if (j == 3) {
        gd_opt_gear_table2(&t);
    }
    return t;
}

gd_status gd_row_optimize_post(const gd_case *c, const gd_run_env *env, gd_optimize_outcome *o, gd_error *err)
{
    gd_pair pairs[GD_OPTPOST_NFLANKS];
    for (int j = 0; j < GD_OPTPOST_NFLANKS; j++) {
        gd_pair t = gd_row_optimize_flank(c, o, j);
        /* as gd_opt_gear_value_of_pair evaluates it: the variables read off the flank and put back */
        double y[GD_OPT_GEAR_NVARS];
        gd_opt_gear_from_pair(&o->vars, &t, y);
        pairs[j] = t;
        gd_opt_gear_apply(&o->vars, &pairs[j], y);
    }
    gd_optpost *p = calloc(1, sizeof *p);
    if (!p)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    const gd_stop_hook stop = gd_row_stop(env);
    gd_status st = gd_optpost_compute(c, o->objective, pairs, opt_threads(env ? env->threads : 0), &stop, p, err);
    if (st != GD_OK) {
        free(p);
        return st;
    }
    o->post = p;
    return GD_OK;
}

void gd_row_optimize_post_free(gd_optimize_outcome *o)
{
    gd_optpost_free(o->post);
    free(o->post);
    o->post = NULL;
}
