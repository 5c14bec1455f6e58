/* The shooting system of a periodic orbit (shooting.h): the segment maps and their monodromies
 * (gd_sim_period_map), the derivative in the parameter by a central difference, the Newton
 * corrector and the tangent, both solving the (bordered) Jacobian with GSL's LU decomposition.
 * docs/continuation.md section 2 derives the system. */
#include "shooting.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

gd_status gd_shoot_init(gd_shoot *sh, gd_model_at_fn model_at, void *ctx, const gd_solver_opts *o, int n,
                        const gd_po_opts *po, gd_error *err)
{
    memset(sh, 0, sizeof *sh);
    if (po->nper < 1 || po->nper > GD_PO_MAX_PERIODS)
        return gd_error_set(err, GD_ERR_INPUT, "an orbit of %d mesh periods (valid: 1 to %d)", po->nper,
                            GD_PO_MAX_PERIODS);
    sh->model_at = model_at;
    sh->ctx = ctx;
    sh->o = *o;
    sh->n = n;
    sh->nseg = po->multiple ? po->nper : 1;
    sh->per_seg = po->nper / sh->nseg;
    sh->N = sh->nseg * n;
    /* the central difference's step: about the cube root of the integration's relative error, which
     * balances the truncation error h^2 against the noise of the maps over h */
    sh->dp_rel = po->dp_rel > 0 ? po->dp_rel : cbrt(o->rtol);
    for (int i = 0; i <= sh->N; i++)
        sh->w[i] = 1.0;
    sh->Mk = calloc((size_t)sh->nseg * (size_t)(n * n), sizeof(double));
    if (!sh->Mk)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the shooting system");
    return GD_OK;
}

void gd_shoot_free(gd_shoot *sh)
{
    free(sh->Mk);
    sh->Mk = NULL;
}

/* the end states of every segment at parameter p, without monodromies, into y1 (N values) */
static gd_status maps_plain(gd_shoot *sh, const double *u, double p, double *y1, gd_error *err)
{
    gd_model m;
    gd_status st = sh->model_at(p, &m, sh->ctx, err);
    for (int k = 0; k < sh->nseg && st == GD_OK; k++) {
        st = gd_sim_period_map(&m, &sh->o, u + k * sh->n, sh->per_seg, y1 + k * sh->n, NULL, NULL, err);
    }
    return st;
}

gd_status gd_shoot_eval(gd_shoot *sh, const double *u, int with_p, gd_error *err)
{
    const int n = sh->n, N = sh->N;
    sh->jac_ok = 0;
    double p = u[N];
    gd_model m;
    gd_status st = sh->model_at(p, &m, sh->ctx, err);
    if (st != GD_OK)
        return st;
    memset(sh->events, 0, sizeof sh->events);
    for (int k = 0; k < sh->nseg; k++) {
        double y1[GD_MAX_STATE];
        gd_sim_stats ss;
        st = gd_sim_period_map(&m, &sh->o, u + k * n, sh->per_seg, y1, sh->Mk + (size_t)k * n * n, &ss, err);
        if (st != GD_OK)
            return st;
        const double *next = u + ((k + 1) % sh->nseg) * n;
        for (int i = 0; i < n; i++)
            sh->r[k * n + i] = y1[i] - next[i];
        for (int c = 0; c < m.nclear; c++)
            sh->events[c] += ss.events_by_clearance[c];
    }
    if (!with_p)
        return GD_OK;
    double yp[GD_PO_MAX_PERIODS * GD_MAX_STATE], ym[GD_PO_MAX_PERIODS * GD_MAX_STATE];
    double dp = sh->dp_rel * (1.0 + fabs(p));
    st = maps_plain(sh, u, p + dp, yp, err);
    if (st == GD_OK)
        st = maps_plain(sh, u, p - dp, ym, err);
    if (st != GD_OK)
        return gd_error_prefix(err, "the derivative in the parameter at p = %.9g +- %.3g", p, dp);
    for (int i = 0; i < N; i++)
        sh->rp[i] = (yp[i] - ym[i]) / (2.0 * dp);
    sh->jac_ok = 1;
    return GD_OK;
}

/* The Jacobian of the last evaluation into J (N x N, or N + 1 square bordered by dr/dp and v):
 * block row k has M_k in block column k and -I in block column k + 1 (cyclically). */
static void assemble(const gd_shoot *sh, const double *v, gsl_matrix *J)
{
    const int n = sh->n, N = sh->N;
    gsl_matrix_set_zero(J);
    for (int k = 0; k < sh->nseg; k++) {
        const double *M = sh->Mk + (size_t)k * n * n;
        int kn = ((k + 1) % sh->nseg) * n;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++)
                gsl_matrix_set(J, (size_t)(k * n + i), (size_t)(k * n + j), M[i * n + j]);
            *gsl_matrix_ptr(J, (size_t)(k * n + i), (size_t)(kn + i)) -= 1.0;
        }
    }
    if (!v)
        return;
    for (int i = 0; i < N; i++)
        gsl_matrix_set(J, (size_t)i, (size_t)N, sh->rp[i]);
    for (int j = 0; j <= N; j++)
        gsl_matrix_set(J, (size_t)N, (size_t)j, v[j]);
}

/* x = J^-1 b for the Jacobian of the last evaluation (bordered by v when given), by GSL's LU;
 * *dsign, *dlog (may be NULL): the sign and log-modulus of det J */
static gd_status solve(const gd_shoot *sh, const double *v, const double *b, double *x, int *dsign, double *dlog,
                       gd_error *err)
{
    size_t dim = (size_t)sh->N + (v ? 1 : 0);
    gsl_matrix *J = gsl_matrix_alloc(dim, dim);
    gsl_permutation *perm = gsl_permutation_alloc(dim);
    gsl_vector *bv = gsl_vector_alloc(dim), *xv = gsl_vector_alloc(dim);
    gd_status st = GD_OK;
    if (!J || !perm || !bv || !xv) {
        st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for the shooting Jacobian");
        goto done;
    }
    assemble(sh, v, J);
    for (size_t i = 0; i < dim; i++)
        gsl_vector_set(bv, i, b[i]);
    int signum = 0;
    int rc = gsl_linalg_LU_decomp(J, perm, &signum);
    if (rc == GSL_SUCCESS)
        rc = gsl_linalg_LU_solve(J, perm, bv, xv);
    if (rc != GSL_SUCCESS) {
        st = gd_error_set(err, GD_ERR_GSL, "the shooting Jacobian: gsl_linalg_LU: %s", gsl_strerror(rc));
        goto done;
    }
    for (size_t i = 0; i < dim; i++)
        x[i] = gsl_vector_get(xv, i);
    if (dsign)
        *dsign = gsl_linalg_LU_sgndet(J, signum);
    if (dlog)
        *dlog = gsl_linalg_LU_lndet(J);
done:
    gsl_matrix_free(J);
    gsl_permutation_free(perm);
    gsl_vector_free(bv);
    gsl_vector_free(xv);
    return st;
}

/* The chord iteration (gd_shoot_correct): the Jacobian of the last evaluation, the residual of
 * plain maps, at most CHORD_MAX iterations, each to reduce the residual's max-norm by CHORD_RATE at
 * least. GD_OK when the residual fell below tol; otherwise u is the iterate of smallest residual
 * when that is below the residual at the start (what the chord gained, kept for Newton), else u as
 * it came in. */
#define CHORD_MAX 8
#define CHORD_RATE 0.5
static gd_status chord(gd_shoot *sh, double *u, const double *v, const double *u_pred, double tol, gd_error *err)
{
    const int N = sh->N, n = sh->n;
    double best[GD_SHOOT_UMAX], b[GD_SHOOT_UMAX], dx[GD_SHOOT_UMAX], y1[GD_PO_MAX_PERIODS * GD_MAX_STATE];
    memcpy(best, u, sizeof(double) * (size_t)(N + 1));
    double last = INFINITY, gtol = tol * sqrt(sh->w[0]);
    gd_error e1 = {0};
    for (int it = 0; it <= CHORD_MAX; it++) {
        gd_status st = maps_plain(sh, u, u[N], y1, &e1);
        if (st == GD_ERR_NOMEM)
            return gd_error_set(err, st, "%s", e1.msg);
        double rnorm = 0, g = 0;
        for (int k = 0; k < sh->nseg && st == GD_OK; k++)
            for (int i = 0; i < n; i++) {
                b[k * n + i] = -(y1[k * n + i] - u[((k + 1) % sh->nseg) * n + i]);
                rnorm = fmax(rnorm, fabs(b[k * n + i]));
            }
        for (int i = 0; i <= N; i++)
            g += v[i] * (u[i] - u_pred[i]);
        if (st == GD_OK && rnorm < tol && fabs(g) < gtol)
            return GD_OK;
        if (st != GD_OK || !(rnorm < CHORD_RATE * last) || it == CHORD_MAX) {
            if (st == GD_OK && rnorm < last) /* the last iterate still reduced the residual */
                memcpy(best, u, sizeof(double) * (size_t)(N + 1));
            break;
        }
        if (it > 0)
            memcpy(best, u, sizeof(double) * (size_t)(N + 1));
        last = rnorm;
        b[N] = -g;
        if (solve(sh, v, b, dx, NULL, NULL, &e1) != GD_OK)
            break;
        for (int i = 0; i <= N; i++)
            u[i] += dx[i];
        sh->chord_iterations++;
    }
    memcpy(u, best, sizeof(double) * (size_t)(N + 1));
    return GD_ERR_SOLVER;
}

gd_status gd_shoot_correct(gd_shoot *sh, double *u, const double *v, const double *u_pred, double tol, int max_iter,
                           int *iters, gd_error *err)
{
    if (sh->chord && sh->jac_ok && v) {
        gd_status st = chord(sh, u, v, u_pred, tol, err);
        if (st == GD_ERR_NOMEM)
            return st;
    }
    const int N = sh->N;
    double b[GD_SHOOT_UMAX], dx[GD_SHOOT_UMAX];
    double rnorm = INFINITY;
    for (int it = 0;; it++) {
        *iters = it;
        gd_status st = gd_shoot_eval(sh, u, v != NULL, err);
        if (st != GD_OK)
            return st;
        rnorm = 0;
        for (int i = 0; i < N; i++)
            rnorm = fmax(rnorm, fabs(sh->r[i]));
        double g = 0;
        if (v)
            for (int i = 0; i <= N; i++)
                g += v[i] * (u[i] - u_pred[i]);
        if (!isfinite(rnorm) || !isfinite(g))
            return gd_error_set(err, GD_ERR_SOLVER, "Newton shooting: the residual is not finite");
        if (rnorm < tol && fabs(g) < tol * sqrt(sh->w[0]))
            return GD_OK;
        if (it == max_iter)
            break;
        for (int i = 0; i < N; i++)
            b[i] = -sh->r[i];
        b[N] = -g;
        st = solve(sh, v, b, dx, NULL, NULL, err);
        if (st != GD_OK)
            return st;
        for (int i = 0; i < N + (v ? 1 : 0); i++)
            u[i] += dx[i];
    }
    return gd_error_set(err, GD_ERR_SOLVER,
                        "Newton shooting did not converge: residual %.3g after %d iterations (tol %.3g)", rnorm,
                        max_iter, tol);
}

gd_status gd_shoot_tangent(gd_shoot *sh, const double *v, double *t, gd_error *err)
{
    const int N = sh->N;
    double b[GD_SHOOT_UMAX] = {0};
    b[N] = 1.0;
    int dsign = 0;
    double dlog = 0;
    gd_status st = solve(sh, v, b, t, &dsign, &dlog, err);
    if (st != GD_OK)
        return st;
    double wnorm = 0, enorm = 0, dot = 0;
    for (int i = 0; i <= N; i++) {
        wnorm += sh->w[i] * t[i] * t[i];
        enorm += t[i] * t[i];
        dot += t[i] * v[i];
    }
    /* det [J; v^T] = (v . e) det [J; e^T] for e the Euclidean unit tangent (v less its part along e
     * lies in the rows of J): D = det [J; e^T], whose sign changes at a simple branch point and not
     * at a fold (Keller 1977), whatever the bordering row */
    sh->bp_sign = dsign * (dot < 0 ? -1 : 1);
    sh->bp_log = dlog - log(fabs(dot) / sqrt(enorm));
    double norm = sqrt(wnorm) * (dot < 0 ? -1.0 : 1.0);
    for (int i = 0; i <= N; i++)
        t[i] /= norm;
    return GD_OK;
}

double gd_po_state_scale(const double *y, int n)
{
    double Y = 1.0;
    for (int i = 0; i < n; i++)
        Y = fmax(Y, fabs(y[i]));
    return Y;
}

double gd_po_tol_derived(const gd_solver_opts *o, double Y)
{
    return o->rtol * Y + o->atol;
}

gd_status gd_shoot_orbit(const gd_shoot *sh, const double *u, gd_po *po, gd_error *err)
{
    const int n = sh->n;
    memset(po, 0, sizeof *po);
    po->n = n;
    po->nseg = sh->nseg;
    po->nper = sh->nseg * sh->per_seg;
    po->p = u[sh->N];
    for (int k = 0; k < sh->nseg; k++)
        memcpy(po->y[k], u + k * n, sizeof(double) * (size_t)n);
    for (int i = 0; i < sh->N; i++)
        po->residual = fmax(po->residual, fabs(sh->r[i]));
    memcpy(po->events, sh->events, sizeof po->events);
    /* the whole orbit's monodromy M_{nseg-1} ... M_1 M_0 and its multipliers, from the segments */
    gd_status st = gd_floquet_segments(sh->Mk, sh->nseg, n, po->M, po->mu_re, po->mu_im, err);
    if (st != GD_OK)
        return st;
    po->mu_max = hypot(po->mu_re[0], po->mu_im[0]);
    po->stable = po->mu_max < 1.0;
    return GD_OK;
}
