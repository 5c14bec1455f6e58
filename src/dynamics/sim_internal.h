/* Internal to the integrator (simulate.c and the sim_*.c files): the definition of the
 * opaque gd_sim of gd_sim.h, and the functions its files share. Not part of the public
 * API: no GD_API here (hidden by -fvisibility=hidden). */
#ifndef GD_SIM_INTERNAL_H
#define GD_SIM_INTERNAL_H

#include "geardyn/gd_sim.h"

#include "model_internal.h"
#include "rhs_plan.h"
#include "compat/stepper.h" /* and compat/sundials_compat.h */

#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>
#include <math.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#define SIM_PLANS 8        /* compiled RHS kept, one per recent set of contact modes */
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
    void *adapt_6x;          /* SUNDIALS >= 7.3: the 6.x step-size controller (compat/arkode_6x_defaults.c) */
    int implicit;
    double t;                /* integrator (local) time */
    long shift;              /* whole periods shifted out of t */
    long period;             /* index of the period that contains t */
    double *y_prev;          /* N: the state at the start of the last step */
    int k, N;                /* tangent vectors, total length n (1 + k) */
    double lyap_sum[GD_MAX_STATE];
    double lyap_t0;          /* absolute time where the sums started */
    int tangent_free;        /* 1: no renormalisation (gd_sim_set_tangent): the tangent vectors are D phi V */
    gsl_matrix *qr, *Q, *R;
    gsl_vector *tau;
    double t_step0;          /* start of the last step (local) */
    double samp_t0, samp_dt; /* sample grid (absolute time; samp_dt 0: none): steps end on it */
    int no_edges;            /* 1: the excitation has no discontinuity (no stop time of its own) */
    double cx[GD_MAX_CLEAR], cv[GD_MAX_CLEAR];   /* clearance coordinates and rates at (t, y) when cx_ok */
    double cx0[GD_MAX_CLEAR], cv0[GD_MAX_CLEAR]; /* the same at the start of the last step */
    int cx_ok;
    int nroots;
    int rootsfound[2 * GD_MAX_CLEAR];
    /* gated root finding (docs/numerics.md section 3): ARKODE holds the root functions (armed)
     * only while it locates a crossing that the step-end check found, or redoes a step the
     * grazing watch suspects; every other step ends without its root machinery */
    int gate, armed;
    gd_gap_extrema *gaps;    /* the gap watch's record (gd_sim_watch_gaps), or NULL */
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
    char sunmsg[GD_SUN_MSG_SIZE]; /* SUNDIALS' last error message (compat/sundials_compat.h) */
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
     * opens and closes goes back and forth between two; bta's six clearances at an impacting
     * speed cycle through more than four, and a plan costs about 3 000 instructions to build) */
    gd_rhs_plan plan[SIM_PLANS];
    gd_plan_excitation plan_ex[GD_MAX_MESH];
    int plan_cur, plan_next, use_plan;
    /* a held side (sim_probe.h): while the absolute time lies in [hold_t0, hold_t1] (t0 > t1: outside (t1, t0)) the
     * root function hold_root (2c: x - h, 2c + 1: x + h of clearance hold_clear) reports no crossing and
     * the state's side of it switches no mode: the vector field of the held mode is continued there */
    int hold_on, hold_clear, hold_root;
    double hold_t0, hold_t1;
};

/* sin(Omega t) and cos(Omega t), from the cache when t was one of the last four times */
static inline void sim_phase_at(gd_sim *s, double t, double *sn, double *cs)
{
    /* asked at every stage and most stages miss: the four compares written out, no loop */
    int i = s->sc_t[0] == t ? 0 : s->sc_t[1] == t ? 1 : s->sc_t[2] == t ? 2 : s->sc_t[3] == t ? 3 : -1;
    if (i >= 0) {
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

static inline double sim_abs_time(const gd_sim *s, double t_local)
{
    return t_local + (double)s->shift * s->m.period;
}

/* Whether the root function i is held at the local time t (gd_sim_hold_side). */
static inline int sim_root_held(const gd_sim *s, int i, double t_local)
{
    if (!s->hold_on || i != s->hold_root)
        return 0;
    double ta = sim_abs_time(s, t_local);
    return s->hold_t0 <= s->hold_t1 ? ta >= s->hold_t0 && ta <= s->hold_t1 : ta >= s->hold_t0 || ta <= s->hold_t1;
}

/* Whether clearance c is held at the local time t: its mode is not switched from the state there. */
static inline int sim_clear_held(const gd_sim *s, int c, double t_local)
{
    return s->hold_on && c == s->hold_clear && sim_root_held(s, s->hold_root, t_local);
}

/* simulate.c: the driver */
/* GD_OK for an ARKODE flag >= 0, else the error "<call> failed: <flag name> (<flag>): <message>" */
gd_status gd_sim_sun_check(gd_sim *s, int flag, const char *call, gd_error *err);
/* Return from the calling function (which has a gd_sim *s and a gd_error *err) when a SUNDIALS
 * call fails, with the call's text in the message. */
#define CHECK(call)                                                                                                \
    do {                                                                                                           \
        gd_status st_ = gd_sim_sun_check(s, (call), #call, err);                                                   \
        if (st_ != GD_OK)                                                                                          \
            return st_;                                                                                            \
    } while (0)
/* Reset the integrator at local time t on the current state, keeping the step size reached */
gd_status gd_sim_reset_at(gd_sim *s, double t, gd_error *err);

/* sim_events.c: event location, grazing watch, saltation */
gd_status gd_sim_roots_setup(gd_sim *s, gd_error *err);
gd_status gd_sim_arm_roots(gd_sim *s, int on, gd_error *err);
void gd_sim_clearances_compute(gd_sim *s);
/* The clearance coordinates and rates at the current (t, y) in cx, cv, computed once per state
 * (cx_ok); asked four times a step, inline */
static inline void gd_sim_clearances_now(gd_sim *s)
{
    if (!s->cx_ok)
        gd_sim_clearances_compute(s);
}
gd_status gd_sim_grazing_watch(gd_sim *s, double t0, double t1, double *tg, gd_error *err);
/* After an accepted step (or redone piece) [t0, t1] (absolute): the gap watch when on, then the
 * step hook */
gd_status gd_sim_after_step(gd_sim *s, double t0, double t1, gd_error *err);
double gd_sim_crossing_in_step(gd_sim *s, double t0, double t1);
/* The bisection of the cubic Hermite of a root function over [0, 1] for a sign change (values g0,
 * g1, rates d0, d1 times the step; held = +1 or -1 the side of the held mode): the end past it of
 * the last of 48 halvings (tests/test_bisect_crossing.c checks it against one halving at a time) */
double gd_sim_bisect_crossing(double g0, double d0, double g1, double d1, double held);
gd_status gd_sim_roots_after_step(gd_sim *s, int flag, int refine, double t0, double tret, double tc, int *handled,
                                  gd_error *err);
gd_status gd_sim_repair_held_modes(gd_sim *s, gd_error *err);
gd_status gd_sim_modes_from_state(gd_sim *s, gd_error *err);

/* sim_lyapunov.c: tangent vectors and their QR renormalisation */
gd_status gd_sim_tangent_init(gd_sim *s, gd_error *err);
gd_status gd_sim_orthonormalise(gd_sim *s, int accumulate, gd_error *err);

#endif
