/* Internal: one table of ARKODE entry points per time-stepping module (ERKStep, ARKStep), so
 * that the integrator (simulate.c, sim_*.c) calls either through the same members whatever the
 * SUNDIALS version. See stepper.c for which functions fill them. */
#ifndef GD_STEPPER_H
#define GD_STEPPER_H

#include "sundials_compat.h"

#include <arkode/arkode.h>
#include <arkode/arkode_ls.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

typedef struct gd_stepper_ops {
    const char *module;
    int (*evolve)(void *mem, sunrealtype tout, N_Vector y, sunrealtype *tret, int itask);
    int (*set_stop_time)(void *mem, sunrealtype t);
    int (*reset)(void *mem, sunrealtype t, N_Vector y);
    int (*get_dky)(void *mem, sunrealtype t, int k, N_Vector dky);
    int (*get_root_info)(void *mem, int *rootsfound);
    int (*root_init)(void *mem, int nrtfn, ARKRootFn g);
    int (*set_init_step)(void *mem, sunrealtype h);
    int (*set_max_step)(void *mem, sunrealtype h);
    int (*set_fixed_step)(void *mem, sunrealtype h);
    int (*set_max_num_steps)(void *mem, long n);
    int (*ss_tolerances)(void *mem, sunrealtype rtol, sunrealtype atol);
    int (*set_user_data)(void *mem, void *data);
    /* SUNDIALS' error messages for this integrator into msg (GD_SUN_MSG_SIZE bytes): 6.x's
     * *SetErrHandlerFn with gd_sun_err_handler; from 7.0 nothing to do (gd_sun_context_create) */
    int (*capture_errors)(void *mem, char *msg);
    int (*set_order)(void *mem, int order);
    int (*get_num_steps)(void *mem, long *n);
    int (*get_num_step_attempts)(void *mem, long *n);
    int (*get_num_g_evals)(void *mem, long *n);
    int (*get_last_step)(void *mem, sunrealtype *h);
    int (*set_no_inactive_root_warn)(void *mem);
    int (*set_interpolant_degree)(void *mem, int degree);
    int (*get_current_time)(void *mem, sunrealtype *t);
    char *(*flag_name)(long flag);
    void (*free_mem)(void **mem);
    /* the implicit module only (NULL in the ERKStep table): the linear solver */
    int (*set_linear_solver)(void *mem, SUNLinearSolver LS, SUNMatrix A);
    int (*set_jac_fn)(void *mem, ARKLsJacFn jac);
    int (*set_lsetup_frequency)(void *mem, int msbp);
    int (*set_jac_eval_frequency)(void *mem, long msbj);
    int (*get_num_lin_iters)(void *mem, long *n);
    /* a user's error-weight function in place of the built-in one of ss_tolerances */
    int (*wf_tolerances)(void *mem, ARKEwtFn efun);
} gd_stepper_ops;

extern const gd_stepper_ops gd_stepper_erk;
extern const gd_stepper_ops gd_stepper_ark;

#endif
