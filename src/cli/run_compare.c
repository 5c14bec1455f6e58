/* The `compare-optimizers` analysis on the command line (docs/optimisation.md section 7): the
 * statistics of each problem as it finishes, the convergence and runtime-distribution pictures,
 * the summary line. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *obj_name(const gd_compare_entry *q) { return gd_opt_objective_name(q->objective); }

/* The progress report of one problem: the statistics of each optimiser. */
void cli_compare_problem(void *user, const gd_compare_entry *q, const gd_opt_compare_settings *s)
{
    const cli_progress *o = user;
    if (o->quiet)
        return;
    printf("%s, d = %d%s: %d optimisers x %d runs x %ld evaluations in %.1f s; f_ref %.8g (%s)\n", obj_name(q),
           q->dim, q->shift > 0 ? " (shifted)" : "", s->nalgs, s->runs, s->budget, q->res.wall_s, q->res.f_ref,
           q->res.f_ref_known ? "the minimum" : "best found");
    printf("  %-12s %12s %12s %12s %12s %8s %10s %10s\n", "optimizer", "best", "median", "IQR", "worst",
           "success", "ERT evals", "wall s");
    for (int k = 0; k < s->nalgs; k++) {
        const gd_opt_alg_stats *S = &q->res.stats[k];
        printf("  %-12s %12.6g %12.6g %12.4g %12.6g %7.0f%% %10.4g %10.3g\n", gd_opt_algorithm_name(S->alg),
               S->best, S->median, S->q3 - S->q1, S->worst, 100 * S->success_rate, S->ert, S->wall_mean_s);
    }
    fflush(stdout);
}

static const char *const colours[GD_OPT_NALGORITHMS] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#8c564b",
                                                        "#ff7f0e", "#17becf", "#e377c2", "#7f7f7f"};

static gd_status draw(const char *dir, const gd_compare_outcome *C, gd_error *err)
{
    static const char *fmt[2][2] = {{"pngcairo size %d,%d font ',10'", ".png"},
                                    {"svg size %d,%d dynamic font 'sans,10'", ".svg"}};
    const gd_opt_compare_result *r0 = &C->p[0].res;
    size_t cap = 65536 + (size_t)C->n * 8192;
    char *script = malloc(cap);
    if (!script)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the gnuplot script");
    size_t n = 0;
#define OUT(...) n += (size_t)snprintf(script + n, n < cap ? cap - n : 0, __VA_ARGS__)
    OUT("set datafile separator ','\n");
    for (int fi = 0; fi < 2; fi++) {
        for (int pic = 0; pic < 2; pic++) {
            int panels = pic == 0 ? C->n : C->n + (C->n > 1);
            int cols = panels < 3 ? panels : 3, rows = (panels + cols - 1) / cols;
            char term[128];
            snprintf(term, sizeof term, fmt[fi][0], cols == 1 ? 900 : 520 * cols + 200, 420 * rows + 60);
            OUT("set terminal %s\nset output '.%s%s.tmp'\n", term, pic ? "ecdf" : "convergence", fmt[fi][1]);
            OUT("set multiplot layout %d,%d title '%s: %d optimisers, %d runs each, budget %ld evaluations' noenhanced\n", rows,
                cols, pic ? "Runtime distributions (fraction of (run, target) pairs reached)"
                          : "Convergence: median and quartiles of best - f_ref over the runs", r0->nalgs, r0->runs, r0->budget);
            OUT("set grid\nset logscale x\nset xlabel 'objective evaluations'\nset key outside right top font ',8'\n");
            if (pic == 0)
                OUT("set logscale y\nset ylabel 'best - f_ref' noenhanced\nset format y '10^{%%L}'\n");
            else
                OUT("unset logscale y\nset ylabel 'fraction reached'\nset format y '%%g'\nset yrange [0:1.02]\n");
            for (int j = 0; j < panels; j++) {
                int pooled = j == C->n;
                const gd_compare_entry *q = pooled ? NULL : &C->p[j];
                const gd_opt_compare_result *r = pooled ? r0 : &q->res;
                if (pooled)
                    OUT("set title 'all %d problems pooled' noenhanced\n", C->n);
                else if (pic == 0)
                    OUT("set title '%s, d = %d%s: f_ref = %.6g (%s)' noenhanced\n", obj_name(q), q->dim,
                        q->shift > 0 ? ", shifted" : "", r->f_ref, r->f_ref_known ? "minimum" : "best found");
                else
                    OUT("set title '%s, d = %d%s: %d targets %.3g .. %.3g' noenhanced\n", obj_name(q), q->dim,
                        q->shift > 0 ? ", shifted" : "", r->ntargets, r->targets[0], r->targets[r->ntargets - 1]);
                OUT("plot ");
                for (int a = 0; a < r->nalgs; a++) {
                    const char *an = gd_opt_algorithm_name(r->stats[a].alg);
                    const char *colour = colours[r->stats[a].alg % GD_OPT_NALGORITHMS];
                    char sel[256];
                    snprintf(sel, sizeof sel, "strcol(1) eq '%s' && $2 == %d && strcol(3) eq '%s'",
                             pooled ? "all" : obj_name(q), pooled ? 0 : q->dim, an);
                    if (pic == 0)
                        OUT("%s'convergence.csv' every ::1 using (%s ? $4 : 1/0):($5 > 0 ? $5 : 1/0):($7 > 0 ? $7 : 1/0) "
                            "with filledcurves fs transparent solid 0.12 noborder lc rgb '%s' notitle, "
                            "'' every ::1 using (%s ? $4 : 1/0):($6 > 0 ? $6 : 1/0) with lines lw 2 lc rgb '%s' "
                            "title '%s' noenhanced", a ? ", " : "", sel, colour, sel, colour, an);
                    else
                        OUT("%s'ecdf.csv' every ::1 using (%s ? $4 : 1/0):5 with steps lw 2 lc rgb '%s' title '%s' noenhanced",
                            a ? ", " : "", sel, colour, an);
                }
                OUT("\n");
            }
            OUT("unset multiplot\nunset output\nunset yrange\nunset logscale\n");
        }
    }
#undef OUT
    static const char *names[2] = {"convergence", "ecdf"};
    gd_status st = n >= cap ? gd_error_set(err, GD_ERR_INTERNAL, "gnuplot script too long")
                            : gd_gnuplot_draw(dir, script, names, 2, err);
    free(script);
    return st;
}

void cli_compare_pictures(const cli_case_args *a, const gd_case *c, const void *result, gd_run_dir *out,
                          const char **note)
{
    if (gd_gnuplot_wanted(c->plots, note)) {
        gd_error perr = {0};
        gd_status pst = draw(gd_run_dir_stage(out), result, &perr);
        static const char *pics[] = {"convergence.png", "convergence.svg", "ecdf.png", "ecdf.svg"};
        gd_gnuplot_drawn(pst, &perr, pics, 4, out);
    }
}

void cli_compare_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    (void)c;
    const gd_compare_outcome *C = result;
    if (!a->quiet)
        printf("%s: %d problem%s compared in %.1f s on %d thread%s\n", dir, C->n, C->n == 1 ? "" : "s", C->wall_s,
               C->threads, C->threads == 1 ? "" : "s");
}
