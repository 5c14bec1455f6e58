/* Two objectives: the non-dominated set of the points evaluated so far, kept sorted by the first
 * objective, and the hypervolume it dominates within a reference point (docs/optimisation.md
 * section 13). Minimisation throughout: a dominates b when a1 <= b1 and a2 <= b2, one strictly. */
#include "opt_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- the front of a run ---------------------------------------------------------------------- */

void opt_front_free(opt_front *F)
{
    free(F->y);
    free(F->f);
    memset(F, 0, sizeof *F);
}

static int front_grow(opt_front *F)
{
    if (F->n < F->cap)
        return 1;
    int cap = F->cap ? 2 * F->cap : 64;
    double *y = realloc(F->y, sizeof(double) * (size_t)cap * (size_t)(F->dim > 0 ? F->dim : 1));
    if (!y)
        return 0;
    F->y = y;
    double *f = realloc(F->f, sizeof(double) * 2 * (size_t)cap);
    if (!f)
        return 0;
    F->f = f;
    F->cap = cap;
    return 1;
}

/* The first index whose f1 is above v (the points are sorted by f1 increasing, f2 decreasing). */
static int upper_bound(const opt_front *F, double v)
{
    int lo = 0, hi = F->n;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (F->f[2 * mid] <= v)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* The area point i adds to the staircase of the points before it within ref: (r1 - a_i)(b_{i-1} - b_i)
 * with both coordinates clipped to the reference (b_{-1} = r2). */
static double contribution(const opt_front *F, int i)
{
    if (i < 0 || i >= F->n)
        return 0.0;
    double a = fmin(F->f[2 * i], F->ref[0]), b = fmin(F->f[2 * i + 1], F->ref[1]);
    double prev = i > 0 ? fmin(F->f[2 * (i - 1) + 1], F->ref[1]) : F->ref[1];
    return (F->ref[0] - a) * (prev - b);
}

int opt_front_insert(opt_front *F, const double *y, const double f[2])
{
    /* dominated (or equal) when the last point with f1 <= f[0] has f2 <= f[1] */
    int k = upper_bound(F, f[0]);
    if (k > 0 && F->f[2 * (k - 1) + 1] <= f[1])
        return 0;
    /* the points it dominates follow k - 1 (f1 >= f[0], the one with f1 == f[0] had f2 > f[1]) ... */
    int first = k > 0 && F->f[2 * (k - 1)] == f[0] ? k - 1 : k, last = first;
    while (last < F->n && F->f[2 * last + 1] >= f[1])
        last++;
    /* ... the run [first, last): replaced by the new point; the areas of those and of the point after
     * them (whose predecessor changes) go, the new point's and its successor's come */
    for (int i = first; i <= last; i++)
        F->hv -= contribution(F, i);
    int removed = last - first;
    if (removed == 0 && !front_grow(F))
        return -1;
    int d = F->dim;
    if (removed != 1) {
        memmove(F->f + 2 * (first + 1), F->f + 2 * last, sizeof(double) * 2 * (size_t)(F->n - last));
        if (d > 0)
            memmove(F->y + (size_t)(first + 1) * d, F->y + (size_t)last * d,
                    sizeof(double) * (size_t)d * (size_t)(F->n - last));
        F->n += 1 - removed;
    }
    F->f[2 * first] = f[0];
    F->f[2 * first + 1] = f[1];
    if (d > 0)
        memcpy(F->y + (size_t)first * d, y, sizeof(double) * (size_t)d);
    F->hv += contribution(F, first) + contribution(F, first + 1);
    return 1;
}

double opt_front_hv(const opt_front *F)
{
    double hv = 0;
    for (int i = 0; i < F->n; i++)
        hv += contribution(F, i);
    return hv;
}

/* ---- public ---------------------------------------------------------------------------------- */

typedef struct fi {
    double f1, f2;
    int i;
} fi;

static int by_f1(const void *a, const void *b)
{
    const fi *x = a, *y = b;
    if (x->f1 != y->f1)
        return x->f1 < y->f1 ? -1 : 1;
    if (x->f2 != y->f2)
        return x->f2 < y->f2 ? -1 : 1;
    return x->i - y->i;
}

GD_API int gd_opt_nondominated(const double *f, int n, int *idx)
{
    if (n <= 0)
        return 0;
    fi *v = malloc(sizeof *v * (size_t)n);
    if (!v)
        return -1;
    for (int i = 0; i < n; i++)
        v[i] = (fi){f[2 * i], f[2 * i + 1], i};
    qsort(v, (size_t)n, sizeof *v, by_f1);
    int m = 0;
    double best2 = INFINITY;
    for (int i = 0; i < n; i++)
        if (v[i].f2 < best2) { /* sorted by f1 (ties by f2): a point is kept when it lowers the best f2 */
            best2 = v[i].f2;
            idx[m++] = v[i].i;
        }
    free(v);
    return m;
}

GD_API double gd_opt_hypervolume(const double *f, int n, const double ref[2])
{
    if (n <= 0)
        return 0.0;
    int *idx = malloc(sizeof(int) * (size_t)n);
    if (!idx)
        return NAN;
    int m = gd_opt_nondominated(f, n, idx);
    double hv = 0, prev2 = ref[1];
    for (int k = 0; k < m; k++) {
        double a = f[2 * idx[k]], b = f[2 * idx[k] + 1];
        if (a >= ref[0])
            break;
        if (b >= prev2)
            continue;
        hv += (ref[0] - a) * (prev2 - b);
        prev2 = b;
    }
    free(idx);
    return hv;
}
