/* The picture of an optimize run with two objectives (docs/optimisation.md section 13): the Pareto
 * front of the best run among its evaluations, and for the gear the unmodified flank and the case's own
 * (the evaluations up to twice the hypervolume's reference point); for zdt1 and zdt2 the true front
 * (within the reference point). */
#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void draw(const gd_plotter *pl, const gd_case *c, const gd_optimize_outcome *o)
{
    static const char *names[1] = {"pareto"};
    const gd_opt_pareto_report *P = o->pareto;
    const gd_opt_result *b = &P->res[P->best];
    /* the ranges: the front, the flanks and the reference point */
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int k = 0; k < b->nfront; k++) {
        x0 = fmin(x0, b->front_f[2 * k]);
        x1 = fmax(x1, b->front_f[2 * k]);
        y0 = fmin(y0, b->front_f[2 * k + 1]);
        y1 = fmax(y1, b->front_f[2 * k + 1]);
    }
    for (int j = 0; P->gear && j < 2; j++) {
        x0 = fmin(x0, P->flank_f[j][0]);
        x1 = fmax(x1, P->flank_f[j][0]);
        y0 = fmin(y0, P->flank_f[j][1]);
        y1 = fmax(y1, P->flank_f[j][1]);
    }
    x1 = fmax(x1, P->hv_ref[0]);
    y1 = fmax(y1, P->hv_ref[1]);
    for (long k = 0; P->gear && k < b->evaluations; k++) { /* the gear: the evaluations up to twice the reference */
        const double *f = b->fv_history + (size_t)k * (size_t)(b->nobj + b->naux);
        if (f[0] <= 2 * P->hv_ref[0] && f[1] <= 2 * P->hv_ref[1]) {
            x0 = fmin(x0, f[0]);
            x1 = fmax(x1, f[0]);
            y0 = fmin(y0, f[1]);
            y1 = fmax(y1, f[1]);
        }
    }
    if (!P->gear) { /* the true front from f1 = 0 */
        x0 = fmin(x0, 0.0);
        y0 = fmin(y0, 0.0);
    }
    double xa, xb, ya, yb;
    gd_pad(x0, x1, 0.04, 0, &xa, &xb);
    gd_pad(y0, y1, 0.07, 0, &ya, &yb);
    char what[160];
    if (P->gear)
        snprintf(what, sizeof what, "the LTE and the dynamic response of the flank");
    else
        gd_gp_text(gd_opt_objective_name(o->objective), what, sizeof what);
    gd_plot_script s = {0};
    for (int fi = 0; fi < 2; fi++) {
        gd_fig_begin(&s, fi, 1100, 760, "pareto");
        if (!P->gear) { /* the true front: f2 = 1 - sqrt(f1) (zdt1) or 1 - f1^2 (zdt2) */
            gd_plot_printf(&s, "$TRUE << EOD\nf1,f2\n");
            for (int k = 0; k <= 200; k++) {
                double f1 = k / 200.0;
                gd_plot_printf(&s, "%.6g,%.6g\n", f1, o->objective == GD_OBJ_ZDT1 ? 1 - sqrt(f1) : 1 - f1 * f1);
            }
            gd_plot_printf(&s, "EOD\n");
        }
        if (P->gear)
            gd_plot_printf(&s, "set title \"%s on %s: %d non-dominated points of %ld evaluations,\\nhypervolume "
                               "%.6g within the reference point (%.4g, %.4g)\"\n",
                           gd_optimizer_words(c->opt_algorithm), what, b->nfront, b->evaluations, b->hv,
                           P->hv_ref[0], P->hv_ref[1]);
        else
            gd_plot_printf(&s, "set title \"%s on %s: %d non-dominated points of %ld evaluations,\\nhypervolume %.6g "
                               "within (%.4g, %.4g), the true front's %.6g\"\n",
                           gd_optimizer_words(c->opt_algorithm), what, b->nfront, b->evaluations, b->hv,
                           P->hv_ref[0], P->hv_ref[1], P->true_front_hv);
        /* room for the tick labels, the axis label and the key's rows below (gnuplot's own margin
         * lets the label touch the key) */
        gd_plot_printf(&s, "set bmargin 7\nset xlabel '%s'\nset ylabel '%s'\nset xrange [%.10g:%.10g]\nset yrange [%.10g:%.10g]\n"
                           "set key outside below horizontal spacing %.3f\n",
                       P->label[0], P->label[1], xa, xb, ya, yb, GD_KEY_SPACING(fi, 1.2));
        /* the front's points (for a test problem with the boundary of what they dominate, a staircase:
         * between two points of the front nothing is known), then every evaluation over them */
        gd_plot_printf(&s, "plot 'pareto.csv' using '%s':'%s' with points pt 7 ps 1.1 lc rgb '%s' title 'the Pareto "
                           "front found'", P->column[0], P->column[1], gd_colour[1]);
        if (!P->gear)
            gd_plot_printf(&s, ", '' using '%s':'%s' with steps lw 1.5 lc rgb '%s' notitle, $TRUE using 1:2 with "
                               "lines lw 2 dt 2 lc rgb '%s' title 'the true front'",
                           P->column[0], P->column[1], gd_colour[1], gd_colour[3]);
        gd_plot_printf(&s, ", 'evaluations.csv' using (column('run') == %d ? column('%s') : 1/0):'%s' with points "
                           "pt 7 ps 0.35 lc rgb '#808080' title 'every evaluation'",
                       P->best + 1, P->column[0], P->column[1]);
        if (P->gear) {
            gd_plot_printf(&s, ", '+' using (%.10g):(%.10g) every ::0::0 with points pt 5 ps 1.6 lc rgb '%s' title "
                               "'unmodified flank'",
                           P->flank_f[0][0], P->flank_f[0][1], gd_colour[0]);
            gd_plot_printf(&s, ", '+' using (%.10g):(%.10g) every ::0::0 with points pt 9 ps 1.8 lc rgb '%s' title "
                               "'the case''s modification'",
                           P->flank_f[1][0], P->flank_f[1][1], gd_colour[4]);
        }
        gd_plot_printf(&s, ", '+' using (%.10g):(%.10g) every ::0::0 with points pt 2 ps 1.6 lw 2 lc rgb '%s' title "
                           "'reference point of the hypervolume'\n",
                       P->hv_ref[0], P->hv_ref[1], gd_colour[5]);
        gd_fig_end(&s, 0);
    }
    gd_plot_draw(pl, &s, names, 1, "pictures not drawn");
}

void gd_plot_pareto(const gd_plotter *p, const gd_case *c, const gd_optimize_outcome *o)
{
    if (gd_plot_wanted(p, c->plots))
        draw(p, c, o);
}
