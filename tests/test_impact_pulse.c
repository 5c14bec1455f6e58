/* The mesh-in impact pulse in the dynamic model (excitation.impact = on; docs/model.md section 8.4).
 *
 * (1) The force applied is the force reported: for every model level and arrangement (herringbone
 *     torsional, torsional-lr and bta; helical and spur torsional and bta), the pulse the model's
 *     mesh receives at each half's mesh-in phase (the RHS with the pulses less the RHS of the same
 *     case without them, times the mass of the mesh coordinate) equals derived.model.impact of
 *     summary.json for that half, to rounding. The torsional model of a herringbone receives both
 *     halves' pulses, each at its own phase with its own force; a single pair's torsional model
 *     one, not two.
 * (2) The torsional model of a herringbone is the mean of its two halves (torsional-lr) at every
 *     time of the cycle, pulses included: a_tor(t) = (a_L(t) + a_R(t)) / 2 at a common state.
 * (3) Single-pair torsional = stiff-support bta with impact = on: the NASA Glenn gear-noise-rig
 *     spur pair at 5000 rpm (period-2 with impacts) in both models, supports of 1e13 N/m, the same
 *     mesh deflection (the supports' compliance in series: a relative difference below 1e-4).
 * (4) The impulse of a pulse is m_n v_s, the momentum that stops the approach of the incoming pair,
 *     at every speed while the rectangle of peak F_s and that impulse fits in a mesh period (the
 *     NASA pair at 1000 to 6000 rpm: it grows as the speed); beyond it, the paper's pair at 7000 rpm,
 *     F_s acts for the whole period (the impulse F_s T_m, below m_n v_s). The paper's form keeps
 *     F_s for the rise time capped at a quarter period.
 * (5) No mesh force inside the backlash with damping in contact only and the pulse gated by
 *     contact: every sample of a run with impacts whose deflection lies inside the backlash has a
 *     mesh force of exactly 0 (torsional and bta, the NASA pair at 4000 rpm), while such samples
 *     exist and the pulse acts elsewhere; with the paper's form the pulse shows inside it. */
#include "physics_util.h"
#include "pair_util.h"
#include "tap.h"
#include "geardyn/gd_excitation.h"
#include "geardyn/gd_output.h"

#include <ftw.h>
#include <jansson.h>
#include <unistd.h>

/* the NASA Glenn gear-noise-rig spur pair as commonly described (backlash and blanks assumed) */
#define NASA "gear.arrangement=spur", "gear.normal_module_mm=3.175", "gear.teeth_pinion=28", "gear.teeth_gear=28", \
             "gear.helix_angle_deg=0", "gear.face_width_pinion_mm=6.35", "gear.face_width_gear_mm=6.35",           \
             "operating.torque_nm=72", "clearance.backlash_um=127", "excitation.stiffness=ltca",                   \
             "excitation.impact=on"
/* the paper's herringbone with its misalignment (the halves' impacts differ), a coarse LTCA */
#define PAPER "operating.torque_nm=500", "misalignment.axis_in_plane_arcmin=-0.35355339",                          \
              "misalignment.axis_cross_plane_arcmin=0.35355339", "misalignment.centre_distance_error_mm=0.1",      \
              "excitation.stiffness=ltca", "excitation.impact=on", "solver.ltca_positions_per_cycle=16",          \
              "solver.ltca_face_slices=11"

static char tmpdir[] = "/tmp/geardyn_impact_XXXXXX";

static int rm_entry(const char *p, const struct stat *sb, int flag, struct FTW *ftw)
{
    (void)sb, (void)flag, (void)ftw;
    return remove(p);
}

/* a case from the list sets plus up to four more assignments */
static void make(gd_case *c, const char *const *sets, const char *a, const char *b, const char *d, const char *f)
{
    const char *all[40];
    int n = 0;
    for (int i = 0; sets[i]; i++)
        all[n++] = sets[i];
    const char *more[] = {a, b, d, f};
    for (int i = 0; i < 4; i++)
        if (more[i])
            all[n++] = more[i];
    all[n] = NULL;
    pu_case(c, all);
}

/* summary.json of a short response of c (derived.model.impact is what this test reads) */
static json_t *summary_of(const gd_case *c, const char *name)
{
    gd_error e = {0};
    char dir[2048];
    snprintf(dir, sizeof dir, "%s/%s", tmpdir, name);
    const gd_analysis_type *a = gd_analysis_find(GD_ANALYSIS_RESPONSE);
    gd_run_env env;
    memset(&env, 0, sizeof env);
    gd_run_dir *out;
    void *res = NULL;
    PU_CHECK(gd_run_dir_open(dir, &out, &e), &e);
    PU_CHECK(a->run(c, &env, out, &res, &e), &e);
    PU_CHECK(a->write(c, res, out, &e), &e);
    PU_CHECK(a->summary(c, res, out, &e), &e);
    PU_CHECK(gd_run_dir_publish(out, &e), &e);
    gd_run_dir_close(out);
    a->free(res);
    char path[2100];
    snprintf(path, sizeof path, "%s/summary.json", dir);
    json_error_t je;
    json_t *root = json_load_file(path, 0, &je);
    if (!root) {
        printf("Bail out! %s: %s\n", path, je.text);
        exit(1);
    }
    return root;
}

static double jnum(json_t *o, const char *k)
{
    json_t *v = o ? json_object_get(o, k) : NULL;
    return v && json_is_number(v) ? json_number_value(v) : NAN;
}

/* The pulse force (N) the model's mesh j receives at dimensionless time t: the acceleration of its
 * mesh coordinate with the pulses (m) less without (m0, the same case with impact = off), at the
 * state y in drive-side contact, times the coordinate's mass; the modes follow the state. */
static double applied(const gd_model *m, const gd_model *m0, int j, double t, const double *y)
{
    gd_modes md;
    memset(&md, 0, sizeof md);
    md.from_state = 1;
    double a[GD_MAX_STATE], a0[GD_MAX_STATE];
    gd_model_rhs(m, t, y, a, &md);
    gd_model_rhs(m0, t, y, a0, &md);
    int q = m->q_dof[j];
    return -(a[m->ndof + q] - a0[m->ndof + q]) * m->mass[q] * m->k_ref * m->bc_m;
}

/* (1) for one model level and arrangement */
static void force_reported(const char *label, const char *const *sets, const char *model)
{
    gd_error e = {0};
    gd_case c, c0;
    make(&c, sets, model, "run.transient_periods=1", "run.record_periods=1", "run.lyapunov_exponents=0");
    make(&c0, sets, model, "excitation.impact=off", NULL, NULL);
    gd_model m, m0;
    pu_build(&c, &m);
    pu_build(&c0, &m0);
    char name[64];
    snprintf(name, sizeof name, "s%d", (int)(label[0]) + (int)strlen(label) + (int)strlen(model));
    json_t *root = summary_of(&c, name);
    json_t *imp = json_object_get(json_object_get(json_object_get(root, "derived"), "model"), "impact");
    double y[GD_MAX_STATE];
    gd_modes md;
    memset(&md, 0, sizeof md);
    PU_CHECK(gd_model_static_state(&m, y, &md, &e), &e);
    int herring = c.arrangement == GD_ARR_HERRINGBONE, nh = herring ? 2 : 1;
    double F[2], ph[2], dur[2];
    int ok = 1, checked = 0;
    for (int h = 0; h < nh; h++) {
        json_t *o = json_object_get(imp, herring ? (h ? "right" : "left") : "mesh");
        F[h] = jnum(o, "force_n"), ph[h] = jnum(o, "phase_of_mesh_cycle"), dur[h] = jnum(o, "duration_s");
        if (!isfinite(F[h]) || !isfinite(ph[h]) || !isfinite(dur[h])) {
            ok = 0;
            printf("#   %s %s: summary.json has no impact for the %s\n", label, model,
                   herring ? (h ? "right half" : "left half") : "mesh");
        }
    }
    double worst = 0;
    for (int h = 0; ok && h < nh; h++) {
        /* just after the half's mesh-in, on the mesh of the half (the torsional model's one mesh
         * carries both): the reported pulses of that mesh in their phases then */
        int j = m.nmesh == 1 ? 0 : h;
        double cyc = ph[h] + 1e-4, t = 2.0 * M_PI * cyc / m.Omega, want = 0;
        for (int p = 0; p < nh; p++) {
            if (m.nmesh != 1 && p != h)
                continue;
            double f = cyc - ph[p];
            f -= floor(f);
            if (f < dur[p] * m.mesh_freq_hz)
                want += F[p];
        }
        double Fa = applied(&m, &m0, j, t, y);
        printf("#   %s, %s, %s: applied %.9g N at phase %.6f, reported %.9g N (its pulse %.9g N)\n", label, model,
               herring ? (h ? "right" : "left") : "mesh", Fa, cyc, want, F[h]);
        worst = fmax(worst, fabs(Fa - want) / F[h]);
        checked++;
    }
    tap_ok(ok && checked == (herring ? 2 : 1) && worst < 1e-9,
           "%s, %s: the pulse force applied at each mesh-in = summary.json's (%d pulse(s), largest difference %.3g)",
           label, model, checked, worst);
    json_decref(root);
    gd_case_free(&c);
    gd_case_free(&c0);
}

/* (2) a_tor = (a_L + a_R)/2 at every time of the cycle at a common state */
static void torsional_is_mean(void)
{
    const char *sets[] = {PAPER, "operating.speed_rpm=2000", NULL};
    gd_case ct, clr;
    make(&ct, sets, "scene.model=torsional", NULL, NULL, NULL);
    make(&clr, sets, "scene.model=torsional-lr", NULL, NULL, NULL);
    gd_model mt, mlr;
    pu_build(&ct, &mt);
    pu_build(&clr, &mlr);
    gd_error e = {0};
    double y[GD_MAX_STATE], ylr[GD_MAX_STATE] = {0};
    gd_modes md;
    memset(&md, 0, sizeof md);
    PU_CHECK(gd_model_static_state(&mt, y, &md, &e), &e);
    ylr[0] = ylr[1] = y[0];
    double worst = 0, scale = 0, fmaxp = 0;
    gd_modes ms;
    memset(&ms, 0, sizeof ms);
    ms.from_state = 1;
    for (int i = 0; i < 4096; i++) {
        double t = mt.period * i / 4096.0, at[GD_MAX_STATE], al[GD_MAX_STATE];
        gd_model_rhs(&mt, t, y, at, &ms);
        gd_model_rhs(&mlr, t, ylr, al, &ms);
        double mean = 0.5 * (al[2] + al[3]);
        worst = fmax(worst, fabs(at[1] - mean));
        scale = fmax(scale, fabs(mean));
        fmaxp = fmax(fmaxp, fabs(at[1]));
    }
    tap_ok(worst <= 1e-12 * scale, "herringbone: the torsional model's acceleration = the mean of its halves' "
           "(torsional-lr) at 4096 times of the cycle, pulses included (largest difference %.3g of %.3g)", worst, scale);
    gd_case_free(&ct);
    gd_case_free(&clr);
}

typedef struct lam_hist {
    long n, cap;
    double *lam, *force;
    double h_um, lmin, lmax;
} lam_hist;

static int on_sample(void *user, const gd_sample *s)
{
    lam_hist *l = user;
    if (l->n < l->cap) {
        l->lam[l->n] = s->lambda_um[0];
        l->force[l->n] = s->force_n[0];
        l->n++;
    }
    return 0;
}

static void response(const gd_case *c, lam_hist *l, gd_response_result *r)
{
    gd_error e = {0};
    gd_model m;
    pu_build(c, &m);
    l->cap = (long)c->record_periods * c->samples_per_period + 8;
    l->n = 0;
    l->lam = calloc((size_t)l->cap, sizeof(double));
    l->force = calloc((size_t)l->cap, sizeof(double));
    l->h_um = 0.5 * c->backlash_um;
    gd_response_hooks hk = {on_sample, NULL, NULL, NULL};
    memset(r, 0, sizeof *r);
    PU_CHECK(gd_response_run(c, &m, NULL, &hk, l, r, &e), &e);
}

/* (3) single-pair torsional = stiff-support bta with impact = on */
static void torsional_is_stiff_bta(void)
{
    const char *sets[] = {NASA, "operating.speed_rpm=5000", "run.transient_periods=200", "run.record_periods=40",
                          "run.lyapunov_exponents=0", "solver.rtol=1e-11", "solver.atol=1e-13",
                          "solver.exact_samples=on", NULL};
    gd_case ct, cb;
    make(&ct, sets, "scene.model=torsional", NULL, NULL, NULL);
    const char *stiff[] = {NASA, "operating.speed_rpm=5000", "run.transient_periods=200", "run.record_periods=40",
                           "run.lyapunov_exponents=0", "solver.rtol=1e-11", "solver.atol=1e-13",
                           "solver.exact_samples=on", "scene.bearing_clearance=off",
                           "support.radial_stiffness_pinion_n_per_m=1e13", "support.radial_stiffness_gear_n_per_m=1e13",
                           "support.axial_stiffness_pinion_n_per_m=1e13", NULL};
    make(&cb, stiff, "scene.model=bta", "support.axial_stiffness_gear_n_per_m=1e13", NULL, NULL);
    lam_hist lt, lb;
    gd_response_result rt, rb;
    response(&ct, &lt, &rt);
    response(&cb, &lb, &rb);
    double d = 0, sc = 0;
    for (long i = 0; i < lt.n && i < lb.n; i++) {
        d = fmax(d, fabs(lt.lam[i] - lb.lam[i]));
        sc = fmax(sc, fabs(lt.lam[i]));
    }
    printf("#   torsional: %s, %s, %ld events; bta: %s, %s, %ld events; deflection %.6f..%.6f / %.6f..%.6f um\n",
           rt.motion, gd_impact_regime_name(rt.impact_regime[2]), rt.record_events, rb.motion,
           gd_impact_regime_name(rb.impact_regime[2]), rb.record_events, rt.lambda_min_um[0], rt.lambda_max_um[0],
           rb.lambda_min_um[0], rb.lambda_max_um[0]);
    tap_ok(rt.record_events > 0 && rt.record_events == rb.record_events,
           "NASA spur pair, 5000 rpm, impact on: torsional and stiff-support bta have the same impacts (%ld, %ld events)",
           rt.record_events, rb.record_events);
    tap_ok(lt.n == lb.n && lt.n > 0 && d < 1e-4 * sc,
           "and the same mesh deflection at every sample (largest difference %.3g um of %.4g um)", d, sc);
    free(lt.lam), free(lt.force), free(lb.lam), free(lb.force);
    gd_case_free(&ct);
    gd_case_free(&cb);
}

/* the pulse of mesh 0 over one cycle from the RHS (from the state: its width is the time where it
 * acts): its force while it acts (N), its duration (s) and impulse (N s) */
static void pulse_of(const gd_case *c, double *F, double *dur, double *J)
{
    gd_error e = {0};
    gd_model m, m0;
    pu_build(c, &m);
    for (int j = 0; j < m.nmesh; j++) /* no error: the static state touches for the whole cycle */
        m.mesh[j].e_r = 0.0;
    m0 = m;
    for (int j = 0; j < m0.nmesh; j++) /* the same model with pulses of no force */
        memset(&m0.mesh[j].imp_force, 0, sizeof m0.mesh[j].imp_force);
    double y[GD_MAX_STATE];
    gd_modes md;
    memset(&md, 0, sizeof md);
    PU_CHECK(gd_model_static_state(&m, y, &md, &e), &e);
    const int N = 200000;
    double sum = 0, fmx = 0;
    long on = 0;
    for (int i = 0; i < N; i++) {
        double t = m.period * (i + 0.5) / N, f = applied(&m, &m0, 0, t, y);
        sum += f;
        fmx = fmax(fmx, f);
        on += f > 0;
    }
    double Tm = 1.0 / m.mesh_freq_hz;
    *F = fmx;
    *dur = Tm * (double)on / N;
    *J = sum * Tm / N;
}

/* (4) the impulse against m_n v_s */
static void impulse(void)
{
    gd_error e = {0};
    const char *sets[] = {NASA, NULL};
    double prev = 0;
    int grows = 1;
    for (int k = 0; k < 4; k++) {
        static const char *speed[] = {"operating.speed_rpm=1000", "operating.speed_rpm=2000",
                                      "operating.speed_rpm=4000", "operating.speed_rpm=6000"};
        gd_case c;
        make(&c, sets, "scene.model=torsional", speed[k], NULL, NULL);
        gd_model m;
        pu_build(&c, &m);
        const gd_ltca_excitation *x;
        PU_CHECK(gd_ltca_excitation_cached(PAIR_OF(&c), LTCA_SET_OF(&c), &x, &e), &e);
        double vs = fabs(x->impact[0].vs_per_omega) * 2.0 * M_PI * c.speed_rpm / 60.0, mv = m.m_ref * vs;
        double Fs, rise;
        gd_impact_force(vs, m.m_ref, x->impact[0].ks, x->impact[0].delta_m, 1.0, &Fs, &rise);
        gd_ltca_excitation_release(x);
        double F, dur, J;
        pulse_of(&c, &F, &dur, &J);
        printf("#   NASA pair, %.0f rpm: v_s %.6f m/s, m_n v_s %.6g N s; pulse %.6g N (F_s %.6g N) for %.4g s, "
               "impulse %.6g N s\n", c.speed_rpm, vs, mv, F, Fs, dur, J);
        TAP_REL(J, mv, 2e-4, "NASA pair: the pulse's impulse = m_n v_s (the momentum that stops the approach)");
        TAP_REL(F, Fs, 1e-12, "and its force = F_s of the energy balance");
        if (k > 0)
            grows &= fabs(J / prev - c.speed_rpm / (k == 1 ? 1000.0 : k == 2 ? 2000.0 : 4000.0)) < 1e-3;
        prev = J;
        gd_case_free(&c);
    }
    tap_ok(grows, "the impulse grows as the speed does (as v_s)");

    /* beyond the limit: the paper's pair at 7000 rpm, where m_n v_s / F_s exceeds the mesh period */
    const char *psets[] = {PAPER, "operating.speed_rpm=7000", "scene.model=torsional-lr", NULL};
    gd_case c;
    pu_case(&c, psets);
    gd_model m;
    pu_build(&c, &m);
    const gd_ltca_excitation *x;
    PU_CHECK(gd_ltca_excitation_cached(PAIR_OF(&c), LTCA_SET_OF(&c), &x, &e), &e);
    double vs = fabs(x->impact[0].vs_per_omega) * 2.0 * M_PI * c.speed_rpm / 60.0, Fs, rise;
    gd_impact_force(vs, m.m_ref, x->impact[0].ks, x->impact[0].delta_m, 1.0, &Fs, &rise);
    gd_ltca_excitation_release(x);
    double F, dur, J, Tm = 1.0 / m.mesh_freq_hz;
    pulse_of(&c, &F, &dur, &J);
    printf("#   paper's pair, 7000 rpm: m_n v_s / F_s = %.4g s, mesh period %.4g s; pulse %.6g N for %.4g s\n",
           m.m_ref * vs / Fs, Tm, F, dur);
    tap_ok(m.m_ref * vs / Fs > Tm && fabs(dur - Tm) < 1e-9 && fabs(F - Fs) < 1e-9 * Fs && J < m.m_ref * vs,
           "beyond the limit F_s acts for the whole period (impulse %.4g N s, below m_n v_s = %.4g N s)", J,
           m.m_ref * vs);
    gd_case_free(&c);
}

/* the paper's form: F_s for the rise time, at most a quarter of the mesh period */
static void paper_form(void)
{
    const char *qsets[] = {PAPER, "operating.speed_rpm=4000", "scene.model=torsional-lr", "excitation.impact_form=paper",
                           NULL};
    gd_case c;
    gd_model m;
    pu_case(&c, qsets);
    pu_build(&c, &m);
    double F, dur, J;
    pulse_of(&c, &F, &dur, &J);
    TAP_CLOSE(dur, 0.25 / m.mesh_freq_hz, 1e-9, "the paper's form at 4000 rpm: a quarter of the mesh period");
    gd_case_free(&c);
}

/* (5) no mesh force inside the backlash */
static void inside_backlash(const char *model, const char *form, int expect_zero)
{
    const char *sets[] = {NASA, "operating.speed_rpm=4000", "run.transient_periods=200", "run.record_periods=60",
                          "run.lyapunov_exponents=0", "damping.mesh_damping_mode=contact", NULL};
    gd_case c;
    make(&c, sets, model, form, NULL, NULL);
    lam_hist l;
    gd_response_result r;
    response(&c, &l, &r);
    long inside = 0, nonzero = 0;
    double worst = 0;
    for (long i = 0; i < l.n; i++) {
        if (fabs(l.lam[i]) < l.h_um * (1.0 - 1e-9)) {
            inside++;
            if (l.force[i] != 0.0)
                nonzero++, worst = fmax(worst, fabs(l.force[i]));
        }
    }
    printf("#   %s, %s: %s, %ld events, %ld of %ld samples inside the backlash, %ld with a force (largest %.6g N)\n",
           model, form ? form : "contact form", gd_impact_regime_name(r.impact_regime[2]), r.record_events, inside,
           l.n, nonzero, worst);
    if (expect_zero)
        tap_ok(inside > 0 && nonzero == 0 && r.record_events > 0,
               "%s, damping and pulse in contact only: no mesh force at the %ld samples inside the backlash", model,
               inside);
    else
        tap_ok(inside > 0 && nonzero > 0, "%s, the paper's form: the pulse acts inside the backlash (%ld samples)",
               model, nonzero);
    free(l.lam), free(l.force);
    gd_case_free(&c);
}

int main(void)
{
    if (!mkdtemp(tmpdir)) {
        printf("Bail out! no temporary directory\n");
        return 1;
    }
    printf("# (1) the force applied is the force reported\n");
    const char *herring[] = {PAPER, "operating.speed_rpm=2000", NULL};
    const char *helical[] = {"gear.arrangement=helical", "gear.helix_angle_deg=15", "gear.face_width_pinion_mm=30",
                             "gear.face_width_gear_mm=30", "operating.torque_nm=300", "operating.speed_rpm=2000",
                             "excitation.stiffness=ltca", "excitation.impact=on", "solver.ltca_positions_per_cycle=16",
                             "solver.ltca_face_slices=11", NULL};
    const char *spur[] = {NASA, "operating.speed_rpm=4000", NULL};
    force_reported("herringbone", herring, "scene.model=torsional");
    force_reported("herringbone", herring, "scene.model=torsional-lr");
    force_reported("herringbone", herring, "scene.model=bta");
    force_reported("helical", helical, "scene.model=torsional");
    force_reported("helical", helical, "scene.model=bta");
    force_reported("spur", spur, "scene.model=torsional");
    force_reported("spur", spur, "scene.model=bta");
    printf("# (2) the herringbone's torsional model is the mean of its halves\n");
    torsional_is_mean();
    printf("# (3) single-pair torsional = stiff-support bta, impact on\n");
    torsional_is_stiff_bta();
    printf("# (4) the impulse\n");
    impulse();
    printf("# (5) no mesh force inside the backlash\n");
    inside_backlash("scene.model=torsional", NULL, 1);
    inside_backlash("scene.model=bta", NULL, 1);
    printf("# the paper's form\n");
    paper_form();
    inside_backlash("scene.model=torsional", "excitation.impact_form=paper", 0);
    nftw(tmpdir, rm_entry, 16, FTW_DEPTH | FTW_PHYS);
    return tap_done();
}
