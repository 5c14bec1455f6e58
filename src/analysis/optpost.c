/* What an optimisation over load and speed reports after it (include/geardyn/gd_optpost.h,
 * docs/optimisation.md section 12): for the unmodified flank, the case's own and the optimum, the
 * response curves over speed of the dynamic objective on the loop's model and on bta, and the LTE
 * amplitude over a grid of torques (the Harris map). Every piece is one flank at one model or one
 * torque, computed in parallel and each a function of its inputs alone. */
#include "geardyn/gd_optpost.h"
#include "geardyn/gd_scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

static const char *const flank_names[GD_OPTPOST_NFLANKS] = {"unmodified", "case", "optimum"};

GD_API const char *gd_optpost_flank_name(int j) { return j >= 0 && j < GD_OPTPOST_NFLANKS ? flank_names[j] : NULL; }

GD_API void gd_optpost_free(gd_optpost *p)
{
    if (!p)
        return;
    for (int j = 0; j < GD_OPTPOST_NFLANKS; j++) {
        gd_dyn_result_free(&p->curve[j]);
        if (p->bta_separate)
            gd_dyn_result_free(&p->on_bta[j]);
    }
    memset(p, 0, sizeof *p);
}

/* The grid of the Harris map: optimize.harris_torques torques from harris_torque_from_nm to
 * harris_torque_to_nm, and the objective's own (marked), increasing, without repeats. */
static void harris_grid(const gd_case *c, gd_optpost *p)
{
    const int m = c->opt_harris_torques < 2 ? 2 : c->opt_harris_torques > GD_OPTPOST_HARRIS_GRID
                                                  ? GD_OPTPOST_HARRIS_GRID : c->opt_harris_torques;
    int n = 0;
    for (int i = 0; i < m; i++) {
        p->harris_torque_nm[n] = c->opt_harris_from_nm + (c->opt_harris_to_nm - c->opt_harris_from_nm) * i / (m - 1);
        p->harris_objective[n++] = 0;
    }
    for (int k = 0; k < c->n_opt_torques; k++) {
        int found = 0;
        for (int i = 0; i < n && !found; i++)
            if (p->harris_torque_nm[i] == c->opt_torques_nm[k])
                found = p->harris_objective[i] = 1;
        if (!found) {
            p->harris_torque_nm[n] = c->opt_torques_nm[k];
            p->harris_objective[n++] = 1;
        }
    }
    for (int i = 1; i < n; i++) /* insertion sort: at most 108 */
        for (int j = i; j > 0 && p->harris_torque_nm[j] < p->harris_torque_nm[j - 1]; j--) {
            double t = p->harris_torque_nm[j];
            int o = p->harris_objective[j];
            p->harris_torque_nm[j] = p->harris_torque_nm[j - 1];
            p->harris_objective[j] = p->harris_objective[j - 1];
            p->harris_torque_nm[j - 1] = t;
            p->harris_objective[j - 1] = o;
        }
    p->nharris = n;
}

/* Each flank's place (0 the lowest) by value, ties in the flanks' order. */
static void rank_of(const gd_dyn_result *r, int *rank)
{
    for (int j = 0; j < GD_OPTPOST_NFLANKS; j++) {
        rank[j] = 0;
        for (int i = 0; i < GD_OPTPOST_NFLANKS; i++)
            if (r[i].value < r[j].value || (r[i].value == r[j].value && i < j))
                rank[j]++;
    }
}

GD_API gd_status gd_optpost_compute(const gd_case *c, int objective, const gd_pair pairs[GD_OPTPOST_NFLANKS], int threads,
                                    const gd_stop_hook *stop, gd_optpost *p, gd_error *err)
{
    memset(p, 0, sizeof *p);
    if (objective != GD_OBJ_GEAR_LTE_RANGE && objective != GD_OBJ_GEAR_DYNAMIC)
        return gd_error_set(err, GD_ERR_INPUT, "optimize report: the objective is %s (valid: gear-lte-range, "
                            "gear-dynamic)", gd_opt_objective_name(objective));
    p->dynamic = objective == GD_OBJ_GEAR_DYNAMIC;
    gd_dynobj_settings loop, bta;
    gd_dynobj_settings_from_case(c, &loop);
    bta = loop;
    bta.model = GD_MODEL_BTA;
    p->bta_separate = p->dynamic && loop.model != GD_MODEL_BTA;
    harris_grid(c, p);
    const gd_ltca_settings lset = gd_ltca_settings_from_case(c);
    /* the tasks: the dynamic evaluations first (the longest), then the LTE amplitudes */
    const int ndyn = p->dynamic ? (p->bta_separate ? 2 : 1) * GD_OPTPOST_NFLANKS : 0;
    const int ntask = ndyn + GD_OPTPOST_NFLANKS * p->nharris;
    gd_status *sts = calloc((size_t)ntask, sizeof *sts);
    gd_error *errs = calloc((size_t)ntask, sizeof *errs);
    if (!sts || !errs) {
        free(sts);
        free(errs);
        return gd_error_set(err, GD_ERR_NOMEM, "optimize report: out of memory");
    }
    int nt = threads;
#ifdef _OPENMP
    if (nt < 1)
        nt = omp_get_max_threads();
#endif
    if (nt < 1)
        nt = 1;
#pragma omp parallel for schedule(dynamic, 1) num_threads(nt)
    for (int t = 0; t < ntask; t++) {
        if (gd_stop_asked(stop)) {
            sts[t] = gd_error_set(&errs[t], GD_ERR_INTERRUPTED, "stopped");
            continue;
        }
        if (t < ndyn) {
            int j = t % GD_OPTPOST_NFLANKS, on_bta = t >= GD_OPTPOST_NFLANKS;
            gd_dyn_result *r = on_bta ? &p->on_bta[j] : &p->curve[j];
            sts[t] = gd_dyn_evaluate(c, on_bta ? &bta : &loop, &pairs[j], stop, r, &errs[t]);
            if (sts[t] != GD_OK)
                gd_error_prefix(&errs[t], "the %s flank on %s", flank_names[j], on_bta ? "bta" : "the loop's model");
        } else {
            int u = t - ndyn, j = u / p->nharris, i = u % p->nharris;
            gd_ltca_settings set = lset;
            set.stop = stop ? *stop : (gd_stop_hook){0};
            set.torque_nm = p->harris_torque_nm[i];
            sts[t] = gd_opt_gear_lte_pp(&pairs[j], &set, &p->harris_lte_pp_arcsec[j][i], &errs[t]);
            if (sts[t] != GD_OK)
                gd_error_prefix(&errs[t], "the LTE of the %s flank at %g N m", flank_names[j], set.torque_nm);
        }
    }
    gd_status st = GD_OK;
    for (int t = 0; t < ntask && st == GD_OK; t++)
        if (sts[t] != GD_OK) {
            st = sts[t];
            if (err)
                *err = errs[t];
        }
    free(sts);
    free(errs);
    if (st != GD_OK) {
        gd_optpost_free(p);
        return gd_error_prefix(err, "optimize report");
    }
    if (p->dynamic) {
        for (int j = 0; j < GD_OPTPOST_NFLANKS; j++) {
            p->loop_cpu_s += p->curve[j].cpu_s;
            if (!p->bta_separate)
                p->on_bta[j] = p->curve[j]; /* the same curves: freed once */
            p->bta_cpu_s += p->on_bta[j].cpu_s;
        }
        rank_of(p->curve, p->rank_loop);
        rank_of(p->on_bta, p->rank_bta);
        p->same_ranking = 1;
        for (int j = 0; j < GD_OPTPOST_NFLANKS; j++)
            p->same_ranking &= p->rank_loop[j] == p->rank_bta[j];
    }
    return GD_OK;
}
