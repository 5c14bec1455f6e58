/* Two objectives by a single-objective NLopt method: a grid of scalarised subproblems, each run on
 * its share of the budget (docs/optimisation.md section 13). The objectives are divided by the
 * reference point r of the hypervolume (every objective here is >= 0, so 0 is the ideal point and r
 * the nadir the designer accepts): a = f1 / r1, b = f2 / r2.
 *
 *   weighted-sum    K subproblems: minimise w_k a + (1 - w_k) b, w_k = k / (K - 1) (k = 0 .. K - 1;
 *                   w = 1 is f1 alone, w = 0 f2 alone). A weighted sum reaches only the convex hull
 *                   of the front (Das & Dennis 1997): nothing inside a concave stretch.
 *   eps-constraint  subproblem 0 minimises a alone; a_min is the least a it found; subproblems
 *                   k = 1 .. K - 1 minimise b subject to a <= e_k, e_k = a_min + (1 - a_min) k / (K - 1)
 *                   (Haimes, Lasdon & Wismer 1971; the grid from the ideal to the nadir, Mavrotas
 *                   2009). The constraint is Deb's feasibility rule as one number: an infeasible point
 *                   is worth OPT_EPS_INFEASIBLE + (a - e_k), after every feasible one.
 *
 * Subproblem k has floor(B / K) evaluations, one more for k < B mod K, and the seed s + 1000003 k.
 * Every evaluation of every subproblem enters the run's front (the wrapper), so the front is the
 * non-dominated set of all of them. */
#include "opt_internal.h"

#include <math.h>
#include <stdlib.h>

gd_status opt_scalarised(opt_ctx *c, const gd_opt_settings *s, gd_opt_result *r, gd_error *err)
{
    if (c->nobj != 2)
        return gd_error_set(err, GD_ERR_INPUT, "%s: %d objectives (valid: 2)", gd_opt_algorithm_name(s->algorithm),
                            c->nobj);
    const int K = s->scalar_grid;
    const long B = c->budget;
    const int eps = s->algorithm == GD_OPT_EPS_CONSTRAINT;
    gd_opt_settings sub = *s;
    sub.algorithm = s->scalar_algorithm;
    gd_status st = GD_OK;
    long end = 0;
    double a_min = 1.0;
    for (int k = 0; k < K && st == GD_OK; k++) {
        long share = B / K + (k < B % K);
        end += share;
        if (share == 0)
            continue;
        if (eps && k == 0) {
            c->sc_kind = OPT_SC_WEIGHTED;
            c->sc_w = 1.0;
        } else if (eps) {
            c->sc_kind = OPT_SC_EPS;
            c->sc_eps = K > 1 ? a_min + (1.0 - a_min) * k / (K - 1) : 1.0;
        } else {
            c->sc_kind = OPT_SC_WEIGHTED;
            c->sc_w = K > 1 ? (double)k / (K - 1) : 0.5;
        }
        c->budget = end;
        c->best_f = INFINITY;
        sub.seed = s->seed + 1000003UL * (unsigned long)k;
        st = opt_nlopt(c, &sub, r, err);
        if (st == GD_OK && eps && k == 0) {
            /* the least a of the front so far: the front is sorted by f1 */
            a_min = c->front.n > 0 ? c->front.f[0] / c->hv_ref[0] : 1.0;
            if (!(a_min < 1.0))
                a_min = 0.0;
        }
    }
    c->budget = B;
    c->sc_kind = OPT_SC_NONE;
    return st;
}
