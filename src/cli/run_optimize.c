/* The `optimize` analysis on the command line (docs/optimisation.md): a line per run as it
 * finishes, the pictures of the convergence and (the gear) of the LTE, the summary lines. */
#include "cli.h"

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

static gd_status draw(const char *dir, const gd_case *c, const gd_optimize_outcome *o, gd_error *err)
{
    static const char *fmt[2][2] = {{"pngcairo size 1100,700 font ',11'", ".png"},
                                    {"svg size 1100,700 dynamic font 'sans,11'", ".svg"}};
    static const char *names[NPICS] = {"convergence", "lte"};
    int npics = o->gear ? 2 : 1;
    char script[16384];
    int n = 0;
    const gd_opt_result *b = &o->res[o->best];
    n += snprintf(script + n, sizeof script - n, "set datafile separator ','\n");
    for (int fi = 0; fi < 2; fi++) {
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '.convergence%s.tmp'\n"
            "set title '%s on %s (%d variables): %d run%s of %ld evaluations, best %.6g%s%s' noenhanced\n"
            "set xlabel 'objective evaluations'\nset ylabel '%s (%s)' noenhanced\nset logscale y\nset grid\nset key top right\n"
            "plot 'convergence.csv' every ::1 using ($1 == %d ? $3 : 1/0):4 with points pt 7 ps 0.25 lc rgb '#b0b0b0' "
            "title 'every evaluation (best run)'",
            fmt[fi][0], fmt[fi][1], gd_opt_algorithm_name(c->opt_algorithm), gd_opt_objective_name(o->objective),
            o->dim, o->runs, o->runs == 1 ? "" : "s", b->evaluations, b->f, o->gear ? " " : "", unit_of(c, o),
            o->gear ? gd_opt_objective_name(o->objective) : "objective", unit_of(c, o), o->best + 1);
        for (int r = 0; r < o->runs && r < 20; r++)
            n += snprintf(script + n, sizeof script - n, ", 'convergence.csv' every ::1 using ($1 == %d ? $3 : 1/0):5 "
                          "with lines lw %d title 'best so far, run %d'", r + 1, r == o->best ? 3 : 1, r + 1);
        n += snprintf(script + n, sizeof script - n, "\nunset output\nunset logscale y\n");
        if (o->gear) {
            int nl = o->paper ? 4 : 3;
            double m[4];
            for (int j = 0; j < nl; j++)
                m[j] = o->lte[j].lte_mean_arcsec;
            n += snprintf(script + n, sizeof script - n,
                "set terminal %s\nset output '.lte%s.tmp'\n"
                "set title 'Loaded transmission error over one mesh cycle, %.0f N m (about each mean)'\n"
                "set xlabel 'pinion angle (deg)'\nset ylabel 'LTE (arcsec of the gear)'\nset key bottom right\n"
                "plot 'lte.csv' every ::1 using 1:($2 - %.10g) with linespoints pt 7 ps 0.5 lw 2 "
                "title sprintf('unmodified: %.4f arcsec p-p'), "
                "'' every ::1 using 1:($3 - %.10g) with linespoints pt 5 ps 0.5 lw 2 dt 2 "
                "title sprintf('the case''s modification: %.4f arcsec p-p'), "
                "'' every ::1 using 1:($4 - %.10g) with linespoints pt 9 ps 0.6 lw 3 "
                "title sprintf('optimum: %.4f arcsec p-p')",
                fmt[fi][0], fmt[fi][1], c->torque_nm, m[0], o->lte[0].lte_pp_arcsec, m[1],
                o->lte[1].lte_pp_arcsec, m[2], o->lte[2].lte_pp_arcsec);
            if (o->paper)
                n += snprintf(script + n, sizeof script - n,
                    ", '' every ::1 using 1:($5 - %.10g) with linespoints pt 4 ps 0.5 lw 1 dt 3 "
                    "title sprintf('the paper''s Table 2: %.4f arcsec p-p')", m[3], o->lte[3].lte_pp_arcsec);
            n += snprintf(script + n, sizeof script - n, "\nunset output\n");
        }
    }
    if (n >= (int)sizeof script)
        return gd_error_set(err, GD_ERR_INTERNAL, "gnuplot script too long");
    return gd_gnuplot_draw(dir, script, names, npics, err);
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
