/* The right-hand side compiled for the held contact modes (src/dynamics/rhs_plan.h), which the
 * integrator evaluates at every stage, against the model's own general evaluation
 * (gd_model_rhs, gd_model_tangent): the same function written twice in different orders of the
 * floating-point operations, so they must agree to rounding, in every combination of contact
 * modes, with the mesh-in impact pulse on and off, with damping that acts always or only in
 * contact, with harmonic, tabulated, rectangular and constant stiffness, with a tabulated error
 * (excitation.ste = ltca), for every model size (bta 10, torsional-lr 2, torsional 1 degrees of freedom: the
 * sizes compiled with a constant) and for a hand-built five-degree-of-freedom model (the
 * general size). A wrong sign or a missing term (a bearing contact's offset, the mesh damping of
 * an open mesh, the pulse, the mass scaling) shows as a difference of the order of the term,
 * some 1e-3 to 1 of the accelerations; rounding is about 1e-15.
 *
 * Then whole runs: the integrator with the compiled RHS and with the general one, same case,
 * must end in the same state to the tolerance's order and see the same events. */
#include "physics_util.h"
#include "dynamics/rhs_plan.h"
#include "tap.h"
#include "geardyn/gd_scene.h"

#include <gsl/gsl_rng.h>

#define TOL 1e-13 /* relative to the largest acceleration */

static double rnd(gsl_rng *r, double a) { return a * (2.0 * gsl_rng_uniform(r) - 1.0); }

/* largest difference of plan and general RHS and tangent over every mode combination, relative */
static void compare(const char *name, const gd_model *m, gsl_rng *r, double *dr, double *dt, long *ncomb)
{
    int nc = m->nclear, combos = 1;
    for (int c = 0; c < nc; c++)
        combos *= 3;
    *dr = 0.0, *dt = 0.0;
    *ncomb = 0;
    for (int code = 0; code < combos; code++) {
        gd_modes md;
        memset(&md, 0, sizeof md);
        for (int c = 0, k = code; c < nc; c++, k /= 3)
            md.mode[c] = k % 3 - 1;
        for (int rep = 0; rep < 4; rep++) {
            for (int j = 0; j < m->nmesh; j++) /* both pulses' bits in turn (one pulse: on, off) */
                md.pulse_on[j] = (rep + j) % 4, md.rect_level[j] = rep / 2;
            double y[GD_MAX_STATE], v[GD_MAX_STATE], f0[GD_MAX_STATE], f1[GD_MAX_STATE], t0[GD_MAX_STATE],
                t1[GD_MAX_STATE];
            for (int i = 0; i < m->n; i++)
                y[i] = rnd(r, 5.0), v[i] = rnd(r, 1.0);
            double t = gsl_rng_uniform(r) * 3.0 * m->period;
            gd_rhs_plan p;
            gd_plan_excitation ex[GD_MAX_MESH];
            gd_plan_excitation_build(ex, m);
            gd_rhs_plan_build(&p, m, &md, ex);
            double s0 = 0.0, c0 = 1.0;
            if (m->nmesh > 0)
                sincos(m->Omega * t, &s0, &c0);
            gd_model_rhs(m, t, y, f0, &md);
            gd_rhs_plan_rhs(&p, m, t, s0, c0, y, f1, &md);
            gd_model_tangent(m, t, y, v, t0, &md);
            gd_rhs_plan_tangent(&p, m, t, s0, c0, v, t1, &md);
            double sr = 0, st = 0, er = 0, et = 0;
            for (int i = 0; i < m->n; i++) {
                sr = fmax(sr, fabs(f0[i])), st = fmax(st, fabs(t0[i]));
                er = fmax(er, fabs(f1[i] - f0[i])), et = fmax(et, fabs(t1[i] - t0[i]));
                if (!isfinite(f1[i]) || !isfinite(t1[i]))
                    er = et = INFINITY;
            }
            *dr = fmax(*dr, er / fmax(sr, 1e-300));
            *dt = fmax(*dt, et / fmax(st, 1e-300));
        }
        (*ncomb)++;
    }
    (void)name;
}

static void check_model(const char *name, gd_model *m, gsl_rng *r)
{
    double dr, dt;
    long nco;
    compare(name, m, r, &dr, &dt, &nco);
    tap_ok(dr <= TOL, "%s: RHS compiled for the modes = the general RHS in all %ld mode combinations "
                      "(largest difference %.3g of the largest acceleration, tol %.1g)", name, nco, dr, TOL);
    tap_ok(dt <= TOL, "%s: tangent map compiled = general (largest difference %.3g, tol %.1g)", name, dt, TOL);
}

/* five masses in a chain on springs and dampers, a mesh across 0-1-3 with harmonic stiffness and
 * error, a bearing on 2 and one on 4 with a two-term coordinate (general size of the plan) */
static void hand_model(gd_model *m)
{
    memset(m, 0, sizeof *m);
    m->ndof = 5, m->n = 10;
    m->Omega = 1.3, m->period = 2.0 * M_PI / m->Omega;
    double mass[5] = {1.0, 2.0, 0.5, 1.5, 3.0};
    for (int i = 0; i < 5; i++)
        m->mass[i] = mass[i], m->inv_mass[i] = 1.0 / mass[i], m->F0[i] = 0.1 * (i + 1);
    for (int i = 0; i < 4; i++) {
        m->K0[m->nk++] = (gd_nz){i, i, 2.0 + i};
        m->K0[m->nk++] = (gd_nz){i, i + 1, -1.0 - 0.1 * i};
        m->K0[m->nk++] = (gd_nz){i + 1, i, -1.0 - 0.1 * i};
        m->C0[m->nc++] = (gd_nz){i + 1, i, -0.01};
        m->C0[m->nc++] = (gd_nz){i, i + 1, -0.01};
    }
    m->K0[m->nk++] = (gd_nz){4, 4, 1.0};
    m->C0[m->nc++] = (gd_nz){2, 2, 0.03};
    m->nmesh = 1, m->nclear = 3;
    gd_mesh_excitation *x = &m->mesh[0];
    x->kind = GD_STIFF_HARMONIC, x->nh = 2, x->mean = 1.0;
    x->a[0] = 0.2, x->phi[0] = 0.3, x->a[1] = 0.05, x->phi[1] = -1.1;
    for (int h = 0; h < 2; h++)
        x->cphi[h] = cos(x->phi[h]), x->sphi[h] = sin(x->phi[h]);
    x->phase = 0.7, x->cph = cos(0.7), x->sph = sin(0.7);
    x->e_m = 0.1, x->e_r = 0.4, x->e_phi = 0.2, x->ce = cos(0.2), x->se = sin(0.2);
    x->nimp = 1, x->imp_force[0] = 0.9, x->imp_phase[0] = 0.5, x->imp_width[0] = 0.4;
    m->mesh_clear[0] = 0;
    m->clear[0] = (gd_clearance){.kind = GD_CLR_MESH, .mesh = 0, .nw = 3, .widx = {0, 1, 3},
                                 .wval = {0.8, -0.8, 0.6}, .h = 0.5, .k = 3.0, .c = 0.05, .damp_contact_only = 0};
    m->clear[1] = (gd_clearance){.kind = GD_CLR_BEARING, .mesh = -1, .nw = 1, .widx = {2}, .wval = {1.0},
                                 .h = 0.3, .k = 5.0, .c = 0.02, .damp_contact_only = 1};
    m->clear[2] = (gd_clearance){.kind = GD_CLR_BEARING, .mesh = -1, .nw = 2, .widx = {4, 3}, .wval = {0.6, 0.8},
                                 .h = 0.0, .k = 2.0, .c = 0.04, .damp_contact_only = 0};
}

static void whole_run(const char *name, const char *const *sets, int periods, int lyap)
{
    gd_case c;
    gd_model m;
    gd_error err = {0};
    pu_case(&c, sets);
    pu_build(&c, &m);
    double y0[GD_MAX_STATE], ye[2][GD_MAX_STATE], mle[2] = {0, 0};
    gd_modes md;
    PU_CHECK(gd_model_static_state(&m, y0, &md, &err), &err);
    long events[2];
    for (int g = 0; g < 2; g++) {
        gd_solver_opts o;
        gd_solver_opts_from_case(&c, &o);
        o.rtol = 1e-10;
        o.generic_rhs = g;
        o.n_tangent = lyap;
        gd_sim *s;
        PU_CHECK(gd_sim_create(&m, &o, y0, &md, &s, &err), &err);
        if (lyap)
            gd_sim_lyapunov_start(s);
        for (int p = 0; p < periods; p++)
            PU_CHECK(gd_sim_period(s, &err), &err);
        memcpy(ye[g], gd_sim_state(s), sizeof(double) * (size_t)m.n);
        gd_sim_stats st;
        gd_sim_get_stats(s, &st);
        events[g] = st.events;
        if (lyap) {
            double ex[GD_MAX_STATE], el;
            gd_sim_lyapunov(s, ex, &el);
            mle[g] = ex[0];
        }
        gd_sim_free(s);
    }
    double d = 0, sc = 0;
    for (int i = 0; i < m.n; i++)
        d = fmax(d, fabs(ye[0][i] - ye[1][i])), sc = fmax(sc, fabs(ye[1][i]));
    tap_ok(d <= 1e-7 * sc && events[0] == events[1],
           "%s, %d periods: the compiled and the general RHS end in the same state (largest difference %.3g of "
           "the largest component, tol 1e-7) with the same events (%ld, %ld)",
           name, periods, d / sc, events[0], events[1]);
    if (lyap)
        TAP_CLOSE(mle[0], mle[1], 1e-6 * fmax(1.0, fabs(mle[1])), "largest Lyapunov exponent, compiled vs general");
    gd_case_free(&c);
}

int main(void)
{
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 20261122UL);
    const char *bta[] = {"scene.model=bta", "operating.speed_rpm=4000", "operating.torque_nm=500",
                         "clearance.backlash_um=10", "clearance.bearing_clearance_um=5",
                         "excitation.ste_amplitude_um=10", NULL};
    gd_case c;
    gd_model m;
    pu_case(&c, bta);
    pu_build(&c, &m);
    for (int j = 0; j < m.nmesh; j++) /* an impact pulse on every mesh (the case's needs LTCA) */
        m.mesh[j].nimp = 1, m.mesh[j].imp_force[0] = 0.3 + 0.1 * j, m.mesh[j].imp_phase[0] = 0.2,
        m.mesh[j].imp_width[0] = 1.0;
    check_model("bta, harmonic stiffness, damping always", &m, r);
    for (int j = 0; j < m.nmesh; j++) /* the pulses acting only in drive-side contact */
        m.mesh[j].imp_contact_only = 1;
    check_model("bta, the impact pulses gated by drive-side contact", &m, r);
    /* damped bearing clearances, some acting only in contact, and contact-only mesh damping */
    for (int k = 0; k < m.nclear; k++)
        if (m.clear[k].kind == GD_CLR_BEARING)
            m.clear[k].c = 0.01 * (k + 1), m.clear[k].damp_contact_only = k % 2;
        else
            m.clear[k].damp_contact_only = 1;
    check_model("bta, damped bearings, damping in contact only", &m, r);

    /* a tabulated (LTCA-like) stiffness of 24 harmonics on each half, with the halves' phases */
    for (int j = 0; j < m.nmesh; j++) {
        gd_mesh_excitation *x = &m.mesh[j];
        x->kind = GD_STIFF_TABLE, x->nh = 24, x->mean = 0.93;
        for (int h = 0; h < x->nh; h++) {
            x->a[h] = 0.2 / (1.0 + h * h) * (1.0 + 0.3 * gsl_rng_uniform(r));
            x->phi[h] = rnd(r, M_PI);
            x->cphi[h] = cos(x->phi[h]), x->sphi[h] = sin(x->phi[h]);
        }
    }
    check_model("bta, tabulated stiffness of 24 harmonics", &m, r);
    /* and a tabulated error (excitation.ste = ltca) of 16 harmonics on each half, the right half
     * shifted in phase */
    {
        gd_error e = {0};
        double samp[32];
        m.mesh[1].phase = 0.7, m.mesh[1].cph = cos(0.7), m.mesh[1].sph = sin(0.7);
        for (int j = 0; j < m.nmesh; j++) {
            for (int i = 0; i < 32; i++)
                samp[i] = 1e-6 * (0.4 * sin(2 * M_PI * i / 32.0 + j) + 0.1 * rnd(r, 1.0));
            if (gd_model_set_error_table(&m, j, samp, 32, &e) != GD_OK)
                tap_ok(0, "gd_model_set_error_table: %s", e.msg);
        }
        check_model("bta, tabulated stiffness and tabulated error, phase-shifted right half", &m, r);
    }

    const char *cst[] = {"scene.model=bta", "excitation.stiffness=constant", NULL};
    gd_case_free(&c);
    pu_case(&c, cst);
    pu_build(&c, &m);
    check_model("bta, constant stiffness", &m, r);

    const char *rect[] = {"scene.model=bta", "excitation.stiffness=rectangular", "damping.mesh_damping_mode=contact",
                          NULL};
    gd_case_free(&c);
    pu_case(&c, rect);
    pu_build(&c, &m);
    check_model("bta, rectangular stiffness", &m, r);

    const char *lr[] = {"scene.model=torsional-lr", "clearance.backlash_um=20", NULL};
    gd_case_free(&c);
    pu_case(&c, lr);
    pu_build(&c, &m);
    check_model("torsional-lr", &m, r);

    const char *tor[] = {"scene.model=torsional", NULL};
    gd_case_free(&c);
    pu_case(&c, tor);
    pu_build(&c, &m);
    check_model("torsional", &m, r);
    /* the torsional model of a herringbone: both halves' pulses on its one mesh, gated and not */
    m.mesh[0].nimp = 2;
    m.mesh[0].imp_force[0] = 0.4, m.mesh[0].imp_phase[0] = 1.0, m.mesh[0].imp_width[0] = 0.8;
    m.mesh[0].imp_force[1] = 0.3, m.mesh[0].imp_phase[1] = 1.2, m.mesh[0].imp_width[1] = 0.7;
    check_model("torsional, two pulses", &m, r);
    m.mesh[0].imp_contact_only = 1;
    check_model("torsional, two pulses gated by drive-side contact", &m, r);

    gd_case_free(&c);
    hand_model(&m);
    check_model("hand-built 5 degrees of freedom (general size)", &m, r);
    gsl_rng_free(r);

    whole_run("bta 4000 rpm, impacting", bta, 40, 0);
    const char *bta_lyap[] = {"scene.model=bta", "operating.speed_rpm=2000", "operating.torque_nm=200",
                              "clearance.backlash_um=10", "excitation.ste_amplitude_um=20", NULL};
    whole_run("bta 2000 rpm with the tangent equations", bta_lyap, 20, 1);
    const char *tor_run[] = {"scene.model=torsional", "operating.speed_rpm=3000", "excitation.ste_amplitude_um=20",
                             NULL};
    whole_run("torsional 3000 rpm", tor_run, 40, 0);
    return tap_done();
}
