/* Internal: what the files of the work-precision analysis share (work_precision.c, wp_run.c,
 * wp_errors.c; wp_families.c only needs analysis_internal.h). */
#ifndef GD_ANALYSIS_WP_INTERNAL_H
#define GD_ANALYSIS_WP_INTERNAL_H

#include "geardyn/gd_workprec.h"
#include "analysis_internal.h"

typedef struct wp_ev {
    double t;
    int clearance, kind, old_mode, new_mode;
} wp_ev;

typedef struct wp_setting {
    int method, order, root_finding, fixed, steps;
    double rtol, atol;
    double max_step_fraction; /* 0: the case's */
    int exact_samples;        /* steps end on the sample times (the reference; else the case's setting) */
} wp_setting;

typedef struct wp_trace {
    double *pts;             /* (periods + 1) x n */
    long npts;
    wp_ev *ev;
    long nev, cap;
    long flipflops;          /* events removed as undone at once (pairs, counted as events) */
    double rms;
    gd_sim_stats stats;
    double cpu;              /* CPU time of the calling thread, s */
    int status;              /* gd_wp_status */
    int complete;            /* every period integrated (OK, or UNSTABLE run to the end) */
    char msg[256];
} wp_trace;

/* wp_run.c */
/* Integrate `periods` mesh periods from (y0, md0) with setting w: the Poincare points, the
 * events, the RMS of the mean mesh acceleration (when sample) and the statistics. A failed or
 * over-budget run is not an error of the analysis: it is reported in tr->status. */
gd_status wp_run_one(const gd_case *c, const gd_model *m, const wp_setting *w, const double *y0,
                     const gd_modes *md0, long periods, int sample, long budget, const gd_stop_hook *stop,
                     wp_trace *tr, gd_error *err);
void wp_trace_free(wp_trace *tr);
/* The largest Lyapunov exponent per mesh period of setting w over the window (a response run). */
gd_status wp_lyapunov_run(const gd_case *c, const gd_model *m, const wp_setting *w, const double *y0,
                          const gd_modes *md0, long periods, const gd_stop_hook *stop, double *mle, gd_error *err);

/* wp_errors.c: a run's errors against the reference into r (gd_wp_run) */
void wp_fill_run(gd_wp_run *r, const wp_trace *tr, const wp_trace *ref, long periods, long horizon, int chaotic,
                 double period, int n, gd_error *err, gd_status *st);
/* The valid levels (error between 100 x floor and 1e-2: above the reference floor, past the
 * unstable or pre-asymptotic start) and the orders fitted over them (gd_wp_order). */
void wp_fit_order(gd_wp_order *o, double floor_);

#endif
