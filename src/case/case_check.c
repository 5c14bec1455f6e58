/* The cross-key checks of a case that need no physics: torque or power, the STE amplitude, the
 * stiffness harmonics, the solver settings and tables; the values they derive. */
#include "case_keys.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The Butcher tables of ARKODE 6.4 by name, and Verner's three that geardyn adds under the names
 * of later SUNDIALS (src/dynamics/compat/erk_verner.c); checked here so that ARKODE, which prints to
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

/* Whether the comma-separated list names name (items trimmed of blanks). */
static int listed(const char *list, const char *name)
{
    size_t n = strlen(name);
    for (const char *p = list; *p;) {
        while (*p == ' ' || *p == '\t' || *p == ',')
            p++;
        const char *e = p;
        while (*e && *e != ',')
            e++;
        const char *f = e;
        while (f > p && (f[-1] == ' ' || f[-1] == '\t'))
            f--;
        if ((size_t)(f - p) == n && strncmp(p, name, n) == 0)
            return 1;
        p = e;
    }
    return 0;
}

/* The analyses that integrate the dynamics need the speed and the load; those of the loaded
 * contact (LTCA, the optimisation of the gear's LTE) the load only; TCA and the test functions
 * neither. */
static int needs_speed(const gd_case *c)
{
    return c->analysis == GD_ANALYSIS_RESPONSE || c->analysis == GD_ANALYSIS_SWEEP ||
           c->analysis == GD_ANALYSIS_CONTINUATION || c->analysis == GD_ANALYSIS_WORK_PRECISION;
}

static int needs_load(const gd_case *c)
{
    if (needs_speed(c) || c->analysis == GD_ANALYSIS_LTCA)
        return 1;
    return (c->analysis == GD_ANALYSIS_OPTIMIZE || c->analysis == GD_ANALYSIS_COMPARE_OPTIMIZERS) &&
           strstr(c->opt_objective, "gear-lte") != NULL;
}

/* A key of [operating] whose value the case gives: in the file, by --set, or written into the
 * structure by a program (a finite value where the schema has none). */
static int operating_known(const gd_case *c, const char *key, double v)
{
    gd_source s = (gd_source)c->src[gd_case_key_index("operating", key)];
    return s == GD_SRC_FILE || s == GD_SRC_SET || (s == GD_SRC_DEFAULT && isfinite(v));
}

/* 1 when a sweep or a continuation of this case varies the key "section.key"; *start: the value it
 * gives the key at its start (a sweep's first value, a continuation's start value; NaN while the
 * analysis's own keys lack it, which its check reports). */
static int varied(const gd_case *c, const char *name, double *start)
{
    *start = NAN;
    if (c->analysis == GD_ANALYSIS_SWEEP && strcmp(c->sweep_parameter, name) == 0)
        *start = c->sweep_from;
    else if (c->analysis == GD_ANALYSIS_SWEEP && strcmp(c->sweep_parameter2, name) == 0)
        *start = c->sweep_from2;
    else if (c->analysis == GD_ANALYSIS_CONTINUATION && strcmp(c->cont_parameter, name) == 0)
        *start = gd_case_key_given(c, "continuation", "start_value") ? c->cont_start_value
               : c->cont_direction == 0 ? c->cont_from /* the schema's up|down|both */
               : c->cont_direction == 1 ? c->cont_to : 0.5 * (c->cont_from + c->cont_to);
    else
        return 0;
    return 1;
}

static gd_status missing(const gd_case *c, const char *key, const char *what, gd_error *err)
{
    char w[GD_PATH_MAX + 32], an[32], range[96];
    gd_case_key_where(c, "operating", key, w, sizeof w);
    gd_case_key_choice("scene", "analysis", c->analysis, an, sizeof an);
    gd_case_key_range_text(gd_case_find_key("operating", key), range, sizeof range);
    return gd_error_set(err, GD_ERR_INPUT, "%s: operating.%s: missing: the %s analysis needs %s, which has no "
                        "default (valid: %s, in [operating] or by --set%s)", w, key, an, what, range,
                        strcmp(key, "torque_nm") == 0 ? "; or operating.power_kw" : "");
}

/* The operating point: the speed, and the torque or the power (one of them; the other derived, T =
 * 9550 P / n, and range-checked). Neither has a default: an analysis that needs them refuses a case
 * without them, unless it varies them itself (a sweep or continuation of the key: its start). */
static gd_status check_load(gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    if (gd_case_key_given(c, "operating", "torque_nm") && gd_case_key_given(c, "operating", "power_kw")) {
        gd_case_key_where(c, "operating", "power_kw", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: operating.power_kw: give torque_nm or power_kw, not both "
                            "(valid: one of them; torque = 9550 P / n)", w);
    }
    double v;
    if (!operating_known(c, "speed_rpm", c->speed_rpm)) {
        if (varied(c, "operating.speed_rpm", &v)) {
            if (isfinite(v))
                gd_case_key_derive(c, "operating", "speed_rpm", &c->speed_rpm, v);
        } else if (needs_speed(c)) {
            return missing(c, "speed_rpm", "the operating point's pinion speed", err);
        }
    }
    int power = operating_known(c, "power_kw", c->power_kw), torque = !power && operating_known(c, "torque_nm", c->torque_nm);
    if (!power && !torque) {
        if (varied(c, "operating.power_kw", &v)) {
            if (!isfinite(v))
                return GD_OK;
            gd_case_key_derive(c, "operating", "power_kw", &c->power_kw, v);
            power = 1;
        } else if (varied(c, "operating.torque_nm", &v)) {
            if (!isfinite(v))
                return GD_OK;
            gd_case_key_derive(c, "operating", "torque_nm", &c->torque_nm, v);
            torque = 1;
        } else if (needs_load(c)) {
            return missing(c, "torque_nm", "the operating point's pinion torque", err);
        } else {
            return GD_OK;
        }
    }
    if (power) {
        if (!isfinite(c->speed_rpm))
            return missing(c, "speed_rpm", "the speed to turn operating.power_kw into a torque", err);
        gd_case_key_derive(c, "operating", "torque_nm", &c->torque_nm, 9550.0 * c->power_kw / c->speed_rpm);
        const gd_keyspec *k = gd_case_find_key("operating", "torque_nm");
        if (!gd_case_key_in_range(k, c->torque_nm)) {
            gd_case_key_where(c, "operating", "power_kw", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: operating.power_kw: the torque 9550 P / n = %.3g N m from "
                                "operating.power_kw = %g kW and operating.speed_rpm = %g rpm is out of range (valid: "
                                "a torque in [%g, %g] N m: power_kw <= %.3g at this speed)", w, c->torque_nm,
                                c->power_kw, c->speed_rpm, k->min, k->max, k->max * c->speed_rpm / 9550.0);
        }
    } else if (isfinite(c->speed_rpm)) {
        gd_case_key_derive(c, "operating", "power_kw", &c->power_kw, c->torque_nm * c->speed_rpm / 9550.0);
    }
    return GD_OK;
}

GD_API gd_status gd_case_check(gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    if (c->transient_max_periods > 0 && c->transient_max_periods < c->transient_periods) {
        gd_case_key_where(c, "run", "transient_max_periods", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: run.transient_max_periods: %d is below run.transient_periods = %d "
                            "(valid: 0, or at least transient_periods)", w, c->transient_max_periods,
                            c->transient_periods);
    }
    gd_status st = check_load(c, err);
    if (st != GD_OK)
        return st;
    /* static transmission error amplitude */
    int has_fa = gd_case_key_given(c, "excitation", "base_pitch_deviation_um");
    int has_fb = gd_case_key_given(c, "excitation", "profile_deviation_um");
    if (has_fa != has_fb) {
        gd_case_key_where(c, "excitation", has_fa ? "base_pitch_deviation_um" : "profile_deviation_um", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.%s: give both base_pitch_deviation_um and "
                            "profile_deviation_um (valid: both, e_r = sqrt(f_a^2 + f_b^2))", w,
                            has_fa ? "base_pitch_deviation_um" : "profile_deviation_um");
    }
    if (has_fa && gd_case_key_given(c, "excitation", "ste_amplitude_um")) {
        gd_case_key_where(c, "excitation", "ste_amplitude_um", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.ste_amplitude_um: give the amplitude or the two "
                            "deviations, not both (valid: one way)", w);
    }
    if (has_fa)
        gd_case_key_derive(c, "excitation", "ste_amplitude_um", &c->ste_amplitude_um,
               hypot(c->base_pitch_deviation_um, c->profile_deviation_um));
    else if (!gd_case_key_given(c, "excitation", "ste_amplitude_um"))
        c->ste_amplitude_um = 10.0;
    /* LTCA's transmission error as the error excitation: with LTCA's stiffness, or a constant one
     * (e = LTE - F/k(t) is the rest of the loaded TE once the mesh stiffness has given its share) */
    if (c->ste_source == GD_STE_LTCA && c->stiffness != GD_STIFF_LTCA && c->stiffness != GD_STIFF_CONSTANT) {
        gd_case_key_where(c, "excitation", "ste", w, sizeof w);
        char kind[32];
        gd_case_key_choice("excitation", "stiffness", c->stiffness, kind, sizeof kind);
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.ste: ltca with excitation.stiffness = %s (valid: "
                            "stiffness = ltca or constant; LTCA's transmission error is taken less the share F/k(t) "
                            "of the mesh stiffness, which must be LTCA's own or constant)", w, kind);
    }
    /* the periodicity tolerance follows the integration tolerance: a period of about a hundred
     * steps, each within rtol of the state (docs/numerics.md section 8) */
    gd_case_key_derive(c, "run", "periodicity_tol", &c->periodicity_tol,
                       c->method == GD_METHOD_RK4 || c->fixed_step ? 1e-6 : fmin(0.1, 100.0 * c->rtol));
    /* stiffness harmonics */
    if (c->n_stiffness_phases > c->n_stiffness_harmonics) {
        gd_case_key_where(c, "excitation", "stiffness_phases_deg", w, sizeof w);
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
        gd_case_key_where(c, "excitation", "stiffness_harmonics", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.stiffness_harmonics: amplitudes sum to %g, the "
                            "stiffness could become negative (valid: sum below 1)", w, asum);
    }
    if (c->gravity && c->model != GD_MODEL_BTA) {
        gd_case_key_where(c, "scene", "gravity", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: scene.gravity: on with scene.model = %s (valid: gravity = on only "
                            "with model = bta; the torsional models have no translation for the weights to move)", w,
                            c->model == GD_MODEL_TORSIONAL ? "torsional" : "torsional-lr");
    }
    if (c->impact && c->stiffness != GD_STIFF_LTCA) {
        static const char *const kind[] = {"constant", "harmonic", "rectangular"};
        gd_case_key_where(c, "excitation", "impact", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.impact: on with excitation.stiffness = %s (valid: "
                            "impact = on only with stiffness = ltca; the pulse sits at LTCA's mesh-in phase of LTCA's "
                            "mesh cycle, which a %s stiffness does not have)", w, kind[c->stiffness], kind[c->stiffness]);
    }
    if (gd_case_key_given(c, "solver", "order") && c->method == GD_METHOD_DIRK && c->order > 5) {
        gd_case_key_where(c, "solver", "order", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: solver.order: %d for dirk (valid: 2 to 5)", w, c->order);
    }
    if (c->lyapunov_exponents > 0 && c->lyapunov_method == GD_LYAP_TANGENT && !c->root_finding) {
        gd_case_key_where(c, gd_case_key_given(c, "run", "lyapunov_exponents") ? "run" : "solver",
              gd_case_key_given(c, "run", "lyapunov_exponents") ? "lyapunov_exponents" : "root_finding", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: run.lyapunov_exponents: the tangent method needs "
                            "solver.root_finding = on, the variational equations must switch exactly at every "
                            "contact (valid: lyapunov_exponents = 0, or lyapunov_method = two-trajectory)", w);
    }
    if (c->lyapunov_method == GD_LYAP_TWO_TRAJECTORY && c->lyapunov_exponents > 1) {
        gd_case_key_where(c, "run", "lyapunov_exponents", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: run.lyapunov_exponents: %d with the two-trajectory method "
                            "(valid: 1; the tangent method gives more)", w, c->lyapunov_exponents);
    }
    if (c->method == GD_METHOD_DIRK && !gd_case_key_given(c, "solver", "order"))
        c->order = 4;
    if (c->table[0]) {
        int dirk = c->method == GD_METHOD_DIRK;
        if (c->method == GD_METHOD_RK4 || !known_table(dirk ? dirk_tables : erk_tables, c->table)) {
            gd_case_key_where(c, "solver", "table", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: solver.table: '%s' is not an ARKODE %s table (valid:%s)", w,
                                c->table, c->method == GD_METHOD_RK4 ? "table for rk4" : dirk ? "DIRK" : "ERK",
                                c->method == GD_METHOD_RK4 ? " none for rk4, it is the classical RK4"
                                                          : dirk ? dirk_tables : erk_tables);
        }
    }
    return GD_OK;
}

GD_API const char *gd_case_key_unused(const gd_case *c, size_t i, int *absent)
{
    const gd_keyspec *k = &gd_case_schema(NULL)[i];
    int single = c->arrangement != GD_ARR_HERRINGBONE;
    *absent = 0;
#define IS(S_, K_) (strcmp(k->section, S_) == 0 && strcmp(k->key, K_) == 0)
    if (single && (IS("gear", "groove_width_mm") || IS("support", "shaft_stiffness_pinion_n_per_m") ||
                   IS("support", "shaft_stiffness_gear_n_per_m") || IS("damping", "shaft_damping_ratio"))) {
        *absent = 1;
        return "not used: a single pair has no relief groove and no groove shafts";
    }
    if (single && IS("excitation", "half_phase_deg")) {
        *absent = 1;
        return "not used: a single pair has one mesh";
    }
    if (c->stiffness != GD_STIFF_HARMONIC &&
        (IS("excitation", "stiffness_harmonics") || IS("excitation", "stiffness_phases_deg"))) {
        static const char *const why[] = {"ignored: excitation.stiffness = constant",
                                          "ignored: excitation.stiffness = harmonic",
                                          "ignored: excitation.stiffness = rectangular",
                                          "ignored: excitation.stiffness = ltca"};
        return c->stiffness >= 0 && c->stiffness < 4 ? why[c->stiffness] : "ignored";
    }
    if (c->stiffness != GD_STIFF_RECTANGULAR &&
        (IS("excitation", "rectangular_variation") || IS("excitation", "rectangular_high_fraction")))
        return "ignored: only excitation.stiffness = rectangular uses it";
    int ste = IS("excitation", "ste_amplitude_um") || IS("excitation", "ste_phase_deg") ||
              IS("excitation", "base_pitch_deviation_um") || IS("excitation", "profile_deviation_um");
    if (!c->error_excitation && (ste || IS("excitation", "ste_mean_um") || IS("excitation", "ste")))
        return "ignored: scene.error_excitation = off";
    if (c->ste_source == GD_STE_LTCA && ste)
        return "ignored: excitation.ste = ltca";
    if (!c->impact && IS("excitation", "impact_exponent"))
        return "ignored: excitation.impact = off";
    if (strcmp(k->section, "optimize") == 0) { /* the keys of the objectives over load and speed */
        int dyn = strcmp(c->opt_objective, "gear-dynamic") == 0 || strcmp(c->opt_objective2, "gear-dynamic") == 0;
        int range = strcmp(c->opt_objective, "gear-lte-range") == 0;
        if (!dyn && !range && (IS("optimize", "torques_nm") || IS("optimize", "torque_weights")))
            return "ignored: only optimize.objective = gear-lte-range or gear-dynamic uses it";
        if (!range && IS("optimize", "lte_range_combine"))
            return "ignored: only optimize.objective = gear-lte-range uses it";
        if (!dyn && (IS("optimize", "dynamic_combine") || IS("optimize", "speed_from_rpm") ||
                     IS("optimize", "speed_to_rpm") || IS("optimize", "dynamic_response") ||
                     IS("optimize", "dynamic_model") || IS("optimize", "dynamic_sweep_step_rpm")))
            return "ignored: only optimize.objective = gear-dynamic uses it";
        if ((c->opt_objective2[0] || (!dyn && !range)) && strncmp(k->key, "harris_", 7) == 0)
            return "ignored: only optimize.objective = gear-lte-range or gear-dynamic, with one objective, draws the "
                   "Harris map";
        if (!c->opt_robust && strncmp(k->key, "robust_", 7) == 0)
            return "ignored: optimize.robust = off";
        /* MOALO and the scalarisations: optimize's algorithm, or one of compare-optimizers' list */
        int compare = c->analysis == GD_ANALYSIS_COMPARE_OPTIMIZERS;
        int moalo = compare ? listed(c->opt_optimizers, "moalo") : c->opt_algorithm == 9; /* GD_OPT_MOALO */
        int scalar = compare ? listed(c->opt_optimizers, "weighted-sum") || listed(c->opt_optimizers, "eps-constraint")
                             : c->opt_algorithm == 10 || c->opt_algorithm == 11;
        if (!moalo && IS("optimize", "archive"))
            return compare ? "ignored: only optimize.optimizers with moalo uses it"
                           : "ignored: only optimize.algorithm = moalo uses it";
        if (!scalar && (IS("optimize", "scalar_algorithm") || IS("optimize", "scalar_grid")))
            return compare ? "ignored: only optimize.optimizers with weighted-sum or eps-constraint uses it"
                           : "ignored: only optimize.algorithm = weighted-sum or eps-constraint uses it";
    }
#undef IS
    return NULL;
}
