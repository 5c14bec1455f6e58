/* Internal: explicit Butcher tables made safe for ERKStep 6.4.1 (see erk_table.c). */
#ifndef GD_ERK_TABLE_H
#define GD_ERK_TABLE_H

#include <stdio.h>
#include <arkode/arkode_butcher.h>

const char *gd_erk_default_table(int order);
/* A copy of B that ERKStep integrates at its nominal order (caller frees). */
ARKodeButcherTable gd_erk_table_fsal_safe(ARKodeButcherTable B);
ARKodeButcherTable gd_erk_classical_rk4(void);
/* An explicit table by name: Verner's 7(6), 8(7) and 9(8) pairs (erk_verner.c), else ARKODE's own
 * (call only with a name that one of them has: ARKODE prints on an unknown name). Caller frees. */
ARKodeButcherTable gd_erk_load(const char *name);
ARKodeButcherTable gd_erk_verner(const char *name);
int gd_erk_verner_known(const char *name);

#endif
