/* The LTCA contact problem (Eq. 11) by the primal active-set method of gd_contact_solve
 * (Lawson & Hanson's NNLS extended to equality constraints), specialised to a block-diagonal
 * flexibility matrix: points of different tooth pairs are not coupled, so the equality-constrained
 * QP on a loaded set splits into one Cholesky factorisation per tooth pair and an m x m Schur
 * complement for the rigid freedoms (docs/ltca.md section 3.4):
 *   L_FF q - G_F z = -w_F,  G_F^T q = f   =>   S z = f + G_F^T L_FF^{-1} w_F,  S = G_F^T L_FF^{-1} G_F,
 *   q = L_FF^{-1} (G_F z - w_F).
 * A warm start whose loads are not all positive is pruned (its non-positive loads dropped and the
 * subspace problem solved again) instead of being thrown away. Convergence criterion and report
 * as gd_contact_solve (gd_contact.h); the tests check both solvers give the same loads. */
#include "contact_internal.h"
#include "ltca_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct ltca_qp {
    int nmax, bmax, m;
    double *M;               /* bmax x bmax factor of one block */
    double *Y;               /* nmax x (m + 1): L_FF^{-1} [G_F w_F] per free point */
    int *fidx;               /* free points of the current block */
    unsigned char *in_free;
    unsigned char *tabu;     /* points whose entry was refused (rounding; see below) */
    double *q, *Lp;
};

gd_status ltca_qp_alloc(int nmax, int bmax, int m, ltca_qp **out, gd_error *err)
{
    *out = NULL;
    if (nmax < 1 || bmax < 1 || m < 1 || m > GD_CONTACT_MAX_FREEDOMS)
        return gd_error_set(err, GD_ERR_INTERNAL, "LTCA solver: %d points, blocks of %d, %d freedoms", nmax, bmax, m);
    ltca_qp *q = calloc(1, sizeof *q);
    if (!q)
        return gd_error_set(err, GD_ERR_NOMEM, "LTCA solver: out of memory");
    q->nmax = nmax;
    q->bmax = bmax;
    q->m = m;
    q->M = malloc(sizeof(double) * (size_t)bmax * (size_t)bmax);
    q->Y = malloc(sizeof(double) * (size_t)nmax * (size_t)(m + 1));
    q->fidx = malloc(sizeof(int) * (size_t)bmax);
    q->in_free = malloc((size_t)nmax);
    q->tabu = malloc((size_t)nmax);
    q->q = malloc(sizeof(double) * (size_t)nmax);
    q->Lp = malloc(sizeof(double) * (size_t)nmax);
    if (!q->M || !q->Y || !q->fidx || !q->in_free || !q->tabu || !q->q || !q->Lp) {
        ltca_qp_free(q);
        return gd_error_set(err, GD_ERR_NOMEM, "LTCA solver: out of memory for %d points", nmax);
    }
    *out = q;
    return GD_OK;
}

void ltca_qp_free(ltca_qp *q)
{
    if (!q)
        return;
    free(q->M);
    free(q->Y);
    free(q->fidx);
    free(q->in_free);
    free(q->tabu);
    free(q->q);
    free(q->Lp);
    free(q);
}

/* In-place Cholesky L L^T of the k x k row-major matrix a (lower triangle); 1 if not positive
 * definite. */
static int chol(double *a, int k)
{
    for (int j = 0; j < k; j++) {
        double s = a[j * k + j];
        for (int l = 0; l < j; l++)
            s -= a[j * k + l] * a[j * k + l];
        if (!(s > 0))
            return 1;
        double r = sqrt(s);
        a[j * k + j] = r;
        for (int i = j + 1; i < k; i++) {
            double t = a[i * k + j];
            for (int l = 0; l < j; l++)
                t -= a[i * k + l] * a[j * k + l];
            a[i * k + j] = t / r;
        }
    }
    return 0;
}

/* solve L L^T x = b in place (b of stride `stride`) */
static void chol_solve(const double *a, int k, double *b, int stride)
{
    for (int i = 0; i < k; i++) {
        double s = b[i * stride];
        for (int l = 0; l < i; l++)
            s -= a[i * k + l] * b[l * stride];
        b[i * stride] = s / a[i * k + i];
    }
    for (int i = k - 1; i >= 0; i--) {
        double s = b[i * stride];
        for (int l = i + 1; l < k; l++)
            s -= a[l * k + i] * b[l * stride];
        b[i * stride] = s / a[i * k + i];
    }
}

/* The equality-constrained QP on the free set: loads in q->q (zero off the set) and z.
 * Returns 0, 1 when singular (the loaded set cannot carry a freedom), 2 when a block of L is not
 * positive definite. */
static int solve_free(ltca_qp *q, const gd_contact_problem *pb, int nb, const int *bstart, double *z)
{
    int n = pb->n, m = pb->m, m1 = m + 1;
    double S[GD_CONTACT_MAX_FREEDOMS * GD_CONTACT_MAX_FREEDOMS] = {0}, r[GD_CONTACT_MAX_FREEDOMS];
    for (int c = 0; c < m; c++)
        r[c] = pb->f[c];
    int any = 0;
    for (int b = 0; b < nb; b++) {
        int k = 0;
        for (int i = bstart[b]; i < bstart[b + 1]; i++)
            if (q->in_free[i])
                q->fidx[k++] = i;
        if (!k)
            continue;
        any = 1;
        for (int a = 0; a < k; a++) {
            const double *row = pb->L + (size_t)q->fidx[a] * (size_t)n;
            for (int e = 0; e <= a; e++)
                q->M[a * k + e] = row[q->fidx[e]];
        }
        if (chol(q->M, k))
            return 2;
        double *Y = q->Y + (size_t)bstart[b] * (size_t)m1; /* rows of this block's free points */
        for (int a = 0; a < k; a++) {
            int i = q->fidx[a];
            for (int c = 0; c < m; c++)
                Y[a * m1 + c] = pb->G[(size_t)i * (size_t)m + (size_t)c];
            Y[a * m1 + m] = pb->w[i];
        }
        for (int c = 0; c <= m; c++)
            chol_solve(q->M, k, Y + c, m1);
        for (int a = 0; a < k; a++) {
            int i = q->fidx[a];
            for (int c = 0; c < m; c++) {
                double g = pb->G[(size_t)i * (size_t)m + (size_t)c];
                for (int e = 0; e < m; e++)
                    S[c * m + e] += g * Y[a * m1 + e];
                r[c] += g * Y[a * m1 + m];
            }
        }
    }
    if (!any)
        return 1;
    /* S z = r: S symmetric positive semi-definite; singular when a freedom has no loaded point */
    double smax = 0;
    for (int c = 0; c < m; c++)
        smax = fmax(smax, S[c * m + c]);
    for (int c = 0; c < m; c++)
        for (int e = 0; e < c; e++)
            S[c * m + e] = S[e * m + c] = 0.5 * (S[c * m + e] + S[e * m + c]);
    for (int j = 0; j < m; j++) {
        double s = S[j * m + j];
        for (int l = 0; l < j; l++)
            s -= S[j * m + l] * S[j * m + l];
        if (!(s > 1e-12 * smax))
            return 1;
        double rt = sqrt(s);
        S[j * m + j] = rt;
        for (int i = j + 1; i < m; i++) {
            double t = S[i * m + j];
            for (int l = 0; l < j; l++)
                t -= S[i * m + l] * S[j * m + l];
            S[i * m + j] = t / rt;
        }
    }
    chol_solve(S, m, r, 1);
    for (int c = 0; c < m; c++)
        z[c] = r[c];
    memset(q->q, 0, sizeof(double) * (size_t)n);
    for (int b = 0; b < nb; b++) {
        const double *Y = q->Y + (size_t)bstart[b] * (size_t)m1;
        int a = 0;
        for (int i = bstart[b]; i < bstart[b + 1]; i++)
            if (q->in_free[i]) {
                double s = -Y[a * m1 + m];
                for (int c = 0; c < m; c++)
                    s += Y[a * m1 + c] * z[c];
                q->q[i] = s;
                a++;
            }
    }
    return 0;
}

static void gaps(const gd_contact_problem *pb, int nb, const int *bstart, const unsigned char *in_free,
                 const double *p, const double *z, double *Lp, double *d)
{
    int n = pb->n, m = pb->m;
    for (int b = 0; b < nb; b++)
        for (int i = bstart[b]; i < bstart[b + 1]; i++) {
            const double *row = pb->L + (size_t)i * (size_t)n;
            double s = 0;
            for (int k = bstart[b]; k < bstart[b + 1]; k++)
                if (in_free[k])
                    s += row[k] * p[k];
            Lp[i] = s;
            double gz = 0;
            for (int c = 0; c < m; c++)
                gz += pb->G[(size_t)i * (size_t)m + (size_t)c] * z[c];
            d[i] = pb->w[i] + s - gz;
        }
}

static int all_positive(const ltca_qp *q, int n)
{
    for (int i = 0; i < n; i++)
        if (q->in_free[i] && !(q->q[i] > 0))
            return 0;
    return 1;
}

int ltca_qp_start(const gd_contact_problem *pb, unsigned char *loaded)
{
    int n = pb->n;
    memset(loaded, 0, (size_t)n);
    if (pb->m != 2 || n < 2)
        return 0;
    int i0 = 0;
    for (int i = 1; i < n; i++)
        if (pb->w[i] < pb->w[i0])
            i0 = i;
    const double *g0 = pb->G + (size_t)i0 * 2;
    int best = -1;
    for (int j = 0; j < n; j++) {
        if (j == i0 || (best >= 0 && pb->w[j] >= pb->w[best]))
            continue;
        const double *g1 = pb->G + (size_t)j * 2;
        double det = g0[0] * g1[1] - g0[1] * g1[0];
        if (!(fabs(det) > 1e-12 * (fabs(g0[0] * g1[1]) + fabs(g0[1] * g1[0]))))
            continue;
        /* the loads that carry f on the two points alone: G_F^T p = f */
        double p0 = (pb->f[0] * g1[1] - pb->f[1] * g1[0]) / det, p1 = (g0[0] * pb->f[1] - g0[1] * pb->f[0]) / det;
        if (p0 > 0 && p1 > 0)
            best = j;
    }
    if (best < 0)
        return 0;
    loaded[i0] = loaded[best] = 1;
    return 1;
}

/* Sizes of the problem against the workspace, and the gaps finite; *wmax the largest |gap|. */
static gd_status check_problem(const ltca_qp *q, const gd_contact_problem *pb, int nb, const int *bstart,
                               double *wmax, gd_error *err)
{
    int n = pb->n, m = pb->m;
    if (n < 1 || n > q->nmax || m != q->m)
        return gd_error_set(err, GD_ERR_INTERNAL, "LTCA solver: problem %dx%d for a workspace %dx%d", n, m, q->nmax,
                            q->m);
    for (int b = 0; b < nb; b++)
        if (bstart[b + 1] - bstart[b] > q->bmax)
            return gd_error_set(err, GD_ERR_INTERNAL, "LTCA solver: block of %d points (at most %d)",
                                bstart[b + 1] - bstart[b], q->bmax);
    *wmax = 0;
    for (int i = 0; i < n; i++) {
        if (!isfinite(pb->w[i]))
            return gd_error_set(err, GD_ERR_INPUT, "LTCA solver: gap %d is not finite", i);
        *wmax = fmax(*wmax, fabs(pb->w[i]));
    }
    return GD_OK;
}

static gd_status not_positive_definite(gd_error *err)
{
    return gd_error_set(err, GD_ERR_INTERNAL, "LTCA solver: a block of the flexibility matrix is not "
                        "positive definite");
}

/* Warm start: the hint, pruned of the loads that turn non-positive. */
static gd_status start_warm(ltca_qp *q, const gd_contact_problem *pb, int nb, const int *bstart,
                            const unsigned char *hint, double *z, int *ok, gd_error *err)
{
    int n = pb->n;
    for (int i = 0; i < n; i++)
        q->in_free[i] = hint[i] != 0;
    for (int round = 0; round < 50; round++) {
        int rc = solve_free(q, pb, nb, bstart, z);
        if (rc == 2)
            return not_positive_definite(err);
        if (rc)
            break;
        if (all_positive(q, n)) {
            *ok = 1;
            break;
        }
        for (int i = 0; i < n; i++)
            if (q->in_free[i] && !(q->q[i] > 0))
                q->in_free[i] = 0;
    }
    return GD_OK;
}

/* Cold start: the least-gap points whose rows of G are independent, one per freedom. */
static gd_status start_cold(ltca_qp *q, const gd_contact_problem *pb, int nb, const int *bstart, double *z, int *ok,
                            gd_error *err)
{
    int n = pb->n, m = pb->m;
    int nbas = contact_cold_start(pb, q->in_free);
    if (nbas == m) {
        int rc = solve_free(q, pb, nb, bstart, z);
        if (rc == 2)
            return not_positive_definite(err);
        *ok = rc == 0 && all_positive(q, n);
    }
    return GD_OK;
}

/* A feasible loaded set to start from: the warm start, the two-point start, or the cold start. */
static gd_status find_start(ltca_qp *q, const gd_contact_problem *pb, int nb, const int *bstart,
                            const unsigned char *hint, double *z, gd_error *err)
{
    int n = pb->n, m = pb->m;
    int ok = 0;
    gd_status st;
    if (hint && (st = start_warm(q, pb, nb, bstart, hint, z, &ok, err)) != GD_OK)
        return st;
    if (!ok && m == 2 && ltca_qp_start(pb, q->in_free)) {
        int rc = solve_free(q, pb, nb, bstart, z);
        if (rc == 2)
            return not_positive_definite(err);
        ok = rc == 0 && all_positive(q, n);
    }
    if (!ok && (st = start_cold(q, pb, nb, bstart, z, &ok, err)) != GD_OK)
        return st;
    if (!ok)
        return gd_error_set(err, GD_ERR_PHYSICS, "LTCA solver: no loaded set carries the load without tension "
                            "(%d points, %d freedoms): the flanks cannot transmit it", n, m);
    return GD_OK;
}

/* Point j enters the loaded set: solve on the set, stepping back towards the previous loads and
 * dropping the point that reaches zero first until all loads are positive. */
static gd_status enter_point(ltca_qp *q, const gd_contact_problem *pb, int nb, const int *bstart, int j, double *p,
                             double *z, int *it, int maxit, gd_error *err)
{
    int n = pb->n;
    q->in_free[j] = 1;
    for (int first = 1;; first = 0) {
        int rc = solve_free(q, pb, nb, bstart, z);
        if (rc)
            return gd_error_set(err, rc == 2 ? GD_ERR_INTERNAL : GD_ERR_PHYSICS,
                                "LTCA solver: %s loaded set", rc == 2 ? "indefinite block in the" : "singular");
        double alpha = 1.0;
        int anyneg = 0, jhit = -1;
        for (int i = 0; i < n; i++) {
            if (!q->in_free[i] || q->q[i] > 0)
                continue;
            anyneg = 1;
            double t = p[i] / (p[i] - q->q[i]);
            if (jhit < 0 || t < alpha) {
                alpha = fmin(t, alpha);
                jhit = i;
            }
        }
        if (!anyneg) {
            memcpy(p, q->q, sizeof(double) * (size_t)n);
            break;
        }
        if (first && jhit == j && !(alpha > 0)) {
            /* the entering point would take no load: in exact arithmetic the most penetrating
             * point always takes a positive load (Lawson & Hanson), so its penetration is
             * rounding; refuse it for the rest of the solve instead of cycling */
            q->in_free[j] = 0;
            q->tabu[j] = 1;
            rc = solve_free(q, pb, nb, bstart, z);
            if (rc)
                return gd_error_set(err, GD_ERR_INTERNAL, "LTCA solver: lost the loaded set");
            memcpy(p, q->q, sizeof(double) * (size_t)n);
            break;
        }
        double pmax = 0;
        for (int i = 0; i < n; i++) {
            p[i] += alpha * (q->q[i] - p[i]);
            pmax = fmax(pmax, fabs(p[i]));
        }
        p[jhit] = 0.0;
        for (int i = 0; i < n; i++)
            if (q->in_free[i] && p[i] <= 1e-14 * pmax) {
                p[i] = 0;
                q->in_free[i] = 0;
            }
        if (++*it > maxit)
            return gd_error_set(err, GD_ERR_INTERNAL, "LTCA solver: no convergence in %d iterations", maxit);
    }
    return GD_OK;
}

/* The active-set iterations from the start: the most penetrating free point enters until none
 * penetrates beyond the tolerance. */
static gd_status active_set(ltca_qp *q, const gd_contact_problem *pb, int nb, const int *bstart, double wmax,
                            const gd_stop_hook *stop, double *p, double *d, double *z, int *it, gd_error *err)
{
    int n = pb->n, maxit = 10 * n + 50;
    for (;;) {
        if (gd_stop_asked(stop))
            return gd_error_set(err, GD_ERR_INTERRUPTED, "LTCA: stopped in the contact solve");
        gaps(pb, nb, bstart, q->in_free, p, z, q->Lp, d);
        double lmax = 0;
        for (int i = 0; i < n; i++)
            lmax = fmax(lmax, fabs(q->Lp[i]));
        double tol = 1e-12 * (wmax + lmax);
        int j = -1;
        for (int i = 0; i < n; i++)
            if (!q->in_free[i] && !q->tabu[i] && d[i] < -tol && (j < 0 || d[i] < d[j]))
                j = i;
        if (j < 0)
            break;
        if (++*it > maxit)
            return gd_error_set(err, GD_ERR_INTERNAL, "LTCA solver: no convergence in %d iterations", maxit);
        gd_status st = enter_point(q, pb, nb, bstart, j, p, z, it, maxit, err);
        if (st != GD_OK)
            return st;
    }
    return GD_OK;
}

/* The report of gd_contact.h: loads off the set zeroed, loaded count and residual. */
static void report_solution(const ltca_qp *q, const gd_contact_problem *pb, double wmax, const double *z, int it,
                            gd_contact_solution *sol)
{
    int n = pb->n, m = pb->m;
    double *p = sol->p, *d = sol->d;
    double res = 0;
    int loaded = 0;
    for (int i = 0; i < n; i++) {
        if (q->in_free[i]) {
            loaded++;
            res = fmax(res, fabs(d[i]));
        } else {
            res = fmax(res, -d[i]);
            p[i] = 0.0;
        }
        if (p[i] < 0)
            res = INFINITY;
    }
    /* the equilibrium residual as a gap-equivalent: relative to the largest force, times the gap scale */
    double fmaxv = 0;
    for (int c = 0; c < m; c++)
        fmaxv = fmax(fmaxv, fabs(pb->f[c]));
    for (int c = 0; c < m; c++) {
        double s = 0;
        for (int i = 0; i < n; i++)
            s += pb->G[(size_t)i * (size_t)m + (size_t)c] * p[i];
        sol->z[c] = z[c];
        res = fmax(res, fabs(s - pb->f[c]) / (fmaxv + 1e-300) * (wmax + 1e-300));
    }
    sol->loaded = loaded;
    sol->iterations = it;
    sol->residual = res;
}

gd_status ltca_qp_solve(ltca_qp *q, const gd_contact_problem *pb, int nb, const int *bstart,
                        const unsigned char *hint, const gd_stop_hook *stop, gd_contact_solution *sol,
                        gd_error *err)
{
    double z[GD_CONTACT_MAX_FREEDOMS] = {0};
    double wmax = 0;
    gd_status st = check_problem(q, pb, nb, bstart, &wmax, err);
    if (st != GD_OK)
        return st;
    st = find_start(q, pb, nb, bstart, hint, z, err);
    if (st != GD_OK)
        return st;
    int n = pb->n;
    memcpy(sol->p, q->q, sizeof(double) * (size_t)n);
    memset(q->tabu, 0, (size_t)n);
    int it = 0;
    st = active_set(q, pb, nb, bstart, wmax, stop, sol->p, sol->d, z, &it, err);
    if (st != GD_OK)
        return st;
    report_solution(q, pb, wmax, z, it, sol);
    return GD_OK;
}
