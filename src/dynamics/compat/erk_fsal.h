/* Internal: explicit Butcher tables that ERKStep integrates at their nominal order, whatever
 * the SUNDIALS version (erk_fsal.c). */
#ifndef GD_ERK_FSAL_H
#define GD_ERK_FSAL_H

#include "sundials_compat.h"

#include <arkode/arkode_butcher.h>

#if GD_SUNDIALS_AT_LEAST(6, 7)
/* 6.7.0 and later: ERKStep treats a table as FSAL only when it is (LLNL/sundials PR #324): a copy */
static inline ARKodeButcherTable gd_erk_table_fsal_safe(ARKodeButcherTable B)
{
    return B ? ARKodeButcherTable_Copy(B) : NULL;
}
#else
/* A copy of B that ERKStep integrates at its nominal order (caller frees): erk_fsal.c */
ARKodeButcherTable gd_erk_table_fsal_safe(ARKodeButcherTable B);
#endif

#endif
