/* Internal: one table of ARKODE entry points per time-stepping module (ERKStep, ARKStep). */
#ifndef GD_STEPPER_H
#define GD_STEPPER_H

#include <arkode/arkode.h>
#include <nvector/nvector_serial.h>

typedef struct gd_stepper_ops {
    const char *module;
    int (*evolve)(void *mem, realtype tout, N_Vector y, realtype *tret, int itask);
    int (*set_stop_time)(void *mem, realtype t);
    int (*reset)(void *mem, realtype t, N_Vector y);
    int (*get_dky)(void *mem, realtype t, int k, N_Vector dky);
    int (*get_root_info)(void *mem, int *rootsfound);
    int (*root_init)(void *mem, int nrtfn, ARKRootFn g);
    int (*set_init_step)(void *mem, realtype h);
    int (*set_max_step)(void *mem, realtype h);
    int (*set_fixed_step)(void *mem, realtype h);
    int (*set_max_num_steps)(void *mem, long n);
    int (*ss_tolerances)(void *mem, realtype rtol, realtype atol);
    int (*set_user_data)(void *mem, void *data);
    int (*set_err_handler)(void *mem, ARKErrHandlerFn fn, void *data);
    int (*set_order)(void *mem, int order);
    int (*get_num_steps)(void *mem, long *n);
    int (*get_num_step_attempts)(void *mem, long *n);
    int (*get_num_g_evals)(void *mem, long *n);
    int (*get_last_step)(void *mem, realtype *h);
    int (*set_no_inactive_root_warn)(void *mem);
    int (*set_interpolant_degree)(void *mem, int degree);
    int (*get_current_time)(void *mem, realtype *t);
    char *(*flag_name)(long flag);
    void (*free_mem)(void **mem);
} gd_stepper_ops;

extern const gd_stepper_ops gd_stepper_erk;
extern const gd_stepper_ops gd_stepper_ark;

#endif
