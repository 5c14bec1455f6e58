/* The `optimize` analysis on the command line (docs/optimisation.md): a line per run as it
 * finishes, the pictures of the convergence and (the gear) of the LTE, the summary lines. */
#include "cli.h"
#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NPICS 2

void cli_optimize_run(void *user, int run, int runs, unsigned long seed, const gd_opt_result *r)
{
    const cli_progress *o = user;
    if (!o->quiet && runs > 1)
        printf("  run %d (seed %lu): %.8g after %ld evaluations, %.1f s\n", run + 1, seed, r->f, r->evaluations,
               r->wall_s);
}

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

static gd_status draw(const char *dir, const gd_case *c, const gd_optimize_outcome *o, gd_error *err)
{
    static const char *names[NPICS] = {"convergence", "lte"};
    int npics = o->gear ? 2 : 1;
    const gd_opt_result *b = &o->res[o->best];
    gd_gnuplot_script s = {0};
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
        cli_gp_text(gd_opt_objective_name(o->objective), obj, sizeof obj);
        snprintf(ylabel, sizeof ylabel, "objective value f (-)");
    }
    for (int fi = 0; fi < 2; fi++) {
        cli_fig_begin(&s, fi, 1250, 720, "convergence");
        gd_gnuplot_printf(&s, "set title '%s on %s (%d variable%s): %d run%s of %ld evaluations, best %.6g%s%s'\n",
                          cli_optimizer_words(c->opt_algorithm), obj, o->dim, o->dim == 1 ? "" : "s", o->runs,
                          o->runs == 1 ? "" : "s", b->evaluations, b->f, unit[0] ? " " : "", unit);
        gd_gnuplot_printf(&s, "set xlabel 'objective evaluations'\nset ylabel '%s'\nset logscale y\n"
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
            double st = cli_nice_step(yhi - ylo, 5);
            gd_gnuplot_printf(&s, "set ytics (");
            for (double t = ceil(ylo / st) * st; t <= yhi * (1 + 1e-12); t += st)
                gd_gnuplot_printf(&s, "%s%.10g", t > ceil(ylo / st) * st ? ", " : "", t);
            gd_gnuplot_printf(&s, ")\n");
        } else if (yhi > ylo) {
            cli_log_tics(&s, "y", ylo, yhi);
        }
        gd_gnuplot_printf(&s, "plot 'convergence.csv' using (column('run') == %d ? column('evaluation') : 1/0):"
                              "(column('f') > 0 ? column('f') : 1/0) with points pt 7 ps 0.3 lc rgb '#999999' "
                              "title 'every evaluation of the best run'",
                          o->best + 1);
        for (int r = 0; r < o->runs && r < 20; r++) {
            const char *colour;
            int dash;
            cli_series_style(r, &colour, &dash);
            gd_gnuplot_printf(&s, ", 'convergence.csv' using (column('run') == %d ? column('evaluation') : 1/0):"
                                  "(column('best_f') > 0 ? column('best_f') : 1/0) with lines lw %g dt %d lc rgb '%s' "
                                  "title 'best so far, run %d%s'",
                              r + 1, r == o->best ? 3.0 : 1.3, dash, colour, r + 1, r == o->best ? " (the best)" : "");
        }
        gd_gnuplot_printf(&s, "\n");
        cli_fig_end(&s, 0);
        if (o->gear) {
            int nl = o->paper ? 4 : 3;
            double m[4];
            for (int j = 0; j < nl; j++)
                m[j] = o->lte[j].lte_mean_arcsec;
            cli_fig_begin(&s, fi, 1250, 680, "lte");
            gd_gnuplot_printf(&s, "set title 'Loaded transmission error over one mesh cycle, %.0f N m, each about its "
                                  "mean'\nset xlabel 'pinion angle φ_1 (deg)'\nset ylabel 'loaded transmission error "
                                  "about its mean, gear (arcsec)'\nset key outside below horizontal\n",
                              c->torque_nm);
            /* the case's own modification drawn apart only where it differs from the unmodified flank
             * and from the published one (a curve drawn twice hides the first under the second) */
            int same = same_lte(&o->lte[1], &o->lte[0]), as_paper = !same && o->paper && same_lte(&o->lte[1], &o->lte[3]);
            gd_gnuplot_printf(&s, "plot 'lte.csv' using 'phi1_deg':(column('lte_unmodified_arcsec') - %.10g) with "
                                  "linespoints pt 7 ps 0.6 lw 2 lc rgb '%s' title 'unmodified%s: %.4f arcsec "
                                  "peak-to-peak'",
                              m[0], cli_colour[0], same ? ", as the case is" : "", o->lte[0].lte_pp_arcsec);
            if (!same && !as_paper)
                gd_gnuplot_printf(&s, ", '' using 'phi1_deg':(column('lte_case_arcsec') - %.10g) with linespoints pt 5 "
                                      "ps 0.6 lw 2 dt 2 lc rgb '%s' title 'the case''s modification: %.4f arcsec "
                                      "peak-to-peak'",
                                  m[1], cli_colour[1], o->lte[1].lte_pp_arcsec);
            gd_gnuplot_printf(&s, ", '' using 'phi1_deg':(column('lte_optimum_arcsec') - %.10g) with linespoints pt 9 "
                                  "ps 0.7 lw 3 lc rgb '%s' title 'optimum: %.4f arcsec peak-to-peak'",
                              m[2], cli_colour[4], o->lte[2].lte_pp_arcsec);
            if (o->paper)
                gd_gnuplot_printf(&s, ", '' using 'phi1_deg':(column('lte_paper_table2_arcsec') - %.10g) with linespoints "
                                      "pt 12 ps 0.7 lw 1.5 dt 3 lc rgb '%s' title 'the modification published with "
                                      "the paper''s pair%s: %.4f arcsec peak-to-peak'",
                                  m[3], cli_colour[2], as_paper ? ", as the case''s" : "", o->lte[3].lte_pp_arcsec);
            gd_gnuplot_printf(&s, "\n");
            cli_fig_end(&s, 0);
        }
    }
    if (s.bad) {
        free(s.p);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the gnuplot script");
    }
    gd_status st = gd_gnuplot_draw(dir, s.p, names, npics, err);
    free(s.p);
    return st;
}

void cli_optimize_pictures(const cli_case_args *a, const gd_case *c, const void *result, gd_run_dir *out,
                           const char **note)
{
    const gd_optimize_outcome *o = result;
    if (gd_gnuplot_wanted(c->plots, note)) {
        gd_error perr = {0};
        gd_status pst = draw(gd_run_dir_stage(out), c, o, &perr);
        static const char *pics[] = {"convergence.png", "convergence.svg", "lte.png", "lte.svg"};
        gd_gnuplot_drawn(pst, &perr, pics, o->gear ? 4 : 2, out);
    }
}

/* The progress report: the best run, its variables and for the gear the LTE of the unmodified pair,
 * the case's own modification and the optimum (and the paper's Table 2 for the paper's pair), the
 * variables without effect, and whether the run had converged. */
void cli_optimize_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    const gd_optimize_outcome *o = result;
    if (a->quiet)
        return;
    long budget = o->settings.budget;
    double wall = o->wall_s;
    int threads = o->threads;
    const gd_opt_result *b = &o->res[o->best];
    printf("%s: %s on %s, %d variable%s, %d run%s of %ld evaluations (%.1f s, %d thread%s): best %.8g%s%s "
           "(evaluation %ld of run %d)\n", dir, gd_opt_algorithm_name(c->opt_algorithm),
           gd_opt_objective_name(o->objective), o->dim, o->dim == 1 ? "" : "s", o->runs, o->runs == 1 ? "" : "s",
           budget, wall, threads, threads == 1 ? "" : "s", b->f, o->gear ? " " : "", unit_of(c, o), b->best_at,
           o->best + 1);
    for (int i = 0; i < o->dim; i++) {
        const char *unit = "", *sym = o->names[i];
        if (o->gear)
            gd_opt_gear_variable(o->vars.var[i], &unit, &sym);
        printf("  %-4s %-28s %12.6g %-3s in [%g, %g]   %s %g", sym, o->names[i], b->y[i], unit, o->lower[i],
               o->upper[i], o->gear ? "case" : "minimiser", o->reference[i]);
        if (o->gear && o->paper)
            printf(", Table 2 %g", o->table2[i]);
        if (o->gear && o->no_effect[i][0])
            printf("   (%s)", o->no_effect[i]);
        printf("\n");
    }
    if (o->gear && o->objective != GD_OBJ_GEAR_LTE) {
        int dyn = o->objective == GD_OBJ_GEAR_DYNAMIC;
        printf("  %s (%s): unmodified %.6g, the case's modification %.6g, optimum %.6g (%+.1f %% against the "
               "unmodified pair)\n", gd_opt_objective_name(o->objective), unit_of(c, o), o->objective_of[0],
               o->objective_of[1], o->objective_of[2],
               100 * (o->objective_of[2] - o->objective_of[0]) / o->objective_of[0]);
        for (int k = 0; k < c->n_opt_torques; k++) {
            printf("    at %g N m: unmodified %.6g, the case's %.6g, optimum %.6g", c->opt_torques_nm[k],
                   o->aux_of[0][dyn ? 2 * k : k], o->aux_of[1][dyn ? 2 * k : k], o->aux_of[2][dyn ? 2 * k : k]);
            if (dyn)
                printf(" (the optimum's curve by %s)", gd_dyn_method_name((int)o->aux_of[2][2 * k + 1]));
            printf("\n");
        }
    }
    if (o->gear) {
        char at[64] = ""; /* the objective over several torques: the LTE table's own */
        if (o->objective != GD_OBJ_GEAR_LTE)
            snprintf(at, sizeof at, " at %g N m", c->torque_nm);
        printf("  LTE peak-to-peak%s: unmodified %.6g, the case's modification %.6g, optimum %.6g arcsec "
               "(%+.1f %% against the unmodified pair, %+.1f %% against the case's)\n", at,
               o->lte[0].lte_pp_arcsec,
               o->lte[1].lte_pp_arcsec, o->lte[2].lte_pp_arcsec,
               100 * (o->lte[2].lte_pp_arcsec - o->lte[0].lte_pp_arcsec) / o->lte[0].lte_pp_arcsec,
               100 * (o->lte[2].lte_pp_arcsec - o->lte[1].lte_pp_arcsec) / o->lte[1].lte_pp_arcsec);
        if (o->paper)
            printf("  the paper's pair: its Table 2 gives %.6g arcsec here; the paper: 4.194 -> 1.157, -72.41 %%\n",
                   o->lte[3].lte_pp_arcsec);
    }
    if (!o->converged)
        printf("  not converged: the best value fell by %.3g %% over the last tenth of the evaluations (best at "
               "evaluation %ld of %ld); more iterations may lower it\n", 100 * o->last_tenth_improvement, b->best_at,
               b->evaluations);
}
