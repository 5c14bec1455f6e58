/* LTCA mesh stiffness (Eq. 14; docs/ltca.md section 6):
 *  1. the mean mesh stiffness of unmodified aligned pairs against ISO 6336-1:2006 method B,
 *     written out here as the oracle (clause 9): the virtual numbers of teeth of ISO 21771,
 *     z_n = z / (cos^2(beta_b) cos(beta)); q' from the nine coefficients; c'_th = 1/q';
 *     c' = c'_th C_M C_R C_B cos(beta) with C_M = 0.8, C_R = 1 (solid blanks) and the basic rack
 *     factor C_B = [1 + 0.5 (1.2 - h_fP/m_n)] [1 - 0.02 (20 deg - alpha_n)]; below a specific load
 *     F_t K_A / b of 100 N/mm c' is reduced by ((F_t K_A / b) / 100)^0.25; the mean mesh stiffness
 *     c_gamma_alpha = c' (0.75 eps_alpha + 0.25) (x 0.9 below eps_alpha = 1.2) -- the mean over the
 *     mesh cycle, which is what the LTCA's mean of k is (c' is the single pair's largest) -- times
 *     the face width, in the transverse plane, divided by cos^2(beta_b) for the normal direction.
 *     Within 20 % for a spur pair, a 15-degree helical pair and the paper's 33.27-degree pair. The
 *     LTCA of an aligned unmodified pair (linear compliance, the contact lines closed along their
 *     length) hardly depends on the load, which the test checks (500 against 1000 N m); ISO's
 *     low-load reduction is empirical, from measured real teeth, so the comparison is made at a
 *     specific load of at least 100 N/mm, where ISO's c' does not depend on the load either (the
 *     paper's pair at 1000 N m; at its 500 N m, 70 N/mm per half, ISO's value is 8.6 % lower and
 *     the difference is printed).
 *  2. Gu, Velex, Sainsot & Bruyere (2015): every harmonic of a helical pair's mesh stiffness carries
 *     sinc(k eps_beta), so the fluctuation nearly vanishes when the overlap ratio is an integer and
 *     is clearly present at 1.5 (face widths chosen here for eps_beta = 1, 1.5, 2). */
#include "ltca_util.h"
#include "pair_util.h"
#include "geardyn/gd_geometry.h"

#include <math.h>
#include <stdlib.h>

/* ISO 6336-1 method B mean mesh stiffness of one half along the normal (N/m), K_A = 1; the
 * specific load of the case's torque into *line_load (N/mm) */
static double iso_mesh_stiffness(const gd_case *c, double *line_load)
{
    static const double C[9] = {0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182};
    double beta = c->helix_angle_deg * M_PI / 180, an = c->normal_pressure_angle_deg * M_PI / 180;
    double bb = asin(sin(beta) * cos(an));
    double zf = cos(bb) * cos(bb) * cos(beta);
    double zn1 = c->teeth_pinion / zf, zn2 = c->teeth_gear / zf, x1 = c->profile_shift_pinion,
           x2 = c->profile_shift_gear;
    double q = C[0] + C[1] / zn1 + C[2] / zn2 + C[3] * x1 + C[4] * x1 / zn1 + C[5] * x2 + C[6] * x2 / zn2 +
               C[7] * x1 * x1 + C[8] * x2 * x2;
    double CB = (1 + 0.5 * (1.2 - c->dedendum_coefficient)) * (1 - 0.02 * (20 - c->normal_pressure_angle_deg));
    double cprime = 1.0 / q * 0.8 * 1.0 * CB * cos(beta);
    /* transverse contact ratio (ISO 21771), written out again */
    double mn = c->normal_module_mm, at = atan(tan(an) / cos(beta)), mt = mn / cos(beta);
    double r1 = 0.5 * c->teeth_pinion * mt, r2 = 0.5 * c->teeth_gear * mt;
    double rb1 = r1 * cos(at), rb2 = r2 * cos(at), ra1 = r1 + mn, ra2 = r2 + mn, a = r1 + r2;
    double ea = (sqrt(ra1 * ra1 - rb1 * rb1) + sqrt(ra2 * ra2 - rb2 * rb2) - a * sin(at)) / (M_PI * mt * cos(at));
    double b = fmin(c->face_width_pinion_mm, c->face_width_gear_mm);
    /* specific load: the tangential force at the reference circle of one half over its face width */
    int halves = c->arrangement == GD_ARR_HERRINGBONE ? 2 : 1;
    double ft = c->torque_nm / halves / (r1 * 1e-3);
    *line_load = ft / b;
    if (*line_load < 100)
        cprime *= pow(*line_load / 100, 0.25);
    double cga = cprime * (0.75 * ea + 0.25) * (ea < 1.2 ? 0.9 : 1.0);
    return cga * b * 1e6 / (cos(bb) * cos(bb));
}

static double fluctuation(gd_case *c, double *a1, double *pp)
{
    enum { N = 64 };
    double k[N], km[2];
    gd_error e = {0};
    if (gd_ltca_mesh_stiffness(PAIR_OF(c), LTCA_SET_OF(c), N, k, NULL, NULL, km, &e) != GD_OK) {
        tap_ok(0, "mesh stiffness: %s", e.msg);
        return NAN;
    }
    double lo = INFINITY, hi = -INFINITY, re = 0, im = 0;
    for (int i = 0; i < N; i++) {
        lo = fmin(lo, k[i]);
        hi = fmax(hi, k[i]);
        re += k[i] * cos(2 * M_PI * i / N);
        im += k[i] * sin(2 * M_PI * i / N);
    }
    *a1 = 2 * hypot(re, im) / N / km[0]; /* first harmonic (mesh frequency) over the mean */
    *pp = (hi - lo) / km[0];
    return km[0];
}

int main(void)
{
    /* 1. ISO 6336-1 */
    struct {
        const char *label;
        const char *set[3];
    } iso[] = {
        {"spur 30/72, b 40 mm, 500 N m", {"gear.arrangement=spur", "gear.helix_angle_deg=0", NULL}},
        {"helical 15 deg 30/72, b 40 mm, 500 N m", {"gear.arrangement=helical", "gear.helix_angle_deg=15", NULL}},
        {"paper Table 1 herringbone (33.27 deg), per half, 1000 N m", {"operating.torque_nm=1000", NULL}},
    };
    for (size_t i = 0; i < sizeof iso / sizeof iso[0]; i++) {
        gd_case c;
        if (lt_case(&c, 0, iso[i].set[0], iso[i].set[1], iso[i].set[2], NULL))
            continue;
        gd_error e = {0};
        gd_ltca_result r;
        if (gd_ltca_run_opts(PAIR_OF(&c), LTCA_SET_OF(&c), 32, 0, &r, &e) != GD_OK) {
            tap_ok(0, "%s: %s", iso[i].label, e.msg);
            gd_case_free(&c);
            continue;
        }
        double q, k = r.stiffness_mean[0], kiso = iso_mesh_stiffness(&c, &q);
        tap_ok(q >= 100, "%s: specific load %.1f N/mm, in ISO's load-independent range", iso[i].label, q);
        TAP_REL(k, kiso, 0.20, iso[i].label);
        if (r.halves > 1) {
            TAP_REL(r.stiffness_mean[1], r.stiffness_mean[0], 1e-9, "aligned herringbone: both halves alike");
            /* the same pair at the paper's 500 N m: a linear problem (all gaps zero), the same stiffness */
            gd_case c5;
            gd_ltca_result r5;
            if (!lt_case(&c5, 0, NULL) && gd_ltca_run_opts(PAIR_OF(&c5), LTCA_SET_OF(&c5), 32, 0, &r5, &e) == GD_OK) {
                double q5, k5iso = iso_mesh_stiffness(&c5, &q5);
                TAP_REL(r5.stiffness_mean[0], k, 0.02, "aligned unmodified pair: the LTCA stiffness hardly depends on the "
                        "load (500 against 1000 N m: only the contacts at the ends of the lines are added)");
                printf("# at 500 N m (%.1f N/mm per half) ISO 6336-1 reduces c' by %.4f: %.5g N/m, the LTCA %.5g N/m "
                       "(%+.1f %%)\n", q5, pow(q5 / 100, 0.25), k5iso, r5.stiffness_mean[0],
                       100 * (r5.stiffness_mean[0] / k5iso - 1));
                gd_ltca_result_free(&r5);
                gd_case_free(&c5);
            } else
                tap_ok(0, "the paper's pair at 500 N m: %s", e.msg);
        }
        gd_ltca_result_free(&r);
        gd_case_free(&c);
    }

    /* 2. fluctuation against the overlap ratio: helical, unmodified, aligned, pinion and gear of
     * the face width that gives eps_beta = 1, 1.5 and 2 */
    double eb[3] = {1.0, 1.5, 2.0}, A1[3], PP[3];
    for (int q = 0; q < 3; q++) {
        char b1[64], b2[64];
        double b = eb[q] * M_PI * 5.0 / sin(33.27 * M_PI / 180);
        snprintf(b1, sizeof b1, "gear.face_width_pinion_mm=%.12g", b);
        snprintf(b2, sizeof b2, "gear.face_width_gear_mm=%.12g", b);
        gd_case c;
        A1[q] = PP[q] = NAN;
        if (lt_case(&c, 0, "gear.arrangement=helical", b1, b2, "solver.ltca_face_slices=41", NULL))
            continue;
        gd_geometry g;
        gd_error e = {0};
        gd_geometry_compute(PAIR_OF(&c), &g, &e);
        double km = fluctuation(&c, &A1[q], &PP[q]);
        printf("# eps_beta %.4f (b = %.3f mm): mean %.5g N/m, first harmonic %.4f, peak-to-peak %.4f of the mean\n",
               g.eps_beta, b, km, A1[q], PP[q]);
        gd_case_free(&c);
    }
    tap_ok(A1[1] > 0.03, "eps_beta = 1.5: the mesh-frequency harmonic of the stiffness is clearly present (%.4f of "
           "the mean)", A1[1]);
    tap_ok(A1[0] < 0.25 * A1[1] && A1[2] < 0.25 * A1[1], "eps_beta = 1 and 2: the mesh-frequency harmonic nearly "
           "vanishes (%.4f and %.4f against %.4f at 1.5)", A1[0], A1[2], A1[1]);
    tap_ok(PP[0] < 0.5 * PP[1] && PP[2] < 0.5 * PP[1], "eps_beta = 1 and 2: peak-to-peak fluctuation below half of "
           "that at 1.5 (%.4f, %.4f against %.4f)", PP[0], PP[2], PP[1]);
    return tap_done();
}
