/* The tables of a response run: time_history.csv and poincare.csv row by row as the run goes,
 * then the local analysis's variable.csv, variable_poincare.csv and spectrum.csv. The right
 * mesh's columns (_R) exist only in a model with two meshes: a single pair and the one-coordinate
 * torsional model have one mesh, whose columns are the _L ones. */
#include "output_internal.h"

#include <string.h>

void gd_time_history_header(FILE *fp, const gd_model *m)
{
    fprintf(fp, "t_s,period");
    for (int j = 0; j < (m->nmesh > 1 ? 2 : 1); j++) {
        char h = j ? 'R' : 'L';
        fprintf(fp, ",lambda_%c_um,lambda_dot_%c_mps,accel_%c_mps2,dte_%c_um,force_%c_n", h, h, h, h, h);
    }
    for (int i = 0; i < m->ndof; i++)
        fprintf(fp, ",%s_um", m->dof_name[i]);
    fprintf(fp, "\n");
}

void gd_time_history_row(FILE *fp, const gd_model *m, const gd_sample *s)
{
    fprintf(fp, "%.12g,%ld", s->t_s, s->period);
    for (int j = 0; j < (m->nmesh > 1 ? 2 : 1); j++)
        fprintf(fp, ",%.9g,%.9g,%.9g,%.9g,%.9g", s->lambda_um[j], s->lambda_dot_mps[j], s->accel_mps2[j],
                s->dte_um[j], s->force_n[j]);
    double um = m->bc_m * 1e6;
    for (int i = 0; i < m->ndof; i++)
        fprintf(fp, ",%.9g", s->y[i] * um);
    fputc('\n', fp);
}

void gd_poincare_header(FILE *fp, const gd_model *m)
{
    fprintf(fp, "period,t_s,lambda_L,lambda_dot_L%s", m->nmesh > 1 ? ",lambda_R,lambda_dot_R" : "");
    for (int i = 0; i < m->n; i++)
        fprintf(fp, ",%s%s", m->dof_name[i % m->ndof], i < m->ndof ? "" : "_dot");
    fprintf(fp, "\n");
}

void gd_poincare_row(FILE *fp, const gd_model *m, long period, double t_s, const double *y)
{
    gd_modes md;
    memset(&md, 0, sizeof md);
    double t = t_s * m->omega_n;
    fprintf(fp, "%ld,%.12g", period, t_s);
    for (int j = 0; j < (m->nmesh > 1 ? 2 : 1); j++) {
        int c = m->mesh_clear[j];
        double x, xd;
        gd_model_clearance(m, c, t, y, &md, &x, &xd);
        fprintf(fp, ",%.12g,%.12g", x, xd);
    }
    for (int i = 0; i < m->n; i++)
        fprintf(fp, ",%.12g", y[i]);
    fputc('\n', fp);
}

gd_status gd_local_write_tables(gd_run_dir *d, const gd_local *L, double mesh_freq_hz, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "variable.csv", &fp, err);
    if (st != GD_OK)
        return st;
    fprintf(fp, "t_s,%s_um,%s_rate_mps\n", L->name, L->name);
    for (size_t i = 0; i < L->n; i++)
        fprintf(fp, "%.12g,%.9g,%.9g\n", L->t[i], L->x[i], L->xd[i]);
    if ((st = gd_run_dir_commit(d, fp, err)) != GD_OK)
        return st;
    if ((st = gd_run_dir_create(d, "variable_poincare.csv", &fp, err)) != GD_OK)
        return st;
    fprintf(fp, "%s_um,%s_rate_mps\n", L->name, L->name);
    for (size_t i = 0; i < L->np; i++)
        fprintf(fp, "%.12g,%.12g\n", L->px[i], L->pxd[i]);
    if ((st = gd_run_dir_commit(d, fp, err)) != GD_OK)
        return st;
    if ((st = gd_run_dir_create(d, "spectrum.csv", &fp, err)) != GD_OK)
        return st;
    fprintf(fp, "frequency_hz,order,amplitude_um\n");
    for (size_t k = 0; k < L->nfreq; k++)
        fprintf(fp, "%.9g,%.9g,%.9g\n", L->freq_hz[k], L->freq_hz[k] / mesh_freq_hz, L->amp_um[k]);
    return gd_run_dir_commit(d, fp, err);
}
