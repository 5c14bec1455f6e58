/* geardyn check: validate a case and print every resolved parameter with unit and source. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

int cmd_check(int argc, char **argv)
{
    cli_case_args a;
    gd_case c;
    int rc = cli_open_case(argc, argv, 0, &a, &c);
    if (rc)
        return rc;
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    printf("# %s: valid\n", a.case_path);
    const char *sec = "";
    for (size_t i = 0; i < n; i++) {
        if (strcmp(sec, s[i].section) != 0) {
            sec = s[i].section;
            printf("\n[%s]\n", sec);
        }
        char val[1200], where[64];
        gd_case_format_value(&c, i, val, sizeof val);
        int line;
        gd_source src = gd_case_source(&c, i, &line);
        if (src == GD_SRC_FILE)
            snprintf(where, sizeof where, "file line %d", line);
        else if (src == GD_SRC_SET)
            snprintf(where, sizeof where, "--set #%d", line);
        else
            snprintf(where, sizeof where, "%s", gd_source_name(src));
        char lhs[1400];
        if (s[i].type == GD_KEY_DOUBLE && isnan(*(const double *)((const char *)&c + s[i].offset)))
            snprintf(lhs, sizeof lhs, "%s = none", s[i].key); /* not given and not derived: not used */
        else
            snprintf(lhs, sizeof lhs, "%s = %s%s%s", s[i].key, val[0] ? val : "\"\"", s[i].unit[0] ? " " : "",
                     s[i].unit);
        printf("%-58s ; %s\n", lhs, where);
    }
    gd_geometry g;
    gd_model m;
    gd_error err = {0};
    const gd_pair pair = gd_pair_from_case(&c);
    if (gd_geometry_compute(&pair, &g, &err) == GD_OK && gd_model_build(&c, &m, &err) == GD_OK) {
        const double deg = 180.0 / M_PI;
        printf("\n# derived geometry (ISO 21771), pinion / gear\n");
        printf("transverse_module_mm = %.6g\n", g.mt * 1e3);
        printf("transverse_pressure_angle_deg = %.6g\n", g.alpha_t * deg);
        printf("working_pressure_angle_deg = %.6g\n", g.alpha_wt * deg);
        printf("base_helix_angle_deg = %.6g\n", g.beta_b * deg);
        printf("reference_radius_mm = %.6g / %.6g\n", g.r[0] * 1e3, g.r[1] * 1e3);
        printf("base_radius_mm = %.6g / %.6g\n", g.rb[0] * 1e3, g.rb[1] * 1e3);
        printf("tip_radius_mm = %.6g / %.6g\n", g.ra[0] * 1e3, g.ra[1] * 1e3);
        printf("root_radius_mm = %.6g / %.6g\n", g.rf[0] * 1e3, g.rf[1] * 1e3);
        printf("start_of_active_profile_radius_mm = %.6g / %.6g\n", g.r_sap[0] * 1e3, g.r_sap[1] * 1e3);
        printf("centre_distance_mm = %.6g\n", g.a * 1e3);
        printf("contact_ratio_transverse = %.6g\n", g.eps_alpha);
        printf("contact_ratio_overlap = %.6g\n", g.eps_beta);
        printf("\n# derived model scales\n");
        printf("degrees_of_freedom = %d\n", m.ndof);
        printf("normal_equivalent_mass_kg = %.6g\n", m.m_ref);
        printf("natural_frequency_hz = %.6g   ; sqrt(k_m / m_n) / 2 pi of one mesh\n", m.omega_n / (2 * M_PI));
        printf("mesh_frequency_hz = %.6g\n", m.mesh_freq_hz);
        printf("frequency_ratio = %.6g\n", m.Omega);
        printf("static_mesh_force_n = %.6g   ; per mesh (herringbone: per half), along the tooth normal\n", m.static_load_n);
        printf("static_deflection_um = %.6g\n", m.static_load_n / m.k_ref * 1e6);
        if (c.stiffness == GD_STIFF_LTCA)
            printf("# with stiffness = ltca the mesh stiffness above is ISO 6336-1's; run replaces it by LTCA's mean\n");
    }
    const gd_run_cost *k = &a.cost;
    char est[200];
    gd_run_cost_format(k, est, sizeof est);
    printf("\n# estimated cost of the run (check runs no LTCA and no integration; docs/performance.md)\n");
    printf("time_class = %s   ; %s, limit run.max_time_s = %.4g s\n", k->time_class, est, c.max_time_s);
    if (k->points > 0)
        printf("integration = %.4g runs of %.4g mesh periods, about %.2g steps\n", k->points, k->periods, k->steps);
    if (k->ltca_unknowns > 0)
        printf("ltca_contact_points = %.0f   ; per position, a dense system of that size\n", k->ltca_unknowns);
    printf("memory_bytes = %.3g\n", k->memory_bytes);
    printf("disk_bytes = %.3g   ; limit output.max_bytes = %.4g\n", k->disk_bytes, c.max_bytes);
    gd_case_free(&c);
    return 0;
}
