/* The robust variant in the optimize row: the report of the unmodified flank, the case's own and the
 * optimum, each with its robust objective (the quantile over the Monte Carlo sample), its nominal one
 * and the value of every sample (docs/optimisation.md section 12). */
#include "row_optimize_robust.h"
#include "../optimisation/opt_internal.h"

#include <stdlib.h>
#include <string.h>

gd_status row_robust_init(const gd_case *c, gd_optimize_outcome *o, gd_error *err)
{
    const double *dev;
    int n = gd_opt_gear_robust_sample(o->gear_problem, &dev);
    if (n <= 0)
        return GD_OK;
    gd_opt_robust_report *r = calloc(1, sizeof *r);
    if (!r)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    o->robust = r;
    gd_opt_case_robust(c, &r->settings);
    if (r->settings.quantile == 0)
        r->settings.quantile = 0.9;
    r->nvars = o->vars.n;
    r->dev = dev;
    for (int j = 0; j < 3; j++)
        if (!(r->values[j] = calloc((size_t)n * 2, sizeof(double)))) /* two objectives at most */
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    return GD_OK;
}

void row_robust_flank(gd_optimize_outcome *o, int j)
{
    gd_opt_robust_report *r = o->robust;
    if (!r)
        return;
    r->robust[j] = o->objective_of[j];
    r->nominal[j] = o->aux_of[j][0];
    memmove(o->aux_of[j], o->aux_of[j] + 1, sizeof o->aux_of[j] - sizeof o->aux_of[j][0]);
}

void row_robust_free(gd_opt_robust_report *r)
{
    if (!r)
        return;
    for (int j = 0; j < 3; j++)
        free(r->values[j]);
    free(r);
}
