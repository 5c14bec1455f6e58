/* Lyapunov exponents: closed forms, the Lorenz system, Liouville's identity, a stable
 * periodic gear response, the two methods on a chaotic gear response, and the exponent
 * of the stroboscopic map against the Floquet multipliers found by finite differences. */
#include "analysis_util.h"
#include "tap.h"
#include "geardyn/gd_scene.h"

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_complex_math.h>
#include <string.h>

/* run a sim: transient periods, then k exponents over `record` periods; trace average too */
typedef struct trace_acc { const gd_model *m; double sum, time; } trace_acc;

static int trace_hook(gd_sim *s, double t0, double t1, void *user)
{
    trace_acc *a = user;
    const gd_model *m = a->m;
    double J[GD_MAX_STATE * GD_MAX_STATE];
    /* modes are constant inside a step (they flip only at located roots, which end steps) */
    gd_model_jacobian(m, t0, gd_sim_state(s), J, gd_sim_modes(s));
    double tr = 0;
    for (int i = 0; i < m->n; i++)
        tr += J[i * m->n + i];
    a->sum += tr * (t1 - t0);
    a->time += t1 - t0;
    return 0;
}

static int exponents(const gd_case *c, const gd_model *m, int k, int transient, int record, double *ex,
                     trace_acc *tr)
{
    gd_error e = {0};
    gd_solver_opts o;
    gd_solver_opts_from_case(c, &o);
    o.n_tangent = k;
    double y[GD_MAX_STATE];
    gd_modes md;
    if (gd_initial_state(c, m, y, &md, &e) != GD_OK)
        au_die(&e);
    gd_sim *s;
    if (gd_sim_create(m, &o, y, &md, &s, &e) != GD_OK)
        au_die(&e);
    for (int p = 0; p < transient; p++)
        if (gd_sim_period(s, &e) != GD_OK)
            au_die(&e);
    gd_sim_lyapunov_start(s);
    if (tr) {
        tr->m = m;
        gd_sim_set_hooks(s, trace_hook, NULL, tr);
    }
    for (int p = 0; p < record; p++)
        if (gd_sim_period(s, &e) != GD_OK)
            au_die(&e);
    int n = gd_sim_lyapunov(s, ex, NULL);
    gd_sim_free(s);
    return n;
}

static void lorenz(double t, const double *y, double *f, void *ctx)
{
    f[0] = 10.0 * (y[1] - y[0]);
    f[1] = y[0] * (28.0 - y[2]) - y[1];
    f[2] = y[0] * y[1] - 8.0 / 3.0 * y[2];
}

static void lorenz_tangent(double t, const double *y, const double *v, double *o, void *ctx)
{
    o[0] = 10.0 * (v[1] - v[0]);
    o[1] = (28.0 - y[2]) * v[0] - v[1] - y[0] * v[2];
    o[2] = y[1] * v[0] + y[0] * v[1] - 8.0 / 3.0 * v[2];
}

int main(void)
{
    gd_case c;
    gd_model m;
    double ex[GD_MAX_STATE];
    const char *linear[] = {"scene.error_excitation=off", "solver.rtol=1e-10", "solver.atol=1e-12", NULL};

    /* 1. linear oscillator x'' + 2 zeta x' + x = F (no clearance reached): eigenvalues
     *    -zeta +- i sqrt(1 - zeta^2) (both exponents -zeta), or real -zeta +- sqrt(zeta^2 - 1) */
    au_ks_case(&c, &m, 0.0, 0.05, 50.0, 0.0, 1.3, linear);
    exponents(&c, &m, 2, 5, 200, ex, NULL);
    TAP_CLOSE(ex[0], -0.05, 2e-4, "underdamped oscillator: lambda_1 = -zeta");
    TAP_CLOSE(ex[1], -0.05, 2e-4, "underdamped oscillator: lambda_2 = -zeta");
    gd_case_free(&c);
    au_ks_case(&c, &m, 0.0, 2.0, 50.0, 0.0, 1.3, linear);
    exponents(&c, &m, 2, 5, 100, ex, NULL);
    TAP_REL(ex[0], -2.0 + sqrt(3.0), 1e-5, "overdamped oscillator: lambda_1 = -zeta + sqrt(zeta^2 - 1)");
    TAP_REL(ex[1], -2.0 - sqrt(3.0), 1e-5, "overdamped oscillator: lambda_2 = -zeta - sqrt(zeta^2 - 1)");
    gd_case_free(&c);

    /* 2. Lorenz (sigma 10, rho 28, beta 8/3): largest exponent 0.9056 (Sprott 2003) */
    {
        gd_custom_system sys = {3, lorenz, lorenz_tangent, NULL, NULL};
        gd_model lm;
        gd_model_custom(&lm, &sys, 1.0);
        gd_solver_opts o;
        memset(&o, 0, sizeof o);
        o.method = GD_METHOD_ERK;
        o.order = 5;
        o.rtol = 1e-9;
        o.atol = 1e-10;
        o.max_step_fraction = 1.0;
        o.max_events_per_period = 10;
        o.max_separated_periods = 10;
        o.n_tangent = 3;
        double y0[3] = {1.0, 1.0, 20.0};
        gd_modes md = {0};
        gd_sim *s;
        gd_error e = {0};
        if (gd_sim_create(&lm, &o, y0, &md, &s, &e) != GD_OK)
            au_die(&e);
        for (int p = 0; p < 50; p++)
            gd_sim_period(s, &e);
        gd_sim_lyapunov_start(s);
        for (int p = 0; p < 2000; p++)
            if (gd_sim_period(s, &e) != GD_OK)
                au_die(&e);
        gd_sim_lyapunov(s, ex, NULL);
        gd_sim_free(s);
        TAP_CLOSE(ex[0], 0.9056, 0.01, "Lorenz: largest exponent");
        TAP_CLOSE(ex[1], 0.0, 0.01, "Lorenz: second exponent (the flow direction)");
        TAP_REL(ex[0] + ex[1] + ex[2], -(10.0 + 1.0 + 8.0 / 3.0), 1e-6, "Lorenz: sum = trace = -(sigma + 1 + beta)");
    }

    /* 3. Liouville: the sum of all exponents equals the time average of the Jacobian trace,
     *    on a chaotic gear response with damping acting only in contact (the trace switches at
     *    every contact event and the vector field jumps there: saltation in play) */
    {
        const char *extra[] = {"scene.model=torsional-lr", "damping.mesh_damping_mode=contact",
                               "excitation.half_phase_deg=30", NULL};
        au_ks_case(&c, &m, 0.2, 0.05, 0.1, 0.2, 1.5, extra);
        trace_acc tr = {0};
        int k = exponents(&c, &m, m.n, 100, 200, ex, &tr);
        double sum = 0;
        for (int i = 0; i < k; i++)
            sum += ex[i];
        TAP_REL(sum, tr.sum / tr.time, 1e-6, "gear, contact damping: sum of the 4 exponents = mean Jacobian trace");
        tap_ok(ex[0] > 0.01, "that response is chaotic: lambda_1 = %.4g per unit time", ex[0]);
        gd_case_free(&c);
    }

    /* 4. a stable periodic gear response has a negative largest exponent; 5. on a chaotic
     *    one the tangent and two-trajectory methods agree within 0.02 per mesh period */
    {
        gd_response_result r1, r2;
        gd_error e = {0};
        const char *tan[] = {"run.transient_periods=200", "run.record_periods=300", NULL};
        au_ks_case(&c, &m, 0.2, 0.05, 0.1, 0.2, 0.6, tan);
        if (gd_response_run(&c, &m, NULL, NULL, NULL, &r1, &e) != GD_OK)
            au_die(&e);
        tap_ok(strcmp(r1.motion, "period-1") == 0 && r1.mle_per_period < -0.05,
               "periodic gear response (%s): largest exponent %.4g per mesh period < 0", r1.motion, r1.mle_per_period);
        gd_case_free(&c);
        /* both methods along one and the same trajectory: the reference carries a tangent
         * vector, the companion starts 1e-8 away and is pulled back every period */
        au_ks_case(&c, &m, 0.2, 0.05, 0.1, 0.2, 1.5, tan);
        gd_solver_opts o;
        gd_solver_opts_from_case(&c, &o);
        double y[GD_MAX_STATE], y2[GD_MAX_STATE];
        gd_modes md, md2;
        gd_initial_state(&c, &m, y, &md, &e);
        o.n_tangent = 1;
        gd_sim *s1, *s2;
        if (gd_sim_create(&m, &o, y, &md, &s1, &e) != GD_OK)
            au_die(&e);
        const double d0 = 1e-6; /* well above the integration error of each trajectory (rtol 1e-8) */
        memcpy(y2, y, sizeof y2);
        y2[0] += d0;
        md2 = md;
        gd_model_consistent_modes(&m, 0.0, y2, &md2, &e);
        o.n_tangent = 0;
        if (gd_sim_create(&m, &o, y2, &md2, &s2, &e) != GD_OK)
            au_die(&e);
        double lsum = 0;
        int nrec = 2000;
        for (int p = 0; p < 200 + nrec; p++) {
            if (p == 200)
                gd_sim_lyapunov_start(s1);
            if (gd_sim_period(s1, &e) != GD_OK || gd_sim_period(s2, &e) != GD_OK)
                au_die(&e);
            const double *a = gd_sim_state(s1), *b = gd_sim_state(s2);
            double d = 0;
            for (int i = 0; i < m.n; i++)
                d += (b[i] - a[i]) * (b[i] - a[i]);
            d = sqrt(d);
            if (p >= 200)
                lsum += log(d / d0);
            for (int i = 0; i < m.n; i++)
                y2[i] = a[i] + (b[i] - a[i]) * d0 / d;
            if (gd_sim_set_state(s2, y2, &e) != GD_OK)
                au_die(&e);
        }
        gd_sim_lyapunov(s1, ex, NULL);
        double tangent = ex[0] * m.period, benettin = lsum / nrec;
        gd_sim_free(s1);
        gd_sim_free(s2);
        TAP_CLOSE(benettin, tangent, 2e-3, "chaotic gear response, one trajectory: two-trajectory vs tangent exponent "
                  "(per mesh period)");
        tap_ok(tangent > 0.1, "that response is chaotic (%.4g per mesh period)", tangent);
        gd_case_free(&c);
        /* and the response analysis with either method, each on its own trajectory */
        const char *two[] = {"run.transient_periods=200", "run.record_periods=3000",
                             "run.lyapunov_method=two-trajectory", NULL};
        au_ks_case(&c, &m, 0.2, 0.05, 0.1, 0.2, 1.5, two);
        if (gd_response_run(&c, &m, NULL, NULL, NULL, &r2, &e) != GD_OK)
            au_die(&e);
        gd_case_free(&c);
        au_ks_case(&c, &m, 0.2, 0.05, 0.1, 0.2, 1.5, two);
        au_set(&c, "run.lyapunov_method=tangent");
        if (gd_response_run(&c, &m, NULL, NULL, NULL, &r1, &e) != GD_OK)
            au_die(&e);
        TAP_CLOSE(r2.mle_per_period, r1.mle_per_period, 0.05,
                  "chaotic gear response, separate trajectories of 3000 periods: the two methods (per mesh period)");
        tap_ok(strcmp(r1.motion, "chaotic") == 0 && strcmp(r2.motion, "chaotic") == 0, "both classify it chaotic");
        gd_case_free(&c);
    }

    /* 6. the exponent of the stroboscopic map is the flow exponent times the period: on a
     *    period-1 orbit with impacts, log|mu_max| of the monodromy matrix (central finite
     *    differences of the one-period map, eigenvalues by GSL) against lambda_1 T */
    {
        const char *ex6[] = {"solver.rtol=1e-11", "solver.atol=1e-13", NULL};
        au_ks_case(&c, &m, 0.2, 0.05, 0.1, 0.2, 0.6, ex6);
        gd_error e = {0};
        gd_solver_opts o;
        gd_solver_opts_from_case(&c, &o);
        double y[GD_MAX_STATE], yp[GD_MAX_STATE];
        gd_modes md;
        gd_initial_state(&c, &m, y, &md, &e);
        gd_sim *s;
        o.n_tangent = 1;
        gd_sim_create(&m, &o, y, &md, &s, &e);
        for (int p = 0; p < 400; p++)
            gd_sim_period(s, &e);
        memcpy(y, gd_sim_state(s), sizeof(double) * (size_t)m.n);
        gd_modes mfix = *gd_sim_modes(s);
        gd_sim_lyapunov_start(s);
        for (int p = 0; p < 400; p++)
            gd_sim_period(s, &e);
        gd_sim_lyapunov(s, ex, NULL);
        gd_sim_free(s);
        o.n_tangent = 0;
        int n = m.n;
        gsl_matrix *DP = gsl_matrix_alloc((size_t)n, (size_t)n);
        double h = 1e-6;
        for (int j = 0; j < n; j++) {
            double col[2][GD_MAX_STATE];
            for (int sg = 0; sg < 2; sg++) {
                memcpy(yp, y, sizeof yp);
                yp[j] += sg ? -h : h;
                gd_modes mj = mfix;
                gd_model_consistent_modes(&m, 0.0, yp, &mj, &e);
                gd_sim_create(&m, &o, yp, &mj, &s, &e);
                gd_sim_period(s, &e);
                memcpy(col[sg], gd_sim_state(s), sizeof(double) * (size_t)n);
                gd_sim_free(s);
            }
            for (int i = 0; i < n; i++)
                gsl_matrix_set(DP, (size_t)i, (size_t)j, (col[0][i] - col[1][i]) / (2 * h));
        }
        gsl_vector_complex *ev = gsl_vector_complex_alloc((size_t)n);
        gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc((size_t)n);
        int rc = gsl_eigen_nonsymm(DP, ev, w);
        double mu = 0;
        for (int i = 0; i < n; i++)
            mu = fmax(mu, gsl_complex_abs(gsl_vector_complex_get(ev, (size_t)i)));
        tap_ok(rc == 0, "gsl_eigen_nonsymm of the monodromy matrix");
        TAP_CLOSE(log(mu), ex[0] * m.period, 2e-3, "stroboscopic map exponent log|mu_max| = lambda_1 T");
        gsl_eigen_nonsymm_free(w);
        gsl_vector_complex_free(ev);
        gsl_matrix_free(DP);
        gd_case_free(&c);
    }
    return tap_done();
}
