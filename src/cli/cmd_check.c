/* geardyn check: validate a case and print every resolved parameter with unit and source. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The derivation of ISO 6336-1's mesh stiffness, every factor (docs/model.md section 9.3). */
static void print_iso6336(const gd_pair *pair, const gd_geometry *g)
{
    gd_iso6336_terms t;
    gd_iso6336_mesh_stiffness_terms(pair, g, &t);
    printf("\n# ISO 6336-1 mesh stiffness (method B) of one mesh, along the tooth normal\n");
    printf("# k = c_gamma_alpha b / cos^2(beta_b) = %.6g N/(mm um) x %.6g mm / %.6g = %.6g N/m\n", t.c_gamma_alpha,
           t.face_width_mm, t.cos2_beta_b, t.k_n_per_m);
    printf("#   b: the common face width of the mesh (the narrower body's); / cos^2(beta_b): ISO's transverse "
           "stiffness referred to the normal\n");
    printf("# c_gamma_alpha = c' (0.75 eps_alpha + 0.25)%s = %.6g x %.6g\n", t.eps_alpha < 1.2 ? " x 0.9" : "",
           t.c_prime, t.eps_factor);
    printf("# c' = c'_th C_M C_R C_B cos(beta) = %.6g x %.3g x %.3g x %.6g x %.6g = %.6g N/(mm um)\n", t.c_th, t.c_m,
           t.c_r, t.c_b, t.cos_beta, t.c_prime);
    printf("# c'_th = 1 / q', q' = %.6g mm um/N from z_n = z / (cos^2(beta_b) cos(beta)) = %.6g / %.6g and x = %.6g / "
           "%.6g\n", t.q_prime, t.zn[0], t.zn[1], pair->profile_shift_pinion, pair->profile_shift_gear);
    printf("#   C_M 0.8 (solid blanks), C_R 1; no reduction below 100 N/mm line load\n");
}

/* Where each excitation of the dynamics comes from, one line each. */
static void print_excitations(const gd_case *c, const gd_model *m)
{
    static const char *const kind[] = {"constant", "harmonic", "rectangular", "ltca"};
    printf("\n# the excitations of the dynamics and where each comes from\n");
    if (c->stiffness == GD_STIFF_LTCA)
        printf("mesh_stiffness = ltca   ; LTCA's mesh stiffness of each half at %.6g N m, %d positions per mesh cycle "
               "(the run computes it; the mean above is ISO 6336-1's until then); stiffness_harmonics ignored\n",
               c->torque_nm, c->ltca_positions_per_cycle);
    else if (c->stiffness == GD_STIFF_HARMONIC)
        printf("mesh_stiffness = harmonic   ; k_m (1 + sum a_j cos(j w_m t + phi_j)), %d harmonic%s from "
               "excitation.stiffness_harmonics (%s)\n", c->n_stiffness_harmonics, c->n_stiffness_harmonics == 1 ? "" : "s",
               gd_source_name(gd_case_source(c, (size_t)(gd_case_find_key("excitation", "stiffness_harmonics") -
                                                         gd_case_schema(NULL)), NULL)));
    else if (c->stiffness == GD_STIFF_RECTANGULAR)
        printf("mesh_stiffness = rectangular   ; k_m (1 + %g) for %.4g of the mesh period, lower for the rest "
               "(excitation.rectangular_*)\n", c->rectangular_variation, c->rectangular_high_fraction);
    else
        printf("mesh_stiffness = %s   ; k_m, no variation\n", kind[0]);
    if (!c->error_excitation)
        printf("transmission_error = off   ; scene.error_excitation = off\n");
    else if (c->ste_source == GD_STE_LTCA)
        printf("transmission_error = ltca   ; LTCA's loaded transmission error of each half less its share F/k(t) "
               "from the mesh stiffness, mean removed, plus ste_mean_um (ste_amplitude_um, ste_phase_deg ignored)\n");
    else {
        size_t ia = (size_t)(gd_case_find_key("excitation", "ste_amplitude_um") - gd_case_schema(NULL));
        int line;
        gd_source src = gd_case_source(c, ia, &line);
        printf("transmission_error = sinusoid   ; e_m + e_r sin(w_m t + phi), e_r = %g um %s\n", c->ste_amplitude_um,
               src == GD_SRC_DERIVED ? "(from base_pitch_deviation_um and profile_deviation_um)"
               : src == GD_SRC_DEFAULT ? "(excitation.ste_amplitude_um, default: not this pair's)"
                                       : "(excitation.ste_amplitude_um)");
    }
    printf("mesh_in_impact = %s\n", c->impact ? "ltca   ; LTCA's mesh-in of each half, by energy balance (paper "
                                                 "Eq. 15-16)" : "off   ; excitation.impact = off");
    (void)m;
}

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
        int absent = 0;
        const char *unused = gd_case_key_unused(&c, i, &absent);
        gd_source src0 = gd_case_source(&c, i, NULL);
        if (absent && src0 != GD_SRC_FILE && src0 != GD_SRC_SET)
            continue; /* a key this pair does not have (a single pair's groove) */
        if (strcmp(sec, s[i].section) != 0) {
            sec = s[i].section;
            printf("\n[%s]\n", sec);
        }
        char val[1200], where[256];
        gd_case_format_value(&c, i, val, sizeof val);
        int line;
        gd_source src = gd_case_source(&c, i, &line);
        if (src == GD_SRC_FILE)
            snprintf(where, sizeof where, "file line %d", line);
        else if (src == GD_SRC_SET)
            snprintf(where, sizeof where, "--set #%d", line);
        else
            snprintf(where, sizeof where, "%s", gd_source_name(src));
        if (src == GD_SRC_DERIVED && strcmp(s[i].key, "mesh_stiffness_n_per_m") == 0)
            snprintf(where, sizeof where, "derived: ISO 6336-1, c_gamma_alpha b / cos^2(beta_b) (below)");
        if (unused) {
            size_t u = strlen(where);
            snprintf(where + u, sizeof where - u, ", %s", unused);
        }
        char lhs[1400];
        if (s[i].type == GD_KEY_DOUBLE && isnan(*(const double *)((const char *)&c + s[i].offset)))
            snprintf(lhs, sizeof lhs, "%s = none", s[i].key); /* not given and not derived: not used */
        else
            snprintf(lhs, sizeof lhs, "%s = %s%s%s", s[i].key, val[0] ? val : "\"\"", s[i].unit[0] ? " " : "",
                     s[i].unit);
        printf("%-58s ; %s\n", lhs, where);
    }
    printf("\n");
    cli_print_defaulted(stdout, &c, "# ");
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
        if (isfinite(c.speed_rpm)) {
            printf("mesh_frequency_hz = %.6g\n", m.mesh_freq_hz);
            printf("frequency_ratio = %.6g\n", m.Omega);
        } else {
            printf("# no operating.speed_rpm (this analysis does not use it): no mesh frequency\n");
        }
        if (isfinite(c.torque_nm)) {
            printf("static_mesh_force_n = %.6g   ; per mesh (herringbone: per half), along the tooth normal\n",
                   m.static_load_n);
            printf("static_axial_force_n = %.6g   ; its axial component F_n sin(beta_b), taken by the axial supports\n",
                   m.static_load_n * sin(g.beta_b));
            printf("static_deflection_um = %.6g\n", m.static_load_n / m.k_ref * 1e6);
        } else {
            printf("# no operating.torque_nm (this analysis does not use it): no static mesh force\n");
        }
        if (c.stiffness == GD_STIFF_LTCA)
            printf("# with stiffness = ltca the mesh stiffness above is ISO 6336-1's; run replaces it by LTCA's mean\n");
        print_iso6336(&pair, &g);
        print_excitations(&c, &m);
        cli_check_modes(&c, &m);
    }
    const gd_run_cost *k = &a.cost;
    cli_check_step(&c, k);
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
