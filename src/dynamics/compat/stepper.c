/* The ARKODE stepper tables: ERKStep (explicit, also the fixed-step RK4) and ARKStep (DIRK).
 *
 * Up to SUNDIALS 7.0 each module has its own setters and getters (ERKStepXxx, ARKStepXxx); 7.1.0
 * (LLNL/sundials PR #459) made the shared ARKodeXxx interface serve every module and deprecated
 * the module's own, so from 7.1 both tables are filled from ARKodeXxx. The tables become
 * unnecessary once the oldest supported SUNDIALS is 7.1: the callers can then call ARKodeXxx
 * directly (ERKStepCreate, ARKStepCreate, ERKStepSetTable and ARKStepSetTableName remain). */
#include "stepper.h"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>

#if GD_SUNDIALS_AT_LEAST(7, 0)
/* 7.x: the context's handler stack receives the errors (gd_sun_context_create) */
static int capture_in_context(void *mem, char *msg) { return 0; }
#endif

#if GD_SUNDIALS_AT_LEAST(7, 1)

#define GD_ARKODE_COMMON                                                                                           \
    .evolve = ARKodeEvolve, .set_stop_time = ARKodeSetStopTime, .reset = ARKodeReset, .get_dky = ARKodeGetDky,     \
    .get_root_info = ARKodeGetRootInfo, .root_init = ARKodeRootInit, .set_init_step = ARKodeSetInitStep,           \
    .set_max_step = ARKodeSetMaxStep, .set_fixed_step = ARKodeSetFixedStep,                                        \
    .set_max_num_steps = ARKodeSetMaxNumSteps, .ss_tolerances = ARKodeSStolerances,                               \
    .set_user_data = ARKodeSetUserData, .capture_errors = capture_in_context, .set_order = ARKodeSetOrder,         \
    .get_num_steps = ARKodeGetNumSteps, .get_num_step_attempts = ARKodeGetNumStepAttempts,                        \
    .get_num_g_evals = ARKodeGetNumGEvals, .get_last_step = ARKodeGetLastStep,                                     \
    .set_no_inactive_root_warn = ARKodeSetNoInactiveRootWarn, .set_interpolant_degree = ARKodeSetInterpolantDegree, \
    .get_current_time = ARKodeGetCurrentTime, .flag_name = ARKodeGetReturnFlagName, .free_mem = ARKodeFree,     \
    .wf_tolerances = ARKodeWFtolerances

const gd_stepper_ops gd_stepper_erk = {.module = "ERKStep", GD_ARKODE_COMMON};

const gd_stepper_ops gd_stepper_ark = {
    .module = "ARKStep", GD_ARKODE_COMMON,
    .set_linear_solver = ARKodeSetLinearSolver, .set_jac_fn = ARKodeSetJacFn,
    .set_lsetup_frequency = ARKodeSetLSetupFrequency, .set_jac_eval_frequency = ARKodeSetJacEvalFrequency,
    .get_num_lin_iters = ARKodeGetNumLinIters,
};

#else /* 6.x and 7.0 */

#if GD_SUNDIALS_AT_LEAST(7, 0)
#define erk_capture_errors capture_in_context
#define ark_capture_errors capture_in_context
#else
static int erk_capture_errors(void *mem, char *msg) { return ERKStepSetErrHandlerFn(mem, gd_sun_err_handler, msg); }
static int ark_capture_errors(void *mem, char *msg) { return ARKStepSetErrHandlerFn(mem, gd_sun_err_handler, msg); }
#endif

const gd_stepper_ops gd_stepper_erk = {
    "ERKStep", ERKStepEvolve, ERKStepSetStopTime, ERKStepReset, ERKStepGetDky, ERKStepGetRootInfo,
    ERKStepRootInit, ERKStepSetInitStep, ERKStepSetMaxStep, ERKStepSetFixedStep, ERKStepSetMaxNumSteps,
    ERKStepSStolerances, ERKStepSetUserData, erk_capture_errors, ERKStepSetOrder, ERKStepGetNumSteps,
    ERKStepGetNumStepAttempts, ERKStepGetNumGEvals, ERKStepGetLastStep, ERKStepSetNoInactiveRootWarn,
    ERKStepSetInterpolantDegree, ERKStepGetCurrentTime, ERKStepGetReturnFlagName, ERKStepFree,
    NULL, NULL, NULL, NULL, NULL, ERKStepWFtolerances,
};

const gd_stepper_ops gd_stepper_ark = {
    "ARKStep", ARKStepEvolve, ARKStepSetStopTime, ARKStepReset, ARKStepGetDky, ARKStepGetRootInfo,
    ARKStepRootInit, ARKStepSetInitStep, ARKStepSetMaxStep, ARKStepSetFixedStep, ARKStepSetMaxNumSteps,
    ARKStepSStolerances, ARKStepSetUserData, ark_capture_errors, ARKStepSetOrder, ARKStepGetNumSteps,
    ARKStepGetNumStepAttempts, ARKStepGetNumGEvals, ARKStepGetLastStep, ARKStepSetNoInactiveRootWarn,
    ARKStepSetInterpolantDegree, ARKStepGetCurrentTime, ARKStepGetReturnFlagName, ARKStepFree,
    ARKStepSetLinearSolver, ARKStepSetJacFn, ARKStepSetLSetupFrequency, ARKStepSetJacEvalFrequency,
    ARKStepGetNumLinIters, ARKStepWFtolerances,
};

#endif
