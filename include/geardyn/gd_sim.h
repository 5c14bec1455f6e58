/* Event-exact time integration of a gd_model with SUNDIALS ARKODE.
 *
 * Methods: ARKODE ERKStep explicit Runge-Kutta (order 2-8 or a named table), ARKODE
 * ARKStep DIRK (implicit, dense linear solver, analytic Jacobian) for stiff scenes, and
 * the classical fixed-step RK4 (the paper's method) run through ERKStep with its
 * Butcher table and a fixed step, so that it too can locate events.
 *
 * Root finding on both sides of every clearance: at a located root the contact mode held
 * in gd_modes flips and the integrator is reset there (SUNDIALS' recipe for non-smooth
 * right-hand sides). Time discontinuities of the excitation and the mesh-period
 * boundaries are stop times, so Poincare samples are exact. A near-grazing watch
 * re-integrates any step in which a clearance coordinate, interpolated by a cubic
 * Hermite from its values and rates at both ends, crosses and returns. */
#ifndef GD_SIM_H
#define GD_SIM_H

#include "geardyn/gd_model.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gd_solver_opts {
    int method;              /* gd_method */
    int order;
    char table[128];
    double rtol, atol;
    int steps_per_period;    /* rk4, and erk when fixed_step is on */
    int fixed_step;          /* erk: fixed step of period/steps_per_period instead of adaptive */
    int root_finding;
    int grazing_watch;
    double max_step_fraction;
    int max_events_per_period;
    int max_separated_periods; /* a mesh open this long stops the run (GD_ERR_PHYSICS) */
    int n_tangent;           /* tangent vectors integrated with the trajectory (Lyapunov), 0..n */
    int refine_events;       /* redo the step to a located root with the method (not the interpolant) */
    int interp_degree;       /* degree of ARKODE's Hermite dense output: 0 = 3 (cubic: no RHS evaluation
                              * of its own); 4 and 5 cost 1 and 4 RHS evaluations per use */
    int library_vector_ops;  /* 1: SUNDIALS' own serial vector kernels; 0: geardyn's (the same
                              * results bit for bit, compiled with geardyn; docs/performance.md) */
    int generic_rhs;         /* 1: the model's general RHS and tangent loops at every stage; 0 (default):
                              * compiled for the held contact modes at each change of modes (the same
                              * function, a different order of the operations: equal to rounding) */
    int ungated_roots;       /* 1: ARKODE checks the root functions at every step; 0 (default): geardyn checks
                              * their signs at each step end and ARKODE, given the functions only then,
                              * redoes a step that crossed and locates the root (docs/numerics.md
                              * section 3; adaptive ERK with refine_events; the same events) */
    int arkode_dense;        /* gd_sim_dense: 0 (default) the septic Hermite of the positions through
                              * both ends of the step (values, rates, accelerations, jerks; gear models;
                              * docs/numerics.md section 9), 1 ARKODE's Hermite interpolant (of
                              * interp_degree); custom systems always use ARKODE's */
} gd_solver_opts;

/* The options of a case's default [solver] keys (gd_solver_opts_from_case of a case that gives
 * none): ERK order 8, rtol 1e-8, events located, the compiled RHS; no tangent vectors. */
GD_API gd_solver_opts gd_solver_opts_defaults(void);


typedef enum gd_event_kind {
    GD_EV_CONTACT = 0,       /* into drive-side contact (bearing: positive side) */
    GD_EV_SEPARATION = 1,    /* out of drive-side contact into the gap */
    GD_EV_BACK_CONTACT = 2,  /* into back-side contact (bearing: negative side) */
    GD_EV_BACK_SEPARATION = 3,
    GD_EV_NKINDS = 4
} gd_event_kind;

GD_API const char *gd_event_kind_name(int kind);

typedef struct gd_event {
    double t;                /* dimensionless time since the start of the run */
    long period;             /* mesh period index since the start of the run */
    int clearance;           /* index into model->clear */
    int kind;                /* gd_event_kind */
    int direction;           /* +1 coordinate increasing, -1 decreasing */
    int old_mode, new_mode;
    double x, xdot;          /* clearance coordinate and rate at the crossing (dimensionless) */
    int located;             /* 1: located by root finding; 0: seen at a step end (root finding off) */
} gd_event;

typedef struct gd_sim_stats {
    long steps, step_attempts, rhs_evals, root_evals, jac_evals, lin_iters;
    long extra_rhs_evals;    /* RHS calls of the analysis (accelerations at samples), not the integrator's */
    long resets, grazing_suspects, grazing_rewinds;
    long events, events_by_kind[GD_EV_NKINDS];
    long events_by_clearance[GD_MAX_CLEAR];
} gd_sim_stats;

typedef struct gd_sim gd_sim;

/* Hooks (all optional). step: after every accepted step, interpolation over (t0, t1]
 * is available through gd_sim_dense. event: at every located event. Return nonzero
 * from a hook to stop the run with GD_ERR_INTERRUPTED. */
typedef int (*gd_step_hook)(gd_sim *s, double t0, double t1, void *user);
typedef int (*gd_event_hook)(gd_sim *s, const gd_event *ev, void *user);

GD_API gd_status gd_sim_create(const gd_model *m, const gd_solver_opts *o, const double *y0, const gd_modes *md0,
                               gd_sim **out, gd_error *err);
GD_API void gd_sim_free(gd_sim *s);
GD_API void gd_sim_set_hooks(gd_sim *s, gd_step_hook step, gd_event_hook event, void *user);

/* Advance by one mesh period, ending exactly on the period boundary. */
GD_API gd_status gd_sim_period(gd_sim *s, gd_error *err);
/* Advance to an absolute dimensionless time inside the current period or beyond. */
GD_API gd_status gd_sim_advance_to(gd_sim *s, double t_end, gd_error *err);

/* Make steps end on the times t_first + k dt (absolute; dt = 0: no grid), so that states
 * sampled there are the method's solution, not an interpolant's. */
GD_API void gd_sim_set_sample_grid(gd_sim *s, double t_first, double dt);
/* Current time (absolute, dimensionless), state and modes. */
GD_API double gd_sim_time(const gd_sim *s);
GD_API long gd_sim_period_index(const gd_sim *s);
GD_API const double *gd_sim_state(const gd_sim *s);
GD_API const gd_modes *gd_sim_modes(const gd_sim *s);
/* Interpolated state at absolute time t inside the last step (valid inside hooks). */
GD_API gd_status gd_sim_dense(gd_sim *s, double t, double *y, gd_error *err);
/* Right-hand side at (t, y) with the current modes (counted in the statistics). */
GD_API void gd_sim_rhs(gd_sim *s, double t, const double *y, double *ydot);
GD_API void gd_sim_get_stats(const gd_sim *s, gd_sim_stats *st);

/* Lyapunov exponents from the tangent vectors (opts.n_tangent > 0): the variational
 * equations are integrated with the trajectory in the current contact mode, switched
 * exactly at every located event with the saltation matrix applied, and renormalised
 * (QR) at every mesh period. gd_sim_lyapunov_start zeroes the sums (call it after the
 * transient); gd_sim_lyapunov gives the exponents per unit of dimensionless time and
 * returns their number. */
GD_API void gd_sim_lyapunov_start(gd_sim *s);
/* Replace the trajectory state (not the tangent vectors) at the current time; the modes
 * are made consistent with it and the integrator is reset. */
GD_API gd_status gd_sim_set_state(gd_sim *s, const double *y, gd_error *err);
GD_API int gd_sim_lyapunov(const gd_sim *s, double *exponents, double *elapsed);

/* Variational mode (the monodromy of a periodic orbit): set the opts.n_tangent tangent vectors
 * to the columns of V (n x n_tangent, row-major) and integrate them from now on without the
 * renormalisation of every mesh period, so that they are D phi(t, t0) V, with the saltation
 * matrix applied at every located event. */
GD_API gd_status gd_sim_set_tangent(gd_sim *s, const double *V, gd_error *err);
/* The tangent vectors as the columns of V (n x n_tangent, row-major). */
GD_API void gd_sim_get_tangent(const gd_sim *s, double *V);

/* The stroboscopic map of nper mesh periods from the state y0 at t = 0 (modes consistent with
 * y0): y1 = phi(nper T, 0, y0), and when M is not NULL its Jacobian, the monodromy matrix
 * (n x n, row-major), from the variational equations with a saltation matrix at every located
 * event (o->n_tangent is replaced by n, or 0 when M is NULL). st (may be NULL): the statistics
 * of the run, its events by clearance among them. M needs o->root_finding on a model with clearances
 * (GD_ERR_INPUT otherwise: a mode switched from the state has no saltation matrix). */
GD_API gd_status gd_sim_period_map(const gd_model *m, const gd_solver_opts *o, const double *y0, int nper,
                                   double *y1, double *M, gd_sim_stats *st, gd_error *err);
GD_API const gd_model *gd_sim_model(const gd_sim *s);

/* The local extrema of the clearance coordinates over a run: where the rate of a coordinate
 * changes sign inside a step, the time at which it vanishes, found on the dense output
 * (gd_sim_dense) by GSL's Brent solver, and the coordinate there. The distance of an extremum
 * to a boundary, x - h or x + h, is signed: its zero is a grazing (docs/continuation.md). */
#define GD_GAP_EXTREMA_MAX 64
typedef struct gd_gap_extrema {
    int n[GD_MAX_CLEAR];                        /* extrema recorded, by clearance */
    long dropped;                               /* extrema beyond GD_GAP_EXTREMA_MAX, not recorded */
    double h[GD_MAX_CLEAR];                     /* the clearance's half gap (boundaries at +-h) */
    double t[GD_MAX_CLEAR][GD_GAP_EXTREMA_MAX]; /* time of the extremum, dimensionless, from the start */
    double x[GD_MAX_CLEAR][GD_GAP_EXTREMA_MAX]; /* the clearance coordinate there */
    signed char kind[GD_MAX_CLEAR][GD_GAP_EXTREMA_MAX]; /* +1 maximum, -1 minimum */
} gd_gap_extrema;
/* Record into g (cleared here) the extrema of every step from now on; NULL stops. */
GD_API void gd_sim_watch_gaps(gd_sim *s, gd_gap_extrema *g);
/* The extrema of the clearance coordinates over nper mesh periods from y0 at t = 0 (a plain
 * integration, as gd_sim_period_map without M). */
GD_API gd_status gd_sim_orbit_gaps(const gd_model *m, const gd_solver_opts *o, const double *y0, int nper,
                                   gd_gap_extrema *g, gd_error *err);


/* Linear stability of a fixed explicit step (o: RK4, or ERK with fixed_step; h = period /
 * steps_per_period) on the model's Jacobian at the state y in the modes md, at eight phases of the
 * mesh period: the largest amplification |R(h lambda)| of the method's stability function R over
 * the eigenvalues lambda, the eigenvalue attaining it, and the fewest steps per mesh period for
 * which every |R| <= 1 (docs/accuracy.md). An adaptive or implicit method, or a custom system
 * without a Jacobian: amplification NaN, unstable 0, min_steps_per_period 0. */
typedef struct gd_step_stability {
    double h;                 /* the step, dimensionless */
    double amplification;     /* max |R(h lambda)| */
    int unstable;             /* amplification > 1 (beyond rounding) */
    double lambda_re, lambda_im; /* the eigenvalue attaining it (|Im|), over omega_n */
    double freq_hz;           /* its |Im lambda| in Hz */
    double damping_ratio;     /* -Re lambda / |lambda| */
    long min_steps_per_period;
} gd_step_stability;
GD_API gd_status gd_sim_step_stability(const gd_model *m, const gd_solver_opts *o, const double *y, const gd_modes *md,
                                       gd_step_stability *out, gd_error *err);


#ifdef __cplusplus
}
#endif
#endif
