/* The tables of a tca run: the GTE and contact of every position (gte.csv), the contact path
 * on both flanks (contact_path.csv) and the separation topography of each half
 * (separation_left.csv, separation_right.csv). */
#include "output_internal.h"

#include <math.h>
#include <stdio.h>

static const char *half_name[2] = {"left", "right"};

static gd_status write_gte(gd_run_dir *d, const gd_case *c, const gd_tca_result *r, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "gte.csv", &fp, err);
    if (st != GD_OK)
        return st;
    fprintf(fp, "phi1_deg");
    for (int h = 0; h < r->halves; h++)
        fprintf(fp, ",gte_%s_arcsec,te_%s_arcsec,edge_%s,pairs_%s", half_name[h], half_name[h], half_name[h],
                half_name[h]);
    if (c->tca_formulation == GD_TCA_BOTH)
        for (int h = 0; h < r->halves; h++)
            fprintf(fp, ",te_tangency_%s_arcsec", half_name[h]);
    fputc('\n', fp);
    const double as = 180.0 * 3600.0 / M_PI;
    for (int k = 0; k < r->npos; k++) {
        fprintf(fp, "%.10g", r->phi1[k] * 180 / M_PI);
        for (int h = 0; h < r->halves; h++) {
            const gd_tca_contact *ck = &r->contact[h][k];
            fprintf(fp, ",%.10g,%.10g,%u,%d", r->gte_arcsec[h][k], ck->te * as, ck->edge, ck->pairs_in_contact);
        }
        if (c->tca_formulation == GD_TCA_BOTH)
            for (int h = 0; h < r->halves; h++) {
                const gd_tca_contact *ca = &r->contact_a[h][k];
                if (ca->converged)
                    fprintf(fp, ",%.10g", ca->te * as);
                else
                    fprintf(fp, ",NaN");
            }
        fputc('\n', fp);
    }
    return gd_run_dir_commit(d, fp, err);
}

static gd_status write_path(gd_run_dir *d, const gd_tca_result *r, const double rb[2], gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "contact_path.csv", &fp, err);
    if (st != GD_OK)
        return st;
    fprintf(fp, "half,phi1_deg,pair,pinion_roll_mm,pinion_face_mm,gear_roll_mm,gear_face_mm,x_mm,y_mm,z_mm,"
                  "nx,ny,nz,pressure_angle_deg,edge\n");
    for (int h = 0; h < r->halves; h++)
        for (int k = 0; k < r->npos; k++) {
            const gd_tca_contact *ck = &r->contact[h][k];
            fprintf(fp, "%s,%.10g,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%u\n", half_name[h],
                    r->phi1[k] * 180 / M_PI, ck->pair, ck->u1 * rb[0] * 1e3, ck->z1 * 1e3, ck->u2 * rb[1] * 1e3,
                    ck->z2 * 1e3, ck->pos[0] * 1e3, ck->pos[1] * 1e3, ck->pos[2] * 1e3, ck->normal[0], ck->normal[1],
                    ck->normal[2], ck->alpha_op * 180 / M_PI, ck->edge);
        }
    return gd_run_dir_commit(d, fp, err);
}

static gd_status write_separation(gd_run_dir *d, const gd_tca_result *r, int h, gd_error *err)
{
    char name[64];
    snprintf(name, sizeof name, "separation_%s.csv", half_name[h]);
    FILE *fp;
    gd_status st = gd_run_dir_create(d, name, &fp, err);
    if (st != GD_OK)
        return st;
    fprintf(fp, "face_mm,roll_mm,separation_um,ease_off_um\n");
    for (int j = 0; j < r->nface; j++)
        for (int i = 0; i < r->nprof; i++) {
            size_t n = (size_t)j * r->nprof + i;
            double s = r->sep[h][n], e = r->ease_off[h][n];
            fprintf(fp, "%.9g,%.9g,", r->z[j] * 1e3, r->rho[i] * 1e3);
            if (isfinite(s))
                fprintf(fp, "%.9g,%.9g\n", s * 1e6, e * 1e6);
            else
                fprintf(fp, "NaN,NaN\n");
        }
    return gd_run_dir_commit(d, fp, err);
}

gd_status gd_tca_write_tables(gd_run_dir *d, const gd_case *c, const gd_tca_result *r, const double rb[2],
                              gd_error *err)
{
    gd_status st = write_gte(d, c, r, err);
    if (st == GD_OK)
        st = write_path(d, r, rb, err);
    for (int h = 0; h < r->halves && st == GD_OK; h++)
        st = write_separation(d, r, h, err);
    return st;
}
