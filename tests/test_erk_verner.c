/* Verner's tables (src/dynamics/erk_verner.c) satisfy the order conditions that every digit of
 * them enters: consistency of the nodes (c_i = sum_j a_ij), the quadrature conditions
 * sum_i b_i c_i^k = 1/(k+1) up to k = q-1, and sum_i b_i sum_j a_ij c_j^k = 1/((k+1)(k+2)) up to
 * k = q-2; the same for the embedded weights d with the order p. A mistyped coefficient breaks
 * one of them by far more than the rounding of the published digits (below 1e-12 with
 * coefficients up to 120 in size). The orders the
 * methods reach in integration are measured in test_erk_tables.c. */
#include "tap.h"

#include <math.h>
#include <stdio.h>
#include <arkode/arkode_butcher.h>

#include "erk_table.h"

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

int main(void)
{
    const struct { const char *name; int stages, q, p; } t[] = {
        {"ARKODE_VERNER_10_6_7", 10, 7, 6}, {"ARKODE_VERNER_13_7_8", 13, 8, 7}, {"ARKODE_VERNER_16_8_9", 16, 9, 8}};
    for (int k = 0; k < 3; k++) {
        ARKodeButcherTable B = gd_erk_verner(t[k].name);
        tap_ok(B && B->stages == t[k].stages && B->q == t[k].q && B->p == t[k].p, "%s: %d stages, order %d(%d)",
               t[k].name, B ? B->stages : -1, B ? B->q : -1, B ? B->p : -1);
        if (!B)
            continue;
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
    tap_ok(gd_erk_verner("ARKODE_FEHLBERG_13_7_8") == NULL && !gd_erk_verner_known("ARKODE_VERNER_8_5_6"),
           "names that are ARKODE's own are not taken");
    return tap_done();
}
