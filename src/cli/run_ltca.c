/* The `ltca` analysis on the command line: pictures of the load distribution on the unrolled
 * flank and of the LTE, GTE and mesh stiffness, and the summary lines (docs/ltca.md). */
#include "cli.h"
#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *half_name[2] = {"left", "right"};

/* Pictures: the load distribution on the unrolled pinion flank of each half over the cycle (line
 * load in colour: the loaded contact pattern) and the LTE, GTE and mesh stiffness curves. */
static gd_status draw(const char *dir, const gd_ltca_result *r, gd_error *err)
{
    int H = r->halves;
    /* fixed ranges (the flank), so that a half without load still draws */
    double zl = INFINITY, zh = -INFINITY, rl = INFINITY, rh = -INFINITY, qmax = 0;
    for (int i = 0; i < r->first[r->npos]; i++) {
        qmax = fmax(qmax, r->points[i].line_load * 1e-3);
        zl = fmin(zl, r->points[i].z1);
        zh = fmax(zh, r->points[i].z1);
        rl = fmin(rl, r->points[i].rho1);
        rh = fmax(rh, r->points[i].rho1);
    }
    double za, zb, ra, rb;
    cli_pad(zl * 1e3, zh * 1e3, 0.05, 0, &za, &zb);
    cli_pad(rl * 1e3, rh * 1e3, 0.07, 0, &ra, &rb);
    gd_gnuplot_script s = {0};
    for (int fi = 0; fi < 2; fi++) {
        cli_fig_begin(&s, fi, H > 1 ? 1400 : 820, 660, "load_distribution");
        gd_gnuplot_printf(&s, "set multiplot layout 1,%d title 'Load distribution on the unrolled pinion flank over one "
                              "mesh cycle (%d positions, %.0f N m)'\n",
                          H, r->npos, r->torque_nm);
        gd_gnuplot_printf(&s, "set xlabel 'face position from the middle of the %s z (mm)'\nset ylabel 'roll length "
                              "(mm)'\nset cblabel 'line load (N/mm)' offset 1.2,0\nset cbtics out\n",
                          H > 1 ? "half" : "face");
        cli_palette_viridis(&s, 0, 0.8);
        /* one colour scale for both halves, its bar beside the last */
        gd_gnuplot_printf(&s, "unset key\nset xrange [%.6g:%.6g]\nset yrange [%.6g:%.6g]\nset cbrange [0:%.6g]\n", za, zb,
                          ra, rb, qmax > 0 ? qmax : 1);
        for (int h = 0; h < H; h++) {
            /* panels of one width, one colour scale: its bar beside the last */
            cli_flank_panel(&s, h, H);
            gd_gnuplot_printf(&s, "set title '%s: load share %.3f, largest pressure %.0f MPa%s'\n",
                              H > 1 ? cli_half_words(h, H) : "the pair", r->load_share[h], r->pressure_max[h] * 1e-6,
                              r->edge_positions[h] ? ", edge loading" : "");
            gd_gnuplot_printf(&s, "plot 'load_distribution.csv' using (strcol('half') eq '%s' && column('load_n') > 0 ? "
                                  "column('face_mm') : 1/0):'roll_mm':'line_load_n_per_mm' with points pt 7 ps 0.6 "
                                  "lc palette\n",
                              half_name[h]);
        }
        cli_fig_end(&s, 1);
        cli_fig_begin(&s, fi, 1400, 680, "lte");
        gd_gnuplot_printf(&s, "set multiplot layout 1,2 title 'Loaded transmission error and mesh stiffness over one "
                              "mesh cycle, %.0f N m'\n", r->torque_nm);
        gd_gnuplot_printf(&s, "set xlabel 'pinion angle φ_1 (deg)'\nset ylabel 'transmission error about its mean, "
                              "gear (arcsec)'\nset key outside below horizontal\n");
        gd_gnuplot_printf(&s, "set title 'LTE %.4g arcsec peak-to-peak about its mean %.4g arcsec'\n", r->lte_pp_arcsec,
                          r->lte_mean_arcsec);
        gd_gnuplot_printf(&s, "plot 'lte.csv' using 'phi1_deg':(column('lte_arcsec') - %.10g) with linespoints pt 7 "
                              "ps 0.6 lw 2 lc rgb '%s' title 'LTE'",
                          r->lte_mean_arcsec, cli_colour[0]);
        for (int h = 0; h < H; h++) {
            double gm = 0;
            for (int k = 0; k < r->npos; k++)
                gm += r->gte_arcsec[h][k] / r->npos;
            gd_gnuplot_printf(&s, ", 'lte.csv' using 'phi1_deg':(column('gte_%s_arcsec') - %.10g) with lines lw 1.5 "
                                  "dt %d lc rgb '%s' title 'GTE%s%s (TCA)'",
                              half_name[h], gm, 2 + h, cli_colour[4 + h], H > 1 ? ", " : "",
                              cli_half_words(h, H));
        }
        gd_gnuplot_printf(&s, "\nset ylabel 'mesh stiffness k (N/µm)'\nset title 'mesh stiffness of %s'\nplot ",
                          H > 1 ? "each half" : "the pair");
        for (int h = 0; h < H; h++)
            gd_gnuplot_printf(&s, "%s'lte.csv' using 'phi1_deg':(column('stiffness_%s_n_per_m')*1e-6) with linespoints "
                                  "pt %d ps 0.6 dt %d lc rgb '%s' title '%s'",
                              h ? ", " : "", half_name[h], h ? 6 : 7, h ? 2 : 1, cli_colour[4 + h],
                              H > 1 ? cli_half_words(h, H) : "the pair");
        gd_gnuplot_printf(&s, "\n");
        cli_fig_end(&s, 1);
    }
    if (s.bad) {
        free(s.p);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the gnuplot script");
    }
    static const char *names[] = {"load_distribution", "lte"};
    gd_status st = gd_gnuplot_draw(dir, s.p, names, 2, err);
    free(s.p);
    return st;
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
