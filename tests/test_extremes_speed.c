/* Extremes of speed, excitation and support stiffness (suite 'extremes', docs/accuracy.md):
 * 100 rpm and 8000 rpm, zero and 20 um transmission error amplitude, and supports 100 times
 * stiffer than the default run with the implicit method (ARKODE DIRK), whose cost the test
 * reports next to the explicit method's. The paper's pair and bta model at 4000 rpm (quickstart
 * data) unless stated; each scene at two tolerances (extremes_util.h): completes, no NaN/inf,
 * events bounded, the two runs agree within the stated tolerances. */
#include "extremes_util.h"

#define S(...) ((const char *const[]){__VA_ARGS__, NULL})
#define STIFF                                                                                                      \
    "support.radial_stiffness_pinion_n_per_m=1e11", "support.radial_stiffness_gear_n_per_m=1e11",                  \
        "support.axial_stiffness_pinion_n_per_m=5e10", "support.axial_stiffness_gear_n_per_m=5e10"

static void cost_line(const char *label, const ex_run *r)
{
    printf("# cost, %s: %.3f s for %ld periods, %.1f steps, %.1f RHS evaluations, %.1f Jacobians per mesh period\n",
           label, r->wall_s, r->periods, (double)r->res.stats.steps / (double)r->periods,
           (double)r->res.stats.rhs_evals / (double)r->periods, (double)r->res.stats.jac_evals / (double)r->periods);
}

/* Supports 100 x stiffer with linear bearings (period-1 with mesh impacts): the implicit
 * method at rtol 1e-6 and 1e-8 against each other and against the explicit method at 1e-9, and
 * the cost of each. With bearing clearance the stiff journals rattle chaotically: the implicit
 * method must still complete, finite, with bounded events and matching statistics. */
static void stiff(void)
{
    const char *const dirk[] = {STIFF, "scene.bearing_clearance=off", "solver.method=dirk", NULL};
    const char *const erk[] = {STIFF, "scene.bearing_clearance=off", NULL};
    ex_spec sp = {"bta, supports x100, linear bearings, DIRK", 30, 10, 1e-5, 10, 1e-5, 1e-6, 30, 1e-6, 1e-8};
    ex_check(&sp, dirk, NULL);
    ex_run d, x;
    ex_run_case(dirk, NULL, 1e-8, 30, 10, &d);
    ex_run_case(erk, NULL, 1e-9, 30, 10, &x);
    cost_line("DIRK order 4, rtol 1e-8", &d);
    cost_line("ERK, default order, rtol 1e-9", &x);
    double e = gd_workprec_poincare_error(d.pts, x.pts, 31, d.n);
    tap_ok(d.st == GD_OK && x.st == GD_OK && e <= 1e-7,
           "supports x100: DIRK (rtol 1e-8) agrees with ERK (rtol 1e-9) over 30 periods: %.3g (tol 1e-7); DIRK "
           "%.3f s, ERK %.3f s (ratio %.1f)", e, d.wall_s, x.wall_s, d.wall_s / x.wall_s);
    ex_free(&d);
    ex_free(&x);
    ex_spec sc = {"bta, supports x100, bearing clearance, DIRK (chaotic)", 40, 2, 1e-5, 30, 0, 0.15, 60, 1e-6, 1e-8};
    ex_check(&sc, S(STIFF, "solver.method=dirk"), NULL);
}

int main(void)
{
    /* 100 rpm: mesh period 20 ms against 19 kHz groove modes: some 2000 steps per period */
    ex_spec slow = {"bta, 100 rpm", 30, 10, 1e-5, 10, 1e-5, 1e-3, 60, 0, 0};
    ex_check(&slow, S("operating.speed_rpm=100"), NULL);
    ex_spec fast = {"bta, 8000 rpm", 300, 20, 1e-5, 100, 1e-5, 1e-6, 60, 0, 0};
    ex_check(&fast, S("operating.speed_rpm=8000"), NULL);
    ex_spec e0 = {"bta, no transmission error (e_r = 0)", 300, 20, 1e-5, 100, 1e-5, 1e-6, 60, 0, 0};
    ex_check(&e0, S("excitation.ste_amplitude_um=0"), NULL);
    ex_spec e20 = {"bta, e_r = 20 um", 300, 20, 1e-5, 100, 1e-5, 1e-6, 60, 0, 0};
    ex_check(&e20, S("excitation.ste_amplitude_um=20"), NULL);
    stiff();
    return tap_done();
}
