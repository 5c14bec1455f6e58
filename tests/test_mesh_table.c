/* Tabulated mesh stiffness and the mesh-in impact pulse in the dynamic model.
 * 1. The trigonometric interpolant of a table passes through every sample, and a table sampled
 *    from a harmonic stiffness gives the harmonic stiffness's response.
 * 2. A force pulse of height F over a part of every mesh period, on a linear oscillator: the
 *    state at every period boundary against the exact piecewise map (the pulse edges must be
 *    stop times), and the pulse's mean force shifts the mean deflection by F d / T exactly. */
#include "analysis_util.h"
#include "tap.h"
#include "geardyn/gd_scene.h"

#include <gsl/gsl_rng.h>

static void segment(double k, double z, double F, double t, double *x, double *v)
{
    double xs = F / k, wn = sqrt(k), zz = z / wn;
    double wd = wn * sqrt(1 - zz * zz), a = zz * wn;
    double x0 = *x - xs, v0 = *v;
    double e = exp(-a * t), c = cos(wd * t), s = sin(wd * t);
    *x = xs + e * (x0 * c + (v0 + a * x0) / wd * s);
    *v = e * (v0 * c - (a * v0 + wn * wn * x0) / wd * s);
}

int main(void)
{
    gd_case c;
    gd_model m;
    gd_error e = {0};
    const char *extra[] = {"scene.model=torsional-lr", "scene.error_excitation=off", "solver.rtol=1e-12",
                           "solver.atol=1e-14", NULL};
    au_ks_case(&c, &m, 0.0, 0.05, 20.0, 0.0, 1.5, extra);
    /* 1a. exact at the samples */
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 3);
    int n = 32;
    double k[32];
    for (int i = 0; i < n; i++)
        k[i] = m.k_ref * (0.8 + 0.4 * gsl_rng_uniform(r));
    tap_ok(gd_model_set_stiffness_table(&m, 0, k, n, &e) == GD_OK, "table of 32 random samples (%s)", e.msg);
    gd_modes md = {0};
    double worst = 0;
    for (int i = 0; i < n; i++) {
        double t = (2.0 * M_PI * i / n) / m.Omega;
        worst = fmax(worst, fabs(gd_model_stiffness(&m, 0, t, &md) - k[i] / m.k_ref));
    }
    TAP_CLOSE(worst, 0.0, 1e-12, "the interpolant passes through every sample (relative to k_ref)");
    gsl_rng_free(r);
    /* 1b. a table of a harmonic stiffness reproduces the harmonic response */
    gd_model mh, mt;
    gd_case ch;
    const char *extra2[] = {"scene.model=torsional-lr", "scene.error_excitation=off", "solver.rtol=1e-12",
                            "solver.atol=1e-14", NULL};
    au_ks_case(&ch, &mh, 0.2, 0.05, 20.0, 0.0, 1.5, extra2);
    mt = mh;
    for (int i = 0; i < n; i++)
        k[i] = mh.k_ref * (1.0 + 0.2 * cos(2.0 * M_PI * i / n));
    gd_model_set_stiffness_table(&mt, 0, k, n, &e);
    gd_model_set_stiffness_table(&mt, 1, k, n, &e);
    double y0[GD_MAX_STATE] = {0};
    gd_modes m0 = {0};
    gd_initial_state(&ch, &mh, y0, &m0, &e);
    y0[2] = 0.7;
    gd_solver_opts o;
    gd_solver_opts_from_case(&ch, &o);
    gd_sim *sh, *st;
    gd_sim_create(&mh, &o, y0, &m0, &sh, &e);
    gd_sim_create(&mt, &o, y0, &m0, &st, &e);
    double dmax = 0;
    for (int p = 0; p < 30; p++) {
        gd_sim_period(sh, &e);
        gd_sim_period(st, &e);
        for (int i = 0; i < mh.n; i++)
            dmax = fmax(dmax, fabs(gd_sim_state(sh)[i] - gd_sim_state(st)[i]));
    }
    TAP_CLOSE(dmax, 0.0, 1e-9, "harmonic stiffness and its table: same response over 30 periods");
    {
        /* and the comparison can fail: a table of amplitude 0.25 answers differently */
        gd_model mw = mh;
        for (int i = 0; i < n; i++)
            k[i] = mh.k_ref * (1.0 + 0.25 * cos(2.0 * M_PI * i / n));
        gd_model_set_stiffness_table(&mw, 0, k, n, &e);
        gd_sim *sa, *sb;
        gd_sim_create(&mh, &o, y0, &m0, &sa, &e);
        gd_sim_create(&mw, &o, y0, &m0, &sb, &e);
        for (int p = 0; p < 30; p++) {
            gd_sim_period(sa, &e);
            gd_sim_period(sb, &e);
        }
        tap_ok(fabs(gd_sim_state(sa)[0] - gd_sim_state(sb)[0]) > 1e-3, "a different table gives a different response");
        gd_sim_free(sa);
        gd_sim_free(sb);
    }
    gd_sim_free(sh);
    gd_sim_free(st);
    gd_case_free(&ch);

    /* 2. impact pulses on the linear oscillator (constant stiffness, no clearance reached) */
    gd_case_free(&c);
    au_ks_case(&c, &m, 0.0, 0.05, 20.0, 0.0, 1.5, extra);
    double Fimp = 3.0, d = 0.15; /* dimensionless height (K&S units of one half), fraction of the period */
    double T = m.period, phase = 1.0;
    double F_n = Fimp * m.k_ref * m.bc_m, dur_s = d * T / m.omega_n;
    tap_ok(gd_model_set_impact(&m, 0, F_n, phase, dur_s, &e) == GD_OK, "impact pulse set (%s)", e.msg);
    double y[GD_MAX_STATE] = {0};
    gd_modes md2 = {0};
    gd_initial_state(&c, &m, y, &md2, &e);
    y[0] += 1.0;
    gd_solver_opts_from_case(&c, &o);
    gd_sim *s;
    gd_sim_create(&m, &o, y, &md2, &s, &e);
    /* left half: x'' + 2 zeta x' + (x - 1) + pulse = 20, x' = x - 1: the impact force is a contact
     * force between the teeth, so it acts on the mesh coordinate like the mesh force */
    double xe = y[0] - 1.0, ve = y[2], t0 = phase / m.Omega, t1 = t0 + d * T, worst2 = 0, mean = 0;
    long nper = 40;
    for (int p = 0; p < nper; p++) {
        gd_sim_period(s, &e);
        segment(1.0, 0.05, 20.0, t0, &xe, &ve);
        segment(1.0, 0.05, 20.0 - Fimp, t1 - t0, &xe, &ve);
        segment(1.0, 0.05, 20.0, T - t1, &xe, &ve);
        worst2 = fmax(worst2, fmax(fabs(gd_sim_state(s)[0] - 1.0 - xe), fabs(gd_sim_state(s)[2] - ve)));
        mean += gd_sim_state(s)[0];
    }
    gd_sim_stats stt;
    gd_sim_get_stats(s, &stt);
    TAP_CLOSE(worst2, 0.0, 1e-9, "state at every period boundary against the exact map with the pulse");
    tap_ok(stt.resets >= 2 * nper, "both pulse edges are stop times (%ld resets over %ld periods)", stt.resets, nper);
    tap_ok(stt.events == 0, "no clearance reached (%ld events)", stt.events);
    TAP_CLOSE(gd_sim_state(s)[1] - y[1], 0.0, 1e-12, "the right half has no pulse: it stays at rest");
    gd_sim_free(s);
    gd_case_free(&c);
    return tap_done();
}
