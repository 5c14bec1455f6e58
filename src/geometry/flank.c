/* Tooth flank surfaces: the form-ground 3D-modified pinion flank (paper Eq. 1-6) and the
 * unmodified gear flank, in closed form with first and second derivatives (docs/geometry.md). */
#include "geardyn/gd_case.h" /* the enums of arrangement and hand */
#include "geardyn/gd_flank.h"
#include "geardyn/gd_geometry.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

GD_API int gd_flank_pinion_hand(const gd_pair *pair, int half)
{
    if (pair->arrangement == GD_ARR_SPUR || pair->helix_angle_deg == 0.0)
        return 0;
    int h = pair->pinion_hand == GD_HAND_RIGHT ? 1 : -1;
    return half == 0 ? h : -h;
}

/* Normal tooth thickness (arc) of body i at radius r. */
static double thickness_n(const gd_geometry *g, int i, double r)
{
    double a = acos(fmin(1.0, g->rb[i] / r));
    double st = 2 * r * (g->psi_b[i] - gd_involute(a));
    double beta_r = atan(tan(g->beta) * r / g->r[i]);
    return st * cos(beta_r);
}

static double feed_projection(double cos_bb, double eta_b, double u) { return cos_bb * sin(eta_b + u); }

GD_API double gd_flank_feed_projection(const gd_flank *f, double u) { return feed_projection(f->cos_bb, f->eta_b, u); }

GD_API gd_status gd_modification_check(const gd_pair *pair, const gd_geometry *g, const char **bad_key, gd_error *err)
{
    const char *dummy;
    if (!bad_key)
        bad_key = &dummy;
    *bad_key = NULL;
    double y1 = pair->root_relief_amount_um * 1e-6, y2 = pair->root_relief_length_mm * 1e-3;
    double y3 = pair->tip_relief_amount_um * 1e-6, y4 = pair->tip_relief_length_mm * 1e-3;
    double y5 = pair->lead_relief_inner_um * 1e-6, y6 = pair->lead_relief_outer_um * 1e-6;
    double y7 = pair->lead_unmodified_length_mm * 1e-3, y8 = pair->lead_unmodified_centre_mm * 1e-3;
    double y9 = pair->helix_slope_um * 1e-6;
    double active = g->rho_a[0] - g->rho_sap[0];
    double b1 = g->b[0];
    if (y1 > 0 && y2 <= 0) {
        *bad_key = "root_relief_length_mm";
        return gd_error_set(err, GD_ERR_INPUT, "0 with a root relief amount of %g um (valid: a positive roll length "
                            "up to %.4g mm)", y1 * 1e6, active * 1e3);
    }
    if (y3 > 0 && y4 <= 0) {
        *bad_key = "tip_relief_length_mm";
        return gd_error_set(err, GD_ERR_INPUT, "0 with a tip relief amount of %g um (valid: a positive roll length "
                            "up to %.4g mm)", y3 * 1e6, active * 1e3);
    }
    if (y2 + y4 > active * (1 + 1e-12)) {
        *bad_key = y4 > 0 ? "tip_relief_length_mm" : "root_relief_length_mm";
        return gd_error_set(err, GD_ERR_INPUT, "root and tip relief lengths %.4g + %.4g mm do not fit on the active "
                            "profile of the pinion (roll length %.4g mm from the start of active profile to the tip) "
                            "(valid: root + tip length at most %.4g mm)", y2 * 1e3, y4 * 1e3, active * 1e3, active * 1e3);
    }
    if (y7 > b1 * (1 + 1e-12)) {
        *bad_key = "lead_unmodified_length_mm";
        return gd_error_set(err, GD_ERR_INPUT, "%.4g mm is longer than the pinion face of one half %.4g mm (valid: 0 "
                            "to %.4g mm)", y7 * 1e3, b1 * 1e3, b1 * 1e3);
    }
    if (fabs(y8) + 0.5 * y7 > 0.5 * b1 * (1 + 1e-12)) {
        *bad_key = "lead_unmodified_centre_mm";
        return gd_error_set(err, GD_ERR_INPUT, "%.4g mm moves the unmodified lead band of %.4g mm off the %.4g mm "
                            "face (valid: |y8| + y7/2 at most half the face, |y8| <= %.4g mm)", y8 * 1e3, y7 * 1e3,
                            b1 * 1e3, 0.5 * (b1 - y7) * 1e3);
    }
    if ((y5 > 0 || y6 > 0) && y7 >= b1 * (1 - 1e-12)) {
        *bad_key = "lead_unmodified_length_mm";
        return gd_error_set(err, GD_ERR_INPUT, "%.4g mm leaves no room on the %.4g mm face for the lead relief of "
                            "%g/%g um (valid: below %.4g mm)", y7 * 1e3, b1 * 1e3, y5 * 1e6, y6 * 1e6, b1 * 1e3);
    }
    /* no relief may take half the tooth away: at the tip corner and at the form-circle corner */
    double cos_bb = cos(g->beta_b), eta = g->eta_b[0], rb = g->rb[0];
    double uref = tan(g->alpha_t), ua = g->rho_a[0] / rb, uf = fmax(g->rho_form[0], 0) / rb;
    double lead = fmax(y5, y6) / feed_projection(cos_bb, eta, uref);
    double tip_total = y3 + lead * feed_projection(cos_bb, eta, ua) + 0.5 * fabs(y9);
    double s_tip = g->tip_thickness_n[0];
    if (tip_total >= 0.5 * s_tip) {
        *bad_key = y3 > 0 ? "tip_relief_amount_um" : y5 > 0 || y6 > 0 ? (y5 >= y6 ? "lead_relief_inner_um" :
                   "lead_relief_outer_um") : "helix_slope_um";
        return gd_error_set(err, GD_ERR_INPUT, "the relief at the tip corner (%.4g um) takes half the normal tip "
                            "thickness %.4g mm (valid: tip + lead relief below %.4g um)", tip_total * 1e6, s_tip * 1e3,
                            0.5 * s_tip * 1e6);
    }
    double rho_c = g->rho_sap[0] + y2;
    double root_form = y2 > 0 ? y1 * pow((rho_c - fmax(g->rho_form[0], 0)) / y2, 2) : 0;
    double s_root = thickness_n(g, 0, g->r_form[0]);
    double root_total = root_form + lead * feed_projection(cos_bb, eta, uf) + 0.5 * fabs(y9);
    if (root_total >= 0.5 * s_root) {
        *bad_key = y1 > 0 ? "root_relief_amount_um" : y5 > 0 || y6 > 0 ? (y5 >= y6 ? "lead_relief_inner_um" :
                   "lead_relief_outer_um") : "helix_slope_um";
        return gd_error_set(err, GD_ERR_INPUT, "the relief at the root corner (%.4g um at the form circle) takes half "
                            "the normal tooth thickness %.4g mm there (valid: a smaller amount or a shorter length)",
                            root_total * 1e6, s_root * 1e3);
    }
    return GD_OK;
}

static void common(const gd_pair *pair, const gd_geometry *g, int i, int hand, gd_flank *f)
{
    memset(f, 0, sizeof *f);
    f->body = i;
    f->hand = hand;
    f->rb = g->rb[i];
    f->k = hand * tan(g->beta) / g->r[i];
    f->eta_b = g->eta_b[i];
    f->cos_bb = cos(g->beta_b);
    f->sin_bb = sin(g->beta_b);
    double rho_lo = fmax(g->rho_form[i], 1e-3 * g->rb[i]);
    f->u_min = rho_lo / g->rb[i];
    f->u_max = g->rho_a[i] / g->rb[i];
    f->z_min = -0.5 * g->b[i];
    f->z_max = 0.5 * g->b[i];
    f->u_ref = tan(g->alpha_t);
    f->z_lo = f->z_min;
    f->z_hi = f->z_max;
    (void)pair;
}

GD_API gd_status gd_flank_pinion(const gd_pair *pair, const gd_geometry *g, int half, gd_flank *f, gd_error *err)
{
    const char *key;
    gd_status st = gd_modification_check(pair, g, &key, err);
    if (st != GD_OK)
        return gd_error_prefix(err, "modification.%s", key ? key : "?");
    common(pair, g, 0, gd_flank_pinion_hand(pair, half), f);
    double y1 = pair->root_relief_amount_um * 1e-6, y2 = pair->root_relief_length_mm * 1e-3;
    double y3 = pair->tip_relief_amount_um * 1e-6, y4 = pair->tip_relief_length_mm * 1e-3;
    double y5 = pair->lead_relief_inner_um * 1e-6, y6 = pair->lead_relief_outer_um * 1e-6;
    double y7 = pair->lead_unmodified_length_mm * 1e-3, y8 = pair->lead_unmodified_centre_mm * 1e-3;
    double y9 = pair->helix_slope_um * 1e-6;
    if (y1 > 0) {
        f->root_amount = y1;
        f->root_len = y2;
        f->rho_c = g->rho_sap[0] + y2;
    }
    if (y3 > 0) {
        f->tip_amount = y3;
        f->tip_len = y4;
        f->rho_g = g->rho_a[0] - y4;
    }
    /* lead: y5 at the inner end (toward the groove: +z of the left half, -z of the right half;
     * -z of a single helical or spur pair), y6 at the outer end; s6 the side (+1: +z) of the y6 end */
    double lo_amount = y6, hi_amount = y5, s6 = -1.0;
    if (pair->arrangement != GD_ARR_HERRINGBONE || half == 1) {
        lo_amount = y5;
        hi_amount = y6;
        s6 = 1.0;
    }
    /* the unmodified band of length y7, its middle y8 toward the y6 end */
    f->z_lo = s6 * y8 - 0.5 * y7;
    f->z_hi = s6 * y8 + 0.5 * y7;
    double zone_lo = 0.5 * (g->b[0] - y7), zone_hi = zone_lo; /* a centred band: as written, to the bit */
    if (y8 != 0.0) {
        zone_lo = f->z_lo - f->z_min;
        zone_hi = f->z_max - f->z_hi;
    }
    double proj = feed_projection(f->cos_bb, f->eta_b, f->u_ref);
    if (lo_amount > 0 && zone_lo > 0)
        f->a_lo = lo_amount / proj / (zone_lo * zone_lo);
    if (hi_amount > 0 && zone_hi > 0)
        f->a_hi = hi_amount / proj / (zone_hi * zone_hi);
    /* helix slope y9: the flank turned about the axis by theta(z) = dk z, which moves an involute
     * helicoid normal to itself by r_b cos(beta_b) theta everywhere on the profile (forward, into
     * the mating flank, for theta > 0: the drive flank faces +theta); material removed y9 z/b at
     * the y6 end (z toward it) is theta = -s6 y9 z / (b r_b cos(beta_b)) */
    if (y9 != 0.0) {
        f->dk = -s6 * y9 / (g->b[0] * f->rb * f->cos_bb);
        f->k += f->dk;
    }
    f->modified = f->root_amount > 0 || f->tip_amount > 0 || f->a_lo > 0 || f->a_hi > 0;
    return GD_OK;
}

GD_API gd_status gd_flank_gear(const gd_pair *pair, const gd_geometry *g, int half, gd_flank *f, gd_error *err)
{
    (void)err;
    common(pair, g, 1, -gd_flank_pinion_hand(pair, half), f);
    return GD_OK;
}

/* Profile relief normal to the flank and its first two derivatives with respect to rho. */
static void profile_relief(const gd_flank *f, double rho, double *h, double *h1, double *h2)
{
    *h = *h1 = *h2 = 0;
    if (f->root_amount > 0 && rho < f->rho_c) {
        double a = f->root_amount / (f->root_len * f->root_len), d = f->rho_c - rho;
        *h = a * d * d;
        *h1 = -2 * a * d;
        *h2 = 2 * a;
    } else if (f->tip_amount > 0 && rho > f->rho_g) {
        double a = f->tip_amount / (f->tip_len * f->tip_len), d = rho - f->rho_g;
        *h = a * d * d;
        *h1 = 2 * a * d;
        *h2 = 2 * a;
    }
}

/* Radial feed l(z) of the grinding wheel and its derivatives. */
static void lead_feed(const gd_flank *f, double z, double *l, double *l1, double *l2)
{
    *l = *l1 = *l2 = 0;
    if (f->a_lo > 0 && z < f->z_lo) {
        double d = f->z_lo - z;
        *l = f->a_lo * d * d;
        *l1 = -2 * f->a_lo * d;
        *l2 = 2 * f->a_lo;
    } else if (f->a_hi > 0 && z > f->z_hi) {
        double d = z - f->z_hi;
        *l = f->a_hi * d * d;
        *l1 = 2 * f->a_hi * d;
        *l2 = 2 * f->a_hi;
    }
}

GD_API void gd_flank_relief(const gd_flank *f, double u, double z, double *profile_normal, double *lead)
{
    double h1, h2, l1, l2;
    profile_relief(f, f->rb * u, profile_normal, &h1, &h2);
    lead_feed(f, z, lead, &l1, &l2);
}

GD_API void gd_flank_eval_at(const gd_flank *f, double u, double z, int order, gd_flank_eval *e)
{
    double psi = -f->eta_b - u;
    double cp = cos(psi), sp = sin(psi);
    double er[2] = {cp, sp}, et[2] = {-sp, cp};
    double rb = f->rb;
    double H = 0, H1 = 0, H2 = 0, l = 0, l1 = 0, l2 = 0;
    if (f->modified) {
        double hn, hn1, hn2;
        profile_relief(f, rb * u, &hn, &hn1, &hn2);
        H = hn / f->cos_bb;
        H1 = rb * hn1 / f->cos_bb;
        H2 = rb * rb * hn2 / f->cos_bb;
        lead_feed(f, z, &l, &l1, &l2);
    }
    /* transverse profile w(u) and the section v = w - l e_x */
    double w[2] = {rb * (er[0] + u * et[0]) - H * et[0], rb * (er[1] + u * et[1]) - H * et[1]};
    double v[2] = {w[0] - l, w[1]};
    double ang = f->k * z, ca = cos(ang), sa = sin(ang);
#define ROT(a, out) do { (out)[0] = ca * (a)[0] - sa * (a)[1]; (out)[1] = sa * (a)[0] + ca * (a)[1]; } while (0)
    double Rv[2];
    ROT(v, Rv);
    e->r[0] = Rv[0];
    e->r[1] = Rv[1];
    e->r[2] = z;
    if (order < 1)
        return;
    double w1[2] = {(rb * u - H) * er[0] - H1 * et[0], (rb * u - H) * er[1] - H1 * et[1]};
    double Rw1[2], Rex[2] = {ca, sa};
    ROT(w1, Rw1);
    double k = f->k;
    e->ru[0] = Rw1[0];
    e->ru[1] = Rw1[1];
    e->ru[2] = 0;
    /* J (a, b) = (-b, a) */
    e->rz[0] = -k * Rv[1] - l1 * Rex[0];
    e->rz[1] = k * Rv[0] - l1 * Rex[1];
    e->rz[2] = 1;
    if (order < 2)
        return;
    double w2[2] = {(rb - 2 * H1) * er[0] - (rb * u - H + H2) * et[0], (rb - 2 * H1) * er[1] - (rb * u - H + H2) * et[1]};
    double Rw2[2];
    ROT(w2, Rw2);
    e->ruu[0] = Rw2[0];
    e->ruu[1] = Rw2[1];
    e->ruu[2] = 0;
    e->ruz[0] = -k * Rw1[1];
    e->ruz[1] = k * Rw1[0];
    e->ruz[2] = 0;
    e->rzz[0] = -k * k * Rv[0] - 2 * k * l1 * (-Rex[1]) - l2 * Rex[0];
    e->rzz[1] = -k * k * Rv[1] - 2 * k * l1 * Rex[0] - l2 * Rex[1];
    e->rzz[2] = 0;
#undef ROT
}

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

GD_API void gd_flank_normal(const gd_flank_eval *e, double n[3])
{
    cross(e->rz, e->ru, n);
    double m = sqrt(dot(n, n));
    n[0] /= m;
    n[1] /= m;
    n[2] /= m;
}

GD_API void gd_flank_curvature(const gd_flank_eval *e, double k[2], double dir[2][3])
{
    double n[3];
    gd_flank_normal(e, n);
    /* second fundamental form with the inward normal: convex is positive */
    double E = dot(e->ru, e->ru), F = dot(e->ru, e->rz), G = dot(e->rz, e->rz);
    double L = -dot(e->ruu, n), M = -dot(e->ruz, n), N = -dot(e->rzz, n);
    double det = E * G - F * F;
    /* shape operator S = I^-1 II */
    double s11 = (G * L - F * M) / det, s12 = (G * M - F * N) / det;
    double s21 = (E * M - F * L) / det, s22 = (E * N - F * M) / det;
    double tr = s11 + s22, dt = s11 * s22 - s12 * s21;
    double disc = sqrt(fmax(0.0, 0.25 * tr * tr - dt));
    k[0] = 0.5 * tr - disc;
    k[1] = 0.5 * tr + disc;
    for (int i = 0; i < 2; i++) {
        /* eigenvector (a, b) of S for k[i] */
        double a, b;
        if (fabs(s12) > fabs(s21) && fabs(s12) > 1e-300) {
            a = s12;
            b = k[i] - s11;
        } else if (fabs(s21) > 1e-300) {
            a = k[i] - s22;
            b = s21;
        } else {
            /* diagonal: the parameter lines are the principal directions (k[0] the smaller) */
            int u_is_min = s11 <= s22;
            int along_u = i == 0 ? u_is_min : !u_is_min;
            a = along_u ? 1 : 0;
            b = along_u ? 0 : 1;
        }
        double d[3] = {a * e->ru[0] + b * e->rz[0], a * e->ru[1] + b * e->rz[1], a * e->ru[2] + b * e->rz[2]};
        double m = sqrt(dot(d, d));
        for (int j = 0; j < 3; j++)
            dir[i][j] = m > 0 ? d[j] / m : 0;
    }
}
