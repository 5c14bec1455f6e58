/* The sweep row: the plan and its points, every pending point of this process's share (the
 * environment's hooks journal them, resume, distribute and stop: the command line's --resume,
 * signals and MPI ranks), then sweep.csv, bifurcation.csv and summary.json from the points in
 * slot order. */
#include "rows.h"
#include "../output/output_internal.h"

#include <stdlib.h>

void gd_row_sweep_free(void *result)
{
    gd_sweep_outcome *o = result;
    if (!o)
        return;
    gd_sweep_points_free(&o->plan, o->pts);
    gd_sweep_plan_free(&o->plan);
    free(o);
}

/* Every pending point of this process's share, between the environment's start and end. */
static gd_status run_points(const gd_case *c, const gd_run_env *env, gd_run_dir *out, gd_sweep_outcome *o,
                            gd_error *err)
{
    gd_status st = env && env->sweep_start ? env->sweep_start(env->user, &o->plan, o->pts, out, err) : GD_OK;
    if (st != GD_OK)
        return st;
    gd_sweep_opts so;
    gd_sweep_opts_default(&so);
    if (env) {
        so.threads = env->threads;
        so.rank = env->rank;
        so.nranks = env->nranks;
        so.point_done = env->sweep_point;
        so.should_stop = env->should_stop;
        so.user = env->user;
    }
    st = gd_sweep_run(c, &o->plan, o->pts, &so, err);
    if (env && env->sweep_end)
        st = env->sweep_end(env->user, &o->plan, o->pts, st, err);
    int pending = st == GD_OK ? gd_sweep_pending(&o->plan, o->pts) : 0;
    if (pending)
        st = gd_error_set(err, GD_ERR_INTERNAL, "%d points were not run", pending);
    return st;
}

gd_status gd_row_sweep_run(const gd_case *c, const gd_run_env *env, gd_run_dir *out, void **result, gd_error *err)
{
    *result = NULL;
    gd_sweep_outcome *o = calloc(1, sizeof *o);
    if (!o)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    gd_status st = gd_sweep_plan_create(c, &o->plan, err);
    if (st != GD_OK) {
        free(o);
        return st;
    }
    st = gd_sweep_points_create(&o->plan, &o->pts, err);
    if (st == GD_OK) {
        gd_row_case_modes(c, &o->modes); /* before the points: the case's LTCA is still in the cache */
        st = run_points(c, env, out, o, err);
    }
    if (st != GD_OK) {
        gd_row_sweep_free(o);
        return st;
    }
    *result = o;
    return GD_OK;
}

gd_status gd_row_sweep_write(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    (void)c;
    const gd_sweep_outcome *o = result;
    gd_status st = gd_sweep_write_tables(out, &o->plan, o->pts, err);
    return st == GD_OK ? gd_sweep_write_states(out, &o->plan, o->pts, err) : st;
}

gd_status gd_row_sweep_summary(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    const gd_sweep_outcome *o = result;
    return gd_sweep_write_summary(out, c, &o->modes, &o->plan, o->pts, err);
}

void gd_row_sweep_pictures(const gd_case *c, const void *result, gd_run_dir *out, const gd_run_env *env)
{
    const gd_plotter p = gd_row_plotter(env, out);
    gd_plot_sweep(&p, c, (const gd_sweep_outcome *)result);
}
