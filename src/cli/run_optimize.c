/* The `optimize` analysis on the command line (docs/optimisation.md): a line per run as it
 * finishes, the pictures of the convergence and (the gear) of the LTE, the summary lines. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* On a terminal: the evaluations done of all the runs' budgets, their rate and the time left at that
 * rate, at most four times a second (the objective's evaluations dominate an optimisation: what
 * follows them, the flanks' LTE and for an objective over load and speed their report, is not
 * counted). */
void cli_optimize_progress(void *user, long done, long total)
{
    cli_progress *o = user;
    if (!o->tty)
        return;
    double t = now();
    if (o->t0 == 0) {
        o->t0 = t;
        o->last = t;
    }
    if (done < total && t - o->last < 0.25)
        return;
    o->last = t;
    double el = t - o->t0, rate = el > 0 ? (double)done / el : 0;
    char eta[64] = "";
    if (done < total && rate > 0) {
        double sec = (double)(total - done) / rate;
        snprintf(eta, sizeof eta, sec < 90 ? ", about %.0f s left" : sec < 5400 ? ", about %.0f min left"
                                                                                 : ", about %.1f h left",
                 sec < 90 ? sec : sec < 5400 ? sec / 60 : sec / 3600);
    }
    fprintf(stderr, "\rgeardyn: optimize %ld/%ld evaluations (%ld%%), %.3g per s%s   %s", done, total,
            total ? done * 100 / total : 100, rate, eta, done == total ? "\n" : "");
    fflush(stderr);
}

void cli_optimize_after_run(const cli_progress *p, gd_status st)
{
    if (p->tty && st != GD_OK && p->t0 != 0)
        fputc('\n', stderr);
}

void cli_optimize_run(void *user, int run, int runs, unsigned long seed, const gd_opt_result *r)
{
    const cli_progress *o = user;
    if (o->tty && !o->quiet && runs > 1 && run + 1 < runs) /* the run's line below the progress line */
        fputc('\n', stderr);
    if (!o->quiet && runs > 1 && r->nobj == 2)
        printf("  run %d (seed %lu): %d non-dominated points, hypervolume %.8g after %ld evaluations, %.1f s\n",
               run + 1, seed, r->nfront, r->hv, r->evaluations, r->wall_s);
    else if (!o->quiet && runs > 1)
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

/* The progress report: the best run, its variables and for the gear the LTE of the unmodified pair,
 * the case's own modification and the optimum (and the paper's Table 2 for the paper's pair), the
 * variables without effect, and whether the run had converged. */
void cli_optimize_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    const gd_optimize_outcome *o = result;
    if (a->quiet)
        return;
    if (o->pareto) {
        cli_optimize_pareto_report(dir, c, o);
        return;
    }
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
    cli_optimize_robust_report(c, o);
    cli_optpost_report(c, o);
    if (!o->converged)
        printf("  not converged: the best value fell by %.3g %% over the last tenth of the evaluations (best at "
               "evaluation %ld of %ld); more iterations may lower it\n", 100 * o->last_tenth_improvement, b->best_at,
               b->evaluations);
}
