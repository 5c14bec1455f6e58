/* The robust variant in the optimize row (docs/optimisation.md section 12): its report of the three
 * flanks (row_optimize_robust.c). */
#ifndef GD_ROW_OPTIMIZE_ROBUST_H
#define GD_ROW_OPTIMIZE_ROBUST_H

#include "geardyn/gd_optimize.h"

/* o->robust for the gear problem's robust sample (NULL when the problem is not robust). */
gd_status row_robust_init(const gd_case *c, gd_optimize_outcome *o, gd_error *err);
/* Flank j's numbers just computed (objective_of[j] the quantile, aux_of[j] the nominal value and then the
 * objective's own numbers): the nominal value into the report, aux_of[j] left with the objective's own. */
void row_robust_flank(gd_optimize_outcome *o, int j);
void row_robust_free(gd_opt_robust_report *r);

#endif
