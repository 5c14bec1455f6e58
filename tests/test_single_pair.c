/* A spur or single-helical pair in the dynamics: one mesh on the whole bodies under the whole
 * torque (docs/model.md section 5.4).
 *
 * (1) Reduction. A herringbone of two identical in-phase halves of face b (no groove, torsional,
 *     so no axial coupling) under the torque T is, half by half, a single helical pair of face 2b
 *     under T: its masses and inertias, its ISO 6336 stiffness, its damping and its normal load
 *     are all twice one half's, so its dimensionless equation is the half's and the mesh
 *     deflection history and the RMS mesh acceleration are the same; the mesh force is twice a
 *     half's.
 * (2) Static deflection. A spur pair with constant stiffness, no transmission error, started at
 *     rest with the flanks apart, settles at lambda = b + T/(r_b1 k_m) (the half backlash plus the
 *     elastic deflection under the whole torque); in bta the same, and a single helical pair's
 *     axial support carries the axial mesh force F_n sin(beta_b) (nothing else can).
 * (3) Refusals: torsional-lr, a half phase, and a floating pinion of a single helical pair in bta,
 *     each as bad input (exit status 2) naming the keys and the valid values.
 * (4) LTCA. With stiffness = ltca a single pair's model stiffness passes through the LTCA samples
 *     at the case's torque, not at twice it, and the derived mean mesh stiffness is their mean. */
#include "physics_util.h"
#include "pair_util.h"
#include "tap.h"
#include "geardyn/gd_excitation.h"
#include "geardyn/gd_geometry.h"

/* Mesh deflection of mesh 0 at every sample (dimensionless), and its RMS acceleration from the
 * response run. */
static void run(const gd_case *c, gd_model *m, long nper, long rec0, pu_samples *p, double *rms)
{
    gd_error e;
    memset(&e, 0, sizeof e);
    pu_build(c, m);
    double y0[GD_MAX_STATE];
    gd_modes md;
    memset(&md, 0, sizeof md);
    PU_CHECK(gd_model_static_state(m, y0, &md, &e), &e);
    gd_solver_opts o;
    gd_solver_opts_from_case(c, &o);
    pu_run_sampled_ex(m, &o, y0, &md, nper, rec0, 32, c->exact_samples, p, NULL);
    gd_response_result r;
    memset(&r, 0, sizeof r);
    PU_CHECK(gd_response_run(c, m, NULL, NULL, NULL, &r, &e), &e);
    *rms = r.rms_accel_mps2[0];
    printf("#   %s: %s, %s, %ld events recorded, RMS mesh acceleration %.9g m/s^2\n",
           c->arrangement == GD_ARR_HERRINGBONE ? "herringbone" : "single pair", r.motion,
           gd_impact_regime_name(r.impact_regime[2]), r.record_events, *rms);
}

static void reduction(void)
{
    printf("# (1) herringbone of two in-phase halves of 20 mm against a helical pair of 40 mm, same torque\n");
    const char *common[] = {"scene.model=torsional", "gear.helix_angle_deg=15", "gear.groove_width_mm=0",
                            "excitation.stiffness=harmonic", "excitation.stiffness_harmonics=0.2",
                            "excitation.ste_amplitude_um=12", "excitation.half_phase_deg=0", "operating.torque_nm=600",
                            "run.transient_periods=100", "run.record_periods=100", "solver.rtol=1e-12",
                            "solver.atol=1e-14", "solver.exact_samples=on"};
    const char *sets_h[20], *sets_s[20];
    int n = 0;
    for (size_t i = 0; i < sizeof common / sizeof common[0]; i++, n++)
        sets_h[n] = sets_s[n] = common[i];
    sets_h[n] = "gear.arrangement=herringbone";
    sets_s[n++] = "gear.arrangement=helical";
    sets_h[n] = "gear.face_width_pinion_mm=20";
    sets_s[n++] = "gear.face_width_pinion_mm=40";
    sets_h[n] = "gear.face_width_gear_mm=20";
    sets_s[n++] = "gear.face_width_gear_mm=40";
    sets_h[n] = sets_s[n] = NULL;
    gd_case ch, cs;
    pu_case(&ch, sets_h);
    pu_case(&cs, sets_s);
    gd_model mh, ms;
    pu_samples ph, ps;
    double rms_h, rms_s;
    run(&ch, &mh, 200, 100, &ph, &rms_h);
    run(&cs, &ms, 200, 100, &ps, &rms_s);
    tap_ok(mh.nmesh == 1 && ms.nmesh == 1, "torsional: one mesh coordinate each (%d, %d)", mh.nmesh, ms.nmesh);
    TAP_REL(cs.pinion_inertia_kgm2, 2.0 * ch.pinion_inertia_kgm2, 1e-14, "pinion inertia: the pair's = 2 x a half's");
    TAP_REL(cs.gear_mass_kg, 2.0 * ch.gear_mass_kg, 1e-14, "gear mass: the pair's = 2 x a half's");
    TAP_REL(cs.mesh_stiffness_n_per_m, 2.0 * ch.mesh_stiffness_n_per_m, 1e-14,
            "ISO 6336 mesh stiffness: the pair's = 2 x a half's");
    TAP_REL(ms.static_load_n, 2.0 * mh.static_load_n, 1e-14, "normal load: the pair's = 2 x a half's");
    TAP_REL(ms.omega_n, mh.omega_n, 1e-14, "natural frequency of the mesh: the same");
    double dmax = 0, lmax = 0, lmin = INFINITY;
    gd_modes md;
    memset(&md, 0, sizeof md);
    for (long k = 0; k < ph.count; k++) {
        double a = pu_lambda(&mh, 0, ph.t[k], ph.y + k * ph.n, &md);
        double b = pu_lambda(&ms, 0, ps.t[k], ps.y + k * ps.n, &md);
        dmax = fmax(dmax, fabs(a - b));
        lmax = fmax(lmax, fabs(a));
        lmin = fmin(lmin, a);
    }
    tap_ok(lmin < mh.clear[0].h, "the run loses contact (min lambda %.6g below the half backlash %.6g)", lmin,
           mh.clear[0].h);
    TAP_CLOSE(dmax / lmax, 0.0, 1e-12, "max |lambda_pair - lambda_half| / max |lambda| over 100 periods");
    TAP_REL(rms_s, rms_h, 1e-9, "RMS mesh acceleration: the pair's = a half's");
    pu_samples_free(&ph);
    pu_samples_free(&ps);
    gd_case_free(&ch);
    gd_case_free(&cs);
}

/* The state after nper periods from rest with the flanks apart (dimensionless). */
static void settle(const gd_case *c, gd_model *m, long nper, double *y)
{
    gd_error e;
    memset(&e, 0, sizeof e);
    pu_build(c, m);
    double y0[GD_MAX_STATE] = {0};
    gd_modes md;
    memset(&md, 0, sizeof md);
    PU_CHECK(gd_model_consistent_modes(m, 0.0, y0, &md, &e), &e);
    gd_solver_opts o;
    gd_solver_opts_from_case(c, &o);
    gd_sim *s = NULL;
    PU_CHECK(gd_sim_create(m, &o, y0, &md, &s, &e), &e);
    for (long k = 0; k < nper; k++)
        PU_CHECK(gd_sim_period(s, &e), &e);
    memcpy(y, gd_sim_state(s), sizeof(double) * (size_t)m->n);
    gd_sim_free(s);
}

static void static_deflection(void)
{
    printf("# (2) static deflection of a single pair under the whole torque\n");
    static const char *models[] = {"scene.model=torsional", "scene.model=bta"};
    for (int arr = 0; arr < 2; arr++)
        for (int im = 0; im < 2; im++) {
            const char *sets[] = {arr ? "gear.arrangement=helical" : "gear.arrangement=spur",
                                  arr ? "gear.helix_angle_deg=20" : "gear.helix_angle_deg=0", models[im],
                                  "gear.face_width_pinion_mm=30", "gear.face_width_gear_mm=30",
                                  "operating.torque_nm=300", "excitation.stiffness=constant",
                                  "scene.error_excitation=off", "scene.bearing_clearance=off",
                                  "clearance.backlash_um=40", "damping.mesh_damping_ratio=0.3",
                                  "damping.support_damping_ratio=0.3", NULL};
            gd_case c;
            pu_case(&c, sets);
            gd_geometry g;
            gd_error e;
            memset(&e, 0, sizeof e);
            PU_CHECK(gd_geometry_compute(PAIR_OF(&c), &g, &e), &e);
            gd_model m;
            double y[GD_MAX_STATE];
            settle(&c, &m, 400, y);
            gd_modes md;
            memset(&md, 0, sizeof md);
            double lam_um = pu_lambda(&m, 0, 0.0, y, &md) * m.bc_m * 1e6;
            double cb = cos(g.beta_b), fn = c.torque_nm / (g.rb[0] * cb);
            double expect_um = 20.0 + fn / c.mesh_stiffness_n_per_m * 1e6; /* b + F_n / k_n */
            printf("#   %s, %s: lambda %.12g um, b + T/(r_b1 cos(beta_b) k_m) = %.12g um (T/(r_b1 k_m) = %.6g um)\n",
                   arr ? "helical" : "spur", im ? "bta" : "torsional", lam_um, expect_um,
                   c.torque_nm / (g.rb[0] * c.mesh_stiffness_n_per_m) * 1e6);
            char name[160];
            snprintf(name, sizeof name, "%s, %s: settled lambda = b + T/(r_b1 cos(beta_b) k_m)",
                     arr ? "helical" : "spur", im ? "bta" : "torsional");
            TAP_REL(lam_um, expect_um, 1e-8, name);
            if (im == 1) {
                double z1 = y[1] * m.bc_m, fz = c.axial_stiffness_pinion_n_per_m * z1;
                double fz_expect = -fn * sin(g.beta_b);
                printf("#   axial support of the pinion carries %.9g N (expected %.9g N)\n", fz, fz_expect);
                snprintf(name, sizeof name, "%s, bta: the pinion's axial support carries -F_n sin(beta_b)",
                         arr ? "helical" : "spur");
                if (arr)
                    TAP_REL(fz, fz_expect, 1e-8, name);
                else
                    TAP_CLOSE(fz, 0.0, 1e-9, name);
                tap_ok(m.ndof == 5 && m.nmesh == 1, "%s, bta: five DOFs and one mesh (%d, %d)", arr ? "helical" : "spur",
                       m.ndof, m.nmesh);
            }
            gd_case_free(&c);
        }
}

/* The case resolves with status GD_ERR_INPUT and a message holding every one of the words. */
static void refused(const char *what, const char *const *sets, const char *const *words)
{
    gd_case c;
    gd_error e;
    memset(&e, 0, sizeof e);
    PU_CHECK(gd_case_init(&c, &e), &e);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    for (int i = 0; sets[i]; i++)
        PU_CHECK(gd_case_set(&c, sets[i], i, &e), &e); /* the message numbers it i + 1 */
    gd_status st = gd_case_resolve(&c, &e);
    int all = st != GD_OK;
    for (int i = 0; all && words[i]; i++)
        all = strstr(e.msg, words[i]) != NULL;
    printf("#   %s\n", e.msg);
    tap_ok(st == GD_ERR_INPUT && gd_status_exit_code(st) == 2 && all, "%s: refused as bad input naming the keys", what);
    gd_case_free(&c);
}

static void refusals(void)
{
    printf("# (3) refusals\n");
    refused("torsional-lr of a spur pair",
            (const char *[]){"gear.arrangement=spur", "gear.helix_angle_deg=0", "scene.model=torsional-lr", NULL},
            (const char *[]){"--set #3", "scene.model", "gear.arrangement = spur", "--set #1", "valid: torsional, bta",
                             NULL});
    refused("torsional-lr of a helical pair", (const char *[]){"gear.arrangement=helical", "scene.model=torsional-lr", NULL},
            (const char *[]){"scene.model", "gear.arrangement = helical", "valid: torsional, bta", NULL});
    refused("a half phase of a single pair",
            (const char *[]){"gear.arrangement=helical", "scene.model=bta", "excitation.half_phase_deg=30", NULL},
            (const char *[]){"--set #3", "excitation.half_phase_deg", "gear.arrangement = helical", "valid: 0", NULL});
    refused("a floating pinion of a single helical pair in bta",
            (const char *[]){"gear.arrangement=helical", "scene.model=bta", "support.axial_stiffness_pinion_n_per_m=0",
                             NULL},
            (const char *[]){"support.axial_stiffness_pinion_n_per_m", "gear.arrangement = helical", "scene.model = bta",
                             "valid: above 0", NULL});
    gd_case c;
    pu_case(&c, (const char *[]){"gear.arrangement=spur", "gear.helix_angle_deg=0", "scene.model=bta",
                                 "support.axial_stiffness_pinion_n_per_m=0", NULL});
    gd_model m;
    gd_error e;
    memset(&e, 0, sizeof e);
    tap_ok(gd_model_build(&c, &m, &e) == GD_OK, "a floating pinion of a spur pair is accepted (no axial mesh force)");
    gd_case_free(&c);
}

static void ltca(void)
{
    printf("# (4) LTCA stiffness of a single pair at the whole torque\n");
    const char *sets[] = {"gear.arrangement=spur", "gear.helix_angle_deg=0", "gear.normal_module_mm=3",
                          "gear.teeth_pinion=25", "gear.teeth_gear=60", "gear.face_width_pinion_mm=30",
                          "gear.face_width_gear_mm=30", "scene.model=torsional", "excitation.stiffness=ltca",
                          "operating.torque_nm=120", "solver.ltca_positions_per_cycle=16", NULL};
    gd_case c;
    pu_case(&c, sets);
    gd_model m;
    pu_build(&c, &m);
    gd_error e;
    memset(&e, 0, sizeof e);
    const gd_ltca_excitation *x[2];
    for (int k = 0; k < 2; k++) { /* LTCA at the case's torque and at twice it */
        gd_ltca_settings set = gd_ltca_settings_from_case(&c);
        set.torque_nm = (k + 1) * 120.0;
        PU_CHECK(gd_ltca_excitation_cached(PAIR_OF(&c), &set, &x[k], &e), &e);
    }
    tap_ok(x[0]->halves == 1, "LTCA of a spur pair: one mesh (%d)", x[0]->halves);
    gd_modes md;
    memset(&md, 0, sizeof md);
    double worst[2] = {0, 0};
    for (int k = 0; k < 2; k++)
        for (int i = 0; i < x[k]->npos; i++) {
            double t = (2.0 * M_PI * i / x[k]->npos) / m.Omega;
            double d = fabs(gd_model_stiffness(&m, 0, t, &md) * m.k_ref - x[k]->k[0][i]) / x[k]->k[0][i];
            worst[k] = fmax(worst[k], d);
        }
    printf("#   LTCA mean stiffness %.6g N/m at 120 N m, %.6g N/m at 240 N m\n", x[0]->k_mean[0], x[1]->k_mean[0]);
    TAP_CLOSE(worst[0], 0.0, 1e-12, "model stiffness at the LTCA positions = LTCA at the case's torque (relative)");
    tap_ok(worst[1] > 1e-3, "and not LTCA at twice the torque (worst relative difference %.3g, above 1e-3)", worst[1]);
    TAP_REL(c.mesh_stiffness_n_per_m, x[0]->k_mean[0], 1e-14, "derived mean mesh stiffness = LTCA mean at the torque");
    gd_geometry g;
    PU_CHECK(gd_geometry_compute(PAIR_OF(&c), &g, &e), &e);
    TAP_REL(m.static_load_n, 120.0 / g.rb[0], 1e-14, "static mesh force = T / r_b1 (the whole torque on one mesh)");
    gd_ltca_excitation_release(x[0]);
    gd_ltca_excitation_release(x[1]);
    gd_case_free(&c);
}

int main(void)
{
    reduction();
    static_deflection();
    refusals();
    ltca();
    return tap_done();
}
