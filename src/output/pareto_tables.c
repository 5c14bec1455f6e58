/* The files of an optimize run with two objectives (docs/optimisation.md section 13): the Pareto front
 * of the best run (pareto.csv: every non-dominated point of its evaluations, the design variables and
 * both objectives in their units), every evaluation of every run with the hypervolume after it
 * (evaluations.csv), and summary.json. */
#include "output_internal.h"

#include "json_util.h"

#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

gd_status gd_pareto_write(gd_run_dir *d, const gd_optimize_outcome *o, gd_error *err)
{
    const gd_opt_pareto_report *P = o->pareto;
    const gd_opt_result *b = &P->res[P->best];
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "pareto.csv", &fp, err);
    if (st != GD_OK)
        return st;
    fprintf(fp, "point");
    for (int i = 0; i < o->dim; i++)
        fprintf(fp, ",%s", o->names[i]);
    fprintf(fp, ",%s,%s\n", P->column[0], P->column[1]);
    for (int k = 0; k < b->nfront; k++) {
        fprintf(fp, "%d", k + 1);
        for (int i = 0; i < o->dim; i++)
            fprintf(fp, ",%.12g", b->front_y[(size_t)k * (size_t)o->dim + (size_t)i]);
        fprintf(fp, ",%.17g,%.17g\n", b->front_f[2 * k], b->front_f[2 * k + 1]);
    }
    if ((st = gd_run_dir_commit(d, fp, err)) != GD_OK)
        return st;
    if ((st = gd_run_dir_create(d, "evaluations.csv", &fp, err)) != GD_OK)
        return st;
    fprintf(fp, "run,evaluation,%s,%s,hypervolume\n", P->column[0], P->column[1]);
    for (int r = 0; r < P->runs; r++) {
        const gd_opt_result *u = &P->res[r];
        const int nf = u->nobj + u->naux;
        for (long k = 0; k < u->evaluations; k++)
            fprintf(fp, "%d,%ld,%.17g,%.17g,%.17g\n", r + 1, k + 1, u->fv_history[(size_t)k * (size_t)nf],
                    u->fv_history[(size_t)k * (size_t)nf + 1], u->hv_history[k]);
    }
    return gd_run_dir_commit(d, fp, err);
}

gd_status gd_summary_write_pareto(gd_run_dir *d, const gd_case *c, const gd_optimize_outcome *o, gd_error *err)
{
    const gd_opt_pareto_report *P = o->pareto;
    const gd_opt_result *b = &P->res[P->best];
    json_t *root = gd_json_root(c, "optimize", NULL, NULL);
    json_t *set = json_object();
    json_object_set_new(set, "algorithm", json_string(gd_opt_algorithm_name(c->opt_algorithm)));
    json_t *objs = json_array();
    json_array_append_new(objs, json_string(gd_opt_objective_name(P->objective)));
    if (P->gear)
        json_array_append_new(objs, json_string(gd_opt_objective_name(P->objective2)));
    json_object_set_new(set, "objectives", objs);
    json_t *cols = json_array();
    for (int k = 0; k < 2; k++)
        json_array_append_new(cols, json_string(P->column[k]));
    json_object_set_new(set, "objective_columns", cols);
    json_object_set_new(set, "dimension", json_integer(o->dim));
    json_object_set_new(set, "budget_evals", json_integer(o->settings.budget));
    json_object_set_new(set, "runs", json_integer(P->runs));
    json_object_set_new(set, "seed", json_integer(c->opt_seed));
    json_object_set_new(set, "population", json_integer(c->opt_population));
    if (c->opt_algorithm == GD_OPT_MOALO)
        json_object_set_new(set, "archive", json_integer(c->opt_archive));
    if (c->opt_algorithm == GD_OPT_WEIGHTED_SUM || c->opt_algorithm == GD_OPT_EPS_CONSTRAINT) {
        json_object_set_new(set, "scalar_algorithm", json_string(gd_opt_algorithm_name(c->opt_scalar_algorithm)));
        json_object_set_new(set, "scalar_grid", json_integer(c->opt_scalar_grid));
    }
    json_t *ref = json_array();
    json_array_append_new(ref, gd_json_num(P->hv_ref[0]));
    json_array_append_new(ref, gd_json_num(P->hv_ref[1]));
    json_object_set_new(set, "hv_reference", ref);
    json_object_set_new(set, "hv_reference_is", json_string(!P->hv_ref_derived ? "optimize.hv_reference"
                                                            : P->gear ? "1.1 times the unmodified flank's objectives"
                                                                      : "1.1, 1.1"));
    json_object_set_new(set, "threads", json_integer(o->threads));
    if (P->gear) {
        json_t *vars = json_array();
        for (int i = 0; i < o->dim; i++) {
            const char *sym;
            gd_opt_gear_variable(o->vars.var[i], NULL, &sym);
            json_array_append_new(vars, json_string(sym));
        }
        json_object_set_new(set, "variables", vars);
    }
    json_object_set_new(root, "settings", set);

    json_t *res = json_object();
    json_object_set_new(res, "hypervolume", gd_json_num(b->hv));
    json_object_set_new(res, "front_points", json_integer(b->nfront));
    json_object_set_new(res, "evaluations", json_integer(b->evaluations));
    json_object_set_new(res, "best_run", json_integer(P->best + 1));
    json_t *rh = json_array();
    for (int r = 0; r < P->runs; r++)
        json_array_append_new(rh, gd_json_num(P->res[r].hv));
    json_object_set_new(res, "run_hypervolumes", rh);
    if (c->opt_algorithm == GD_OPT_MOALO) {
        json_object_set_new(res, "archive_points", json_integer(b->narchive));
        json_object_set_new(res, "archive_hypervolume", gd_json_num(b->archive_hv));
    }
    /* the ends of the front: the least of each objective */
    if (b->nfront > 0) {
        json_t *ends = json_object();
        json_object_set_new(ends, P->column[0], gd_json_num(b->front_f[0]));
        json_object_set_new(ends, P->column[1], gd_json_num(b->front_f[2 * (b->nfront - 1) + 1]));
        json_object_set_new(res, "least", ends);
    }
    if (P->gear) {
        static const char *const flank[2] = {"unmodified", "case"};
        json_t *fl = json_object();
        for (int j = 0; j < 2; j++) {
            json_t *f = json_object();
            for (int k = 0; k < 2; k++)
                json_object_set_new(f, P->column[k], gd_json_num(P->flank_f[j][k]));
            /* whether a point of the front dominates the flank */
            int dominated = 0;
            for (int q = 0; q < b->nfront && !dominated; q++)
                dominated = b->front_f[2 * q] <= P->flank_f[j][0] && b->front_f[2 * q + 1] <= P->flank_f[j][1] &&
                            (b->front_f[2 * q] < P->flank_f[j][0] || b->front_f[2 * q + 1] < P->flank_f[j][1]);
            json_object_set_new(f, "dominated_by_the_front", json_boolean(dominated));
            json_object_set_new(fl, flank[j], f);
        }
        json_object_set_new(res, "flanks", fl);
    } else {
        json_object_set_new(res, "true_front_hypervolume", gd_json_num(P->true_front_hv));
        json_object_set_new(res, "hypervolume_gap_percent", gd_json_num(100.0 * (P->true_front_hv - b->hv) /
                                                                          P->true_front_hv));
    }
    json_object_set_new(res, "wall_s", gd_json_num(o->wall_s));
    json_object_set_new(root, "results", res);
    return gd_json_write_summary(d, root, err);
}
