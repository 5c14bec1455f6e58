/* The picture of a continuation's curves in two parameters (curves.png, .svg; continuation.parameter2):
 * every curve in the plane of the two keys, one colour and dash per kind (fold, period doubling,
 * grazing), the bifurcation each starts from marked. Drawn by gnuplot from curves.csv. */
#include "cli.h"

#include <stdlib.h>
#include <string.h>

static void plot_one(gd_gnuplot_script *s, const gd_case *c, const gd_contin_result *res, const char *term,
                     const char *ext)
{
    const char *k1 = strchr(res->parameter, '.') + 1, *k2 = strchr(res->parameter2, '.') + 1;
    gd_gnuplot_printf(s, "set terminal %s\nset output '.curves%s.tmp'\n", term, ext);
    gd_gnuplot_printf(s, "set title \"%s%sfolds, period doublings and grazings in (%s, %s)\" noenhanced\n",
                      c->title, c->title[0] ? "\\n" : "", res->parameter, res->parameter2);
    gd_gnuplot_printf(s, "set xlabel '%s' noenhanced\nset ylabel '%s' noenhanced\nset grid\nset key below horizontal "
                         "noenhanced\nset xrange [%.12g:%.12g]\nset yrange [%.12g:%.12g]\n",
                      k1, k2, c->cont_from, c->cont_to, c->cont_from2, c->cont_to2);
    static const struct { const char *kind, *label; const char *colour; int dt; } kinds[] = {
        {"fold", "fold", "#1f5fbf", 1}, {"period-doubling", "period doubling", "#c0392b", 2},
        {"grazing", "grazing", "#2e8b57", 4}};
    gd_gnuplot_printf(s, "plot ");
    const char *sep = "";
    for (int i = 0; i < res->ncurves; i++) {
        int k = res->curve[i].cv.kind == GD_CURVE_FOLD ? 0 : res->curve[i].cv.kind == GD_CURVE_PERIOD_DOUBLING ? 1 : 2;
        gd_gnuplot_printf(s, "%s'curves.csv' every ::1 using 7:($1 == %d ? $8 : 1/0) with lines lw 2 dt %d "
                             "lc rgb '%s' notitle", sep, i, kinds[k].dt, kinds[k].colour);
        sep = ", \\\n  ";
    }
    for (int k = 0; k < 3; k++)
        gd_gnuplot_printf(s, "%s1/0 with lines lw 2 dt %d lc rgb '%s' title '%s'", sep, kinds[k].dt,
                          kinds[k].colour, kinds[k].label);
    gd_gnuplot_printf(s, "%s'curves.csv' every ::1 using 7:($6 == 0 ? $8 : 1/0) with points pt 7 ps 1.2 lc rgb "
                         "'black' title 'start (a bifurcation of a branch)'\nunset output\n", sep);
}

gd_status cli_curves_draw(const char *dir, const gd_case *c, const gd_contin_result *res, gd_error *err)
{
    if (res->ncurves == 0)
        return GD_OK;
    gd_gnuplot_script s = {0};
    gd_gnuplot_printf(&s, "set datafile separator ','\nset datafile missing 'NaN'\n");
    plot_one(&s, c, res, "pngcairo size 1200,720 font ',11'", ".png");
    plot_one(&s, c, res, "svg size 1200,720 dynamic font 'sans,11'", ".svg");
    if (s.bad) {
        free(s.p);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the curves' gnuplot script");
    }
    static const char *names[] = {"curves"};
    gd_status st = gd_gnuplot_draw(dir, s.p, names, 1, err);
    free(s.p);
    return st;
}
