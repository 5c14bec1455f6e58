/* The serial vector operations ARKODE calls at every step, compiled with geardyn.
 *
 * Not an API defect but a build one, in compat/ all the same and compiled for every version:
 * Debian 12's SUNDIALS 6.4.1 runs unoptimised (below). SUNDIALS' CMake added no optimisation
 * flags unless a build type was given until 7.0.0 made RelWithDebInfo the default build type
 * (LLNL/sundials PR #422); with an optimised SUNDIALS the file is unnecessary. It stays
 * selectable at run time: solver.vector_kernels = geardyn (the default) or sundials.
 *
 * Why this file exists (docs/performance.md, "Where the time goes"): Debian 12's SUNDIALS 6.4.1
 * is built without optimisation (-O0), and its serial vector kernels are 57 % of all
 * instructions of a bta run (N_VLinearCombination_Serial alone 44 %: about 2 300 instructions
 * per stage sum of 20-element vectors). SUNDIALS' vector interface is an operations table that a
 * program may fill with its own implementations (the documented route for custom N_Vectors);
 * gd_vector_use_compiled_ops puts these into the table of a serial vector, whose clones (every
 * vector ARKODE allocates) inherit it. Everything else, the data layout included, stays
 * SUNDIALS' serial vector.
 *
 * Each kernel performs, element by element, the same floating-point operations in the same
 * order as the serial vector of SUNDIALS 6.4.1, including the special cases it takes for
 * coefficients of +1 and -1 and for aliased arguments (which change the rounding: c*(x+y) is
 * not c*x + c*y). The results are therefore bit-for-bit those of the library's kernels, which
 * tests/test_vector_kernels.c checks operation by operation and on whole runs; only the speed
 * differs. solver.vector_kernels = sundials keeps the library's own table. */
#include "vector_kernels.h"

#include <math.h>
#include <string.h>

#define LEN(v) NV_LENGTH_S(v)

/* two doubles in one register (GCC and Clang vector extension; SSE2 on x86-64): lane-wise
 * multiply and add are the scalar operations, so the results keep their bits */
typedef double v2 __attribute__((vector_size(16)));
_Static_assert(sizeof(sunrealtype) == sizeof(double), "SUNDIALS built with double precision");
static inline v2 ld2(const sunrealtype *p)
{
    v2 r;
    memcpy(&r, p, sizeof r);
    return r;
}
static inline void st2(sunrealtype *p, v2 a) { memcpy(p, &a, sizeof a); }
#define DAT(v) NV_DATA_S(v)

/* z = a x + b y, with the library's special cases (each changes the rounding or the aliasing) */
static void k_linearsum(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z)
{
    const sunindextype n = LEN(x);
    sunrealtype *xd = DAT(x), *yd = DAT(y), *zd = DAT(z);
    if (z == y && b == 1.0) { /* y += a x */
        if (a == 1.0)
            for (sunindextype i = 0; i < n; i++) yd[i] += xd[i];
        else if (a == -1.0)
            for (sunindextype i = 0; i < n; i++) yd[i] -= xd[i];
        else
            for (sunindextype i = 0; i < n; i++) yd[i] += a * xd[i];
        return;
    }
    if (z == x && a == 1.0) { /* x += b y */
        if (b == 1.0)
            for (sunindextype i = 0; i < n; i++) xd[i] += yd[i];
        else if (b == -1.0)
            for (sunindextype i = 0; i < n; i++) xd[i] -= yd[i];
        else
            for (sunindextype i = 0; i < n; i++) xd[i] += b * yd[i];
        return;
    }
    if (a == 1.0 && b == 1.0) {
        for (sunindextype i = 0; i < n; i++) zd[i] = xd[i] + yd[i];
        return;
    }
    if (a == 1.0 && b == -1.0) {
        for (sunindextype i = 0; i < n; i++) zd[i] = xd[i] - yd[i];
        return;
    }
    if (a == -1.0 && b == 1.0) {
        for (sunindextype i = 0; i < n; i++) zd[i] = yd[i] - xd[i];
        return;
    }
    if (a == 1.0) { /* b y + x */
        for (sunindextype i = 0; i < n; i++) zd[i] = (b * yd[i]) + xd[i];
        return;
    }
    if (b == 1.0) { /* a x + y */
        for (sunindextype i = 0; i < n; i++) zd[i] = (a * xd[i]) + yd[i];
        return;
    }
    if (a == -1.0) { /* b y - x */
        for (sunindextype i = 0; i < n; i++) zd[i] = (b * yd[i]) - xd[i];
        return;
    }
    if (b == -1.0) { /* a x - y */
        for (sunindextype i = 0; i < n; i++) zd[i] = (a * xd[i]) - yd[i];
        return;
    }
    if (a == b) {
        for (sunindextype i = 0; i < n; i++) zd[i] = a * (xd[i] + yd[i]);
        return;
    }
    if (a == -b) {
        for (sunindextype i = 0; i < n; i++) zd[i] = a * (xd[i] - yd[i]);
        return;
    }
    for (sunindextype i = 0; i < n; i++) zd[i] = (a * xd[i]) + (b * yd[i]);
}

static void k_const(sunrealtype c, N_Vector z)
{
    const sunindextype n = LEN(z);
    sunrealtype *zd = DAT(z);
    for (sunindextype i = 0; i < n; i++) zd[i] = c;
}

static void k_prod(N_Vector x, N_Vector y, N_Vector z)
{
    const sunindextype n = LEN(x);
    sunrealtype *xd = DAT(x), *yd = DAT(y), *zd = DAT(z);
    for (sunindextype i = 0; i < n; i++) zd[i] = xd[i] * yd[i];
}

static void k_div(N_Vector x, N_Vector y, N_Vector z)
{
    const sunindextype n = LEN(x);
    sunrealtype *xd = DAT(x), *yd = DAT(y), *zd = DAT(z);
    for (sunindextype i = 0; i < n; i++) zd[i] = xd[i] / yd[i];
}

/* z[i] = F(x[i]) element by element, two at a time (each lane the scalar operation) */
#define ELEMENTWISE(n, xd, zd, F)                                                                                  \
    do {                                                                                                           \
        sunindextype i_ = 0;                                                                                       \
        for (; i_ + 2 <= (n); i_ += 2) {                                                                           \
            v2 x_ = ld2((xd) + i_);                                                                                \
            st2((zd) + i_, F(x_));                                                                                 \
        }                                                                                                          \
        for (; i_ < (n); i_++)                                                                                     \
            (zd)[i_] = F((xd)[i_]);                                                                                \
    } while (0)
#define F_SCALE(x) (c * (x))
#define F_NEG(x) (-(x))
#define F_INV(x) (1.0 / (x))

static void k_scale(sunrealtype c, N_Vector x, N_Vector z)
{
    const sunindextype n = LEN(x);
    sunrealtype *xd = DAT(x), *zd = DAT(z);
    if (z == x)
        ELEMENTWISE(n, xd, xd, F_SCALE);
    else if (c == 1.0) /* a copy: ARKODE's N_VScale(1, x, z) at every step */
        memcpy(zd, xd, (size_t)n * sizeof *zd);
    else if (c == -1.0)
        ELEMENTWISE(n, xd, zd, F_NEG);
    else
        ELEMENTWISE(n, xd, zd, F_SCALE);
}

static void k_abs(N_Vector x, N_Vector z)
{
    const sunindextype n = LEN(x);
    sunrealtype *xd = DAT(x), *zd = DAT(z);
    for (sunindextype i = 0; i < n; i++) zd[i] = fabs(xd[i]);
}

static void k_inv(N_Vector x, N_Vector z)
{
    const sunindextype n = LEN(x);
    sunrealtype *xd = DAT(x), *zd = DAT(z);
    ELEMENTWISE(n, xd, zd, F_INV);
}

static void k_addconst(N_Vector x, sunrealtype b, N_Vector z)
{
    const sunindextype n = LEN(x);
    sunrealtype *xd = DAT(x), *zd = DAT(z);
    for (sunindextype i = 0; i < n; i++) zd[i] = xd[i] + b;
}

static sunrealtype k_dotprod(N_Vector x, N_Vector y)
{
    const sunindextype n = LEN(x);
    const sunrealtype *xd = DAT(x), *yd = DAT(y);
    sunrealtype s = 0.0;
    for (sunindextype i = 0; i < n; i++) s += xd[i] * yd[i];
    return s;
}

static sunrealtype k_maxnorm(N_Vector x)
{
    const sunindextype n = LEN(x);
    const sunrealtype *xd = DAT(x);
    sunrealtype m = 0.0;
    for (sunindextype i = 0; i < n; i++)
        if (fabs(xd[i]) > m)
            m = fabs(xd[i]);
    return m;
}

static sunrealtype k_wsqrsum(N_Vector x, N_Vector w)
{
    const sunindextype n = LEN(x);
    const sunrealtype *xd = DAT(x), *wd = DAT(w);
    sunrealtype s = 0.0;
    for (sunindextype i = 0; i < n; i++) {
        const sunrealtype p = xd[i] * wd[i];
        s += p * p;
    }
    return s;
}

static sunrealtype k_wrmsnorm(N_Vector x, N_Vector w)
{
    return sqrt(k_wsqrsum(x, w) / (sunrealtype)LEN(x));
}

static sunrealtype k_min(N_Vector x)
{
    const sunindextype n = LEN(x);
    const sunrealtype *xd = DAT(x);
    sunrealtype m = xd[0];
    for (sunindextype i = 1; i < n; i++)
        if (xd[i] < m)
            m = xd[i];
    return m;
}

/* The sum of k_linearcombination when z is none of X[1..]: z[j] = c[0] X[0][j] (or z[j] itself
 * when X[0] is z with c[0] = 1), then + c[i] X[i][j] for i = 1, 2, ... in this order. Each element
 * is an independent chain of the scalar operations, so computing several elements at once in the
 * lanes of a register (element-outer loop, one pass over the X[i] per block) keeps the bits. */
static void lc_sum_sse2(int nvec, const sunrealtype *c, const sunrealtype *const *xs, sunrealtype *zd, sunindextype n,
                        int skip)
{
    sunindextype j = 0;
    for (; j + 8 <= n; j += 8) {
        v2 a0, a1, a2, a3;
        if (skip) {
            a0 = ld2(zd + j), a1 = ld2(zd + j + 2), a2 = ld2(zd + j + 4), a3 = ld2(zd + j + 6);
        } else {
            const sunrealtype *x0 = xs[0] + j;
            const v2 c0 = {c[0], c[0]};
            a0 = c0 * ld2(x0), a1 = c0 * ld2(x0 + 2), a2 = c0 * ld2(x0 + 4), a3 = c0 * ld2(x0 + 6);
        }
        for (int i = 1; i < nvec; i++) {
            const v2 ci = {c[i], c[i]};
            const sunrealtype *xi = xs[i] + j;
            a0 += ci * ld2(xi), a1 += ci * ld2(xi + 2), a2 += ci * ld2(xi + 4), a3 += ci * ld2(xi + 6);
        }
        st2(zd + j, a0), st2(zd + j + 2, a1), st2(zd + j + 4, a2), st2(zd + j + 6, a3);
    }
    for (; j + 2 <= n; j += 2) {
        v2 a0 = skip ? ld2(zd + j) : (v2){c[0], c[0]} * ld2(xs[0] + j);
        for (int i = 1; i < nvec; i++) a0 += (v2){c[i], c[i]} * ld2(xs[i] + j);
        st2(zd + j, a0);
    }
    for (; j < n; j++) {
        sunrealtype acc = skip ? zd[j] : c[0] * xs[0][j];
        for (int i = 1; i < nvec; i++) acc += c[i] * xs[i][j];
        zd[j] = acc;
    }
}

/* z = sum c[i] X[i] with the vectors accumulated one after the other (vector-outer loop), as the
 * library does: with z one of the X[i] this order is part of the result. Returns 0. */
static int lc_vector_outer(int nvec, const sunrealtype *c, N_Vector *X, N_Vector z)
{
    const sunindextype n = LEN(z);
    sunrealtype *zd = DAT(z);
    if (X[0] == z) {
        if (c[0] != 1.0)
            for (sunindextype j = 0; j < n; j++) zd[j] *= c[0];
    } else {
        const sunrealtype *x0 = DAT(X[0]);
        for (sunindextype j = 0; j < n; j++) zd[j] = c[0] * x0[j];
    }
    for (int i = 1; i < nvec; i++) {
        const sunrealtype *xd = DAT(X[i]);
        const sunrealtype ci = c[i];
        for (sunindextype j = 0; j < n; j++) zd[j] += ci * xd[j];
    }
    return 0;
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define GD_HAVE_AVX_KERNEL 1
/* The same sum four lanes wide, for processors with AVX (chosen at run time). Separate
 * multiply and add instructions as above (AVX has no fused multiply-add; FMA is not enabled),
 * so the bits are those of the scalar chain. */
typedef double v4 __attribute__((vector_size(32)));
#define LD4(p) (__extension__({ v4 r_; memcpy(&r_, (p), sizeof r_); r_; }))
#define ST4(p, a) (__extension__({ v4 a_ = (a); memcpy((p), &a_, sizeof a_); }))
__attribute__((target("avx"))) static void lc_sum_avx(int nvec, const sunrealtype *c, const sunrealtype *const *xs,
                                                      sunrealtype *zd, sunindextype n, int skip)
{
    sunindextype j = 0;
    for (; j + 20 <= n; j += 20) { /* the bta state: one pass over the vectors */
        v4 a0, a1, a2, a3, a4;
        if (skip) {
            a0 = LD4(zd + j), a1 = LD4(zd + j + 4), a2 = LD4(zd + j + 8), a3 = LD4(zd + j + 12);
            a4 = LD4(zd + j + 16);
        } else {
            const sunrealtype *x0 = xs[0] + j;
            const v4 c0 = {c[0], c[0], c[0], c[0]};
            a0 = c0 * LD4(x0), a1 = c0 * LD4(x0 + 4), a2 = c0 * LD4(x0 + 8), a3 = c0 * LD4(x0 + 12);
            a4 = c0 * LD4(x0 + 16);
        }
        for (int i = 1; i < nvec; i++) {
            const v4 ci = {c[i], c[i], c[i], c[i]};
            const sunrealtype *xi = xs[i] + j;
            a0 += ci * LD4(xi), a1 += ci * LD4(xi + 4), a2 += ci * LD4(xi + 8), a3 += ci * LD4(xi + 12);
            a4 += ci * LD4(xi + 16);
        }
        ST4(zd + j, a0), ST4(zd + j + 4, a1), ST4(zd + j + 8, a2), ST4(zd + j + 12, a3);
        ST4(zd + j + 16, a4);
    }
    for (; j + 16 <= n; j += 16) {
        v4 a0, a1, a2, a3;
        if (skip) {
            a0 = LD4(zd + j), a1 = LD4(zd + j + 4), a2 = LD4(zd + j + 8), a3 = LD4(zd + j + 12);
        } else {
            const sunrealtype *x0 = xs[0] + j;
            const v4 c0 = {c[0], c[0], c[0], c[0]};
            a0 = c0 * LD4(x0), a1 = c0 * LD4(x0 + 4), a2 = c0 * LD4(x0 + 8), a3 = c0 * LD4(x0 + 12);
        }
        for (int i = 1; i < nvec; i++) {
            const v4 ci = {c[i], c[i], c[i], c[i]};
            const sunrealtype *xi = xs[i] + j;
            a0 += ci * LD4(xi), a1 += ci * LD4(xi + 4), a2 += ci * LD4(xi + 8), a3 += ci * LD4(xi + 12);
        }
        ST4(zd + j, a0), ST4(zd + j + 4, a1), ST4(zd + j + 8, a2), ST4(zd + j + 12, a3);
    }
    for (; j + 4 <= n; j += 4) {
        v4 a0;
        if (skip) {
            a0 = LD4(zd + j);
        } else {
            const v4 c0 = {c[0], c[0], c[0], c[0]};
            a0 = c0 * LD4(xs[0] + j);
        }
        for (int i = 1; i < nvec; i++) {
            const v4 ci = {c[i], c[i], c[i], c[i]};
            a0 += ci * LD4(xs[i] + j);
        }
        ST4(zd + j, a0);
    }
    for (; j < n; j++) {
        sunrealtype acc = skip ? zd[j] : c[0] * xs[0][j];
        for (int i = 1; i < nvec; i++) acc += c[i] * xs[i][j];
        zd[j] = acc;
    }
}

/* The same sum for the short vectors of the runs (n <= 20: the torsional and bta states), in one
 * pass that also reads the data pointers and tests the aliasing, with everything in registers
 * until the end: B blocks of four (B a constant in each copy, so the unused accumulators vanish)
 * and r = n - 4 B < 4 single elements. Returns 1, having written nothing, when z is one of
 * X[1..]. The operations of each element are those of lc_sum_avx, in the same order. */
#define LC_BLOCKS(OP)                                                                                              \
    do {                                                                                                           \
        if (B > 0) OP(a0, 0);                                                                                      \
        if (B > 1) OP(a1, 4);                                                                                      \
        if (B > 2) OP(a2, 8);                                                                                      \
        if (B > 3) OP(a3, 12);                                                                                     \
        if (B > 4) OP(a4, 16);                                                                                     \
    } while (0)
__attribute__((target("avx"), always_inline)) static inline int lc_short_avx(const int B, int nvec, const sunrealtype *c,
                                                                             N_Vector *X, N_Vector z, int r, int skip)
{
    sunrealtype *zd = DAT(z);
    const sunrealtype *p = skip ? zd : DAT(X[0]);
    const sunrealtype c0 = c[0];
    const v4 cv = {c0, c0, c0, c0};
    v4 a0 = {0}, a1 = {0}, a2 = {0}, a3 = {0}, a4 = {0};
    sunrealtype s0 = 0.0, s1 = 0.0, s2 = 0.0;
    const int t = 4 * B;
#define LC_FIRST(a, o) (a = skip ? LD4(p + (o)) : cv * LD4(p + (o)))
    LC_BLOCKS(LC_FIRST);
    if (r > 0) s0 = skip ? p[t] : c0 * p[t];
    if (r > 1) s1 = skip ? p[t + 1] : c0 * p[t + 1];
    if (r > 2) s2 = skip ? p[t + 2] : c0 * p[t + 2];
    for (int i = 1; i < nvec; i++) {
        if (X[i] == z)
            return 1;
        const sunrealtype ci = c[i];
        const v4 civ = {ci, ci, ci, ci};
        const sunrealtype *xi = DAT(X[i]);
#define LC_ADD(a, o) (a += civ * LD4(xi + (o)))
        LC_BLOCKS(LC_ADD);
        if (r > 0) s0 += ci * xi[t];
        if (r > 1) s1 += ci * xi[t + 1];
        if (r > 2) s2 += ci * xi[t + 2];
    }
#define LC_STORE(a, o) ST4(zd + (o), a)
    LC_BLOCKS(LC_STORE);
    if (r > 0) zd[t] = s0;
    if (r > 1) zd[t + 1] = s1;
    if (r > 2) zd[t + 2] = s2;
    return 0;
#undef LC_FIRST
#undef LC_ADD
#undef LC_STORE
}

/* The linear combination for n <= 20: lc_short_avx, one copy per number of blocks and one more
 * without single elements (r a constant 0 there: no test in the loop), or the vector-outer loop
 * when z is one of X[1..]. Returns 0. */
__attribute__((target("avx"))) static int lc_short_avx_n(int nvec, const sunrealtype *c, N_Vector *X, N_Vector z)
{
    const sunindextype n = LEN(z);
    const int r = (int)(n % 4), skip = X[0] == z && c[0] == 1.0;
    int aliased;
#define LC_COPY(B)                                                                                                 \
    (r ? lc_short_avx(B, nvec, c, X, z, r, skip) : lc_short_avx(B, nvec, c, X, z, 0, skip))
    switch (n / 4) {
    case 0: aliased = lc_short_avx(0, nvec, c, X, z, r, skip); break;
    case 1: aliased = LC_COPY(1); break;
    case 2: aliased = LC_COPY(2); break;
    case 3: aliased = LC_COPY(3); break;
    case 4: aliased = LC_COPY(4); break;
    default: aliased = LC_COPY(5); break;
    }
#undef LC_COPY
    return aliased ? lc_vector_outer(nvec, c, X, z) : 0;
}
#undef LC_BLOCKS
#endif

static int lc_narrow; /* 1: two lanes even where AVX is available (gd_vector_kernels_wide(0), for the tests) */

static void lc_sum(int nvec, const sunrealtype *c, const sunrealtype *const *xs, sunrealtype *zd, sunindextype n,
                   int skip)
{
#ifdef GD_HAVE_AVX_KERNEL
    if (!lc_narrow && __builtin_cpu_supports("avx")) {
        lc_sum_avx(nvec, c, xs, zd, n, skip);
        return;
    }
#endif
    lc_sum_sse2(nvec, c, xs, zd, n, skip);
}

/* z = sum c[i] X[i], bit for bit the library's vector-outer loop (lc_vector_outer) */
static int k_linearcombination(int nvec, sunrealtype *c, N_Vector *X, N_Vector z)
{
    if (nvec < 1)
        return -1;
    if (nvec == 1) {
        k_scale(c[0], X[0], z);
        return 0;
    }
    if (nvec == 2) {
        k_linearsum(c[0], X[0], c[1], X[1], z);
        return 0;
    }
    const sunindextype n = LEN(z);
#ifdef GD_HAVE_AVX_KERNEL
    if (n <= 20 && !lc_narrow && __builtin_cpu_supports("avx"))
        return lc_short_avx_n(nvec, c, X, z);
#endif
    sunrealtype *zd = DAT(z);
    enum { MAXV = 16 };
    if (nvec <= MAXV) { /* the data pointers and the aliasing test in one pass; z among X[1..]:
                         * the vector-outer loop below */
        const sunrealtype *xs[MAXV];
        xs[0] = DAT(X[0]);
        int i = 1;
        for (; i < nvec && X[i] != z; i++)
            xs[i] = DAT(X[i]);
        if (i == nvec) {
            lc_sum(nvec, c, xs, zd, n, X[0] == z && c[0] == 1.0);
            return 0;
        }
    }
    return lc_vector_outer(nvec, c, X, z);
}

/* Z[i] = Y[i] + a[i] x */
static int k_scaleaddmulti(int nvec, sunrealtype *a, N_Vector x, N_Vector *Y, N_Vector *Z)
{
    if (nvec < 1)
        return -1;
    if (nvec == 1) {
        k_linearsum(a[0], x, 1.0, Y[0], Z[0]);
        return 0;
    }
    const sunindextype n = LEN(x);
    const sunrealtype *xd = DAT(x);
    for (int i = 0; i < nvec; i++) {
        sunrealtype *yd = DAT(Y[i]);
        if (Y == Z) {
            for (sunindextype j = 0; j < n; j++) yd[j] += a[i] * xd[j];
        } else {
            sunrealtype *zd = DAT(Z[i]);
            for (sunindextype j = 0; j < n; j++) zd[j] = a[i] * xd[j] + yd[j];
        }
    }
    return 0;
}

int gd_vector_error_weights(N_Vector y, N_Vector w, double rtol, double atol)
{
    typedef unsigned long long u2 __attribute__((vector_size(16)));
    const sunrealtype *yd = DAT(y);
    sunrealtype *wd = DAT(w);
    const sunindextype n = LEN(y);
    const v2 r = {rtol, rtol}, a = {atol, atol}, one = {1.0, 1.0};
    const u2 magnitude = {0x7fffffffffffffffULL, 0x7fffffffffffffffULL}; /* fabs: the sign bit cleared */
    if (atol == 0.0) /* ARKODE's N_VMin test of the sums, made only then */
        for (sunindextype i = 0; i < n; i++)
            if (rtol * fabs(yd[i]) + atol <= 0.0)
                return -1;
    sunindextype i = 0;
    for (; i + 2 <= n; i += 2)
        st2(wd + i, one / (r * (v2)((u2)ld2(yd + i) & magnitude) + a));
    for (; i < n; i++)
        wd[i] = 1.0 / (rtol * fabs(yd[i]) + atol);
    return 0;
}

int gd_vector_kernels_wide(int on)
{
    lc_narrow = !on;
#ifdef GD_HAVE_AVX_KERNEL
    return on && __builtin_cpu_supports("avx");
#else
    return 0;
#endif
}

int gd_vector_use_compiled_ops(N_Vector v)
{
    if (!v || !v->ops || N_VGetVectorID(v) != SUNDIALS_NVEC_SERIAL)
        return -1;
    N_Vector_Ops o = v->ops;
    o->nvlinearsum = k_linearsum;
    o->nvconst = k_const;
    o->nvprod = k_prod;
    o->nvdiv = k_div;
    o->nvscale = k_scale;
    o->nvabs = k_abs;
    o->nvinv = k_inv;
    o->nvaddconst = k_addconst;
    o->nvdotprod = k_dotprod;
    o->nvdotprodlocal = k_dotprod;
    o->nvmaxnorm = k_maxnorm;
    o->nvmaxnormlocal = k_maxnorm;
    o->nvwrmsnorm = k_wrmsnorm;
    o->nvwsqrsumlocal = k_wsqrsum;
    o->nvmin = k_min;
    o->nvminlocal = k_min;
    o->nvlinearcombination = k_linearcombination;
    o->nvscaleaddmulti = k_scaleaddmulti;
    return 0;
}
