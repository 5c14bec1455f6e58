/* The `work-precision` analysis: how much accuracy each method and tolerance buys, and at
 * what cost (docs/accuracy.md).
 *
 * One scene (the case), one starting state on its attractor (the state after
 * run.transient_periods, integrated with the case's own [solver]), and from that state:
 *
 *  - a reference over run.record_periods mesh periods: the explicit method of order
 *    workprecision.reference_order at workprecision.reference_rtol, events located, steps of at
 *    most reference_max_step_fraction of a period (event times come from ARKODE's interpolant),
 *    and a check of it by a second, independent method (order workprecision.check_order at the
 *    same tolerance); their difference is the accuracy floor of every error reported;
 *  - a grid of runs over the same window: classical RK4 at fixed steps (rk4_steps_min to
 *    rk4_steps_max per mesh period, doubling), ARKODE explicit tables by order and ARKODE
 *    DIRK tables over rtol (rtol_loosest to rtol_tightest), each with root finding on and,
 *    when root_finding_off is on, off; a run over max_steps_per_period stops (over-budget, and
 *    the tighter settings of its family are skipped), a run whose state grows past 1e6 times its
 *    start stops (failed: an unstable step);
 *  - an order study: every explicit family at fixed steps over the short horizon
 *    (horizon_periods), with and without event location, and the convergence order of the
 *    Poincare points fitted from it.
 *
 * Errors are measured where users look: the Poincare points (max over points and state
 * components of |p - p_ref| / (1 + max |p_ref|) per component, the periodicity metric of
 * gd_poincare_period), the RMS mesh acceleration (relative), the event times (the largest
 * time difference of each reference event to the nearest event of the same clearance and
 * kind, in mesh periods, capped at 1; an event undone by the next event of its clearance within
 * 1e-6 of a period is a flip-flop of the event handling, not of the motion, and is counted
 * apart, not compared), and for chaotic scenes the short-horizon trajectory error (the
 * Poincare error over the first horizon_periods) and the largest Lyapunov exponent (absolute,
 * per mesh period). Cost: the CPU time of the run's thread (best of `repeats`; on an idle core
 * the wall time, and not inflated by other load), integrator RHS evaluations, steps,
 * events. The library never prints; results come back in gd_wp_result and through hooks. */
#ifndef GD_WORKPREC_H
#define GD_WORKPREC_H

#include "geardyn/gd_response.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GD_WP_MAX_FAMILIES 24
#define GD_WP_MAX_LEVELS 32

/* [workprecision] scene_class */
typedef enum gd_wp_class { GD_WP_CLASS_AUTO = 0, GD_WP_CLASS_PERIODIC = 1, GD_WP_CLASS_CHAOTIC = 2 } gd_wp_class;

/* A family: one method and table at a varying step (rk4, fixed steps) or tolerance. */
typedef struct gd_wp_family {
    char name[24];           /* "rk4", "erk5", "erk5-noroot", "dirk4", ... */
    int method;              /* gd_method */
    int order;
    int root_finding;
    int fixed;               /* 1: the level is steps per mesh period, 0: rtol */
} gd_wp_family;

typedef enum gd_wp_status {
    GD_WP_OK = 0,
    GD_WP_OVER_BUDGET = 1,   /* stopped at workprecision.max_steps_per_period */
    GD_WP_FAILED = 2,        /* the integration failed (message) */
    GD_WP_SKIPPED = 3,       /* a looser setting of its family was over budget */
    GD_WP_UNSTABLE = 4       /* a fixed step outside the method's stability region on the linearised
                              * model (gd_sim_step_stability): its numbers, when it ran to the end, are
                              * kept, and no diagram, fit or choice uses them */
} gd_wp_status;
GD_API const char *gd_wp_status_name(int status);

/* One run of the grid (or of the order study). */
typedef struct gd_wp_run {
    int family;              /* index into gd_wp_result.families */
    char label[48];          /* "erk5 rtol=1e-08", "rk4 N=64" */
    int fixed_step, steps_per_period;
    double rtol, atol;
    int status;              /* gd_wp_status */
    char message[256];
    double cpu_s;            /* CPU time of the thread, best of the repeats */
    long periods;
    long rhs_evals, steps, step_attempts, root_evals, jac_evals, events, ref_events;
    long flipflop_events;    /* events undone by the next event of their clearance within 1e-6 period (not compared) */
    double rms_accel_mps2, mle_per_period;
    /* errors (NaN where not measured) */
    double err_poincare;     /* over the whole window */
    double err_short;        /* over the first horizon_periods */
    double err_rms;          /* relative */
    double err_events;       /* mesh periods, capped at 1 */
    double err_mle;          /* per mesh period */
} gd_wp_run;

/* Convergence order of the Poincare points of one fixed-step family over the horizon. */
typedef struct gd_wp_order {
    int family;
    int nominal;             /* nominal order of the method */
    int nlevels;
    int steps[GD_WP_MAX_LEVELS];
    double err[GD_WP_MAX_LEVELS];
    /* Valid levels: errors between 100 x the reference floor and 1e-2, the longest run of
     * consecutive ones. order: least-squares slope of -log(err) against log(steps) over the
     * three finest valid levels (the asymptotic order); order_range: the same over all of them. */
    double order, order_range;
    int fit_from, fit_to;    /* levels of `order` (inclusive) */
    int range_from;          /* first level of order_range (it ends at fit_to) */
} gd_wp_order;

typedef struct gd_wp_reference {
    char method[96];         /* "erk8 (ARKODE_FEHLBERG_13_7_8) rtol=1e-13 max step 0.002 period" */
    char check_method[96];
    double rtol;
    double check_poincare, check_short, check_rms, check_events; /* reference against its check */
    double floor;            /* accuracy floor of the Poincare errors: max(check, 1e-14) */
    int converged;           /* check difference below workprecision.reference_max_error */
    double rms_accel_mps2, mle_per_period;
    char motion[32];
    int chaotic;             /* the class used for the errors */
    long events, flipflop_events;
    double cpu_s;
    long rhs_evals, steps;
} gd_wp_reference;

typedef struct gd_wp_result {
    gd_wp_reference ref;
    int nfamilies;
    gd_wp_family families[GD_WP_MAX_FAMILIES];
    int nruns;
    gd_wp_run *runs;         /* grid, family after family, loosest setting first */
    int norders;
    gd_wp_order *orders;     /* one per explicit family and root-finding setting */
    gd_wp_run *order_runs;   /* the runs of the order study (norder_runs) */
    int norder_runs;
    long window_periods, horizon_periods;
    double mesh_period_s;
    double start_state[GD_MAX_STATE];
    double wall_s;
} gd_wp_result;

/* Progress: called before each run (what: "reference", "check", "grid", "order") and after
 * it with the finished run (run != NULL). Return nonzero to stop with GD_ERR_INTERRUPTED.
 * should_stop is asked also after every mesh period of every integration (the transient, the
 * reference and its Lyapunov exponent, each run): nonzero stops with GD_ERR_INTERRUPTED. */
typedef struct gd_wp_hooks {
    int (*start)(void *user, const char *what, const char *label, int index, int total);
    int (*done)(void *user, const char *what, const gd_wp_run *run, const gd_wp_result *res);
    int (*should_stop)(void *user);
} gd_wp_hooks;


GD_API gd_status gd_workprec_run(const gd_case *c, const gd_model *m, const gd_wp_hooks *hooks, void *user,
                                 gd_wp_result *res, gd_error *err);
GD_API void gd_workprec_free(gd_wp_result *res);

/* The cheapest finished grid run (CPU time) whose errors are all at or below target: the
 * Poincare error (periodic scenes; the short-horizon error for chaotic ones), the relative RMS
 * error (periodic scenes: the RMS of a chaotic window has a statistical floor of its own), and
 * when with_events the event time error (mesh periods). Returns its index or -1. */
GD_API int gd_workprec_cheapest(const gd_wp_result *res, double target, int with_events);


/* The Poincare error metric: max over k < npts and i < n of |a_ki - b_ki| / (1 + max_k |b_ki|). */
GD_API double gd_workprec_poincare_error(const double *a, const double *b, long npts, int n);

/* The result of the work-precision row of the table of analyses (gd_analysis.h). */
typedef struct gd_workprec_outcome {
    gd_model model;
    gd_wp_result res;
} gd_workprec_outcome;

#ifdef __cplusplus
}
#endif
#endif
