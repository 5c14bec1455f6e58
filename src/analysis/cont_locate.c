/* The bifurcations between two points of a branch (docs/continuation.md section 3): the sign
 * changes of the test functions (cont_tests.c), each located in the arclength from the first point
 * by GSL's Brent solver, every value one corrected point; a contact change on the distance of a
 * followed extremum of its clearance coordinate to the boundary, or by bisection of the clearance's
 * event count where no followed extremum crossed. A location is checked afterwards: the test
 * function must have become small in its final bracket (a jump is reported as such, not as a zero);
 * a trial point without an orbit leaves the bracket reached. A branch point where the orbit is of
 * half its period is the vertex of a period doubling of that orbit and ends the branch there. */
#include "cont_internal.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* What a location follows: the test function of a kind at a point. */
typedef struct tfun {
    int kind;                /* gd_bif_kind */
    int clr;                 /* a contact change: the clearance, else -1 */
    int index;               /* a Neimark-Sacker point: the order statistic of the multipliers' moduli */
    int by_events;           /* a contact change on the event count (+1 where it equals ref, else -1) */
    long ref;
    gap_ref gap;             /* a contact change on an extremum */
    double bp_ref;           /* the branch-point test: log |D| at the first point */
} tfun;

/* The test function along the arclength s from a towards b, for GSL's root solver: each value one
 * corrected point (cont_step from the cubic Hermite of the branch), every one kept with its point.
 * A failure is kept in st (the value NAN stops the solver). */
#define LOC_CACHE 64
typedef struct loc {
    cont *c;
    tfun tf;
    const cpoint *a, *b;
    double ds1;
    int nc;
    double s[LOC_CACHE], f[LOC_CACHE], ph[LOC_CACHE]; /* arclength, value, phase of the followed extremum */
    cpoint *pt;              /* LOC_CACHE points */
    gd_status st;
    gd_error *err;
} loc;

static int loc_find(const loc *L, double s)
{
    for (int i = 0; i < L->nc; i++)
        if (L->s[i] == s)
            return i;
    return -1;
}

/* the value at the point q; for an extremum, followed from the phase ref_phase (*phase: where it is) */
static double value_at(loc *L, cpoint *q, double ref_phase, double *phase)
{
    const tfun *tf = &L->tf;
    *phase = ref_phase;
    switch (tf->kind) {
    case GD_BIF_FOLD:
        return cont_fold_test(L->c, q);
    case GD_BIF_BRANCH_POINT:
        return cont_bp_test(q, tf->bp_ref);
    case GD_BIF_PERIOD_DOUBLING:
        return cont_pd_test(&q->po);
    case GD_BIF_NEIMARK_SACKER:
        return cont_modulus_test(&q->po, tf->index);
    default:
        if (tf->by_events)
            return q->po.events[tf->clr] == tf->ref ? 1.0 : -1.0;
        L->st = cont_gaps(L->c, q, L->err);
        if (L->st != GD_OK)
            return NAN;
        gap_ref r = tf->gap;
        r.phase = ref_phase;
        return cont_gap_value(&q->g, &r, phase);
    }
}

static void keep(loc *L, double s, double f, double phase, const cpoint *q)
{
    if (L->nc == LOC_CACHE) /* (loc_value stops before) */
        return;
    L->s[L->nc] = s;
    L->f[L->nc] = f;
    L->ph[L->nc] = phase;
    L->pt[L->nc++] = *q;
}

/* The guess for the point at arclength s: the cubic Hermite of the branch between the evaluated
 * points nearest s on either side (a and b at first), in sigma = <a.t, u - a.u>, which every corrected
 * point satisfies (sigma is its arclength s), with du/dsigma = t / <a.t, t> at both ends. As the
 * bracket shrinks the guess comes from its own ends: near a branch point, where another branch
 * passes close, Newton starts on the one followed. */
static void hermite_guess(const loc *L, double s, double *g)
{
    const cont *c = L->c;
    int il = -1, ir = -1;
    for (int j = 0; j < L->nc; j++) {
        if (L->s[j] < s && (il < 0 || L->s[j] > L->s[il]))
            il = j;
        if (L->s[j] > s && (ir < 0 || L->s[j] < L->s[ir]))
            ir = j;
    }
    const cpoint *l = il >= 0 ? &L->pt[il] : L->a, *r = ir >= 0 ? &L->pt[ir] : L->b;
    double sl = il >= 0 ? L->s[il] : 0.0, sr = ir >= 0 ? L->s[ir] : L->ds1, h = sr - sl, x = (s - sl) / h;
    double dl = cont_dot(c, L->a->t, l->t), dr = cont_dot(c, L->a->t, r->t);
    double h00 = (1 + 2 * x) * (1 - x) * (1 - x), h10 = x * (1 - x) * (1 - x), h01 = x * x * (3 - 2 * x),
           h11 = x * x * (x - 1);
    for (int i = 0; i <= c->sh.N; i++)
        g[i] = h00 * l->u[i] + h10 * h * l->t[i] / dl + h01 * r->u[i] + h11 * h * r->t[i] / dr;
}

static double loc_value(double s, void *params)
{
    loc *L = params;
    int i = loc_find(L, s);
    if (i >= 0)
        return L->f[i];
    if (L->st != GD_OK)
        return NAN;
    if (L->nc == LOC_CACHE) { /* a location this long ends with the bracket it has */
        L->st = gd_error_set(L->err, GD_ERR_SOLVER, "more than %d trial points", LOC_CACHE);
        return NAN;
    }
    /* the extremum is followed from the phase it had at the evaluated point nearest s */
    int near = 0;
    for (int j = 1; j < L->nc; j++)
        if (fabs(L->s[j] - s) < fabs(L->s[near] - s))
            near = j;
    double g[UMAX], phase;
    cpoint q;
    int iters;
    hermite_guess(L, s, g);
    L->st = cont_step(L->c, L->a, s, g, &q, &iters, L->err);
    if (L->st == GD_ERR_SOLVER || L->st == GD_ERR_GSL) {
        /* no orbit there: at a branch point the bordered Jacobian is singular, and Brent's secant may
         * land on it exactly; a quarter of the tolerance beyond stands for it */
        double s2 = s + 0.25 * L->c->locate_tol * (s < 0.5 * L->ds1 ? 1.0 : -1.0);
        gd_error_clear(L->err);
        hermite_guess(L, s2, g);
        L->st = cont_step(L->c, L->a, s2, g, &q, &iters, L->err);
    }
    if (L->st != GD_OK)
        return NAN;
    double f = value_at(L, &q, L->ph[near], &phase);
    if (L->st != GD_OK)
        return NAN;
    keep(L, s, f, phase, &q);
    return f;
}

/* Brent's method (GSL) on the test function between the arclengths *lo and *hi (values known to
 * L) until the bracket is below locate_tol. Brent's iterates converge on the root from one side;
 * once the estimate moves by less than half the tolerance, the point half a tolerance beyond it
 * closes the bracket, or starts a new one. */
static gd_status brent_locate(loc *L, double *lo, double *hi, gd_error *err)
{
    const double tol = L->c->locate_tol;
    gsl_function F = {loc_value, L};
    gsl_root_fsolver *rs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!rs)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the root solver");
    int rc = gsl_root_fsolver_set(rs, &F, *lo, *hi);
    double r_prev = NAN;
    while (rc == GSL_SUCCESS && *hi - *lo > tol) {
        rc = gsl_root_fsolver_iterate(rs);
        if (rc != GSL_SUCCESS)
            break;
        double r = gsl_root_fsolver_root(rs);
        *lo = gsl_root_fsolver_x_lower(rs);
        *hi = gsl_root_fsolver_x_upper(rs);
        if (*hi - *lo <= tol || !(fabs(r - r_prev) < 0.5 * tol) || loc_find(L, r) < 0) {
            r_prev = r;
            continue;
        }
        double fr = L->f[loc_find(L, r)], x = r - *lo > *hi - r ? r - 0.5 * tol : r + 0.5 * tol;
        double fx = loc_value(x, L);
        if (!isfinite(fx))
            break;
        if ((fx > 0) != (fr > 0)) { /* closed: [r, x] */
            *lo = fmin(r, x), *hi = fmax(r, x);
            break;
        }
        if (x < r) /* the root lies beyond x, away from r */
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
        return gd_error_set(err, GD_ERR_GSL, "locating a %s: gsl_root_fsolver_brent: %s", gd_bif_kind_name(L->tf.kind),
                            gsl_strerror(rc));
    return GD_OK;
}

/* Bisection of a test function that takes two values (the events of a clearance) between the
 * arclengths *lo and *hi until the bracket is below locate_tol. */
static gd_status bisect_locate(loc *L, double f_lo, double *lo, double *hi)
{
    while (*hi - *lo > L->c->locate_tol) {
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

static gd_status note(gd_branch *br, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static gd_status note(gd_branch *br, const char *fmt, ...)
{
    if (br->nnotes < GD_BRANCH_NOTES) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(br->notes[br->nnotes++], sizeof br->notes[0], fmt, ap);
        va_end(ap);
    } else {
        br->notes_dropped++;
    }
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

/* A sign change of the test function tf between a and b (at arclength ds1): located (Brent, or a
 * bisection of the event count) until the bracket is below locate_tol, into *out (its location
 * status says how it ended) with its point in *q (q may be NULL) at arclength *sq from a. */
static gd_status locate(cont *c, tfun *tf, const cpoint *a, const cpoint *b, double ds1, gd_bifurcation *out,
                        cpoint *q, double *sq, gd_error *err)
{
    const int N = c->sh.N;
    loc L = {.c = c, .tf = *tf, .a = a, .b = b, .ds1 = ds1, .st = GD_OK, .err = err};
    L.pt = malloc(sizeof *L.pt * LOC_CACHE);
    if (!L.pt)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a location");
    double pa = tf->gap.phase, pb = pa, fa, fb;
    cpoint *ends = malloc(2 * sizeof *ends);
    if (!ends) {
        free(L.pt);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a location");
    }
    cpoint *ca = ends, *cb = ends + 1;
    *ca = *a;
    *cb = *b;
    fa = value_at(&L, ca, pa, &pa);
    fb = value_at(&L, cb, pa, &pb); /* an extremum: b's counterpart of a's, nearest in phase */
    keep(&L, 0.0, fa, pa, ca);
    keep(&L, ds1, fb, pb, cb);
    const long corr0 = c->br->corrections;
    double lo = 0.0, hi = ds1;
    gd_status st = L.st;
    if (st == GD_OK)
        st = tf->by_events ? bisect_locate(&L, fa, &lo, &hi) : brent_locate(&L, &lo, &hi, err);
    int where = GD_LOC_LOCATED;
    if (st == GD_ERR_GSL && tf->kind == GD_BIF_CONTACT_CHANGE && !tf->by_events && L.st == GD_OK &&
        a->po.events[tf->clr] != b->po.events[tf->clr]) {
        /* the followed extremum vanished inside the step: the event count instead */
        gd_error_clear(err);
        L.tf.by_events = 1;
        L.tf.ref = a->po.events[tf->clr];
        L.nc = 0;
        keep(&L, 0.0, 1.0, pa, ca);
        keep(&L, ds1, -1.0, pb, cb);
        lo = 0.0, hi = ds1;
        st = bisect_locate(&L, 1.0, &lo, &hi);
    }
    /* a trial point without an orbit (the corrector failed between two points of the branch), or a
     * test function that is not finite there: the bracket reached so far is kept, and the branch
     * goes on */
    const int soft = st != GD_OK && st != GD_ERR_NOMEM && st != GD_ERR_INTERNAL && st != GD_ERR_INTERRUPTED;
    free(ends);
    if (st != GD_OK && !soft) {
        free(L.pt);
        return st;
    }
    if (soft) {
        gd_error_clear(err);
        where = GD_LOC_BRACKET;
    }
    int ilo = loc_find(&L, lo), ihi = loc_find(&L, hi);
    if (ilo < 0 || ihi < 0) { /* (Brent's bracket ends are evaluated points) */
        free(L.pt);
        return gd_error_set(err, GD_ERR_INTERNAL, "a location lost its bracket");
    }
    int best = fabs(L.f[ihi]) < fabs(L.f[ilo]) ? ihi : ilo;
    if (L.tf.by_events) {
        where = where == GD_LOC_BRACKET ? where : GD_LOC_EVENTS;
        best = ihi; /* the first point with the other count */
    } else if (where == GD_LOC_LOCATED) {
        /* a continuous test function is small in a bracket that shrank from ds1 to hi - lo; one that
         * jumps keeps its size there */
        double shrink = sqrt((hi - lo) / ds1);
        if (!(fabs(L.f[ilo]) + fabs(L.f[ihi]) <= shrink * (fabs(fa) + fabs(fb))))
            where = GD_LOC_JUMP;
    }
    const cpoint *r = &L.pt[best];
    memset(out, 0, sizeof *out);
    out->kind = tf->kind;
    out->clearance = tf->kind == GD_BIF_CONTACT_CHANGE ? tf->clr : -1;
    out->p = r->u[N];
    out->p_lo = L.pt[ilo].u[N];
    out->p_hi = L.pt[ihi].u[N];
    out->location = where;
    cont_critical_multiplier(&r->po, tf->kind == GD_BIF_PERIOD_DOUBLING ? -1.0 : 1.0, &out->mu_re, &out->mu_im);
    memcpy(out->y, r->po.y[0], sizeof(double) * (size_t)r->po.n);
    out->after = c->br->npoints;
    out->corrections = (int)(c->br->corrections - corr0);
    if (q)
        *q = *r;
    if (sq)
        *sq = L.s[best];
    free(L.pt);
    return GD_OK;
}

/* A modulus that passed 1, located: a Neimark-Sacker point when a complex multiplier lies within 1e-3
 * of the unit circle there; not when the multiplier there is real at -1 or 1 (a pair that met on the
 * real axis and crossed as a period doubling or a fold); anything else (the location jumped, or
 * failed) is noted on the branch and not kept. */
static gd_status keep_ns(cont *c, gd_bifurcation *bf, const cpoint *q, gd_error *err)
{
    double re, im;
    if (cont_ns_multiplier(&q->po, &re, &im) && fabs(hypot(re, im) - 1.0) <= 1e-3) {
        bf->mu_re = re;
        bf->mu_im = im;
        return push_bif(c->br, bf, err);
    }
    int j = 0;
    for (int i = 1; i < q->po.n; i++)
        if (fabs(hypot(q->po.mu_re[i], q->po.mu_im[i]) - 1.0) < fabs(hypot(q->po.mu_re[j], q->po.mu_im[j]) - 1.0))
            j = i;
    /* a pair that met on the real axis and passed -1 or 1 there: the period doubling's or fold's test
     * has it */
    if (q->po.mu_im[j] == 0.0 && bf->location == GD_LOC_LOCATED &&
        fabs(fabs(q->po.mu_re[j]) - 1.0) <= 1e-3)
        return GD_OK;
    return note(c->br, "p = %.9g: a complex multiplier's modulus passes 1 in the step, but at the located point the "
                "multiplier nearest the unit circle is %.6g%+.6gi (location %s): not kept as a Neimark-Sacker point",
                bf->p, q->po.mu_re[j], q->po.mu_im[j], gd_bif_location_name(bf->location));
}

/* The order statistics of the moduli that passed 1 between the orbits a and b with a complex
 * multiplier among them at either end (a real one passing 1 is a period doubling's or a fold's): one
 * per conjugate pair, into idx; their number. */
static int ns_crossings(const gd_po *a, const gd_po *b, int *idx)
{
    int k = 0;
    for (int j = 0; j < a->n; j++) {
        if ((cont_modulus_test(a, j) > 0) == (cont_modulus_test(b, j) > 0))
            continue;
        if (a->mu_im[j] == 0.0 && b->mu_im[j] == 0.0)
            continue;
        /* the second of a pair: the same modulus as the one before (conjugates, sorted together) */
        if (k > 0 && idx[k - 1] == j - 1 &&
            ((a->mu_im[j] != 0.0 && a->mu_im[j] == -a->mu_im[j - 1]) ||
             (b->mu_im[j] != 0.0 && b->mu_im[j] == -b->mu_im[j - 1])))
            continue;
        idx[k++] = j;
    }
    return k;
}

gd_status cont_detect(cont *c, const cpoint *a, const cpoint *b, double ds, gd_error *err)
{
    gd_status st = GD_OK;
    const cpoint *e = b; /* (the end of the step) */
    double se = ds;
    int fold = (cont_fold_test(c, a) > 0) != (cont_fold_test(c, b) > 0), have_bp = 0;
    gd_bifurcation bp;
    if (a->bp_sign != b->bp_sign) {
        tfun tf = {.kind = GD_BIF_BRANCH_POINT, .clr = -1, .bp_ref = a->bp_log};
        cpoint *q = malloc(sizeof *q);
        if (!q)
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a branch point");
        st = locate(c, &tf, a, b, ds, &bp, q, NULL, err);
        have_bp = st == GD_OK;
        /* a fold at the branch point itself (a pitchfork's vertex): the tangent's parameter part vanishes
         * there, and the point is one */
        if (have_bp && fold &&
            fabs(cont_fold_test(c, q)) <= 1e-2 * fmax(fabs(cont_fold_test(c, a)), fabs(cont_fold_test(c, b))))
            fold = 0;
        free(q);
        if (st != GD_OK)
            return st;
    }
    if (fold) {
        tfun tf = {.kind = GD_BIF_FOLD, .clr = -1};
        gd_bifurcation bf;
        st = locate(c, &tf, a, e, se, &bf, NULL, NULL, err);
        if (st == GD_OK)
            st = push_bif(c->br, &bf, err);
    }
    if (st == GD_OK && have_bp)
        st = push_bif(c->br, &bp, err);
    if (st == GD_OK && (cont_pd_test(&e->po) > 0) != (cont_pd_test(&a->po) > 0)) {
        tfun tf = {.kind = GD_BIF_PERIOD_DOUBLING, .clr = -1};
        gd_bifurcation bf;
        st = locate(c, &tf, a, e, se, &bf, NULL, NULL, err);
        if (st == GD_OK)
            st = push_bif(c->br, &bf, err);
    }
    int ns[GD_MAX_STATE], nns = st == GD_OK ? ns_crossings(&a->po, &e->po, ns) : 0;
    for (int i = 0; i < nns && st == GD_OK; i++) {
        tfun tf = {.kind = GD_BIF_NEIMARK_SACKER, .clr = -1, .index = ns[i]};
        gd_bifurcation bf;
        cpoint *q = malloc(sizeof *q);
        if (!q)
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a Neimark-Sacker point");
        st = locate(c, &tf, a, e, se, &bf, q, NULL, err);
        if (st == GD_OK)
            st = keep_ns(c, &bf, q, err);
        free(q);
    }
    /* contact changes: every followed extremum that crossed a boundary; the event count where the
     * count changed and none did */
    for (int k = 0; k < GD_MAX_CLEAR && st == GD_OK; k++) {
        gap_ref r[8];
        int nr = a->gaps_ok && e->gaps_ok && !c->co->contact_by_events ? cont_gap_crossings(&a->g, &e->g, k, r, 8) : 0;
        for (int i = 0; i < nr && st == GD_OK; i++) {
            tfun tf = {.kind = GD_BIF_CONTACT_CHANGE, .clr = k, .gap = r[i]};
            gd_bifurcation bf;
            st = locate(c, &tf, a, e, se, &bf, NULL, NULL, err);
            if (st == GD_OK)
                st = push_bif(c->br, &bf, err);
        }
        if (st == GD_OK && nr == 0 && a->po.events[k] != e->po.events[k]) {
            tfun tf = {.kind = GD_BIF_CONTACT_CHANGE, .clr = k, .by_events = 1, .ref = a->po.events[k]};
            gd_bifurcation bf;
            st = locate(c, &tf, a, e, se, &bf, NULL, NULL, err);
            if (st == GD_OK)
                st = push_bif(c->br, &bf, err);
        }
    }
    return st;
}
