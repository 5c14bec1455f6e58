/* summary.json of a work-precision run: the resolved case, the model scales, the reference
 * and its check, every run of the grid and of the order study, the measured orders and the
 * cheapest setting for each accuracy target (docs/accuracy.md). */
#include "output_internal.h"
#include "geardyn/gd_workprec.h"
#include "json_util.h"
#include "../case/case_keys.h"

#include <jansson.h>
#include <math.h>
#include <string.h>

static json_t *run_json(const gd_wp_result *res, const gd_wp_run *r)
{
    const gd_wp_family *F = &res->families[r->family];
    char method[32];
    gd_case_key_choice("solver", "method", F->method, method, sizeof method);
    json_t *o = json_object();
    json_object_set_new(o, "label", json_string(r->label));
    json_object_set_new(o, "family", json_string(F->name));
    json_object_set_new(o, "method", json_string(method));
    json_object_set_new(o, "order", json_integer(F->order));
    json_object_set_new(o, "root_finding", json_boolean(F->root_finding));
    json_object_set_new(o, "fixed_step", json_boolean(r->fixed_step));
    json_object_set_new(o, "steps_per_period", r->fixed_step ? json_integer(r->steps_per_period) : json_null());
    json_object_set_new(o, "rtol", gd_json_num(r->rtol));
    json_object_set_new(o, "atol", gd_json_num(r->atol));
    json_object_set_new(o, "status", json_string(gd_wp_status_name(r->status)));
    if (r->message[0])
        json_object_set_new(o, "message", json_string(r->message));
    json_object_set_new(o, "cpu_s", gd_json_num(r->cpu_s));
    json_object_set_new(o, "periods", json_integer(r->periods));
    json_object_set_new(o, "us_per_period", gd_json_num(r->periods > 0 ? 1e6 * r->cpu_s / (double)r->periods : NAN));
    json_object_set_new(o, "rhs_evals", json_integer(r->rhs_evals));
    json_object_set_new(o, "steps", json_integer(r->steps));
    json_object_set_new(o, "step_attempts", json_integer(r->step_attempts));
    json_object_set_new(o, "root_evals", json_integer(r->root_evals));
    json_object_set_new(o, "jac_evals", json_integer(r->jac_evals));
    json_object_set_new(o, "events", json_integer(r->events));
    json_object_set_new(o, "flipflop_events", json_integer(r->flipflop_events));
    json_object_set_new(o, "reference_events", json_integer(r->ref_events));
    json_object_set_new(o, "rms_accel_mps2", gd_json_num(r->rms_accel_mps2));
    json_object_set_new(o, "mle_per_period", gd_json_num(r->mle_per_period));
    json_t *e = json_object();
    json_object_set_new(e, "poincare", gd_json_num(r->err_poincare));
    json_object_set_new(e, "short_horizon", gd_json_num(r->err_short));
    json_object_set_new(e, "rms_accel_relative", gd_json_num(r->err_rms));
    json_object_set_new(e, "event_times_periods", gd_json_num(r->err_events));
    json_object_set_new(e, "mle_per_period", gd_json_num(r->err_mle));
    json_object_set_new(o, "errors", e);
    return o;
}

gd_status gd_summary_write_workprec(gd_run_dir *d, const gd_case *c, const gd_model *m,
                                           const gd_wp_result *res, gd_error *err)
{
    json_t *root = gd_json_root(c, "work-precision", "scene", "model");

    json_t *mod = json_object();
    json_object_set_new(mod, "degrees_of_freedom", json_integer(m->ndof));
    json_object_set_new(mod, "clearances", json_integer(m->nclear));
    json_object_set_new(mod, "natural_frequency_hz", gd_json_num(m->omega_n / (2 * M_PI)));
    json_object_set_new(mod, "mesh_frequency_hz", gd_json_num(m->mesh_freq_hz));
    json_object_set_new(mod, "frequency_ratio", gd_json_num(m->Omega));
    json_object_set_new(mod, "mesh_period_s", gd_json_num(res->mesh_period_s));
    json_object_set_new(root, "model_scales", mod);

    const gd_wp_reference *R = &res->ref;
    json_t *ref = json_object();
    json_object_set_new(ref, "method", json_string(R->method));
    json_object_set_new(ref, "check_method", json_string(R->check_method));
    json_object_set_new(ref, "rtol", gd_json_num(R->rtol));
    json_object_set_new(ref, "window_periods", json_integer(res->window_periods));
    json_object_set_new(ref, "horizon_periods", json_integer(res->horizon_periods));
    json_object_set_new(ref, "motion", json_string(R->motion));
    json_object_set_new(ref, "scene_class", json_string(R->chaotic ? "chaotic" : "periodic"));
    json_object_set_new(ref, "rms_accel_mps2", gd_json_num(R->rms_accel_mps2));
    json_object_set_new(ref, "mle_per_period", gd_json_num(R->mle_per_period));
    json_object_set_new(ref, "events", json_integer(R->events));
    json_object_set_new(ref, "flipflop_events", json_integer(R->flipflop_events));
    json_object_set_new(ref, "cpu_s", gd_json_num(R->cpu_s));
    json_object_set_new(ref, "rhs_evals", json_integer(R->rhs_evals));
    json_object_set_new(ref, "steps", json_integer(R->steps));
    json_t *chk = json_object();
    json_object_set_new(chk, "poincare", gd_json_num(R->check_poincare));
    json_object_set_new(chk, "short_horizon", gd_json_num(R->check_short));
    json_object_set_new(chk, "rms_accel_relative", gd_json_num(R->check_rms));
    json_object_set_new(chk, "event_times_periods", gd_json_num(R->check_events));
    json_object_set_new(ref, "check_difference", chk);
    json_object_set_new(ref, "floor", gd_json_num(R->floor));
    json_object_set_new(ref, "converged", json_boolean(R->converged));
    json_object_set_new(ref, "converged_below", gd_json_num(c->wp_reference_max_error));
    json_object_set_new(root, "reference", ref);

    json_t *runs = json_array();
    for (int i = 0; i < res->nruns; i++)
        json_array_append_new(runs, run_json(res, &res->runs[i]));
    json_object_set_new(root, "runs", runs);

    json_t *ords = json_array();
    for (int i = 0; i < res->norders; i++) {
        const gd_wp_order *O = &res->orders[i];
        const gd_wp_family *F = &res->families[O->family];
        json_t *o = json_object();
        json_object_set_new(o, "family", json_string(F->name));
        json_object_set_new(o, "root_finding", json_boolean(F->root_finding));
        json_object_set_new(o, "nominal_order", json_integer(O->nominal));
        json_object_set_new(o, "measured_order", gd_json_num(O->order));
        json_object_set_new(o, "measured_order_over_range", gd_json_num(O->order_range));
        json_object_set_new(o, "range_steps", O->range_from >= 0 ? json_pack("[ii]", O->steps[O->range_from],
                                                                              O->steps[O->fit_to])
                                                                : json_null());
        json_t *st = json_array(), *er = json_array();
        for (int l = 0; l < O->nlevels; l++) {
            json_array_append_new(st, json_integer(O->steps[l]));
            json_array_append_new(er, gd_json_num(O->err[l]));
        }
        json_object_set_new(o, "steps_per_period", st);
        json_object_set_new(o, "poincare_error", er);
        json_object_set_new(o, "fitted_steps", O->fit_from >= 0 ? json_pack("[ii]", O->steps[O->fit_from],
                                                                               O->steps[O->fit_to])
                                                                 : json_null());
        json_array_append_new(ords, o);
    }
    json_object_set_new(root, "orders", ords);

    json_t *rec = json_array();
    static const double targets[] = {1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-10};
    for (size_t k = 0; k < 2 * (sizeof targets / sizeof targets[0]); k++) {
        int ev = k >= sizeof targets / sizeof targets[0];
        double target = targets[k % (sizeof targets / sizeof targets[0])];
        int i = gd_workprec_cheapest(res, target, ev);
        json_t *o = json_object();
        json_object_set_new(o, "target", gd_json_num(target));
        json_object_set_new(o, "event_times_too", json_boolean(ev));
        json_object_set_new(o, "cheapest", i >= 0 ? json_string(res->runs[i].label) : json_null());
        json_object_set_new(o, "cpu_s", gd_json_num(i >= 0 ? res->runs[i].cpu_s : NAN));
        json_object_set_new(o, "us_per_period", gd_json_num(i >= 0 ? 1e6 * res->runs[i].cpu_s / (double)res->runs[i].periods
                                                          : NAN));
        json_array_append_new(rec, o);
    }
    json_object_set_new(root, "cheapest_at_target", rec);
    json_object_set_new(root, "wall_s", gd_json_num(res->wall_s));

    return gd_json_write_summary(d, root, err);
}
