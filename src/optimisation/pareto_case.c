/* Two objectives at once from the case's [optimize] keys (docs/optimisation.md section 13): which
 * pairs of objectives, which optimisers, the reference point of the hypervolume; the checks the keys'
 * ranges do not make. */
#include "opt_internal.h"
#include "../case/case_keys.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static gd_status check_two_keys(const gd_case *c, gd_error *err);

int gd_opt_case_nobj(const gd_case *c)
{
    if (c->analysis != GD_ANALYSIS_OPTIMIZE)
        return 1;
    if (c->opt_objective2[0])
        return 2;
    int o = gd_opt_objective_parse(c->opt_objective);
    return o >= 0 ? gd_opt_objective_count(o) : 1;
}

/* compare-optimizers: objective2 beside gear-lte only; every problem of one kind (one objective or two)
 * and every optimiser able to minimise it. */
static gd_status resolve_compare(const gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    int objs[GD_OBJ_NOBJECTIVES], algs[GD_OPT_NALGORITHMS];
    int no = gd_opt_case_objectives(c, objs, GD_OBJ_NOBJECTIVES);
    int na = gd_opt_case_optimizers(c, algs, GD_OPT_NALGORITHMS);
    if (c->opt_objective2[0]) {
        gd_case_key_where(c, "optimize", "objective2", w, sizeof w);
        if (gd_opt_objective_parse(c->opt_objective2) != GD_OBJ_GEAR_DYNAMIC)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective2: '%s' (valid: gear-dynamic, beside "
                                "objective gear-lte; or empty)", w, c->opt_objective2);
        for (int i = 0; i < no; i++)
            if (objs[i] != GD_OBJ_GEAR_LTE)
                return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective2: gear-dynamic beside %s in "
                                    "compare-optimizers (valid: beside gear-lte alone)", w,
                                    gd_opt_objective_name(objs[i]));
    }
    int kinds = 0;
    for (int i = 0; i < no; i++) {
        for (int k = 0; (objs[i] == GD_OBJ_ZDT1 || objs[i] == GD_OBJ_ZDT2) && k < c->n_opt_dimensions; k++)
            if (c->opt_dimensions[k] < 2) {
                gd_case_key_where(c, "optimize", "dimension", w, sizeof w);
                return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.dimension: %g for %s (valid: 2 to 1000)", w,
                                    c->opt_dimensions[k], gd_opt_objective_name(objs[i]));
            }
        int nobj = objs[i] == GD_OBJ_GEAR_LTE ? (c->opt_objective2[0] ? 2 : 1) : gd_opt_objective_count(objs[i]);
        kinds |= nobj;
        for (int a = 0; a < na; a++)
            if (!(gd_opt_algorithm_objectives(algs[a]) & (nobj == 2 ? 2 : 1))) {
                gd_case_key_where(c, "optimize", "optimizers", w, sizeof w);
                return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.optimizers: %s for %s, %s (valid: %s)", w,
                                    gd_opt_algorithm_name(algs[a]), gd_opt_objective_name(objs[i]),
                                    nobj == 2 ? "two objectives" : "one objective",
                                    nobj == 2 ? "moalo, weighted-sum, eps-constraint, random"
                                              : "alo, gn_direct_l, gn_crs2_lm, gn_isres, gn_esch, ln_bobyqa, "
                                                "ln_cobyla, ln_sbplx, random");
            }
    }
    if (kinds == 3) {
        gd_case_key_where(c, "optimize", "objective", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective: problems of one objective and of two in one "
                            "comparison (valid: all of one kind: their values, best values or hypervolume "
                            "shortfalls, are not compared)", w);
    }
    if (kinds == 2 && c->opt_robust) { /* refused by gd_opt_resolve_robust before */
        gd_case_key_where(c, "optimize", "robust", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.robust: on with two objectives (valid: off)", w);
    }
    return kinds == 2 ? check_two_keys(c, err) : GD_OK;
}

gd_status gd_opt_resolve_two(gd_case *c, int compare, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    if (compare)
        return resolve_compare(c, err);
    const int o1 = gd_opt_objective_parse(c->opt_objective);
    if (c->opt_objective2[0]) {
        gd_case_key_where(c, "optimize", "objective2", w, sizeof w);
        int o2 = gd_opt_objective_parse(c->opt_objective2);
        if (o2 != GD_OBJ_GEAR_DYNAMIC)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective2: '%s' (valid: gear-dynamic, beside "
                                "objective gear-lte or gear-lte-range; or empty)", w, c->opt_objective2);
        if (o1 != GD_OBJ_GEAR_LTE && o1 != GD_OBJ_GEAR_LTE_RANGE)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective2: gear-dynamic beside objective %s "
                                "(valid: beside gear-lte or gear-lte-range)", w, c->opt_objective);
    }
    const int nobj = gd_opt_case_nobj(c);
    if (!(gd_opt_algorithm_objectives(c->opt_algorithm) & (nobj == 2 ? 2 : 1))) {
        gd_case_key_where(c, "optimize", "algorithm", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.algorithm: %s for %s (valid: %s)", w,
                            gd_opt_algorithm_name(c->opt_algorithm), nobj == 2 ? "two objectives" : "one objective",
                            nobj == 2 ? "moalo, weighted-sum, eps-constraint, random"
                                      : "alo, gn_direct_l, gn_crs2_lm, gn_isres, gn_esch, ln_bobyqa, ln_cobyla, "
                                        "ln_sbplx, random; moalo, weighted-sum and eps-constraint take two objectives");
    }
    if (nobj == 1)
        return GD_OK;
    if (c->opt_robust) {
        gd_case_key_where(c, "optimize", "robust", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.robust: on with two objectives (valid: off; the robust "
                            "variant takes one objective)", w);
    }
    if ((o1 == GD_OBJ_ZDT1 || o1 == GD_OBJ_ZDT2) && c->opt_dimensions[0] < 2) {
        gd_case_key_where(c, "optimize", "dimension", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.dimension: %g for %s (valid: 2 to 1000)", w,
                            c->opt_dimensions[0], c->opt_objective);
    }
    return check_two_keys(c, err);
}

/* The keys of two objectives: the scalarisations' method, the reference point. */
static gd_status check_two_keys(const gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    int algs[GD_OPT_NALGORITHMS], scal = 0;
    int na = gd_opt_case_optimizers(c, algs, GD_OPT_NALGORITHMS);
    for (int a = 0; a < na; a++)
        scal |= algs[a] == GD_OPT_WEIGHTED_SUM || algs[a] == GD_OPT_EPS_CONSTRAINT;
    if (c->opt_scalar_algorithm == GD_OPT_ALO && scal) {
        gd_case_key_where(c, "optimize", "scalar_algorithm", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.scalar_algorithm: alo (valid: an NLopt method, "
                            "gn_direct_l, gn_crs2_lm, gn_isres, gn_esch, ln_bobyqa, ln_cobyla, ln_sbplx)", w);
    }
    if (c->n_opt_hv_reference != 0) {
        gd_case_key_where(c, "optimize", "hv_reference", w, sizeof w);
        if (c->n_opt_hv_reference != 2)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.hv_reference: %d numbers (valid: two, one per "
                                "objective, in their units)", w, c->n_opt_hv_reference);
        for (int k = 0; k < 2; k++)
            if (!(c->opt_hv_reference[k] > 0))
                return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.hv_reference: %g (valid: > 0; every objective "
                                    "here is >= 0)", w, c->opt_hv_reference[k]);
    }
    return GD_OK;
}
