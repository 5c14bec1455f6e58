/* Rectangular-wave mesh stiffness: the edges are time discontinuities the integrator must hit
 * exactly (stop times). A linear oscillator x'' + 2 zeta x' + k(t) x = F with k piecewise
 * constant has an exact one-period map: the product of the closed-form 2x2 transition
 * matrices of the two segments (plus the particular solution F/k of each). geardyn's state after
 * each period must match it to the integration tolerance; the mean of k must be 1. */
#include "analysis_util.h"
#include "tap.h"
#include "geardyn/gd_scene.h"

/* exact transition over time t of x'' + 2 z x' + k x = F from (x, v); underdamped */
static void segment(double k, double z, double F, double t, double *x, double *v)
{
    double xs = F / k, wn = sqrt(k), zz = z / wn; /* x'' + 2 zz wn x' + wn^2 x */
    double wd = wn * sqrt(1 - zz * zz), a = zz * wn;
    double x0 = *x - xs, v0 = *v;
    double e = exp(-a * t), c = cos(wd * t), s = sin(wd * t);
    double xn = e * (x0 * c + (v0 + a * x0) / wd * s);
    double vn = e * (v0 * c - (a * v0 + wn * wn * x0) / wd * s);
    *x = xn + xs;
    *v = vn;
}

int main(void)
{
    gd_case c;
    gd_model m;
    const char *extra[] = {"excitation.stiffness=rectangular", "excitation.rectangular_variation=0.3",
                           "excitation.rectangular_high_fraction=0.35", "scene.error_excitation=off",
                           "solver.rtol=1e-12", "solver.atol=1e-14", NULL};
    au_ks_case(&c, &m, 0.0, 0.05, 20.0, 0.0, 1.5, extra); /* between the parametric-resonance tongues at 2 and 1 */
    const gd_mesh_excitation *ex = &m.mesh[0];
    double d = ex->rect_frac, kh = ex->rect_high, kl = ex->rect_low;
    TAP_CLOSE(d * kh + (1 - d) * kl, 1.0, 1e-15, "the rectangular stiffness keeps the mean");
    TAP_CLOSE(kh, 1.3, 1e-15, "high level 1 + variation");
    gd_error e = {0};
    gd_solver_opts o;
    gd_solver_opts_from_case(&c, &o);
    double y[GD_MAX_STATE] = {0};
    gd_modes md = {0};
    /* start away from equilibrium, in contact (x > h = 1) */
    y[0] = 21.0 + 2.0;
    y[1] = 0.5;
    gd_model_consistent_modes(&m, 0.0, y, &md, &e);
    gd_sim *s;
    if (gd_sim_create(&m, &o, y, &md, &s, &e) != GD_OK)
        au_die(&e);
    /* K&S form: mass 2, k = 2 s(t), c = 4 zeta, F0 = 2 Fm: divide by 2; the contact force acts on
     * x - h, so in the oscillator x' = x - 1 the load is Fm */
    double xe = y[0] - 1.0, ve = y[1], T = m.period, worst = 0;
    for (int p = 0; p < 20; p++) {
        if (gd_sim_period(s, &e) != GD_OK)
            au_die(&e);
        segment(kh, 0.05, 20.0, d * T, &xe, &ve);
        segment(kl, 0.05, 20.0, (1 - d) * T, &xe, &ve);
        const double *yy = gd_sim_state(s);
        worst = fmax(worst, fmax(fabs(yy[0] - 1.0 - xe), fabs(yy[1] - ve)) / 3.0);
    }
    gd_sim_stats st;
    gd_sim_get_stats(s, &st);
    TAP_CLOSE(worst, 0.0, 1e-9, "state at every period boundary against the exact piecewise map (relative)");
    tap_ok(st.events == 0, "no clearance is reached (%ld events)", st.events);
    tap_ok(st.resets >= 40, "every edge is a stop time followed by a reset (%ld resets over 20 periods)", st.resets);
    gd_sim_free(s);
    gd_case_free(&c);
    return tap_done();
}
