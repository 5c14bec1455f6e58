/* The counting wrapper and the NLopt baselines (docs/optimisation.md sections 3 and 5): the
 * evaluation count of every optimiser is exactly the objective's own count and never above the
 * budget; the best point reported is the best evaluated (COBYLA may return its last one); the
 * repair of the linear constraints; every optimiser returns a feasible point on a constrained
 * problem whose unconstrained minimum is infeasible, and evaluates only feasible points; errors
 * of the objective stop every optimiser with their message. TAP output. */
#include "geardyn/geardyn.h"
#include "tap.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

typedef struct counting {
    atomic_long calls;
    atomic_long infeasible;   /* points given to the objective outside the box or the constraints */
    const gd_opt_problem *self;
    double o[8];
    long fail_at;             /* > 0: fail on this call */
    int nan_at;
} counting;

static gd_status count_eval(void *state, const double *y, double *f, gd_error *err)
{
    counting *c = state;
    long k = atomic_fetch_add(&c->calls, 1) + 1;
    if (c->self && !gd_opt_feasible(c->self, y, 1e-12))
        atomic_fetch_add(&c->infeasible, 1);
    double s = 0;
    for (int i = 0; i < c->self->dim; i++)
        s += (y[i] - c->o[i]) * (y[i] - c->o[i]);
    *f = s;
    if (c->fail_at > 0 && k == c->fail_at)
        return gd_error_set(err, GD_ERR_PHYSICS, "deliberate failure at call %ld", k);
    if (c->nan_at > 0 && k == c->nan_at)
        *f = NAN;
    return GD_OK;
}

static int run(const gd_opt_problem *p, int alg, long budget, gd_opt_result *r, gd_error *e)
{
    gd_opt_settings s;
    gd_opt_settings_default(&s);
    s.algorithm = alg;
    s.budget = budget;
    s.seed = 11;
    s.population = 10;
    s.threads = 2;
    s.keep_history = 1;
    return gd_opt_run(p, &s, r, e);
}

int main(void)
{
    gd_error e = {0};
    /* ---- the repair of A y <= b toward the anchor ------------------------------------------------ */
    double lo[5] = {-1, -1, -1, -1, -1}, hi[5] = {1, 1, 1, 1, 1};
    double A[10] = {1, 1, 0, 0, 0, 0, 0, 1, 1, 1}, b[2] = {0.5, 1.0};
    gd_opt_problem p = {0};
    p.dim = 5;
    p.lower = lo;
    p.upper = hi;
    p.ncons = 2;
    p.A = A;
    p.b = b;
    p.eval = count_eval;
    double anchor[5];
    tap_ok(gd_opt_problem_check(&p, anchor, &e) == GD_OK && anchor[0] == 0 && anchor[4] == 0,
           "the centre of the box is the anchor (strictly feasible)");
    {
        gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
        int feasible_kept = 1, repaired_ok = 1, on_boundary = 1, on_segment = 1, nrep = 0;
        for (int k = 0; k < 2000; k++) {
            double y[5], z[5];
            for (int i = 0; i < 5; i++)
                y[i] = 2 * gsl_rng_uniform(rng) - 1;
            gd_opt_repair(&p, anchor, y, z);
            int feas = y[0] + y[1] <= 0.5 && y[2] + y[3] + y[4] <= 1.0;
            if (feas) {
                feasible_kept &= memcmp(y, z, sizeof y) == 0;
                continue;
            }
            nrep++;
            repaired_ok &= gd_opt_feasible(&p, z, 0) && z[0] + z[1] < 0.5 + 1e-15 && z[2] + z[3] + z[4] < 1.0 + 1e-15;
            double g1 = 0.5 - (z[0] + z[1]), g2 = 1.0 - (z[2] + z[3] + z[4]);
            on_boundary &= fmin(g1, g2) < 1e-9 && fmin(g1, g2) >= 0;
            double s = z[0] / y[0]; /* the anchor is 0: z = s y */
            for (int i = 1; i < 5; i++)
                on_segment &= fabs(z[i] - s * y[i]) <= 1e-14;
        }
        gsl_rng_free(rng);
        tap_ok(feasible_kept, "repair: feasible points unchanged (bitwise)");
        tap_ok(repaired_ok && nrep > 500, "repair: %d infeasible points made feasible", nrep);
        tap_ok(on_boundary, "repair: the repaired point lies on the boundary (a constraint active within 1e-9)");
        tap_ok(on_segment, "repair: the repaired point lies on the segment from the anchor");
    }
    {
        double bad_anchor[5] = {0.4, 0.4, 0, 0, 0};
        gd_opt_problem q = p;
        q.anchor = bad_anchor;
        gd_error e2 = {0};
        tap_ok(gd_opt_problem_check(&q, NULL, &e2) == GD_ERR_INPUT, "an infeasible anchor is refused (%s)", e2.msg);
    }

    /* ---- every optimiser: the count, the budget, the best point ---------------------------------- */
    const long budget = 1237;
    for (int alg = 0; alg < GD_OPT_NALGORITHMS; alg++) {
        if (!(gd_opt_algorithm_objectives(alg) & 1))
            continue; /* two objectives only: test_optimize_moalo.c */
        counting c;
        memset(&c, 0, sizeof c);
        double lo4[4] = {-5, -5, -5, -5}, hi4[4] = {5, 5, 5, 5};
        gd_opt_problem q = {0};
        q.dim = 4;
        q.lower = lo4;
        q.upper = hi4;
        q.eval = count_eval;
        q.user = &c;
        c.self = &q;
        for (int i = 0; i < 4; i++)
            c.o[i] = 1.0 + 0.5 * i;
        gd_opt_result r;
        const char *name = gd_opt_algorithm_name(alg);
        if (run(&q, alg, budget, &r, &e) != GD_OK) {
            tap_ok(0, "%s: %s", name, e.msg);
            continue;
        }
        long calls = atomic_load(&c.calls);
        long expect = alg == GD_OPT_ALO ? 10L * (budget / 10) : budget;
        /* DIRECT_L is deterministic and not restarted: it may end before the budget */
        int count_ok = calls == r.evaluations && r.evaluations <= budget &&
                       (alg == GD_OPT_GN_DIRECT_L ? r.evaluations > 0 : r.evaluations == expect);
        tap_ok(count_ok, "%s: %ld evaluations reported, %ld counted by the objective, budget %ld (expected %ld)", name,
               r.evaluations, calls, budget, alg == GD_OPT_GN_DIRECT_L ? r.evaluations : expect);
        double fmin_ = INFINITY;
        long at = 0;
        int hist_ok = 1;
        for (long k = 0; k < r.evaluations; k++) {
            if (r.f_history[k] < fmin_) {
                fmin_ = r.f_history[k];
                at = k + 1;
            }
            hist_ok &= r.best_history[k] == fmin_;
        }
        double fy;
        count_eval(&c, r.y, &fy, &e);
        tap_ok(hist_ok && r.f == fmin_ && r.best_at == at && fy == r.f,
               "%s: the result is the best evaluation (f %.3g at %ld = f(y) recomputed %.3g; best-so-far history "
               "consistent)", name, r.f, r.best_at, fy);
        gd_opt_result_free(&r);
    }

    /* ---- a constrained problem: the unconstrained minimum o = 0.9 (1, ..., 1) is infeasible; the
     * constrained minimum is o projected on y1 + y2 <= 0.5, y3 + y4 + y5 <= 1:
     * (0.25, 0.25, 1/3, 1/3, 1/3), f* = 2 (0.65)^2 + 3 (0.9 - 1/3)^2 ---------------------------- */
    const double fstar = 2 * 0.65 * 0.65 + 3 * pow(0.9 - 1.0 / 3.0, 2);
    for (int alg = 0; alg < GD_OPT_NALGORITHMS; alg++) {
        if (!(gd_opt_algorithm_objectives(alg) & 1))
            continue; /* two objectives only: test_optimize_moalo.c */
        counting c;
        memset(&c, 0, sizeof c);
        gd_opt_problem q = p;
        q.user = &c;
        c.self = &q;
        for (int i = 0; i < 5; i++)
            c.o[i] = 0.9;
        gd_opt_result r;
        const char *name = gd_opt_algorithm_name(alg);
        if (run(&q, alg, 3000, &r, &e) != GD_OK) {
            tap_ok(0, "%s: %s", name, e.msg);
            continue;
        }
        /* the uncounted check call below must not count as infeasible either */
        int feas = gd_opt_feasible(&q, r.y, 0);
        tap_ok(feas && atomic_load(&c.infeasible) == 0 && r.f >= fstar - 1e-12,
               "%s: returns a feasible point (y1 + y2 = %.6f <= 0.5, y3 + y4 + y5 = %.6f <= 1), evaluated no infeasible "
               "point (%ld of %ld), f = %.6f >= f* = %.6f", name, r.y[0] + r.y[1], r.y[2] + r.y[3] + r.y[4],
               atomic_load(&c.infeasible), r.evaluations, r.f, fstar);
        /* and makes progress from the anchor's value 5 (0.81) = 4.05 toward f* */
        tap_ok(r.f < fstar + 0.25 * (4.05 - fstar), "%s: f - f* = %.3g, within a quarter of the anchor's gap %.3g", name,
               r.f - fstar, 4.05 - fstar);
        gd_opt_result_free(&r);
    }

    /* ---- errors of the objective stop every optimiser with their message; NaN is refused --------- */
    for (int alg = 0; alg < GD_OPT_NALGORITHMS; alg++) {
        if (!(gd_opt_algorithm_objectives(alg) & 1))
            continue; /* two objectives only: test_optimize_moalo.c */
        counting c;
        memset(&c, 0, sizeof c);
        gd_opt_problem q = p;
        q.user = &c;
        c.self = &q;
        c.fail_at = 25;
        gd_opt_result r;
        gd_error e2 = {0};
        gd_status st = run(&q, alg, 500, &r, &e2);
        tap_ok(st == GD_ERR_PHYSICS && strstr(e2.msg, "deliberate failure at call 25") && atomic_load(&c.calls) <= 35,
               "%s: an objective error stops the run (%s; %ld calls)", gd_opt_algorithm_name(alg), e2.msg,
               atomic_load(&c.calls));
        if (st == GD_OK)
            gd_opt_result_free(&r);
        memset(&c, 0, sizeof c);
        c.self = &q;
        c.nan_at = 7;
        gd_error e3 = {0};
        st = run(&q, alg, 500, &r, &e3);
        tap_ok(st == GD_ERR_INTERNAL && strstr(e3.msg, "NaN"), "%s: a NaN value stops the run (%s)",
               gd_opt_algorithm_name(alg), e3.msg);
        if (st == GD_OK)
            gd_opt_result_free(&r);
    }
    return tap_done();
}
