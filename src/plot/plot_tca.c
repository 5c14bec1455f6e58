/* The pictures of `tca`: the contact pattern on the unrolled flank and the GTE (contact_pattern, gte). */
#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *half_name[2] = {"left", "right"};

/* A GTE flat to 1e-9 of the gear's angular pitch is round-off: an exact involute pair in line
 * contact. */
static int gte_flat(const gd_case *c, const gd_tca_result *r, int h)
{
    double pitch = 360.0 * 3600.0 / (c->teeth_gear > 0 ? c->teeth_gear : 1);
    return !(r->gte_pp_arcsec[h] > 1e-9 * pitch);
}

/* Pictures: contact pattern on the unrolled flank of each half (face position across, roll length
 * up, separation in colour, the paint thickness as the edge of the dark pattern, the path of the
 * first contact as points unless the flanks touch along whole lines) and the GTE curves. */
static void draw(const gd_plotter *pl, const gd_case *c, const gd_tca_result *r)
{
    double p = c->paint_thickness_um;
    int H = r->halves, flat = 1;
    for (int h = 0; h < H; h++)
        flat &= gte_flat(c, r, h);
    char face[160];
    snprintf(face, sizeof face, "face position from the middle of the %s z (mm)", H > 1 ? "half" : "face");
    gd_plot_script s = {0};
    for (int fi = 0; fi < 2; fi++) {
        gd_fig_begin(&s, fi, H > 1 ? 1400 : 820, 660, "contact_pattern");
        /* on the single pair's narrower picture the title takes two lines */
        gd_plot_printf(&s, "set multiplot layout 1,%d title 'Contact pattern on the unrolled pinion flank:%sflank "
                              "points closer than the paint thickness %.3g µm to the mating flank%s'\n",
                          H, H > 1 ? " " : "' . \"\\n\" . '", p, flat ? "" : " (black: the path of the first contact)");
        gd_plot_printf(&s, "set xlabel '%s'\nset ylabel 'roll length (mm)'\nset cbrange [0:%.6g]\n"
                              "set cblabel 'least separation (µm)' offset 1.2,0\nset cbtics out\n"
                              "set palette defined (0 '#7f0000', %.6g '#d7301f', %.6g '#fdd49e', %.6g '#f7f7f7')\n"
                              "unset key\nset grid front\n",
                          face, 8 * p, p, p * 1.0001, 8 * p);
        for (int h = 0; h < H; h++) {
            char gte[160];
            /* panels of one width, one colour scale: its bar beside the last */
            gd_flank_panel(&s, h, H);
            if (gte_flat(c, r, h))
                snprintf(gte, sizeof gte, "GTE zero to round-off, line contact");
            else
                snprintf(gte, sizeof gte, "GTE %.4g arcsec peak-to-peak", r->gte_pp_arcsec[h]);
            gd_plot_printf(&s, "set title '%s%s%s%s'\n", H > 1 ? gd_half_words(h, H) : "the pair", ": ", gte,
                              r->edge_kinds[h] ? ", edge contact" : "");
            gd_plot_printf(&s, "plot 'separation_%s.csv' using 'face_mm':'roll_mm':(column('separation_um') > %.6g ? "
                                  "%.6g : column('separation_um')) with image",
                              half_name[h], 8 * p, 8 * p);
            if (!gte_flat(c, r, h))
                gd_plot_printf(&s, ", 'contact_path.csv' using (strcol('half') eq '%s' ? column('pinion_face_mm') : "
                                      "1/0):'pinion_roll_mm' with points pt 7 ps 0.5 lc rgb 'black'",
                                  half_name[h]);
            gd_plot_printf(&s, "\n");
        }
        gd_fig_end(&s, 1);
        gd_fig_begin(&s, fi, 1300, 620, "gte");
        if (flat) {
            double pp = 0;
            for (int h = 0; h < H; h++)
                pp = fmax(pp, r->gte_pp_arcsec[h]);
            gd_plot_printf(&s, "set title 'Geometric transmission error: zero to round-off (%.2g arcsec "
                                  "peak-to-peak), drawn flat'\nset yrange [-1:1]\n", pp);
        } else {
            gd_plot_printf(&s, "set title 'Geometric transmission error over %d mesh cycles, relative to the first "
                                  "position'\n", c->tca_cycles);
        }
        gd_plot_printf(&s, "set xlabel 'pinion angle φ_1 (deg)'\nset ylabel 'geometric transmission error, "
                              "gear (arcsec)'\nset key outside top center horizontal\nplot ");
        for (int h = 0; h < H; h++)
            gd_plot_printf(&s, "%s'gte.csv' using 'phi1_deg':'gte_%s_arcsec' with linespoints pt %d ps 0.6 lw 1.5 dt %d "
                                  "lc rgb '%s' title '%s'",
                              h ? ", " : "", half_name[h], h ? 6 : 7, h ? 2 : 1, gd_colour[h ? 5 : 4],
                              H > 1 ? gd_half_words(h, H) : "the pair");
        gd_plot_printf(&s, "\n");
        gd_fig_end(&s, 0);
    }
    static const char *names[] = {"contact_pattern", "gte"};
    gd_plot_draw(pl, &s, names, 2, "pictures not drawn");
}
void gd_plot_tca(const gd_plotter *p, const gd_case *c, const gd_tca_result *r)
{
    if (gd_plot_wanted(p, c->plots))
        draw(p, c, r);
}
