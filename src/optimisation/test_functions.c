/* Standard test functions (sphere, Rosenbrock, Rastrigin, Ackley, Griewank) with their minimiser
 * moved to a point o, and seeded instances with a shifted minimiser (docs/optimisation.md
 * section 6). Domains as Mirjalili 2015, Tables 1-2. */
#include "geardyn/gd_optimize.h"
#include "../core/gsl_quiet.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const obj_names[GD_OBJ_NOBJECTIVES] = {"gear-lte", "sphere", "rosenbrock", "rastrigin", "ackley",
                                                           "griewank", "zdt1", "zdt2", "gear-lte-range",
                                                           "gear-dynamic"};

GD_API const char *gd_opt_objective_name(int o) { return o >= 0 && o < GD_OBJ_NOBJECTIVES ? obj_names[o] : NULL; }

GD_API int gd_opt_objective_parse(const char *name)
{
    for (int o = 0; o < GD_OBJ_NOBJECTIVES; o++)
        if (strcmp(name, obj_names[o]) == 0)
            return o;
    return -1;
}

GD_API int gd_opt_objective_is_gear(int o)
{
    return o == GD_OBJ_GEAR_LTE || o == GD_OBJ_GEAR_LTE_RANGE || o == GD_OBJ_GEAR_DYNAMIC;
}

GD_API int gd_opt_objective_count(int o) { return o == GD_OBJ_ZDT1 || o == GD_OBJ_ZDT2 ? 2 : 1; }

GD_API void gd_opt_zdt_value(int fn, int d, const double *x, double f[2])
{
    double s = 0;
    for (int i = 1; i < d; i++)
        s += x[i];
    double g = 1.0 + 9.0 * s / (d - 1), q = x[0] / g;
    f[0] = x[0];
    f[1] = fn == GD_OBJ_ZDT2 ? g * (1.0 - q * q) : g * (1.0 - sqrt(q));
}

/* The area between the front f2 = 1 - f1^p (p = 1/2 or 2) on [0, 1] and the reference point r
 * (r1, r2 >= 1): r1 r2 minus the area under the front, 1 - 1/(p + 1). */
GD_API double gd_opt_zdt_front_hv(int fn, const double ref[2])
{
    double under = fn == GD_OBJ_ZDT2 ? 2.0 / 3.0 : 1.0 / 3.0;
    return ref[0] * ref[1] - under;
}

GD_API void gd_opt_function_domain(int fn, double *lo, double *hi)
{
    if (fn == GD_OBJ_ZDT1 || fn == GD_OBJ_ZDT2) {
        *lo = 0.0;
        *hi = 1.0;
        return;
    }
    double h;
    switch (fn) {
    case GD_OBJ_SPHERE: h = 100; break;
    case GD_OBJ_ROSENBROCK: h = 30; break;
    case GD_OBJ_RASTRIGIN: h = 5.12; break;
    case GD_OBJ_ACKLEY: h = 32; break;
    case GD_OBJ_GRIEWANK: h = 600; break;
    default: h = NAN; break;
    }
    *lo = -h;
    *hi = h;
}

GD_API double gd_opt_function_value(int fn, int d, const double *o, const double *x)
{
    double s = 0;
#define Z(i) (x[i] - (o ? o[i] : 0.0))
    switch (fn) {
    case GD_OBJ_SPHERE:
        for (int i = 0; i < d; i++)
            s += Z(i) * Z(i);
        return s;
    case GD_OBJ_ROSENBROCK:
        for (int i = 0; i + 1 < d; i++) {
            double zi = Z(i) + 1.0, zn = Z(i + 1) + 1.0;
            s += 100.0 * (zn - zi * zi) * (zn - zi * zi) + (zi - 1.0) * (zi - 1.0);
        }
        return s;
    case GD_OBJ_RASTRIGIN:
        for (int i = 0; i < d; i++)
            s += Z(i) * Z(i) - 10.0 * cos(2.0 * M_PI * Z(i));
        return 10.0 * d + s;
    case GD_OBJ_ACKLEY: {
        double c = 0;
        for (int i = 0; i < d; i++) {
            s += Z(i) * Z(i);
            c += cos(2.0 * M_PI * Z(i));
        }
        double v = -20.0 * exp(-0.2 * sqrt(s / d)) - exp(c / d) + 20.0 + M_E;
        return v > 0 ? v : 0.0; /* the exact minimum rounds to about -4e-16 */
    }
    case GD_OBJ_GRIEWANK: {
        double p = 1;
        for (int i = 0; i < d; i++) {
            s += Z(i) * Z(i);
            p *= cos(Z(i) / sqrt((double)(i + 1)));
        }
        return 1.0 + s / 4000.0 - p;
    }
    default: return NAN;
    }
#undef Z
}

GD_API void gd_opt_testfn_free(gd_opt_testfn *t)
{
    if (!t)
        return;
    free(t->lower);
    memset(t, 0, sizeof *t);
}

GD_API gd_status gd_opt_testfn_init(gd_opt_testfn *t, int fn, int dim, double shift, unsigned long seed, gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    memset(t, 0, sizeof *t);
    int zdt = fn == GD_OBJ_ZDT1 || fn == GD_OBJ_ZDT2;
    if (!zdt && (fn < GD_OBJ_SPHERE || fn > GD_OBJ_GRIEWANK))
        return gd_error_set(err, GD_ERR_INPUT, "test function %d (valid: sphere .. griewank, zdt1, zdt2)", fn);
    if (dim < 1 || ((fn == GD_OBJ_ROSENBROCK || zdt) && dim < 2))
        return gd_error_set(err, GD_ERR_INPUT, "%s in %d dimensions (valid: %s)", gd_opt_objective_name(fn), dim,
                            fn == GD_OBJ_ROSENBROCK || zdt ? ">= 2" : ">= 1");
    if (!(shift >= 0 && shift <= 0.9) || (zdt && shift != 0))
        return gd_error_set(err, GD_ERR_INPUT, "test function shift %g (valid: 0 to 0.9; 0 for %s)", shift,
                            zdt ? gd_opt_objective_name(fn) : "zdt1 and zdt2");
    t->objective = fn;
    t->dim = dim;
    t->lower = malloc(3 * sizeof(double) * (size_t)dim);
    if (!t->lower)
        return gd_error_set(err, GD_ERR_NOMEM, "test function: out of memory");
    t->upper = t->lower + dim;
    t->optimum = t->upper + dim;
    double lo, hi;
    gd_opt_function_domain(fn, &lo, &hi);
    gsl_rng *rng = NULL;
    if (shift > 0) {
        rng = gsl_rng_alloc(gsl_rng_mt19937);
        if (!rng) {
            gd_opt_testfn_free(t);
            return gd_error_set(err, GD_ERR_NOMEM, "test function: out of memory");
        }
        gsl_rng_set(rng, seed);
    }
    for (int i = 0; i < dim; i++) {
        t->lower[i] = lo;
        t->upper[i] = hi;
        t->optimum[i] = rng ? shift * hi * (2.0 * gsl_rng_uniform(rng) - 1.0) : 0.0;
    }
    gsl_rng_free(rng);
    return GD_OK;
}

static gd_status testfn_eval(void *state, const double *y, double *f, gd_error *err)
{
    (void)err;
    const gd_opt_testfn *t = state;
    *f = gd_opt_function_value(t->objective, t->dim, t->optimum, y);
    return GD_OK;
}

static gd_status zdt_eval(void *state, const double *y, double *f, gd_error *err)
{
    (void)err;
    const gd_opt_testfn *t = state;
    gd_opt_zdt_value(t->objective, t->dim, y, f);
    return GD_OK;
}

GD_API void gd_opt_testfn_problem(gd_opt_testfn *t, gd_opt_problem *p)
{
    memset(p, 0, sizeof *p);
    p->dim = t->dim;
    p->lower = t->lower;
    p->upper = t->upper;
    if (gd_opt_objective_count(t->objective) == 2) {
        p->evalv = zdt_eval;
        p->nobj = 2;
    } else {
        p->eval = testfn_eval;
    }
    p->user = t;
}
