/* Poincare sections and the motion class on the Kahraman & Singh oscillator.
 *
 * The torsional model with harmonic mesh stiffness k = 1 + alpha cos(Omega tau) and the
 * base-excited error is (after dividing by the mass 2) exactly the Kahraman & Singh
 * equation with F_m = 0.1, F_a = 0.1, zeta = 0.05, alpha = 0.2 and the half backlash as
 * the length unit. Around Omega = 2 omega_n the parametric excitation doubles the period:
 * for Omega in about [1.63, 1.80] the steady state is a period-2 orbit with one tooth
 * separation every two mesh periods (found by a sweep; Omega 1.85 and below 1.6 are
 * period 1). Checked here:
 *  - Omega = 1.2 (period 1, single-sided impacts): consecutive stroboscopic samples are
 *    equal within the tolerance and the response is classified period-1;
 *  - Omega = 1.72 (period 2): samples two periods apart are equal, consecutive ones are
 *    not (they alternate between two points), the mesh deflection history repeats after
 *    two mesh periods but not after one, and the response is classified period-2 with
 *    two distinct points. */
#include "physics_util.h"
#include "tap.h"

#define MAXP 256

typedef struct collect {
    int n;
    long count;
    double y[MAXP][GD_MAX_STATE];
    long ns;
    double lam[MAXP * 64];   /* mesh deflection samples (um) */
} collect;

static int on_poincare(void *user, long period, double t_s, const double *y)
{
    (void)period;
    (void)t_s;
    collect *c = user;
    if (c->count < MAXP)
        memcpy(c->y[c->count], y, sizeof(double) * (size_t)c->n);
    c->count++;
    return 0;
}

static int on_sample(void *user, const gd_sample *s)
{
    collect *c = user;
    if (c->ns < MAXP * 64)
        c->lam[c->ns] = s->lambda_um[0];
    c->ns++;
    return 0;
}

/* max over components of |a - b| / (1 + max_k |y_k|), the metric of gd_poincare_period */
static double pdist(const collect *c, long i, long j)
{
    double d = 0;
    for (int q = 0; q < c->n; q++) {
        double s = 0;
        for (long k = 0; k < c->count && k < MAXP; k++)
            s = fmax(s, fabs(c->y[k][q]));
        d = fmax(d, fabs(c->y[i][q] - c->y[j][q]) / (1.0 + s));
    }
    return d;
}

static void run(double Omega, collect *col, gd_response_result *r)
{
    const char *sets[] = {"scene.model=torsional", "excitation.stiffness=harmonic",
                          "excitation.stiffness_harmonics=0.2", "scene.error_excitation=on",
                          "excitation.ste_amplitude_um=0.1", "excitation.ste_phase_deg=90",
                          "damping.mesh_damping_ratio=0.05", "clearance.backlash_um=2",
                          "solver.characteristic_length_um=1", "run.transient_periods=400",
                          "run.record_periods=64", "output.samples_per_period=64", "solver.rtol=1e-10",
                          "solver.atol=1e-12", NULL};
    gd_case c;
    pu_case(&c, sets);
    pu_tune(&c, 0.1, Omega);
    gd_model m;
    pu_build(&c, &m);
    memset(col, 0, sizeof *col);
    col->n = m.n;
    gd_response_hooks hooks;
    memset(&hooks, 0, sizeof hooks);
    hooks.poincare = on_poincare;
    hooks.sample = on_sample;
    gd_response_opts ro;
    gd_response_opts_default(&ro);
    gd_error e;
    memset(&e, 0, sizeof e);
    PU_CHECK(gd_response_run(&c, &m, &ro, &hooks, col, r, &e), &e);
    printf("# Omega %.4g: %s, %d distinct Poincare points of %ld, impacts %s, %ld events recorded, lambda %.6g .. "
           "%.6g (b)\n", Omega, r->motion, r->poincare_distinct, r->poincare_count,
           gd_impact_regime_name(r->impact_regime[0]), r->record_events, r->lambda_min_um[0], r->lambda_max_um[0]);
    gd_case_free(&c);
}

/* max |lambda(t + p T) - lambda(t)| over the record, relative to the peak-to-peak */
static double shift_dev(const collect *c, int p)
{
    long lag = 64L * p;
    double d = 0, lo = INFINITY, hi = -INFINITY;
    for (long k = 0; k < c->ns; k++) {
        lo = fmin(lo, c->lam[k]);
        hi = fmax(hi, c->lam[k]);
    }
    for (long k = 0; k + lag < c->ns; k++)
        d = fmax(d, fabs(c->lam[k + lag] - c->lam[k]));
    return d / (hi - lo);
}

static collect col;

int main(void)
{
    gd_response_result r;

    run(1.2, &col, &r);
    double d1 = 0;
    for (long k = 0; k + 1 < col.count; k++)
        d1 = fmax(d1, pdist(&col, k, k + 1));
    tap_ok(col.count == 65, "period 1: 65 Poincare samples (%ld)", col.count);
    tap_ok(r.record_events > 0, "period 1: the orbit has impacts (%ld events recorded)", r.record_events);
    TAP_CLOSE(d1, 0.0, 1e-6, "period 1: max distance between consecutive Poincare samples");
    tap_ok(strcmp(r.motion, "period-1") == 0 && r.period_n == 1, "period 1: classified '%s' (period-1)", r.motion);
    TAP_CLOSE((double)r.poincare_distinct, 1.0, 0.0, "period 1: distinct Poincare points");
    TAP_CLOSE(shift_dev(&col, 1), 0.0, 1e-6, "period 1: max |lambda(t + T) - lambda(t)| / peak-to-peak");

    run(1.72, &col, &r);
    double d2 = 0, dnext = INFINITY;
    for (long k = 0; k + 2 < col.count; k++)
        d2 = fmax(d2, pdist(&col, k, k + 2));
    for (long k = 0; k + 1 < col.count; k++)
        dnext = fmin(dnext, pdist(&col, k, k + 1));
    TAP_CLOSE(d2, 0.0, 1e-6, "period 2: max distance between Poincare samples two periods apart");
    tap_ok(dnext > 1e-3, "period 2: consecutive samples alternate: min distance %.4g (above 1e-3)", dnext);
    tap_ok(strcmp(r.motion, "period-2") == 0 && r.period_n == 2, "period 2: classified '%s' (period-2)", r.motion);
    TAP_CLOSE((double)r.poincare_distinct, 2.0, 0.0, "period 2: distinct Poincare points");
    TAP_CLOSE(shift_dev(&col, 2), 0.0, 1e-6, "period 2: max |lambda(t + 2T) - lambda(t)| / peak-to-peak");
    double s1 = shift_dev(&col, 1);
    tap_ok(s1 > 1e-2, "period 2: the history does not repeat after one period: max |lambda(t + T) - lambda(t)| / "
           "peak-to-peak = %.4g (above 1e-2)", s1);
    return tap_done();
}
