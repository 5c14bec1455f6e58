/* Tooth compliance by the potential-energy method: a variable-thickness Timoshenko cantilever
 * with exact influence coefficients from tabulated cumulative integrals, Sainsot's fillet
 * foundation, linear Hertz, and the face coupling kernel. */
#include "geardyn/gd_compliance.h"
#include "../core/gsl_quiet.h"
#include "geardyn/gd_geometry.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_spline.h>
#include <math.h>
#include <string.h>

/* angle of the half thickness at radius r: the involute above the base circle, the radial line
 * of the base angle below it (Tian 2004) */
static double half_angle(const gd_tooth *t, double r)
{
    return r > t->rb ? t->psi_b - gd_involute(acos(t->rb / r)) : t->psi_b;
}

/* centre-line coordinate x(r), its derivative, and the half thickness y(r) */
static void section(const gd_tooth *t, double r, double *x, double *dx, double *y)
{
    if (t->psi_b < 0) {
        *x = r;
        *dx = 1;
        *y = t->beam_y;
        return;
    }
    double th = half_angle(t, r);
    /* d theta / dr = -d inv(alpha)/dr = -tan^2(alpha) * d alpha/dr, d alpha/dr = rb / (r^2 sin alpha) */
    double dth = 0;
    if (r > t->rb) {
        double a = acos(t->rb / r);
        dth = -tan(a) * tan(a) * t->rb / (r * r * sin(a));
    }
    *x = r * cos(th);
    *dx = cos(th) - r * sin(th) * dth;
    *y = r * sin(th);
}

typedef struct integrand { const gd_tooth *t; int which; } integrand;

static double f_int(double r, void *p)
{
    const integrand *q = p;
    const gd_tooth *t = q->t;
    double x, dx, y;
    section(t, r, &x, &dx, &y);
    double E = t->E / (1.0 - t->nu * t->nu); /* plane strain: slices of a wide tooth */
    double G = t->E / (2.0 * (1.0 + t->nu));
    double I = pow(2.0 * y, 3) / 12.0, A = 2.0 * y;
    switch (q->which) {
    case 0: return dx / (E * I);
    case 1: return x * dx / (E * I);
    case 2: return x * x * dx / (E * I);
    case 3: return dx / (G * A);
    default: return dx / (E * A);
    }
}

static gd_status tabulate(gd_tooth *t, gd_error *err)
{
    double r[GD_TOOTH_GRID], F[5][GD_TOOTH_GRID];
    gsl_integration_glfixed_table *tab = gsl_integration_glfixed_table_alloc(16);
    if (!tab)
        return gd_error_set(err, GD_ERR_NOMEM, "tooth compliance: GSL Gauss-Legendre table");
    for (int i = 0; i < GD_TOOTH_GRID; i++) {
        /* denser near the root, where the integrands are largest */
        double s = (double)i / (GD_TOOTH_GRID - 1);
        r[i] = t->r0 + (t->r1 - t->r0) * s * s * (3 - 2 * s) * 0.5 + (t->r1 - t->r0) * s * 0.5;
    }
    for (int w = 0; w < 5; w++) {
        integrand q = {t, w};
        gsl_function fn = {f_int, &q};
        F[w][0] = 0;
        for (int i = 1; i < GD_TOOTH_GRID; i++)
            F[w][i] = F[w][i - 1] + gsl_integration_glfixed(&fn, r[i - 1], r[i], tab);
    }
    gsl_integration_glfixed_table_free(tab);
    for (int w = 0; w < 5; w++) {
        gsl_spline *sp = gsl_spline_alloc(gsl_interp_cspline, GD_TOOTH_GRID);
        gsl_interp_accel *ac = gsl_interp_accel_alloc();
        if (!sp || !ac) {
            gsl_spline_free(sp);
            gsl_interp_accel_free(ac);
            gd_tooth_free(t);
            return gd_error_set(err, GD_ERR_NOMEM, "tooth compliance: GSL spline");
        }
        int rc = gsl_spline_init(sp, r, F[w], GD_TOOTH_GRID);
        if (rc != GSL_SUCCESS) {
            gsl_spline_free(sp);
            gsl_interp_accel_free(ac);
            gd_tooth_free(t);
            return gd_error_set(err, GD_ERR_GSL, "tooth compliance: gsl_spline_init: %s", gsl_strerror(rc));
        }
        t->spline[w] = sp;
        t->acc[w] = ac;
    }
    return GD_OK;
}

GD_API void gd_tooth_free(gd_tooth *t)
{
    for (int w = 0; w < 5; w++) {
        gsl_spline_free(t->spline[w]);
        gsl_interp_accel_free(t->acc[w]);
        t->spline[w] = t->acc[w] = NULL;
    }
}

GD_API gd_status gd_tooth_init(const gd_pair *pair, const gd_geometry *g, int body, gd_tooth *t, gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    memset(t, 0, sizeof *t);
    t->E = pair->youngs_modulus_gpa * 1e9;
    t->nu = pair->poisson_ratio;
    t->rb = g->rb[body];
    t->rf = g->rf[body];
    t->ra = g->ra[body];
    double s_t = g->mt * (M_PI / 2 + 2 * g->x[body] * tan(g->alpha_n)); /* transverse reference thickness */
    t->psi_b = s_t / (2 * g->r[body]) + gd_involute(g->alpha_t);
    t->theta_f = half_angle(t, t->rf);
    t->x_root = t->rf * cos(t->theta_f);
    double rbore = 0.5e-3 * (body == 0 ? pair->bore_diameter_pinion_mm : pair->bore_diameter_gear_mm);
    /* Sainsot's fit covers h_fi = r_f / r_int from thin rims to solid blanks; a solid blank is
     * taken at h_fi = 1.6, the solid end of the range the fit was made for */
    t->h_fi = rbore > 0 ? t->rf / rbore : 1.6;
    t->r0 = t->rf;
    t->r1 = t->ra;
    t->height = t->ra * cos(half_angle(t, t->ra)) - t->x_root;
    return tabulate(t, err);
}

GD_API gd_status gd_tooth_init_beam(gd_tooth *t, double E, double nu, double x_root, double x_tip, double y,
                                    gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    memset(t, 0, sizeof *t);
    t->E = E;
    t->nu = nu;
    t->psi_b = -1;
    t->beam_y = y;
    t->x_root = x_root;
    t->r0 = x_root;
    t->r1 = x_tip;
    t->height = x_tip - x_root;
    return tabulate(t, err);
}

GD_API void gd_load_point_at(const gd_tooth *t, double r, gd_load_point *p)
{
    p->r = r;
    if (t->psi_b < 0) { /* beam: a load across the centre line at x = r */
        p->x = r;
        p->h = 0;
        p->cos_a = 1;
        p->sin_a = 0;
        return;
    }
    double th = half_angle(t, r);
    double alpha = r > t->rb ? acos(t->rb / r) : 0.0; /* pressure angle at r */
    double a1 = alpha - th;                            /* load angle to the centre-line normal */
    p->x = r * cos(th);
    p->h = r * sin(th);
    p->cos_a = cos(a1);
    p->sin_a = sin(a1);
}

static double F(const gd_tooth *t, int w, double r)
{
    /* clamp to the table's own range: its last node can round just below the tip radius, and an
     * evaluation outside would go to GSL's error handler */
    const gsl_spline *sp = t->spline[w];
    r = fmin(fmax(r, sp->interp->xmin), sp->interp->xmax);
    return gsl_spline_eval(sp, r, (gsl_interp_accel *)t->acc[w]);
}

/* Maxwell-Betti: int M_j M_k / (E' I) + 1.2 V_j V_k / (G A) + N_j N_k / (E' A) dx from the root to
 * the lower load point, unit loads along the contact normals; M_j(x) = a_j - c_j x with
 * a_j = cos(alpha_j) x_j - sin(alpha_j) h_j, c_j = cos(alpha_j). */
GD_API double gd_tooth_influence(const gd_tooth *t, const gd_load_point *j, const gd_load_point *k)
{
    double r = j->x < k->x ? j->r : k->r;
    double aj = j->cos_a * j->x - j->sin_a * j->h, ak = k->cos_a * k->x - k->sin_a * k->h;
    double cj = j->cos_a, ck = k->cos_a;
    double f0 = F(t, 0, r), f1 = F(t, 1, r), f2 = F(t, 2, r), sh = F(t, 3, r), ax = F(t, 4, r);
    return aj * ak * f0 - (aj * ck + ak * cj) * f1 + cj * ck * f2 + 1.2 * cj * ck * sh + j->sin_a * k->sin_a * ax;
}

GD_API double gd_tooth_foundation(const gd_tooth *t, const gd_load_point *p)
{
    if (t->psi_b < 0)
        return 0.0;
    static const double C[4][6] = {
        /*  A          B           C           D           E        F */
        {-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045},  /* L* */
        {60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086},  /* M* */
        {-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236},   /* P* */
        {-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904}, /* Q* */
    };
    double h = t->h_fi, th = t->theta_f, X[4];
    for (int i = 0; i < 4; i++)
        X[i] = C[i][0] / (th * th) + C[i][1] * h * h + C[i][2] * h / th + C[i][3] / th + C[i][4] * h + C[i][5];
    double Sf = 2.0 * t->rf * sin(th);
    /* where the line of the load meets the centre line, measured from the root circle */
    double uf = p->x - p->h * p->sin_a / p->cos_a - t->x_root;
    double u = uf / Sf;
    double E = t->E / (1.0 - t->nu * t->nu);
    double ta = p->sin_a / p->cos_a;
    return p->cos_a * p->cos_a / E * (X[0] * u * u + X[1] * u + X[2] * (1.0 + X[3] * ta * ta));
}

GD_API double gd_hertz_compliance(double E, double nu) { return 4.0 * (1.0 - nu * nu) / (M_PI * E); }

GD_API double gd_face_kernel(double za, double zb, double z0, double z1, double ell)
{
    double g = exp(-fabs(za - zb) / ell);
    g += exp(-fabs(za + zb - 2.0 * z0) / ell); /* images in the faces: free ends are softer */
    g += exp(-fabs(za + zb - 2.0 * z1) / ell);
    return g / (2.0 * ell);
}

GD_API double gd_face_kernel_pair(double za, double zb, double z0, double z1, double ell_a, double ell_b)
{
    return gd_face_kernel(za, zb, z0, z1, sqrt(0.5 * (ell_a * ell_a + ell_b * ell_b)));
}

GD_API double gd_face_kernel_cells(double alo, double ahi, double blo, double bhi, double z0, double z1, double ell_a,
                                   double ell_b)
{
    double l = sqrt(0.5 * (ell_a * ell_a + ell_b * ell_b)), r = 1.0 / l;
    double wa = ahi - alo, wb = bhi - blo;
    /* int_I int_J e^{-|x - y|/l} = l^2 e^{-gap/l} (1 - e^{-|I|/l}) (1 - e^{-|J|/l}) for disjoint
     * cells, 2 l |I| - 2 l^2 (1 - e^{-|I|/l}) for one cell; the images in the faces factorise */
    double Ea = -expm1(-wa * r), Eb = wb == wa ? Ea : -expm1(-wb * r);
    double direct;
    if (alo == blo && ahi == bhi)
        direct = 2.0 * l * wa - 2.0 * l * l * Ea;
    else
        direct = l * l * exp(-fmax(alo < blo ? blo - ahi : alo - bhi, 0.0) * r) * Ea * Eb;
    double images = l * l * Ea * Eb * (exp(-(fmax(alo - z0, 0.0) + fmax(blo - z0, 0.0)) * r) +
                                       exp(-(fmax(z1 - ahi, 0.0) + fmax(z1 - bhi, 0.0)) * r));
    return (direct + images) * 0.5 * r / (wa * wb);
}

/* The spread of a load along a thick cantilever plate strip (docs/ltca.md section 2): the
 * Fourier-transformed Mindlin plate equations of a strip clamped at the root and free at the tip,
 * with the tooth's own (tapered) thickness, spread a load at height a over a length that grows in
 * proportion to a and levels off toward the thin tip; with these decay lengths the exponential
 * kernel reproduces the plate's stiffness under line loads of the kinds a contact line makes
 * (along the face at one height, across the height, ending inside the face) within 5 % on teeth
 * of 30 to 117 teeth, where the uniform 2h/pi overestimated it by 10 to 41 %
 * (tests/test_ltca_kernel.c). */
#define SPREAD_SLOPE 0.8 /* ell / a up to half the height */
#define SPREAD_EDGE 0.4  /* ell / height above it */

GD_API double gd_tooth_spread(const gd_tooth *t, const gd_load_point *p)
{
    double a = fmax(p->x - t->x_root, 0.0);
    return fmax(fmin(SPREAD_SLOPE * a, SPREAD_EDGE * t->height), 1e-3 * t->height);
}
