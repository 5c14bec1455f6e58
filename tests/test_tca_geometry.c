/* Geometry for contact analysis (docs/geometry.md):
 * 1. The derived values of the paper's Table 1 pair against the ISO 21771 formulas written out
 *    again here (transverse module and pressure angle, radii, base helix angle, centre distance,
 *    contact ratios, start of active profile, involute form circle), and the working pressure
 *    angle and centre distance of a profile-shifted pair against an independent inverse involute.
 * 2. Impossible or unsafe geometry and modifications are refused with a message naming the key:
 *    undercut, pointed tip, transverse contact ratio below 1, interference (the mating tip on the
 *    fillet), a relief without length, relief lengths that do not fit on the active profile, an
 *    unmodified lead length longer than the face, a relief that takes half the tip, a centre
 *    distance error that leaves a contact ratio below 1, a spur arrangement with a helix angle. */
#include "geardyn/geardyn.h"
#include "pair_util.h"
#include "tap.h"

#include <gsl/gsl_errno.h>
#include <stdlib.h>
#include <string.h>

static double inv(double a) { return tan(a) - a; }

/* inverse involute by bisection (independent of the library's Brent solve) */
static double inv_inv(double t)
{
    double lo = 0, hi = 1.4;
    for (int i = 0; i < 200; i++) {
        double m = 0.5 * (lo + hi);
        if (inv(m) < t)
            lo = m;
        else
            hi = m;
    }
    return 0.5 * (lo + hi);
}

static gd_status resolve_with(const char *const *sets, int n, gd_case *c, gd_error *err)
{
    gd_case_init(c, err);
    c->speed_rpm = 4000, c->torque_nm = 500; /* the paper's operating point: a case must give one */
    for (int i = 0; i < n; i++) {
        gd_status st = gd_case_set(c, sets[i], i + 1, err);
        if (st != GD_OK)
            return st;
    }
    return gd_case_resolve(c, err);
}

static void refused(const char *name, const char *const *sets, int n, const char *key, const char *words)
{
    gd_case c;
    gd_error err = {0};
    gd_status st = resolve_with(sets, n, &c, &err);
    tap_ok(st == GD_ERR_GEOMETRY || st == GD_ERR_INPUT, "%s: refused (status %d: %s)", name, st, err.msg);
    tap_ok(strstr(err.msg, key) != NULL, "%s: the message names %s", name, key);
    tap_ok(strstr(err.msg, words) != NULL, "%s: the message says '%s'", name, words);
    tap_ok(strstr(err.msg, "(valid") != NULL || st == GD_ERR_GEOMETRY, "%s: the message gives the valid range", name);
    gd_case_free(&c);
}

int main(void)
{
    gsl_set_error_handler_off();
    /* 1. Table 1: m_n 5, z 30/72, beta 33.27, alpha_n 20, b 40/44, x = 0, h_a* 1, h_f* 1.25 */
    gd_case c;
    gd_error err = {0};
    gd_status st = resolve_with(NULL, 0, &c, &err);
    tap_ok(st == GD_OK, "the default case (Table 1) resolves (%s)", err.msg);
    gd_geometry g;
    st = gd_geometry_compute(PAIR_OF(&c), &g, &err);
    tap_ok(st == GD_OK, "gd_geometry_compute on Table 1");
    const double d2r = M_PI / 180;
    double mn = 5e-3, beta = 33.27 * d2r, an = 20 * d2r, z1 = 30, z2 = 72, b = 40e-3;
    double mt = mn / cos(beta);
    double at = atan(tan(an) / cos(beta));
    double r1 = z1 * mt / 2, r2 = z2 * mt / 2;
    double rb1 = r1 * cos(at), rb2 = r2 * cos(at);
    double ra1 = r1 + mn, ra2 = r2 + mn, rf1 = r1 - 1.25 * mn, rf2 = r2 - 1.25 * mn;
    double bb = atan(tan(beta) * cos(at));
    double a = r1 + r2;
    double pbt = M_PI * mt * cos(at);
    double ga1 = sqrt(ra1 * ra1 - rb1 * rb1), ga2 = sqrt(ra2 * ra2 - rb2 * rb2);
    double eps_a = (ga1 + ga2 - a * sin(at)) / pbt;
    double eps_b = b * sin(beta) / (M_PI * mn);
    double rsap1 = hypot(rb1, a * sin(at) - ga2), rsap2 = hypot(rb2, a * sin(at) - ga1);
    double rform1 = hypot(rb1, r1 * sin(at) - mn / sin(at));
    double t = 1e-12;
    TAP_CLOSE(g.mt, mt, t, "transverse module (m)");
    TAP_CLOSE(g.alpha_t, at, 1e-14, "transverse pressure angle (rad)");
    TAP_CLOSE(g.beta_b, bb, 1e-14, "base helix angle (rad), tan(beta_b) = tan(beta) cos(alpha_t)");
    TAP_CLOSE(g.r[0], r1, t, "pinion reference radius");
    TAP_CLOSE(g.r[1], r2, t, "gear reference radius");
    TAP_CLOSE(g.rb[0], rb1, t, "pinion base radius");
    TAP_CLOSE(g.rb[1], rb2, t, "gear base radius");
    TAP_CLOSE(g.ra[0], ra1, t, "pinion tip radius");
    TAP_CLOSE(g.ra[1], ra2, t, "gear tip radius");
    TAP_CLOSE(g.rf[0], rf1, t, "pinion root radius");
    TAP_CLOSE(g.rf[1], rf2, t, "gear root radius");
    TAP_CLOSE(g.a, a, t, "centre distance");
    TAP_CLOSE(g.a * 1e3, 304.989, 1e-3, "centre distance close to 305 mm (model-notes.md)");
    TAP_CLOSE(g.eps_alpha, eps_a, 1e-12, "transverse contact ratio");
    TAP_CLOSE(g.eps_beta, eps_b, 1e-12, "overlap contact ratio");
    TAP_CLOSE(g.r_sap[0], rsap1, t, "pinion start of active profile");
    TAP_CLOSE(g.r_sap[1], rsap2, t, "gear start of active profile");
    TAP_CLOSE(g.r_form[0], rform1, t, "pinion involute form circle (rack straight flank h_a* m_n)");
    tap_ok(g.r_form[0] < g.r_sap[0] && g.r_sap[0] < g.ra[0], "pinion: form circle < SAP < tip (%.4f < %.4f < %.4f mm)",
           g.r_form[0] * 1e3, g.r_sap[0] * 1e3, g.ra[0] * 1e3);
    TAP_CLOSE(g.pbn, pbt * cos(bb), t, "normal base pitch");
    gd_case_free(&c);

    /* profile-shifted helical pair: working pressure angle and centre distance */
    {
        const char *sets[] = {"gear.profile_shift_pinion=0.4", "gear.profile_shift_gear=-0.1", "gear.teeth_pinion=19"};
        st = resolve_with(sets, 3, &c, &err);
        tap_ok(st == GD_OK, "profile-shifted pair resolves (%s)", err.msg);
        gd_geometry_compute(PAIR_OF(&c), &g, &err);
        double r1s = 19 * mt / 2;
        double awt = inv_inv(inv(at) + 2 * tan(an) * (0.4 - 0.1) / (19 + 72));
        TAP_CLOSE(g.alpha_wt, awt, 1e-12, "working transverse pressure angle, inv(a_wt) = inv(a_t) + 2 tan(a_n) (x1+x2)/(z1+z2)");
        TAP_CLOSE(g.a, (r1s + r2) * cos(at) / cos(awt), 1e-12, "working centre distance a = a0 cos(a_t)/cos(a_wt)");
        TAP_CLOSE(g.ra[0], r1s + mn * 1.4, 1e-12, "shifted tip radius r + m_n (h_a* + x)");
        gd_case_free(&c);
    }

    /* 2. refusals */
    {
        const char *s[] = {"gear.teeth_pinion=8", "gear.helix_angle_deg=0", "gear.arrangement=spur"};
        refused("undercut", s, 3, "gear.teeth_pinion", "undercut");
    }
    {
        const char *s[] = {"gear.teeth_pinion=12", "gear.helix_angle_deg=0", "gear.profile_shift_pinion=1.2",
                           "gear.arrangement=spur"};
        refused("pointed tip", s, 4, "gear.profile_shift_pinion", "pointed tip");
    }
    {
        const char *s[] = {"gear.addendum_coefficient=0.5"};
        refused("contact ratio below 1", s, 1, "gear.addendum_coefficient", "transverse contact ratio");
    }
    {
        const char *s[] = {"gear.teeth_pinion=18", "gear.teeth_gear=80", "gear.helix_angle_deg=0",
                           "gear.profile_shift_gear=-0.5", "gear.arrangement=spur"};
        refused("interference on the fillet", s, 5, "gear.profile_shift_pinion", "reaches the fillet");
    }
    {
        const char *s[] = {"modification.tip_relief_amount_um=20"};
        refused("relief without length", s, 1, "modification.tip_relief_length_mm", "0 with a tip relief amount");
    }
    {
        const char *s[] = {"modification.tip_relief_amount_um=20", "modification.tip_relief_length_mm=15",
                           "modification.root_relief_amount_um=20", "modification.root_relief_length_mm=10"};
        refused("relief lengths longer than the active profile", s, 4, "modification.tip_relief_length_mm",
                "do not fit on the active profile");
    }
    {
        const char *s[] = {"modification.lead_unmodified_length_mm=41"};
        refused("unmodified lead length longer than the face", s, 1, "modification.lead_unmodified_length_mm",
                "longer than the pinion face");
    }
    {
        const char *s[] = {"modification.lead_relief_inner_um=20", "modification.lead_unmodified_length_mm=40"};
        refused("lead relief without room", s, 2, "modification.lead_unmodified_length_mm", "leaves no room");
    }
    {
        const char *s[] = {"modification.tip_relief_amount_um=1000", "modification.tip_relief_length_mm=5",
                           "modification.lead_relief_outer_um=1000"};
        refused("relief taking half the tip", s, 3, "modification.tip_relief_amount_um", "takes half the normal tip");
    }
    {
        const char *s[] = {"misalignment.centre_distance_error_mm=8"};
        refused("centre distance error leaving a contact ratio below 1", s, 1, "misalignment.centre_distance_error_mm",
                "below 1 at the operating centre distance");
    }
    {
        const char *s[] = {"gear.arrangement=spur"};
        refused("spur arrangement with a helix angle", s, 1, "gear.helix_angle_deg", "arrangement = spur");
    }
    {
        /* the paper's Table 2 fits */
        const char *s[] = {"modification.root_relief_amount_um=25", "modification.root_relief_length_mm=1.5",
                           "modification.tip_relief_amount_um=35", "modification.tip_relief_length_mm=2.5",
                           "modification.lead_relief_inner_um=25", "modification.lead_relief_outer_um=25",
                           "modification.lead_unmodified_length_mm=35", "misalignment.centre_distance_error_mm=0.1"};
        st = resolve_with(s, 8, &c, &err);
        tap_ok(st == GD_OK, "the paper's Table 2 modification with dE = 0.1 mm is accepted (%s)", err.msg);
        gd_case_free(&c);
    }
    return tap_done();
}
