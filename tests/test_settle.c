/* The adaptive transient (run.transient_max_periods): the transient is extended while the
 * Poincare section still converges to a period-n orbit, and only then.
 *  - a lightly damped linear oscillator (K&S form without backlash contact loss, zeta 0.002)
 *    converges slowly: a fixed transient of 100 periods leaves it unsettled, the adaptive one
 *    runs on until the section settles, and its first recorded point equals the steady state
 *    of a run with a fixed transient of 8000 periods;
 *  - the same oscillator forced at 5 times its natural frequency: its free vibration turns
 *    by 2 pi / 5 per mesh period, so points five periods apart nearly coincide long before
 *    the motion has settled. The section must settle on period 1, not on a false period 5
 *    (which a fixed transient of 3000 periods does report);
 *  - a period-2 response is found with its period;
 *  - a chaotic response costs (almost) nothing beyond the fixed transient. */
#include "analysis_util.h"
#include "tap.h"

#include <math.h>
#include <string.h>

static void run(double alpha, double zeta, double Fm, double ea, double Omega, int trans, int trans_max, int rec,
                gd_response_result *r)
{
    gd_case c;
    gd_model m;
    gd_error e = {0};
    char t1[64], t2[64], t3[64];
    snprintf(t1, sizeof t1, "run.transient_periods=%d", trans);
    snprintf(t2, sizeof t2, "run.transient_max_periods=%d", trans_max);
    snprintf(t3, sizeof t3, "run.record_periods=%d", rec);
    const char *extra[] = {t1, t2, t3, "run.lyapunov_exponents=1", NULL};
    au_ks_case(&c, &m, alpha, zeta, Fm, ea, Omega, extra);
    gd_response_opts o;
    gd_response_opts_default(&o);
    o.max_period = 16;
    if (gd_response_run(&c, &m, &o, NULL, NULL, r, &e) != GD_OK)
        au_die(&e);
    gd_case_free(&c);
}

int main(void)
{
    static gd_response_result a, b, ref;

    /* 1. slow convergence to period 1 (Fm 20 keeps the teeth in contact: a linear oscillator) */
    run(0.0, 0.002, 20.0, 0.5, 0.9, 100, 0, 20, &a);
    tap_ok(strcmp(a.motion, "period-1") != 0, "fixed transient of 100 periods: not settled (%s, mle %.3g per period)",
           a.motion, a.mle_per_period);
    run(0.0, 0.002, 20.0, 0.5, 0.9, 100, 20000, 20, &b);
    tap_ok(strcmp(b.motion, "period-1") == 0, "adaptive transient: %s after %ld transient periods", b.motion,
           b.transient_periods);
    tap_ok(b.transient_periods > 300 && b.transient_periods < 8000,
           "the transient was extended to %ld periods (decay 0.0126 per period: about 1100 to reach 1e-6)",
           b.transient_periods);
    run(0.0, 0.002, 20.0, 0.5, 0.9, 8000, 0, 20, &ref);
    double dmax = 0, scale = 0;
    for (int i = 0; i < 2; i++) {
        dmax = fmax(dmax, fabs(b.y_final[i] - ref.y_final[i]));
        scale = fmax(scale, fabs(ref.y_final[i]));
    }
    tap_ok(dmax <= 2e-5 * (1 + scale), "its section agrees with a fixed transient of 8000 periods: %.3g (scale %.3g)",
           dmax, scale);

    /* 2. the false period 5 of a slow spiral */
    run(0.0, 0.002, 20.0, 0.5, 5.0, 3000, 0, 40, &a);
    tap_ok(strcmp(a.motion, "period-5") == 0,
           "fixed transient of 3000 periods, forced at 5 times the natural frequency: %s (the trap is real)",
           a.motion);
    run(0.0, 0.002, 20.0, 0.5, 5.0, 100, 40000, 40, &b);
    tap_ok(strcmp(b.motion, "period-1") == 0, "adaptive transient: %s after %ld periods, not a false period 5",
           b.motion, b.transient_periods);

    /* 3. period 2 (Kahraman & Singh, alpha 0.2, zeta 0.05, Fm 0.1, Fa 0.2, Omega 0.8) */
    run(0.2, 0.05, 0.1, 0.2, 0.8, 100, 5000, 100, &b);
    tap_ok(strcmp(b.motion, "period-2") == 0 && b.poincare_distinct == 2, "period 2: %s, %d distinct points, %ld "
           "transient periods", b.motion, b.poincare_distinct, b.transient_periods);

    /* 4. chaos (Omega 1.5): the section never settles, the transient is not extended (or barely) */
    run(0.2, 0.05, 0.1, 0.2, 1.5, 300, 5000, 100, &b);
    tap_ok(strcmp(b.motion, "chaotic") == 0, "chaotic: %s, mle %.3g per period", b.motion, b.mle_per_period);
    tap_ok(b.transient_periods <= 332, "chaos costs at most one decay window more: %ld transient periods (fixed 300)",
           b.transient_periods);
    return tap_done();
}
