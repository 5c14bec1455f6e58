/* The pictures of `compare-optimizers` (docs/optimisation.md section 7): the convergence and the
 * runtime distributions. */
#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *obj_name(const gd_compare_entry *q) { return gd_opt_objective_name(q->objective); }

/* The objective as a picture names it. */
static const char *obj_words(const gd_compare_entry *q)
{
    if (q->gear)
        return q->nobj == 2 ? "LTE and dynamic response of the gear pair" : "LTE of the gear pair";
    return obj_name(q);
}


/* The panel of problem j (or the pooled panel) on a grid of cols columns: its frame in screen
 * fractions. */
typedef struct grid {
    int cols, rows, legend_slot; /* legend_slot: the grid cell of the shared key, -1: a column of its own */
    int W, H;
    double pw, ph;               /* a cell, pixels */
} grid;

static void panel_box(const grid *g, int cell, double *l, double *r, double *b, double *t)
{
    int c = cell % g->cols, row = cell / g->cols;
    double pw = g->pw, ph = g->ph, left = 20;
    *l = (left + c * pw + 80) / g->W;
    *r = (left + (c + 1) * pw - 25) / g->W;
    *t = 1 - (60 + row * ph + 40) / g->H;
    *b = 1 - (60 + (row + 1) * ph - 55) / g->H;
}

static void draw(const gd_plotter *pl, const gd_compare_outcome *C, const char *hv_unit)
{
    const gd_opt_compare_result *r0 = &C->p[0].res;
    gd_plot_script s = {0};
    int gear = C->p[0].gear != NULL;
    int two = C->p[0].nobj == 2; /* every problem then has two objectives: hypervolumes (section 13) */
    for (int fi = 0; fi < 2; fi++) {
        for (int pic = 0; pic < 2; pic++) {
            int panels = pic == 0 ? C->n : C->n + (C->n > 1);
            grid g;
            g.cols = panels < 3 ? panels : 3;
            g.rows = (panels + g.cols - 1) / g.cols;
            g.legend_slot = g.cols * g.rows > panels ? panels : -1;
            g.pw = panels == 1 ? 760 : 560;
            g.ph = panels == 1 ? 560 : 430;
            g.W = (int)(20 + g.cols * g.pw + (g.legend_slot < 0 ? 230 : 0));
            g.H = (int)(60 + g.rows * g.ph);
            gd_fig_begin(&s, fi, g.W, g.H, pic ? "ecdf" : "convergence");
            /* one panel is too narrow for the title on one line: two */
            const char *brk = panels == 1 ? "\\n" : " ";
            if (pic == 0 && two)
                gd_plot_printf(&s, "set multiplot title \"Convergence: the median over %d runs of the hypervolume of "
                                      "the reference HV_{ref} minus that of the front found;%sbars: its quartiles at the "
                                      "budget of %ld evaluations\"\n", r0->runs, brk, r0->budget);
            else if (pic == 0)
                gd_plot_printf(&s, "set multiplot title \"Convergence: the median over %d runs of the best value found "
                                      "minus the reference value f_{ref};%sbars: its quartiles at the budget of %ld "
                                      "evaluations\"\n", r0->runs, brk, r0->budget);
            else
                gd_plot_printf(&s, "set multiplot title 'Runtime distributions: the fraction of (run, target) pairs "
                                      "reached, %d runs, %ld evaluations each'\n", r0->runs, r0->budget);
            gd_plot_printf(&s, "set logscale x\nset xlabel 'objective evaluations'\nset xrange [1:%.6g]\n",
                              pic == 0 ? r0->budget * 1.8 : (double)r0->budget);
            if (pic == 0 && two)
                gd_plot_printf(&s, "set logscale y\nset format y '%%g'\nset ylabel 'hypervolume below the "
                                      "reference HV_{ref} - HV (%s)'\n", gear ? hv_unit : "-");
            else if (pic == 0)
                gd_plot_printf(&s, "set logscale y\nset format y '%%g'\nset ylabel 'best value minus the reference "
                                      "f - f_{ref} (%s)'\n", gear ? "arcsec" : "-");
            else
                gd_plot_printf(&s, "set ylabel 'fraction of (run, target) pairs reached (-)'\n"
                                      "set yrange [-0.04:1.04]\nset ytics 0,0.2,1\n");
            /* the key, shared: in the grid's empty cell or in a column of its own */
            double kx, ky;
            if (g.legend_slot >= 0) {
                double l, rr, b, t;
                panel_box(&g, g.legend_slot, &l, &rr, &b, &t);
                kx = l;
                ky = t;
            } else {
                kx = (20.0 + g.cols * g.pw + 10) / g.W;
                ky = 1 - 100.0 / g.H;
            }
            for (int j = 0; j < panels; j++) {
                int pooled = j == C->n;
                const gd_compare_entry *q = pooled ? NULL : &C->p[j];
                const gd_opt_compare_result *r = pooled ? r0 : &q->res;
                double l, rr, b, t;
                panel_box(&g, j, &l, &rr, &b, &t);
                gd_plot_printf(&s, "set lmargin at screen %.5f\nset rmargin at screen %.5f\nset bmargin at screen %.5f\n"
                                      "set tmargin at screen %.5f\n", l, rr, b, t);
                if (j == 0)
                    gd_plot_printf(&s, "set key at screen %.5f,%.5f left top vertical Left reverse samplen 3 "
                                          "spacing 1.3 title 'optimiser'\n", kx, ky);
                else
                    gd_plot_printf(&s, "unset key\n");
                if (pooled)
                    gd_plot_printf(&s, "set title 'all %d problems pooled'\n", C->n);
                else if (pic == 0 && two)
                    gd_plot_printf(&s, "set title '%s, d = %d: HV_{ref} = %.4g (%s)'\n", obj_words(q), q->dim,
                                   q->hv_ref[0] * q->hv_ref[1] - r->f_ref,
                                   r->f_ref_known ? "the true front" : "the best run");
                else if (pic == 0)
                    gd_plot_printf(&s, "set title '%s, d = %d%s: f_{ref} = %.4g (%s)'\n", obj_words(q), q->dim,
                                      q->shift > 0 ? ", shifted" : "", r->f_ref, r->f_ref_known ? "the minimum" : "best found");
                else
                    gd_plot_printf(&s, "set title '%s, d = %d%s: %d targets from %.3g to %.3g'\n", obj_words(q), q->dim,
                                      q->shift > 0 ? ", shifted" : "", r->ntargets, r->targets[0],
                                      r->targets[r->ntargets - 1]);
                if (pic == 0) {
                    /* a logarithmic axis over less than a decade and a half labels one power of ten or
                     * none: label 1, 2 and 5 times the powers of ten within the data's range */
                    double ylo = INFINITY, yhi = 0, yq[3];
                    for (int a = 0; a < r->nalgs; a++) {
                        gd_opt_compare_quartiles(r, a, r->budget, yq);
                        for (int k = 0; k < 3; k++)
                            if (yq[k] > 0)
                                ylo = fmin(ylo, yq[k]);
                        gd_opt_compare_quartiles(r, a, 1, yq);
                        yhi = fmax(yhi, yq[2]);
                    }
                    gd_plot_printf(&s, "set ytics autofreq\n");
                    if (yhi > 0 && ylo < yhi && yhi / ylo < 30) {
                        gd_plot_printf(&s, "set ytics add (");
                        int first = 1;
                        for (double d = pow(10, floor(log10(ylo))); d <= yhi * 1.0001; d *= 10)
                            for (int m = 1; m <= 5; m += m == 1 ? 1 : 3) /* 1, 2, 5 */
                                if (m * d >= ylo / 1.0001 && m * d <= yhi * 1.0001) {
                                    gd_plot_printf(&s, "%s%.6g", first ? "" : ", ", m * d);
                                    first = 0;
                                }
                        gd_plot_printf(&s, ")\n");
                        if (first) /* none in the range: an empty list is a syntax error */
                            gd_plot_printf(&s, "set ytics autofreq\n");
                    }
                    /* the quartiles at the budget, each optimiser's bar a little to the right of the last */
                    gd_plot_printf(&s, "$IQR%d << EOD\nx,y,lo,hi\n", j);
                    for (int a = 0; a < r->nalgs; a++) {
                        const gd_opt_alg_stats *S = &r->stats[a];
                        double m = S->median - r->f_ref, lo = S->q1 - r->f_ref, hi = S->q3 - r->f_ref;
                        if (m > 0 && lo > 0 && hi > 0)
                            gd_plot_printf(&s, "%.6g,%.10g,%.10g,%.10g\n", r->budget * pow(1.05, a + 1), m, lo, hi);
                        else
                            gd_plot_printf(&s, "NaN,NaN,NaN,NaN\n");
                    }
                    gd_plot_printf(&s, "EOD\n");
                }
                gd_plot_printf(&s, "plot ");
                for (int a = 0; a < r->nalgs; a++) {
                    const char *an = gd_opt_algorithm_name(r->stats[a].alg);
                    const char *colour;
                    int dash;
                    gd_series_style(a, &colour, &dash);
                    /* later curves thinner: where two coincide both show */
                    double lw = 3.2 - 1.8 * a / (r->nalgs > 1 ? r->nalgs - 1 : 1);
                    char sel[256], title[96];
                    snprintf(sel, sizeof sel, "strcol('objective') eq '%s' && column('dimension') == %d && "
                                              "strcol('optimizer') eq '%s'",
                             pooled ? "all" : obj_name(q), pooled ? 0 : q->dim, an);
                    if (j == 0)
                        snprintf(title, sizeof title, "title '%s'", gd_optimizer_words(r->stats[a].alg));
                    else
                        snprintf(title, sizeof title, "notitle");
                    if (pic == 0)
                        gd_plot_printf(&s, "%s'convergence.csv' using (%s ? column('evaluations') : 1/0):"
                                              "(column('median_delta_f') > 0 ? column('median_delta_f') : 1/0) with lines "
                                              "lw %.2f dt %d lc rgb '%s' %s, $IQR%d every ::%d::%d using 1:2:3:4 with "
                                              "yerrorbars pt 7 ps 0.6 lw 1.5 lc rgb '%s' notitle",
                                          a ? ", " : "", sel, lw, dash, colour, title, j, a, a, colour);
                    else
                        gd_plot_printf(&s, "%s'ecdf.csv' using (%s ? column('evaluations') : 1/0):'fraction' with "
                                              "steps lw %.2f dt %d lc rgb '%s' %s",
                                          a ? ", " : "", sel, lw, dash, colour, title);
                }
                gd_plot_printf(&s, "\n");
            }
            gd_fig_end(&s, 1);
        }
    }
    static const char *names[2] = {"convergence", "ecdf"};
    gd_plot_draw(pl, &s, names, 2, "pictures not drawn");
}
void gd_plot_compare(const gd_plotter *p, const gd_case *c, const gd_compare_outcome *o)
{
    if (gd_plot_wanted(p, c->plots)) /* the gear's hypervolume: the LTE times the dynamic response */
        draw(p, o, c->opt_dynamic_response == GD_DYN_DTE_PP ? "arcsec µm" : "arcsec m/s²");
}
