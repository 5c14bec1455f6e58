/* The optimize row (docs/optimisation.md): minimise the case's objective with its [optimize]
 * algorithm (`runs` runs, the best kept); the optimum, the convergence history and summary.json;
 * for the gear also the LTE of the optimum beside the unmodified pair's and the case's own
 * modification's (and, for the paper's pair, the paper's Table 2), the variables without effect at
 * the optimum, and the optimum's full LTCA (loaded contact pattern) and TCA (contact pattern)
 * outputs in optimum/ and optimum-tca/, through the rows of those analyses. */
#include "rows.h"
#include "geardyn/gd_scene.h"
#include "geardyn/gd_dynobj.h"
#include "geardyn/gd_geometry.h"
#include "../optimisation/opt_internal.h"
#include "../output/output_internal.h"
#include "row_optimize_robust.h"
#include "row_optimize_pareto.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A case for a flank's own LTCA / TCA outputs: the flank j (gd_row_optimize_flank) as its
 * [modification]; the unmodified flank's keys and the optimum's variables marked derived. */
static gd_status flank_case(const gd_case *c, const gd_optimize_outcome *o, int j, int analysis, gd_case *out,
                            gd_error *err)
{
    gd_status st = gd_case_copy(out, c, err);
    if (st != GD_OK)
        return st;
    const gd_pair pair = gd_row_optimize_flank(c, o, j);
    gd_pair_modification_to_case(&pair, out);
    out->analysis = analysis;
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    static const char *const all[] = {"root_relief_amount_um", "root_relief_length_mm", "tip_relief_amount_um",
                                      "tip_relief_length_mm", "lead_relief_inner_um", "lead_relief_outer_um",
                                      "lead_unmodified_length_mm", "lead_unmodified_centre_mm", "helix_slope_um"};
    if (j == 0)
        for (size_t k = 0; k < sizeof all / sizeof all[0]; k++)
            out->src[gd_case_find_key("modification", all[k]) - s] = GD_SRC_DERIVED;
    if (j != 2)
        return GD_OK;
    const gd_opt_gear_vars *v = &o->vars;
    for (int k = 0; k < v->n; k++)
        out->src[gd_case_find_key("modification", gd_opt_gear_variable(v->var[k], NULL, NULL)) - s] = GD_SRC_DERIVED;
    if (v->n > 0) { /* y6 follows y5 when only y5 is a variable */
        int y5 = 0, y6 = 0;
        for (int k = 0; k < v->n; k++) {
            y5 |= v->var[k] == 4;
            y6 |= v->var[k] == 5;
        }
        if (y5 && !y6)
            out->src[gd_case_find_key("modification", "lead_relief_outer_um") - s] = GD_SRC_DERIVED;
    }
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
    for (int j = 0; j < 4; j++)
        gd_ltca_result_free(&o->lte[j]);
    free(o->run_f);
    gd_opt_gear_free(o->gear_problem);
    gd_row_optimize_post_free(o);
    if (o->user_free)
        o->user_free(o->user);
    gd_opt_testfn_free(&o->tf);
    row_robust_free(o->robust);
    row_pareto_free(o->pareto);
    free(o);
}

static void dynobj_free(void *user) { gd_dynobj_free(user); }

/* gear-lte-range and gear-dynamic (docs/optimisation.md section 12): the objective of the gear
 * problem, its state kept in the outcome. */
static gd_status set_objective(const gd_case *c, gd_stop_hook stop, gd_optimize_outcome *o, gd_opt_gear *gear,
                               gd_error *err)
{
    gd_opt_gear_objective obj;
    if (o->objective == GD_OBJ_GEAR_LTE_RANGE || o->objective == GD_OBJ_GEAR_LTE) {
        gd_opt_lte_range *r = &o->lte_range;
        r->set = gd_ltca_settings_from_case(c);
        r->set.stop = stop;
        r->n = o->objective == GD_OBJ_GEAR_LTE ? 1 : c->n_opt_torques; /* gear-lte: the case's torque */
        for (int k = 0; k < r->n; k++) {
            r->torques_nm[k] = o->objective == GD_OBJ_GEAR_LTE ? c->torque_nm : c->opt_torques_nm[k];
            r->weights[k] = c->n_opt_torque_weights && o->objective != GD_OBJ_GEAR_LTE ? c->opt_torque_weights[k] : 1.0;
        }
        r->combine = c->opt_lte_range_combine;
        gd_opt_lte_range_objective(r, &obj);
    } else {
        gd_dynobj_settings ds;
        gd_dynobj_settings_from_case(c, &ds);
        gd_dynobj *d;
        gd_status st = gd_dynobj_create(c, &ds, &stop, &d, err);
        if (st != GD_OK)
            return st;
        o->user = d;
        o->user_free = dynobj_free;
        gd_dynobj_objective(d, &obj);
    }
    gd_opt_robust rb; /* optimize.robust */
    gd_opt_case_robust(c, &rb);
    gd_status st = gd_opt_gear_set_objectives(gear, 1, &obj, &rb, err);
    return st == GD_OK ? row_robust_init(c, o, err) : st;
}

/* The objective (and its recorded numbers) of the unmodified flank, the case's own and the optimum. */
static gd_status objective_of_flanks(const gd_case *c, gd_optimize_outcome *o, gd_error *err)
{
    for (int j = 0; j < 3; j++) {
        gd_pair t = gd_row_optimize_flank(c, o, j);
        gd_status st = opt_gear_value_of_pair_samples(o->gear_problem, &t, &o->objective_of[j], o->aux_of[j],
                                                      o->robust ? o->robust->values[j] : NULL, err);
        if (st != GD_OK)
            return gd_error_prefix(err, "the %s flank", j == 0 ? "unmodified" : j == 1 ? "case's" : "optimum's");
        row_robust_flank(o, j);
    }
    return GD_OK;
}

/* The problem of the case's first objective (the gear's modification or a test function), its
 * variables' names and bounds. */
static gd_status setup_problem(const gd_case *c, gd_stop_hook stop, gd_optimize_outcome *o, gd_opt_gear **gear,
                               gd_opt_testfn *tf, gd_opt_problem *p, gd_error *err)
{
    int objs[GD_OBJ_NOBJECTIVES];
    gd_opt_case_objectives(c, objs, GD_OBJ_NOBJECTIVES);
    o->objective = objs[0];
    o->gear = gd_opt_objective_is_gear(o->objective);
    if (o->gear)
        gd_opt_case_gear_vars(c, &o->vars);
    o->dim = o->gear ? o->vars.n : (int)c->opt_dimensions[0];
    o->runs = c->opt_runs;
    gd_status st;
    if (o->gear) {
        const gd_pair pair = gd_pair_from_case(c);
        gd_ltca_settings set = gd_ltca_settings_from_case(c);
        set.stop = stop; /* every evaluation's LTCA */
        double lower[GD_OPT_GEAR_NVARS], upper[GD_OPT_GEAR_NVARS];
        gd_opt_gear_bounds(c, &o->vars, lower, upper);
        st = gd_opt_gear_create(&pair, &set, &o->vars, lower, upper, gear, err);
        if (st == GD_OK && (o->objective != GD_OBJ_GEAR_LTE || c->opt_robust))
            st = set_objective(c, stop, o, *gear, err);
        if (st == GD_OK) {
            gd_opt_gear_problem(*gear, p);
            o->active_mm = gd_opt_gear_active_profile_mm(*gear);
            o->pair = pair;
            gd_opt_gear_from_pair(&o->vars, &pair, o->case_value);
            o->reference = o->case_value;
            o->paper = gd_opt_gear_is_paper_pair(&pair);
            if (o->paper) {
                gd_pair t = pair;
                gd_opt_gear_table2(&t);
                gd_opt_gear_from_pair(&o->vars, &t, o->table2);
            }
            for (int i = 0; i < o->dim; i++)
                snprintf(o->names[i], sizeof o->names[i], "%s", gd_opt_gear_variable(o->vars.var[i], NULL, NULL));
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
/* The evaluations of all the runs for the caller's progress (gd_run_env.optimize_progress): run r
 * of runs, each of budget evaluations. */
typedef struct opt_progress {
    const gd_run_env *env;
    long run, runs, budget;
} opt_progress;

static void on_evaluation(void *user, long evaluations, long budget)
{
    const opt_progress *q = user;
    (void)budget;
    q->env->optimize_progress(q->env->user, q->run * q->budget + evaluations, q->runs * q->budget);
}

static gd_status run_all(const gd_run_env *env, const gd_case *c, const gd_opt_problem *p, gd_opt_settings *s,
                         gd_optimize_outcome *o, double *run_f, double *wall, gd_error *err)
{
    opt_progress q = {env, 0, o->runs, s->budget};
    if (env && env->optimize_progress) {
        s->progress = on_evaluation;
        s->progress_user = &q;
    }
    for (int r = 0; r < o->runs; r++) {
        q.run = r;
        s->seed = gd_opt_run_seed(c, r);
        gd_status st = gd_opt_run(p, s, &o->res[r], err);
        if (st != GD_OK) {
            s->progress = NULL;
            s->progress_user = NULL;
            return st;
        }
        run_f[r] = o->res[r].f;
        *wall += o->res[r].wall_s;
        if (o->res[r].f < o->res[o->best].f)
            o->best = r;
        if (env && env->optimize_run)
            env->optimize_run(env->user, r, o->runs, s->seed, &o->res[r]);
    }
    s->progress = NULL; /* q is this function's */
    s->progress_user = NULL;
    return GD_OK;
}

/* The gear: LTE of the unmodified pair, of the case's own modification, of the optimum and, for the
 * paper's pair, of the paper's Table 2 (the same LTCA as the objective). */
static gd_status compute_lte(const gd_case *c, gd_stop_hook stop, gd_optimize_outcome *o, gd_error *err)
{
    gd_status st = GD_OK;
    for (int j = 0; j < (o->paper ? 4 : 3) && st == GD_OK; j++) {
        gd_pair t = gd_row_optimize_flank(c, o, j);
        gd_ltca_settings set = gd_ltca_settings_from_case(c);
        set.stop = stop;
        st = gd_ltca_run_opts(&t, &set, 0, 0, &o->lte[j], err);
    }
    return st;
}

/* The variables without effect at the optimum: a relief length (y2, y4) whose amount (y1, y3), or
 * the unmodified lead band (y7, y8) when both lead reliefs (y5, y6) are, below 1 % of the optimum's
 * LTE as a displacement normal to the flank (LTE r_b2 cos(beta_b)): a relief cannot change the
 * LTE by more than its amount, so where it lies cannot matter; and the convergence of the best run:
 * the relative fall of its best value over the last tenth of its evaluations. */
static void assess_optimum(const gd_case *c, gd_optimize_outcome *o)
{
    const gd_opt_result *b = &o->res[o->best];
    if (o->gear) {
        for (int k = 0; k < o->dim; k++)
            o->no_effect[k][0] = '\0';
        gd_pair t = gd_pair_from_case(c);
        gd_opt_gear_apply(&o->vars, &t, b->y);
        gd_geometry g;
        gd_error e = {0};
        double tiny = 0.0; /* um */
        if (gd_geometry_compute(&t, &g, &e) == GD_OK)
            tiny = 0.01 * b->f * M_PI / (180.0 * 3600.0) * g.rb[1] * cos(g.beta_b) * 1e6;
        double lead = fmax(t.lead_relief_inner_um, t.lead_relief_outer_um);
        for (int k = 0; k < o->dim; k++) {
            int id = o->vars.var[k];
            if (id == 1 && t.root_relief_amount_um < tiny)
                snprintf(o->no_effect[k], sizeof o->no_effect[k], "no effect: the root relief y1 is %.3g um",
                         t.root_relief_amount_um);
            else if (id == 3 && t.tip_relief_amount_um < tiny)
                snprintf(o->no_effect[k], sizeof o->no_effect[k], "no effect: the tip relief y3 is %.3g um",
                         t.tip_relief_amount_um);
            else if ((id == 6 || id == 7) && lead < tiny)
                snprintf(o->no_effect[k], sizeof o->no_effect[k], "no effect: the lead relief y5 / y6 is %.3g um",
                         lead);
        }
        for (int k = 0; k < o->dim; k++)
            o->no_effect_ptr[k] = o->no_effect[k][0] ? o->no_effect[k] : NULL;
    }
    long n = b->evaluations, m = n - (n >= 10 ? n / 10 : 1); /* the best before the last tenth */
    double before = m >= 1 && b->best_history ? b->best_history[m - 1] : b->f;
    o->last_tenth_improvement = (before - b->f) / fmax(fabs(b->f), 1e-300);
    o->converged = o->last_tenth_improvement <= 1e-3;
}

/* A flank's own analysis (LTCA or TCA; flank j of gd_row_optimize_flank) in the directory sub of
 * out, through that analysis's row, quietly (no progress), with its pictures (env); sub joins out's
 * files. */
static gd_status flank_outputs(const gd_case *c, const gd_run_env *env, const gd_optimize_outcome *o, int j,
                               int analysis, const char *sub, gd_run_dir *out, gd_error *err)
{
    gd_case t;
    gd_status st = flank_case(c, o, j, analysis, &t, err);
    if (st != GD_OK)
        return st;
    gd_run_env quiet = {0};
    if (env) {
        quiet.user = env->user;
        quiet.threads = env->threads;
        quiet.pictures = env->pictures;
        quiet.draw = env->draw;
        quiet.note = env->note;
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
    if (gd_opt_case_nobj(&c) == 2) { /* two objectives: their Pareto front (row_optimize_pareto.c) */
        gd_status st = row_pareto_run(&c, env, o, err);
        if (st != GD_OK) {
            gd_row_optimize_free(o);
            return st;
        }
        *result = o;
        return GD_OK;
    }
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
    if (st == GD_OK)
        assess_optimum(&c, o);
    if (st == GD_OK && o->gear)
        st = compute_lte(&c, stop, o, err);
    if (st == GD_OK && o->gear && (o->objective != GD_OBJ_GEAR_LTE || o->robust))
        st = objective_of_flanks(&c, o, err);
    if (st == GD_OK && o->gear && o->objective != GD_OBJ_GEAR_LTE)
        st = gd_row_optimize_post(&c, env, o, err);
    /* each flank's loaded contact pattern (LTCA) and unloaded one (TCA), in unmodified/, case/,
     * optimum/ and their -tca/ */
    static const char *const sub[3][2] = {{"unmodified", "unmodified-tca"}, {"case", "case-tca"},
                                          {"optimum", "optimum-tca"}};
    for (int j = 0; j < 3 && o->gear && st == GD_OK; j++) {
        st = flank_outputs(&c, env, o, j, GD_ANALYSIS_LTCA, sub[j][0], out, err);
        if (st == GD_OK)
            st = flank_outputs(&c, env, o, j, GD_ANALYSIS_TCA, sub[j][1], out, err);
    }
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
    const gd_optimize_outcome *o = result;
    if (o->pareto)
        return gd_pareto_write(out, o, err);
    if (o->gear)
        gd_optimize_write_lte(out, o, err);
    gd_status st = gd_optimize_write_optimum(out, o, err);
    if (st == GD_OK && o->robust)
        st = gd_optimize_write_robust(out, c, o, err);
    if (st == GD_OK)
        st = gd_optimize_write_convergence(out, o, err);
    if (st == GD_OK && o->post)
        st = gd_optpost_write_tables(out, c, o->post, err);
    return st;
}

/* summary.json of the optimisation. */
gd_status gd_row_optimize_summary(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    const gd_optimize_outcome *o = result;
    if (o->pareto)
        return gd_summary_write_pareto(out, c, o, err);
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
    sm.lte_case = o->gear ? o->lte[1].lte_pp_arcsec : NAN;
    sm.lte_optimum = o->gear ? o->lte[2].lte_pp_arcsec : NAN;
    sm.lte_table2 = o->gear && o->paper ? o->lte[3].lte_pp_arcsec : NAN;
    sm.vars = o->gear ? &o->vars : NULL;
    sm.case_value = o->gear ? o->case_value : NULL;
    sm.table2 = o->gear && o->paper ? o->table2 : NULL;
    sm.no_effect = o->gear ? o->no_effect_ptr : NULL;
    sm.last_tenth_improvement = o->last_tenth_improvement;
    sm.converged = o->converged;
    sm.active_profile_mm = o->active_mm;
    if (o->gear && (o->objective != GD_OBJ_GEAR_LTE || o->robust)) {
        sm.objective_unit = o->objective != GD_OBJ_GEAR_DYNAMIC ? "arcsec"
                            : c->opt_dynamic_response == GD_DYN_DTE_PP ? "um" : "m/s^2";
        sm.ntorques = o->objective == GD_OBJ_GEAR_LTE ? 1 : c->n_opt_torques;
        sm.torques_nm = o->objective == GD_OBJ_GEAR_LTE ? &c->torque_nm : c->opt_torques_nm;
        sm.robust = o->robust;
        for (int j = 0; j < 3; j++) {
            sm.objective_of[j] = o->objective_of[j];
            sm.aux_of[j] = o->aux_of[j];
        }
        sm.post = o->post;
    }
    sm.wall_s = wall;
    return gd_summary_write_optimize(out, c, &sm, err);
}

void gd_row_optimize_pictures(const gd_case *c, const void *result, gd_run_dir *out, const gd_run_env *env)
{
    const gd_plotter p = gd_row_plotter(env, out);
    if (((const gd_optimize_outcome *)result)->pareto) {
        gd_plot_pareto(&p, c, (const gd_optimize_outcome *)result);
    } else {
        gd_plot_optimize(&p, c, (const gd_optimize_outcome *)result);
        gd_plot_optpost(&p, c, (const gd_optimize_outcome *)result);
    }
}
