/* Benchmark: geardyn against the floor set by the right-hand side itself, a minimal fixed-step
 * classical RK4 loop in plain C calling gd_model_rhs (docs/performance.md).
 *
 * The loop has no events: the contact mode of every clearance follows the state at every RHS
 * call (gd_modes.from_state), as in any hand-written integrator; its cost is four RHS calls and
 * a few vector updates per step, nothing else. geardyn runs the same scene with ARKODE (ERK order
 * 5 and 8 over rtol, classical RK4 at fixed steps, events located). Every run starts from the
 * static state and is compared, Poincare point by Poincare point over the window, with a
 * reference (ERK order 8, rtol 1e-13, largest step 0.002 of a period); the error metric is that of
 * gd_workprec_poincare_error. Reported: the cost per mesh period of each run and, for each
 * accuracy target, the cheapest run of each kind that reaches it.
 *
 * Scenes: the torsional model at 4000 rpm (period-1, double-sided impacts), the same without
 * impacts (permanent contact: smooth, where the loop keeps its 4th order), and the bta model at
 * 7000 rpm (period-1, single-sided impacts; cases/accuracy/period1-7000rpm.ini).
 *
 * Usage: bench_rk4_floor [repeats]   (best of the repeats; default 3) */
#include "geardyn/geardyn.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef struct row {
    char label[64];
    double us_per_period, err;
    int kind; /* 0 plain loop, 1 geardyn */
} row;

static row rows[256];
static int nrows;

/* The floor: y += h/6 (k1 + 2 k2 + 2 k3 + k4), N steps per mesh period, modes from the state. */
static void rk4_loop(const gd_model *m, const double *y0, long periods, int N, double *pts)
{
    const int n = m->n;
    double y[GD_MAX_STATE], k1[GD_MAX_STATE], k2[GD_MAX_STATE], k3[GD_MAX_STATE], k4[GD_MAX_STATE],
        t1[GD_MAX_STATE];
    gd_modes md;
    memset(&md, 0, sizeof md);
    md.from_state = 1;
    memcpy(y, y0, sizeof(double) * (size_t)n);
    memcpy(pts, y, sizeof(double) * (size_t)n);
    const double h = m->period / N;
    for (long p = 0; p < periods; p++) {
        for (int s = 0; s < N; s++) {
            double t = m->period * (double)p + h * s;
            gd_model_rhs(m, t, y, k1, &md);
            for (int i = 0; i < n; i++)
                t1[i] = y[i] + 0.5 * h * k1[i];
            gd_model_rhs(m, t + 0.5 * h, t1, k2, &md);
            for (int i = 0; i < n; i++)
                t1[i] = y[i] + 0.5 * h * k2[i];
            gd_model_rhs(m, t + 0.5 * h, t1, k3, &md);
            for (int i = 0; i < n; i++)
                t1[i] = y[i] + h * k3[i];
            gd_model_rhs(m, t + h, t1, k4, &md);
            for (int i = 0; i < n; i++)
                y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
        memcpy(pts + (p + 1) * n, y, sizeof(double) * (size_t)n);
    }
}

static int sim_run(const gd_model *m, const gd_solver_opts *o, const double *y0, const gd_modes *md0, long periods,
                   double *pts)
{
    gd_error e = {0};
    gd_sim *s;
    if (gd_sim_create(m, o, y0, md0, &s, &e) != GD_OK) {
        fprintf(stderr, "%s\n", e.msg);
        return 1;
    }
    memcpy(pts, y0, sizeof(double) * (size_t)m->n);
    for (long p = 0; p < periods; p++) {
        if (gd_sim_period(s, &e) != GD_OK) {
            fprintf(stderr, "%s\n", e.msg);
            gd_sim_free(s);
            return 1;
        }
        memcpy(pts + (p + 1) * m->n, gd_sim_state(s), sizeof(double) * (size_t)m->n);
    }
    gd_sim_free(s);
    return 0;
}

static void add(const char *label, int kind, double us, double err)
{
    if (nrows >= 256)
        return;
    snprintf(rows[nrows].label, sizeof rows[nrows].label, "%s", label);
    rows[nrows].kind = kind;
    rows[nrows].us_per_period = us;
    rows[nrows].err = err;
    nrows++;
    printf("  %-34s %10.2f us/period   Poincare error %.3g\n", label, us, err);
    fflush(stdout);
}

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
    if (sim_run(&m, &o, y0, &md0, periods, ref))
        return 1;
    nrows = 0;
    for (int N = 32; N <= 65536; N *= 2) {
        double best = 1e300;
        for (int r = 0; r < repeats; r++) {
            double t0 = now();
            rk4_loop(&m, y0, periods, N, pts);
            best = fmin(best, now() - t0);
        }
        char label[64];
        snprintf(label, sizeof label, "plain RK4 loop, N=%d", N);
        double err = gd_workprec_poincare_error(pts, ref, periods + 1, m.n);
        add(label, 0, 1e6 * best / periods, err);
        if (err < 1e-11 || (best > 20.0 && N > 64))
            break;
    }
    struct {
        int method, order;
        const char *name;
    } meth[] = {{GD_METHOD_ERK, 5, "geardyn ERK5"}, {GD_METHOD_ERK, 8, "geardyn ERK8"}};
    for (int k = 0; k < 2; k++)
        for (double rt = 1e-4; rt >= 0.9e-12; rt /= 100) {
            gd_solver_opts_from_case(&c, &o);
            o.method = meth[k].method;
            o.order = meth[k].order;
            o.rtol = rt;
            o.atol = rt / 100;
            double best = 1e300;
            for (int r = 0; r < repeats; r++) {
                double t0 = now();
                if (sim_run(&m, &o, y0, &md0, periods, pts))
                    return 1;
                best = fmin(best, now() - t0);
            }
            char label[64];
            snprintf(label, sizeof label, "%s, events, rtol %.0e", meth[k].name, rt);
            add(label, 1, 1e6 * best / periods, gd_workprec_poincare_error(pts, ref, periods + 1, m.n));
        }
    for (int N = 64; N <= 4096; N *= 4) {
        gd_solver_opts_from_case(&c, &o);
        o.method = GD_METHOD_RK4;
        o.steps_per_period = N;
        double best = 1e300;
        for (int r = 0; r < repeats; r++) {
            double t0 = now();
            if (sim_run(&m, &o, y0, &md0, periods, pts))
                return 1;
            best = fmin(best, now() - t0);
        }
        char label[64];
        snprintf(label, sizeof label, "geardyn RK4, events, N=%d", N);
        add(label, 1, 1e6 * best / periods, gd_workprec_poincare_error(pts, ref, periods + 1, m.n));
    }
    printf("  cheapest at each Poincare accuracy (us per mesh period):\n");
    for (double target = 1e-4; target >= 0.9e-10; target /= 100) {
        int b[2] = {-1, -1};
        for (int i = 0; i < nrows; i++)
            if (rows[i].err <= target && (b[rows[i].kind] < 0 || rows[i].us_per_period < rows[b[rows[i].kind]].us_per_period))
                b[rows[i].kind] = i;
        printf("    %.0e: plain loop: %s, geardyn: %s", target, b[0] >= 0 ? rows[b[0]].label : "not reached",
               b[1] >= 0 ? rows[b[1]].label : "not reached");
        if (b[0] >= 0 && b[1] >= 0) {
            double r = rows[b[0]].us_per_period / rows[b[1]].us_per_period;
            printf(" -> %.1f against %.1f us: geardyn %.2f times %s", rows[b[0]].us_per_period,
                   rows[b[1]].us_per_period, r >= 1 ? r : 1 / r, r >= 1 ? "faster" : "slower");
        }
        printf("\n");
    }
    free(ref);
    free(pts);
    gd_case_free(&c);
    return 0;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 3;
    printf("geardyn %s: the plain RK4 loop (no events, modes from the state) against geardyn, best of %d\n",
           GD_VERSION_STRING, repeats);
    const char *tors[] = {"scene.model=torsional", "operating.speed_rpm=4000", "operating.torque_nm=500", NULL};
    const char *smooth[] = {"scene.model=torsional", "clearance.backlash_um=0", "operating.speed_rpm=4000",
                            "operating.torque_nm=20000", NULL};
    const char *bta[] = {"scene.model=bta", "operating.speed_rpm=7000", "operating.torque_nm=500",
                         "excitation.ste_amplitude_um=3", NULL};
    int rc = 0;
    rc |= scene("torsional, 4000 rpm, double-sided impacts", tors, 100, repeats);
    rc |= scene("torsional, permanent contact (smooth)", smooth, 100, repeats);
    rc |= scene("bta, 7000 rpm, e_r 3 um, period-1 with single-sided impacts", bta, 20, repeats);
    return rc;
}
