/* Reductions between the three model levels.
 *
 * (a) bta with rigid supports is torsional-lr: there is no 'rigid' switch, so every
 *     support and groove-shaft stiffness is scaled by 1e2 ... 1e5. The support
 *     compliance adds to the mesh compliance in series, so the difference of the mesh
 *     deflections must fall in proportion to 1/scale (a factor of about 10 per decade)
 *     and be small at the stiffest.
 * (b) A symmetric herringbone (identical halves, no stagger) keeps q_L = q_R through
 *     impacts on the flanks and in the bearings, and its halves, being of opposite hand,
 *     move axially in mirror image (z_L = -z_R); a staggered one (half_phase_deg = 90)
 *     does not keep q_L = q_R.
 * (c) torsional-lr with equal halves is the torsional model: mass 1 and stiffness 1 per
 *     half against mass 2 and stiffness 2 for the pair, so the same mesh deflection
 *     history, impacts included. */
#include "physics_util.h"
#include "tap.h"
#include "geardyn/gd_analysis.h"
#include "geardyn/gd_scene.h"

static const char *support_keys[] = {
    "support.radial_stiffness_pinion_n_per_m", "support.radial_stiffness_gear_n_per_m",
    "support.axial_stiffness_pinion_n_per_m",  "support.axial_stiffness_gear_n_per_m",
    "support.shaft_stiffness_pinion_n_per_m",  "support.shaft_stiffness_gear_n_per_m"};

/* A case from a base list, a model and optional extra assignments. */
static void make(gd_case *c, const char *const *base, const char *model, const char *const *extra)
{
    gd_error e;
    memset(&e, 0, sizeof e);
    PU_CHECK(gd_case_init(c, &e), &e);
    c->speed_rpm = 4000, c->torque_nm = 500; /* the paper's operating point: a case must give one */
    for (int i = 0; base[i]; i++)
        pu_set(c, base[i]);
    for (int i = 0; extra && extra[i]; i++)
        pu_set(c, extra[i]);
    char buf[64];
    snprintf(buf, sizeof buf, "scene.model=%s", model);
    pu_set(c, buf);
    PU_CHECK(gd_case_resolve(c, &e), &e);
}

/* Static start, nper periods, samples of periods [rec0, nper). */
static void simulate(const gd_case *c, gd_model *m, long nper, long rec0, int ns, pu_samples *p)
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
    gd_sim_stats st;
    pu_run_sampled_ex(m, &o, y0, &md, nper, rec0, ns, c->exact_samples, p, &st);
    p->m = m;
    printf("#   %s: %ld steps, %ld events\n", c->model == GD_MODEL_BTA ? "bta" : c->model == GD_MODEL_TORSIONAL_LR ?
           "torsional-lr" : "torsional", st.steps, st.events);
}

static double lam(const pu_samples *p, int j, long k)
{
    gd_modes md;
    memset(&md, 0, sizeof md);
    return pu_lambda(p->m, j, p->t[k], p->y + k * p->n, &md);
}

/* RMS of the alternating part of lambda_j. */
static double rms_alt(const pu_samples *p, int j)
{
    double mean = 0, s = 0;
    for (long k = 0; k < p->count; k++)
        mean += lam(p, j, k);
    mean /= (double)p->count;
    for (long k = 0; k < p->count; k++)
        s += (lam(p, j, k) - mean) * (lam(p, j, k) - mean);
    return sqrt(s / (double)p->count);
}

static void rigid_supports(void)
{
    printf("# (a) bta with ever stiffer supports against torsional-lr\n");
    /* no impacts: the mesh stays in contact, the bearings are linear (clearance off) */
    const char *base[] = {"excitation.stiffness=harmonic", "scene.error_excitation=on", "scene.bearing_clearance=off",
                          "excitation.ste_amplitude_um=3", "operating.torque_nm=1500",
                          "damping.mesh_damping_ratio=0.05", "solver.rtol=1e-10", "solver.atol=1e-12",
                          /* a common base for the groove shafts, so that x1e5 stays in range */
                          "support.shaft_stiffness_pinion_n_per_m=1e9", "support.shaft_stiffness_gear_n_per_m=1e9",
                          NULL};
    const long nper = 60, rec0 = 40;
    const int ns = 32;
    gd_case c;
    gd_model mref;
    pu_samples ref;
    make(&c, base, "torsional-lr", NULL);
    simulate(&c, &mref, nper, rec0, ns, &ref);
    gd_case_free(&c);
    double scale_ref = 0.5 * (rms_alt(&ref, 0) + rms_alt(&ref, 1));
    printf("#   torsional-lr: RMS of the alternating mesh deflection %.6g (b_c)\n", scale_ref);
    double prev = NAN;
    for (double sc = 1e2; sc <= 1e5; sc *= 10) {
        make(&c, base, "bta", NULL);
        for (int i = 0; i < 6; i++) {
            double v;
            gd_error e;
            PU_CHECK(gd_case_get_number(&c, support_keys[i], &v, &e), &e);
            pu_set_number(&c, support_keys[i], v * sc);
        }
        gd_error e;
        PU_CHECK(gd_case_resolve(&c, &e), &e);
        gd_model m;
        pu_samples p;
        simulate(&c, &m, nper, rec0, ns, &p);
        double d2 = 0;
        for (long k = 0; k < ref.count; k++)
            for (int j = 0; j < 2; j++) {
                double d = lam(&p, j, k) - lam(&ref, j, k);
                d2 += d * d;
            }
        double rel = sqrt(d2 / (2.0 * (double)ref.count)) / scale_ref;
        char name[160];
        snprintf(name, sizeof name, "supports x%.0e: RMS |lambda_bta - lambda_lr| / RMS alternating lambda", sc);
        tap_ok(isfinite(rel) && rel < 0.1, "%s: %.4e (below 0.1)", name, rel);
        if (isfinite(prev)) {
            snprintf(name, sizeof name, "supports x%.0e: difference falls with the compliance (factor per decade)", sc);
            TAP_CLOSE(prev / rel, 10.0, 2.0, name);
        }
        if (sc == 1e5)
            TAP_CLOSE(rel, 0.0, 1e-4, "stiffest supports: relative difference");
        prev = rel;
        pu_samples_free(&p);
        gd_case_free(&c);
    }
    pu_samples_free(&ref);
}

static void symmetry(void)
{
    printf("# (b) symmetric and staggered herringbone (bta, flank and bearing impacts)\n");
    const char *base[] = {"excitation.stiffness=harmonic", "excitation.stiffness_harmonics=0.2,0.05",
                          "scene.error_excitation=on", "scene.bearing_clearance=on", "scene.axial_coupling=on",
                          NULL};
    const long nper = 200, rec0 = 100;
    const int ns = 32;
    for (int stagger = 0; stagger < 2; stagger++) {
        const char *extra[] = {stagger ? "excitation.half_phase_deg=90" : "excitation.half_phase_deg=0", NULL};
        gd_case c;
        gd_model m;
        pu_samples p;
        make(&c, base, "bta", extra);
        simulate(&c, &m, nper, rec0, ns, &p);
        /* DOFs per half: y1 z1 y2 z2 q (model_build.c); the right half is the mirror image */
        double dq = 0, qs = 0, dl = 0, dz = 0, zs = 0;
        for (long k = 0; k < p.count; k++) {
            const double *y = p.y + k * p.n;
            double qL = y[m.q_dof[0]], qR = y[m.q_dof[1]];
            dq = fmax(dq, fabs(qL - qR));
            qs = fmax(qs, fmax(fabs(qL), fabs(qR)));
            dl = fmax(dl, fabs(lam(&p, 0, k) - lam(&p, 1, k)));
            for (int body = 0; body < 2; body++) {
                double zL = y[1 + 2 * body], zR = y[6 + 2 * body];
                dz = fmax(dz, fabs(zL + zR));
                zs = fmax(zs, fmax(fabs(zL), fabs(zR)));
            }
        }
        gd_response_result r;
        memset(&r, 0, sizeof r);
        gd_error e;
        memset(&e, 0, sizeof e);
        PU_CHECK(gd_response_run(&c, &m, NULL, NULL, NULL, &r, &e), &e);
        printf("#   half phase %d deg: response %s, impacts %s, %ld events in the record; max |qL - qR| / max |q| = "
               "%.3e, max |lambda_L - lambda_R| = %.3e b_c\n", stagger ? 90 : 0, r.motion,
               gd_impact_regime_name(r.impact_regime[2]), r.record_events, dq / qs, dl);
        if (!stagger) {
            tap_ok(r.record_events > 0, "symmetric: the run has impacts (%ld events recorded)", r.record_events);
            TAP_CLOSE(dq / qs, 0.0, 1e-9, "symmetric halves: max |q_L - q_R| / max |q|");
            /* opposite hands: the axial mesh forces of the halves are equal and opposite,
             * so each body's halves move axially in mirror image (z_L = -z_R) */
            printf("#   max axial displacement %.4g b_c\n", zs);
            tap_ok(zs > 1e-3, "symmetric halves: the axial DOFs move (max |z| = %.4g b_c)", zs);
            TAP_CLOSE(dz / zs, 0.0, 1e-9, "symmetric herringbone: max |z_L + z_R| / max |z| (opposite hands)");
        } else {
            tap_ok(dq / qs > 1e-2, "staggered halves (90 deg): q_L and q_R differ: max |q_L - q_R| / max |q| = %.4g "
                   "(above 1e-2)", dq / qs);
        }
        pu_samples_free(&p);
        gd_case_free(&c);
    }
}

static void equal_halves(void)
{
    printf("# (c) torsional-lr with equal halves against torsional (double-sided impacts)\n");
    const char *base[] = {"excitation.stiffness=harmonic", "excitation.stiffness_harmonics=0.2",
                          "scene.error_excitation=on", "excitation.ste_amplitude_um=12", "operating.torque_nm=300",
                          "solver.rtol=1e-13", "solver.atol=1e-15", "solver.exact_samples=on", NULL};
    const long nper = 200, rec0 = 0;
    const int ns = 32;
    gd_case c1, c2;
    gd_model m1, m2;
    pu_samples p1, p2;
    make(&c1, base, "torsional", NULL);
    make(&c2, base, "torsional-lr", NULL);
    simulate(&c1, &m1, nper, rec0, ns, &p1);
    simulate(&c2, &m2, nper, rec0, ns, &p2);
    double dmax = 0, lmax = 0, lmin = INFINITY;
    for (long k = 0; k < p1.count; k++) {
        double a = lam(&p1, 0, k);
        lmax = fmax(lmax, fabs(a));
        lmin = fmin(lmin, a);
        for (int j = 0; j < 2; j++)
            dmax = fmax(dmax, fabs(lam(&p2, j, k) - a));
    }
    printf("#   min lambda %.6g (half backlash %.6g)\n", lmin, m1.clear[0].h);
    tap_ok(lmin < -m1.clear[0].h, "the run reaches the back flank: min lambda %.6g < -h = %.6g", lmin, -m1.clear[0].h);
    TAP_CLOSE(dmax / lmax, 0.0, 1e-11, "max |lambda_{L,R} - lambda_torsional| / max |lambda| over 200 periods");
    pu_samples_free(&p1);
    pu_samples_free(&p2);
    gd_case_free(&c1);
    gd_case_free(&c2);
}

int main(void)
{
    rigid_supports();
    symmetry();
    equal_halves();
    return tap_done();
}
