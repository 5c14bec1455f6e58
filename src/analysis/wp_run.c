/* One integration of a work-precision study: a method setting from the common start over the
 * window, with its Poincare points, events (a flip-flop of one crossing dropped), the RMS of the
 * mean mesh acceleration, statistics and CPU time; over budget or diverged is a status, not an
 * error; and the largest Lyapunov exponent of a setting (docs/accuracy.md). */
#include "wp_internal.h"
#include "geardyn/gd_scene.h"
#include "../core/clock.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct wp_ctx {
    const gd_model *m;
    wp_trace *tr;
    int sample;
    double dt_sample;
    long next, nsamples, count;
    double sum2;
    long steps, budget;
    double ybound;           /* a state beyond this has diverged (an unstable step) */
    int over, nomem, diverged;
    gd_error herr;
    int hst;
} wp_ctx;

static double mean_accel(const gd_model *m, double t, const double *yd, const gd_modes *md)
{
    double acc[2];
    for (int j = 0; j < 2; j++) {
        int jj = j < m->nmesh ? j : 0;
        const gd_clearance *cl = &m->clear[m->mesh_clear[jj]];
        double a = 0, e, ed, edd;
        for (int q = 0; q < cl->nw; q++)
            a += cl->wval[q] * yd[m->ndof + cl->widx[q]];
        gd_model_error(m, jj, t, md, &e, &ed, &edd);
        acc[j] = a - edd;
    }
    return 0.5 * (acc[0] + acc[1]);
}

static int take_samples(gd_sim *s, wp_ctx *x, double t0, double t1)
{
    while (x->next < x->nsamples) {
        double ts = (double)x->next * x->dt_sample;
        if (ts > t1)
            break;
        if (ts < t0) {
            x->next++;
            continue;
        }
        double y[GD_MAX_STATE], yd[GD_MAX_STATE];
        if (gd_sim_dense(s, ts, y, &x->herr) != GD_OK) {
            x->hst = x->herr.code;
            return 1;
        }
        gd_sim_rhs(s, ts, y, yd);
        double a = mean_accel(x->m, ts, yd, gd_sim_modes(s));
        x->sum2 += a * a;
        x->count++;
        x->next++;
    }
    return 0;
}

static int on_step(gd_sim *s, double t0, double t1, void *user)
{
    wp_ctx *x = user;
    x->steps++;
    long done = (long)floor(t1 / x->m->period);
    if (x->budget > 0 && x->steps > x->budget * (done + 1)) {
        x->over = 1;
        return 1;
    }
    const double *y = gd_sim_state(s);
    for (int i = 0; i < x->m->n; i++)
        if (!(fabs(y[i]) <= x->ybound)) {
            x->diverged = 1;
            return 1;
        }
    return x->sample ? take_samples(s, x, t0, t1) : 0;
}

static int on_event(gd_sim *s, const gd_event *ev, void *user)
{
    (void)s;
    wp_ctx *x = user;
    wp_trace *tr = x->tr;
    if (tr->nev == tr->cap) {
        long cap = tr->cap ? 2 * tr->cap : 1024;
        wp_ev *p = realloc(tr->ev, sizeof *p * (size_t)cap);
        if (!p) {
            x->nomem = 1;
            return 1;
        }
        tr->ev = p;
        tr->cap = cap;
    }
    tr->ev[tr->nev].t = ev->t;
    tr->ev[tr->nev].clearance = ev->clearance;
    tr->ev[tr->nev].kind = ev->kind;
    tr->ev[tr->nev].old_mode = ev->old_mode;
    tr->ev[tr->nev].new_mode = ev->new_mode;
    tr->nev++;
    return 0;
}

/* An event undone by the next event of the same clearance within 1e-6 of a mesh period (a
 * mode flipped and flipped back at one crossing, as the simultaneous-crossing pass can do
 * when two clearances cross within rounding) is no event of the motion: both are removed
 * before the event times are compared, and counted. */
static void drop_flipflops(wp_trace *tr, double period)
{
    long last[GD_MAX_CLEAR];
    for (int c = 0; c < GD_MAX_CLEAR; c++)
        last[c] = -1;
    long *link = malloc(sizeof(long) * (size_t)(tr->nev > 0 ? tr->nev : 1));
    char *dead = calloc((size_t)(tr->nev > 0 ? tr->nev : 1), 1);
    if (!link || !dead) {
        free(link);
        free(dead);
        return; /* then nothing is filtered */
    }
    for (long i = 0; i < tr->nev; i++) {
        const wp_ev *e = &tr->ev[i];
        int c = e->clearance;
        long j = last[c];
        if (j >= 0 && e->t - tr->ev[j].t <= 1e-6 * period && e->new_mode == tr->ev[j].old_mode) {
            dead[i] = dead[j] = 1;
            last[c] = link[j];
            tr->flipflops += 2;
            continue;
        }
        link[i] = j;
        last[c] = i;
    }
    long k = 0;
    for (long i = 0; i < tr->nev; i++)
        if (!dead[i])
            tr->ev[k++] = tr->ev[i];
    tr->nev = k;
    free(link);
    free(dead);
}

void wp_trace_free(wp_trace *tr)
{
    free(tr->pts);
    free(tr->ev);
    memset(tr, 0, sizeof *tr);
}

static void opts_of(const gd_case *c, const wp_setting *w, gd_solver_opts *o)
{
    gd_solver_opts_from_case(c, o);
    o->method = w->method;
    o->order = w->order;
    o->table[0] = '\0';
    o->root_finding = w->root_finding;
    o->grazing_watch = w->root_finding ? c->grazing_watch : 0;
    o->fixed_step = w->fixed && w->method != GD_METHOD_RK4;
    o->steps_per_period = w->fixed ? w->steps : c->steps_per_period;
    o->rtol = w->rtol;
    o->atol = w->atol;
    o->n_tangent = 0;
    if (w->max_step_fraction > 0)
        o->max_step_fraction = w->max_step_fraction;
}

/* A fixed step outside the method's stability region on the model linearised at the start
 * (gd_sim_step_stability) makes a run that ended (ran to the end, or failed other than by its
 * budget; failure: why, "" when it ran) UNSTABLE, with the mode and the
 * fewest stable steps in its message: its numbers, when it ran to the end, are those of a round-off
 * amplified every step until the contacts bounded it. */
static gd_status fixed_step_stability(const gd_model *m, const gd_solver_opts *o, const double *y0, const gd_modes *md0,
                                      int ended, const char *failure, wp_trace *tr, gd_error *err)
{
    if (!ended || !(o->method == GD_METHOD_RK4 || o->fixed_step))
        return GD_OK;
    gd_step_stability sb;
    gd_status st = gd_sim_step_stability(m, o, y0, md0, &sb, err);
    if (st != GD_OK || !sb.unstable)
        return st;
    tr->status = GD_WP_UNSTABLE;
    snprintf(tr->msg, sizeof tr->msg,
             "unstable step: |R(h lambda)| = %.3g > 1 on the %.5g Hz mode (damping ratio %.2g) of the model "
             "linearised at the start; stable from %ld steps per mesh period%s%s",
             sb.amplification, sb.freq_hz, sb.damping_ratio, sb.min_steps_per_period, failure[0] ? "; the run failed: " : "",
             failure);
    return GD_OK;
}

/* Integrate `periods` mesh periods from (y0, md0) with setting w: the Poincare points, the
 * events, the RMS of the mean mesh acceleration (when sample) and the statistics. A failed or
 * over-budget run is not an error of the analysis: it is reported in tr->status. */
gd_status wp_run_one(const gd_case *c, const gd_model *m, const wp_setting *w, const double *y0,
                     const gd_modes *md0, long periods, int sample, long budget, const gd_stop_hook *stop,
                     wp_trace *tr, gd_error *err)
{
    memset(tr, 0, sizeof *tr);
    tr->pts = malloc(sizeof(double) * (size_t)m->n * (size_t)(periods + 1));
    if (!tr->pts)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for %ld Poincare points", periods + 1);
    gd_solver_opts o;
    opts_of(c, w, &o);
    wp_ctx x;
    memset(&x, 0, sizeof x);
    x.m = m;
    x.tr = tr;
    x.sample = sample;
    x.dt_sample = m->period / c->samples_per_period;
    x.nsamples = periods * c->samples_per_period;
    x.budget = budget;
    double y0max = 0;
    for (int i = 0; i < m->n; i++)
        y0max = fmax(y0max, fabs(y0[i]));
    x.ybound = 1e6 * (1.0 + y0max);
    /* the cost of a run: CPU time of the calling thread (equal to the wall time of a
     * single-threaded run on an idle core, and not inflated by other load on the machine) */
    double t0 = gd_clock_thread_cpu_s();
    gd_sim *s = NULL;
    gd_error e = {0};
    gd_status st = gd_sim_create(m, &o, y0, md0, &s, &e);
    if (st != GD_OK) {
        free(tr->pts);
        tr->pts = NULL;
        if (st == GD_ERR_NOMEM)
            return gd_error_set(err, st, "%s", e.msg);
        tr->status = GD_WP_FAILED;
        snprintf(tr->msg, sizeof tr->msg, "%s", e.msg);
        return GD_OK;
    }
    gd_sim_set_hooks(s, on_step, on_event, &x);
    memcpy(tr->pts, gd_sim_state(s), sizeof(double) * (size_t)m->n);
    tr->npts = 1;
    if (sample) {
        take_samples(s, &x, 0.0, 0.0);
        if (w->exact_samples || c->exact_samples) /* samples on step ends, as in a response run */
            gd_sim_set_sample_grid(s, 0.0, x.dt_sample);
    }
    int stopped = 0;
    for (long k = 0; k < periods; k++) {
        if ((stopped = gd_stop_asked(stop)))
            break;
        st = gd_sim_period(s, &e);
        if (st != GD_OK)
            break;
        memcpy(tr->pts + tr->npts * m->n, gd_sim_state(s), sizeof(double) * (size_t)m->n);
        tr->npts++;
    }
    gd_sim_get_stats(s, &tr->stats);
    gd_sim_free(s);
    if (stopped) {
        wp_trace_free(tr);
        return gd_error_set(err, GD_ERR_INTERRUPTED, "interrupted");
    }
    tr->cpu = gd_clock_thread_cpu_s() - t0;
    if (x.nomem)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the event list");
    gd_status stab = fixed_step_stability(m, &o, y0, md0, !x.over, st == GD_OK ? "" : x.diverged ? "the state grew past 1e6 times its start" : x.hst ? x.herr.msg : e.msg, tr, err);
    if (stab != GD_OK) {
        wp_trace_free(tr);
        return stab;
    }
    if (tr->status == GD_WP_UNSTABLE) {
        if (st == GD_OK) {
            tr->complete = 1;
            drop_flipflops(tr, m->period);
            tr->rms = x.count > 0 ? sqrt(x.sum2 / (double)x.count) * m->bc_m * m->omega_n * m->omega_n : NAN;
        }
        return GD_OK;
    }
    if (st != GD_OK) {
        if (x.over) {
            tr->status = GD_WP_OVER_BUDGET;
            snprintf(tr->msg, sizeof tr->msg, "more than %ld steps per mesh period", budget);
        } else if (x.diverged) {
            tr->status = GD_WP_FAILED;
            snprintf(tr->msg, sizeof tr->msg, "diverged: the state grew past 1e6 times its start (unstable step)");
        } else {
            tr->status = GD_WP_FAILED;
            snprintf(tr->msg, sizeof tr->msg, "%s", x.hst ? x.herr.msg : e.msg);
        }
        return GD_OK;
    }
    tr->complete = 1;
    drop_flipflops(tr, m->period);
    tr->rms = x.count > 0 ? sqrt(x.sum2 / (double)x.count) * m->bc_m * m->omega_n * m->omega_n : NAN;
    return GD_OK;
}

/* The response's progress hook: asks the stop hook after each mesh period. */
static int lyapunov_progress(void *user, long period, long total)
{
    (void)period, (void)total;
    return gd_stop_asked(user);
}

gd_status wp_lyapunov_run(const gd_case *c, const gd_model *m, const wp_setting *w, const double *y0,
                          const gd_modes *md0, long periods, const gd_stop_hook *stop, double *mle, gd_error *err)
{
    gd_case cc = *c;
    cc.transient_periods = 0;
    cc.record_periods = (int)periods;
    cc.method = w->method;
    cc.order = w->order;
    cc.table[0] = '\0';
    cc.root_finding = w->root_finding;
    cc.grazing_watch = w->root_finding ? c->grazing_watch : 0;
    cc.fixed_step = w->fixed && w->method != GD_METHOD_RK4;
    cc.steps_per_period = w->fixed ? w->steps : c->steps_per_period;
    cc.rtol = w->rtol;
    cc.atol = w->atol;
    if (w->max_step_fraction > 0)
        cc.max_step_fraction = w->max_step_fraction;
    cc.lyapunov_exponents = 1;
    cc.lyapunov_method = w->root_finding ? GD_LYAP_TANGENT : GD_LYAP_TWO_TRAJECTORY;
    gd_response_opts ro;
    gd_response_opts_default(&ro);
    ro.y0 = y0;
    ro.md0 = md0;
    gd_response_result rr;
    const gd_response_hooks hooks = {.progress = lyapunov_progress};
    gd_status st = gd_response_run(&cc, m, &ro, &hooks, (void *)stop, &rr, err);
    *mle = st == GD_OK ? rr.mle_per_period : NAN;
    return st;
}
