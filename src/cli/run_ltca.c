/* The `ltca` analysis on the command line: pictures of the load distribution on the unrolled
 * flank and of the LTE, GTE and mesh stiffness, and the summary lines (docs/ltca.md). */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *half_name[2] = {"left", "right"};

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
            "set terminal %s\nset output '.load_distribution%s.tmp'\n"
            "set multiplot layout 1,%d title 'Load distribution on the unrolled pinion flank over one mesh cycle "
            "(%d positions, %.0f N m)'\n"
            "set xlabel 'face position from the middle of the half (mm)'\nset ylabel 'roll length (mm)'\n"
            "set cblabel 'line load (N/mm)'\nset palette defined (0 '#fff7bc', 1 '#fec44f', 2 '#d95f0e', 3 '#7f0000')\n"
            "set key off\nset grid\nset xrange [%.6g:%.6g]\nset yrange [%.6g:%.6g]\nset cbrange [0:*]\n",
            fmt[fi][0], fmt[fi][1], r->halves, r->npos, r->torque_nm, zl * 1e3 - 1, zh * 1e3 + 1, rl * 1e3 - 1,
            rh * 1e3 + 1);
        for (int h = 0; h < r->halves; h++)
            n += snprintf(script + n, sizeof script - n,
                "set title '%s half: load share %.3f, max pressure %.0f MPa%s'\n"
                "plot 'load_distribution.csv' every ::1 using (strcol(3) eq '%s' && $9 > 0 ? $6 : 1/0):7:10 "
                "with points pt 7 ps 0.6 lc palette\n",
                half_name[h], r->load_share[h], r->pressure_max[h] * 1e-6, r->edge_positions[h] ? ", edge loading" : "",
                half_name[h]);
        n += snprintf(script + n, sizeof script - n, "unset multiplot\nunset output\nset autoscale\n");
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '.lte%s.tmp'\n"
            "set multiplot layout 1,2 title 'Loaded transmission error (Eq. 12) and mesh stiffness (Eq. 14)'\n"
            "set xlabel 'pinion angle (deg)'\nset ylabel 'arc-seconds of the gear, about the mean'\n"
            "set key on bottom right\nset title 'LTE %.4f arcsec p-p (mean %.4f)'\n"
            "plot 'lte.csv' every ::1 using 1:($2 - %.10g) with linespoints pt 7 ps 0.5 lw 2 title 'LTE'",
            fmt[fi][0], fmt[fi][1], r->lte_pp_arcsec, r->lte_mean_arcsec, r->lte_mean_arcsec);
        for (int h = 0; h < r->halves; h++) {
            double gm = 0;
            for (int k = 0; k < r->npos; k++)
                gm += r->gte_arcsec[h][k] / r->npos;
            n += snprintf(script + n, sizeof script - n, ", 'lte.csv' every ::1 using 1:($%d - %.10g) with lines "
                          "lw 1.5 dt %d title 'GTE %s (TCA)'", 4 + 8 * h, gm, 2 + h, half_name[h]);
        }
        n += snprintf(script + n, sizeof script - n,
            "\nset ylabel 'mesh stiffness (N/um)'\nset title 'mesh stiffness of each half'\nplot ");
        for (int h = 0; h < r->halves; h++)
            n += snprintf(script + n, sizeof script - n, "%s'lte.csv' every ::1 using 1:($%d*1e-6) with "
                          "linespoints pt 7 ps 0.5 title '%s half'", h ? ", " : "", 8 + 8 * h, half_name[h]);
        n += snprintf(script + n, sizeof script - n, "\nunset multiplot\nunset output\n");
    }
    if (n >= (int)sizeof script)
        return gd_error_set(err, GD_ERR_INTERNAL, "gnuplot script too long");
    static const char *names[] = {"load_distribution", "lte"};
    return gd_gnuplot_draw(dir, script, names, 2, err);
}

void cli_ltca_pictures(const cli_case_args *a, const gd_case *c, const void *result, gd_run_dir *out,
                       const char **note)
{
    if (gd_gnuplot_wanted(c->plots, note)) {
        gd_error perr = {0};
        gd_status pst = draw(gd_run_dir_stage(out), result, &perr);
        static const char *pics[] = {"load_distribution.png", "load_distribution.svg", "lte.png", "lte.svg"};
        gd_gnuplot_drawn(pst, &perr, pics, 4, out);
    }
}

void cli_ltca_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    const gd_ltca_result *r = result;
    if (a->quiet)
        return;
    /* ISO 6336-1's mean mesh stiffness of one mesh, beside LTCA's (the same as check's default) */
    double iso = NAN;
    gd_geometry g;
    gd_error e = {0};
    const gd_pair pair = gd_pair_from_case(c);
    if (gd_geometry_compute(&pair, &g, &e) == GD_OK)
        iso = gd_iso6336_mesh_stiffness(&pair, &g);
    printf("%s: LTCA, %d positions, %d slices per half, %s pinion, %.6g N m: LTE %.6g arcsec p-p\n", dir, r->npos,
           r->nslices, r->floating ? "floating" : "fixed", r->torque_nm, r->lte_pp_arcsec);
    for (int h = 0; h < r->halves; h++) {
        printf("  %-5s mean mesh stiffness %.6g N/m (%.4g .. %.4g; ISO 6336-1 %.4g), load share %.4f, max pressure "
               "%.0f MPa, edge loading %s", half_name[h], r->stiffness_mean[h], r->stiffness_min[h],
               r->stiffness_max[h], iso, r->load_share[h], r->pressure_max[h] * 1e-6, r->edge_positions[h] ? "yes" : "no");
        if (r->edge_positions[h])
            printf(" at %d of %d positions (face-end line load up to %.3g x its line's mean)", r->edge_positions[h],
                   r->npos, r->edge_ratio_max[h]);
        if (r->tip_positions[h])
            printf(", tip contact at %d of %d positions", r->tip_positions[h], r->npos);
        printf("\n");
    }
    printf("  %ld active-set iterations, largest residual %.3g m, %.3f s\n", r->iterations, r->max_residual,
           r->wall_s);
}
