/* Explicit Butcher tables for ERKStep: the default table of each order, tables by name, and
 * classical RK4. The workarounds for older SUNDIALS versions they go through (ERKStep's FSAL
 * defect, Verner's pairs) are in compat/erk_fsal.c and compat/erk_verner.c. */
#include "geardyn/gd_sim.h"

#include <stdio.h>
#include <arkode/arkode_butcher_erk.h>
#include <string.h>

#include "erk_table.h"
#include "compat/erk_verner.h"

const char *gd_erk_default_table(int order)
{
    switch (order) {
    case 2: return "ARKODE_HEUN_EULER_2_1_2";
    case 3: return "ARKODE_BOGACKI_SHAMPINE_4_2_3";
    case 4: return "ARKODE_ZONNEVELD_5_3_4";
    case 5: return "ARKODE_CASH_KARP_6_4_5"; /* SUNDIALS 6.4 default; fewer steps than DP on bta */
    case 6: return "ARKODE_VERNER_8_5_6";
    case 7: return "ARKODE_VERNER_10_6_7";   /* compat/erk_verner.c before SUNDIALS 7.3 */
    case 8: return "ARKODE_VERNER_13_7_8";   /* the same; docs/accuracy.md: fewer steps and 5-15x smaller
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
