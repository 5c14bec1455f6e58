/* The modified pinion flank (paper Eq. 1-6, docs/geometry.md), checked against the involute
 * helicoid written out again here in polar form: a point (r, theta, z) lies on the drive flank of
 * the tooth space at z when theta = -eta_b - inv(acos(rb/r)) + k z, and its normal distance from
 * that flank is rb cos(beta_b) times the angle between them (the involute helicoids of one base
 * cylinder rotated by an angle are parallel surfaces).
 * 1. No modification: the flank is the involute helicoid (distance below 1e-12 m = 1e-9 mm), for
 *    both hands (left and right half), and the gear flank too.
 * 2. Profile relief only: the normal deviation equals the prescribed parabolic relief H_n(rho),
 *    exactly (it is a move along the transverse generating line).
 * 3. Lead relief only: the normal deviation equals the radial feed l(z) projected on the normal,
 *    l cos(beta_b) sin(eta_b + u), within the second-order term of the tangential part of the
 *    feed; the amount is y5/y6 at the reference circle at the face ends, inner and outer ends
 *    mapped to the halves as documented.
 * 4. Table 2 (both reliefs): the deviation is their sum within the same second-order bound.
 * 5. Normals are unit, orthogonal to both tangents and point out of the tooth; the analytic first
 *    and second derivatives match central differences; the unmodified helicoid has principal
 *    curvatures 0 (along its generator) and cos(beta_b)/rho.
 * 6. Helix slope y9 only: the normal deviation is y9 z / b toward the y6 end, at every point of the
 *    profile, exactly (the flank turned about the axis).
 * 7. Asymmetric lead relief: the unmodified band moved by y8; the relief at both face ends is y5 /
 *    y6 over zones of different lengths, a quarter of it in the middle of each zone. */
#include "geardyn/geardyn.h"
#include "pair_util.h"
#include "tap.h"

#include <gsl/gsl_errno.h>
#include <stdlib.h>
#include <string.h>

static double inv(double a) { return tan(a) - a; }

/* the Table 1 geometry written out again */
typedef struct ref {
    double mn, beta, an, mt, at, bb, r1, rb1, eta1, r2, rb2, eta2;
} ref;

static void ref_init(ref *R)
{
    R->mn = 5e-3;
    R->beta = 33.27 * M_PI / 180;
    R->an = 20 * M_PI / 180;
    R->mt = R->mn / cos(R->beta);
    R->at = atan(tan(R->an) / cos(R->beta));
    R->bb = asin(sin(R->beta) * cos(R->an));
    R->r1 = 30 * R->mt / 2;
    R->r2 = 72 * R->mt / 2;
    R->rb1 = R->r1 * cos(R->at);
    R->rb2 = R->r2 * cos(R->at);
    double st = M_PI * R->mt / 2; /* x = 0 */
    R->eta1 = M_PI / 30 - (st / (2 * R->r1) + inv(R->at));
    R->eta2 = M_PI / 72 - (st / (2 * R->r2) + inv(R->at));
}

/* normal distance of point p below the unmodified flank (positive: material removed) */
static double depth(const double p[3], double rb, double eta, double k, double cbb)
{
    double r = hypot(p[0], p[1]), th = atan2(p[1], p[0]);
    double thf = -eta - inv(acos(rb / r)) + k * p[2];
    return (thf - th) * rb * cbb;
}

static gd_case make_case(const char *const *sets, int n)
{
    gd_case c;
    gd_error err = {0};
    gd_case_init(&c, &err);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    for (int i = 0; i < n; i++)
        if (gd_case_set(&c, sets[i], i + 1, &err) != GD_OK) {
            printf("Bail out! %s\n", err.msg);
            exit(1);
        }
    if (gd_case_resolve(&c, &err) != GD_OK) {
        printf("Bail out! %s\n", err.msg);
        exit(1);
    }
    return c;
}

static void flanks(const gd_case *c, int half, gd_flank *f1, gd_flank *f2)
{
    gd_geometry g;
    gd_error err = {0};
    if (gd_geometry_compute(PAIR_OF(c), &g, &err) != GD_OK ||
        gd_flank_pinion(PAIR_OF(c), &g, half, f1, &err) != GD_OK ||
        gd_flank_gear(PAIR_OF(c), &g, half, f2, &err) != GD_OK) {
        printf("Bail out! %s\n", err.msg);
        exit(1);
    }
}

int main(void)
{
    gsl_set_error_handler_off();
    ref R;
    ref_init(&R);
    double cbb = cos(R.bb);
    double kref = tan(R.beta) / R.r1; /* right hand, pinion */

    /* 1. unmodified: exact involute helicoid, both hands; gear flank too */
    {
        gd_case c = make_case(NULL, 0);
        for (int half = 0; half < 2; half++) {
            gd_flank f1, f2;
            flanks(&c, half, &f1, &f2);
            double hand = half == 0 ? 1 : -1; /* pinion right hand in the left half */
            TAP_CLOSE(f1.k, hand * kref, 1e-15, half ? "right half: pinion twist rate (left hand)" : "left half: pinion twist rate (right hand)");
            TAP_CLOSE(f2.k, -hand * tan(R.beta) / R.r2, 1e-15, "gear twist rate (opposite hand)");
            double worst = 0, worst2 = 0;
            for (int i = 0; i <= 20; i++)
                for (int j = 0; j <= 20; j++) {
                    double u = f1.u_min + (f1.u_max - f1.u_min) * i / 20, z = f1.z_min + (f1.z_max - f1.z_min) * j / 20;
                    gd_flank_eval e;
                    gd_flank_eval_at(&f1, u, z, 0, &e);
                    worst = fmax(worst, fabs(depth(e.r, R.rb1, R.eta1, hand * kref, cbb)));
                    double u2 = f2.u_min + (f2.u_max - f2.u_min) * i / 20, z2 = f2.z_min + (f2.z_max - f2.z_min) * j / 20;
                    gd_flank_eval_at(&f2, u2, z2, 0, &e);
                    worst2 = fmax(worst2, fabs(depth(e.r, R.rb2, R.eta2, -hand * tan(R.beta) / R.r2, cbb)));
                }
            TAP_CLOSE(worst, 0, 1e-12, half ? "right half, no modification: largest distance from the involute helicoid (m)"
                                            : "left half, no modification: largest distance from the involute helicoid (m)");
            TAP_CLOSE(worst2, 0, 1e-12, "gear flank: largest distance from the involute helicoid (m)");
        }
        gd_case_free(&c);
    }

    /* 2. profile relief only */
    {
        const char *s[] = {"modification.root_relief_amount_um=25", "modification.root_relief_length_mm=1.5",
                           "modification.tip_relief_amount_um=35", "modification.tip_relief_length_mm=2.5"};
        gd_case c = make_case(s, 4);
        gd_geometry g;
        gd_error err = {0};
        gd_geometry_compute(PAIR_OF(&c), &g, &err);
        double ra1 = R.r1 + R.mn, ra2 = R.r2 + R.mn, a = R.r1 + R.r2;
        double rho_a = sqrt(ra1 * ra1 - R.rb1 * R.rb1);
        double rho_sap = a * sin(R.at) - sqrt(ra2 * ra2 - R.rb2 * R.rb2);
        double rho_c = rho_sap + 1.5e-3, rho_g = rho_a - 2.5e-3;
        gd_flank f1, f2;
        flanks(&c, 0, &f1, &f2);
        double worst = 0, at_tip = NAN, at_sap = NAN;
        int n = 0;
        for (int i = 0; i <= 200; i++) {
            double u = f1.u_min + (f1.u_max - f1.u_min) * i / 200.0;
            double rho = R.rb1 * u;
            double H = 0;
            if (rho < rho_c)
                H = 25e-6 * pow((rho_c - rho) / 1.5e-3, 2);
            else if (rho > rho_g)
                H = 35e-6 * pow((rho - rho_g) / 2.5e-3, 2);
            for (int j = 0; j <= 4; j++) {
                double z = f1.z_min + (f1.z_max - f1.z_min) * j / 4;
                gd_flank_eval e;
                gd_flank_eval_at(&f1, u, z, 0, &e);
                double d = depth(e.r, R.rb1, R.eta1, kref, cbb);
                worst = fmax(worst, fabs(d - H));
                n++;
            }
        }
        gd_flank_eval e;
        gd_flank_eval_at(&f1, rho_a / R.rb1, 0, 0, &e);
        at_tip = depth(e.r, R.rb1, R.eta1, kref, cbb);
        gd_flank_eval_at(&f1, rho_sap / R.rb1, 0, 0, &e);
        at_sap = depth(e.r, R.rb1, R.eta1, kref, cbb);
        TAP_CLOSE(worst, 0, 1e-12, "profile relief: largest |normal deviation - H_n(rho)| over 1005 points (m)");
        TAP_CLOSE(at_tip, 35e-6, 1e-12, "tip relief amount y3 at the tip, normal to the flank (m)");
        TAP_CLOSE(at_sap, 25e-6, 1e-12, "root relief amount y1 at the start of active profile (m)");
        (void)n;
        gd_case_free(&c);
    }

    /* 3. lead relief only, different amounts at the two ends; 4. Table 2 */
    for (int table2 = 0; table2 < 2; table2++) {
        const char *s3[] = {"modification.lead_relief_inner_um=25", "modification.lead_relief_outer_um=10",
                            "modification.lead_unmodified_length_mm=20"};
        const char *s4[] = {"modification.root_relief_amount_um=25", "modification.root_relief_length_mm=1.5",
                            "modification.tip_relief_amount_um=35", "modification.tip_relief_length_mm=2.5",
                            "modification.lead_relief_inner_um=25", "modification.lead_relief_outer_um=25",
                            "modification.lead_unmodified_length_mm=35"};
        gd_case c = table2 ? make_case(s4, 7) : make_case(s3, 3);
        double y5 = 25e-6, y6 = table2 ? 25e-6 : 10e-6, y7 = table2 ? 35e-3 : 20e-3, b = 40e-3;
        double ra1 = R.r1 + R.mn, ra2 = R.r2 + R.mn, a = R.r1 + R.r2;
        double rho_a = sqrt(ra1 * ra1 - R.rb1 * R.rb1);
        double rho_sap = a * sin(R.at) - sqrt(ra2 * ra2 - R.rb2 * R.rb2);
        double uref = tan(R.at);
        double proj_ref = cbb * sin(R.eta1 + uref);
        for (int half = 0; half < 2; half++) {
            gd_flank f1, f2;
            flanks(&c, half, &f1, &f2);
            double k = (half == 0 ? 1 : -1) * kref;
            /* inner end (toward the groove): +z of the left half, -z of the right half */
            double amt_hi = half == 0 ? y5 : y6, amt_lo = half == 0 ? y6 : y5;
            double zone = 0.5 * (b - y7);
            double worst = 0, worst_tol = 0;
            for (int i = 0; i <= 40; i++)
                for (int j = 0; j <= 80; j++) {
                    double u = f1.u_min + (f1.u_max - f1.u_min) * i / 40.0;
                    double z = -0.5 * b + b * j / 80.0;
                    double rho = R.rb1 * u, H = 0;
                    if (table2) {
                        double rc = rho_sap + 1.5e-3, rg = rho_a - 2.5e-3;
                        if (rho < rc)
                            H = 25e-6 * pow((rc - rho) / 1.5e-3, 2);
                        else if (rho > rg)
                            H = 35e-6 * pow((rho - rg) / 2.5e-3, 2);
                    }
                    double l = 0;
                    if (z > 0.5 * y7)
                        l = amt_hi / proj_ref * pow((z - 0.5 * y7) / zone, 2);
                    else if (z < -0.5 * y7)
                        l = amt_lo / proj_ref * pow((-0.5 * y7 - z) / zone, 2);
                    double lead = l * cbb * sin(R.eta1 + u);
                    double tang = l * cos(R.eta1 + u);
                    double tol = 1.01 * tang * tang / (2 * (rho - H / cbb)) * cbb + 1e-13;
                    gd_flank_eval e;
                    gd_flank_eval_at(&f1, u, z, 0, &e);
                    double d = depth(e.r, R.rb1, R.eta1, k, cbb);
                    double dev = fabs(d - (H + lead));
                    if (dev / tol > worst_tol)
                        worst_tol = dev / tol;
                    worst = fmax(worst, dev);
                }
            char name[200];
            snprintf(name, sizeof name, "%s, %s half: |deviation - (profile + projected lead)| within the second-order "
                     "bound at every point (ratio %.3g, largest %.3g m)", table2 ? "Table 2" : "lead relief only",
                     half ? "right" : "left", worst_tol, worst);
            tap_ok(worst_tol <= 1.0, "%s", name);
            /* the amounts at the reference circle at the face ends */
            gd_flank_eval e;
            gd_flank_eval_at(&f1, uref, 0.5 * b, 0, &e);
            double dhi = depth(e.r, R.rb1, R.eta1, k, cbb);
            gd_flank_eval_at(&f1, uref, -0.5 * b, 0, &e);
            double dlo = depth(e.r, R.rb1, R.eta1, k, cbb);
            double lend_hi = amt_hi / proj_ref, lend_lo = amt_lo / proj_ref;
            double t_hi = pow(lend_hi * cos(R.eta1 + uref), 2) / (2 * R.rb1 * uref) * cbb * 1.01 + 1e-13;
            double t_lo = pow(lend_lo * cos(R.eta1 + uref), 2) / (2 * R.rb1 * uref) * cbb * 1.01 + 1e-13;
            snprintf(name, sizeof name, "%s half: lead relief at the reference circle, +z end (%s end) (m)",
                     half ? "right" : "left", half ? "outer" : "inner");
            TAP_CLOSE(dhi, amt_hi, t_hi, name);
            snprintf(name, sizeof name, "%s half: lead relief at the reference circle, -z end (%s end) (m)",
                     half ? "right" : "left", half ? "inner" : "outer");
            TAP_CLOSE(dlo, amt_lo, t_lo, name);
            gd_flank_eval_at(&f1, uref, 0.5 * y7 - 1e-6, 0, &e);
            TAP_CLOSE(depth(e.r, R.rb1, R.eta1, k, cbb), 0, 1e-12, "no lead relief inside the unmodified length y7");
        }
        gd_case_free(&c);
    }

    /* 6. helix slope y9 only: the flank turned about the axis, a normal deviation y9 z / b toward the
     * y6 end (the outer end: -z of the left half, +z of the right half; +: material removed), the
     * same at every point of the profile (exact: a turned involute helicoid is parallel to itself);
     * and with a single pair the y6 end is +z */
    for (int single = 0; single < 2; single++) {
        const char *s6[] = {"modification.helix_slope_um=8", "gear.arrangement=helical"};
        gd_case c = make_case(s6, single ? 2 : 1);
        for (int half = 0; half < (single ? 1 : 2); half++) {
            gd_flank f1, f2;
            flanks(&c, half, &f1, &f2);
            double k = (half == 0 ? 1 : -1) * kref, toward6 = half == 0 && !single ? -1 : 1, b = 40e-3;
            double worst = 0;
            for (int i = 0; i <= 20; i++)
                for (int j = 0; j <= 20; j++) {
                    double u = f1.u_min + (f1.u_max - f1.u_min) * i / 20, z = f1.z_min + (f1.z_max - f1.z_min) * j / 20;
                    gd_flank_eval e;
                    gd_flank_eval_at(&f1, u, z, 0, &e);
                    worst = fmax(worst, fabs(depth(e.r, R.rb1, R.eta1, k, cbb) - 8e-6 * toward6 * z / b));
                }
            char name[160];
            snprintf(name, sizeof name, "helix slope 8 um, %s: largest |normal deviation - y9 z / b| toward the y6 end "
                     "(m)", single ? "single helical pair" : half ? "right half" : "left half");
            TAP_CLOSE(worst, 0, 1e-12, name);
        }
        gd_case_free(&c);
    }

    /* 7. asymmetric lead relief: the unmodified band of y7 = 16 mm moved by y8 = 6 mm toward the y6
     * end; no relief on the band, the relief y5 / y6 at the face ends (zones of 18 and 6 mm on the
     * left half, whose y6 end is -z), a quarter of it in the middle of each zone */
    {
        const char *s7[] = {"modification.lead_relief_inner_um=20", "modification.lead_relief_outer_um=12",
                            "modification.lead_unmodified_length_mm=16", "modification.lead_unmodified_centre_mm=6"};
        gd_case c = make_case(s7, 4);
        gd_flank f1, f2;
        flanks(&c, 0, &f1, &f2);
        double uref = tan(R.at), b = 40e-3;
        double lo = -6e-3 - 8e-3, hi = -6e-3 + 8e-3; /* the band on the left half */
        TAP_CLOSE(f1.z_lo, lo, 1e-15, "y8 = 6 mm toward the outer (y6) end: the band starts at z = -14 mm (left half)");
        TAP_CLOSE(f1.z_hi, hi, 1e-15, "and ends at z = 2 mm");
        double at[5][2] = {{-0.5 * b, 12e-6}, {0.5 * (-0.5 * b + lo), 3e-6}, {-6e-3, 0}, {0.5 * (hi + 0.5 * b), 5e-6},
                           {0.5 * b, 20e-6}};
        for (int q = 0; q < 5; q++) {
            gd_flank_eval e;
            gd_flank_eval_at(&f1, uref, at[q][0], 0, &e);
            double d = depth(e.r, R.rb1, R.eta1, kref, cbb);
            /* the second-order term of the feed's tangential part, as in 3 */
            double l = at[q][1] / (cbb * sin(R.eta1 + uref));
            double tol = 1.01 * pow(l * cos(R.eta1 + uref), 2) / (2 * R.rb1 * uref) * cbb + 1e-13;
            char name[160];
            snprintf(name, sizeof name, "asymmetric lead relief at z = %.1f mm, reference circle: %.3g um (m)",
                     at[q][0] * 1e3, at[q][1] * 1e6);
            TAP_CLOSE(d, at[q][1], tol, name);
        }
        gd_case_free(&c);
    }

    /* 5. normals, derivatives, curvature */
    {
        const char *s4[] = {"modification.root_relief_amount_um=25", "modification.root_relief_length_mm=1.5",
                            "modification.tip_relief_amount_um=35", "modification.tip_relief_length_mm=2.5",
                            "modification.lead_relief_inner_um=25", "modification.lead_relief_outer_um=25",
                            "modification.lead_unmodified_length_mm=35"};
        gd_case c = make_case(s4, 7);
        gd_flank f1, f2;
        flanks(&c, 1, &f1, &f2);
        double worst_unit = 0, worst_orth = 0, worst_d1 = 0, worst_d2 = 0;
        int outward = 1;
        for (int i = 0; i <= 12; i++)
            for (int j = 0; j <= 12; j++) {
                double u = f1.u_min + (f1.u_max - f1.u_min) * i / 12.0, z = f1.z_min + (f1.z_max - f1.z_min) * j / 12.0;
                gd_flank_eval e, a, b2;
                gd_flank_eval_at(&f1, u, z, 2, &e);
                double n[3];
                gd_flank_normal(&e, n);
                double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                worst_unit = fmax(worst_unit, fabs(nn - 1));
                double lu = sqrt(e.ru[0] * e.ru[0] + e.ru[1] * e.ru[1] + e.ru[2] * e.ru[2]);
                double lz = sqrt(e.rz[0] * e.rz[0] + e.rz[1] * e.rz[1] + e.rz[2] * e.rz[2]);
                worst_orth = fmax(worst_orth, fabs(n[0] * e.ru[0] + n[1] * e.ru[1] + n[2] * e.ru[2]) / lu);
                worst_orth = fmax(worst_orth, fabs(n[0] * e.rz[0] + n[1] * e.rz[1] + n[2] * e.rz[2]) / lz);
                /* out of the tooth: toward increasing polar angle (the space above the flank) */
                double th = atan2(e.r[1], e.r[0]);
                if (-sin(th) * n[0] + cos(th) * n[1] <= 0)
                    outward = 0;
                /* central differences (avoid straddling a zone boundary: compare relative) */
                double hu = 1e-6, hz = 1e-6;
                gd_flank_eval_at(&f1, u + hu, z, 1, &a);
                gd_flank_eval_at(&f1, u - hu, z, 1, &b2);
                for (int d = 0; d < 3; d++) {
                    worst_d1 = fmax(worst_d1, fabs((a.r[d] - b2.r[d]) / (2 * hu) - e.ru[d]) / lu);
                    worst_d2 = fmax(worst_d2, fabs((a.ru[d] - b2.ru[d]) / (2 * hu) - e.ruu[d]) / (lu + 1e-3));
                    worst_d2 = fmax(worst_d2, fabs((a.rz[d] - b2.rz[d]) / (2 * hu) - e.ruz[d]) / (lz + 1e-3));
                }
                gd_flank_eval_at(&f1, u, z + hz, 1, &a);
                gd_flank_eval_at(&f1, u, z - hz, 1, &b2);
                for (int d = 0; d < 3; d++) {
                    worst_d1 = fmax(worst_d1, fabs((a.r[d] - b2.r[d]) / (2 * hz) - e.rz[d]) / lz);
                    worst_d2 = fmax(worst_d2, fabs((a.rz[d] - b2.rz[d]) / (2 * hz) - e.rzz[d]) / (lz + 1e-3));
                }
            }
        TAP_CLOSE(worst_unit, 0, 1e-14, "normals are unit vectors (largest |n| - 1)");
        TAP_CLOSE(worst_orth, 0, 1e-14, "normals are orthogonal to both tangents (largest cosine)");
        tap_ok(outward, "normals point out of the tooth material");
        TAP_CLOSE(worst_d1, 0, 1e-8, "first derivatives against central differences (relative)");
        TAP_CLOSE(worst_d2, 0, 1e-5, "second derivatives against central differences (relative)");
        gd_case_free(&c);

        gd_case c0 = make_case(NULL, 0);
        flanks(&c0, 0, &f1, &f2);
        double wk0 = 0, wk1 = 0;
        for (int i = 0; i <= 10; i++) {
            double u = f1.u_min + (f1.u_max - f1.u_min) * i / 10.0;
            gd_flank_eval e;
            gd_flank_eval_at(&f1, u, 3e-3, 2, &e);
            double k[2], dir[2][3];
            gd_flank_curvature(&e, k, dir);
            double rho = R.rb1 * u;
            wk0 = fmax(wk0, fabs(k[0]) * rho);
            wk1 = fmax(wk1, fabs(k[1] * rho / cbb - 1));
        }
        TAP_CLOSE(wk0, 0, 1e-9, "unmodified helicoid: the smaller principal curvature is 0 (times rho)");
        TAP_CLOSE(wk1, 0, 1e-9, "unmodified helicoid: the other is cos(beta_b)/rho (relative)");
        gd_case_free(&c0);
    }
    return tap_done();
}
