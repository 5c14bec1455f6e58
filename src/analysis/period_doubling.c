/* Branch switching at a period doubling (docs/continuation.md section 3): the orbit of twice the
 * period, born where a real Floquet multiplier passes -1, found by shooting from the bifurcation's
 * orbit moved along that multiplier's eigenvector (Seydel 2010, on branching at period doubling),
 * and accepted only when it is that orbit: its two halves about the orbit that doubled, its amplitude
 * growing as the square root of the distance to the doubling. The eigenvector is GSL's
 * (gsl_eigen_nonsymmv). */
#include "geardyn/gd_periodic.h"

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* the real eigenvector v (unit length) of the eigenvalue of M nearest -1 */
static gd_status flip_vector(const double *M, int n, double *v, gd_error *err)
{
    gsl_matrix *A = gsl_matrix_alloc((size_t)n, (size_t)n);
    gsl_vector_complex *ev = gsl_vector_complex_alloc((size_t)n);
    gsl_matrix_complex *V = gsl_matrix_complex_alloc((size_t)n, (size_t)n);
    gsl_eigen_nonsymmv_workspace *w = gsl_eigen_nonsymmv_alloc((size_t)n);
    gd_status st = GD_OK;
    if (!A || !ev || !V || !w) {
        st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for the eigenvectors");
        goto done;
    }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            gsl_matrix_set(A, (size_t)i, (size_t)j, M[i * n + j]);
    int rc = gsl_eigen_nonsymmv(A, ev, V, w);
    if (rc != GSL_SUCCESS) {
        st = gd_error_set(err, GD_ERR_GSL, "the eigenvectors of the monodromy: gsl_eigen_nonsymmv: %s",
                          gsl_strerror(rc));
        goto done;
    }
    size_t best = 0;
    for (size_t i = 1; i < (size_t)n; i++) {
        gsl_complex a = gsl_vector_complex_get(ev, i), b = gsl_vector_complex_get(ev, best);
        if (hypot(GSL_REAL(a) + 1.0, GSL_IMAG(a)) < hypot(GSL_REAL(b) + 1.0, GSL_IMAG(b)))
            best = i;
    }
    double norm = 0;
    for (int i = 0; i < n; i++) {
        v[i] = GSL_REAL(gsl_matrix_complex_get(V, (size_t)i, best));
        norm += v[i] * v[i];
    }
    for (int i = 0; i < n; i++)
        v[i] /= sqrt(norm);
done:
    gsl_eigen_nonsymmv_free(w);
    gsl_matrix_complex_free(V);
    gsl_vector_complex_free(ev);
    gsl_matrix_free(A);
    return st;
}

/* half the max-norm distance of the doubled orbit's phase-0 state y0 from its state nper periods later,
 * yn, and the max-norm distance of their mean from the nearest of yc's (the orbit of half the period's
 * nc states at phase 0): the amplitude of the doubling and its asymmetry about that orbit */
static void halves(const double *y0, const double *yn, const double yc[][GD_MAX_STATE], int nc, int n, double *amp,
                   double *asym)
{
    *amp = 0;
    *asym = INFINITY;
    for (int i = 0; i < n; i++)
        *amp = fmax(*amp, 0.5 * fabs(y0[i] - yn[i]));
    for (int k = 0; k < nc; k++) {
        double a = 0;
        for (int i = 0; i < n; i++)
            a = fmax(a, fabs(0.5 * (y0[i] + yn[i]) - yc[k][i]));
        *asym = fmin(*asym, a);
    }
}

/* The doubled orbit of 2 nper periods at parameter p from the guess y (into *out), with its amplitude
 * and asymmetry about the orbit of nper periods at p (shot from yc0, into yc). */
static gd_status doubled_at(gd_model_at_fn model_at, void *ctx, const gd_solver_opts *o, const gd_po_opts *po,
                            double p, const double *y, const double *yc0, gd_po *out, double *amp, double *asym,
                            gd_error *err)
{
    gd_model m;
    gd_po_opts p2 = *po;
    p2.nper = 2 * po->nper;
    gd_po c;
    double yn[GD_MAX_STATE];
    gd_status st = model_at(p, &m, ctx, err);
    if (st == GD_OK)
        st = gd_po_solve(&m, o, &p2, y, out, err);
    if (st == GD_OK)
        st = gd_sim_period_map(&m, o, out->y[0], po->nper, yn, NULL, NULL, err);
    if (st == GD_OK)
        st = gd_po_solve(&m, o, po, yc0, &c, err);
    for (int k = 1; k < po->nper && st == GD_OK; k++) /* its states at phase 0 (one per mesh period) */
        st = gd_sim_period_map(&m, o, c.y[k - 1], 1, c.y[k], NULL, NULL, err);
    if (st == GD_OK)
        halves(out->y[0], yn, (const double(*)[GD_MAX_STATE])c.y, po->nper, m.n, amp, asym);
    return st;
}

GD_API gd_status gd_po_period_doubled(gd_model_at_fn model_at, void *ctx, const gd_solver_opts *o,
                                      const gd_po_opts *po, const gd_bifurcation *b, double dp, double eps,
                                      gd_po *out, gd_error *err)
{
    if (b->kind != GD_BIF_PERIOD_DOUBLING)
        return gd_error_set(err, GD_ERR_INPUT, "branch switching needs a period doubling, not a %s",
                            gd_bif_kind_name(b->kind));
    if (2 * po->nper > GD_PO_MAX_PERIODS)
        return gd_error_set(err, GD_ERR_INPUT, "an orbit of %d mesh periods (valid: up to %d)", 2 * po->nper,
                            GD_PO_MAX_PERIODS);
    gd_model m;
    gd_po at;
    double v[GD_MAX_STATE];
    gd_status st = model_at(b->p, &m, ctx, err);
    if (st == GD_OK)
        st = gd_po_solve(&m, o, po, b->y, &at, err);
    if (st == GD_OK)
        st = flip_vector(at.M, at.n, v, err);
    if (st != GD_OK)
        return gd_error_prefix(err, "the period doubling at p = %.9g", b->p);
    double Y = 1.0;
    for (int i = 0; i < at.n; i++)
        Y = fmax(Y, fabs(at.y[0][i]));
    const double tol = po->tol > 0 ? po->tol : o->rtol * Y + o->atol;
    gd_error e1 = {0};
    char why[GD_ERROR_MSG_MAX] = "";
    for (int trial = 0; trial < 8; trial++) {
        /* 1 and 1/8 of dp, on either side, moved either way along v */
        double dpt = trial < 4 ? dp : 0.125 * dp, side = trial % 4 < 2 ? 1.0 : -1.0;
        double s = (trial % 2 ? -eps : eps) * Y * (trial < 4 ? 1.0 : sqrt(0.125)), y[GD_MAX_STATE], amp, asym;
        for (int i = 0; i < at.n; i++)
            y[i] = at.y[0][i] + s * v[i];
        if (doubled_at(model_at, ctx, o, po, b->p + side * dpt, y, at.y[0], out, &amp, &asym, &e1) != GD_OK)
            continue;
        if (2 * amp <= 1e3 * tol) { /* the orbit of nper periods again */
            snprintf(why, sizeof why, "the orbit of %d mesh period%s again", po->nper, po->nper > 1 ? "s" : "");
            continue;
        }
        if (asym > 2.0 * amp) { /* not about the orbit that doubled: both halves within 3 amp of it */
            snprintf(why, sizeof why, "an orbit of %d mesh periods not about the one that doubled (its halves' mean "
                     "%.3g from it, amplitude %.3g)", 2 * po->nper, asym, amp);
            continue;
        }
        /* born at the doubling: the amplitude as the square root of the distance to it */
        gd_po q;
        double amp4 = 0, asym4;
        for (int g = 0; g < 2 && !(amp4 > 1e3 * tol); g++) { /* from the orbit found, then from half its offset */
            for (int i = 0; i < at.n; i++)
                y[i] = g ? at.y[0][i] + 0.5 * (out->y[0][i] - at.y[0][i]) : out->y[0][i];
            if (doubled_at(model_at, ctx, o, po, b->p + 0.25 * side * dpt, y, at.y[0], &q, &amp4, &asym4, &e1) != GD_OK)
                amp4 = 0;
        }
        if (!(amp4 > 0.35 * amp && amp4 < 0.7 * amp)) {
            snprintf(why, sizeof why, "an orbit of %d mesh periods whose amplitude %.3g at %.9g is %.3g at a quarter "
                     "of the distance (not half: not born at the doubling)", 2 * po->nper, amp, b->p + side * dpt, amp4);
            continue;
        }
        out->p = b->p + side * dpt;
        return GD_OK;
    }
    return gd_error_set(err, GD_ERR_SOLVER,
                        "no orbit of %d mesh periods born at the period doubling at p = %.9g found at +- %.3g or "
                        "an eighth of it%s%s",
                        2 * po->nper, b->p, dp, why[0] ? ": " : e1.msg[0] ? ": " : "", why[0] ? why : e1.msg);
}
