/* The Floquet multipliers of a product of segment monodromies (gd_floquet_segments, floquet.c)
 * against products whose eigenvalues are known, and against the explicit product where that is
 * accurate.
 *
 * 1. Known products: M_k = Q_{k+1} T_k Q_k^T with random orthogonal Q_k (Q_K = Q_0, GSL's QR of a
 *    Gaussian matrix, seeded) and T_k upper triangular with the diagonal g^(1 - 2i/(n-1)) and a 2 x 2
 *    rotation by theta in the middle, so that the product is Q_0 (T_{K-1} ... T_0) Q_0^T: its
 *    multipliers are g^(K(1 - 2i/(n-1))) and the pair e^(+-i K theta) on the unit circle. With n 20,
 *    K 16 and g 3, 10 the multipliers span 1e-7 .. 1e7 and 1e-16 .. 1e16. Every one, the smallest
 *    included, to a relative 1e-8, and the pair's modulus to 1e-10 of 1. The explicit product,
 *    whose error is about eps |mu_max|, is printed beside (it misses the small multipliers by
 *    orders of magnitude: the reason for the method).
 * 2. A real orbit: the period-2 orbit of the Kahraman & Singh oscillator at Omega 1.3 by multiple
 *    shooting (two segments, impacting): the multipliers from the segments equal those of the
 *    explicit product (well conditioned there, |mu_max| < 1) to 1e-12.
 * 3. One segment: gd_floquet_segments equals gd_floquet of the matrix, exactly. */
#include "analysis/shooting.h"
#include "analysis_util.h"
#include "tap.h"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <string.h>

static void random_orthogonal(gsl_rng *r, gsl_matrix *Q)
{
    const size_t n = Q->size1;
    gsl_matrix *A = gsl_matrix_alloc(n, n), *R = gsl_matrix_alloc(n, n);
    gsl_vector *tau = gsl_vector_alloc(n);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            gsl_matrix_set(A, i, j, gsl_ran_gaussian(r, 1.0));
    gsl_linalg_QR_decomp(A, tau);
    gsl_linalg_QR_unpack(A, tau, Q, R);
    gsl_matrix_free(A);
    gsl_matrix_free(R);
    gsl_vector_free(tau);
}

/* the largest relative error of the multipliers (re, im) against the known (kre, kim), each known one
 * matched to the nearest computed; *pair: the modulus of the computed multiplier nearest the pair */
static double worst(const double *re, const double *im, const double *kre, const double *kim, int n, int ipair,
                    double *pair)
{
    double w = 0;
    for (int i = 0; i < n; i++) {
        double best = INFINITY;
        int jb = 0;
        for (int j = 0; j < n; j++) {
            double d = hypot(re[j] - kre[i], im[j] - kim[i]);
            if (d < best)
                best = d, jb = j;
        }
        w = fmax(w, best / hypot(kre[i], kim[i]));
        if (i == ipair)
            *pair = hypot(re[jb], im[jb]);
    }
    return w;
}

static void known_product(int n, int K, double g, gsl_rng *r)
{
    gd_error e = {0};
    const double theta = 0.3;
    const int c = n / 2 - 1;
    double kre[GD_MAX_STATE], kim[GD_MAX_STATE];
    for (int i = 0; i < n; i++) {
        kre[i] = pow(g, K * (1.0 - 2.0 * i / (n - 1)));
        kim[i] = 0;
    }
    kre[c] = kre[c + 1] = cos(K * theta);
    kim[c] = sin(K * theta);
    kim[c + 1] = -sin(K * theta);
    gsl_matrix *Q0 = gsl_matrix_alloc((size_t)n, (size_t)n), *Qk = gsl_matrix_alloc((size_t)n, (size_t)n);
    gsl_matrix *Qn = gsl_matrix_alloc((size_t)n, (size_t)n), *T = gsl_matrix_alloc((size_t)n, (size_t)n);
    gsl_matrix *A = gsl_matrix_alloc((size_t)n, (size_t)n);
    random_orthogonal(r, Q0);
    gsl_matrix_memcpy(Qk, Q0);
    double *Mk = malloc(sizeof(double) * (size_t)(K * n * n));
    for (int k = 0; k < K; k++) {
        if (k == K - 1)
            gsl_matrix_memcpy(Qn, Q0);
        else
            random_orthogonal(r, Qn);
        gsl_matrix_set_zero(T);
        for (int i = 0; i < n; i++) {
            gsl_matrix_set(T, (size_t)i, (size_t)i, pow(g, 1.0 - 2.0 * i / (n - 1)));
            for (int j = i + 1; j < n; j++)
                gsl_matrix_set(T, (size_t)i, (size_t)j, gsl_ran_gaussian(r, 0.5));
        }
        gsl_matrix_set(T, (size_t)c, (size_t)c, cos(theta));
        gsl_matrix_set(T, (size_t)c, (size_t)c + 1, -sin(theta));
        gsl_matrix_set(T, (size_t)c + 1, (size_t)c, sin(theta));
        gsl_matrix_set(T, (size_t)c + 1, (size_t)c + 1, cos(theta));
        gsl_matrix_view Mv = gsl_matrix_view_array(Mk + (size_t)k * n * n, (size_t)n, (size_t)n);
        gsl_blas_dgemm(CblasNoTrans, CblasTrans, 1.0, T, Qk, 0.0, A);
        gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, Qn, A, 0.0, &Mv.matrix);
        gsl_matrix_memcpy(Qk, Qn);
    }
    double M[GD_MAX_STATE * GD_MAX_STATE], re[GD_MAX_STATE], im[GD_MAX_STATE], pre[GD_MAX_STATE], pim[GD_MAX_STATE];
    if (gd_floquet_segments(Mk, K, n, M, re, im, &e) != GD_OK || gd_floquet(M, n, pre, pim, &e) != GD_OK)
        au_die(&e);
    double pair = NAN, ppair = NAN;
    double w = worst(re, im, kre, kim, n, c, &pair), wp = worst(pre, pim, kre, kim, n, c, &ppair);
    printf("# n %d, K %d, g %g: multipliers %.3g .. %.3g; from the segments: worst relative error %.3g, the pair's "
           "modulus %.15f; the explicit product: %.3g, %.15f\n", n, K, g, kre[0], kre[n - 1], w, pair, wp, ppair);
    char label[160];
    snprintf(label, sizeof label, "n %d, K %d, multipliers %.0e .. %.0e: worst relative error of a multiplier", n, K,
             kre[0], kre[n - 1]);
    TAP_CLOSE(w, 0.0, 1e-8, label);
    snprintf(label, sizeof label, "n %d, K %d, g %g: the pair on the unit circle, its modulus", n, K, g);
    TAP_CLOSE(pair, 1.0, 1e-10, label);
    free(Mk);
    gsl_matrix_free(Q0);
    gsl_matrix_free(Qk);
    gsl_matrix_free(Qn);
    gsl_matrix_free(T);
    gsl_matrix_free(A);
}

int main(void)
{
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 32);
    known_product(20, 16, 3.0, r);
    known_product(20, 16, 10.0, r);
    known_product(6, 4, 30.0, r);
    gsl_rng_free(r);

    /* 2. the period-2 orbit of K&S at Omega 1.3 */
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    gd_error e = {0};
    const char *sets[] = {"excitation.ste_phase_deg=90", "solver.rtol=1e-10", "solver.atol=1e-12", NULL};
    au_ks_case(&c, &m, 0.0, 0.05, 0.1, 0.1, 1.3, sets);
    gd_solver_opts_from_case(&c, &o);
    double y[GD_MAX_STATE];
    gd_modes md;
    gd_po_opts po;
    gd_po_opts_default(&po);
    po.nper = 2;
    gd_po orbit;
    if (gd_initial_state(&c, &m, y, &md, &e) != GD_OK || gd_sim_period_map(&m, &o, y, 300, y, NULL, NULL, &e) != GD_OK ||
        gd_po_solve(&m, &o, &po, y, &orbit, &e) != GD_OK)
        au_die(&e);
    double pre[GD_MAX_STATE], pim[GD_MAX_STATE], d = 0;
    if (gd_floquet(orbit.M, m.n, pre, pim, &e) != GD_OK)
        au_die(&e);
    for (int i = 0; i < m.n; i++)
        d = fmax(d, hypot(orbit.mu_re[i] - pre[i], orbit.mu_im[i] - pim[i]));
    printf("# K&S period 2 at Omega 1.3: mu %.12f%+.12fi, %.12f%+.12fi, events %ld\n", orbit.mu_re[0], orbit.mu_im[0],
           orbit.mu_re[1], orbit.mu_im[1], orbit.events[0]);
    tap_ok(orbit.nseg == 2 && orbit.events[0] > 0 && orbit.mu_max < 1, "K&S at Omega 1.3: a stable impacting period-2 "
           "orbit of two segments (events %ld, |mu_max| %.6f)", orbit.events[0], orbit.mu_max);
    TAP_CLOSE(d, 0.0, 1e-12, "K&S period 2: multipliers from the segments against the explicit product");
    gd_case_free(&c);

    /* 3. one segment */
    double M1[9] = {0.5, 1.0, -2.0, 0.1, -0.3, 0.7, 2.0, 0.0, 0.25}, a_re[3], a_im[3], b_re[3], b_im[3], Mo[9];
    if (gd_floquet_segments(M1, 1, 3, Mo, a_re, a_im, &e) != GD_OK || gd_floquet(M1, 3, b_re, b_im, &e) != GD_OK)
        au_die(&e);
    tap_ok(memcmp(a_re, b_re, sizeof a_re) == 0 && memcmp(a_im, b_im, sizeof a_im) == 0 && memcmp(Mo, M1, sizeof Mo) == 0,
           "one segment: the multipliers of gd_floquet, the matrix itself as the product");
    return tap_done();
}
