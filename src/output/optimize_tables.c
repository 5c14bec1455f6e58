/* The tables of an optimize run: the optimum with its bounds and reference (optimum.csv), the
 * convergence of every run (convergence.csv) and, for the gear, the LTE of the unmodified pair,
 * the case's own modification, the optimum and, for the paper's pair, the paper's Table 2 (lte.csv). */
#include "output_internal.h"

#include <math.h>
#include <stdio.h>

gd_status gd_optimize_write_optimum(gd_run_dir *d, const gd_optimize_outcome *o, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "optimum.csv", &fp, err);
    if (st != GD_OK)
        return st;
    const gd_opt_result *b = &o->res[o->best];
    if (!o->gear) {
        fprintf(fp, "variable,symbol,unit,value,lower,upper,minimiser\n");
        for (int i = 0; i < o->dim; i++)
            fprintf(fp, "%s,%s,,%.10g,%.10g,%.10g,%.10g\n", o->names[i], o->names[i], b->y[i], o->lower[i],
                    o->upper[i], o->reference[i]);
        return gd_run_dir_commit(d, fp, err);
    }
    /* the gear: each variable beside the case's own value, whether it has an effect at the optimum,
     * and for the paper's pair the paper's Table 2; y6 follows y5 in its own row when only y5 varies */
    fprintf(fp, "variable,symbol,unit,value,lower,upper,case_value,effect%s\n", o->paper ? ",paper_table2" : "");
    int y6 = 0;
    for (int i = 0; i < o->dim; i++)
        y6 |= o->vars.var[i] == 5;
    for (int i = 0; i < o->dim; i++) {
        const char *unit = "", *sym = "";
        for (int twin = 0; twin < 2; twin++) {
            int id = twin ? 5 : o->vars.var[i];
            if (twin && (o->vars.var[i] != 4 || y6))
                break;
            const char *key = gd_opt_gear_variable(id, &unit, &sym);
            fprintf(fp, "%s,%s,%s,%.10g,%.10g,%.10g,%.10g,%s", key, sym, unit, b->y[i], o->lower[i], o->upper[i],
                    twin ? o->pair.lead_relief_outer_um : o->case_value[i],
                    o->no_effect[i][0] ? o->no_effect[i] : (twin ? "y6 = y5" : "yes"));
            if (o->paper)
                fprintf(fp, ",%.10g", o->table2[i]);
            fputc('\n', fp);
        }
    }
    return gd_run_dir_commit(d, fp, err);
}

gd_status gd_optimize_write_convergence(gd_run_dir *d, const gd_optimize_outcome *o, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "convergence.csv", &fp, err);
    if (st != GD_OK)
        return st;
    fprintf(fp, "run,seed_offset,evaluation,f,best_f\n");
    for (int r = 0; r < o->runs; r++)
        for (long k = 0; k < o->res[r].evaluations; k++)
            fprintf(fp, "%d,%d,%ld,%.12g,%.12g\n", r + 1, r, k + 1, o->res[r].f_history[k], o->res[r].best_history[k]);
    return gd_run_dir_commit(d, fp, err);
}

gd_status gd_optimize_write_lte(gd_run_dir *d, const gd_optimize_outcome *o, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "lte.csv", &fp, err);
    if (st != GD_OK)
        return st;
    fprintf(fp, "phi1_deg,lte_unmodified_arcsec,lte_case_arcsec,lte_optimum_arcsec%s\n",
            o->paper ? ",lte_paper_table2_arcsec" : "");
    for (int k = 0; k < o->lte[0].npos; k++) {
        fprintf(fp, "%.10g,%.10g,%.10g,%.10g", o->lte[0].phi1[k] * 180 / M_PI, o->lte[0].lte_arcsec[k],
                o->lte[1].lte_arcsec[k], o->lte[2].lte_arcsec[k]);
        if (o->paper)
            fprintf(fp, ",%.10g", o->lte[3].lte_arcsec[k]);
        fputc('\n', fp);
    }
    return gd_run_dir_commit(d, fp, err);
}
