/* The table of analyses and the resolution of a case through it (include/geardyn/gd_analysis.h). */
#include "rows.h"
#include "geardyn/gd_scene.h"
#include "geardyn/gd_sweep.h"
#include "geardyn/gd_workprec.h"
#include "geardyn/gd_optimize.h"
#include "geardyn/gd_continuation.h"
#include "../case/case_keys.h"
#include "../analysis/analysis_internal.h"
#include "../optimisation/opt_internal.h"

#include <stdio.h>
#include <string.h>

/* LTCA needs a load. */
static gd_status ltca_check_case(gd_case *c, gd_error *err)
{
    if (c->torque_nm > 0)
        return GD_OK;
    char w[GD_PATH_MAX + 32];
    const char *k = gd_case_key_given(c, "operating", "power_kw") ? "power_kw" : "torque_nm";
    gd_case_key_where(c, "operating", k, w, sizeof w);
    return gd_error_set(err, GD_ERR_INPUT, "%s: operating.%s: a pinion torque of %g N m for LTCA (valid: > 0, "
                        "the loaded contact needs a load)", w, k, c->torque_nm);
}

/* [sweep]: the swept keys and every value of the grid. */
static gd_status sweep_check_case(gd_case *c, gd_error *err) { return gd_sweep_check_case(c, err); }

static gd_status workprec_check_case(gd_case *c, gd_error *err)
{
    if (gd_workprec_check_case(c, err) != GD_OK)
        return gd_error_prefix(err, "%s", c->path[0] ? c->path : "case");
    return GD_OK;
}

/* [optimize]; the gear objective's box is checked on the case's pair. */
static gd_status optimize_check_case(gd_case *c, gd_error *err)
{
    const gd_pair pair = gd_pair_from_case(c);
    return gd_opt_resolve_case(c, &pair, err);
}

static const gd_analysis_type analyses[] = {
    { GD_ANALYSIS_RESPONSE, "response", "the event-exact response of one operating point", NULL,
      gd_row_response_run, gd_row_response_write, gd_row_response_summary, gd_row_response_free,
      gd_row_response_pictures },
    { GD_ANALYSIS_SWEEP, "sweep", "the response over a grid of one or two keys, continued up and down",
      sweep_check_case, gd_row_sweep_run, gd_row_sweep_write, gd_row_sweep_summary, gd_row_sweep_free,
      gd_row_sweep_pictures },
    { GD_ANALYSIS_TCA, "tca", "geometric tooth contact analysis", NULL,
      gd_row_tca_run, gd_row_tca_write, gd_row_tca_summary, gd_row_tca_free,
      gd_row_tca_pictures },
    { GD_ANALYSIS_LTCA, "ltca", "loaded tooth contact analysis", ltca_check_case,
      gd_row_ltca_run, gd_row_ltca_write, gd_row_ltca_summary, gd_row_ltca_free,
      gd_row_ltca_pictures },
    { GD_ANALYSIS_OPTIMIZE, "optimize", "the modification of minimum LTE amplitude", optimize_check_case,
      gd_row_optimize_run, gd_row_optimize_write, gd_row_optimize_summary, gd_row_optimize_free,
      gd_row_optimize_pictures },
    { GD_ANALYSIS_COMPARE_OPTIMIZERS, "compare-optimizers", "ALO against NLopt's methods on one budget",
      optimize_check_case, gd_row_compare_run, gd_row_compare_write, gd_row_compare_summary,
      gd_row_compare_free,
      gd_row_compare_pictures },
    { GD_ANALYSIS_WORK_PRECISION, "work-precision", "error against cost over methods and tolerances",
      workprec_check_case, gd_row_workprec_run, gd_row_workprec_write, gd_row_workprec_summary,
      gd_row_workprec_free,
      gd_row_workprec_pictures },
    { GD_ANALYSIS_CONTINUATION, "continuation",
      "periodic orbits followed in one key, stable and unstable, with their bifurcations", gd_row_continuation_check,
      gd_row_continuation_run, gd_row_continuation_write, gd_row_continuation_summary, gd_row_continuation_free,
      gd_row_continuation_pictures },
    { GD_ANALYSIS_BASINS, "basins",
      "the attractors of the stroboscopic map, their basins and fractions, over a parameter", gd_row_basins_check,
      gd_row_basins_run, gd_row_basins_write, gd_row_basins_summary, gd_row_basins_free,
      gd_row_basins_pictures },
};

GD_API const gd_analysis_type *gd_analysis_types(size_t *n)
{
    *n = sizeof analyses / sizeof analyses[0];
    return analyses;
}

GD_API const gd_analysis_type *gd_analysis_find(int id)
{
    for (size_t i = 0; i < sizeof analyses / sizeof analyses[0]; i++)
        if (analyses[i].id == id)
            return &analyses[i];
    return NULL;
}

/* The analysis names no row: list those there are. */
static gd_status unknown_analysis(const gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32], avail[256] = "";
    for (size_t i = 0; i < sizeof analyses / sizeof analyses[0]; i++) {
        size_t used = strlen(avail);
        snprintf(avail + used, sizeof avail - used, "%s%s", used ? ", " : "", analyses[i].name);
    }
    gd_case_key_where(c, "scene", "analysis", w, sizeof w);
    return gd_error_set(err, GD_ERR_INPUT, "%s: scene.analysis: %d is not available in this version of geardyn "
                        "(valid: %s)", w, c->analysis, avail);
}

GD_API gd_status gd_case_resolve(gd_case *c, gd_error *err)
{
    const gd_analysis_type *a = gd_analysis_find(c->analysis);
    if (!a)
        return unknown_analysis(c, err);
    gd_status st = gd_case_check(c, err);
    if (st == GD_OK)
        st = gd_scene_resolve(c, err);
    if (st == GD_OK && a->check_case)
        st = a->check_case(c, err);
    return st;
}

GD_API gd_status gd_analysis_run_dir(const gd_analysis_type *a, const gd_case *c, const gd_run_env *env,
                                     gd_run_dir *out, gd_error *err)
{
    void *res = NULL;
    gd_status st = a->run(c, env, out, &res, err);
    if (env && env->ran)
        env->ran(env->user, c, st);
    if (st == GD_OK)
        st = a->write(c, res, out, err);
    if (st == GD_OK && a->pictures)
        a->pictures(c, res, out, env);
    if (st == GD_OK && env && env->pictures)
        env->pictures(env->user, c, res, out);
    if (st == GD_OK)
        st = a->summary(c, res, out, err);
    if (st == GD_OK && env && env->should_stop && env->should_stop(env->user))
        st = gd_error_set(err, GD_ERR_INTERRUPTED, "%s: interrupted: nothing published", gd_run_dir_path(out));
    if (st == GD_OK)
        st = gd_run_dir_publish(out, err);
    if (st == GD_OK && env && env->done)
        env->done(env->user, c, res, out);
    if (res)
        a->free(res);
    return st;
}

GD_API gd_status gd_analysis_run_in(const gd_analysis_type *a, const gd_case *c, const gd_run_env *env,
                                    const char *dir, gd_error *err)
{
    gd_run_dir *out = NULL;
    gd_status st = gd_run_dir_open(dir, &out, err);
    if (st == GD_OK)
        st = gd_analysis_run_dir(a, c, env, out, err);
    gd_run_dir_close(out);
    return st;
}
