/* Pseudo-arclength continuation of a periodic orbit in a parameter (docs/continuation.md section
 * 3): predictor along the unit tangent, Newton corrector on the shooting system bordered by the
 * arclength condition (shooting.c), an adaptive step, and the location between two points, by
 * GSL's Brent solver on a test function of the arclength, of the folds (the tangent's parameter
 * component changes sign), period doublings (det(M + I), the product of 1 + mu over the
 * multipliers, changes sign: a real multiplier passed -1), Neimark-Sacker points and changes of
 * the contact sequence (the events of a clearance per orbit change in number: an extremum of its
 * coordinate crossed a boundary, through a grazing; its distance to the boundary is the test
 * function, with the bisection of the event count where no extremum crossed). */
#include "shooting.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
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

/* The bialternate product prod_{i<j} (mu_i mu_j - 1) (real: the multipliers are closed under
 * conjugation) as a continuous function of the same sign and zeros: its sign (each factor divided
 * by its modulus, so that no product overflows) times the smallest modulus of a factor. It changes
 * sign where a complex pair crosses the unit circle (mu conj(mu) = 1), and at a neutral saddle
 * (two real multipliers with mu_i mu_j = 1), which locate() tells apart. */
static double ns_test(const gd_po *po)
{
    double re = 1.0, im = 0.0, mmin = INFINITY;
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
            mmin = fmin(mmin, m);
        }
    return re > 0 ? mmin : -mmin;
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
 * its orbit; *iters the Newton iterations. Newton starts from guess when given, else from the
 * predictor u0 + ds t0. */
static gd_status step_from(cont *c, const double *u0, const double *t0, double ds, const double *guess, double *u,
                           double *t, gd_po *po, int *iters, gd_error *err)
{
    const int N = c->sh.N;
    double up[UMAX];
    for (int i = 0; i <= N; i++) {
        up[i] = u0[i] + ds * t0[i];
        u[i] = guess ? guess[i] : up[i];
    }
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

/* The guess for the point at arclength s between u0 (tangent t0) and u1 (tangent t1, at ds1): the
 * cubic Hermite of the branch in sigma = t0 . (u - u0), which is 0 at u0 and ds1 at u1 (the
 * arclength condition), with du/dsigma = t / (t0 . t) at both ends. */
static void hermite_guess(int N, const double *u0, const double *t0, const double *u1, const double *t1, double ds1,
                          double s, double *g)
{
    double x = s / ds1, dot = 0;
    for (int i = 0; i <= N; i++)
        dot += t0[i] * t1[i];
    double h00 = (1 + 2 * x) * (1 - x) * (1 - x), h10 = x * (1 - x) * (1 - x), h01 = x * x * (3 - 2 * x),
           h11 = x * x * (x - 1);
    for (int i = 0; i <= N; i++)
        g[i] = h00 * u0[i] + h10 * ds1 * t0[i] + h01 * u1[i] + h11 * ds1 * t1[i] / dot;
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

/* A contact change followed by the distance of one extremum of the clearance coordinate to one
 * boundary: the extremum of kind `sign` (+1 maximum, -1 minimum) nearest the orbit phase `phase`
 * (its time over the orbit's duration), less the boundary b (+h or -h). */
typedef struct gap_ref {
    int clr, sign;
    double phase, b;
} gap_ref;

/* the extrema of the orbit po (gd_sim_orbit_gaps), their times turned into phases of the orbit */
static gd_status orbit_gaps(cont *c, const gd_po *po, gd_gap_extrema *g, gd_error *err)
{
    gd_model m;
    gd_status st = c->sh.model_at(po->p, &m, c->sh.ctx, err);
    if (st == GD_OK)
        st = gd_sim_orbit_gaps(&m, &c->sh.o, po->y[0], po->nper, g, err);
    if (st == GD_OK && g->dropped)
        return gd_error_set(err, GD_ERR_SOLVER, "more than %d extrema of a clearance coordinate per orbit",
                            GD_GAP_EXTREMA_MAX);
    for (int k = 0; k < GD_MAX_CLEAR && st == GD_OK; k++)
        for (int i = 0; i < g->n[k]; i++)
            g->t[k][i] /= po->nper * m.period;
    return st;
}

/* the extremum of g followed by r, less its boundary; NAN when the orbit has none of its kind */
static double gap_value(const gd_gap_extrema *g, const gap_ref *r)
{
    int best = -1;
    double dbest = 2.0;
    for (int i = 0; i < g->n[r->clr]; i++) {
        double d = fabs(g->t[r->clr][i] - r->phase);
        d = fmin(d, 1.0 - d); /* the phase is periodic */
        if (g->kind[r->clr][i] == r->sign && d < dbest)
            best = i, dbest = d;
    }
    return best < 0 ? NAN : g->x[r->clr][best] - r->b;
}

/* The extremum whose distance to a boundary changed sign between the orbits po0 and po1: its
 * nearest counterpart of the same kind and phase in po1 lies on the other side of the boundary.
 * Returns 1 with *r, or 0 when no extremum did (the events changed otherwise). */
static int gap_crossing(const gd_gap_extrema *g0, const gd_gap_extrema *g1, int clr, gap_ref *r)
{
    double score = INFINITY;
    int found = 0;
    for (int i = 0; i < g0->n[clr]; i++)
        for (int side = 0; side < 2; side++) {
            gap_ref q = {clr, g0->kind[clr][i], g0->t[clr][i], side ? -g0->h[clr] : g0->h[clr]};
            double d0 = g0->x[clr][i] - q.b, d1 = gap_value(g1, &q);
            if (isfinite(d1) && (d0 > 0) != (d1 > 0) && fabs(d0) + fabs(d1) < score)
                *r = q, score = fabs(d0) + fabs(d1), found = 1;
        }
    return found;
}

/* The test function of `kind` at a point with tangent t and orbit po: its sign changes at the
 * bifurcation. Fold, period doubling and Neimark-Sacker: continuous in the arclength. A contact
 * change: the distance of the followed extremum to its boundary (gap, continuous), or, without
 * one (gap NULL), +1 when the events of clearance clr per orbit equal those of the point before
 * (ref), else -1. */
static double test_value(cont *c, int kind, int clr, long ref, const gap_ref *gap, const double *t,
                         const gd_po *po, gd_status *st, gd_error *err)
{
    switch (kind) {
    case GD_BIF_FOLD:
        return t[c->sh.N];
    case GD_BIF_PERIOD_DOUBLING:
        return pd_test(po);
    case GD_BIF_NEIMARK_SACKER:
        return ns_test(po);
    default:
        if (!gap)
            return po->events[clr] == ref ? 1.0 : -1.0;
        gd_gap_extrema g;
        *st = orbit_gaps(c, po, &g, err);
        return *st == GD_OK ? gap_value(&g, gap) : NAN;
    }
}

/* The test function along the arclength s from (u0, t0), for GSL's root solver: each value one
 * corrected point (step_from). The values at the bracket's ends are known; the last few are kept
 * with their parameters. A failure is kept in st (the value NAN stops the solver). */
#define LOC_CACHE 64
#define LOC_ORBITS 4
typedef struct loc {
    cont *c;
    int kind, clr;
    long ref;
    const gap_ref *gap;
    const double *u0, *t0, *u1, *t1;
    double ds1;
    double s[LOC_CACHE], f[LOC_CACHE], p[LOC_CACHE];
    int nc;
    double os[LOC_ORBITS]; /* the orbits of the last few values, at these arclengths */
    gd_po orbit[LOC_ORBITS];
    int no;
    gd_status st;
    gd_error *err;
} loc;

static void loc_keep(loc *L, double s, double f, double p)
{
    int i = L->nc++ % LOC_CACHE;
    L->s[i] = s, L->f[i] = f, L->p[i] = p;
}

static void loc_keep_orbit(loc *L, double s, const gd_po *po)
{
    int i = L->no++ % LOC_ORBITS;
    L->os[i] = s;
    L->orbit[i] = *po;
}

static int loc_find(const loc *L, double s)
{
    for (int i = 0; i < LOC_CACHE && i < L->nc; i++)
        if (L->s[i] == s)
            return i;
    return -1;
}

static double loc_value(double s, void *params)
{
    loc *L = params;
    int i = loc_find(L, s);
    if (i >= 0)
        return L->f[i];
    if (L->st != GD_OK)
        return NAN;
    double u[UMAX], t[UMAX];
    gd_po po;
    int iters;
    double g[UMAX];
    hermite_guess(L->c->sh.N, L->u0, L->t0, L->u1, L->t1, L->ds1, s, g);
    L->st = step_from(L->c, L->u0, L->t0, s, g, u, t, &po, &iters, L->err);
    if (L->st != GD_OK)
        return NAN;
    double f = test_value(L->c, L->kind, L->clr, L->ref, L->gap, t, &po, &L->st, L->err);
    if (L->st == GD_OK) {
        loc_keep(L, s, f, u[L->c->sh.N]);
        loc_keep_orbit(L, s, &po);
    }
    return L->st == GD_OK ? f : NAN;
}

/* Brent's method (GSL) on the test function between the arclengths *lo and *hi (values known to
 * L) until the bracket is below locate_tol. Brent's iterates converge on the root from one side;
 * once the estimate moves by less than half the tolerance, the point half a tolerance beyond it
 * closes the bracket, or starts a new one. */
static gd_status brent_locate(loc *L, double *lo, double *hi, gd_error *err)
{
    const double tol = L->c->co->locate_tol;
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
        return gd_error_set(err, GD_ERR_GSL, "locating a %s: gsl_root_fsolver_brent: %s", gd_bif_kind_name(L->kind),
                            gsl_strerror(rc));
    return GD_OK;
}

/* Bisection of a test function that takes two values (the events of a clearance) between the
 * arclengths *lo and *hi until the bracket is below locate_tol. */
static gd_status bisect_locate(loc *L, double f_lo, double *lo, double *hi)
{
    while (*hi - *lo > L->c->co->locate_tol) {
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

/* A sign change of the test function of `kind` (clearance clr for a contact change) between the
 * point (u0, t0, po0) and the one at arclength ds1 (t1, po1): located in the arclength from u0
 * along t0 by Brent's method (a contact change: on the distance of an extremum of its coordinate
 * to the boundary; by bisection of the event count when no extremum crossed) until the bracket is
 * below locate_tol; the bifurcation is the point at the middle of the bracket. */
static gd_status locate(cont *c, int kind, int clr, const double *u0, const double *t0, const gd_po *po0,
                        const double *u1, const double *t1, const gd_po *po1, double ds1, gd_error *err)
{
    const int N = c->sh.N;
    gap_ref gap;
    int use_gap = 0;
    gd_status st = GD_OK;
    double f0 = 0, f1 = 0;
    if (kind == GD_BIF_CONTACT_CHANGE) {
        gd_gap_extrema g0, g1;
        st = orbit_gaps(c, po0, &g0, err);
        if (st == GD_OK)
            st = orbit_gaps(c, po1, &g1, err);
        if (st != GD_OK)
            return st;
        use_gap = gap_crossing(&g0, &g1, clr, &gap);
        if (use_gap)
            f0 = gap_value(&g0, &gap), f1 = gap_value(&g1, &gap);
    }
    loc L = {.c = c, .kind = kind, .clr = clr, .ref = clr >= 0 ? po0->events[clr] : 0, .gap = use_gap ? &gap : NULL,
             .u0 = u0, .t0 = t0, .u1 = u1, .t1 = t1, .ds1 = ds1, .st = GD_OK, .err = err};
    if (kind != GD_BIF_CONTACT_CHANGE) {
        f0 = test_value(c, kind, clr, 0, NULL, t0, po0, &st, err);
        f1 = test_value(c, kind, clr, 0, NULL, t1, po1, &st, err);
    } else if (!use_gap) {
        f0 = 1.0, f1 = -1.0;
    }
    loc_keep(&L, 0.0, f0, u0[N]);
    loc_keep(&L, ds1, f1, po1->p);
    const long corr0 = c->br->corrections;
    double lo = 0.0, hi = ds1;
    st = kind == GD_BIF_CONTACT_CHANGE && !use_gap ? bisect_locate(&L, f0, &lo, &hi) : brent_locate(&L, &lo, &hi, err);
    if (st == GD_ERR_GSL && use_gap && L.st == GD_OK) { /* the extremum vanished inside: the event count */
        use_gap = 0;
        L.gap = NULL;
        L.nc = L.no = 0;
        loc_keep(&L, 0.0, 1.0, u0[N]);
        loc_keep(&L, ds1, -1.0, po1->p);
        lo = 0.0, hi = ds1;
        st = bisect_locate(&L, 1.0, &lo, &hi);
    }
    /* a trial point without an orbit (the corrector failed between two points of the branch): the
     * bifurcation keeps the bracket reached so far, wider than locate_tol, and the branch goes on */
    const int soft = st != GD_OK && st != GD_ERR_NOMEM && st != GD_ERR_INTERNAL && st != GD_ERR_INTERRUPTED;
    if (st != GD_OK && !soft)
        return st;
    if (soft)
        gd_error_clear(err);
    int ilo = loc_find(&L, lo), ihi = loc_find(&L, hi);
    double p_lo = ilo >= 0 ? L.p[ilo] : NAN, p_hi = ihi >= 0 ? L.p[ihi] : NAN;
    /* the point reported: the bracket's end nearer the root (the smaller test function), or, after
     * a bisection of the event count or without that end's orbit, the middle corrected again */
    const gd_po *po = NULL;
    double s_best = ilo >= 0 && ihi >= 0 && fabs(L.f[ihi]) < fabs(L.f[ilo]) ? hi : lo;
    for (int i = 0; i < LOC_ORBITS && i < L.no && (use_gap || kind != GD_BIF_CONTACT_CHANGE); i++)
        if (L.os[i] == s_best)
            po = &L.orbit[i];
    gd_po mid;
    if (!po && soft) { /* the branch's own point at an end of the bracket */
        po = s_best == ds1 ? po1 : po0;
        if (s_best != 0.0 && s_best != ds1)
            p_lo = u0[N], p_hi = po1->p;
    }
    if (!po) {
        double u[UMAX], t[UMAX], g[UMAX];
        int iters;
        hermite_guess(N, u0, t0, u1, t1, ds1, 0.5 * (lo + hi), g);
        st = step_from(c, u0, t0, 0.5 * (lo + hi), g, u, t, &mid, &iters, err);
        if (st != GD_OK)
            return st;
        po = &mid;
    }
    gd_bifurcation b;
    memset(&b, 0, sizeof b);
    b.kind = kind;
    b.clearance = clr;
    b.p = po->p;
    b.p_lo = p_lo;
    b.p_hi = p_hi;
    critical_multiplier(po, kind == GD_BIF_PERIOD_DOUBLING ? -1.0 : 1.0, &b.mu_re, &b.mu_im);
    if (kind == GD_BIF_NEIMARK_SACKER && /* a neutral saddle, not a complex pair on the unit circle */
        (!ns_multiplier(po, &b.mu_re, &b.mu_im) || fabs(hypot(b.mu_re, b.mu_im) - 1.0) > 1e-3))
        return GD_OK;
    memcpy(b.y, po->y[0], sizeof(double) * (size_t)po->n);
    b.after = c->br->npoints;
    b.corrections = (int)(c->br->corrections - corr0);
    return push_bif(c->br, &b, err);
}

/* Locate every test function that changed sign between (u, t, po) and the point (u1, t1, po1) at
 * arclength ds. */
static gd_status detect(cont *c, const double *u, const double *t, const gd_po *po, const double *u1,
                        const double *t1, const gd_po *po1, double ds, gd_error *err)
{
    const int N = c->sh.N;
    gd_status st = GD_OK;
    if ((t1[N] > 0) != (t[N] > 0))
        st = locate(c, GD_BIF_FOLD, -1, u, t, po, u1, t1, po1, ds, err);
    if (st == GD_OK && (pd_test(po1) > 0) != (pd_test(po) > 0))
        st = locate(c, GD_BIF_PERIOD_DOUBLING, -1, u, t, po, u1, t1, po1, ds, err);
    if (st == GD_OK && (ns_test(po1) > 0) != (ns_test(po) > 0))
        st = locate(c, GD_BIF_NEIMARK_SACKER, -1, u, t, po, u1, t1, po1, ds, err);
    for (int k = 0; k < GD_MAX_CLEAR && st == GD_OK; k++)
        if (po1->events[k] != po->events[k])
            st = locate(c, GD_BIF_CONTACT_CHANGE, k, u, t, po, u1, t1, po1, ds, err);
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

#define DP_MARGIN 0.98 /* steps aim at this fraction of dp_max */

/* The branch's first point u0 with its tangent t0, and whether the branch has left it (been farther
 * from it, and from its shifts, than twice the step that got there). */
typedef struct first_point {
    double u[UMAX], t[UMAX];
    int left;
} first_point;

/* x shifted by k segments: the same orbit started k segments later (the parameter kept) */
static void shifted(const gd_shoot *sh, const double *x, int k, double *out)
{
    for (int j = 0; j < sh->nseg; j++)
        memcpy(out + j * sh->n, x + ((j + k) % sh->nseg) * sh->n, sizeof(double) * (size_t)sh->n);
    out[sh->N] = x[sh->N];
}

/* Whether the chord from a to b passes the first point (or a shift of it by whole segments) within a
 * quarter of its length with the tangent tb along the first point's: the branch is a closed curve,
 * followed once round (docs/continuation.md section 3). A shifted first point may be passed the other
 * way (*reversed): the curve is symmetric under the shift, and what follows is the mirror image of
 * the branch's other direction from its start. *kshift: the shift, in segments. */
static int closes(const gd_shoot *sh, first_point *f, const double *a, const double *b, const double *tb,
                  int *kshift, int *reversed)
{
    const int M = sh->N + 1;
    double d2 = 0, nearest = INFINITY;
    for (int i = 0; i < M; i++)
        d2 += (b[i] - a[i]) * (b[i] - a[i]);
    int hit = 0;
    for (int k = 0; k < sh->nseg && !hit; k++) {
        double s[UMAX], ts[UMAX], w_d = 0, align = 0, dist2 = 0, db2 = 0;
        shifted(sh, f->u, k, s);
        shifted(sh, f->t, k, ts);
        for (int i = 0; i < M; i++) {
            w_d += (s[i] - a[i]) * (b[i] - a[i]);
            align += tb[i] * ts[i];
            db2 += (b[i] - s[i]) * (b[i] - s[i]);
        }
        double lam = d2 > 0 ? fmin(fmax(w_d / d2, 0.0), 1.0) : 0.0;
        for (int i = 0; i < M; i++) {
            double r = a[i] + lam * (b[i] - a[i]) - s[i];
            dist2 += r * r;
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
 * the same to the corrector's tolerance): the branch has crossed onto the orbit it doubled from. */
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
    first_point first = {.left = 0};
    memcpy(first.u, u, sizeof first.u);
    memcpy(first.t, t, sizeof first.t);
    double ds = co->ds;
    /* the corrected change of p over the predicted one, ds t_p, at the last step (at least 1): the
     * corrector moves p further than the tangent where the branch curves, and a step that then
     * exceeds dp_max is a correction lost */
    double gain = 1.0;
    while (c->br->npoints < co->max_points) {
        if (gd_stop_asked(&co->stop))
            return gd_error_set(err, GD_ERR_INTERRUPTED, "the continuation was stopped at p = %.9g", u[N]);
        int iters = 0;
        gd_error e1 = {0};
        if (co->dp_max > 0 && fabs(ds * t[N]) * gain > DP_MARGIN * co->dp_max)
            ds = fmax(DP_MARGIN * co->dp_max / (fabs(t[N]) * gain), co->ds_min);
        st = step_from(c, u, t, ds, NULL, u1, t1, &po1, &iters, &e1);
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
            /* p moved too far: shorter in proportion; else half the step */
            ds = fmax(st == GD_OK && turn >= 0.5 ? ds * DP_MARGIN * co->dp_max / fabs(u1[N] - u[N]) : 0.5 * ds,
                      co->ds_min);
            continue;
        }
        gain = fmax(1.0, fabs(u1[N] - u[N]) / fabs(ds * t[N]));
        if (!isfinite(gain))
            gain = 1.0;
        if (u1[N] < co->p_min || u1[N] > co->p_max)
            return end_on_bound(c, u, t, u1[N] < co->p_min ? co->p_min : co->p_max, err);
        st = detect(c, u, t, &po, u1, t1, &po1, ds, err);
        if (st == GD_OK)
            st = push_point(c->br, &po1, t1[N], ds, err);
        if (st != GD_OK)
            return st;
        if (half_period(&c->sh, u1, co->po.tol)) {
            c->br->end = GD_END_HALF;
            snprintf(c->br->end_reason, sizeof c->br->end_reason, "the orbit of half the period reached at p = %.9g",
                     u1[N]);
            return GD_OK;
        }
        int k = 0, rev = 0;
        if (closes(&c->sh, &first, u, u1, t1, &k, &rev)) {
            c->br->end = GD_END_CLOSED;
            c->br->closed_shift = k * c->sh.per_seg;
            c->br->closed_reversed = rev;
            snprintf(c->br->end_reason, sizeof c->br->end_reason, "closed: back at its first orbit%s%s at p = %.9g",
                     k ? " shifted by whole mesh periods" : "", rev ? ", the other way" : "", u1[N]);
            return GD_OK;
        }
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
    c.sh.chord = 1;
    if (st == GD_OK)
        st = run(&c, start, err);
    br->chord_iterations = c.sh.chord_iterations;
    gd_shoot_free(&c.sh);
    return st;
}
