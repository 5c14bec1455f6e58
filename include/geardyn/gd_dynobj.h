/* The dynamic objective of a flank modification (docs/optimisation.md section 12): the response of
 * the stable motion over a speed range at each torque of a list, the largest over the range,
 * combined over the torques (worst case or duty-weighted mean).
 *
 * At each torque the candidate's flank (the pair's modification and misalignment) goes into a copy
 * of the case, whose model takes that flank's LTCA mesh stiffness, mesh-in impact and (with
 * excitation.ste = ltca) transmission error (gd_model_build). The response curve over speed is the
 * period-1 orbit followed by pseudo-arclength continuation (gd_continue, gd_periodic.h) from the
 * attractor at the lowest speed; where the orbit is unstable or the branch is lost (ended before
 * the top of the range) a short sweep takes over: natural parameter continuation of the attractor
 * with plain integration at grid speeds, from the last stable orbit. The largest value of the
 * stable branch is refined between its neighbours (golden section on orbits solved by shooting).
 *
 * The optimisers see it only as a gear objective (gd_opt_gear_objective, gd_optimize.h): the
 * analysis layer assembles it, so the optimisation layer stays below the scene and the dynamics
 * (docs/architecture.md). */
#ifndef GD_DYNOBJ_H
#define GD_DYNOBJ_H

#include "geardyn/gd_case.h"
#include "geardyn/gd_optimize.h"
#include "geardyn/gd_pair.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The response measured: the RMS mesh acceleration, or the peak-to-peak dynamic transmission error;
 * of a herringbone's two meshes the larger (not the combined acceleration, which cancels where the
 * halves vibrate in antiphase). */
typedef enum gd_dyn_measure { GD_DYN_RMS_ACCEL = 0, GD_DYN_DTE_PP = 1 } gd_dyn_measure;
/* How a torque's curve was obtained: the continuation alone, with a short sweep, or the sweep alone
 * (the start orbit was not found). */
typedef enum gd_dyn_method { GD_DYN_CONTINUATION = 0, GD_DYN_CONT_SWEEP = 1, GD_DYN_SWEEP = 2 } gd_dyn_method;
GD_API const char *gd_dyn_method_name(int method);
GD_API const char *gd_dyn_measure_name(int measure);

typedef struct gd_dynobj_settings {
    int ntorques;
    double torques_nm[GD_OPT_MAX_TORQUES];
    double weights[GD_OPT_MAX_TORQUES];
    int combine;             /* gd_opt_combine over the torques */
    double speed_from_rpm, speed_to_rpm;
    int measure;             /* gd_dyn_measure */
    int model;               /* gd_model_kind of the dynamics in the loop */
    double sweep_step_rpm;   /* the short sweep's spacing (0: (to - from) / 50) */
    int transient_periods;   /* of a sweep point and of the start's transient */
    int record_periods;      /* of a sweep point */
    double dp_max_rpm;       /* the continuation's largest step in speed (0: (to - from) / 50) */
} gd_dynobj_settings;

/* The case's [optimize] keys of the dynamic objective (torques_nm, torque_weights, speed range,
 * dynamic_response, dynamic_model, dynamic_combine, dynamic_sweep_step_rpm) and [run]
 * transient_periods, record_periods. */
GD_API void gd_dynobj_settings_from_case(const gd_case *c, gd_dynobj_settings *s);

/* A point of a torque's response curve. */
typedef enum gd_dyn_source { GD_DYN_BRANCH = 0, GD_DYN_SWEPT = 1, GD_DYN_REFINED = 2 } gd_dyn_source;
typedef struct gd_dyn_point {
    double speed_rpm;
    double value;            /* the measure (m/s^2 or um) */
    int source;              /* gd_dyn_source */
    int stable;              /* branch: the orbit is stable; a sweep point: 1 */
    int period_n;            /* branch: 1; a sweep point: its Poincare period (0: none found) */
} gd_dyn_point;

typedef struct gd_dyn_curve {
    double torque_nm;
    int npts, cap;
    gd_dyn_point *pt;        /* the branch's points in the order found, then the refined and swept ones */
    double peak;             /* the largest value of the stable response over the range */
    double peak_speed_rpm;
    int method;              /* gd_dyn_method */
    int branch_points, swept_points, refined_points;
    double swept_rpm;        /* total width of the speed intervals swept */
    char branch_end[160];    /* how the continuation ended */
} gd_dyn_curve;

typedef struct gd_dyn_result {
    int ntorques;
    gd_dyn_curve curve[GD_OPT_MAX_TORQUES];
    double value;            /* the peaks combined over the torques */
    double cpu_s;
} gd_dyn_result;

/* The dynamic objective of the flank of pair (its modification and misalignment; the rest of the
 * pair is the case's) on the resolved case c with settings s. stop (may be NULL) is asked between
 * orbits and periods. */
GD_API gd_status gd_dyn_evaluate(const gd_case *c, const gd_dynobj_settings *s, const gd_pair *pair,
                                 const gd_stop_hook *stop, gd_dyn_result *r, gd_error *err);
GD_API void gd_dyn_result_free(gd_dyn_result *r);

/* The gear objective (gd_optimize.h) of the dynamic response: one state per concurrent caller, each
 * with its own copy of the case. Records, per torque, its peak and its gd_dyn_method. */
typedef struct gd_dynobj gd_dynobj;
GD_API gd_status gd_dynobj_create(const gd_case *c, const gd_dynobj_settings *s, const gd_stop_hook *stop,
                                  gd_dynobj **out, gd_error *err);
GD_API void gd_dynobj_objective(gd_dynobj *d, gd_opt_gear_objective *o);
GD_API void gd_dynobj_free(gd_dynobj *d);

#ifdef __cplusplus
}
#endif
#endif
