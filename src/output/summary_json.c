/* summary.json: the resolved case, derived values, solver statistics and results (jansson). */
#include "output_internal.h"
#include "geardyn/gd_geometry.h"
#include "geardyn/gd_scene.h"

#include "json_util.h"
#include "../case/case_keys.h"

#include <jansson.h>
#include <math.h>
#include <string.h>

static json_t *lr(double l, double r)
{
    json_t *o = json_object();
    json_object_set_new(o, "left", gd_json_num(l));
    json_object_set_new(o, "right", gd_json_num(r));
    return o;
}

/* a value of each body: pinion and gear */
static json_t *pg(double p, double g)
{
    json_t *o = json_object();
    json_object_set_new(o, "pinion", gd_json_num(p));
    json_object_set_new(o, "gear", gd_json_num(g));
    return o;
}

/* derived.model.impact: the mesh-in impact pulses (excitation.impact = on, from LTCA), each as the
 * model's mesh receives it: one per mesh, and both halves' on the one mesh of a herringbone's torsional
 * model. */
static json_t *impact_json(const gd_model *m)
{
    json_t *imp = json_object();
    static const char *const half_name[] = {"left", "right"};
    int herringbone = m->nmesh == 2 || m->force_share != 1.0;
    for (int j = 0; j < m->nmesh && j < 2; j++) {
        const gd_mesh_excitation *x = &m->mesh[j];
        for (int k = 0; k < x->nimp; k++) {
            json_t *o = json_object();
            double fn = x->imp_force[k] * m->k_ref * m->bc_m, dur = x->imp_width[k] / (m->omega_n * m->Omega);
            json_object_set_new(o, "force_n", gd_json_num(fn));
            json_object_set_new(o, "duration_s", gd_json_num(dur));
            json_object_set_new(o, "impulse_n_s", gd_json_num(fn * dur));
            json_object_set_new(o, "phase_of_mesh_cycle", gd_json_num(x->imp_phase[k] / (2.0 * M_PI)));
            json_object_set_new(o, "force_over_static", gd_json_num(fn / m->static_load_n));
            json_object_set_new(o, "acts", json_string(x->imp_contact_only ? "in drive-side contact" : "always"));
            json_object_set_new(imp, herringbone ? half_name[x->imp_half[k]] : "mesh", o);
        }
    }
    return imp;
}

/* "derived": the geometry of the pair (when it computes) and the model's scales. */
static json_t *response_derived_json(const gd_case *c, const gd_model *m)
{
    gd_geometry g;
    gd_error e2;
    json_t *der = json_object();
    const gd_pair pair = gd_pair_from_case(c);
    double sin_bb = NAN;
    if (gd_geometry_compute(&pair, &g, &e2) == GD_OK) {
        sin_bb = sin(g.beta_b);
        json_t *geo = json_object();
        json_object_set_new(geo, "transverse_module_mm", gd_json_num(g.mt * 1e3));
        json_object_set_new(geo, "transverse_pressure_angle_deg", gd_json_num(g.alpha_t * 180 / M_PI));
        json_object_set_new(geo, "working_pressure_angle_deg", gd_json_num(g.alpha_wt * 180 / M_PI));
        json_object_set_new(geo, "base_helix_angle_deg", gd_json_num(g.beta_b * 180 / M_PI));
        json_object_set_new(geo, "reference_radius_mm", pg(g.r[0] * 1e3, g.r[1] * 1e3));
        json_object_set_new(geo, "base_radius_mm", pg(g.rb[0] * 1e3, g.rb[1] * 1e3));
        json_object_set_new(geo, "tip_radius_mm", pg(g.ra[0] * 1e3, g.ra[1] * 1e3));
        json_object_set_new(geo, "root_radius_mm", pg(g.rf[0] * 1e3, g.rf[1] * 1e3));
        json_object_set_new(geo, "centre_distance_mm", gd_json_num(g.a * 1e3));
        json_object_set_new(geo, "contact_ratio_transverse", gd_json_num(g.eps_alpha));
        json_object_set_new(geo, "contact_ratio_overlap", gd_json_num(g.eps_beta));
        json_object_set_new(der, "geometry", geo);
    }
    json_t *mod = json_object();
    json_object_set_new(mod, "degrees_of_freedom", json_integer(m->ndof));
    json_object_set_new(mod, "natural_frequency_hz", gd_json_num(m->omega_n / (2 * M_PI)));
    json_object_set_new(mod, "mesh_frequency_hz", gd_json_num(m->mesh_freq_hz));
    json_object_set_new(mod, "frequency_ratio", gd_json_num(m->Omega));
    json_object_set_new(mod, "normal_equivalent_mass_kg", gd_json_num(m->m_ref));
    json_object_set_new(mod, "mesh_stiffness_n_per_m", gd_json_num(m->k_ref));
    json_object_set_new(mod, "static_mesh_force_n", gd_json_num(m->static_load_n));
    /* its axial component, taken by the axial supports (a herringbone's halves: opposite senses) */
    json_object_set_new(mod, "static_axial_force_n", gd_json_num(m->static_load_n * sin_bb));
    json_object_set_new(mod, "static_deflection_um", gd_json_num(m->static_load_n / m->k_ref * 1e6));
    if (c->impact)
        json_object_set_new(mod, "impact", impact_json(m));
    /* where each excitation comes from (geardyn check says the same) */
    {
        static const char *const kind[] = {"constant", "harmonic", "rectangular", "ltca"};
        json_t *ex = json_object();
        json_object_set_new(ex, "mesh_stiffness", json_string(c->stiffness >= 0 && c->stiffness < 4 ?
                                                              kind[c->stiffness] : "?"));
        json_object_set_new(ex, "transmission_error", json_string(!c->error_excitation ? "off" :
                                                                  c->ste_source == GD_STE_LTCA ? "ltca" : "sinusoid"));
        json_object_set_new(ex, "mesh_in_impact", json_string(c->impact ? "ltca" : "off"));
        json_object_set_new(mod, "excitations", ex);
    }
    json_object_set_new(der, "model", mod);
    return der;
}

/* A fixed step (rk4, or erk with a fixed step) against its method's stability region on the model
 * linearised at its static operating point (gd_sim_step_stability, as geardyn check and the note of
 * geardyn run judge it): NULL for an adaptive or implicit solver, or where it cannot be judged. */
static json_t *fixed_step_json(const gd_case *c, const gd_model *m)
{
    gd_solver_opts o;
    gd_solver_opts_from_case(c, &o);
    if (m->custom || !(o.method == GD_METHOD_RK4 || (o.method == GD_METHOD_ERK && o.fixed_step)))
        return NULL;
    double y[GD_MAX_STATE];
    gd_modes md;
    gd_step_stability sb;
    gd_error e = {0};
    if (gd_model_static_state(m, y, &md, &e) != GD_OK || gd_sim_step_stability(m, &o, y, &md, &sb, &e) != GD_OK)
        return NULL;
    json_t *f = json_object();
    json_object_set_new(f, "steps_per_period", json_integer(c->steps_per_period));
    json_object_set_new(f, "stable", json_boolean(!sb.unstable));
    json_object_set_new(f, "amplification", gd_json_num(sb.amplification));
    json_object_set_new(f, "mode_hz", gd_json_num(sb.freq_hz));
    json_object_set_new(f, "stable_from_steps_per_period", json_integer(sb.min_steps_per_period));
    return f;
}

/* "solver": the method and the statistics of the run. */
static json_t *response_solver_json(const gd_case *c, const gd_model *m, const gd_response_result *r)
{
    json_t *sol = json_object();
    char choice[32]; /* an enum value's name (json_string copies it) */
    gd_case_key_choice("solver", "method", c->method, choice, sizeof choice);
    json_object_set_new(sol, "method", json_string(choice));
    json_object_set_new(sol, "order", json_integer(c->method == GD_METHOD_RK4 ? 4 : c->order));
    json_object_set_new(sol, "table", json_string(c->table));
    json_object_set_new(sol, "rtol", gd_json_num(c->rtol));
    json_object_set_new(sol, "atol", gd_json_num(c->atol));
    json_object_set_new(sol, "root_finding", json_boolean(c->root_finding));
    json_t *fixed = fixed_step_json(c, m);
    json_object_set_new(sol, "fixed_step", fixed ? fixed : json_null());
    json_object_set_new(sol, "steps", json_integer(r->stats.steps));
    json_object_set_new(sol, "step_attempts", json_integer(r->stats.step_attempts));
    json_object_set_new(sol, "rhs_evals", json_integer(r->stats.rhs_evals));
    json_object_set_new(sol, "analysis_rhs_evals", json_integer(r->stats.extra_rhs_evals));
    json_object_set_new(sol, "root_evals", json_integer(r->stats.root_evals));
    json_object_set_new(sol, "jac_evals", json_integer(r->stats.jac_evals));
    json_object_set_new(sol, "resets", json_integer(r->stats.resets));
    json_object_set_new(sol, "grazing_rewinds", json_integer(r->stats.grazing_rewinds));
    json_object_set_new(sol, "events", json_integer(r->stats.events));
    json_t *bk = json_object();
    for (int k = 0; k < GD_EV_NKINDS; k++)
        json_object_set_new(bk, gd_event_kind_name(k), json_integer(r->stats.events_by_kind[k]));
    json_object_set_new(sol, "events_by_kind", bk);
    json_t *bc = json_object();
    for (int k = 0; k < m->nclear; k++)
        json_object_set_new(bc, m->clear[k].name, json_integer(r->stats.events_by_clearance[k]));
    json_object_set_new(sol, "events_by_clearance", bc);
    json_object_set_new(sol, "wall_s", gd_json_num(r->wall_s));
    long periods = r->transient_periods + c->record_periods;
    json_object_set_new(sol, "rhs_evals_per_period", gd_json_num((double)r->stats.rhs_evals / (double)periods));
    return sol;
}

/* "results": accelerations, DTE, mesh deflection, motion, impacts and exponents. */
static json_t *response_results_json(const gd_case *c, const gd_model *m, const gd_response_result *r)
{
    json_t *res = json_object();
    json_t *acc = lr(r->rms_accel_mps2[0], r->rms_accel_mps2[1]);
    json_object_set_new(acc, "combined", gd_json_num(r->rms_accel_mps2[2]));
    json_object_set_new(res, "rms_accel_mps2", acc);
    json_object_set_new(res, "dte_mean_um", lr(r->dte_mean_um[0], r->dte_mean_um[1]));
    json_object_set_new(res, "dte_rms_um", lr(r->dte_rms_um[0], r->dte_rms_um[1]));
    json_object_set_new(res, "dte_pp_um", lr(r->dte_pp_um[0], r->dte_pp_um[1]));
    json_object_set_new(res, "mesh_deflection_min_um", lr(r->lambda_min_um[0], r->lambda_min_um[1]));
    json_object_set_new(res, "mesh_deflection_max_um", lr(r->lambda_max_um[0], r->lambda_max_um[1]));
    json_object_set_new(res, "mesh_force_max_n", lr(r->force_max_n[0], r->force_max_n[1]));
    json_object_set_new(res, "dynamic_load_factor", lr(r->dynamic_load_factor[0], r->dynamic_load_factor[1]));
    json_object_set_new(res, "motion", json_string(r->motion));
    json_object_set_new(res, "period_n", json_integer(r->period_n));
    json_object_set_new(res, "poincare_distinct", json_integer(r->poincare_distinct));
    json_object_set_new(res, "poincare_points", json_integer(r->poincare_count));
    json_object_set_new(res, "transient_periods", json_integer(r->transient_periods));
    json_object_set_new(res, "impact_regime", json_string(gd_impact_regime_name(r->impact_regime[2])));
    json_t *ir = json_object();
    json_object_set_new(ir, "left", json_string(gd_impact_regime_name(r->impact_regime[0])));
    json_object_set_new(ir, "right", json_string(gd_impact_regime_name(r->impact_regime[1])));
    json_object_set_new(res, "impact_regime_by_mesh", ir);
    if (m->nmesh < 2) { /* one mesh (a single pair, the torsional model): no right one */
        const char *key;
        json_t *v;
        json_object_foreach(res, key, v) {
            if (json_is_object(v) && json_object_get(v, "right"))
                json_object_set_new(v, "right", json_null());
        }
    }
    json_object_set_new(res, "recorded_events", json_integer(r->record_events));
    char choice[32];
    gd_case_key_choice("run", "lyapunov_method", c->lyapunov_method, choice, sizeof choice);
    json_object_set_new(res, "lyapunov_method", r->n_lyapunov ? json_string(choice) : json_null());
    json_object_set_new(res, "mle_per_period", gd_json_num(r->n_lyapunov ? r->mle_per_period : NAN));
    json_object_set_new(res, "mle_per_s", gd_json_num(r->n_lyapunov ? r->mle_per_s : NAN));
    json_t *spec = json_array();
    for (int i = 0; i < r->n_lyapunov; i++)
        json_array_append_new(spec, gd_json_num(r->lyapunov[i] * m->period));
    json_object_set_new(res, "lyapunov_spectrum_per_period", spec);
    return res;
}

gd_status gd_summary_write_response(gd_run_dir *d, const gd_case *c, const gd_model *m, const gd_modal *modes,
                                    const gd_response_result *r, gd_error *err)
{
    json_t *root = gd_json_root(c, "response", "scene", "model");
    json_object_set_new(root, "derived", response_derived_json(c, m));
    json_object_set_new(json_object_get(root, "derived"), "modal", gd_modal_json(c, modes));
    json_object_set_new(root, "solver", response_solver_json(c, m, r));
    json_object_set_new(root, "results", response_results_json(c, m, r));
    return gd_json_write_summary(d, root, err);
}

/* "derived" of a dynamic run as above, for geardyn check's JSON (check_json.c). */
json_t *gd_json_response_derived(const gd_case *c, const gd_model *m) { return response_derived_json(c, m); }
