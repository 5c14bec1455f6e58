/* Internal: the model's evaluations with the sine and cosine of Omega t given by the caller.
 * Every evaluation at a time t needs sin(Omega t) and cos(Omega t) once (for all meshes and
 * harmonics); an integrator evaluates several times at the same t (stages of a Runge-Kutta step
 * with equal nodes, the root functions at the step end), so gd_sim keeps the last few and passes
 * them in. The results are those of gd_model_rhs, gd_model_roots and gd_model_tangent with the
 * same sincos values, to the bit. */
#ifndef GD_MODEL_INTERNAL_H
#define GD_MODEL_INTERNAL_H

#include "geardyn/gd_model.h"

void gd_model_rhs_sc(const gd_model *m, double t, double s0, double c0, const double *y, double *ydot,
                     const gd_modes *md);
void gd_model_roots_sc(const gd_model *m, double t, double s0, double c0, const double *y, double *g,
                       const gd_modes *md);
void gd_model_tangent_sc(const gd_model *m, double t, double s0, double c0, const double *y, const double *v,
                         double *out, const gd_modes *md);
void gd_model_error_sc(const gd_model *m, int j, double t, double s0, double c0, const gd_modes *md, double *e,
                       double *edot, double *eddot);

#endif
