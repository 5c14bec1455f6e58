/* A periodic orbit at a fixed parameter: Newton shooting from a guess (shooting.c), the Floquet
 * multipliers by GSL's nonsymmetric eigensolver, and the model at a parameter value (a mesh
 * frequency, or a case key with the model built again). */
#include "shooting.h"
#include "geardyn/gd_scene.h"

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

GD_API void gd_po_opts_default(gd_po_opts *po)
{
    memset(po, 0, sizeof *po);
    po->nper = 1;
    po->multiple = 1;
    po->tol = 1e-9;
    po->max_iter = 12;
    po->dp_rel = 1e-6;
}

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

GD_API gd_status gd_floquet(const double *M, int n, double *mu_re, double *mu_im, gd_error *err)
{
    if (n < 1 || n > GD_MAX_STATE)
        return gd_error_set(err, GD_ERR_INPUT, "a %d x %d monodromy matrix (valid: 1 to %d)", n, n, GD_MAX_STATE);
    gsl_matrix *A = gsl_matrix_alloc((size_t)n, (size_t)n);
    gsl_vector_complex *ev = gsl_vector_complex_alloc((size_t)n);
    gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc((size_t)n);
    gd_status st = GD_OK;
    if (!A || !ev || !w) {
        st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for the Floquet multipliers");
        goto done;
    }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            gsl_matrix_set(A, (size_t)i, (size_t)j, M[i * n + j]);
    gsl_eigen_nonsymm_params(0, 1, w); /* balance: the monodromy mixes positions and velocities */
    int rc = gsl_eigen_nonsymm(A, ev, w);
    if (rc != GSL_SUCCESS) {
        st = gd_error_set(err, GD_ERR_GSL, "the Floquet multipliers: gsl_eigen_nonsymm: %s", gsl_strerror(rc));
        goto done;
    }
    mu_pair mu[GD_MAX_STATE];
    for (int i = 0; i < n; i++) {
        gsl_complex z = gsl_vector_complex_get(ev, (size_t)i);
        mu[i].re = GSL_REAL(z);
        mu[i].im = GSL_IMAG(z);
    }
    qsort(mu, (size_t)n, sizeof mu[0], by_modulus);
    for (int i = 0; i < n; i++) {
        mu_re[i] = mu[i].re;
        mu_im[i] = mu[i].im;
    }
done:
    gsl_eigen_nonsymm_free(w);
    gsl_vector_complex_free(ev);
    gsl_matrix_free(A);
    return st;
}

/* the model of gd_po_solve: the one given, whatever p */
static gd_status model_fixed(double p, gd_model *m, void *ctx, gd_error *err)
{
    (void)p;
    (void)err;
    *m = *(const gd_model *)ctx;
    return GD_OK;
}

GD_API gd_status gd_po_solve(const gd_model *m, const gd_solver_opts *o, const gd_po_opts *po, const double *y0,
                             gd_po *orbit, gd_error *err)
{
    gd_shoot sh;
    gd_status st = gd_shoot_init(&sh, model_fixed, (void *)m, o, m->n, po, err);
    if (st != GD_OK)
        return st;
    double u[GD_PO_MAX_PERIODS * GD_MAX_STATE + 1];
    memcpy(u, y0, sizeof(double) * (size_t)m->n);
    for (int k = 1; k < sh.nseg && st == GD_OK; k++) /* the other segments start on the images of y0 */
        st = gd_sim_period_map(m, o, u + (k - 1) * m->n, sh.per_seg, u + k * m->n, NULL, NULL, err);
    u[sh.N] = m->Omega;
    int iters = 0;
    if (st == GD_OK)
        st = gd_shoot_correct(&sh, u, NULL, NULL, po->tol, po->max_iter, &iters, err);
    if (st == GD_OK)
        st = gd_shoot_orbit(&sh, u, orbit, err);
    if (st == GD_OK)
        orbit->iterations = iters;
    gd_shoot_free(&sh);
    return st;
}

GD_API gd_status gd_model_at_mesh_frequency(double Omega, gd_model *m, void *ctx, gd_error *err)
{
    const gd_model *base = ctx;
    if (!(Omega > 0) || !isfinite(Omega))
        return gd_error_set(err, GD_ERR_INPUT, "mesh frequency Omega = %g (valid: above 0)", Omega);
    for (int j = 0; j < base->nmesh; j++)
        if (base->mesh[j].nimp > 0)
            return gd_error_set(err, GD_ERR_INPUT,
                                "the mesh-in impact of mesh %d lasts a fixed time, so its phase width depends on the "
                                "speed: a model of another mesh frequency must be built from the case", j);
    *m = *base;
    m->Omega = Omega;
    m->period = 2.0 * M_PI / Omega;
    m->mesh_freq_hz = Omega * m->omega_n / (2.0 * M_PI);
    return GD_OK;
}

GD_API gd_status gd_model_at_case_key(double p, gd_model *m, void *ctx, gd_error *err)
{
    const gd_case_param *a = ctx;
    gd_status st = gd_case_set_number(a->c, a->key, a->scale * p, err);
    /* resolved as gd_case_resolve resolves a response: the analysis's own keys do not change */
    if (st == GD_OK)
        st = gd_case_check(a->c, err);
    if (st == GD_OK)
        st = gd_scene_resolve(a->c, err);
    if (st == GD_OK)
        st = gd_model_build(a->c, m, err);
    return st == GD_OK ? GD_OK : gd_error_prefix(err, "the model at %s = %.9g", a->key, a->scale * p);
}
