/* The supports of the bta model: the bodies' weights (scene.gravity) and the radial bearing damper
 * that acts only while the journal touches its clearance's boundary
 * (damping.bearing_damping_mode = contact). docs/model.md section 5.2.
 *
 * (1) Gravity. The mesh force at rest is the torque's whatever the weights (the torsional equation
 *     holds it), so the weights change only the supports: with linear bearings the static state
 *     with gravity is the one without, every body displaced along y by its weight's component
 *     m_i g cos(angle) over its radial stiffness, exactly, and the mesh deflection unchanged (the
 *     torsional coordinate takes up the bodies' displacement); at 90 degrees, or off, nothing moves. The spur NASA
 *     pair and the paper's herringbone (the weight of each half on its own supports). With the
 *     bearing clearance, a pinion whose weight exceeds the mesh force's component on the line of
 *     action rests on the other side of its clearance. The torsional models refuse it.
 * (2) The bearing damper in contact only. In the clearance (mode 0) the journal's velocity gives
 *     no force; in contact it gives the damping force of the always-acting damper (the same
 *     coefficient 2 zeta sqrt(k m)). Through a response whose bearings rattle (the paper's pair at
 *     4000 rpm), the RHS compiled for the held modes agrees with the general one (same events, same
 *     end state), and the run differs from the always-acting damper's. */
#include "physics_util.h"
#include "tap.h"

static void build(const char *const *sets, const char *a, const char *b, gd_case *c, gd_model *m)
{
    const char *all[40];
    int n = 0;
    for (int i = 0; sets[i]; i++)
        all[n++] = sets[i];
    if (a)
        all[n++] = a;
    if (b)
        all[n++] = b;
    all[n] = NULL;
    pu_case(c, all);
    pu_build(c, m);
}

static void statics(const gd_model *m, double *y)
{
    gd_error e = {0};
    gd_modes md;
    memset(&md, 0, sizeof md);
    PU_CHECK(gd_model_static_state(m, y, &md, &e), &e);
}

/* (1) for one pair: the static displacement by the weights at angle deg */
static void gravity(const char *label, const char *const *sets, const char *angle, double deg)
{
    gd_case c0, c1;
    gd_model m0, m1;
    build(sets, NULL, NULL, &c0, &m0);
    build(sets, "scene.gravity=on", angle, &c1, &m1);
    double y0[GD_MAX_STATE], y1[GD_MAX_STATE];
    statics(&m0, y0);
    statics(&m1, y1);
    const double g = 9.80665, len = m0.bc_m, cg = cos(deg * M_PI / 180.0);
    double worst = 0, dq = 0;
    int halves = m0.nmesh;
    for (int s = 0; s < halves; s++) {
        int b0 = 5 * s;
        double w1 = c0.pinion_mass_kg * g * cg, w2 = c0.gear_mass_kg * g * cg;
        double d1 = (y1[b0] - y0[b0]) * len, d2 = (y1[b0 + 2] - y0[b0 + 2]) * len;
        double e1 = w1 / c0.radial_stiffness_pinion_n_per_m, e2 = w2 / c0.radial_stiffness_gear_n_per_m;
        printf("#   %s, %g deg, half %d: pinion %.9g um (weight/stiffness %.9g), gear %.9g um (%.9g)\n", label, deg, s,
               d1 * 1e6, e1 * 1e6, d2 * 1e6, e2 * 1e6);
        double sc = fmax(fabs(e1), 1e-9 * fabs(w1 / c0.radial_stiffness_pinion_n_per_m) + 1e-18);
        worst = fmax(worst, fmax(fabs(d1 - e1), fabs(d2 - e2)) / fmax(sc, fabs(e2) + 1e-30));
        /* the mesh force (deflection beyond the half backlash times the stiffness) is the torque's */
        double x0, v0, x1, v1;
        gd_modes md;
        memset(&md, 0, sizeof md);
        md.from_state = 1;
        gd_model_clearance(&m0, m0.mesh_clear[s], 0.0, y0, &md, &x0, &v0);
        gd_model_clearance(&m1, m1.mesh_clear[s], 0.0, y1, &md, &x1, &v1);
        dq = fmax(dq, fabs(x1 - x0) / fabs(x0));
    }
    if (fabs(cg) > 1e-12)
        tap_ok(worst < 1e-9 && dq < 1e-12, "%s, gravity at %g deg: each body moves by its weight's component over "
               "its radial stiffness (largest relative difference %.3g), the mesh force unchanged (%.3g)", label, deg,
               worst, dq);
    else {
        double d = 0;
        for (int i = 0; i < m0.ndof; i++)
            d = fmax(d, fabs(y1[i] - y0[i]));
        tap_ok(d < 1e-12, "%s, gravity at 90 deg (across the line of action): nothing moves (%.3g)", label, d);
    }
    gd_case_free(&c0);
    gd_case_free(&c1);
}

/* the acceleration of DOF i at the state y with the held modes md */
static double accel(const gd_model *m, const double *y, const gd_modes *md, int i)
{
    double f[GD_MAX_STATE];
    gd_model_rhs(m, 0.3, y, f, md);
    return f[m->ndof + i];
}

int main(void)
{
    printf("# (1) gravity\n");
    const char *nasa[] = {"gear.arrangement=spur", "gear.normal_module_mm=3.175", "gear.teeth_pinion=28",
                          "gear.teeth_gear=28", "gear.helix_angle_deg=0", "gear.face_width_pinion_mm=6.35",
                          "gear.face_width_gear_mm=6.35", "operating.torque_nm=72", "clearance.backlash_um=127",
                          "scene.bearing_clearance=off", "excitation.stiffness=constant", NULL};
    const char *paper[] = {"scene.bearing_clearance=off", "excitation.stiffness=constant", NULL};
    gravity("NASA spur pair", nasa, "support.gravity_angle_deg=0", 0.0);
    gravity("NASA spur pair", nasa, "support.gravity_angle_deg=150", 150.0);
    gravity("NASA spur pair", nasa, "support.gravity_angle_deg=90", 90.0);
    gravity("paper's herringbone", paper, "support.gravity_angle_deg=30", 30.0);
    {
        /* off: the weights do not enter (the model of the case without the key) */
        gd_case c0, c1;
        gd_model m0, m1;
        build(nasa, NULL, NULL, &c0, &m0);
        build(nasa, "scene.gravity=off", "support.gravity_angle_deg=0", &c1, &m1);
        tap_ok(memcmp(m0.F0, m1.F0, sizeof m0.F0) == 0, "gravity off: the loads of the model without it");
        gd_case_free(&c0);
        gd_case_free(&c1);
    }
    {
        /* with the bearing clearance: the NASA pinion (weight 3.03 N along +y, angle 0) at 2 N m
         * (mesh force 47.9 N, pushing it to -y) lies against the clearance's -y side; at 0.1 N m
         * (2.39 N) its weight puts it on the +y side */
        const char *light[] = {"gear.arrangement=spur", "gear.normal_module_mm=3.175", "gear.teeth_pinion=28",
                               "gear.teeth_gear=28", "gear.helix_angle_deg=0", "gear.face_width_pinion_mm=6.35",
                               "gear.face_width_gear_mm=6.35", "clearance.backlash_um=127",
                               "excitation.stiffness=constant", "scene.gravity=on", "support.gravity_angle_deg=0",
                               NULL};
        gd_case c;
        gd_model m;
        double y[GD_MAX_STATE];
        build(light, "operating.torque_nm=2", NULL, &c, &m);
        statics(&m, y);
        int side2 = y[0] < 0;
        gd_case_free(&c);
        build(light, "operating.torque_nm=0.1", NULL, &c, &m);
        statics(&m, y);
        int side02 = y[0] > 0;
        tap_ok(side2 && side02, "bearing clearance: the pinion rests on the side of the larger of the mesh force's "
               "and its weight's components (2 N m: %s; 0.1 N m: %s)", side2 ? "-y" : "+y",
               side02 ? "+y" : "-y");
        gd_case_free(&c);
    }
    {
        gd_case c;
        gd_error e = {0};
        gd_case_init(&c, &e);
        c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
        gd_case_set(&c, "scene.model=torsional", 0, &e);
        gd_case_set(&c, "scene.gravity=on", 1, &e);
        gd_status st = gd_case_resolve(&c, &e);
        tap_ok(st == GD_ERR_INPUT && strstr(e.msg, "scene.gravity") && strstr(e.msg, "bta"),
               "gravity with a torsional model is refused, naming the key (%s)", e.msg);
        gd_case_free(&c);
    }

    printf("# (2) the bearing damper in contact only\n");
    const char *rattle[] = {"scene.model=bta", "operating.speed_rpm=4000", "clearance.bearing_clearance_um=5",
                            "damping.support_damping_ratio=0.05", NULL};
    gd_case ca, cc;
    gd_model ma, mc;
    build(rattle, NULL, NULL, &ca, &ma);
    build(rattle, "damping.bearing_damping_mode=contact", NULL, &cc, &mc);
    double y[GD_MAX_STATE];
    statics(&mc, y);
    int bc = -1; /* the pinion's bearing of the left half and its DOF */
    for (int k = 0; k < mc.nclear; k++)
        if (mc.clear[k].kind == GD_CLR_BEARING && mc.clear[k].widx[0] == 0)
            bc = k;
    gd_modes md;
    memset(&md, 0, sizeof md);
    for (int k = 0; k < mc.nclear; k++)
        md.mode[k] = mc.clear[k].kind == GD_CLR_MESH ? 1 : 0;
    gd_model ma0 = ma, mc0 = mc; /* without the mesh damper, whose rate contains the journal's */
    for (int k = 0; k < mc.nclear; k++)
        if (mc.clear[k].kind == GD_CLR_MESH)
            ma0.clear[k].c = mc0.clear[k].c = 0.0;
    double yv[GD_MAX_STATE];
    memcpy(yv, y, sizeof yv);
    yv[mc.ndof + 0] = 0.7; /* the pinion journal moves */
    double gap_c = accel(&mc0, yv, &md, 0) - accel(&mc0, y, &md, 0);
    double gap_a = accel(&ma0, yv, &md, 0) - accel(&ma0, y, &md, 0);
    md.mode[bc] = -1;
    double con_c = accel(&mc0, yv, &md, 0) - accel(&mc0, y, &md, 0);
    double con_a = accel(&ma0, yv, &md, 0) - accel(&ma0, y, &md, 0);
    printf("#   damping acceleration of the pinion journal: in the clearance %.9g (always %.9g), in contact %.9g "
           "(always %.9g)\n", gap_c, gap_a, con_c, con_a);
    tap_ok(bc >= 0 && gap_c == 0.0 && gap_a < 0.0,
           "in the clearance the journal's velocity gives no force (the always-acting damper: %.6g)", gap_a);
    TAP_REL(con_c, con_a, 1e-14, "in contact the damping force of the always-acting damper");

    gd_solver_opts o;
    gd_solver_opts_from_case(&cc, &o);
    o.rtol = 1e-10;
    double ye[3][GD_MAX_STATE];
    long ev[3] = {0};
    for (int g = 0; g < 3; g++) {
        gd_error e = {0};
        const gd_model *m = g == 2 ? &ma : &mc;
        gd_modes m0;
        double y0[GD_MAX_STATE];
        memset(&m0, 0, sizeof m0);
        PU_CHECK(gd_model_static_state(m, y0, &m0, &e), &e);
        o.generic_rhs = g == 1;
        gd_sim *s;
        PU_CHECK(gd_sim_create(m, &o, y0, &m0, &s, &e), &e);
        for (int p = 0; p < 40; p++)
            PU_CHECK(gd_sim_period(s, &e), &e);
        memcpy(ye[g], gd_sim_state(s), sizeof(double) * (size_t)m->n);
        gd_sim_stats st;
        gd_sim_get_stats(s, &st);
        ev[g] = st.events_by_clearance[bc];
        gd_sim_free(s);
    }
    double d = 0, sc = 0, dd = 0;
    for (int i = 0; i < mc.n; i++) {
        d = fmax(d, fabs(ye[0][i] - ye[1][i]));
        dd = fmax(dd, fabs(ye[0][i] - ye[2][i]));
        sc = fmax(sc, fabs(ye[1][i]));
    }
    tap_ok(ev[0] > 0 && ev[0] == ev[1] && d < 1e-7 * sc,
           "40 periods at 4000 rpm, bearings rattling (%ld events of the pinion's left bearing): the compiled RHS ends "
           "where the general one does (%.3g of the largest component)", ev[0], d / sc);
    tap_ok(dd > 1e-4 * sc, "and elsewhere than with the always-acting damper (%.3g)", dd / sc);
    gd_case_free(&ca);
    gd_case_free(&cc);
    return tap_done();
}
