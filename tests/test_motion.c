/* Motion classes from the Poincare section and the largest Lyapunov exponent, on known
 * responses of the Kahraman & Singh oscillator (alpha 0.2, zeta 0.05, Fm 0.1, Fa 0.2):
 * period-1 at Omega 0.6, period-2 at 0.8, chaotic at 1.5; and quasi-periodic: an undamped
 * linear oscillator forced at an irrational frequency ratio with its free vibration excited
 * (two incommensurate frequencies: the section is a closed curve and the exponent is 0). */
#include "analysis_util.h"
#include "tap.h"

#include <string.h>

static void classify(double Omega, const char *expect, int expect_n)
{
    gd_case c;
    gd_model m;
    gd_response_result r;
    gd_error e = {0};
    const char *extra[] = {"run.transient_periods=300", "run.record_periods=200", NULL};
    au_ks_case(&c, &m, 0.2, 0.05, 0.1, 0.2, Omega, extra);
    if (gd_response_run(&c, &m, NULL, NULL, NULL, &r, &e) != GD_OK)
        au_die(&e);
    tap_ok(strcmp(r.motion, expect) == 0 && (expect_n == 0 || r.poincare_distinct == expect_n),
           "Omega %.2f: %s with %d distinct points, mle %.4g per period (expected %s)", Omega, r.motion,
           r.poincare_distinct, r.mle_per_period, expect);
    gd_case_free(&c);
}

int main(void)
{
    classify(0.6, "period-1", 1);
    classify(0.8, "period-2", 2);
    classify(1.5, "chaotic", 0);

    /* quasi-periodic */
    gd_case c;
    gd_model m;
    gd_response_result r;
    gd_error e = {0};
    const char *extra[] = {"run.transient_periods=50", "run.record_periods=400", "solver.rtol=1e-10",
                           "solver.atol=1e-12", NULL};
    double Omega = (sqrt(5.0) - 1.0) / 2.0 * 2.0; /* golden ratio: as irrational as it gets */
    au_ks_case(&c, &m, 0.0, 0.0, 20.0, 0.5, Omega, extra);
    double y0[GD_MAX_STATE];
    gd_modes md0;
    gd_initial_state(&c, &m, y0, &md0, &e);
    y0[1] = 3.0; /* free vibration of amplitude 3 about the static deflection 21: never leaves contact */
    gd_response_opts o;
    gd_response_opts_default(&o);
    o.y0 = y0;
    o.md0 = &md0;
    if (gd_response_run(&c, &m, &o, NULL, NULL, &r, &e) != GD_OK)
        au_die(&e);
    tap_ok(strcmp(r.motion, "quasi-periodic") == 0,
           "undamped, two incommensurate frequencies: %s, %d distinct points of %ld, mle %.3g per period", r.motion,
           r.poincare_distinct, r.poincare_count, r.mle_per_period);
    tap_ok(r.impact_regime[2] == GD_IMPACT_NONE, "and it never leaves contact (%s)",
           gd_impact_regime_name(r.impact_regime[2]));
    gd_case_free(&c);

    /* the classifier's rules themselves */
    char buf[32];
    gd_motion_classify(3, 1, 0.5, 0.01, buf, sizeof buf);
    tap_ok(strcmp(buf, "period-3") == 0, "a repeating section is periodic whatever the exponent (%s)", buf);
    gd_motion_classify(0, 1, 0.02, 0.01, buf, sizeof buf);
    tap_ok(strcmp(buf, "chaotic") == 0, "positive exponent above the threshold: %s", buf);
    gd_motion_classify(0, 1, -0.005, 0.01, buf, sizeof buf);
    tap_ok(strcmp(buf, "quasi-periodic") == 0, "exponent within the threshold: %s", buf);
    gd_motion_classify(0, 1, -0.2, 0.01, buf, sizeof buf);
    tap_ok(strcmp(buf, "not-periodic") == 0, "negative exponent, no repetition (transient): %s", buf);
    gd_motion_classify(0, 0, NAN, 0.01, buf, sizeof buf);
    tap_ok(strcmp(buf, "not-periodic") == 0, "no exponent computed: %s", buf);
    return tap_done();
}
