/* LTCA mesh stiffness (Eq. 14; docs/ltca.md section 6):
 *  1. the mean mesh stiffness of unmodified aligned pairs against ISO 6336-1 (method B, written
 *     out here as the oracle: c' = c'_th C_M C_R C_B cos(beta), c_gamma_alpha = c' (0.75 eps_alpha
 *     + 0.25), times the face width, transverse; divided by cos^2(beta_b) for the normal direction),
 *     within 20 % for a spur pair and a 15-degree helical pair; the paper's 33.27-degree pair is
 *     23 % stiffer than ISO and is recorded as a TAP TODO (docs/ltca.md section 6 discusses it);
 *  2. Gu, Velex, Sainsot & Bruyere (2015): every harmonic of a helical pair's mesh stiffness carries
 *     sinc(k eps_beta), so the fluctuation nearly vanishes when the overlap ratio is an integer and
 *     is clearly present at 1.5 (face widths chosen here for eps_beta = 1, 1.5, 2). */
#include "ltca_util.h"

#include <math.h>
#include <stdlib.h>

/* ISO 6336-1 mean mesh stiffness of one half along the normal (N/m) */
static double iso_mesh_stiffness(const gd_case *c)
{
    static const double C[9] = {0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182};
    double beta = c->helix_angle_deg * M_PI / 180, an = c->normal_pressure_angle_deg * M_PI / 180;
    double cb3 = pow(cos(beta), 3);
    double zn1 = c->teeth_pinion / cb3, zn2 = c->teeth_gear / cb3, x1 = c->profile_shift_pinion,
           x2 = c->profile_shift_gear;
    double q = C[0] + C[1] / zn1 + C[2] / zn2 + C[3] * x1 + C[4] * x1 / zn1 + C[5] * x2 + C[6] * x2 / zn2 +
               C[7] * x1 * x1 + C[8] * x2 * x2;
    double cprime = 1.0 / q * 0.8 * 1.0 * 0.975 * cos(beta);
    /* transverse contact ratio and base helix angle (ISO 21771), written out again */
    double mn = c->normal_module_mm, at = atan(tan(an) / cos(beta)), mt = mn / cos(beta);
    double r1 = 0.5 * c->teeth_pinion * mt, r2 = 0.5 * c->teeth_gear * mt;
    double rb1 = r1 * cos(at), rb2 = r2 * cos(at), ra1 = r1 + mn, ra2 = r2 + mn, a = r1 + r2;
    double ea = (sqrt(ra1 * ra1 - rb1 * rb1) + sqrt(ra2 * ra2 - rb2 * rb2) - a * sin(at)) / (M_PI * mt * cos(at));
    double cga = cprime * (0.75 * ea + 0.25) * (ea < 1.2 ? 0.9 : 1.0);
    double b = fmin(c->face_width_pinion_mm, c->face_width_gear_mm);
    double bb = asin(sin(beta) * cos(an));
    return cga * b * 1e6 / (cos(bb) * cos(bb));
}

static double fluctuation(gd_case *c, double *a1, double *pp)
{
    enum { N = 64 };
    double k[N], km[2];
    gd_error e = {0};
    if (gd_ltca_mesh_stiffness(c, N, k, NULL, NULL, km, &e) != GD_OK) {
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
        int todo;
    } iso[] = {
        {"spur 30/72, b 40 mm", {"gear.arrangement=spur", "gear.helix_angle_deg=0", NULL}, 0},
        {"helical 15 deg 30/72, b 40 mm", {"gear.arrangement=helical", "gear.helix_angle_deg=15", NULL}, 0},
        {"paper Table 1 herringbone (33.27 deg), per half", {NULL}, 1},
    };
    for (size_t i = 0; i < sizeof iso / sizeof iso[0]; i++) {
        gd_case c;
        if (lt_case(&c, 0, iso[i].set[0], iso[i].set[1], iso[i].set[2], NULL))
            continue;
        gd_error e = {0};
        gd_ltca_result r;
        if (gd_ltca_run_opts(&c, 32, 0, &r, &e) != GD_OK) {
            tap_ok(0, "%s: %s", iso[i].label, e.msg);
            gd_case_free(&c);
            continue;
        }
        double k = r.stiffness_mean[0], kiso = iso_mesh_stiffness(&c);
        double rel = fabs(k - kiso) / kiso;
        if (iso[i].todo)
            printf("not ok %d - %s: mean mesh stiffness %.5g N/m vs ISO 6336-1 %.5g N/m (rel %.3f, tol 0.2) "
                   "# TODO the normal-section slice model is 23 %% stiffer than ISO's cos(beta) rule at 33 deg "
                   "(docs/ltca.md section 6)\n", ++tap_n, iso[i].label, k, kiso, rel);
        else
            TAP_REL(k, kiso, 0.20, iso[i].label);
        if (r.halves > 1)
            TAP_REL(r.stiffness_mean[1], r.stiffness_mean[0], 1e-9, "aligned herringbone: both halves alike");
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
        gd_geometry_compute(&c, &g, &e);
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
