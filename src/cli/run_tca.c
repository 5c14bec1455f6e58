/* The `tca` analysis on the command line: GTE and contact tables, the separation topography of
 * each half, pictures of the contact pattern on the unrolled flank and of the GTE, summary.json. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *half_name[2] = {"left", "right"};

static gd_status write_gte(const char *dir, const gd_case *c, const gd_tca_result *r, gd_error *err)
{
    gd_atomic_file f;
    gd_status st = gd_atomic_open(&f, dir, "gte.csv", err);
    if (st != GD_OK)
        return st;
    fprintf(f.fp, "phi1_deg");
    for (int h = 0; h < r->halves; h++)
        fprintf(f.fp, ",gte_%s_arcsec,te_%s_arcsec,edge_%s,pairs_%s", half_name[h], half_name[h], half_name[h],
                half_name[h]);
    if (c->tca_formulation == GD_TCA_BOTH)
        for (int h = 0; h < r->halves; h++)
            fprintf(f.fp, ",te_tangency_%s_arcsec", half_name[h]);
    fputc('\n', f.fp);
    const double as = 180.0 * 3600.0 / M_PI;
    for (int k = 0; k < r->npos; k++) {
        fprintf(f.fp, "%.10g", r->phi1[k] * 180 / M_PI);
        for (int h = 0; h < r->halves; h++) {
            const gd_tca_contact *ck = &r->contact[h][k];
            fprintf(f.fp, ",%.10g,%.10g,%u,%d", r->gte_arcsec[h][k], ck->te * as, ck->edge, ck->pairs_in_contact);
        }
        if (c->tca_formulation == GD_TCA_BOTH)
            for (int h = 0; h < r->halves; h++) {
                const gd_tca_contact *ca = &r->contact_a[h][k];
                if (ca->converged)
                    fprintf(f.fp, ",%.10g", ca->te * as);
                else
                    fprintf(f.fp, ",NaN");
            }
        fputc('\n', f.fp);
    }
    return gd_atomic_commit(&f, err);
}

static gd_status write_path(const char *dir, const gd_case *c, const gd_tca_result *r, gd_error *err)
{
    gd_geometry g;
    const gd_pair pair = gd_pair_from_case(c);
    gd_status st = gd_geometry_compute(&pair, &g, err);
    if (st != GD_OK)
        return st;
    gd_atomic_file f;
    st = gd_atomic_open(&f, dir, "contact_path.csv", err);
    if (st != GD_OK)
        return st;
    fprintf(f.fp, "half,phi1_deg,pair,pinion_roll_mm,pinion_face_mm,gear_roll_mm,gear_face_mm,x_mm,y_mm,z_mm,"
                  "nx,ny,nz,pressure_angle_deg,edge\n");
    for (int h = 0; h < r->halves; h++)
        for (int k = 0; k < r->npos; k++) {
            const gd_tca_contact *ck = &r->contact[h][k];
            fprintf(f.fp, "%s,%.10g,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%u\n", half_name[h],
                    r->phi1[k] * 180 / M_PI, ck->pair, ck->u1 * g.rb[0] * 1e3, ck->z1 * 1e3, ck->u2 * g.rb[1] * 1e3,
                    ck->z2 * 1e3, ck->pos[0] * 1e3, ck->pos[1] * 1e3, ck->pos[2] * 1e3, ck->normal[0], ck->normal[1],
                    ck->normal[2], ck->alpha_op * 180 / M_PI, ck->edge);
        }
    return gd_atomic_commit(&f, err);
}

static gd_status write_separation(const char *dir, const gd_tca_result *r, int h, gd_error *err)
{
    char name[64];
    snprintf(name, sizeof name, "separation_%s.csv", half_name[h]);
    gd_atomic_file f;
    gd_status st = gd_atomic_open(&f, dir, name, err);
    if (st != GD_OK)
        return st;
    fprintf(f.fp, "face_mm,roll_mm,separation_um,ease_off_um\n");
    for (int j = 0; j < r->nface; j++)
        for (int i = 0; i < r->nprof; i++) {
            size_t n = (size_t)j * r->nprof + i;
            double s = r->sep[h][n], e = r->ease_off[h][n];
            fprintf(f.fp, "%.9g,%.9g,", r->z[j] * 1e3, r->rho[i] * 1e3);
            if (isfinite(s))
                fprintf(f.fp, "%.9g,%.9g\n", s * 1e6, e * 1e6);
            else
                fprintf(f.fp, "NaN,NaN\n");
        }
    return gd_atomic_commit(&f, err);
}

/* Pictures: contact pattern on the unrolled flank of each half (face position across, roll length
 * up, separation in colour, the paint thickness as the edge of the dark pattern, the contact path
 * as points) and the GTE curves. */
static gd_status draw(const char *dir, const gd_case *c, const gd_tca_result *r, gd_error *err)
{
    static const char *fmt[2][2] = {{"pngcairo size 1400,640 font ',11'", ".png"},
                                    {"svg size 1400,640 dynamic font 'sans,11'", ".svg"}};
    double p = c->paint_thickness_um;
    char script[16384];
    int n = 0;
    n += snprintf(script + n, sizeof script - n, "set datafile separator ','\nset datafile missing 'NaN'\n");
    for (int fi = 0; fi < 2; fi++) {
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '%s/.contact_pattern%s.tmp'\n"
            "set multiplot layout 1,%d title 'Contact pattern on the unrolled pinion flank (paint thickness %.3g um; "
            "black: path of the first contact)'\n"
            "set xlabel 'face position from the middle of the half (mm)'\nset ylabel 'roll length (mm)'\n"
            "set cbrange [0:%.6g]\nset cblabel 'least separation (um)'\n"
            "set palette defined (0 '#7f0000', %.6g '#d7301f', %.6g '#fdd49e', %.6g '#f7f7f7')\n"
            "set key off\nset grid front\n",
            fmt[fi][0], dir, fmt[fi][1], r->halves, p, 8 * p, p, p * 1.0001, 8 * p);
        for (int h = 0; h < r->halves; h++)
            n += snprintf(script + n, sizeof script - n,
                "set title '%s half (GTE %.4g arcsec p-p%s)'\n"
                "plot '%s/separation_%s.csv' every ::1 using 1:2:($3 > %.6g ? %.6g : $3) with image, "
                "'%s/contact_path.csv' every ::1 using (strcol(1) eq '%s' ? $5 : 1/0):4 with points pt 7 ps 0.5 lc rgb 'black'\n",
                half_name[h], r->gte_pp_arcsec[h], r->edge_kinds[h] ? ", edge contact" : "", dir, half_name[h], 8 * p,
                8 * p, dir, half_name[h]);
        n += snprintf(script + n, sizeof script - n, "unset multiplot\nunset output\n");
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '%s/.gte%s.tmp'\nset title 'Geometric transmission error (Eq. 10)'\n"
            "set xlabel 'pinion angle (deg)'\nset ylabel 'GTE (arc-seconds of the gear)'\nset key on top right\n"
            "unset colorbox\nplot '%s/gte.csv' every ::1 using 1:2 with linespoints pt 7 ps 0.5 lw 1.5 title 'left half'",
            fmt[fi][0], dir, fmt[fi][1], dir);
        if (r->halves > 1)
            n += snprintf(script + n, sizeof script - n,
                          ", '%s/gte.csv' every ::1 using 1:6 with linespoints pt 6 ps 0.5 lw 1.5 dt 2 title 'right half'",
                          dir);
        n += snprintf(script + n, sizeof script - n, "\nunset output\nset colorbox\n");
    }
    if (n >= (int)sizeof script)
        return gd_error_set(err, GD_ERR_INTERNAL, "gnuplot script too long");
    static const char *names[] = {"contact_pattern", "gte"};
    return gd_gnuplot_draw(dir, script, names, 2, err);
}

int run_tca(const cli_case_args *a, gd_case *cp, const char *dir)
{
    gd_case c = *cp;
    gd_error err = {0};
    gd_tca_result r;
    const gd_pair pair = gd_pair_from_case(&c);
    const gd_tca_settings set = gd_tca_settings_from_case(&c);
    if (gd_tca_run(&pair, &set, &r, &err) != GD_OK)
        return cli_fail(&err);
    if (gd_mkdir_p(dir, &err) != GD_OK) {
        gd_tca_result_free(&r);
        return cli_fail(&err);
    }
    const char *files[16];
    int nfiles = 0;
    gd_status st = write_gte(dir, &c, &r, &err);
    if (st == GD_OK) {
        files[nfiles++] = "gte.csv";
        st = write_path(dir, &c, &r, &err);
    }
    if (st == GD_OK)
        files[nfiles++] = "contact_path.csv";
    for (int h = 0; h < r.halves && st == GD_OK; h++) {
        st = write_separation(dir, &r, h, &err);
        if (st == GD_OK)
            files[nfiles++] = h ? "separation_right.csv" : "separation_left.csv";
    }
    if (st != GD_OK) {
        gd_tca_result_free(&r);
        return cli_fail(&err);
    }
    const char *note = NULL;
    if (gd_gnuplot_wanted(c.plots, &note)) {
        gd_error perr = {0};
        gd_status pst = draw(dir, &c, &r, &perr);
        static const char *pics[] = {"contact_pattern.png", "contact_pattern.svg", "gte.png", "gte.svg"};
        gd_gnuplot_drawn(pst, &perr, pics, 4, files, &nfiles);
    }
    files[nfiles++] = "summary.json";
    st = gd_summary_write_tca(dir, &c, &r, files, nfiles, &err);
    if (st != GD_OK) {
        gd_tca_result_free(&r);
        return cli_fail(&err);
    }
    if (note && !a->quiet)
        fprintf(stderr, "geardyn: note: %s\n", note);
    if (!a->quiet) {
        printf("%s: TCA, %d positions per half, GTE peak-to-peak", dir, r.npos);
        for (int h = 0; h < r.halves; h++)
            printf(" %s %.6g arcsec%s", half_name[h], r.gte_pp_arcsec[h], h + 1 < r.halves ? "," : "");
        printf("; edge contact");
        for (int h = 0; h < r.halves; h++)
            printf(" %s %s", half_name[h], r.edge_kinds[h] ? "yes" : "no");
        printf("\n  operating pressure angle %.6g deg, %ld Newton iterations, %.3f s\n", r.alpha_op_mean * 180 / M_PI,
               r.iterations, r.wall_s);
        if (c.tca_formulation == GD_TCA_BOTH)
            printf("  formulations (a) and (b): %d of %d positions compared, largest difference %.3g arcsec\n",
                   r.compared, r.npos * r.halves, r.max_diff_arcsec);
    }
    gd_tca_result_free(&r);
    return 0;
}
