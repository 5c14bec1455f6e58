/* The Harris map of a spur pair with profile relief only (docs/optimisation.md section 13): the
 * torque T* at which the LTE amplitude is smallest grows with the relief amount C_a, in proportion
 * to the tooth-pair deflection.
 *
 * Derivation (two pairs in the double-contact zone, each of stiffness k, single-pair deflection
 * u = F/k): the pinion's tip and root reliefs are parabolic in the roll length (docs/geometry.md,
 * H = C_a (s/L)^2) over the double-contact zone, L = (eps_alpha - 1) p_bt. At the fraction sigma of
 * that zone the leaving pair has the relief C_a sigma^2 and the entering one C_a (1 - sigma)^2. Both
 * loaded, the approach is (u + C_a (1 - 2 sigma + 2 sigma^2)) / 2; the entering pair carries no load
 * while u <= C_a (1 - 2 sigma), where the approach is u + C_a sigma^2. With the single-contact
 * approach u the amplitude over the cycle is
 *     A(u) = (C_a - u)^2 / (4 C_a)                       for u <= C_a / 2,
 *     A(u) = u/2 - C_a/4 + (C_a - u)^2 / (4 C_a)          for C_a / 2 <= u <= C_a,
 *     A(u) = u/2 - C_a/4                                  for u >= C_a,
 * smallest at u* = C_a / 2, where A = C_a / 16, with slopes -1/4 and +1/4 either side. The
 * unmodified pair's amplitude is A0 = u - u/2 = u/2, so the optimal torque is where the unmodified
 * pair's LTE amplitude, the difference of its single- and double-contact deflections, equals C_a / 4:
 * A0(T*) = C_a / 4. For a real pair the double-zone deflection differs from u/2 and the stiffness
 * varies along the path; A0 measured by LTCA carries both. So T* is proportional to C_a, with the
 * constant the inverse of the unmodified amplitude per unit torque.
 *
 * Tolerance: LTCA's amplitude is the model's plus what the model leaves out (the stiffness varying
 * along the path, contact beyond the theoretical path, Hertzian flattening), an error e(u); where it
 * is at most E near the minimum, the minimum of A + e lies where A <= A_min + 2 E, so |u - u*| <=
 * 8 E and |T* - T_pred| / T_pred <= 16 E / C_a. E is estimated by LTCA's own excess at the minimum
 * over the model's C_a / 16. TAP output. */
#include "geardyn/geardyn.h"
#include "tap.h"

#include <math.h>
#include <stdio.h>

#define ARCSEC (180.0 * 3600.0 / M_PI)

static gd_pair P;
static gd_ltca_settings S;
static double rb2;

/* The LTE amplitude of P at torque T as a displacement along the line of action (um). */
static double amp(double T)
{
    S.torque_nm = T;
    double pp;
    gd_error e = {0};
    if (gd_opt_gear_lte_pp(&P, &S, &pp, &e) != GD_OK) {
        tap_ok(0, "LTCA at %g N m: %s", T, e.msg);
        return NAN;
    }
    return pp / ARCSEC * rb2 * 1e6;
}

/* The smallest of amp over [a, b] by golden section (the amplitude is a V near its minimum). */
static double argmin(double a, double b, double *fmin)
{
    const double gr = (sqrt(5.0) - 1) / 2;
    double x1 = b - gr * (b - a), x2 = a + gr * (b - a), f1 = amp(x1), f2 = amp(x2);
    while (b - a > 1e-4 * (a + b)) {
        if (f1 < f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - gr * (b - a);
            f1 = amp(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + gr * (b - a);
            f2 = amp(x2);
        }
    }
    double t = 0.5 * (a + b);
    *fmin = amp(t);
    return t;
}

int main(void)
{
    gd_error e = {0};
    gd_case c;
    /* the guide's spur pair (cases/guide/spur.ini): m 3 mm, 25 / 60 teeth, x +-0.2, 30 mm face */
    const char *sets[] = {"scene.analysis=ltca", "gear.arrangement=spur", "gear.normal_module_mm=3",
                          "gear.teeth_pinion=25", "gear.teeth_gear=60", "gear.helix_angle_deg=0",
                          "gear.profile_shift_pinion=0.2", "gear.profile_shift_gear=-0.2",
                          "gear.face_width_pinion_mm=30", "gear.face_width_gear_mm=30", "operating.torque_nm=100",
                          "solver.ltca_positions_per_cycle=40", NULL};
    gd_case_init(&c, &e);
    for (int i = 0; sets[i]; i++)
        gd_case_set(&c, sets[i], i + 1, &e);
    if (gd_case_resolve(&c, &e) != GD_OK) {
        tap_ok(0, "the spur pair: %s", e.msg);
        return tap_done();
    }
    const gd_pair pair = gd_pair_from_case(&c);
    S = gd_ltca_settings_from_case(&c);
    gd_geometry g;
    gd_geometry_compute(&pair, &g, &e);
    rb2 = g.rb[1];
    const double L = (g.eps_alpha - 1) * g.pbt * 1e3; /* the double-contact zone (mm) */
    printf("# eps_alpha %.4f, double-contact zone %.4f mm: the length of both reliefs\n", g.eps_alpha, L);

    const double Ca[4] = {5, 10, 15, 20};
    double Ts[4], ratio[4];
    int grows = 1;
    for (int i = 0; i < 4; i++) {
        /* the prediction: the unmodified pair's amplitude A0(T) = Ca / 4 (A0 is nearly linear in T) */
        P = pair;
        double T = 100;
        for (int it = 0; it < 4; it++)
            T *= (Ca[i] / 4) / amp(T);
        double Tpred = T;
        P = pair;
        P.tip_relief_amount_um = P.root_relief_amount_um = Ca[i];
        P.tip_relief_length_mm = P.root_relief_length_mm = L;
        double amin;
        Ts[i] = argmin(0.5 * Tpred, 1.5 * Tpred, &amin);
        double E = fabs(amin - Ca[i] / 16), tol = 16 * E / Ca[i];
        ratio[i] = Ts[i] / Ca[i];
        tap_ok(fabs(Ts[i] - Tpred) <= tol * Tpred, "Ca = %g um: the least LTE amplitude at T* = %.2f N m against A0(T) "
               "= Ca/4 at %.2f N m (%.2f %%; tolerance 16 E / Ca = %.2f %%, E = |%.4f - Ca/16| um)", Ca[i], Ts[i], Tpred,
               100 * (Ts[i] - Tpred) / Tpred, 100 * tol, amin);
        TAP_CLOSE(amin, Ca[i] / 16, 0.15 * Ca[i] / 16, "  the least amplitude against the model's Ca/16 (15 %)");
        if (i > 0)
            grows = grows && Ts[i] > Ts[i - 1];
    }
    tap_ok(grows, "T* grows with Ca: %.1f, %.1f, %.1f, %.1f N m", Ts[0], Ts[1], Ts[2], Ts[3]);
    double lo = fmin(fmin(ratio[0], ratio[1]), fmin(ratio[2], ratio[3]));
    double hi = fmax(fmax(ratio[0], ratio[1]), fmax(ratio[2], ratio[3]));
    tap_ok(hi - lo <= 0.1 * lo, "T* / Ca is nearly constant (proportional): %.3f .. %.3f N m per um (within 10 %%)", lo,
           hi);
    /* the ideal pair (constant stiffness, double-zone deflection u/2) would put T* where the
     * single-pair deflection is Ca/2: LTCA's pair is not that pair, and the test above does not
     * assume it */
    P = pair;
    S.torque_nm = 100;
    gd_ltca_result r;
    if (gd_ltca_run_opts(&P, &S, 0, 0, &r, &e) == GD_OK) {
        double dmax = 0;
        for (int k = 0; k < r.npos; k++)
            dmax = fmax(dmax, -r.lte_arcsec[k] / ARCSEC * rb2 * 1e6);
        printf("# single-pair deflection %.4f um per N m: the ideal pair's T* would be Ca/2 over it, %.2f N m per um "
               "(LTCA's pair: %.2f .. %.2f)\n", dmax / 100, 1 / (2 * dmax / 100), lo, hi);
        gd_ltca_result_free(&r);
    }
    gd_case_free(&c);
    return tap_done();
}
