/* Validation against the Kahraman & Singh oscillator (cases/validation/kahraman-singh.ini).
 *
 *   x'' + 2 zeta x' + (1 + alpha cos(Omega tau)) f(x) = F_m + F_a Omega^2 cos(Omega tau)
 *
 * 1. The shipped case maps exactly onto the equation: the dimensionless numbers the model
 *    builds from the physical inputs of the file are zeta 0.05, F_m 0.1, F_a 0.1,
 *    alpha 0.2, Omega 1.2 and the half backlash 1.
 * 2. The equation integrated independently (GSL odeiv2, Prince-Dormand 8(9) with tight
 *    tolerances and a bounded step, no event location: the dead zone is evaluated from
 *    the state) and geardyn's mesh deflection from the same initial state agree over
 *    the transient and the steady state, impacts included (single-sided, mild).
 * 3. The response analysis of the file as shipped (static start) reaches the same orbit:
 *    period-1 with single-sided impacts and the extrema of the independent solution. */
#include "physics_util.h"
#include "tap.h"
#include "geardyn/gd_analysis.h"
#include "geardyn/gd_scene.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

typedef struct ks_par {
    double zeta, Fm, Fa, alpha, Omega;
} ks_par;

static int ks_rhs(double t, const double y[], double dydt[], void *params)
{
    const ks_par *p = params;
    double x = y[0], f = x > 1.0 ? x - 1.0 : (x < -1.0 ? x + 1.0 : 0.0);
    double c = cos(p->Omega * t);
    dydt[0] = y[1];
    dydt[1] = p->Fm + p->Fa * p->Omega * p->Omega * c - 2.0 * p->zeta * y[1] - (1.0 + p->alpha * c) * f;
    return GSL_SUCCESS;
}

int main(void)
{
    const ks_par P = {0.05, 0.1, 0.1, 0.2, 1.2};
    const char *src = getenv("GEARDYN_SOURCE");
    char path[2048];
    snprintf(path, sizeof path, "%s/cases/validation/kahraman-singh.ini", src ? src : ".");
    gd_case c;
    gd_error e;
    memset(&e, 0, sizeof e);
    PU_CHECK(gd_case_init(&c, &e), &e);
    PU_CHECK(gd_case_load(&c, path, &e), &e);
    PU_CHECK(gd_case_resolve(&c, &e), &e);
    gd_model m;
    pu_build(&c, &m);

    /* 1. the mapping */
    const gd_clearance *cl = &m.clear[0];
    TAP_REL(m.Omega, P.Omega, 1e-12, "Omega = omega_m / omega_n");
    TAP_REL(m.F0[0] / m.mass[0], P.Fm, 1e-12, "F_m = F0 / 2");
    TAP_REL(cl->c / m.mass[0], 2.0 * P.zeta, 1e-14, "2 zeta = c / 2");
    TAP_REL(cl->k / m.mass[0], 1.0, 1e-14, "mean stiffness k / 2 = 1");
    TAP_REL(cl->h, 1.0, 1e-14, "half backlash = 1");
    TAP_REL(m.mesh[0].a[0], P.alpha, 1e-14, "alpha (first stiffness harmonic)");
    TAP_CLOSE(m.mesh[0].phi[0], 0.0, 0.0, "stiffness phase");
    TAP_REL(m.mesh[0].e_r, P.Fa, 1e-14, "F_a = e_r / b");
    TAP_REL(m.mesh[0].e_phi, M_PI / 2, 1e-14, "error phase 90 deg: e = F_a cos(Omega tau)");
    TAP_CLOSE(m.mesh[0].e_m, 0.0, 0.0, "error mean");
    tap_ok(m.nmesh == 1 && m.nclear == 1 && !cl->damp_contact_only && c.error_excitation,
           "one mesh, damping always, error on");

    /* 2. both integrators from x = 1.1, x' = 0 (drive-side contact) over 100 periods */
    const long nper = 100;
    const int ns = 64;
    gd_solver_opts o;
    gd_solver_opts_from_case(&c, &o);
    double y0[GD_MAX_STATE] = {0};
    double e0, ed0;
    gd_modes md0;
    memset(&md0, 0, sizeof md0);
    gd_model_error(&m, 0, 0.0, &md0, &e0, &ed0, NULL);
    y0[0] = 1.1 + e0; /* q = x + e */
    y0[1] = 0.0 + ed0;
    md0.mode[0] = 1;
    pu_samples p;
    gd_sim_stats st;
    pu_run_sampled(&m, &o, y0, &md0, nper, 0, ns, &p, &st);

    ks_par par = P;
    gsl_odeiv2_system sys = {ks_rhs, NULL, 2, &par};
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-4, 1e-13, 1e-13);
    gsl_odeiv2_driver_set_hmax(d, m.period / 200.0);
    double t = 0.0, x[2] = {1.1, 0.0};
    double dmax = 0, dmax_ss = 0, lo = INFINITY, hi = -INFINITY;
    long nsep = 0;
    int was_in = 1;
    for (long k = 0; k < p.count; k++) {
        if (p.t[k] > t) {
            int rc = gsl_odeiv2_driver_apply(d, &t, p.t[k], x);
            if (rc != GSL_SUCCESS) {
                printf("Bail out! gsl_odeiv2_driver_apply: %s\n", gsl_strerror(rc));
                return 1;
            }
        }
        gd_modes md;
        memset(&md, 0, sizeof md);
        double lam = pu_lambda(&m, 0, p.t[k], p.y + k * p.n, &md);
        double dx = fabs(lam - x[0]);
        dmax = fmax(dmax, dx);
        if (k >= (nper - 20) * ns) { /* the last 20 periods: steady state */
            dmax_ss = fmax(dmax_ss, dx);
            lo = fmin(lo, x[0]);
            hi = fmax(hi, x[0]);
        }
        int in = x[0] > 1.0;
        if (was_in && !in)
            nsep++;
        was_in = in;
    }
    gsl_odeiv2_driver_free(d);
    printf("# geardyn: %ld steps, %ld events; GSL: samples show %ld separations; steady-state x %.9g .. %.9g\n",
           st.steps, st.events, nsep, lo, hi);
    tap_ok(lo < 1.0 && lo > -1.0 && st.events >= nper,
           "the case impacts mildly: steady-state min x %.6g in (-1, 1), %ld events", lo, st.events);
    TAP_CLOSE(dmax, 0.0, 1e-7, "max |x_geardyn - x_K&S| over 100 periods (units of b)");
    TAP_CLOSE(dmax_ss, 0.0, 1e-7, "max |x_geardyn - x_K&S| over the last 20 periods (steady state)");

    /* 3. the shipped case through the response analysis. Its static start sits exactly on
     * the contact boundary (x = 1 + F_m - e(0) = 1 + 0.1 - 0.1) at rest, with the
     * acceleration F_m + F_a Omega^2 > 0 pushing it into drive-side contact: the start
     * mode must be +1 (a gap mode there would let the pinion run away, since x - h
     * never changes sign for the root finder). */
    double ys[GD_MAX_STATE];
    gd_modes mds;
    memset(&e, 0, sizeof e);
    PU_CHECK(gd_initial_state(&c, &m, ys, &mds, &e), &e);
    double xs, vs;
    gd_model_clearance(&m, 0, 0.0, ys, &mds, &xs, &vs);
    printf("# static start: x - h = %.3g, x' = %.3g\n", xs - cl->h, vs);
    tap_ok(fabs(xs - cl->h) < 1e-12 && mds.mode[0] == 1,
           "static start on the boundary (x - h = %.3g) begins in drive-side contact (mode %d)", xs - cl->h,
           mds.mode[0]);
    gd_response_result r;
    memset(&e, 0, sizeof e);
    PU_CHECK(gd_response_run(&c, &m, NULL, NULL, NULL, &r, &e), &e);
    double b_um = c.characteristic_length_um;
    printf("# response of the shipped case: %s, %s, x %.9g .. %.9g\n", r.motion,
           gd_impact_regime_name(r.impact_regime[2]), r.lambda_min_um[0] / b_um, r.lambda_max_um[0] / b_um);
    tap_ok(strcmp(r.motion, "period-1") == 0, "shipped case: motion '%s' (period-1)", r.motion);
    tap_ok(r.impact_regime[2] == GD_IMPACT_SINGLE, "shipped case: impact regime %s (single-sided)",
           gd_impact_regime_name(r.impact_regime[2]));
    TAP_CLOSE(r.lambda_min_um[0] / b_um, lo, 1e-7, "shipped case: min x against the independent steady state");
    TAP_CLOSE(r.lambda_max_um[0] / b_um, hi, 1e-7, "shipped case: max x against the independent steady state");
    pu_samples_free(&p);
    gd_case_free(&c);
    return tap_done();
}
