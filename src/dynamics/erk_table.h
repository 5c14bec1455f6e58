/* Internal: the explicit Butcher tables geardyn integrates with ERKStep (erk_table.c). */
#ifndef GD_ERK_TABLE_H
#define GD_ERK_TABLE_H

#include <stdio.h>
#include <arkode/arkode_butcher.h>

#include "compat/erk_fsal.h" /* gd_erk_table_fsal_safe: the table ERKStep integrates at its order */

const char *gd_erk_default_table(int order);
/* Classical RK4, made safe for ERKStep's FSAL test (gd_erk_table_fsal_safe; caller frees). */
ARKodeButcherTable gd_erk_classical_rk4(void);
/* An explicit table by name: Verner's 7(6), 8(7) and 9(8) pairs (compat/erk_verner.c before
 * SUNDIALS 7.3, ARKODE's own from 7.3: the same bits), else ARKODE's own (call only with a name
 * that one of them has: ARKODE prints on an unknown name). Caller frees. */
ARKodeButcherTable gd_erk_load(const char *name);

#endif
