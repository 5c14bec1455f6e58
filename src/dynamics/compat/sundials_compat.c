/* The SUNContext with geardyn's error handler, for every SUNDIALS version (sundials_compat.h).
 *
 * Needed as long as geardyn supports both sides of SUNDIALS 7.0.0, which took a SUNComm in
 * SUNContext_Create (LLNL/sundials PR #370) and replaced the integrators' error handler
 * (ARKErrHandlerFn, ERKStepSetErrHandlerFn, ARKStepSetErrHandlerFn: PRs #373, #379, #398) by the
 * context's handler stack and logger; with 6.x gone, gd_sun_context_create is the 7.x branch. */
#include "sundials_compat.h"

#include <stdio.h>
#if GD_SUNDIALS_AT_LEAST(7, 0)
#include <sundials/sundials_logger.h>
#endif

#if GD_SUNDIALS_AT_LEAST(7, 0)
void gd_sun_err_handler(int line, const char *func, const char *file, const char *msg, SUNErrCode code, void *user,
                        SUNContext ctx)
{
    snprintf(user, GD_SUN_MSG_SIZE, "%s: %s", func ? func : "", msg ? msg : "");
}

int gd_sun_context_create(SUNContext *ctx, char *msg)
{
    *ctx = NULL;
    if (SUNContext_Create(GD_SUN_COMM_NULL, ctx) != 0)
        return -1;
    /* errors: geardyn's handler alone (the default one logs them to stderr); warnings, which
     * 6.x passed to the handler: to nowhere (the logger's default is stdout, and "" leaves it) */
    SUNLogger logger = NULL;
    if (SUNContext_ClearErrHandlers(*ctx) != 0 || SUNContext_PushErrHandler(*ctx, gd_sun_err_handler, msg) != 0 ||
        SUNContext_GetLogger(*ctx, &logger) != 0 ||
        (logger && SUNLogger_SetWarningFilename(logger, "/dev/null") != 0)) {
        SUNContext_Free(ctx);
        return -1;
    }
    return 0;
}
#else
void gd_sun_err_handler(int code, const char *module, const char *function, char *msg, void *user)
{
    snprintf(user, GD_SUN_MSG_SIZE, "%s %s: %s", module, function, msg);
}

int gd_sun_context_create(SUNContext *ctx, char *msg)
{
    *ctx = NULL;
    return SUNContext_Create(GD_SUN_COMM_NULL, ctx) == 0 ? 0 : -1;
}
#endif
