/* The tangent vectors integrated with the trajectory. For Lyapunov exponents: their
 * reproducible initial directions, the QR (GSL Householder) renormalisation at every mesh
 * period with the sums of log|R_ii|, and the exponents from those sums. For a monodromy
 * matrix: vectors set by the caller and integrated without renormalisation (sim_map.c). */
#include "sim_internal.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <string.h>

/* The tangent vectors (s->k > 0) at the start of the run: the QR workspace, and the initial
 * directions after the trajectory's state in s->y. */
gd_status gd_sim_tangent_init(gd_sim *s, gd_error *err)
{
    const gd_model *m = &s->m;
    s->qr = gsl_matrix_alloc((size_t)m->n, (size_t)s->k);
    s->Q = gsl_matrix_alloc((size_t)m->n, (size_t)m->n);
    s->R = gsl_matrix_alloc((size_t)m->n, (size_t)s->k);
    s->tau = gsl_vector_alloc((size_t)s->k);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    if (!s->qr || !s->Q || !s->R || !s->tau || !rng) {
        gsl_rng_free(rng);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the tangent vectors");
    }
    /* reproducible, generic initial directions: seeded uniform, then orthonormalised */
    gsl_rng_set(rng, 20261121UL);
    double *yy = NV_DATA_S(s->y);
    for (int v = 1; v <= s->k; v++)
        for (int i = 0; i < m->n; i++)
            yy[v * m->n + i] = 2.0 * gsl_rng_uniform(rng) - 1.0;
    gsl_rng_free(rng);
    return gd_sim_orthonormalise(s, 0, err);
}

/* QR (GSL Householder) of the tangent vectors: replace them by Q's first k columns and,
 * when accumulate, add log|R_ii| to the sums. */
gd_status gd_sim_orthonormalise(gd_sim *s, int accumulate, gd_error *err)
{
    const int n = s->m.n, k = s->k;
    double *y = NV_DATA_S(s->y);
    for (int v = 0; v < k; v++)
        for (int i = 0; i < n; i++)
            gsl_matrix_set(s->qr, (size_t)i, (size_t)v, y[(v + 1) * n + i]);
    int rc = gsl_linalg_QR_decomp(s->qr, s->tau);
    if (rc == GSL_SUCCESS)
        rc = gsl_linalg_QR_unpack(s->qr, s->tau, s->Q, s->R);
    if (rc != GSL_SUCCESS)
        return gd_error_set(err, GD_ERR_GSL, "renormalising the tangent vectors: gsl_linalg_QR: %s",
                            gsl_strerror(rc));
    for (int v = 0; v < k; v++) {
        double r = gsl_matrix_get(s->R, (size_t)v, (size_t)v);
        if (!(fabs(r) > 0) || !isfinite(r))
            return gd_error_set(err, GD_ERR_SOLVER, "tangent vector %d collapsed or diverged (|R| = %g)", v + 1, r);
        if (accumulate)
            s->lyap_sum[v] += log(fabs(r));
        double sg = r < 0 ? -1.0 : 1.0; /* keep orientation: Q R with a positive diagonal */
        for (int i = 0; i < n; i++)
            y[(v + 1) * n + i] = sg * gsl_matrix_get(s->Q, (size_t)i, (size_t)v);
    }
    return GD_OK;
}

GD_API void gd_sim_lyapunov_start(gd_sim *s)
{
    memset(s->lyap_sum, 0, sizeof s->lyap_sum);
    s->lyap_t0 = sim_abs_time(s, s->t);
}

GD_API int gd_sim_lyapunov(const gd_sim *s, double *exponents, double *elapsed)
{
    double T = sim_abs_time(s, s->t) - s->lyap_t0;
    if (elapsed)
        *elapsed = T;
    for (int v = 0; v < s->k; v++)
        exponents[v] = T > 0 ? s->lyap_sum[v] / T : NAN;
    return s->k;
}


GD_API gd_status gd_sim_set_tangent(gd_sim *s, const double *V, gd_error *err)
{
    const int n = s->m.n, k = s->k;
    double *y = NV_DATA_S(s->y);
    for (int v = 0; v < k; v++)
        for (int i = 0; i < n; i++)
            y[(v + 1) * n + i] = V[i * k + v];
    s->tangent_free = 1;
    return gd_sim_reset_at(s, s->t, err);
}

GD_API void gd_sim_get_tangent(const gd_sim *s, double *V)
{
    const int n = s->m.n, k = s->k;
    const double *y = NV_DATA_S(s->y);
    for (int v = 0; v < k; v++)
        for (int i = 0; i < n; i++)
            V[i * k + v] = y[(v + 1) * n + i];
}
