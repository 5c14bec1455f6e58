/* Internal: Verner's 7(6), 8(7) and 9(8) pairs with the digits of ARKODE 7.3 (erk_verner.c),
 * for the SUNDIALS versions whose ARKODE lacks them or rounds them differently. */
#ifndef GD_ERK_VERNER_H
#define GD_ERK_VERNER_H

#include "sundials_compat.h"

#include <stddef.h>
#include <arkode/arkode_butcher.h>

#if GD_SUNDIALS_AT_LEAST(7, 3)
/* 7.3.0 and later: ARKODE's own tables by name are these, bit for bit (LLNL/sundials PR #675) */
static inline ARKodeButcherTable gd_erk_verner(const char *name) { return NULL; }
static inline int gd_erk_verner_known(const char *name) { return 0; }
#else
/* The table of that name (ARKODE_VERNER_10_6_7, _13_7_8, _16_8_9), else NULL; caller frees */
ARKodeButcherTable gd_erk_verner(const char *name);
/* 1 if name is one of them */
int gd_erk_verner_known(const char *name);
#endif

#endif
