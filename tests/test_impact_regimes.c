/* Impact regimes of the Kahraman & Singh oscillator with F_m = 0.1.
 *
 * With the half backlash b as the length unit (characteristic_length_um = backlash/2)
 * the torsional model is x'' + 2 zeta x' + f(x) = F_m + F_a Omega^2 cos(Omega tau),
 * x = lambda the mesh deflection, f the dead zone of half width 1. In drive-side contact
 * the mean is 1 + F_m = 1.1 and the linear alternating amplitude is
 *     A = F_a Omega^2 / |1 - Omega^2 + 2 i zeta Omega|.
 * The teeth separate when lambda < 1, i.e. A > F_m = 0.1, and hit the back flank when
 * lambda < -1, i.e. (linearly) A > 2 + F_m = 2.1. Below 0.1 the linear solution is the
 * exact one, so the first threshold is sharp; the cases just below and just above it
 * (A = 0.09, 0.12) test it. Above the first threshold the response is no longer linear,
 * so the other cases sit well inside their bands. At Omega = 3 (far above resonance) the
 * gear body barely moves and lambda follows -e(t) in or out of contact, which keeps the
 * nonlinear response close to the linear estimate (at low frequency a free flight across
 * the gap would carry a single-sided estimate into double-sided impacts).
 *
 * Checked per case: the impact regime of the response, the extrema of the recorded
 * lambda against the thresholds +1 and -1 (units of b), and the kinds of the recorded
 * events; in the no-impact cases the recorded amplitude equals A. */
#include "physics_util.h"
#include "tap.h"

#include <complex.h>

int main(void)
{
    const double Fm = 0.1, zeta = 0.05, Omega = 3.0;
    const double H = Omega * Omega / cabs(1.0 - Omega * Omega + 2.0 * I * zeta * Omega);
    const struct {
        double A;
        int regime;
    } cases[] = {{0.05, GD_IMPACT_NONE}, {0.09, GD_IMPACT_NONE}, {0.12, GD_IMPACT_SINGLE},
                 {1.0, GD_IMPACT_SINGLE}, {4.0, GD_IMPACT_DOUBLE}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double A = cases[i].A, Fa = A / H;
        char ste[64], name[200];
        snprintf(ste, sizeof ste, "excitation.ste_amplitude_um=%.17g", Fa);
        const char *sets[] = {"scene.model=torsional", "excitation.stiffness=constant", "scene.error_excitation=on",
                              ste, "excitation.ste_phase_deg=90", "damping.mesh_damping_ratio=0.05",
                              "clearance.backlash_um=2", "solver.characteristic_length_um=1",
                              "run.transient_periods=300", "run.record_periods=20", "output.samples_per_period=1024",
                              "solver.rtol=1e-10", "solver.atol=1e-12", NULL};
        gd_case c;
        pu_case(&c, sets);
        pu_tune(&c, Fm, Omega);
        gd_model m;
        pu_build(&c, &m);
        gd_response_result r;
        gd_error e;
        memset(&e, 0, sizeof e);
        PU_CHECK(gd_response_run(&c, &m, NULL, NULL, NULL, &r, &e), &e);
        double lo = r.lambda_min_um[0], hi = r.lambda_max_um[0]; /* b = 1 um */
        printf("# A = %g (F_a = %.6g): %s, %s, lambda %.6g .. %.6g, events: %ld separations, %ld back contacts\n", A,
               Fa, gd_impact_regime_name(r.impact_regime[0]), r.motion, lo, hi,
               r.record_events_by_kind[GD_EV_SEPARATION], r.record_events_by_kind[GD_EV_BACK_CONTACT]);
        snprintf(name, sizeof name, "A = %g: impact regime %s (expected %s)", A,
                 gd_impact_regime_name(r.impact_regime[0]), gd_impact_regime_name(cases[i].regime));
        tap_ok(r.impact_regime[0] == cases[i].regime && r.impact_regime[2] == cases[i].regime, "%s", name);
        switch (cases[i].regime) {
        case GD_IMPACT_NONE:
            tap_ok(lo > 1.0, "A = %g: min lambda %.9g stays above 1 (drive flank in contact)", A, lo);
            tap_ok(r.record_events == 0, "A = %g: no events (%ld)", A, r.record_events);
            snprintf(name, sizeof name, "A = %g: recorded amplitude (max - min)/2 equals the linear A", A);
            TAP_REL(0.5 * (hi - lo), A, 1e-5, name);
            snprintf(name, sizeof name, "A = %g: recorded mean (max + min)/2 equals 1 + F_m", A);
            TAP_REL(0.5 * (hi + lo), 1.0 + Fm, 1e-5, name);
            break;
        case GD_IMPACT_SINGLE:
            tap_ok(lo < 1.0 && lo > -1.0, "A = %g: min lambda %.9g between -1 and 1 (separation, no back contact)", A,
                   lo);
            tap_ok(r.record_events_by_kind[GD_EV_SEPARATION] > 0 && r.record_events_by_kind[GD_EV_BACK_CONTACT] == 0,
                   "A = %g: separations (%ld) and no back contacts (%ld)", A,
                   r.record_events_by_kind[GD_EV_SEPARATION], r.record_events_by_kind[GD_EV_BACK_CONTACT]);
            break;
        default:
            tap_ok(lo < -1.0 && hi > 1.0, "A = %g: lambda %.9g .. %.9g crosses both -1 and 1", A, lo, hi);
            tap_ok(r.record_events_by_kind[GD_EV_BACK_CONTACT] > 0,
                   "A = %g: back contacts recorded (%ld)", A, r.record_events_by_kind[GD_EV_BACK_CONTACT]);
            break;
        }
        gd_case_free(&c);
    }
    return tap_done();
}
