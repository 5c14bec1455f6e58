/* The optimize row (docs/optimisation.md): minimise the case's objective with its [optimize]
 * algorithm (`runs` runs, the best kept); the optimum, the convergence history and summary.json;
 * for the gear also the LTE of the optimum beside the unmodified pair's and the paper's Table 2,
 * and the optimum's full LTCA (loaded contact pattern) and TCA (contact pattern) outputs in
 * optimum/ and optimum-tca/, through the rows of those analyses. */
#include "rows.h"
#include "geardyn/gd_scene.h"
#include "../optimisation/opt_internal.h"
#include "../output/output_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A case for the optimum's own LTCA / TCA outputs: the optimum as its [modification], marked derived. */
static gd_status optimum_case(const gd_case *c, const double *x, int analysis, gd_case *out, gd_error *err)
{
    gd_status st = gd_case_copy(out, c, err);
    if (st != GD_OK)
        return st;
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
    return GD_OK;
}

void gd_row_optimize_free(void *result)
{
    gd_optimize_outcome *o = result;
    if (!o)
        return;
    if (o->res)
        for (int r = 0; r < o->runs; r++)
            gd_opt_result_free(&o->res[r]);
    free(o->res);
    for (int j = 0; j < 3; j++)
        gd_ltca_result_free(&o->lte[j]);
    free(o->run_f);
    gd_opt_gear_free(o->gear_problem);
    gd_opt_testfn_free(&o->tf);
    free(o);
}

/* The problem of the case's first objective (the gear's modification or a test function), its
 * variables' names and bounds. */
static gd_status setup_problem(const gd_case *c, gd_stop_hook stop, gd_optimize_outcome *o, gd_opt_gear **gear,
                               gd_opt_testfn *tf, gd_opt_problem *p, gd_error *err)
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
        gd_ltca_settings set = gd_ltca_settings_from_case(c);
        set.stop = stop; /* every evaluation's LTCA */
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
static gd_status run_all(const gd_run_env *env, const gd_case *c, const gd_opt_problem *p, gd_opt_settings *s,
                         gd_optimize_outcome *o, double *run_f, double *wall, gd_error *err)
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
        if (env && env->optimize_run)
            env->optimize_run(env->user, r, o->runs, s->seed, &o->res[r]);
    }
    return GD_OK;
}

/* The gear: LTE of the unmodified pair, Table 2 and the optimum (the same LTCA as the objective). */
static gd_status compute_lte(const gd_case *c, gd_stop_hook stop, gd_optimize_outcome *o, gd_error *err)
{
    const double zero[GD_OPT_GEAR_DIM] = {0};
    const double *xs[3] = {zero, o->table2, o->res[o->best].y};
    gd_status st = GD_OK;
    for (int j = 0; j < 3 && st == GD_OK; j++) {
        gd_pair t = gd_pair_from_case(c);
        gd_ltca_settings set = gd_ltca_settings_from_case(c);
        set.stop = stop;
        gd_opt_gear_apply(&t, xs[j]);
        st = gd_ltca_run_opts(&t, &set, 0, 0, &o->lte[j], err);
    }
    return st;
}

/* The optimum's own analysis (LTCA or TCA) in the directory sub of out, through that analysis's
 * row, quietly (no progress), with its pictures (env); sub joins out's files. */
static gd_status optimum_outputs(const gd_case *c, const gd_run_env *env, const double *y, int analysis,
                                 const char *sub, gd_run_dir *out, gd_error *err)
{
    gd_case t;
    gd_status st = optimum_case(c, y, analysis, &t, err);
    if (st != GD_OK)
        return st;
    gd_run_env quiet = {0};
    if (env) {
        quiet.user = env->user;
        quiet.threads = env->threads;
        quiet.pictures = env->pictures;
        quiet.should_stop = env->should_stop;
    }
    char name[64];
    gd_run_dir *sd = NULL;
    st = gd_run_dir_open_sub(out, sub, &sd, err); /* made in out's stage (or kept with out's files) */
    if (st == GD_OK)
        st = gd_analysis_run_dir(gd_analysis_find(analysis), &t, &quiet, sd, err);
    gd_run_dir_close(sd);
    gd_case_free(&t);
    snprintf(name, sizeof name, "%s/", sub);
    return st == GD_OK ? gd_run_dir_add(out, name, err) : st;
}

gd_status gd_row_optimize_run(const gd_case *cp, const gd_run_env *env, gd_run_dir *out, void **result,
                              gd_error *err)
{
    *result = NULL;
    gd_case c = *cp;
    gd_optimize_outcome *o = calloc(1, sizeof *o); /* about 80 kB: names and bounds of up to 1000 variables */
    if (!o)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    gd_opt_problem p;
    const gd_stop_hook stop = gd_row_stop(env);
    gd_status st = setup_problem(&c, stop, o, &o->gear_problem, &o->tf, &p, err);
    if (st == GD_OK) {
        o->res = calloc((size_t)o->runs, sizeof *o->res);
        o->run_f = calloc((size_t)o->runs, sizeof(double));
        if (!o->res || !o->run_f)
            st = gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    }
    int threads = env ? env->threads : 0;
    gd_opt_settings *s = &o->settings;
    gd_opt_settings_default(s);
    s->algorithm = c.opt_algorithm;
    s->budget = gd_opt_case_budget(&c);
    s->population = c.opt_population;
    s->threads = threads;
    s->keep_history = 1;
    s->stop = stop;
    o->threads = opt_threads(c.opt_algorithm == GD_OPT_ALO || c.opt_algorithm == GD_OPT_RANDOM ? threads : 1);
    if (st == GD_OK)
        st = run_all(env, &c, &p, s, o, o->run_f, &o->wall_s, err);
    if (st == GD_OK && o->gear)
        st = compute_lte(&c, stop, o, err);
    if (st == GD_OK && o->gear)
        st = optimum_outputs(&c, env, o->res[o->best].y, GD_ANALYSIS_LTCA, "optimum", out, err);
    if (st == GD_OK && o->gear)
        st = optimum_outputs(&c, env, o->res[o->best].y, GD_ANALYSIS_TCA, "optimum-tca", out, err);
    if (st != GD_OK) {
        gd_row_optimize_free(o);
        return st;
    }
    *result = o;
    return GD_OK;
}

/* lte.csv (the gear; a failure there leaves it out), optimum.csv, convergence.csv. */
gd_status gd_row_optimize_write(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    (void)c;
    const gd_optimize_outcome *o = result;
    if (o->gear)
        gd_optimize_write_lte(out, o, err);
    gd_status st = gd_optimize_write_optimum(out, o, err);
    if (st == GD_OK)
        st = gd_optimize_write_convergence(out, o, err);
    return st;
}

/* summary.json of the optimisation. */
gd_status gd_row_optimize_summary(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    const gd_optimize_outcome *o = result;
    const gd_opt_testfn *tf = &o->tf;
    const gd_opt_settings *s = &o->settings;
    int threads = o->threads;
    const double *run_f = o->run_f;
    double wall = o->wall_s;
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
    return gd_summary_write_optimize(out, c, &sm, err);
}

