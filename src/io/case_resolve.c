/* Resolving a case: cross-key consistency and the derived values that were not pinned. */
#include "geardyn/gd_case.h"
#include "geardyn/gd_geometry.h"
#include "geardyn/gd_flank.h"
#include "geardyn/gd_excitation.h"
#include "geardyn/gd_sweep.h"
#include "geardyn/gd_workprec.h"
#include "geardyn/gd_optimize.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The Butcher tables of ARKODE 6.4 by name, and Verner's three that geardyn adds under the names
 * of later SUNDIALS (src/dynamics/erk_verner.c); checked here so that ARKODE, which prints to
 * stderr on an unknown name, is only ever asked for one it has. */
static const char *const erk_tables =
    " ARKODE_HEUN_EULER_2_1_2 ARKODE_BOGACKI_SHAMPINE_4_2_3 ARKODE_ARK324L2SA_ERK_4_2_3 ARKODE_ZONNEVELD_5_3_4"
    " ARKODE_ARK436L2SA_ERK_6_3_4 ARKODE_SAYFY_ABURUB_6_3_4 ARKODE_CASH_KARP_6_4_5 ARKODE_FEHLBERG_6_4_5"
    " ARKODE_DORMAND_PRINCE_7_4_5 ARKODE_ARK548L2SA_ERK_8_4_5 ARKODE_VERNER_8_5_6 ARKODE_FEHLBERG_13_7_8"
    " ARKODE_KNOTH_WOLKE_3_3 ARKODE_ARK437L2SA_ERK_7_3_4 ARKODE_ARK548L2SAb_ERK_8_4_5"
    " ARKODE_VERNER_10_6_7 ARKODE_VERNER_13_7_8 ARKODE_VERNER_16_8_9 ";
static const char *const dirk_tables =
    " ARKODE_SDIRK_2_1_2 ARKODE_BILLINGTON_3_3_2 ARKODE_TRBDF2_3_3_2 ARKODE_KVAERNO_4_2_3"
    " ARKODE_ARK324L2SA_DIRK_4_2_3 ARKODE_CASH_5_2_4 ARKODE_CASH_5_3_4 ARKODE_SDIRK_5_3_4 ARKODE_KVAERNO_5_3_4"
    " ARKODE_ARK436L2SA_DIRK_6_3_4 ARKODE_KVAERNO_7_4_5 ARKODE_ARK548L2SA_DIRK_8_4_5 ARKODE_ARK437L2SA_DIRK_7_3_4"
    " ARKODE_ARK548L2SAb_DIRK_8_4_5 ARKODE_ESDIRK324L2SA_4_2_3 ARKODE_ESDIRK325L2SA_5_2_3"
    " ARKODE_ESDIRK32I5L2SA_5_2_3 ARKODE_ESDIRK436L2SA_6_3_4 ARKODE_ESDIRK43I6L2SA_6_3_4"
    " ARKODE_QESDIRK436L2SA_6_3_4 ARKODE_ESDIRK437L2SA_7_3_4 ARKODE_ESDIRK547L2SA_7_4_5"
    " ARKODE_ESDIRK547L2SA2_7_4_5 ";

static int known_table(const char *list, const char *name)
{
    char key[160];
    if (strchr(name, ' ') || strlen(name) > 128)
        return 0;
    snprintf(key, sizeof key, " %s ", name);
    return strstr(list, key) != NULL;
}

static size_t key_index(const char *section, const char *key)
{
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    return (size_t)(gd_case_find_key(section, key) - s);
}

static int given(const gd_case *c, const char *section, const char *key)
{
    size_t i = key_index(section, key);
    return c->src[i] == GD_SRC_FILE || c->src[i] == GD_SRC_SET;
}

static void where(const gd_case *c, const char *section, const char *key, char *buf, size_t len)
{
    size_t i = key_index(section, key);
    if (c->src[i] == GD_SRC_FILE)
        snprintf(buf, len, "%s:%d", c->path, c->src_line[i]);
    else if (c->src[i] == GD_SRC_SET)
        snprintf(buf, len, "--set #%d", c->src_line[i]);
    else
        snprintf(buf, len, "%s", c->path[0] ? c->path : "case");
}

static void derive(gd_case *c, const char *section, const char *key, double *field, double value)
{
    size_t i = key_index(section, key);
    if (c->src[i] == GD_SRC_FILE || c->src[i] == GD_SRC_SET)
        return;
    *field = value;
    c->src[i] = GD_SRC_DERIVED;
}

GD_API gd_status gd_case_resolve(gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    if (!gd_analysis_available(c->analysis)) {
        size_t n;
        const gd_keyspec *s = gd_case_schema(&n);
        size_t i = key_index("scene", "analysis");
        char name[64], avail[256] = "";
        gd_case_format_value(c, i, name, sizeof name);
        for (int a = 0; a <= GD_ANALYSIS_WORK_PRECISION; a++)
            if (gd_analysis_available(a)) {
                gd_case tmp = *c;
                tmp.analysis = a;
                char nm[64];
                gd_case_format_value(&tmp, i, nm, sizeof nm);
                size_t used = strlen(avail);
                snprintf(avail + used, sizeof avail - used, "%s%s", used ? ", " : "", nm);
            }
        (void)s;
        where(c, "scene", "analysis", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: scene.analysis: '%s' is not available in this version of geardyn "
                            "(valid: %s)", w, name, avail);
    }
    if (c->transient_max_periods > 0 && c->transient_max_periods < c->transient_periods) {
        where(c, "run", "transient_max_periods", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: run.transient_max_periods: %d is below run.transient_periods = %d "
                            "(valid: 0, or at least transient_periods)", w, c->transient_max_periods,
                            c->transient_periods);
    }
    /* torque or power */
    if (given(c, "operating", "torque_nm") && given(c, "operating", "power_kw")) {
        where(c, "operating", "power_kw", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: operating.power_kw: give torque_nm or power_kw, not both "
                            "(valid: one of them; torque = 9550 P / n)", w);
    }
    if (given(c, "operating", "power_kw"))
        derive(c, "operating", "torque_nm", &c->torque_nm, 9550.0 * c->power_kw / c->speed_rpm);
    else {
        if (!given(c, "operating", "torque_nm")) {
            c->torque_nm = 500.0;
            c->src[key_index("operating", "torque_nm")] = GD_SRC_DEFAULT;
        }
        derive(c, "operating", "power_kw", &c->power_kw, c->torque_nm * c->speed_rpm / 9550.0);
    }
    /* static transmission error amplitude */
    int has_fa = given(c, "excitation", "base_pitch_deviation_um");
    int has_fb = given(c, "excitation", "profile_deviation_um");
    if (has_fa != has_fb) {
        where(c, "excitation", has_fa ? "base_pitch_deviation_um" : "profile_deviation_um", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.%s: give both base_pitch_deviation_um and "
                            "profile_deviation_um (valid: both, e_r = sqrt(f_a^2 + f_b^2))", w,
                            has_fa ? "base_pitch_deviation_um" : "profile_deviation_um");
    }
    if (has_fa && given(c, "excitation", "ste_amplitude_um")) {
        where(c, "excitation", "ste_amplitude_um", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.ste_amplitude_um: give the amplitude or the two "
                            "deviations, not both (valid: one way)", w);
    }
    if (has_fa)
        derive(c, "excitation", "ste_amplitude_um", &c->ste_amplitude_um,
               hypot(c->base_pitch_deviation_um, c->profile_deviation_um));
    else if (!given(c, "excitation", "ste_amplitude_um"))
        c->ste_amplitude_um = 10.0;
    /* stiffness harmonics */
    if (c->n_stiffness_phases > c->n_stiffness_harmonics) {
        where(c, "excitation", "stiffness_phases_deg", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.stiffness_phases_deg: %d phases for %d harmonics "
                            "(valid: at most one phase per harmonic)", w, c->n_stiffness_phases, c->n_stiffness_harmonics);
    }
    if (c->stiffness == GD_STIFF_HARMONIC && c->n_stiffness_harmonics == 0) {
        c->stiffness_harmonics[0] = 0.1;
        c->n_stiffness_harmonics = 1;
    }
    double asum = 0;
    for (int j = 0; j < c->n_stiffness_harmonics; j++)
        asum += c->stiffness_harmonics[j];
    if (c->stiffness == GD_STIFF_HARMONIC && asum >= 1.0) {
        where(c, "excitation", "stiffness_harmonics", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.stiffness_harmonics: amplitudes sum to %g, the "
                            "stiffness could become negative (valid: sum below 1)", w, asum);
    }
    if (given(c, "solver", "order") && c->method == GD_METHOD_DIRK && c->order > 5) {
        where(c, "solver", "order", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: solver.order: %d for dirk (valid: 2 to 5)", w, c->order);
    }
    if (c->lyapunov_exponents > 0 && c->lyapunov_method == GD_LYAP_TANGENT && !c->root_finding) {
        where(c, given(c, "run", "lyapunov_exponents") ? "run" : "solver",
              given(c, "run", "lyapunov_exponents") ? "lyapunov_exponents" : "root_finding", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: run.lyapunov_exponents: the tangent method needs "
                            "solver.root_finding = on, the variational equations must switch exactly at every "
                            "contact (valid: lyapunov_exponents = 0, or lyapunov_method = two-trajectory)", w);
    }
    if (c->lyapunov_method == GD_LYAP_TWO_TRAJECTORY && c->lyapunov_exponents > 1) {
        where(c, "run", "lyapunov_exponents", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: run.lyapunov_exponents: %d with the two-trajectory method "
                            "(valid: 1; the tangent method gives more)", w, c->lyapunov_exponents);
    }
    if (c->method == GD_METHOD_DIRK && !given(c, "solver", "order"))
        c->order = 4;
    if (c->table[0]) {
        int dirk = c->method == GD_METHOD_DIRK;
        if (c->method == GD_METHOD_RK4 || !known_table(dirk ? dirk_tables : erk_tables, c->table)) {
            where(c, "solver", "table", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: solver.table: '%s' is not an ARKODE %s table (valid:%s)", w,
                                c->table, c->method == GD_METHOD_RK4 ? "table for rk4" : dirk ? "DIRK" : "ERK",
                                c->method == GD_METHOD_RK4 ? " none for rk4, it is the classical RK4"
                                                          : dirk ? dirk_tables : erk_tables);
        }
    }
    /* geometry and what follows from it */
    gd_geometry g;
    gd_status st = gd_geometry_compute(c, &g, err);
    if (st != GD_OK) {
        if (st == GD_ERR_GEOMETRY && g.bad_key) {
            where(c, "gear", g.bad_key, w, sizeof w);
            return gd_error_prefix(err, "%s: gear.%s", w, g.bad_key);
        }
        return gd_error_prefix(err, "%s: [gear]", c->path[0] ? c->path : "case");
    }
    for (int i = 0; i < 2; i++) {
        double bore = i == 0 ? c->bore_diameter_pinion_mm : c->bore_diameter_gear_mm;
        if (bore * 0.5e-3 >= g.rf[i]) {
            const char *k = i == 0 ? "bore_diameter_pinion_mm" : "bore_diameter_gear_mm";
            where(c, "gear", k, w, sizeof w);
            return gd_error_set(err, GD_ERR_GEOMETRY, "%s: gear.%s: bore %g mm does not fit inside the root circle "
                                "(valid: below %.4g mm)", w, k, bore, 2e3 * g.rf[i]);
        }
    }
    /* arrangement, [modification] on the pinion flank, [misalignment] (docs/geometry.md) */
    if (c->arrangement == GD_ARR_SPUR && c->helix_angle_deg != 0) {
        where(c, "gear", "helix_angle_deg", w, sizeof w);
        return gd_error_set(err, GD_ERR_GEOMETRY, "%s: gear.helix_angle_deg: %g with arrangement = spur (valid: 0)", w,
                            c->helix_angle_deg);
    }
    if (!c->modification_apply) { /* the unmodified pair: amounts and lengths resolve to 0, marked derived */
        static const char *const mk[] = { "root_relief_amount_um", "root_relief_length_mm", "tip_relief_amount_um",
                                          "tip_relief_length_mm", "lead_relief_inner_um", "lead_relief_outer_um",
                                          "lead_unmodified_length_mm" };
        double *mf[] = { &c->root_relief_amount_um, &c->root_relief_length_mm, &c->tip_relief_amount_um,
                         &c->tip_relief_length_mm, &c->lead_relief_inner_um, &c->lead_relief_outer_um,
                         &c->lead_unmodified_length_mm };
        for (size_t k = 0; k < sizeof mk / sizeof mk[0]; k++) {
            *mf[k] = 0.0;
            c->src[key_index("modification", mk[k])] = GD_SRC_DERIVED;
        }
    }
    const char *mkey = NULL;
    if (gd_modification_check(c, &g, &mkey, err) != GD_OK) {
        where(c, "modification", mkey, w, sizeof w);
        return gd_error_prefix(err, "%s: modification.%s", w, mkey);
    }
    {
        double sb = g.rb[0] + g.rb[1], aop = g.a + c->centre_distance_error_mm * 1e-3;
        double ea = (g.rho_a[0] + g.rho_a[1] - sqrt(aop * aop - sb * sb)) / g.pbt;
        if (ea < 1.0) {
            double amax = sqrt(sb * sb + pow(g.rho_a[0] + g.rho_a[1] - g.pbt, 2));
            where(c, "misalignment", "centre_distance_error_mm", w, sizeof w);
            return gd_error_set(err, GD_ERR_GEOMETRY, "%s: misalignment.centre_distance_error_mm: transverse contact ratio "
                                "%.4f below 1 at the operating centre distance %.6g mm (valid: below %.4g mm)", w, ea,
                                aop * 1e3, (amax - g.a) * 1e3);
        }
    }
    double m1, i1, m2, i2;
    gd_body_half(c, &g, 0, &m1, &i1);
    gd_body_half(c, &g, 1, &m2, &i2);
    derive(c, "gear", "pinion_mass_kg", &c->pinion_mass_kg, m1);
    derive(c, "gear", "gear_mass_kg", &c->gear_mass_kg, m2);
    derive(c, "gear", "pinion_inertia_kgm2", &c->pinion_inertia_kgm2, i1);
    derive(c, "gear", "gear_inertia_kgm2", &c->gear_inertia_kgm2, i2);
    double I1 = c->pinion_inertia_kgm2, I2 = c->gear_inertia_kgm2;
    derive(c, "gear", "equivalent_mass_kg", &c->equivalent_mass_kg,
           I1 * I2 / (I1 * g.rb[1] * g.rb[1] + I2 * g.rb[0] * g.rb[0]));
    if (c->stiffness == GD_STIFF_LTCA || c->impact) {
        const char *k = c->stiffness == GD_STIFF_LTCA ? "stiffness" : "impact";
        if (!(c->torque_nm > 0)) {
            where(c, "excitation", k, w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.%s: LTCA needs a load, the torque is %g N m "
                                "(valid: operating.torque_nm > 0)", w, k, c->torque_nm);
        }
        if (c->stiffness == GD_STIFF_LTCA && c->half_phase_deg != 0.0) {
            where(c, "excitation", "half_phase_deg", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.half_phase_deg: %g with stiffness = ltca (valid: 0; "
                                "the halves' relative phase comes from their geometry)", w, c->half_phase_deg);
        }
        const gd_ltca_excitation *x;
        gd_status sx = gd_ltca_excitation_cached(c, &x, err);
        if (sx != GD_OK)
            return gd_error_prefix(err, "%s", c->path[0] ? c->path : "case");
        if (c->stiffness == GD_STIFF_LTCA)
            derive(c, "excitation", "mesh_stiffness_n_per_m", &c->mesh_stiffness_n_per_m,
                   x->halves > 1 && x->k[1] ? 0.5 * (x->k_mean[0] + x->k_mean[1]) : x->k_mean[0]);
    }
    if (c->stiffness != GD_STIFF_LTCA)
        derive(c, "excitation", "mesh_stiffness_n_per_m", &c->mesh_stiffness_n_per_m, gd_iso6336_mesh_stiffness(c, &g));
    derive(c, "support", "shaft_stiffness_pinion_n_per_m", &c->shaft_stiffness_pinion_n_per_m,
           gd_groove_shaft_stiffness(c, &g, 0));
    derive(c, "support", "shaft_stiffness_gear_n_per_m", &c->shaft_stiffness_gear_n_per_m,
           gd_groove_shaft_stiffness(c, &g, 1));
    double frac = g.eps_alpha - floor(g.eps_alpha);
    if (frac < 0.02 || frac > 0.98)
        frac = 0.5;
    derive(c, "excitation", "rectangular_high_fraction", &c->rectangular_high_fraction, frac);
    if (c->stiffness == GD_STIFF_RECTANGULAR) {
        double d = c->rectangular_high_fraction;
        if (c->rectangular_variation * d / (1 - d) >= 1.0) {
            where(c, "excitation", "rectangular_variation", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.rectangular_variation: %g with high fraction %g "
                                "makes the low level negative (valid: below %g)", w, c->rectangular_variation, d,
                                (1 - d) / d);
        }
    }
    if (c->analysis == GD_ANALYSIS_LTCA && !(c->torque_nm > 0)) {
        const char *k = given(c, "operating", "power_kw") ? "power_kw" : "torque_nm";
        where(c, "operating", k, w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: operating.%s: a pinion torque of %g N m for LTCA (valid: > 0, "
                            "the loaded contact needs a load)", w, k, c->torque_nm);
    }
    /* [sweep]: the swept keys and every value of the grid */
    if (c->analysis == GD_ANALYSIS_SWEEP)
        return gd_sweep_check_case(c, err);
    if (c->analysis == GD_ANALYSIS_WORK_PRECISION && gd_workprec_check_case(c, err) != GD_OK)
        return gd_error_prefix(err, "%s", c->path[0] ? c->path : "case");
    if (c->analysis == GD_ANALYSIS_OPTIMIZE || c->analysis == GD_ANALYSIS_COMPARE_OPTIMIZERS)
        return gd_opt_resolve_case(c, err);
    return GD_OK;
}
