/* The event-exact integration driver: one mesh period at a time, stop times on the
 * period boundary and on excitation discontinuities, root finding on every clearance
 * with mode flips and resets, a near-grazing watch, and chattering and endless-separation
 * guards. */
#include "geardyn/gd_sim.h"

#include "erk_table.h"
#include "model_internal.h"
#include "stepper.h"
#include "vector_kernels.h"
#include "rhs_plan.h"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_butcher.h>
#include <arkode/arkode_erkstep.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_rng.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#define SHIFT_PERIODS 32 /* keep the integrator's time below this many periods (root tolerance grows with |t|) */

struct gd_sim {
    gd_model m;
    gd_solver_opts o;
    gd_modes md;
    SUNContext ctx;
    N_Vector y;
    N_Vector tmp;
    SUNMatrix A;
    SUNLinearSolver LS;
    void *mem;
    const gd_stepper_ops *ops;
    int implicit;
    double t;                /* integrator (local) time */
    long shift;              /* whole periods shifted out of t */
    long period;             /* index of the period that contains t */
    double *y_prev;          /* N: the state at the start of the last step */
    int k, N;                /* tangent vectors, total length n (1 + k) */
    double lyap_sum[GD_MAX_STATE];
    double lyap_t0;          /* absolute time where the sums started */
    gsl_matrix *qr, *Q, *R;
    gsl_vector *tau;
    double t_step0;          /* start of the last step (local) */
    double samp_t0, samp_dt; /* sample grid (absolute time; samp_dt 0: none): steps end on it */
    double cx[GD_MAX_CLEAR], cv[GD_MAX_CLEAR];   /* clearance coordinates and rates at (t, y) when cx_ok */
    double cx0[GD_MAX_CLEAR], cv0[GD_MAX_CLEAR]; /* the same at the start of the last step */
    int cx_ok;
    int nroots;
    int rootsfound[2 * GD_MAX_CLEAR];
    /* gated root finding (docs/numerics.md section 3): ARKODE holds the root functions (armed)
     * only while it locates a crossing that the step-end check found, or redoes a step the
     * grazing watch suspects; every other step ends without its root machinery */
    int gate, armed;
    gd_step_hook step_hook;
    gd_event_hook event_hook;
    void *hook_user;
    long events_this_period;
    long open_periods[GD_MAX_MESH];
    int was_open[GD_MAX_MESH];
    long events_at_start[GD_MAX_CLEAR];
    long nrhs, nroot_evals;  /* counted here: ARKODE's own counters restart at every Reset */
    long extra_rhs, jac_calls, resets, grazing_suspects, grazing_rewinds;
    long events, by_kind[GD_EV_NKINDS], by_clear[GD_MAX_CLEAR];
    char sunmsg[512];
    int nonfinite;           /* a root function met a non-finite state */
    double h_resume;         /* > 0: the step to restart with at the next reset (the step that found a root) */
    /* the septic dense output of the last step (gd_sim_dense): its ends, states and
     * accelerations, valid while nrhs == dq_key (every new step evaluates the RHS) */
    int dq_ok;
    long dq_key;
    double dq_t0, dq_h, dq_t1;
    double dq_y0[GD_MAX_STATE], dq_y1[GD_MAX_STATE], dq_a0[GD_MAX_DOF], dq_a1[GD_MAX_DOF];
    double dq_j0[GD_MAX_DOF], dq_j1[GD_MAX_DOF];
    long dq_resets;          /* resets when the ends were read: the next step's start is this end */
    gd_modes dq_md;          /* ... if no reset came between and the modes are the same */
    /* sin and cos of Omega t at the last few times evaluated (model_internal.h): the stages of a
     * step with equal nodes and the root functions at its end share them */
    double sc_t[4], sc_s[4], sc_c[4];
    int sc_next;
    /* the RHS compiled for the held modes (rhs_plan.h): the last few sets of modes (a mesh that
     * opens and closes goes back and forth between two) */
    gd_rhs_plan plan[4];
    gd_plan_excitation plan_ex[GD_MAX_MESH];
    int plan_cur, plan_next, use_plan;
};

/* sin(Omega t) and cos(Omega t), from the cache when t was one of the last four times */
static inline void phase_at(gd_sim *s, double t, double *sn, double *cs)
{
    for (int i = 0; i < 4; i++)
        if (s->sc_t[i] == t) {
            *sn = s->sc_s[i];
            *cs = s->sc_c[i];
            return;
        }
    *sn = 0.0, *cs = 1.0;
    if (s->m.nmesh > 0)
        sincos(s->m.Omega * t, sn, cs);
    s->sc_t[s->sc_next] = t, s->sc_s[s->sc_next] = *sn, s->sc_c[s->sc_next] = *cs;
    s->sc_next = (s->sc_next + 1) & 3;
}

GD_API const char *gd_event_kind_name(int kind)
{
    static const char *names[] = {"contact", "separation", "back-contact", "back-separation"};
    return kind >= 0 && kind < GD_EV_NKINDS ? names[kind] : "?";
}

/* the compiled RHS of the held modes: the one used last, another kept, or built now */
static const gd_rhs_plan *plan_for(gd_sim *s)
{
    if (gd_rhs_plan_current(&s->plan[s->plan_cur], &s->md))
        return &s->plan[s->plan_cur];
    for (int i = 0; i < 4; i++)
        if (gd_rhs_plan_current(&s->plan[i], &s->md)) {
            s->plan_cur = i;
            return &s->plan[i];
        }
    s->plan_cur = s->plan_next;
    s->plan_next = (s->plan_next + 1) % 4;
    gd_rhs_plan_build(&s->plan[s->plan_cur], &s->m, &s->md, s->plan_ex);
    return &s->plan[s->plan_cur];
}

/* The vectors are the serial ones created in gd_sim_create: their data are read with the
 * NV_DATA_S macro (N_VGetArrayPointer is a call into Debian's unoptimised library per use). */
static int rhs_fn(realtype t, N_Vector y, N_Vector ydot, void *user)
{
    gd_sim *s = user;
    const double *yy = NV_DATA_S(y);
    double *yd = NV_DATA_S(ydot);
    double sn, cs;
    phase_at(s, t, &sn, &cs);
    s->nrhs++;
    if (s->use_plan && gd_rhs_plan_applies(&s->m, &s->md)) {
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

/* A value of a root function exactly on its boundary (g = 0) counts as the side of the held mode:
 * ARKODE switches off a root function that is exactly zero where it restarts, and a crossing back
 * in the first step after an event on the boundary (a grazing separation) would go unseen. */
#define ON_BOUNDARY 1e-100

static int root_fn(realtype t, N_Vector y, realtype *g, void *user)
{
    gd_sim *s = user;
    double sn, cs;
    phase_at(s, t, &sn, &cs);
    gd_model_roots_sc(&s->m, t, sn, cs, NV_DATA_S(y), g, &s->md);
    s->nroot_evals++;
    for (int i = 0; i < s->nroots; i++)
        if (g[i] == 0.0) {
            int mode = s->md.mode[i / 2]; /* g[2c] = x - h > 0 in mode +1; g[2c+1] = x + h < 0 in mode -1 */
            g[i] = (i % 2 == 0 ? mode > 0 : mode >= 0) ? ON_BOUNDARY : -ON_BOUNDARY;
        }
    /* a solution gone NaN or infinite inside a step (an unstable fixed step) would send
     * ARKODE's root search around for ever: fail the step instead */
    for (int i = 0; i < s->nroots; i++)
        if (!isfinite(g[i])) {
            s->nonfinite = 1;
            return -1;
        }
    return 0;
}

static int jac_fn(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *user, N_Vector t1, N_Vector t2, N_Vector t3)
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

static void err_handler(int code, const char *module, const char *function, char *msg, void *user)
{
    gd_sim *s = user;
    snprintf(s->sunmsg, sizeof s->sunmsg, "%s %s: %s", module, function, msg);
}

static gd_status sun_check(gd_sim *s, int flag, const char *call, gd_error *err)
{
    if (flag >= 0)
        return GD_OK;
    return gd_error_set(err, GD_ERR_SOLVER, "%s failed: %s (%d)%s%s", call, s->ops ? s->ops->flag_name(flag) : "",
                        flag, s->sunmsg[0] ? ": " : "", s->sunmsg);
}

#define CHECK(call)                                                                                                \
    do {                                                                                                           \
        gd_status st_ = sun_check(s, (call), #call, err);                                                          \
        if (st_ != GD_OK)                                                                                          \
            goto fail;                                                                                             \
    } while (0)

gd_status gd_sim_orthonormalise(gd_sim *s, int accumulate, gd_error *err);
static double abs_time(const gd_sim *s, double t_local);
static gd_status reset_at(gd_sim *s, double t, gd_error *err);

GD_API gd_status gd_sim_create(const gd_model *m, const gd_solver_opts *o, const double *y0, const gd_modes *md0,
                               gd_sim **out, gd_error *err)
{
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
    s->use_plan = !o->generic_rhs;
    gd_plan_excitation_build(s->plan_ex, m);
    if (SUNContext_Create(NULL, &s->ctx) != 0) {
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
    s->k = o->n_tangent;
    s->N = m->n * (1 + s->k);
    s->y = N_VNew_Serial(s->N, s->ctx);
    s->tmp = N_VNew_Serial(s->N, s->ctx);
    s->y_prev = calloc((size_t)s->N, sizeof(double));
    if (!s->y || !s->tmp || !s->y_prev) {
        gd_error_set(err, GD_ERR_NOMEM, "N_VNew_Serial failed");
        goto fail;
    }
    /* fused vector operations: one pass over the short state vectors instead of several */
    if (N_VEnableFusedOps_Serial(s->y, SUNTRUE) != 0 || N_VEnableFusedOps_Serial(s->tmp, SUNTRUE) != 0) {
        gd_error_set(err, GD_ERR_SOLVER, "N_VEnableFusedOps_Serial failed");
        goto fail;
    }
    /* the per-step vector kernels compiled with geardyn (Debian's SUNDIALS is built at -O0;
     * same results bit for bit, vector_kernels.c); every vector ARKODE clones inherits them */
    if (!o->library_vector_ops &&
        (gd_vector_use_compiled_ops(s->y) != 0 || gd_vector_use_compiled_ops(s->tmp) != 0)) {
        gd_error_set(err, GD_ERR_SOLVER, "the state vector is not a serial N_Vector");
        goto fail;
    }
    memcpy(NV_DATA_S(s->y), y0, sizeof(double) * (size_t)m->n);
    if (s->k > 0) {
        s->qr = gsl_matrix_alloc((size_t)m->n, (size_t)s->k);
        s->Q = gsl_matrix_alloc((size_t)m->n, (size_t)m->n);
        s->R = gsl_matrix_alloc((size_t)m->n, (size_t)s->k);
        s->tau = gsl_vector_alloc((size_t)s->k);
        gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
        if (!s->qr || !s->Q || !s->R || !s->tau || !rng) {
            gsl_rng_free(rng);
            gd_error_set(err, GD_ERR_NOMEM, "out of memory for the tangent vectors");
            goto fail;
        }
        /* reproducible, generic initial directions: seeded uniform, then orthonormalised */
        gsl_rng_set(rng, 20261121UL);
        double *yy = NV_DATA_S(s->y);
        for (int v = 1; v <= s->k; v++)
            for (int i = 0; i < m->n; i++)
                yy[v * m->n + i] = 2.0 * gsl_rng_uniform(rng) - 1.0;
        gsl_rng_free(rng);
        gd_status st0 = gd_sim_orthonormalise(s, 0, err);
        if (st0 != GD_OK)
            goto fail;
    }
    s->implicit = o->method == GD_METHOD_DIRK;
    s->ops = s->implicit ? &gd_stepper_ark : &gd_stepper_erk;
    s->mem = s->implicit ? ARKStepCreate(NULL, rhs_fn, 0.0, s->y, s->ctx) : ERKStepCreate(rhs_fn, 0.0, s->y, s->ctx);
    if (!s->mem) {
        gd_error_set(err, GD_ERR_SOLVER, "%sCreate failed", s->ops->module);
        goto fail;
    }
    CHECK(s->ops->set_err_handler(s->mem, err_handler, s));
    /* cubic Hermite dense output by default: built from the step's end values and derivatives,
     * it costs no RHS evaluation (ARKODE's degrees 4 and 5 cost 1 and 4 per use, and its root
     * check uses it at every step); events are located with the method (refine_root_state) */
    CHECK(s->ops->set_interpolant_degree(s->mem, o->interp_degree > 0 ? o->interp_degree : 3));
    CHECK(s->ops->set_user_data(s->mem, s));
    CHECK(s->ops->ss_tolerances(s->mem, o->rtol, o->atol));
    CHECK(s->ops->set_max_num_steps(s->mem, 1000000));
    CHECK(s->ops->set_max_step(s->mem, o->max_step_fraction * m->period));
    if (s->implicit) {
        if (o->table[0])
            CHECK(ARKStepSetTableName(s->mem, o->table, "ARKODE_ERK_NONE"));
        else
            CHECK(s->ops->set_order(s->mem, o->order));
    } else {
        /* explicit tables go through gd_erk_table_fsal_safe (SUNDIALS 6.4.1 FSAL bug) */
        ARKodeButcherTable B = NULL;
        if (o->method == GD_METHOD_RK4) {
            B = gd_erk_classical_rk4();
        } else {
            const char *name = o->table[0] ? o->table : gd_erk_default_table(o->order);
            ARKodeButcherTable B0 = name ? gd_erk_load(name) : NULL;
            if (!B0) {
                gd_error_set(err, GD_ERR_INPUT, "no explicit Runge-Kutta table '%s' of order %d", name ? name : "",
                             o->order);
                goto fail;
            }
            B = gd_erk_table_fsal_safe(B0);
            ARKodeButcherTable_Free(B0);
        }
        if (!B) {
            gd_error_set(err, GD_ERR_NOMEM, "Butcher table allocation failed");
            goto fail;
        }
        int flag = ERKStepSetTable(s->mem, B);
        ARKodeButcherTable_Free(B);
        CHECK(flag);
        if (o->method == GD_METHOD_RK4 || o->fixed_step)
            CHECK(s->ops->set_fixed_step(s->mem, m->period / o->steps_per_period));
    }
    if (s->implicit) {
        s->A = SUNDenseMatrix(s->N, s->N, s->ctx);
        s->LS = s->A ? SUNLinSol_Dense(s->y, s->A, s->ctx) : NULL;
        if (!s->A || !s->LS) {
            gd_error_set(err, GD_ERR_NOMEM, "dense linear solver allocation failed");
            goto fail;
        }
        CHECK(ARKStepSetLinearSolver(s->mem, s->LS, s->A));
        CHECK(ARKStepSetJacFn(s->mem, jac_fn));
        CHECK(ARKStepSetLSetupFrequency(s->mem, 1));
        CHECK(ARKStepSetJacEvalFrequency(s->mem, 1));
        if (o->fixed_step)
            CHECK(s->ops->set_fixed_step(s->mem, m->period / o->steps_per_period));
    }
    if (o->root_finding && m->nclear > 0) {
        s->nroots = 2 * m->nclear;
        s->gate = !o->ungated_roots && o->refine_events && !s->implicit && o->method != GD_METHOD_RK4 && !o->fixed_step;
        if (!s->gate) {
            CHECK(s->ops->root_init(s->mem, s->nroots, root_fn));
            CHECK(s->ops->set_no_inactive_root_warn(s->mem));
            s->armed = 1;
        }
    }
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

/* QR (GSL Householder) of the tangent vectors: replace them by Q's first k columns and,
 * when accumulate, add log|R_ii| to the sums. */
gd_status gd_sim_orthonormalise(gd_sim *s, int accumulate, gd_error *err)
{
    const int n = s->m.n, k = s->k;
    double *y = NV_DATA_S(s->y);
    for (int v = 0; v < k; v++)
        for (int i = 0; i < n; i++)
            gsl_matrix_set(s->qr, (size_t)i, (size_t)v, y[(v + 1) * n + i]);
    int rc = gsl_linalg_QR_decomp(s->qr, s->tau);
    if (rc == GSL_SUCCESS)
        rc = gsl_linalg_QR_unpack(s->qr, s->tau, s->Q, s->R);
    if (rc != GSL_SUCCESS)
        return gd_error_set(err, GD_ERR_GSL, "renormalising the tangent vectors: gsl_linalg_QR: %s",
                            gsl_strerror(rc));
    for (int v = 0; v < k; v++) {
        double r = gsl_matrix_get(s->R, (size_t)v, (size_t)v);
        if (!(fabs(r) > 0) || !isfinite(r))
            return gd_error_set(err, GD_ERR_SOLVER, "tangent vector %d collapsed or diverged (|R| = %g)", v + 1, r);
        if (accumulate)
            s->lyap_sum[v] += log(fabs(r));
        double sg = r < 0 ? -1.0 : 1.0; /* keep orientation: Q R with a positive diagonal */
        for (int i = 0; i < n; i++)
            y[(v + 1) * n + i] = sg * gsl_matrix_get(s->Q, (size_t)i, (size_t)v);
    }
    return GD_OK;
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
    return reset_at(s, s->t, err);
}

GD_API void gd_sim_lyapunov_start(gd_sim *s)
{
    memset(s->lyap_sum, 0, sizeof s->lyap_sum);
    s->lyap_t0 = abs_time(s, s->t);
}

GD_API int gd_sim_lyapunov(const gd_sim *s, double *exponents, double *elapsed)
{
    double T = abs_time(s, s->t) - s->lyap_t0;
    if (elapsed)
        *elapsed = T;
    for (int v = 0; v < s->k; v++)
        exponents[v] = T > 0 ? s->lyap_sum[v] / T : NAN;
    return s->k;
}

GD_API void gd_sim_free(gd_sim *s)
{
    if (!s)
        return;
    if (s->mem)
        s->ops->free_mem(&s->mem);
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

static int state_finite(const double *y, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(y[i]))
            return 0;
    return 1;
}

static double abs_time(const gd_sim *s, double t_local) { return t_local + (double)s->shift * s->m.period; }

static gd_status reset_at(gd_sim *s, double t, gd_error *err)
{
    double h = 0;
    s->ops->get_last_step(s->mem, &h);
    if (s->h_resume > 0) /* after a refined event: the step the controller had reached, not the redone piece */
        h = s->h_resume;
    s->h_resume = 0;
    int flag = s->ops->reset(s->mem, t, s->y);
    if (flag < 0)
        return sun_check(s, flag, "Reset", err);
    /* keep the step size the controller had reached rather than re-estimating it */
    if (h > 0 && s->o.method != GD_METHOD_RK4 && !s->o.fixed_step)
        s->ops->set_init_step(s->mem, h);
    s->resets++;
    return GD_OK;
}

/* Cubic Hermite of g over a step (values g0, g1, rates d0, d1 times h): does it cross
 * zero and come back? Returns the fraction of the step at the far extremum, or -1. */
static double grazing_fraction(double g0, double g1, double d0, double d1)
{
    if ((g0 > 0) != (g1 > 0) || g0 == 0.0 || g1 == 0.0)
        return -1.0;
    /* most steps: p keeps the sign of g0 for a simple reason. h00 + h01 = 1 with both >= 0, and
     * s (1 - s)^2 and s^2 (1 - s) are at most 4/27 on [0, 1], so |p(s)| >= min(|g0|, |g1|) - 4/27
     * (the rate terms that point towards zero) */
    double sg = g0 > 0 ? 1.0 : -1.0;
    if (fmin(sg * g0, sg * g1) > (4.0 / 27.0) * (fmax(-sg * d0, 0.0) + fmax(sg * d1, 0.0)))
        return -1.0;
    /* p(s) = g0 h00 + d0 h10 + g1 h01 + d1 h11; p'(s) = A s^2 + B s + C */
    double A = 6 * g0 + 3 * d0 - 6 * g1 + 3 * d1;
    double B = -6 * g0 - 4 * d0 + 6 * g1 - 2 * d1;
    double C = d0;
    double roots[2];
    int nr = 0;
    if (fabs(A) < 1e-300) {
        if (fabs(B) > 1e-300)
            roots[nr++] = -C / B;
    } else {
        double disc = B * B - 4 * A * C;
        if (disc >= 0) {
            double sq = sqrt(disc);
            double q = -0.5 * (B + (B >= 0 ? sq : -sq));
            roots[nr++] = q / A;
            if (q != 0)
                roots[nr++] = C / q;
        }
    }
    for (int i = 0; i < nr; i++) {
        double x = roots[i];
        if (!(x > 0 && x < 1))
            continue;
        double h00 = (1 + 2 * x) * (1 - x) * (1 - x), h10 = x * (1 - x) * (1 - x);
        double h01 = x * x * (3 - 2 * x), h11 = x * x * (x - 1);
        double p = g0 * h00 + d0 * h10 + g1 * h01 + d1 * h11;
        if ((p > 0) != (g0 > 0))
            return x;
    }
    return -1.0;
}

/* The clearance coordinates and rates at the current (t, y), computed once per state. */
static void clearances_now(gd_sim *s)
{
    if (!s->cx_ok)
        gd_model_clearances(&s->m, s->t, NV_DATA_S(s->y), &s->md, s->cx, s->cv);
    s->cx_ok = 1;
}

/* A touch hidden inside the step [t0, t1]? Returns the time to stop at, or -1. The clearances at
 * t0 are in cx0, cv0, those at t1 (the current state) in cx, cv. */
static double grazing_check(gd_sim *s, double t0, double t1)
{
    double best = -1.0;
    clearances_now(s);
    for (int c = 0; c < s->m.nclear; c++) {
        double x0 = s->cx0[c], v0 = s->cv0[c], x1 = s->cx[c], v1 = s->cv[c];
        double h = s->m.clear[c].h, dt = t1 - t0;
        for (int side = 0; side < 2; side++) {
            double off = side ? h : -h;
            double f = grazing_fraction(x0 + off, x1 + off, v0 * dt, v1 * dt);
            if (f > 0) {
                double tc = t0 + f * dt;
                if (best < 0 || tc < best)
                    best = tc;
            }
        }
    }
    return best;
}

static int new_mode_for(int old, int r_hi, int r_lo)
{
    /* r_hi: crossing of x - h; r_lo: crossing of x + h (+1 up, -1 down, 0 none) */
    if (r_hi && r_lo)
        return r_hi > 0 ? 1 : -1;
    if (r_hi)
        return r_hi > 0 ? 1 : 0;
    if (r_lo)
        return r_lo < 0 ? -1 : 0;
    return old;
}

static int kind_of(int old, int nw)
{
    return nw == 1 ? GD_EV_CONTACT : nw == -1 ? GD_EV_BACK_CONTACT : old == 1 ? GD_EV_SEPARATION
                                                                          : GD_EV_BACK_SEPARATION;
}

static gd_status record_event(gd_sim *s, int c, int old, int nw, int direction, int located, gd_error *err)
{
    gd_event ev;
    ev.t = abs_time(s, s->t);
    ev.period = s->period;
    ev.clearance = c;
    ev.old_mode = old;
    ev.new_mode = nw;
    ev.direction = direction;
    ev.located = located;
    ev.kind = kind_of(old, nw);
    gd_model_clearance(&s->m, c, s->t, NV_DATA_S(s->y), &s->md, &ev.x, &ev.xdot);
    s->events++;
    s->by_kind[ev.kind]++;
    s->by_clear[c]++;
    s->events_this_period++;
    if (s->event_hook && s->event_hook(s, &ev, s->hook_user))
        return gd_error_set(err, GD_ERR_INTERRUPTED, "stopped by the event hook");
    return GD_OK;
}

/* Tangent vectors across the switching surface of clearance c (mode about to become nw):
 * d+ = d + (f+ - f-) (n . d) / (n . f- + dg/dt), n = grad of g = w.x - e(t) -/+ h. With a
 * continuous dead-zone force and damping that acts always, f+ = f- and this is the identity;
 * damping in contact only makes the vector field jump. */
static void saltation(gd_sim *s, int c, int nw)
{
    const gd_model *m = &s->m;
    const int n = m->n, nd = m->ndof;
    double *y = NV_DATA_S(s->y);
    double fm[GD_MAX_STATE], fp[GD_MAX_STATE];
    gd_model_rhs(m, s->t, y, fm, &s->md);
    int old = s->md.mode[c];
    s->md.mode[c] = nw;
    gd_model_rhs(m, s->t, y, fp, &s->md);
    s->md.mode[c] = old;
    s->extra_rhs += 2;
    double x, xdot;
    gd_model_clearance(m, c, s->t, y, &s->md, &x, &xdot); /* n . f- + dg/dt */
    if (fabs(xdot) < 1e-300)
        return;
    const gd_clearance *cl = &m->clear[c];
    for (int v = 1; v <= s->k; v++) {
        double *d = y + v * n;
        double nd_ = 0;
        for (int q = 0; q < cl->nw; q++)
            nd_ += cl->wval[q] * d[cl->widx[q]];
        double f = nd_ / xdot;
        for (int i = nd; i < n; i++) /* only accelerations can jump */
            d[i] += (fp[i] - fm[i]) * f;
    }
}

/* Where the method itself crosses. ARKODE locates a root on its Hermite interpolant over the
 * step [t0, t1] (cubic by default: no RHS evaluation of its own), which is less accurate than
 * the method. The step is redone with the method from t0 to a little past that root,
 * tr + REFINE_MARGIN (t1 - t0), with root finding on: the crossing is then located again on the
 * interpolant of the redone step, whose end point is the method's solution and lies just past
 * the crossing, so the interpolation error at the root is smaller by about (margin / step)^2
 * and the state at the event has the method's accuracy. The roots found by the redone step
 * replace the first ones (they are the method's). If the interpolant's root was early by more
 * than the margin, the step goes on to t1; if the method does not cross in [t0, t1] at all, no
 * root is reported and the run goes on from t1. Each redone piece is one ARKODE step, and the
 * step hook runs for it on its interpolant. */
#define REFINE_MARGIN 1e-4

/* Give ARKODE the root functions (on) or take them away (gated root finding only). */
static gd_status arm_roots(gd_sim *s, int on, gd_error *err)
{
    if (!s->gate || s->armed == on)
        return GD_OK;
    int flag = s->ops->root_init(s->mem, on ? s->nroots : 0, on ? root_fn : NULL);
    if (flag >= 0 && on)
        flag = s->ops->set_no_inactive_root_warn(s->mem);
    if (flag < 0)
        return sun_check(s, flag, "RootInit", err);
    s->armed = on;
    return GD_OK;
}

/* Gated root finding, after a step [t0, t1] taken without the root functions: the time at which a
 * root function changed sign, by ARKODE's rule (a value exactly zero counts as the side of the held
 * mode, as in root_fn), estimated as the first zero of the cubic Hermite of g from the clearances
 * and rates at both ends; -1 when none changed sign. The estimate only places the end of the step
 * that ARKODE then redoes with its root finding on (refine_root_state), which locates the root. */
static double crossing_in_step(gd_sim *s, double t0, double t1)
{
    double best = -1.0, dt = t1 - t0;
    clearances_now(s);
    for (int c = 0; c < s->m.nclear; c++) {
        int mode = s->md.mode[c];
        double h = s->m.clear[c].h;
        for (int side = 0; side < 2; side++) { /* g = x - h (side 0), x + h (side 1) */
            double off = side ? h : -h;
            double held = side == 0 ? (mode > 0 ? 1.0 : -1.0) : (mode >= 0 ? 1.0 : -1.0);
            double g0 = s->cx0[c] + off, g1 = s->cx[c] + off;
            if (!(g1 * held < 0) || g0 * held < 0)
                continue;
            double d0 = s->cv0[c] * dt, d1 = s->cv[c] * dt, lo = 0.0, hi = 1.0;
            for (int it = 0; it < 48; it++) { /* p(lo) on the held side, p(hi) past it */
                double x = 0.5 * (lo + hi);
                double h00 = (1 + 2 * x) * (1 - x) * (1 - x), h10 = x * (1 - x) * (1 - x);
                double h01 = x * x * (3 - 2 * x), h11 = x * x * (x - 1);
                double p = g0 * h00 + d0 * h10 + g1 * h01 + d1 * h11;
                if (p * held < 0)
                    hi = x;
                else
                    lo = x;
            }
            /* a root in the step's first instant (a second clearance crossing just after one
             * handled at t0) still gets a piece of step for ARKODE to find it in */
            double tc = t0 + fmax(hi, 1e-9) * dt;
            if (best < 0 || tc < best)
                best = tc;
        }
    }
    return best;
}

static gd_status refine_root_state(gd_sim *s, double t0, double tr, gd_error *err)
{
    double t1 = tr;
    if (s->ops->get_current_time(s->mem, &t1) < 0 || !(t1 >= tr))
        t1 = tr;
    if (!(tr > t0))
        return GD_OK;
    int fixed = s->o.method == GD_METHOD_RK4 || s->o.fixed_step;
    double target = fmin(t1, tr + REFINE_MARGIN * (t1 - t0)), ta = t0;
    s->h_resume = t1 - t0;
    memcpy(NV_DATA_S(s->y), s->y_prev, sizeof(double) * (size_t)s->N);
    gd_status ast = arm_roots(s, 1, err);
    if (ast != GD_OK)
        return ast;
    int flag = s->ops->reset(s->mem, t0, s->y), found = 0;
    if (flag >= 0)
        flag = fixed ? s->ops->set_fixed_step(s->mem, target - t0) : s->ops->set_init_step(s->mem, target - t0);
    s->resets++;
    while (flag >= 0) {
        flag = s->ops->set_stop_time(s->mem, target);
        double t2 = ta;
        if (flag >= 0)
            flag = s->ops->evolve(s->mem, target, s->y, &t2, ARK_ONE_STEP);
        if (flag < 0)
            break;
        s->t_step0 = ta;
        s->t = t2;
        s->cx_ok = 0;
        if (s->step_hook && s->step_hook(s, abs_time(s, ta), abs_time(s, t2), s->hook_user))
            return gd_error_set(err, GD_ERR_INTERRUPTED, "stopped by the step hook");
        if (flag == ARK_ROOT_RETURN) {
            flag = s->ops->get_root_info(s->mem, s->rootsfound);
            found = 1;
            break;
        }
        if (!(t2 < t1))
            break; /* the method did not cross in this step */
        if (!(t2 < target)) { /* the crossing lies beyond the margin: on to the end of the step */
            target = t1;
            if (fixed)
                flag = s->ops->set_fixed_step(s->mem, t1 - t2);
        }
        ta = t2;
    }
    if (fixed && flag >= 0) {
        int f2 = s->ops->set_fixed_step(s->mem, s->m.period / s->o.steps_per_period);
        if (f2 < 0)
            flag = f2;
    }
    if (flag < 0)
        return sun_check(s, flag, "refining the state at an event", err);
    if (!found)
        memset(s->rootsfound, 0, sizeof s->rootsfound);
    return GD_OK;
}

static gd_status handle_roots(gd_sim *s, gd_error *err)
{
    for (int c = 0; c < s->m.nclear; c++) {
        int r_hi = s->rootsfound[2 * c], r_lo = s->rootsfound[2 * c + 1];
        if (!r_hi && !r_lo)
            continue;
        int old = s->md.mode[c];
        int nw = new_mode_for(old, r_hi, r_lo);
        if (nw == old)
            continue;
        if (s->k > 0)
            saltation(s, c, nw);
        s->md.mode[c] = nw;
        gd_status st = record_event(s, c, old, nw, (r_hi ? r_hi : r_lo) > 0 ? 1 : -1, 1, err);
        if (st != GD_OK)
            return st;
    }
    /* Another clearance may have crossed within the root tolerance of this one (two halves
     * that touch together, up to rounding) or once the state was refined: a coordinate past
     * a boundary its held mode does not allow switches here and now, or ARKODE, restarting
     * with the root function already past zero, would never see that crossing. */
    clearances_now(s);
    for (int c = 0; c < s->m.nclear; c++) {
        if (s->rootsfound[2 * c] || s->rootsfound[2 * c + 1])
            continue;
        double x = s->cx[c], xd = s->cv[c];
        int old = s->md.mode[c], nw = gd_model_mode_of(&s->m, c, x);
        if (nw == old)
            continue;
        if (s->k > 0)
            saltation(s, c, nw);
        s->md.mode[c] = nw;
        gd_status st = record_event(s, c, old, nw, xd >= 0 ? 1 : -1, 1, err);
        if (st != GD_OK)
            return st;
    }
    if (s->events_this_period > s->o.max_events_per_period)
        return gd_error_set(err, GD_ERR_CHATTER,
                            "chattering: more than %d events in mesh period %ld (t = %.9g periods) without progress; "
                            "raise solver.max_events_per_period or look at the event log",
                            s->o.max_events_per_period, s->period, abs_time(s, s->t) / s->m.period);
    return reset_at(s, s->t, err);
}

/* Root finding on, after a step that ended without a root: a held mode the state has left by
 * more than 1e-6 (1 + h) is a crossing the root finding could not see. It happens at a grazing
 * contact: a separation located exactly on the boundary restarts its root function at exactly
 * zero, ARKODE deactivates it, and a return to contact within the first instants of the next
 * step is never reported; the teeth would then pass through each other without force. The mode
 * is switched at the step end and the event logged as not located (located = 0). The threshold
 * is far above the distance (about 1e-8) a refined event state may lie on the old side of its
 * boundary, and far below any physical length. */
static gd_status repair_held_modes(gd_sim *s, gd_error *err)
{
    int changed = 0;
    clearances_now(s);
    for (int c = 0; c < s->m.nclear; c++) {
        double x = s->cx[c], h = s->m.clear[c].h;
        int old = s->md.mode[c], nw = gd_model_mode_of(&s->m, c, x);
        if (nw == old)
            continue;
        /* distance past the boundary of the region the held mode allows */
        double past = old > 0 ? h - x : old < 0 ? x + h : fabs(x) - h;
        if (!(past > 1e-6 * (1.0 + fabs(h))))
            continue;
        if (s->k > 0)
            saltation(s, c, nw);
        s->md.mode[c] = nw;
        changed = 1;
        gd_status st = record_event(s, c, old, nw, nw > old ? 1 : -1, 0, err);
        if (st != GD_OK)
            return st;
    }
    return changed ? reset_at(s, s->t, err) : GD_OK;
}

/* Root finding off: the modes follow the state; a change between two step ends is
 * reported as an event at the step end (not located, as a fixed-step user would see it). */
static gd_status modes_from_state(gd_sim *s, gd_error *err)
{
    const double *y = NV_DATA_S(s->y);
    for (int c = 0; c < s->m.nclear; c++) {
        double x, v;
        gd_model_clearance(&s->m, c, s->t, y, &s->md, &x, &v);
        int nw = gd_model_mode_of(&s->m, c, x), old = s->md.mode[c];
        if (nw == old)
            continue;
        s->md.mode[c] = nw;
        gd_status st = record_event(s, c, old, nw, nw > old ? 1 : -1, 0, err);
        if (st != GD_OK)
            return st;
    }
    if (s->events_this_period > s->o.max_events_per_period)
        return gd_error_set(err, GD_ERR_CHATTER, "chattering: more than %d events in mesh period %ld",
                            s->o.max_events_per_period, s->period);
    return GD_OK;
}

GD_API gd_status gd_sim_advance_to(gd_sim *s, double t_end_abs, gd_error *err)
{
    double t_end = t_end_abs - (double)s->shift * s->m.period;
    int rewound = 0;
    double t_graze_stop = -1.0;
    while (s->t < t_end) {
        double disc = gd_model_next_discontinuity(&s->m, s->t, &s->md);
        double tstop = fmin(t_end, disc);
        if (s->samp_dt > 0) {
            double ta = abs_time(s, s->t), tiny = 1e-12 * (fabs(ta) + s->m.period);
            double k = ceil((ta + tiny - s->samp_t0) / s->samp_dt);
            if (k < 0)
                k = 0;
            double ts = s->samp_t0 + k * s->samp_dt - (double)s->shift * s->m.period;
            if (ts > s->t && ts < tstop)
                tstop = ts;
        }
        if (rewound && t_graze_stop > s->t && t_graze_stop < tstop)
            tstop = t_graze_stop;
        int flag = s->ops->set_stop_time(s->mem, tstop);
        if (flag < 0)
            return sun_check(s, flag, "SetStopTime", err);
        double t0 = s->t;
        memcpy(s->y_prev, NV_DATA_S(s->y), sizeof(double) * (size_t)s->N);
        if (s->nroots && (s->o.grazing_watch || !s->armed)) { /* the clearances at the start: grazing watch, gate */
            clearances_now(s);
            memcpy(s->cx0, s->cx, sizeof s->cx);
            memcpy(s->cv0, s->cv, sizeof s->cv);
        }
        s->cx_ok = 0;
        double tret = t0;
        s->sunmsg[0] = '\0';
        flag = s->ops->evolve(s->mem, tstop, s->y, &tret, ARK_ONE_STEP);
        if (flag < 0 && s->nonfinite)
            return gd_error_set(err, GD_ERR_SOLVER, "the solution became NaN or infinite at t = %.9g mesh periods",
                                abs_time(s, t0) / s->m.period);
        if (flag < 0) {
            sun_check(s, flag, "Evolve", err);
            return gd_error_prefix(err, "at t = %.9g mesh periods", abs_time(s, t0) / s->m.period);
        }
        if (!state_finite(NV_DATA_S(s->y), s->N))
            return gd_error_set(err, GD_ERR_SOLVER, "the solution became NaN or infinite at t = %.9g mesh periods",
                                abs_time(s, tret) / s->m.period);
        /* near-grazing watch: a crossing and return hidden inside the step */
        if (s->nroots && s->o.grazing_watch && flag != ARK_ROOT_RETURN && !rewound) {
            s->t = tret;
            double tg = grazing_check(s, t0, tret);
            if (tg > 0) {
                s->grazing_suspects++;
                s->grazing_rewinds++;
                memcpy(NV_DATA_S(s->y), s->y_prev, sizeof(double) * (size_t)s->N);
                s->t = t0;
                memcpy(s->cx, s->cx0, sizeof s->cx);
                memcpy(s->cv, s->cv0, sizeof s->cv);
                s->cx_ok = 1;
                gd_status st = arm_roots(s, 1, err); /* the redone steps locate the touch */
                if (st == GD_OK)
                    st = reset_at(s, t0, err);
                if (st != GD_OK)
                    return st;
                if (s->o.method != GD_METHOD_RK4 && !s->o.fixed_step)
                    s->ops->set_init_step(s->mem, 0.5 * (tg - t0));
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
        double tc = s->nroots && !s->armed && !s->md.from_state ? crossing_in_step(s, t0, tret) : -1.0;
        int refine = (flag == ARK_ROOT_RETURN && s->o.refine_events) || tc > 0;
        if (!refine && s->step_hook && s->step_hook(s, abs_time(s, t0), abs_time(s, tret), s->hook_user))
            return gd_error_set(err, GD_ERR_INTERRUPTED, "stopped by the step hook");
        int handled = 0;
        if (flag == ARK_ROOT_RETURN) {
            int f2 = s->ops->get_root_info(s->mem, s->rootsfound);
            if (f2 < 0)
                return sun_check(s, f2, "GetRootInfo", err);
            if (refine) { /* the hook runs on the redone pieces */
                gd_status st = refine_root_state(s, t0, tret, err);
                if (st != GD_OK)
                    return st;
            }
            gd_status st = handle_roots(s, err);
            if (st != GD_OK)
                return st;
            rewound = 0;
            handled = 1;
        } else if (tc > 0) { /* ARKODE redoes the step with its root finding on and locates it */
            memset(s->rootsfound, 0, sizeof s->rootsfound);
            gd_status st = refine_root_state(s, t0, tc, err);
            if (st != GD_OK)
                return st;
            for (int i = 0; i < s->nroots; i++)
                handled |= s->rootsfound[i] != 0;
            if (handled) {
                st = handle_roots(s, err);
                if (st != GD_OK)
                    return st;
                rewound = 0;
            }
        }
        if (!handled && flag == ARK_TSTOP_RETURN) {
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
                gd_status st = reset_at(s, tret, err);
                if (st != GD_OK)
                    return st;
            }
        }
        if (!rewound) {
            gd_status st = arm_roots(s, 0, err);
            if (st != GD_OK)
                return st;
        }
        if (s->md.from_state) {
            gd_status st = modes_from_state(s, err);
            if (st != GD_OK)
                return st;
        } else if (s->nroots && !handled) {
            gd_status st = repair_held_modes(s, err);
            if (st != GD_OK)
                return st;
        }
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
    if (s->k > 0) {
        st = gd_sim_orthonormalise(s, 1, err);
        if (st != GD_OK)
            return st;
        if (s->period - s->shift < SHIFT_PERIODS) {
            st = reset_at(s, s->t, err);
            if (st != GD_OK)
                return st;
        }
    }
    if (s->period - s->shift >= SHIFT_PERIODS) {
        s->shift = s->period;
        st = reset_at(s, 0.0, err);
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

GD_API double gd_sim_time(const gd_sim *s) { return abs_time(s, s->t); }
GD_API long gd_sim_period_index(const gd_sim *s) { return s->period; }
GD_API const double *gd_sim_state(const gd_sim *s) { return NV_DATA_S(s->y); }
GD_API const gd_modes *gd_sim_modes(const gd_sim *s) { return &s->md; }
GD_API const gd_model *gd_sim_model(const gd_sim *s) { return &s->m; }

/* Dense output of a gear model inside the last step [t0, t1] = [tn - h, tn]. The state is
 * (q, v) with q' = v, so the ends give each position its value, rate, acceleration (the RHS at
 * the ends, which ARKODE's Hermite interpolant holds) and jerk (the time derivative of the RHS
 * along the solution, gd_model_jerk, with the step's modes): the septic Hermite Q of q through
 * these eight values, and v = Q'. The error is O(h^8) in q and O(h^7) in v, against O(h^4) for
 * ARKODE's cubic, at four interpolant reads and two jerk evaluations per step with samples and no
 * RHS evaluation (docs/numerics.md section 9). Returns 0 with y filled, 1 when t is not inside
 * the last step (the caller falls back to ARKODE's interpolant), or a negative ARKODE flag. */
static int dense_septic(gd_sim *s, double t, double *y)
{
    const int n = s->m.n, nd = s->m.ndof;
    if (!s->dq_ok || s->dq_key != s->nrhs) {
        double tn = 0, h = 0;
        if (s->ops->get_current_time(s->mem, &tn) < 0 || s->ops->get_last_step(s->mem, &h) < 0 || !(h > 0))
            return 1;
        double t0 = tn - h;
        int flag;
        /* the start of this step is the end of the last step read, when the integrator went on
         * from there (no reset) in the same modes: its values, acceleration and jerk carry over */
        if (s->dq_ok && t0 == s->dq_t1 && s->resets == s->dq_resets &&
            memcmp(&s->md, &s->dq_md, sizeof s->md) == 0) {
            memcpy(s->dq_y0, s->dq_y1, sizeof(double) * (size_t)n);
            memcpy(s->dq_a0, s->dq_a1, sizeof(double) * (size_t)nd);
            memcpy(s->dq_j0, s->dq_j1, sizeof(double) * (size_t)nd);
        } else {
            if ((flag = s->ops->get_dky(s->mem, t0, 0, s->tmp)) < 0)
                return flag;
            memcpy(s->dq_y0, NV_DATA_S(s->tmp), sizeof(double) * (size_t)n);
            if ((flag = s->ops->get_dky(s->mem, t0, 1, s->tmp)) < 0)
                return flag;
            memcpy(s->dq_a0, NV_DATA_S(s->tmp) + nd, sizeof(double) * (size_t)nd);
            if (gd_model_jerk(&s->m, t0, s->dq_y0, s->dq_a0, s->dq_j0, &s->md) != 0)
                return 1;
        }
        if ((flag = s->ops->get_dky(s->mem, tn, 0, s->tmp)) < 0)
            return flag;
        memcpy(s->dq_y1, NV_DATA_S(s->tmp), sizeof(double) * (size_t)n);
        if ((flag = s->ops->get_dky(s->mem, tn, 1, s->tmp)) < 0)
            return flag;
        memcpy(s->dq_a1, NV_DATA_S(s->tmp) + nd, sizeof(double) * (size_t)nd);
        if (gd_model_jerk(&s->m, tn, s->dq_y1, s->dq_a1, s->dq_j1, &s->md) != 0)
            return 1;
        s->dq_resets = s->resets;
        s->dq_md = s->md;
        s->dq_t0 = t0;
        s->dq_h = h;
        s->dq_t1 = tn;
        s->dq_ok = 1;
        s->dq_key = s->nrhs; /* after the reads: a read at tn may evaluate the RHS */
    }
    const double h = s->dq_h, tol = 1e-12 * (fabs(s->dq_t0) + h);
    if (t < s->dq_t0 - tol || t > s->dq_t0 + h + tol)
        return 1;
    double x = (t - s->dq_t0) / h;
    x = x < 0 ? 0 : (x > 1 ? 1 : x);
    const double x2 = x * x, x3 = x2 * x, x4 = x3 * x, x5 = x4 * x, x6 = x5 * x, x7 = x6 * x;
    const double h2 = h * h, h3 = h2 * h;
    for (int i = 0; i < nd; i++) {
        const double q0 = s->dq_y0[i], q1 = s->dq_y1[i], v0 = s->dq_y0[nd + i], v1 = s->dq_y1[nd + i];
        const double a0 = s->dq_a0[i], a1 = s->dq_a1[i], j0 = s->dq_j0[i], j1 = s->dq_j1[i];
        /* Q(x) = q0 + h v0 x + h^2 a0 x^2/2 + h^3 j0 x^3/6 + c4 x^4 + ... + c7 x^7; the residuals of
         * the Taylor part at x = 1 in value and first three derivatives fix c4..c7 */
        const double r0 = q1 - (q0 + h * (v0 + h * (0.5 * a0 + h * j0 / 6.0)));
        const double r1 = h * (v1 - (v0 + h * (a0 + 0.5 * h * j0)));
        const double r2 = h2 * (a1 - (a0 + h * j0));
        const double r3 = h3 * (j1 - j0);
        const double c4 = 35.0 * r0 - 15.0 * r1 + 2.5 * r2 - r3 / 6.0;
        const double c5 = -84.0 * r0 + 39.0 * r1 - 7.0 * r2 + 0.5 * r3;
        const double c6 = 70.0 * r0 - 34.0 * r1 + 6.5 * r2 - 0.5 * r3;
        const double c7 = -20.0 * r0 + 10.0 * r1 - 2.0 * r2 + r3 / 6.0;
        y[i] = q0 + h * (v0 * x + h * (0.5 * a0 * x2 + h * j0 * x3 / 6.0)) + c4 * x4 + c5 * x5 + c6 * x6 + c7 * x7;
        y[nd + i] = v0 + h * (a0 * x + 0.5 * h * j0 * x2) + (4.0 * c4 * x3 + 5.0 * c5 * x4 + 6.0 * c6 * x5 + 7.0 * c7 * x6) / h;
    }
    return 0;
}

GD_API gd_status gd_sim_dense(gd_sim *s, double t_abs, double *y, gd_error *err)
{
    double t = t_abs - (double)s->shift * s->m.period;
    /* the absolute/local conversion can move t by an ulp outside the last step: clamp */
    double tol = 1e-12 * (fabs(s->t) + s->m.period);
    if (t > s->t && t <= s->t + tol)
        t = s->t;
    if (t < s->t_step0 && t >= s->t_step0 - tol)
        t = s->t_step0;
    if (t == s->t) { /* the current state (also before the first step, when there is no interpolant) */
        memcpy(y, NV_DATA_S(s->y), sizeof(double) * (size_t)s->m.n);
        return GD_OK;
    }
    if (!s->o.arkode_dense && !s->m.custom) {
        int r = dense_septic(s, t, y);
        if (r < 0)
            return sun_check(s, r, "GetDky", err);
        if (r == 0)
            return GD_OK;
    }
    int flag = s->ops->get_dky(s->mem, t, 0, s->tmp);
    if (flag < 0)
        return sun_check(s, flag, "GetDky", err);
    memcpy(y, NV_DATA_S(s->tmp), sizeof(double) * (size_t)s->m.n);
    return GD_OK;
}

GD_API void gd_sim_rhs(gd_sim *s, double t_abs, const double *y, double *ydot)
{
    double t = t_abs - (double)s->shift * s->m.period;
    gd_model_rhs(&s->m, t, y, ydot, &s->md);
    s->extra_rhs++;
}

GD_API void gd_sim_get_stats(const gd_sim *s, gd_sim_stats *st)
{
    memset(st, 0, sizeof *st);
    s->ops->get_num_steps(s->mem, &st->steps);
    s->ops->get_num_step_attempts(s->mem, &st->step_attempts);
    st->root_evals = s->nroot_evals;
    st->rhs_evals = s->nrhs;
    st->extra_rhs_evals = s->extra_rhs;
    st->jac_evals = s->jac_calls;
    if (s->implicit)
        ARKStepGetNumLinIters(s->mem, &st->lin_iters);
    st->resets = s->resets;
    st->grazing_suspects = s->grazing_suspects;
    st->grazing_rewinds = s->grazing_rewinds;
    st->events = s->events;
    memcpy(st->events_by_kind, s->by_kind, sizeof s->by_kind);
    memcpy(st->events_by_clearance, s->by_clear, sizeof s->by_clear);
}
