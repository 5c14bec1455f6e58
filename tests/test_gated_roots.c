/* Gated root finding (docs/numerics.md section 3): ARKODE is given the root functions only to
 * locate a crossing that geardyn's check of their signs at a step end found, instead of checking
 * them at every step itself. The physics must not change: the same events, located at the same
 * times, and the same trajectory, on scenes that stress the event engine — a light-load rattle
 * across the backlash and every bearing clearance (about 24 events per mesh period, the two halves
 * crossing together), a loaded impacting mesh, the torsional model's double-sided impacts, and
 * zero backlash and zero bearing clearance (both root functions of a clearance are then one
 * surface). A crossing the gate failed to report, or reported late, would show as a missing event
 * or as an event time off by a fraction of a step (1e-3 to 1e-1 here); rounding moves them by
 * about 1e-12. */
#include "physics_util.h"
#include "tap.h"
#include "geardyn/gd_scene.h"

#define MAXEV 20000

typedef struct {
    long n;
    double t[MAXEV];
    int key[MAXEV]; /* clearance, old and new mode */
} evlist;

static int on_event(gd_sim *s, const gd_event *e, void *user)
{
    (void)s;
    evlist *l = user;
    if (l->n < MAXEV) {
        l->t[l->n] = e->t;
        l->key[l->n] = 100 * e->clearance + 10 * (e->old_mode + 1) + (e->new_mode + 1);
    }
    l->n++;
    return 0;
}

static void run(const gd_model *m, const gd_case *c, int gated, int periods, evlist *l, double *y, long *steps,
                long *located)
{
    gd_error err = {0};
    double y0[GD_MAX_STATE];
    gd_modes md;
    PU_CHECK(gd_model_static_state(m, y0, &md, &err), &err);
    gd_solver_opts o;
    gd_solver_opts_from_case(c, &o);
    o.rtol = 1e-10;
    o.ungated_roots = !gated;
    gd_sim *s;
    PU_CHECK(gd_sim_create(m, &o, y0, &md, &s, &err), &err);
    l->n = 0;
    gd_sim_set_hooks(s, NULL, on_event, l);
    for (int p = 0; p < periods; p++)
        PU_CHECK(gd_sim_period(s, &err), &err);
    memcpy(y, gd_sim_state(s), sizeof(double) * (size_t)m->n);
    gd_sim_stats st;
    gd_sim_get_stats(s, &st);
    *steps = st.steps;
    *located = st.events;
    gd_sim_free(s);
}

static void scene(const char *name, const char *const *sets, int periods)
{
    static evlist a, b;
    gd_case c;
    gd_model m;
    pu_case(&c, sets);
    pu_build(&c, &m);
    double ya[GD_MAX_STATE], yb[GD_MAX_STATE];
    long sa, sb, ea, eb;
    run(&m, &c, 1, periods, &a, ya, &sa, &ea);
    run(&m, &c, 0, periods, &b, yb, &sb, &eb);
    int same_n = a.n == b.n && a.n <= MAXEV;
    /* events at equal times (the two halves) may come in either order: compare each event with
     * the nearest one of the same clearance and modes in the other run */
    double dt = 0.0;
    int unmatched = 0;
    for (long i = 0; same_n && i < a.n; i++) {
        double best = INFINITY;
        for (long j = i > 8 ? i - 8 : 0; j < b.n && j <= i + 8; j++)
            if (b.key[j] == a.key[i])
                best = fmin(best, fabs(a.t[i] - b.t[j]));
        if (!isfinite(best))
            unmatched++;
        else
            dt = fmax(dt, best / m.period);
    }
    tap_ok(same_n && unmatched == 0 && dt <= 1e-9,
           "%s, %d periods: gated and ungated root finding find the same %ld events (%ld) at the same times "
           "(largest difference %.3g mesh periods, tol 1e-9; %d unmatched)",
           name, periods, a.n, b.n, dt, unmatched);
    double d = 0, sc = 0;
    for (int i = 0; i < m.n; i++)
        d = fmax(d, fabs(ya[i] - yb[i])), sc = fmax(sc, fabs(yb[i]));
    tap_ok(d <= 1e-8 * sc, "%s: the same final state (largest difference %.3g of the largest component, tol 1e-8); "
                           "steps gated %ld, ungated %ld",
           name, d / sc, sa, sb);
    gd_case_free(&c);
}

int main(void)
{
    const char *rattle[] = {"scene.model=bta", "operating.speed_rpm=4000", "operating.torque_nm=10",
                            "clearance.backlash_um=10", "clearance.bearing_clearance_um=5",
                            "excitation.stiffness_harmonics=0.1", "excitation.ste_amplitude_um=10", NULL};
    scene("bta rattle, 4000 rpm, 10 N m", rattle, 20);
    const char *loaded[] = {"scene.model=bta", "operating.speed_rpm=4000", "operating.torque_nm=500",
                            "clearance.backlash_um=10", "clearance.bearing_clearance_um=5",
                            "excitation.ste_amplitude_um=10", NULL};
    scene("bta loaded, 4000 rpm, 500 N m", loaded, 20);
    const char *tors[] = {"scene.model=torsional", "operating.speed_rpm=4000", "operating.torque_nm=50",
                          "clearance.backlash_um=10", "excitation.ste_amplitude_um=20", NULL};
    scene("torsional, double-sided impacts", tors, 40);
    const char *zero[] = {"scene.model=bta", "operating.speed_rpm=3000", "operating.torque_nm=30",
                          "clearance.backlash_um=0", "clearance.bearing_clearance_um=0",
                          "excitation.ste_amplitude_um=20", NULL};
    scene("bta, zero backlash and bearing clearance", zero, 20);
    return tap_done();
}
