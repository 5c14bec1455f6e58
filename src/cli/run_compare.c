/* The `compare-optimizers` analysis on the command line (docs/optimisation.md section 7): every
 * optimiser of the case, on every objective (and dimension) of the case, with the same budget,
 * seeds and problem instances; tables of the runs and statistics, convergence quartiles and
 * runtime distributions (COCO/BBOB), pictures and summary.json. Everything but the wall-time
 * columns is independent of the thread count. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAXPROB 64

typedef struct cmp_problem {
    int objective, dim;
    double shift;
    gd_opt_gear *gear;
    gd_opt_testfn *tf;          /* runs instances */
    gd_opt_problem *pb;         /* runs */
    const gd_opt_problem **pp;  /* runs */
    gd_opt_compare_result res;
} cmp_problem;

typedef struct cmp {
    int n;
    cmp_problem p[MAXPROB];
    int runs;
    long *grid;                 /* evaluation counts of the convergence and ECDF tables */
    int ngrid;
} cmp;

static void problem_free(cmp_problem *q, int runs)
{
    gd_opt_gear_free(q->gear);
    if (q->tf)
        for (int r = 0; r < runs; r++)
            gd_opt_testfn_free(&q->tf[r]);
    free(q->tf);
    free(q->pb);
    free(q->pp);
    gd_opt_compare_result_free(&q->res);
}

/* log-spaced evaluation counts from 1 to the budget (about 20 per decade), and the budget */
static int make_grid(long budget, long **out)
{
    int cap = 32 + (int)(20 * log10((double)budget + 1));
    long *g = malloc(sizeof(long) * (size_t)cap);
    if (!g)
        return -1;
    int n = 0;
    for (int k = 0; n < cap - 1; k++) {
        long v = (long)floor(pow(10.0, k / 20.0) + 0.5);
        if (v > budget)
            break;
        if (n == 0 || v > g[n - 1])
            g[n++] = v;
    }
    if (n == 0 || g[n - 1] != budget)
        g[n++] = budget;
    *out = g;
    return n;
}

static const char *obj_name(const cmp_problem *q) { return gd_opt_objective_name(q->objective); }

static gd_status write_tables(const char *dir, const cmp *C, gd_error *err)
{
    gd_atomic_file f;
    gd_status st = gd_atomic_open(&f, dir, "runs.csv", err);
    if (st != GD_OK)
        return st;
    fprintf(f.fp, "objective,dimension,optimizer,run,seed,final_f,final_delta_f,evaluations,evals_to_target,starts,"
                  "wall_s\n");
    for (int j = 0; j < C->n; j++) {
        const gd_opt_compare_result *r = &C->p[j].res;
        for (int i = 0; i < r->nalgs * r->runs; i++) {
            const gd_opt_compare_run *u = &r->run[i];
            fprintf(f.fp, "%s,%d,%s,%d,%lu,%.12g,%.12g,%ld,%ld,%d,%.6g\n", obj_name(&C->p[j]), C->p[j].dim,
                    gd_opt_algorithm_name(u->alg), u->run + 1, u->seed, u->f, u->f - r->f_ref, u->evaluations,
                    u->evals_to_target, u->starts, u->wall_s);
        }
    }
    if ((st = gd_atomic_commit(&f, err)) != GD_OK)
        return st;

    if ((st = gd_atomic_open(&f, dir, "statistics.csv", err)) != GD_OK)
        return st;
    fprintf(f.fp, "objective,dimension,optimizer,runs,budget_evals,f_ref,target,best,q1,median,q3,iqr,worst,mean,"
                  "successes,success_rate,evals_to_target_median,ert_evals,wall_mean_s,wall_total_s\n");
    for (int j = 0; j < C->n; j++) {
        const gd_opt_compare_result *r = &C->p[j].res;
        for (int a = 0; a < r->nalgs; a++) {
            const gd_opt_alg_stats *S = &r->stats[a];
            fprintf(f.fp, "%s,%d,%s,%d,%ld,%.12g,%.6g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%d,%.6g,%.6g,%.6g,"
                    "%.6g,%.6g\n", obj_name(&C->p[j]), C->p[j].dim, gd_opt_algorithm_name(S->alg), r->runs, r->budget,
                    r->f_ref, r->target, S->best, S->q1, S->median, S->q3, S->q3 - S->q1, S->worst, S->mean,
                    S->successes, S->success_rate, S->evals_to_target_median, S->ert, S->wall_mean_s,
                    S->wall_total_s);
        }
    }
    if ((st = gd_atomic_commit(&f, err)) != GD_OK)
        return st;

    if ((st = gd_atomic_open(&f, dir, "convergence.csv", err)) != GD_OK)
        return st;
    fprintf(f.fp, "objective,dimension,optimizer,evaluations,q1_delta_f,median_delta_f,q3_delta_f\n");
    for (int j = 0; j < C->n; j++) {
        const gd_opt_compare_result *r = &C->p[j].res;
        for (int a = 0; a < r->nalgs; a++)
            for (int k = 0; k < C->ngrid; k++) {
                double q[3];
                gd_opt_compare_quartiles(r, a, C->grid[k], q);
                fprintf(f.fp, "%s,%d,%s,%ld,%.10g,%.10g,%.10g\n", obj_name(&C->p[j]), C->p[j].dim,
                        gd_opt_algorithm_name(r->stats[a].alg), C->grid[k], q[0], q[1], q[2]);
            }
    }
    if ((st = gd_atomic_commit(&f, err)) != GD_OK)
        return st;

    if ((st = gd_atomic_open(&f, dir, "ecdf.csv", err)) != GD_OK)
        return st;
    fprintf(f.fp, "objective,dimension,optimizer,evaluations,fraction\n");
    const gd_opt_compare_result *all[MAXPROB];
    for (int j = 0; j < C->n; j++)
        all[j] = &C->p[j].res;
    for (int j = 0; j <= C->n; j++) {
        const gd_opt_compare_result *const *rs = j < C->n ? &all[j] : all;
        int nr = j < C->n ? 1 : C->n;
        for (int a = 0; a < all[0]->nalgs; a++)
            for (int k = 0; k < C->ngrid; k++)
                fprintf(f.fp, "%s,%d,%s,%ld,%.6g\n", j < C->n ? obj_name(&C->p[j]) : "all",
                        j < C->n ? C->p[j].dim : 0, gd_opt_algorithm_name(all[0]->stats[a].alg), C->grid[k],
                        gd_opt_compare_ecdf(rs, nr, a, C->grid[k]));
    }
    if ((st = gd_atomic_commit(&f, err)) != GD_OK)
        return st;

    if ((st = gd_atomic_open(&f, dir, "best_points.csv", err)) != GD_OK)
        return st;
    fprintf(f.fp, "objective,dimension,optimizer,run,variable,unit,value\n");
    for (int j = 0; j < C->n; j++) {
        const gd_opt_compare_result *r = &C->p[j].res;
        int gear = C->p[j].objective == GD_OBJ_GEAR_LTE;
        for (int i = 0; i < r->nalgs * r->runs; i++)
            for (int k = 0; k < r->dim; k++) {
                const char *unit = "";
                char name[48];
                if (gear)
                    snprintf(name, sizeof name, "%s", gd_opt_gear_variable(k, &unit, NULL));
                else
                    snprintf(name, sizeof name, "x%d", k + 1);
                fprintf(f.fp, "%s,%d,%s,%d,%s,%s,%.12g\n", obj_name(&C->p[j]), C->p[j].dim,
                        gd_opt_algorithm_name(r->run[i].alg), r->run[i].run + 1, name, unit, r->run[i].y[k]);
            }
    }
    return gd_atomic_commit(&f, err);
}

static const char *const colours[GD_OPT_NALGORITHMS] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#8c564b",
                                                        "#ff7f0e", "#17becf", "#e377c2", "#7f7f7f"};

static gd_status draw(const char *dir, const cmp *C, gd_error *err)
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
            OUT("set terminal %s\nset output '%s/.%s%s.tmp'\n", term, dir, pic ? "ecdf" : "convergence", fmt[fi][1]);
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
                const cmp_problem *q = pooled ? NULL : &C->p[j];
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
                        OUT("%s'%s/convergence.csv' every ::1 using (%s ? $4 : 1/0):($5 > 0 ? $5 : 1/0):($7 > 0 ? $7 : 1/0) "
                            "with filledcurves fs transparent solid 0.12 noborder lc rgb '%s' notitle, "
                            "'' every ::1 using (%s ? $4 : 1/0):($6 > 0 ? $6 : 1/0) with lines lw 2 lc rgb '%s' "
                            "title '%s' noenhanced", a ? ", " : "", dir, sel, colour, sel, colour, an);
                    else
                        OUT("%s'%s/ecdf.csv' every ::1 using (%s ? $4 : 1/0):5 with steps lw 2 lc rgb '%s' title '%s' noenhanced",
                            a ? ", " : "", dir, sel, colour, an);
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

/* The problem instances of one (objective, dimension): the gear problem, the same for every run,
 * or one test-function instance per run (shifted minimisers drawn from the run's instance seed). */
static gd_status build(const gd_case *c, cmp_problem *q, int runs, gd_error *err)
{
    q->pb = calloc((size_t)runs, sizeof *q->pb);
    q->pp = calloc((size_t)runs, sizeof *q->pp);
    if (!q->pb || !q->pp)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    if (q->objective == GD_OBJ_GEAR_LTE) {
        const gd_pair pair = gd_pair_from_case(c);
        const gd_ltca_settings set = gd_ltca_settings_from_case(c);
        double lower[GD_OPT_GEAR_DIM], upper[GD_OPT_GEAR_DIM];
        gd_opt_gear_bounds(c, lower, upper);
        gd_status st = gd_opt_gear_create(&pair, &set, lower, upper, &q->gear, err);
        if (st != GD_OK)
            return st;
        for (int r = 0; r < runs; r++) {
            gd_opt_gear_problem(q->gear, &q->pb[r]);
            q->pp[r] = &q->pb[r];
        }
        return GD_OK;
    }
    q->tf = calloc((size_t)runs, sizeof *q->tf);
    if (!q->tf)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    for (int r = 0; r < runs; r++) {
        gd_status st = gd_opt_testfn_init(&q->tf[r], q->objective, q->dim, q->shift, gd_opt_instance_seed(c, r), err);
        if (st != GD_OK)
            return st;
        gd_opt_testfn_problem(&q->tf[r], &q->pb[r]);
        q->pp[r] = &q->pb[r];
    }
    return GD_OK;
}

/* The problems of the case: every objective, the test functions in every dimension. */
static void list_problems(const gd_case *c, cmp *C)
{
    int objs[GD_OBJ_NOBJECTIVES];
    int nobj = gd_opt_case_objectives(c, objs, GD_OBJ_NOBJECTIVES);
    for (int i = 0; i < nobj; i++) {
        int nd = objs[i] == GD_OBJ_GEAR_LTE ? 1 : c->n_opt_dimensions;
        for (int k = 0; k < nd && C->n < MAXPROB; k++) {
            cmp_problem *q = &C->p[C->n++];
            q->objective = objs[i];
            q->dim = objs[i] == GD_OBJ_GEAR_LTE ? GD_OPT_GEAR_DIM : (int)c->opt_dimensions[k];
            q->shift = objs[i] == GD_OBJ_GEAR_LTE ? 0.0 : c->opt_shift;
        }
    }
    C->runs = c->opt_runs;
}

/* The settings of the comparison from the case's [optimize] keys. */
static void compare_settings(const gd_case *c, const cli_case_args *a, gd_opt_compare_settings *s)
{
    memset(s, 0, sizeof *s);
    s->nalgs = gd_opt_case_optimizers(c, s->algs, GD_OPT_NALGORITHMS);
    s->runs = c->opt_runs;
    s->seed = gd_opt_run_seed(c, 0);
    s->budget = gd_opt_case_budget(c);
    s->population = c->opt_population;
    s->target = c->opt_target;
    s->target_loosest = c->opt_target_loosest;
    s->ntargets = c->opt_ecdf_targets;
    s->threads = a->threads;
}

/* The progress report of one problem: the statistics of each optimiser. */
static void print_problem(const cmp_problem *q, const gd_opt_compare_settings *s)
{
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

/* Build and compare every problem; the wall time summed in *wall. Returns 0 or the exit status. */
static int compare_all(const cli_case_args *a, const gd_case *c, cmp *C, gd_opt_compare_settings *s, double *wall)
{
    gd_error err = {0};
    for (int j = 0; j < C->n; j++) {
        cmp_problem *q = &C->p[j];
        gd_status st = build(c, q, C->runs, &err);
        if (st == GD_OK) {
            s->f_ref = q->objective == GD_OBJ_GEAR_LTE ? NAN : 0.0;
            st = gd_opt_compare(q->pp, s, &q->res, &err);
        }
        if (st != GD_OK)
            return cli_fail(&err);
        *wall += q->res.wall_s;
        if (!a->quiet)
            print_problem(q, s);
    }
    return 0;
}

/* summary.json of the comparison. */
static gd_status write_summary(const char *dir, const gd_case *c, const cmp *C, const char **files, int nfiles,
                               int threads, gd_error *err)
{
    gd_opt_compare_problem pb[MAXPROB];
    for (int j = 0; j < C->n; j++) {
        pb[j].objective = C->p[j].objective;
        pb[j].dim = C->p[j].dim;
        pb[j].shift = C->p[j].shift;
        pb[j].res = &C->p[j].res;
    }
    return gd_summary_write_compare(dir, c, pb, C->n, files, nfiles, threads, err);
}

int run_compare(const cli_case_args *a, gd_case *cp, const char *dir)
{
    gd_case c = *cp;
    gd_error err = {0};
    cmp *C = calloc(1, sizeof *C);
    if (!C) {
        fprintf(stderr, "geardyn: out of memory\n");
        return 1;
    }
    list_problems(&c, C);
    gd_opt_compare_settings s;
    compare_settings(&c, a, &s);
    int threads = cli_threads(a->threads);
    double wall = 0;
    int rc = compare_all(a, &c, C, &s, &wall);
    if (rc)
        goto done;
    C->ngrid = make_grid(s.budget, &C->grid);
    if (C->ngrid < 0) {
        fprintf(stderr, "geardyn: out of memory\n");
        rc = 1;
        goto done;
    }
    if (gd_mkdir_p(dir, &err) != GD_OK || write_tables(dir, C, &err) != GD_OK) {
        rc = cli_fail(&err);
        goto done;
    }
    const char *files[16] = {"runs.csv", "statistics.csv", "convergence.csv", "ecdf.csv", "best_points.csv"};
    int nfiles = 5;
    const char *note = NULL;
    if (gd_gnuplot_wanted(c.plots, &note)) {
        gd_error perr = {0};
        gd_status pst = draw(dir, C, &perr);
        static const char *pics[] = {"convergence.png", "convergence.svg", "ecdf.png", "ecdf.svg"};
        gd_gnuplot_drawn(pst, &perr, pics, 4, files, &nfiles);
    }
    files[nfiles++] = "summary.json";
    if (write_summary(dir, &c, C, files, nfiles, threads, &err) != GD_OK) {
        rc = cli_fail(&err);
        goto done;
    }
    if (note && !a->quiet)
        fprintf(stderr, "geardyn: note: %s\n", note);
    if (!a->quiet)
        printf("%s: %d problem%s compared in %.1f s on %d thread%s\n", dir, C->n, C->n == 1 ? "" : "s", wall, threads,
               threads == 1 ? "" : "s");
done:
    for (int j = 0; j < C->n; j++)
        problem_free(&C->p[j], C->runs);
    free(C->grid);
    free(C);
    return rc;
}
