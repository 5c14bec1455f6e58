/* A curve of codimension-one bifurcations of periodic orbits in two parameters (gd_envelope.h,
 * docs/continuation.md section 8): its start corrected from a one-parameter bifurcation at fixed p2,
 * pseudo-arclength continuation of the defining system (curve_system.c) in a norm that scales the
 * state and the two parameters, borders refreshed at every accepted point, the test functions of the
 * codimension-two points at every point and their sign changes located by GSL's Brent solver, and
 * the ends: the box, the budget, the smallest step, a closed curve, a change of the orbit's contact
 * sequence (a grazing met, located on the distance of the followed extremum to its boundary), a
 * strong resonance 1:1 or 1:2 on a Neimark-Sacker curve, the model's validity, a jump of the model in a
 * parameter (curve_system.c's differences), no progress (points in a row at the smallest step). */
#include "curve_internal.h"
#include "cont_internal.h"
#include "geardyn/gd_scene.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

GD_API void gd_curve_opts_default(gd_curve_opts *co)
{
    memset(co, 0, sizeof *co);
    gd_po_opts_default(&co->po);
    co->p_min[0] = co->p_min[1] = -INFINITY;
    co->p_max[0] = co->p_max[1] = INFINITY;
    co->ds = 0.02;
    co->ds_min = 1e-6;
    co->ds_max = 0.2;
    co->max_points = 400;
    co->direction = 1;
}

GD_API const char *gd_curve_kind_name(int kind)
{
    static const char *names[] = {"fold", "period-doubling", "neimark-sacker", "grazing"};
    return kind >= 0 && kind <= GD_CURVE_GRAZING ? names[kind] : "?";
}

GD_API const char *gd_codim2_kind_name(int kind)
{
    static const char *names[] = {"cusp", "fold-flip", "resonance-1:1", "resonance-1:2", "resonance-1:3",
                                  "resonance-1:4", "grazing-fold", "grazing-period-doubling",
                                  "grazing-neimark-sacker", "double-grazing"};
    return kind >= 0 && kind <= GD_C2_DOUBLE_GRAZING ? names[kind] : "?";
}

GD_API const char *gd_codim2_label(int kind)
{
    static const char *names[] = {"CP", "FF", "R1", "R2", "R3", "R4", "GF", "GPD", "GNS", "DG"};
    return kind >= 0 && kind <= GD_C2_DOUBLE_GRAZING ? names[kind] : "?";
}

GD_API const char *gd_curve_end_name(int end)
{
    static const char *names[] = {"bound", "budget", "step", "closed", "contact", "resonance", "invalid",
                                  "inadmissible", "discontinuous", "stall"};
    return end >= 0 && end <= GD_CEND_STALL ? names[end] : "?";
}

GD_API void gd_curve_free(gd_curve *cv)
{
    if (!cv)
        return;
    free(cv->pt);
    free(cv->c2);
    memset(cv, 0, sizeof *cv);
}

GD_API gd_status gd_model_at_case_keys(double p1, double p2, gd_model *m, void *ctx, gd_error *err)
{
    const gd_case_param2 *a = ctx;
    gd_status st = gd_case_set_number(a->c, a->key1, a->scale1 * p1, err);
    if (st == GD_OK)
        st = gd_case_set_number(a->c, a->key2, a->scale2 * p2, err);
    if (st == GD_OK)
        st = gd_case_check(a->c, err);
    if (st == GD_OK)
        st = gd_scene_resolve(a->c, err);
    if (st == GD_OK)
        st = gd_model_build(a->c, m, err);
    return st == GD_OK ? GD_OK
                       : gd_error_prefix(err, "the model at %s = %.9g, %s = %.9g", a->key1, a->scale1 * p1, a->key2,
                                         a->scale2 * p2);
}

/* ---- the continuation ---- */

typedef struct ccont {
    csys *S;
    const gd_curve_opts *co;
    gd_curve *cv;
    double tol, locate_tol, Y, R[2], dp_max[2];
    double *Jc;              /* the Jacobian of the last accepted point, kept for the chord iteration */
    double *Jn;              /* that of the new point */
    int have_Jc;
} ccont;

/* A point of the curve: unknowns, unit tangent, what it carries, and the extrema of its clearance
 * coordinates (phases of the orbit in [0, 1)). */
typedef struct cpt {
    double u[CMAX], t[CMAX];
    gd_curve_point pt;
    int seq_changed;
    int gaps_ok;
    gd_gap_extrema g;
    double xddg;             /* grazing: the clearance coordinate's acceleration at the touch */
    double v[GD_MAX_STATE], wl[GD_MAX_STATE], X[GD_MAX_STATE * 2], Psi[GD_MAX_STATE * 2]; /* its null vectors */
} cpt;

static double dot_w(const ccont *C, const double *a, const double *b)
{
    double d = 0;
    for (int i = 0; i < C->S->D; i++)
        d += C->S->w[i] * a[i] * b[i];
    return d;
}

static gd_status push_point(gd_curve *cv, const gd_curve_point *p, gd_error *err)
{
    if (cv->npoints == cv->cap) {
        int cap = cv->cap ? 2 * cv->cap : 64;
        gd_curve_point *q = realloc(cv->pt, sizeof *q * (size_t)cap);
        if (!q)
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a curve");
        cv->pt = q;
        cv->cap = cap;
    }
    cv->pt[cv->npoints++] = *p;
    return GD_OK;
}

static gd_status push_c2(gd_curve *cv, const gd_codim2 *c, gd_error *err)
{
    if (cv->nc2 == cv->c2_cap) {
        int cap = cv->c2_cap ? 2 * cv->c2_cap : 8;
        gd_codim2 *q = realloc(cv->c2, sizeof *q * (size_t)cap);
        if (!q)
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a curve's codimension-two points");
        cv->c2 = q;
        cv->c2_cap = cap;
    }
    cv->c2[cv->nc2++] = *c;
    return GD_OK;
}

/* the largest residual of the orbit's equations, and of the defining equations relative to their tolerance */
static int converged(const ccont *C, const double *v, const double *u, const double *u_pred)
{
    const csys *S = C->S;
    double r = 0, gmax = 0;
    for (int i = 0; i < S->N; i++)
        r = fmax(r, fabs(S->F[i]));
    double tg = S->kind == GD_CURVE_GRAZING ? C->tol : S->rtol_g + C->tol / C->Y;
    for (int i = S->N; i < S->D - 1; i++)
        gmax = fmax(gmax, fabs(S->F[i]) / tg);
    double g = 0;
    if (v)
        for (int i = 0; i < S->D; i++)
            g += v[i] * (u[i] - u_pred[i]);
    return r < C->tol && gmax < 1.0 && fabs(g) < C->tol * sqrt(S->w[0]) && isfinite(r + gmax + g);
}

/* The residual against the tolerances of converged(): the orbit's part over tol, the extra equations over
 * theirs (a corrector's progress). */
static double merit(const ccont *C)
{
    const csys *S = C->S;
    double r = 0;
    for (int i = 0; i < S->N; i++)
        r = fmax(r, fabs(S->F[i]) / C->tol);
    double tg = S->kind == GD_CURVE_GRAZING ? C->tol : S->rtol_g + C->tol / C->Y;
    for (int i = S->N; i < S->D - 1; i++)
        r = fmax(r, fabs(S->F[i]) / tg);
    return isfinite(r) ? r : INFINITY;
}

/* x = [J; v^T]^-1 b for the Jacobian Jm ((D - 1) x D) bordered by v */
static gd_status bordered_solve(const ccont *C, const double *Jm, const double *v, const double *b, double *x,
                                gd_error *err)
{
    const int D = C->S->D;
    gsl_matrix *A = gsl_matrix_alloc((size_t)D, (size_t)D);
    gsl_permutation *perm = gsl_permutation_alloc((size_t)D);
    gsl_vector *bv = gsl_vector_alloc((size_t)D), *xv = gsl_vector_alloc((size_t)D);
    gd_status st = GD_OK;
    if (!A || !perm || !bv || !xv) {
        st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for a curve's Newton system");
        goto done;
    }
    for (int i = 0; i < D - 1; i++)
        for (int j = 0; j < D; j++)
            gsl_matrix_set(A, (size_t)i, (size_t)j, Jm[(size_t)i * D + j]);
    for (int j = 0; j < D; j++) {
        gsl_matrix_set(A, (size_t)(D - 1), (size_t)j, v[j]);
        gsl_vector_set(bv, (size_t)j, b[j]);
    }
    int signum, rc = gsl_linalg_LU_decomp(A, perm, &signum);
    if (rc == GSL_SUCCESS)
        rc = gsl_linalg_LU_solve(A, perm, bv, xv);
    if (rc != GSL_SUCCESS) {
        st = gd_error_set(err, GD_ERR_GSL, "a curve's Newton system: gsl_linalg_LU: %s", gsl_strerror(rc));
        goto done;
    }
    for (int j = 0; j < D; j++)
        x[j] = gsl_vector_get(xv, (size_t)j);
    for (int j = 0; j < D; j++)
        if (!isfinite(x[j]))
            st = gd_error_set(err, GD_ERR_SOLVER, "a curve's Newton system is singular");
done:
    gsl_matrix_free(A);
    gsl_permutation_free(perm);
    gsl_vector_free(bv);
    gsl_vector_free(xv);
    return st;
}

/* Newton on the curve's system bordered by v . (u - u_pred) = 0, from u (in and out): the chord
 * iteration with the kept Jacobian first (residuals only, while each at least halves the residual's
 * norm), then Newton, given up when CORRECT_NO_GAIN iterations in a row bring the residual (merit) no
 * lower than its best: a corrector that diverges, or stagnates on the integration's noise, fails after
 * a few Jacobians instead of max_iter (the step is halved and tried again). The last evaluation is at
 * the returned u, with its Jacobian. */
#define CORRECT_NO_GAIN 3
static gd_status correct(ccont *C, double *u, const double *v, const double *u_pred, int *iters, gd_error *err)
{
    csys *S = C->S;
    const int D = S->D;
    double b[CMAX], dx[CMAX];
    *iters = 0;
    C->cv->corrections++;
    S->sus_q = -1;
    if (C->have_Jc) {
        double last = INFINITY, keep[CMAX];
        memcpy(keep, u, sizeof(double) * (size_t)D);
        for (int it = 0; it < 8; it++) {
            gd_error e1 = {0};
            gd_status st = csys_eval(S, u, 0, &e1);
            if (st == GD_ERR_NOMEM || st == GD_ERR_INTERRUPTED)
                return gd_error_set(err, st, "%s", e1.msg);
            if (st != GD_OK)
                break;
            double rn = 0;
            for (int i = 0; i < D - 1; i++)
                rn = fmax(rn, fabs(S->F[i]));
            if (converged(C, v, u, u_pred)) {
                st = csys_eval(S, u, 1, err);
                return st;
            }
            if (!(rn < 0.5 * last))
                break;
            memcpy(keep, u, sizeof(double) * (size_t)D);
            last = rn;
            double g = 0;
            for (int i = 0; i < D; i++)
                g += v[i] * (u[i] - u_pred[i]);
            for (int i = 0; i < D - 1; i++)
                b[i] = -S->F[i];
            b[D - 1] = -g;
            if (bordered_solve(C, C->Jc, v, b, dx, &e1) != GD_OK)
                break;
            for (int i = 0; i < D; i++)
                u[i] += dx[i];
        }
        memcpy(u, keep, sizeof(double) * (size_t)D);
    }
    const int max_iter = C->co->po.max_iter > 0 ? C->co->po.max_iter : 12;
    double best = INFINITY;
    int best_it = 0;
    for (int it = 0;; it++) {
        *iters = it;
        gd_status st = csys_eval(S, u, 1, err);
        if (st != GD_OK)
            return st;
        if (converged(C, v, u, u_pred))
            return GD_OK;
        const double m = merit(C);
        if (m < best)
            best = m, best_it = it;
        if (it == max_iter || it - best_it >= CORRECT_NO_GAIN)
            break;
        double g = 0;
        for (int i = 0; i < D; i++)
            g += v[i] * (u[i] - u_pred[i]);
        for (int i = 0; i < D - 1; i++)
            b[i] = -S->F[i];
        b[D - 1] = -g;
        st = bordered_solve(C, S->J, v, b, dx, err);
        if (st != GD_OK)
            return st;
        for (int i = 0; i < D; i++)
            u[i] += dx[i];
        C->cv->newton_iterations++;
    }
    double rn = 0;
    for (int i = 0; i < D - 1; i++)
        rn = fmax(rn, fabs(S->F[i]));
    return gd_error_set(err, GD_ERR_SOLVER, "the curve's corrector did not converge: residual %.3g after %d "
                        "iterations%s", rn, *iters, *iters < max_iter ? " (no progress in the last three)" : "");
}

/* the unit tangent at the last evaluation (its Jacobian), oriented along v */
static gd_status tangent(ccont *C, const double *v, double *t, gd_error *err)
{
    const int D = C->S->D;
    double b[CMAX] = {0};
    b[D - 1] = 1.0;
    gd_status st = bordered_solve(C, C->S->J, v, b, t, err);
    if (st != GD_OK)
        return st;
    double nrm = sqrt(dot_w(C, t, t)), d = 0;
    for (int i = 0; i < D; i++)
        d += t[i] * v[i];
    nrm *= d < 0 ? -1.0 : 1.0;
    for (int i = 0; i < D; i++)
        t[i] /= nrm;
    return GD_OK;
}

/* What a point carries, from the last evaluation at q->u (with its Jacobian): the orbit, its
 * multipliers, the test functions. */
static gd_status fill_point(ccont *C, cpt *q, int iters, double ds, gd_error *err)
{
    csys *S = C->S;
    const int n = S->n, N = S->N;
    gd_curve_point *p = &q->pt;
    memset(p, 0, sizeof *p);
    gd_po *o = &p->orbit;
    o->n = n;
    o->nper = S->nper;
    o->nseg = S->nseg;
    o->p = q->u[N];
    for (int k = 0; k < S->nseg; k++)
        memcpy(o->y[k], q->u + k * n, sizeof(double) * (size_t)n);
    for (int i = 0; i < N; i++)
        o->residual = fmax(o->residual, fabs(S->F[i]));
    memcpy(o->events, S->events, sizeof o->events);
    gd_status st = gd_floquet_segments(S->Mk, S->nseg, n, o->M, o->mu_re, o->mu_im, err);
    if (st != GD_OK)
        return st;
    o->mu_max = hypot(o->mu_re[0], o->mu_im[0]);
    o->stable = o->mu_max < 1.0;
    o->iterations = iters;
    p->p2 = q->u[N + 1];
    p->kappa = S->kind == GD_CURVE_NEIMARK_SACKER ? q->u[N + 2] : NAN;
    p->t_graze = S->kind == GD_CURVE_GRAZING ? q->u[N + 2] - floor(q->u[N + 2]) : NAN;
    for (int i = 0; i < GD_CURVE_NTEST; i++)
        p->test[i] = NAN;
    if (S->kind == GD_CURVE_FOLD)
        p->test[GD_CT_CUSP] = S->cusp;
    if (S->kind != GD_CURVE_FOLD)
        p->test[GD_CT_FOLD] = cont_det_test(o, 1.0);
    if (S->kind != GD_CURVE_PERIOD_DOUBLING)
        p->test[GD_CT_PD] = cont_pd_test(o);
    if (S->kind == GD_CURVE_NEIMARK_SACKER) {
        double k = q->u[N + 2];
        p->test[GD_CT_R1] = k - 1.0;
        p->test[GD_CT_R2] = k + 1.0;
        p->test[GD_CT_R3] = k + 0.5;
        p->test[GD_CT_R4] = k;
    }
    if (S->kind == GD_CURVE_GRAZING) {
        double re, im;
        p->test[GD_CT_NS] = cont_ns_multiplier(o, &re, &im) ? hypot(re, im) - 1.0 : NAN;
    }
    p->tangent_p[0] = q->t[N];
    p->tangent_p[1] = q->t[N + 1];
    p->ds = ds;
    q->seq_changed = S->seq_changed;
    q->gaps_ok = 0;
    q->xddg = S->kind == GD_CURVE_GRAZING ? S->xddg : NAN;
    memcpy(q->v, S->v, sizeof q->v);
    memcpy(q->wl, S->wl, sizeof q->wl);
    memcpy(q->X, S->X, sizeof q->X);
    memcpy(q->Psi, S->Psi, sizeof q->Psi);
    return GD_OK;
}

/* One corrected point q at arclength s from a (predictor a.u + s a.t, the arclength condition along
 * a.t), Newton from guess when given; its tangent and what it carries. */
static gd_status step_to(ccont *C, const cpt *a, double s, const double *guess, cpt *q, int *iters, gd_error *err)
{
    csys *S = C->S;
    const int D = S->D;
    double up[CMAX], v[CMAX];
    for (int i = 0; i < D; i++) {
        up[i] = a->u[i] + s * a->t[i];
        q->u[i] = guess ? guess[i] : up[i];
        v[i] = S->w[i] * a->t[i];
    }
    gd_status st = correct(C, q->u, v, up, iters, err);
    if (st == GD_OK)
        st = tangent(C, v, q->t, err);
    if (st == GD_OK)
        st = fill_point(C, q, *iters, s, err);
    return st;
}

/* The extrema of the clearance coordinates over q's orbit (the segments' runs with the grazing's held
 * window), as phases of the orbit. */
static gd_status point_gaps(ccont *C, cpt *q, gd_error *err)
{
    if (q->gaps_ok)
        return GD_OK;
    csys *S = C->S;
    const int n = S->n, N = S->N;
    gd_model m;
    gd_status st = S->model_at(q->u[N], q->u[N + 1], &m, S->ctx, err);
    if (st != GD_OK)
        return st;
    gd_model keep = S->m;
    S->m = m;
    memset(&q->g, 0, sizeof q->g);
    const double P = S->nper * m.period, Ts = S->per_seg * m.period;
    for (int k = 0; k < S->nseg && st == GD_OK; k++) {
        gd_gap_extrema g;
        gd_map_probe pr;
        memset(&pr, 0, sizeof pr);
        pr.t_probe = -1.0;
        pr.gaps = &g;
        csys_hold_for(S, k, q->u[N + 2], &pr.hold); /* (a grazing's held window: as csys_eval's runs) */
        st = gd_sim_map_probe(&m, &S->o, q->u + k * n, S->per_seg, &pr, err);
        if (st == GD_OK && g.dropped)
            st = gd_error_set(err, GD_ERR_SOLVER, "more than %d extrema of a clearance coordinate per orbit",
                              GD_GAP_EXTREMA_MAX);
        for (int c = 0; c < GD_MAX_CLEAR && st == GD_OK; c++) {
            q->g.h[c] = g.h[c];
            for (int i = 0; i < g.n[c] && q->g.n[c] < GD_GAP_EXTREMA_MAX; i++) {
                int j = q->g.n[c]++;
                q->g.t[c][j] = (k * Ts + g.t[c][i]) / P;
                q->g.x[c][j] = g.x[c][i];
                q->g.kind[c][j] = g.kind[c][i];
            }
        }
    }
    S->m = keep;
    if (st == GD_OK)
        q->gaps_ok = 1;
    return st;
}

/* Whether extremum i of clearance c is the grazing curve's own touch (not followed as a crossing). */
static int own_touch(const ccont *C, const gd_gap_extrema *g, int c, int i, double phi)
{
    const csys *S = C->S;
    if (S->kind != GD_CURVE_GRAZING || c != S->gclr || g->kind[c][i] != S->gkind)
        return 0;
    double d = fabs(g->t[c][i] - (phi - floor(phi)));
    d -= floor(d);
    return fmin(d, 1.0 - d) < 0.5 * S->ghalf;
}

/* ---- location ---- */

/* Admissibility of a grazing orbit. Inside the touch's held window no crossing of the grazed boundary
 * is located (the held mode is continued), so there the orbit must stay on the held mode's side: its
 * touch an extremum of the grazing's kind (x_c'' of the other sign than the kind), and no other
 * extremum of that kind of the clearance coordinate beyond the boundary (by more than the state's
 * tolerance). Outside the window every crossing of every clearance's boundary is an event, and a
 * change of the events ends the curve (end `contact`). 1: admissible; *bad the extremum beyond
 * (-1: none, the touch's curvature is wrong). The gaps of q must be known. */
static int admissible(const ccont *C, const cpt *q, int *bad)
{
    const csys *S = C->S;
    const int c = S->gclr;
    const double phi = q->u[S->N + 2] - floor(q->u[S->N + 2]), bnd = S->gside ? -q->g.h[c] : q->g.h[c];
    double worst = C->tol;
    *bad = -1;
    for (int i = 0; i < q->g.n[c]; i++) {
        if (q->g.kind[c][i] != S->gkind || own_touch(C, &q->g, c, i, phi))
            continue;
        double d = fabs(q->g.t[c][i] - phi);
        d -= floor(d);
        if (fmin(d, 1.0 - d) > S->ghalf)
            continue;
        double past = S->gkind * (q->g.x[c][i] - bnd);
        if (past > worst)
            worst = past, *bad = i;
    }
    return *bad < 0 && S->gkind * q->xddg < 0;
}

enum { T_TEST = 0, T_MODULUS = 1, T_GAP = 2, T_SEQ = 3, T_ADMIT = 4 };
typedef struct tfn {
    int type;
    int index;               /* T_TEST: the test's index; T_MODULUS: the order statistic */
    gap_ref gap;             /* T_GAP */
} tfn;

#define LOC_MAX 64
typedef struct locx {
    ccont *C;
    tfn tf;
    const cpt *a, *b;
    double ds1;
    int nc;
    double s[LOC_MAX], f[LOC_MAX], ph[LOC_MAX];
    cpt *pt;
    gd_status st;
    gd_error *err;
} locx;

static double value_at(locx *L, cpt *q, double ref_phase, double *phase)
{
    *phase = ref_phase;
    switch (L->tf.type) {
    case T_TEST:
        return q->pt.test[L->tf.index];
    case T_MODULUS:
        return cont_modulus_test(&q->pt.orbit, L->tf.index);
    case T_SEQ:
        return q->seq_changed ? -1.0 : 1.0;
    case T_ADMIT: {
        int bad;
        L->st = point_gaps(L->C, q, L->err);
        return L->st != GD_OK ? NAN : admissible(L->C, q, &bad) ? 1.0 : -1.0;
    }
    default: {
        L->st = point_gaps(L->C, q, L->err);
        if (L->st != GD_OK)
            return NAN;
        gap_ref r = L->tf.gap;
        r.phase = ref_phase;
        return cont_gap_value(&q->g, &r, phase);
    }
    }
}

static void keepv(locx *L, double s, double f, double ph, const cpt *q)
{
    if (L->nc == LOC_MAX)
        return;
    L->s[L->nc] = s;
    L->f[L->nc] = f;
    L->ph[L->nc] = ph;
    L->pt[L->nc++] = *q;
}

static int find_s(const locx *L, double s)
{
    for (int i = 0; i < L->nc; i++)
        if (L->s[i] == s)
            return i;
    return -1;
}

/* the cubic Hermite of the curve between the evaluated points nearest s on either side */
static void hermite(const locx *L, double s, double *g)
{
    const ccont *C = L->C;
    int il = -1, ir = -1;
    for (int j = 0; j < L->nc; j++) {
        if (L->s[j] < s && (il < 0 || L->s[j] > L->s[il]))
            il = j;
        if (L->s[j] > s && (ir < 0 || L->s[j] < L->s[ir]))
            ir = j;
    }
    const cpt *l = il >= 0 ? &L->pt[il] : L->a, *r = ir >= 0 ? &L->pt[ir] : L->b;
    double sl = il >= 0 ? L->s[il] : 0.0, sr = ir >= 0 ? L->s[ir] : L->ds1, h = sr - sl, x = (s - sl) / h;
    double dl = dot_w(C, L->a->t, l->t), dr = dot_w(C, L->a->t, r->t);
    double h00 = (1 + 2 * x) * (1 - x) * (1 - x), h10 = x * (1 - x) * (1 - x), h01 = x * x * (3 - 2 * x),
           h11 = x * x * (x - 1);
    for (int i = 0; i < C->S->D; i++)
        g[i] = h00 * l->u[i] + h10 * h * l->t[i] / dl + h01 * r->u[i] + h11 * h * r->t[i] / dr;
}

static double loc_value(double s, void *params)
{
    locx *L = params;
    int i = find_s(L, s);
    if (i >= 0)
        return L->f[i];
    if (L->st != GD_OK || L->nc == LOC_MAX) {
        if (L->st == GD_OK)
            L->st = gd_error_set(L->err, GD_ERR_SOLVER, "more than %d trial points", LOC_MAX);
        return NAN;
    }
    int near = 0;
    for (int j = 1; j < L->nc; j++)
        if (fabs(L->s[j] - s) < fabs(L->s[near] - s))
            near = j;
    double g[CMAX], ph;
    cpt *q = malloc(sizeof *q);
    if (!q) {
        L->st = gd_error_set(L->err, GD_ERR_NOMEM, "out of memory for a location");
        return NAN;
    }
    int iters;
    hermite(L, s, g);
    L->st = step_to(L->C, L->a, s, g, q, &iters, L->err);
    double f = NAN;
    if (L->st == GD_OK) {
        f = value_at(L, q, L->ph[near], &ph);
        if (L->st == GD_OK)
            keepv(L, s, f, ph, q);
    }
    free(q);
    return L->st == GD_OK ? f : NAN;
}

/* Brent's method (GSL) on the test function between *lo and *hi until the bracket is below locate_tol
 * (the half-tolerance step beyond a converging iterate, as cont_locate.c) */
static gd_status brent(locx *L, double *lo, double *hi)
{
    const double tol = L->C->locate_tol;
    gsl_function F = {loc_value, L};
    gsl_root_fsolver *rs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!rs)
        return gd_error_set(L->err, GD_ERR_NOMEM, "out of memory for the root solver");
    int rc = gsl_root_fsolver_set(rs, &F, *lo, *hi);
    double r_prev = NAN;
    while (rc == GSL_SUCCESS && *hi - *lo > tol) {
        rc = gsl_root_fsolver_iterate(rs);
        if (rc != GSL_SUCCESS)
            break;
        double r = gsl_root_fsolver_root(rs);
        *lo = gsl_root_fsolver_x_lower(rs);
        *hi = gsl_root_fsolver_x_upper(rs);
        if (*hi - *lo <= tol || !(fabs(r - r_prev) < 0.5 * tol) || find_s(L, r) < 0) {
            r_prev = r;
            continue;
        }
        double fr = L->f[find_s(L, r)], x = r - *lo > *hi - r ? r - 0.5 * tol : r + 0.5 * tol;
        double fx = loc_value(x, L);
        if (!isfinite(fx))
            break;
        if ((fx > 0) != (fr > 0)) {
            *lo = fmin(r, x), *hi = fmax(r, x);
            break;
        }
        if (x < r)
            *hi = x;
        else
            *lo = x;
        rc = gsl_root_fsolver_set(rs, &F, *lo, *hi);
        r_prev = NAN;
    }
    gsl_root_fsolver_free(rs);
    if (L->st != GD_OK)
        return L->st;
    if (rc != GSL_SUCCESS)
        return gd_error_set(L->err, GD_ERR_GSL, "locating a codimension-two point: gsl_root_fsolver_brent: %s",
                            gsl_strerror(rc));
    return GD_OK;
}

static gd_status bisect(locx *L, double f_lo, double *lo, double *hi)
{
    while (*hi - *lo > L->C->locate_tol) {
        double mid = 0.5 * (*lo + *hi), f = loc_value(mid, L);
        if (L->st != GD_OK)
            return L->st;
        if ((f > 0) == (f_lo > 0))
            *lo = mid;
        else
            *hi = mid;
    }
    return GD_OK;
}

/* A grazing that ends the curve, where Brent's method stopped on a trial point whose corrector failed:
 * beyond the grazing the orbit's contact events are not the curve's, and the corrector of the curve's
 * sequence fails there, so a failed trial point takes the side of b and the bisection goes on; *lo
 * converges on the last point of the curve's side (its gap's sign is f_lo's), *hi_failed set when the
 * upper end of the bracket is such a point (it has no corrected point). */
static gd_status bisect_past_failures(locx *L, double f_lo, double *lo, double *hi, int *hi_failed)
{
    while (*hi - *lo > L->C->locate_tol) {
        double mid = 0.5 * (*lo + *hi), f = loc_value(mid, L);
        if (L->st == GD_OK) {
            if ((f > 0) == (f_lo > 0))
                *lo = mid;
            else
                *hi = mid, *hi_failed = 0;
            continue;
        }
        if (L->st == GD_ERR_NOMEM || L->st == GD_ERR_INTERRUPTED || L->st == GD_ERR_INTERNAL || L->nc == LOC_MAX)
            return L->st;
        gd_error_clear(L->err); /* the corrector failed: beyond the grazing */
        L->st = GD_OK;
        *hi = mid;
        *hi_failed = 1;
    }
    return GD_OK;
}

/* A sign change of tf between a and b (at arclength ds1): located into *out (kind, clearance set by
 * the caller) and its point into *q (may be NULL). */
static gd_status locate(ccont *C, const tfn *tf, const cpt *a, const cpt *b, double ds1, gd_codim2 *out, cpt *q,
                        gd_error *err)
{
    const int N = C->S->N;
    locx L = {.C = C, .tf = *tf, .a = a, .b = b, .ds1 = ds1, .st = GD_OK, .err = err};
    L.pt = malloc(sizeof *L.pt * LOC_MAX);
    cpt *ends = malloc(2 * sizeof *ends);
    if (!L.pt || !ends) {
        free(L.pt);
        free(ends);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a location");
    }
    ends[0] = *a;
    ends[1] = *b;
    double pa = tf->gap.phase, pb = pa;
    double fa = value_at(&L, &ends[0], pa, &pa), fb = value_at(&L, &ends[1], pa, &pb);
    keepv(&L, 0.0, fa, pa, &ends[0]);
    keepv(&L, ds1, fb, pb, &ends[1]);
    free(ends);
    double lo = 0.0, hi = ds1;
    gd_status st = L.st;
    if (st == GD_OK)
        st = tf->type == T_SEQ || tf->type == T_ADMIT ? bisect(&L, fa, &lo, &hi) : brent(&L, &lo, &hi);
    int hi_failed = 0;
    if (tf->type == T_GAP && st == GD_ERR_SOLVER && L.nc < LOC_MAX) {
        gd_error_clear(err);
        L.st = GD_OK;
        st = bisect_past_failures(&L, fa, &lo, &hi, &hi_failed);
    }
    int where = GD_LOC_LOCATED;
    const int soft = st != GD_OK && st != GD_ERR_NOMEM && st != GD_ERR_INTERNAL && st != GD_ERR_INTERRUPTED;
    if (st != GD_OK && !soft) {
        free(L.pt);
        return st;
    }
    if (soft) {
        gd_error_clear(err);
        where = GD_LOC_BRACKET;
    }
    int ilo = find_s(&L, lo), ihi = hi_failed ? ilo : find_s(&L, hi);
    if (ilo < 0 || ihi < 0) {
        free(L.pt);
        return gd_error_set(err, GD_ERR_INTERNAL, "a location lost its bracket");
    }
    int best = fabs(L.f[ihi]) < fabs(L.f[ilo]) ? ihi : ilo;
    if (tf->type == T_SEQ) {
        where = where == GD_LOC_BRACKET ? where : GD_LOC_EVENTS;
        best = ilo; /* the last point with the curve's sequence */
    } else if (tf->type == T_ADMIT) {
        best = ilo; /* the last admissible point */
    } else if (tf->type == T_GAP) {
        /* a grazing ends the curve: its point is the end on the curve's side of the boundary */
        best = (L.f[ilo] > 0) == (fa > 0) ? ilo : ihi;
    }
    if (where == GD_LOC_LOCATED && tf->type != T_SEQ && tf->type != T_ADMIT) {
        /* the test function shrinks with the bracket, as a continuous one does at its root (past failed
         * trial points: its value at the bracket's lower end, against the one at a) */
        double shrink = sqrt((hi - lo) / ds1);
        if (hi_failed ? !(fabs(L.f[ilo]) <= shrink * fabs(fa))
                      : !(fabs(L.f[ilo]) + fabs(L.f[ihi]) <= shrink * (fabs(fa) + fabs(fb))))
            where = GD_LOC_JUMP;
    }
    const cpt *r = &L.pt[best];
    memset(out, 0, sizeof *out);
    out->p1 = r->u[N];
    out->p2 = r->u[N + 1];
    out->p1_lo = L.pt[ilo].u[N];
    out->p2_lo = L.pt[ilo].u[N + 1];
    out->p1_hi = L.pt[ihi].u[N];
    out->p2_hi = L.pt[ihi].u[N + 1];
    if (hi_failed) { /* not corrected: the predictor's point there */
        double g[CMAX];
        hermite(&L, hi, g);
        out->p1_hi = g[N];
        out->p2_hi = g[N + 1];
    }
    out->kappa = r->pt.kappa;
    out->clearance = -1;
    out->location = where;
    out->point = C->cv->npoints;
    memcpy(out->y, r->u, sizeof(double) * (size_t)C->S->n);
    cont_critical_multiplier(&r->pt.orbit, 1.0, &out->mu_re, &out->mu_im);
    if (q)
        *q = *r;
    free(L.pt);
    return GD_OK;
}

/* ---- the codimension-two points between two points ---- */

/* The contact sequence changed between a and b: the grazing met, located on the followed extremum
 * that crossed a boundary (or the sequence bisected); *q its point. */
static gd_status locate_contact(ccont *C, const cpt *a, cpt *b, double ds, gd_codim2 *c2, cpt *q, gd_error *err)
{
    const int N = C->S->N;
    gd_status st = point_gaps(C, (cpt *)a, err);
    if (st == GD_OK)
        st = point_gaps(C, b, err);
    if (st != GD_OK)
        return st;
    gap_ref best = {0};
    int found = 0, clr = -1;
    double bestd = INFINITY;
    for (int c = 0; c < GD_MAX_CLEAR; c++) {
        gap_ref r[8];
        int nr = cont_gap_crossings(&a->g, &b->g, c, r, 8);
        for (int i = 0; i < nr; i++) {
            /* not the grazing curve's own touch */
            int own = 0;
            for (int j = 0; j < a->g.n[c]; j++)
                if (a->g.t[c][j] == r[i].phase && own_touch(C, &a->g, c, j, a->u[N + 2]))
                    own = 1;
            if (own)
                continue;
            double phase, d = fabs(cont_gap_value(&a->g, &r[i], &phase));
            if (d < bestd)
                bestd = d, best = r[i], found = 1, clr = c;
        }
    }
    tfn tf = {.type = found ? T_GAP : T_SEQ, .gap = best};
    st = locate(C, &tf, a, b, ds, c2, q, err);
    if (st != GD_OK)
        return st;
    static const int kinds[] = {GD_C2_GRAZING_FOLD, GD_C2_GRAZING_PD, GD_C2_GRAZING_NS, GD_C2_DOUBLE_GRAZING};
    c2->kind = kinds[C->S->kind];
    /* the curve's own critical multiplier there: -1 on a period-doubling curve, the pair on the unit
     * circle on a Neimark-Sacker curve (+1 on a fold curve, as located) */
    if (C->S->kind == GD_CURVE_PERIOD_DOUBLING)
        cont_critical_multiplier(&q->pt.orbit, -1.0, &c2->mu_re, &c2->mu_im);
    else if (C->S->kind == GD_CURVE_NEIMARK_SACKER && !cont_ns_multiplier(&q->pt.orbit, &c2->mu_re, &c2->mu_im))
        cont_critical_multiplier(&q->pt.orbit, 1.0, &c2->mu_re, &c2->mu_im);
    c2->clearance = clr;
    c2->ends_curve = 1;
    if (!found) { /* which clearance's events changed */
        for (int c = 0; c < GD_MAX_CLEAR; c++)
            if (a->pt.orbit.events[c] != b->pt.orbit.events[c])
                c2->clearance = c;
    }
    return GD_OK;
}

/* b, a point of a grazing curve, is not admissible (a is): where it stops being so, located into *q;
 * *c2_ok set with *c2 the double grazing when another extremum of the grazing's kind, followed from a,
 * crossed the boundary (located on its distance to it), else bisected on the admissibility itself (the
 * touch's curvature turned: a degenerate grazing, no codimension-two point of codim2.csv's kinds). */
static gd_status locate_inadmissible(ccont *C, const cpt *a, cpt *b, double ds, int bad, int *c2_ok, gd_codim2 *c2,
                                     cpt *q, gd_error *err)
{
    const csys *S = C->S;
    const int c = S->gclr;
    tfn tf = {.type = T_ADMIT};
    *c2_ok = 0;
    if (bad >= 0) {
        gap_ref r = {c, S->gkind, b->g.t[c][bad], S->gside ? -b->g.h[c] : b->g.h[c]};
        double pa, va = cont_gap_value(&a->g, &r, &pa);
        int own = 0;
        for (int j = 0; j < a->g.n[c]; j++)
            if (a->g.t[c][j] == pa && own_touch(C, &a->g, c, j, a->u[S->N + 2]))
                own = 1;
        if (isfinite(va) && S->gkind * va < 0 && !own) {
            tf.type = T_GAP;
            tf.gap = r;
            tf.gap.phase = pa;
            *c2_ok = 1;
        }
    }
    gd_status st = locate(C, &tf, a, b, ds, c2, q, err);
    if (st != GD_OK)
        return st;
    c2->kind = GD_C2_DOUBLE_GRAZING;
    c2->clearance = c;
    c2->ends_curve = 1;
    return GD_OK;
}

/* The codimension-two sign changes between a and b (same contact sequence), located and recorded;
 * *end: a resonance 1:1 or 1:2 that ends a Neimark-Sacker curve (its point into *qe). */
static gd_status detect(ccont *C, const cpt *a, const cpt *b, double ds, int *end, cpt *qe, gd_error *err)
{
    csys *S = C->S;
    gd_status st = GD_OK;
    *end = 0;
    typedef struct {
        int test, c2;
    } tpair;
    tpair tests[8];
    int nt = 0;
    if (S->kind == GD_CURVE_FOLD) {
        tests[nt++] = (tpair){GD_CT_CUSP, GD_C2_CUSP};
        tests[nt++] = (tpair){GD_CT_PD, GD_C2_FOLD_FLIP};
    } else if (S->kind == GD_CURVE_PERIOD_DOUBLING) {
        tests[nt++] = (tpair){GD_CT_FOLD, GD_C2_FOLD_FLIP};
    } else if (S->kind == GD_CURVE_NEIMARK_SACKER) {
        tests[nt++] = (tpair){GD_CT_R1, GD_C2_R1};
        tests[nt++] = (tpair){GD_CT_R2, GD_C2_R2};
        tests[nt++] = (tpair){GD_CT_R3, GD_C2_R3};
        tests[nt++] = (tpair){GD_CT_R4, GD_C2_R4};
    } else {
        tests[nt++] = (tpair){GD_CT_FOLD, GD_C2_GRAZING_FOLD};
        tests[nt++] = (tpair){GD_CT_PD, GD_C2_GRAZING_PD};
    }
    for (int i = 0; i < nt && st == GD_OK && !*end; i++) {
        double fa = a->pt.test[tests[i].test], fb = b->pt.test[tests[i].test];
        if (!isfinite(fa) || !isfinite(fb) || (fa > 0) == (fb > 0))
            continue;
        tfn tf = {.type = T_TEST, .index = tests[i].test};
        gd_codim2 c2;
        cpt *q = malloc(sizeof *q);
        if (!q)
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a location");
        st = locate(C, &tf, a, b, ds, &c2, q, err);
        if (st == GD_OK) {
            c2.kind = tests[i].c2;
            /* the multiplier that makes it codimension two: -1 of a fold-flip on a fold curve and of a
             * grazing-period-doubling, the pair of a resonance, else +1 */
            double re, im, target = (c2.kind == GD_C2_FOLD_FLIP && S->kind == GD_CURVE_FOLD) ||
                                            c2.kind == GD_C2_GRAZING_PD ? -1.0 : 1.0;
            if (!(c2.kind >= GD_C2_R1 && c2.kind <= GD_C2_R4 && cont_ns_multiplier(&q->pt.orbit, &re, &im)))
                cont_critical_multiplier(&q->pt.orbit, target, &re, &im);
            c2.mu_re = re;
            c2.mu_im = im;
            if (c2.kind == GD_C2_R1 || c2.kind == GD_C2_R2) {
                c2.ends_curve = 1;
                *end = 1;
                *qe = *q;
            }
            st = push_c2(C->cv, &c2, err);
        }
        free(q);
    }
    /* a complex pair crossing the unit circle on a grazing curve */
    if (S->kind == GD_CURVE_GRAZING && st == GD_OK) {
        const gd_po *pa = &a->pt.orbit, *pb = &b->pt.orbit;
        for (int j = 0; j < pa->n && st == GD_OK; j++) {
            if ((cont_modulus_test(pa, j) > 0) == (cont_modulus_test(pb, j) > 0))
                continue;
            if (pa->mu_im[j] == 0.0 && pb->mu_im[j] == 0.0)
                continue;
            if (j > 0 && (pa->mu_im[j] == -pa->mu_im[j - 1] || pb->mu_im[j] == -pb->mu_im[j - 1]))
                continue;
            tfn tf = {.type = T_MODULUS, .index = j};
            gd_codim2 c2;
            cpt *q = malloc(sizeof *q);
            if (!q)
                return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a location");
            st = locate(C, &tf, a, b, ds, &c2, q, err);
            double re, im;
            if (st == GD_OK && cont_ns_multiplier(&q->pt.orbit, &re, &im) && fabs(hypot(re, im) - 1.0) < 1e-3) {
                c2.kind = GD_C2_GRAZING_NS;
                c2.mu_re = re;
                c2.mu_im = im;
                st = push_c2(C->cv, &c2, err);
            }
            free(q);
        }
    }
    return st;
}

/* ---- the curve ---- */

static void end_with(gd_curve *cv, int end, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static void end_with(gd_curve *cv, int end, const char *fmt, ...)
{
    cv->end = end;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(cv->end_reason, sizeof cv->end_reason, fmt, ap);
    va_end(ap);
}

/* the box's side the step a -> b crossed first (q: the parameter, *pb the bound), or -1 */
static int crossed_bound(const ccont *C, const cpt *a, const cpt *b, double *pb)
{
    const int N = C->S->N;
    int which = -1;
    double frac = INFINITY;
    for (int q = 0; q < 2; q++) {
        double lo = C->co->p_min[q], hi = C->co->p_max[q], x0 = a->u[N + q], x1 = b->u[N + q];
        double bnd = x1 < lo ? lo : x1 > hi ? hi : NAN;
        if (isnan(bnd))
            continue;
        double f = x1 != x0 ? (bnd - x0) / (x1 - x0) : 0.0;
        if (f < frac)
            frac = f, which = q, *pb = bnd;
    }
    return which;
}

/* the point of the curve on the bound p_q = pb, from a (the bordering row e_q) */
static gd_status bound_point(ccont *C, const cpt *a, int q, double pb, cpt *b, gd_error *err)
{
    csys *S = C->S;
    const int D = S->D, N = S->N;
    double s = (pb - a->u[N + q]) / a->t[N + q], up[CMAX], e[CMAX] = {0}, v[CMAX];
    if (!isfinite(s))
        s = 0;
    for (int i = 0; i < D; i++) {
        up[i] = b->u[i] = a->u[i] + s * a->t[i];
        v[i] = S->w[i] * a->t[i];
    }
    up[N + q] = b->u[N + q] = pb;
    e[N + q] = 1.0;
    int iters;
    gd_status st = correct(C, b->u, e, up, &iters, err);
    if (st == GD_OK)
        st = tangent(C, v, b->t, err);
    if (st == GD_OK)
        st = fill_point(C, b, iters, s, err);
    return st;
}

/* a parameter's value in its key's unit, for end reasons */
static double p_value(const ccont *C, int q, double p)
{
    double s = C->co->words.value_scale[q];
    return s != 0 ? s * p : p;
}

/* "key = value unit" of parameter q at p */
static const char *p_text(const ccont *C, int q, double p, char *buf, size_t n)
{
    const char *k = C->co->words.key[q], *u = C->co->words.unit[q];
    snprintf(buf, n, "%s = %.10g%s%s", k ? k : q ? "p2" : "p1", p_value(C, q, p), u && u[0] ? " " : "", u ? u : "");
    return buf;
}

/* both parameters of a point: "key1 = v1 unit1, key2 = v2 unit2" */
typedef struct { char s[2 * GD_PATH_MAX]; } ptext;
static ptext at_text(const ccont *C, double p1, double p2)
{
    ptext t;
    char a[GD_PATH_MAX], b[GD_PATH_MAX - 8];
    snprintf(t.s, sizeof t.s, "%s, %s", p_text(C, 0, p1, a, sizeof a), p_text(C, 1, p2, b, sizeof b));
    return t;
}
#define PP(u) at_text(C, (u)[C->S->N], (u)[C->S->N + 1]).s

/* A jump of the model: in parameter q at p, found by one-sided differences that disagree down to dp. */
typedef struct {
    int q;
    double p, dp;
} cjump;

/* The point of a curve ended next to a jump of the model lies JUMP_MARGIN of the jump's dp short of it:
 * its own differences in q, shrunk twice (par_runs), do not reach across. */
#define JUMP_MARGIN 64.0

static void end_jump(ccont *C, const cpt *last, const cjump *J)
{
    const gd_curve_opts *co = C->co;
    const char *un = co->words.unit[J->q];
    end_with(C->cv, GD_CEND_DISCONTINUOUS, "the model is discontinuous in %s at %.10g%s%s (to %.3g%s%s), beyond %s: "
             "the orbit's residual jumps there (no curve across a jump of the model)",
             co->words.key[J->q] ? co->words.key[J->q] : J->q ? "p2" : "p1", p_value(C, J->q, J->p),
             un && un[0] ? " " : "", un ? un : "", fabs(p_value(C, J->q, J->dp)), un && un[0] ? " " : "", un ? un : "",
             PP(last->u));
}

static gd_status run(ccont *C, const cpt *a0, gd_error *err)
{
    csys *S = C->S;
    const gd_curve_opts *co = C->co;
    const int D = S->D, N = S->N;
    /* a and b swap at every accepted point: both owned here */
    cpt *a = malloc(sizeof *a), *b = malloc(sizeof *b), *q = malloc(sizeof *q);
    gd_status st = GD_OK;
    if (a)
        *a = *a0;
    if (!a || !b || !q) {
        st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for a curve");
        goto done;
    }
    double first_u[CMAX], first_t[CMAX];
    memcpy(first_u, a->u, sizeof first_u);
    memcpy(first_t, a->t, sizeof first_t);
    int left_first = 0, stalled = 0, crawled = 0;
    cjump jump_at = {-1, NAN, NAN}, near = {-1, NAN, NAN}; /* near: a jump a failed step from a met */
    double ds = co->ds;
    while (C->cv->npoints < co->max_points) {
        if (gd_stop_asked(&co->stop)) {
            st = gd_error_set(err, GD_ERR_INTERRUPTED, "the curve was stopped at %s", PP(a->u));
            goto done;
        }
        for (int k = 0; k < 2; k++)
            if (fabs(ds * a->t[N + k]) > 0.98 * C->dp_max[k])
                ds = fmax(0.98 * C->dp_max[k] / fabs(a->t[N + k]), co->ds_min);
        int iters = 0;
        gd_error e1 = {0};
        st = step_to(C, a, ds, NULL, b, &iters, &e1);
        if (st == GD_OK)
            memcpy(C->Jn, S->J, sizeof(double) * (size_t)(D - 1) * D);
        if (st == GD_ERR_NOMEM || st == GD_ERR_INTERNAL || st == GD_ERR_INTERRUPTED) {
            st = gd_error_set(err, st, "%s", e1.msg);
            goto done;
        }
        int qf = -1, jump_end = 0;
        double pf = NAN;
        /* a jump of the model within the step: the corrector met it (it failed, or converged too far or
         * turning, or on the jump's far side: a step over the jump lands on another curve) */
        int conv_reject = 0;
        if (st == GD_OK) {
            int tf = 0;
            for (int k = 0; k < 2; k++)
                tf |= fabs(b->u[N + k] - a->u[N + k]) > C->dp_max[k];
            conv_reject = tf || dot_w(C, a->t, b->t) < 0.5;
        }
        const int failed = (st != GD_OK && st != GD_ERR_INPUT) || conv_reject;
        cjump jm = {st != GD_OK ? S->jump_q : -1, S->jump_p, S->jump_dp};
        if (jm.q < 0 && S->sus_q >= 0 && (failed || st == GD_OK)) {
            /* the corrector's differences saw a jump nearby, perhaps: located by the residual alone (for an
             * accepted step only when that window reaches into the step) */
            const int sq = S->sus_q;
            const double w0 = S->sus_u[N + sq] - S->sus_dp, w1 = S->sus_u[N + sq] + S->sus_dp;
            const double lo = fmin(a->u[N + sq], b->u[N + sq]), hi = fmax(a->u[N + sq], b->u[N + sq]);
            if (failed || (w1 >= lo && w0 <= hi)) {
                int found = 0;
                gd_error e2 = {0};
                gd_status sj = csys_find_jump(S, &jm.q, &jm.p, &jm.dp, &found, &e2);
                if (sj == GD_ERR_NOMEM || sj == GD_ERR_INTERRUPTED) {
                    st = gd_error_set(err, sj, "%s", e2.msg);
                    goto done;
                }
                if (sj != GD_OK || !found)
                    jm.q = -1;
            }
        }
        for (int k = 0; k < 2 && jm.q < 0 && conv_reject; k++) {
            /* converged too far or turning, no jump seen by the corrector (the chord iteration has no
             * differences): a jump of the model between a and b in either parameter, at a's state? */
            int found = 0;
            gd_error e2 = {0};
            gd_status sj = csys_find_jump_between(S, a->u, k, a->u[N + k], b->u[N + k], &jm.p, &jm.dp, &found, &e2);
            if (sj == GD_ERR_NOMEM || sj == GD_ERR_INTERRUPTED) {
                st = gd_error_set(err, sj, "%s", e2.msg);
                goto done;
            }
            if (sj == GD_OK && found)
                jm.q = k;
        }
        int crossed = 0;
        if (jm.q >= 0 && !failed) { /* converged: a jump between a and b? */
            crossed = (jm.p - a->u[N + jm.q]) * (jm.p - b->u[N + jm.q]) < 0;
            if (!crossed)
                jm.q = -1;
        }
        if (jm.q >= 0) {
            const cjump J = jm;
            const double pa = a->u[N + J.q], sg = J.p > pa ? 1.0 : -1.0;
            const double pstep = st == GD_OK ? b->u[N + J.q] - pa : ds * a->t[N + J.q];
            /* (a step converged too far or turning reaches no farther than its prediction) */
            const double reach =
                fmax(fabs(ds * a->t[N + J.q]), st == GD_OK && !conv_reject ? fabs(b->u[N + J.q] - pa) : 0.0);
            const double margin = JUMP_MARGIN * J.dp, pt = J.p - sg * margin;
            int ok_end = 0;
            /* the point on the near side of the jump must be a step of this curve away: within twice the
             * step's reach (a jump a wandering iterate met farther along is approached by smaller steps) */
            if (pstep * sg > 0 && fabs(J.p - pa) <= 2.0 * reach + margin) {
                if ((pt - pa) * sg <= 0) { /* a itself is at the jump */
                    end_jump(C, a, &J);
                    st = GD_OK;
                    goto done;
                }
                gd_error e2 = {0};
                gd_status sj = pt >= co->p_min[J.q] && pt <= co->p_max[J.q] ? bound_point(C, a, J.q, pt, b, &e2)
                                                                          : GD_ERR_SOLVER;
                if (sj == GD_ERR_NOMEM || sj == GD_ERR_INTERRUPTED) {
                    st = gd_error_set(err, sj, "%s", e2.msg);
                    goto done;
                }
                const int other = 1 - J.q;
                ok_end = sj == GD_OK && b->u[N + other] >= co->p_min[other] && b->u[N + other] <= co->p_max[other] &&
                         dot_w(C, a->t, b->t) >= 0.5;
            }
            if (!ok_end)
                near = J; /* for the smallest step (below) */
            if (ok_end) {
                st = GD_OK;
                qf = J.q;
                pf = pt;
                jump_end = 1;
                jump_at = J;
            } else if (crossed) { /* a step over the jump is not a step of this curve */
                const char *un = co->words.unit[J.q];
                st = GD_ERR_SOLVER;
                snprintf(e1.msg, sizeof e1.msg, "the step crosses a jump of the model in %s at %.10g%s%s",
                         co->words.key[J.q] ? co->words.key[J.q] : J.q ? "p2" : "p1", p_value(C, J.q, J.p),
                         un && un[0] ? " " : "", un ? un : "");
            }
        }
        /* the model is not valid at a prediction beyond the box (a bound of the box on the edge of the key's
         * range: backlash 0): the point on the bound ends the curve, as for a step that crosses it */
        char bound_fail[GD_ERROR_MSG_MAX + 96] = "";
        if (st == GD_ERR_INPUT) {
            double frac = INFINITY;
            for (int k = 0; k < 2; k++) {
                double x0 = a->u[N + k], x1 = x0 + ds * a->t[N + k], lo = co->p_min[k], hi = co->p_max[k];
                double bnd = x1 < lo ? lo : x1 > hi ? hi : NAN;
                double f = isnan(bnd) || x1 == x0 ? INFINITY : (bnd - x0) / (x1 - x0);
                if (f < frac)
                    frac = f, qf = k, pf = bnd;
            }
            if (qf >= 0) {
                gd_error e2 = {0};
                gd_status sb2 = bound_point(C, a, qf, pf, b, &e2);
                if (sb2 == GD_OK)
                    st = GD_OK;
                else if (sb2 == GD_ERR_NOMEM || sb2 == GD_ERR_INTERRUPTED) {
                    st = gd_error_set(err, sb2, "%s", e2.msg);
                    goto done;
                } else {
                    snprintf(bound_fail, sizeof bound_fail, "; on the bound %s = %.10g: %s",
                             co->words.bound_key[qf][pf >= co->p_max[qf]] ? co->words.bound_key[qf][pf >= co->p_max[qf]]
                                                                          : qf ? "p2" : "p1",
                             p_value(C, qf, pf), e2.msg);
                    qf = -1;
                }
            }
        }
        double turn = st == GD_OK ? dot_w(C, a->t, b->t) : 0.0;
        int too_far = 0;
        for (int k = 0; k < 2 && st == GD_OK && qf < 0; k++)
            too_far |= fabs(b->u[N + k] - a->u[N + k]) > C->dp_max[k];
        if (qf >= 0)
            turn = 1.0;
        if (st == GD_ERR_INPUT) { /* the model is not valid there */
            if (ds <= co->ds_min) {
                end_with(C->cv, GD_CEND_INVALID, "the model is not valid beyond %s: %s%s", PP(a->u), e1.msg,
                         bound_fail);
                st = GD_OK;
                goto done;
            }
            ds = fmax(0.5 * ds, co->ds_min);
            continue;
        }
        if (st != GD_OK || turn < 0.5 || too_far) {
            const char *why = st != GD_OK ? e1.msg : too_far ? "a parameter moves more than dp_max"
                                                             : "the tangent turns too sharply";
            if (st != GD_OK && S->jump_q >= 0 && ds <= co->ds_min) {
                /* the model jumps at the step's end: the curve ends at its last point before the jump */
                const cjump J = {S->jump_q, S->jump_p, S->jump_dp};
                end_jump(C, a, &J);
                st = GD_OK;
                goto done;
            }
            if (ds <= co->ds_min) {
                /* a jump of the model within two of the parameter differences' steps of a ends the curve at a:
                 * one the corrector met at this step or a longer one from a (the differences at a reach across
                 * it, whichever way the curve turns there), else one sought ahead of a */
                if (near.q >= 0 &&
                    fabs(near.p - a->u[N + near.q]) <= 2.0 * S->dp_rel * (1.0 + fabs(a->u[N + near.q]))) {
                    end_jump(C, a, &near);
                    st = GD_OK;
                    goto done;
                }
                for (int k = 0; k < 2; k++) {
                    const double pk = a->u[N + k], w = 2.0 * S->dp_rel * (1.0 + fabs(pk));
                    cjump J = {k, NAN, NAN};
                    int found = 0;
                    gd_error e2 = {0};
                    gd_status sj = csys_find_jump_between(S, a->u, k, pk, pk + (a->t[N + k] < 0 ? -w : w), &J.p,
                                                          &J.dp, &found, &e2);
                    if (sj == GD_ERR_NOMEM || sj == GD_ERR_INTERRUPTED) {
                        st = gd_error_set(err, sj, "%s", e2.msg);
                        goto done;
                    }
                    if (sj == GD_OK && found) {
                        end_jump(C, a, &J);
                        st = GD_OK;
                        goto done;
                    }
                }
                end_with(C->cv, GD_CEND_STEP, "no convergence at the smallest step %.3g from %s: %s",
                         ds, PP(a->u), why);
                st = GD_OK;
                goto done;
            }
            ds = fmax(0.5 * ds, co->ds_min);
            continue;
        }
        double pbnd = pf;
        int qb = qf >= 0 ? qf : crossed_bound(C, a, b, &pbnd);
        int ended = 0;
        double sb = ds;
        if (qb >= 0) { /* the point on the bound replaces b */
            if (qf < 0)
                st = bound_point(C, a, qb, pbnd, b, &e1);
            if (st != GD_OK) {
                end_with(C->cv, GD_CEND_BOUND, "the curve leaves the box after %s (no point on the bound: "
                         "%s)", PP(a->u), e1.msg);
                st = st == GD_ERR_NOMEM || st == GD_ERR_INTERRUPTED ? gd_error_set(err, st, "%s", e1.msg) : GD_OK;
                goto done;
            }
            double d[CMAX];
            for (int i = 0; i < D; i++)
                d[i] = b->u[i] - a->u[i];
            sb = dot_w(C, a->t, d);
            ended = 1;
        }
        if (b->seq_changed) { /* a grazing met: located, and the curve ends there */
            gd_codim2 c2;
            st = locate_contact(C, a, b, sb, &c2, q, err);
            if (st != GD_OK)
                goto done;
            st = push_c2(C->cv, &c2, err);
            if (st == GD_OK)
                st = push_point(C->cv, &q->pt, err);
            end_with(C->cv, GD_CEND_CONTACT, "the orbit's contact sequence changes at %s (%s%s%s, location %s): "
                     "the curve ends there", at_text(C, c2.p1, c2.p2).s, gd_codim2_kind_name(c2.kind),
                     c2.clearance >= 0 ? " of " : "", c2.clearance >= 0 ? S->m.clear[c2.clearance].name : "",
                     gd_bif_location_name(c2.location));
            goto done;
        }
        if (S->kind == GD_CURVE_GRAZING) { /* admissible? (a, the last accepted point, is) */
            int bad;
            st = point_gaps(C, b, err);
            if (st == GD_OK)
                st = point_gaps(C, a, err);
            if (st != GD_OK)
                goto done;
            if (!admissible(C, b, &bad)) {
                gd_codim2 c2;
                int c2_ok;
                st = locate_inadmissible(C, a, b, sb, bad, &c2_ok, &c2, q, err);
                if (st == GD_OK && c2_ok)
                    st = push_c2(C->cv, &c2, err);
                if (st == GD_OK)
                    st = push_point(C->cv, &q->pt, err);
                end_with(C->cv, GD_CEND_INADMISSIBLE, "the grazing orbit is not admissible beyond %s (%s, location "
                         "%s): inside the touch's window it would cross the boundary of %s unseen; the curve ends "
                         "there", at_text(C, q->u[N], q->u[N + 1]).s,
                         c2_ok ? "another extremum reaches the boundary: double grazing"
                               : "the touch's curvature turns: a degenerate grazing",
                         gd_bif_location_name(c2.location), S->m.clear[S->gclr].name);
                goto done;
            }
        }
        int res_end = 0;
        st = detect(C, a, b, sb, &res_end, q, err);
        if (st != GD_OK)
            goto done;
        if (res_end) {
            const gd_codim2 *c2 = &C->cv->c2[C->cv->nc2 - 1];
            st = push_point(C->cv, &q->pt, err);
            end_with(C->cv, GD_CEND_RESONANCE, "strong resonance %s at %s: the pair meets on the real axis "
                     "(beyond it a neutral saddle, no Neimark-Sacker point)", c2->kind == GD_C2_R1 ? "1:1" : "1:2",
                     at_text(C, c2->p1, c2->p2).s);
            goto done;
        }
        st = push_point(C->cv, &b->pt, err);
        if (st != GD_OK)
            goto done;
        /* no progress: points in a row at the smallest step (below twice ds_min: the step could not grow;
         * not when ds_max itself allows no more) */
        stalled = ds < 2.0 * co->ds_min && co->ds_max >= 2.0 * co->ds_min ? stalled + 1 : 0;
        if (!ended && stalled >= GD_CURVE_STALL_POINTS) {
            const int k0 = C->cv->npoints - GD_CURVE_STALL_POINTS;
            const gd_curve_point *p0 = &C->cv->pt[k0 > 0 ? k0 - 1 : 0];
            char d1[GD_PATH_MAX], d2[GD_PATH_MAX];
            end_with(C->cv, GD_CEND_STALL, "no progress at %s: %d points in a row at the smallest step %.3g moved "
                     "%s and %s (the corrector needs several iterations however small the step: a Jacobian that "
                     "does not fit the residual there)", PP(b->u), GD_CURVE_STALL_POINTS, co->ds_min,
                     p_text(C, 0, fabs(b->u[N] - p0->orbit.p), d1, sizeof d1),
                     p_text(C, 1, fabs(b->u[N + 1] - p0->p2), d2, sizeof d2));
            goto done;
        }
        /* crawling: points in a row whose steps stay small (below 100 ds_min: the corrector needs four or five
         * iterations at every step, so the step never grows) that moved less than a hundredth of the box in
         * both parameters; at that pace the curve would not cross the box within any budget */
        crawled = ds < 100.0 * co->ds_min && co->ds_max >= 200.0 * co->ds_min ? crawled + 1 : 0;
        if (!ended && crawled >= GD_CURVE_CRAWL_POINTS) {
            const int k0 = C->cv->npoints - GD_CURVE_CRAWL_POINTS;
            const gd_curve_point *p0 = &C->cv->pt[k0 > 0 ? k0 - 1 : 0];
            double m1 = fabs(b->u[N] - p0->orbit.p), m2 = fabs(b->u[N + 1] - p0->p2);
            if (m1 < 0.01 * C->R[0] && m2 < 0.01 * C->R[1]) {
                char d1[GD_PATH_MAX], d2[GD_PATH_MAX];
                end_with(C->cv, GD_CEND_STALL, "no progress at %s: %d points in a row at steps below %.3g moved %s "
                         "and %s, less than a hundredth of the box (the corrector needs several iterations however "
                         "small the step: a Jacobian that does not fit the residual there)", PP(b->u),
                         GD_CURVE_CRAWL_POINTS, 100.0 * co->ds_min, p_text(C, 0, m1, d1, sizeof d1),
                         p_text(C, 1, m2, d2, sizeof d2));
                goto done;
            }
        }
        if (jump_end) {
            end_jump(C, b, &jump_at);
            goto done;
        }
        if (ended) {
            const char *bk = co->words.bound_key[qb][pbnd >= co->p_max[qb]];
            const char *un = co->words.unit[qb];
            char other[GD_PATH_MAX];
            end_with(C->cv, GD_CEND_BOUND, "ended on the bound %s%s = %.10g%s%s at %s", bk ? bk : "",
                     bk ? "" : qb ? "p2" : "p1", p_value(C, qb, pbnd), un && un[0] ? " " : "", un ? un : "",
                     p_text(C, 1 - qb, b->u[N + 1 - qb], other, sizeof other));
            goto done;
        }
        /* closed: the chord a -> b passes the first point within a quarter of its length, the tangent along */
        {
            double d2 = 0, wd = 0, dist2 = 0, db2 = 0;
            for (int i = 0; i < D; i++) {
                d2 += S->w[i] * (b->u[i] - a->u[i]) * (b->u[i] - a->u[i]);
                wd += S->w[i] * (first_u[i] - a->u[i]) * (b->u[i] - a->u[i]);
                db2 += S->w[i] * (b->u[i] - first_u[i]) * (b->u[i] - first_u[i]);
            }
            double lam = d2 > 0 ? fmin(fmax(wd / d2, 0.0), 1.0) : 0.0;
            for (int i = 0; i < D; i++) {
                double r = a->u[i] + lam * (b->u[i] - a->u[i]) - first_u[i];
                dist2 += S->w[i] * r * r;
            }
            if (left_first && dist2 < 0.0625 * d2 && dot_w(C, b->t, first_t) > 0.5) {
                end_with(C->cv, GD_CEND_CLOSED, "closed: back at its first point at %s", PP(b->u));
                goto done;
            }
            if (db2 > 4.0 * d2)
                left_first = 1;
        }
        csys_refresh_borders(S, b->pt.orbit.M, b->v, b->wl, b->X, b->Psi);
        double *J = C->Jc;
        C->Jc = C->Jn;
        C->Jn = J;
        cpt *t = a;
        a = b;
        b = t;
        near.q = -1;
        ds = iters <= 3 ? fmin(1.5 * ds, co->ds_max) : iters >= 6 ? fmax(0.5 * ds, co->ds_min) : ds;
    }
    end_with(C->cv, GD_CEND_BUDGET, "%d points reached at %s", co->max_points, PP(a->u));
done:
    free(a);
    free(b);
    free(q);
    return st;
}

/* The grazing's extremum at the start: of clearance c the extremum nearest a boundary. */
static gd_status graze_start(csys *S, const gd_model *m, const double *y, int c, double *phi, gd_error *err)
{
    gd_gap_extrema g;
    gd_status st = gd_sim_orbit_gaps(m, &S->o, y, S->nper, &g, err);
    if (st != GD_OK)
        return st;
    if (c < 0 || c >= m->nclear || g.n[c] == 0)
        return gd_error_set(err, GD_ERR_INPUT, "the grazing's clearance %d has no extremum on the orbit", c);
    const double P = S->nper * m->period, h = m->clear[c].h;
    int best = -1, side = 0;
    double bd = INFINITY;
    for (int i = 0; i < g.n[c]; i++)
        for (int sd = 0; sd < 2; sd++) {
            double d = fabs(g.x[c][i] - (sd ? -h : h));
            if (d < bd)
                bd = d, best = i, side = sd;
        }
    S->gclr = c;
    S->gside = side;
    S->gkind = g.kind[c][best];
    /* the mode on the side where the contact does not happen, around the touch */
    S->gmode = side == 0 ? (S->gkind < 0 ? 1 : 0) : (S->gkind < 0 ? 0 : -1);
    *phi = g.t[c][best] / P;
    double near = 0.5;
    for (int i = 0; i < g.n[c]; i++) {
        if (i == best)
            continue;
        double d = fabs(g.t[c][i] - g.t[c][best]) / P;
        d -= floor(d);
        near = fmin(near, fmin(d, 1.0 - d));
    }
    S->ghalf = fmin(0.5 * near, 0.25);
    return GD_OK;
}

GD_API gd_status gd_curve_follow(gd_model_at2_fn model_at, void *ctx, const gd_solver_opts *o, const gd_curve_opts *co,
                                 const gd_curve_start *start, gd_curve *cv, gd_error *err)
{
    memset(cv, 0, sizeof *cv);
    cv->kind = start->kind;
    cv->nper = start->nper;
    cv->clearance = start->kind == GD_CURVE_GRAZING ? start->clearance : -1;
    gd_model m;
    gd_status st = model_at(start->p1, start->p2, &m, ctx, err);
    if (st != GD_OK)
        return st;
    csys *S = calloc(1, sizeof *S);
    ccont C = {0};
    cpt *a = malloc(sizeof *a);
    if (!S || !a) {
        free(S);
        free(a);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a curve");
    }
    gd_po_opts po = co->po;
    po.nper = start->nper;
    st = csys_init(S, model_at, ctx, o, start->kind, m.n, &po, err);
    C.S = S;
    C.co = co;
    C.cv = cv;
    const int n = m.n, N = S->N;
    double *u = a->u;
    memset(a, 0, sizeof *a);
    if (st == GD_OK) {
        memcpy(u, start->y, sizeof(double) * (size_t)n);
        for (int k = 1; k < S->nseg && st == GD_OK; k++)
            st = gd_sim_period_map(&m, o, u + (k - 1) * n, S->per_seg, u + k * n, NULL, NULL, err);
        u[N] = start->p1;
        u[N + 1] = start->p2;
    }
    S->m = m;
    if (st == GD_OK && start->kind == GD_CURVE_GRAZING)
        st = graze_start(S, &m, start->y, start->clearance, &u[N + 2], err);
    if (st == GD_OK && start->kind == GD_CURVE_NEIMARK_SACKER) {
        gd_po orb;
        gd_po_opts p1 = po;
        st = gd_po_solve(&m, o, &p1, start->y, &orb, err);
        double re, im;
        if (st == GD_OK && !cont_ns_multiplier(&orb, &re, &im))
            st = gd_error_set(err, GD_ERR_INPUT, "no complex multiplier at the Neimark-Sacker point's orbit");
        if (st == GD_OK)
            u[N + 2] = re / hypot(re, im);
    }
    cv->graze_side = S->gside;
    cv->graze_extremum = S->gkind;
    /* the scales and tolerances */
    double Y = co->y_scale > 0 ? co->y_scale : 1.0;
    if (!(co->y_scale > 0))
        for (int i = 0; i < N; i++)
            Y = fmax(Y, fabs(u[i]));
    C.Y = Y;
    for (int q = 0; q < 2; q++) {
        double R = co->p_scale[q];
        if (!(R > 0))
            R = isfinite(co->p_max[q] - co->p_min[q]) && co->p_max[q] > co->p_min[q] ? co->p_max[q] - co->p_min[q]
                                                                                 : fmax(1.0, fabs(u[N + q]));
        C.R[q] = R;
        C.dp_max[q] = co->dp_max[q] > 0 ? co->dp_max[q] : 0.02 * R;
    }
    C.tol = co->po.tol > 0 ? co->po.tol : o->rtol * Y + o->atol;
    C.locate_tol = co->locate_tol > 0 ? co->locate_tol : 10.0 * C.tol / Y;
    for (int i = 0; i < N; i++)
        S->w[i] = 1.0 / (S->nseg * Y * Y);
    S->w[N] = 1.0 / (C.R[0] * C.R[0]);
    S->w[N + 1] = 1.0 / (C.R[1] * C.R[1]);
    if (S->ne)
        S->w[N + 2] = S->kind == GD_CURVE_NEIMARK_SACKER ? 0.25 : 1.0;
    cv->y_scale = Y;
    cv->p_scale[0] = C.R[0];
    cv->p_scale[1] = C.R[1];
    cv->tol = C.tol;
    cv->locate_tol = C.locate_tol;
    C.Jc = st == GD_OK ? malloc(sizeof(double) * (size_t)(S->D - 1) * S->D) : NULL;
    C.Jn = st == GD_OK ? malloc(sizeof(double) * (size_t)(S->D - 1) * S->D) : NULL;
    if (st == GD_OK && (!C.Jc || !C.Jn))
        st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for a curve");
    /* the start: corrected with p2 fixed, its sequence the curve's */
    if (st == GD_OK)
        st = csys_start_borders(S, u, err);
    double e2[CMAX] = {0}, up[CMAX];
    e2[N + 1] = 1.0;
    memcpy(up, u, sizeof up);
    int iters = 0;
    if (st == GD_OK) {
        /* two rounds: the borders refreshed at the corrected point, and corrected again */
        for (int round = 0; round < 2 && st == GD_OK; round++) {
            st = correct(&C, u, e2, up, &iters, err);
            if (st == GD_OK)
                csys_refresh_borders(S, S->M, S->v, S->wl, S->X, S->Psi);
        }
        if (st != GD_OK)
            gd_error_prefix(err, "the %s curve's start at %s", gd_curve_kind_name(start->kind),
                            at_text(&C, start->p1, start->p2).s);
    }
    if (st == GD_OK) {
        st = csys_eval(S, u, 1, err);
        for (int k = 0; k < S->nseg; k++)
            S->seq_ref[k] = S->seq[k];
        S->seq_set = 1;
    }
    if (st == GD_OK) {
        /* the tangent: towards increasing (direction +1) or decreasing p2 */
        double e[CMAX] = {0};
        e[N + 1] = co->direction < 0 ? -1.0 : 1.0;
        gd_error e3 = {0};
        st = tangent(&C, e, a->t, &e3);
        if (st != GD_OK || fabs(a->t[N + 1]) < 1e-8 * sqrt(dot_w(&C, a->t, a->t)) / sqrt(S->w[N + 1])) {
            memset(e, 0, sizeof e);
            e[N] = co->direction < 0 ? -1.0 : 1.0;
            st = tangent(&C, e, a->t, err);
        }
    }
    if (st == GD_OK)
        st = fill_point(&C, a, iters, 0.0, err);
    if (st == GD_OK) {
        memcpy(C.Jc, S->J, sizeof(double) * (size_t)(S->D - 1) * S->D);
        C.have_Jc = 1;
        st = push_point(cv, &a->pt, err);
    }
    if (st == GD_OK)
        st = run(&C, a, err);
    csys_free(S);
    free(C.Jc);
    free(C.Jn);
    free(S);
    free(a);
    if (st != GD_OK)
        gd_curve_free(cv);
    return st;
}
