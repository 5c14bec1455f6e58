/* SUNDIALS 6.x's defaults of ARKODE's step-size adaptivity and DIRK tables, restored on
 * SUNDIALS 7.3.0 and later (compiled only there: compat/meson.build).
 *
 * SUNDIALS 7.3.0 made an I controller (safety factor 0.9, error bias 1, fixed-step bounds
 * [1, 1], adaptivity adjustment 0) the default step-size adaptivity (LLNL/sundials PR #565) and
 * newer tables the default DIRK methods (PR #547). geardyn's tolerances, documented orders and
 * results were measured with 6.x's defaults: ERKStep's PI controller (0.8, -0.31) with bias 1.2,
 * ARKStep's PID with bias 1.5 and safety factor 0.96, for both bounds [1, 1.5] and adjustment -1,
 * and the DIRK tables SDIRK_2_1_2, ARK324L2SA_DIRK_4_2_3, SDIRK_5_3_4, ARK548L2SA_DIRK_8_4_5 of
 * orders 2 to 5; this file sets them explicitly with the calls of 7.3.0's release notes, but for
 * one: their ERKStep recipe sets the safety factor 0.96, whereas ERKStep's own default, 0.99 in
 * 6.x, is still set by ERKStepCreate in 7.3 to 7.5 (erkStep_SetDefaults), so that it is left
 * alone. What it cannot restore:
 * 7.3.0's Soderlind controller starts as an I controller until it has a history (PR #548), and
 * ARK324L2SA_DIRK_4_2_3 has more precise digits from 7.3.0 (PR #675).
 *
 * Unnecessary once geardyn adopts the new defaults: when the oldest supported SUNDIALS is 7.3
 * and docs/accuracy.md's measurements are redone with them. */
#include "arkode_6x_defaults.h"

#include <arkode/arkode.h>
#include <sunadaptcontroller/sunadaptcontroller_soderlind.h>

int gd_arkode_6x_adaptivity(void *mem, SUNContext ctx, int implicit, void **controller)
{
    SUNAdaptController C = implicit ? SUNAdaptController_PID(ctx) : SUNAdaptController_Soderlind(ctx);
    *controller = C;
    if (!C)
        return ARK_MEM_FAIL;
    if (!implicit && SUNAdaptController_SetParams_PI(C, 0.8, -0.31) != SUN_SUCCESS)
        return ARK_ILL_INPUT;
    if (SUNAdaptController_SetErrorBias(C, implicit ? 1.5 : 1.2) != SUN_SUCCESS)
        return ARK_ILL_INPUT;
    int flag;
    if ((flag = ARKodeSetAdaptController(mem, C)) < 0 || (implicit && (flag = ARKodeSetSafetyFactor(mem, 0.96)) < 0) ||
        (flag = ARKodeSetFixedStepBounds(mem, 1.0, 1.5)) < 0 || (flag = ARKodeSetAdaptivityAdjustment(mem, -1)) < 0)
        return flag;
    return ARK_SUCCESS;
}

void gd_arkode_6x_free(void **controller)
{
    SUNAdaptController C = *controller;
    if (C)
        SUNAdaptController_Destroy(C);
    *controller = NULL;
}

const char *gd_arkode_6x_dirk_table(int order)
{
    switch (order) {
    case 2: return "ARKODE_SDIRK_2_1_2";
    case 3: return "ARKODE_ARK324L2SA_DIRK_4_2_3";
    case 4: return "ARKODE_SDIRK_5_3_4";
    case 5: return "ARKODE_ARK548L2SA_DIRK_8_4_5";
    default: return NULL;
    }
}
