/* The tables and summary.json entries of what an optimisation over load and speed reports after it
 * (include/geardyn/gd_optpost.h, docs/optimisation.md section 12): response_over_speed.csv (the
 * curves the dynamic objective took its maxima from, each flank and torque, on the loop's model and
 * on bta), lte_over_torque.csv
 * (the Harris map), results.objective_on_bta, results.response_over_speed and
 * results.lte_over_torque. */
#include "output_internal.h"

#include "json_util.h"

#include <jansson.h>
#include <math.h>
#include <stdio.h>

static const char *const source_names[] = {"branch", "swept", "refined"};
static const char *const model_names[] = {"torsional", "torsional-lr", "bta"}; /* gd_model_kind */

gd_status gd_optpost_write_tables(gd_run_dir *d, const gd_case *c, const gd_optpost *p, gd_error *err)
{
    FILE *fp;
    gd_status st;
    if (p->dynamic) {
        if ((st = gd_run_dir_create(d, "response_over_speed.csv", &fp, err)) != GD_OK)
            return st;
        fprintf(fp, "model,flank,torque_nm,point,speed_rpm,%s,stable,source,period_n\n",
                c->opt_dynamic_response == GD_DYN_DTE_PP ? "dte_pp_um" : "rms_accel_mps2");
        for (int m = 0; m < (p->bta_separate ? 2 : 1); m++) /* the loop's model, then bta */
            for (int j = 0; j < GD_OPTPOST_NFLANKS; j++) {
                const gd_dyn_result *r = m == 0 ? &p->curve[j] : &p->on_bta[j];
                for (int k = 0; k < r->ntorques; k++) {
                    const gd_dyn_curve *cv = &r->curve[k];
                    for (int i = 0; i < cv->npts; i++)
                        fprintf(fp, "%s,%s,%.10g,%d,%.10g,%.17g,%d,%s,%d\n",
                                model_names[m == 0 ? c->opt_dynamic_model : GD_MODEL_BTA], gd_optpost_flank_name(j),
                                cv->torque_nm, i + 1, cv->pt[i].speed_rpm, cv->pt[i].value, cv->pt[i].stable,
                                source_names[cv->pt[i].source], cv->pt[i].period_n);
                }
            }
        if ((st = gd_run_dir_commit(d, fp, err)) != GD_OK)
            return st;
    }
    if ((st = gd_run_dir_create(d, "lte_over_torque.csv", &fp, err)) != GD_OK)
        return st;
    fprintf(fp, "torque_nm,objective_torque,lte_unmodified_arcsec,lte_case_arcsec,lte_optimum_arcsec\n");
    for (int i = 0; i < p->nharris; i++)
        fprintf(fp, "%.10g,%d,%.17g,%.17g,%.17g\n", p->harris_torque_nm[i], p->harris_objective[i],
                p->harris_lte_pp_arcsec[0][i], p->harris_lte_pp_arcsec[1][i], p->harris_lte_pp_arcsec[2][i]);
    return gd_run_dir_commit(d, fp, err);
}

/* A flank's objective on one model: value, and per torque the peak, its speed and the method. */
static json_t *flank_json(const gd_dyn_result *r)
{
    json_t *fo = json_object(), *each = json_array();
    json_object_set_new(fo, "value", gd_json_num(r->value));
    for (int k = 0; k < r->ntorques; k++) {
        const gd_dyn_curve *cv = &r->curve[k];
        json_t *t = json_object();
        json_object_set_new(t, "torque_nm", gd_json_num(cv->torque_nm));
        json_object_set_new(t, "peak", gd_json_num(cv->peak));
        json_object_set_new(t, "peak_speed_rpm", gd_json_num(cv->peak_speed_rpm));
        json_object_set_new(t, "method", json_string(gd_dyn_method_name(cv->method)));
        json_object_set_new(t, "branch_points", json_integer(cv->branch_points));
        json_object_set_new(t, "swept_points", json_integer(cv->swept_points));
        json_object_set_new(t, "refined_points", json_integer(cv->refined_points));
        json_array_append_new(each, t);
    }
    json_object_set_new(fo, "torques", each);
    json_object_set_new(fo, "cpu_s", gd_json_num(r->cpu_s));
    return fo;
}

/* The flanks' names from the lowest value to the highest. */
static json_t *ranking_json(const int *rank)
{
    json_t *a = json_array();
    for (int r = 0; r < GD_OPTPOST_NFLANKS; r++)
        for (int j = 0; j < GD_OPTPOST_NFLANKS; j++)
            if (rank[j] == r)
                json_array_append_new(a, json_string(gd_optpost_flank_name(j)));
    return a;
}

void gd_optpost_summary(json_t *res, const gd_case *c, const gd_optpost *p)
{
    if (p->dynamic) {
        json_t *b = json_object();
        json_object_set_new(b, "model_in_loop", json_string(model_names[c->opt_dynamic_model]));
        json_object_set_new(b, "model", json_string("bta"));
        for (int j = 0; j < GD_OPTPOST_NFLANKS; j++)
            json_object_set_new(b, gd_optpost_flank_name(j), flank_json(&p->on_bta[j]));
        json_object_set_new(b, "ranking", ranking_json(p->rank_bta));
        json_object_set_new(b, "ranking_in_loop", ranking_json(p->rank_loop));
        json_object_set_new(b, "same_ranking", json_boolean(p->same_ranking));
        json_object_set_new(b, "cpu_s", gd_json_num(p->bta_cpu_s));
        json_object_set_new(b, "cpu_s_in_loop", gd_json_num(p->loop_cpu_s));
        json_object_set_new(res, "objective_on_bta", b);
        json_t *r = json_object();
        json_object_set_new(r, "file", json_string("response_over_speed.csv"));
        json_object_set_new(r, "model", json_string(model_names[c->opt_dynamic_model]));
        for (int j = 0; j < GD_OPTPOST_NFLANKS; j++)
            json_object_set_new(r, gd_optpost_flank_name(j), flank_json(&p->curve[j]));
        json_object_set_new(res, "response_over_speed", r);
    }
    json_t *h = json_object(), *tq = json_array(), *obj = json_array();
    json_object_set_new(h, "file", json_string("lte_over_torque.csv"));
    for (int i = 0; i < p->nharris; i++) {
        json_array_append_new(tq, gd_json_num(p->harris_torque_nm[i]));
        json_array_append_new(obj, json_boolean(p->harris_objective[i]));
    }
    json_object_set_new(h, "torques_nm", tq);
    json_object_set_new(h, "objective_torque", obj);
    for (int j = 0; j < GD_OPTPOST_NFLANKS; j++) {
        json_t *f = json_object(), *v = json_array();
        int least = 0;
        for (int i = 0; i < p->nharris; i++) {
            json_array_append_new(v, gd_json_num(p->harris_lte_pp_arcsec[j][i]));
            if (p->harris_lte_pp_arcsec[j][i] < p->harris_lte_pp_arcsec[j][least])
                least = i;
        }
        json_object_set_new(f, "lte_pp_arcsec", v);
        json_object_set_new(f, "least_lte_pp_arcsec", gd_json_num(p->harris_lte_pp_arcsec[j][least]));
        json_object_set_new(f, "least_at_torque_nm", gd_json_num(p->harris_torque_nm[least]));
        json_object_set_new(h, gd_optpost_flank_name(j), f);
    }
    json_object_set_new(res, "lte_over_torque", h);
}
