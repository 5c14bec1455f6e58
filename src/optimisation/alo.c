/* The Ant Lion Optimizer (S. Mirjalili, The Ant Lion Optimizer, Adv. Eng. Softw. 83 (2015) 80-98),
 * the published algorithm in the normalised box [-1, 1]^d (docs/optimisation.md section 4):
 *
 *   antlions: N random points, evaluated; sorted; the best is the elite.
 *   for t = 1 .. T:
 *     for every ant i (random numbers drawn serially, in a fixed order):
 *       antlion j chosen by a roulette wheel on the ranks (weight N - rank: valid for any sign of f);
 *       R_A, R_E: random walks (cumulative sums of +-1 steps over T steps, Eq. 2.1) min-max
 *       normalised (Eq. 2.7) into [A_j + c_t, A_j + d_t] and [E + c_t, E + d_t], where
 *       c_t = -1 / I(t), d_t = +1 / I(t) (Eq. 2.8-2.11: the box shrunk by the ratio I and moved
 *       to the antlion), taken at step t;
 *       ant i = (R_A + R_E) / 2 (Eq. 2.13), clamped to the box;
 *     the ants are evaluated (in parallel);
 *     antlions := the N best of antlions and ants with their own fitness (Eq. 2.12: an antlion
 *     is replaced by a fitter ant); the elite is the best antlion (it is never lost).
 *
 * Evaluations: N (T + 1). */
#include "opt_internal.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

GD_API double gd_alo_ratio(int t, int T)
{
    double f = (double)t / (double)T;
    int w = 0;
    if (f > 0.95)
        w = 6;
    else if (f > 0.9)
        w = 5;
    else if (f > 0.75)
        w = 4;
    else if (f > 0.5)
        w = 3;
    else if (f > 0.1)
        w = 2;
    return w ? 1.0 + pow(10.0, w) * f : 1.0;
}

GD_API int gd_alo_iterations(long budget, int population)
{
    if (population < 1)
        return 0;
    long T = budget / population - 1;
    if (T < 1)
        return 0;
    return T > 100000000L ? 100000000 : (int)T;
}

/* Eight steps of a walk at once: sum of the steps (bit 1: +1, bit 0: -1) and the least and the
 * largest partial sum after each of the eight. */
void opt_walk_table(walk_byte tab[256])
{
    for (int v = 0; v < 256; v++) {
        int x = 0, lo = 1 << 20, hi = -(1 << 20);
        for (int b = 0; b < 8; b++) {
            x += (v >> b) & 1 ? 1 : -1;
            lo = x < lo ? x : lo;
            hi = x > hi ? x : hi;
        }
        tab[v].sum = (signed char)x;
        tab[v].lo = (signed char)lo;
        tab[v].hi = (signed char)hi;
    }
}

/* A random walk X_0 = 0, X_k = X_{k-1} +- 1 (k = 1 .. T, fair steps from the generator's bits),
 * min-max normalised into [c, d]; its value at step t. */
double opt_walk(gsl_rng *rng, const walk_byte *tab, int T, int t, double c, double d)
{
    long x = 0, lo = 0, hi = 0, xt = 0;
    int k = 0;           /* steps taken */
    unsigned long word = 0;
    int bits = 0;
    while (k < T) {
        if (bits < 8) {
            word = gsl_rng_get(rng) & 0xffffffffUL; /* MT19937: 32 random bits */
            bits = 32;
        }
        unsigned v = (unsigned)(word & 0xffu);
        word >>= 8;
        bits -= 8;
        if (k + 8 <= T && (t <= k || t > k + 8)) {
            lo = x + tab[v].lo < lo ? x + tab[v].lo : lo;
            hi = x + tab[v].hi > hi ? x + tab[v].hi : hi;
            x += tab[v].sum;
            k += 8;
            continue;
        }
        for (int b = 0; b < 8 && k < T; b++) {
            x += (v >> b) & 1u ? 1 : -1;
            k++;
            lo = x < lo ? x : lo;
            hi = x > hi ? x : hi;
            if (k == t)
                xt = x;
        }
    }
    if (t == 0)
        xt = 0;
    /* hi > lo: every step moves the walk (T >= 1) */
    return (double)(xt - lo) * (d - c) / (double)(hi - lo) + c;
}

typedef struct ranked {
    double f;
    int idx;             /* position in the pool: antlions first, then ants */
} ranked;

static int by_f(const void *a, const void *b)
{
    const ranked *x = a, *y = b;
    if (x->f < y->f)
        return -1;
    if (x->f > y->f)
        return 1;
    return x->idx - y->idx; /* ties: the older (antlion) first, then by index: a total order */
}

/* The arrays of a run: N antlions and N ants of d coordinates with their fitness, the pool
 * of the selection (2 N positions), the ranks and the roulette wheel. */
typedef struct alo_arrays {
    int N, d;
    size_t nd;
    double *lion, *ant, *pool, *flion, *fant, *cum;
    ranked *rk;
} alo_arrays;

/* Sort the evaluated initial antlions by fitness (pool and fant as scratch). */
static void alo_sort_antlions(alo_arrays *A)
{
    const int N = A->N, d = A->d;
    for (int i = 0; i < N; i++) {
        A->rk[i].f = A->flion[i];
        A->rk[i].idx = i;
    }
    qsort(A->rk, (size_t)N, sizeof *A->rk, by_f);
    for (int i = 0; i < N; i++) {
        memcpy(A->pool + (size_t)i * d, A->lion + (size_t)A->rk[i].idx * d, (size_t)d * sizeof(double));
        A->fant[i] = A->rk[i].f;
    }
    memcpy(A->lion, A->pool, A->nd * sizeof(double));
    memcpy(A->flion, A->fant, (size_t)N * sizeof(double));
}

/* The ants of iteration t: each walks around an antlion chosen by the roulette wheel and
 * around the elite (random numbers drawn serially, in a fixed order). */
static void alo_walk_ants(alo_arrays *A, gsl_rng *rng, const walk_byte *tab, int T, int t, double total)
{
    const int N = A->N, d = A->d;
    double w = 1.0 / gd_alo_ratio(t, T);
    const double *elite = A->lion; /* the antlions are sorted: the first is the elite */
    for (int i = 0; i < N; i++) {
        double u = gsl_rng_uniform(rng) * total;
        int j = 0;
        while (j < N - 1 && u >= A->cum[j])
            j++;
        const double *L = A->lion + (size_t)j * d;
        double *x = A->ant + (size_t)i * d;
        for (int k = 0; k < d; k++) {
            double ra = opt_walk(rng, tab, T, t, L[k] - w, L[k] + w);
            double re = opt_walk(rng, tab, T, t, elite[k] - w, elite[k] + w);
            double v = 0.5 * (ra + re);
            x[k] = v < -1.0 ? -1.0 : v > 1.0 ? 1.0 : v;
        }
    }
}

/* The new antlions: the N best of the antlions and the m evaluated ants, each with its own
 * fitness, sorted. */
static void alo_select(alo_arrays *A, int m)
{
    const int N = A->N, d = A->d;
    for (int i = 0; i < N; i++) {
        A->rk[i].f = A->flion[i];
        A->rk[i].idx = i;
    }
    for (int i = 0; i < m; i++) {
        A->rk[N + i].f = A->fant[i];
        A->rk[N + i].idx = N + i;
    }
    qsort(A->rk, (size_t)(N + m), sizeof *A->rk, by_f);
    for (int i = 0; i < N; i++) {
        int q = A->rk[i].idx;
        const double *src = q < N ? A->lion + (size_t)q * d : A->ant + (size_t)(q - N) * d;
        memcpy(A->pool + (size_t)i * d, src, (size_t)d * sizeof(double));
        A->pool[A->nd + (size_t)i] = A->rk[i].f; /* the fitness goes with its position */
    }
    memcpy(A->lion, A->pool, A->nd * sizeof(double));
    memcpy(A->flion, A->pool + A->nd, (size_t)N * sizeof(double));
}

gd_status opt_alo(opt_ctx *c, const gd_opt_settings *s, gd_opt_result *r, gd_error *err)
{
    const int N = s->population, d = c->dim;
    const int T = gd_alo_iterations(c->budget, N);
    if (T < 1)
        return gd_error_set(err, GD_ERR_INPUT, "ALO: budget %ld below two populations of %d", c->budget, N);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    alo_arrays A = {N, d, (size_t)N * (size_t)d, NULL, NULL, NULL, NULL, NULL, NULL, NULL};
    size_t nd = A.nd;
    A.lion = malloc(nd * sizeof(double));
    A.ant = malloc(nd * sizeof(double));
    A.pool = malloc(2 * nd * sizeof(double));
    A.flion = malloc((size_t)N * sizeof(double));
    A.fant = malloc((size_t)N * sizeof(double));
    A.rk = malloc(2 * (size_t)N * sizeof(ranked));
    A.cum = malloc((size_t)N * sizeof(double));
    walk_byte tab[256];
    gd_status st = GD_OK;
    if (!rng || !A.lion || !A.ant || !A.pool || !A.flion || !A.fant || !A.rk || !A.cum) {
        st = gd_error_set(err, GD_ERR_NOMEM, "ALO: out of memory for %d ants in %d dimensions", N, d);
        goto done;
    }
    opt_walk_table(tab);
    gsl_rng_set(rng, s->seed);
    /* the initial antlions, uniform in the box (the initial ants of the reference code are
     * overwritten by the first walks before they are evaluated: they are not drawn here) */
    for (size_t i = 0; i < nd; i++)
        A.lion[i] = 2.0 * gsl_rng_uniform(rng) - 1.0;
    int m;
    st = opt_eval_batch(c, A.lion, N, A.flion, NULL, s->threads, &m, err);
    if (st != GD_OK)
        goto done;
    if (m < N) { /* cannot happen: the budget holds two populations */
        st = gd_error_set(err, GD_ERR_INTERNAL, "ALO: the initial population was cut by the budget");
        goto done;
    }
    alo_sort_antlions(&A);
    /* rank weights of the roulette wheel: N for the best antlion down to 1 for the worst */
    double total = 0;
    for (int j = 0; j < N; j++) {
        total += (double)(N - j);
        A.cum[j] = total;
    }
    int t;
    for (t = 1; t <= T; t++) {
        alo_walk_ants(&A, rng, tab, T, t, total);
        st = opt_eval_batch(c, A.ant, N, A.fant, NULL, s->threads, &m, err);
        if (st != GD_OK)
            goto done;
        alo_select(&A, m);
        if (m < N)
            break; /* the budget ended inside this iteration */
    }
    r->iterations = t > T ? T : t;
done:
    gsl_rng_free(rng);
    free(A.lion);
    free(A.ant);
    free(A.pool);
    free(A.flion);
    free(A.fant);
    free(A.rk);
    free(A.cum);
    return st;
}
