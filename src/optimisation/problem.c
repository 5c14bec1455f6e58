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
    "moalo", "weighted-sum", "eps-constraint",
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

GD_API int gd_opt_algorithm_objectives(int a)
{
    if (a == GD_OPT_RANDOM)
        return 3;
    if (a == GD_OPT_MOALO || a == GD_OPT_WEIGHTED_SUM || a == GD_OPT_EPS_CONSTRAINT)
        return 2;
    return a >= 0 && a < GD_OPT_NALGORITHMS ? 1 : 0;
}

int opt_problem_nobj(const gd_opt_problem *p) { return p->evalv ? p->nobj : 1; }

int opt_problem_nf(const gd_opt_problem *p) { return p->evalv ? p->nobj + p->naux : 1; }

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
    s->archive = 100;
    s->scalar_algorithm = GD_OPT_GN_CRS2_LM;
    s->scalar_grid = 8;
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
    if (!p || p->dim < 1 || !p->lower || !p->upper || (!p->eval && !p->evalv))
        return gd_error_set(err, GD_ERR_INPUT, "optimisation problem: no dimension, bounds or objective");
    if (p->evalv && (p->nobj < 1 || p->nobj > 2 || p->naux < 0 || p->naux > GD_OPT_MAX_AUX))
        return gd_error_set(err, GD_ERR_INPUT, "optimisation problem: %d objectives and %d recorded values (valid: 1 "
                            "or 2 objectives, 0 to %d values)", p->nobj, p->naux, GD_OPT_MAX_AUX);
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
    free(c->fbuf);
    free(c->fv_hist);
    free(c->hv_hist);
    opt_front_free(&c->front);
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
    c->nobj = opt_problem_nobj(p);
    c->naux = p->evalv ? p->naux : 0;
    c->nf = opt_problem_nf(p);
    c->front.dim = p->dim;
    size_t d = (size_t)p->dim, nf = (size_t)(c->nf > 0 ? c->nf : 1);
    c->centre = malloc(4 * d * sizeof(double));
    c->best_y = calloc(d, sizeof(double));
    c->ybuf = malloc((size_t)c->nstates * d * sizeof(double));
    c->fbuf = malloc((size_t)c->nstates * nf * sizeof(double));
    c->states = calloc((size_t)c->nstates, sizeof(void *));
    int ok = c->centre && c->best_y && c->ybuf && c->fbuf && c->states;
    if (ok && keep) {
        c->f_hist = malloc((size_t)budget * sizeof(double));
        c->best_hist = malloc((size_t)budget * sizeof(double));
        c->fv_hist = p->evalv ? malloc((size_t)budget * nf * sizeof(double)) : NULL;
        c->hv_hist = c->nobj == 2 ? malloc((size_t)budget * sizeof(double)) : NULL;
        ok = c->f_hist && c->best_hist && (!p->evalv || c->fv_hist) && (c->nobj != 2 || c->hv_hist);
    }
    if (!ok) {
        opt_ctx_free(c);
        return gd_error_set(err, GD_ERR_NOMEM, "optimisation: out of memory for a budget of %ld evaluations", budget);
    }
    c->half = c->centre + d;
    c->anchor = c->half + d;
    c->yrec = c->anchor + d;
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

/* The objective of problem p at y into fv (nf values) on state. */
static gd_status call_eval(const gd_opt_problem *p, void *state, const double *y, double *fv, gd_error *err)
{
    if (p->evalv)
        return p->evalv(state, y, fv, err);
    return p->eval(state, y, fv, err);
}

double opt_scalar(const opt_ctx *c, const double *fv)
{
    if (c->nobj < 2)
        return fv[0];
    double a = fv[0] / c->hv_ref[0], b = fv[1] / c->hv_ref[1];
    switch (c->sc_kind) {
    case OPT_SC_WEIGHTED: return c->sc_w * a + (1.0 - c->sc_w) * b;
    case OPT_SC_EPS: return a <= c->sc_eps ? b : OPT_EPS_INFEASIBLE + (a - c->sc_eps);
    default: return fv[0];
    }
}

static gd_status record(opt_ctx *c, const double *x, const double *fv, gd_error *err)
{
    for (int k = 0; k < c->nobj; k++)
        if (isnan(fv[k])) {
            opt_to_physical(c, x, c->yrec);
            return gd_error_set(err, GD_ERR_INTERNAL, "optimisation: the objective%s returned NaN at evaluation %ld "
                                "(y1 = %g)", c->nobj > 1 ? "s" : "", c->count + 1, c->yrec[0]);
        }
    double f = opt_scalar(c, fv);
    c->count++;
    if (f < c->best_f) {
        c->best_f = f;
        c->best_at = c->count;
        opt_to_physical(c, x, c->best_y);
    }
    if (c->nobj == 2) {
        opt_to_physical(c, x, c->yrec);
        if (opt_front_insert(&c->front, c->yrec, fv) < 0)
            return gd_error_set(err, GD_ERR_NOMEM, "optimisation: out of memory for the front");
    }
    if (c->keep) {
        c->f_hist[c->count - 1] = f;
        c->best_hist[c->count - 1] = c->best_f;
        if (c->fv_hist)
            memcpy(c->fv_hist + (size_t)(c->count - 1) * (size_t)c->nf, fv, sizeof(double) * (size_t)c->nf);
        if (c->hv_hist)
            c->hv_hist[c->count - 1] = c->front.hv;
    }
    if (c->progress)
        c->progress(c->progress_user, c->count, c->budget);
    return GD_OK;
}

gd_status opt_eval_batch(opt_ctx *c, const double *X, int n, double *f, double *fv, int threads, int *m,
                         gd_error *err)
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
    const int nf = c->nf;
    double *vals = fv ? fv : malloc(sizeof(double) * (size_t)todo * (size_t)nf);
    if (!vals)
        return gd_error_set(err, GD_ERR_NOMEM, "optimisation: out of memory");
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
                                               : call_eval(p, c->states[tid], y, vals + (size_t)i * (size_t)nf, &e);
        if (st != GD_OK)
            opt_first_failure_note(&bad, i, st, &e);
    }
    opt_first_failure_destroy(&bad);
    for (int i = 0; i < bad.index; i++) {
        const double *v = vals + (size_t)i * (size_t)nf;
        gd_status st = record(c, X + (size_t)i * (size_t)d, v, err);
        if (st != GD_OK) {
            if (!fv)
                free(vals);
            return st;
        }
        f[i] = opt_scalar(c, v);
        (*m)++;
    }
    for (int i = bad.index; i < todo; i++)
        f[i] = INFINITY;
    if (!fv)
        free(vals);
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
    double *y = c->ybuf, *v = c->fbuf;
    opt_to_physical(c, x, y);
    gd_status st = gd_stop_asked(&c->stop) ? gd_error_set(err, GD_ERR_INTERRUPTED, "stopped")
                                           : call_eval(c->p, c->states[0], y, v, err);
    if (st != GD_OK)
        return gd_error_prefix(err, "optimisation, evaluation %ld", c->count + 1);
    st = record(c, x, v, err);
    *f = opt_scalar(c, v);
    return st;
}

/* ---- one run ---------------------------------------------------------------------------------- */

GD_API void gd_opt_result_free(gd_opt_result *r)
{
    if (!r)
        return;
    free(r->y);
    free(r->f_history);
    free(r->best_history);
    free(r->fv_history);
    free(r->front_y);
    free(r->front_f);
    free(r->hv_history);
    free(r->archive_y);
    free(r->archive_f);
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
    if ((st_.algorithm == GD_OPT_ALO || st_.algorithm == GD_OPT_MOALO) &&
        gd_alo_iterations(st_.budget, st_.population) < 1)
        return gd_error_set(err, GD_ERR_INPUT, "%s: a budget of %ld evaluations for %d ants (valid: at least two "
                            "populations, %d)", gd_opt_algorithm_name(st_.algorithm), st_.budget, st_.population,
                            2 * st_.population);
    int nobj = p ? opt_problem_nobj(p) : 1;
    if (!(gd_opt_algorithm_objectives(st_.algorithm) & (nobj == 2 ? 2 : 1)))
        return gd_error_set(err, GD_ERR_INPUT, "optimisation: %s minimises %s, the problem has %d objective%s",
                            gd_opt_algorithm_name(st_.algorithm), nobj == 2 ? "one objective" : "two objectives",
                            nobj, nobj == 1 ? "" : "s");
    if (nobj == 2 && !(st_.hv_ref[0] > 0 && st_.hv_ref[1] > 0 && isfinite(st_.hv_ref[0]) && isfinite(st_.hv_ref[1])))
        return gd_error_set(err, GD_ERR_INPUT, "optimisation: two objectives with the reference point (%g, %g) "
                            "(valid: both finite and positive)", st_.hv_ref[0], st_.hv_ref[1]);
    if (st_.archive <= 0)
        st_.archive = 100;
    if (st_.scalar_grid <= 0)
        st_.scalar_grid = 8;
    if (st_.scalar_algorithm <= 0)
        st_.scalar_algorithm = GD_OPT_GN_CRS2_LM;
    if ((st_.algorithm == GD_OPT_WEIGHTED_SUM || st_.algorithm == GD_OPT_EPS_CONSTRAINT) &&
        (gd_opt_algorithm_objectives(st_.scalar_algorithm) != 1 || st_.scalar_algorithm == GD_OPT_ALO))
        return gd_error_set(err, GD_ERR_INPUT, "optimisation: %s with %s (valid: an NLopt method, gn_* or ln_*)",
                            gd_opt_algorithm_name(st_.algorithm), gd_opt_algorithm_name(st_.scalar_algorithm) ?
                            gd_opt_algorithm_name(st_.scalar_algorithm) : "an unknown method");
    int parallel = st_.algorithm == GD_OPT_ALO || st_.algorithm == GD_OPT_RANDOM || st_.algorithm == GD_OPT_MOALO;
    int threads = parallel ? opt_threads(st_.threads) : 1;
    if (threads > st_.population)
        threads = st_.population;
    opt_ctx c;
    gd_status st = opt_ctx_init(&c, p, st_.budget, threads, st_.keep_history, err);
    if (st != GD_OK)
        return st;
    st_.threads = threads;
    c.stop = st_.stop;
    c.hv_ref[0] = c.front.ref[0] = st_.hv_ref[0];
    c.hv_ref[1] = c.front.ref[1] = st_.hv_ref[1];
    c.progress = st_.progress;
    c.progress_user = st_.progress_user;
    r->dim = p->dim;
    r->algorithm = st_.algorithm;
    r->nobj = c.nobj;
    r->naux = c.naux;
    double t0 = gd_clock_wall_s();
    switch (st_.algorithm) {
    case GD_OPT_ALO: st = opt_alo(&c, &st_, r, err); break;
    case GD_OPT_RANDOM: st = opt_random(&c, &st_, r, err); break;
    case GD_OPT_MOALO: st = opt_moalo(&c, &st_, r, err); break;
    case GD_OPT_WEIGHTED_SUM:
    case GD_OPT_EPS_CONSTRAINT: st = opt_scalarised(&c, &st_, r, err); break;
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
    r->fv_history = c.fv_hist;
    r->hv_history = c.hv_hist;
    c.f_hist = c.best_hist = c.fv_hist = c.hv_hist = NULL;
    if (c.nobj == 2) {
        r->f = NAN; /* two objectives: the front, not a best value */
        r->nfront = c.front.n;
        r->front_y = c.front.y;
        r->front_f = c.front.f;
        r->hv = opt_front_hv(&c.front); /* summed afresh: no rounding of the running sum */
        c.front.y = c.front.f = NULL;
        c.front.n = 0;
    }
    opt_ctx_free(&c);
    return GD_OK;
}
