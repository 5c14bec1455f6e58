/* The modal analysis of the linearised model (gd_modal_analyse, gd_scene_modes; docs/model.md
 * section 9.7):
 *  - torsional: one mode, the two-mass torsional closed form omega^2 = k_m cos^2(beta_b)
 *    (r_b1^2 / I_1 + r_b2^2 / I_2) from the inertias and base radii, for a spur pair and for a
 *    herringbone (per half), all of its strain energy in the mesh;
 *  - the stiffness matrix assembled from the model's springs equals -M times the model's own
 *    Jacobian (gd_model_jacobian) and the central differences of its right-hand side at the static
 *    state; the element strain energies of every mode add up to omega^2 / 2 with that independent
 *    matrix (Rayleigh), so no spring is missed or counted twice, and the shares sum to 1;
 *  - bta of a spur pair with supports 1e2 ... 1e4 times stiffer: its mesh mode tends to the
 *    torsional frequency, the difference falling like 1 / scale (the supports are compliances in
 *    series with the mesh); its axial modes are sqrt(k_z / m) exactly;
 *  - the symmetric herringbone (the paper's pair in bta, torsional-lr): every mode symmetric or
 *    antisymmetric under the mirror of the halves, the two meshes of a mode carry equal energy;
 *    torsional-lr's two equal frequencies split into (1, 1) and (1, -1); a floating pinion's
 *    rigid-body mode (z1L = z1R = d, qL = -sin(beta_b) d, qR = +sin(beta_b) d) is found and kept
 *    out of the elastic modes; halves of unequal stiffness are not called symmetric;
 *  - against sweeps: the largest RMS mesh acceleration of a speed sweep of the NASA Glenn spur
 *    pair lies at the predicted main resonance of its mesh mode, in bta (10808 rpm) and in
 *    torsional (12524 rpm), 14 % apart: within one grid step (about 1 % of the speed). The
 *    excitation (0.2 um of STE, constant stiffness) is small enough that the flanks stay in
 *    contact, so the response is linear; damping moves the peak: the RMS of the relative
 *    acceleration of the base-excited oscillator, Omega^4 / sqrt((1 - Omega^2)^2 + (2 zeta Omega)^2),
 *    peaks at Omega^2 = 1 + 6 zeta^2 to first order, +0.75 % in speed for zeta = 0.05, and the
 *    torsional sweep's peak is the grid point nearest that;
 *  - a custom system is refused. */
#include "geardyn/gd_modal.h"
#include "geardyn/gd_sweep.h"
#include "geardyn/gd_geometry.h"
#include "physics_util.h"
#include "tap.h"

static gd_modal modes_of(const gd_case *c, gd_model *m)
{
    gd_modal md;
    gd_error e = {0};
    pu_build(c, m);
    PU_CHECK(gd_scene_modes(c, m, &md, &e), &e);
    return md;
}

static int elem_index(const gd_modal *md, const char *name)
{
    for (int e = 0; e < md->nelem; e++)
        if (strcmp(md->elem[e].name, name) == 0)
            return e;
    return -1;
}

/* The share of the meshes in mode k. */
static double mesh_share(const gd_model *m, const gd_modal *md, int k)
{
    double s = 0.0;
    for (int e = 0; e < md->nelem; e++)
        if (md->elem[e].kind == GD_MODAL_CLEARANCE && m->clear[md->elem[e].clear].kind == GD_CLR_MESH)
            s += md->share[k][e];
    return s;
}

/* The two-mass torsional closed form of one mesh (Hz). */
static double two_mass_hz(const gd_case *c)
{
    gd_geometry g;
    gd_error e = {0};
    const gd_pair pair = gd_pair_from_case(c);
    PU_CHECK(gd_geometry_compute(&pair, &g, &e), &e);
    double cb = cos(g.beta_b);
    double w2 = c->mesh_stiffness_n_per_m * cb * cb *
                (g.rb[0] * g.rb[0] / c->pinion_inertia_kgm2 + g.rb[1] * g.rb[1] / c->gear_inertia_kgm2);
    return sqrt(w2) / (2.0 * M_PI);
}

static const char *spur[] = {"gear.arrangement=spur", "gear.normal_module_mm=3", "gear.teeth_pinion=25",
                             "gear.teeth_gear=60", "gear.helix_angle_deg=0", "gear.profile_shift_pinion=0.2",
                             "gear.profile_shift_gear=-0.2", "gear.face_width_pinion_mm=30",
                             "gear.face_width_gear_mm=30", "gear.bore_diameter_pinion_mm=30",
                             "gear.bore_diameter_gear_mm=60", "operating.speed_rpm=1500", "operating.torque_nm=120",
                             "clearance.backlash_um=80", "excitation.stiffness=rectangular", NULL};

/* A case of base with the extra assignments. */
static void make(gd_case *c, const char *const *base, const char *const *extra)
{
    const char *sets[64];
    int n = 0;
    for (int i = 0; base && base[i]; i++)
        sets[n++] = base[i];
    for (int i = 0; extra && extra[i]; i++)
        sets[n++] = extra[i];
    sets[n] = NULL;
    pu_case(c, sets);
}

static void two_mass(void)
{
    gd_case c;
    gd_model m;
    const char *tors[] = {"scene.model=torsional", NULL};
    make(&c, spur, tors);
    gd_modal md = modes_of(&c, &m);
    tap_ok(md.nmodes == 1 && md.nrigid == 0, "spur torsional: one elastic mode, no rigid one (%d, %d)", md.nmodes,
           md.nrigid);
    TAP_REL(md.freq_hz[0], two_mass_hz(&c), 1e-13, "spur torsional: two-mass closed form (Hz)");
    TAP_REL(md.share[0][elem_index(&md, "mesh")], 1.0, 1e-15, "spur torsional: all strain energy in the mesh");
    TAP_REL(md.resonance_rpm[0][0], 60.0 * two_mass_hz(&c) / 25.0, 1e-13, "spur: main resonance 60 f / z1 (rpm)");
    TAP_REL(md.resonance_rpm[0][2], md.resonance_rpm[0][0] / 3.0, 1e-15, "spur: superharmonic at 1/3 of it");
    gd_case_free(&c);

    make(&c, NULL, tors); /* the paper's herringbone: per half */
    md = modes_of(&c, &m);
    tap_ok(md.nmodes == 1, "herringbone torsional: one mode");
    TAP_REL(md.freq_hz[0], two_mass_hz(&c), 1e-13, "herringbone torsional: two-mass closed form of a half (Hz)");
    TAP_REL(md.freq_hz[0], 1617.5288, 1e-7, "herringbone torsional: 1617.53 Hz (docs/model.md 9.5)");
    gd_case_free(&c);
}

/* K of the modal analysis against the model's Jacobian and the central differences of its RHS at
 * the static state; the Rayleigh quotient of every mode with that K. */
static void stiffness_and_energy(const char *label, const char *const *sets)
{
    gd_case c;
    gd_model m;
    make(&c, sets, NULL);
    gd_modal md = modes_of(&c, &m);
    const int nd = m.ndof, n = m.n;
    gd_modes mo;
    memset(&mo, 0, sizeof mo);
    double y[GD_MAX_STATE];
    gd_error e = {0};
    PU_CHECK(gd_model_static_state(&m, y, &mo, &e), &e);
    for (int c2 = 0; c2 < m.nclear; c2++)
        tap_ok(mo.mode[c2] == md.contact[c2], "%s: %s linearised in its static contact mode %d", label,
               m.clear[c2].name, mo.mode[c2]);
    double K[GD_MAX_DOF * GD_MAX_DOF];
    PU_CHECK(gd_modal_stiffness(&m, &mo, K, &e), &e);
    /* the model with each mesh at its mean stiffness as a constant one: its Jacobian is -M^-1 K */
    gd_model mc = m;
    for (int j = 0; j < m.nmesh; j++) {
        mc.mesh[j].kind = GD_STIFF_CONSTANT;
        mc.clear[m.mesh_clear[j]].k *= gd_modal_mean_stiffness(&m, j);
    }
    static double J[GD_MAX_STATE * GD_MAX_STATE];
    gd_model_jacobian(&mc, 0.0, y, J, &mo);
    double djac = 0.0, dfd = 0.0, kmax = 0.0;
    /* central differences: the RHS is linear in the positions within the held modes, so any step
     * inside them gives the derivative to rounding; 1e-3 of the static mesh deflection */
    double h = 1e-3 * m.F0[m.q_dof[0]] / mc.clear[m.mesh_clear[0]].k;
    for (int j = 0; j < nd; j++) {
        double yp[GD_MAX_STATE], ym[GD_MAX_STATE], fp[GD_MAX_STATE], fm[GD_MAX_STATE];
        memcpy(yp, y, sizeof yp);
        memcpy(ym, y, sizeof ym);
        yp[j] += h;
        ym[j] -= h;
        gd_model_rhs(&mc, 0.0, yp, fp, &mo);
        gd_model_rhs(&mc, 0.0, ym, fm, &mo);
        for (int i = 0; i < nd; i++) {
            double kij = K[i * nd + j];
            kmax = fmax(kmax, fabs(kij));
            djac = fmax(djac, fabs(-m.mass[i] * J[(nd + i) * n + j] - kij));
            dfd = fmax(dfd, fabs(-m.mass[i] * (fp[nd + i] - fm[nd + i]) / (2.0 * h) - kij));
        }
    }
    tap_ok(djac <= 1e-14 * kmax, "%s: K = -M J of gd_model_jacobian (max diff %.3g of %.3g)", label, djac, kmax);
    tap_ok(dfd <= 1e-8 * kmax, "%s: K = central differences of the RHS, step %.3g (max diff %.3g of %.3g)", label, h,
           dfd, kmax);
    double worst = 0.0, worst_sum = 0.0;
    for (int k = 0; k < md.nmodes; k++) {
        /* the shape back to mass-normalised: phi.M.phi = 1 */
        double nrm = 0.0, q = 0.0, strain = 0.0, sum = 0.0;
        for (int i = 0; i < nd; i++)
            nrm += m.mass[i] * md.shape[k][i] * md.shape[k][i];
        for (int i = 0; i < nd; i++)
            for (int j = 0; j < nd; j++)
                q += md.shape[k][i] * K[i * nd + j] * md.shape[k][j];
        for (int el = 0; el < md.nelem; el++) {
            strain += md.strain[k][el];
            sum += md.share[k][el];
        }
        worst = fmax(worst, fabs(2.0 * strain - q / nrm) / md.lambda[k]);
        worst = fmax(worst, fabs(q / nrm - md.lambda[k]) / md.lambda[k]);
        worst_sum = fmax(worst_sum, fabs(sum - 1.0));
    }
    tap_ok(worst <= 1e-10, "%s: every mode's element strain energies add up to omega^2/2 = phi.K.phi/2 (worst rel %.3g)",
           label, worst);
    tap_ok(worst_sum <= 1e-13, "%s: the shares of every mode sum to 1 (worst %.3g)", label, worst_sum);
    gd_case_free(&c);
}

/* bta of the spur pair with stiff supports reduces to torsional: the mesh mode's frequency
 * approaches the torsional one with an error ~ 1 / scale. */
static void stiff_supports(void)
{
    gd_case c;
    gd_model m;
    const char *tors[] = {"scene.model=torsional", NULL};
    make(&c, spur, tors);
    double ft = modes_of(&c, &m).freq_hz[0];
    gd_case_free(&c);
    double prev = NAN;
    for (int p = 2; p <= 4; p++) {
        char a[4][80];
        double s = pow(10.0, p);
        snprintf(a[0], sizeof a[0], "support.radial_stiffness_pinion_n_per_m=%g", 1e9 * s);
        snprintf(a[1], sizeof a[1], "support.radial_stiffness_gear_n_per_m=%g", 1e9 * s);
        snprintf(a[2], sizeof a[2], "support.axial_stiffness_pinion_n_per_m=%g", 5e8 * s);
        snprintf(a[3], sizeof a[3], "support.axial_stiffness_gear_n_per_m=%g", 5e8 * s);
        const char *extra[] = {"scene.model=bta", a[0], a[1], a[2], a[3], NULL};
        make(&c, spur, extra);
        gd_modal md = modes_of(&c, &m);
        int best = 0;
        for (int k = 1; k < md.nmodes; k++)
            if (mesh_share(&m, &md, k) > mesh_share(&m, &md, best))
                best = k;
        double rel = fabs(md.freq_hz[best] - ft) / ft;
        printf("# supports x 1e%d: mesh mode %d at %.6f Hz (mesh share %.6f), torsional %.6f Hz, rel %.3g\n", p,
               best + 1, md.freq_hz[best], mesh_share(&m, &md, best), ft, rel);
        if (p == 4)
            tap_ok(rel < 1e-4, "bta with supports x 1e4: the mesh mode at the torsional frequency (rel %.3g)", rel);
        if (p > 2)
            tap_ok(rel < prev / 8 && rel > prev / 12, "bta supports x 1e%d: the difference falls like 1/scale (%.3g "
                   "after %.3g)", p, rel, prev);
        prev = rel;
        if (p == 2) { /* the axial modes of a spur pair: each body alone on its axial support */
            double fz1 = sqrt(c.axial_stiffness_pinion_n_per_m / c.pinion_mass_kg) / (2 * M_PI),
                   fz2 = sqrt(c.axial_stiffness_gear_n_per_m / c.gear_mass_kg) / (2 * M_PI);
            int e1 = elem_index(&md, "axial-1"), e2 = elem_index(&md, "axial-2"), ok1 = 0, ok2 = 0;
            for (int k = 0; k < md.nmodes; k++) {
                ok1 |= md.share[k][e1] > 1 - 1e-12 && fabs(md.freq_hz[k] - fz1) <= 1e-12 * fz1;
                ok2 |= md.share[k][e2] > 1 - 1e-12 && fabs(md.freq_hz[k] - fz2) <= 1e-12 * fz2;
            }
            tap_ok(ok1 && ok2, "bta spur: axial modes sqrt(k_z/m) of each body (%.6g, %.6g Hz)", fz1, fz2);
        }
        gd_case_free(&c);
    }
}

/* The symmetric herringbone: mirror classes, equal halves, degenerate pairs split, the floating
 * pinion's rigid-body mode. */
static void herringbone(void)
{
    gd_case c;
    gd_model m;
    const char *bta[] = {"scene.model=bta", NULL};
    make(&c, NULL, bta);
    gd_modal md = modes_of(&c, &m);
    int ok = md.mirrored && md.nmodes == 10 && md.nrigid == 0, nsym = 0;
    double worst = 0.0, worst_mesh = 0.0;
    int eL = elem_index(&md, "mesh-L"), eR = elem_index(&md, "mesh-R");
    for (int k = 0; k < md.nmodes; k++) {
        double s = md.mirror_corr[k] > 0 ? 1.0 : -1.0;
        nsym += s > 0;
        worst = fmax(worst, fabs(fabs(md.mirror_corr[k]) - 1.0));
        for (int i = 0; i < 10; i++) {
            double sg = (i % 5 == 1 || i % 5 == 3) ? -1.0 : 1.0;
            worst = fmax(worst, fabs(md.shape[k][(i + 5) % 10] * sg * s - md.shape[k][i]));
        }
        worst_mesh = fmax(worst_mesh, fabs(md.share[k][eL] - md.share[k][eR]));
    }
    tap_ok(ok && worst < 1e-9, "paper's bta: 10 modes, each symmetric or antisymmetric under the mirror (worst %.3g)",
           worst);
    tap_ok(nsym == 5, "paper's bta: 5 symmetric and 5 antisymmetric modes (%d symmetric)", nsym);
    tap_ok(worst_mesh < 1e-10, "paper's bta: both meshes carry the same share in every mode (worst %.3g)", worst_mesh);
    /* the figures of docs/model.md section 9.6 */
    TAP_REL(md.freq_hz[6], 2239.485, 1e-6, "paper's bta: mode 7, the symmetric mesh mode (Hz)");
    tap_ok(md.mirror_corr[6] > 0 && mesh_share(&m, &md, 6) > 0.76, "paper's bta: mode 7 symmetric, 76 %% mesh (%.4f)",
           mesh_share(&m, &md, 6));
    TAP_REL(md.freq_hz[7], 2352.405, 1e-6, "paper's bta: mode 8, the antisymmetric mesh mode (Hz)");
    gd_case_free(&c);

    /* torsional-lr: two equal frequencies, split into the symmetric and antisymmetric pair */
    const char *lr[] = {"scene.model=torsional-lr", NULL};
    make(&c, NULL, lr);
    md = modes_of(&c, &m);
    ok = md.mirrored && md.nmodes == 2 && fabs(md.freq_hz[1] - md.freq_hz[0]) <= 1e-12 * md.freq_hz[0];
    ok = ok && md.mirror_corr[0] > 0 && fabs(md.shape[0][0] - 1) < 1e-12 && fabs(md.shape[0][1] - 1) < 1e-12;
    ok = ok && md.mirror_corr[1] < 0 && fabs(md.shape[1][0] - 1) < 1e-12 && fabs(md.shape[1][1] + 1) < 1e-12;
    tap_ok(ok, "torsional-lr: one frequency twice, shapes (1, 1) symmetric and (1, -1) antisymmetric "
           "((%.3g, %.3g), (%.3g, %.3g))", md.shape[0][0], md.shape[0][1], md.shape[1][0], md.shape[1][1]);
    gd_case_free(&c);

    /* the floating pinion: one rigid-body mode, z1L = z1R = d, qL = -sin(beta_b) d, qR = +sin(beta_b) d */
    const char *fl[] = {"scene.model=bta", "support.axial_stiffness_pinion_n_per_m=0", NULL};
    make(&c, NULL, fl);
    md = modes_of(&c, &m);
    gd_geometry g;
    gd_error e = {0};
    const gd_pair pair = gd_pair_from_case(&c);
    PU_CHECK(gd_geometry_compute(&pair, &g, &e), &e);
    double sb = sin(g.beta_b), want[10] = {0, 1, 0, 0, -sb, 0, 1, 0, 0, sb}, d = 0;
    for (int i = 0; md.nrigid == 1 && i < 10; i++)
        d = fmax(d, fabs(md.rigid_shape[0][i] - want[i]));
    tap_ok(md.nrigid == 1 && md.nmodes == 9 && d < 1e-9, "floating pinion: one rigid-body mode (z1L = z1R = 1, qL = "
           "-qR = -sin beta_b = %.6f) kept out of 9 elastic modes (%d rigid, diff %.3g)", -sb, md.nrigid, d);
    gd_case_free(&c);

    /* halves of unequal stiffness: the mirror no longer maps the model onto itself */
    const char *un[] = {"scene.model=bta", "excitation.stiffness=rectangular", NULL};
    make(&c, NULL, un);
    pu_build(&c, &m);
    m.clear[m.mesh_clear[1]].k *= 1.1;
    gd_modes mo;
    memset(&mo, 0, sizeof mo);
    double y[GD_MAX_STATE];
    PU_CHECK(gd_model_static_state(&m, y, &mo, &e), &e);
    gd_modal_mirror mir;
    for (int i = 0; i < 10; i++) {
        mir.dof[i] = (i + 5) % 10;
        mir.sign[i] = (i % 5 == 1 || i % 5 == 3) ? -1.0 : 1.0;
    }
    PU_CHECK(gd_modal_analyse(&m, &mo, &mir, &md, &e), &e);
    tap_ok(!md.mirrored, "halves of unequal stiffness: not called symmetric");
    gd_case_free(&c);
}

/* The NASA Glenn spur pair (28/28, module 3.175 mm, 20 deg, face 6.35 mm, solid blanks, 72 N m):
 * the largest RMS acceleration of a speed sweep at the predicted main resonance of the mesh mode. */
static void sweep_peak(const char *model, double from, double to, int points, int sdof)
{
    char a[4][64];
    snprintf(a[0], sizeof a[0], "scene.model=%s", model);
    snprintf(a[1], sizeof a[1], "sweep.from=%g", from);
    snprintf(a[2], sizeof a[2], "sweep.to=%g", to);
    snprintf(a[3], sizeof a[3], "sweep.points=%d", points);
    const char *sets[] = {"scene.analysis=sweep", "gear.arrangement=spur", "gear.normal_module_mm=3.175",
                          "gear.teeth_pinion=28", "gear.teeth_gear=28", "gear.helix_angle_deg=0",
                          "gear.face_width_pinion_mm=6.35", "gear.face_width_gear_mm=6.35",
                          "gear.bore_diameter_pinion_mm=0", "gear.bore_diameter_gear_mm=0", "operating.torque_nm=72",
                          "operating.speed_rpm=4000", "clearance.backlash_um=127", "excitation.stiffness=constant",
                          "excitation.ste_amplitude_um=0.2", "damping.mesh_damping_ratio=0.05",
                          "run.transient_periods=200", "run.record_periods=20", "sweep.parameter=operating.speed_rpm",
                          "sweep.mode=independent", a[0], a[1], a[2], a[3], NULL};
    gd_case c;
    gd_model m;
    pu_case(&c, sets);
    gd_modal md = modes_of(&c, &m);
    int best = 0;
    for (int k = 1; k < md.nmodes; k++)
        if (mesh_share(&m, &md, k) > mesh_share(&m, &md, best))
            best = k;
    double pred = md.resonance_rpm[best][0];
    gd_sweep_plan p;
    gd_sweep_point *pts;
    gd_error e = {0};
    PU_CHECK(gd_sweep_plan_create(&c, &p, &e), &e);
    PU_CHECK(gd_sweep_points_create(&p, &pts, &e), &e);
    gd_sweep_opts o;
    gd_sweep_opts_default(&o);
    PU_CHECK(gd_sweep_run(&c, &p, pts, &o, &e), &e);
    int top = 0, contact = 1;
    for (int s = 0; s < p.nslots; s++) {
        if (pts[s].rms_accel_mps2[2] > pts[top].rms_accel_mps2[2])
            top = s;
        contact &= pts[s].impact_regime[2] == GD_IMPACT_NONE;
    }
    double step = (to - from) / (points - 1), peak = pts[top].value[0];
    printf("# %s: mode %d (mesh share %.3f) at %.2f Hz predicts %.1f rpm; sweep peak %.1f rpm, %.1f m/s^2\n", model,
           best + 1, mesh_share(&m, &md, best), md.freq_hz[best], pred, peak, pts[top].rms_accel_mps2[2]);
    tap_ok(contact, "NASA pair %s: the flanks stay in contact at every point (a linear response)", model);
    tap_ok(fabs(peak - pred) <= step, "NASA pair %s: the sweep's peak %.0f rpm within one step (%.0f rpm) of the "
           "predicted main resonance %.1f rpm", model, peak, step, pred);
    if (sdof) { /* one DOF, damping ratio 0.05: the peak of the acceleration at Omega = sqrt(1 + 6 zeta^2) */
        double damped = pred * sqrt(1.0 + 6.0 * 0.05 * 0.05);
        tap_ok(fabs(peak - damped) <= 0.5 * step, "NASA pair %s: the peak is the grid point nearest the damped "
               "oscillator's %.1f rpm", model, damped);
    }
    gd_sweep_points_free(&p, pts);
    gd_sweep_plan_free(&p);
    gd_case_free(&c);
}

static void custom_refused(void)
{
    gd_custom_system sys = {2, NULL, NULL, NULL, NULL};
    gd_model m;
    gd_model_custom(&m, &sys, 1.0);
    gd_modes mo;
    memset(&mo, 0, sizeof mo);
    gd_modal md;
    gd_error e = {0};
    tap_ok(gd_modal_analyse(&m, &mo, NULL, &md, &e) == GD_ERR_INPUT, "a custom system is refused: %s", e.msg);
}

int main(void)
{
    two_mass();
    const char *bta_spur[] = {"scene.model=bta", "gear.arrangement=spur", "gear.helix_angle_deg=0", NULL};
    stiffness_and_energy("spur torsional", (const char *[]){"scene.model=torsional", "gear.arrangement=spur",
                                                             "gear.helix_angle_deg=0", NULL});
    stiffness_and_energy("spur bta", bta_spur);
    stiffness_and_energy("helical bta", (const char *[]){"scene.model=bta", "gear.arrangement=helical", NULL});
    stiffness_and_energy("herringbone bta, bearing clearance", (const char *[]){"scene.model=bta", NULL});
    stiffness_and_energy("herringbone bta, linear bearings, rectangular",
                         (const char *[]){"scene.model=bta", "scene.bearing_clearance=off",
                                          "excitation.stiffness=rectangular", NULL});
    stiffness_and_energy("herringbone torsional-lr", (const char *[]){"scene.model=torsional-lr", NULL});
    stiff_supports();
    herringbone();
    sweep_peak("bta", 9500, 12000, 26, 0);
    sweep_peak("torsional", 11000, 14000, 31, 1);
    custom_refused();
    return tap_done();
}
