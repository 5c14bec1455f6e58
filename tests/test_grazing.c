/* A touch inside one step is not missed: the near-grazing watch.
 *
 * Torsional model, constant stiffness, no damping, no error. In the backlash gap the
 * motion is a parabola x(t) = x0 + v0 t + a t^2/2 (a = static deflection, from the
 * load). Starting mid-gap with v0 < 0 chosen so that the apex dips delta below the back
 * flank -h, the true solution enters back-side contact at
 *   t1 = (-v0 - sqrt(v0^2 - 2 a (x0 + h))) / a
 * and leaves it a short time later. An RK method integrates the parabola exactly, so its
 * error control takes steps far longer than the dip and both ends of the step lie in the
 * gap: without the watch the touch is missed silently. With it the step is redone and the
 * contact is located at t1. */
#include "geardyn/geardyn.h"
#include "tap.h"

typedef struct hits { int n; double t[16]; int kind[16]; } hits;

static int on_event(gd_sim *s, const gd_event *ev, void *user)
{
    hits *h = user;
    if (h->n < 16) {
        h->t[h->n] = ev->t;
        h->kind[h->n] = ev->kind;
    }
    h->n++;
    return 0;
}

static int run(int watch, double delta, hits *h, double *t1, double *period)
{
    gd_case c;
    gd_error err = {0};
    gd_case_init(&c, &err);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    const char *sets[] = {"scene.model=torsional", "excitation.stiffness=constant", "scene.error_excitation=off",
                          "damping.mesh_damping_ratio=0", "clearance.backlash_um=20",
                          "solver.characteristic_length_um=1", "solver.rtol=1e-6", "solver.atol=1e-9",
                          "solver.max_step_fraction=1"};
    for (int i = 0; i < 9; i++)
        gd_case_set(&c, sets[i], i, &err);
    gd_case_resolve(&c, &err);
    gd_model m;
    gd_model_build(&c, &m, &err);
    /* load giving a dimensionless static deflection (= acceleration in the gap) of 1 */
    double a_now = m.F0[0] / m.mass[0];
    c.torque_nm *= 1.0 / a_now;
    gd_model_build(&c, &m, &err);
    double a = m.F0[0] / m.mass[0], h0 = m.clear[0].h, x0 = 0.0;
    double v0 = -sqrt(2.0 * a * (x0 + h0 + delta));
    *t1 = (-v0 - sqrt(v0 * v0 - 2.0 * a * (x0 + h0))) / a;
    *period = m.period;
    gd_solver_opts o;
    gd_solver_opts_from_case(&c, &o);
    o.grazing_watch = watch;
    double y[GD_MAX_STATE] = {x0, v0};
    gd_modes md = {0};
    gd_sim *s;
    if (gd_sim_create(&m, &o, y, &md, &s, &err) != GD_OK)
        return -1;
    h->n = 0;
    gd_sim_set_hooks(s, NULL, on_event, h);
    gd_status st = gd_sim_advance_to(s, 2.0 * (*t1), &err);
    gd_sim_stats stats;
    gd_sim_get_stats(s, &stats);
    printf("# watch %s: %d events, %ld steps, %ld rewinds\n", watch ? "on" : "off", h->n, stats.steps,
           stats.grazing_rewinds);
    gd_sim_free(s);
    gd_case_free(&c);
    return st == GD_OK ? 0 : -1;
}

int main(void)
{
    double t1, T;
    hits on, off;
    int rc1 = run(1, 1e-4, &on, &t1, &T);
    int rc0 = run(0, 1e-4, &off, &t1, &T);
    tap_ok(rc1 == 0 && rc0 == 0, "both runs complete");
    tap_ok(off.n == 0, "without the watch the touch is missed (%d events): the scenario really is a hidden graze",
           off.n);
    tap_ok(on.n == 2, "with the watch the touch is found: %d events (back-contact, back-separation)", on.n);
    if (on.n >= 2) {
        tap_ok(on.kind[0] == GD_EV_BACK_CONTACT && on.kind[1] == GD_EV_BACK_SEPARATION, "kinds %s then %s",
               gd_event_kind_name(on.kind[0]), gd_event_kind_name(on.kind[1]));
        TAP_CLOSE(on.t[0] / T, t1 / T, 1e-9, "contact time (mesh periods) against the closed form");
        tap_ok(on.t[1] > on.t[0], "separation after contact (dwell %.3g periods)", (on.t[1] - on.t[0]) / T);
    }
    return tap_done();
}
