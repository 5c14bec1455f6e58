/* The test functions of the continuation at one point (docs/continuation.md section 3): each is
 * continuous along the branch and changes sign at its bifurcation. Fold: the parameter component of
 * the tangent. Branch point: the determinant of the shooting Jacobian bordered by the tangent
 * (shooting.c). Period doubling: det(M + I), evaluated as its sign times the smallest modulus of a
 * factor, which has the same sign and zeros and cannot overflow. Neimark-Sacker: the modulus of a
 * multiplier less 1, one function per order statistic. Contact change: the distance of an extremum of
 * a clearance coordinate, followed from point to point, to a boundary of the clearance. */
#include "cont_internal.h"

#include <math.h>
#include <string.h>

double cont_dot(const cont *c, const double *a, const double *b)
{
    double d = 0;
    for (int i = 0; i <= c->sh.N; i++)
        d += c->sh.w[i] * a[i] * b[i];
    return d;
}

double cont_fold_test(const cont *c, const cpoint *q)
{
    return q->t[c->sh.N];
}

/* det(M + I) = prod (1 + mu_i) over the multipliers (real: a conjugate pair gives |1 + mu|^2), as
 * its sign (each factor divided by its modulus) times the smallest modulus of a factor */
double cont_pd_test(const gd_po *po)
{
    return cont_det_test(po, -1.0);
}

/* det(M - s I) = prod (mu_i - s) over the multipliers, as its sign times the smallest |mu_i - s|
 * (s = -1: the period doubling's test; s = +1: a real multiplier passing 1, a smooth fold's) */
double cont_det_test(const gd_po *po, double s)
{
    double re = 1.0, im = 0.0, mmin = INFINITY;
    for (int i = 0; i < po->n; i++) {
        double a = s > 0 ? po->mu_re[i] - 1.0 : 1.0 + po->mu_re[i], b = po->mu_im[i], m = hypot(a, b);
        if (m == 0)
            return 0.0;
        double r2 = (re * a - im * b) / m;
        im = (re * b + im * a) / m;
        re = r2;
        mmin = fmin(mmin, m);
    }
    return re > 0 ? mmin : -mmin;
}

/* The Neimark-Sacker test of order statistic j: |mu_(j)| - 1, the j-th largest modulus of a
 * multiplier less 1 (the multipliers are sorted by modulus). Order statistics of continuous
 * functions are continuous, so each changes sign where one multiplier's modulus passes 1: with one
 * function per multiplier that crossed, two pairs crossing the circle in one step are both found
 * (a product over the multipliers, such as the bialternate product, changes sign only with the
 * parity of the crossings, and also at neutral saddles where no multiplier is on the circle). */
double cont_modulus_test(const gd_po *po, int j)
{
    return hypot(po->mu_re[j], po->mu_im[j]) - 1.0;
}

double cont_bp_test(const cpoint *q, double ref)
{
    return q->bp_sign * exp(fmin(q->bp_log - ref, 700.0));
}

int cont_ns_multiplier(const gd_po *po, double *re, double *im)
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

void cont_critical_multiplier(const gd_po *po, double target, double *re, double *im)
{
    int best = 0;
    for (int i = 1; i < po->n; i++)
        if (hypot(po->mu_re[i] - target, po->mu_im[i]) < hypot(po->mu_re[best] - target, po->mu_im[best]))
            best = i;
    *re = po->mu_re[best];
    *im = po->mu_im[best];
}

gd_status cont_half(cont *c, cpoint *q, gd_error *err)
{
    const gd_po *po = &q->po;
    const int n = po->n;
    if (q->half_ok || po->nper % 2)
        return GD_OK;
    if (po->nseg == po->nper) {
        for (int i = 0; i < n; i++)
            q->dh[i] = po->y[0][i] - po->y[po->nseg / 2][i];
        q->half_ok = 1;
        return GD_OK;
    }
    gd_model m;
    double y1[GD_MAX_STATE];
    gd_status st = c->sh.model_at(po->p, &m, c->sh.ctx, err);
    if (st == GD_OK)
        st = gd_sim_period_map(&m, &c->sh.o, po->y[0], po->nper / 2, y1, NULL, NULL, err);
    if (st != GD_OK)
        return st;
    for (int i = 0; i < n; i++)
        q->dh[i] = po->y[0][i] - y1[i];
    q->half_ok = 1;
    return GD_OK;
}

gd_status cont_gaps(cont *c, cpoint *q, gd_error *err)
{
    if (q->gaps_ok)
        return GD_OK;
    gd_model m;
    gd_status st = c->sh.model_at(q->po.p, &m, c->sh.ctx, err);
    if (st == GD_OK)
        st = gd_sim_orbit_gaps(&m, &c->sh.o, q->po.y[0], q->po.nper, &q->g, err);
    if (st == GD_OK && q->g.dropped)
        return gd_error_set(err, GD_ERR_SOLVER, "more than %d extrema of a clearance coordinate per orbit",
                            GD_GAP_EXTREMA_MAX);
    if (st != GD_OK)
        return st;
    for (int k = 0; k < GD_MAX_CLEAR; k++)
        for (int i = 0; i < q->g.n[k]; i++)
            q->g.t[k][i] /= q->po.nper * m.period;
    q->gaps_ok = 1;
    return GD_OK;
}

/* the distance of two phases of an orbit (periodic in 1) */
static double phase_gap(double a, double b)
{
    double d = fabs(a - b);
    d -= floor(d);
    return fmin(d, 1.0 - d);
}

/* the extremum of clearance clr and kind `sign` in g nearest the phase; -1 when none */
static int nearest_extremum(const gd_gap_extrema *g, int clr, int sign, double phase)
{
    int best = -1;
    double dbest = INFINITY;
    for (int i = 0; i < g->n[clr]; i++) {
        double d = phase_gap(g->t[clr][i], phase);
        if (g->kind[clr][i] == sign && d < dbest)
            best = i, dbest = d;
    }
    return best;
}

double cont_gap_value(const gd_gap_extrema *g, const gap_ref *r, double *phase)
{
    int i = nearest_extremum(g, r->clr, r->sign, r->phase);
    if (i < 0)
        return NAN;
    if (phase)
        *phase = g->t[r->clr][i];
    return g->x[r->clr][i] - r->b;
}

int cont_gap_crossings(const gd_gap_extrema *ga, const gd_gap_extrema *gb, int clr, gap_ref *r, int max)
{
    int nr = 0;
    for (int i = 0; i < ga->n[clr]; i++) {
        int sign = ga->kind[clr][i], j = nearest_extremum(gb, clr, sign, ga->t[clr][i]);
        /* followed: the nearest of each other's (an extremum born or gone in the step has no partner) */
        if (j < 0 || nearest_extremum(ga, clr, sign, gb->t[clr][j]) != i)
            continue;
        for (int side = 0; side < 2 && nr < max; side++) {
            double bnd = side ? -ga->h[clr] : ga->h[clr];
            double da = ga->x[clr][i] - bnd, db = gb->x[clr][j] - bnd;
            if ((da > 0) != (db > 0))
                r[nr++] = (gap_ref){clr, sign, ga->t[clr][i], bnd};
        }
    }
    return nr;
}
