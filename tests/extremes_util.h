/* Helpers of the 'extremes' suite (tests/test_extremes_*.c): run a scene at two tolerances
 * and check that it completes, stays finite, keeps its events bounded, and that the two runs
 * agree (docs/accuracy.md, section "Extremes"). Header-only: each test is one translation unit.
 *
 * A scene runs from its initial state for `periods` mesh periods, every period recorded
 * (transient_periods = 0), so that the two runs can be compared on
 *   - the horizon: the Poincare points of the first `horizon` periods (the trajectory itself,
 *     meaningful whatever the motion: chaotic ones included, over a short enough horizon);
 *   - the tail: the Poincare points and the RMS mesh acceleration of the last `tail` periods
 *     (the steady response; the Poincare points only when the motion is not chaotic, and the
 *     RMS within a statistical tolerance when it is).
 * The Poincare distance is that of gd_workprec_poincare_error (relative to 1 + the largest
 * value of each state variable). */
#ifndef GD_EXTREMES_UTIL_H
#define GD_EXTREMES_UTIL_H

#include "geardyn/geardyn.h"
#include "tap.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct ex_run {
    gd_status st;
    char msg[GD_ERROR_MSG_MAX];
    int n;
    long periods, tail;
    double *pts;             /* (periods + 1) x n */
    long npts;
    double sum2;             /* combined acceleration squared over the tail */
    long count;
    double rms_tail;
    int finite;              /* every sample and every Poincare point finite */
    double wall_s;
    gd_response_result res;
    char motion[32];
    int period_tail;         /* period of the tail's Poincare points (0: none up to 64) */
} ex_run;

static inline double ex_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int ex_on_sample(void *user, const gd_sample *s)
{
    ex_run *r = user;
    double a = 0.5 * (s->accel_mps2[0] + s->accel_mps2[1]);
    if (!isfinite(a) || !isfinite(s->lambda_um[0]) || !isfinite(s->force_n[0]))
        r->finite = 0;
    if (s->period >= r->periods - r->tail) {
        r->sum2 += a * a;
        r->count++;
    }
    return 0;
}

static int ex_on_poincare(void *user, long period, double t_s, const double *y)
{
    ex_run *r = user;
    (void)period;
    (void)t_s;
    if (r->npts <= r->periods) {
        memcpy(r->pts + r->npts * r->n, y, sizeof(double) * (size_t)r->n);
        for (int i = 0; i < r->n; i++)
            if (!isfinite(y[i]))
                r->finite = 0;
        r->npts++;
    }
    return 0;
}

/* Build the case from the defaults, `sets` and `extra` (NULL-terminated), with the given rtol
 * (atol = rtol / 100), and run it `periods` periods from its initial state. */
static inline void ex_run_case(const char *const *sets, const char *const *extra, double rtol, long periods, long tail,
                               ex_run *r)
{
    memset(r, 0, sizeof *r);
    r->finite = 1;
    gd_case c;
    gd_error e = {0};
    gd_case_init(&c, &e);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    int k = 0;
    for (int pass = 0; pass < 2; pass++)
        for (const char *const *p = pass ? extra : sets; p && *p; p++)
            if (gd_case_set(&c, *p, k++, &e) != GD_OK) {
                printf("Bail out! %s: %s\n", *p, e.msg);
                exit(1);
            }
    gd_case_set_number(&c, "solver.rtol", rtol, &e);
    gd_case_set_number(&c, "solver.atol", rtol / 100, &e);
    gd_case_set_number(&c, "run.transient_periods", 0, &e);
    gd_case_set_number(&c, "run.record_periods", (double)periods, &e);
    if (gd_case_resolve(&c, &e) != GD_OK) {
        printf("Bail out! %s\n", e.msg);
        exit(1);
    }
    gd_model m;
    if (gd_model_build(&c, &m, &e) != GD_OK) {
        printf("Bail out! %s\n", e.msg);
        exit(1);
    }
    r->n = m.n;
    r->periods = periods;
    r->tail = tail;
    r->pts = calloc((size_t)(periods + 1) * (size_t)m.n, sizeof(double));
    if (!r->pts) {
        printf("Bail out! out of memory\n");
        exit(1);
    }
    gd_response_hooks h = {ex_on_sample, ex_on_poincare, NULL, NULL};
    double t0 = ex_now();
    r->st = gd_response_run(&c, &m, NULL, &h, r, &r->res, &e);
    r->wall_s = ex_now() - t0;
    snprintf(r->msg, sizeof r->msg, "%s", r->st == GD_OK ? "" : e.msg);
    r->rms_tail = r->count ? sqrt(r->sum2 / (double)r->count) : NAN;
    if (r->st == GD_OK && r->npts == periods + 1 && tail > 0)
        r->period_tail = gd_poincare_period(r->pts + (periods - tail) * m.n, tail + 1, m.n, 1e-6, 64);
    snprintf(r->motion, sizeof r->motion, "%s", r->res.motion);
    gd_case_free(&c);
}

static inline void ex_free(ex_run *r)
{
    free(r->pts);
    r->pts = NULL;
}

typedef struct ex_spec {
    const char *label;
    long periods;            /* mesh periods run */
    long horizon;            /* compare the first `horizon` Poincare points (0: no) */
    double tol_horizon;
    long tail;               /* the last `tail` periods: RMS and Poincare points */
    double tol_tail;         /* Poincare points of the tail (0: not compared, e.g. chaotic) */
    double tol_rms;          /* relative RMS of the tail */
    double max_events_per_period;
    double rtol_a, rtol_b;   /* 0: 1e-7 and 1e-9 */
} ex_spec;

static inline void ex_describe(const char *label, const char *tag, const ex_run *r)
{
    printf("# %s, %s: %s; %.3f s, %.1f steps and %.1f events per mesh period, tail RMS %.6g m/s^2, %s\n", label, tag,
           r->st == GD_OK ? "completed" : r->msg, r->wall_s, (double)r->res.stats.steps / (double)r->periods,
           (double)r->res.stats.events / (double)r->periods, r->rms_tail, r->motion);
}

/* The standard check of an extreme: both tolerances complete, finite, events bounded, agree. */
static inline void ex_check(const ex_spec *sp, const char *const *sets, const char *const *extra)
{
    double ra = sp->rtol_a > 0 ? sp->rtol_a : 1e-7, rb = sp->rtol_b > 0 ? sp->rtol_b : 1e-9;
    ex_run a, b;
    ex_run_case(sets, extra, ra, sp->periods, sp->tail, &a);
    ex_run_case(sets, extra, rb, sp->periods, sp->tail, &b);
    char tag[32];
    snprintf(tag, sizeof tag, "rtol %.0e", ra);
    ex_describe(sp->label, tag, &a);
    snprintf(tag, sizeof tag, "rtol %.0e", rb);
    ex_describe(sp->label, tag, &b);
    tap_ok(a.st == GD_OK && b.st == GD_OK, "%s: completes at rtol %.0e and %.0e%s%s", sp->label, ra, rb,
           a.st != GD_OK ? ": " : b.st != GD_OK ? ": " : "", a.st != GD_OK ? a.msg : b.msg);
    if (a.st != GD_OK || b.st != GD_OK) {
        ex_free(&a);
        ex_free(&b);
        return;
    }
    tap_ok(a.finite && b.finite && isfinite(a.rms_tail) && isfinite(b.rms_tail),
           "%s: no NaN or inf in any sample or Poincare point", sp->label);
    double epp = fmax((double)a.res.stats.events, (double)b.res.stats.events) / (double)sp->periods;
    tap_ok(epp <= sp->max_events_per_period, "%s: events bounded: %.2f per mesh period (at most %g)", sp->label, epp,
           sp->max_events_per_period);
    if (sp->horizon > 0) {
        double d = gd_workprec_poincare_error(a.pts, b.pts, sp->horizon + 1, a.n);
        tap_ok(d <= sp->tol_horizon, "%s: trajectories agree over the first %ld periods: %.3g (tol %g)", sp->label,
               sp->horizon, d, sp->tol_horizon);
    }
    if (sp->tol_tail > 0) {
        long off = sp->periods - sp->tail;
        double d = gd_workprec_poincare_error(a.pts + off * a.n, b.pts + off * b.n, sp->tail + 1, a.n);
        char cls[40];
        if (b.period_tail > 0)
            snprintf(cls, sizeof cls, "period-%d", b.period_tail);
        else
            snprintf(cls, sizeof cls, "not periodic to 1e-6");
        tap_ok(d <= sp->tol_tail, "%s: Poincare points of the last %ld periods (%s) agree: %.3g (tol %g)", sp->label,
               sp->tail, cls, d, sp->tol_tail);
    }
    if (sp->tol_rms > 0) {
        double d = fabs(a.rms_tail - b.rms_tail) / b.rms_tail;
        tap_ok(d <= sp->tol_rms, "%s: RMS acceleration of the last %ld periods agrees: %.6g and %.6g m/s^2, "
               "relative %.3g (tol %g)", sp->label, sp->tail, a.rms_tail, b.rms_tail, d, sp->tol_rms);
    }
    ex_free(&a);
    ex_free(&b);
}

#endif
