/* The compare-optimizers row (docs/optimisation.md section 7): every optimiser of the case, on
 * every objective (and dimension) of the case, with the same budget, seeds and problem instances;
 * the tables of the runs and statistics, convergence quartiles and runtime distributions
 * (COCO/BBOB), summary.json. Everything but the wall-time columns is independent of the thread
 * count. */
#include "rows.h"
#include "geardyn/gd_dynobj.h"
#include "geardyn/gd_scene.h"
#include "../optimisation/opt_internal.h"
#include "../output/output_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* gear-lte beside objective2 = gear-dynamic: the two objectives' states (they outlive the gear problem) */
typedef struct two_objectives {
    gd_opt_lte_range lte;
    gd_dynobj *dyn;
} two_objectives;

static void problem_free(gd_compare_entry *q, int runs)
{
    gd_opt_gear_free(q->gear);
    if (q->dyn) {
        gd_dynobj_free(((two_objectives *)q->dyn)->dyn);
        free(q->dyn);
    }
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

/* The gear's LTE at the case's torque and its dynamic response (optimize.objective2), and the reference
 * point: optimize.hv_reference, or 1.1 times the unmodified flank's two objectives. */
static gd_status gear_two(const gd_case *c, gd_stop_hook stop, const gd_ltca_settings *set, gd_compare_entry *q,
                          gd_error *err)
{
    two_objectives *t = calloc(1, sizeof *t);
    if (!t)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    q->dyn = t;
    t->lte.set = *set;
    t->lte.n = 1;
    t->lte.torques_nm[0] = c->torque_nm;
    t->lte.weights[0] = 1.0;
    gd_opt_gear_objective obj[2];
    gd_opt_lte_range_objective(&t->lte, &obj[0]);
    gd_dynobj_settings ds;
    gd_dynobj_settings_from_case(c, &ds);
    gd_status st = gd_dynobj_create(c, &ds, &stop, &t->dyn, err);
    if (st != GD_OK)
        return st;
    gd_dynobj_objective(t->dyn, &obj[1]);
    if ((st = gd_opt_gear_set_objectives(q->gear, 2, obj, NULL, err)) != GD_OK)
        return st;
    if (c->n_opt_hv_reference == 2) {
        q->hv_ref[0] = c->opt_hv_reference[0];
        q->hv_ref[1] = c->opt_hv_reference[1];
        return GD_OK;
    }
    gd_pair u = gd_pair_from_case(c);
    u.root_relief_amount_um = u.root_relief_length_mm = u.tip_relief_amount_um = u.tip_relief_length_mm = 0;
    u.lead_relief_inner_um = u.lead_relief_outer_um = u.lead_unmodified_length_mm = 0;
    u.lead_unmodified_centre_mm = u.helix_slope_um = 0;
    double f[2], aux[GD_OPT_MAX_AUX];
    if ((st = gd_opt_gear_value_of_pair(q->gear, &u, f, aux, err)) != GD_OK)
        return gd_error_prefix(err, "the unmodified flank");
    q->hv_ref[0] = 1.1 * f[0];
    q->hv_ref[1] = 1.1 * f[1];
    return GD_OK;
}

/* The problem instances of one (objective, dimension): the gear problem, the same for every run,
 * or one test-function instance per run (shifted minimisers drawn from the run's instance seed). */
static gd_status build(const gd_case *c, gd_stop_hook stop, gd_compare_entry *q, int runs, gd_error *err)
{
    q->pb = calloc((size_t)runs, sizeof *q->pb);
    q->pp = calloc((size_t)runs, sizeof *q->pp);
    if (!q->pb || !q->pp)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    if (q->objective == GD_OBJ_GEAR_LTE) {
        const gd_pair pair = gd_pair_from_case(c);
        gd_ltca_settings set = gd_ltca_settings_from_case(c);
        set.stop = stop; /* every evaluation's LTCA */
        double lower[GD_OPT_GEAR_NVARS], upper[GD_OPT_GEAR_NVARS];
        gd_opt_gear_vars v;
        gd_opt_case_gear_vars(c, &v);
        gd_opt_gear_bounds(c, &v, lower, upper);
        gd_status st = gd_opt_gear_create(&pair, &set, &v, lower, upper, &q->gear, err);
        if (st == GD_OK && q->nobj == 2)
            st = gear_two(c, stop, &set, q, err);
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
static void list_problems(const gd_case *c, gd_compare_outcome *C)
{
    int objs[GD_OBJ_NOBJECTIVES];
    int nobj = gd_opt_case_objectives(c, objs, GD_OBJ_NOBJECTIVES);
    for (int i = 0; i < nobj; i++) {
        int nd = objs[i] == GD_OBJ_GEAR_LTE ? 1 : c->n_opt_dimensions;
        for (int k = 0; k < nd && C->n < GD_COMPARE_MAX; k++) {
            gd_compare_entry *q = &C->p[C->n++];
            q->objective = objs[i];
            gd_opt_gear_vars v;
            gd_opt_case_gear_vars(c, &v);
            q->dim = objs[i] == GD_OBJ_GEAR_LTE ? v.n : (int)c->opt_dimensions[k];
            q->shift = objs[i] == GD_OBJ_GEAR_LTE ? 0.0 : c->opt_shift;
            q->nobj = objs[i] == GD_OBJ_GEAR_LTE ? (c->opt_objective2[0] ? 2 : 1) : gd_opt_objective_count(objs[i]);
            q->hv_ref[0] = q->hv_ref[1] = 1.1; /* zdt1, zdt2 (the gear's: gear_two) */
            if (c->n_opt_hv_reference == 2) {
                q->hv_ref[0] = c->opt_hv_reference[0];
                q->hv_ref[1] = c->opt_hv_reference[1];
            }
        }
    }
    C->runs = c->opt_runs;
}

/* The settings of the comparison from the case's [optimize] keys. */
static void compare_settings(const gd_case *c, int threads, gd_opt_compare_settings *s)
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
    s->threads = threads;
    s->archive = c->opt_archive;
    s->scalar_algorithm = c->opt_scalar_algorithm;
    s->scalar_grid = c->opt_scalar_grid;
}

/* Build and compare every problem; the wall time summed in C->wall_s. */
static gd_status compare_all(const gd_case *c, const gd_run_env *env, gd_compare_outcome *C, gd_error *err)
{
    gd_opt_compare_settings *s = &C->settings;
    for (int j = 0; j < C->n; j++) {
        gd_compare_entry *q = &C->p[j];
        gd_status st = build(c, s->stop, q, C->runs, err);
        if (st == GD_OK) {
            s->f_ref = q->objective == GD_OBJ_GEAR_LTE ? NAN : 0.0;
            s->hv_ref[0] = q->hv_ref[0];
            s->hv_ref[1] = q->hv_ref[1];
            if (q->nobj == 2 && q->objective != GD_OBJ_GEAR_LTE) /* ZDT: the true front's shortfall */
                s->f_ref = q->hv_ref[0] * q->hv_ref[1] - gd_opt_zdt_front_hv(q->objective, q->hv_ref);
            st = gd_opt_compare(q->pp, s, &q->res, err);
        }
        if (st != GD_OK)
            return st;
        C->wall_s += q->res.wall_s;
        if (env && env->compare_problem)
            env->compare_problem(env->user, q, s);
    }
    return GD_OK;
}

void gd_row_compare_free(void *result)
{
    gd_compare_outcome *C = result;
    if (!C)
        return;
    for (int j = 0; j < C->n; j++)
        problem_free(&C->p[j], C->runs);
    free(C->grid);
    free(C);
}

gd_status gd_row_compare_run(const gd_case *cp, const gd_run_env *env, gd_run_dir *out, void **result,
                             gd_error *err)
{
    (void)out;
    *result = NULL;
    gd_case c = *cp;
    gd_compare_outcome *C = calloc(1, sizeof *C);
    if (!C)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    int threads = env ? env->threads : 0;
    list_problems(&c, C);
    compare_settings(&c, threads, &C->settings);
    C->settings.stop = gd_row_stop(env);
    C->threads = opt_threads(threads);
    gd_status st = compare_all(&c, env, C, err);
    if (st == GD_OK) {
        C->ngrid = make_grid(C->settings.budget, &C->grid);
        if (C->ngrid < 0)
            st = gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    }
    if (st != GD_OK) {
        gd_row_compare_free(C);
        return st;
    }
    *result = C;
    return GD_OK;
}

gd_status gd_row_compare_write(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    (void)c;
    return gd_compare_write_tables(out, result, err);
}

gd_status gd_row_compare_summary(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err)
{
    const gd_compare_outcome *C = result;
    gd_opt_compare_problem pb[GD_COMPARE_MAX];
    for (int j = 0; j < C->n; j++) {
        pb[j].objective = C->p[j].objective;
        pb[j].dim = C->p[j].dim;
        pb[j].shift = C->p[j].shift;
        pb[j].nobj = C->p[j].nobj;
        pb[j].hv_ref[0] = C->p[j].hv_ref[0];
        pb[j].hv_ref[1] = C->p[j].hv_ref[1];
        pb[j].res = &C->p[j].res;
    }
    return gd_summary_write_compare(out, c, pb, C->n, C->threads, err);
}

void gd_row_compare_pictures(const gd_case *c, const void *result, gd_run_dir *out, const gd_run_env *env)
{
    const gd_plotter p = gd_row_plotter(env, out);
    gd_plot_compare(&p, c, (const gd_compare_outcome *)result);
}
