/* ISO 21771 involute helical geometry: radii, angles, centre distance, contact ratios,
 * and the checks that refuse impossible geometry (undercut, pointed tip, eps_alpha < 1,
 * involute interference). */
#include "geardyn/gd_geometry.h"
#include "../core/gsl_quiet.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <math.h>

GD_API double gd_involute(double a) { return tan(a) - a; }

static double inv_fn(double a, void *p) { return gd_involute(a) - *(double *)p; }

/* alpha with inv(alpha) = target, by GSL's Brent solver on (0, 80 deg). */
static gd_status inverse_involute(double target, double *alpha, gd_error *err)
{
    gsl_function F = {inv_fn, &target};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s)
        return gd_error_set(err, GD_ERR_NOMEM, "gsl_root_fsolver_alloc failed");
    double lo = 1e-9, hi = 80.0 * M_PI / 180.0;
    int rc = gsl_root_fsolver_set(s, &F, lo, hi);
    int it = 0;
    while (rc == GSL_SUCCESS && it++ < 200) {
        rc = gsl_root_fsolver_iterate(s);
        if (rc != GSL_SUCCESS)
            break;
        lo = gsl_root_fsolver_x_lower(s);
        hi = gsl_root_fsolver_x_upper(s);
        rc = gsl_root_test_interval(lo, hi, 0, 1e-15);
        if (rc == GSL_SUCCESS)
            break;
        if (rc == GSL_CONTINUE)
            rc = GSL_SUCCESS;
    }
    *alpha = gsl_root_fsolver_root(s);
    gsl_root_fsolver_free(s);
    if (rc != GSL_SUCCESS)
        return gd_error_set(err, GD_ERR_GSL, "inverse involute: GSL Brent solver: %s", gsl_strerror(rc));
    return GD_OK;
}

/* Angles, pitches, the working pressure angle, the radii and the centre distance. */
static gd_status geometry_radii(const gd_pair *pair, gd_geometry *g, gd_error *err)
{
    const double deg = M_PI / 180.0;
    g->mn = pair->normal_module_mm * 1e-3;
    g->beta = pair->helix_angle_deg * deg;
    g->alpha_n = pair->normal_pressure_angle_deg * deg;
    g->z[0] = pair->teeth_pinion;
    g->z[1] = pair->teeth_gear;
    g->x[0] = pair->profile_shift_pinion;
    g->x[1] = pair->profile_shift_gear;
    g->mt = g->mn / cos(g->beta);
    g->alpha_t = atan(tan(g->alpha_n) / cos(g->beta));
    g->beta_b = asin(sin(g->beta) * cos(g->alpha_n));
    g->pbt = M_PI * g->mt * cos(g->alpha_t);
    g->pn = M_PI * g->mn;
    double inv_wt = gd_involute(g->alpha_t) + 2.0 * tan(g->alpha_n) * (g->x[0] + g->x[1]) / (g->z[0] + g->z[1]);
    gd_status st = inverse_involute(inv_wt, &g->alpha_wt, err);
    if (st != GD_OK)
        return st;
    for (int i = 0; i < 2; i++) {
        g->r[i] = 0.5 * g->z[i] * g->mt;
        g->rb[i] = g->r[i] * cos(g->alpha_t);
        g->ra[i] = g->r[i] + g->mn * (pair->addendum_coefficient + g->x[i]);
        g->rf[i] = g->r[i] - g->mn * (pair->dedendum_coefficient - g->x[i]);
        g->rw[i] = g->rb[i] / cos(g->alpha_wt);
    }
    g->a0 = g->r[0] + g->r[1];
    g->a = g->a0 * cos(g->alpha_t) / cos(g->alpha_wt);
    g->b[0] = pair->face_width_pinion_mm * 1e-3;
    g->b[1] = pair->face_width_gear_mm * 1e-3;
    g->b_contact = fmin(g->b[0], g->b[1]);
    return GD_OK;
}

/* The contact ratios, the start of active profile, the tooth thicknesses and the involute
 * form circle of each member; returns the length of the line of action between the base
 * circles' tangent points. */
static double geometry_contact(const gd_pair *pair, gd_geometry *g)
{
    double ga[2];
    for (int i = 0; i < 2; i++)
        ga[i] = sqrt(g->ra[i] * g->ra[i] - g->rb[i] * g->rb[i]);
    double loa = g->a * sin(g->alpha_wt);
    g->eps_alpha = (ga[0] + ga[1] - loa) / g->pbt;
    g->eps_beta = g->b_contact * sin(g->beta) / (M_PI * g->mn);
    g->eps_gamma = g->eps_alpha + g->eps_beta;
    for (int i = 0; i < 2; i++) {
        double rho = loa - ga[1 - i]; /* roll length at the start of active profile */
        g->r_sap[i] = sqrt(g->rb[i] * g->rb[i] + (rho > 0 ? rho * rho : 0));
        /* tooth thickness at the tip (transverse arc), then normal */
        double s_t = g->mt * (M_PI / 2 + 2 * g->x[i] * tan(g->alpha_n));
        double alpha_a = acos(g->rb[i] / g->ra[i]);
        double s_at = 2 * g->ra[i] * (s_t / (2 * g->r[i]) + gd_involute(g->alpha_t) - gd_involute(alpha_a));
        double beta_a = atan(tan(g->beta) * g->ra[i] / g->r[i]);
        g->tip_thickness_n[i] = s_at * cos(beta_a);
        g->psi_b[i] = s_t / (2 * g->r[i]) + gd_involute(g->alpha_t);
        g->eta_b[i] = M_PI / g->z[i] - g->psi_b[i];
        g->rho_a[i] = ga[i];
        g->rho_sap[i] = rho > 0 ? rho : 0;
        /* involute form circle: the generating rack's straight flank ends h_a* m_n above its
         * datum line (ISO 53: the rest of the rack tip is the fillet-generating radius), so the
         * generated involute starts at the roll length r sin(alpha_t) - (h_a* - x) m_n / sin(alpha_t) */
        g->rho_form[i] = g->r[i] * sin(g->alpha_t) - (pair->addendum_coefficient - g->x[i]) * g->mn / sin(g->alpha_t);
        g->r_form[i] = sqrt(g->rb[i] * g->rb[i] + (g->rho_form[i] > 0 ? g->rho_form[i] * g->rho_form[i] : 0));
    }
    g->pbn = g->pbt * cos(g->beta_b);
    return loa;
}

/* The checks that refuse impossible geometry; g->bad_key names the key to blame. */
static gd_status geometry_check(const gd_pair *pair, gd_geometry *g, double loa, gd_error *err)
{
    static const char *name[2] = {"pinion", "gear"};
    static const char *shift_key[2] = {"profile_shift_pinion", "profile_shift_gear"};
    static const char *teeth_key[2] = {"teeth_pinion", "teeth_gear"};
    g->bad_key = NULL;
    for (int i = 0; i < 2; i++) {
        g->bad_key = shift_key[i];
        if (g->rf[i] <= 0)
            return gd_error_set(err, GD_ERR_GEOMETRY, "%s: impossible geometry: root radius %.4g mm is not positive",
                                name[i], g->rf[i] * 1e3);
        /* undercut: the generating rack's tip line (h_a* above the datum) must not cut below
         * the interference point of the base circle: m_n (h_a* - x) <= r sin^2(alpha_t) */
        double need = g->mn * (pair->addendum_coefficient - g->x[i]);
        g->bad_key = teeth_key[i];
        if (need > g->r[i] * sin(g->alpha_t) * sin(g->alpha_t) + 1e-12)
            return gd_error_set(err, GD_ERR_GEOMETRY,
                "%s: undercut: z = %d with profile shift %.3g is undercut (needs x >= %.3f)", name[i], g->z[i],
                g->x[i], pair->addendum_coefficient - g->r[i] * pow(sin(g->alpha_t), 2) / g->mn);
        g->bad_key = shift_key[i];
        if (g->tip_thickness_n[i] <= 0.2 * g->mn)
            return gd_error_set(err, GD_ERR_GEOMETRY,
                "%s: pointed tip: normal tip thickness %.3g mm below 0.2 m_n = %.3g mm (reduce profile shift or addendum)",
                name[i], g->tip_thickness_n[i] * 1e3, 0.2 * g->mn * 1e3);
        if (loa - g->rho_a[1 - i] < 0)
            return gd_error_set(err, GD_ERR_GEOMETRY,
                "%s: involute interference: the mating tip reaches below the base circle (start of active profile undefined)",
                name[i]);
        if (g->r_sap[i] < g->rf[i])
            return gd_error_set(err, GD_ERR_GEOMETRY,
                "%s: interference: start of active profile %.4g mm lies below the root circle %.4g mm", name[i],
                g->r_sap[i] * 1e3, g->rf[i] * 1e3);
        if (g->rho_sap[i] < g->rho_form[i] - 1e-12)
            return gd_error_set(err, GD_ERR_GEOMETRY,
                "%s: interference: the mating tip reaches the fillet (start of active profile %.4g mm below the "
                "involute form circle %.4g mm)", name[i], g->r_sap[i] * 1e3, g->r_form[i] * 1e3);
    }
    g->bad_key = "addendum_coefficient";
    if (!(g->eps_alpha >= 1.0))
        return gd_error_set(err, GD_ERR_GEOMETRY, "transverse contact ratio %.4f below 1: the pair cannot mesh continuously",
                            g->eps_alpha);
    g->bad_key = NULL;
    return GD_OK;
}

GD_API gd_status gd_geometry_compute(const gd_pair *pair, gd_geometry *g, gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    gd_status st = geometry_radii(pair, g, err);
    if (st != GD_OK)
        return st;
    double loa = geometry_contact(pair, g);
    return geometry_check(pair, g, loa, err);
}
