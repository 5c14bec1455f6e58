/* The tables of an ltca run: the loaded transmission error and mesh stiffness per position
 * (lte.csv), the load of every contact point (load_distribution.csv) and the load sharing
 * between tooth pairs (pair_loads.csv). */
#include "output_internal.h"

#include <math.h>
#include <stdio.h>

static const char *half_name[2] = {"left", "right"};

static gd_status write_lte(gd_run_dir *d, const gd_ltca_result *r, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "lte.csv", &fp, err);
    if (st != GD_OK)
        return st;
    fprintf(fp, "phi1_deg,lte_arcsec,axial_shift_um");
    for (int h = 0; h < r->halves; h++) {
        const char *n = half_name[h];
        fprintf(fp, ",gte_%s_arcsec,lte_%s_arcsec,load_%s_n,share_%s,stiffness_%s_n_per_m,pairs_%s,"
                      "max_pressure_%s_mpa,edge_%s", n, n, n, n, n, n, n, n);
    }
    fputc('\n', fp);
    for (int k = 0; k < r->npos; k++) {
        fprintf(fp, "%.10g,%.10g,%.10g", r->phi1[k] * 180 / M_PI, r->lte_arcsec[k], r->axial_shift[k] * 1e6);
        for (int h = 0; h < r->halves; h++)
            fprintf(fp, ",%.10g,%.10g,%.10g,%.10g,%.10g,%d,%.10g,%u", r->gte_arcsec[h][k], r->lte_half_arcsec[h][k],
                    r->load[h][k], r->load[h][k] / r->normal_force_n, r->stiffness[h][k], r->pairs_loaded[h][k],
                    r->max_pressure[h][k] * 1e-6, r->edge_loaded[h][k]);
        fputc('\n', fp);
    }
    return gd_run_dir_commit(d, fp, err);
}

static gd_status write_points(gd_run_dir *d, const gd_ltca_result *r, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "load_distribution.csv", &fp, err);
    if (st != GD_OK)
        return st;
    fprintf(fp, "position,phi1_deg,half,pair,slice,face_mm,roll_mm,gap_um,load_n,line_load_n_per_mm,pressure_mpa,"
                  "hertz_half_width_mm,deformed_gap_um,edge\n");
    for (int k = 0; k < r->npos; k++)
        for (int i = r->first[k]; i < r->first[k + 1]; i++) {
            const gd_ltca_point *P = &r->points[i];
            fprintf(fp, "%d,%.10g,%s,%d,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%u\n", k, r->phi1[k] * 180 / M_PI,
                    half_name[P->half], P->pair, P->slice, P->z1 * 1e3, P->rho1 * 1e3, P->gap * 1e6, P->load,
                    P->line_load * 1e-3, P->pressure * 1e-6, P->hertz_half_width * 1e3, P->deformed_gap * 1e6,
                    P->edge);
        }
    return gd_run_dir_commit(d, fp, err);
}

/* load sharing between the tooth pairs: one row per position, half and loaded pair */
static gd_status write_pairs(gd_run_dir *d, const gd_ltca_result *r, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "pair_loads.csv", &fp, err);
    if (st != GD_OK)
        return st;
    fprintf(fp, "position,phi1_deg,half,pair,load_n,share_of_half,loaded_points,max_pressure_mpa\n");
    for (int k = 0; k < r->npos; k++)
        for (int h = 0; h < r->halves; h++) {
            int i = r->first[k], end = r->first[k + 1];
            while (i < end) {
                const gd_ltca_point *P = &r->points[i];
                if (P->half != h) {
                    i++;
                    continue;
                }
                int pair = P->pair, nl = 0;
                double load = 0, pmax = 0;
                while (i < end && r->points[i].half == h && r->points[i].pair == pair) {
                    if (r->points[i].load > 0) {
                        load += r->points[i].load;
                        nl++;
                        pmax = fmax(pmax, r->points[i].pressure);
                    }
                    i++;
                }
                if (nl)
                    fprintf(fp, "%d,%.10g,%s,%d,%.9g,%.9g,%d,%.9g\n", k, r->phi1[k] * 180 / M_PI, half_name[h], pair,
                            load, r->load[h][k] > 0 ? load / r->load[h][k] : 0.0, nl, pmax * 1e-6);
            }
        }
    return gd_run_dir_commit(d, fp, err);
}

gd_status gd_ltca_write_tables(gd_run_dir *d, const gd_ltca_result *r, gd_error *err)
{
    gd_status st = write_lte(d, r, err);
    if (st == GD_OK)
        st = write_points(d, r, err);
    if (st == GD_OK)
        st = write_pairs(d, r, err);
    return st;
}
