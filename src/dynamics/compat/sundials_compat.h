/* Internal: what differs between the SUNDIALS versions geardyn builds against (6.4.1, Debian 12
 * and CI, to 7.x), in one place: the version test, the first argument of SUNContext_Create, and
 * the context with geardyn's error handler.
 *
 * The rest of src/dynamics/ does not test the version. Each workaround of this folder is a file
 * whose first comment names the upstream change that makes it unnecessary; those needed by some
 * versions only are compiled only for them (compat/meson.build reads the version from
 * sundials_config.h at configure time, and their headers give the other versions an inline
 * stand-in), the others adapt with the #if below:
 *   stepper.c           the ERKStep/ARKStep entry points; ARKodeXxx from 7.1.0   always
 *   sundials_compat.c   context and error handler (7.0.0 moved the handler)      always
 *   vector_kernels.c    serial vector kernels compiled with geardyn (-O0 Debian)  always
 *   erk_fsal.c          ERKStep's FSAL defect, fixed in 6.7.0                     < 6.7
 *   erk_verner.c        Verner's 7(6), 8(7), 9(8) pairs, ARKODE's digits in 7.3.0 < 7.3
 *   arkode_6x_defaults.c  6.x's adaptivity and DIRK defaults, changed in 7.3.0     >= 7.3 */
#ifndef GD_SUNDIALS_COMPAT_H
#define GD_SUNDIALS_COMPAT_H

#include <sundials/sundials_config.h> /* SUNDIALS_VERSION_MAJOR, SUNDIALS_VERSION_MINOR */
#include <sundials/sundials_context.h>

/* 1 when the SUNDIALS headers are version major.minor or later */
#define GD_SUNDIALS_AT_LEAST(major, minor)                                                                         \
    (SUNDIALS_VERSION_MAJOR > (major) || (SUNDIALS_VERSION_MAJOR == (major) && SUNDIALS_VERSION_MINOR >= (minor)))

/* SUNContext_Create's communicator: a SUNComm from 7.0.0 (LLNL/sundials PR #370), a void * before */
#if GD_SUNDIALS_AT_LEAST(7, 0)
#define GD_SUN_COMM_NULL SUN_COMM_NULL
#else
#define GD_SUN_COMM_NULL NULL
#endif

/* the size of the buffer that receives SUNDIALS' last error message */
#define GD_SUN_MSG_SIZE 512

/* A SUNContext whose errors are written into msg (GD_SUN_MSG_SIZE bytes) and that prints
 * nothing: 6.x sends errors and warnings to the handler of each integrator (set with its table's
 * capture_errors, compat/stepper.h), 7.x to the context's handler stack (7.0.0, PRs #373, #379,
 * #398: ARKErrHandlerFn and *SetErrHandlerFn removed) and its warnings to its SUNLogger, which
 * prints them on stdout unless told otherwise. Returns 0, or -1 (nothing to free). */
int gd_sun_context_create(SUNContext *ctx, char *msg);

#if GD_SUNDIALS_AT_LEAST(7, 0)
/* 7.x: SUNErrHandlerFn, user data the message buffer */
void gd_sun_err_handler(int line, const char *func, const char *file, const char *msg, SUNErrCode code, void *user,
                        SUNContext ctx);
#else
/* 6.x: ARKErrHandlerFn, user data the message buffer */
void gd_sun_err_handler(int code, const char *module, const char *function, char *msg, void *user);
#endif

#endif
