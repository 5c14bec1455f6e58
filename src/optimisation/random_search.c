/* Uniform random search: the floor every optimiser must beat (docs/optimisation.md section 5).
 * Batches of `population` points drawn serially from GSL's MT19937, evaluated in parallel. */
#include "opt_internal.h"

#include <gsl/gsl_rng.h>
#include <stdlib.h>

gd_status opt_random(opt_ctx *c, const gd_opt_settings *s, gd_opt_result *r, gd_error *err)
{
    int n = s->population, d = c->dim;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    double *X = malloc((size_t)n * (size_t)d * sizeof(double));
    double *f = malloc((size_t)n * sizeof(double));
    gd_status st = GD_OK;
    if (!rng || !X || !f) {
        st = gd_error_set(err, GD_ERR_NOMEM, "random search: out of memory");
        goto done;
    }
    gsl_rng_set(rng, s->seed);
    while (c->count < c->budget) {
        for (size_t i = 0; i < (size_t)n * (size_t)d; i++)
            X[i] = 2.0 * gsl_rng_uniform(rng) - 1.0;
        int m;
        st = opt_eval_batch(c, X, n, f, NULL, s->threads, &m, err);
        if (st != GD_OK)
            break;
        r->starts++;
    }
done:
    gsl_rng_free(rng);
    free(X);
    free(f);
    return st;
}
