/* summary.json of the optimize and compare-optimizers analyses (docs/optimisation.md section 8):
 * the resolved case, the settings, the results under stable keys; the optimum of the gear problem
 * beside the case's own modification (and the paper's Table 2 for the paper's pair). */
#include "output_internal.h"

#include "json_util.h"
#include "geardyn/gd_dynobj.h"

#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

gd_status gd_summary_write_optimize(gd_run_dir *d, const gd_case *c, const gd_opt_optimize_summary *s,
                                           gd_error *err)
{
    json_t *root = gd_json_root(c, "optimize", NULL, NULL);
    int gear = gd_opt_objective_is_gear(s->objective);
    json_t *set = json_object();
    json_object_set_new(set, "algorithm", json_string(gd_opt_algorithm_name(s->algorithm)));
    json_object_set_new(set, "objective", json_string(gd_opt_objective_name(s->objective)));
    json_object_set_new(set, "dimension", json_integer(s->dim));
    json_object_set_new(set, "budget_evals", json_integer(s->budget));
    json_object_set_new(set, "runs", json_integer(s->runs));
    json_object_set_new(set, "seed", json_integer(c->opt_seed));
    json_object_set_new(set, "population", json_integer(c->opt_population));
    json_object_set_new(set, "alo_iterations", s->algorithm == GD_OPT_ALO ?
                        json_integer(gd_alo_iterations(s->budget, c->opt_population)) : json_null());
    json_object_set_new(set, "threads", json_integer(s->threads));
    json_object_set_new(set, "constraints", json_string(gear ?
        "bounds of Eq. 13 on the normalised box [-1, 1]^d; y2 + y4 <= active profile (and |y8| + y7/2 <= half the "
        "face) by repair toward a feasible anchor (docs/optimisation.md section 3)" : "bounds (normalised box "
        "[-1, 1]^d)"));
    if (gear) {
        json_t *vars = json_array();
        for (int i = 0; i < s->dim; i++) {
            const char *sym;
            gd_opt_gear_variable(s->vars->var[i], NULL, &sym);
            json_array_append_new(vars, json_string(sym));
        }
        json_object_set_new(set, "variables", vars);
    }
    if (gear)
        json_object_set_new(set, "active_profile_mm", gd_json_num(s->active_profile_mm));
    json_object_set_new(root, "settings", set);

    const gd_opt_result *b = s->best;
    json_t *res = json_object();
    json_object_set_new(res, "objective_value", gd_json_num(b->f));
    json_object_set_new(res, "objective_unit", json_string(s->objective_unit ? s->objective_unit : gear ? "arcsec" : ""));
    json_t *x = json_object(), *bounds = json_object();
    for (int i = 0; i < s->dim; i++) {
        json_object_set_new(x, s->names[i], gd_json_num(b->y[i]));
        json_t *bb = json_array();
        json_array_append_new(bb, gd_json_num(s->lower[i]));
        json_array_append_new(bb, gd_json_num(s->upper[i]));
        json_object_set_new(bounds, s->names[i], bb);
    }
    json_object_set_new(res, "optimum", x);
    json_object_set_new(res, "bounds", bounds);
    json_object_set_new(res, "evaluations", json_integer(b->evaluations));
    json_object_set_new(res, "found_at_evaluation", json_integer(b->best_at));
    json_object_set_new(res, "best_run", json_integer(s->best_run + 1));
    json_t *rf = json_array();
    for (int k = 0; k < s->runs; k++)
        json_array_append_new(rf, gd_json_num(s->run_f[k]));
    json_object_set_new(res, "run_values", rf);
    if (s->algorithm != GD_OPT_ALO && s->algorithm != GD_OPT_RANDOM) {
        json_object_set_new(res, "nlopt_starts", json_integer(b->starts));
        json_object_set_new(res, "nlopt_last_code", json_integer(b->nlopt_code));
    }
    if (s->true_optimum) {
        json_t *o = json_array();
        double d2 = 0;
        for (int i = 0; i < s->dim; i++) {
            json_array_append_new(o, gd_json_num(s->true_optimum[i]));
            d2 += (b->y[i] - s->true_optimum[i]) * (b->y[i] - s->true_optimum[i]);
        }
        json_object_set_new(res, "true_minimiser", o);
        json_object_set_new(res, "distance_to_minimiser", gd_json_num(sqrt(d2)));
    }
    json_object_set_new(res, "converged", json_boolean(s->converged));
    json_object_set_new(res, "improvement_last_tenth_percent", gd_json_num(100.0 * s->last_tenth_improvement));
    if (gear) {
        json_t *lte = json_object();
        json_object_set_new(lte, "unmodified", gd_json_num(s->lte_unmodified));
        json_object_set_new(lte, "case", gd_json_num(s->lte_case));
        json_object_set_new(lte, "optimum", gd_json_num(s->lte_optimum));
        if (s->table2)
            json_object_set_new(lte, "paper_table2", gd_json_num(s->lte_table2));
        json_object_set_new(res, "lte_pp_arcsec", lte);
        json_object_set_new(res, "change_vs_unmodified_percent",
                            gd_json_num(100.0 * (s->lte_optimum - s->lte_unmodified) / s->lte_unmodified));
        json_object_set_new(res, "change_vs_case_percent",
                            gd_json_num(100.0 * (s->lte_optimum - s->lte_case) / s->lte_case));
        /* each variable at the optimum beside the case's own value (and the paper's Table 2 for its pair) */
        json_t *tab = json_object(), *none = json_array();
        for (int i = 0; i < s->dim; i++) {
            const char *unit, *sym;
            const char *key = gd_opt_gear_variable(s->vars->var[i], &unit, &sym);
            json_t *row = json_object();
            json_object_set_new(row, "variable", json_string(key));
            json_object_set_new(row, "unit", json_string(unit));
            json_object_set_new(row, "optimum", gd_json_num(b->y[i]));
            json_object_set_new(row, "case", gd_json_num(s->case_value[i]));
            if (s->table2)
                json_object_set_new(row, "paper_table2", gd_json_num(s->table2[i]));
            json_object_set_new(row, "effect", json_string(s->no_effect && s->no_effect[i] ? s->no_effect[i] : "yes"));
            json_object_set_new(tab, sym, row);
            if (s->no_effect && s->no_effect[i])
                json_array_append_new(none, json_string(sym));
        }
        json_object_set_new(res, "optimum_vs_case", tab);
        json_object_set_new(res, "without_effect", none);
        if (s->table2) { /* the paper's pair: its Table 2 and Fig. 12 beside ours */
            json_t *paper = json_object();
            json_object_set_new(paper, "lte_pp_unmodified_arcsec", gd_json_num(4.194));
            json_object_set_new(paper, "lte_pp_table2_arcsec", gd_json_num(1.157));
            json_object_set_new(paper, "change_percent", gd_json_num(-72.41));
            json_object_set_new(res, "paper", paper);
        }
    }
    if (s->objective_unit) { /* gear-lte-range, gear-dynamic: the objective of three flanks, per torque */
        static const char *const flank[3] = {"unmodified", "case", "optimum"};
        int dyn = s->objective == GD_OBJ_GEAR_DYNAMIC;
        json_t *of = json_object();
        for (int j = 0; j < 3; j++) {
            json_t *fo = json_object(), *each = json_array();
            json_object_set_new(fo, "value", gd_json_num(s->objective_of[j]));
            for (int k = 0; k < s->ntorques; k++) {
                json_t *t = json_object();
                json_object_set_new(t, "torque_nm", gd_json_num(s->torques_nm[k]));
                json_object_set_new(t, dyn ? "peak" : "lte_pp_arcsec", gd_json_num(s->aux_of[j][dyn ? 2 * k : k]));
                if (dyn)
                    json_object_set_new(t, "method", json_string(gd_dyn_method_name((int)s->aux_of[j][2 * k + 1])));
                json_array_append_new(each, t);
            }
            json_object_set_new(fo, "torques", each);
            json_object_set_new(of, flank[j], fo);
        }
        json_object_set_new(res, "objective_of", of);
    }
    if (s->post)
        gd_optpost_summary(res, c, s->post);
    if (s->robust)
        json_object_set_new(res, "robust", gd_optimize_robust_json(s->robust));
    json_object_set_new(res, "wall_s", gd_json_num(s->wall_s));
    json_object_set_new(root, "results", res);
    return gd_json_write_summary(d, root, err);
}

static json_t *stats_json(const gd_opt_alg_stats *S)
{
    json_t *o = json_object();
    json_object_set_new(o, "best", gd_json_num(S->best));
    json_object_set_new(o, "q1", gd_json_num(S->q1));
    json_object_set_new(o, "median", gd_json_num(S->median));
    json_object_set_new(o, "q3", gd_json_num(S->q3));
    json_object_set_new(o, "iqr", gd_json_num(S->q3 - S->q1));
    json_object_set_new(o, "worst", gd_json_num(S->worst));
    json_object_set_new(o, "mean", gd_json_num(S->mean));
    json_object_set_new(o, "successes", json_integer(S->successes));
    json_object_set_new(o, "success_rate", gd_json_num(S->success_rate));
    json_object_set_new(o, "evals_to_target_median", gd_json_num(S->evals_to_target_median));
    json_object_set_new(o, "ert_evals", gd_json_num(S->ert));
    json_object_set_new(o, "wall_mean_s", gd_json_num(S->wall_mean_s));
    json_object_set_new(o, "wall_total_s", gd_json_num(S->wall_total_s));
    return o;
}

gd_status gd_summary_write_compare(gd_run_dir *d, const gd_case *c, const gd_opt_compare_problem *pb,
                                          int nproblems, int threads,
                                          gd_error *err)
{
    json_t *root = gd_json_root(c, "compare-optimizers", NULL, NULL);
    if (nproblems < 1)
        return gd_json_write(d, "summary.json", root, err);
    const gd_opt_compare_result *r0 = pb[0].res;
    json_t *set = json_object();
    json_t *algs = json_array();
    for (int a = 0; a < r0->nalgs; a++)
        json_array_append_new(algs, json_string(gd_opt_algorithm_name(r0->stats[a].alg)));
    json_object_set_new(set, "optimizers", algs);
    json_object_set_new(set, "runs", json_integer(r0->runs));
    json_object_set_new(set, "budget_evals", json_integer(r0->budget));
    json_object_set_new(set, "seeds", json_string("seed + r for run r = 0 .. runs - 1, the same for every optimiser"));
    json_object_set_new(set, "seed", json_integer(c->opt_seed));
    json_object_set_new(set, "population", json_integer(c->opt_population));
    json_object_set_new(set, "threads", json_integer(threads));
    json_object_set_new(root, "settings", set);

    json_t *probs = json_array();
    for (int p = 0; p < nproblems; p++) {
        const gd_opt_compare_result *r = pb[p].res;
        json_t *o = json_object();
        json_object_set_new(o, "objective", json_string(gd_opt_objective_name(pb[p].objective)));
        json_object_set_new(o, "dimension", json_integer(pb[p].dim));
        json_object_set_new(o, "shift", gd_json_num(pb[p].shift));
        /* two objectives: the hypervolume's, the product of the gear's two (LTE and the dynamic response) */
        const char *two_unit = pb[p].objective != GD_OBJ_GEAR_LTE ? ""
                               : c->opt_dynamic_response == GD_DYN_DTE_PP ? "arcsec um" : "arcsec m/s^2";
        json_object_set_new(o, "objective_unit", json_string(pb[p].nobj == 2 ? two_unit
                                                             : pb[p].objective == GD_OBJ_GEAR_LTE ? "arcsec" : ""));
        if (pb[p].nobj == 2) { /* two objectives: every value is a hypervolume shortfall (section 13) */
            json_object_set_new(o, "objectives", json_integer(2));
            json_object_set_new(o, "value", json_string("the hypervolume shortfall: the area of the reference box "
                                                        "hv_reference[0] hv_reference[1] the front does not dominate"));
            json_t *ref = json_array();
            json_array_append_new(ref, gd_json_num(pb[p].hv_ref[0]));
            json_array_append_new(ref, gd_json_num(pb[p].hv_ref[1]));
            json_object_set_new(o, "hv_reference", ref);
        }
        json_object_set_new(o, "f_ref", gd_json_num(r->f_ref));
        json_object_set_new(o, "f_ref_is", json_string(r->f_ref_known ? "the known minimum"
                                                                       : "the best value found by any run"));
        json_object_set_new(o, "target", gd_json_num(r->target));
        json_t *tg = json_array();
        for (int k = 0; k < r->ntargets; k++)
            json_array_append_new(tg, gd_json_num(r->targets[k]));
        json_object_set_new(o, "ecdf_targets", tg);
        json_t *st = json_object();
        for (int a = 0; a < r->nalgs; a++)
            json_object_set_new(st, gd_opt_algorithm_name(r->stats[a].alg), stats_json(&r->stats[a]));
        json_object_set_new(o, "optimizers", st);
        json_object_set_new(o, "wall_s", gd_json_num(r->wall_s));
        json_array_append_new(probs, o);
    }
    json_object_set_new(root, "problems", probs);

    /* the runtime distribution pooled over every problem: the fraction of (problem, run, target)
     * pairs reached at 1 %, 10 % and 100 % of the budget */
    const gd_opt_compare_result *rs[64];
    int nr = nproblems < 64 ? nproblems : 64;
    for (int p = 0; p < nr; p++)
        rs[p] = pb[p].res;
    json_t *pool = json_object();
    for (int a = 0; a < r0->nalgs; a++) {
        json_t *o = json_object();
        json_object_set_new(o, "at_1_percent", gd_json_num(gd_opt_compare_ecdf(rs, nr, a, r0->budget / 100 > 0 ?
                                                                               r0->budget / 100 : 1)));
        json_object_set_new(o, "at_10_percent", gd_json_num(gd_opt_compare_ecdf(rs, nr, a, r0->budget / 10 > 0 ?
                                                                                r0->budget / 10 : 1)));
        json_object_set_new(o, "at_budget", gd_json_num(gd_opt_compare_ecdf(rs, nr, a, r0->budget)));
        json_object_set_new(pool, gd_opt_algorithm_name(r0->stats[a].alg), o);
    }
    json_object_set_new(root, "ecdf_pooled", pool);
    return gd_json_write_summary(d, root, err);
}
