/* Internal: SUNDIALS 6.x's step-size adaptivity and default DIRK tables, restored on 7.3.0 and
 * later (arkode_6x_defaults.c); nothing to do before 7.3 (the inline stand-ins below). */
#ifndef GD_ARKODE_6X_DEFAULTS_H
#define GD_ARKODE_6X_DEFAULTS_H

#include "sundials_compat.h"

#include <stddef.h>

#if GD_SUNDIALS_AT_LEAST(7, 3)
/* Give the integrator mem (ERKStep, or ARKStep when implicit) 6.x's controller, safety factor,
 * fixed-step bounds and adaptivity adjustment. *controller receives the controller, to be
 * released with gd_arkode_6x_free after the integrator. Returns an ARKODE flag (< 0: failure). */
int gd_arkode_6x_adaptivity(void *mem, SUNContext ctx, int implicit, void **controller);
void gd_arkode_6x_free(void **controller);
/* 6.x's default DIRK table of an order (2 to 5), else NULL */
const char *gd_arkode_6x_dirk_table(int order);
#else
static inline int gd_arkode_6x_adaptivity(void *mem, SUNContext ctx, int implicit, void **controller)
{
    *controller = NULL;
    return 0;
}
static inline void gd_arkode_6x_free(void **controller) { *controller = NULL; }
static inline const char *gd_arkode_6x_dirk_table(int order) { return NULL; }
#endif

#endif
