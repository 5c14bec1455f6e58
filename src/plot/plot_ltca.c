/* The pictures of `ltca`: the load distribution on the unrolled flank and the LTE, GTE and mesh
 * stiffness (load_distribution, lte; docs/ltca.md). */
#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *half_name[2] = {"left", "right"};

/* Pictures: the load distribution on the unrolled pinion flank of each half over the cycle (line
 * load in colour: the loaded contact pattern) and the LTE, GTE and mesh stiffness curves. */
static void draw(const gd_plotter *pl, const gd_ltca_result *r)
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
    gd_pad(zl * 1e3, zh * 1e3, 0.05, 0, &za, &zb);
    gd_pad(rl * 1e3, rh * 1e3, 0.07, 0, &ra, &rb);
    gd_plot_script s = {0};
    for (int fi = 0; fi < 2; fi++) {
        gd_fig_begin(&s, fi, H > 1 ? 1400 : 820, 660, "load_distribution");
        gd_plot_printf(&s, "set multiplot layout 1,%d title 'Load distribution on the unrolled pinion flank over one "
                              "mesh cycle (%d positions, %.0f N m)'\n",
                          H, r->npos, r->torque_nm);
        gd_plot_printf(&s, "set xlabel 'face position from the middle of the %s z (mm)'\nset ylabel 'roll length "
                              "(mm)'\nset cblabel 'line load (N/mm)' offset 1.2,0\nset cbtics out\n",
                          H > 1 ? "half" : "face");
        gd_palette_viridis(&s, 0, 0.8);
        /* one colour scale for both halves, its bar beside the last */
        gd_plot_printf(&s, "unset key\nset xrange [%.6g:%.6g]\nset yrange [%.6g:%.6g]\nset cbrange [0:%.6g]\n", za, zb,
                          ra, rb, qmax > 0 ? qmax : 1);
        for (int h = 0; h < H; h++) {
            /* panels of one width, one colour scale: its bar beside the last */
            gd_flank_panel(&s, h, H);
            gd_plot_printf(&s, "set title '%s: load share %.3f, largest pressure %.0f MPa%s'\n",
                              H > 1 ? gd_half_words(h, H) : "the pair", r->load_share[h], r->pressure_max[h] * 1e-6,
                              r->edge_positions[h] ? ", edge loading" : "");
            gd_plot_printf(&s, "plot 'load_distribution.csv' using (strcol('half') eq '%s' && column('load_n') > 0 ? "
                                  "column('face_mm') : 1/0):'roll_mm':'line_load_n_per_mm' with points pt 7 ps 0.6 "
                                  "lc palette\n",
                              half_name[h]);
        }
        gd_fig_end(&s, 1);
        gd_fig_begin(&s, fi, 1400, 680, "lte");
        gd_plot_printf(&s, "set multiplot layout 1,2 title 'Loaded transmission error and mesh stiffness over one "
                              "mesh cycle, %.0f N m'\n", r->torque_nm);
        gd_plot_printf(&s, "set xlabel 'pinion angle φ_1 (deg)'\nset ylabel 'transmission error about its mean, "
                              "gear (arcsec)'\nset key outside below horizontal\n");
        gd_plot_printf(&s, "set title 'LTE %.4g arcsec peak-to-peak about its mean %.4g arcsec'\n", r->lte_pp_arcsec,
                          r->lte_mean_arcsec);
        gd_plot_printf(&s, "plot 'lte.csv' using 'phi1_deg':(column('lte_arcsec') - %.10g) with linespoints pt 7 "
                              "ps 0.6 lw 2 lc rgb '%s' title 'LTE'",
                          r->lte_mean_arcsec, gd_colour[0]);
        for (int h = 0; h < H; h++) {
            double gm = 0;
            for (int k = 0; k < r->npos; k++)
                gm += r->gte_arcsec[h][k] / r->npos;
            gd_plot_printf(&s, ", 'lte.csv' using 'phi1_deg':(column('gte_%s_arcsec') - %.10g) with lines lw 1.5 "
                                  "dt %d lc rgb '%s' title 'GTE%s%s (TCA)'",
                              half_name[h], gm, 2 + h, gd_colour[4 + h], H > 1 ? ", " : "",
                              gd_half_words(h, H));
        }
        gd_plot_printf(&s, "\nset ylabel 'mesh stiffness k (N/µm)'\nset title 'mesh stiffness of %s'\nplot ",
                          H > 1 ? "each half" : "the pair");
        for (int h = 0; h < H; h++)
            gd_plot_printf(&s, "%s'lte.csv' using 'phi1_deg':(column('stiffness_%s_n_per_m')*1e-6) with linespoints "
                                  "pt %d ps 0.6 dt %d lc rgb '%s' title '%s'",
                              h ? ", " : "", half_name[h], h ? 6 : 7, h ? 2 : 1, gd_colour[4 + h],
                              H > 1 ? gd_half_words(h, H) : "the pair");
        gd_plot_printf(&s, "\n");
        gd_fig_end(&s, 1);
    }
    static const char *names[] = {"load_distribution", "lte"};
    gd_plot_draw(pl, &s, names, 2, "pictures not drawn");
}
void gd_plot_ltca(const gd_plotter *p, const gd_case *c, const gd_ltca_result *r)
{
    if (gd_plot_wanted(p, c->plots))
        draw(p, r);
}
