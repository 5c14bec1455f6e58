/* The basins row: its keys checked (and the continuation it names read), the basins of the case run
 * (gd_basins_run: the picture and the fractions, or the fractions over a parameter, this process's
 * share of its values, gathered and matched), then the tables and summary.json. */
#include "rows.h"
#include "geardyn/gd_basins.h"
#include "../output/output_internal.h"

#include <stdlib.h>

/* The row's result: the basins' first (what the command line reads as a gd_basins_result), the modes
 * of the case's model for summary.json and the continuation's points. */
typedef struct basins_outcome {
    gd_basins_result res;
    gd_modal modes;
    gd_basins_known known;
} basins_outcome;

gd_status gd_row_basins_check(gd_case *c, gd_error *err)
{
    gd_status st = gd_basins_check_case(c, err);
    if (st != GD_OK || !c->bas_continuation[0])
        return st;
    gd_basins_known k;
    st = gd_basins_read_continuation(c, &k, err);
    gd_basins_known_free(&k);
    return st;
}

static int on_progress(void *user, long done, long total)
{
    const gd_run_env *env = user;
    if (env && env->should_stop && env->should_stop(env->user))
        return 1;
    return env && env->basins_progress ? env->basins_progress(env->user, done, total) : 0;
}

gd_status gd_row_basins_run(const gd_case *c, const gd_run_env *env, gd_run_dir *out, void **result, gd_error *err)
{
    (void)out;
    *result = NULL;
    basins_outcome *r = calloc(1, sizeof *r);
    if (!r)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    gd_status st = c->bas_continuation[0] ? gd_basins_read_continuation(c, &r->known, err) : GD_OK;
    if (st != GD_OK) {
        free(r);
        return st;
    }
    gd_row_case_modes(c, &r->modes);
    gd_basins_hooks h = {on_progress, (void *)env, gd_row_stop(env), env ? env->threads : 0, env ? env->rank : 0,
                         env && env->nranks > 1 && c->bas_parameter[0] ? env->nranks : 1};
    const gd_basins_known *known = c->bas_continuation[0] ? &r->known : NULL;
    st = gd_basins_run(c, known, &h, &r->res, err);
    if (h.nranks > 1 && env->basins_end) {
        gd_status s2 = env->basins_end(env->user, &r->res, st, err);
        if (s2 == GD_OK && st == GD_OK)
            st = gd_basins_match(c, known, &h, &r->res, err);
        else if (st == GD_OK)
            st = s2;
    }
    if (st != GD_OK) {
        gd_basins_result_free(&r->res);
        gd_basins_known_free(&r->known);
        free(r);
        return st;
    }
    *result = r;
    return GD_OK;
}

gd_status gd_row_basins_write(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    return gd_basins_write_tables(out, c, &((const basins_outcome *)result)->res, err);
}

gd_status gd_row_basins_summary(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    const basins_outcome *r = result;
    return gd_summary_write_basins(out, c, &r->modes, &r->res, err);
}

void gd_row_basins_free(void *result)
{
    if (!result)
        return;
    basins_outcome *r = result;
    gd_basins_result_free(&r->res);
    gd_basins_known_free(&r->known);
    free(r);
}

void gd_row_basins_pictures(const gd_case *c, const void *result, gd_run_dir *out, const gd_run_env *env)
{
    const gd_plotter p = gd_row_plotter(env, out);
    gd_plot_basins(&p, c, (const gd_basins_result *)result);
}
