/* Pseudo-arclength continuation of a periodic orbit in a parameter (docs/continuation.md section
 * 3): predictor along the unit tangent, Newton corrector on the shooting system bordered by the
 * arclength condition (shooting.c), an adaptive step, and the location by bisection in the
 * arclength of the folds (the tangent's parameter component changes sign), period doublings
 * (det(M + I), the product of 1 + mu over the multipliers, changes sign: a real multiplier passed
 * -1) and changes of the contact sequence (the events of a clearance per orbit change in number:
 * a contact appears or disappears, through a grazing) found between two points. */
#include "shooting.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define UMAX (GD_PO_MAX_PERIODS * GD_MAX_STATE + 1)

GD_API void gd_cont_opts_default(gd_cont_opts *co)
{
    memset(co, 0, sizeof *co);
    gd_po_opts_default(&co->po);
    co->p_min = 0.0;
    co->p_max = INFINITY;
    co->ds = 0.02;
    co->ds_min = 1e-6;
    co->ds_max = 0.1;
    co->max_points = 400;
    co->direction = 1;
    co->locate_tol = 1e-8;
}

GD_API const char *gd_bif_kind_name(int kind)
{
    static const char *names[] = {"fold", "period-doubling", "contact-change", "neimark-sacker"};
    return kind >= 0 && kind <= GD_BIF_NEIMARK_SACKER ? names[kind] : "?";
}

GD_API void gd_branch_free(gd_branch *br)
{
    if (!br)
        return;
    free(br->pt);
    free(br->bif);
    memset(br, 0, sizeof *br);
}

typedef struct cont {
    gd_shoot sh;
    const gd_cont_opts *co;
    gd_branch *br;
} cont;

static gd_status push_point(gd_branch *br, const gd_po *po, double tp, double ds, gd_error *err)
{
    if (br->npoints == br->cap) {
        int cap = br->cap ? 2 * br->cap : 64;
        gd_cont_point *pt = realloc(br->pt, sizeof *pt * (size_t)cap);
        if (!pt)
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the branch");
        br->pt = pt;
        br->cap = cap;
    }
    gd_cont_point *q = &br->pt[br->npoints++];
    q->orbit = *po;
    q->tangent_p = tp;
    q->ds = ds;
    return GD_OK;
}

static gd_status push_bif(gd_branch *br, const gd_bifurcation *b, gd_error *err)
{
    if (br->nbif == br->bif_cap) {
        int cap = br->bif_cap ? 2 * br->bif_cap : 8;
        gd_bifurcation *bb = realloc(br->bif, sizeof *bb * (size_t)cap);
        if (!bb)
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the bifurcations");
        br->bif = bb;
        br->bif_cap = cap;
    }
    br->bif[br->nbif++] = *b;
    return GD_OK;
}

/* det(M + I) = prod (1 + mu_i) over the multipliers (real: conjugate pairs give |1 + mu|^2) */
static double pd_test(const gd_po *po)
{
    double re = 1.0, im = 0.0;
    for (int i = 0; i < po->n; i++) {
        double a = 1.0 + po->mu_re[i], b = po->mu_im[i];
        double r2 = re * a - im * b;
        im = re * b + im * a;
        re = r2;
    }
    return re;
}

/* The sign of the bialternate product prod_{i<j} (mu_i mu_j - 1) (real: the multipliers are closed under
 * conjugation). It changes sign where a complex pair crosses the unit circle (mu conj(mu) = 1), and at
 * a neutral saddle (two real multipliers with mu_i mu_j = 1), which locate() tells apart. Each factor
 * is divided by its modulus so that no product overflows. */
static double ns_test(const gd_po *po)
{
    double re = 1.0, im = 0.0;
    for (int i = 0; i < po->n; i++)
        for (int j = i + 1; j < po->n; j++) {
            double a = po->mu_re[i] * po->mu_re[j] - po->mu_im[i] * po->mu_im[j] - 1.0;
            double b = po->mu_re[i] * po->mu_im[j] + po->mu_im[i] * po->mu_re[j];
            double m = hypot(a, b);
            if (m == 0)
                return 0.0;
            double r2 = (re * a - im * b) / m;
            im = (re * b + im * a) / m;
            re = r2;
        }
    return re;
}

/* The complex multiplier (positive imaginary part) nearest the unit circle; 0 when there is none. */
static int ns_multiplier(const gd_po *po, double *re, double *im)
{
    int best = -1;
    for (int i = 0; i < po->n; i++)
        if (po->mu_im[i] > 1e-9 * (1.0 + fabs(po->mu_re[i])) &&
            (best < 0 || fabs(hypot(po->mu_re[i], po->mu_im[i]) - 1.0) <
                             fabs(hypot(po->mu_re[best], po->mu_im[best]) - 1.0)))
            best = i;
    if (best < 0)
        return 0;
    *re = po->mu_re[best];
    *im = po->mu_im[best];
    return 1;
}

/* One corrected point at arclength ds from (u0, t0): *u, its tangent *t (oriented along t0) and
 * its orbit; *iters the Newton iterations. */
static gd_status step_from(cont *c, const double *u0, const double *t0, double ds, double *u, double *t, gd_po *po,
                           int *iters, gd_error *err)
{
    const int N = c->sh.N;
    double up[UMAX];
    for (int i = 0; i <= N; i++)
        up[i] = u[i] = u0[i] + ds * t0[i];
    c->br->corrections++;
    gd_status st = gd_shoot_correct(&c->sh, u, t0, up, c->co->po.tol, c->co->po.max_iter, iters, err);
    c->br->newton_iterations += *iters;
    if (st == GD_OK)
        st = gd_shoot_tangent(&c->sh, t0, t, err);
    if (st == GD_OK)
        st = gd_shoot_orbit(&c->sh, u, po, err);
    if (st == GD_OK)
        po->iterations = *iters;
    return st;
}

/* the multiplier nearest target (fold: 1, period doubling: -1) */
static void critical_multiplier(const gd_po *po, double target, double *re, double *im)
{
    int best = 0;
    for (int i = 1; i < po->n; i++)
        if (hypot(po->mu_re[i] - target, po->mu_im[i]) < hypot(po->mu_re[best] - target, po->mu_im[best]))
            best = i;
    *re = po->mu_re[best];
    *im = po->mu_im[best];
}

/* The test function of `kind` at a point with tangent t and orbit po: its sign changes at the
 * bifurcation. A change of the contact sequence compares the events of clearance c per orbit with
 * those of the point before (ref): +1 the same, -1 different. */
static double test_value(int kind, int c, long ref, const double *t, int N, const gd_po *po)
{
    switch (kind) {
    case GD_BIF_FOLD:
        return t[N];
    case GD_BIF_PERIOD_DOUBLING:
        return pd_test(po);
    case GD_BIF_NEIMARK_SACKER:
        return ns_test(po);
    default:
        return po->events[c] == ref ? 1.0 : -1.0;
    }
}

/* A sign change of the test function of `kind` (clearance c for a contact change) between the point
 * (u0, t0, po0) and the one at arclength ds1: bisection in the arclength from u0 along t0 until the
 * bracket is below locate_tol. */
static gd_status locate(cont *c, int kind, int clr, const double *u0, const double *t0, const gd_po *po0, double ds1,
                        gd_error *err)
{
    const int N = c->sh.N;
    const long ref = clr >= 0 ? po0->events[clr] : 0;
    const double tau0 = test_value(kind, clr, ref, t0, N, po0);
    double lo = 0.0, hi = ds1, p_lo = u0[N], p_hi = NAN;
    double u[UMAX], t[UMAX];
    gd_po po;
    int iters;
    while (hi - lo > c->co->locate_tol) {
        double mid = 0.5 * (lo + hi);
        gd_status st = step_from(c, u0, t0, mid, u, t, &po, &iters, err);
        if (st != GD_OK)
            return st;
        if ((test_value(kind, clr, ref, t, N, &po) > 0) == (tau0 > 0))
            lo = mid, p_lo = u[N];
        else
            hi = mid, p_hi = u[N];
    }
    gd_status st = step_from(c, u0, t0, 0.5 * (lo + hi), u, t, &po, &iters, err);
    if (st != GD_OK)
        return st;
    gd_bifurcation b;
    memset(&b, 0, sizeof b);
    b.kind = kind;
    b.clearance = clr;
    b.p = u[N];
    b.p_lo = p_lo;
    b.p_hi = isnan(p_hi) ? u0[N] + ds1 * t0[N] : p_hi;
    critical_multiplier(&po, kind == GD_BIF_PERIOD_DOUBLING ? -1.0 : 1.0, &b.mu_re, &b.mu_im);
    if (kind == GD_BIF_NEIMARK_SACKER && /* a neutral saddle, not a complex pair on the unit circle */
        (!ns_multiplier(&po, &b.mu_re, &b.mu_im) || fabs(hypot(b.mu_re, b.mu_im) - 1.0) > 1e-3))
        return GD_OK;
    memcpy(b.y, po.y[0], sizeof(double) * (size_t)po.n);
    b.after = c->br->npoints;
    return push_bif(c->br, &b, err);
}

/* Locate every test function that changed sign between (u, t, po) and the point (t1, po1) at
 * arclength ds. */
static gd_status detect(cont *c, const double *u, const double *t, const gd_po *po, const double *t1,
                        const gd_po *po1, double ds, gd_error *err)
{
    const int N = c->sh.N;
    gd_status st = GD_OK;
    if ((t1[N] > 0) != (t[N] > 0))
        st = locate(c, GD_BIF_FOLD, -1, u, t, po, ds, err);
    if (st == GD_OK && (pd_test(po1) > 0) != (pd_test(po) > 0))
        st = locate(c, GD_BIF_PERIOD_DOUBLING, -1, u, t, po, ds, err);
    if (st == GD_OK && (ns_test(po1) > 0) != (ns_test(po) > 0))
        st = locate(c, GD_BIF_NEIMARK_SACKER, -1, u, t, po, ds, err);
    for (int k = 0; k < GD_MAX_CLEAR && st == GD_OK; k++)
        if (po1->events[k] != po->events[k])
            st = locate(c, GD_BIF_CONTACT_CHANGE, k, u, t, po, ds, err);
    return st;
}

/* the start: the orbit corrected at its parameter, the tangent pointing to co->direction */
static gd_status start_branch(cont *c, const gd_po *start, double *u, double *t, gd_po *po, gd_error *err)
{
    const int n = c->sh.n, N = c->sh.N;
    gd_model m;
    gd_status st = c->sh.model_at(start->p, &m, c->sh.ctx, err);
    memcpy(u, start->y[0], sizeof(double) * (size_t)n);
    for (int k = 1; k < c->sh.nseg && st == GD_OK; k++)
        st = gd_sim_period_map(&m, &c->sh.o, u + (k - 1) * n, c->sh.per_seg, u + k * n, NULL, NULL, err);
    u[N] = start->p;
    int iters = 0;
    if (st == GD_OK)
        st = gd_shoot_correct(&c->sh, u, NULL, NULL, c->co->po.tol, c->co->po.max_iter, &iters, err);
    c->br->newton_iterations += iters;
    c->br->corrections++;
    if (st == GD_OK)
        st = gd_shoot_eval(&c->sh, u, 1, err);
    double e[UMAX] = {0};
    e[N] = c->co->direction < 0 ? -1.0 : 1.0;
    if (st == GD_OK)
        st = gd_shoot_tangent(&c->sh, e, t, err);
    if (st == GD_OK)
        st = gd_shoot_orbit(&c->sh, u, po, err);
    if (st == GD_OK)
        po->iterations = iters;
    return st;
}

/* next step size: grow after an easy correction, shrink after a hard one */
static double adapt(const gd_cont_opts *co, double ds, int iters)
{
    if (iters <= 3)
        return fmin(1.5 * ds, co->ds_max);
    if (iters >= 6)
        return fmax(0.5 * ds, co->ds_min);
    return ds;
}

/* The step crossed the bound pb: the last point is the orbit at p = pb, corrected with the
 * parameter fixed (the bordering row e_p, the predictor on the tangent where it meets pb). */
static gd_status end_on_bound(cont *c, const double *u, const double *t, double pb, gd_error *err)
{
    const int N = c->sh.N;
    double up[UMAX], u1[UMAX], e[UMAX] = {0};
    double s = (pb - u[N]) / t[N];
    if (!isfinite(s)) /* a tangent without a parameter component: start from the last point */
        s = 0.0;
    for (int i = 0; i <= N; i++)
        up[i] = u1[i] = u[i] + s * t[i];
    up[N] = u1[N] = pb;
    e[N] = 1.0;
    int iters = 0;
    gd_error e1 = {0};
    c->br->corrections++;
    gd_status st = gd_shoot_correct(&c->sh, u1, e, up, c->co->po.tol, c->co->po.max_iter, &iters, &e1);
    c->br->newton_iterations += iters;
    gd_po po;
    double t1[UMAX];
    if (st == GD_OK)
        st = gd_shoot_tangent(&c->sh, t, t1, &e1);
    if (st == GD_OK)
        st = gd_shoot_orbit(&c->sh, u1, &po, &e1);
    c->br->end = GD_END_BOUND;
    if (st != GD_OK) { /* the branch ends at the last point inside */
        snprintf(c->br->end_detail, sizeof c->br->end_detail, "%s", e1.msg);
        snprintf(c->br->end_reason, sizeof c->br->end_reason, "the parameter left [%.9g, %.9g] after p = %.9g "
                 "(no orbit at the bound: %s)", c->co->p_min, c->co->p_max, u[N], e1.msg);
        return st == GD_ERR_NOMEM ? gd_error_set(err, st, "%s", e1.msg) : GD_OK;
    }
    po.iterations = iters;
    snprintf(c->br->end_reason, sizeof c->br->end_reason, "the bound p = %.9g reached", pb);
    return push_point(c->br, &po, t1[N], s, err);
}

static gd_status run(cont *c, const gd_po *start, gd_error *err)
{
    const gd_cont_opts *co = c->co;
    const int N = c->sh.N;
    double u[UMAX], t[UMAX], u1[UMAX], t1[UMAX];
    gd_po po, po1;
    gd_status st = start_branch(c, start, u, t, &po, err);
    if (st == GD_OK)
        st = push_point(c->br, &po, t[N], 0.0, err);
    if (st != GD_OK)
        return st;
    double ds = co->ds;
    while (c->br->npoints < co->max_points) {
        int iters = 0;
        gd_error e1 = {0};
        if (co->dp_max > 0 && fabs(ds * t[N]) > co->dp_max)
            ds = fmax(co->dp_max / fabs(t[N]), co->ds_min);
        st = step_from(c, u, t, ds, u1, t1, &po1, &iters, &e1);
        double turn = 0;
        for (int i = 0; i <= N && st == GD_OK; i++)
            turn += t[i] * t1[i];
        if (st == GD_ERR_NOMEM || st == GD_ERR_INTERNAL)
            return gd_error_set(err, st, "%s", e1.msg);
        int too_far = st == GD_OK && co->dp_max > 0 && fabs(u1[N] - u[N]) > co->dp_max;
        if (st != GD_OK || turn < 0.5 || too_far) { /* no convergence, a turn too sharp, or p moved too far */
            if (ds <= co->ds_min) {
                c->br->end = GD_END_STEP;
                snprintf(c->br->end_detail, sizeof c->br->end_detail, "%s", st != GD_OK ? e1.msg : too_far
                         ? "the parameter moves more than dp_max" : "the tangent turns too sharply");
                snprintf(c->br->end_reason, sizeof c->br->end_reason, "no convergence at the smallest step %.3g "
                         "from p = %.9g: %s", ds, u[N], st != GD_OK ? e1.msg : too_far ? "the parameter moves more than dp_max"
                         : "the tangent turns too sharply");
                return GD_OK;
            }
            ds = fmax(0.5 * ds, co->ds_min);
            continue;
        }
        if (u1[N] < co->p_min || u1[N] > co->p_max)
            return end_on_bound(c, u, t, u1[N] < co->p_min ? co->p_min : co->p_max, err);
        st = detect(c, u, t, &po, t1, &po1, ds, err);
        if (st == GD_OK)
            st = push_point(c->br, &po1, t1[N], ds, err);
        if (st != GD_OK)
            return st;
        memcpy(u, u1, sizeof u);
        memcpy(t, t1, sizeof t);
        po = po1;
        ds = adapt(co, ds, iters);
    }
    c->br->end = GD_END_BUDGET;
    snprintf(c->br->end_reason, sizeof c->br->end_reason, "%d points reached at p = %.9g", co->max_points, u[N]);
    return GD_OK;
}

GD_API gd_status gd_continue(gd_model_at_fn model_at, void *ctx, const gd_solver_opts *o, const gd_cont_opts *co,
                             const gd_po *start, gd_branch *br, gd_error *err)
{
    memset(br, 0, sizeof *br);
    cont c;
    c.co = co;
    c.br = br;
    gd_status st = gd_shoot_init(&c.sh, model_at, ctx, o, start->n, &co->po, err);
    if (st == GD_OK)
        st = run(&c, start, err);
    gd_shoot_free(&c.sh);
    return st;
}
