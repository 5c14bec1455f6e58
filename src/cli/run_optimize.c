/* The `optimize` analysis on the command line (docs/optimisation.md): minimise the case's objective
 * with its [optimize] algorithm (`runs` runs, the best kept), and write the optimum, the
 * convergence history, summary.json and pictures; for the gear problem also the LTE of the
 * optimum beside the unmodified pair's and the paper's Table 2, and the optimum's full LTCA
 * (loaded contact pattern) and TCA (contact pattern) outputs in optimum/ and optimum-tca/. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NPICS 2
#define OPT_MAXDIM 1000 /* the schema's largest dimension */

typedef struct opt_out {
    int objective, dim, gear, runs;
    gd_opt_result *res;      /* runs */
    int best;
    char names[OPT_MAXDIM][48];
    const char *name_ptr[OPT_MAXDIM];
    double lower[OPT_MAXDIM], upper[OPT_MAXDIM];
    const double *reference; /* Table 2 (gear) or the true minimiser */
    double table2[GD_OPT_GEAR_DIM];
    gd_ltca_result lte[3];   /* gear: unmodified, Table 2, optimum */
    double active_mm;
} opt_out;

static gd_status write_optimum(const char *dir, const opt_out *o, gd_error *err)
{
    gd_atomic_file f;
    gd_status st = gd_atomic_open(&f, dir, "optimum.csv", err);
    if (st != GD_OK)
        return st;
    const gd_opt_result *b = &o->res[o->best];
    fprintf(f.fp, "variable,symbol,unit,value,lower,upper,%s\n", o->gear ? "paper_table2" : "minimiser");
    for (int i = 0; i < o->dim; i++) {
        const char *unit = "", *sym = o->names[i];
        const char *key = o->gear ? gd_opt_gear_variable(i, &unit, &sym) : o->names[i];
        fprintf(f.fp, "%s,%s,%s,%.10g,%.10g,%.10g,%.10g\n", key, sym, unit, b->y[i], o->lower[i], o->upper[i],
                o->reference[i]);
        if (o->gear && i == 4) /* y6 = y5: the symmetric lead relief */
            fprintf(f.fp, "lead_relief_outer_um,y6,um,%.10g,%.10g,%.10g,%.10g\n", b->y[4], o->lower[4], o->upper[4],
                    o->reference[4]);
    }
    return gd_atomic_commit(&f, err);
}

static gd_status write_convergence(const char *dir, const opt_out *o, gd_error *err)
{
    gd_atomic_file f;
    gd_status st = gd_atomic_open(&f, dir, "convergence.csv", err);
    if (st != GD_OK)
        return st;
    fprintf(f.fp, "run,seed_offset,evaluation,f,best_f\n");
    for (int r = 0; r < o->runs; r++)
        for (long k = 0; k < o->res[r].evaluations; k++)
            fprintf(f.fp, "%d,%d,%ld,%.12g,%.12g\n", r + 1, r, k + 1, o->res[r].f_history[k], o->res[r].best_history[k]);
    return gd_atomic_commit(&f, err);
}

static gd_status write_lte(const char *dir, const opt_out *o, gd_error *err)
{
    gd_atomic_file f;
    gd_status st = gd_atomic_open(&f, dir, "lte.csv", err);
    if (st != GD_OK)
        return st;
    fprintf(f.fp, "phi1_deg,lte_unmodified_arcsec,lte_table2_arcsec,lte_optimum_arcsec\n");
    for (int k = 0; k < o->lte[0].npos; k++)
        fprintf(f.fp, "%.10g,%.10g,%.10g,%.10g\n", o->lte[0].phi1[k] * 180 / M_PI, o->lte[0].lte_arcsec[k],
                o->lte[1].lte_arcsec[k], o->lte[2].lte_arcsec[k]);
    return gd_atomic_commit(&f, err);
}

static gd_status draw(const char *dir, const gd_case *c, const opt_out *o, gd_error *err)
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
            "set terminal %s\nset output '%s/.convergence%s.tmp'\n"
            "set title '%s on %s (%d variables): %d run%s of %ld evaluations, best %.6g%s' noenhanced\n"
            "set xlabel 'objective evaluations'\nset ylabel '%s'\nset logscale y\nset grid\nset key top right\n"
            "plot '%s/convergence.csv' every ::1 using ($1 == %d ? $3 : 1/0):4 with points pt 7 ps 0.25 lc rgb '#b0b0b0' "
            "title 'every evaluation (best run)'",
            fmt[fi][0], dir, fmt[fi][1], gd_opt_algorithm_name(c->opt_algorithm), gd_opt_objective_name(o->objective),
            o->dim, o->runs, o->runs == 1 ? "" : "s", b->evaluations, b->f, o->gear ? " arcsec" : "",
            o->gear ? "LTE peak-to-peak (arcsec)" : "objective", dir, o->best + 1);
        for (int r = 0; r < o->runs && r < 20; r++)
            n += snprintf(script + n, sizeof script - n, ", '%s/convergence.csv' every ::1 using ($1 == %d ? $3 : 1/0):5 "
                          "with lines lw %d title 'best so far, run %d'", dir, r + 1, r == o->best ? 3 : 1, r + 1);
        n += snprintf(script + n, sizeof script - n, "\nunset output\nunset logscale y\n");
        if (o->gear) {
            double m[3];
            for (int j = 0; j < 3; j++)
                m[j] = o->lte[j].lte_mean_arcsec;
            n += snprintf(script + n, sizeof script - n,
                "set terminal %s\nset output '%s/.lte%s.tmp'\n"
                "set title 'Loaded transmission error over one mesh cycle, %.0f N m (about each mean)'\n"
                "set xlabel 'pinion angle (deg)'\nset ylabel 'LTE (arcsec of the gear)'\nset key bottom right\n"
                "plot '%s/lte.csv' every ::1 using 1:($2 - %.10g) with linespoints pt 7 ps 0.5 lw 2 "
                "title sprintf('unmodified: %.4f arcsec p-p'), "
                "'' every ::1 using 1:($3 - %.10g) with linespoints pt 5 ps 0.5 lw 2 dt 2 "
                "title sprintf('paper Table 2: %.4f arcsec p-p'), "
                "'' every ::1 using 1:($4 - %.10g) with linespoints pt 9 ps 0.6 lw 3 "
                "title sprintf('optimum: %.4f arcsec p-p')\nunset output\n",
                fmt[fi][0], dir, fmt[fi][1], c->torque_nm, dir, m[0], o->lte[0].lte_pp_arcsec, m[1],
                o->lte[1].lte_pp_arcsec, m[2], o->lte[2].lte_pp_arcsec);
        }
    }
    if (n >= (int)sizeof script)
        return gd_error_set(err, GD_ERR_INTERNAL, "gnuplot script too long");
    return gd_gnuplot_draw(dir, script, names, npics, err);
}

/* A case for the optimum's own LTCA / TCA outputs: the optimum as its [modification], marked derived. */
static int optimum_case(const gd_case *c, const double *x, int analysis, gd_case *out, gd_error *err)
{
    if (gd_case_copy(out, c, err) != GD_OK)
        return 1;
    gd_pair pair = gd_pair_from_case(out);
    gd_opt_gear_apply(&pair, x);
    gd_pair_modification_to_case(&pair, out);
    out->analysis = analysis;
    static const char *const keys[] = {"root_relief_amount_um", "root_relief_length_mm", "tip_relief_amount_um",
                                       "tip_relief_length_mm", "lead_relief_inner_um", "lead_relief_outer_um",
                                       "lead_unmodified_length_mm"};
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        out->src[gd_case_find_key("modification", keys[i]) - s] = GD_SRC_DERIVED;
    return 0;
}

static void out_free(opt_out *o)
{
    if (o->res)
        for (int r = 0; r < o->runs; r++)
            gd_opt_result_free(&o->res[r]);
    free(o->res);
    for (int j = 0; j < 3; j++)
        gd_ltca_result_free(&o->lte[j]);
}

/* The problem of the case's first objective (the gear's modification or a test function), its
 * variables' names and bounds. */
static gd_status setup_problem(const gd_case *c, opt_out *o, gd_opt_gear **gear, gd_opt_testfn *tf,
                               gd_opt_problem *p, gd_error *err)
{
    int objs[GD_OBJ_NOBJECTIVES];
    gd_opt_case_objectives(c, objs, GD_OBJ_NOBJECTIVES);
    o->objective = objs[0];
    o->gear = o->objective == GD_OBJ_GEAR_LTE;
    o->dim = o->gear ? GD_OPT_GEAR_DIM : (int)c->opt_dimensions[0];
    o->runs = c->opt_runs;
    gd_status st;
    if (o->gear) {
        const gd_pair pair = gd_pair_from_case(c);
        const gd_ltca_settings set = gd_ltca_settings_from_case(c);
        double lower[GD_OPT_GEAR_DIM], upper[GD_OPT_GEAR_DIM];
        gd_opt_gear_bounds(c, lower, upper);
        st = gd_opt_gear_create(&pair, &set, lower, upper, gear, err);
        if (st == GD_OK) {
            gd_opt_gear_problem(*gear, p);
            o->active_mm = gd_opt_gear_active_profile_mm(*gear);
            gd_opt_gear_table2(o->table2);
            o->reference = o->table2;
            for (int i = 0; i < o->dim; i++)
                snprintf(o->names[i], sizeof o->names[i], "%s", gd_opt_gear_variable(i, NULL, NULL));
        }
    } else {
        st = gd_opt_testfn_init(tf, o->objective, o->dim, c->opt_shift, gd_opt_instance_seed(c, 0), err);
        if (st == GD_OK) {
            gd_opt_testfn_problem(tf, p);
            o->reference = tf->optimum;
            for (int i = 0; i < o->dim; i++)
                snprintf(o->names[i], sizeof o->names[i], "x%d", i + 1);
        }
    }
    if (st != GD_OK)
        return st;
    for (int i = 0; i < o->dim; i++) {
        o->lower[i] = p->lower[i];
        o->upper[i] = p->upper[i];
        o->name_ptr[i] = o->names[i];
    }
    return GD_OK;
}

/* The runs, each from its own seed; the best kept in o->best, each run's best in run_f, their
 * wall time summed in *wall. */
static gd_status run_all(const cli_case_args *a, const gd_case *c, const gd_opt_problem *p, gd_opt_settings *s,
                         opt_out *o, double *run_f, double *wall, gd_error *err)
{
    for (int r = 0; r < o->runs; r++) {
        s->seed = gd_opt_run_seed(c, r);
        gd_status st = gd_opt_run(p, s, &o->res[r], err);
        if (st != GD_OK)
            return st;
        run_f[r] = o->res[r].f;
        *wall += o->res[r].wall_s;
        if (o->res[r].f < o->res[o->best].f)
            o->best = r;
        if (!a->quiet && o->runs > 1)
            printf("  run %d (seed %lu): %.8g after %ld evaluations, %.1f s\n", r + 1, s->seed, o->res[r].f,
                   o->res[r].evaluations, o->res[r].wall_s);
    }
    return GD_OK;
}

/* The gear: LTE of the unmodified pair, Table 2 and the optimum (the same LTCA as the objective). */
static gd_status compute_lte(const gd_case *c, opt_out *o, gd_error *err)
{
    const double zero[GD_OPT_GEAR_DIM] = {0};
    const double *xs[3] = {zero, o->table2, o->res[o->best].y};
    gd_status st = GD_OK;
    for (int j = 0; j < 3 && st == GD_OK; j++) {
        gd_pair t = gd_pair_from_case(c);
        const gd_ltca_settings set = gd_ltca_settings_from_case(c);
        gd_opt_gear_apply(&t, xs[j]);
        st = gd_ltca_run_opts(&t, &set, 0, 0, &o->lte[j], err);
    }
    return st;
}

/* The gear: the optimum's loaded contact pattern and its TCA contact pattern, with the writers of
 * those analyses, and lte.csv; returns 0 or the exit status. */
static int write_gear_outputs(const cli_case_args *a, const gd_case *c, const char *dir, const opt_out *o,
                              const char **files, int *nfiles, gd_error *err)
{
    const gd_opt_result *b = &o->res[o->best];
    cli_case_args sub = *a;
    sub.quiet = 1;
    char sdir[GD_PATH_MAX + 32];
    gd_case t;
    snprintf(sdir, sizeof sdir, "%s/optimum", dir);
    if (optimum_case(c, b->y, GD_ANALYSIS_LTCA, &t, err) != 0)
        return cli_fail(err);
    int rc = run_ltca(&sub, &t, sdir);
    gd_case_free(&t);
    if (rc)
        return rc;
    files[(*nfiles)++] = "optimum/";
    snprintf(sdir, sizeof sdir, "%s/optimum-tca", dir);
    if (optimum_case(c, b->y, GD_ANALYSIS_TCA, &t, err) != 0)
        return cli_fail(err);
    rc = run_tca(&sub, &t, sdir);
    gd_case_free(&t);
    if (rc)
        return rc;
    files[(*nfiles)++] = "optimum-tca/";
    if (write_lte(dir, o, err) == GD_OK)
        files[(*nfiles)++] = "lte.csv";
    return 0;
}

/* summary.json of the optimisation. */
static gd_status write_summary(const char *dir, const gd_case *c, const opt_out *o, const gd_opt_testfn *tf,
                               const gd_opt_settings *s, int threads, const double *run_f, double wall,
                               const char **files, int nfiles, gd_error *err)
{
    gd_opt_optimize_summary sm;
    memset(&sm, 0, sizeof sm);
    sm.objective = o->objective;
    sm.dim = o->dim;
    sm.algorithm = c->opt_algorithm;
    sm.runs = o->runs;
    sm.threads = threads;
    sm.budget = s->budget;
    sm.names = o->name_ptr;
    sm.lower = o->lower;
    sm.upper = o->upper;
    sm.best = &o->res[o->best];
    sm.best_run = o->best;
    sm.run_f = run_f;
    sm.true_optimum = o->gear ? NULL : tf->optimum;
    sm.lte_unmodified = o->gear ? o->lte[0].lte_pp_arcsec : NAN;
    sm.lte_table2 = o->gear ? o->lte[1].lte_pp_arcsec : NAN;
    sm.lte_optimum = o->gear ? o->lte[2].lte_pp_arcsec : NAN;
    sm.active_profile_mm = o->active_mm;
    sm.wall_s = wall;
    return gd_summary_write_optimize(dir, c, &sm, files, nfiles, err);
}

/* The progress report: the best run, its variables and for the gear the LTE of the three pairs. */
static void print_result(const char *dir, const gd_case *c, const opt_out *o, long budget, double wall, int threads)
{
    const gd_opt_result *b = &o->res[o->best];
    printf("%s: %s on %s, %d variable%s, %d run%s of %ld evaluations (%.1f s, %d thread%s): best %.8g%s "
           "(evaluation %ld of run %d)\n", dir, gd_opt_algorithm_name(c->opt_algorithm),
           gd_opt_objective_name(o->objective), o->dim, o->dim == 1 ? "" : "s", o->runs, o->runs == 1 ? "" : "s",
           budget, wall, threads, threads == 1 ? "" : "s", b->f, o->gear ? " arcsec" : "", b->best_at, o->best + 1);
    for (int i = 0; i < o->dim; i++) {
        const char *unit = "", *sym = o->names[i];
        if (o->gear)
            gd_opt_gear_variable(i, &unit, &sym);
        printf("  %-4s %-28s %12.6g %-3s in [%g, %g]   %s %g\n", sym, o->names[i], b->y[i], unit, o->lower[i],
               o->upper[i], o->gear ? "Table 2" : "minimiser", o->reference[i]);
    }
    if (o->gear)
        printf("  LTE peak-to-peak: unmodified %.6g, Table 2 %.6g, optimum %.6g arcsec (%+.1f %% against the "
               "unmodified pair; the paper: 4.194 -> 1.157, -72.41 %%)\n", o->lte[0].lte_pp_arcsec,
               o->lte[1].lte_pp_arcsec, o->lte[2].lte_pp_arcsec,
               100 * (o->lte[2].lte_pp_arcsec - o->lte[0].lte_pp_arcsec) / o->lte[0].lte_pp_arcsec);
}

int run_optimize(const cli_case_args *a, gd_case *cp, const char *dir)
{
    gd_case c = *cp;
    gd_error err = {0};
    opt_out o; /* about 80 kB: names and bounds of up to OPT_MAXDIM variables */
    memset(&o, 0, sizeof o);
    gd_opt_gear *gear = NULL;
    gd_opt_testfn tf;
    memset(&tf, 0, sizeof tf);
    gd_opt_problem p;
    gd_status st = setup_problem(&c, &o, &gear, &tf, &p, &err);
    if (st != GD_OK)
        return cli_fail(&err);
    int rc = 0;
    o.res = calloc((size_t)o.runs, sizeof *o.res);
    double *run_f = calloc((size_t)o.runs, sizeof(double));
    if (!o.res || !run_f) {
        fprintf(stderr, "geardyn: out of memory\n");
        rc = 1;
        goto done;
    }
    gd_opt_settings s;
    gd_opt_settings_default(&s);
    s.algorithm = c.opt_algorithm;
    s.budget = gd_opt_case_budget(&c);
    s.population = c.opt_population;
    s.threads = a->threads;
    s.keep_history = 1;
    int threads = cli_threads(c.opt_algorithm == GD_OPT_ALO || c.opt_algorithm == GD_OPT_RANDOM ? a->threads : 1);
    double wall = 0;
    if (run_all(a, &c, &p, &s, &o, run_f, &wall, &err) != GD_OK ||
        (o.gear && compute_lte(&c, &o, &err) != GD_OK) || gd_mkdir_p(dir, &err) != GD_OK) {
        rc = cli_fail(&err);
        goto done;
    }
    const char *files[32];
    int nfiles = 0;
    if (o.gear && (rc = write_gear_outputs(a, &c, dir, &o, files, &nfiles, &err)) != 0)
        goto done;
    st = write_optimum(dir, &o, &err);
    if (st == GD_OK) {
        files[nfiles++] = "optimum.csv";
        st = write_convergence(dir, &o, &err);
    }
    if (st != GD_OK) {
        rc = cli_fail(&err);
        goto done;
    }
    files[nfiles++] = "convergence.csv";
    const char *note = NULL;
    if (gd_gnuplot_wanted(c.plots, &note)) {
        gd_error perr = {0};
        gd_status pst = draw(dir, &c, &o, &perr);
        static const char *pics[] = {"convergence.png", "convergence.svg", "lte.png", "lte.svg"};
        gd_gnuplot_drawn(pst, &perr, pics, o.gear ? 4 : 2, files, &nfiles);
    }
    files[nfiles++] = "summary.json";
    st = write_summary(dir, &c, &o, &tf, &s, threads, run_f, wall, files, nfiles, &err);
    if (st != GD_OK) {
        rc = cli_fail(&err);
        goto done;
    }
    if (note && !a->quiet)
        fprintf(stderr, "geardyn: note: %s\n", note);
    if (!a->quiet)
        print_result(dir, &c, &o, s.budget, wall, threads);
done:
    free(run_f);
    out_free(&o);
    gd_opt_gear_free(gear);
    gd_opt_testfn_free(&tf);
    return rc;
}
