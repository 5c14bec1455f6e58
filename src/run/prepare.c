/* A case made ready for a run as geardyn run makes it, every check before any work
 * (gd_case_prepare), geardyn check's values as JSON (gd_case_check_json), and the threads of a
 * run (include/geardyn/gd_analysis.h). */
#include "rows.h"
#include "../output/output_internal.h"

#include <stdlib.h>
#ifdef _OPENMP
#include <omp.h>
#endif

/* Resolve c without LTCA (as geardyn check does), build its model and check the run's estimated
 * cost: every check before any work, whatever the run would compute first. */
static gd_status probe_cost(gd_case *c, gd_model *m, int threads, gd_run_cost *cost,
                            gd_error *err)
{
    c->ltca_deferred = 1;
    gd_status st = gd_case_resolve(c, err);
    if (st == GD_OK)
        st = gd_model_build(c, m, err);
    if (st == GD_OK) {
        gd_run_cost_estimate(c, m, threads > 0 ? threads : gd_threads_default(), cost);
        st = gd_run_cost_check(c, m, cost, err);
    }
    return st;
}

GD_API gd_status gd_case_prepare(gd_case *c, int check_only, int threads, gd_run_cost *cost,
                                 gd_error *err)
{
    gd_run_cost own;
    if (!cost)
        cost = &own;
    gd_case probe;
    gd_status st = gd_case_copy(&probe, c, err);
    if (st != GD_OK)
        return st;
    gd_model *m = malloc(sizeof *m);
    if (!m) {
        gd_case_free(&probe);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    }
    st = probe_cost(&probe, m, threads, cost, err);
    if (st == GD_OK && check_only) { /* check shows the case as probed */
        gd_case_free(c);
        *c = probe;
        free(m);
        return GD_OK;
    }
    gd_case_free(&probe);
    if (st == GD_OK)
        st = gd_case_resolve(c, err);
    if (st == GD_OK)
        st = gd_model_build(c, m, err);
    free(m);
    return st;
}

GD_API gd_status gd_case_check_json(const gd_case *c, char **json, gd_error *err)
{
    *json = NULL;
    gd_case probe;
    gd_status st = gd_case_copy(&probe, c, err);
    if (st != GD_OK)
        return st;
    gd_run_cost cost;
    gd_model *m = malloc(sizeof *m);
    if (!m)
        st = gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    if (st == GD_OK)
        st = gd_case_prepare(&probe, 1, 0, &cost, err);
    if (st == GD_OK)
        st = gd_model_build(&probe, m, err);
    if (st == GD_OK)
        st = gd_check_json_text(&probe, m, &cost, json, err);
    free(m);
    gd_case_free(&probe);
    return st;
}

GD_API int gd_threads_default(void)
{
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

GD_API int gd_openmp_version(void)
{
#ifdef _OPENMP
    return _OPENMP;
#else
    return 0;
#endif
}
