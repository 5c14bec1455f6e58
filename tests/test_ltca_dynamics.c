/* The LTCA excitations in the dynamic model (excitation.stiffness = ltca, excitation.impact = on):
 * the model's stiffness passes through every LTCA sample of each half; the derived mean mesh
 * stiffness is the halves' mean; LTCA is computed once for a sweep over speed (cache); the impact
 * force follows the energy balance F_s = v_s sqrt(m k_s), grows with speed as v_s does, and tip
 * relief lowers it; with excitation.ste = ltca the quasi-static model reproduces LTCA's loaded
 * transmission error of each half. */
#include "geardyn/geardyn.h"
#include "pair_util.h"
#include "tap.h"

#include <string.h>

static void base(gd_case *c, const char *const *extra)
{
    gd_error e = {0};
    gd_case_init(c, &e);
    c->speed_rpm = 4000, c->torque_nm = 500; /* the paper's operating point: a case must give one */
    const char *sets[] = {"scene.model=torsional-lr", "excitation.stiffness=ltca", "excitation.impact=on",
                          "operating.torque_nm=500", "solver.ltca_positions_per_cycle=32", NULL};
    for (int i = 0; sets[i]; i++)
        gd_case_set(c, sets[i], i, &e);
    for (int i = 0; extra && extra[i]; i++)
        if (gd_case_set(c, extra[i], 10 + i, &e) != GD_OK)
            printf("# %s\n", e.msg);
    if (gd_case_resolve(c, &e) != GD_OK)
        printf("Bail out! %s\n", e.msg);
}

/* excitation.ste = ltca: (a) on the paper's pair, misaligned and modified (torsional-lr, each half
 * its own TE), the model's quasi-static mesh coordinate e(t) + F/k(t) at the LTCA positions is each
 * half's loaded approach -LTE r_b2 cos(beta_b) but for a constant; (b) a response of the guide's
 * single-helical pair at 20 rpm (quasi-static: the mesh frequency 1/675 of the natural one) has the
 * dynamic transmission error of LTCA's loaded TE, peak to peak, where the sinusoid of
 * ste_amplitude_um gives its 20 um. */
static void ste_ltca(void)
{
    gd_error e = {0};
    gd_case c;
    gd_model m;
    const char *ex[] = {"excitation.ste=ltca", "excitation.impact=off", "misalignment.axis_in_plane_arcmin=-0.35355339",
                        "misalignment.axis_cross_plane_arcmin=0.35355339", "modification.tip_relief_amount_um=35",
                        "modification.tip_relief_length_mm=2.5", "modification.lead_relief_inner_um=25",
                        "modification.lead_relief_outer_um=25", "modification.lead_unmodified_length_mm=35", NULL};
    base(&c, ex);
    if (gd_model_build(&c, &m, &e) != GD_OK) {
        tap_ok(0, "ste = ltca: %s", e.msg);
        gd_case_free(&c);
        return;
    }
    const gd_ltca_excitation *x;
    gd_ltca_excitation_cached(PAIR_OF(&c), LTCA_SET_OF(&c), &x, &e);
    gd_geometry g;
    gd_geometry_compute(PAIR_OF(&c), &g, &e);
    gd_modes md = {0};
    double worst = 0, pp = 0;
    for (int j = 0; j < 2; j++) {
        double d0 = NAN, lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i < x->npos; i++) {
            double t = (2.0 * M_PI * i / x->npos) / m.Omega, ev, ed, edd;
            gd_model_error(&m, j, t, &md, &ev, &ed, &edd);
            double q = ev * m.bc_m + m.static_load_n / (gd_model_stiffness(&m, j, t, &md) * m.k_ref);
            double q_ltca = -x->lte_half_arcsec[j][i] * M_PI / (180 * 3600) * g.rb[1] * cos(g.beta_b);
            if (i == 0)
                d0 = q - q_ltca;
            worst = fmax(worst, fabs(q - q_ltca - d0));
            lo = fmin(lo, q_ltca);
            hi = fmax(hi, q_ltca);
        }
        pp = fmax(pp, hi - lo);
    }
    tap_ok(worst <= 1e-9 * pp && pp > 0, "ste = ltca, torsional-lr, both halves: e(t) + F/k(t) at the LTCA positions = "
           "-LTE r_b2 cos(beta_b) + const (largest difference %.3g m of %.3g m peak-to-peak)", worst, pp);
    gd_ltca_excitation_release(x);
    gd_case_free(&c);

    /* (b) the guide's single-helical pair, quasi-static */
    const char *hp[] = {"scene.model=bta", "gear.arrangement=helical", "gear.normal_module_mm=3.5",
                        "gear.teeth_pinion=21", "gear.teeth_gear=67", "gear.helix_angle_deg=20",
                        "gear.profile_shift_pinion=0.3", "gear.profile_shift_gear=-0.1", "gear.face_width_pinion_mm=40",
                        "gear.face_width_gear_mm=38", "modification.tip_relief_amount_um=8",
                        "modification.tip_relief_length_mm=2.5", "modification.lead_relief_inner_um=6",
                        "modification.lead_relief_outer_um=6", "misalignment.axis_cross_plane_arcmin=1",
                        "operating.torque_nm=350", "operating.speed_rpm=20", "clearance.backlash_um=80",
                        "excitation.stiffness=ltca", "run.transient_periods=200", "run.record_periods=20", NULL};
    double dte[2];
    for (int v = 0; v < 2; v++) {
        gd_case_init(&c, &e);
        int k = 0;
        for (; hp[k]; k++)
            gd_case_set(&c, hp[k], k + 1, &e);
        gd_case_set(&c, v ? "excitation.ste=ltca" : "excitation.ste=sinusoid", k + 1, &e);
        gd_response_result r;
        gd_response_opts ro;
        gd_response_opts_default(&ro);
        if (gd_case_resolve(&c, &e) != GD_OK || gd_model_build(&c, &m, &e) != GD_OK ||
            gd_response_run(&c, &m, &ro, NULL, NULL, &r, &e) != GD_OK) {
            tap_ok(0, "single-helical pair at 20 rpm: %s", e.msg);
            gd_case_free(&c);
            return;
        }
        dte[v] = r.dte_pp_um[0];
        if (v) {
            gd_ltca_result lr;
            gd_ltca_run(PAIR_OF(&c), LTCA_SET_OF(&c), &lr, &e);
            gd_geometry_compute(PAIR_OF(&c), &g, &e);
            double lte_um = lr.lte_pp_arcsec * M_PI / (180 * 3600) * g.rb[1] * 1e6;
            TAP_REL(dte[1], lte_um, 5e-3, "ste = ltca, single-helical pair at 20 rpm: the DTE peak-to-peak (um, "
                    "transverse) = LTCA's loaded TE times r_b2");
            tap_ok(dte[0] > 20 * lte_um, "with the sinusoid of the default 10 um instead: %.4g um, %.0f times it",
                   dte[0], dte[0] / lte_um);
            gd_ltca_result_free(&lr);
        }
        gd_case_free(&c);
    }
}

int main(void)
{
    gd_error e = {0};
    gd_case c;
    gd_model m;
    long before = gd_ltca_cache_computations();
    base(&c, NULL);
    tap_ok(gd_model_build(&c, &m, &e) == GD_OK, "model with the LTCA stiffness and impact (%s)", e.msg);
    const gd_ltca_excitation *x;
    gd_ltca_excitation_cached(PAIR_OF(&c), LTCA_SET_OF(&c), &x, &e);
    /* 1. the table passes through the LTCA samples of each half */
    gd_modes md = {0};
    double worst = 0;
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < x->npos; i++) {
            double t = (2.0 * M_PI * i / x->npos) / m.Omega;
            worst = fmax(worst, fabs(gd_model_stiffness(&m, j, t, &md) * m.k_ref - x->k[j][i]) / x->k[j][i]);
        }
    TAP_CLOSE(worst, 0.0, 1e-12, "model stiffness at the LTCA positions = LTCA stiffness (relative, both halves)");
    TAP_REL(c.mesh_stiffness_n_per_m, 0.5 * (x->k_mean[0] + x->k_mean[1]), 1e-14,
            "derived mean mesh stiffness = mean of the halves' LTCA means");
    /* 2. one LTCA for a sweep over speed */
    for (int k = 0; k < 5; k++) {
        gd_case c2;
        gd_model m2;
        char buf[64];
        snprintf(buf, sizeof buf, "operating.speed_rpm=%d", 1000 + 1500 * k);
        const char *extra[] = {buf, NULL};
        base(&c2, extra);
        gd_model_build(&c2, &m2, &e);
        gd_case_free(&c2);
    }
    tap_ok(gd_ltca_cache_computations() - before == 1, "six models at five speeds: %ld LTCA computation(s)",
           gd_ltca_cache_computations() - before);
    /* 3. impact force by energy balance */
    const gd_ltca_impact *im = &x->impact[0];
    tap_ok(im->found, "mesh-in found for the left half (phase %.4f of the cycle)", im->phase);
    double omega1 = 2.0 * M_PI * c.speed_rpm / 60.0, F, dur;
    gd_impact_force(im->vs_per_omega * omega1, m.m_ref, im->ks, im->delta_m, 1.0, &F, &dur);
    TAP_REL(F, fabs(im->vs_per_omega * omega1) * sqrt(m.m_ref * im->ks), 1e-14, "linear law: F_s = v_s sqrt(m k_s)");
    TAP_REL(m.mesh[0].imp_force[0] * m.k_ref * m.bc_m, F, 1e-12, "and that force is the model's pulse (N)");
    double F2, d2;
    gd_impact_force(2 * im->vs_per_omega * omega1, m.m_ref, im->ks, im->delta_m, 1.5, &F2, &d2);
    gd_impact_force(im->vs_per_omega * omega1, m.m_ref, im->ks, im->delta_m, 1.5, &F, &dur);
    TAP_REL(F2 / F, pow(2.0, 2 * 1.5 / 2.5), 1e-12, "Hertz-like law n = 1.5: F_s grows as v^(2n/(n+1))");
    gd_ltca_excitation_release(x); /* im pointed into x */
    gd_case_free(&c);
    /* 4. tip relief lowers the impact (aligned pair, same speed and load) */
    double Fun = 0, Frel = 0;
    for (int relief = 0; relief < 2; relief++) {
        /* the driving pinion meets at mesh-in with its root the gear's tip: the relief that eases
         * mesh-in is the pinion's root relief (tip relief of the mating flank region) */
        const char *extra[] = {relief ? "modification.root_relief_amount_um=25" : "operating.speed_rpm=4000",
                               relief ? "modification.root_relief_length_mm=1.5" : "operating.speed_rpm=4000", NULL};
        base(&c, extra);
        if (gd_model_build(&c, &m, &e) != GD_OK)
            printf("# %s\n", e.msg);
        double f = m.mesh[0].imp_force[0] * m.k_ref * m.bc_m;
        if (relief)
            Frel = f;
        else
            Fun = f;
        gd_case_free(&c);
    }
    tap_ok(Frel < Fun && Frel > 0, "relief at mesh-in lowers the mesh-in impact: %.4g N against %.4g N unmodified",
           Frel, Fun);
    ste_ltca();
    return tap_done();
}
