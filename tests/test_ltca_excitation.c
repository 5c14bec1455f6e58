/* What the dynamic model takes from LTCA (gd_ltca.h, docs/ltca.md section 8):
 *  1. gd_ltca_mesh_stiffness: the stiffness of each half at npos positions k tau1 / npos (phase 0
 *     = TCA's pinion angle 0), the same numbers as the analysis; periodic over one pinion pitch;
 *     a helical pair leaves the right half alone;
 *  2. the mesh-in impact of each half: the incoming pair touches at the found angle (open just
 *     before, loaded just after); the relative normal velocity from the rigid-body kinematics
 *     equals the rate at which the gap of that flank point closes (finite differences of TCA's
 *     gap at the ideal gear position); the stiffness k_s and the power law of the incoming pair;
 *     mirror symmetry of the halves of an aligned pair; an aligned spur pair (the NASA rig's) meshes
 *     in along a line, reported at its middle, and converges in the number of face slices;
 *  3. the cache key: unchanged by the speed, changed by everything LTCA reads;
 *  4. bad arguments are refused. */
#include "ltca_util.h"
#include "pair_util.h"
#include "geardyn/gd_analysis.h"
#include "geardyn/gd_geometry.h"

#include <math.h>
#include <stdlib.h>

static void stiffness_api(void)
{
    gd_case c;
    if (lt_case(&c, LT_MIS | LT_MOD, NULL))
        return;
    enum { N = 24 };
    double kl[N], kr[N], lte[N], km[2];
    gd_error e = {0};
    gd_ltca_result r;
    if (gd_ltca_mesh_stiffness(PAIR_OF(&c), LTCA_SET_OF(&c), N, kl, kr, lte, km, &e) != GD_OK ||
        gd_ltca_run_opts(PAIR_OF(&c), LTCA_SET_OF(&c), N, 0, &r, &e) != GD_OK) {
        tap_ok(0, "mesh stiffness: %s", e.msg);
        return;
    }
    double d = 0, mean[2] = {0, 0};
    for (int k = 0; k < N; k++) {
        d = fmax(d, fabs(kl[k] - r.stiffness[0][k]) + fabs(kr[k] - r.stiffness[1][k]) + fabs(lte[k] - r.lte_arcsec[k]));
        mean[0] += kl[k] / N;
        mean[1] += kr[k] / N;
    }
    TAP_CLOSE(d, 0.0, 0.0, "gd_ltca_mesh_stiffness gives the analysis's stiffness and LTE");
    TAP_REL(km[0], mean[0], 1e-12, "its mean (left) is the mean of the positions");
    TAP_REL(km[1], mean[1], 1e-12, "its mean (right) is the mean of the positions");
    double tau = 2 * M_PI / c.teeth_pinion;
    TAP_CLOSE(r.phi1[7], 7 * tau / N, 1e-15, "position 7 of 24 is at phi1 = 7 tau1 / 24 (phase 0 = TCA's angle 0)");
    gd_ltca_result_free(&r);

    /* periodic over one pinion pitch */
    gd_ltca *w;
    if (gd_ltca_create(PAIR_OF(&c), LTCA_SET_OF(&c), &w, &e) == GD_OK) {
        gd_ltca_position a, b;
        gd_ltca_solve_at(w, 0.3 * tau, c.torque_nm, &a, &e);
        gd_ltca_solve_at(w, 1.3 * tau, c.torque_nm, &b, &e);
        TAP_REL(b.stiffness[0], a.stiffness[0], 1e-9, "stiffness at phi1 + tau1 = at phi1 (left)");
        TAP_REL(b.stiffness[1], a.stiffness[1], 1e-9, "stiffness at phi1 + tau1 = at phi1 (right)");
        TAP_CLOSE(b.lte * 206264.806, a.lte * 206264.806, 1e-9, "LTE at phi1 + tau1 = at phi1 (arcsec)");
        gd_ltca_free(w);
    }
    gd_case_free(&c);

    /* one half: the right array is not written */
    if (lt_case(&c, 0, "gear.arrangement=helical", NULL))
        return;
    double sentinel[4] = {-1, -1, -1, -1}, left[4], k2[2];
    if (gd_ltca_mesh_stiffness(PAIR_OF(&c), LTCA_SET_OF(&c), 4, left, sentinel, NULL, k2, &e) != GD_OK)
        tap_ok(0, "helical: %s", e.msg);
    tap_ok(sentinel[0] == -1 && sentinel[3] == -1 && isnan(k2[1]) && left[0] > 0,
           "helical pair: k_right untouched, k_mean[1] NaN, k_left %.4g N/m", left[0]);
    gd_case_free(&c);
}

static void impact(void)
{
    gd_case c;
    if (lt_case(&c, LT_MIS | LT_MOD, NULL))
        return;
    gd_error e = {0};
    gd_ltca_excitation x;
    if (gd_ltca_excitation_compute(PAIR_OF(&c), LTCA_SET_OF(&c), 32, &x, &e) != GD_OK) {
        tap_ok(0, "excitation: %s", e.msg);
        return;
    }
    TAP_CLOSE((double)(x.key == gd_ltca_cache_key(PAIR_OF(&c), LTCA_SET_OF(&c), 32)), 1.0, 0.0,
              "the excitation carries its cache key");
    gd_ltca *w;
    if (gd_ltca_create(PAIR_OF(&c), LTCA_SET_OF(&c), &w, &e) != GD_OK) {
        tap_ok(0, "workspace: %s", e.msg);
        return;
    }
    gd_geometry g;
    gd_geometry_compute(PAIR_OF(&c), &g, &e);
    const double tau = 2 * M_PI / c.teeth_pinion, s = g.rb[1] * cos(g.beta_b);
    for (int h = 0; h < 2; h++) {
        const gd_ltca_impact *im = &x.impact[h];
        const char *hn = h ? "right" : "left";
        tap_ok(im->found && im->phase >= 0 && im->phase < 1, "%s half: mesh-in found at phase %.6f of the cycle "
               "(pair %d, roll %.3f mm against the start of contact %.3f mm, face %.2f mm, %.1f um off the plane of "
               "action)", hn, im->phase, im->pair, im->rho1 * 1e3, im->rho_sap * 1e3, im->z1 * 1e3,
               im->offset_loa * 1e6);
        if (!im->found)
            continue;
        /* the incoming pair: open just before, loaded just after */
        double load[2];
        for (int side = 0; side < 2; side++) {
            gd_ltca_position p;
            gd_ltca_solve_at(w, im->phi1 + (side ? 1e-4 : -1e-4) * tau, c.torque_nm, &p, &e);
            int n;
            const gd_ltca_point *pts = gd_ltca_points(w, &n);
            load[side] = 0;
            for (int i = 0; i < n; i++)
                if (pts[i].half == h && pts[i].pair == im->pair)
                    load[side] += pts[i].load;
        }
        tap_ok(load[0] == 0 && load[1] > 0, "%s half: the incoming pair is unloaded 1e-4 of a cycle before and loaded "
               "(%.3g N) after", hn, load[1]);
        /* relative normal velocity against the closing rate of the gap at that flank point */
        double gp, gm, r2, z2, hstep = 1e-6;
        double u1 = im->rho1 / g.rb[0];
        gd_tca *t = gd_ltca_tca(w);
        gd_tca_gap(t, h, im->phi1 + hstep, im->pair, u1, im->z1, &gp, &r2, &z2);
        gd_tca_gap(t, h, im->phi1 - hstep, im->pair, u1, im->z1, &gm, &r2, &z2);
        double fd = -s * (gp - gm) / (2 * hstep);
        printf("# %s half: v_s / omega1 = %.6g mm (kinematics) vs %.6g mm (closing rate of the gap); k_s %.4g N/m at "
               "%.3f um, F = %.4g delta^%.4f\n", hn, im->vs_per_omega * 1e3, fd * 1e3, im->ks, im->delta_m * 1e6,
               im->fit_c, im->fit_n);
        char name[128];
        snprintf(name, sizeof name, "%s half: relative normal velocity = closing rate of the gap (m per rad)", hn);
        TAP_REL(im->vs_per_omega, fd, 0.02, name);
        tap_ok(im->vs_per_omega > 0, "%s half: the flanks approach at the mesh-in (%.4g m/s at 1 rad/s)", hn,
               im->vs_per_omega);
        tap_ok(im->ks > 0 && im->delta_m > 0 && im->fit_n > 0.8 && im->fit_n < 2.0, "%s half: k_s %.4g N/m at the "
               "loaded deflection %.3f um, power law exponent %.3f", hn, im->ks, im->delta_m * 1e6, im->fit_n);
    }
    gd_ltca_free(w);
    gd_ltca_excitation_free(&x);
    gd_case_free(&c);

    /* an aligned pair: the halves are mirror images */
    if (lt_case(&c, 0, NULL))
        return;
    if (gd_ltca_excitation_compute(PAIR_OF(&c), LTCA_SET_OF(&c), 16, &x, &e) == GD_OK) {
        TAP_CLOSE(x.impact[1].phase, x.impact[0].phase, 1e-9, "aligned pair: both halves mesh in at the same phase");
        TAP_REL(x.impact[1].vs_per_omega, x.impact[0].vs_per_omega, 1e-6, "aligned pair: with the same velocity");
        TAP_CLOSE(x.impact[1].z1, -x.impact[0].z1, 1e-12, "aligned pair: at mirrored face positions (m)");
        gd_ltca_excitation_free(&x);
    } else {
        tap_ok(0, "aligned excitation: %s", e.msg);
    }
    gd_case_free(&c);
}

static void cache_key(void)
{
    gd_case c;
    if (lt_case(&c, LT_MIS | LT_MOD, NULL))
        return;
    uint64_t k0 = gd_ltca_cache_key(PAIR_OF(&c), LTCA_SET_OF(&c), 32);
    tap_ok(k0 == gd_ltca_cache_key(PAIR_OF(&c), LTCA_SET_OF(&c), 32) &&
               k0 == gd_ltca_cache_key(PAIR_OF(&c), LTCA_SET_OF(&c), 0),
           "cache key: deterministic, npos <= 0 "
           "means the case's 32 positions (%016llx)", (unsigned long long)k0);
    gd_error e = {0};
    gd_case_set_number(&c, "operating.speed_rpm", 7000, &e);
    tap_ok(gd_ltca_cache_key(PAIR_OF(&c), LTCA_SET_OF(&c), 32) == k0,
           "cache key: a new speed at the same torque reuses the LTCA");
    struct {
        const char *key;
        double value;
    } ch[] = {{"operating.torque_nm", 400}, {"modification.tip_relief_amount_um", 30},
              {"misalignment.axis_in_plane_arcmin", 0.2}, {"misalignment.centre_distance_error_mm", 0.05},
              {"gear.face_width_pinion_mm", 38}, {"solver.ltca_face_slices", 41}, {"gear.youngs_modulus_gpa", 210}};
    for (size_t i = 0; i < sizeof ch / sizeof ch[0]; i++) {
        gd_case d;
        gd_case_copy(&d, &c, &e);
        gd_case_set_number(&d, ch[i].key, ch[i].value, &e);
        tap_ok(gd_ltca_cache_key(PAIR_OF(&d), LTCA_SET_OF(&d), 32) != k0, "cache key: changes with %s", ch[i].key);
        gd_case_free(&d);
    }
    c.pinion_axial = GD_PINION_FIXED;
    tap_ok(gd_ltca_cache_key(PAIR_OF(&c), LTCA_SET_OF(&c), 32) != k0, "cache key: changes with support.pinion_axial");
    tap_ok(gd_ltca_cache_key(PAIR_OF(&c), LTCA_SET_OF(&c), 32) != gd_ltca_cache_key(PAIR_OF(&c), LTCA_SET_OF(&c), 64),
           "cache key: changes with the positions");
    gd_case_free(&c);
}

static void refusals(void)
{
    gd_case c;
    if (lt_case(&c, 0, NULL))
        return;
    gd_error e = {0};
    double k[4];
    tap_ok(gd_ltca_mesh_stiffness(PAIR_OF(&c), LTCA_SET_OF(&c), 1, k, NULL, NULL, NULL, &e) == GD_ERR_INPUT,
           "one position is refused: %s", e.msg);
    gd_ltca *w;
    gd_ltca_position p;
    if (gd_ltca_create(PAIR_OF(&c), LTCA_SET_OF(&c), &w, &e) == GD_OK) {
        tap_ok(gd_ltca_solve_at(w, 0, 0.0, &p, &e) == GD_ERR_INPUT, "zero torque is refused: %s", e.msg);
        tap_ok(gd_ltca_solve_at(w, 0, -5.0, &p, &e) == GD_ERR_INPUT, "negative torque is refused");
        gd_ltca_free(w);
    }
    gd_case_free(&c);
    /* the case itself: analysis = ltca needs a torque */
    gd_case_init(&c, &e);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    gd_case_set(&c, "scene.analysis=ltca", 0, &e);
    gd_case_set(&c, "operating.torque_nm=0", 1, &e);
    tap_ok(gd_case_resolve(&c, &e) == GD_ERR_INPUT && strstr(e.msg, "operating.torque_nm") != NULL,
           "analysis = ltca with torque 0 is refused at resolve: %s", e.msg);
    gd_case_free(&c);
}

/* An aligned spur pair (the NASA Glenn gear-noise-rig pair: 28/28, m 3.175 mm, 6.35 mm face, 72 N m):
 * the incoming pair touches along the whole face at once, so the mesh-in is a line, reported at
 * the middle of the face without a face end's edge, and what the impact pulse takes from it
 * (phase, velocity, loaded deflection, k_s) does not depend on the number of face slices. */
static void line_touch(void)
{
    static const int slices[] = {11, 21, 41, 81};
    double ph[4], vs[4], dm[4], ks[4];
    int mid = 1, ends = 0;
    for (int k = 0; k < 4; k++) {
        char ns[64];
        snprintf(ns, sizeof ns, "solver.ltca_face_slices=%d", slices[k]);
        gd_case c;
        if (lt_case(&c, 0, "gear.arrangement=spur", "gear.normal_module_mm=3.175", "gear.teeth_pinion=28",
                    "gear.teeth_gear=28", "gear.helix_angle_deg=0", "gear.face_width_pinion_mm=6.35",
                    "gear.face_width_gear_mm=6.35", "operating.torque_nm=72", ns, NULL))
            return;
        gd_error e = {0};
        gd_ltca_excitation x;
        if (gd_ltca_excitation_compute(PAIR_OF(&c), LTCA_SET_OF(&c), 32, &x, &e) != GD_OK) {
            tap_ok(0, "NASA pair excitation: %s", e.msg);
            gd_case_free(&c);
            return;
        }
        const gd_ltca_impact *im = &x.impact[0];
        ph[k] = im->phase, vs[k] = im->vs_per_omega, dm[k] = im->delta_m, ks[k] = im->ks;
        printf("# NASA spur pair, %d slices: mesh-in at phase %.9f, face %.4f mm, edges 0x%x, v_s/omega1 %.9g mm, "
               "delta_m %.6f um, k_s %.9g N/m\n", slices[k], im->phase, im->z1 * 1e3, im->edge,
               im->vs_per_omega * 1e3, im->delta_m * 1e6, im->ks);
        mid &= im->found && fabs(im->z1) < 1e-9;
        ends |= (int)(im->edge & (GD_EDGE_PINION_END_LO | GD_EDGE_PINION_END_HI | GD_EDGE_GEAR_END_LO |
                                  GD_EDGE_GEAR_END_HI));
        gd_ltca_excitation_free(&x);
        gd_case_free(&c);
    }
    tap_ok(mid && !ends, "NASA spur pair: the mesh-in is a line along the face, reported at its middle without a face "
           "end's edge, at 11 to 81 slices");
    double sp = 0, sv = 0, sd = 0, sk = 0;
    for (int k = 1; k < 4; k++) {
        sp = fmax(sp, fabs(ph[k] - ph[3]));
        sv = fmax(sv, fabs(vs[k] / vs[3] - 1));
        sd = fmax(sd, fabs(dm[k] / dm[3] - 1));
        sk = fmax(sk, fabs(ks[k] / ks[3] - 1));
    }
    tap_ok(sp < 1e-6 && sv < 1e-5 && sd < 1e-5 && sk < 1e-5,
           "and converged in the slices: from 21 slices on, phase within %.2g of the cycle, velocity %.2g, loaded "
           "deflection %.2g, k_s %.2g of 81 slices'", sp, sv, sd, sk);
}

int main(void)
{
    stiffness_api();
    impact();
    line_touch();
    cache_key();
    refusals();
    return tap_done();
}
