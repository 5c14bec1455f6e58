/* Internal: the functions of the rows of the table of analyses (src/run/analyses.c), one file
 * per analysis (row_NAME.c). */
#ifndef GD_RUN_ROWS_H
#define GD_RUN_ROWS_H

#include "geardyn/gd_analysis.h"
#include "geardyn/gd_scene.h"
#include "../plot/plot.h"

#include <stdio.h>

#define GD_ROW_DECLARE(NAME)                                                                                     \
    gd_status gd_row_##NAME##_run(const gd_case *c, const gd_run_env *env, gd_run_dir *out, void **result,       \
                                  gd_error *err);                                                              \
    gd_status gd_row_##NAME##_write(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err);       \
    gd_status gd_row_##NAME##_summary(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err);     \
    void gd_row_##NAME##_free(void *result);                                                                     \
    void gd_row_##NAME##_pictures(const gd_case *c, const void *result, gd_run_dir *out, const gd_run_env *env);

GD_ROW_DECLARE(response)
GD_ROW_DECLARE(sweep)
GD_ROW_DECLARE(tca)
GD_ROW_DECLARE(ltca)
GD_ROW_DECLARE(workprec)
GD_ROW_DECLARE(optimize)
/* optimize over load and speed: the three flanks' report (gd_optpost.h) into o->post, and its freeing */
gd_status gd_row_optimize_post(const gd_case *c, const gd_run_env *env, gd_optimize_outcome *o, gd_error *err);
void gd_row_optimize_post_free(gd_optimize_outcome *o);
/* The flank j of an optimisation of the gear as a pair: 0 unmodified (every amount and length 0), 1
 * the case's own modification, 2 the optimum, 3 the paper's Table 2; the rest is the case's. */
gd_pair gd_row_optimize_flank(const gd_case *c, const gd_optimize_outcome *o, int j);
GD_ROW_DECLARE(compare)
GD_ROW_DECLARE(continuation)
/* continuation's check_case: gd_contin_check_case, and the sweep's point with start = sweep */
gd_status gd_row_continuation_check(gd_case *c, gd_error *err);

GD_ROW_DECLARE(basins)
/* basins' check_case: gd_basins_check_case, and the continuation's directory read */
gd_status gd_row_basins_check(gd_case *c, gd_error *err);

/* Where the pictures of a run go: env's drawer and notes, out's stage. */
static inline gd_plotter gd_row_plotter(const gd_run_env *env, gd_run_dir *out)
{
    return env ? (gd_plotter){env->draw, env->note, env->user, out} : (gd_plotter){NULL, NULL, NULL, out};
}

/* The environment's should_stop (the command line's signals) as the stop hook of a computation
 * that has no hook of its own in gd_run_env (TCA, LTCA, the optimisers); none without env. */
static inline gd_stop_hook gd_row_stop(const gd_run_env *env)
{
    return env ? (gd_stop_hook){env->should_stop, env->user} : (gd_stop_hook){NULL, NULL};
}

/* The modes of the model m of the resolved case c for summary.json (gd_scene_modes): a modal
 * analysis that fails does not fail the run, its message goes into out->failed. */
static inline void gd_row_modes(const gd_case *c, const gd_model *m, gd_modal *out)
{
    gd_error e = {0};
    if (gd_scene_modes(c, m, out, &e) != GD_OK)
        snprintf(out->failed, sizeof out->failed, "%s", e.msg[0] ? e.msg : "modal analysis failed");
}

/* The same for the model the case builds (with its LTCA excitation, from the cache resolving the
 * case filled). */
static inline void gd_row_case_modes(const gd_case *c, gd_modal *out)
{
    gd_error e = {0};
    gd_model m;
    if (gd_model_build(c, &m, &e) != GD_OK) {
        snprintf(out->failed, sizeof out->failed, "%s", e.msg[0] ? e.msg : "the model did not build");
        return;
    }
    gd_row_modes(c, &m, out);
}

#endif
