/* Linear stability of a fixed explicit Runge-Kutta step on a model (gd_sim.h).
 *
 * A Runge-Kutta method with Butcher table (A, b) applied to y' = lambda y multiplies y by the
 * stability function R(z) = 1 + z b^T (I - z A)^-1 1, z = h lambda, every step (Hairer & Wanner,
 * Solving Ordinary Differential Equations II, 2nd ed., Springer 1996, section IV.2); for an
 * explicit table A is strictly lower triangular and (I - z A)^-1 1 is a forward substitution. A
 * linear system y' = J y is integrated stably by a fixed step h exactly when |R(h lambda)| <= 1 for
 * every eigenvalue lambda of J. Here J is the model's Jacobian in the held contact modes at a
 * state, at eight phases of the mesh period (the mesh stiffness varies along it); its eigenvalues
 * come from GSL's nonsymmetric eigensolver. A step outside the region on a mode amplifies that
 * mode by |R| per step: round-off grows until the nonlinearity of the contacts bounds it, and the
 * run's results are meaningless (the classical RK4's bound on the imaginary axis is
 * |z| = 2 sqrt 2, so on an undamped mode of angular frequency w the step must satisfy h w <= 2.83).
 * The tables are the ones gd_sim_create integrates with (erk_table.c). */
#include "geardyn/gd_sim.h"
#include "erk_table.h"

#include "../core/gsl_quiet.h"

#include <complex.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#define PHASES 8
#define UNSTABLE (1.0 + 1e-9) /* |R| above this amplifies (a zero eigenvalue gives 1 to rounding) */

/* |R(z)| of the explicit table B. */
static double amplification(ARKodeButcherTable B, double complex z)
{
    double complex k[32], sum = 0;
    int s = B->stages < 32 ? B->stages : 32;
    for (int i = 0; i < s; i++) {
        double complex acc = 1.0;
        for (int j = 0; j < i; j++)
            acc += z * B->A[i][j] * k[j];
        k[i] = acc;
        sum += B->b[i] * k[i];
    }
    return cabs(1.0 + z * sum);
}

/* The largest |R(h lambda)| over the eigenvalues ev[0..n), and which one. */
static double worst(ARKodeButcherTable B, const double complex *ev, int n, double h, int *which)
{
    double a = 0;
    *which = -1;
    for (int i = 0; i < n; i++) {
        double r = amplification(B, h * ev[i]);
        if (!(r <= a)) {
            a = r;
            *which = i;
        }
    }
    return a;
}

GD_API gd_status gd_sim_step_stability(const gd_model *m, const gd_solver_opts *o, const double *y, const gd_modes *md,
                                       gd_step_stability *out, gd_error *err)
{
    memset(out, 0, sizeof *out);
    out->amplification = out->lambda_re = out->lambda_im = out->freq_hz = out->damping_ratio = NAN;
    out->h = o->steps_per_period > 0 ? m->period / o->steps_per_period : NAN;
    int fixed = o->method == GD_METHOD_RK4 || (o->method == GD_METHOD_ERK && o->fixed_step);
    if (!fixed || !(out->h > 0) || (m->custom && !m->custom->jacobian))
        return GD_OK; /* an adaptive or implicit step, or no Jacobian: not applicable */
    ARKodeButcherTable B = NULL;
    if (o->method == GD_METHOD_RK4) {
        B = gd_erk_classical_rk4();
    } else {
        const char *name = o->table[0] ? o->table : gd_erk_default_table(o->order);
        if (!name)
            return gd_error_set(err, GD_ERR_INPUT, "no explicit Runge-Kutta table of order %d", o->order);
        B = gd_erk_load(name);
    }
    if (!B)
        return gd_error_set(err, GD_ERR_NOMEM, "Butcher table allocation failed");
    gd_gsl_quiet();
    int n = m->n;
    gsl_matrix *J = gsl_matrix_alloc((size_t)n, (size_t)n);
    gsl_vector_complex *ev = gsl_vector_complex_alloc((size_t)n);
    gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc((size_t)n);
    double complex lam[PHASES * GD_MAX_STATE];
    int nl = 0;
    gd_status st = GD_OK;
    if (!J || !ev || !w) {
        st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for the eigenvalues of the Jacobian");
        goto done;
    }
    for (int k = 0; k < PHASES; k++) {
        double Jd[GD_MAX_STATE * GD_MAX_STATE];
        gd_model_jacobian(m, m->period * k / PHASES, y, Jd, md);
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++)
                gsl_matrix_set(J, (size_t)i, (size_t)j, Jd[i * n + j]);
        int e = gsl_eigen_nonsymm(J, ev, w);
        if (e != GSL_SUCCESS) {
            st = gd_error_set(err, GD_ERR_GSL, "the eigenvalues of the Jacobian: gsl_eigen_nonsymm: %s",
                              gsl_strerror(e));
            goto done;
        }
        for (int i = 0; i < n; i++) {
            gsl_complex z = gsl_vector_complex_get(ev, (size_t)i);
            lam[nl++] = GSL_REAL(z) + I * GSL_IMAG(z);
        }
    }
    int which;
    out->amplification = worst(B, lam, nl, out->h, &which);
    if (which >= 0) {
        double complex l = lam[which];
        out->lambda_re = creal(l);
        out->lambda_im = fabs(cimag(l));
        out->freq_hz = fabs(cimag(l)) * m->omega_n / (2.0 * M_PI);
        out->damping_ratio = cabs(l) > 0 ? -creal(l) / cabs(l) : NAN;
    }
    /* the fewest steps per mesh period stable on every eigenvalue: doubled to a stable count, then
     * bisected (the region along each eigenvalue's ray is an interval from the origin for the
     * tables geardyn uses) */
    long hi = 1;
    while (hi < (1L << 24) && worst(B, lam, nl, m->period / (double)hi, &which) > UNSTABLE)
        hi *= 2;
    long lo = hi / 2;
    while (hi - lo > 1) {
        long mid = (lo + hi) / 2;
        if (worst(B, lam, nl, m->period / (double)mid, &which) > UNSTABLE)
            lo = mid;
        else
            hi = mid;
    }
    out->min_steps_per_period = hi;
    out->unstable = out->amplification > UNSTABLE;
done:
    gsl_eigen_nonsymm_free(w);
    gsl_vector_complex_free(ev);
    gsl_matrix_free(J);
    ARKodeButcherTable_Free(B);
    return st;
}
