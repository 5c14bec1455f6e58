/* The LTCA excitations in the dynamic model (excitation.stiffness = ltca, excitation.impact = on):
 * the model's stiffness passes through every LTCA sample of each half; the derived mean mesh
 * stiffness is the halves' mean; LTCA is computed once for a sweep over speed (cache); the impact
 * force follows the energy balance F_s = v_s sqrt(m k_s), grows with speed as v_s does, and tip
 * relief lowers it. */
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
    return tap_done();
}
