/* The work-precision row: build the model, run the grid, the reference and the order study
 * (progress through the environment's hooks), then the tables and summary.json. */
#include "rows.h"
#include "geardyn/gd_scene.h"
#include "../output/output_internal.h"

#include <stdlib.h>

gd_status gd_row_workprec_run(const gd_case *cp, const gd_run_env *env, gd_run_dir *out, void **result,
                              gd_error *err)
{
    (void)out;
    *result = NULL;
    gd_case c = *cp;
    gd_workprec_outcome *r = calloc(1, sizeof *r);
    if (!r)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    gd_wp_hooks hooks = {0};
    if (env) {
        hooks = env->workprec;
        if (!hooks.should_stop)
            hooks.should_stop = env->should_stop;
    }
    gd_status st = gd_model_build(&c, &r->model, err);
    if (st == GD_OK)
        st = gd_workprec_run(&c, &r->model, &hooks, env ? env->user : NULL, &r->res, err);
    if (st != GD_OK) {
        free(r);
        return st;
    }
    *result = r;
    return GD_OK;
}

gd_status gd_row_workprec_write(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    (void)c;
    const gd_workprec_outcome *r = result;
    return gd_workprec_write_tables(out, &r->res, err);
}

gd_status gd_row_workprec_summary(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    const gd_workprec_outcome *r = result;
    return gd_summary_write_workprec(out, c, &r->model, &r->res, err);
}

void gd_row_workprec_free(void *result)
{
    gd_workprec_outcome *r = result;
    if (!r)
        return;
    gd_workprec_free(&r->res);
    free(r);
}

void gd_row_workprec_pictures(const gd_case *c, const void *result, gd_run_dir *out, const gd_run_env *env)
{
    const gd_plotter p = gd_row_plotter(env, out);
    gd_plot_workprec(&p, c, (const gd_workprec_outcome *)result);
}
