/* The dense output of gear models (gd_sim_dense, docs/numerics.md section 9): the septic
 * Hermite of the positions through both ends of the step (value, rate, acceleration and jerk at
 * each end), with the velocities its derivative.
 *
 * Its ingredient gd_model_jerk is checked first against a central difference of the RHS along
 * the motion, (f(t + d, y + d f) - f(t - d, y - d f)) / 2d, in every contact mode of the mesh and
 * with harmonic and rectangular stiffness (the rectangular factor is constant between its edges).
 *
 * A run of the bta model with a fixed-step 8th-order ERK is sampled 64 times per mesh period
 * inside its steps, and the samples are compared with a reference whose steps end on the sample
 * times (rtol 1e-13: its samples are the method's states). The method's own error is O(h^8),
 * so the sample error is the interpolation error: it must fall with the order of the
 * interpolant, at least 6.5 for the septic (O(h^7) in the velocities, O(h^8) in the
 * positions; the quintic it replaced measured 5.25) and about 4 for ARKODE's cubic Hermite, and
 * the septic must be at least 500 times more accurate than the cubic at the same steps (the
 * quintic: 20 to 97 times). Both read the same steps, so the comparison
 * is of the interpolants alone. */
#include "physics_util.h"
#include "tap.h"
#include "geardyn/gd_scene.h"

#define NS 64     /* samples per mesh period */
#define P0 2      /* recorded periods [P0, P1) */
#define P1 4

static const char *const scene[] = {
    "scene.model=bta", "operating.speed_rpm=7000", "operating.torque_nm=500", "clearance.backlash_um=10",
    "clearance.bearing_clearance_um=5", "excitation.ste_amplitude_um=3", NULL};

/* the samples of periods [P0, P1) of one run; exact: steps end on the sample times */
static void run(const gd_model *m, const gd_solver_opts *o, const double *y0, const gd_modes *md, int exact,
                pu_samples *p)
{
    pu_run_sampled_ex(m, o, y0, md, P1, P0, NS, exact, p, NULL);
}

/* largest error of the samples, each variable relative to its largest magnitude in the reference */
static double sample_error(const pu_samples *a, const pu_samples *ref)
{
    int n = ref->n;
    double err = 0;
    for (int i = 0; i < n; i++) {
        double scale = 0;
        for (long k = 0; k < ref->count; k++)
            scale = fmax(scale, fabs(ref->y[k * n + i]));
        if (scale == 0)
            continue;
        for (long k = 0; k < ref->count; k++)
            err = fmax(err, fabs(a->y[k * n + i] - ref->y[k * n + i]) / scale);
    }
    return err;
}

/* largest difference between gd_model_jerk and the central difference of the RHS along the motion
 * at (t, y) with the modes md, relative to the largest jerk */
static double jerk_error(const gd_model *m, double t, const double *y, const gd_modes *md, double *jmax)
{
    const int n = m->n, nd = m->ndof;
    double f[GD_MAX_STATE], fp[GD_MAX_STATE], fm[GD_MAX_STATE], yp[GD_MAX_STATE], ym[GD_MAX_STATE], j[GD_MAX_DOF];
    gd_model_rhs(m, t, y, f, md);
    if (gd_model_jerk(m, t, y, f + nd, j, md) != 0)
        return INFINITY;
    const double d = 1e-4 * m->period;
    for (int i = 0; i < n; i++) {
        yp[i] = y[i] + d * f[i];
        ym[i] = y[i] - d * f[i];
    }
    gd_model_rhs(m, t + d, yp, fp, md);
    gd_model_rhs(m, t - d, ym, fm, md);
    double err = 0, big = 0;
    for (int i = 0; i < nd; i++) {
        big = fmax(big, fabs(j[i]));
        err = fmax(err, fabs(j[i] - (fp[nd + i] - fm[nd + i]) / (2 * d)));
    }
    *jmax = big;
    return big > 0 ? err / big : INFINITY;
}

static void check_jerk(const char *label, const char *const *sets)
{
    gd_case c;
    pu_case(&c, sets);
    gd_model m;
    pu_build(&c, &m);
    gd_error e;
    memset(&e, 0, sizeof e);
    double y[GD_MAX_STATE];
    gd_modes md;
    PU_CHECK(gd_model_static_state(&m, y, &md, &e), &e);
    for (int i = 0; i < m.ndof; i++) /* a motion: every velocity nonzero */
        y[m.ndof + i] = 0.3 * sin(1.0 + i);
    const int c0 = m.mesh_clear[0];
    double worst = 0, jmax = 0;
    for (int mode = -1; mode <= 1; mode++) {
        md.mode[c0] = mode;
        for (int k = 0; k < 4; k++) {
            double jm = 0, r = jerk_error(&m, (0.1 + 0.2 * k) * m.period, y, &md, &jm);
            worst = fmax(worst, r);
            jmax = fmax(jmax, jm);
        }
    }
    tap_ok(worst < 1e-6 && jmax > 0, "%s: the jerk equals the central difference of the RHS along the motion in every "
           "mesh mode (largest relative difference %.1e)", label, worst);
    gd_case_free(&c);
}

int main(void)
{
    const char *const harm[] = {"scene.model=bta", "operating.speed_rpm=3000", "excitation.ste_amplitude_um=5",
                                "damping.mesh_damping_ratio=0.05", NULL};
    const char *const rect[] = {"scene.model=torsional", "operating.speed_rpm=3000", "excitation.stiffness=rectangular",
                                NULL};
    check_jerk("bta, harmonic stiffness", harm);
    check_jerk("torsional, rectangular stiffness", rect);

    gd_case c;
    pu_case(&c, scene);
    gd_model m;
    pu_build(&c, &m);
    gd_error e;
    memset(&e, 0, sizeof e);
    double y0[GD_MAX_STATE];
    gd_modes md;
    PU_CHECK(gd_model_static_state(&m, y0, &md, &e), &e);

    gd_solver_opts o;
    gd_solver_opts_from_case(&c, &o);
    o.order = 8;
    o.rtol = 1e-13;
    o.atol = 1e-15;
    pu_samples ref;
    run(&m, &o, y0, &md, 1, &ref);

    const int steps[] = {24, 48, 96};
    double eq[3], ec[3];
    for (int r = 0; r < 3; r++) {
        gd_solver_opts f = o;
        f.fixed_step = 1;
        f.steps_per_period = steps[r];
        pu_samples pq, pc;
        f.arkode_dense = 0;
        run(&m, &f, y0, &md, 0, &pq);
        f.arkode_dense = 1;
        run(&m, &f, y0, &md, 0, &pc);
        eq[r] = sample_error(&pq, &ref);
        ec[r] = sample_error(&pc, &ref);
        printf("# %3d steps per period: sample error septic %.3e, ARKODE cubic %.3e\n", steps[r], eq[r], ec[r]);
        pu_samples_free(&pq);
        pu_samples_free(&pc);
    }
    double oq = log2(eq[1] / eq[2]), oc = log2(ec[1] / ec[2]);
    printf("# observed order (48 -> 96 steps): septic %.2f, cubic %.2f\n", oq, oc);
    tap_ok(oq >= 6.5, "the septic's sample error falls with order >= 6.5 (measured %.2f)", oq);
    tap_ok(oc > 3.5 && oc < 4.5, "ARKODE's cubic Hermite falls with order about 4 (measured %.2f)", oc);
    int better = 1;
    for (int r = 0; r < 3; r++)
        better &= eq[r] * 500 <= ec[r];
    tap_ok(better, "the septic is at least 500x more accurate than the cubic at every step size (%.1fx, %.1fx, %.1fx)",
           ec[0] / eq[0], ec[1] / eq[1], ec[2] / eq[2]);
    pu_samples_free(&ref);
    gd_case_free(&c);
    return tap_done();
}
