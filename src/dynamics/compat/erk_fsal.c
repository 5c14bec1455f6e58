/* ERKStep's first-same-as-last defect, worked around (SUNDIALS before 6.7.0 only).
 *
 * Unnecessary from SUNDIALS 6.7.0 (LLNL/sundials PR #324, commit e659bb81: "Fixed a bug in
 * ERKStep where methods with c[s-1] = 1 but a[s-1,j] != b[j] were incorrectly treated as having
 * the first same as last (FSAL) property"); compiled only for older versions (compat/meson.build),
 * where erk_fsal.h's inline copy stands in.
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
#include "erk_fsal.h"

#include <math.h>

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
