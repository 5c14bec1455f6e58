/* The bodies' masses and polar inertias from their blanks (src/geometry/bodies.c, docs/model.md
 * section 9.2) against closed forms written another way: a blank is a solid disc of the reference
 * radius over the face, less the two pockets between hub and rim beside the web, plus the hub's
 * part beyond the face, less the bore through the hub; each term a cylinder, m = rho pi r^2 L and
 * J = rho pi r^4 L / 2. The sum of annuli of gd_body_of_mesh must give the same to rounding:
 *   1. a webbed gear with a hub and a solid pinion with a hub (the guide's spur pair);
 *   2. a herringbone: each half carries half of the web, hub and groove (the whole body / 2);
 *   3. reductions: no rim and no hub is the solid cylinder less the bore; a web as thick as the face
 *      and a hub as long is that cylinder again;
 *   4. through a case: the derived masses, inertias and hub length; a blank that does not fit
 *      (rim below the hub, above the root circle, a rim without a web, a web without a rim, a hub
 *      length without a hub) is refused naming the key; a given inertia (from CAD) is kept. */
#include "physics_util.h"
#include "pair_util.h"
#include "tap.h"
#include "geardyn/gd_geometry.h"
#include "case/case_keys.h"

#include <math.h>
#include <string.h>

/* Cylinder of radius r and length L: mass and inertia (added). */
static void cyl(double rho, double r, double L, double sign, double *m, double *j)
{
    *m += sign * rho * M_PI * r * r * L;
    *j += sign * 0.5 * rho * M_PI * pow(r, 4) * L;
}

/* The closed form by subtraction for a body of width W (the face, or both halves and the groove)
 * with teeth of reference radius r over bt (the face, or both halves) and, over the groove, the
 * root radius rf over lg: all lengths and radii in m. */
static void by_subtraction(double rho, double r, double bt, double rf, double lg, double rbore, double rhub,
                           double rrim, double web, double hub_len, double *m, double *j)
{
    double W = bt + lg;
    *m = *j = 0;
    cyl(rho, r, bt, +1, m, j);                  /* the solid teeth over the face */
    cyl(rho, rf, lg, +1, m, j);                 /* the groove */
    cyl(rho, rrim, W - web, -1, m, j);          /* the pockets beside the web ... */
    cyl(rho, rhub, W - web, +1, m, j);          /* ... down to the hub */
    cyl(rho, rhub, hub_len - W, +1, m, j);      /* the hub beyond the body's width */
    cyl(rho, rbore, hub_len, -1, m, j);         /* the bore through the hub */
}

static void resolved(gd_case *c, const char *const *sets)
{
    pu_case(c, sets);
}

static void refused(const char *const *sets, const char *needle, const char *label)
{
    gd_case c;
    gd_error e = {0};
    PU_CHECK(gd_case_init(&c, &e), &e);
    c.speed_rpm = 1500, c.torque_nm = 120;
    for (int i = 0; sets[i]; i++)
        PU_CHECK(gd_case_set(&c, sets[i], i, &e), &e);
    gd_status st = gd_case_resolve(&c, &e);
    tap_ok(st != GD_OK && strstr(e.msg, needle) != NULL, "%s: refused naming %s (%s)", label, needle, e.msg);
    gd_case_free(&c);
}

int main(void)
{
    const double rho = 7850;
    /* 1. the guide's spur pair: module 3, 25/60 teeth, shifts +0.2/-0.2, 30 mm face */
    const char *spur[] = {"gear.arrangement=spur", "gear.helix_angle_deg=0", "gear.normal_module_mm=3",
                          "gear.teeth_pinion=25", "gear.teeth_gear=60", "gear.profile_shift_pinion=0.2",
                          "gear.profile_shift_gear=-0.2", "gear.face_width_pinion_mm=30", "gear.face_width_gear_mm=30",
                          "gear.bore_diameter_pinion_mm=30", "gear.hub_diameter_pinion_mm=50",
                          "gear.hub_length_pinion_mm=45", "gear.bore_diameter_gear_mm=60",
                          "gear.hub_diameter_gear_mm=100", "gear.hub_length_gear_mm=50",
                          "gear.rim_inner_diameter_gear_mm=150", "gear.web_thickness_gear_mm=10",
                          "operating.speed_rpm=1500", "operating.torque_nm=120", NULL};
    gd_case c;
    resolved(&c, spur);
    gd_geometry g;
    gd_error e = {0};
    PU_CHECK(gd_geometry_compute(PAIR_OF(&c), &g, &e), &e);
    double m, j, mx, jx;
    /* the pinion: solid over the face, a hub 45 mm long of 50 mm on a 30 mm bore */
    by_subtraction(rho, g.r[0], 0.030, g.rf[0], 0, 0.015, 0.025, 0.025, 0, 0.045, &mx, &jx);
    gd_body_of_mesh(PAIR_OF(&c), &g, 0, &m, &j);
    printf("# pinion: %.9g kg, %.9g kg m^2 (closed form %.9g, %.9g)\n", m, j, mx, jx);
    const double m_pinion = m;
    TAP_REL(m, mx, 1e-13, "spur pinion with a hub: mass");
    TAP_REL(j, jx, 1e-13, "spur pinion with a hub: polar inertia");
    /* the gear: rim from 150 mm, web 10 mm, hub 100 mm x 50 mm on a 60 mm bore */
    by_subtraction(rho, g.r[1], 0.030, g.rf[1], 0, 0.030, 0.050, 0.075, 0.010, 0.050, &mx, &jx);
    gd_body_of_mesh(PAIR_OF(&c), &g, 1, &m, &j);
    printf("# gear: %.9g kg, %.9g kg m^2 (closed form %.9g, %.9g)\n", m, j, mx, jx);
    TAP_REL(m, mx, 1e-13, "webbed spur gear with a hub: mass");
    TAP_REL(j, jx, 1e-13, "webbed spur gear with a hub: polar inertia");
    TAP_REL(c.gear_inertia_kgm2, j, 1e-15, "the case's derived gear inertia is the body's");
    TAP_REL(c.pinion_mass_kg, m_pinion, 1e-15, "the case's derived pinion mass is the body's");
    double solid_j = 0.5 * rho * M_PI * (pow(g.r[1], 4) - pow(0.030, 4)) * 0.030;
    printf("# the web and rim take %.1f %% off the gear's inertia of a solid blank on the same bore\n",
           100 * (1 - j / solid_j));
    tap_ok(j < 0.8 * solid_j, "the webbed gear is lighter in inertia than its solid blank (%.3g < %.3g)", j, solid_j);
    gd_case_free(&c);

    /* 3. reductions */
    const char *plain[] = {"gear.arrangement=spur", "gear.helix_angle_deg=0", "gear.face_width_pinion_mm=30",
                           "gear.face_width_gear_mm=30", "gear.bore_diameter_gear_mm=80", "operating.speed_rpm=1500",
                           "operating.torque_nm=120", NULL};
    resolved(&c, plain);
    PU_CHECK(gd_geometry_compute(PAIR_OF(&c), &g, &e), &e);
    gd_body_of_mesh(PAIR_OF(&c), &g, 1, &m, &j);
    TAP_REL(j, 0.5 * rho * M_PI * (pow(g.r[1], 4) - pow(0.040, 4)) * 0.030, 1e-13,
            "no rim, no hub: the cylinder of the reference radius less the bore");
    pu_set(&c, "gear.rim_inner_diameter_gear_mm=200");
    pu_set(&c, "gear.web_thickness_gear_mm=30");
    pu_set(&c, "gear.hub_diameter_gear_mm=120");
    pu_set(&c, "gear.hub_length_gear_mm=30");
    gd_body_of_mesh(PAIR_OF(&c), &g, 1, &mx, &jx);
    TAP_REL(jx, j, 1e-13, "a web as thick as the face and a hub as long: the solid blank again (inertia)");
    TAP_REL(mx, m, 1e-13, "... and mass");
    gd_case_free(&c);

    /* 2. a herringbone (the paper's pair): each half half of the whole body */
    const char *hb[] = {"gear.bore_diameter_gear_mm=120", "gear.hub_diameter_gear_mm=200", "gear.hub_length_gear_mm=180",
                        "gear.rim_inner_diameter_gear_mm=360", "gear.web_thickness_gear_mm=30",
                        "operating.speed_rpm=4000", "operating.torque_nm=500", NULL};
    resolved(&c, hb);
    PU_CHECK(gd_geometry_compute(PAIR_OF(&c), &g, &e), &e);
    by_subtraction(rho, g.r[1], 2 * 0.044, g.rf[1], 0.050, 0.060, 0.100, 0.180, 0.030, 0.180, &mx, &jx);
    gd_body_of_mesh(PAIR_OF(&c), &g, 1, &m, &j);
    printf("# herringbone gear half: %.9g kg, %.9g kg m^2 (the whole body %.9g, %.9g)\n", m, j, mx, jx);
    TAP_REL(2 * m, mx, 1e-13, "herringbone: a half's mass is half the webbed body's");
    TAP_REL(2 * j, jx, 1e-13, "herringbone: a half's inertia is half the webbed body's");
    gd_case_free(&c);

    /* 4. the derived hub length, and what does not fit */
    const char *len[] = {"gear.hub_diameter_pinion_mm=100", "gear.bore_diameter_pinion_mm=50",
                         "operating.speed_rpm=4000", "operating.torque_nm=500", NULL};
    resolved(&c, len);
    size_t k = gd_case_key_index("gear", "hub_length_pinion_mm");
    tap_ok(c.hub_length_pinion_mm == 2 * 40 + 50 && gd_case_source(&c, k, NULL) == GD_SRC_DERIVED,
           "a hub without a length runs over the body: both halves and the groove, %g mm (derived)",
           c.hub_length_pinion_mm);
    gd_case_free(&c);
    const char *b1[] = {"gear.hub_diameter_gear_mm=300", "gear.rim_inner_diameter_gear_mm=250",
                        "gear.web_thickness_gear_mm=20", NULL};
    refused(b1, "gear.hub_diameter_gear_mm: a hub of 300 mm", "a hub wider than the rim's inner diameter");
    const char *b2[] = {"gear.rim_inner_diameter_pinion_mm=170", "gear.web_thickness_pinion_mm=20", NULL};
    refused(b2, "gear.rim_inner_diameter_pinion_mm: a rim from 170 mm", "a rim below the root circle's 166.9 mm");
    const char *b3[] = {"gear.rim_inner_diameter_pinion_mm=120", NULL};
    refused(b3, "without gear.web_thickness_pinion_mm", "a rim without a web");
    const char *b4[] = {"gear.web_thickness_gear_mm=20", NULL};
    refused(b4, "gear.web_thickness_gear_mm: a web without a rim", "a web without a rim");
    const char *b5[] = {"gear.hub_length_gear_mm=20", NULL};
    refused(b5, "gear.hub_length_gear_mm: a hub length without a hub", "a hub length without a hub");
    /* a given inertia (from CAD) is kept, the blank's derived one is not used for it */
    const char *cad[] = {"gear.rim_inner_diameter_gear_mm=360", "gear.web_thickness_gear_mm=30",
                         "gear.gear_inertia_kgm2=2.5", "operating.speed_rpm=4000", "operating.torque_nm=500", NULL};
    resolved(&c, cad);
    tap_ok(c.gear_inertia_kgm2 == 2.5 && gd_case_source(&c, gd_case_key_index("gear", "gear_inertia_kgm2"), NULL) ==
           GD_SRC_SET, "a given inertia is kept (%g kg m^2)", c.gear_inertia_kgm2);
    gd_case_free(&c);
    return tap_done();
}
