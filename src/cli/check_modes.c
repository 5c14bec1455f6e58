/* geardyn check: the natural frequencies of the case's model, its resonance speeds and the share of
 * each spring in each mode's strain energy (gd_scene_modes; docs/model.md section 9.7). */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Where the mesh stiffness of the linearisation comes from, in words. */
static void stiffness_line(const gd_case *c, const gd_model *m)
{
    const gd_keyspec *s0, *k = gd_case_find_key("excitation", "mesh_stiffness_n_per_m");
    size_t n;
    s0 = gd_case_schema(&n);
    int line;
    gd_source src = gd_case_source(c, (size_t)(k - s0), &line);
    if (c->stiffness == GD_STIFF_LTCA && c->ltca_deferred) {
        printf("# mesh stiffness: ISO 6336-1's %.5g N/m, an estimate: with stiffness = ltca the run takes LTCA's mean\n"
               "#   of each mesh instead (check runs no LTCA); a mode's frequency moves with the square root of the\n"
               "#   stiffness in proportion to its mesh share\n", m->k_ref);
        return;
    }
    printf("# mesh stiffness: ");
    for (int j = 0; j < m->nmesh; j++)
        printf("%s%.5g", j ? " / " : "", m->k_ref * gd_modal_mean_stiffness(m, j));
    printf(" N/m, the mean over a mesh cycle (%s%s)\n",
           c->stiffness == GD_STIFF_LTCA ? "LTCA" : src == GD_SRC_DERIVED ? "ISO 6336-1" : gd_source_name(src),
           m->nmesh > 1 ? ", per half" : "");
}

/* The springs holding more than 1 % of the mode's strain energy, largest first. */
static void shares(const gd_modal *md, int k)
{
    int used[GD_MODAL_MAX_ELEM] = {0}, printed = 0;
    double rest = 0.0;
    for (;;) {
        int best = -1;
        for (int e = 0; e < md->nelem; e++)
            if (!used[e] && (best < 0 || md->share[k][e] > md->share[k][best] * (1.0 + 1e-9))) /* ties: in order */
                best = e;
        if (best < 0 || md->share[k][best] < 0.01)
            break;
        used[best] = 1;
        printf("%s%s %.3g %%", printed++ ? ", " : "", md->elem[best].name, 100.0 * md->share[k][best]);
    }
    for (int e = 0; e < md->nelem; e++)
        if (!used[e])
            rest += md->share[k][e];
    if (rest > 0.0005)
        printf(", others %.2g %%", 100.0 * rest);
}

void cli_check_modes(const gd_case *c, const gd_model *m)
{
    gd_modal md;
    gd_error err = {0};
    printf("\n# natural frequencies (docs/model.md section 9.7): the model linearised at its static operating point,\n"
           "#   every mesh in drive-side contact at its mean stiffness, every bearing on the side the load puts it;\n"
           "#   undamped\n");
    if (gd_scene_modes(c, m, &md, &err) != GD_OK) {
        printf("# no modal analysis: %s\n", err.msg);
        return;
    }
    stiffness_line(c, m);
    printf("# resonance speeds, rpm of the pinion: where the mesh frequency meets the natural frequency (main),\n"
           "#   and its 2nd, 3rd, 4th harmonic (the superharmonic resonances at 1/2, 1/3, 1/4 of that speed)\n");
    printf("modes = %d   ; rigid-body modes excluded: %d\n", md.nmodes, md.nrigid);
    for (int r = 0; r < md.nrigid; r++) {
        printf("# rigid-body mode %d (zero frequency, nothing holds it):", r + 1);
        for (int i = 0; i < md.ndof; i++)
            if (fabs(md.rigid_shape[r][i]) > 1e-9)
                printf(" %s %.4g", md.dof_name[i], md.rigid_shape[r][i]);
        printf("\n");
    }
    printf("# mode  frequency_hz   main_rpm    1/2_rpm    1/3_rpm    1/4_rpm  meshes_%%  %s  strain energy share\n",
           md.mirrored ? "halves       " : "");
    for (int k = 0; k < md.nmodes; k++) {
        double mesh = 0.0; /* the meshes' share: how strongly the mesh excites the mode */
        for (int e = 0; e < md.nelem; e++)
            if (md.elem[e].kind == GD_MODAL_CLEARANCE && m->clear[md.elem[e].clear].kind == GD_CLR_MESH)
                mesh += md.share[k][e];
        printf("%6d  %12.6g %10.6g %10.6g %10.6g %10.6g  %8.2f  ", k + 1, md.freq_hz[k], md.resonance_rpm[k][0],
               md.resonance_rpm[k][1], md.resonance_rpm[k][2], md.resonance_rpm[k][3], 100.0 * mesh);
        if (md.mirrored)
            printf("%-13s  ", gd_modal_halves(&md, k));
        shares(&md, k);
        printf("\n");
    }
}

/* The case's fixed step (rk4, or erk with solver.fixed_step) against the stability region of its
 * method on the model linearised at its static operating point (gd_run_cost's step_ fields). */
void cli_check_step(const gd_case *c, const gd_run_cost *k)
{
    if (k->stable_steps_per_period <= 0)
        return;
    printf("\n# the fixed step against the stability region of its method (docs/accuracy.md section 1)\n");
    printf("step_amplification = %.4g   ; max |R(h lambda)| over the model's eigenvalues at %d steps per mesh period, "
           "on the %.6g Hz mode\n", k->step_amplification, c->steps_per_period, k->step_mode_hz);
    printf("stable_from_steps_per_period = %ld%s\n", k->stable_steps_per_period,
           k->step_amplification > 1.0 + 1e-9 ? "   ; UNSTABLE: solver.steps_per_period is below it, the run's results "
                                                "are round-off grown every step" : "");
}
