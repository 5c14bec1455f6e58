/* The contact solver: a closed form (two springs with different gaps), random problems against
 * brute-force enumeration of every loaded set (the QP's solution is unique), the optimality
 * conditions on a large problem, a warm start, and a load the flanks cannot carry. */
#include "geardyn/gd_contact.h"
#include "tap.h"

#include <gsl/gsl_linalg.h>
#include <gsl/gsl_rng.h>
#include <stdlib.h>
#include <string.h>

static void random_problem(gsl_rng *r, int n, int m, double *L, double *w, double *G, double *f)
{
    /* L = A A^T + n I (SPD, scale ~1e-9 m/N); gaps up to 10 um; G: approach (1) and axial (+-1) */
    double *A = malloc(sizeof(double) * (size_t)n * (size_t)n);
    for (int i = 0; i < n * n; i++)
        A[i] = gsl_rng_uniform(r) - 0.5;
    for (int i = 0; i < n; i++)
        for (int k = 0; k < n; k++) {
            double s = i == k ? 0.3 * n : 0.0;
            for (int j = 0; j < n; j++)
                s += A[i * n + j] * A[k * n + j];
            L[i * n + k] = 1e-9 * s / n;
        }
    free(A);
    for (int i = 0; i < n; i++) {
        w[i] = 1e-5 * gsl_rng_uniform(r);
        G[i * m + 0] = 1.0;
        if (m > 1)
            G[i * m + 1] = i < n / 2 ? 1.0 : -1.0;
    }
    f[0] = 5000.0;
    if (m > 1)
        f[1] = 0.0;
}

/* brute force: the loaded set whose equality-QP solution satisfies every condition */
static int brute(int n, int m, const double *L, const double *w, const double *G, const double *f, double *pbest)
{
    int found = 0;
    for (unsigned mask = 1; mask < (1u << n); mask++) {
        int k = __builtin_popcount(mask), idx[16], a = 0;
        if (k < m)
            continue;
        for (int i = 0; i < n; i++)
            if (mask & (1u << i))
                idx[a++] = i;
        int N = k + m;
        gsl_matrix *K = gsl_matrix_calloc((size_t)N, (size_t)N);
        gsl_vector *rhs = gsl_vector_calloc((size_t)N), *x = gsl_vector_alloc((size_t)N);
        gsl_permutation *P = gsl_permutation_alloc((size_t)N);
        for (int i = 0; i < k; i++) {
            for (int j = 0; j < k; j++)
                gsl_matrix_set(K, (size_t)i, (size_t)j, L[idx[i] * n + idx[j]]);
            for (int c = 0; c < m; c++) {
                gsl_matrix_set(K, (size_t)i, (size_t)(k + c), -G[idx[i] * m + c]);
                gsl_matrix_set(K, (size_t)(k + c), (size_t)i, G[idx[i] * m + c]);
            }
            gsl_vector_set(rhs, (size_t)i, -w[idx[i]]);
        }
        for (int c = 0; c < m; c++)
            gsl_vector_set(rhs, (size_t)(k + c), f[c]);
        int sg, good = gsl_linalg_LU_decomp(K, P, &sg) == 0 && fabs(gsl_linalg_LU_det(K, sg)) > 1e-300 &&
                       gsl_linalg_LU_solve(K, P, rhs, x) == 0;
        double p[16] = {0}, z[4] = {0};
        if (good) {
            for (int i = 0; i < k; i++) {
                p[idx[i]] = gsl_vector_get(x, (size_t)i);
                if (!(p[idx[i]] > 0))
                    good = 0;
            }
            for (int c = 0; c < m; c++)
                z[c] = gsl_vector_get(x, (size_t)(k + c));
        }
        for (int i = 0; good && i < n; i++) {
            if (mask & (1u << i))
                continue;
            double d = w[i];
            for (int j = 0; j < n; j++)
                d += L[i * n + j] * p[j];
            for (int c = 0; c < m; c++)
                d -= G[i * m + c] * z[c];
            if (d < -1e-15)
                good = 0;
        }
        if (good) {
            memcpy(pbest, p, sizeof(double) * (size_t)n);
            found++;
        }
        gsl_matrix_free(K);
        gsl_vector_free(rhs);
        gsl_vector_free(x);
        gsl_permutation_free(P);
    }
    return found;
}

int main(void)
{
    gd_error e = {0};
    gd_contact_workspace *ws;
    /* 1. two springs, gaps 0 and 2 um, compliances 1e-9 and 2e-9 m/N, total load P */
    {
        double L[4] = {1e-9, 0, 0, 2e-9}, w[2] = {0, 2e-6}, G[2] = {1, 1}, p[2], d[2];
        gd_contact_workspace_alloc(2, 1, &ws, &e);
        for (int c = 0; c < 2; c++) {
            double P = c ? 5000.0 : 1000.0, f[1] = {P};
            gd_contact_problem pb = {2, 1, L, w, G, f};
            gd_contact_solution s = {p, d, {0}, 0, 0, 0};
            gd_contact_solve(&pb, NULL, ws, &s, &e);
            double p1 = P * 1e-9 < 2e-6 ? P : (2e-6 + 2e-9 * P) / 3e-9;
            TAP_REL(p[0], p1, 1e-12, c ? "two springs, both loaded: load of the first" : "two springs, one loaded");
            TAP_CLOSE(p[0] + p[1], P, 1e-9, "load balance (N)");
            TAP_REL(s.z[0], 1e-9 * p1, 1e-12, "approach = deflection of the loaded first spring");
        }
        gd_contact_workspace_free(ws);
    }
    /* 2. random problems against brute force */
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 7);
    for (int m = 1; m <= 2; m++)
        for (int rep = 0; rep < 20; rep++) {
            int n = 10;
            double L[100], w[10], G[20], f[2], p[10], d[10], pb_[10];
            random_problem(r, n, m, L, w, G, f);
            gd_contact_workspace_alloc(n, m, &ws, &e);
            gd_contact_problem pb = {n, m, L, w, G, f};
            gd_contact_solution s = {p, d, {0}, 0, 0, 0};
            gd_status st = gd_contact_solve(&pb, NULL, ws, &s, &e);
            int found = brute(n, m, L, w, G, f, pb_);
            double diff = 0;
            for (int i = 0; i < n; i++)
                diff = fmax(diff, fabs(p[i] - pb_[i]));
            if (rep < 3 || diff > 1e-8 || st != GD_OK || found != 1)
                tap_ok(st == GD_OK && found == 1 && diff < 1e-8,
                       "random n=%d m=%d #%d: unique brute-force solution (%d found), max |p - p_bf| = %.3g N, %d loaded, "
                       "%d iterations", n, m, rep, found, diff, s.loaded, s.iterations);
            gd_contact_workspace_free(ws);
        }
    /* 3. a large problem: the optimality conditions, and a warm start */
    {
        int n = 240, m = 2;
        double *L = malloc(sizeof(double) * n * n), *w = malloc(sizeof(double) * n), *G = malloc(sizeof(double) * n * m);
        double f[2], *p = malloc(sizeof(double) * n), *d = malloc(sizeof(double) * n), *p2 = malloc(sizeof(double) * n);
        random_problem(r, n, m, L, w, G, f);
        gd_contact_workspace_alloc(n, m, &ws, &e);
        gd_contact_problem pb = {n, m, L, w, G, f};
        gd_contact_solution s = {p, d, {0}, 0, 0, 0};
        tap_ok(gd_contact_solve(&pb, NULL, ws, &s, &e) == GD_OK, "240 points, 2 freedoms: solved (%s)", e.msg);
        double pmin = 0, dmin = 0, comp = 0, bal0 = 0, bal1 = 0;
        for (int i = 0; i < n; i++) {
            pmin = fmin(pmin, p[i]);
            dmin = fmin(dmin, d[i]);
            comp = fmax(comp, fabs(p[i] * d[i]));
            bal0 += p[i];
            bal1 += G[i * m + 1] * p[i];
        }
        TAP_CLOSE(pmin, 0.0, 0.0, "no tensile load");
        TAP_CLOSE(dmin, 0.0, 1e-15, "no penetration (m)");
        TAP_CLOSE(comp, 0.0, 1e-15, "complementarity max |p d| (N m)");
        TAP_REL(bal0, f[0], 1e-12, "load balance");
        TAP_CLOSE(bal1, 0.0, 1e-9, "axial balance of a floating pinion (N)");
        unsigned char *hint = malloc((size_t)n);
        for (int i = 0; i < n; i++)
            hint[i] = p[i] > 0;
        int it0 = s.iterations;
        gd_contact_solution s2 = {p2, d, {0}, 0, 0, 0};
        gd_contact_solve(&pb, hint, ws, &s2, &e);
        double diff = 0;
        for (int i = 0; i < n; i++)
            diff = fmax(diff, fabs(p2[i] - p[i]));
        tap_ok(diff < 1e-9 * f[0] && s2.iterations == 0,
               "warm start from the solution: same loads (max diff %.3g N), %d iterations (cold: %d)", diff,
               s2.iterations, it0);
        free(hint);
        free(L); free(w); free(G); free(p); free(d); free(p2);
        gd_contact_workspace_free(ws);
    }
    /* 4. a pull cannot be carried */
    {
        double L[1] = {1e-9}, w[1] = {0}, G[1] = {1}, f[1] = {-100}, p[1], d[1];
        gd_contact_workspace_alloc(1, 1, &ws, &e);
        gd_contact_problem pb = {1, 1, L, w, G, f};
        gd_contact_solution s = {p, d, {0}, 0, 0, 0};
        gd_status st = gd_contact_solve(&pb, NULL, ws, &s, &e);
        tap_ok(st == GD_ERR_PHYSICS, "a negative load is refused: %s", e.msg);
        gd_contact_workspace_free(ws);
    }
    gsl_rng_free(r);
    return tap_done();
}
