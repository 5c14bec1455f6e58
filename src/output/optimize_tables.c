/* The tables of an optimize run: the optimum with its bounds and reference (optimum.csv), the
 * convergence of every run (convergence.csv) and, for the gear, the LTE of the unmodified pair,
 * the paper's Table 2 and the optimum (lte.csv). */
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
    fprintf(fp, "variable,symbol,unit,value,lower,upper,%s\n", o->gear ? "paper_table2" : "minimiser");
    for (int i = 0; i < o->dim; i++) {
        const char *unit = "", *sym = o->names[i];
        const char *key = o->gear ? gd_opt_gear_variable(i, &unit, &sym) : o->names[i];
        fprintf(fp, "%s,%s,%s,%.10g,%.10g,%.10g,%.10g\n", key, sym, unit, b->y[i], o->lower[i], o->upper[i],
                o->reference[i]);
        if (o->gear && i == 4) /* y6 = y5: the symmetric lead relief */
            fprintf(fp, "lead_relief_outer_um,y6,um,%.10g,%.10g,%.10g,%.10g\n", b->y[4], o->lower[4], o->upper[4],
                    o->reference[4]);
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
    fprintf(fp, "phi1_deg,lte_unmodified_arcsec,lte_table2_arcsec,lte_optimum_arcsec\n");
    for (int k = 0; k < o->lte[0].npos; k++)
        fprintf(fp, "%.10g,%.10g,%.10g,%.10g\n", o->lte[0].phi1[k] * 180 / M_PI, o->lte[0].lte_arcsec[k],
                o->lte[1].lte_arcsec[k], o->lte[2].lte_arcsec[k]);
    return gd_run_dir_commit(d, fp, err);
}

