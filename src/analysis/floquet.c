/* Floquet multipliers: the eigenvalues of a monodromy matrix (gd_floquet, GSL's nonsymmetric
 * eigensolver), and those of a product of segment monodromies M_{K-1} ... M_1 M_0 without forming
 * the product (gd_floquet_segments, docs/continuation.md section 2).
 *
 * The product of K segment matrices formed in floating point carries an absolute error of about
 * eps |mu_max| (eps the unit roundoff) in every eigenvalue, so the small multipliers of a strongly
 * unstable orbit are lost. The block-cyclic matrix C with M_k in block (k + 1 mod K, k) has the
 * K-th roots of the multipliers as its eigenvalues (C^K is block diagonal with the cyclic products,
 * all similar to the product): C's eigenvalues are computed by GSL's nonsymmetric eigensolver
 * (balanced), whose backward error is relative to the largest segment, not to the product, and each
 * multiplier is the mean of the K-th powers of its K roots. A periodic Schur decomposition
 * (Bojanczyk, Golub & Van Dooren 1992) would cost K n^3 instead of (K n)^3; neither GSL nor the
 * other dependencies offer one, and at the sizes of the shooting system (K n at most 320) the
 * cyclic matrix costs tens of milliseconds (docs/continuation.md section 5). */
#include "shooting.h"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct mu_pair { double re, im; } mu_pair;

/* decreasing modulus; a conjugate pair with the positive imaginary part first */
static int by_modulus(const void *a, const void *b)
{
    const mu_pair *x = a, *y = b;
    double ax = hypot(x->re, x->im), ay = hypot(y->re, y->im);
    if (ax != ay)
        return ax < ay ? 1 : -1;
    return x->im < y->im ? 1 : x->im > y->im ? -1 : 0;
}

static void sorted_out(mu_pair *mu, int n, double *mu_re, double *mu_im)
{
    qsort(mu, (size_t)n, sizeof mu[0], by_modulus);
    for (int i = 0; i < n; i++) {
        mu_re[i] = mu[i].re;
        mu_im[i] = mu[i].im;
    }
}

/* The eigenvalues of the m x m matrix A (GSL's nonsymmetric eigensolver, balanced: the monodromy
 * mixes positions and velocities) into mu. A is overwritten. */
static gd_status eigenvalues(gsl_matrix *A, mu_pair *mu, gd_error *err)
{
    const size_t m = A->size1;
    gsl_vector_complex *ev = gsl_vector_complex_alloc(m);
    gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc(m);
    gd_status st = GD_OK;
    if (!ev || !w) {
        st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for the Floquet multipliers");
        goto done;
    }
    gsl_eigen_nonsymm_params(0, 1, w);
    int rc = gsl_eigen_nonsymm(A, ev, w);
    if (rc != GSL_SUCCESS) {
        st = gd_error_set(err, GD_ERR_GSL, "the Floquet multipliers: gsl_eigen_nonsymm: %s", gsl_strerror(rc));
        goto done;
    }
    for (size_t i = 0; i < m; i++) {
        gsl_complex z = gsl_vector_complex_get(ev, i);
        mu[i].re = GSL_REAL(z);
        mu[i].im = GSL_IMAG(z);
    }
done:
    gsl_eigen_nonsymm_free(w);
    gsl_vector_complex_free(ev);
    return st;
}

GD_API gd_status gd_floquet(const double *M, int n, double *mu_re, double *mu_im, gd_error *err)
{
    if (n < 1 || n > GD_MAX_STATE)
        return gd_error_set(err, GD_ERR_INPUT, "a %d x %d monodromy matrix (valid: 1 to %d)", n, n, GD_MAX_STATE);
    gsl_matrix *A = gsl_matrix_alloc((size_t)n, (size_t)n);
    if (!A)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the Floquet multipliers");
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            gsl_matrix_set(A, (size_t)i, (size_t)j, M[i * n + j]);
    mu_pair mu[GD_MAX_STATE];
    gd_status st = eigenvalues(A, mu, err);
    gsl_matrix_free(A);
    if (st == GD_OK)
        sorted_out(mu, n, mu_re, mu_im);
    return st;
}

/* The K-th powers of the eigenvalues of C (K n of them) grouped into the n multipliers: the largest
 * power not yet taken with the K - 1 others nearest it, their mean. */
static void group_powers(const mu_pair *lam, int K, int n, mu_pair *mu)
{
    const int m = K * n;
    char taken[GD_PO_MAX_PERIODS * GD_MAX_STATE] = {0};
    for (int g = 0; g < n; g++) {
        int top = -1;
        for (int j = 0; j < m; j++)
            if (!taken[j] && (top < 0 || hypot(lam[j].re, lam[j].im) > hypot(lam[top].re, lam[top].im)))
                top = j;
        double sre = 0, sim = 0;
        for (int c = 0; c < K; c++) {
            int best = -1;
            double dbest = INFINITY;
            for (int j = 0; j < m; j++) {
                double d = hypot(lam[j].re - lam[top].re, lam[j].im - lam[top].im);
                if (!taken[j] && d < dbest)
                    best = j, dbest = d;
            }
            taken[best] = 1;
            sre += lam[best].re;
            sim += lam[best].im;
        }
        mu[g].re = sre / K;
        mu[g].im = sim / K;
        if (fabs(mu[g].im) <= 8.0 * K * DBL_EPSILON * fabs(mu[g].re)) /* a real multiplier's rounding */
            mu[g].im = 0.0;
    }
}

GD_API gd_status gd_floquet_segments(const double *Mk, int K, int n, double *M, double *mu_re, double *mu_im,
                                     gd_error *err)
{
    if (K < 1 || K > GD_PO_MAX_PERIODS || n < 1 || n > GD_MAX_STATE)
        return gd_error_set(err, GD_ERR_INPUT, "%d segments of %d x %d (valid: 1 to %d segments of at most %d)", K, n,
                            n, GD_PO_MAX_PERIODS, GD_MAX_STATE);
    /* the product, for the caller (the eigenvector of a period doubling) */
    double A[GD_MAX_STATE * GD_MAX_STATE], B[GD_MAX_STATE * GD_MAX_STATE];
    memcpy(A, Mk, sizeof(double) * (size_t)(n * n));
    for (int k = 1; k < K; k++) {
        gsl_matrix_const_view Mv = gsl_matrix_const_view_array(Mk + (size_t)k * n * n, (size_t)n, (size_t)n);
        gsl_matrix_const_view Av = gsl_matrix_const_view_array(A, (size_t)n, (size_t)n);
        gsl_matrix_view Bv = gsl_matrix_view_array(B, (size_t)n, (size_t)n);
        int rc = gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, &Mv.matrix, &Av.matrix, 0.0, &Bv.matrix);
        if (rc != GSL_SUCCESS)
            return gd_error_set(err, GD_ERR_GSL, "the orbit's monodromy: gsl_blas_dgemm: %s", gsl_strerror(rc));
        memcpy(A, B, sizeof A);
    }
    if (M)
        memcpy(M, A, sizeof(double) * (size_t)(n * n));
    if (K == 1)
        return gd_floquet(A, n, mu_re, mu_im, err);
    const size_t m = (size_t)K * (size_t)n;
    gsl_matrix *C = gsl_matrix_calloc(m, m);
    if (!C)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the cyclic matrix of the multipliers");
    for (int k = 0; k < K; k++) {
        size_t row = (size_t)((k + 1) % K) * (size_t)n, col = (size_t)k * (size_t)n;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++)
                gsl_matrix_set(C, row + (size_t)i, col + (size_t)j, Mk[(size_t)k * n * n + (size_t)(i * n + j)]);
    }
    mu_pair nu[GD_PO_MAX_PERIODS * GD_MAX_STATE], mu[GD_MAX_STATE];
    gd_status st = eigenvalues(C, nu, err);
    gsl_matrix_free(C);
    if (st != GD_OK)
        return st;
    for (size_t j = 0; j < m; j++) { /* nu^K in polar form */
        double r = pow(hypot(nu[j].re, nu[j].im), K), th = K * atan2(nu[j].im, nu[j].re);
        nu[j].re = r * cos(th);
        nu[j].im = r * sin(th);
    }
    group_powers(nu, K, n, mu);
    sorted_out(mu, n, mu_re, mu_im);
    return GD_OK;
}
