/* The `work-precision` analysis (gd_workprec.h, docs/accuracy.md): the transient to one common
 * state on the attractor, a reference and its independent check, a grid of methods and settings
 * from that state (wp_run.c, their errors wp_errors.c) and the convergence order of the Poincare
 * points with and without event location. */
#include "wp_internal.h"
#include "geardyn/gd_scene.h"
#include "../core/clock.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

GD_API const char *gd_wp_status_name(int status)
{
    static const char *names[] = {"ok", "over-budget", "failed", "skipped", "unstable"};
    return status >= 0 && status <= 4 ? names[status] : "?";
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
    gd_status st = wp_run_one(j->c, j->m, wr, j->y0, &j->md0, j->W, 1, 0, &j->stop, &j->ref, err);
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
    if ((st = wp_run_one(j->c, j->m, wc, j->y0, &j->md0, j->W, 1, 0, &j->stop, chk, err)) != GD_OK)
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
        if ((st = wp_lyapunov_run(c, j->m, wr, j->y0, &j->md0, j->W, &j->stop, &R->mle_per_period, err)) != GD_OK) {
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
    wp_fill_run(&tmp, chk, &j->ref, j->W, j->H, R->chaotic, j->m->period, j->m->n, err, &st);
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
    wp_trace_free(&chk);
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
    gd_status st = wp_run_one(c, j->m, w, j->y0, &j->md0, j->W, 1, c->wp_max_steps_per_period, &j->stop, &tr, err);
    if (st != GD_OK) {
        wp_trace_free(&tr);
        return st;
    }
    double best = tr.cpu;
    for (int k = 1; k < c->wp_repeats && tr.status == GD_WP_OK; k++) {
        wp_trace again;
        st = wp_run_one(c, j->m, w, j->y0, &j->md0, j->W, 1, c->wp_max_steps_per_period, &j->stop, &again, err);
        if (st == GD_OK)
            best = fmin(best, again.cpu);
        wp_trace_free(&again);
        if (st != GD_OK) {
            wp_trace_free(&tr);
            return st;
        }
    }
    wp_fill_run(r, &tr, &j->ref, j->W, j->H, R->chaotic, j->m->period, j->m->n, err, &st);
    if (st != GD_OK) {
        wp_trace_free(&tr);
        return st;
    }
    r->cpu_s = best;
    *over = tr.status == GD_WP_OVER_BUDGET;
    if (tr.status == GD_WP_OK && R->chaotic && c->wp_lyapunov && isfinite(R->mle_per_period)) {
        gd_error le = {0};
        st = wp_lyapunov_run(c, j->m, w, j->y0, &j->md0, j->W, &j->stop, &r->mle_per_period, &le);
        if (st == GD_OK)
            r->err_mle = fabs(r->mle_per_period - R->mle_per_period);
        else if (st == GD_ERR_INTERRUPTED) { /* a failed exponent is only missing; a stop ends the analysis */
            wp_trace_free(&tr);
            return interrupted(err);
        }
    }
    wp_trace_free(&tr);
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
    gd_status st = wp_run_one(c, j->m, &w, j->y0, &j->md0, j->H, 0, c->wp_max_steps_per_period, &j->stop, &tr, err);
    if (st == GD_OK)
        wp_fill_run(r, &tr, &j->ref, j->H, j->H, 1, j->m->period, j->m->n, err, &st);
    if (st != GD_OK) {
        wp_trace_free(&tr);
        return st;
    }
    r->cpu_s = tr.cpu;
    r->err_rms = NAN; /* no samples in the order study */
    wp_trace_free(&tr);
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
        wp_fit_order(O, fmax(res->ref.check_short, 1e-14));
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
    wp_trace_free(&j->ref);
    res->wall_s = gd_clock_wall_s() - w0;
    if (st != GD_OK)
        gd_workprec_free(res);
    return st;
}
