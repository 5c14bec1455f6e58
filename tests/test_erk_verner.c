/* Verner's 7(6), 8(7) and 9(8) pairs as geardyn integrates them (gd_erk_load: its own tables,
 * src/dynamics/compat/erk_verner.c, with SUNDIALS before 7.3; ARKODE's by name from 7.3).
 *
 * 1. They satisfy the order conditions that every digit of them enters: consistency of the
 *    nodes (c_i = sum_j a_ij), the quadrature conditions sum_i b_i c_i^k = 1/(k+1) up to k = q-1,
 *    and sum_i b_i sum_j a_ij c_j^k = 1/((k+1)(k+2)) up to k = q-2; the same for the embedded
 *    weights d with the order p. A mistyped coefficient breaks one of them by far more than the
 *    rounding of the published digits (below 1e-12 with coefficients up to 120 in size).
 * 2. They are the same bits on every SUNDIALS version: a fingerprint (FNV-1a) of the stages,
 *    orders and every coefficient equals the one recorded from erk_verner.c. Before 7.3 this
 *    proves erk_verner.c unchanged; from 7.3 that ARKODE's tables are geardyn's bit for bit, the
 *    ground for compiling erk_verner.c only before 7.3 (ARKODE 6.7 to 7.2 rounds 15 and 16
 *    coefficients of the 7(6) and 8(7) pairs differently; LLNL/sundials PR #675 in 7.3.0).
 * The orders the methods reach in integration are measured in test_erk_tables.c. */
#include "tap.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <arkode/arkode_butcher.h>

#include "core/hash.h"
#include "dynamics/compat/erk_verner.h"
#include "dynamics/erk_table.h"

/* recorded from erk_verner.c (SUNDIALS 6.4.1, x86-64): change only with the tables */
#define FP_10_6_7 0x3c7921a6fd4043e5ULL
#define FP_13_7_8 0x39d2c2cbeed7e670ULL
#define FP_16_8_9 0x09b61d7cf6b9e775ULL

static double ipow(double x, int k)
{
    double r = 1.0;
    for (int i = 0; i < k; i++)
        r *= x;
    return r;
}

/* the largest violation of the conditions above for weights w of order ord */
static double violation(ARKodeButcherTable B, const double *w, int ord)
{
    int s = B->stages;
    double worst = 0.0;
    for (int k = 0; k <= ord - 1; k++) {
        double sum = 0.0;
        for (int i = 0; i < s; i++)
            sum += w[i] * ipow(B->c[i], k);
        worst = fmax(worst, fabs(sum - 1.0 / (k + 1)));
    }
    for (int k = 0; k <= ord - 2; k++) {
        double sum = 0.0;
        for (int i = 0; i < s; i++)
            for (int j = 0; j < i; j++)
                sum += w[i] * B->A[i][j] * ipow(B->c[j], k);
        worst = fmax(worst, fabs(sum - 1.0 / ((k + 1) * (k + 2))));
    }
    return worst;
}

/* FNV-1a of the stages, the orders and the bits of c, b, d and A (every entry, zeros included) */
static uint64_t fingerprint(ARKodeButcherTable B)
{
    int s = B->stages, head[3] = {B->stages, B->q, B->p};
    uint64_t h = gd_fnv1a(GD_FNV1A_OFFSET_BASIS, head, sizeof head);
    h = gd_fnv1a(h, B->c, sizeof(double) * (size_t)s);
    h = gd_fnv1a(h, B->b, sizeof(double) * (size_t)s);
    if (B->d)
        h = gd_fnv1a(h, B->d, sizeof(double) * (size_t)s);
    for (int i = 0; i < s; i++)
        h = gd_fnv1a(h, B->A[i], sizeof(double) * (size_t)s);
    return h;
}

int main(void)
{
    const struct { const char *name; int stages, q, p; uint64_t fp; } t[] = {
        {"ARKODE_VERNER_10_6_7", 10, 7, 6, FP_10_6_7},
        {"ARKODE_VERNER_13_7_8", 13, 8, 7, FP_13_7_8},
        {"ARKODE_VERNER_16_8_9", 16, 9, 8, FP_16_8_9}};
    const char *from = GD_SUNDIALS_AT_LEAST(7, 3) ? "ARKODE's table" : "geardyn's table";
    for (int k = 0; k < 3; k++) {
        ARKodeButcherTable B = gd_erk_load(t[k].name);
        tap_ok(B && B->stages == t[k].stages && B->q == t[k].q && B->p == t[k].p, "%s (%s): %d stages, order %d(%d)",
               t[k].name, from, B ? B->stages : -1, B ? B->q : -1, B ? B->p : -1);
        if (!B)
            continue;
        uint64_t fp = fingerprint(B);
        tap_ok(fp == t[k].fp, "%s (%s): the same bits on every SUNDIALS version (fingerprint %016llx, recorded "
               "%016llx)", t[k].name, from, (unsigned long long)fp, (unsigned long long)t[k].fp);
        double rows = 0.0;
        int explicit_ok = 1;
        for (int i = 0; i < B->stages; i++) {
            double sum = 0.0;
            for (int j = 0; j < B->stages; j++) {
                if (j >= i && B->A[i][j] != 0.0)
                    explicit_ok = 0;
                sum += B->A[i][j];
            }
            rows = fmax(rows, fabs(sum - B->c[i]));
        }
        tap_ok(explicit_ok && rows < 1e-13, "%s: explicit, nodes are the row sums (largest difference %.2g)",
               t[k].name, rows);
        double vb = violation(B, B->b, B->q), vd = violation(B, B->d, B->p);
        tap_ok(vb < 1e-12, "%s: order-%d conditions on b hold (largest violation %.2g)", t[k].name, B->q, vb);
        tap_ok(vd < 1e-12, "%s: order-%d conditions on the embedded d hold (largest violation %.2g)", t[k].name, B->p,
               vd);
        /* a condition of one order higher fails: the check can tell */
        double over = violation(B, B->d, B->p + 1);
        tap_ok(over > 1e-8, "%s: the embedded d does not reach order %d (violation %.2g): the check discriminates",
               t[k].name, B->p + 1, over);
        ARKodeButcherTable_Free(B);
    }
#if !GD_SUNDIALS_AT_LEAST(7, 3) /* from 7.3 every name is ARKODE's */
    tap_ok(gd_erk_verner("ARKODE_FEHLBERG_13_7_8") == NULL && !gd_erk_verner_known("ARKODE_VERNER_8_5_6"),
           "names that are ARKODE's own are not taken");
#endif
    return tap_done();
}
