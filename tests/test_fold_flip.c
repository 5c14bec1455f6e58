/* A fold-flip point (a fold curve meeting a period-doubling curve: the orbit has the multipliers +1
 * and -1 at once; Kuznetsov, Elements of Applied Bifurcation Theory, 3rd ed., ch. 9) located by
 * gd_curve_follow on both curves, independently, on a system whose curves are known in closed form
 * (docs/continuation.md section 8, "Tests and their figures").
 *
 * Why not a gear model: the Kahraman & Singh oscillator has one degree of freedom, so its monodromy
 * is 2 x 2 with det M = exp(-2 zeta 2 pi n / Omega) > 0 (Liouville; the saltation matrices of the
 * continuous dead-zone force are the identity), while multipliers +1 and -1 make det M = -1: no
 * orbit of it, of any period, is a fold-flip. (Any Poincare map of a flow preserves orientation; a
 * fold-flip needs a state of three dimensions or more.)
 *
 * The system (period 2 pi, state (x, y1, y2)):
 *   x'  = mu - sin(x)^2,                       mu = p1 - p2^2
 *   y'  = (J / 2 + R(t/2) diag(c, c2) R(-t/2)) y + (1e-3 cos t, 0),   c = 1/2 - p1 - p2, c2 = -0.3
 * with J the rotation generator and R(a) the rotation by a. In the rotating frame z = R(-t/2) y the
 * y-part is z' = diag(c, c2) z (plus forcing), and R(pi) = -I, so the y-part's monodromy is
 * -exp(2 pi diag(c, c2)): the multipliers -exp(2 pi c) and -exp(2 pi c2), each real and simple. The
 * orbit's x is a constant root, sin x = +-sqrt(mu), with the multiplier exp(-2 pi sin 2x) (sin x, not x:
 * the field stays bounded, where x' = mu - x^2 blows up in finite time from below the unstable root, and
 * a shooting run from there never ends). So:
 *   the fold curve (x = 0, the multiplier +1) is p1 = p2^2 (a saddle-node: x' = mu - x^2 + O(x^4));
 *   the period-doubling curve (multiplier -1) is c = 0: p1 = 1/2 - p2;
 *   they meet at the fold-flip p2* = (sqrt(3) - 1) / 2, p1* = p2*^2 = 1/2 - p2*.
 * Checks:
 * 1. The fold curve, from p2 = 0.1 up, keeps p1 = p2^2 to 1e-8 at every point and locates a
 *    fold-flip on test_period_doubling at (p1*, p2*) to 1e-8, with the second multiplier -1.
 * 2. The period-doubling curve, from p2 = 0.1 (on the stable orbit sin x = +sqrt(mu)) up, keeps
 *    p1 = 1/2 - p2 to 1e-8 at every point, passes the fold-flip (its orbit's x runs through 0 onto the
 *    unstable root, the multiplier exp(-2 pi sin 2x) through +1, and the curve turns back down the same
 *    line of the plane to the box) and locates it on test_fold at (p1*, p2*) to 1e-8.
 * 3. The two locations, from independent continuations, agree to 1e-8 in both parameters (the
 *    brief's 1e-6 relative with a margin: each is located to the curves' locate_tol in arclength).
 * 4. The fold curve below p2 = 0.1 and the period-doubling curve down from p2 = 0.1 meet no
 *    fold-flip (none exists there). */
#include "analysis_util.h"
#include "tap.h"
#include "geardyn/gd_envelope.h"

#include <math.h>
#include <string.h>

typedef struct ff {
    double p1, p2;
    gd_custom_system sys;
} ff;
static const double C2 = -0.3;
static double ff_mu(const ff *F) { return F->p1 - F->p2 * F->p2; }
static double ff_c(const ff *F) { return 0.5 - F->p1 - F->p2; }
/* A(t) = J / 2 + R(t/2) diag(c, c2) R(-t/2) */
static void ff_a(const ff *F, double t, double A[4])
{
    double s = sin(0.5 * t), co = cos(0.5 * t), c = ff_c(F);
    A[0] = c * co * co + C2 * s * s;
    A[1] = (c - C2) * s * co - 0.5;
    A[2] = (c - C2) * s * co + 0.5;
    A[3] = c * s * s + C2 * co * co;
}
static void ff_rhs(double t, const double *y, double *yd, void *ctx)
{
    const ff *F = ctx;
    double A[4];
    ff_a(F, t, A);
    double sx = sin(y[0]);
    yd[0] = ff_mu(F) - sx * sx;
    yd[1] = A[0] * y[1] + A[1] * y[2] + 1e-3 * cos(t);
    yd[2] = A[2] * y[1] + A[3] * y[2];
}
static void ff_tangent(double t, const double *y, const double *v, double *out, void *ctx)
{
    const ff *F = ctx;
    double A[4];
    ff_a(F, t, A);
    out[0] = -sin(2.0 * y[0]) * v[0];
    out[1] = A[0] * v[1] + A[1] * v[2];
    out[2] = A[2] * v[1] + A[3] * v[2];
}
static gd_status ff_at(double p1, double p2, gd_model *m, void *ctx, gd_error *err)
{
    (void)err;
    ff *F = ctx;
    F->p1 = p1;
    F->p2 = p2;
    gd_model_custom(m, &F->sys, 2.0 * M_PI);
    return GD_OK;
}

int main(void)
{
    ff F;
    memset(&F, 0, sizeof F);
    F.sys.n = 3;
    F.sys.rhs = ff_rhs;
    F.sys.tangent = ff_tangent;
    F.sys.ctx = &F;
    gd_solver_opts o;
    au_smooth_opts(&o);
    gd_curve_opts co;
    gd_curve_opts_default(&co);
    co.p_min[0] = -0.5;
    co.p_max[0] = 1.0;
    co.p_min[1] = 0.0;
    co.p_max[1] = 0.7;
    const double p2s = 0.5 * (sqrt(3.0) - 1.0), p1s = p2s * p2s; /* the fold-flip */
    gd_codim2 at[2];
    int found[2] = {0, 0};
    for (int kind = 0; kind < 2; kind++) { /* 0: the fold curve, 1: the period-doubling curve */
        const char *name = kind == 0 ? "fold" : "period-doubling";
        gd_curve_start s;
        memset(&s, 0, sizeof s);
        s.kind = kind == 0 ? GD_CURVE_FOLD : GD_CURVE_PERIOD_DOUBLING;
        s.nper = 1;
        s.clearance = -1;
        s.p2 = 0.1;
        s.p1 = kind == 0 ? 0.01 : 0.4;
        s.y[0] = kind == 0 ? 0.0 : asin(sqrt(0.4 - 0.01));
        for (int dir = -1; dir <= 1; dir += 2) {
            gd_error e = {0};
            gd_curve cv;
            co.direction = dir;
            if (gd_curve_follow(ff_at, &F, &o, &co, &s, &cv, &e) != GD_OK)
                au_die(&e);
            double worst = 0, xmin = INFINITY;
            for (int i = 0; i < cv.npoints; i++) {
                double p1 = cv.pt[i].orbit.p, p2 = cv.pt[i].p2;
                worst = fmax(worst, fabs(kind == 0 ? p1 - p2 * p2 : p1 - (0.5 - p2)));
                xmin = fmin(xmin, cv.pt[i].orbit.y[0][0]);
            }
            printf("# %s curve %s: %d points, %ld corrections, smallest x %.4f: %s\n", name, dir > 0 ? "up" : "down",
                   cv.npoints, cv.corrections, xmin, cv.end_reason);
            for (int i = 0; i < cv.nc2; i++)
                printf("#   %s at (%.12f, %.12f) on %s, multiplier (%.10f, %.10f), location %s\n",
                       gd_codim2_kind_name(cv.c2[i].kind), cv.c2[i].p1, cv.c2[i].p2, name, cv.c2[i].mu_re,
                       cv.c2[i].mu_im, gd_bif_location_name(cv.c2[i].location));
            tap_ok(cv.npoints >= 5 && worst < 1e-8, "%s curve %s: %d points, %s at every point to %.2g", name,
                   dir > 0 ? "up" : "down", cv.npoints, kind == 0 ? "p1 = p2^2" : "p1 = 1/2 - p2", worst);
            if (dir < 0) {
                tap_ok(cv.nc2 == 0, "%s curve down from p2 = 0.1: no codimension-two point (%d)", name, cv.nc2);
            } else {
                int n = 0;
                for (int i = 0; i < cv.nc2; i++)
                    if (cv.c2[i].kind == GD_C2_FOLD_FLIP) {
                        at[kind] = cv.c2[i];
                        n++;
                    }
                found[kind] = n == 1;
                double e1 = n ? fabs(at[kind].p1 - p1s) : INFINITY, e2 = n ? fabs(at[kind].p2 - p2s) : INFINITY;
                double mu = n ? hypot(at[kind].mu_re - (kind == 0 ? -1.0 : 1.0), at[kind].mu_im) : INFINITY;
                tap_ok(n == 1 && cv.nc2 == 1 && at[kind].location == GD_LOC_LOCATED && e1 < 1e-8 && e2 < 1e-8,
                       "%s curve up: one fold-flip, located on %s at p1 %.12f, p2 %.12f: the closed form "
                       "((sqrt(3) - 1)^2 / 4, (sqrt(3) - 1) / 2) to %.2g, %.2g", name,
                       kind == 0 ? "test_period_doubling" : "test_fold", n ? at[kind].p1 : NAN, n ? at[kind].p2 : NAN,
                       e1, e2);
                tap_ok(mu < 1e-6, "%s curve up: the fold-flip's second multiplier is %s1 (to %.2g)", name,
                       kind == 0 ? "-" : "+", mu);
                if (kind == 1)
                    tap_ok(xmin < -0.05 && cv.end == GD_CEND_BOUND, "the period-doubling curve runs on past the "
                           "fold-flip onto the unstable orbit (x down to %.3f) to the box (%s)", xmin,
                           gd_curve_end_name(cv.end));
            }
            gd_curve_free(&cv);
        }
    }
    if (found[0] && found[1]) {
        double d1 = fabs(at[0].p1 - at[1].p1) / p1s, d2 = fabs(at[0].p2 - at[1].p2) / p2s;
        tap_ok(d1 < 1e-8 && d2 < 1e-8, "the fold-flip from the fold curve and from the period-doubling curve, two "
               "independent continuations: the same point to %.2g in p1, %.2g in p2 (relative)", d1, d2);
    } else {
        tap_ok(0, "the fold-flip located from both curves");
    }
    return tap_done();
}
