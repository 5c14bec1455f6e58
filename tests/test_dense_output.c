/* The dense output of gear models (gd_sim_dense, docs/numerics.md section 9): the quintic
 * Hermite of the positions through both ends of the step, with the velocities its derivative.
 *
 * A run of the bta model with a fixed-step 8th-order ERK is sampled 64 times per mesh period
 * inside its steps, and the samples are compared with a reference whose steps end on the sample
 * times (rtol 1e-13: its samples are the method's states). The method's own error is O(h^8),
 * so the sample error is the interpolation error: it must fall with the order of the
 * interpolant, at least 4.6 for the quintic (O(h^5) in the velocities, O(h^6) in the
 * positions) and about 4 for ARKODE's cubic Hermite, and the quintic must be at least ten times
 * more accurate than the cubic at the same steps. Both read the same steps, so the comparison
 * is of the interpolants alone. */
#include "physics_util.h"
#include "tap.h"

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

int main(void)
{
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
        printf("# %3d steps per period: sample error quintic %.3e, ARKODE cubic %.3e\n", steps[r], eq[r], ec[r]);
        pu_samples_free(&pq);
        pu_samples_free(&pc);
    }
    double oq = log2(eq[1] / eq[2]), oc = log2(ec[1] / ec[2]);
    printf("# observed order (48 -> 96 steps): quintic %.2f, cubic %.2f\n", oq, oc);
    tap_ok(oq >= 4.6, "the quintic's sample error falls with order >= 4.6 (measured %.2f)", oq);
    tap_ok(oc > 3.5 && oc < 4.5, "ARKODE's cubic Hermite falls with order about 4 (measured %.2f)", oc);
    int better = 1;
    for (int r = 0; r < 3; r++)
        better &= eq[r] * 10 <= ec[r];
    tap_ok(better, "the quintic is at least 10x more accurate than the cubic at every step size (%.1fx, %.1fx, %.1fx)",
           ec[0] / eq[0], ec[1] / eq[1], ec[2] / eq[2]);
    pu_samples_free(&ref);
    gd_case_free(&c);
    return tap_done();
}
