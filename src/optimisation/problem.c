/* Optimisation problems: bounds, the normalised box [-1, 1]^d, the repair of the linear
 * constraints, the counting wrapper every optimiser goes through, and gd_opt_run
 * (docs/optimisation.md sections 2 and 3). */
#include "opt_internal.h"
#include "../core/gsl_quiet.h"
#include "../core/clock.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

static const char *const alg_names[GD_OPT_NALGORITHMS] = {
    "alo", "gn_direct_l", "gn_crs2_lm", "gn_isres", "gn_esch", "ln_bobyqa", "ln_cobyla", "ln_sbplx", "random",
};

GD_API const char *gd_opt_algorithm_name(int a)
{
    return a >= 0 && a < GD_OPT_NALGORITHMS ? alg_names[a] : NULL;
}

GD_API int gd_opt_algorithm_parse(const char *name)
{
    for (int a = 0; a < GD_OPT_NALGORITHMS; a++)
        if (strcmp(name, alg_names[a]) == 0)
            return a;
    return -1;
}

GD_API int gd_opt_algorithm_is_local(int a)
{
    return a == GD_OPT_LN_BOBYQA || a == GD_OPT_LN_COBYLA || a == GD_OPT_LN_SBPLX;
}

GD_API int gd_opt_algorithm_is_deterministic(int a) { return a == GD_OPT_GN_DIRECT_L; }

GD_API void gd_opt_settings_default(gd_opt_settings *s)
{
    memset(s, 0, sizeof *s);
    s->algorithm = GD_OPT_ALO;
    s->budget = 3030;
    s->seed = 1;
    s->population = 30;
    s->threads = 1;
    s->local_xtol = 1e-8;
    s->local_step = 0.25;
}

int opt_threads(int requested)
{
#ifdef _OPENMP
    int n = requested > 0 ? requested : omp_get_max_threads();
    return n > 0 ? n : 1;
#else
    (void)requested;
    return 1;
#endif
}

void opt_first_failure_init(opt_first_failure *f, int n)
{
    pthread_mutex_init(&f->lock, NULL);
    f->index = n;
    f->st = GD_OK;
    memset(&f->err, 0, sizeof f->err);
}

void opt_first_failure_note(opt_first_failure *f, int i, gd_status st, const gd_error *e)
{
    pthread_mutex_lock(&f->lock);
    if (i < f->index) {
        f->index = i;
        f->st = st;
        f->err = *e;
    }
    pthread_mutex_unlock(&f->lock);
}

void opt_first_failure_destroy(opt_first_failure *f) { pthread_mutex_destroy(&f->lock); }

/* ---- constraints ------------------------------------------------------------------------------ */

static double row_dot(const gd_opt_problem *p, int i, const double *y)
{
    double s = 0;
    for (int k = 0; k < p->dim; k++)
        s += p->A[(size_t)i * (size_t)p->dim + (size_t)k] * y[k];
    return s;
}

static int strictly_feasible(const gd_opt_problem *p, const double *y)
{
    for (int i = 0; i < p->ncons; i++)
        if (!(row_dot(p, i, y) < p->b[i]))
            return 0;
    return 1;
}

GD_API gd_status gd_opt_problem_check(const gd_opt_problem *p, double *anchor, gd_error *err)
{
    if (!p || p->dim < 1 || !p->lower || !p->upper || !p->eval)
        return gd_error_set(err, GD_ERR_INPUT, "optimisation problem: no dimension, bounds or objective");
    for (int k = 0; k < p->dim; k++)
        if (!(isfinite(p->lower[k]) && isfinite(p->upper[k]) && p->lower[k] < p->upper[k]))
            return gd_error_set(err, GD_ERR_INPUT, "optimisation problem: variable %d has bounds [%g, %g] (valid: "
                                "finite, lower below upper)", k + 1, p->lower[k], p->upper[k]);
    if (p->ncons < 0 || (p->ncons > 0 && (!p->A || !p->b)))
        return gd_error_set(err, GD_ERR_INPUT, "optimisation problem: %d linear constraints without A or b", p->ncons);
    double *a = malloc(sizeof(double) * (size_t)p->dim);
    if (!a)
        return gd_error_set(err, GD_ERR_NOMEM, "optimisation problem: out of memory");
    int ok;
    if (p->anchor) {
        memcpy(a, p->anchor, sizeof(double) * (size_t)p->dim);
        ok = strictly_feasible(p, a);
        for (int k = 0; k < p->dim; k++)
            ok = ok && a[k] >= p->lower[k] && a[k] <= p->upper[k];
    } else {
        for (int k = 0; k < p->dim; k++)
            a[k] = 0.5 * (p->lower[k] + p->upper[k]);
        ok = strictly_feasible(p, a);
        if (!ok) {
            memcpy(a, p->lower, sizeof(double) * (size_t)p->dim);
            ok = strictly_feasible(p, a);
        }
    }
    if (ok && anchor)
        memcpy(anchor, a, sizeof(double) * (size_t)p->dim);
    free(a);
    if (!ok)
        return gd_error_set(err, GD_ERR_INPUT, "optimisation problem: %s (valid: a box whose %s satisfies A y < b "
                            "strictly)", p->anchor ? "the anchor is not strictly feasible" :
                            "neither the centre nor the lower corner of the box satisfies the linear constraints",
                            p->anchor ? "anchor lies in it and" : "centre or lower corner");
    return GD_OK;
}

GD_API void gd_opt_repair(const gd_opt_problem *p, const double *anchor, const double *y, double *out)
{
    int d = p->dim;
    double s = 1.0;
    for (int i = 0; i < p->ncons; i++) {
        double ay = row_dot(p, i, y);
        if (ay <= p->b[i])
            continue;
        double aa = row_dot(p, i, anchor);
        /* a.(anchor + s (y - anchor)) = b  <=>  s = (b - a.anchor) / (a.y - a.anchor), a.y > b > a.anchor */
        double si = (p->b[i] - aa) / (ay - aa);
        if (si < s)
            s = si;
    }
    if (s >= 1.0) {
        if (out != y)
            memcpy(out, y, sizeof(double) * (size_t)d);
        return;
    }
    s *= 1.0 - 1e-12;
    if (s < 0)
        s = 0;
    for (int k = 0; k < d; k++)
        out[k] = anchor[k] + s * (y[k] - anchor[k]);
}

GD_API int gd_opt_feasible(const gd_opt_problem *p, const double *y, double tol)
{
    for (int k = 0; k < p->dim; k++) {
        double h = 0.5 * (p->upper[k] - p->lower[k]);
        if (!(y[k] >= p->lower[k] - tol * h && y[k] <= p->upper[k] + tol * h))
            return 0;
    }
    for (int i = 0; i < p->ncons; i++)
        if (!(row_dot(p, i, y) <= p->b[i] + tol * (1.0 + fabs(p->b[i]))))
            return 0;
    return 1;
}

/* ---- the counting wrapper --------------------------------------------------------------------- */

void opt_ctx_free(opt_ctx *c)
{
    if (!c)
        return;
    if (c->states && c->p && c->p->state_alloc) {
        for (int i = 0; i < c->nstates; i++)
            if (c->states[i] && c->p->state_free)
                c->p->state_free(c->states[i]);
    }
    free(c->states);
    free(c->centre);
    free(c->best_y);
    free(c->ybuf);
    free(c->f_hist);
    free(c->best_hist);
    memset(c, 0, sizeof *c);
}

gd_status opt_ctx_init(opt_ctx *c, const gd_opt_problem *p, long budget, int nstates, int keep, gd_error *err)
{
    memset(c, 0, sizeof *c);
    c->p = p;
    c->dim = p->dim;
    c->budget = budget;
    c->keep = keep;
    c->best_f = INFINITY;
    c->nstates = nstates < 1 ? 1 : nstates;
    size_t d = (size_t)p->dim;
    c->centre = malloc(3 * d * sizeof(double));
    c->best_y = calloc(d, sizeof(double));
    c->ybuf = malloc((size_t)c->nstates * d * sizeof(double));
    c->states = calloc((size_t)c->nstates, sizeof(void *));
    int ok = c->centre && c->best_y && c->ybuf && c->states;
    if (ok && keep) {
        c->f_hist = malloc((size_t)budget * sizeof(double));
        c->best_hist = malloc((size_t)budget * sizeof(double));
        ok = c->f_hist && c->best_hist;
    }
    if (!ok) {
        opt_ctx_free(c);
        return gd_error_set(err, GD_ERR_NOMEM, "optimisation: out of memory for a budget of %ld evaluations", budget);
    }
    c->half = c->centre + d;
    c->anchor = c->half + d;
    for (size_t k = 0; k < d; k++) {
        c->centre[k] = 0.5 * (p->lower[k] + p->upper[k]);
        c->half[k] = 0.5 * (p->upper[k] - p->lower[k]);
    }
    gd_status st = gd_opt_problem_check(p, c->anchor, err);
    for (int i = 0; i < c->nstates && st == GD_OK; i++) {
        if (p->state_alloc)
            st = p->state_alloc(p->user, &c->states[i], err);
        else
            c->states[i] = p->user;
    }
    if (st != GD_OK)
        opt_ctx_free(c);
    return st;
}

void opt_to_physical(const opt_ctx *c, const double *x, double *y)
{
    for (int k = 0; k < c->dim; k++) {
        double xk = x[k] < -1.0 ? -1.0 : x[k] > 1.0 ? 1.0 : x[k];
        double v = c->centre[k] + c->half[k] * xk;
        /* the ends of the box exactly, whatever the rounding */
        y[k] = xk == -1.0 ? c->p->lower[k] : xk == 1.0 ? c->p->upper[k] : v;
    }
    gd_opt_repair(c->p, c->anchor, y, y);
}

static gd_status record(opt_ctx *c, const double *x, double f, gd_error *err)
{
    if (isnan(f)) {
        double y[64];
        int d = c->dim < 64 ? c->dim : 64;
        opt_to_physical(c, x, c->ybuf);
        memcpy(y, c->ybuf, sizeof(double) * (size_t)d);
        return gd_error_set(err, GD_ERR_INTERNAL, "optimisation: the objective returned NaN at evaluation %ld "
                            "(y1 = %g)", c->count + 1, y[0]);
    }
    c->count++;
    if (f < c->best_f) {
        c->best_f = f;
        c->best_at = c->count;
        opt_to_physical(c, x, c->best_y);
    }
    if (c->keep) {
        c->f_hist[c->count - 1] = f;
        c->best_hist[c->count - 1] = c->best_f;
    }
    return GD_OK;
}

gd_status opt_eval_batch(opt_ctx *c, const double *X, int n, double *f, int threads, int *m, gd_error *err)
{
    long left = c->budget - c->count;
    int todo = left < (long)n ? (int)(left > 0 ? left : 0) : n;
    *m = 0;
    for (int i = todo; i < n; i++)
        f[i] = INFINITY;
    if (todo == 0)
        return GD_OK;
    int nt = threads < 1 ? 1 : threads > c->nstates ? c->nstates : threads;
    if (nt > todo)
        nt = todo;
    opt_first_failure bad;
    opt_first_failure_init(&bad, todo);
    const gd_opt_problem *p = c->p;
    int d = c->dim;
#pragma omp parallel for schedule(dynamic, 1) num_threads(nt)
    for (int i = 0; i < todo; i++) {
        int tid = 0;
#ifdef _OPENMP
        tid = omp_get_thread_num();
#endif
        double *y = c->ybuf + (size_t)tid * (size_t)d;
        opt_to_physical(c, X + (size_t)i * (size_t)d, y);
        gd_error e = {0};
        gd_status st = gd_stop_asked(&c->stop) ? gd_error_set(&e, GD_ERR_INTERRUPTED, "stopped")
                                               : p->eval(c->states[tid], y, &f[i], &e);
        if (st != GD_OK)
            opt_first_failure_note(&bad, i, st, &e);
    }
    opt_first_failure_destroy(&bad);
    for (int i = 0; i < bad.index; i++) {
        gd_status st = record(c, X + (size_t)i * (size_t)d, f[i], err);
        if (st != GD_OK)
            return st;
        (*m)++;
    }
    if (bad.st != GD_OK) {
        if (err)
            *err = bad.err;
        gd_error_prefix(err, "optimisation, evaluation %ld", c->count + 1);
        return bad.st; /* recorded by another thread: this thread's last status is not it */
    }
    return GD_OK;
}

gd_status opt_eval_one(opt_ctx *c, const double *x, double *f, int *done, gd_error *err)
{
    *done = 0;
    if (c->count >= c->budget) {
        *done = 1;
        *f = c->best_f;
        return GD_OK;
    }
    double *y = c->ybuf;
    opt_to_physical(c, x, y);
    gd_status st = gd_stop_asked(&c->stop) ? gd_error_set(err, GD_ERR_INTERRUPTED, "stopped")
                                           : c->p->eval(c->states[0], y, f, err);
    if (st != GD_OK)
        return gd_error_prefix(err, "optimisation, evaluation %ld", c->count + 1);
    return record(c, x, *f, err);
}

/* ---- one run ---------------------------------------------------------------------------------- */

GD_API void gd_opt_result_free(gd_opt_result *r)
{
    if (!r)
        return;
    free(r->y);
    free(r->f_history);
    free(r->best_history);
    memset(r, 0, sizeof *r);
}

GD_API gd_status gd_opt_run(const gd_opt_problem *p, const gd_opt_settings *s, gd_opt_result *r, gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    memset(r, 0, sizeof *r);
    if (!gd_opt_algorithm_name(s->algorithm))
        return gd_error_set(err, GD_ERR_INPUT, "optimisation: unknown algorithm %d", s->algorithm);
    if (s->budget < 1)
        return gd_error_set(err, GD_ERR_INPUT, "optimisation: a budget of %ld evaluations (valid: >= 1)", s->budget);
    gd_opt_settings st_ = *s;
    if (st_.population <= 0)
        st_.population = 30;
    if (st_.local_xtol <= 0)
        st_.local_xtol = 1e-8;
    if (st_.local_step <= 0)
        st_.local_step = 0.25;
    if (st_.population < 2)
        return gd_error_set(err, GD_ERR_INPUT, "optimisation: a population of %d (valid: >= 2)", st_.population);
    if (st_.algorithm == GD_OPT_ALO && gd_alo_iterations(st_.budget, st_.population) < 1)
        return gd_error_set(err, GD_ERR_INPUT, "ALO: a budget of %ld evaluations for %d ants (valid: at least two "
                            "populations, %d)", st_.budget, st_.population, 2 * st_.population);
    int parallel = st_.algorithm == GD_OPT_ALO || st_.algorithm == GD_OPT_RANDOM;
    int threads = parallel ? opt_threads(st_.threads) : 1;
    if (threads > st_.population)
        threads = st_.population;
    opt_ctx c;
    gd_status st = opt_ctx_init(&c, p, st_.budget, threads, st_.keep_history, err);
    if (st != GD_OK)
        return st;
    st_.threads = threads;
    c.stop = st_.stop;
    r->dim = p->dim;
    r->algorithm = st_.algorithm;
    double t0 = gd_clock_wall_s();
    switch (st_.algorithm) {
    case GD_OPT_ALO: st = opt_alo(&c, &st_, r, err); break;
    case GD_OPT_RANDOM: st = opt_random(&c, &st_, r, err); break;
    default: st = opt_nlopt(&c, &st_, r, err); break;
    }
    r->wall_s = gd_clock_wall_s() - t0;
    if (st == GD_OK && c.count == 0)
        st = gd_error_set(err, GD_ERR_INTERNAL, "optimisation: %s made no evaluation", gd_opt_algorithm_name(s->algorithm));
    if (st == GD_OK && c.count > c.budget)
        st = gd_error_set(err, GD_ERR_INTERNAL, "optimisation: %ld evaluations over a budget of %ld", c.count, c.budget);
    if (st != GD_OK) {
        opt_ctx_free(&c);
        gd_opt_result_free(r);
        return st;
    }
    r->y = c.best_y;
    c.best_y = NULL;
    r->f = c.best_f;
    r->evaluations = c.count;
    r->best_at = c.best_at;
    r->f_history = c.f_hist;
    r->best_history = c.best_hist;
    c.f_hist = c.best_hist = NULL;
    opt_ctx_free(&c);
    return GD_OK;
}
