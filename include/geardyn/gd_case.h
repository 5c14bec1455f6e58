/* A case: every resolved input of a run, with its unit and where it came from.
 *
 * Case files are INI files (read with inih). One schema table (gd_case_schema)
 * names every section and key, its type, unit, valid range and default; parsing,
 * validation, --set overrides, `geardyn check` and sweeps all go through it.
 * Keys carry their unit in the name (speed_rpm, backlash_um, ...). Values are
 * stored in SI-friendly case units exactly as written; gd_case_resolve() then
 * fills the derived quantities (torque from power, masses and inertias from the
 * geometry, mean mesh stiffness from ISO 6336-1, ...) unless the user pinned them. */
#ifndef GD_CASE_H
#define GD_CASE_H

#include "geardyn/gd_error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GD_MAX_HARMONICS 8
#define GD_PATH_MAX 1024

typedef enum gd_analysis {
    GD_ANALYSIS_RESPONSE = 0, GD_ANALYSIS_SWEEP = 1, GD_ANALYSIS_TCA = 2, GD_ANALYSIS_LTCA = 3,
    GD_ANALYSIS_OPTIMIZE = 4, GD_ANALYSIS_COMPARE_OPTIMIZERS = 5, GD_ANALYSIS_WORK_PRECISION = 6,
    GD_ANALYSIS_CONTINUATION = 7,
    GD_ANALYSIS_BASINS = 8
} gd_analysis;
typedef enum gd_model_kind { GD_MODEL_TORSIONAL = 0, GD_MODEL_TORSIONAL_LR = 1, GD_MODEL_BTA = 2 } gd_model_kind;
typedef enum gd_stiffness_kind {
    GD_STIFF_CONSTANT = 0, GD_STIFF_HARMONIC = 1, GD_STIFF_RECTANGULAR = 2, GD_STIFF_LTCA = 3,
    GD_STIFF_TABLE = 100 /* model level: a tabulated stiffness (from LTCA) */
} gd_stiffness_kind;
typedef enum gd_method { GD_METHOD_ERK = 0, GD_METHOD_DIRK = 1, GD_METHOD_RK4 = 2 } gd_method;
typedef enum gd_vector_kernels { GD_VECTOR_KERNELS_GEARDYN = 0, GD_VECTOR_KERNELS_SUNDIALS = 1 } gd_vector_kernels;
typedef enum gd_damping_mode { GD_DAMP_ALWAYS = 0, GD_DAMP_CONTACT = 1 } gd_damping_mode;
/* [excitation] impact_form: the mesh-in pulse while the drive flanks touch, with the impulse m_n v_s;
 * or the paper's external force, acting whatever the contact, for the rise time capped at a quarter period */
typedef enum gd_impact_form { GD_IMPACT_CONTACT = 0, GD_IMPACT_PAPER = 1 } gd_impact_form;
typedef enum gd_initial { GD_INIT_STATIC = 0, GD_INIT_ZERO = 1 } gd_initial;
/* [gear] arrangement: two helical halves of opposite hand, one helical pair, or a spur pair (beta = 0) */
typedef enum gd_arrangement { GD_ARR_HERRINGBONE = 0, GD_ARR_HELICAL = 1, GD_ARR_SPUR = 2 } gd_arrangement;
typedef enum gd_hand { GD_HAND_RIGHT = 0, GD_HAND_LEFT = 1 } gd_hand;
/* [excitation] ste: the static transmission error e(t) as a sinusoid, or LTCA's own */
typedef enum gd_ste_source { GD_STE_SINUSOID = 0, GD_STE_LTCA = 1 } gd_ste_source;
/* [solver] tca_formulation: (b) surface separation, (a) surface tangency, or both compared */
typedef enum gd_tca_formulation { GD_TCA_SEPARATION = 0, GD_TCA_TANGENCY = 1, GD_TCA_BOTH = 2 } gd_tca_formulation;
/* [support] pinion_axial: LTCA with an axially floating pinion (equal axial forces on the halves) or a fixed one */
typedef enum gd_pinion_axial { GD_PINION_FLOATING = 0, GD_PINION_FIXED = 1 } gd_pinion_axial;
/* [continuation] shooting, start and the response drawn */
typedef enum gd_cont_shooting { GD_SHOOT_MULTIPLE = 0, GD_SHOOT_SINGLE = 1 } gd_cont_shooting;
typedef enum gd_cont_start { GD_CONT_START_ATTRACTOR = 0, GD_CONT_START_STATE = 1, GD_CONT_START_SWEEP = 2 } gd_cont_start;
typedef enum gd_cont_response {
    GD_CONT_RESP_RMS_ACCEL = 0, GD_CONT_RESP_MAX_DEFLECTION = 1, GD_CONT_RESP_MIN_DEFLECTION = 2,
    GD_CONT_RESP_POINCARE = 3, GD_CONT_RESP_DYNAMIC_LOAD_FACTOR = 4
} gd_cont_response;
/* [basins] base: the components off the section at the static state or at a given state */
typedef enum gd_basins_base { GD_BASINS_BASE_STATIC = 0, GD_BASINS_BASE_STATE = 1 } gd_basins_base;
typedef enum gd_lyapunov_method { GD_LYAP_TANGENT = 0, GD_LYAP_TWO_TRAJECTORY = 1 } gd_lyapunov_method;

/* Where a resolved value came from. */
typedef enum gd_source { GD_SRC_DEFAULT = 0, GD_SRC_FILE = 1, GD_SRC_SET = 2, GD_SRC_DERIVED = 3 } gd_source;

typedef struct gd_case {
    /* [scene] */
    int analysis;            /* gd_analysis */
    int model;               /* gd_model_kind */
    int bearing_clearance;   /* physics switches: 1 on, 0 off */
    int error_excitation;
    int axial_coupling;
    int gravity;             /* the bodies' weights on their supports (bta) */
    char title[256];
    /* [gear] geometry (ISO 21771) and bodies; masses and inertias are per helical half,
     * each including half of the relief groove */
    double normal_module_mm, helix_angle_deg, normal_pressure_angle_deg;
    int teeth_pinion, teeth_gear;
    double profile_shift_pinion, profile_shift_gear, addendum_coefficient, dedendum_coefficient;
    double face_width_pinion_mm, face_width_gear_mm, groove_width_mm;
    double bore_diameter_pinion_mm, bore_diameter_gear_mm;
    /* the blank of a body that is not a solid disc (docs/model.md section 9.2): a rim down to its inner
     * diameter (0: none, a solid blank), a web of an axial thickness, a hub of a diameter and length */
    double rim_inner_diameter_pinion_mm, rim_inner_diameter_gear_mm, web_thickness_pinion_mm, web_thickness_gear_mm;
    double hub_diameter_pinion_mm, hub_diameter_gear_mm, hub_length_pinion_mm, hub_length_gear_mm;
    double youngs_modulus_gpa, poisson_ratio, density_kg_per_m3;
    double pinion_mass_kg, gear_mass_kg, pinion_inertia_kgm2, gear_inertia_kgm2;
    double equivalent_mass_kg; /* torsional equivalent mass of one half, m_e */
    int arrangement;         /* gd_arrangement */
    int pinion_hand;         /* gd_hand of the pinion helix in the left half (gear and right half opposite) */
    /* [modification] of the pinion flank (docs/geometry.md): amounts normal to the flank, profile
     * lengths as transverse roll lengths, lead lengths along the axis */
    double root_relief_amount_um, root_relief_length_mm, tip_relief_amount_um, tip_relief_length_mm; /* y1..y4 */
    double lead_relief_inner_um, lead_relief_outer_um, lead_unmodified_length_mm;                 /* y5, y6, y7 */
    double lead_unmodified_centre_mm, helix_slope_um;                                           /* y8, y9 */
    int modification_apply;  /* 0: the amounts above are kept in the case but the flank is unmodified */
    /* [misalignment] of the gear axis about the middle of the gear, and centre-distance error */
    double axis_in_plane_arcmin, axis_cross_plane_arcmin, centre_distance_error_mm;
    /* [operating] */
    double speed_rpm, torque_nm, power_kw;
    /* [clearance]: total backlash 2b and total radial bearing clearance 2*eps */
    double backlash_um, bearing_clearance_um;
    /* [excitation] */
    int stiffness;           /* gd_stiffness_kind */
    double mesh_stiffness_n_per_m;  /* mean mesh stiffness of one half */
    double stiffness_harmonics[GD_MAX_HARMONICS]; int n_stiffness_harmonics; /* relative amplitudes */
    double stiffness_phases_deg[GD_MAX_HARMONICS]; int n_stiffness_phases;
    double rectangular_variation;   /* (k_high - k_mean)/k_mean */
    double rectangular_high_fraction; /* fraction of the mesh period at the high level */
    int ste_source;          /* gd_ste_source: the sinusoid or LTCA's transmission error */
    double ste_amplitude_um, ste_mean_um, ste_phase_deg;
    double base_pitch_deviation_um, profile_deviation_um;
    double half_phase_deg;   /* mesh phase of the right half relative to the left */
    int impact;              /* mesh-in impact from LTCA */
    int impact_form;         /* gd_impact_form */
    double impact_exponent;
    /* [damping] */
    double mesh_damping_ratio, support_damping_ratio, shaft_damping_ratio;
    int mesh_damping_mode;   /* gd_damping_mode */
    int bearing_damping_mode; /* gd_damping_mode of the radial bearings with a clearance */
    /* [support] (per half, per body) */
    double radial_stiffness_pinion_n_per_m, radial_stiffness_gear_n_per_m;
    double axial_stiffness_pinion_n_per_m, axial_stiffness_gear_n_per_m;
    double shaft_stiffness_pinion_n_per_m, shaft_stiffness_gear_n_per_m; /* groove shafts, axial */
    int pinion_axial;        /* gd_pinion_axial (LTCA) */
    double gravity_angle_deg; /* direction of the weights from +y (the transverse line of action) */
    /* [solver] */
    int method;              /* gd_method */
    int order;
    char table[128];
    double rtol, atol;
    int steps_per_period;    /* rk4, erk with fixed_step */
    int fixed_step;
    int root_finding;
    int grazing_watch;
    int exact_samples;       /* steps end on the sample times of the recorded window (docs/numerics.md section 9) */
    int vector_kernels;      /* gd_vector_kernels */
    int gated_roots;         /* 1: ARKODE is given the root functions only to locate a crossing found at a step end */
    int compiled_rhs;        /* 1: the RHS compiled for the held contact modes (src/dynamics/rhs_plan.h) */
    double max_step_fraction;
    double characteristic_length_um;
    int max_events_per_period;
    int tca_profile_points, tca_face_points, tca_positions_per_cycle, tca_cycles;
    int tca_formulation;     /* gd_tca_formulation */
    int tca_refine;          /* refine the grid minimum to the exact minimum (Newton) */
    int ltca_positions_per_cycle, ltca_face_slices; /* LTCA discretisation */
    /* [run] */
    int transient_periods, record_periods;
    int transient_max_periods; /* 0: the transient is transient_periods; else extended until the section settles */
    int initial_condition;   /* gd_initial */
    int lyapunov_exponents;  /* 0 off, 1 the largest, k the first k */
    int lyapunov_method;     /* gd_lyapunov_method */
    double lyapunov_separation; /* two-trajectory: initial separation (dimensionless) */
    double periodicity_tol;  /* relative tolerance for equal Poincare points */
    double chaos_threshold_per_period; /* |MLE| per mesh period separating chaos / quasi-periodicity */
    double max_time_s;       /* a run whose estimated time exceeds this is refused (gd_run_cost_check) */
    /* [output] */
    char directory[GD_PATH_MAX];
    int samples_per_period;
    int time_history, event_log, plots;
    char response_variable[32];
    double max_bytes;        /* a run whose estimated memory or files exceed this is refused (gd_run_cost_check) */
    /* [sweep] (analysis = sweep; gd_sweep.h): parameter and parameter2 are "section.key" */
    char sweep_parameter[256], sweep_parameter2[256];
    double sweep_from, sweep_to, sweep_from2, sweep_to2; /* in the unit of the swept key */
    int sweep_points, sweep_points2;
    int sweep_spacing, sweep_spacing2; /* gd_sweep_spacing */
    int sweep_mode;          /* gd_sweep_mode */
    int sweep_direction;     /* gd_sweep_direction */
    char sweep_response[256]; /* Poincare responses, comma-separated ("": lambda_L, lambda_R) */
    double paint_thickness_um; /* TCA contact pattern: separation below this is marked */

    /* [workprecision] (analysis = work-precision; gd_workprec.h, docs/accuracy.md) */
    char wp_families[256];   /* comma-separated: rk4, erk2..erk8, dirk2..dirk5 */
    int wp_root_finding_off; /* also run every family with root finding off */
    int wp_rk4_steps_min, wp_rk4_steps_max;
    double wp_rtol_loosest, wp_rtol_tightest;
    int wp_rtols_per_decade;
    double wp_atol_over_rtol;
    double wp_reference_rtol, wp_reference_max_error, wp_reference_max_step_fraction;
    int wp_reference_order, wp_check_order;
    int wp_horizon_periods;
    int wp_order_study, wp_order_steps_min, wp_order_steps_max;
    int wp_repeats, wp_max_steps_per_period;
    int wp_lyapunov;
    int wp_scene_class;      /* gd_wp_class */

    /* [optimize] (analysis = optimize, compare-optimizers; gd_optimize.h, docs/optimisation.md) */
    int opt_algorithm;       /* gd_opt_algorithm (optimize) */
    char opt_optimizers[256]; /* comma-separated algorithm names (compare-optimizers) */
    char opt_objective[256]; /* comma-separated objectives: gear-lte or test functions */
    double opt_dimensions[GD_MAX_HARMONICS]; int n_opt_dimensions; /* test functions */
    int opt_iterations, opt_population, opt_seed, opt_runs, opt_budget_evals, opt_ecdf_targets;
    double opt_target, opt_target_loosest, opt_shift;
    char opt_variables[128]; /* gear-lte: the design variables (symbols y1 .. y9), comma-separated */
    /* bounds of the gear variables (Eq. 13 for y1..y7; y6 has y5's) */
    double opt_root_amount_min_um, opt_root_amount_max_um, opt_root_length_min_mm, opt_root_length_max_mm;
    double opt_tip_amount_min_um, opt_tip_amount_max_um, opt_tip_length_min_mm, opt_tip_length_max_mm;
    double opt_lead_amount_min_um, opt_lead_amount_max_um, opt_lead_length_min_mm, opt_lead_length_max_mm;
    double opt_lead_centre_min_mm, opt_lead_centre_max_mm, opt_helix_slope_min_um, opt_helix_slope_max_um;
    /* the objectives over load and speed (docs/optimisation.md section 12) */
    double opt_torques_nm[GD_MAX_HARMONICS]; int n_opt_torques;
    double opt_torque_weights[GD_MAX_HARMONICS]; int n_opt_torque_weights;
    int opt_lte_range_combine, opt_dynamic_combine; /* gd_opt_combine */
    double opt_speed_from_rpm, opt_speed_to_rpm, opt_dynamic_sweep_step_rpm;
    int opt_dynamic_response; /* gd_dyn_measure */
    int opt_dynamic_model;    /* gd_model_kind of the dynamics in the loop */
    double opt_harris_from_nm, opt_harris_to_nm; /* the Harris map after the optimum: its torque grid */
    int opt_harris_torques;
    int opt_robust, opt_robust_samples; /* the robust variant of the gear objectives */
    double opt_robust_quantile, opt_robust_tilt_arcmin, opt_robust_centre_distance_mm;
    double opt_robust_amount_um, opt_robust_length_mm;
    char opt_objective2[256]; /* two objectives at once: the second (gear-dynamic), or "" */
    int opt_archive, opt_scalar_algorithm, opt_scalar_grid;
    double opt_hv_reference[GD_MAX_HARMONICS]; int n_opt_hv_reference;

    /* [continuation] (analysis = continuation; gd_continuation.h, docs/continuation.md) */
    char cont_parameter[256]; /* "section.key" */
    double cont_from, cont_to, cont_start_value; /* in the unit of the parameter's key */
    int cont_direction;      /* gd_sweep_direction: up, down, both */
    double cont_ds, cont_ds_min, cont_ds_max; /* arclength steps (dimensionless) */
    double cont_dp_max;      /* in the unit of the parameter's key; 0: no limit */
    int cont_max_points;
    double cont_newton_tol;
    int cont_newton_max_iterations;
    double cont_locate_tol;
    int cont_period;         /* mesh periods of the orbit; 0: found after the transient */
    int cont_shooting;       /* gd_cont_shooting */
    int cont_start;          /* gd_cont_start */
    char cont_state[1024];   /* start = state: the dimensionless state, comma-separated */
    char cont_start_sweep[GD_PATH_MAX]; /* start = sweep: a finished sweep's directory */
    int cont_start_sweep_direction; /* gd_sweep_branch of the sweep's point: up, down, independent */
    int cont_max_branches;   /* branches at most, the start's and the switched ones */
    int cont_branch_switching;
    char cont_overlay_sweep[GD_PATH_MAX]; /* a finished sweep's directory ("": none) */
    int cont_response;       /* gd_cont_response */
    char cont_parameter2[256]; /* "section.key" of the curves' second parameter ("": no curves) */
    double cont_from2, cont_to2; /* its bounds, in the unit of its key */
    int cont_curve_max_points; /* points of one curve in one direction at most */
    char cont_curve_start[GD_PATH_MAX]; /* an earlier continuation's bifurcations.csv: one row's curve only ("": all) */
    int cont_curve_start_row; /* its data row, 1 the first */
    char cont_curve_kinds[128]; /* the kinds of bifurcation continued in parameter2, comma-separated */
    char cont_overlay_map[GD_PATH_MAX]; /* a finished regime map in the two keys, under the curves ("": none) */
    char cont_overlay_curves[GD_PATH_MAX]; /* an earlier continuation's curves in the two keys, beside them ("": none) */

    /* [basins] (analysis = basins; gd_basins.h, docs/basins.md) */
    char bas_x[32], bas_y[32];   /* the section's coordinates */
    double bas_x_from, bas_x_to, bas_y_from, bas_y_to; /* its box, in the coordinates' units (NaN: derived) */
    double bas_phase_deg;    /* mesh phase of the section */
    int bas_base;            /* gd_basins_base */
    char bas_state[1024];    /* base = state: the dimensionless state, comma-separated */
    int bas_resolution, bas_resolution_y; /* cells of the box per coordinate (resolution_y 0: resolution) */
    int bas_picture;         /* the grid of resolution x resolution_y initial states */
    int bas_samples, bas_seed; /* the random sample of the fractions, its seed */
    int bas_max_periods;     /* mesh periods of one trajectory at most */
    double bas_margin;       /* the tessellation beyond the box, in box widths */
    int bas_consecutive_recurrences, bas_consecutive_attractor_steps, bas_consecutive_basin_steps,
        bas_consecutive_lost_steps;
    int bas_lyapunov_periods;
    double bas_newton_tol;
    int bas_entropy_box_cells;
    char bas_continuation[GD_PATH_MAX]; /* a finished continuation's directory ("": none) */
    char bas_parameter[256]; /* the fractions over a numeric key, "section.key" ("": one value) */
    double bas_from, bas_to; /* in the unit of that key */
    int bas_points;

    /* bookkeeping, not keys */
    char path[GD_PATH_MAX];  /* case file it was read from ("" if none) */
    unsigned char *src;      /* gd_source per schema entry */
    int *src_line;           /* file line (or --set index) per schema entry */
    int ltca_deferred;       /* 1 (geardyn check): resolving and building run no LTCA; the mesh stiffness of
                              * stiffness = ltca is ISO 6336-1's estimate until a run computes it */
    gd_stop_hook stop;       /* asked before each position of the LTCA that resolving or building the model
                              * of this case runs (gd_ltca_settings_from_case hands it on); copies keep it;
                              * never part of a cache key. {NULL}: never stopped */
} gd_case;

typedef enum gd_keytype {
    GD_KEY_DOUBLE, GD_KEY_INT, GD_KEY_ENUM, GD_KEY_BOOL, GD_KEY_STRING, GD_KEY_DLIST
} gd_keytype;

typedef struct gd_keyspec {
    const char *section;
    const char *key;
    gd_keytype type;
    const char *unit;        /* "" for dimensionless */
    size_t offset;           /* into gd_case */
    size_t count_offset;     /* DLIST: offset of the int count */
    double min, max;         /* valid closed range (DOUBLE, INT, DLIST elements) */
    int min_open, max_open;  /* 1: the bound itself is excluded */
    double def;              /* default (NaN: derived from other inputs) */
    const char *choices;     /* ENUM: '|'-separated names, index = stored value; STRING: default */
    const char *help;
} gd_keyspec;

GD_API const gd_keyspec *gd_case_schema(size_t *n);
GD_API const gd_keyspec *gd_case_find_key(const char *section, const char *key);

/* Initialise with every default. Free with gd_case_free. */
GD_API gd_status gd_case_init(gd_case *c, gd_error *err);
GD_API void gd_case_free(gd_case *c);
GD_API gd_status gd_case_copy(gd_case *dst, const gd_case *src, gd_error *err);
/* The same on the heap, for a caller that does not know the size of gd_case (a foreign-function
 * interface): a case with every default, or a copy of src; NULL with err set when out of memory.
 * Free with gd_case_delete (NULL allowed). */
GD_API gd_case *gd_case_new(gd_error *err);
GD_API gd_case *gd_case_dup(const gd_case *src, gd_error *err);
GD_API void gd_case_delete(gd_case *c);

/* Read an INI case file over the defaults; strict validation of every line. */
GD_API gd_status gd_case_load(gd_case *c, const char *path, gd_error *err);
/* The same from the len bytes of text, checked as a case file's are; name stands for the file in
 * messages and is the case's path (relative paths in it are taken from the working directory). */
GD_API gd_status gd_case_load_text(gd_case *c, const char *text, size_t len, const char *name, gd_error *err);
/* Apply "section.key=value" (the command line's --set). */
GD_API gd_status gd_case_set(gd_case *c, const char *assignment, int set_index, gd_error *err);
/* The cross-key checks that need no physics (torque or power, STE, stiffness harmonics, solver
 * settings) and the values they derive; the first step of gd_case_resolve (gd_analysis.h). */
GD_API gd_status gd_case_check(gd_case *c, gd_error *err);

/* Value of a numeric key as a double ("operating.speed_rpm"); for sweeps. */
GD_API gd_status gd_case_get_number(const gd_case *c, const char *name, double *value, gd_error *err);
GD_API gd_status gd_case_set_number(gd_case *c, const char *name, double value, gd_error *err);
/* The values of a key that is a list of numbers: the first max into values, their count in *n. */
GD_API gd_status gd_case_get_list(const gd_case *c, const char *name, double *values, int max, int *n,
                                  gd_error *err);
/* The value of schema entry i formatted as the case file would write it. */
GD_API void gd_case_format_value(const gd_case *c, size_t i, char *buf, size_t len);
GD_API gd_source gd_case_source(const gd_case *c, size_t i, int *line);
/* Whether schema entry i is unused by the case as resolved: NULL when it is used, else why not
 * ("ignored: excitation.stiffness = ltca"); *absent = 1 when the key does not exist for this pair
 * at all (a single pair's groove width and groove shafts), so that a listing may leave it out. */
GD_API const char *gd_case_key_unused(const gd_case *c, size_t i, int *absent);
GD_API const char *gd_source_name(gd_source s);
/* The physical values a resolved case takes from the schema's defaults: the numbers of [gear],
 * [modification], [misalignment], [clearance], [excitation], [damping] and [support] that its
 * analysis and model use, that neither the file nor --set gives, that no other key derives and that
 * its sweep or continuation does not vary. Writes up to cap schema indices into idx (may be NULL)
 * and returns how many there are. (The operating point has no default: gd_case_check refuses a case
 * whose analysis needs it and lacks it.) */
GD_API size_t gd_case_defaulted_keys(const gd_case *c, size_t *idx, size_t cap);

#ifdef __cplusplus
}
#endif
#endif
