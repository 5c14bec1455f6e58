/* Linear limit: the torsional model with constant mesh stiffness, a harmonic static
 * transmission error and a load high enough that the teeth never leave drive-side
 * contact is a linear, base-excited oscillator. Its steady state is known in closed form.
 *
 * Dimensionless equation of the torsional model (model_build.c: mass 2, mesh k = 2,
 * c = 4 zeta, load F0; the mesh force acts on lambda = q - e(t)):
 *     2 q'' + 4 zeta lambda' + 2 (lambda - h) = F0,   e = e_m + e_r sin(Omega tau + phi).
 * With q = lambda + e and F_m = F0 / 2:
 *     lambda'' + 2 zeta lambda' + lambda = h + F_m + e_r Omega^2 sin(Omega tau + phi)
 * so in steady state
 *     lambda(tau) = h + F_m + Im[X exp(i (Omega tau + phi))],
 *     X = e_r Omega^2 / (1 - Omega^2 + 2 i zeta Omega),
 * i.e. amplitude |X| and a phase lag arg(1 - Omega^2 + 2 i zeta Omega) behind the
 * forcing sin(Omega tau + phi). The error enters as base excitation, hence Omega^2: a
 * sign error in the excitation shifts the phase by pi, a missing e'' changes both.
 *
 * The run starts from the static deflection (not from the steady state) and the
 * transient decays as exp(-zeta tau) before recording.
 *
 * The same closed form checks solver.exact_samples: with it the samples of a response run
 * are the method's solution at step ends (order 8 at rtol 1e-11: 1e-12 of the amplitude),
 * where the cubic dense output between the long steps of that table is 2e-6 off. */
#include "physics_util.h"
#include "pair_util.h"
#include "tap.h"
#include "geardyn/gd_analysis.h"
#include "geardyn/gd_scene.h"
#include "geardyn/gd_geometry.h"

#include <complex.h>

/* Samples of a response run against the closed form: the largest deviation of lambda over the
 * recorded window, relative to the amplitude. */
typedef struct lin_ref {
    double omega_n, Omega, phi, lag, mean, amp, maxdev;
    long count;
} lin_ref;

static int on_lin_sample(void *user, const gd_sample *smp)
{
    lin_ref *r = user;
    double tau = smp->t_s * r->omega_n;
    double exact = r->mean + r->amp * sin(r->Omega * tau + r->phi - r->lag);
    r->maxdev = fmax(r->maxdev, fabs(smp->lambda_um[0] - exact) / r->amp); /* b_c = 1 um */
    r->count++;
    return 0;
}

static void lin_response(const char *const *sets, double Fm, double Omega, const char *const *extra, lin_ref *r,
                         gd_response_result *out)
{
    gd_case c;
    pu_case(&c, sets);
    pu_tune(&c, Fm, Omega);
    for (int i = 0; extra[i]; i++)
        pu_set(&c, extra[i]);
    gd_error e;
    memset(&e, 0, sizeof e);
    PU_CHECK(gd_case_resolve(&c, &e), &e);
    gd_model m;
    pu_build(&c, &m);
    gd_response_hooks h = {on_lin_sample, NULL, NULL, NULL};
    gd_response_result res;
    r->maxdev = 0;
    r->count = 0;
    PU_CHECK(gd_response_run(&c, &m, NULL, &h, r, &res, &e), &e);
    if (out)
        *out = res;
    gd_case_free(&c);
}

int main(void)
{
    const double zeta = 0.1, Omega = 0.8, e_r_um = 3.0, phi_deg = 30.0, bc_um = 1.0, Fm = 20.0;
    const double backlash_um = 10.0; /* h = 5 */
    const char *sets[] = {"scene.model=torsional",
                          "excitation.stiffness=constant",
                          "scene.error_excitation=on",
                          "excitation.ste_amplitude_um=3",
                          "excitation.ste_mean_um=0.5",
                          "excitation.ste_phase_deg=30",
                          "clearance.backlash_um=10",
                          "damping.mesh_damping_ratio=0.1",
                          "solver.characteristic_length_um=1",
                          "solver.rtol=1e-11",
                          "solver.atol=1e-13",
                          NULL};
    gd_case c;
    pu_case(&c, sets);
    pu_tune(&c, Fm, Omega);
    gd_model m;
    pu_build(&c, &m);

    /* the build itself: dimensionless numbers from the physical inputs */
    gd_error e;
    memset(&e, 0, sizeof e);
    gd_geometry g;
    PU_CHECK(gd_geometry_compute(PAIR_OF(&c), &g, &e), &e);
    double cb = cos(g.beta_b);
    double mn = c.equivalent_mass_kg / (cb * cb), km = c.mesh_stiffness_n_per_m;
    double omega_n = sqrt(km / mn);
    double Omega_expect = 2 * M_PI * c.teeth_pinion * c.speed_rpm / 60.0 / omega_n;
    double Fm_expect = c.torque_nm / (2 * g.rb[0] * cb) / (km * bc_um * 1e-6);
    TAP_REL(m.Omega, Omega_expect, 1e-12, "Omega = 2 pi z1 n / 60 / sqrt(k_m / m_n)");
    TAP_REL(m.Omega, Omega, 1e-12, "Omega as tuned");
    TAP_REL(m.F0[0] / m.mass[0], Fm_expect, 1e-12, "F_m = T / (2 r_b1 cos(beta_b)) / (k_m b_c)");
    TAP_REL(m.clear[0].c / m.mass[0], 2 * zeta, 1e-14, "damping 2 zeta after dividing by the mass 2");
    TAP_REL(m.clear[0].k / m.mass[0], 1.0, 1e-14, "stiffness 1 after dividing by the mass 2");

    const double h = 0.5 * backlash_um / bc_um, e_r = e_r_um / bc_um, phi = phi_deg * M_PI / 180.0;
    double complex X = e_r * Omega * Omega / (1.0 - Omega * Omega + 2.0 * I * zeta * Omega);
    double amp = cabs(X), lag = -carg(X); /* lambda_alt = |X| sin(Omega tau + phi - lag) */
    double mean = h + Fm;
    printf("# closed form: mean %.12g, amplitude %.12g, phase lag %.12g rad; min lambda %.6g > h %.6g\n", mean, amp,
           lag, mean - amp, h);

    double y0[GD_MAX_STATE];
    gd_modes md0;
    memset(&md0, 0, sizeof md0);
    PU_CHECK(gd_model_static_state(&m, y0, &md0, &e), &e);
    gd_solver_opts o;
    gd_solver_opts_from_case(&c, &o);
    const long nper = 48, rec0 = 40;
    const int ns = 64;
    pu_samples p;
    gd_sim_stats st;
    pu_run_sampled(&m, &o, y0, &md0, nper, rec0, ns, &p, &st);
    tap_ok(st.events == 0, "no contact event in the linear limit (%ld events)", st.events);

    /* Fourier coefficients over whole periods: exact for a constant plus one harmonic */
    double s0 = 0, sc = 0, ss = 0, maxdev = 0, lam_min = INFINITY;
    gd_modes md;
    memset(&md, 0, sizeof md);
    md.mode[0] = 1;
    for (long k = 0; k < p.count; k++) {
        double t = p.t[k], *y = p.y + k * p.n;
        double lam = pu_lambda(&m, 0, t, y, &md);
        s0 += lam;
        sc += lam * cos(Omega * t + phi);
        ss += lam * sin(Omega * t + phi);
        double exact = mean + amp * sin(Omega * t + phi - lag);
        maxdev = fmax(maxdev, fabs(lam - exact));
        lam_min = fmin(lam_min, lam);
    }
    double N = (double)p.count;
    double a0 = s0 / N, ac = 2 * sc / N, as = 2 * ss / N; /* lambda = a0 + as sin(.) + ac cos(.) */
    double amp_num = hypot(ac, as), lag_num = -atan2(ac, as);
    tap_ok(lam_min > h, "teeth stay in drive-side contact: min lambda %.9g > h %.9g", lam_min, h);
    TAP_REL(a0, mean, 1e-6, "mean mesh deflection h + F_m");
    TAP_REL(amp_num, amp, 1e-6, "steady-state amplitude e_r Omega^2 / |1 - Omega^2 + 2 i zeta Omega|");
    TAP_CLOSE(lag_num, lag, 1e-6, "phase lag behind the forcing (rad)");
    TAP_CLOSE(maxdev / amp, 0.0, 1e-6, "time history: max |lambda - closed form| / amplitude");
    /* the transmitted coordinate q = lambda + e: its amplitude is |X + e_r| */
    double qdev = 0;
    for (long k = 0; k < p.count; k++) {
        double t = p.t[k];
        double q_exact = mean + amp * sin(Omega * t + phi - lag) + 0.5 / bc_um + e_r * sin(Omega * t + phi);
        qdev = fmax(qdev, fabs(p.y[k * p.n] - q_exact));
    }
    TAP_CLOSE(qdev / amp, 0.0, 1e-6, "time history: max |q - (lambda + e)| / amplitude");
    printf("# %ld samples over %ld periods, %ld steps\n", p.count, nper - rec0, st.steps);

    /* solver.exact_samples: the samples of a response run are the method's solution (steps end on
     * them), not the cubic dense output between the long steps of the 8th-order table */
    {
        lin_ref r = {omega_n, Omega, phi, lag, mean, amp, 0, 0};
        const char *off[] = {"solver.order=8", "solver.rtol=1e-11", "solver.atol=1e-13", "run.transient_periods=40",
                             "run.record_periods=8", "run.lyapunov_exponents=0", "solver.exact_samples=off", NULL};
        const char *on[] = {"solver.order=8", "solver.rtol=1e-11", "solver.atol=1e-13", "run.transient_periods=40",
                            "run.record_periods=8", "run.lyapunov_exponents=0", "solver.exact_samples=on", NULL};
        lin_response(sets, Fm, Omega, off, &r, NULL);
        double dev_interp = r.maxdev;
        lin_response(sets, Fm, Omega, on, &r, NULL);
        printf("# order 8, rtol 1e-11, %ld samples: max |lambda - closed form| / amplitude %.3g from the cubic "
               "dense output, %.3g on step ends\n", r.count, dev_interp, r.maxdev);
        tap_ok(r.count == 8 * 64, "exact samples: 64 samples per period over 8 periods (%ld)", r.count);
        TAP_CLOSE(r.maxdev, 0.0, 1e-9, "exact samples (order 8, rtol 1e-11): max |lambda - closed form| / amplitude");
    }

    /* the dynamic load factor of the response: the mesh force k (lambda - h) + c lambda' of the
     * steady state is F_m + Im[(1 + 2 i zeta Omega) X exp(i (Omega tau + phi))] per unit mass, so the
     * largest over the static F_m is 1 + |X| |1 + 2 i zeta Omega| / F_m (1.2467 here; without the
     * damper's share 1.2436). Sampled 1024 times a period, the largest sample lies within
     * 1 - cos(pi / 1024) = 5e-6 of the peak's dynamic part. */
    {
        lin_ref r = {omega_n, Omega, phi, lag, mean, amp, 0, 0};
        const char *fine[] = {"run.transient_periods=60", "run.record_periods=8", "run.lyapunov_exponents=0",
                              "output.samples_per_period=1024", NULL};
        gd_response_result res;
        lin_response(sets, Fm, Omega, fine, &r, &res);
        double dlf = 1.0 + amp * cabs(1.0 + 2.0 * I * zeta * Omega) / Fm;
        printf("# dynamic load factor %.9g, closed form %.9g (without the damper %.9g); largest force %.6g N\n",
               res.dynamic_load_factor[0], dlf, 1.0 + amp / Fm, res.force_max_n[0]);
        TAP_CLOSE(res.dynamic_load_factor[0] - 1.0, dlf - 1.0, 1e-5 * (dlf - 1.0),
                  "dynamic load factor: 1 + |X| |1 + 2 i zeta Omega| / F_m of the linear oscillator");
        TAP_REL(res.dynamic_load_factor[1], res.dynamic_load_factor[0], 1e-15,
                "the one mesh of the torsional model gives both columns");
        TAP_REL(res.force_max_n[0], res.dynamic_load_factor[0] * m.static_load_n, 1e-14,
                "the largest mesh force is the factor times the static force");
    }
    pu_samples_free(&p);
    gd_case_free(&c);
    return tap_done();
}
