/* Dense output: the state at any time inside the last step, from the septic Hermite of the
 * positions through both ends of the step (gear models), or from ARKODE's Hermite interpolant
 * (custom systems, or solver.arkode_dense). */
#include "sim_internal.h"

#include <math.h>
#include <string.h>

/* Dense output of a gear model inside the last step [t0, t1] = [tn - h, tn]. The state is
 * (q, v) with q' = v, so the ends give each position its value, rate, acceleration (the RHS at
 * the ends, which ARKODE's Hermite interpolant holds) and jerk (the time derivative of the RHS
 * along the solution, gd_model_jerk, with the step's modes): the septic Hermite Q of q through
 * these eight values, and v = Q'. The error is O(h^8) in q and O(h^7) in v, against O(h^4) for
 * ARKODE's cubic, at four interpolant reads and two jerk evaluations per step with samples and no
 * RHS evaluation (docs/numerics.md section 9). Returns 0 with y filled, 1 when t is not inside
 * the last step (the caller falls back to ARKODE's interpolant), or a negative ARKODE flag. */
static int dense_septic(gd_sim *s, double t, double *y)
{
    const int n = s->m.n, nd = s->m.ndof;
    if (!s->dq_ok || s->dq_key != s->nrhs) {
        double tn = 0, h = 0;
        if (s->ops->get_current_time(s->mem, &tn) < 0 || s->ops->get_last_step(s->mem, &h) < 0 || !(h > 0))
            return 1;
        double t0 = tn - h;
        int flag;
        /* the start of this step is the end of the last step read, when the integrator went on
         * from there (no reset) in the same modes: its values, acceleration and jerk carry over */
        if (s->dq_ok && t0 == s->dq_t1 && s->resets == s->dq_resets &&
            memcmp(&s->md, &s->dq_md, sizeof s->md) == 0) {
            memcpy(s->dq_y0, s->dq_y1, sizeof(double) * (size_t)n);
            memcpy(s->dq_a0, s->dq_a1, sizeof(double) * (size_t)nd);
            memcpy(s->dq_j0, s->dq_j1, sizeof(double) * (size_t)nd);
        } else {
            if ((flag = s->ops->get_dky(s->mem, t0, 0, s->tmp)) < 0)
                return flag;
            memcpy(s->dq_y0, NV_DATA_S(s->tmp), sizeof(double) * (size_t)n);
            if ((flag = s->ops->get_dky(s->mem, t0, 1, s->tmp)) < 0)
                return flag;
            memcpy(s->dq_a0, NV_DATA_S(s->tmp) + nd, sizeof(double) * (size_t)nd);
            if (gd_model_jerk(&s->m, t0, s->dq_y0, s->dq_a0, s->dq_j0, &s->md) != 0)
                return 1;
        }
        if ((flag = s->ops->get_dky(s->mem, tn, 0, s->tmp)) < 0)
            return flag;
        memcpy(s->dq_y1, NV_DATA_S(s->tmp), sizeof(double) * (size_t)n);
        if ((flag = s->ops->get_dky(s->mem, tn, 1, s->tmp)) < 0)
            return flag;
        memcpy(s->dq_a1, NV_DATA_S(s->tmp) + nd, sizeof(double) * (size_t)nd);
        if (gd_model_jerk(&s->m, tn, s->dq_y1, s->dq_a1, s->dq_j1, &s->md) != 0)
            return 1;
        s->dq_resets = s->resets;
        s->dq_md = s->md;
        s->dq_t0 = t0;
        s->dq_h = h;
        s->dq_t1 = tn;
        s->dq_ok = 1;
        s->dq_key = s->nrhs; /* after the reads: a read at tn may evaluate the RHS */
    }
    const double h = s->dq_h, tol = 1e-12 * (fabs(s->dq_t0) + h);
    if (t < s->dq_t0 - tol || t > s->dq_t0 + h + tol)
        return 1;
    double x = (t - s->dq_t0) / h;
    x = x < 0 ? 0 : (x > 1 ? 1 : x);
    const double x2 = x * x, x3 = x2 * x, x4 = x3 * x, x5 = x4 * x, x6 = x5 * x, x7 = x6 * x;
    const double h2 = h * h, h3 = h2 * h;
    for (int i = 0; i < nd; i++) {
        const double q0 = s->dq_y0[i], q1 = s->dq_y1[i], v0 = s->dq_y0[nd + i], v1 = s->dq_y1[nd + i];
        const double a0 = s->dq_a0[i], a1 = s->dq_a1[i], j0 = s->dq_j0[i], j1 = s->dq_j1[i];
        /* Q(x) = q0 + h v0 x + h^2 a0 x^2/2 + h^3 j0 x^3/6 + c4 x^4 + ... + c7 x^7; the residuals of
         * the Taylor part at x = 1 in value and first three derivatives fix c4..c7 */
        const double r0 = q1 - (q0 + h * (v0 + h * (0.5 * a0 + h * j0 / 6.0)));
        const double r1 = h * (v1 - (v0 + h * (a0 + 0.5 * h * j0)));
        const double r2 = h2 * (a1 - (a0 + h * j0));
        const double r3 = h3 * (j1 - j0);
        const double c4 = 35.0 * r0 - 15.0 * r1 + 2.5 * r2 - r3 / 6.0;
        const double c5 = -84.0 * r0 + 39.0 * r1 - 7.0 * r2 + 0.5 * r3;
        const double c6 = 70.0 * r0 - 34.0 * r1 + 6.5 * r2 - 0.5 * r3;
        const double c7 = -20.0 * r0 + 10.0 * r1 - 2.0 * r2 + r3 / 6.0;
        y[i] = q0 + h * (v0 * x + h * (0.5 * a0 * x2 + h * j0 * x3 / 6.0)) + c4 * x4 + c5 * x5 + c6 * x6 + c7 * x7;
        y[nd + i] = v0 + h * (a0 * x + 0.5 * h * j0 * x2) + (4.0 * c4 * x3 + 5.0 * c5 * x4 + 6.0 * c6 * x5 + 7.0 * c7 * x6) / h;
    }
    return 0;
}

GD_API gd_status gd_sim_dense(gd_sim *s, double t_abs, double *y, gd_error *err)
{
    double t = t_abs - (double)s->shift * s->m.period;
    /* the absolute/local conversion can move t by an ulp outside the last step: clamp */
    double tol = 1e-12 * (fabs(s->t) + s->m.period);
    if (t > s->t && t <= s->t + tol)
        t = s->t;
    if (t < s->t_step0 && t >= s->t_step0 - tol)
        t = s->t_step0;
    if (t == s->t) { /* the current state (also before the first step, when there is no interpolant) */
        memcpy(y, NV_DATA_S(s->y), sizeof(double) * (size_t)s->m.n);
        return GD_OK;
    }
    if (!s->o.arkode_dense && !s->m.custom) {
        int r = dense_septic(s, t, y);
        if (r < 0)
            return gd_sim_sun_check(s, r, "GetDky", err);
        if (r == 0)
            return GD_OK;
    }
    int flag = s->ops->get_dky(s->mem, t, 0, s->tmp);
    if (flag < 0)
        return gd_sim_sun_check(s, flag, "GetDky", err);
    memcpy(y, NV_DATA_S(s->tmp), sizeof(double) * (size_t)s->m.n);
    return GD_OK;
}
