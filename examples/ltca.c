/* Example: loaded tooth contact analysis of a pair written in C, without a case file.
 *
 *   example_ltca
 *
 * The spur pair of cases/guide/spur.ini from its drawing (module 3 mm, 25 / 60 teeth, 20 deg,
 * profile shifts +0.2 / -0.2, 30 mm face, steel) as a gd_pair, unmodified and aligned, and the
 * LTCA settings (120 N m at the pinion, 32 positions over a mesh cycle, 21 slices across the face)
 * as a gd_ltca_settings. gd_ltca_run solves the contact problem at every position; the result
 * holds the mesh stiffness of each position (Eq. 14 of docs/ltca.md: load over loaded minus
 * geometric approach), its mean, minimum and maximum, and the loaded transmission error. For
 * comparison the program prints the ISO 6336-1 mesh stiffness c_gamma b of the same pair
 * (gd_iso6336_mesh_stiffness), an independent estimate from a formula fitted to measurements.
 *
 * The pair and the settings start from their defaults (gd_pair_defaults, gd_ltca_settings_defaults:
 * the defaults of their case keys, `geardyn keys`) and set what the drawing and the load give, so
 * that this pair is the one `geardyn run cases/guide/spur.ini --set scene.analysis=ltca` analyses.
 * The test `example_ltca` (tests/test_examples.py) checks the mean stiffness against that run's
 * summary.json. */
#include <geardyn/geardyn.h>

#include <stdio.h>

int main(void)
{
    gd_pair pair = gd_pair_defaults();          /* steel, ISO 53 rack, unmodified, aligned */
    pair.arrangement = GD_ARR_SPUR;
    pair.normal_module_mm = 3.0;
    pair.helix_angle_deg = 0.0;
    pair.normal_pressure_angle_deg = 20.0;
    pair.teeth_pinion = 25;
    pair.teeth_gear = 60;
    pair.profile_shift_pinion = 0.2;
    pair.profile_shift_gear = -0.2;
    pair.face_width_pinion_mm = 30.0;
    pair.face_width_gear_mm = 30.0;
    pair.bore_diameter_pinion_mm = 30.0;
    pair.bore_diameter_gear_mm = 60.0;

    gd_ltca_settings set = gd_ltca_settings_defaults(); /* 32 positions, 21 slices; no load */
    set.torque_nm = 120.0;                      /* at the pinion */

    gd_error err = {0};
    gd_ltca_result r;
    gd_geometry g;
    gd_status st = gd_ltca_run(&pair, &set, &r, &err);
    if (st == GD_OK)
        st = gd_geometry_compute(&pair, &g, &err);
    if (st != GD_OK) {
        fprintf(stderr, "ltca: %s\n", err.msg);
        return gd_status_exit_code(st);
    }

    printf("positions = %d\n", r.npos);
    printf("stiffness_mean_n_per_m = %.17g\n", r.stiffness_mean[0]);
    printf("stiffness_min_n_per_m = %.17g\n", r.stiffness_min[0]);
    printf("stiffness_max_n_per_m = %.17g\n", r.stiffness_max[0]);
    printf("lte_pp_arcsec = %.17g\n", r.lte_pp_arcsec);
    printf("iso6336_stiffness_n_per_m = %.17g\n", gd_iso6336_mesh_stiffness(&pair, &g));
    /* the stiffness of every position, phase k / npos of the mesh cycle */
    for (int k = 0; k < r.npos; k++)
        printf("# %2d %.6f %.6e %d\n", k, (double)k / r.npos, r.stiffness[0][k], r.pairs_loaded[0][k]);
    gd_ltca_result_free(&r);
    return 0;
}
