/* Two objectives at once in the optimize row (docs/optimisation.md section 13; row_optimize_pareto.c). */
#ifndef GD_ROW_OPTIMIZE_PARETO_H
#define GD_ROW_OPTIMIZE_PARETO_H

#include "geardyn/gd_analysis.h"
#include "geardyn/gd_optimize.h"

/* The runs of the case's two-objective optimiser on its two objectives (o->pareto). */
gd_status row_pareto_run(const gd_case *c, const gd_run_env *env, gd_optimize_outcome *o, gd_error *err);
void row_pareto_free(gd_opt_pareto_report *p);

#endif
