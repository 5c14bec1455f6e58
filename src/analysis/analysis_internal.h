/* Internal: the local analysis of a response as the response row fills it (src/run/). */
#ifndef GD_ANALYSIS_INTERNAL_H
#define GD_ANALYSIS_INTERNAL_H

#include "geardyn/gd_response.h"

/* Which variable [output] response_variable names (GD_ERR_INPUT naming the key when none). */
gd_status gd_local_resolve(const gd_case *c, const gd_model *m, gd_local *L, gd_error *err);
/* Its value (um) and rate (m/s) at dimensionless time t in state y. */
void gd_local_value(const gd_model *m, const gd_local *L, double t, const double *y, double *x, double *xdot);
/* Append a sample or a Poincare point: 0, or 1 when memory ran out. */
int gd_local_add_sample(gd_local *L, double t_s, double x, double xdot);
int gd_local_add_poincare(gd_local *L, double x, double xdot);
/* The amplitude spectrum of the samples (sampling step dt_s) and its largest amplitude. */
gd_status gd_local_spectrum(gd_local *L, double dt_s, gd_error *err);
void gd_local_free(gd_local *L);

#endif
