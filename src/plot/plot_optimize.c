/* The pictures of `optimize` (docs/optimisation.md): the convergence and, for the gear, the LTE of the
 * unmodified pair, the case's modification and the optimum. */
#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NPICS 2

/* The unit of the objective: the LTE's arcsec, the dynamic response's m/s^2 or um, none. */
static const char *unit_of(const gd_case *c, const gd_optimize_outcome *o)
{
    if (o->objective == GD_OBJ_GEAR_DYNAMIC)
        return c->opt_dynamic_response == GD_DYN_DTE_PP ? "um" : "m/s^2";
    return o->gear ? "arcsec" : "";
}

/* Two LTE curves equal to round-off (the case's modification is the unmodified flank or the
 * published one). */
static int same_lte(const gd_ltca_result *a, const gd_ltca_result *b)
{
    double d = 0, sc = 0;
    for (int k = 0; k < a->npos && k < b->npos; k++) {
        d = fmax(d, fabs(a->lte_arcsec[k] - b->lte_arcsec[k]));
        sc = fmax(sc, fabs(b->lte_arcsec[k]));
    }
    return a->npos == b->npos && d <= 1e-9 * fmax(sc, 1e-300);
}

static void draw(const gd_plotter *pl, const gd_case *c, const gd_optimize_outcome *o)
{
    static const char *names[NPICS] = {"convergence", "lte"};
    int npics = o->gear ? 2 : 1;
    const gd_opt_result *b = &o->res[o->best];
    gd_plot_script s = {0};
    char obj[160], ylabel[200];
    const char *unit = strcmp(unit_of(c, o), "um") == 0      ? "µm"
                       : strcmp(unit_of(c, o), "m/s^2") == 0 ? "m/s²"
                                                             : unit_of(c, o);
    int worst_dyn = c->opt_dynamic_combine == GD_OPT_COMBINE_MAX, worst_lte = c->opt_lte_range_combine == GD_OPT_COMBINE_MAX;
    if (o->objective == GD_OBJ_GEAR_DYNAMIC) {
        snprintf(obj, sizeof obj, "the dynamic response of the gear pair");
        snprintf(ylabel, sizeof ylabel, "%s %s over the speeds and torques (%s)",
                 worst_dyn ? "largest" : "duty-weighted mean of the largest",
                 c->opt_dynamic_response == GD_DYN_DTE_PP ? "peak-to-peak dynamic transmission error"
                                                          : "RMS mesh acceleration", unit);
    } else if (o->objective == GD_OBJ_GEAR_LTE_RANGE) {
        snprintf(obj, sizeof obj, "the LTE of the gear pair over its torques");
        snprintf(ylabel, sizeof ylabel, "%s peak-to-peak loaded transmission error over the torques (arcsec)",
                 worst_lte ? "largest" : "duty-weighted mean");
    } else if (o->gear) {
        snprintf(obj, sizeof obj, "the LTE of the gear pair");
        snprintf(ylabel, sizeof ylabel, "peak-to-peak loaded transmission error (arcsec)");
    } else {
        gd_gp_text(gd_opt_objective_name(o->objective), obj, sizeof obj);
        snprintf(ylabel, sizeof ylabel, "objective value f (-)");
    }
    for (int fi = 0; fi < 2; fi++) {
        gd_fig_begin(&s, fi, 1250, 720, "convergence");
        gd_plot_printf(&s, "set title '%s on %s (%d variable%s): %d run%s of %ld evaluations, best %.6g%s%s'\n",
                          gd_optimizer_words(c->opt_algorithm), obj, o->dim, o->dim == 1 ? "" : "s", o->runs,
                          o->runs == 1 ? "" : "s", b->evaluations, b->f, unit[0] ? " " : "", unit);
        gd_plot_printf(&s, "set xlabel 'objective evaluations'\nset ylabel '%s'\nset logscale y\n"
                              "set format y '%%g'\nset key outside right top vertical Left reverse\n",
                          ylabel);
        /* the ticks of the values drawn: 1, 2 and 5 times the powers of ten on a short log axis */
        double ylo = INFINITY, yhi = -INFINITY;
        for (long k = 0; b->f_history && k < b->evaluations; k++)
            if (b->f_history[k] > 0) {
                ylo = fmin(ylo, b->f_history[k]);
                yhi = fmax(yhi, b->f_history[k]);
            }
        for (int r = 0; r < o->runs && r < 20; r++)
            for (long k = 0; o->res[r].best_history && k < o->res[r].evaluations; k++)
                if (o->res[r].best_history[k] > 0) {
                    ylo = fmin(ylo, o->res[r].best_history[k]);
                    yhi = fmax(yhi, o->res[r].best_history[k]);
                }
        if (yhi > ylo && yhi < 10 * ylo) { /* less than a decade: round steps, as on a linear axis */
            double st = gd_nice_step(yhi - ylo, 5);
            gd_plot_printf(&s, "set ytics (");
            for (double t = ceil(ylo / st) * st; t <= yhi * (1 + 1e-12); t += st)
                gd_plot_printf(&s, "%s%.10g", t > ceil(ylo / st) * st ? ", " : "", t);
            gd_plot_printf(&s, ")\n");
        } else if (yhi > ylo) {
            gd_log_tics(&s, "y", ylo, yhi);
        }
        gd_plot_printf(&s, "plot 'convergence.csv' using (column('run') == %d ? column('evaluation') : 1/0):"
                              "(column('f') > 0 ? column('f') : 1/0) with points pt 7 ps 0.3 lc rgb '#999999' "
                              "title 'every evaluation of the best run'",
                          o->best + 1);
        for (int r = 0; r < o->runs && r < 20; r++) {
            const char *colour;
            int dash;
            gd_series_style(r, &colour, &dash);
            gd_plot_printf(&s, ", 'convergence.csv' using (column('run') == %d ? column('evaluation') : 1/0):"
                                  "(column('best_f') > 0 ? column('best_f') : 1/0) with lines lw %g dt %d lc rgb '%s' "
                                  "title 'best so far, run %d%s'",
                              r + 1, r == o->best ? 3.0 : 1.3, dash, colour, r + 1, r == o->best ? " (the best)" : "");
        }
        gd_plot_printf(&s, "\n");
        gd_fig_end(&s, 0);
        if (o->gear) {
            int nl = o->paper ? 4 : 3;
            double m[4];
            for (int j = 0; j < nl; j++)
                m[j] = o->lte[j].lte_mean_arcsec;
            gd_fig_begin(&s, fi, 1250, 680, "lte");
            gd_plot_printf(&s, "set title 'Loaded transmission error over one mesh cycle, %.0f N m, each about its "
                                  "mean'\nset xlabel 'pinion angle φ_1 (deg)'\nset ylabel 'loaded transmission error "
                                  "about its mean, gear (arcsec)'\nset key outside below horizontal\n",
                              c->torque_nm);
            /* the case's own modification drawn apart only where it differs from the unmodified flank
             * and from the published one (a curve drawn twice hides the first under the second) */
            int same = same_lte(&o->lte[1], &o->lte[0]), as_paper = !same && o->paper && same_lte(&o->lte[1], &o->lte[3]);
            gd_plot_printf(&s, "plot 'lte.csv' using 'phi1_deg':(column('lte_unmodified_arcsec') - %.10g) with "
                                  "linespoints pt 7 ps 0.6 lw 2 lc rgb '%s' title 'unmodified%s: %.4f arcsec "
                                  "peak-to-peak'",
                              m[0], gd_colour[0], same ? ", as the case is" : "", o->lte[0].lte_pp_arcsec);
            if (!same && !as_paper)
                gd_plot_printf(&s, ", '' using 'phi1_deg':(column('lte_case_arcsec') - %.10g) with linespoints pt 5 "
                                      "ps 0.6 lw 2 dt 2 lc rgb '%s' title 'the case''s modification: %.4f arcsec "
                                      "peak-to-peak'",
                                  m[1], gd_colour[1], o->lte[1].lte_pp_arcsec);
            gd_plot_printf(&s, ", '' using 'phi1_deg':(column('lte_optimum_arcsec') - %.10g) with linespoints pt 9 "
                                  "ps 0.7 lw 3 lc rgb '%s' title 'optimum: %.4f arcsec peak-to-peak'",
                              m[2], gd_colour[4], o->lte[2].lte_pp_arcsec);
            if (o->paper)
                gd_plot_printf(&s, ", '' using 'phi1_deg':(column('lte_paper_table2_arcsec') - %.10g) with linespoints "
                                      "pt 12 ps 0.7 lw 1.5 dt 3 lc rgb '%s' title 'the modification published with "
                                      "the paper''s pair%s: %.4f arcsec peak-to-peak'",
                                  m[3], gd_colour[2], as_paper ? ", as the case''s" : "", o->lte[3].lte_pp_arcsec);
            gd_plot_printf(&s, "\n");
            gd_fig_end(&s, 0);
        }
    }
    gd_plot_draw(pl, &s, names, npics, "pictures not drawn");
}
void gd_plot_optimize(const gd_plotter *p, const gd_case *c, const gd_optimize_outcome *o)
{
    if (gd_plot_wanted(p, c->plots))
        draw(p, c, o);
}
