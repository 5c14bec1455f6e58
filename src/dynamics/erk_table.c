/* Explicit Butcher tables for ERKStep, with a workaround for SUNDIALS 6.4.1.
 *
 * ERKStep 6.4.1 decides whether the last stage of a step can be reused as the first
 * stage of the next (first same as last, FSAL) from c[s-1] == 1 alone. For tables
 * whose last node is 1 but whose last row is not the weights b (classical RK4,
 * ARKODE_VERNER_8_5_6, ARKODE_SAYFY_ABURUB_6_3_4, the ARK*_ERK tables, ...) it then
 * reuses f at the wrong state, and the method silently loses orders (Verner 6 runs at
 * order 3, RK4 at order 3; tests/test_erk_tables.c measures it). The fix here appends
 * one stage with A[s][:] = b, c[s] = 1, b[s] = d[s] = 0: the solution is unchanged and
 * the new last stage is exactly f(t_{n+1}, y_{n+1}), so the reuse becomes correct and
 * costs nothing. */
#include "geardyn/gd_sim.h"

#include <math.h>
#include <stdio.h>
#include <arkode/arkode_butcher_erk.h>
#include <string.h>

#include "erk_table.h"

const char *gd_erk_default_table(int order)
{
    switch (order) {
    case 2: return "ARKODE_HEUN_EULER_2_1_2";
    case 3: return "ARKODE_BOGACKI_SHAMPINE_4_2_3";
    case 4: return "ARKODE_ZONNEVELD_5_3_4";
    case 5: return "ARKODE_CASH_KARP_6_4_5"; /* SUNDIALS 6.4 default; fewer steps than DP on bta */
    case 6: return "ARKODE_VERNER_8_5_6";
    case 7: return "ARKODE_VERNER_10_6_7";   /* erk_verner.c */
    case 8: return "ARKODE_VERNER_13_7_8";   /* erk_verner.c; docs/accuracy.md: fewer steps and 5-15x smaller
                                              * Poincare errors than Fehlberg 7(8) at equal rtol */
    default: return NULL;
    }
}

ARKodeButcherTable gd_erk_load(const char *name)
{
    if (gd_erk_verner_known(name))
        return gd_erk_verner(name);
    return ARKodeButcherTable_LoadERKByName(name);
}

static int needs_fix(ARKodeButcherTable B)
{
    int s = B->stages;
    if (fabs(B->c[s - 1] - 1.0) > 1e-14)
        return 0;
    for (int j = 0; j < s; j++)
        if (B->A[s - 1][j] != B->b[j])
            return 1;
    return 0;
}

ARKodeButcherTable gd_erk_table_fsal_safe(ARKodeButcherTable B)
{
    if (!B)
        return NULL;
    if (!needs_fix(B))
        return ARKodeButcherTable_Copy(B);
    int s = B->stages;
    int embedded = B->d != NULL;
    ARKodeButcherTable F = ARKodeButcherTable_Alloc(s + 1, embedded ? SUNTRUE : SUNFALSE);
    if (!F)
        return NULL;
    F->q = B->q;
    F->p = B->p;
    for (int i = 0; i < s; i++) {
        F->c[i] = B->c[i];
        F->b[i] = B->b[i];
        if (embedded)
            F->d[i] = B->d[i];
        for (int j = 0; j < s; j++)
            F->A[i][j] = B->A[i][j];
    }
    for (int j = 0; j < s; j++)
        F->A[s][j] = B->b[j];
    F->c[s] = 1.0;
    F->b[s] = 0.0;
    if (embedded)
        F->d[s] = 0.0;
    return F;
}

ARKodeButcherTable gd_erk_classical_rk4(void)
{
    ARKodeButcherTable B = ARKodeButcherTable_Alloc(4, SUNFALSE);
    if (!B)
        return NULL;
    B->q = 4;
    B->p = 0;
    B->c[0] = 0.0; B->c[1] = 0.5; B->c[2] = 0.5; B->c[3] = 1.0;
    B->A[1][0] = 0.5; B->A[2][1] = 0.5; B->A[3][2] = 1.0;
    B->b[0] = 1.0 / 6.0; B->b[1] = 1.0 / 3.0; B->b[2] = 1.0 / 3.0; B->b[3] = 1.0 / 6.0;
    ARKodeButcherTable F = gd_erk_table_fsal_safe(B);
    ARKodeButcherTable_Free(B);
    return F;
}
