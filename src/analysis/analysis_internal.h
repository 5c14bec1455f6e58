/* Internal: the local analysis of a response as the response row fills it (src/run/), the
 * sweep's and work-precision's helpers and the checks the table of analyses calls. */
#ifndef GD_ANALYSIS_INTERNAL_H
#define GD_ANALYSIS_INTERNAL_H

#include "geardyn/gd_response.h"
#include "geardyn/gd_sweep.h"
#include "geardyn/gd_workprec.h"
#include "geardyn/gd_continuation.h"

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

/* The names of the state's components, as the tables name them: the degrees of freedom (y1L, ...),
 * then their rates (y1L_dot, ...). */
void gd_state_names(const gd_model *m, char name[][16]);

/* ---- sweep ---- */
/* Check the [sweep] keys of a resolved case (gd_case_resolve calls it for analysis =
 * sweep): the parameters name numeric keys, every value of the grid is inside the key's
 * range (and whole for an integer key), log spacing has positive bounds, the responses
 * exist in the model. Messages name the case file line. */
gd_status gd_sweep_check_case(const gd_case *c, gd_error *err);
/* Value i of axis a (0: parameter, 1: parameter2) of the case's grid; i = 0 gives `from`
 * and i = points - 1 gives `to` exactly. */
double gd_sweep_axis_value(const gd_case *c, int axis, int i);
/* Forget the result of a point (back to pending). */
void gd_sweep_point_clear(gd_sweep_point *pt);
/* The dynamic load factor of a point: the larger of its meshes' (NaN when neither has one). */
double gd_sweep_point_dlf(const gd_sweep_point *pt);
/* The initial state of a point: the case's initial condition when prev is NULL or failed,
 * else prev's final state with its contact modes made consistent with this point's model
 * (the clearances may have changed). Continuation point k starts from exactly this. */
gd_status gd_sweep_start_state(const gd_case *c, const gd_model *m, const gd_sweep_point *prev, double *y0,
                                      gd_modes *md0, gd_error *err);
/* Responses of the plan at a Poincare point (t_s, y) of model m: out[nresp]. */
void gd_sweep_responses(const gd_sweep_plan *p, const gd_model *m, double t_s, const double *y, double *out);

/* ---- continuation ---- */
/* The parameter's value at the starting orbit: continuation.start_value, else from with
 * direction up, to with down, the middle with both. */
double gd_contin_start_value(const gd_case *c);
/* continuation_curves.c: the keys of the curves (continuation.parameter2), and the curves of the
 * folds, period doublings, Neimark-Sacker points and grazings of res's branches in (parameter, parameter2) (work: the run's
 * case, left with parameter2 at its value; co: the branches' options; row: only its curve, or NULL) */
gd_status gd_contin_check_curves(const gd_case *c, gd_error *err);
/* continuation.curve_kinds as bits 1 << gd_curve_kind; 0 when a word is not a kind's name or names one
 * twice (that word in bad) or when the list names none (bad "") */
unsigned gd_contin_curve_kinds(const char *list, char *bad, size_t nbad);
gd_status gd_contin_curves(const gd_case *c, gd_case *work, const gd_solver_opts *o, const gd_cont_opts *co,
                           const gd_contin_curve_row *row, gd_contin_result *res, gd_error *err);

/* ---- work-precision ---- */
/* The method families of the case's [workprecision] (families, root_finding_off): n <= max. */
gd_status gd_workprec_families(const gd_case *c, gd_wp_family *fam, int max, int *n, gd_error *err);
/* Cross-key checks of [workprecision] (called by gd_case_resolve). */
gd_status gd_workprec_check_case(const gd_case *c, gd_error *err);

#endif
