/* The continuation row: its keys checked (with start = sweep, the sweep's point read), periodic
 * orbits followed in one key (gd_contin_run), then branch.csv, bifurcations.csv and summary.json. */
#include "rows.h"
#include "geardyn/gd_continuation.h"
#include "../output/output_internal.h"

#include <stdlib.h>

/* The row's result: the continuation's, first (what the command line reads as a gd_contin_result),
 * and the modes of the case's model for summary.json. */
typedef struct contin_outcome {
    gd_contin_result res;
    gd_modal modes;
} contin_outcome;

/* The run's progress, after each branch, through the caller's hook (the run's should_stop is
 * asked before every point of a branch, gd_contin_run's stop, and here between branches). */
static int on_branch(void *user, int done, int planned)
{
    const gd_run_env *env = user;
    if (env && env->should_stop && env->should_stop(env->user))
        return 1;
    return env && env->continuation_branch ? env->continuation_branch(env->user, done, planned) : 0;
}

/* The [continuation] keys, with curve_start its row, and with start = sweep the sweep's directory and
 * point. */
gd_status gd_row_continuation_check(gd_case *c, gd_error *err)
{
    gd_status st = gd_contin_check_case(c, err);
    if (st == GD_OK)
        st = gd_contin_overlays_check(c, err);
    if (st == GD_OK && c->cont_curve_start[0]) {
        gd_contin_curve_row *row = malloc(sizeof *row);
        st = row ? gd_contin_curve_row_read(c, row, err) : gd_error_set(err, GD_ERR_NOMEM, "out of memory");
        free(row);
    }
    if (st != GD_OK || c->cont_start != GD_CONT_START_SWEEP)
        return st;
    gd_contin_start s;
    return gd_contin_sweep_start(c, &s, err);
}

gd_status gd_row_continuation_run(const gd_case *c, const gd_run_env *env, gd_run_dir *out, void **result,
                                  gd_error *err)
{
    (void)out;
    *result = NULL;
    gd_contin_start s;
    gd_status st = c->cont_start == GD_CONT_START_SWEEP ? gd_contin_sweep_start(c, &s, err) : GD_OK;
    if (st != GD_OK)
        return st;
    gd_contin_curve_row row;
    if (c->cont_curve_start[0]) {
        st = gd_contin_curve_row_read(c, &row, err);
        if (st != GD_OK)
            return st;
    }
    contin_outcome *r = calloc(1, sizeof *r);
    if (!r)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    gd_row_case_modes(c, &r->modes);
    const gd_stop_hook stop = gd_row_stop(env);
    st = gd_contin_run_curve(c, c->cont_start == GD_CONT_START_SWEEP ? &s : NULL, c->cont_curve_start[0] ? &row : NULL,
                             on_branch, (void *)env, &stop, &r->res, err);
    if (st != GD_OK) {
        free(r);
        return st;
    }
    *result = r;
    return GD_OK;
}

gd_status gd_row_continuation_write(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    const gd_contin_result *res = &((const contin_outcome *)result)->res;
    gd_status st = gd_contin_write_tables(out, res, err);
    if (st != GD_OK || !res->parameter2[0] || res->ncurves == 0 || c->cont_overlay_map[0])
        return st;
    /* the regions named from the run, where curves.png names them (regions.csv) */
    gd_curve_regions *rg = malloc(sizeof *rg);
    if (!rg)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory naming the regions of the curves");
    st = gd_plot_curve_regions(c, res, rg, err);
    if (st == GD_OK)
        st = gd_contin_write_regions(out, res, rg, err);
    free(rg);
    return st;
}

gd_status gd_row_continuation_summary(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    const contin_outcome *r = result;
    return gd_contin_write_summary(out, c, &r->modes, &r->res, err);
}

void gd_row_continuation_free(void *result)
{
    if (!result)
        return;
    gd_contin_result_free(&((contin_outcome *)result)->res);
    free(result);
}

void gd_row_continuation_pictures(const gd_case *c, const void *result, gd_run_dir *out, const gd_run_env *env)
{
    const gd_plotter p = gd_row_plotter(env, out);
    gd_plot_continuation(&p, c, (const gd_contin_result *)result);
}
