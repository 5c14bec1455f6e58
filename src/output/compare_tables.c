/* The tables of a compare-optimizers run: every run (runs.csv), the statistics of each optimiser
 * (statistics.csv), convergence quartiles (convergence.csv), runtime distributions (ecdf.csv)
 * and the best points (best_points.csv). */
#include "output_internal.h"

#include <stdio.h>

static const char *obj_name(const gd_compare_entry *q) { return gd_opt_objective_name(q->objective); }

gd_status gd_compare_write_tables(gd_run_dir *d, const gd_compare_outcome *C, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "runs.csv", &fp, err);
    if (st != GD_OK)
        return st;
    fprintf(fp, "objective,dimension,optimizer,run,seed,final_f,final_delta_f,evaluations,evals_to_target,starts,"
                  "wall_s\n");
    for (int j = 0; j < C->n; j++) {
        const gd_opt_compare_result *r = &C->p[j].res;
        for (int i = 0; i < r->nalgs * r->runs; i++) {
            const gd_opt_compare_run *u = &r->run[i];
            fprintf(fp, "%s,%d,%s,%d,%lu,%.12g,%.12g,%ld,%ld,%d,%.6g\n", obj_name(&C->p[j]), C->p[j].dim,
                    gd_opt_algorithm_name(u->alg), u->run + 1, u->seed, u->f, u->f - r->f_ref, u->evaluations,
                    u->evals_to_target, u->starts, u->wall_s);
        }
    }
    if ((st = gd_run_dir_commit(d, fp, err)) != GD_OK)
        return st;

    if ((st = gd_run_dir_create(d, "statistics.csv", &fp, err)) != GD_OK)
        return st;
    fprintf(fp, "objective,dimension,optimizer,runs,budget_evals,f_ref,target,best,q1,median,q3,iqr,worst,mean,"
                  "successes,success_rate,evals_to_target_median,ert_evals,wall_mean_s,wall_total_s\n");
    for (int j = 0; j < C->n; j++) {
        const gd_opt_compare_result *r = &C->p[j].res;
        for (int a = 0; a < r->nalgs; a++) {
            const gd_opt_alg_stats *S = &r->stats[a];
            fprintf(fp, "%s,%d,%s,%d,%ld,%.12g,%.6g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%d,%.6g,%.6g,%.6g,"
                    "%.6g,%.6g\n", obj_name(&C->p[j]), C->p[j].dim, gd_opt_algorithm_name(S->alg), r->runs, r->budget,
                    r->f_ref, r->target, S->best, S->q1, S->median, S->q3, S->q3 - S->q1, S->worst, S->mean,
                    S->successes, S->success_rate, S->evals_to_target_median, S->ert, S->wall_mean_s,
                    S->wall_total_s);
        }
    }
    if ((st = gd_run_dir_commit(d, fp, err)) != GD_OK)
        return st;

    if ((st = gd_run_dir_create(d, "convergence.csv", &fp, err)) != GD_OK)
        return st;
    fprintf(fp, "objective,dimension,optimizer,evaluations,q1_delta_f,median_delta_f,q3_delta_f\n");
    for (int j = 0; j < C->n; j++) {
        const gd_opt_compare_result *r = &C->p[j].res;
        for (int a = 0; a < r->nalgs; a++)
            for (int k = 0; k < C->ngrid; k++) {
                double q[3];
                gd_opt_compare_quartiles(r, a, C->grid[k], q);
                fprintf(fp, "%s,%d,%s,%ld,%.10g,%.10g,%.10g\n", obj_name(&C->p[j]), C->p[j].dim,
                        gd_opt_algorithm_name(r->stats[a].alg), C->grid[k], q[0], q[1], q[2]);
            }
    }
    if ((st = gd_run_dir_commit(d, fp, err)) != GD_OK)
        return st;

    if ((st = gd_run_dir_create(d, "ecdf.csv", &fp, err)) != GD_OK)
        return st;
    fprintf(fp, "objective,dimension,optimizer,evaluations,fraction\n");
    const gd_opt_compare_result *all[GD_COMPARE_MAX];
    for (int j = 0; j < C->n; j++)
        all[j] = &C->p[j].res;
    for (int j = 0; j <= C->n; j++) {
        const gd_opt_compare_result *const *rs = j < C->n ? &all[j] : all;
        int nr = j < C->n ? 1 : C->n;
        for (int a = 0; a < all[0]->nalgs; a++)
            for (int k = 0; k < C->ngrid; k++)
                fprintf(fp, "%s,%d,%s,%ld,%.6g\n", j < C->n ? obj_name(&C->p[j]) : "all",
                        j < C->n ? C->p[j].dim : 0, gd_opt_algorithm_name(all[0]->stats[a].alg), C->grid[k],
                        gd_opt_compare_ecdf(rs, nr, a, C->grid[k]));
    }
    if ((st = gd_run_dir_commit(d, fp, err)) != GD_OK)
        return st;

    if ((st = gd_run_dir_create(d, "best_points.csv", &fp, err)) != GD_OK)
        return st;
    fprintf(fp, "objective,dimension,optimizer,run,variable,unit,value\n");
    for (int j = 0; j < C->n; j++) {
        const gd_opt_compare_result *r = &C->p[j].res;
        int gear = C->p[j].objective == GD_OBJ_GEAR_LTE;
        for (int i = 0; i < r->nalgs * r->runs; i++)
            for (int k = 0; k < r->dim; k++) {
                const char *unit = "";
                char name[48];
                if (gear)
                    snprintf(name, sizeof name, "%s",
                             gd_opt_gear_variable(gd_opt_gear_vars_of(C->p[j].gear)->var[k], &unit, NULL));
                else
                    snprintf(name, sizeof name, "x%d", k + 1);
                fprintf(fp, "%s,%d,%s,%d,%s,%s,%.12g\n", obj_name(&C->p[j]), C->p[j].dim,
                        gd_opt_algorithm_name(r->run[i].alg), r->run[i].run + 1, name, unit, r->run[i].y[k]);
            }
    }
    return gd_run_dir_commit(d, fp, err);
}

