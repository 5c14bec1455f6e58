/* Tooth compliance: the tabulated potential-energy integrals against the closed-form Timoshenko
 * cantilever (tip load and two-point influence), reciprocity, the face kernel's normalisation,
 * and the single-pair stiffness of spur pairs at the pitch point against ISO 6336-1's single
 * stiffness c' (an empirical fit of measurements and FE: two independent routes, within 10 %). */
#include "geardyn/geardyn.h"
#include "pair_util.h"
#include "geardyn/gd_compliance.h"
#include "tap.h"

#include <string.h>

/* ISO 6336-1 single stiffness of a spur pair without profile shift, solid blanks, standard rack:
 * c' = c'_th C_M C_R C_B with C_M = 0.8, C_R = 1, C_B = 0.975 (N / (mm um)) */
static double iso_cprime(int z1, int z2)
{
    double q = 0.04723 + 0.15551 / z1 + 0.25791 / z2;
    return 0.8 * 0.975 / q;
}

int main(void)
{
    gd_error e = {0};
    /* 1. a uniform cantilever, plane-strain modulus, Timoshenko shear factor 1.2 */
    double E = 206e9, nu = 0.3, Ep = E / (1 - nu * nu), G = E / (2 * (1 + nu));
    double x0 = 0.1, L = 0.012, y = 0.003;
    gd_tooth b;
    tap_ok(gd_tooth_init_beam(&b, E, nu, x0, x0 + L, y, &e) == GD_OK, "beam tables");
    double I = pow(2 * y, 3) / 12, A = 2 * y;
    gd_load_point tip, mid;
    gd_load_point_at(&b, x0 + L, &tip);
    gd_load_point_at(&b, x0 + 0.4 * L, &mid);
    TAP_REL(gd_tooth_influence(&b, &tip, &tip), L * L * L / (3 * Ep * I) + 1.2 * L / (G * A), 1e-9,
            "cantilever tip compliance = L^3/(3EI) + 1.2 L/(GA)");
    double a = 0.4 * L;
    TAP_REL(gd_tooth_influence(&b, &mid, &tip), a * a * (3 * L - a) / (6 * Ep * I) + 1.2 * a / (G * A), 1e-9,
            "influence of a tip load at 0.4 L = a^2 (3L - a)/(6EI) + 1.2 a/(GA)");
    TAP_REL(gd_tooth_influence(&b, &tip, &mid), gd_tooth_influence(&b, &mid, &tip), 1e-15, "reciprocity");
    gd_tooth_free(&b);

    /* 2. the face kernel integrates to 1 in the middle of a long face and more near the ends */
    double ell = 0.007, z0 = -0.05, z1 = 0.05, s = 0, se = 0;
    for (int i = 0; i < 20000; i++) {
        double z = z0 + (i + 0.5) * (z1 - z0) / 20000;
        s += gd_face_kernel(0.0, z, z0, z1, ell) * (z1 - z0) / 20000;
        se += gd_face_kernel(z0 + 0.001, z, z0, z1, ell) * (z1 - z0) / 20000;
    }
    TAP_CLOSE(s, 1.0, 1e-4, "face kernel: a uniform line load gives the slice deflection (unit weight)");
    TAP_CLOSE(se, 1.0, 1e-4, "also near a face (the images keep the weight)");
    double soft = gd_face_kernel(z0, z0, z0, z1, ell) / gd_face_kernel(0, 0, z0, z1, ell);
    TAP_CLOSE(soft, 2.0, 1e-3, "a point load on a free face deflects twice as much as mid-face");

    /* 3. spur pairs: single-pair stiffness at the pitch point against ISO 6336-1 c'_th */
    int pairs[3][2] = {{30, 72}, {20, 40}, {40, 40}};
    for (int k = 0; k < 3; k++) {
        gd_case c;
        gd_case_init(&c, &e);
        c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
        char buf[64];
        gd_case_set(&c, "gear.helix_angle_deg=0", 0, &e);
        snprintf(buf, sizeof buf, "gear.teeth_pinion=%d", pairs[k][0]);
        gd_case_set(&c, buf, 1, &e);
        snprintf(buf, sizeof buf, "gear.teeth_gear=%d", pairs[k][1]);
        gd_case_set(&c, buf, 2, &e);
        if (gd_case_resolve(&c, &e) != GD_OK) {
            tap_ok(0, "%s", e.msg);
            continue;
        }
        gd_geometry g;
        gd_geometry_compute(PAIR_OF(&c), &g, &e);
        gd_tooth tp, tg;
        gd_tooth_init(PAIR_OF(&c), &g, 0, &tp, &e);
        gd_tooth_init(PAIR_OF(&c), &g, 1, &tg, &e);
        gd_load_point tipg, tipp;
        gd_load_point_at(&tg, g.ra[1], &tipg);
        gd_load_point_at(&tp, g.ra[0], &tipp);
        tap_ok(isfinite(gd_tooth_influence(&tg, &tipg, &tipg)) && isfinite(gd_tooth_influence(&tp, &tipp, &tipp)),
               "loads at the tip radii are inside the tables");
        gd_load_point pp, pg;
        gd_load_point_at(&tp, g.rw[0], &pp);
        gd_load_point_at(&tg, g.rw[1], &pg);
        double comp = gd_tooth_influence(&tp, &pp, &pp) + gd_tooth_influence(&tg, &pg, &pg) +
                      gd_tooth_foundation(&tp, &pp) + gd_tooth_foundation(&tg, &pg) + gd_hertz_compliance(E, nu);
        double cprime = 1.0 / comp * 1e-9; /* N/m per m of face -> N/(mm um) */
        printf("# z %d/%d: bending+shear+compression %.3g + %.3g, foundation %.3g + %.3g, Hertz %.3g m^2/N\n",
               pairs[k][0], pairs[k][1], gd_tooth_influence(&tp, &pp, &pp), gd_tooth_influence(&tg, &pg, &pg),
               gd_tooth_foundation(&tp, &pp), gd_tooth_foundation(&tg, &pg), gd_hertz_compliance(E, nu));
        TAP_REL(cprime, iso_cprime(pairs[k][0], pairs[k][1]), 0.10,
                "single-pair stiffness at the pitch point vs ISO 6336-1 c' = 0.78 c'_th (N/(mm um))");
        gd_tooth_free(&tp);
        gd_tooth_free(&tg);
        gd_case_free(&c);
    }
    return tap_done();
}
