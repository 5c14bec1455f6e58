/* Branch switching at a period doubling (docs/continuation.md section 3): the orbit of twice the
 * period, born where a real Floquet multiplier passes -1, found by shooting from the bifurcation's
 * orbit moved along that multiplier's eigenvector (Seydel 2010, on branching at period doubling).
 * The eigenvector is GSL's (gsl_eigen_nonsymmv). */
#include "geardyn/gd_periodic.h"

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <math.h>
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
    gd_po_opts p2 = *po;
    p2.nper = 2 * po->nper;
    gd_error e1 = {0};
    for (int trial = 0; trial < 4; trial++) {
        double p = b->p + (trial < 2 ? dp : -dp), s = trial % 2 ? -eps : eps;
        double y[GD_MAX_STATE], yn[GD_MAX_STATE];
        for (int i = 0; i < at.n; i++)
            y[i] = at.y[0][i] + s * v[i];
        if (model_at(p, &m, ctx, &e1) != GD_OK || gd_po_solve(&m, o, &p2, y, out, &e1) != GD_OK ||
            gd_sim_period_map(&m, o, out->y[0], po->nper, yn, NULL, NULL, &e1) != GD_OK)
            continue;
        double d = 0;
        for (int i = 0; i < at.n; i++)
            d = fmax(d, fabs(yn[i] - out->y[0][i]));
        if (d > 1e3 * po->tol) { /* not the period-nper orbit again */
            out->p = p;
            return GD_OK;
        }
    }
    return gd_error_set(err, GD_ERR_SOLVER,
                        "no orbit of %d mesh periods found at p = %.9g +- %.3g from the period doubling at %.9g%s%s",
                        p2.nper, b->p, dp, b->p, e1.msg[0] ? ": " : "", e1.msg);
}
