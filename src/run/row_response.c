/* The response row: build the model, run the response with time_history.csv, poincare.csv and
 * events.csv streaming into the run's directory, the local analysis of the response variable;
 * then its tables and summary.json. */
#include "rows.h"
#include "geardyn/gd_scene.h"
#include "../analysis/analysis_internal.h"
#include "../output/output_internal.h"

#include <stdlib.h>
#include <string.h>

typedef struct stream {
    const gd_model *m;
    const gd_run_env *env;
    FILE *th, *pc, *ev;
    gd_local *local;
    int local_failed;
} stream;

static int on_sample(void *user, const gd_sample *s)
{
    stream *o = user;
    const gd_model *m = o->m;
    double vx, vxd;
    gd_local_value(m, o->local, s->t_s * m->omega_n, s->y, &vx, &vxd);
    o->local_failed |= gd_local_add_sample(o->local, s->t_s, vx, vxd);
    if (o->th)
        gd_time_history_row(o->th, m, s);
    return 0;
}

static int on_poincare(void *user, long period, double t_s, const double *y)
{
    stream *o = user;
    const gd_model *m = o->m;
    double vx, vxd;
    gd_local_value(m, o->local, t_s * m->omega_n, y, &vx, &vxd);
    o->local_failed |= gd_local_add_poincare(o->local, vx, vxd);
    gd_poincare_row(o->pc, m, period, t_s, y);
    return 0;
}

static int on_event(void *user, const gd_event *ev, int recording)
{
    stream *o = user;
    if (o->ev)
        gd_eventlog_row(o->ev, o->m, ev, recording);
    return 0;
}

static int on_progress(void *user, long done, long total)
{
    stream *o = user;
    return o->env && o->env->progress ? o->env->progress(o->env->user, done, total) : 0;
}

/* poincare.csv, and time_history.csv and events.csv when [output] asks for them, with headers. */
static gd_status open_streams(const gd_case *c, gd_run_dir *out, stream *o, gd_error *err)
{
    gd_status st = gd_run_dir_create(out, "poincare.csv", &o->pc, err);
    if (st == GD_OK && c->time_history)
        st = gd_run_dir_create(out, "time_history.csv", &o->th, err);
    if (st == GD_OK && c->event_log)
        st = gd_run_dir_create(out, "events.csv", &o->ev, err);
    if (st != GD_OK)
        return st;
    gd_poincare_header(o->pc, o->m);
    if (o->th)
        gd_time_history_header(o->th, o->m);
    if (o->ev)
        gd_eventlog_header(o->ev);
    return GD_OK;
}

static gd_status commit_streams(gd_run_dir *out, stream *o, gd_error *err)
{
    gd_status st = gd_run_dir_commit(out, o->pc, err);
    if (st == GD_OK && o->th)
        st = gd_run_dir_commit(out, o->th, err);
    if (st == GD_OK && o->ev)
        st = gd_run_dir_commit(out, o->ev, err);
    return st;
}

void gd_row_response_free(void *result)
{
    gd_response_outcome *r = result;
    if (!r)
        return;
    gd_local_free(&r->local);
    free(r);
}

gd_status gd_row_response_run(const gd_case *cp, const gd_run_env *env, gd_run_dir *out, void **result,
                              gd_error *err)
{
    *result = NULL;
    gd_case c = *cp;
    if (!c.stop.should_stop)
        c.stop = gd_row_stop(env); /* the LTCA of the model, when the resolution did not cache it */
    gd_response_outcome *r = calloc(1, sizeof *r);
    if (!r)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    gd_model *m = &r->model;
    stream o = {m, env, NULL, NULL, NULL, &r->local, 0};
    gd_status st = gd_model_build(&c, m, err);
    if (st == GD_OK) {
        gd_row_modes(&c, m, &r->modes);
        st = gd_local_resolve(&c, m, &r->local, err);
    }
    if (st == GD_OK)
        st = open_streams(&c, out, &o, err);
    gd_response_hooks hooks = {on_sample, on_poincare, on_event, on_progress};
    if (st == GD_OK)
        st = gd_response_run(&c, m, NULL, &hooks, &o, &r->res, err);
    if (st == GD_OK)
        st = commit_streams(out, &o, err);
    if (st == GD_OK && o.local_failed)
        st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for the local analysis");
    if (st == GD_OK)
        st = gd_local_spectrum(&r->local, (1.0 / m->mesh_freq_hz) / c.samples_per_period, err);
    if (st != GD_OK) {
        gd_run_dir_discard(out, o.pc);
        gd_run_dir_discard(out, o.th);
        gd_run_dir_discard(out, o.ev);
        gd_row_response_free(r);
        return st;
    }
    *result = r;
    return GD_OK;
}

gd_status gd_row_response_write(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    (void)c;
    const gd_response_outcome *r = result;
    return gd_local_write_tables(out, &r->local, r->model.mesh_freq_hz, err);
}

gd_status gd_row_response_summary(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    const gd_response_outcome *r = result;
    return gd_summary_write_response(out, c, &r->model, &r->modes, &r->res, err);
}

void gd_row_response_pictures(const gd_case *c, const void *result, gd_run_dir *out, const gd_run_env *env)
{
    const gd_plotter p = gd_row_plotter(env, out);
    gd_plot_response(&p, c, (const gd_response_outcome *)result);
}
