/* Energy conservation across thousands of contacts.
 *
 * Without damping, with constant mesh stiffness and without transmission error, the
 * model is conservative: gd_model_energy (kinetic + linear springs + dead-zone springs
 * - F0.x) is an exact invariant, whatever the contact sequence, because the dead-zone
 * force is continuous. With root finding on, every contact and separation is a located
 * event and the integrator never steps across a kink, so the invariant holds to the
 * integration tolerance over the whole run. With root finding off the contact mode
 * follows the state inside a step and every step across a kink carries an O(h^2) local
 * error the error estimator only partly sees: the drift is much larger. The test asserts
 * both the conservation (1e-8 relative) and the ratio, which is what shows that event
 * location matters. Done for torsional-lr (with a constant load, so F0.x is part of the
 * invariant) and for bta (ten DOF, backlash on both meshes and radial clearance in all
 * four bearings of each half, axial coupling and the groove shafts). */
#include "physics_util.h"
#include "tap.h"

typedef struct erun {
    const gd_model *m;
    double E0, maxdev;
    long nsteps;
} erun;

static int on_step(gd_sim *s, double t0, double t1, void *user)
{
    (void)t0;
    erun *r = user;
    double E = gd_model_energy(r->m, t1, gd_sim_state(s), gd_sim_modes(s));
    r->maxdev = fmax(r->maxdev, fabs(E - r->E0));
    r->nsteps++;
    return 0;
}

/* Run nper periods from (y0, md0); returns the largest |E - E0| / |E0| seen at step ends. */
static double drift(const gd_model *m, const gd_solver_opts *o, const double *y0, const gd_modes *md0, long nper,
                    gd_sim_stats *st)
{
    gd_error e;
    memset(&e, 0, sizeof e);
    gd_sim *s = NULL;
    PU_CHECK(gd_sim_create(m, o, y0, md0, &s, &e), &e);
    erun r = {m, gd_model_energy(m, 0.0, y0, md0), 0.0, 0};
    gd_sim_set_hooks(s, on_step, NULL, &r);
    for (long k = 0; k < nper; k++)
        PU_CHECK(gd_sim_period(s, &e), &e);
    gd_sim_get_stats(s, st);
    gd_sim_free(s);
    return r.maxdev / fabs(r.E0);
}

static void modes_of(const gd_model *m, const double *y, gd_modes *md)
{
    memset(md, 0, sizeof *md);
    for (int c = 0; c < m->nclear; c++) {
        double x, v;
        gd_model_clearance(m, c, 0.0, y, md, &x, &v);
        md->mode[c] = gd_model_mode_of(m, c, x);
    }
}

static void check(const char *label, const gd_model *m, gd_solver_opts *o, const double *y0, long nper,
                  long min_events)
{
    gd_modes md0;
    modes_of(m, y0, &md0);
    gd_sim_stats on, off;
    o->root_finding = 1;
    double d_on = drift(m, o, y0, &md0, nper, &on);
    o->root_finding = 0;
    double d_off = drift(m, o, y0, &md0, nper, &off);
    long contacts = on.events_by_kind[GD_EV_CONTACT] + on.events_by_kind[GD_EV_BACK_CONTACT];
    printf("# %s: E0 = %.12g; %ld events (%ld contacts: mesh ", label, gd_model_energy(m, 0.0, y0, &md0), on.events,
           contacts);
    for (int c = 0; c < m->nclear; c++)
        printf("%s%s %ld", c ? ", " : "", m->clear[c].name, on.events_by_clearance[c]);
    printf(") in %ld mesh periods; steps: events on %ld, off %ld\n", nper, on.steps, off.steps);
    printf("# %s: relative energy drift, root finding on %.3e, off %.3e (ratio %.3g)\n", label, d_on, d_off,
           d_off / d_on);
    char name[200];
    snprintf(name, sizeof name, "%s: thousands of contacts (at least %ld)", label, min_events);
    tap_ok(contacts >= min_events, "%s: %ld", name, contacts);
    snprintf(name, sizeof name, "%s: max |E - E0| / |E0| with event location", label);
    TAP_CLOSE(d_on, 0.0, 1e-8, name);
    snprintf(name, sizeof name, "%s: drift without root finding / drift with it", label);
    tap_ok(d_off > 100.0 * d_on, "%s: %.4g (must exceed 100; %.3e vs %.3e)", name, d_off / d_on, d_off, d_on);
}

int main(void)
{
    /* torsional-lr: two independent halves, load 0.1 (in units of the half backlash), both
     * flanks hit; energy includes -F0.x */
    {
        const char *sets[] = {"scene.model=torsional-lr", "excitation.stiffness=constant", "scene.error_excitation=off",
                              "clearance.backlash_um=10", "solver.characteristic_length_um=5",
                              "damping.mesh_damping_ratio=0", "solver.rtol=1e-12", "solver.atol=1e-14", NULL};
        gd_case c;
        pu_case(&c, sets);
        pu_tune(&c, 0.1, 1.0);
        gd_model m;
        pu_build(&c, &m);
        gd_solver_opts o;
        gd_solver_opts_from_case(&c, &o);
        double y0[GD_MAX_STATE] = {0.0, 0.3, 1.7, -1.1};
        check("torsional-lr", &m, &o, y0, 1000, 2000);
        gd_case_free(&c);
    }
    /* bta: no load, the pair rattles in the backlash and the bodies in their bearings */
    {
        const char *sets[] = {"scene.model=bta", "excitation.stiffness=constant", "scene.error_excitation=off",
                              "scene.bearing_clearance=on", "scene.axial_coupling=on", "clearance.backlash_um=10",
                              "clearance.bearing_clearance_um=5", "damping.mesh_damping_ratio=0",
                              "damping.support_damping_ratio=0", "damping.shaft_damping_ratio=0",
                              "solver.rtol=1e-12", "solver.atol=1e-14", NULL};
        gd_case c;
        pu_case(&c, sets);
        pu_tune(&c, 0.0, 1.0);
        gd_model m;
        pu_build(&c, &m);
        gd_solver_opts o;
        gd_solver_opts_from_case(&c, &o);
        double y0[GD_MAX_STATE] = {0};
        /* velocities: y1 z1 y2 z2 q of each half */
        const double v[10] = {0.8, 0.2, -0.5, -0.1, 2.0, -0.6, 0.1, 0.4, 0.05, -1.5};
        for (int i = 0; i < 10; i++)
            y0[10 + i] = v[i];
        y0[0] = 0.5;  /* y1L inside its clearance */
        y0[9] = -1.0; /* qR */
        check("bta", &m, &o, y0, 300, 2000);
        gd_case_free(&c);
    }
    return tap_done();
}
