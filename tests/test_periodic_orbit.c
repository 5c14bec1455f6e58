/* Periodic orbits by Newton shooting and their Floquet multipliers (gd_periodic.h).
 *
 * 1. Linear limit. The Kahraman & Singh oscillator with constant stiffness and an error so small
 *    (F_a = 0.005, amplitude at most F_a / (2 zeta) = 0.05 < F_m = 0.1) that the mesh never
 *    separates is x'' + 2 zeta x' + (x - 1) = F_m - e''(t), e = F_a sin(Omega t + phi): its orbit is
 *    x = 1 + F_m + Im(F_a Omega^2 e^{i(Omega t + phi)} / (1 - Omega^2 + 2 i zeta Omega)) and its
 *    multipliers over n mesh periods are the eigenvalues of exp(A n T), A the Jacobian in contact
 *    (GSL's gsl_linalg_exponential_ss), i.e. exp((-zeta +- i sqrt(1 - zeta^2)) n T). Checked to 1e-8
 *    at speeds through the resonance, by single shooting over one period and by multiple shooting
 *    over two, and along a continuation in Omega from 0.5 to 1.5 (every point).
 * 2. Lyapunov exponent. For a stable impacting orbit the largest exponent of the tangent method
 *    (QR every mesh period, 4000 periods after the transient) times the mesh period equals
 *    ln |mu_max| / n of the orbit's multipliers; the exponent's own error is of order
 *    1 / (record periods), hence the tolerance 1e-3.
 * 3. Convergence: Newton iterations from the settled state and from a state 1e-2 away. */
#include "analysis_util.h"
#include "tap.h"
#include "geardyn/gd_periodic.h"
#include "geardyn/gd_scene.h"

#include <complex.h>
#include <gsl/gsl_linalg.h>
#include <string.h>

static const double zeta = 0.05, Fm = 0.1, Fa = 0.005;

/* the closed-form orbit at t = 0: the state (q, q') with q = x + e */
static void harmonic(const gd_model *m, double Omega, double *y)
{
    const gd_mesh_excitation *x = &m->mesh[0];
    double complex X = x->e_r * Omega * Omega * cexp(I * x->e_phi) / (1.0 - Omega * Omega + 2.0 * I * zeta * Omega);
    double lam = 1.0 + Fm + cimag(X), lamd = cimag(I * Omega * X);
    double e = x->e_m + x->e_r * sin(x->e_phi), ed = x->e_r * Omega * cos(x->e_phi);
    y[0] = lam + e;
    y[1] = lamd + ed;
}

/* max |mu - eig(exp(A nper T))| over the sorted multipliers */
static double multiplier_error(const gd_model *m, const gd_po *po)
{
    gd_error e = {0};
    double J[GD_MAX_STATE * GD_MAX_STATE], y[GD_MAX_STATE], re[GD_MAX_STATE], im[GD_MAX_STATE];
    gd_modes md = {0};
    md.mode[0] = 1;
    harmonic(m, m->Omega, y);
    gd_model_jacobian(m, 0.0, y, J, &md);
    const int n = m->n;
    gsl_matrix *A = gsl_matrix_alloc((size_t)n, (size_t)n), *E = gsl_matrix_alloc((size_t)n, (size_t)n);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            gsl_matrix_set(A, (size_t)i, (size_t)j, J[i * n + j] * po->nper * m->period);
    if (gsl_linalg_exponential_ss(A, E, GSL_PREC_DOUBLE) != 0) {
        printf("Bail out! gsl_linalg_exponential_ss failed\n");
        exit(1);
    }
    double Ed[GD_MAX_STATE * GD_MAX_STATE];
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            Ed[i * n + j] = gsl_matrix_get(E, (size_t)i, (size_t)j);
    if (gd_floquet(Ed, n, re, im, &e) != GD_OK)
        au_die(&e);
    gsl_matrix_free(A);
    gsl_matrix_free(E);
    double d = 0;
    for (int i = 0; i < n; i++)
        d = fmax(d, hypot(po->mu_re[i] - re[i], po->mu_im[i] - im[i]));
    /* and the closed form exp(lambda n T) */
    double complex mu = cexp((-zeta + I * sqrt(1.0 - zeta * zeta)) * po->nper * m->period);
    d = fmax(d, hypot(po->mu_re[0] - creal(mu), fabs(po->mu_im[0]) - fabs(cimag(mu))));
    return d;
}

static void linear_limit(void)
{
    const char *sets[] = {"excitation.ste_phase_deg=90", "solver.rtol=1e-12", "solver.atol=1e-14", NULL};
    const double Om[] = {0.5, 0.9, 1.0, 1.1, 1.5};
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    gd_error e = {0};
    double dy = 0, dmu = 0;
    int iters = 0;
    for (int k = 0; k < 5; k++)
        for (int multi = 0; multi < 2; multi++) {
            au_ks_case(&c, &m, 0.0, zeta, Fm, Fa, Om[k], sets);
            gd_solver_opts_from_case(&c, &o);
            gd_po_opts po;
            gd_po_opts_default(&po);
            po.nper = multi ? 2 : 1;
            po.multiple = multi;
            po.tol = 1e-11;
            double y0[GD_MAX_STATE], yh[GD_MAX_STATE];
            harmonic(&m, m.Omega, yh);
            memcpy(y0, yh, sizeof y0);
            y0[0] += 0.02; /* a guess away from the orbit, still in contact */
            gd_po orbit;
            if (gd_po_solve(&m, &o, &po, y0, &orbit, &e) != GD_OK)
                au_die(&e);
            for (int s = 0; s < orbit.nseg; s++)
                for (int i = 0; i < m.n; i++)
                    dy = fmax(dy, fabs(orbit.y[s][i] - yh[i]));
            dmu = fmax(dmu, multiplier_error(&m, &orbit));
            iters = iters > orbit.iterations ? iters : orbit.iterations;
            gd_case_free(&c);
        }
    printf("# linear limit, 5 speeds x (single, double multiple shooting): at most %d Newton iterations\n", iters);
    TAP_CLOSE(dy, 0.0, 1e-8, "linear limit: max |y_orbit - y_harmonic|");
    TAP_CLOSE(dmu, 0.0, 1e-8, "linear limit: max |mu - eig exp(A n T)|");
    tap_ok(iters <= 3, "linear limit: Newton converges in %d iterations (a linear map: 1, then the check)", iters);

    /* the continuation in Omega through the resonance */
    au_ks_case(&c, &m, 0.0, zeta, Fm, Fa, 0.5, sets);
    gd_solver_opts_from_case(&c, &o);
    gd_cont_opts co;
    gd_cont_opts_default(&co);
    co.po.tol = 1e-11;
    co.p_min = 0.5;
    co.p_max = 1.5;
    co.ds = 0.05;
    co.ds_max = 0.05;
    double yh[GD_MAX_STATE];
    harmonic(&m, m.Omega, yh);
    gd_po start;
    if (gd_po_solve(&m, &o, &co.po, yh, &start, &e) != GD_OK)
        au_die(&e);
    gd_branch br;
    if (gd_continue(gd_model_at_mesh_frequency, &m, &o, &co, &start, &br, &e) != GD_OK)
        au_die(&e);
    dy = dmu = 0;
    double pmax = 0;
    for (int i = 0; i < br.npoints; i++) {
        const gd_po *q = &br.pt[i].orbit;
        gd_model mq;
        gd_model_at_mesh_frequency(q->p, &mq, &m, &e);
        harmonic(&mq, q->p, yh);
        for (int j = 0; j < m.n; j++)
            dy = fmax(dy, fabs(q->y[0][j] - yh[j]));
        dmu = fmax(dmu, multiplier_error(&mq, q));
        pmax = fmax(pmax, q->p);
    }
    printf("# continuation 0.5 -> 1.5: %d points, %ld Newton iterations, %d bifurcations, end: %s\n", br.npoints,
           br.newton_iterations, br.nbif, br.end_reason);
    tap_ok(br.end == GD_END_BOUND && fabs(pmax - 1.5) < 1e-12 && br.nbif == 0,
           "linear continuation ends on the bound Omega 1.5 (%.15g) with no bifurcation (%d)", pmax, br.nbif);
    TAP_CLOSE(dy, 0.0, 1e-8, "linear continuation: max |y - y_harmonic| over the branch");
    TAP_CLOSE(dmu, 0.0, 1e-8, "linear continuation: max |mu - eig exp(A T)| over the branch");
    gd_branch_free(&br);
    gd_case_free(&c);
}

/* the largest Lyapunov exponent of the tangent method from y0, per unit time */
static double lyapunov(const gd_model *m, const gd_solver_opts *o0, const double *y0, int record)
{
    gd_error e = {0};
    gd_solver_opts o = *o0;
    o.n_tangent = 1;
    gd_modes md = {0};
    if (gd_model_consistent_modes(m, 0.0, y0, &md, &e) != GD_OK)
        au_die(&e);
    gd_sim *s;
    if (gd_sim_create(m, &o, y0, &md, &s, &e) != GD_OK)
        au_die(&e);
    gd_sim_lyapunov_start(s);
    for (int p = 0; p < record; p++)
        if (gd_sim_period(s, &e) != GD_OK)
            au_die(&e);
    double ex[GD_MAX_STATE];
    gd_sim_lyapunov(s, ex, NULL);
    gd_sim_free(s);
    return ex[0];
}

static void stable_orbit(const char *name, const gd_case *c, const gd_model *m, int nper)
{
    gd_error e = {0};
    gd_solver_opts o;
    gd_solver_opts_from_case(c, &o);
    double y[GD_MAX_STATE];
    gd_modes md;
    if (gd_initial_state(c, m, y, &md, &e) != GD_OK || gd_sim_period_map(m, &o, y, 300, y, NULL, NULL, &e) != GD_OK)
        au_die(&e);
    gd_po_opts po;
    gd_po_opts_default(&po);
    po.nper = nper;
    gd_po orbit;
    if (gd_po_solve(m, &o, &po, y, &orbit, &e) != GD_OK)
        au_die(&e);
    int it_settled = orbit.iterations;
    double yg[GD_MAX_STATE];
    for (int i = 0; i < m->n; i++)
        yg[i] = orbit.y[0][i] + 1e-2;
    gd_po o2;
    if (gd_po_solve(m, &o, &po, yg, &o2, &e) != GD_OK)
        au_die(&e);
    double dy = 0;
    for (int i = 0; i < m->n; i++)
        dy = fmax(dy, fabs(o2.y[0][i] - orbit.y[0][i]));
    double lam = lyapunov(m, &o, orbit.y[0], 4000);
    printf("# %s: mu_max %.9g (%+.6g %+.6gi), events per period %ld, Newton %d (settled start), %d (1e-2 away)\n",
           name, orbit.mu_max, orbit.mu_re[0], orbit.mu_im[0], orbit.events[0], it_settled, o2.iterations);
    char label[200];
    snprintf(label, sizeof label, "%s: lambda_1 T = ln|mu_max| / n", name);
    TAP_CLOSE(lam * m->period, log(orbit.mu_max) / nper, 1e-3, label);
    tap_ok(orbit.stable && orbit.events[0] > 0, "%s: stable (mu_max %.6g) and impacting (%ld events)", name,
           orbit.mu_max, orbit.events[0]);
    snprintf(label, sizeof label, "%s: the same orbit from a guess 1e-2 away", name);
    TAP_CLOSE(dy, 0.0, 1e-8, label);
}

int main(void)
{
    linear_limit();

    gd_case c;
    gd_model m;
    gd_error e = {0};
    const char *src = getenv("GEARDYN_SOURCE");
    char path[2048];
    snprintf(path, sizeof path, "%s/cases/validation/kahraman-singh.ini", src ? src : ".");
    if (gd_case_init(&c, &e) != GD_OK || gd_case_load(&c, path, &e) != GD_OK || gd_case_resolve(&c, &e) != GD_OK ||
        gd_model_build(&c, &m, &e) != GD_OK)
        au_die(&e);
    stable_orbit("K&S single-sided, Omega 1.2", &c, &m, 1);
    gd_case_free(&c);
    {
        const double Omega = 3.0, A = 4.0;
        double H = Omega * Omega / hypot(1.0 - Omega * Omega, 2.0 * 0.05 * Omega);
        const char *sets[] = {"excitation.ste_phase_deg=90", NULL};
        au_ks_case(&c, &m, 0.0, 0.05, 0.1, A / H, Omega, sets);
        stable_orbit("K&S double-sided, Omega 3", &c, &m, 1);
        gd_case_free(&c);
    }
    return tap_done();
}
