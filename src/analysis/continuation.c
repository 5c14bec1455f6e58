/* Pseudo-arclength continuation of a periodic orbit in a parameter (docs/continuation.md section
 * 3): predictor along the unit tangent, Newton corrector on the shooting system bordered by the
 * arclength condition (shooting.c), both in a norm that scales the state by its size and the
 * parameter by its range; an adaptive step; at every point the test functions (cont_tests.c) and
 * between every two points their sign changes, located (cont_locate.c), the step to a parameter
 * bound included; the branch ends on a bound, its budget, a failure at the smallest step, or by its
 * geometry: closed, onto the orbit of half its period, or at the vertex of a period doubling of that
 * orbit (where it would turn onto its own image shifted by half the period). */
#include "cont_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

GD_API void gd_cont_opts_default(gd_cont_opts *co)
{
    memset(co, 0, sizeof *co);
    gd_po_opts_default(&co->po);
    co->p_min = 0.0;
    co->p_max = INFINITY;
    co->ds = 0.02;
    co->ds_min = 1e-6;
    co->ds_max = 0.2;
    co->max_points = 400;
    co->direction = 1;
}

GD_API const char *gd_bif_kind_name(int kind)
{
    static const char *names[] = {"fold", "period-doubling", "contact-change", "neimark-sacker", "branch-point"};
    return kind >= 0 && kind <= GD_BIF_BRANCH_POINT ? names[kind] : "?";
}

GD_API const char *gd_bif_location_name(int location)
{
    static const char *names[] = {"located", "bracket", "jump", "event-count"};
    return location >= 0 && location <= GD_LOC_EVENTS ? names[location] : "?";
}

GD_API void gd_branch_free(gd_branch *br)
{
    if (!br)
        return;
    free(br->pt);
    free(br->bif);
    memset(br, 0, sizeof *br);
}

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

gd_status cont_step(cont *c, const cpoint *a, double s, const double *guess, cpoint *q, int *iters, gd_error *err)
{
    const int N = c->sh.N;
    double up[UMAX], v[UMAX];
    for (int i = 0; i <= N; i++) {
        up[i] = a->u[i] + s * a->t[i];
        q->u[i] = guess ? guess[i] : up[i];
        v[i] = c->sh.w[i] * a->t[i];
    }
    q->gaps_ok = q->half_ok = 0;
    c->br->corrections++;
    gd_status st = gd_shoot_correct(&c->sh, q->u, v, up, c->tol, c->co->po.max_iter, iters, err);
    c->br->newton_iterations += *iters;
    if (st == GD_OK)
        st = gd_shoot_tangent(&c->sh, v, q->t, err);
    if (st == GD_OK)
        st = gd_shoot_orbit(&c->sh, q->u, &q->po, err);
    if (st == GD_OK) {
        q->po.iterations = *iters;
        q->bp_sign = c->sh.bp_sign;
        q->bp_log = c->sh.bp_log;
    }
    return st;
}

/* the start: the orbit corrected at its parameter, the tangent pointing to co->direction */
static gd_status start_branch(cont *c, const gd_po *start, cpoint *a, gd_error *err)
{
    const int n = c->sh.n, N = c->sh.N;
    gd_model m;
    gd_status st = c->sh.model_at(start->p, &m, c->sh.ctx, err);
    memcpy(a->u, start->y[0], sizeof(double) * (size_t)n);
    for (int k = 1; k < c->sh.nseg && st == GD_OK; k++)
        st = gd_sim_period_map(&m, &c->sh.o, a->u + (k - 1) * n, c->sh.per_seg, a->u + k * n, NULL, NULL, err);
    a->u[N] = start->p;
    a->gaps_ok = a->half_ok = 0;
    int iters = 0;
    if (st == GD_OK)
        st = gd_shoot_correct(&c->sh, a->u, NULL, NULL, c->tol, c->co->po.max_iter, &iters, err);
    c->br->newton_iterations += iters;
    c->br->corrections++;
    if (st == GD_OK)
        st = gd_shoot_eval(&c->sh, a->u, 1, err);
    double e[UMAX] = {0};
    e[N] = c->co->direction < 0 ? -1.0 : 1.0;
    if (st == GD_OK)
        st = gd_shoot_tangent(&c->sh, e, a->t, err);
    if (st == GD_OK)
        st = gd_shoot_orbit(&c->sh, a->u, &a->po, err);
    if (st == GD_OK) {
        a->po.iterations = iters;
        a->bp_sign = c->sh.bp_sign;
        a->bp_log = c->sh.bp_log;
        st = cont_gaps(c, a, err);
    }
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

/* The step from a crossed the bound pb: the orbit at p = pb, corrected with the parameter fixed (the
 * bordering row e_p, the predictor on the tangent where it meets pb), into *q, with its tangent
 * (oriented along a's) and extrema. */
static gd_status bound_point(cont *c, const cpoint *a, double pb, cpoint *q, gd_error *err)
{
    const int N = c->sh.N;
    double up[UMAX], e[UMAX] = {0}, v[UMAX];
    double s = (pb - a->u[N]) / a->t[N];
    if (!isfinite(s)) /* a tangent without a parameter component: start from the last point */
        s = 0.0;
    for (int i = 0; i <= N; i++) {
        up[i] = q->u[i] = a->u[i] + s * a->t[i];
        v[i] = c->sh.w[i] * a->t[i];
    }
    up[N] = q->u[N] = pb;
    e[N] = 1.0;
    q->gaps_ok = q->half_ok = 0;
    int iters = 0;
    c->br->corrections++;
    gd_status st = gd_shoot_correct(&c->sh, q->u, e, up, c->tol, c->co->po.max_iter, &iters, err);
    c->br->newton_iterations += iters;
    if (st == GD_OK)
        st = gd_shoot_tangent(&c->sh, v, q->t, err);
    if (st == GD_OK)
        st = gd_shoot_orbit(&c->sh, q->u, &q->po, err);
    if (st == GD_OK) {
        q->po.iterations = iters;
        q->bp_sign = c->sh.bp_sign;
        q->bp_log = c->sh.bp_log;
        st = cont_gaps(c, q, err);
    }
    return st;
}

/* The vertex of a period doubling of the orbit of half the period (docs/continuation.md section 3).
 * On a branch of an even period the orbit's antisymmetric part dh = y_0 - y_{nper/2} vanishes only on
 * the orbit of half the period repeated; where the branch meets that orbit, at a period doubling of
 * it, the branch has a branch point with a vertical tangent (a pitchfork of the map of nper periods):
 * beyond it runs the branch's own image shifted by half the period (dh reversed), and across it the
 * orbit of half the period itself (dh = 0). The arclength's hyperplane there nearly contains that
 * other branch, so a long step lands on it and no location in the arclength resolves the vertex.
 * A step whose |dh| shrinks below a quarter of the last point's without reversing (onto the orbit of
 * half the period, or towards it too fast) is shortened to keep a quarter (linearly in the step);
 * the branch ends at its last point when a step passes onto its image (dh reversed, of comparable
 * size) from a point within vertex_reach of the vertex, or when the step cannot be shortened. The
 * vertex's parameter is that of the parabola p = p_v + c |dh|^2 through the last two points: the
 * branch and its image are one curve, symmetric in dh, through the vertex. */
typedef enum { VTX_NONE, VTX_SHORTEN, VTX_END } vertex_step;

/* How near the vertex a point's |dh| must be for a step onto the image to end the branch: near the
 * vertex the shooting system is singular to order |dh|, so a point converged to tol is off by about
 * tol / |dh|, while p - p_v grows as |dh|^2; the two balance at (tol Y^2)^(1/3) (Y the state's
 * scale), and ten times that keeps the last points well above the balance. */
static double vertex_reach(const cont *c)
{
    return 10.0 * cbrt(c->tol * c->Y * c->Y);
}

static vertex_step vertex_check(const cont *c, const cpoint *a, const cpoint *b, double ds, double *ratio)
{
    if (!a->half_ok || !b->half_ok)
        return VTX_NONE;
    double ra = 0, rb = 0, proj = 0;
    for (int i = 0; i < a->po.n; i++) {
        ra += a->dh[i] * a->dh[i];
        rb += b->dh[i] * b->dh[i];
        proj += a->dh[i] * b->dh[i];
    }
    ra = sqrt(ra), rb = sqrt(rb), proj = ra > 0 ? proj / ra : 0.0;
    if (proj >= 0 && rb >= 0.25 * ra)
        return VTX_NONE;
    if ((proj < 0 && rb >= 0.25 * ra && ra <= vertex_reach(c)) || ds <= c->co->ds_min)
        return VTX_END;
    *ratio = proj >= 0 ? 0.75 * ra / (ra - proj) : 0.5;
    return VTX_SHORTEN;
}

static void end_at_vertex(cont *c, const cpoint *prev, const cpoint *a, const cpoint *b)
{
    double pv = a->po.p, aa = 0, ap = 0;
    for (int i = 0; i < a->po.n; i++)
        aa += a->dh[i] * a->dh[i];
    if (prev && prev->half_ok) { /* p = p_v + c alpha^2 through prev and a */
        for (int i = 0; i < prev->po.n; i++)
            ap += prev->dh[i] * prev->dh[i];
        if (ap > aa)
            pv = a->po.p - (prev->po.p - a->po.p) / (ap - aa) * aa;
    }
    c->br->end = GD_END_DOUBLING;
    c->br->vertex_p = pv;
    for (int i = 0; i < a->po.n; i++) /* the orbit of half the period, about: the mean of y_0 and y_{nper/2} */
        c->br->vertex_y[i] = a->po.y[0][i] - 0.5 * a->dh[i];
    snprintf(c->br->end_reason, sizeof c->br->end_reason, "at the vertex of a period doubling of the orbit of half "
             "the period, p = %.9g (estimated; the last point at p = %.9g, the next step reached p = %.9g)", pv,
             a->po.p, b->po.p);
}

/* The last step crossed the bound pb: the bifurcations between the last point inside and the orbit
 * on the bound are located, and the bound's orbit ends the branch (or a vertex before it). */
static gd_status end_on_bound(cont *c, const cpoint *prev, const cpoint *a, double pb, gd_error *err)
{
    const int N = c->sh.N;
    cpoint *q = malloc(2 * sizeof *q);
    if (!q)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the branch's last point");
    gd_error e1 = {0};
    gd_status st = bound_point(c, a, pb, q, &e1);
    c->br->end = GD_END_BOUND;
    if (st != GD_OK) { /* the branch ends at the last point inside */
        snprintf(c->br->end_detail, sizeof c->br->end_detail, "%s", e1.msg);
        snprintf(c->br->end_reason, sizeof c->br->end_reason, "the parameter left [%.9g, %.9g] after p = %.9g "
                 "(no orbit at the bound: %s)", c->co->p_min, c->co->p_max, a->u[N], e1.msg);
        free(q);
        return st == GD_ERR_NOMEM || st == GD_ERR_INTERRUPTED ? gd_error_set(err, st, "%s", e1.msg) : GD_OK;
    }
    double d[UMAX];
    for (int i = 0; i <= N; i++)
        d[i] = q->u[i] - a->u[i];
    double s = cont_dot(c, a->t, d); /* the bound point's arclength from a, along a's tangent */
    double ratio;
    st = cont_half(c, q, err);
    if (st == GD_OK && vertex_check(c, a, q, c->co->ds_min, &ratio) != VTX_NONE) { /* (a bound beyond the vertex) */
        end_at_vertex(c, prev, a, q);
        free(q);
        return GD_OK;
    }
    if (s > 0)
        st = cont_detect(c, a, q, s, err);
    if (st == GD_OK) {
        snprintf(c->br->end_reason, sizeof c->br->end_reason, "the bound p = %.9g reached", pb);
        st = push_point(c->br, &q->po, cont_fold_test(c, q), s, err);
    }
    free(q);
    return st;
}

#define DP_MARGIN 0.98 /* steps aim at this fraction of dp_max */

/* A point of the branch that a later step may come back to (the first point, and every
 * ANCHOR_EVERY-th after it), with its tangent, and whether the branch has left it (been farther from
 * it, and from its shifts, than twice the step that got there). */
#define ANCHOR_EVERY 8
typedef struct first_point {
    double u[UMAX], t[UMAX];
    int left, point;
} first_point;

/* x shifted by k segments: the same orbit started k segments later (the parameter kept) */
static void shifted(const gd_shoot *sh, const double *x, int k, double *out)
{
    for (int j = 0; j < sh->nseg; j++)
        memcpy(out + j * sh->n, x + ((j + k) % sh->nseg) * sh->n, sizeof(double) * (size_t)sh->n);
    out[sh->N] = x[sh->N];
}

/* Whether the chord from a to b passes the point f (or a shift of it by whole segments) within a
 * quarter of its length with the tangent tb along f's: the branch is a closed curve from f on,
 * followed once round (docs/continuation.md section 3). A shifted point may be passed the other way
 * (*reversed): the curve is symmetric under the shift, and what follows is the mirror image of the
 * branch's other direction from f. *kshift: the shift, in segments. Distances in the arclength's
 * norm. */
static int closes(const cont *c, first_point *f, const double *a, const double *b, const double *tb, int *kshift,
                  int *reversed)
{
    const gd_shoot *sh = &c->sh;
    const int M = sh->N + 1;
    double d2 = 0, nearest = INFINITY;
    for (int i = 0; i < M; i++)
        d2 += sh->w[i] * (b[i] - a[i]) * (b[i] - a[i]);
    int hit = 0;
    for (int k = 0; k < sh->nseg && !hit; k++) {
        double s[UMAX], ts[UMAX], w_d = 0, align = 0, dist2 = 0, db2 = 0;
        shifted(sh, f->u, k, s);
        shifted(sh, f->t, k, ts);
        for (int i = 0; i < M; i++) {
            w_d += sh->w[i] * (s[i] - a[i]) * (b[i] - a[i]);
            align += sh->w[i] * tb[i] * ts[i];
            db2 += sh->w[i] * (b[i] - s[i]) * (b[i] - s[i]);
        }
        double lam = d2 > 0 ? fmin(fmax(w_d / d2, 0.0), 1.0) : 0.0;
        for (int i = 0; i < M; i++) {
            double r = a[i] + lam * (b[i] - a[i]) - s[i];
            dist2 += sh->w[i] * r * r;
        }
        nearest = fmin(nearest, db2);
        if (f->left && dist2 < 0.0625 * d2 && (align > 0.5 || (k > 0 && align < -0.5)))
            hit = 1, *kshift = k, *reversed = align < 0;
    }
    if (nearest > 4.0 * d2)
        f->left = 1;
    return hit;
}

/* Whether the orbit at u is one of half its period repeated (the states of segment j and j + nseg/2
 * the same to a thousand times the corrector's tolerance): the branch has crossed onto the orbit it
 * doubled from. */
static int half_period(const gd_shoot *sh, const double *u, double tol)
{
    if (sh->nseg < 2 || sh->nseg % 2)
        return 0;
    const int h = sh->nseg / 2 * sh->n;
    double d = 0;
    for (int i = 0; i < h; i++)
        d = fmax(d, fabs(u[i] - u[i + h]));
    return d < 1e3 * tol;
}

/* Whether the step from a to b reversed the parameter's direction (the tangent's parameter part
 * changed sign) with no fold between them: on a smooth branch the parameter turns only where a real
 * multiplier passes 1 (det(M - I) changes sign), and on a non-smooth one where the orbit's contact
 * events change (a corner at a grazing). Neither: the corrector converged onto another part of the
 * branch, past a turn it did not follow (as the way back to a period doubling's vertex of the NASA
 * Glenn pair's period-2 branch did from 6486 rpm, landing at 6579 rpm on the branch's way up). */
static int turned_without_fold(const cont *c, const cpoint *a, const cpoint *b)
{
    if ((cont_fold_test(c, a) > 0) == (cont_fold_test(c, b) > 0))
        return 0;
    if ((cont_det_test(&a->po, 1.0) > 0) != (cont_det_test(&b->po, 1.0) > 0))
        return 0;
    for (int k = 0; k < GD_MAX_CLEAR; k++)
        if (a->po.events[k] != b->po.events[k])
            return 0;
    return 1;
}

static gd_status run(cont *c, const gd_po *start, gd_error *err)
{
    const gd_cont_opts *co = c->co;
    const int N = c->sh.N;
    cpoint *P = malloc(3 * sizeof *P); /* prev, a: the last two points; b: the next */
    if (!P)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the continuation");
    cpoint *prev = NULL, *a = P, *b = P + 1, *spare = P + 2;
    first_point *anchor = NULL;
    gd_status st = start_branch(c, start, a, err);
    if (st == GD_OK)
        st = cont_half(c, a, err);
    if (st == GD_OK)
        st = push_point(c->br, &a->po, cont_fold_test(c, a), 0.0, err);
    if (st != GD_OK)
        goto done;
    /* the points a step may come back to: the first, and every ANCHOR_EVERY-th */
    const int nanchor_max = co->max_points / ANCHOR_EVERY + 2;
    anchor = malloc(sizeof *anchor * (size_t)nanchor_max);
    int nanchor = 0;
    if (!anchor) {
        st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for the continuation");
        goto done;
    }
    anchor[nanchor] = (first_point){.left = 0, .point = 0};
    memcpy(anchor[nanchor].u, a->u, sizeof anchor[0].u);
    memcpy(anchor[nanchor++].t, a->t, sizeof anchor[0].t);
    double ds = co->ds;
    /* the corrected change of p over the predicted one, ds t_p, at the last step (at least 1): the
     * corrector moves p further than the tangent where the branch curves, and a step that then
     * exceeds dp_max is a correction lost */
    double gain = 1.0;
    while (c->br->npoints < co->max_points) {
        if (gd_stop_asked(&co->stop)) {
            st = gd_error_set(err, GD_ERR_INTERRUPTED, "the continuation was stopped at p = %.9g", a->u[N]);
            goto done;
        }
        int iters = 0;
        gd_error e1 = {0};
        if (fabs(ds * a->t[N]) * gain > DP_MARGIN * c->dp_max)
            ds = fmax(DP_MARGIN * c->dp_max / (fabs(a->t[N]) * gain), co->ds_min);
        st = cont_step(c, a, ds, NULL, b, &iters, &e1);
        double turn = st == GD_OK ? cont_dot(c, a->t, b->t) : 0.0;
        if (st == GD_ERR_NOMEM || st == GD_ERR_INTERNAL) {
            st = gd_error_set(err, st, "%s", e1.msg);
            goto done;
        }
        int too_far = st == GD_OK && fabs(b->u[N] - a->u[N]) > c->dp_max;
        if (st != GD_OK || turn < 0.5 || too_far) { /* no convergence, a turn too sharp, or p moved too far */
            const char *why = st != GD_OK ? e1.msg : too_far ? "the parameter moves more than dp_max"
                                                             : "the tangent turns too sharply";
            if (ds <= co->ds_min) {
                c->br->end = GD_END_STEP;
                snprintf(c->br->end_detail, sizeof c->br->end_detail, "%s", why);
                snprintf(c->br->end_reason, sizeof c->br->end_reason, "no convergence at the smallest step %.3g "
                         "from p = %.9g: %s", ds, a->u[N], why);
                st = GD_OK;
                goto done;
            }
            /* p moved too far: shorter in proportion; else half the step */
            ds = fmax(st == GD_OK && turn >= 0.5 ? ds * DP_MARGIN * c->dp_max / fabs(b->u[N] - a->u[N]) : 0.5 * ds,
                      co->ds_min);
            continue;
        }
        gain = fmax(1.0, fabs(b->u[N] - a->u[N]) / fabs(ds * a->t[N]));
        if (!isfinite(gain))
            gain = 1.0;
        st = cont_half(c, b, err);
        double ratio = 1.0;
        vertex_step vs = st == GD_OK ? vertex_check(c, a, b, ds, &ratio) : VTX_NONE;
        if (vs == VTX_END) {
            end_at_vertex(c, prev, a, b);
            goto done;
        }
        if (vs == VTX_SHORTEN) {
            ds = fmax(fmin(ratio, 0.5) * ds, co->ds_min);
            continue;
        }
        if (st == GD_OK && turned_without_fold(c, a, b)) { /* onto another part of the branch: half the step */
            if (ds <= co->ds_min) {
                c->br->end = GD_END_STEP;
                snprintf(c->br->end_detail, sizeof c->br->end_detail, "the parameter's direction reverses with no "
                         "multiplier passing 1 and the contact events unchanged");
                snprintf(c->br->end_reason, sizeof c->br->end_reason, "no convergence at the smallest step %.3g "
                         "from p = %.9g: %s", ds, a->u[N], c->br->end_detail);
                goto done;
            }
            ds = fmax(0.5 * ds, co->ds_min);
            continue;
        }
        if (b->u[N] < co->p_min || b->u[N] > co->p_max) {
            st = end_on_bound(c, prev, a, b->u[N] < co->p_min ? co->p_min : co->p_max, err);
            goto done;
        }
        if (st == GD_OK)
            st = cont_gaps(c, b, err);
        if (st == GD_OK)
            st = cont_detect(c, a, b, ds, err);
        if (st == GD_OK)
            st = push_point(c->br, &b->po, cont_fold_test(c, b), ds, err);
        if (st != GD_OK)
            goto done;
        if (half_period(&c->sh, b->u, c->tol)) {
            c->br->end = GD_END_HALF;
            snprintf(c->br->end_reason, sizeof c->br->end_reason, "the orbit of half the period reached at p = %.9g",
                     b->u[N]);
            goto done;
        }
        int k = 0, rev = 0, j = 0;
        while (j < nanchor && !closes(c, &anchor[j], a->u, b->u, b->t, &k, &rev))
            j++;
        if (j < nanchor) {
            c->br->end = GD_END_CLOSED;
            c->br->closed_shift = k * c->sh.per_seg;
            c->br->closed_reversed = rev;
            c->br->closed_point = anchor[j].point;
            if (anchor[j].point == 0)
                snprintf(c->br->end_reason, sizeof c->br->end_reason, "closed: back at its first orbit%s%s at p = "
                         "%.9g", k ? " shifted by whole mesh periods" : "", rev ? ", the other way" : "", b->u[N]);
            else
                snprintf(c->br->end_reason, sizeof c->br->end_reason, "closed: back at the orbit of its point %d%s%s "
                         "at p = %.9g (a closed curve from there on, followed once round)", anchor[j].point,
                         k ? " shifted by whole mesh periods" : "", rev ? ", the other way" : "", b->u[N]);
            goto done;
        }
        if ((c->br->npoints - 1) % ANCHOR_EVERY == 0 && nanchor < nanchor_max) {
            anchor[nanchor] = (first_point){.left = 0, .point = c->br->npoints - 1};
            memcpy(anchor[nanchor].u, b->u, sizeof anchor[0].u);
            memcpy(anchor[nanchor++].t, b->t, sizeof anchor[0].t);
        }
        cpoint *t = prev ? prev : spare;
        prev = a;
        a = b;
        b = t;
        ds = adapt(co, ds, iters);
    }
    c->br->end = GD_END_BUDGET;
    snprintf(c->br->end_reason, sizeof c->br->end_reason, "%d points reached at p = %.9g", co->max_points, a->u[N]);
done:
    free(anchor);
    free(P);
    return st;
}

/* The scales of the arclength and the tolerances (gd_cont_opts): Y from the starting orbit's nper
 * Poincare points, R from the bounds. */
static gd_status scales(cont *c, const gd_po *start, gd_error *err)
{
    const gd_cont_opts *co = c->co;
    double Y = co->y_scale;
    gd_status st = GD_OK;
    if (!(Y > 0)) {
        gd_model m;
        double y[GD_MAX_STATE];
        memcpy(y, start->y[0], sizeof y);
        Y = gd_po_state_scale(y, start->n);
        st = c->sh.model_at(start->p, &m, c->sh.ctx, err);
        for (int k = 1; k < co->po.nper && st == GD_OK; k++) {
            st = gd_sim_period_map(&m, &c->sh.o, y, 1, y, NULL, NULL, err);
            Y = fmax(Y, gd_po_state_scale(y, start->n));
        }
    }
    double R = co->p_scale;
    if (!(R > 0))
        R = isfinite(co->p_max - co->p_min) && co->p_max > co->p_min ? co->p_max - co->p_min : fmax(1.0, fabs(start->p));
    c->Y = Y;
    c->R = R;
    for (int i = 0; i < c->sh.N; i++)
        c->sh.w[i] = 1.0 / (c->sh.nseg * Y * Y);
    c->sh.w[c->sh.N] = 1.0 / (R * R);
    c->dp_max = co->dp_max > 0 ? co->dp_max : 0.02 * R;
    c->tol = co->po.tol > 0 ? co->po.tol : gd_po_tol_derived(&c->sh.o, Y);
    c->locate_tol = co->locate_tol > 0 ? co->locate_tol : 10.0 * c->tol / Y;
    c->br->y_scale = Y;
    c->br->p_scale = R;
    c->br->tol = c->tol;
    c->br->locate_tol = c->locate_tol;
    return st;
}

GD_API gd_status gd_continue(gd_model_at_fn model_at, void *ctx, const gd_solver_opts *o, const gd_cont_opts *co,
                             const gd_po *start, gd_branch *br, gd_error *err)
{
    memset(br, 0, sizeof *br);
    cont c;
    memset(&c, 0, sizeof c);
    c.co = co;
    c.br = br;
    gd_status st = gd_shoot_init(&c.sh, model_at, ctx, o, start->n, &co->po, err);
    c.sh.chord = 1;
    if (st == GD_OK)
        st = scales(&c, start, err);
    if (st == GD_OK)
        st = run(&c, start, err);
    br->chord_iterations = c.sh.chord_iterations;
    gd_shoot_free(&c.sh);
    return st;
}
