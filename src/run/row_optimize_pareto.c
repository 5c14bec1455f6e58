/* Two objectives at once in the optimize row (docs/optimisation.md section 13): the Pareto front of
 * the LTE (gear-lte or gear-lte-range) and the dynamic response (gear-dynamic) of the flank, or of
 * zdt1 / zdt2, by the case's two-objective optimiser (moalo, weighted-sum, eps-constraint, random);
 * `runs` runs from their seeds, the one of the largest hypervolume kept; for the gear the two
 * objectives of the unmodified flank and of the case's own, and the hypervolume's reference point
 * 1.1 times the unmodified flank's unless optimize.hv_reference gives it. */
#include "row_optimize_pareto.h"
#include "rows.h"
#include "geardyn/gd_dynobj.h"
#include "geardyn/gd_scene.h"
#include "../optimisation/opt_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void dynobj_free(void *user) { gd_dynobj_free(user); }

void row_pareto_free(gd_opt_pareto_report *p)
{
    if (!p)
        return;
    if (p->res)
        for (int r = 0; r < p->runs; r++)
            gd_opt_result_free(&p->res[r]);
    free(p->res);
    free(p);
}

/* The column (with its unit) and the picture's name of a gear objective. */
static void gear_names(const gd_case *c, int objective, char *column, size_t nc, char *label, size_t nl)
{
    if (objective == GD_OBJ_GEAR_LTE) {
        snprintf(column, nc, "lte_pp_arcsec");
        snprintf(label, nl, "peak-to-peak LTE at %g N m (arcsec)", c->torque_nm);
    } else if (objective == GD_OBJ_GEAR_LTE_RANGE) {
        int mx = c->opt_lte_range_combine == GD_OPT_COMBINE_MAX;
        snprintf(column, nc, "lte_pp_%s_arcsec", mx ? "max" : "mean");
        snprintf(label, nl, "%s peak-to-peak LTE over the torques (arcsec)", mx ? "largest" : "duty-weighted mean");
    } else {
        int mx = c->opt_dynamic_combine == GD_OPT_COMBINE_MAX, dte = c->opt_dynamic_response == GD_DYN_DTE_PP;
        snprintf(column, nc, "%s_%s_%s", dte ? "dte_pp" : "rms_accel", mx ? "max" : "mean", dte ? "um" : "mps2");
        snprintf(label, nl, "%s %s over the speeds%s (%s)", mx ? "largest" : "duty-weighted mean of the largest",
                 dte ? "peak-to-peak dynamic transmission error" : "RMS mesh acceleration",
                 mx ? " and torques" : "", dte ? "µm" : "m/s²");
    }
}

/* The gear problem with its two objectives: the LTE at the case's torque or over its torques, and the
 * dynamic response (its state in o->user). */
static gd_status gear_setup(const gd_case *c, gd_stop_hook stop, gd_optimize_outcome *o, gd_opt_problem *p,
                            gd_error *err)
{
    const gd_pair pair = gd_pair_from_case(c);
    gd_ltca_settings set = gd_ltca_settings_from_case(c);
    set.stop = stop;
    double lower[GD_OPT_GEAR_NVARS], upper[GD_OPT_GEAR_NVARS];
    gd_opt_gear_bounds(c, &o->vars, lower, upper);
    gd_status st = gd_opt_gear_create(&pair, &set, &o->vars, lower, upper, &o->gear_problem, err);
    if (st != GD_OK)
        return st;
    gd_opt_lte_range *r = &o->lte_range;
    r->set = set;
    int range = o->objective == GD_OBJ_GEAR_LTE_RANGE;
    r->n = range ? c->n_opt_torques : 1;
    for (int k = 0; k < r->n; k++) {
        r->torques_nm[k] = range ? c->opt_torques_nm[k] : c->torque_nm;
        r->weights[k] = range && c->n_opt_torque_weights ? c->opt_torque_weights[k] : 1.0;
    }
    r->combine = c->opt_lte_range_combine;
    gd_opt_gear_objective obj[2];
    gd_opt_lte_range_objective(r, &obj[0]);
    gd_dynobj_settings ds;
    gd_dynobj_settings_from_case(c, &ds);
    gd_dynobj *d;
    if ((st = gd_dynobj_create(c, &ds, &stop, &d, err)) != GD_OK)
        return st;
    o->user = d;
    o->user_free = dynobj_free;
    gd_dynobj_objective(d, &obj[1]);
    if ((st = gd_opt_gear_set_objectives(o->gear_problem, 2, obj, NULL, err)) != GD_OK)
        return st;
    gd_opt_gear_problem(o->gear_problem, p);
    o->pair = pair;
    gd_opt_gear_from_pair(&o->vars, &pair, o->case_value);
    o->reference = o->case_value;
    for (int i = 0; i < o->dim; i++)
        snprintf(o->names[i], sizeof o->names[i], "%s", gd_opt_gear_variable(o->vars.var[i], NULL, NULL));
    /* the unmodified flank and the case's own */
    for (int j = 0; j < 2; j++) {
        gd_pair t = pair;
        if (j == 0) {
            t.root_relief_amount_um = t.root_relief_length_mm = t.tip_relief_amount_um = t.tip_relief_length_mm = 0;
            t.lead_relief_inner_um = t.lead_relief_outer_um = t.lead_unmodified_length_mm = 0;
            t.lead_unmodified_centre_mm = t.helix_slope_um = 0;
        }
        double aux[GD_OPT_MAX_AUX];
        st = gd_opt_gear_value_of_pair(o->gear_problem, &t, o->pareto->flank_f[j], aux, err);
        if (st != GD_OK)
            return gd_error_prefix(err, "the %s flank", j == 0 ? "unmodified" : "case's");
    }
    return GD_OK;
}

gd_status row_pareto_run(const gd_case *c, const gd_run_env *env, gd_optimize_outcome *o, gd_error *err)
{
    gd_opt_pareto_report *P = calloc(1, sizeof *P);
    if (!P)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    o->pareto = P;
    const gd_stop_hook stop = gd_row_stop(env);
    int objs[GD_OBJ_NOBJECTIVES];
    gd_opt_case_objectives(c, objs, GD_OBJ_NOBJECTIVES);
    o->objective = P->objective = objs[0];
    o->gear = P->gear = gd_opt_objective_is_gear(o->objective);
    P->objective2 = o->gear ? gd_opt_objective_parse(c->opt_objective2) : o->objective;
    if (o->gear)
        gd_opt_case_gear_vars(c, &o->vars);
    o->dim = P->dim = o->gear ? o->vars.n : (int)c->opt_dimensions[0];
    o->runs = P->runs = c->opt_runs;
    P->true_front_hv = NAN;
    gd_opt_problem p;
    gd_status st;
    if (o->gear) {
        st = gear_setup(c, stop, o, &p, err);
        for (int k = 0; k < 2; k++)
            gear_names(c, k ? P->objective2 : P->objective, P->column[k], sizeof P->column[k], P->label[k],
                       sizeof P->label[k]);
    } else {
        st = gd_opt_testfn_init(&o->tf, o->objective, o->dim, 0.0, gd_opt_instance_seed(c, 0), err);
        if (st == GD_OK) {
            gd_opt_testfn_problem(&o->tf, &p);
            for (int i = 0; i < o->dim; i++)
                snprintf(o->names[i], sizeof o->names[i], "x%d", i + 1);
        }
        for (int k = 0; k < 2; k++) {
            snprintf(P->column[k], sizeof P->column[k], "f%d", k + 1);
            snprintf(P->label[k], sizeof P->label[k], "objective f_%d (-)", k + 1);
        }
    }
    if (st != GD_OK)
        return st;
    for (int i = 0; i < o->dim; i++) {
        o->lower[i] = p.lower[i];
        o->upper[i] = p.upper[i];
        o->name_ptr[i] = o->names[i];
    }
    P->hv_ref_derived = c->n_opt_hv_reference != 2;
    for (int k = 0; k < 2; k++)
        P->hv_ref[k] = !P->hv_ref_derived ? c->opt_hv_reference[k] : o->gear ? 1.1 * P->flank_f[0][k] : 1.1;
    if (!o->gear)
        P->true_front_hv = gd_opt_zdt_front_hv(o->objective, P->hv_ref);
    if (!(P->hv_ref[0] > 0 && P->hv_ref[1] > 0))
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.hv_reference: the unmodified flank's objectives %g, %g "
                            "give no reference point (valid: give optimize.hv_reference, two numbers > 0)",
                            c->path[0] ? c->path : "case", P->flank_f[0][0], P->flank_f[0][1]);
    gd_opt_settings *s = &o->settings;
    gd_opt_settings_default(s);
    s->algorithm = c->opt_algorithm;
    s->budget = gd_opt_case_budget(c);
    s->population = c->opt_population;
    s->threads = env ? env->threads : 0;
    s->keep_history = 1;
    s->stop = stop;
    s->archive = c->opt_archive;
    s->scalar_algorithm = c->opt_scalar_algorithm;
    s->scalar_grid = c->opt_scalar_grid;
    s->hv_ref[0] = P->hv_ref[0];
    s->hv_ref[1] = P->hv_ref[1];
    o->threads = opt_threads(c->opt_algorithm == GD_OPT_MOALO || c->opt_algorithm == GD_OPT_RANDOM ? s->threads : 1);
    if (!(P->res = calloc((size_t)P->runs, sizeof *P->res)))
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    for (int r = 0; r < P->runs; r++) {
        s->seed = gd_opt_run_seed(c, r);
        if ((st = gd_opt_run(&p, s, &P->res[r], err)) != GD_OK)
            return st;
        o->wall_s += P->res[r].wall_s;
        if (P->res[r].hv > P->res[P->best].hv)
            P->best = r;
        if (env && env->optimize_run)
            env->optimize_run(env->user, r, P->runs, s->seed, &P->res[r]);
    }
    return GD_OK;
}
