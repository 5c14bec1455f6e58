/* The ARKODE stepper tables: ERKStep (explicit, also the fixed-step RK4) and ARKStep (DIRK). */
#include "stepper.h"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>

const gd_stepper_ops gd_stepper_erk = {
    "ERKStep", ERKStepEvolve, ERKStepSetStopTime, ERKStepReset, ERKStepGetDky, ERKStepGetRootInfo,
    ERKStepRootInit, ERKStepSetInitStep, ERKStepSetMaxStep, ERKStepSetFixedStep, ERKStepSetMaxNumSteps,
    ERKStepSStolerances, ERKStepSetUserData, ERKStepSetErrHandlerFn, ERKStepSetOrder, ERKStepGetNumSteps,
    ERKStepGetNumStepAttempts, ERKStepGetNumGEvals, ERKStepGetLastStep, ERKStepSetNoInactiveRootWarn,
    ERKStepSetInterpolantDegree, ERKStepGetCurrentTime, ERKStepGetReturnFlagName, ERKStepFree,
};

const gd_stepper_ops gd_stepper_ark = {
    "ARKStep", ARKStepEvolve, ARKStepSetStopTime, ARKStepReset, ARKStepGetDky, ARKStepGetRootInfo,
    ARKStepRootInit, ARKStepSetInitStep, ARKStepSetMaxStep, ARKStepSetFixedStep, ARKStepSetMaxNumSteps,
    ARKStepSStolerances, ARKStepSetUserData, ARKStepSetErrHandlerFn, ARKStepSetOrder, ARKStepGetNumSteps,
    ARKStepGetNumStepAttempts, ARKStepGetNumGEvals, ARKStepGetLastStep, ARKStepSetNoInactiveRootWarn,
    ARKStepSetInterpolantDegree, ARKStepGetCurrentTime, ARKStepGetReturnFlagName, ARKStepFree,
};
