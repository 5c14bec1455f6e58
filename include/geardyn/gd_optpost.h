/* What an optimisation over load and speed reports after it has found its optimum
 * (docs/optimisation.md section 12): the unmodified flank, the case's own and the optimum compared
 *
 *  - gear-dynamic: each flank's response curve over speed at each torque on the model of the loop
 *    (the curves the objective took its maxima from), and the three flanks re-evaluated on the
 *    bta model, with whether the flanks rank the same there;
 *  - gear-lte-range and gear-dynamic: the Harris map, the LTE amplitude of each flank over a grid
 *    of torques holding the objective's own.
 *
 * Each flank's values are functions of the flank alone (gd_dyn_evaluate, gd_opt_gear_lte_pp), so
 * the threads that share the work give the same numbers as one. */
#ifndef GD_OPTPOST_H
#define GD_OPTPOST_H

#include "geardyn/gd_case.h"
#include "geardyn/gd_dynobj.h"
#include "geardyn/gd_optimize.h"
#include "geardyn/gd_pair.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The flanks compared: unmodified, the case's own modification, the optimum. */
#define GD_OPTPOST_NFLANKS 3
/* The Harris map's grid: optimize.harris_torques (at most GD_OPTPOST_HARRIS_GRID) torques evenly
 * from optimize.harris_torque_from_nm to harris_torque_to_nm, and the objective's own torques. */
#define GD_OPTPOST_HARRIS_GRID 100
#define GD_OPTPOST_MAX_HARRIS (GD_OPTPOST_HARRIS_GRID + GD_OPT_MAX_TORQUES)

GD_API const char *gd_optpost_flank_name(int j); /* "unmodified", "case", "optimum" */

typedef struct gd_optpost {
    int dynamic;                                /* gear-dynamic: the curves and bta below */
    gd_dyn_result curve[GD_OPTPOST_NFLANKS];    /* each flank on the loop's model */
    double loop_cpu_s;                          /* the three evaluations' CPU time */
    int bta_separate;                           /* the loop's model is not bta: on_bta computed */
    gd_dyn_result on_bta[GD_OPTPOST_NFLANKS];   /* each flank on bta (the curve itself when the loop is bta) */
    double bta_cpu_s;
    int rank_loop[GD_OPTPOST_NFLANKS];          /* each flank's place (0 the lowest) by its objective */
    int rank_bta[GD_OPTPOST_NFLANKS];
    int same_ranking;
    int nharris;                                /* the Harris map: torques, increasing */
    double harris_torque_nm[GD_OPTPOST_MAX_HARRIS];
    int harris_objective[GD_OPTPOST_MAX_HARRIS]; /* 1: a torque of the objective */
    double harris_lte_pp_arcsec[GD_OPTPOST_NFLANKS][GD_OPTPOST_MAX_HARRIS];
} gd_optpost;

/* The reports of the resolved case c for its objective (GD_OBJ_GEAR_LTE_RANGE or
 * GD_OBJ_GEAR_DYNAMIC, with the case's [optimize] keys of it) for the flanks of pairs[] (each pair's modification; the rest is the case's), on threads (0: all
 * the cores OpenMP gives). stop (may be NULL) is asked between evaluations. */
GD_API gd_status gd_optpost_compute(const gd_case *c, int objective, const gd_pair pairs[GD_OPTPOST_NFLANKS], int threads,
                                    const gd_stop_hook *stop, gd_optpost *p, gd_error *err);
GD_API void gd_optpost_free(gd_optpost *p);

#ifdef __cplusplus
}
#endif
#endif
