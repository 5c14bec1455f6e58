/* The `work-precision` analysis (gd_workprec.h, docs/accuracy.md): a reference, a grid of
 * methods and settings from one common state on the attractor, their errors where users
 * look and their cost, and the convergence order of the Poincare points with and without
 * event location. */
#include "geardyn/gd_workprec.h"
#include "analysis_internal.h"
#include "geardyn/gd_scene.h"
#include "../core/clock.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

GD_API const char *gd_wp_status_name(int status)
{
    static const char *names[] = {"ok", "over-budget", "failed", "skipped"};
    return status >= 0 && status <= 3 ? names[status] : "?";
}

/* ---------------------------------------------------------------- families */

static gd_status parse_token(const char *tok, gd_wp_family *f, gd_error *err)
{
    memset(f, 0, sizeof *f);
    f->root_finding = 1;
    if (strcmp(tok, "rk4") == 0) {
        f->method = GD_METHOD_RK4;
        f->order = 4;
        f->fixed = 1;
    } else if (strncmp(tok, "erk", 3) == 0 && isdigit((unsigned char)tok[3]) && tok[4] == '\0') {
        f->method = GD_METHOD_ERK;
        f->order = tok[3] - '0';
        if (f->order < 2 || f->order > 8)
            return gd_error_set(err, GD_ERR_INPUT, "workprecision.families: '%s' (valid orders of erk: 2 to 8)", tok);
    } else if (strncmp(tok, "dirk", 4) == 0 && isdigit((unsigned char)tok[4]) && tok[5] == '\0') {
        f->method = GD_METHOD_DIRK;
        f->order = tok[4] - '0';
        if (f->order < 2 || f->order > 5)
            return gd_error_set(err, GD_ERR_INPUT, "workprecision.families: '%s' (valid orders of dirk: 2 to 5)", tok);
    } else {
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.families: unknown family '%s' (valid: rk4, erk2, erk3, "
                            "erk4, erk5, erk6, erk7, erk8, dirk2, dirk3, dirk4, dirk5)", tok);
    }
    snprintf(f->name, sizeof f->name, "%s", tok);
    return GD_OK;
}

gd_status gd_workprec_families(const gd_case *c, gd_wp_family *fam, int max, int *n, gd_error *err)
{
    *n = 0;
    char buf[sizeof c->wp_families];
    snprintf(buf, sizeof buf, "%s", c->wp_families);
    char *save = NULL;
    for (char *tok = strtok_r(buf, ", \t", &save); tok; tok = strtok_r(NULL, ", \t", &save)) {
        gd_wp_family f;
        gd_status st = parse_token(tok, &f, err);
        if (st != GD_OK)
            return st;
        for (int i = 0; i < *n; i++)
            if (strcmp(fam[i].name, f.name) == 0)
                return gd_error_set(err, GD_ERR_INPUT, "workprecision.families: '%s' given twice", tok);
        int copies = c->wp_root_finding_off ? 2 : 1;
        if (*n + copies > max)
            return gd_error_set(err, GD_ERR_INPUT, "workprecision.families: more than %d families (with root_finding_off "
                                "every family counts twice)", max);
        fam[(*n)++] = f;
        if (c->wp_root_finding_off) {
            f.root_finding = 0;
            snprintf(f.name, sizeof f.name, "%s-noroot", tok);
            fam[(*n)++] = f;
        }
    }
    if (*n == 0)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.families: empty (valid: a comma-separated list such as "
                            "rk4,erk5,erk8)");
    return GD_OK;
}

gd_status gd_workprec_check_case(const gd_case *c, gd_error *err)
{
    gd_wp_family fam[GD_WP_MAX_FAMILIES];
    int n;
    gd_status st = gd_workprec_families(c, fam, GD_WP_MAX_FAMILIES, &n, err);
    if (st != GD_OK)
        return st;
    if (c->wp_rk4_steps_min > c->wp_rk4_steps_max)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.rk4_steps_min: %d above rk4_steps_max %d",
                            c->wp_rk4_steps_min, c->wp_rk4_steps_max);
    if (c->wp_order_steps_min > c->wp_order_steps_max)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.order_steps_min: %d above order_steps_max %d",
                            c->wp_order_steps_min, c->wp_order_steps_max);
    if (c->wp_rtol_tightest > c->wp_rtol_loosest)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.rtol_tightest: %g above rtol_loosest %g",
                            c->wp_rtol_tightest, c->wp_rtol_loosest);
    if (c->wp_check_order == c->wp_reference_order)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.check_order: %d, the order of the reference (valid: "
                            "another order, so that the check is an independent method)", c->wp_check_order);
    if (c->wp_horizon_periods > c->record_periods)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision.horizon_periods: %d longer than run.record_periods %d "
                            "(valid: at most the window)", c->wp_horizon_periods, c->record_periods);
    int levels = 0;
    for (long s = c->wp_rk4_steps_min; s <= c->wp_rk4_steps_max; s *= 2)
        levels++;
    int lo = 0;
    for (long s = c->wp_order_steps_min; s <= c->wp_order_steps_max; s *= 2)
        lo++;
    double decades = log10(c->wp_rtol_loosest / c->wp_rtol_tightest);
    int lr = (int)floor(decades * c->wp_rtols_per_decade + 1e-9) + 1;
    if (levels > GD_WP_MAX_LEVELS || lo > GD_WP_MAX_LEVELS || lr > GD_WP_MAX_LEVELS)
        return gd_error_set(err, GD_ERR_INPUT, "workprecision: more than %d settings in one family (fewer rtols per "
                            "decade or a narrower step range)", GD_WP_MAX_LEVELS);
    return GD_OK;
}

/* ---------------------------------------------------------------- one run */

typedef struct wp_ev {
    double t;
    int clearance, kind, old_mode, new_mode;
} wp_ev;

typedef struct wp_setting {
    int method, order, root_finding, fixed, steps;
    double rtol, atol;
    double max_step_fraction; /* 0: the case's */
    int exact_samples;        /* steps end on the sample times (the reference; else the case's setting) */
} wp_setting;

typedef struct wp_trace {
    double *pts;             /* (periods + 1) x n */
    long npts;
    wp_ev *ev;
    long nev, cap;
    long flipflops;          /* events removed as undone at once (pairs, counted as events) */
    double rms;
    gd_sim_stats stats;
    double cpu;              /* CPU time of the calling thread, s */
    int status;              /* gd_wp_status */
    char msg[256];
} wp_trace;

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

static void trace_free(wp_trace *tr)
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

/* Integrate `periods` mesh periods from (y0, md0) with setting w: the Poincare points, the
 * events, the RMS of the mean mesh acceleration (when sample) and the statistics. A failed or
 * over-budget run is not an error of the analysis: it is reported in tr->status. */
static gd_status run_one(const gd_case *c, const gd_model *m, const wp_setting *w, const double *y0,
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
        trace_free(tr);
        return gd_error_set(err, GD_ERR_INTERRUPTED, "interrupted");
    }
    tr->cpu = gd_clock_thread_cpu_s() - t0;
    if (x.nomem)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the event list");
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
    drop_flipflops(tr, m->period);
    tr->rms = x.count > 0 ? sqrt(x.sum2 / (double)x.count) * m->bc_m * m->omega_n * m->omega_n : NAN;
    return GD_OK;
}

/* ---------------------------------------------------------------- errors */

GD_API double gd_workprec_poincare_error(const double *a, const double *b, long npts, int n)
{
    if (npts <= 0)
        return NAN;
    double worst = 0;
    for (int i = 0; i < n; i++) {
        double sc = 0;
        for (long k = 0; k < npts; k++)
            sc = fmax(sc, fabs(b[k * n + i]));
        sc += 1.0;
        for (long k = 0; k < npts; k++) {
            double d = fabs(a[k * n + i] - b[k * n + i]) / sc;
            if (!(d <= worst)) /* also catches NaN */
                worst = isnan(d) ? INFINITY : d;
        }
    }
    return worst;
}

static int ev_cmp(const void *pa, const void *pb)
{
    const wp_ev *a = pa, *b = pb;
    if (a->clearance != b->clearance)
        return a->clearance - b->clearance;
    if (a->kind != b->kind)
        return a->kind - b->kind;
    return (a->t > b->t) - (a->t < b->t);
}

/* Largest |t - t_ref| (mesh periods, capped at 1) over the reference events before t_end, to
 * the nearest event of the same clearance and kind; 0 when there are no reference events. */
static double event_error(const wp_trace *ref, const wp_trace *tr, double t_end, double period, gd_error *err,
                          gd_status *st)
{
    *st = GD_OK;
    if (ref->nev == 0)
        return tr->nev == 0 ? 0.0 : 1.0;
    wp_ev *s = NULL;
    if (tr->nev > 0) {
        s = malloc(sizeof *s * (size_t)tr->nev);
        if (!s) {
            *st = gd_error_set(err, GD_ERR_NOMEM, "out of memory matching events");
            return NAN;
        }
        memcpy(s, tr->ev, sizeof *s * (size_t)tr->nev);
        qsort(s, (size_t)tr->nev, sizeof *s, ev_cmp);
    }
    double worst = 0;
    for (long i = 0; i < ref->nev; i++) {
        const wp_ev *r = &ref->ev[i];
        if (r->t > t_end)
            continue;
        /* lower bound of (clearance, kind, t) */
        long lo = 0, hi = tr->nev;
        while (lo < hi) {
            long mid = (lo + hi) / 2;
            if (ev_cmp(&s[mid], r) < 0)
                lo = mid + 1;
            else
                hi = mid;
        }
        double best = INFINITY;
        for (long j = lo - 1; j <= lo; j++)
            if (j >= 0 && j < tr->nev && s[j].clearance == r->clearance && s[j].kind == r->kind)
                best = fmin(best, fabs(s[j].t - r->t));
        worst = fmax(worst, fmin(1.0, best / period));
    }
    free(s);
    return worst;
}

/* ---------------------------------------------------------------- the analysis */

/* The response's progress hook: asks the stop hook after each mesh period. */
static int lyapunov_progress(void *user, long period, long total)
{
    (void)period, (void)total;
    return gd_stop_asked(user);
}

static gd_status lyapunov_run(const gd_case *c, const gd_model *m, const wp_setting *w, const double *y0,
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

static void fill_run(gd_wp_run *r, const wp_trace *tr, const wp_trace *ref, long periods, long horizon, int chaotic,
                     double period, int n, gd_error *err, gd_status *st)
{
    *st = GD_OK;
    r->status = tr->status;
    snprintf(r->message, sizeof r->message, "%s", tr->msg);
    r->periods = periods;
    r->rhs_evals = tr->stats.rhs_evals;
    r->steps = tr->stats.steps;
    r->step_attempts = tr->stats.step_attempts;
    r->root_evals = tr->stats.root_evals;
    r->jac_evals = tr->stats.jac_evals;
    r->events = tr->stats.events;
    r->flipflop_events = tr->flipflops;
    r->ref_events = 0;
    for (long i = 0; i < ref->nev; i++)
        r->ref_events += !chaotic || ref->ev[i].t <= horizon * period;
    r->err_poincare = r->err_short = r->err_rms = r->err_events = r->err_mle = NAN;
    r->rms_accel_mps2 = r->mle_per_period = NAN;
    if (tr->status != GD_WP_OK)
        return;
    r->rms_accel_mps2 = tr->rms;
    r->err_poincare = gd_workprec_poincare_error(tr->pts, ref->pts, periods + 1, n);
    long h = horizon < periods ? horizon : periods;
    r->err_short = gd_workprec_poincare_error(tr->pts, ref->pts, h + 1, n);
    if (isfinite(tr->rms) && isfinite(ref->rms))
        r->err_rms = fabs(tr->rms - ref->rms) / fmax(fabs(ref->rms), 1e-300);
    double t_end = (chaotic ? (double)h : (double)periods) * period;
    r->err_events = event_error(ref, tr, t_end, period, err, st);
}

static int hook_start(const gd_wp_hooks *h, void *user, const char *what, const char *label, int i, int n)
{
    if (h && h->should_stop && h->should_stop(user))
        return 1;
    return h && h->start ? h->start(user, what, label, i, n) : 0;
}

static int hook_done(const gd_wp_hooks *h, void *user, const char *what, const gd_wp_run *r, const gd_wp_result *res)
{
    if (h && h->should_stop && h->should_stop(user))
        return 1;
    return h && h->done ? h->done(user, what, r, res) : 0;
}

static void fmt_setting(char *buf, size_t len, const gd_wp_family *f, const wp_setting *w)
{
    if (w->fixed)
        snprintf(buf, len, "%s N=%d", f->name, w->steps);
    else
        snprintf(buf, len, "%s rtol=%.0e", f->name, w->rtol);
}

static double slope(const gd_wp_order *o, int from, int to)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0, nn = to - from + 1;
    for (int i = from; i <= to; i++) {
        double xv = log((double)o->steps[i]), yv = log(o->err[i]);
        sx += xv;
        sy += yv;
        sxx += xv * xv;
        sxy += xv * yv;
    }
    return -(nn * sxy - sx * sy) / (nn * sxx - sx * sx);
}

/* The valid levels (error between 100 x floor and 1e-2: above the reference floor, past the
 * unstable or pre-asymptotic start) and the orders fitted over them (gd_wp_order). */
static void fit_order(gd_wp_order *o, double floor_)
{
    o->order = o->order_range = NAN;
    o->fit_from = o->fit_to = o->range_from = -1;
    int best_from = -1, best_len = 0;
    for (int i = 0; i < o->nlevels;) {
        if (!(isfinite(o->err[i]) && o->err[i] > 100.0 * floor_ && o->err[i] < 1e-2)) {
            i++;
            continue;
        }
        int j = i;
        while (j < o->nlevels && isfinite(o->err[j]) && o->err[j] > 100.0 * floor_ && o->err[j] < 1e-2)
            j++;
        if (j - i > best_len) {
            best_len = j - i;
            best_from = i;
        }
        i = j;
    }
    if (best_len < 2)
        return;
    int last = best_from + best_len - 1;
    o->range_from = best_from;
    o->order_range = slope(o, best_from, last);
    o->fit_to = last;
    o->fit_from = best_len > 3 ? last - 2 : best_from;
    o->order = slope(o, o->fit_from, last);
}

GD_API void gd_workprec_free(gd_wp_result *res)
{
    if (!res)
        return;
    free(res->runs);
    free(res->orders);
    free(res->order_runs);
    res->runs = NULL;
    res->orders = NULL;
    res->order_runs = NULL;
    res->nruns = res->norders = res->norder_runs = 0;
}

GD_API int gd_workprec_cheapest(const gd_wp_result *res, double target, int with_events)
{
    int best = -1;
    for (int i = 0; i < res->nruns; i++) {
        const gd_wp_run *r = &res->runs[i];
        if (r->status != GD_WP_OK)
            continue;
        int ok = res->ref.chaotic ? r->err_short <= target : r->err_poincare <= target && r->err_rms <= target;
        if (with_events)
            ok = ok && r->err_events <= target;
        if (ok && (best < 0 || r->cpu_s < res->runs[best].cpu_s))
            best = i;
    }
    return best;
}

static wp_setting ref_setting(const gd_case *c, int order)
{
    wp_setting w;
    memset(&w, 0, sizeof w);
    w.method = GD_METHOD_ERK;
    w.order = order;
    w.root_finding = 1;
    w.rtol = c->wp_reference_rtol;
    w.atol = c->wp_reference_rtol * c->wp_atol_over_rtol;
    w.max_step_fraction = c->wp_reference_max_step_fraction;
    w.exact_samples = 1; /* the samples (RMS) of the reference are the method's solution */
    return w;
}

static const char *erk_table_name(int order)
{
    switch (order) {
    case 2: return "ARKODE_HEUN_EULER_2_1_2";
    case 3: return "ARKODE_BOGACKI_SHAMPINE_4_2_3";
    case 4: return "ARKODE_ZONNEVELD_5_3_4";
    case 5: return "ARKODE_CASH_KARP_6_4_5";
    case 6: return "ARKODE_VERNER_8_5_6";
    case 8: return "ARKODE_FEHLBERG_13_7_8";
    default: return "?";
    }
}

/* What every phase of a run shares: the inputs, the common start and the reference. */
typedef struct wp_job {
    const gd_case *c;
    const gd_model *m;
    const gd_wp_hooks *hooks;
    void *user;
    gd_stop_hook stop;       /* hooks->should_stop, asked after every mesh period of every integration */
    long W, H;               /* window and horizon, mesh periods */
    double y0[GD_MAX_STATE];
    gd_modes md0;
    wp_trace ref;
    gd_wp_result *res;
} wp_job;

static gd_status interrupted(gd_error *err)
{
    return gd_error_set(err, GD_ERR_INTERRUPTED, "interrupted");
}

/* The common start: the state after the transient, with the case's own solver. */
static gd_status wp_start_state(wp_job *j, gd_error *err)
{
    const gd_case *c = j->c;
    const gd_model *m = j->m;
    gd_status st = gd_initial_state(c, m, j->y0, &j->md0, err);
    if (st != GD_OK)
        return st;
    if (c->transient_periods > 0) {
        if (hook_start(j->hooks, j->user, "transient", "case [solver]", 0, 1))
            return interrupted(err);
        gd_solver_opts o;
        gd_solver_opts_from_case(c, &o);
        gd_sim *s = NULL;
        if ((st = gd_sim_create(m, &o, j->y0, &j->md0, &s, err)) != GD_OK)
            return gd_error_prefix(err, "work-precision transient");
        for (long k = 0; k < c->transient_periods && st == GD_OK; k++)
            st = gd_stop_asked(&j->stop) ? interrupted(err) : gd_sim_period(s, err);
        if (st == GD_OK) {
            memcpy(j->y0, gd_sim_state(s), sizeof(double) * (size_t)m->n);
            j->md0 = *gd_sim_modes(s);
            j->md0.from_state = 0;
        }
        gd_sim_free(s);
        if (st != GD_OK)
            return st == GD_ERR_INTERRUPTED ? st : gd_error_prefix(err, "work-precision transient");
    }
    memcpy(j->res->start_state, j->y0, sizeof(double) * (size_t)m->n);
    return GD_OK;
}

/* The reference (into j->ref) and its independent check: their cost and their agreement. */
static gd_status wp_reference_and_check(wp_job *j, const wp_setting *wr, const wp_setting *wc, wp_trace *chk,
                                        gd_error *err)
{
    gd_wp_reference *R = &j->res->ref;
    if (hook_start(j->hooks, j->user, "reference", R->method, 0, 2))
        return interrupted(err);
    gd_status st = run_one(j->c, j->m, wr, j->y0, &j->md0, j->W, 1, 0, &j->stop, &j->ref, err);
    if (st != GD_OK)
        return st;
    if (j->ref.status != GD_WP_OK)
        return gd_error_set(err, GD_ERR_SOLVER, "the reference (%s) failed: %s", R->method, j->ref.msg);
    R->cpu_s = j->ref.cpu;
    R->rhs_evals = j->ref.stats.rhs_evals;
    R->steps = j->ref.stats.steps;
    R->events = j->ref.stats.events;
    R->flipflop_events = j->ref.flipflops;
    R->rms_accel_mps2 = j->ref.rms;
    if (hook_start(j->hooks, j->user, "check", R->check_method, 1, 2))
        return interrupted(err);
    if ((st = run_one(j->c, j->m, wc, j->y0, &j->md0, j->W, 1, 0, &j->stop, chk, err)) != GD_OK)
        return st;
    if (chk->status != GD_WP_OK)
        return gd_error_set(err, GD_ERR_SOLVER, "the check of the reference (%s) failed: %s", R->check_method,
                            chk->msg);
    return GD_OK;
}

/* The class of the scene: periodic (the section repeats) or chaotic (positive largest
 * exponent); then the errors of the check against the reference, the floor and the verdict. */
static gd_status wp_reference_class(wp_job *j, const wp_setting *wr, const wp_trace *chk, gd_error *err)
{
    const gd_case *c = j->c;
    gd_wp_reference *R = &j->res->ref;
    int period_n = gd_poincare_period(j->ref.pts, j->ref.npts, j->m->n, c->periodicity_tol, 64);
    R->mle_per_period = NAN;
    int need_mle = (c->wp_scene_class == GD_WP_CLASS_AUTO && period_n == 0) ||
                   (c->wp_lyapunov && c->wp_scene_class == GD_WP_CLASS_CHAOTIC);
    gd_status st;
    if (need_mle) {
        if (hook_start(j->hooks, j->user, "reference", "largest Lyapunov exponent", 1, 2))
            return interrupted(err);
        if ((st = lyapunov_run(c, j->m, wr, j->y0, &j->md0, j->W, &j->stop, &R->mle_per_period, err)) != GD_OK) {
            gd_error_prefix(err, "the Lyapunov exponent of the reference");
            return st;
        }
    }
    gd_motion_classify(period_n, isfinite(R->mle_per_period), R->mle_per_period, c->chaos_threshold_per_period,
                       R->motion, sizeof R->motion);
    R->chaotic = c->wp_scene_class == GD_WP_CLASS_CHAOTIC ||
                 (c->wp_scene_class == GD_WP_CLASS_AUTO && strcmp(R->motion, "chaotic") == 0);
    gd_wp_run tmp;
    memset(&tmp, 0, sizeof tmp);
    fill_run(&tmp, chk, &j->ref, j->W, j->H, R->chaotic, j->m->period, j->m->n, err, &st);
    if (st != GD_OK)
        return st;
    R->check_poincare = tmp.err_poincare;
    R->check_short = tmp.err_short;
    R->check_rms = tmp.err_rms;
    R->check_events = tmp.err_events;
    R->floor = fmax(R->chaotic ? R->check_short : R->check_poincare, 1e-14);
    R->converged = (R->chaotic ? R->check_short : R->check_poincare) <= c->wp_reference_max_error;
    return GD_OK;
}

/* The reference and its independent check, described, run and compared (gd_wp_reference). */
static gd_status wp_reference(wp_job *j, gd_error *err)
{
    const gd_case *c = j->c;
    wp_setting wr = ref_setting(c, c->wp_reference_order), wc = ref_setting(c, c->wp_check_order);
    gd_wp_reference *R = &j->res->ref;
    R->rtol = c->wp_reference_rtol;
    snprintf(R->method, sizeof R->method, "erk%d (%s) rtol=%.0e max step %g period", wr.order,
             erk_table_name(wr.order), wr.rtol, wr.max_step_fraction);
    snprintf(R->check_method, sizeof R->check_method, "erk%d (%s) rtol=%.0e max step %g period", wc.order,
             erk_table_name(wc.order), wc.rtol, wc.max_step_fraction);
    wp_trace chk;
    memset(&chk, 0, sizeof chk);
    gd_status st = wp_reference_and_check(j, &wr, &wc, &chk, err);
    if (st == GD_OK)
        st = wp_reference_class(j, &wr, &chk, err);
    trace_free(&chk);
    return st;
}

/* The settings of every family of the grid: lev[f][0..nlev[f]-1]; returns their total. */
static int wp_grid_settings(const gd_case *c, const gd_wp_result *res, int nlev[GD_WP_MAX_FAMILIES],
                            wp_setting lev[GD_WP_MAX_FAMILIES][GD_WP_MAX_LEVELS])
{
    int total = 0;
    for (int f = 0; f < res->nfamilies; f++) {
        const gd_wp_family *F = &res->families[f];
        nlev[f] = 0;
        wp_setting w;
        memset(&w, 0, sizeof w);
        w.method = F->method;
        w.order = F->order;
        w.root_finding = F->root_finding;
        w.fixed = F->fixed;
        if (F->fixed) {
            for (long s = c->wp_rk4_steps_min; s <= c->wp_rk4_steps_max && nlev[f] < GD_WP_MAX_LEVELS; s *= 2) {
                w.steps = (int)s;
                w.rtol = c->rtol;
                w.atol = c->atol;
                lev[f][nlev[f]++] = w;
            }
        } else {
            double decades = log10(c->wp_rtol_loosest / c->wp_rtol_tightest);
            int nl = (int)floor(decades * c->wp_rtols_per_decade + 1e-9) + 1;
            for (int i = 0; i < nl && nlev[f] < GD_WP_MAX_LEVELS; i++) {
                w.rtol = c->wp_rtol_loosest * pow(10.0, -(double)i / c->wp_rtols_per_decade);
                w.atol = w.rtol * c->wp_atol_over_rtol;
                lev[f][nlev[f]++] = w;
            }
        }
        total += nlev[f];
    }
    return total;
}

/* A grid run not made because a looser setting of its family was over budget. */
static void wp_grid_skip(gd_wp_run *r, const gd_wp_family *F)
{
    r->status = GD_WP_SKIPPED;
    snprintf(r->message, sizeof r->message, "a looser setting of %s was over budget", F->name);
    r->err_poincare = r->err_short = r->err_rms = r->err_events = r->err_mle = NAN;
    r->rms_accel_mps2 = r->mle_per_period = NAN;
    r->cpu_s = NAN;
}

/* One grid run with setting w into r: the best CPU time of the repeats, the errors against
 * the reference and, for a chaotic scene, the largest exponent. *over: it was over budget. */
static gd_status wp_grid_measure(wp_job *j, const wp_setting *w, gd_wp_run *r, int *over, gd_error *err)
{
    const gd_case *c = j->c;
    const gd_wp_reference *R = &j->res->ref;
    wp_trace tr;
    gd_status st = run_one(c, j->m, w, j->y0, &j->md0, j->W, 1, c->wp_max_steps_per_period, &j->stop, &tr, err);
    if (st != GD_OK) {
        trace_free(&tr);
        return st;
    }
    double best = tr.cpu;
    for (int k = 1; k < c->wp_repeats && tr.status == GD_WP_OK; k++) {
        wp_trace again;
        st = run_one(c, j->m, w, j->y0, &j->md0, j->W, 1, c->wp_max_steps_per_period, &j->stop, &again, err);
        if (st == GD_OK)
            best = fmin(best, again.cpu);
        trace_free(&again);
        if (st != GD_OK) {
            trace_free(&tr);
            return st;
        }
    }
    fill_run(r, &tr, &j->ref, j->W, j->H, R->chaotic, j->m->period, j->m->n, err, &st);
    if (st != GD_OK) {
        trace_free(&tr);
        return st;
    }
    r->cpu_s = best;
    *over = tr.status == GD_WP_OVER_BUDGET;
    if (tr.status == GD_WP_OK && R->chaotic && c->wp_lyapunov && isfinite(R->mle_per_period)) {
        gd_error le = {0};
        st = lyapunov_run(c, j->m, w, j->y0, &j->md0, j->W, &j->stop, &r->mle_per_period, &le);
        if (st == GD_OK)
            r->err_mle = fabs(r->mle_per_period - R->mle_per_period);
        else if (st == GD_ERR_INTERRUPTED) { /* a failed exponent is only missing; a stop ends the analysis */
            trace_free(&tr);
            return interrupted(err);
        }
    }
    trace_free(&tr);
    return GD_OK;
}

/* The grid: every family over its settings, in order; after an over-budget setting the
 * tighter ones of that family are skipped. */
static gd_status wp_grid(wp_job *j, gd_error *err)
{
    gd_wp_result *res = j->res;
    int nlev[GD_WP_MAX_FAMILIES];
    wp_setting lev[GD_WP_MAX_FAMILIES][GD_WP_MAX_LEVELS];
    int total = wp_grid_settings(j->c, res, nlev, lev);
    res->runs = calloc((size_t)total, sizeof *res->runs);
    if (!res->runs)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for %d runs", total);
    for (int f = 0; f < res->nfamilies; f++) {
        int skipping = 0;
        for (int l = 0; l < nlev[f]; l++) {
            const wp_setting *w = &lev[f][l];
            gd_wp_run *r = &res->runs[res->nruns];
            r->family = f;
            fmt_setting(r->label, sizeof r->label, &res->families[f], w);
            r->fixed_step = w->fixed;
            r->steps_per_period = w->fixed ? w->steps : 0;
            r->rtol = w->fixed ? NAN : w->rtol;
            r->atol = w->fixed ? NAN : w->atol;
            if (hook_start(j->hooks, j->user, "grid", r->label, res->nruns, total))
                return interrupted(err);
            if (skipping) {
                wp_grid_skip(r, &res->families[f]);
            } else {
                int over = 0;
                gd_status st = wp_grid_measure(j, w, r, &over, err);
                if (st != GD_OK)
                    return st;
                if (over)
                    skipping = 1;
            }
            res->nruns++;
            if (hook_done(j->hooks, j->user, "grid", r, res))
                return interrupted(err);
        }
    }
    return GD_OK;
}

/* One level of the order study: family F (index f) at s fixed steps per mesh period over the
 * horizon, into the next order run and the next level of O. idx, total: for the hooks. */
static gd_status wp_order_level(wp_job *j, int f, long s, gd_wp_order *O, int idx, int total, gd_error *err)
{
    const gd_case *c = j->c;
    gd_wp_result *res = j->res;
    const gd_wp_family *F = &res->families[f];
    wp_setting w;
    memset(&w, 0, sizeof w);
    w.method = F->method;
    w.order = F->order;
    w.root_finding = F->root_finding;
    w.fixed = 1;
    w.steps = (int)s;
    w.rtol = c->rtol;
    w.atol = c->atol;
    gd_wp_run *r = &res->order_runs[res->norder_runs];
    r->family = f;
    snprintf(r->label, sizeof r->label, "%s fixed N=%ld", F->name, s);
    r->fixed_step = 1;
    r->steps_per_period = (int)s;
    r->rtol = r->atol = NAN;
    if (hook_start(j->hooks, j->user, "order", r->label, idx, total))
        return interrupted(err);
    wp_trace tr;
    gd_status st = run_one(c, j->m, &w, j->y0, &j->md0, j->H, 0, c->wp_max_steps_per_period, &j->stop, &tr, err);
    if (st == GD_OK)
        fill_run(r, &tr, &j->ref, j->H, j->H, 1, j->m->period, j->m->n, err, &st);
    if (st != GD_OK) {
        trace_free(&tr);
        return st;
    }
    r->cpu_s = tr.cpu;
    r->err_rms = NAN; /* no samples in the order study */
    trace_free(&tr);
    O->steps[O->nlevels] = (int)s;
    O->err[O->nlevels] = r->status == GD_WP_OK ? r->err_short : NAN;
    O->nlevels++;
    res->norder_runs++;
    if (hook_done(j->hooks, j->user, "order", r, res))
        return interrupted(err);
    return GD_OK;
}

/* The order study: explicit families at fixed steps over the horizon, and their fitted orders. */
static gd_status wp_order_study(wp_job *j, gd_error *err)
{
    const gd_case *c = j->c;
    gd_wp_result *res = j->res;
    int nol = 0;
    for (long s = c->wp_order_steps_min; s <= c->wp_order_steps_max && nol < GD_WP_MAX_LEVELS; s *= 2)
        nol++;
    int nfo = 0;
    for (int f = 0; f < res->nfamilies; f++)
        nfo += res->families[f].method != GD_METHOD_DIRK;
    res->orders = calloc((size_t)(nfo > 0 ? nfo : 1), sizeof *res->orders);
    res->order_runs = calloc((size_t)(nfo > 0 ? nfo : 1) * (size_t)nol, sizeof *res->order_runs);
    if (!res->orders || !res->order_runs)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the order study");
    int idx = 0;
    for (int f = 0; f < res->nfamilies; f++) {
        const gd_wp_family *F = &res->families[f];
        if (F->method == GD_METHOD_DIRK)
            continue;
        gd_wp_order *O = &res->orders[res->norders];
        O->family = f;
        O->nominal = F->order;
        long s = c->wp_order_steps_min;
        for (int l = 0; l < nol; l++, s *= 2) {
            gd_status st = wp_order_level(j, f, s, O, idx++, nfo * nol, err);
            if (st != GD_OK)
                return st;
        }
        fit_order(O, fmax(res->ref.check_short, 1e-14));
        res->norders++;
    }
    return GD_OK;
}

GD_API gd_status gd_workprec_run(const gd_case *c, const gd_model *m, const gd_wp_hooks *hooks, void *user,
                                 gd_wp_result *res, gd_error *err)
{
    double w0 = gd_clock_wall_s();
    memset(res, 0, sizeof *res);
    gd_status st = gd_workprec_families(c, res->families, GD_WP_MAX_FAMILIES, &res->nfamilies, err);
    if (st != GD_OK)
        return st;
    wp_job job, *j = &job;
    memset(j, 0, sizeof *j);
    j->c = c;
    j->m = m;
    j->hooks = hooks;
    j->user = user;
    j->stop = (gd_stop_hook){hooks ? hooks->should_stop : NULL, user};
    j->W = c->record_periods;
    j->H = c->wp_horizon_periods < j->W ? c->wp_horizon_periods : j->W;
    j->res = res;
    res->window_periods = j->W;
    res->horizon_periods = j->H;
    res->mesh_period_s = m->period / m->omega_n;
    if ((st = wp_start_state(j, err)) != GD_OK)
        return st;
    st = wp_reference(j, err);
    if (st == GD_OK)
        st = wp_grid(j, err);
    if (st == GD_OK && c->wp_order_study)
        st = wp_order_study(j, err);
    trace_free(&j->ref);
    res->wall_s = gd_clock_wall_s() - w0;
    if (st != GD_OK)
        gd_workprec_free(res);
    return st;
}
