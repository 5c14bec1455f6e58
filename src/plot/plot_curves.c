/* The picture of a continuation's curves in two parameters (curves.png, .svg; continuation.parameter2):
 * every curve in the plane of the two keys, one colour and dash per kind (fold, period doubling,
 * grazing), the bifurcation each starts from marked, the codimension-two points of codim2.csv marked
 * and labelled (CP, FF, GF, ...: gd_codim2_label), the box of the two ranges dotted grey inside a
 * margin (a curve ends on the box). Drawn by gnuplot from curves.csv, in the style of figure.h. */
#include "figure.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CW 1200
#define CH 760

static void plot_one(gd_plot_script *s, int svg, const gd_case *c, const gd_contin_result *res)
{
    gd_qty q1, q2;
    gd_qty_key(res->parameter, &q1);
    gd_qty_key(res->parameter2, &q2);
    char xl[200], yl[200], title[400] = "", n1[140], n2[140];
    gd_qty_label(&q1, xl, sizeof xl);
    gd_qty_label(&q2, yl, sizeof yl);
    gd_gp_text(q1.name, n1, sizeof n1);
    gd_gp_text(q2.name, n2, sizeof n2);
    if (c->title[0])
        gd_gp_title(c->title, title, sizeof title);
    double x0, x1, y0, y1;
    gd_pad(fmin(c->cont_from, c->cont_to), fmax(c->cont_from, c->cont_to), 0.03, 0, &x0, &x1);
    gd_pad(fmin(c->cont_from2, c->cont_to2), fmax(c->cont_from2, c->cont_to2), 0.04, 0, &y0, &y1);
    gd_fig_begin(s, svg, CW, CH, "curves");
    /* the codimension-two points' labels: one per point (the same point found from two curves, or
     * points of different kinds at one place, share one label: "CP", "GF, DG") */
    static const char *c2_words[] = {"cusp", "fold-flip", "1:1", "1:2", "1:3", "1:4", "grazing on a fold",
                                     "grazing on a period doubling", "grazing on a Neimark-Sacker point",
                                     "double grazing"};
    int c2_present[GD_C2_DOUBLE_GRAZING + 1] = {0}, nc2 = 0, nl = 0;
    double dx = 0.01 * (x1 - x0), dy = 0.01 * (y1 - y0);
    struct { double x, y; char text[40]; } lab[64];
    for (int i = 0; i < res->ncurves; i++)
        for (int j = 0; j < res->curve[i].cv.nc2; j++) {
            const gd_codim2 *c2 = &res->curve[i].cv.c2[j];
            double x = gd_contin_value(res, c2->p1), y = c2->p2 * res->scale2;
            const char *t = gd_codim2_label(c2->kind);
            nc2++;
            c2_present[c2->kind] = 1;
            int l = 0;
            while (l < nl && !(fabs(lab[l].x - x) < dx && fabs(lab[l].y - y) < dy))
                l++;
            if (l == nl) {
                if (nl == 64)
                    continue;
                lab[nl].x = x;
                lab[nl].y = y;
                snprintf(lab[nl++].text, sizeof lab[0].text, "%s", t);
            } else if (!strstr(lab[l].text, t) && strlen(lab[l].text) + strlen(t) + 3 < sizeof lab[l].text) {
                strcat(lab[l].text, ", ");
                strcat(lab[l].text, t);
            }
        }
    for (int l = 0; l < nl; l++)
        gd_plot_printf(s, "set label %d '%s' at %.12g, %.12g offset character 1.2, 0.9 left front\n", l + 1,
                          lab[l].text, lab[l].x, lab[l].y);
    gd_plot_printf(s, "set title '%s%sfolds, period doublings and grazings against the %s and the %s'\n", title,
                      title[0] ? "' . \"\\n\" . '" : "", n1, n2);
    gd_plot_printf(s, "set xlabel '%s'\nset ylabel '%s'\nset offsets 0, 0, 0, 0\n"
                         "set xrange [%.12g:%.12g]\nset yrange [%.12g:%.12g]\n"
                         "set lmargin 12\nset rmargin 4\nset tmargin 5\nset bmargin 8\n"
                         "set key at screen 0.5, screen 0.02 center bottom horizontal samplen 3 spacing %.4f\n",
                      xl, yl, x0, x1, y0, y1, GD_KEY_SPACING(svg, 1.2));
    /* the box of the two ranges, where the curves end */
    gd_plot_printf(s, "set object 1 rect from %.12g, %.12g to %.12g, %.12g behind fs empty border lc rgb "
                         "'#999999' dt 3 lw 1\n",
                      fmin(c->cont_from, c->cont_to), fmin(c->cont_from2, c->cont_to2), fmax(c->cont_from, c->cont_to),
                      fmax(c->cont_from2, c->cont_to2));
    /* fold: orange, solid; period doubling: blue, dashed; grazing: bluish green, dotted (Okabe-Ito) */
    static const struct { const char *label; int colour, dt; } kinds[] = {
        {"fold", 1, 1}, {"period doubling", 4, 2}, {"grazing", 3, 3}};
    gd_plot_printf(s, "plot ");
    const char *sep = "";
    for (int i = 0; i < res->ncurves; i++) {
        int k = res->curve[i].cv.kind == GD_CURVE_FOLD ? 0 : res->curve[i].cv.kind == GD_CURVE_PERIOD_DOUBLING ? 1 : 2;
        gd_plot_printf(s, "%s'curves.csv' using 7:($1 == %d ? $8 : 1/0) with lines lw 2.2 dt %d lc rgb '%s' notitle",
                          sep, i, kinds[k].dt, gd_colour[kinds[k].colour]);
        sep = ", \\\n  ";
    }
    int kind_present[3] = {0};
    for (int i = 0; i < res->ncurves; i++)
        kind_present[res->curve[i].cv.kind == GD_CURVE_FOLD ? 0 : res->curve[i].cv.kind == GD_CURVE_PERIOD_DOUBLING ? 1 : 2] = 1;
    for (int k = 0; k < 3; k++)
        if (kind_present[k]) /* the key names the kinds drawn */
            gd_plot_printf(s, "%s1/0 with lines lw 2.2 dt %d lc rgb '%s' title '%s'", sep, kinds[k].dt,
                          gd_colour[kinds[k].colour], kinds[k].label);
    gd_plot_printf(s, "%s'curves.csv' using 7:($6 == 0 ? $8 : 1/0) with points pt 7 ps 1.1 lc rgb '%s' "
                         "title 'start: a bifurcation of a one-parameter branch'",
                      sep, gd_colour[0]);
    if (nc2 > 0) {
        /* the codimension-two points: an open diamond larger than the starts, drawn after them */
        char key[600];
        int n = snprintf(key, sizeof key, "codimension-two point:"), first = 1;
        for (int k = 0; k <= GD_C2_DOUBLE_GRAZING && n < (int)sizeof key; k++)
            if (c2_present[k]) {
                n += snprintf(key + n, sizeof key - (size_t)n, "%s %s %s", first ? "" : ",", gd_codim2_label(k),
                              c2_words[k]);
                first = 0;
            }
        gd_plot_printf(s, "%s'codim2.csv' using 6:7 with points pt 12 ps 2.2 lw 2 lc rgb '%s' title '%s'", sep,
                          gd_colour[0], key);
    }
    gd_plot_printf(s, "\n");
    gd_fig_end(s, 0);
}

void gd_plot_curves(const gd_plotter *p, const gd_case *c, const gd_contin_result *res)
{
    if (res->ncurves == 0)
        return;
    gd_plot_script s = {0};
    plot_one(&s, 0, c, res);
    plot_one(&s, 1, c, res);
    static const char *names[] = {"curves"};
    gd_plot_draw(p, &s, names, 1, "pictures not drawn");
}
