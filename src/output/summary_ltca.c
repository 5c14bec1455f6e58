/* summary.json of an ltca run: the resolved case, the derived geometry, the solver settings and
 * checks, and the results under stable keys (docs/ltca.md, section 5). */
#include "geardyn/gd_ltca.h"
#include "output_internal.h"
#include "geardyn/gd_geometry.h"
#include "geardyn/gd_scene.h"

#include "json_util.h"

#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static json_t *impact_json(const gd_ltca_impact *im)
{
    if (!im->found)
        return json_null();
    json_t *o = json_object();
    json_object_set_new(o, "pinion_angle_deg", gd_json_num(im->phi1 * 180 / M_PI));
    json_object_set_new(o, "phase", gd_json_num(im->phase));
    json_object_set_new(o, "pair", json_integer(im->pair));
    json_object_set_new(o, "pinion_roll_mm", gd_json_num(im->rho1 * 1e3));
    json_object_set_new(o, "pinion_face_mm", gd_json_num(im->z1 * 1e3));
    json_object_set_new(o, "start_of_contact_roll_mm", gd_json_num(im->rho_sap * 1e3));
    json_object_set_new(o, "offset_from_plane_of_action_um", gd_json_num(im->offset_loa * 1e6));
    json_object_set_new(o, "edge", gd_json_edge_names(im->edge));
    json_object_set_new(o, "relative_normal_velocity_per_pinion_speed_m", gd_json_num(im->vs_per_omega));
    json_object_set_new(o, "loaded_deflection_um", gd_json_num(im->delta_m * 1e6));
    json_object_set_new(o, "stiffness_n_per_m", gd_json_num(im->ks));
    json_object_set_new(o, "power_law_c", gd_json_num(im->fit_c));
    json_object_set_new(o, "power_law_n", gd_json_num(im->fit_n));
    return o;
}

/* "derived": the geometry (when it computes), the load and the resultant misalignment. */
static json_t *ltca_derived_json(const gd_case *c, const gd_ltca_result *r)
{
    const double deg = 180.0 / M_PI;
    gd_geometry g;
    gd_error e2;
    json_t *der = json_object();
    const gd_pair pair = gd_pair_from_case(c);
    if (gd_geometry_compute(&pair, &g, &e2) == GD_OK) {
        json_t *geo = json_object();
        json_object_set_new(geo, "base_helix_angle_deg", gd_json_num(g.beta_b * deg));
        json_object_set_new(geo, "contact_ratio_transverse", gd_json_num(g.eps_alpha));
        json_object_set_new(geo, "contact_ratio_overlap", gd_json_num(g.eps_beta));
        json_object_set_new(geo, "iso6336_mesh_stiffness_n_per_m", gd_json_num(gd_iso6336_mesh_stiffness(&pair, &g)));
        json_object_set_new(der, "geometry", geo);
    }
    json_object_set_new(der, "normal_force_n", gd_json_num(r->normal_force_n));
    /* the axial component of one mesh's normal force (a herringbone's half: its share, the halves'
     * in opposite senses), what the pinion's axial support takes */
    if (gd_geometry_compute(&pair, &g, &e2) == GD_OK)
        json_object_set_new(der, "axial_force_n", gd_json_num(r->normal_force_n / r->halves * sin(g.beta_b)));
    json_object_set_new(der, "pinion_torque_nm", gd_json_num(r->torque_nm));
    json_object_set_new(der, "axis_misalignment_resultant_arcmin",
                        gd_json_num(hypot(c->axis_in_plane_arcmin, c->axis_cross_plane_arcmin)));
    return der;
}

/* "solver": the contact problem, its grid, checks and cache key. */
static json_t *ltca_solver_json(const gd_ltca_result *r)
{
    json_t *sol = json_object();
    json_object_set_new(sol, "contact_problem", json_string("Eq. 11 as a strictly convex QP, primal active set "
                                                            "(block-diagonal Cholesky per tooth pair)"));
    json_object_set_new(sol, "pinion_axial", json_string(r->floating ? "floating" : "fixed"));
    json_object_set_new(sol, "positions", json_integer(r->npos));
    json_object_set_new(sol, "face_slices", json_integer(r->nslices));
    json_object_set_new(sol, "active_set_iterations", json_integer(r->iterations));
    json_object_set_new(sol, "max_residual_m", gd_json_num(r->max_residual));
    json_object_set_new(sol, "max_load_balance_error", gd_json_num(r->max_balance));
    json_object_set_new(sol, "max_penetration_m", gd_json_num(r->max_penetration));
    json_object_set_new(sol, "min_load_n", gd_json_num(r->min_load));
    json_object_set_new(sol, "gap_window_um", gd_json_num(r->window_max * 1e6));
    json_object_set_new(sol, "wall_s", gd_json_num(r->wall_s));
    char key[32];
    snprintf(key, sizeof key, "%016llx", (unsigned long long)r->cache_key);
    json_object_set_new(sol, "cache_key", json_string(key));
    return sol;
}

/* results.pinion_axial_shift_um of a floating pinion: mean, min and max over the positions. */
static json_t *axial_shift_json(const gd_ltca_result *r)
{
    double lo = INFINITY, hi = -INFINITY, m = 0;
    for (int k = 0; k < r->npos; k++) {
        lo = fmin(lo, r->axial_shift[k]);
        hi = fmax(hi, r->axial_shift[k]);
        m += r->axial_shift[k] / r->npos;
    }
    json_t *ax = json_object();
    json_object_set_new(ax, "mean", gd_json_num(m * 1e6));
    json_object_set_new(ax, "min", gd_json_num(lo * 1e6));
    json_object_set_new(ax, "max", gd_json_num(hi * 1e6));
    return ax;
}

/* results.loaded_contact_pattern: extent of the loaded points on the pinion flank. */
static json_t *loaded_pattern_json(const gd_ltca_result *r)
{
    json_t *pat = json_object();
    for (int h = 0; h < 2; h++) {
        if (h >= r->halves) {
            json_object_set_new(pat, "right", json_null());
            continue;
        }
        double rl = INFINITY, rh = -INFINITY, zl = INFINITY, zh = -INFINITY;
        for (int i = 0; i < r->first[r->npos]; i++) {
            const gd_ltca_point *P = &r->points[i];
            if (P->half != h || !(P->load > 0))
                continue;
            rl = fmin(rl, P->rho1);
            rh = fmax(rh, P->rho1);
            zl = fmin(zl, P->z1);
            zh = fmax(zh, P->z1);
        }
        json_t *o = json_object();
        json_object_set_new(o, "roll_min_mm", gd_json_num(rl * 1e3));
        json_object_set_new(o, "roll_max_mm", gd_json_num(rh * 1e3));
        json_object_set_new(o, "face_min_mm", gd_json_num(zl * 1e3));
        json_object_set_new(o, "face_max_mm", gd_json_num(zh * 1e3));
        json_object_set_new(pat, h ? "right" : "left", o);
    }
    return pat;
}

/* "results": LTE, stiffness, load sharing, pressure, edge loading, the axial shift, the
 * loaded contact pattern and the mesh-in impact. */
static json_t *ltca_results_json(const gd_ltca_result *r)
{
    json_t *res = json_object();
    json_object_set_new(res, "lte_pp_arcsec", gd_json_num(r->lte_pp_arcsec));
    json_object_set_new(res, "lte_mean_arcsec", gd_json_num(r->lte_mean_arcsec));
    json_object_set_new(res, "gte_pp_arcsec", gd_json_halves_num(r->gte_pp_arcsec, r->halves, 1));
    json_object_set_new(res, "mean_mesh_stiffness_n_per_m", gd_json_halves_num(r->stiffness_mean, r->halves, 1));
    json_object_set_new(res, "min_mesh_stiffness_n_per_m", gd_json_halves_num(r->stiffness_min, r->halves, 1));
    json_object_set_new(res, "max_mesh_stiffness_n_per_m", gd_json_halves_num(r->stiffness_max, r->halves, 1));
    json_object_set_new(res, "load_share", gd_json_halves_num(r->load_share, r->halves, 1));
    json_object_set_new(res, "load_share_min", gd_json_halves_num(r->load_share_min, r->halves, 1));
    json_object_set_new(res, "load_share_max", gd_json_halves_num(r->load_share_max, r->halves, 1));
    json_object_set_new(res, "load_share_difference", gd_json_num(r->halves > 1 ? r->load_share[0] - r->load_share[1] : NAN));
    json_object_set_new(res, "loaded_pairs_mean", gd_json_halves_num(r->pairs_mean, r->halves, 1));
    json_object_set_new(res, "max_contact_pressure_mpa", gd_json_halves_num(r->pressure_max, r->halves, 1e-6));
    json_t *el = json_object(), *ek = json_object(), *tc = json_object();
    json_object_set_new(el, "left", json_boolean(r->edge_positions[0] != 0));
    json_object_set_new(el, "right", r->halves > 1 ? json_boolean(r->edge_positions[1] != 0) : json_null());
    json_object_set_new(tc, "left", json_boolean(r->tip_positions[0] != 0));
    json_object_set_new(tc, "right", r->halves > 1 ? json_boolean(r->tip_positions[1] != 0) : json_null());
    json_object_set_new(ek, "left", gd_json_edge_names(r->edge_kinds[0]));
    json_object_set_new(ek, "right", r->halves > 1 ? gd_json_edge_names(r->edge_kinds[1]) : json_null());
    json_object_set_new(res, "edge_loading", el);
    json_object_set_new(res, "edge_kinds", ek);
    json_object_set_new(res, "edge_positions", gd_json_halves_int(r->edge_positions, r->halves));
    json_object_set_new(res, "edge_load_share_max", gd_json_halves_num(r->edge_load_max, r->halves, 1));
    json_object_set_new(res, "edge_line_load_ratio_max", gd_json_halves_num(r->edge_ratio_max, r->halves, 1));
    json_object_set_new(res, "tip_contact", tc);
    json_object_set_new(res, "tip_contact_positions", gd_json_halves_int(r->tip_positions, r->halves));
    if (r->floating)
        json_object_set_new(res, "pinion_axial_shift_um", axial_shift_json(r));
    json_object_set_new(res, "loaded_contact_pattern", loaded_pattern_json(r));
    json_t *mi = json_object();
    json_object_set_new(mi, "left", impact_json(&r->impact[0]));
    json_object_set_new(mi, "right", r->halves > 1 ? impact_json(&r->impact[1]) : json_null());
    json_object_set_new(res, "mesh_in", mi);
    return res;
}

gd_status gd_summary_write_ltca(gd_run_dir *d, const gd_case *c, const gd_ltca_result *r,
                                       gd_error *err)
{
    json_t *root = gd_json_root(c, "ltca", "gear", "arrangement");
    json_object_set_new(root, "derived", ltca_derived_json(c, r));
    json_object_set_new(root, "solver", ltca_solver_json(r));
    json_object_set_new(root, "results", ltca_results_json(r));
    return gd_json_write_summary(d, root, err);
}
