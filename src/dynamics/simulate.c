/* The event-exact integration driver: one mesh period at a time, stop times on the
 * period boundary and on excitation discontinuities, root finding on every clearance
 * with mode flips and resets, a near-grazing watch, and chattering and endless-separation
 * guards. This file holds the integrator's life cycle (create, free, reset), its right-hand
 * side and Jacobian callbacks and the step loop; the events, Lyapunov renormalisation, dense
 * output and statistics are in the sim_*.c files (sim_internal.h). */
#include "sim_internal.h"
#include "../core/gsl_quiet.h"

#include "erk_table.h"
#include "compat/arkode_6x_defaults.h"
#include "compat/vector_kernels.h"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_butcher.h>
#include <arkode/arkode_erkstep.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

/* the compiled RHS of the held modes: the one used last, another kept, or built now */
static const gd_rhs_plan *plan_for(gd_sim *s)
{
    if (gd_rhs_plan_current(&s->plan[s->plan_cur], &s->md))
        return &s->plan[s->plan_cur];
    for (int i = 0; i < SIM_PLANS; i++)
        if (gd_rhs_plan_current(&s->plan[i], &s->md)) {
            s->plan_cur = i;
            return &s->plan[i];
        }
    s->plan_cur = s->plan_next;
    s->plan_next = (s->plan_next + 1) % SIM_PLANS;
    gd_rhs_plan_build(&s->plan[s->plan_cur], &s->m, &s->md, s->plan_ex);
    return &s->plan[s->plan_cur];
}

/* The vectors are the serial ones created in gd_sim_create: their data are read with the
 * NV_DATA_S macro (N_VGetArrayPointer is a call into Debian's unoptimised library per use). */
static int rhs_fn(sunrealtype t, N_Vector y, N_Vector ydot, void *user)
{
    gd_sim *s = user;
    const double *yy = NV_DATA_S(y);
    double *yd = NV_DATA_S(ydot);
    double sn, cs;
    sim_phase_at(s, t, &sn, &cs);
    s->nrhs++;
    if (s->use_plan && !s->md.from_state) { /* use_plan: a gear model (gd_rhs_plan_applies) */
        const gd_rhs_plan *p = plan_for(s);
        gd_rhs_plan_rhs(p, &s->m, t, sn, cs, yy, yd, &s->md);
        for (int v = 1; v <= s->k; v++)
            gd_rhs_plan_tangent(p, &s->m, t, sn, cs, yy + v * s->m.n, yd + v * s->m.n, &s->md);
        return 0;
    }
    gd_model_rhs_sc(&s->m, t, sn, cs, yy, yd, &s->md);
    for (int v = 1; v <= s->k; v++)
        gd_model_tangent_sc(&s->m, t, sn, cs, yy, yy + v * s->m.n, yd + v * s->m.n, &s->md);
    return 0;
}

/* The error weights that ARKODE asks for after every step, in one pass (its own, arkEwtSetSS, makes
 * four through the vector table): the same operations in the same order, the same bits
 * (compat/vector_kernels.c). */
static int ewt_fn(N_Vector y, N_Vector w, void *user)
{
    const gd_sim *s = user;
    return gd_vector_error_weights(y, w, s->o.rtol, s->o.atol);
}

static int jac_fn(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *user, N_Vector t1, N_Vector t2,
                  N_Vector t3)
{
    gd_sim *s = user;
    int n = s->m.n;
    double Jd[GD_MAX_STATE * GD_MAX_STATE];
    gd_model_jacobian(&s->m, t, NV_DATA_S(y), Jd, &s->md);
    /* the tangent blocks repeat J (within a contact mode J does not depend on the state) */
    SUNMatZero(J);
    for (int b = 0; b <= s->k; b++)
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++)
                SM_ELEMENT_D(J, b * n + i, b * n + j) = Jd[i * n + j];
    s->jac_calls++;
    return 0;
}

gd_status gd_sim_sun_check(gd_sim *s, int flag, const char *call, gd_error *err)
{
    if (flag >= 0)
        return GD_OK;
    char *name = s->ops ? s->ops->flag_name(flag) : NULL; /* malloc'd by ARKODE */
    gd_status st = gd_error_set(err, GD_ERR_SOLVER, "%s failed: %s (%d)%s%s", call, name ? name : "", flag,
                                s->sunmsg[0] ? ": " : "", s->sunmsg);
    free(name);
    return st;
}

/* gd_sim_create, phase 1: the state vector (the trajectory, then the tangent vectors) and the
 * scratch vectors, with the initial state y0. */
static gd_status create_vectors(gd_sim *s, const double *y0, gd_error *err)
{
    const gd_model *m = &s->m;
    const gd_solver_opts *o = &s->o;
    s->k = o->n_tangent;
    s->N = m->n * (1 + s->k);
    s->y = N_VNew_Serial(s->N, s->ctx);
    s->tmp = N_VNew_Serial(s->N, s->ctx);
    s->y_prev = calloc((size_t)s->N, sizeof(double));
    if (!s->y || !s->tmp || !s->y_prev)
        return gd_error_set(err, GD_ERR_NOMEM, "N_VNew_Serial failed");
    /* fused vector operations: one pass over the short state vectors instead of several */
    if (N_VEnableFusedOps_Serial(s->y, SUNTRUE) != 0 || N_VEnableFusedOps_Serial(s->tmp, SUNTRUE) != 0)
        return gd_error_set(err, GD_ERR_SOLVER, "N_VEnableFusedOps_Serial failed");
    /* the per-step vector kernels compiled with geardyn (Debian's SUNDIALS is built at -O0;
     * same results bit for bit, vector_kernels.c); every vector ARKODE clones inherits them */
    if (!o->library_vector_ops &&
        (gd_vector_use_compiled_ops(s->y) != 0 || gd_vector_use_compiled_ops(s->tmp) != 0))
        return gd_error_set(err, GD_ERR_SOLVER, "the state vector is not a serial N_Vector");
    memcpy(NV_DATA_S(s->y), y0, sizeof(double) * (size_t)m->n);
    return GD_OK;
}

/* gd_sim_create, phase 2: the ARKODE module (ARKStep for the implicit method, else ERKStep) and
 * the options common to both. */
static gd_status create_integrator(gd_sim *s, gd_error *err)
{
    const gd_model *m = &s->m;
    const gd_solver_opts *o = &s->o;
    s->implicit = o->method == GD_METHOD_DIRK;
    s->ops = s->implicit ? &gd_stepper_ark : &gd_stepper_erk;
    s->mem = s->implicit ? ARKStepCreate(NULL, rhs_fn, 0.0, s->y, s->ctx) : ERKStepCreate(rhs_fn, 0.0, s->y, s->ctx);
    if (!s->mem)
        return gd_error_set(err, GD_ERR_SOLVER, "%sCreate failed", s->ops->module);
    CHECK(s->ops->capture_errors(s->mem, s->sunmsg));
    /* cubic Hermite dense output by default: built from the step's end values and derivatives,
     * it costs no RHS evaluation (ARKODE's degrees 4 and 5 cost 1 and 4 per use, and its root
     * check uses it at every step); events are located with the method (refine_root_state) */
    CHECK(s->ops->set_interpolant_degree(s->mem, o->interp_degree > 0 ? o->interp_degree : 3));
    CHECK(s->ops->set_user_data(s->mem, s));
    CHECK(s->ops->ss_tolerances(s->mem, o->rtol, o->atol));
    if (!s->implicit) /* the same weights in one pass (ewt_fn); ARKStep's solvers keep ARKODE's own */
        CHECK(s->ops->wf_tolerances(s->mem, ewt_fn));
    CHECK(s->ops->set_max_num_steps(s->mem, 1000000));
    CHECK(s->ops->set_max_step(s->mem, o->max_step_fraction * m->period));
    /* SUNDIALS >= 7.3: 6.x's step-size adaptivity, as geardyn was measured with (no-op before) */
    CHECK(gd_arkode_6x_adaptivity(s->mem, s->ctx, s->implicit, &s->adapt_6x));
    return GD_OK;
}

/* gd_sim_create, phase 3: the method, an implicit table or order, or an explicit Butcher table
 * (fixed step for RK4 and on request). */
static gd_status set_method(gd_sim *s, gd_error *err)
{
    const gd_model *m = &s->m;
    const gd_solver_opts *o = &s->o;
    if (s->implicit) {
        if (o->table[0])
            CHECK(ARKStepSetTableName(s->mem, o->table, "ARKODE_ERK_NONE"));
        else if (gd_arkode_6x_dirk_table(o->order)) /* SUNDIALS >= 7.3: 6.x's default of the order */
            CHECK(ARKStepSetTableName(s->mem, gd_arkode_6x_dirk_table(o->order), "ARKODE_ERK_NONE"));
        else
            CHECK(s->ops->set_order(s->mem, o->order));
    } else {
        /* explicit tables go through gd_erk_table_fsal_safe (compat/erk_fsal.h: ERKStep's FSAL defect before 6.7) */
        ARKodeButcherTable B = NULL;
        if (o->method == GD_METHOD_RK4) {
            B = gd_erk_classical_rk4();
        } else {
            const char *name = o->table[0] ? o->table : gd_erk_default_table(o->order);
            ARKodeButcherTable B0 = name ? gd_erk_load(name) : NULL;
            if (!B0)
                return gd_error_set(err, GD_ERR_INPUT, "no explicit Runge-Kutta table '%s' of order %d",
                                    name ? name : "", o->order);
            B = gd_erk_table_fsal_safe(B0);
            ARKodeButcherTable_Free(B0);
        }
        if (!B)
            return gd_error_set(err, GD_ERR_NOMEM, "Butcher table allocation failed");
        int flag = ERKStepSetTable(s->mem, B);
        ARKodeButcherTable_Free(B);
        CHECK(flag);
        if (o->method == GD_METHOD_RK4 || o->fixed_step)
            CHECK(s->ops->set_fixed_step(s->mem, m->period / o->steps_per_period));
    }
    return GD_OK;
}

/* gd_sim_create, phase 4 (implicit method): the dense linear solver with the analytic Jacobian. */
static gd_status set_linear_solver(gd_sim *s, gd_error *err)
{
    const gd_model *m = &s->m;
    const gd_solver_opts *o = &s->o;
    s->A = SUNDenseMatrix(s->N, s->N, s->ctx);
    s->LS = s->A ? SUNLinSol_Dense(s->y, s->A, s->ctx) : NULL;
    if (!s->A || !s->LS)
        return gd_error_set(err, GD_ERR_NOMEM, "dense linear solver allocation failed");
    CHECK(s->ops->set_linear_solver(s->mem, s->LS, s->A));
    CHECK(s->ops->set_jac_fn(s->mem, jac_fn));
    CHECK(s->ops->set_lsetup_frequency(s->mem, 1));
    CHECK(s->ops->set_jac_eval_frequency(s->mem, 1));
    if (o->fixed_step)
        CHECK(s->ops->set_fixed_step(s->mem, m->period / o->steps_per_period));
    return GD_OK;
}

GD_API gd_status gd_sim_create(const gd_model *m, const gd_solver_opts *o, const double *y0, const gd_modes *md0,
                               gd_sim **out, gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    *out = NULL;
    gd_sim *s = calloc(1, sizeof *s);
    if (!s)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory creating the integrator");
    s->m = *m;
    for (int i = 0; i < 4; i++)
        s->sc_t[i] = NAN; /* equal to no time */
    s->o = *o;
    s->md = *md0;
    s->md.from_state = !o->root_finding;
    s->use_plan = !o->generic_rhs && !m->custom;
    gd_plan_excitation_build(s->plan_ex, m);
    /* no rectangular stiffness and no impact pulse: never an edge (+inf at every time), and the
     * step loop need not ask for one at every step */
    s->no_edges = isinf(gd_model_next_discontinuity(m, 0.0, &s->md));
    if (gd_sun_context_create(&s->ctx, s->sunmsg) != 0) {
        free(s);
        return gd_error_set(err, GD_ERR_SOLVER, "SUNContext_Create failed");
    }
    if (o->n_tangent < 0 || o->n_tangent > m->n) {
        gd_error_set(err, GD_ERR_INPUT, "%d tangent vectors for %d state variables (valid: 0 to %d)", o->n_tangent,
                     m->n, m->n);
        goto fail;
    }
    if (m->custom && o->method == GD_METHOD_DIRK && !m->custom->jacobian) {
        gd_error_set(err, GD_ERR_INPUT, "an implicit method needs the system's Jacobian");
        goto fail;
    }
    if (create_vectors(s, y0, err) != GD_OK)
        goto fail;
    if (s->k > 0 && gd_sim_tangent_init(s, err) != GD_OK)
        goto fail;
    if (create_integrator(s, err) != GD_OK || set_method(s, err) != GD_OK)
        goto fail;
    if (s->implicit && set_linear_solver(s, err) != GD_OK)
        goto fail;
    if (gd_sim_roots_setup(s, err) != GD_OK)
        goto fail;
    for (int j = 0; j < m->nmesh; j++) {
        s->md.rect_level[j] = gd_model_rect_level_after(m, j, 0.0, &s->md);
        s->md.pulse_on[j] = gd_model_pulse_after(m, j, 0.0);
        s->was_open[j] = s->md.mode[m->mesh_clear[j]] == 0;
    }
    memcpy(s->y_prev, NV_DATA_S(s->y), sizeof(double) * (size_t)s->N);
    *out = s;
    return GD_OK;
fail:
    gd_sim_free(s);
    return err ? err->code : GD_ERR_SOLVER;
}

GD_API gd_status gd_sim_set_state(gd_sim *s, const double *y, gd_error *err)
{
    memcpy(NV_DATA_S(s->y), y, sizeof(double) * (size_t)s->m.n);
    s->cx_ok = 0;
    if (!s->md.from_state) {
        gd_status st = gd_model_consistent_modes(&s->m, s->t, y, &s->md, err);
        if (st != GD_OK)
            return st;
    }
    return gd_sim_reset_at(s, s->t, err);
}

GD_API void gd_sim_free(gd_sim *s)
{
    if (!s)
        return;
    if (s->mem)
        s->ops->free_mem(&s->mem);
    gd_arkode_6x_free(&s->adapt_6x);
    if (s->LS)
        SUNLinSolFree(s->LS);
    if (s->A)
        SUNMatDestroy(s->A);
    if (s->y)
        N_VDestroy(s->y);
    if (s->tmp)
        N_VDestroy(s->tmp);
    if (s->ctx)
        SUNContext_Free(&s->ctx);
    free(s->y_prev);
    gsl_matrix_free(s->qr);
    gsl_matrix_free(s->Q);
    gsl_matrix_free(s->R);
    gsl_vector_free(s->tau);
    free(s);
}

GD_API void gd_sim_set_hooks(gd_sim *s, gd_step_hook step, gd_event_hook event, void *user)
{
    s->step_hook = step;
    s->event_hook = event;
    s->hook_user = user;
}

/* 1 when every y[i] is finite. 0 y is +-0 for a finite y and NaN for an infinite or NaN one: the
 * bits of these products ORed, two lanes at a time, have the exponent of a NaN exactly when one
 * is not finite (no branch per value at every step) */
static int state_finite(const double *y, int n)
{
    typedef double d2 __attribute__((vector_size(16)));
    typedef uint64_t u2 __attribute__((vector_size(16)));
    const uint64_t nan_exp = 0x7ff0000000000000u;
    u2 acc = {0, 0};
    int i = 0;
    for (; i + 2 <= n; i += 2) {
        d2 v;
        memcpy(&v, y + i, sizeof v);
        acc |= (u2)(0.0 * v);
    }
    uint64_t bits = acc[0] | acc[1];
    for (; i < n; i++) {
        double z = 0.0 * y[i];
        uint64_t b;
        memcpy(&b, &z, sizeof b);
        bits |= b;
    }
    return (bits & nan_exp) != nan_exp;
}

gd_status gd_sim_reset_at(gd_sim *s, double t, gd_error *err)
{
    double h = 0;
    s->ops->get_last_step(s->mem, &h);
    if (s->h_resume > 0) /* after a refined event: the step the controller had reached, not the redone piece */
        h = s->h_resume;
    s->h_resume = 0;
    int flag = s->ops->reset(s->mem, t, s->y);
    if (flag < 0)
        return gd_sim_sun_check(s, flag, "Reset", err);
    /* keep the step size the controller had reached rather than re-estimating it */
    if (h > 0 && s->o.method != GD_METHOD_RK4 && !s->o.fixed_step)
        s->ops->set_init_step(s->mem, h);
    s->resets++;
    return GD_OK;
}

/* gd_sim_advance_to, phase 1: where the next step is to stop. The end, the next excitation
 * discontinuity, the next time of the sample grid, or the suspected touch that a step redone by
 * the grazing watch (rewound) stops at, whichever comes first. */
static double next_stop_time(gd_sim *s, double t_end, int rewound, double t_graze_stop)
{
    double tstop = s->no_edges ? t_end : fmin(t_end, gd_model_next_discontinuity(&s->m, s->t, &s->md));
    if (s->samp_dt > 0) {
        double ta = sim_abs_time(s, s->t), tiny = 1e-12 * (fabs(ta) + s->m.period);
        double k = ceil((ta + tiny - s->samp_t0) / s->samp_dt);
        if (k < 0)
            k = 0;
        double ts = s->samp_t0 + k * s->samp_dt - (double)s->shift * s->m.period;
        if (ts > s->t && ts < tstop)
            tstop = ts;
    }
    if (rewound && t_graze_stop > s->t && t_graze_stop < tstop)
        tstop = t_graze_stop;
    return tstop;
}

/* gd_sim_advance_to, phase 2: one ARKODE step from s->t towards tstop, its start kept in y_prev
 * (and the clearances there in cx0, cv0); *tret and *flag are ARKODE's. A failed step, or one
 * that ends on a non-finite state, is an error. */
static gd_status take_step(gd_sim *s, double tstop, double *tret_out, int *flag_out, gd_error *err)
{
    int flag = s->ops->set_stop_time(s->mem, tstop);
    if (flag < 0)
        return gd_sim_sun_check(s, flag, "SetStopTime", err);
    double t0 = s->t;
    memcpy(s->y_prev, NV_DATA_S(s->y), sizeof(double) * (size_t)s->N);
    if (s->nroots && (s->o.grazing_watch || !s->armed)) { /* the clearances at the start: grazing watch, gate */
        gd_sim_clearances_now(s);
        memcpy(s->cx0, s->cx, sizeof s->cx);
        memcpy(s->cv0, s->cv, sizeof s->cv);
    }
    s->cx_ok = 0;
    double tret = t0;
    s->sunmsg[0] = '\0';
    flag = s->ops->evolve(s->mem, tstop, s->y, &tret, ARK_ONE_STEP);
    if (flag < 0 && s->nonfinite)
        return gd_error_set(err, GD_ERR_SOLVER, "the solution became NaN or infinite at t = %.9g mesh periods",
                            sim_abs_time(s, t0) / s->m.period);
    if (flag < 0) {
        gd_sim_sun_check(s, flag, "Evolve", err);
        return gd_error_prefix(err, "at t = %.9g mesh periods", sim_abs_time(s, t0) / s->m.period);
    }
    if (!state_finite(NV_DATA_S(s->y), s->N))
        return gd_error_set(err, GD_ERR_SOLVER, "the solution became NaN or infinite at t = %.9g mesh periods",
                            sim_abs_time(s, tret) / s->m.period);
    *tret_out = tret;
    *flag_out = flag;
    return GD_OK;
}

/* gd_sim_advance_to, phase 4: the excitation levels after a stop time tret. */
static gd_status levels_after_stop(gd_sim *s, double tret, gd_error *err)
{
    /* at any stop (an edge, or a period end that an edge shares up to rounding) the
     * level is the one just after this time; a change is a discontinuity: reset */
    int changed = 0;
    for (int j = 0; j < s->m.nmesh; j++) {
        int lv = gd_model_rect_level_after(&s->m, j, tret, &s->md);
        int pv = gd_model_pulse_after(&s->m, j, tret);
        changed |= lv != s->md.rect_level[j] || pv != s->md.pulse_on[j];
        s->md.rect_level[j] = lv;
        s->md.pulse_on[j] = pv;
    }
    if (changed) {
        gd_status st = gd_sim_reset_at(s, tret, err);
        if (st != GD_OK)
            return st;
    }
    return GD_OK;
}

/* gd_sim_advance_to, phase 5: the modes after the step, from the state (root finding off) or,
 * when no root was handled, repaired where the state has left the held mode. */
static gd_status keep_modes(gd_sim *s, int handled, gd_error *err)
{
    if (s->md.from_state) {
        gd_status st = gd_sim_modes_from_state(s, err);
        if (st != GD_OK)
            return st;
    } else if (s->nroots && !handled) {
        gd_status st = gd_sim_repair_held_modes(s, err);
        if (st != GD_OK)
            return st;
    }
    return GD_OK;
}

GD_API gd_status gd_sim_advance_to(gd_sim *s, double t_end_abs, gd_error *err)
{
    double t_end = t_end_abs - (double)s->shift * s->m.period;
    int rewound = 0;
    double t_graze_stop = -1.0;
    while (s->t < t_end) {
        double tstop = next_stop_time(s, t_end, rewound, t_graze_stop);
        double t0 = s->t, tret = t0;
        int flag = 0;
        gd_status st = take_step(s, tstop, &tret, &flag, err);
        if (st != GD_OK)
            return st;
        /* near-grazing watch: a crossing and return hidden inside the step */
        if (s->nroots && s->o.grazing_watch && flag != ARK_ROOT_RETURN && !rewound) {
            double tg = -1.0;
            st = gd_sim_grazing_watch(s, t0, tret, &tg, err);
            if (st != GD_OK)
                return st;
            if (tg > 0) {
                rewound = 1;
                t_graze_stop = tg;
                continue;
            }
        }
        if (rewound && tret >= t_graze_stop)
            rewound = 0;
        s->t = tret;
        s->t_step0 = t0;
        /* gated root finding: a root function that changed sign over the step */
        double tc = s->nroots && !s->armed && !s->md.from_state ? gd_sim_crossing_in_step(s, t0, tret) : -1.0;
        int refine = (flag == ARK_ROOT_RETURN && s->o.refine_events) || tc > 0;
        if (!refine && (st = gd_sim_after_step(s, sim_abs_time(s, t0), sim_abs_time(s, tret), err)) != GD_OK)
            return st;
        /* phase 3: the roots of the step, located and handled (sim_events.c) */
        int handled = 0;
        st = gd_sim_roots_after_step(s, flag, refine, t0, tret, tc, &handled, err);
        if (st != GD_OK)
            return st;
        if (handled)
            rewound = 0;
        if (!handled && flag == ARK_TSTOP_RETURN) {
            st = levels_after_stop(s, tret, err);
            if (st != GD_OK)
                return st;
        }
        if (!rewound && s->armed && s->gate) { /* (a call that does nothing at most steps: not made) */
            st = gd_sim_arm_roots(s, 0, err);
            if (st != GD_OK)
                return st;
        }
        st = keep_modes(s, handled, err);
        if (st != GD_OK)
            return st;
    }
    return GD_OK;
}

GD_API gd_status gd_sim_period(gd_sim *s, gd_error *err)
{
    double t_end_abs = (double)(s->period + 1) * s->m.period;
    gd_status st = gd_sim_advance_to(s, t_end_abs, err);
    if (st != GD_OK)
        return st;
    /* land exactly on the boundary */
    s->t = (double)(s->period + 1 - s->shift) * s->m.period;
    s->cx_ok = 0;
    s->period++;
    s->events_this_period = 0;
    /* endless separation: a mesh open for whole periods, one after another, with no event */
    for (int j = 0; j < s->m.nmesh; j++) {
        int c = s->m.mesh_clear[j];
        int open_all_period = s->md.mode[c] == 0 && s->was_open[j] && s->by_clear[c] == s->events_at_start[c];
        s->open_periods[j] = open_all_period ? s->open_periods[j] + 1 : 0;
        s->was_open[j] = s->md.mode[c] == 0;
        if (s->open_periods[j] > s->o.max_separated_periods)
            return gd_error_set(err, GD_ERR_PHYSICS,
                                "%s: the teeth have been separated for %ld mesh periods without touching again "
                                "(t = %ld periods): the load cannot keep this mesh engaged; raise the torque or the "
                                "damping, or reduce the excitation", s->m.clear[c].name, s->open_periods[j], s->period);
    }
    memcpy(s->events_at_start, s->by_clear, sizeof s->by_clear);
    if (s->k > 0 && !s->tangent_free) {
        st = gd_sim_orthonormalise(s, 1, err);
        if (st != GD_OK)
            return st;
        if (s->period - s->shift < SHIFT_PERIODS) {
            st = gd_sim_reset_at(s, s->t, err);
            if (st != GD_OK)
                return st;
        }
    }
    if (s->period - s->shift >= SHIFT_PERIODS) {
        s->shift = s->period;
        st = gd_sim_reset_at(s, 0.0, err);
        s->t = 0.0;
        s->cx_ok = 0;
        if (st != GD_OK)
            return st;
    }
    return GD_OK;
}

GD_API void gd_sim_set_sample_grid(gd_sim *s, double t_first, double dt)
{
    s->samp_t0 = t_first;
    s->samp_dt = dt > 0 ? dt : 0.0;
}

GD_API double gd_sim_time(const gd_sim *s) { return sim_abs_time(s, s->t); }
GD_API long gd_sim_period_index(const gd_sim *s) { return s->period; }
GD_API const double *gd_sim_state(const gd_sim *s) { return NV_DATA_S(s->y); }
GD_API const gd_modes *gd_sim_modes(const gd_sim *s) { return &s->md; }
GD_API const gd_model *gd_sim_model(const gd_sim *s) { return &s->m; }

GD_API void gd_sim_rhs(gd_sim *s, double t_abs, const double *y, double *ydot)
{
    double t = t_abs - (double)s->shift * s->m.period;
    gd_model_rhs(&s->m, t, y, ydot, &s->md);
    s->extra_rhs++;
}

