/* The loaded contact problem (Eq. 11 of the paper) as a strictly convex QP, solved by a primal
 * active-set method in the manner of Lawson & Hanson's NNLS, extended to equality constraints
 * (C. L. Lawson, R. J. Hanson, Solving Least Squares Problems, 1974, ch. 23). */
#include "contact_internal.h"
#include "../core/gsl_quiet.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct gd_contact_workspace {
    int nmax, m;
    gsl_matrix *K;           /* (k + m)^2 KKT matrix of the current free set */
    gsl_vector *rhs, *sol;
    gsl_permutation *perm;
    int *free_idx;           /* the free (loaded) set */
    unsigned char *in_free;
    double *q, *Lp;
};

GD_API gd_status gd_contact_workspace_alloc(int nmax, int m, gd_contact_workspace **out, gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    *out = NULL;
    if (nmax < 1 || m < 1 || m > GD_CONTACT_MAX_FREEDOMS)
        return gd_error_set(err, GD_ERR_INPUT, "contact workspace: %d points, %d freedoms (valid: >= 1, 1 to %d)",
                            nmax, m, GD_CONTACT_MAX_FREEDOMS);
    gd_contact_workspace *ws = calloc(1, sizeof *ws);
    if (!ws)
        return gd_error_set(err, GD_ERR_NOMEM, "contact workspace: out of memory");
    size_t N = (size_t)(nmax + m);
    ws->nmax = nmax;
    ws->m = m;
    ws->K = gsl_matrix_alloc(N, N);
    ws->rhs = gsl_vector_alloc(N);
    ws->sol = gsl_vector_alloc(N);
    ws->perm = gsl_permutation_alloc(N);
    ws->free_idx = malloc(sizeof(int) * (size_t)nmax);
    ws->in_free = malloc((size_t)nmax);
    ws->q = malloc(sizeof(double) * (size_t)nmax);
    ws->Lp = malloc(sizeof(double) * (size_t)nmax);
    if (!ws->K || !ws->rhs || !ws->sol || !ws->perm || !ws->free_idx || !ws->in_free || !ws->q || !ws->Lp) {
        gd_contact_workspace_free(ws);
        return gd_error_set(err, GD_ERR_NOMEM, "contact workspace: out of memory for %d points", nmax);
    }
    *out = ws;
    return GD_OK;
}

GD_API void gd_contact_workspace_free(gd_contact_workspace *ws)
{
    if (!ws)
        return;
    gsl_matrix_free(ws->K);
    gsl_vector_free(ws->rhs);
    gsl_vector_free(ws->sol);
    gsl_permutation_free(ws->perm);
    free(ws->free_idx);
    free(ws->in_free);
    free(ws->q);
    free(ws->Lp);
    free(ws);
}

/* Equality-constrained QP on the free set F (size k): [L_FF  -G_F; G_F^T  0] [q_F; z] = [-w_F; f].
 * Returns 0, or 1 when the system is singular (a freedom without a loaded point). */
static int solve_free(const gd_contact_problem *pb, gd_contact_workspace *ws, int k, double *z)
{
    int n = pb->n, m = pb->m;
    size_t N = (size_t)(k + m);
    gsl_matrix_view K = gsl_matrix_submatrix(ws->K, 0, 0, N, N);
    gsl_vector_view r = gsl_vector_subvector(ws->rhs, 0, N), x = gsl_vector_subvector(ws->sol, 0, N);
    gsl_permutation p = {N, ws->perm->data};
    for (int a = 0; a < k; a++) {
        int i = ws->free_idx[a];
        for (int b = 0; b < k; b++)
            gsl_matrix_set(&K.matrix, (size_t)a, (size_t)b, pb->L[(size_t)i * (size_t)n + (size_t)ws->free_idx[b]]);
        for (int c = 0; c < m; c++) {
            double g = pb->G[(size_t)i * (size_t)m + (size_t)c];
            gsl_matrix_set(&K.matrix, (size_t)a, (size_t)(k + c), -g);
            gsl_matrix_set(&K.matrix, (size_t)(k + c), (size_t)a, g);
        }
        gsl_vector_set(&r.vector, (size_t)a, -pb->w[i]);
    }
    for (int c = 0; c < m; c++) {
        for (int e = 0; e < m; e++)
            gsl_matrix_set(&K.matrix, (size_t)(k + c), (size_t)(k + e), 0.0);
        gsl_vector_set(&r.vector, (size_t)(k + c), pb->f[c]);
    }
    int sgn;
    if (gsl_linalg_LU_decomp(&K.matrix, &p, &sgn) != GSL_SUCCESS)
        return 1;
    /* a (numerically) singular system: a zero pivot relative to the largest */
    double umax = 0, umin = INFINITY;
    for (size_t i = 0; i < N; i++) {
        double u = fabs(gsl_matrix_get(&K.matrix, i, i));
        umax = fmax(umax, u);
        umin = fmin(umin, u);
    }
    if (!(umin > 1e-14 * umax))
        return 1;
    if (gsl_linalg_LU_solve(&K.matrix, &p, &r.vector, &x.vector) != GSL_SUCCESS)
        return 1;
    memset(ws->q, 0, sizeof(double) * (size_t)n);
    for (int a = 0; a < k; a++)
        ws->q[ws->free_idx[a]] = gsl_vector_get(&x.vector, (size_t)a);
    for (int c = 0; c < m; c++)
        z[c] = gsl_vector_get(&x.vector, (size_t)(k + c));
    return 0;
}

static void gaps(const gd_contact_problem *pb, const double *p, const double *z, double *Lp, double *d)
{
    int n = pb->n, m = pb->m;
    for (int i = 0; i < n; i++) {
        double s = 0;
        const double *row = pb->L + (size_t)i * (size_t)n;
        for (int k = 0; k < n; k++)
            s += row[k] * p[k];
        Lp[i] = s;
        double gz = 0;
        for (int c = 0; c < m; c++)
            gz += pb->G[(size_t)i * (size_t)m + (size_t)c] * z[c];
        d[i] = pb->w[i] + s - gz;
    }
}

static int rebuild_free(gd_contact_workspace *ws, int n)
{
    int k = 0;
    for (int i = 0; i < n; i++)
        if (ws->in_free[i])
            ws->free_idx[k++] = i;
    return k;
}

int contact_cold_start(const gd_contact_problem *pb, unsigned char *in_free)
{
    int n = pb->n, m = pb->m;
    memset(in_free, 0, (size_t)n);
    double basis[GD_CONTACT_MAX_FREEDOMS][GD_CONTACT_MAX_FREEDOMS];
    int nb = 0;
    while (nb < m) {
        int best = -1;
        double bestv[GD_CONTACT_MAX_FREEDOMS];
        for (int i = 0; i < n; i++) {
            if (in_free[i] || (best >= 0 && pb->w[i] >= pb->w[best]))
                continue;
            double v[GD_CONTACT_MAX_FREEDOMS], nrm0 = 0, nrm = 0;
            for (int c = 0; c < m; c++) {
                v[c] = pb->G[(size_t)i * (size_t)m + (size_t)c];
                nrm0 += v[c] * v[c];
            }
            for (int b = 0; b < nb; b++) { /* Gram-Schmidt against the rows taken */
                double dot = 0;
                for (int c = 0; c < m; c++)
                    dot += v[c] * basis[b][c];
                for (int c = 0; c < m; c++)
                    v[c] -= dot * basis[b][c];
            }
            for (int c = 0; c < m; c++)
                nrm += v[c] * v[c];
            if (nrm > 1e-20 * nrm0 && nrm0 > 0) {
                best = i;
                for (int c = 0; c < m; c++)
                    bestv[c] = v[c] / sqrt(nrm);
            }
        }
        if (best < 0)
            break;
        in_free[best] = 1;
        memcpy(basis[nb++], bestv, sizeof bestv);
    }
    return nb;
}

/* 1 when every load of the free set is positive. */
static int free_loads_positive(const gd_contact_workspace *ws, int k)
{
    int ok = 1;
    for (int a = 0; a < k; a++)
        if (!(ws->q[ws->free_idx[a]] > 0))
            ok = 0;
    return ok;
}

/* A feasible start (every load positive, equilibrium met): the hint, else one least-gap point
 * per freedom. */
static gd_status find_start(const gd_contact_problem *pb, const unsigned char *loaded_hint,
                            gd_contact_workspace *ws, double *z, gd_error *err)
{
    int n = pb->n, m = pb->m;
    int k = 0, ok = 0;
    memset(ws->in_free, 0, (size_t)n);
    if (loaded_hint) {
        for (int i = 0; i < n; i++)
            ws->in_free[i] = loaded_hint[i] != 0;
        k = rebuild_free(ws, n);
        if (k > 0 && solve_free(pb, ws, k, z) == 0)
            ok = free_loads_positive(ws, k);
    }
    if (!ok) {
        /* the least-gap points that make G_F^T regular, one per freedom: with as many points as
         * freedoms the loads follow from equilibrium alone */
        int nb = contact_cold_start(pb, ws->in_free);
        k = rebuild_free(ws, n);
        if (nb == m && solve_free(pb, ws, k, z) == 0)
            ok = free_loads_positive(ws, k);
    }
    if (!ok)
        return gd_error_set(err, GD_ERR_PHYSICS, "contact solve: no loaded set carries the load without tension "
                            "(%d points, %d freedoms): the flanks cannot transmit it", n, m);
    return GD_OK;
}

/* Point j has joined the loaded set: solve on the set; when a load is not positive move towards
 * the solution up to the first load that reaches zero, unload the points that did, and again. */
static gd_status enter_point(const gd_contact_problem *pb, gd_contact_workspace *ws, double *p, double *z, int *it,
                             int maxit, gd_error *err)
{
    int n = pb->n;
    for (;;) {
        int k = rebuild_free(ws, n);
        if (solve_free(pb, ws, k, z) != 0)
            return gd_error_set(err, GD_ERR_PHYSICS, "contact solve: singular loaded set (%d points)", k);
        /* feasible: accept; else move towards it up to the first load that reaches zero,
         * and unload the points that did */
        double alpha = 1.0;
        int any = 0, jhit = -1;
        for (int a = 0; a < k; a++) {
            int i = ws->free_idx[a];
            if (ws->q[i] <= 0) {
                any = 1;
                double t = p[i] / (p[i] - ws->q[i]);
                if (t < alpha || jhit < 0) {
                    alpha = t < alpha ? t : alpha;
                    jhit = t <= alpha ? i : jhit;
                }
            }
        }
        if (!any) {
            memcpy(p, ws->q, sizeof(double) * (size_t)n);
            break;
        }
        double pmax = 0;
        for (int i = 0; i < n; i++) {
            p[i] += alpha * (ws->q[i] - p[i]);
            pmax = fmax(pmax, fabs(p[i]));
        }
        if (jhit >= 0)
            p[jhit] = 0.0;
        for (int i = 0; i < n; i++)
            if (ws->in_free[i] && p[i] <= 1e-14 * pmax) {
                p[i] = 0;
                ws->in_free[i] = 0;
            }
        if (++*it > maxit)
            return gd_error_set(err, GD_ERR_INTERNAL, "contact solve: no convergence in %d iterations", maxit);
    }
    return GD_OK;
}

/* The report: loads off the set zeroed, loaded count and residual. */
static void report_solution(const gd_contact_problem *pb, const gd_contact_workspace *ws, double wmax,
                            const double *z, int it, gd_contact_solution *sol)
{
    int n = pb->n, m = pb->m;
    double *p = sol->p, *d = sol->d;
    double res = 0;
    int loaded = 0;
    for (int i = 0; i < n; i++) {
        if (ws->in_free[i]) {
            loaded++;
            res = fmax(res, fabs(d[i]));
        } else {
            res = fmax(res, -d[i]);
            p[i] = 0.0;
        }
        if (p[i] < 0)
            res = INFINITY;
    }
    for (int c = 0; c < m; c++) {
        double s = 0;
        for (int i = 0; i < n; i++)
            s += pb->G[(size_t)i * (size_t)m + (size_t)c] * p[i];
        sol->z[c] = z[c];
        /* the equilibrium residual, as a gap-equivalent: relative to the load, times the gap scale */
        res = fmax(res, fabs(s - pb->f[c]) / (fabs(pb->f[c]) + 1e-300) * (wmax + 1e-300));
    }
    sol->loaded = loaded;
    sol->iterations = it;
    sol->residual = res;
}

GD_API gd_status gd_contact_solve(const gd_contact_problem *pb, const unsigned char *loaded_hint,
                                  gd_contact_workspace *ws, gd_contact_solution *sol, gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    int n = pb->n, m = pb->m;
    if (n < 1 || n > ws->nmax || m != ws->m)
        return gd_error_set(err, GD_ERR_INTERNAL, "contact solve: problem %dx%d for a workspace %dx%d", n, m,
                            ws->nmax, ws->m);
    double *p = sol->p, *d = sol->d, z[GD_CONTACT_MAX_FREEDOMS] = {0};
    double wmax = 0;
    for (int i = 0; i < n; i++) {
        if (!isfinite(pb->w[i]))
            return gd_error_set(err, GD_ERR_INPUT, "contact solve: gap %d is not finite", i);
        wmax = fmax(wmax, fabs(pb->w[i]));
    }
    gd_status st = find_start(pb, loaded_hint, ws, z, err);
    if (st != GD_OK)
        return st;
    memcpy(p, ws->q, sizeof(double) * (size_t)n);
    int it = 0, maxit = 10 * n + 50;
    double tol;
    for (;;) {
        gaps(pb, p, z, ws->Lp, d);
        double lmax = 0;
        for (int i = 0; i < n; i++)
            lmax = fmax(lmax, fabs(ws->Lp[i]));
        tol = 1e-12 * (wmax + lmax);
        /* the most penetrating unloaded point joins the loaded set */
        int j = -1;
        for (int i = 0; i < n; i++)
            if (!ws->in_free[i] && d[i] < -tol && (j < 0 || d[i] < d[j]))
                j = i;
        if (j < 0)
            break;
        if (++it > maxit)
            return gd_error_set(err, GD_ERR_INTERNAL, "contact solve: no convergence in %d iterations", maxit);
        ws->in_free[j] = 1;
        st = enter_point(pb, ws, p, z, &it, maxit, err);
        if (st != GD_OK)
            return st;
    }
    report_solution(pb, ws, wmax, z, it, sol);
    return GD_OK;
}
