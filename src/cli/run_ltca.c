/* The `ltca` analysis on the command line: loaded transmission error and mesh stiffness per
 * position, the load of every contact point (load distribution, loaded contact pattern, contact
 * pressure), the load sharing between tooth pairs, pictures, summary.json (docs/ltca.md). */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *half_name[2] = {"left", "right"};

static gd_status write_lte(const char *dir, const gd_ltca_result *r, gd_error *err)
{
    gd_atomic_file f;
    gd_status st = gd_atomic_open(&f, dir, "lte.csv", err);
    if (st != GD_OK)
        return st;
    fprintf(f.fp, "phi1_deg,lte_arcsec,axial_shift_um");
    for (int h = 0; h < r->halves; h++) {
        const char *n = half_name[h];
        fprintf(f.fp, ",gte_%s_arcsec,lte_%s_arcsec,load_%s_n,share_%s,stiffness_%s_n_per_m,pairs_%s,"
                      "max_pressure_%s_mpa,edge_%s", n, n, n, n, n, n, n, n);
    }
    fputc('\n', f.fp);
    for (int k = 0; k < r->npos; k++) {
        fprintf(f.fp, "%.10g,%.10g,%.10g", r->phi1[k] * 180 / M_PI, r->lte_arcsec[k], r->axial_shift[k] * 1e6);
        for (int h = 0; h < r->halves; h++)
            fprintf(f.fp, ",%.10g,%.10g,%.10g,%.10g,%.10g,%d,%.10g,%u", r->gte_arcsec[h][k], r->lte_half_arcsec[h][k],
                    r->load[h][k], r->load[h][k] / r->normal_force_n, r->stiffness[h][k], r->pairs_loaded[h][k],
                    r->max_pressure[h][k] * 1e-6, r->edge_loaded[h][k]);
        fputc('\n', f.fp);
    }
    return gd_atomic_commit(&f, err);
}

static gd_status write_points(const char *dir, const gd_ltca_result *r, gd_error *err)
{
    gd_atomic_file f;
    gd_status st = gd_atomic_open(&f, dir, "load_distribution.csv", err);
    if (st != GD_OK)
        return st;
    fprintf(f.fp, "position,phi1_deg,half,pair,slice,face_mm,roll_mm,gap_um,load_n,line_load_n_per_mm,pressure_mpa,"
                  "hertz_half_width_mm,deformed_gap_um,edge\n");
    for (int k = 0; k < r->npos; k++)
        for (int i = r->first[k]; i < r->first[k + 1]; i++) {
            const gd_ltca_point *P = &r->points[i];
            fprintf(f.fp, "%d,%.10g,%s,%d,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%u\n", k, r->phi1[k] * 180 / M_PI,
                    half_name[P->half], P->pair, P->slice, P->z1 * 1e3, P->rho1 * 1e3, P->gap * 1e6, P->load,
                    P->line_load * 1e-3, P->pressure * 1e-6, P->hertz_half_width * 1e3, P->deformed_gap * 1e6,
                    P->edge);
        }
    return gd_atomic_commit(&f, err);
}

/* load sharing between the tooth pairs: one row per position, half and loaded pair */
static gd_status write_pairs(const char *dir, const gd_ltca_result *r, gd_error *err)
{
    gd_atomic_file f;
    gd_status st = gd_atomic_open(&f, dir, "pair_loads.csv", err);
    if (st != GD_OK)
        return st;
    fprintf(f.fp, "position,phi1_deg,half,pair,load_n,share_of_half,loaded_points,max_pressure_mpa\n");
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
                    fprintf(f.fp, "%d,%.10g,%s,%d,%.9g,%.9g,%d,%.9g\n", k, r->phi1[k] * 180 / M_PI, half_name[h], pair,
                            load, r->load[h][k] > 0 ? load / r->load[h][k] : 0.0, nl, pmax * 1e-6);
            }
        }
    return gd_atomic_commit(&f, err);
}

/* Pictures: the load distribution on the unrolled pinion flank of each half over the cycle (line
 * load in colour: the loaded contact pattern) and the LTE, GTE and mesh stiffness curves. */
static gd_status draw(const char *dir, const gd_ltca_result *r, gd_error *err)
{
    static const char *fmt[2][2] = {{"pngcairo size 1400,640 font ',11'", ".png"},
                                    {"svg size 1400,640 dynamic font 'sans,11'", ".svg"}};
    char script[16384];
    int n = 0;
    /* fixed ranges (the flank), so that a half without load still draws */
    double zl = INFINITY, zh = -INFINITY, rl = INFINITY, rh = -INFINITY;
    for (int i = 0; i < r->first[r->npos]; i++) {
        zl = fmin(zl, r->points[i].z1);
        zh = fmax(zh, r->points[i].z1);
        rl = fmin(rl, r->points[i].rho1);
        rh = fmax(rh, r->points[i].rho1);
    }
    n += snprintf(script + n, sizeof script - n, "set datafile separator ','\n");
    for (int fi = 0; fi < 2; fi++) {
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '%s/.load_distribution%s.tmp'\n"
            "set multiplot layout 1,%d title 'Load distribution on the unrolled pinion flank over one mesh cycle "
            "(%d positions, %.0f N m)'\n"
            "set xlabel 'face position from the middle of the half (mm)'\nset ylabel 'roll length (mm)'\n"
            "set cblabel 'line load (N/mm)'\nset palette defined (0 '#fff7bc', 1 '#fec44f', 2 '#d95f0e', 3 '#7f0000')\n"
            "set key off\nset grid\nset xrange [%.6g:%.6g]\nset yrange [%.6g:%.6g]\nset cbrange [0:*]\n",
            fmt[fi][0], dir, fmt[fi][1], r->halves, r->npos, r->torque_nm, zl * 1e3 - 1, zh * 1e3 + 1, rl * 1e3 - 1,
            rh * 1e3 + 1);
        for (int h = 0; h < r->halves; h++)
            n += snprintf(script + n, sizeof script - n,
                "set title '%s half: load share %.3f, max pressure %.0f MPa%s'\n"
                "plot '%s/load_distribution.csv' every ::1 using (strcol(3) eq '%s' && $9 > 0 ? $6 : 1/0):7:10 "
                "with points pt 7 ps 0.6 lc palette\n",
                half_name[h], r->load_share[h], r->pressure_max[h] * 1e-6, r->edge_kinds[h] ? ", edge loading" : "",
                dir, half_name[h]);
        n += snprintf(script + n, sizeof script - n, "unset multiplot\nunset output\nset autoscale\n");
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '%s/.lte%s.tmp'\n"
            "set multiplot layout 1,2 title 'Loaded transmission error (Eq. 12) and mesh stiffness (Eq. 14)'\n"
            "set xlabel 'pinion angle (deg)'\nset ylabel 'arc-seconds of the gear, about the mean'\n"
            "set key on bottom right\nset title 'LTE %.4f arcsec p-p (mean %.4f)'\n"
            "plot '%s/lte.csv' every ::1 using 1:($2 - %.10g) with linespoints pt 7 ps 0.5 lw 2 title 'LTE'",
            fmt[fi][0], dir, fmt[fi][1], r->lte_pp_arcsec, r->lte_mean_arcsec, dir, r->lte_mean_arcsec);
        for (int h = 0; h < r->halves; h++) {
            double gm = 0;
            for (int k = 0; k < r->npos; k++)
                gm += r->gte_arcsec[h][k] / r->npos;
            n += snprintf(script + n, sizeof script - n, ", '%s/lte.csv' every ::1 using 1:($%d - %.10g) with lines "
                          "lw 1.5 dt %d title 'GTE %s (TCA)'", dir, 4 + 8 * h, gm, 2 + h, half_name[h]);
        }
        n += snprintf(script + n, sizeof script - n,
            "\nset ylabel 'mesh stiffness (N/um)'\nset title 'mesh stiffness of each half'\nplot ");
        for (int h = 0; h < r->halves; h++)
            n += snprintf(script + n, sizeof script - n, "%s'%s/lte.csv' every ::1 using 1:($%d*1e-6) with "
                          "linespoints pt 7 ps 0.5 title '%s half'", h ? ", " : "", dir, 8 + 8 * h, half_name[h]);
        n += snprintf(script + n, sizeof script - n, "\nunset multiplot\nunset output\n");
    }
    if (n >= (int)sizeof script)
        return gd_error_set(err, GD_ERR_INTERNAL, "gnuplot script too long");
    static const char *names[] = {"load_distribution", "lte"};
    return gd_gnuplot_draw(dir, script, names, 2, err);
}

int run_ltca(const cli_case_args *a, gd_case *cp, const char *dir)
{
    gd_case c = *cp;
    gd_error err = {0};
    gd_ltca_result r;
    const gd_pair pair = gd_pair_from_case(&c);
    const gd_ltca_settings set = gd_ltca_settings_from_case(&c);
    if (gd_ltca_run(&pair, &set, &r, &err) != GD_OK)
        return cli_fail(&err);
    if (gd_mkdir_p(dir, &err) != GD_OK) {
        gd_ltca_result_free(&r);
        return cli_fail(&err);
    }
    const char *files[16];
    int nfiles = 0;
    gd_status st = write_lte(dir, &r, &err);
    if (st == GD_OK) {
        files[nfiles++] = "lte.csv";
        st = write_points(dir, &r, &err);
    }
    if (st == GD_OK) {
        files[nfiles++] = "load_distribution.csv";
        st = write_pairs(dir, &r, &err);
    }
    if (st != GD_OK) {
        gd_ltca_result_free(&r);
        return cli_fail(&err);
    }
    files[nfiles++] = "pair_loads.csv";
    const char *note = NULL;
    if (gd_gnuplot_wanted(c.plots, &note)) {
        gd_error perr = {0};
        gd_status pst = draw(dir, &r, &perr);
        static const char *pics[] = {"load_distribution.png", "load_distribution.svg", "lte.png", "lte.svg"};
        gd_gnuplot_drawn(pst, &perr, pics, 4, files, &nfiles);
    }
    files[nfiles++] = "summary.json";
    st = gd_summary_write_ltca(dir, &c, &r, files, nfiles, &err);
    if (st != GD_OK) {
        gd_ltca_result_free(&r);
        return cli_fail(&err);
    }
    if (note && !a->quiet)
        fprintf(stderr, "geardyn: note: %s\n", note);
    if (!a->quiet) {
        printf("%s: LTCA, %d positions, %d slices per half, %s pinion, %.6g N m: LTE %.6g arcsec p-p\n", dir, r.npos,
               r.nslices, r.halves > 1 ? (r.floating ? "floating" : "fixed") : "one-half", r.torque_nm,
               r.lte_pp_arcsec);
        for (int h = 0; h < r.halves; h++)
            printf("  %-5s mean mesh stiffness %.6g N/m (%.4g .. %.4g), load share %.4f, max pressure %.0f MPa, "
                   "edge loading %s\n", half_name[h], r.stiffness_mean[h], r.stiffness_min[h], r.stiffness_max[h],
                   r.load_share[h], r.pressure_max[h] * 1e-6, r.edge_kinds[h] ? "yes" : "no");
        printf("  %ld active-set iterations, largest residual %.3g m, %.3f s\n", r.iterations, r.max_residual,
               r.wall_s);
    }
    gd_ltca_result_free(&r);
    return 0;
}
