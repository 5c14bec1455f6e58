/* The Newton solves of the contact analysis: GSL's multiroot hybridsj (Powell's hybrid method with
 * an analytic Jacobian and scaled variables), every return code checked. */
#include "tca_internal.h"

#include <gsl/gsl_errno.h>
#include <math.h>

typedef struct nr_ctx {
    tca_fdf_fn fn;
    void *p;
    int n;
} nr_ctx;

static int all_finite(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

static int nr_f(const gsl_vector *x, void *params, gsl_vector *f)
{
    nr_ctx *c = params;
    double J[TCA_MAX_N * TCA_MAX_N];
    if (c->fn(x->data, c->p, f->data, J) != 0 || !all_finite(f->data, c->n))
        return GSL_EBADFUNC;
    return GSL_SUCCESS;
}

static int nr_df(const gsl_vector *x, void *params, gsl_matrix *J)
{
    nr_ctx *c = params;
    double f[TCA_MAX_N], Jd[TCA_MAX_N * TCA_MAX_N];
    if (c->fn(x->data, c->p, f, Jd) != 0 || !all_finite(Jd, c->n * c->n))
        return GSL_EBADFUNC;
    for (int i = 0; i < c->n; i++)
        for (int j = 0; j < c->n; j++)
            gsl_matrix_set(J, i, j, Jd[i * c->n + j]);
    return GSL_SUCCESS;
}

static int nr_fdf(const gsl_vector *x, void *params, gsl_vector *f, gsl_matrix *J)
{
    nr_ctx *c = params;
    double Jd[TCA_MAX_N * TCA_MAX_N];
    if (c->fn(x->data, c->p, f->data, Jd) != 0 || !all_finite(f->data, c->n) || !all_finite(Jd, c->n * c->n))
        return GSL_EBADFUNC;
    for (int i = 0; i < c->n; i++)
        for (int j = 0; j < c->n; j++)
            gsl_matrix_set(J, i, j, Jd[i * c->n + j]);
    return GSL_SUCCESS;
}

gd_status tca_newton(gd_tca *t, int n, tca_fdf_fn fn, void *p, double *x, double xtol, int maxit, int *conv,
                     int *iters, gd_error *err)
{
    *conv = 0;
    *iters = 0;
    if (n < 1 || n > TCA_MAX_N)
        return gd_error_set(err, GD_ERR_INTERNAL, "tca_newton: %d unknowns", n);
    /* the start must be a valid point: hybridsj's set does not check the function's status */
    double f0[TCA_MAX_N], J0[TCA_MAX_N * TCA_MAX_N];
    if (fn(x, p, f0, J0) != 0 || !all_finite(f0, n) || !all_finite(J0, n * n))
        return GD_OK;
    nr_ctx ctx = {fn, p, n};
    gsl_multiroot_function_fdf F = {nr_f, nr_df, nr_fdf, (size_t)n, &ctx};
    gsl_multiroot_fdfsolver *s = t->solver[n];
    gsl_vector *xv = t->xv[n];
    for (int i = 0; i < n; i++)
        gsl_vector_set(xv, i, x[i]);
    int rc = gsl_multiroot_fdfsolver_set(s, &F, xv);
    if (rc != GSL_SUCCESS)
        return gd_error_set(err, GD_ERR_GSL, "gsl_multiroot_fdfsolver_set (hybridsj, %d unknowns): %s", n,
                            gsl_strerror(rc));
    int it = 0;
    while (it < maxit) {
        it++;
        rc = gsl_multiroot_fdfsolver_iterate(s);
        if (rc == GSL_ENOPROG || rc == GSL_ENOPROGJ || rc == GSL_EBADFUNC)
            break; /* no further progress from here: judged by the residual below */
        if (rc != GSL_SUCCESS) {
            t->iterations += it;
            return gd_error_set(err, GD_ERR_GSL, "gsl_multiroot_fdfsolver_iterate (hybridsj, %d unknowns): %s", n,
                                gsl_strerror(rc));
        }
        const gsl_vector *dx = gsl_multiroot_fdfsolver_dx(s);
        if (!all_finite(gsl_multiroot_fdfsolver_root(s)->data, n))
            break;
        double dmax = 0;
        for (int i = 0; i < n; i++)
            dmax = fmax(dmax, fabs(gsl_vector_get(dx, i)));
        if (dmax <= xtol)
            break;
    }
    *iters = it;
    t->iterations += it;
    /* converged when every equation is within 10 xtol of its zero set, measured along its own
     * gradient (|f_i| / |row i of J|, in the units of the unknowns): a step that merely stalls
     * (the trust region shrinking at a minimum of |f| that is not a root) is not a root */
    const gsl_vector *xs = gsl_multiroot_fdfsolver_root(s);
    double xr[TCA_MAX_N], fr[TCA_MAX_N], Jr[TCA_MAX_N * TCA_MAX_N];
    for (int i = 0; i < n; i++)
        xr[i] = gsl_vector_get(xs, i);
    if (!all_finite(xr, n) || fn(xr, p, fr, Jr) != 0 || !all_finite(fr, n) || !all_finite(Jr, n * n))
        return GD_OK;
    for (int i = 0; i < n; i++) {
        double rn = 0;
        for (int j = 0; j < n; j++)
            rn += Jr[i * n + j] * Jr[i * n + j];
        rn = sqrt(rn);
        if (!(fabs(fr[i]) <= 10 * xtol * rn))
            return GD_OK;
    }
    *conv = 1;
    for (int i = 0; i < n; i++)
        x[i] = xr[i];
    return GD_OK;
}
