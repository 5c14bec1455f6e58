/* Benchmark: geardyn against its own adaptive floor, a plain C loop with the same Butcher table
 * (Verner's 8(7) pair, the table gd_erk_load gives geardyn), the same error norm and step control
 * as the ARKODE 6.x defaults geardyn runs with, on the same compiled right-hand side
 * (rhs_plan.h), with events. The difference between the two costs is what ARKODE and geardyn's
 * machinery add per step; the RHS evaluations per period show whether the two take the same steps.
 *
 * The loop, per step of size h from (t, y) with k1 = f(t, y) kept from the last step:
 *   stages k2..k13; y1 = y + h sum b_i k_i; error h sum (b_i - d_i) k_i in the weighted RMS norm
 *   with weights 1 / (rtol |y_i| + atol) at the step's start (ARKODE's ewt and N_VWrmsNorm);
 *   ERKStep's default PI controller on the bias 1.2 error with the embedding's order 7 (k1, k2 =
 *   0.8, 0.31), safety 0.99, growth at most 25 (10^4 on the first step),
 *   no growth in [1, 1.5], shrink at least to 0.1, at most 0.3 after two failures in a row, the
 *   largest step (solver.max_step_fraction of a period) and the stop times (period ends and the
 *   excitation's discontinuities) clip the step.
 *   Events: the root functions of the held modes (gd_model_roots) at the step end; a crossing is
 *   located on the septic Hermite dense output of the step (positions, rates, accelerations and
 *   jerks at both ends, as gd_sim_dense) by the Illinois method to ARKODE's root tolerance, the
 *   step is redone from its start to the root with the method, the mode flips there and the
 *   integration restarts with the step size reached (the controller's history kept, as by an
 *   ARKODE reset). geardyn redoes a piece of step with ARKODE's root finding on instead.
 *
 * Scenes: the default torsional scene and the default bta scene, from the static state; each is
 * compared Poincare point by Poincare point with a reference (geardyn, ERK order 8, rtol 1e-13,
 * largest step 0.002 period; gd_workprec_poincare_error). Reported per run: microseconds per mesh
 * period (best of the repeats; wall clock, noisy on a shared machine), RHS evaluations, steps and
 * events per period, nanoseconds per RHS evaluation (time / RHS evaluations) and the Poincare error.
 *
 * Usage: bench_erk_floor [repeats [periods_torsional [periods_bta [rtol]]]]   (defaults 3, 500, 500;
 * periods 0: not that scene; rtol: only this one of 1e-6, 1e-8, 1e-10). Instruction counts, deterministic on a busy machine:
 *   valgrind --tool=callgrind --toggle-collect=geardyn_run bench_erk_floor 1 100 100 1e-8
 *   valgrind --tool=callgrind --toggle-collect=floor_run_periods bench_erk_floor 1 100 100 1e-8 */
#include "geardyn/geardyn.h"

#include "dynamics/erk_table.h"
#include "dynamics/rhs_plan.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAX_STAGES 16

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef struct floor_run {
    const gd_model *m;
    gd_modes md;
    gd_plan_excitation ex[GD_MAX_MESH];
    gd_rhs_plan plan[4];
    int cur, next;
    ARKodeButcherTable B;
    double rtol, atol, hmax;
    /* the step controller's state (ARKODE's hadapt_mem) */
    double ehist[2], etamax, hnext;
    double sc_t[4], sc_s[4], sc_c[4]; /* sin and cos of Omega t at the last four times (as gd_sim) */
    int sc_next;
    long nrhs, steps, attempts, events;
} floor_run;

static const gd_rhs_plan *plan_for(floor_run *f)
{
    if (gd_rhs_plan_current(&f->plan[f->cur], &f->md))
        return &f->plan[f->cur];
    for (int i = 0; i < 4; i++)
        if (gd_rhs_plan_current(&f->plan[i], &f->md))
            return &f->plan[f->cur = i];
    f->cur = f->next;
    f->next = (f->next + 1) % 4;
    gd_rhs_plan_build(&f->plan[f->cur], f->m, &f->md, f->ex);
    return &f->plan[f->cur];
}

static void rhs(floor_run *f, double t, const double *y, double *yd)
{
    double sn = 0.0, cs = 1.0;
    int i = 0;
    while (i < 4 && f->sc_t[i] != t)
        i++;
    if (i < 4) {
        sn = f->sc_s[i], cs = f->sc_c[i];
    } else {
        if (f->m->nmesh > 0)
            sincos(f->m->Omega * t, &sn, &cs);
        f->sc_t[f->sc_next] = t, f->sc_s[f->sc_next] = sn, f->sc_c[f->sc_next] = cs;
        f->sc_next = (f->sc_next + 1) & 3;
    }
    gd_rhs_plan_rhs(plan_for(f), f->m, t, sn, cs, y, yd, &f->md);
    f->nrhs++;
}

/* one step of the table from (t, y) with k[0] = f(t, y): y1, and the error norm (return); the
 * combinations run over the state with the table's zeros skipped (AVX when the processor has it,
 * as geardyn's vector kernels) */
__attribute__((target_clones("avx", "default"))) static double erk_step(floor_run *f, double t, double h, const double *y, double k[][GD_MAX_STATE], double *y1)
{
    const int n = f->m->n, s = f->B->stages;
    double yt[GD_MAX_STATE], e[GD_MAX_STATE];
    for (int i = 1; i < s; i++) {
        memcpy(yt, y, sizeof(double) * (size_t)n);
        for (int j = 0; j < i; j++) {
            const double a = h * f->B->A[i][j];
            if (a != 0.0)
                for (int c = 0; c < n; c++)
                    yt[c] += a * k[j][c];
        }
        rhs(f, t + f->B->c[i] * h, yt, k[i]);
    }
    memcpy(y1, y, sizeof(double) * (size_t)n);
    memset(e, 0, sizeof(double) * (size_t)n);
    for (int j = 0; j < s; j++) {
        const double b = h * f->B->b[j], d = h * (f->B->b[j] - f->B->d[j]);
        if (b != 0.0)
            for (int c = 0; c < n; c++)
                y1[c] += b * k[j][c];
        if (d != 0.0)
            for (int c = 0; c < n; c++)
                e[c] += d * k[j][c];
    }
    double sum = 0.0;
    for (int c = 0; c < n; c++) {
        double w = e[c] / (f->rtol * fabs(y[c]) + f->atol);
        sum += w * w;
    }
    return sqrt(sum / n);
}

/* ARKODE's arkAdapt with ERKStep's default PI controller: the step ratio after a step of size h
 * with error dsm */
static double controller_eta(floor_run *f, double h, double dsm)
{
    const double p = f->B->p, e1 = fmax(1.2 * dsm, 1e-10);
    double ha = h * pow(e1, -0.8 / p) * pow(fmax(f->ehist[0], 1e-10), 0.31 / p);
    ha *= 0.99;
    ha = fmin(ha, f->etamax * h);
    ha = fmax(ha, 0.1 * h);
    if (dsm <= 1.0 && ha > h * (1.0 - 1e-12) && ha < h * 1.5 * (1.0 + 1e-12))
        ha = h;
    double eta = ha / h;
    return eta / fmax(1.0, h * eta / f->hmax);
}

/* the septic Hermite of the positions through both ends of the step (gd_sim_dense), at x in [0, 1] */
static void septic(int nd, double h, const double *y0, const double *a0, const double *j0, const double *y1,
                   const double *a1, const double *j1, double x, double *y)
{
    const double x2 = x * x, x3 = x2 * x, x4 = x3 * x, x5 = x4 * x, x6 = x5 * x, x7 = x6 * x;
    for (int i = 0; i < nd; i++) {
        const double q0 = y0[i], q1 = y1[i], v0 = y0[nd + i], v1 = y1[nd + i];
        const double r0 = q1 - (q0 + h * (v0 + h * (0.5 * a0[i] + h * j0[i] / 6.0)));
        const double r1 = h * (v1 - (v0 + h * (a0[i] + 0.5 * h * j0[i])));
        const double r2 = h * h * (a1[i] - (a0[i] + h * j0[i]));
        const double r3 = h * h * h * (j1[i] - j0[i]);
        const double c4 = 35.0 * r0 - 15.0 * r1 + 2.5 * r2 - r3 / 6.0, c5 = -84.0 * r0 + 39.0 * r1 - 7.0 * r2 + 0.5 * r3;
        const double c6 = 70.0 * r0 - 34.0 * r1 + 6.5 * r2 - 0.5 * r3, c7 = -20.0 * r0 + 10.0 * r1 - 2.0 * r2 + r3 / 6.0;
        y[i] = q0 + h * (v0 * x + h * (0.5 * a0[i] * x2 + h * j0[i] * x3 / 6.0)) + c4 * x4 + c5 * x5 + c6 * x6 + c7 * x7;
        y[nd + i] = v0 + h * (a0[i] * x + 0.5 * h * j0[i] * x2) +
                    (4.0 * c4 * x3 + 5.0 * c5 * x4 + 6.0 * c6 * x5 + 7.0 * c7 * x6) / h;
    }
}

/* root function i (g[2c] = x - h, positive in mode +1; g[2c+1] = x + h, negative in mode -1) is past
 * the side the held modes allow */
static int past_held_side(const floor_run *f, const double *g, int i)
{
    int mode = f->md.mode[i / 2];
    int held_pos = i % 2 == 0 ? mode > 0 : mode >= 0;
    return held_pos ? g[i] < 0.0 : g[i] > 0.0;
}

/* the mode of clearance i / 2 after root function i crossed from its held side */
static int flip(const floor_run *f, int i)
{
    int old = f->md.mode[i / 2];
    return i % 2 == 0 ? (old > 0 ? 0 : 1) : (old < 0 ? 0 : -1);
}

/* root function i along the step [t, t + h] (g0i at its start, g1i past the held side at its end):
 * where it crosses from the held side, as a fraction of h. A start past the side by rounding only
 * (an event of the twin half just located there) counts as the held side (ARKODE's rule for a root
 * function on its boundary); further past, the crossing is at the start. The septic dense output is
 * sampled at eighths of the step for the first sample past the side (the function may first come
 * back to the held side), then the zero in that bracket is found by the Illinois method to ARKODE's
 * root tolerance. */
static double locate(floor_run *f, int i, double t, double h, const double *y0, const double *a0,
                     const double *j0, const double *y1, const double *a1, const double *j1, double g0i, double g1i)
{
    const gd_model *m = f->m;
    double yx[GD_MAX_STATE], g[2 * GD_MAX_CLEAR], lo = 0.0, hi = 1.0, glo = g0i, ghi = g1i;
    g[i] = g0i;
    if (past_held_side(f, g, i)) {
        if (fabs(g0i) > 1e-9 * (1.0 + m->clear[i / 2].h))
            return 0.0;
        glo = g1i > 0 ? -1e-300 : 1e-300;
    }
    for (int q = 1; q < 8; q++) {
        septic(m->ndof, h, y0, a0, j0, y1, a1, j1, q / 8.0, yx);
        gd_model_roots(m, t + q / 8.0 * h, yx, g, &f->md);
        if (past_held_side(f, g, i)) {
            hi = q / 8.0, ghi = g[i];
            break;
        }
        lo = q / 8.0, glo = g[i];
    }
    const double tol = 100.0 * 2.22e-16 * (fabs(t) + h) / h;
    int side = 0;
    while (hi - lo > tol) {
        double x = (lo * ghi - hi * glo) / (ghi - glo);
        if (!(x > lo && x < hi))
            x = 0.5 * (lo + hi);
        septic(m->ndof, h, y0, a0, j0, y1, a1, j1, x, yx);
        gd_model_roots(m, t + x * h, yx, g, &f->md);
        if (past_held_side(f, g, i)) {
            hi = x, ghi = g[i];
            if (side == 1)
                glo *= 0.5;
            side = 1;
        } else {
            lo = x, glo = g[i];
            if (side == -1)
                ghi *= 0.5;
            side = -1;
        }
    }
    return hi;
}

/* Events in the step [t, t + h] (g1: the root functions at its end): the first crossing, located on
 * the septic dense output; the step is redone to it with the method (y, k[0] at the root, *t moved),
 * its mode flips, and so does that of any other clearance past its held side there. */
static void event_in_step(floor_run *f, double *t, double h, double *y, double k[][GD_MAX_STATE], const double *y1,
                          const double *f1, const double *g1)
{
    const gd_model *m = f->m;
    const int n = m->n, nd = m->ndof;
    double j0[GD_MAX_DOF], j1[GD_MAX_DOF], g0[2 * GD_MAX_CLEAR];
    gd_model_jerk(m, *t, y, k[0] + nd, j0, &f->md);
    gd_model_jerk(m, *t + h, y1, f1 + nd, j1, &f->md);
    gd_model_roots(m, *t, y, g0, &f->md);
    double xr = 2.0, xi[2 * GD_MAX_CLEAR];
    for (int i = 0; i < 2 * m->nclear; i++) {
        xi[i] = 2.0;
        if (past_held_side(f, g1, i)) {
            xi[i] = locate(f, i, *t, h, y, k[0] + nd, j0, y1, f1 + nd, j1, g0[i], g1[i]);
            if (xi[i] < xr)
                xr = xi[i];
        }
    }
    double hr = xr * h, yr[GD_MAX_STATE], g[2 * GD_MAX_CLEAR];
    if (hr > 0.0) {
        erk_step(f, *t, hr, y, k, yr);
        memcpy(y, yr, sizeof(double) * (size_t)n);
        *t += hr;
    }
    /* every root within the root tolerance of the first flips with it (two halves that touch
     * together, to rounding), as ARKODE reports them together; then any other clearance past its
     * held side at the root */
    const double tol = 100.0 * 2.22e-16 * (fabs(*t) + h) / h;
    int flips[GD_MAX_CLEAR] = {0};
    for (int i = 0; i < 2 * m->nclear; i++)
        if (xi[i] <= xr + tol && !flips[i / 2]) {
            f->md.mode[i / 2] = flip(f, i);
            flips[i / 2] = 1;
            f->events++;
        }
    gd_model_roots(m, *t, y, g, &f->md);
    for (int i = 0; i < 2 * m->nclear; i++)
        if (!flips[i / 2] && past_held_side(f, g, i)) {
            f->md.mode[i / 2] = flip(f, i);
            f->events++;
        }
    rhs(f, *t, y, k[0]);
}

/* restart at a stop or an event: as ERKStepReset, which keeps the controller's error history and
 * (after the first step) its growth bound */
static void restart(floor_run *f)
{
    f->etamax = f->steps > 0 ? 25.0 : 1e4;
}

/* the excitation levels after a stop at t; 1 when one changed (a discontinuity: restart) */
static int levels_after(floor_run *f, double t)
{
    int changed = 0;
    for (int j = 0; j < f->m->nmesh; j++) {
        int lv = gd_model_rect_level_after(f->m, j, t, &f->md), pv = gd_model_pulse_after(f->m, j, t);
        changed |= lv != f->md.rect_level[j] || pv != f->md.pulse_on[j];
        f->md.rect_level[j] = lv;
        f->md.pulse_on[j] = pv;
    }
    return changed;
}

/* integrate from *t to t_end (an absolute time: the loop does not shift its clock) */
static int floor_advance(floor_run *f, double *t, double t_end, double *y, double k[][GD_MAX_STATE])
{
    const int n = f->m->n;
    double y1[GD_MAX_STATE], g[2 * GD_MAX_CLEAR];
    while (*t < t_end) {
        double tstop = fmin(t_end, gd_model_next_discontinuity(f->m, *t, &f->md));
        double h = fmin(f->hnext, f->hmax);
        int clipped = *t + h >= tstop;
        if (clipped)
            h = tstop - *t;
        int nef = 0;
        double dsm, eta;
        for (;;) {
            f->attempts++;
            dsm = erk_step(f, *t, h, y, k, y1);
            eta = controller_eta(f, h, dsm);
            if (dsm <= 1.0)
                break;
            if (++nef >= 7)
                return 1;
            f->etamax = 1.0;
            if (nef >= 2)
                eta = fmin(eta, 0.3);
            h *= eta;
            clipped = 0;
        }
        f->steps++;
        f->ehist[1] = f->ehist[0];
        f->ehist[0] = 1.2 * dsm;
        f->etamax = 25.0;
        double hnew = h * eta;
        double f1[GD_MAX_STATE];
        rhs(f, *t + h, y1, f1);
        gd_model_roots(f->m, *t + h, y1, g, &f->md);
        int any = 0;
        for (int i = 0; i < 2 * f->m->nclear; i++)
            any |= past_held_side(f, g, i);
        if (any) {
            event_in_step(f, t, h, y, k, y1, f1, g);
            restart(f);
            f->hnext = h;
            continue;
        }
        *t = clipped ? tstop : *t + h;
        memcpy(y, y1, sizeof(double) * (size_t)n);
        memcpy(k[0], f1, sizeof(double) * (size_t)n);
        f->hnext = hnew;
        if (clipped && levels_after(f, *t)) {
            rhs(f, *t, y, k[0]);
            restart(f);
        }
    }
    return 0;
}

typedef struct stats {
    double us, rhs, steps, events, err;
} stats;

static __attribute__((noinline)) int floor_run_periods(const gd_model *m, const gd_solver_opts *o, const double *y0, const gd_modes *md0,
                             long periods, double *pts, stats *st)
{
    static floor_run f;
    memset(&f, 0, sizeof f);
    f.m = m;
    for (int i = 0; i < 4; i++)
        f.sc_t[i] = NAN;
    f.md = *md0;
    f.md.from_state = 0;
    for (int j = 0; j < m->nmesh; j++) {
        f.md.rect_level[j] = gd_model_rect_level_after(m, j, 0.0, &f.md);
        f.md.pulse_on[j] = gd_model_pulse_after(m, j, 0.0);
    }
    gd_plan_excitation_build(f.ex, m);
    f.B = gd_erk_load(gd_erk_default_table(8));
    if (!f.B || f.B->stages > MAX_STAGES)
        return 1;
    f.rtol = o->rtol;
    f.atol = o->atol;
    f.hmax = o->max_step_fraction * m->period;
    f.hnext = 1e-3 * m->period;
    f.ehist[0] = f.ehist[1] = 1.0;
    restart(&f);
    double y[GD_MAX_STATE], k[MAX_STAGES][GD_MAX_STATE], t = 0.0;
    memcpy(y, y0, sizeof(double) * (size_t)m->n);
    memcpy(pts, y, sizeof(double) * (size_t)m->n);
    rhs(&f, t, y, k[0]);
    int rc = 0;
    for (long p = 0; p < periods && !rc; p++) {
        rc = floor_advance(&f, &t, m->period * (double)(p + 1), y, k);
        t = m->period * (double)(p + 1);
        memcpy(pts + (p + 1) * m->n, y, sizeof(double) * (size_t)m->n);
    }
    ARKodeButcherTable_Free(f.B);
    st->rhs = (double)f.nrhs / periods;
    st->steps = (double)f.steps / periods;
    st->events = (double)f.events / periods;
    return rc;
}

/* geardyn's accepted steps (ARKODE's own counter restarts at every reset): counted by a step hook */
static int count_step(gd_sim *s, double t0, double t1, void *user)
{
    (*(long *)user)++;
    return 0;
}

static long hook_steps;

/* st: the statistics per period; with count_steps, the steps through a step hook (not for timing) */
static int sim_run(const gd_model *m, const gd_solver_opts *o, const double *y0, const gd_modes *md0, long periods,
                   double *pts, stats *st, int count_steps)
{
    gd_error e = {0};
    gd_sim *s;
    if (gd_sim_create(m, o, y0, md0, &s, &e) != GD_OK) {
        fprintf(stderr, "%s\n", e.msg);
        return 1;
    }
    hook_steps = 0;
    if (count_steps)
        gd_sim_set_hooks(s, count_step, NULL, &hook_steps);
    memcpy(pts, y0, sizeof(double) * (size_t)m->n);
    for (long p = 0; p < periods; p++) {
        if (gd_sim_period(s, &e) != GD_OK) {
            fprintf(stderr, "%s\n", e.msg);
            gd_sim_free(s);
            return 1;
        }
        memcpy(pts + (p + 1) * m->n, gd_sim_state(s), sizeof(double) * (size_t)m->n);
    }
    if (st) {
        gd_sim_stats ss;
        gd_sim_get_stats(s, &ss);
        st->rhs = (double)ss.rhs_evals / periods;
        st->events = (double)ss.events / periods;
        if (count_steps)
            st->steps = (double)hook_steps / periods;
    }
    gd_sim_free(s);
    return 0;
}

/* the timed geardyn runs (a function of their own: callgrind --toggle-collect=geardyn_run counts them
 * without the reference run) */
static __attribute__((noinline)) int geardyn_run(const gd_model *m, const gd_solver_opts *o, const double *y0,
                                                 const gd_modes *md0, long periods, double *pts, stats *st)
{
    return sim_run(m, o, y0, md0, periods, pts, st, 0);
}

static void print_row(const char *label, const stats *st)
{
    printf("  %-26s %9.2f us/period %8.1f RHS/period %7.1f steps/period %6.2f events/period %7.1f ns/RHS"
           "   Poincare error %.3g\n",
           label, st->us, st->rhs, st->steps, st->events, 1e3 * st->us / st->rhs, st->err);
    fflush(stdout);
}

static double rtol_only; /* > 0: this tolerance only */

static int scene(const char *title, const char *const *sets, long periods, int repeats)
{
    gd_case c;
    gd_error e = {0};
    gd_case_init(&c, &e);
    for (int i = 0; sets[i]; i++)
        if (gd_case_set(&c, sets[i], i, &e) != GD_OK) {
            fprintf(stderr, "%s: %s\n", sets[i], e.msg);
            return 1;
        }
    gd_model m;
    if (gd_case_resolve(&c, &e) != GD_OK || gd_model_build(&c, &m, &e) != GD_OK) {
        fprintf(stderr, "%s\n", e.msg);
        return 1;
    }
    double y0[GD_MAX_STATE];
    gd_modes md0;
    gd_initial_state(&c, &m, y0, &md0, &e);
    size_t sz = (size_t)(periods + 1) * (size_t)m.n;
    double *ref = malloc(sizeof(double) * sz), *pts = malloc(sizeof(double) * sz);
    gd_solver_opts o;
    gd_solver_opts_from_case(&c, &o);
    o.order = 8;
    o.rtol = 1e-13;
    o.atol = 1e-15;
    o.max_step_fraction = 0.002;
    printf("\n%s: %ld mesh periods from the static state\n", title, periods);
    int rc = sim_run(&m, &o, y0, &md0, periods, ref, NULL, 0);
    for (double rt = 1e-6; rt >= 0.9e-10 && !rc; rt /= 100) {
        if (rtol_only > 0 && fabs(rt / rtol_only - 1.0) > 1e-6)
            continue;
        gd_solver_opts_from_case(&c, &o);
        o.rtol = rt;
        o.atol = rt / 100;
        stats sf = {1e300, 0, 0, 0, 0}, sg = {1e300, 0, 0, 0, 0};
        for (int r = 0; r < repeats && !rc; r++) { /* interleaved: the same machine load for both */
            double t0 = now();
            rc |= floor_run_periods(&m, &o, y0, &md0, periods, pts, &sf);
            sf.us = fmin(sf.us, 1e6 * (now() - t0) / periods);
            sf.err = gd_workprec_poincare_error(pts, ref, periods + 1, m.n);
            t0 = now();
            rc |= geardyn_run(&m, &o, y0, &md0, periods, pts, &sg);
            sg.us = fmin(sg.us, 1e6 * (now() - t0) / periods);
            sg.err = gd_workprec_poincare_error(pts, ref, periods + 1, m.n);
        }
        stats counted = sg;
        rc |= sim_run(&m, &o, y0, &md0, periods, pts, &counted, 1);
        sg.steps = counted.steps;
        char label[64];
        snprintf(label, sizeof label, "plain loop, rtol %.0e", rt);
        print_row(label, &sf);
        snprintf(label, sizeof label, "geardyn,    rtol %.0e", rt);
        print_row(label, &sg);
        printf("    geardyn / floor: %.2f in time, %.2f in RHS evaluations\n", sg.us / sf.us, sg.rhs / sf.rhs);
    }
    free(ref);
    free(pts);
    gd_case_free(&c);
    return rc;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 3;
    long pt = argc > 2 ? atol(argv[2]) : 500, pb = argc > 3 ? atol(argv[3]) : 500;
    rtol_only = argc > 4 ? atof(argv[4]) : 0.0;
    printf("geardyn %s on %s: Verner 8(7) in a plain C loop against geardyn (ERK order 8), best of %d\n",
           GD_VERSION_STRING, GD_SUNDIALS_BUILD, repeats);
    /* the paper's pair at its operating point, 4000 rpm and 500 N m */
    const char *tors[] = {"scene.model=torsional", "operating.speed_rpm=4000", "operating.torque_nm=500", NULL};
    const char *bta[] = {"scene.model=bta", "operating.speed_rpm=4000", "operating.torque_nm=500", NULL};
    int rc = pt > 0 ? scene("torsional, default scene", tors, pt, repeats) : 0;
    rc |= pb > 0 ? scene("bta, default scene", bta, pb, repeats) : 0;
    return rc;
}
