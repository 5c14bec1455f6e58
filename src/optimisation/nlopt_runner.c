/* NLopt baselines (docs/optimisation.md section 5): GN_DIRECT_L, GN_CRS2_LM, GN_ISRES, GN_ESCH and
 * the local LN_BOBYQA, LN_COBYLA, LN_SBPLX, on the normalised box [-1, 1]^d with the bounds as
 * NLopt bounds and the linear constraints repaired by the wrapper (no NLopt constraint is used,
 * so every algorithm sees the same problem).
 *
 * The budget: every start gets maxeval = the evaluations left, and the wrapper calls
 * nlopt_force_stop at the budget (maxeval is not strict) and never evaluates beyond it. Starts:
 * local methods restart from a new seeded random point whenever they stop (xtol reached,
 * ROUNDOFF_LIMITED) until the budget is used; the stochastic global methods likewise, with a new
 * nlopt_srand seed; DIRECT_L is deterministic and is not restarted. nlopt_srand(seed of the start)
 * before every start (NLopt's generator is thread-local in Debian's build). Every return code is
 * checked: our forced stop and ROUNDOFF_LIMITED end a start; other negative codes are errors. An
 * evaluation that fails, or is refused because the caller asked to stop (GD_ERR_INTERRUPTED from
 * the wrapper's stop hook), forces NLopt to stop too and ends the run with that error. */
#include "opt_internal.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <nlopt.h>
#include <stdlib.h>

typedef struct nl_data {
    opt_ctx *c;
    nlopt_opt opt;
    int failed;
    gd_error err;
} nl_data;

/* Stop NLopt; a failure of nlopt_force_stop itself is recorded as the run's error. */
static void stop(nl_data *D)
{
    nlopt_result res = nlopt_force_stop(D->opt);
    if (res < 0 && !D->failed) {
        D->failed = 1;
        gd_error_set(&D->err, GD_ERR_NLOPT, "NLopt: nlopt_force_stop returned %s (%d)", nlopt_result_to_string(res),
                     (int)res);
    }
}

static double nl_objective(unsigned n, const double *x, double *grad, void *data)
{
    (void)n;
    (void)grad; /* derivative-free methods only */
    nl_data *D = data;
    if (D->failed) {
        stop(D);
        return HUGE_VAL;
    }
    double f;
    int done;
    gd_status st = opt_eval_one(D->c, x, &f, &done, &D->err);
    if (st != GD_OK) {
        D->failed = 1;
        stop(D);
        return HUGE_VAL;
    }
    if (done || D->c->count >= D->c->budget)
        stop(D);
    return f;
}

static nlopt_algorithm nl_alg(int a)
{
    switch (a) {
    case GD_OPT_GN_DIRECT_L: return NLOPT_GN_DIRECT_L;
    case GD_OPT_GN_CRS2_LM: return NLOPT_GN_CRS2_LM;
    case GD_OPT_GN_ISRES: return NLOPT_GN_ISRES;
    case GD_OPT_GN_ESCH: return NLOPT_GN_ESCH;
    case GD_OPT_LN_BOBYQA: return NLOPT_LN_BOBYQA;
    case GD_OPT_LN_COBYLA: return NLOPT_LN_COBYLA;
    default: return NLOPT_LN_SBPLX;
    }
}

static gd_status nl_check(nlopt_result res, const char *call, int a, gd_error *err)
{
    if (res >= 0)
        return GD_OK;
    return gd_error_set(err, res == NLOPT_OUT_OF_MEMORY ? GD_ERR_NOMEM : GD_ERR_NLOPT, "NLopt %s: %s returned %s (%d)",
                        gd_opt_algorithm_name(a), call, nlopt_result_to_string(res), (int)res);
}

gd_status opt_nlopt(opt_ctx *c, const gd_opt_settings *s, gd_opt_result *r, gd_error *err)
{
    const int d = c->dim, a = s->algorithm;
    const int local = gd_opt_algorithm_is_local(a);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    double *x = malloc(sizeof(double) * (size_t)d);
    gd_status st = GD_OK;
    if (!rng || !x) {
        st = gd_error_set(err, GD_ERR_NOMEM, "NLopt: out of memory");
        goto done;
    }
    gsl_rng_set(rng, s->seed);
    for (int start = 0; c->count < c->budget; start++) {
        long before = c->count;
        long left = c->budget - c->count;
        nl_data D = {c, NULL, 0, {0}};
        D.opt = nlopt_create(nl_alg(a), (unsigned)d);
        if (!D.opt) {
            st = gd_error_set(err, GD_ERR_NOMEM, "NLopt %s: nlopt_create failed", gd_opt_algorithm_name(a));
            break;
        }
        st = nl_check(nlopt_set_lower_bounds1(D.opt, -1.0), "nlopt_set_lower_bounds1", a, err);
        if (st == GD_OK)
            st = nl_check(nlopt_set_upper_bounds1(D.opt, 1.0), "nlopt_set_upper_bounds1", a, err);
        if (st == GD_OK)
            st = nl_check(nlopt_set_min_objective(D.opt, nl_objective, &D), "nlopt_set_min_objective", a, err);
        if (st == GD_OK)
            st = nl_check(nlopt_set_maxeval(D.opt, left > 2000000000L ? 2000000000 : (int)left), "nlopt_set_maxeval",
                          a, err);
        if (st == GD_OK && local) {
            st = nl_check(nlopt_set_xtol_abs1(D.opt, s->local_xtol), "nlopt_set_xtol_abs1", a, err);
            if (st == GD_OK)
                st = nl_check(nlopt_set_initial_step1(D.opt, s->local_step), "nlopt_set_initial_step1", a, err);
        }
        /* every start from a seeded random point (the centre would favour problems centred in the box) */
        for (int k = 0; k < d; k++)
            x[k] = 2.0 * gsl_rng_uniform(rng) - 1.0;
        double fval = 0;
        nlopt_result res = NLOPT_SUCCESS;
        if (st == GD_OK) {
            nlopt_srand(s->seed * 7919UL + (unsigned long)start);
            res = nlopt_optimize(D.opt, x, &fval);
        }
        nlopt_destroy(D.opt);
        if (st != GD_OK)
            break;
        r->starts++;
        r->nlopt_code = (int)res;
        if (D.failed) {
            if (err)
                *err = D.err;
            st = D.err.code != GD_OK ? D.err.code : GD_ERR_INTERNAL;
            break;
        }
        if (res == NLOPT_FORCED_STOP && c->count < c->budget) {
            st = gd_error_set(err, GD_ERR_INTERNAL, "NLopt %s: stopped before the budget (%ld of %ld)",
                              gd_opt_algorithm_name(a), c->count, c->budget);
            break;
        }
        if (res == NLOPT_ROUNDOFF_LIMITED)
            r->roundoff_stops++;
        else if (res < 0 && res != NLOPT_FORCED_STOP) {
            st = nl_check(res, "nlopt_optimize", a, err);
            break;
        }
        if (gd_opt_algorithm_is_deterministic(a))
            break; /* a restart would repeat the same run */
        if (c->count == before)
            break; /* a start that evaluates nothing would loop for ever */
    }
done:
    gsl_rng_free(rng);
    free(x);
    return st;
}
