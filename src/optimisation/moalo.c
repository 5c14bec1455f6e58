/* The multi-objective Ant Lion Optimizer (S. Mirjalili, P. Jangir, S. Saremi, Multi-objective ant
 * lion optimizer: a multi-objective optimization algorithm for solving engineering problems,
 * Applied Intelligence 46 (2017) 79-95), two objectives, in the normalised box [-1, 1]^d
 * (docs/optimisation.md section 13):
 *
 *   N antlions uniform in the box, evaluated; the archive holds their non-dominated points.
 *   The crowding of an archive member: the members within r_k = (max_k - min_k) / 20 of it in
 *   every objective k, itself included (the niche count N_i >= 1).
 *   elite: an archive member drawn by a roulette wheel with weights 1 / N_i (the less crowded,
 *   the likelier).
 *   for t = 1 .. T:
 *     for every ant i (random numbers drawn serially, in a fixed order):
 *       antlion: an archive member drawn by the roulette wheel 1 / N_i;
 *       ant i = (R_A + R_E) / 2, the random walks of ALO (alo.c, Eq. 2.1-2.13 of Mirjalili 2015)
 *       around the antlion and the elite at step t, in [A +- 1/I(t)], clamped to the box;
 *     the ants are evaluated (in parallel);
 *     the archive takes every ant no member dominates (in index order) and drops the members it
 *     dominates; while it holds more than its size, a member drawn by the roulette wheel with
 *     weights N_i (the more crowded, the likelier) goes, and its neighbours' counts fall by one;
 *     a new elite is drawn.
 *
 * Evaluations: N (T + 1), as ALO. The wrapper (problem.c) keeps, besides, the non-dominated points
 * of every evaluation; MOALO's own front is its archive (r->archive_*). */
#include "opt_internal.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The archive: at most cap + N members (its size plus one population before the cut). */
typedef struct archive {
    int n, cap, d;
    double *x;           /* n x d, normalised */
    double *f;           /* n x 2 */
    double *w;           /* n: the niche counts */
} archive;

static int dominates(const double *a, const double *b)
{
    return a[0] <= b[0] && a[1] <= b[1] && (a[0] < b[0] || a[1] < b[1]);
}

/* Add (x, f) unless a member dominates or equals it; drop the members it dominates. */
static void archive_add(archive *A, const double *x, const double *f)
{
    for (int j = 0; j < A->n; j++)
        if (dominates(A->f + 2 * j, f) || (A->f[2 * j] == f[0] && A->f[2 * j + 1] == f[1]))
            return;
    int m = 0;
    for (int j = 0; j < A->n; j++) {
        if (dominates(f, A->f + 2 * j))
            continue;
        if (m != j) {
            memcpy(A->x + (size_t)m * A->d, A->x + (size_t)j * A->d, sizeof(double) * (size_t)A->d);
            A->f[2 * m] = A->f[2 * j];
            A->f[2 * m + 1] = A->f[2 * j + 1];
        }
        m++;
    }
    memcpy(A->x + (size_t)m * A->d, x, sizeof(double) * (size_t)A->d);
    A->f[2 * m] = f[0];
    A->f[2 * m + 1] = f[1];
    A->n = m + 1;
}

/* The niche radii of the archive: (max - min) / 20 in each objective. */
static void archive_radii(const archive *A, double r[2])
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int j = 0; j < A->n; j++)
        for (int k = 0; k < 2; k++) {
            lo[k] = fmin(lo[k], A->f[2 * j + k]);
            hi[k] = fmax(hi[k], A->f[2 * j + k]);
        }
    r[0] = (hi[0] - lo[0]) / 20.0;
    r[1] = (hi[1] - lo[1]) / 20.0;
}

static int neighbours(const archive *A, int i, int j, const double r[2])
{
    return fabs(A->f[2 * j] - A->f[2 * i]) <= r[0] && fabs(A->f[2 * j + 1] - A->f[2 * i + 1]) <= r[1];
}

/* The niche counts: the members within the radii of each in both objectives, itself included. */
static void archive_niches(archive *A, const double r[2])
{
    for (int i = 0; i < A->n; i++) {
        int cnt = 0;
        for (int j = 0; j < A->n; j++)
            cnt += neighbours(A, i, j, r);
        A->w[i] = cnt;
    }
}

/* A member drawn by the roulette wheel with weights w_i (inverse: 1 / w_i). */
static int roulette(const archive *A, gsl_rng *rng, int inverse)
{
    double total = 0;
    for (int j = 0; j < A->n; j++)
        total += inverse ? 1.0 / A->w[j] : A->w[j];
    double u = gsl_rng_uniform(rng) * total, acc = 0;
    for (int j = 0; j < A->n; j++) {
        acc += inverse ? 1.0 / A->w[j] : A->w[j];
        if (u < acc)
            return j;
    }
    return A->n - 1;
}

/* Cut the archive to its size: remove crowded members one at a time, the niche counts of the
 * removed member's neighbours lowered by one (the radii as at the start of the cut). Then the
 * counts of the archive as it is, for the roulette wheels of the next iteration. */
static void archive_cut(archive *A, gsl_rng *rng)
{
    double r[2];
    archive_radii(A, r);
    archive_niches(A, r);
    while (A->n > A->cap) {
        int j = roulette(A, rng, 0);
        for (int i = 0; i < A->n; i++)
            if (i != j && neighbours(A, i, j, r))
                A->w[i] -= 1.0;
        int last = A->n - 1;
        if (j != last) {
            memmove(A->x + (size_t)j * A->d, A->x + (size_t)(j + 1) * A->d,
                    sizeof(double) * (size_t)A->d * (size_t)(last - j));
            memmove(A->f + 2 * j, A->f + 2 * (j + 1), sizeof(double) * 2 * (size_t)(last - j));
            memmove(A->w + j, A->w + j + 1, sizeof(double) * (size_t)(last - j));
        }
        A->n--;
    }
    archive_radii(A, r);
    archive_niches(A, r);
}

gd_status opt_moalo(opt_ctx *c, const gd_opt_settings *s, gd_opt_result *r, gd_error *err)
{
    const int N = s->population, d = c->dim;
    const int T = gd_alo_iterations(c->budget, N);
    if (T < 1)
        return gd_error_set(err, GD_ERR_INPUT, "MOALO: budget %ld below two populations of %d", c->budget, N);
    if (c->nobj != 2)
        return gd_error_set(err, GD_ERR_INPUT, "MOALO: %d objectives (valid: 2)", c->nobj);
    const int nf = c->nf;
    archive A = {0, s->archive, d, NULL, NULL, NULL};
    size_t room = (size_t)(A.cap + N);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    A.x = malloc(sizeof(double) * room * (size_t)d);
    A.f = malloc(sizeof(double) * 2 * room);
    A.w = malloc(sizeof(double) * room);
    double *X = malloc(sizeof(double) * (size_t)N * (size_t)d);
    double *fs = malloc(sizeof(double) * (size_t)N);
    double *fv = malloc(sizeof(double) * (size_t)N * (size_t)nf);
    double *elite = malloc(sizeof(double) * (size_t)d);
    walk_byte tab[256];
    gd_status st = GD_OK;
    if (!rng || !A.x || !A.f || !A.w || !X || !fs || !fv || !elite) {
        st = gd_error_set(err, GD_ERR_NOMEM, "MOALO: out of memory for %d ants in %d dimensions", N, d);
        goto done;
    }
    opt_walk_table(tab);
    gsl_rng_set(rng, s->seed);
    for (size_t i = 0; i < (size_t)N * (size_t)d; i++)
        X[i] = 2.0 * gsl_rng_uniform(rng) - 1.0;
    int m;
    st = opt_eval_batch(c, X, N, fs, fv, s->threads, &m, err);
    if (st != GD_OK)
        goto done;
    int t = 0;
    for (;;) {
        for (int i = 0; i < m; i++) /* X clamped by the walks, so the archive holds what was evaluated */
            archive_add(&A, X + (size_t)i * d, fv + (size_t)i * nf);
        archive_cut(&A, rng);
        if (m < N || t == T)
            break; /* the budget ended inside this iteration, or the last one */
        t++;
        memcpy(elite, A.x + (size_t)roulette(&A, rng, 1) * d, sizeof(double) * (size_t)d);
        double w = 1.0 / gd_alo_ratio(t, T);
        for (int i = 0; i < N; i++) {
            const double *L = A.x + (size_t)roulette(&A, rng, 1) * d;
            double *x = X + (size_t)i * d;
            for (int k = 0; k < d; k++) {
                double ra = opt_walk(rng, tab, T, t, L[k] - w, L[k] + w);
                double re = opt_walk(rng, tab, T, t, elite[k] - w, elite[k] + w);
                double v = 0.5 * (ra + re);
                x[k] = v < -1.0 ? -1.0 : v > 1.0 ? 1.0 : v;
            }
        }
        st = opt_eval_batch(c, X, N, fs, fv, s->threads, &m, err);
        if (st != GD_OK)
            goto done;
    }
    r->iterations = t;
    /* the archive in physical units, sorted by f1 */
    r->narchive = A.n;
    r->archive_y = malloc(sizeof(double) * (size_t)(A.n > 0 ? A.n : 1) * (size_t)d);
    r->archive_f = malloc(sizeof(double) * 2 * (size_t)(A.n > 0 ? A.n : 1));
    int *idx = malloc(sizeof(int) * (size_t)(A.n > 0 ? A.n : 1));
    if (!r->archive_y || !r->archive_f || !idx) {
        free(idx);
        st = gd_error_set(err, GD_ERR_NOMEM, "MOALO: out of memory");
        goto done;
    }
    int na = gd_opt_nondominated(A.f, A.n, idx); /* the archive is non-dominated: only the order changes */
    for (int k = 0; k < na; k++) {
        opt_to_physical(c, A.x + (size_t)idx[k] * d, r->archive_y + (size_t)k * d);
        r->archive_f[2 * k] = A.f[2 * idx[k]];
        r->archive_f[2 * k + 1] = A.f[2 * idx[k] + 1];
    }
    r->narchive = na;
    r->archive_hv = gd_opt_hypervolume(r->archive_f, na, s->hv_ref);
    free(idx);
done:
    gsl_rng_free(rng);
    free(A.x);
    free(A.f);
    free(A.w);
    free(X);
    free(fs);
    free(fv);
    free(elite);
    return st;
}
