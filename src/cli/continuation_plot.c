/* The picture of a continuation (continuation.png, .svg): the response against the parameter,
 * stable points joined by solid lines and unstable by dashed ones, one colour per branch, a marker
 * and a label per bifurcation kind, and a finished sweep's points over them when the case names
 * one (continuation.overlay_sweep). Drawn by gnuplot from branch.csv and bifurcations.csv. */
#include "cli.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

/* The columns of the response drawn: in branch.csv (after the 2 n multiplier columns) and in
 * bifurcations.csv; its axis label; the overlay sweep's file and column. */
typedef struct resp_cols {
    int branch_col, bif_col;
    const char *label, *sweep_file, *sweep_col;
} resp_cols;

static resp_cols response_columns(int response, int n)
{
    /* branch.csv: branch, period_n, point, key, p, stable, mu_max, 2n multipliers, then the measures;
     * bifurcations.csv: branch, period_n, kind, key, lo, hi, p, mu_re, mu_im, clearance, the measures */
    static const int offset[] = {0, 4, 3, 7, 8};
    static const char *label[] = {"RMS mesh acceleration (m/s^2)", "largest mesh deflection lambda_L (um)",
                                  "smallest mesh deflection lambda_L (um)",
                                  "lambda_L at mesh phase 0 (dimensionless)",
                                  "dynamic load factor (largest mesh force / static, -)"};
    resp_cols r;
    r.branch_col = 8 + 2 * n + offset[response];
    r.bif_col = 11 + offset[response];
    r.label = label[response];
    r.sweep_file = response == GD_CONT_RESP_POINCARE ? "bifurcation.csv" : "sweep.csv";
    r.sweep_col = response == GD_CONT_RESP_POINCARE ? "lambda_L"
                : response == GD_CONT_RESP_DYNAMIC_LOAD_FACTOR ? "dynamic_load_factor" : "rms_accel_mps2";
    return r;
}

static void plot_one(gd_gnuplot_script *s, const char *overlay, const gd_case *c, const gd_contin_result *res,
                     const char *term, const char *ext)
{
    resp_cols rc = response_columns(c->cont_response, res->n);
    const char *key = strchr(res->parameter, '.') + 1;
    gd_gnuplot_printf(s, "set terminal %s\nset output '.continuation%s.tmp'\n", term, ext);
    gd_gnuplot_printf(s, "set title \"%s%scontinuation in %s: solid stable, dashed unstable\" noenhanced\n",
                      c->title, c->title[0] ? "\\n" : "", res->parameter);
    gd_gnuplot_printf(s, "set xlabel '%s' noenhanced\nset ylabel '%s'\nset grid\nset key outside right top "
                         "noenhanced\nset xrange [%.12g:%.12g]\nset offsets 0, 0, graph 0.06, graph 0.02\n", key, rc.label, c->cont_from, c->cont_to);
    gd_gnuplot_printf(s, "plot ");
    const char *sep = "";
    /* a segment joins consecutive points of branch b: solid when both ends are stable, dashed otherwise */
    for (int b = 0; b < res->nbranches; b++) {
        for (int stable = 1; stable >= 0; stable--) {
            gd_gnuplot_printf(s, "%sk1 = -1, x1 = 0, y1 = 0, s1 = 0, 'branch.csv' every ::1 using (x0 = x1, "
                                 "x1 = $4, y0 = y1, y1 = $%d, k0 = k1, k1 = $1, s0 = s1, s1 = $6, k0 == %d && k1 == %d "
                                 "&& (s0 == 1 && s1 == 1) == %d ? x0 : 1/0):(y0):(x1 - x0):(y1 - y0) with vectors "
                                 "nohead lw 2 dt %d lc %d notitle",
                              sep, rc.branch_col, b, b, stable, stable ? 1 : 2, b + 1);
            sep = ", \\\n  ";
        }
        gd_gnuplot_printf(s, "%s1/0 with lines lw 2 lc %d title 'branch %d: period %d'", sep, b + 1, b,
                          res->branch[b].nper);
    }
    gd_gnuplot_printf(s, "%s1/0 with lines lw 2 dt 2 lc rgb 'black' title 'unstable'", sep);
    static const struct { const char *kind, *label, *mark; int pt; } kinds[] = {
        {"fold", "fold", "F", 7}, {"period-doubling", "period doubling", "PD", 5},
        {"neimark-sacker", "Neimark-Sacker", "NS", 13}, {"contact-change", "contact change (grazing)", "C", 9}};
    for (int k = 0; k < 4; k++)
        gd_gnuplot_printf(s, "%s'bifurcations.csv' every ::1 using 4:(strcol(3) eq '%s' ? $%d : 1/0) with points "
                             "pt %d ps 1.6 lc rgb 'black' title '%s', \\\n  'bifurcations.csv' every ::1 using "
                             "4:(strcol(3) eq '%s' ? $%d : 1/0):('%s') with labels offset 0.8,0.8 notitle",
                          sep, kinds[k].kind, rc.bif_col, kinds[k].pt, kinds[k].label, kinds[k].kind,
                          rc.bif_col, kinds[k].mark);
    if (overlay)
        gd_gnuplot_printf(s, "%s'%s/%s' using 'parameter':(strcol('direction') eq 'up' ? column('%s') : 1/0) with "
                             "points pt 8 ps 0.9 lc rgb '#555555' title 'sweep up', \\\n  '%s/%s' using 'parameter':"
                             "(strcol('direction') eq 'down' ? column('%s') : 1/0) with points pt 10 ps 0.9 lc rgb "
                             "'#555555' title 'sweep down'",
                          sep, overlay, rc.sweep_file, rc.sweep_col, overlay,
                          rc.sweep_file, rc.sweep_col);
    gd_gnuplot_printf(s, "\nunset output\n");
}

gd_status cli_continuation_draw(const char *dir, const gd_case *c, const gd_contin_result *res, gd_error *err)
{
    if (res->nbranches == 0)
        return GD_OK;
    /* gnuplot reads the tables in dir, where it runs; the overlay sweep, named relative to this
     * process's working directory, by its absolute path */
    char *overlay = NULL;
    if (c->cont_overlay_sweep[0] && !(overlay = realpath(c->cont_overlay_sweep, NULL)))
        return gd_error_set(err, GD_ERR_IO, "%s: continuation.overlay_sweep: %s", c->cont_overlay_sweep,
                            strerror(errno));
    gd_gnuplot_script s = {0};
    gd_gnuplot_printf(&s, "set datafile separator ','\nset datafile missing 'NaN'\n");
    plot_one(&s, overlay, c, res, "pngcairo size 1200,720 font ',11'", ".png");
    plot_one(&s, overlay, c, res, "svg size 1200,720 dynamic font 'sans,11'", ".svg");
    free(overlay);
    if (s.bad) {
        free(s.p);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the continuation's gnuplot script");
    }
    static const char *names[] = {"continuation"};
    gd_status st = gd_gnuplot_draw(dir, s.p, names, 1, err);
    free(s.p);
    return st;
}
