/* The scene of a case: its geometry and everything derived from it (bodies, the modified flank's
 * limits, the operating contact ratio, the mesh stiffness from ISO 6336 or LTCA, the shaft
 * stiffness), checked against the keys they come from. */
#include "geardyn/gd_scene.h"
#include "geardyn/gd_flank.h"
#include "geardyn/gd_excitation.h"
#include "geardyn/gd_geometry.h"
#include "../case/case_keys.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The geometry of the pair (g), refused with the key to blame, and the bores inside the roots. */
static gd_status resolve_geometry(gd_case *c, gd_geometry *g, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    const gd_pair pair = gd_pair_from_case(c);
    gd_status st = gd_geometry_compute(&pair, g, err);
    if (st != GD_OK) {
        if (st == GD_ERR_GEOMETRY && g->bad_key) {
            gd_case_key_where(c, "gear", g->bad_key, w, sizeof w);
            return gd_error_prefix(err, "%s: gear.%s", w, g->bad_key);
        }
        return gd_error_prefix(err, "%s: [gear]", c->path[0] ? c->path : "case");
    }
    for (int i = 0; i < 2; i++) {
        double bore = i == 0 ? c->bore_diameter_pinion_mm : c->bore_diameter_gear_mm;
        if (bore * 0.5e-3 >= g->rf[i]) {
            const char *k = i == 0 ? "bore_diameter_pinion_mm" : "bore_diameter_gear_mm";
            gd_case_key_where(c, "gear", k, w, sizeof w);
            return gd_error_set(err, GD_ERR_GEOMETRY, "%s: gear.%s: bore %g mm does not fit inside the root circle "
                                "(valid: below %.4g mm)", w, k, bore, 2e3 * g->rf[i]);
        }
    }
    return GD_OK;
}

/* Arrangement, [modification] on the pinion flank, [misalignment] (docs/geometry.md). */
static gd_status resolve_flank(gd_case *c, const gd_geometry *g, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    if (c->arrangement == GD_ARR_SPUR && c->helix_angle_deg != 0) {
        gd_case_key_where(c, "gear", "helix_angle_deg", w, sizeof w);
        return gd_error_set(err, GD_ERR_GEOMETRY, "%s: gear.helix_angle_deg: %g with arrangement = spur (valid: 0)", w,
                            c->helix_angle_deg);
    }
    if (!c->modification_apply) { /* the unmodified pair: amounts and lengths resolve to 0, marked derived */
        static const char *const mk[] = { "root_relief_amount_um", "root_relief_length_mm", "tip_relief_amount_um",
                                          "tip_relief_length_mm", "lead_relief_inner_um", "lead_relief_outer_um",
                                          "lead_unmodified_length_mm", "lead_unmodified_centre_mm", "helix_slope_um" };
        double *mf[] = { &c->root_relief_amount_um, &c->root_relief_length_mm, &c->tip_relief_amount_um,
                         &c->tip_relief_length_mm, &c->lead_relief_inner_um, &c->lead_relief_outer_um,
                         &c->lead_unmodified_length_mm, &c->lead_unmodified_centre_mm, &c->helix_slope_um };
        for (size_t k = 0; k < sizeof mk / sizeof mk[0]; k++) {
            *mf[k] = 0.0;
            c->src[gd_case_key_index("modification", mk[k])] = GD_SRC_DERIVED;
        }
    }
    const char *mkey = NULL;
    const gd_pair pair = gd_pair_from_case(c);
    if (gd_modification_check(&pair, g, &mkey, err) != GD_OK) {
        gd_case_key_where(c, "modification", mkey, w, sizeof w);
        return gd_error_prefix(err, "%s: modification.%s", w, mkey);
    }
    double sb = g->rb[0] + g->rb[1], aop = g->a + c->centre_distance_error_mm * 1e-3;
    double ea = (g->rho_a[0] + g->rho_a[1] - sqrt(aop * aop - sb * sb)) / g->pbt;
    if (ea < 1.0) {
        double amax = sqrt(sb * sb + pow(g->rho_a[0] + g->rho_a[1] - g->pbt, 2));
        gd_case_key_where(c, "misalignment", "centre_distance_error_mm", w, sizeof w);
        return gd_error_set(err, GD_ERR_GEOMETRY, "%s: misalignment.centre_distance_error_mm: transverse contact ratio "
                            "%.4f below 1 at the operating centre distance %.6g mm (valid: below %.4g mm)", w, ea,
                            aop * 1e3, (amax - g->a) * 1e3);
    }
    return GD_OK;
}

/* A spur or single-helical pair is one mesh on the whole bodies (docs/model.md section 5.4): no
 * model of two halves, no stagger of a second half, a single helical mesh's axial force must
 * meet a pinion support in bta, and its pinion is axially fixed for LTCA (nothing else balances
 * the axial force; support.pinion_axial resolves to fixed, derived, and floating is refused). */
static gd_status resolve_single_pair(gd_case *c, gd_error *err)
{
    if (c->arrangement == GD_ARR_HERRINGBONE)
        return GD_OK;
    char w[GD_PATH_MAX + 32], wa[GD_PATH_MAX + 32];
    const char *arr = c->arrangement == GD_ARR_SPUR ? "spur" : "helical";
    gd_case_key_where(c, "gear", "arrangement", wa, sizeof wa);
    if (gd_case_key_given(c, "support", "pinion_axial")) {
        if (c->pinion_axial == GD_PINION_FLOATING) {
            gd_case_key_where(c, "support", "pinion_axial", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: support.pinion_axial: floating with gear.arrangement = %s (%s) "
                                "(valid: fixed; a floating pinion needs the two halves of a herringbone, whose axial "
                                "forces balance)", w, arr, wa);
        }
    } else {
        c->pinion_axial = GD_PINION_FIXED;
        c->src[gd_case_key_index("support", "pinion_axial")] = GD_SRC_DERIVED;
    }
    if (c->model == GD_MODEL_TORSIONAL_LR) {
        gd_case_key_where(c, "scene", "model", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: scene.model: torsional-lr with gear.arrangement = %s (%s) (valid: "
                            "torsional, bta; torsional-lr is the two halves of a herringbone, a single pair has one "
                            "mesh)", w, arr, wa);
    }
    if (c->half_phase_deg != 0.0) {
        gd_case_key_where(c, "excitation", "half_phase_deg", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.half_phase_deg: %g with gear.arrangement = %s (%s) "
                            "(valid: 0, a single pair has one mesh)", w, c->half_phase_deg, arr, wa);
    }
    if (c->model == GD_MODEL_BTA && c->arrangement == GD_ARR_HELICAL && c->axial_coupling &&
        !(c->axial_stiffness_pinion_n_per_m > 0)) {
        gd_case_key_where(c, "support", "axial_stiffness_pinion_n_per_m", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: support.axial_stiffness_pinion_n_per_m: 0 (floating) with "
                            "gear.arrangement = helical (%s) and scene.model = bta (valid: above 0; nothing else takes "
                            "the axial mesh force of a single helical pair)", w, wa);
    }
    return GD_OK;
}

/* The blank of each body: bore < hub < rim inner diameter < root diameter, a web thickness with a
 * rim and none without, a hub length only with a hub (else derived: the body's width). */
static gd_status resolve_blank(gd_case *c, const gd_geometry *g, gd_error *err)
{
    char w[GD_PATH_MAX + 32], k[64];
    for (int i = 0; i < 2; i++) {
        const char *body = i == 0 ? "pinion" : "gear";
        double bore = i == 0 ? c->bore_diameter_pinion_mm : c->bore_diameter_gear_mm;
        double rim = i == 0 ? c->rim_inner_diameter_pinion_mm : c->rim_inner_diameter_gear_mm;
        double web = i == 0 ? c->web_thickness_pinion_mm : c->web_thickness_gear_mm;
        double hub = i == 0 ? c->hub_diameter_pinion_mm : c->hub_diameter_gear_mm;
        double df = 2e3 * g->rf[i];
        if (hub > 0 && !(hub > bore && hub < (rim > 0 ? rim : df))) {
            snprintf(k, sizeof k, "hub_diameter_%s_mm", body);
            gd_case_key_where(c, "gear", k, w, sizeof w);
            return gd_error_set(err, GD_ERR_GEOMETRY, "%s: gear.%s: a hub of %g mm (valid: above the bore %g mm and "
                                "below the %s %.4g mm)", w, k, hub, bore, rim > 0 ? "rim inner diameter" : "root circle",
                                rim > 0 ? rim : df);
        }
        if (rim > 0 && !(rim > fmax(bore, hub) && rim < df)) {
            snprintf(k, sizeof k, "rim_inner_diameter_%s_mm", body);
            gd_case_key_where(c, "gear", k, w, sizeof w);
            return gd_error_set(err, GD_ERR_GEOMETRY, "%s: gear.%s: a rim from %g mm (valid: above the %s %g mm and "
                                "below the root circle %.4g mm)", w, k, rim, hub > 0 ? "hub" : "bore", fmax(bore, hub), df);
        }
        snprintf(k, sizeof k, "web_thickness_%s_mm", body);
        if (rim > 0 && !isfinite(web)) {
            snprintf(k, sizeof k, "rim_inner_diameter_%s_mm", body);
            gd_case_key_where(c, "gear", k, w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: gear.%s: a rim without gear.web_thickness_%s_mm (valid: give "
                                "the web's axial thickness with the rim)", w, k, body);
        }
        if (rim == 0 && gd_case_key_given(c, "gear", k)) {
            gd_case_key_where(c, "gear", k, w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: gear.%s: a web without a rim (valid: give "
                                "gear.rim_inner_diameter_%s_mm, where the web meets the rim)", w, k, body);
        }
        snprintf(k, sizeof k, "hub_length_%s_mm", body);
        if (hub == 0 && gd_case_key_given(c, "gear", k)) {
            gd_case_key_where(c, "gear", k, w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: gear.%s: a hub length without a hub (valid: give "
                                "gear.hub_diameter_%s_mm too)", w, k, body);
        }
        if (hub > 0) {
            const gd_pair pair = gd_pair_from_case(c);
            gd_blank b;
            gd_body_blank(&pair, g, i, &b);
            gd_case_key_derive(c, "gear", k, i == 0 ? &c->hub_length_pinion_mm : &c->hub_length_gear_mm,
                               1e3 * b.width);
        }
    }
    return GD_OK;
}

/* The masses and inertias of the bodies and the equivalent mass, unless given. */
static void resolve_bodies(gd_case *c, const gd_geometry *g)
{
    double m1, i1, m2, i2;
    const gd_pair pair = gd_pair_from_case(c);
    gd_body_of_mesh(&pair, g, 0, &m1, &i1);
    gd_body_of_mesh(&pair, g, 1, &m2, &i2);
    gd_case_key_derive(c, "gear", "pinion_mass_kg", &c->pinion_mass_kg, m1);
    gd_case_key_derive(c, "gear", "gear_mass_kg", &c->gear_mass_kg, m2);
    gd_case_key_derive(c, "gear", "pinion_inertia_kgm2", &c->pinion_inertia_kgm2, i1);
    gd_case_key_derive(c, "gear", "gear_inertia_kgm2", &c->gear_inertia_kgm2, i2);
    double I1 = c->pinion_inertia_kgm2, I2 = c->gear_inertia_kgm2;
    gd_case_key_derive(c, "gear", "equivalent_mass_kg", &c->equivalent_mass_kg,
           I1 * I2 / (I1 * g->rb[1] * g->rb[1] + I2 * g->rb[0] * g->rb[0]));
}

/* The LTCA excitation (stiffness = ltca, the mesh-in impact, or ste = ltca): it needs a load;
 * with stiffness = ltca its mean stiffness is the mesh stiffness. */
static gd_status resolve_ltca(gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    const char *k = c->stiffness == GD_STIFF_LTCA ? "stiffness" : c->impact ? "impact" : "ste";
    if (!(c->torque_nm > 0)) {
        gd_case_key_where(c, "excitation", k, w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.%s: LTCA needs a load, the torque is %g N m "
                            "(valid: operating.torque_nm > 0)", w, k, c->torque_nm);
    }
    if (c->stiffness == GD_STIFF_LTCA && c->half_phase_deg != 0.0) {
        gd_case_key_where(c, "excitation", "half_phase_deg", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.half_phase_deg: %g with stiffness = ltca (valid: 0; "
                            "the halves' relative phase comes from their geometry)", w, c->half_phase_deg);
    }
    if (c->ltca_deferred)  /* geardyn check: the run computes it */
        return GD_OK;
    const gd_ltca_excitation *x;
    const gd_pair pair = gd_pair_from_case(c);
    const gd_ltca_settings set = gd_ltca_settings_from_case(c);
    gd_status sx = gd_ltca_excitation_cached(&pair, &set, &x, err);
    if (sx != GD_OK)
        return gd_error_prefix(err, "%s", c->path[0] ? c->path : "case");
    if (c->stiffness == GD_STIFF_LTCA)
        gd_case_key_derive(c, "excitation", "mesh_stiffness_n_per_m", &c->mesh_stiffness_n_per_m,
               x->halves > 1 && x->k[1] ? 0.5 * (x->k_mean[0] + x->k_mean[1]) : x->k_mean[0]);
    gd_ltca_excitation_release(x);
    return GD_OK;
}

/* The stiffnesses, unless given: mesh (LTCA or ISO 6336), groove shafts, and the high
 * fraction of the rectangular stiffness, which must leave the low level positive. */
static gd_status resolve_stiffness(gd_case *c, const gd_geometry *g, gd_error *err)
{
    const gd_pair pair = gd_pair_from_case(c);
    if (c->stiffness == GD_STIFF_LTCA || c->impact || (c->ste_source == GD_STE_LTCA && c->error_excitation)) {
        gd_status st = resolve_ltca(c, err);
        if (st != GD_OK)
            return st;
    }
    if (c->stiffness != GD_STIFF_LTCA || c->ltca_deferred)
        gd_case_key_derive(c, "excitation", "mesh_stiffness_n_per_m", &c->mesh_stiffness_n_per_m, gd_iso6336_mesh_stiffness(&pair, g));
    gd_case_key_derive(c, "support", "shaft_stiffness_pinion_n_per_m", &c->shaft_stiffness_pinion_n_per_m,
           gd_groove_shaft_stiffness(&pair, g, 0));
    gd_case_key_derive(c, "support", "shaft_stiffness_gear_n_per_m", &c->shaft_stiffness_gear_n_per_m,
           gd_groove_shaft_stiffness(&pair, g, 1));
    double frac = g->eps_alpha - floor(g->eps_alpha);
    if (frac < 0.02 || frac > 0.98)
        frac = 0.5;
    gd_case_key_derive(c, "excitation", "rectangular_high_fraction", &c->rectangular_high_fraction, frac);
    if (c->stiffness == GD_STIFF_RECTANGULAR) {
        double d = c->rectangular_high_fraction;
        if (c->rectangular_variation * d / (1 - d) >= 1.0) {
            char w[GD_PATH_MAX + 32];
            gd_case_key_where(c, "excitation", "rectangular_variation", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.rectangular_variation: %g with high fraction %g "
                                "makes the low level negative (valid: below %g)", w, c->rectangular_variation, d,
                                (1 - d) / d);
        }
    }
    return GD_OK;
}

GD_API gd_status gd_scene_resolve(gd_case *c, gd_error *err)
{
    gd_geometry g;
    gd_status st = resolve_geometry(c, &g, err);
    if (st == GD_OK)
        st = resolve_flank(c, &g, err);
    if (st == GD_OK)
        st = resolve_single_pair(c, err);
    if (st != GD_OK)
        return st;
    if ((st = resolve_blank(c, &g, err)) != GD_OK)
        return st;
    resolve_bodies(c, &g);
    return resolve_stiffness(c, &g, err);
}
