/* summary.json of a tca run: the resolved case, the derived geometry, the solver settings and
 * statistics, and the results under stable keys (docs/tca.md, section 9). */
#include "output_internal.h"
#include "geardyn/gd_tca.h"
#include "geardyn/gd_geometry.h"
#include "geardyn/gd_scene.h"

#include "json_util.h"
#include "../case/case_keys.h"

#include <jansson.h>
#include <math.h>
#include <string.h>

/* "derived": the geometry of the pair (when it computes) and the resultant misalignment. */
static json_t *tca_derived_json(const gd_case *c)
{
    const double deg = 180.0 / M_PI;
    gd_geometry g;
    gd_error e2;
    json_t *der = json_object();
    const gd_pair pair = gd_pair_from_case(c);
    if (gd_geometry_compute(&pair, &g, &e2) == GD_OK) {
        json_t *geo = json_object();
        json_object_set_new(geo, "transverse_module_mm", gd_json_num(g.mt * 1e3));
        json_object_set_new(geo, "transverse_pressure_angle_deg", gd_json_num(g.alpha_t * deg));
        json_object_set_new(geo, "working_pressure_angle_deg", gd_json_num(g.alpha_wt * deg));
        json_object_set_new(geo, "base_helix_angle_deg", gd_json_num(g.beta_b * deg));
#define PG(key, a, b)                                                                                              \
    do {                                                                                                           \
        json_t *o = json_object();                                                                                 \
        json_object_set_new(o, "pinion", gd_json_num(a));                                                                  \
        json_object_set_new(o, "gear", gd_json_num(b));                                                                    \
        json_object_set_new(geo, key, o);                                                                          \
    } while (0)
        PG("reference_radius_mm", g.r[0] * 1e3, g.r[1] * 1e3);
        PG("base_radius_mm", g.rb[0] * 1e3, g.rb[1] * 1e3);
        PG("tip_radius_mm", g.ra[0] * 1e3, g.ra[1] * 1e3);
        PG("root_radius_mm", g.rf[0] * 1e3, g.rf[1] * 1e3);
        PG("form_radius_mm", g.r_form[0] * 1e3, g.r_form[1] * 1e3);
        PG("start_of_active_profile_radius_mm", g.r_sap[0] * 1e3, g.r_sap[1] * 1e3);
#undef PG
        json_object_set_new(geo, "centre_distance_mm", gd_json_num(g.a * 1e3));
        json_object_set_new(geo, "operating_centre_distance_mm", gd_json_num(g.a * 1e3 + c->centre_distance_error_mm));
        json_object_set_new(geo, "contact_ratio_transverse", gd_json_num(g.eps_alpha));
        json_object_set_new(geo, "contact_ratio_overlap", gd_json_num(g.eps_beta));
        json_object_set_new(der, "geometry", geo);
    }
    json_object_set_new(der, "axis_misalignment_resultant_arcmin",
                        gd_json_num(hypot(c->axis_in_plane_arcmin, c->axis_cross_plane_arcmin)));
    return der;
}

/* "solver": the formulation, the grid and the Newton statistics. */
static json_t *tca_solver_json(const gd_case *c, const gd_tca_result *r)
{
    json_t *sol = json_object();
    char form[32];
    gd_case_key_choice("solver", "tca_formulation", c->tca_formulation, form, sizeof form);
    json_object_set_new(sol, "formulation", json_string(form));
    json_object_set_new(sol, "newton", json_string("gsl_multiroot_fdfsolver_hybridsj, analytic Jacobian"));
    json_object_set_new(sol, "profile_points", json_integer(r->nprof));
    json_object_set_new(sol, "face_points", json_integer(r->nface));
    json_object_set_new(sol, "positions", json_integer(r->npos));
    json_object_set_new(sol, "positions_per_cycle", json_integer(c->tca_positions_per_cycle));
    json_object_set_new(sol, "cycles", json_integer(c->tca_cycles));
    json_object_set_new(sol, "refine", json_boolean(c->tca_refine));
    json_object_set_new(sol, "newton_iterations", json_integer(r->iterations));
    json_object_set_new(sol, "wall_s", gd_json_num(r->wall_s));
    return sol;
}

/* results.contact_pattern: share of the flank grid within the paint thickness, and its extent. */
static json_t *tca_pattern_json(const gd_case *c, const gd_tca_result *r)
{
    json_t *pat = json_object();
    json_object_set_new(pat, "paint_thickness_um", gd_json_num(c->paint_thickness_um));
    double frac[2] = {NAN, NAN}, rmin[2], rmax[2], zmin[2], zmax[2];
    for (int h = 0; h < r->halves; h++) {
        int nn = r->nprof * r->nface, in = 0;
        rmin[h] = zmin[h] = INFINITY;
        rmax[h] = zmax[h] = -INFINITY;
        for (int n = 0; n < nn; n++)
            if (r->sep[h][n] <= c->paint_thickness_um * 1e-6) {
                in++;
                double rr = r->rho[n % r->nprof] * 1e3, zz = r->z[n / r->nprof] * 1e3;
                rmin[h] = fmin(rmin[h], rr);
                rmax[h] = fmax(rmax[h], rr);
                zmin[h] = fmin(zmin[h], zz);
                zmax[h] = fmax(zmax[h], zz);
            }
        frac[h] = (double)in / nn;
    }
    json_object_set_new(pat, "grid_fraction", gd_json_halves_num(frac, r->halves, 1));
    json_t *ext = json_object();
    for (int h = 0; h < 2; h++) {
        if (h >= r->halves || !(frac[h] > 0)) {
            json_object_set_new(ext, h ? "right" : "left", json_null());
            continue;
        }
        json_t *o = json_object();
        json_object_set_new(o, "roll_min_mm", gd_json_num(rmin[h]));
        json_object_set_new(o, "roll_max_mm", gd_json_num(rmax[h]));
        json_object_set_new(o, "face_min_mm", gd_json_num(zmin[h]));
        json_object_set_new(o, "face_max_mm", gd_json_num(zmax[h]));
        json_object_set_new(ext, h ? "right" : "left", o);
    }
    json_object_set_new(pat, "extent", ext);
    return pat;
}

/* "results": transmission error, edge contact, contact ratios, pairs in contact, the
 * contact pattern and (both formulations) their comparison. */
static json_t *tca_results_json(const gd_case *c, const gd_tca_result *r)
{
    const double deg = 180.0 / M_PI;
    json_t *res = json_object();
    json_object_set_new(res, "gte_pp_arcsec", gd_json_halves_num(r->gte_pp_arcsec, r->halves, 1));
    json_t *ec = json_object();
    json_object_set_new(ec, "left", json_boolean(r->edge_kinds[0] != 0));
    json_object_set_new(ec, "right", r->halves > 1 ? json_boolean(r->edge_kinds[1] != 0) : json_null());
    json_object_set_new(res, "edge_contact", ec);
    json_t *ek = json_object();
    json_object_set_new(ek, "left", gd_json_edge_names(r->edge_kinds[0]));
    json_object_set_new(ek, "right", r->halves > 1 ? gd_json_edge_names(r->edge_kinds[1]) : json_null());
    json_object_set_new(res, "edge_kinds", ek);
    json_object_set_new(res, "edge_positions", gd_json_halves_int(r->edge_positions, r->halves));
    json_object_set_new(res, "contact_ratio_transverse", gd_json_num(r->contact_ratio_transverse));
    json_object_set_new(res, "contact_ratio_overlap", gd_json_num(r->contact_ratio_overlap));
    json_object_set_new(res, "operating_pressure_angle_deg", gd_json_num(r->alpha_op_mean * deg));
    json_object_set_new(res, "te_mean_arcsec", gd_json_halves_num(r->te_mean_arcsec, r->halves, 1));
    json_object_set_new(res, "pairs_in_contact_mean", gd_json_halves_num(r->pairs_mean, r->halves, 1));
    json_object_set_new(res, "pairs_in_contact_min", gd_json_halves_int(r->pairs_min, r->halves));
    json_object_set_new(res, "pairs_in_contact_max", gd_json_halves_int(r->pairs_max, r->halves));
    json_object_set_new(res, "contact_pattern", tca_pattern_json(c, r));
    if (c->tca_formulation == GD_TCA_BOTH) {
        json_t *cmp = json_object();
        json_object_set_new(cmp, "positions_compared", json_integer(r->compared));
        json_object_set_new(cmp, "positions", json_integer((json_int_t)r->npos * r->halves));
        json_object_set_new(cmp, "max_difference_arcsec", gd_json_num(r->max_diff_arcsec));
        json_object_set_new(res, "formulation_comparison", cmp);
    }
    return res;
}

gd_status gd_summary_write_tca(gd_run_dir *d, const gd_case *c, const gd_tca_result *r,
                                      gd_error *err)
{
    json_t *root = gd_json_root(c, "tca", "gear", "arrangement");
    json_object_set_new(root, "derived", tca_derived_json(c));
    json_object_set_new(root, "solver", tca_solver_json(c, r));
    json_object_set_new(root, "results", tca_results_json(c, r));
    return gd_json_write_summary(d, root, err);
}
