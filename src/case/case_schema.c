/* The case-file schema: every section and key, its type, unit, range and default. */
#include "geardyn/gd_case.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#define OFF(f) offsetof(gd_case, f)
#define D(sec, k, unit, f, lo, hi, lo_open, hi_open, def, help) \
    { sec, k, GD_KEY_DOUBLE, unit, OFF(f), 0, lo, hi, lo_open, hi_open, def, NULL, help }
#define I(sec, k, f, lo, hi, def, help) \
    { sec, k, GD_KEY_INT, "", OFF(f), 0, lo, hi, 0, 0, def, NULL, help }
#define E(sec, k, f, def, choices, help) \
    { sec, k, GD_KEY_ENUM, "", OFF(f), 0, 0, 0, 0, 0, def, choices, help }
#define B(sec, k, f, def, help) \
    { sec, k, GD_KEY_BOOL, "", OFF(f), 0, 0, 1, 0, 0, def, "off|on", help }
#define S(sec, k, f, def, help) \
    { sec, k, GD_KEY_STRING, "", OFF(f), 0, 0, 0, 0, 0, 0, def, help }
#define L(sec, k, unit, f, cnt, lo, hi, help) \
    { sec, k, GD_KEY_DLIST, unit, OFF(f), OFF(cnt), lo, hi, 0, 0, 0, NULL, help }

static const gd_keyspec schema[] = {
    /* [scene] */
    E("scene", "analysis", analysis, 0, "response|sweep|tca|ltca|optimize|compare-optimizers|work-precision|continuation|basins",
      "what to compute"),
    E("scene", "model", model, 2, "torsional|torsional-lr|bta",
      "dynamic model: one mesh coordinate, the two helical halves, or bending-torsion-axial (10 DOF; 5 for a single pair)"),
    B("scene", "bearing_clearance", bearing_clearance, 1, "radial bearing clearance (dead zone) in the supports"),
    B("scene", "error_excitation", error_excitation, 1, "static transmission error excitation e(t)"),
    B("scene", "axial_coupling", axial_coupling, 1, "axial mesh force component and axial DOFs (bta)"),
    B("scene", "gravity", gravity, 0,
      "the weights of the bodies on their radial supports (bta; the direction is support.gravity_angle_deg)"),
    S("scene", "title", title, "", "free text shown in outputs"),

    /* [gear] */
    D("gear", "normal_module_mm", "mm", normal_module_mm, 0.1, 100, 0, 0, 5, "normal module m_n"),
    I("gear", "teeth_pinion", teeth_pinion, 6, 500, 30, "number of teeth z1 (pinion, driving)"),
    I("gear", "teeth_gear", teeth_gear, 6, 2000, 72, "number of teeth z2 (gear, driven)"),
    D("gear", "helix_angle_deg", "deg", helix_angle_deg, 0, 45, 0, 0, 33.27, "reference helix angle beta (left half hand; right half opposite)"),
    D("gear", "normal_pressure_angle_deg", "deg", normal_pressure_angle_deg, 10, 35, 0, 0, 20, "normal pressure angle alpha_n"),
    D("gear", "profile_shift_pinion", "", profile_shift_pinion, -1, 1.5, 0, 0, 0, "profile shift coefficient x1"),
    D("gear", "profile_shift_gear", "", profile_shift_gear, -1, 1.5, 0, 0, 0, "profile shift coefficient x2"),
    D("gear", "addendum_coefficient", "", addendum_coefficient, 0.5, 1.5, 0, 0, 1.0, "addendum coefficient h_a*"),
    D("gear", "dedendum_coefficient", "", dedendum_coefficient, 0.8, 1.8, 0, 0, 1.25, "dedendum coefficient h_f*"),
    D("gear", "face_width_pinion_mm", "mm", face_width_pinion_mm, 0, 5000, 1, 0, 40, "face width of the pinion: one helical half (herringbone) or the pair (spur, helical)"),
    D("gear", "face_width_gear_mm", "mm", face_width_gear_mm, 0, 5000, 1, 0, 44, "face width of the gear: one helical half (herringbone) or the pair (spur, helical)"),
    D("gear", "groove_width_mm", "mm", groove_width_mm, 0, 5000, 0, 0, 50, "relief groove between the halves (herringbone; none in a single pair)"),
    D("gear", "bore_diameter_pinion_mm", "mm", bore_diameter_pinion_mm, 0, 10000, 0, 0, 0, "bore of the pinion body (0: solid)"),
    D("gear", "bore_diameter_gear_mm", "mm", bore_diameter_gear_mm, 0, 10000, 0, 0, 0, "bore of the gear body (0: solid)"),
    D("gear", "rim_inner_diameter_pinion_mm", "mm", rim_inner_diameter_pinion_mm, 0, 10000, 0, 0, 0,
      "inner diameter of the pinion's rim, where its web begins (0: a solid blank; between the hub or bore and the root "
      "circle); the masses and inertias only (docs/model.md section 9.2)"),
    D("gear", "rim_inner_diameter_gear_mm", "mm", rim_inner_diameter_gear_mm, 0, 10000, 0, 0, 0,
      "inner diameter of the gear's rim (see rim_inner_diameter_pinion_mm)"),
    D("gear", "web_thickness_pinion_mm", "mm", web_thickness_pinion_mm, 0, 10000, 1, 0, NAN,
      "axial thickness of the pinion's web between rim and hub (needed with rim_inner_diameter_pinion_mm)"),
    D("gear", "web_thickness_gear_mm", "mm", web_thickness_gear_mm, 0, 10000, 1, 0, NAN,
      "axial thickness of the gear's web (needed with rim_inner_diameter_gear_mm)"),
    D("gear", "hub_diameter_pinion_mm", "mm", hub_diameter_pinion_mm, 0, 10000, 0, 0, 0,
      "outer diameter of the pinion's hub (0: none, the web or the blank reaches the bore)"),
    D("gear", "hub_diameter_gear_mm", "mm", hub_diameter_gear_mm, 0, 10000, 0, 0, 0,
      "outer diameter of the gear's hub (0: none)"),
    D("gear", "hub_length_pinion_mm", "mm", hub_length_pinion_mm, 0, 10000, 1, 0, NAN,
      "axial length of the pinion's hub (derived: the body's width, the face, or both halves and the groove)"),
    D("gear", "hub_length_gear_mm", "mm", hub_length_gear_mm, 0, 10000, 1, 0, NAN,
      "axial length of the gear's hub (derived likewise)"),
    D("gear", "youngs_modulus_gpa", "GPa", youngs_modulus_gpa, 1, 1000, 0, 0, 206, "Young's modulus E"),
    D("gear", "poisson_ratio", "", poisson_ratio, 0, 0.5, 0, 1, 0.3, "Poisson's ratio nu"),
    D("gear", "density_kg_per_m3", "kg/m^3", density_kg_per_m3, 100, 30000, 0, 0, 7850, "density"),
    D("gear", "pinion_mass_kg", "kg", pinion_mass_kg, 0, 1e6, 1, 0, NAN, "mass of the pinion per mesh: one half incl. half the groove, or the whole body of a single pair (derived)"),
    D("gear", "gear_mass_kg", "kg", gear_mass_kg, 0, 1e6, 1, 0, NAN, "mass of the gear per mesh: one half incl. half the groove, or the whole body of a single pair (derived)"),
    D("gear", "pinion_inertia_kgm2", "kg m^2", pinion_inertia_kgm2, 0, 1e6, 1, 0, NAN, "polar inertia of the pinion per mesh: one half, or the whole body of a single pair (derived)"),
    D("gear", "gear_inertia_kgm2", "kg m^2", gear_inertia_kgm2, 0, 1e6, 1, 0, NAN, "polar inertia of the gear per mesh: one half, or the whole body of a single pair (derived)"),
    D("gear", "equivalent_mass_kg", "kg", equivalent_mass_kg, 0, 1e6, 1, 0, NAN,
      "torsional equivalent mass per mesh m_e = I1 I2/(I1 rb2^2 + I2 rb1^2) (derived)"),
    E("gear", "arrangement", arrangement, 0, "herringbone|helical|spur",
      "two helical halves of opposite hand on common bodies, one helical pair, or a spur pair (helix_angle_deg = 0)"),
    E("gear", "pinion_hand", pinion_hand, 0, "right|left",
      "hand of the pinion helix (a herringbone: of its left half; the right half and the gear have the opposite hand)"),

    /* [modification]: pinion flank only, form-ground (docs/geometry.md). Amounts are measured normal to
     * the flank; profile lengths are transverse roll lengths; lead lengths are axial. */
    D("modification", "root_relief_amount_um", "um", root_relief_amount_um, 0, 1000, 0, 0, 0,
      "y1: root relief normal to the flank at the start of active profile (parabolic)"),
    D("modification", "root_relief_length_mm", "mm", root_relief_length_mm, 0, 1000, 0, 0, 0,
      "y2: roll length from the start of active profile up to where the root relief ends"),
    D("modification", "tip_relief_amount_um", "um", tip_relief_amount_um, 0, 1000, 0, 0, 0,
      "y3: tip relief normal to the flank at the tip (parabolic)"),
    D("modification", "tip_relief_length_mm", "mm", tip_relief_length_mm, 0, 1000, 0, 0, 0,
      "y4: roll length from the tip down to where the tip relief ends"),
    D("modification", "lead_relief_inner_um", "um", lead_relief_inner_um, 0, 1000, 0, 0, 0,
      "y5: lead relief normal to the flank on the reference circle at the face end toward the groove "
      "(herringbone) or at the -z end (helical, spur)"),
    D("modification", "lead_relief_outer_um", "um", lead_relief_outer_um, 0, 1000, 0, 0, 0,
      "y6: lead relief at the other face end (same measure as y5)"),
    D("modification", "lead_unmodified_length_mm", "mm", lead_unmodified_length_mm, 0, 5000, 0, 0, 0,
      "y7: axial length without lead relief, centred on the face of each half unless moved by y8 (0: crowned over "
      "the whole face)"),
    D("modification", "lead_unmodified_centre_mm", "mm", lead_unmodified_centre_mm, -2500, 2500, 0, 0, 0,
      "y8: axial position of the middle of the unmodified lead band from the middle of the face, + toward the "
      "y6 end: the lead relief at the y6 end is 2 y8 shorter than at the y5 end (asymmetric lead relief)"),
    D("modification", "helix_slope_um", "um", helix_slope_um, -1000, 1000, 0, 0, 0,
      "y9: helix slope modification (a change of the pinion's helix angle): the flank moved normal to itself by "
      "y9/2 at the y6 end and -y9/2 at the y5 end, linearly across the face (+: material removed toward the y6 end)"),
    B("modification", "apply", modification_apply, 1,
      "off: grind nothing (every amount and length above resolves to 0), so one key switches a case between the "
      "modified and the unmodified pair"),

    /* [misalignment] */
    D("misalignment", "axis_in_plane_arcmin", "arcmin", axis_in_plane_arcmin, -600, 600, 0, 0, 0,
      "gear axis tilt in the plane of the axes, about the middle of the gear (+: its +z end moves away from the "
      "pinion; +z: the end from which the pinion is seen turning counter-clockwise, docs/tca.md section 2)"),
    D("misalignment", "axis_cross_plane_arcmin", "arcmin", axis_cross_plane_arcmin, -600, 600, 0, 0, 0,
      "gear axis tilt across the plane of the axes, about the middle of the gear (+: rotation about the line of "
      "centres, its +z end moves to -y, against the pinion's pitch-point motion); the paper's delta is the "
      "resultant of the two components"),
    D("misalignment", "centre_distance_error_mm", "mm", centre_distance_error_mm, 0, 10, 0, 0, 0,
      "dE: centre distance increase (the flanks have no backlash allowance: a decrease would jam the pair)"),


    /* [operating] */
    D("operating", "speed_rpm", "rpm", speed_rpm, 0, 100000, 1, 0, NAN,
      "pinion (input) speed n; no default: a response, sweep, continuation or work-precision needs it (a sweep or "
      "continuation of this key gives it)"),
    D("operating", "torque_nm", "N m", torque_nm, 0, 1e8, 0, 0, NAN, "pinion torque, of the whole pair (a herringbone's halves share it); no default: this or power_kw is needed by "
      "every analysis but tca (and the optimisers' test functions)"),
    D("operating", "power_kw", "kW", power_kw, 0, 1e6, 1, 0, NAN, "input power P: torque = 9550 P / n (exclusive with torque_nm)"),

    /* [clearance] */
    D("clearance", "backlash_um", "um", backlash_um, 0, 5000, 0, 0, 10, "total backlash 2b of each mesh along the line of action"),
    D("clearance", "bearing_clearance_um", "um", bearing_clearance_um, 0, 5000, 0, 0, 5, "total radial clearance 2*eps of every bearing"),

    /* [excitation] */
    E("excitation", "stiffness", stiffness, 1, "constant|harmonic|rectangular|ltca",
      "mesh stiffness k(t) of each half (ltca: from loaded tooth contact analysis, docs/ltca.md)"),
    B("excitation", "impact", impact, 0,
      "mesh-in impact force from LTCA, once per mesh period per half (paper section 5.2; needs stiffness = ltca)"),
    E("excitation", "impact_form", impact_form, 0, "contact|paper",
      "contact: the pulse acts while the drive flanks touch, peak F_s and impulse m_n v_s; paper: an external force "
      "whatever the contact, F_s for the contact's rise time, at most a quarter mesh period (docs/model.md 8.4)"),
    D("excitation", "impact_exponent", "", impact_exponent, 1, 3, 0, 0, 1,
      "exponent n of the impact contact law F = c delta^n (1: linear, F_s = v_s sqrt(m_n k_s))"),
    D("excitation", "mesh_stiffness_n_per_m", "N/m", mesh_stiffness_n_per_m, 0, 1e12, 1, 0, NAN,
      "mean mesh stiffness per mesh: one half, or a single pair (derived: ISO 6336-1 c_gamma_alpha times face width)"),
    L("excitation", "stiffness_harmonics", "", stiffness_harmonics, n_stiffness_harmonics, 0, 0.95,
      "harmonic: relative amplitudes a_j of k = k_m (1 + sum a_j cos(j w_m t + phi_j))"),
    L("excitation", "stiffness_phases_deg", "deg", stiffness_phases_deg, n_stiffness_phases, -360, 360,
      "harmonic: phases phi_j (default 0)"),
    D("excitation", "rectangular_variation", "", rectangular_variation, 0, 0.95, 0, 0, 0.2,
      "rectangular: (k_high - k_m)/k_m; the low level keeps the mean at k_m"),
    D("excitation", "rectangular_high_fraction", "", rectangular_high_fraction, 0, 1, 1, 1, NAN,
      "rectangular: fraction of the mesh period at the high level (derived: eps_alpha - floor(eps_alpha))"),
    E("excitation", "ste", ste_source, 0, "sinusoid|ltca",
      "static transmission error e(t) of each mesh: the sinusoid of ste_amplitude_um, or LTCA's own loaded "
      "transmission error of each half less the share the mesh stiffness gives, F/k(t) (stiffness = ltca or "
      "constant; docs/ltca.md section 8)"),
    D("excitation", "ste_amplitude_um", "um", ste_amplitude_um, 0, 1000, 0, 0, NAN,
      "amplitude e_r of e(t) = e_m + e_r sin(w_m t + phi) (default 10, or from the deviations)"),
    D("excitation", "ste_mean_um", "um", ste_mean_um, -1000, 1000, 0, 0, 0, "mean e_m of the static transmission error"),
    D("excitation", "ste_phase_deg", "deg", ste_phase_deg, -360, 360, 0, 0, 0, "phase phi of the static transmission error"),
    D("excitation", "base_pitch_deviation_um", "um", base_pitch_deviation_um, 0, 1000, 0, 0, NAN,
      "f_a: with profile_deviation_um gives e_r = sqrt(f_a^2 + f_b^2)"),
    D("excitation", "profile_deviation_um", "um", profile_deviation_um, 0, 1000, 0, 0, NAN, "f_b (see base_pitch_deviation_um)"),
    D("excitation", "half_phase_deg", "deg", half_phase_deg, -360, 360, 0, 0, 0,
      "mesh phase of the right half relative to the left (stagger), degrees of the mesh cycle"),

    /* [damping] */
    D("damping", "mesh_damping_ratio", "", mesh_damping_ratio, 0, 2, 0, 0, 0.02, "zeta: c = 2 zeta sqrt(k_m m_n) (above 1: overdamped)"),
    E("damping", "mesh_damping_mode", mesh_damping_mode, 0, "always|contact",
      "mesh damping acts always (Kahraman & Singh) or only while the teeth are in contact"),
    D("damping", "support_damping_ratio", "", support_damping_ratio, 0, 1, 0, 0, 0.02, "damping ratio of every bearing support"),
    E("damping", "bearing_damping_mode", bearing_damping_mode, 0, "always|contact",
      "radial bearing damper on the journal's velocity always, or only while the journal touches its clearance's "
      "boundary (scene.bearing_clearance = on)"),
    D("damping", "shaft_damping_ratio", "", shaft_damping_ratio, 0, 1, 0, 0, 0.02, "damping ratio of the groove shafts (axial)"),

    /* [support] */
    D("support", "radial_stiffness_pinion_n_per_m", "N/m", radial_stiffness_pinion_n_per_m, 0, 1e14, 1, 0, 1e9, "radial bearing stiffness of each pinion half"),
    D("support", "radial_stiffness_gear_n_per_m", "N/m", radial_stiffness_gear_n_per_m, 0, 1e14, 1, 0, 1e9, "radial bearing stiffness of each gear half"),
    D("support", "axial_stiffness_pinion_n_per_m", "N/m", axial_stiffness_pinion_n_per_m, 0, 1e14, 0, 0, 5e8, "axial support stiffness of each pinion half (0: floating)"),
    D("support", "axial_stiffness_gear_n_per_m", "N/m", axial_stiffness_gear_n_per_m, 0, 1e14, 1, 0, 5e8, "axial support stiffness of each gear half"),
    D("support", "shaft_stiffness_pinion_n_per_m", "N/m", shaft_stiffness_pinion_n_per_m, 0, 1e14, 1, 0, NAN,
      "axial stiffness of the pinion groove shaft (derived: E A / groove width, root circle section)"),
    D("support", "shaft_stiffness_gear_n_per_m", "N/m", shaft_stiffness_gear_n_per_m, 0, 1e14, 1, 0, NAN,
      "axial stiffness of the gear groove shaft (derived likewise)"),
    E("support", "pinion_axial", pinion_axial, 0, "floating|fixed",
      "LTCA: herringbone pinion axially floating (the halves carry equal axial forces) or axially fixed; a single "
      "pair's pinion is fixed (derived: its bearing takes the axial force)"),
    D("support", "gravity_angle_deg", "deg", gravity_angle_deg, -360, 360, 0, 0, 0,
      "scene.gravity: angle in the transverse plane between +y (the line of action, the way the pinion pushes the "
      "gear) and the weights' direction; only their component along y, times cos of it, acts"),

    /* [solver] */
    E("solver", "method", method, 0, "erk|dirk|rk4", "ARKODE explicit RK, ARKODE implicit DIRK, or fixed-step classical RK4"),
    I("solver", "order", order, 2, 8, 8, "order of the ARKODE method (erk 2-8, dirk 2-5; default 8, Verner's 8(7) table; dirk: 4 unless given)"),
    S("solver", "table", table, "", "ARKODE Butcher table name (overrides order), e.g. ARKODE_VERNER_8_5_6"),
    D("solver", "rtol", "", rtol, 1e-14, 1e-1, 0, 0, 1e-8, "relative tolerance"),
    D("solver", "atol", "", atol, 1e-16, 1, 0, 0, 1e-10, "absolute tolerance, dimensionless (characteristic lengths)"),
    I("solver", "steps_per_period", steps_per_period, 4, 1000000, 64, "rk4 (and erk with fixed_step): steps per mesh period"),
    B("solver", "fixed_step", fixed_step, 0, "erk: fixed step of one mesh period / steps_per_period instead of error control"),
    B("solver", "root_finding", root_finding, 1, "locate every contact and separation exactly (off: contact mode from the state at every RHS call)"),
    B("solver", "grazing_watch", grazing_watch, 1, "re-check each step for a touch that leaves and returns inside it"),
    B("solver", "exact_samples", exact_samples, 0,
      "end steps on the sample times of the recorded window: samples are the method's solution, not the dense output's"),
    E("solver", "vector_kernels", vector_kernels, 0, "geardyn|sundials",
      "serial vector operations of the integrator: compiled with geardyn, or the SUNDIALS library's own (same results bit for bit)"),
    B("solver", "gated_roots", gated_roots, 1,
      "check the root functions' signs at each step end and give them to ARKODE only to locate a crossing (off: ARKODE checks them at every step; the same events)"),
    B("solver", "compiled_rhs", compiled_rhs, 1,
      "evaluate the gear model compiled for the held contact modes (off: the model's general loops; the same function to rounding)"),
    D("solver", "max_step_fraction", "", max_step_fraction, 0, 1, 1, 0, 0.1, "largest step as a fraction of the mesh period"),
    D("solver", "characteristic_length_um", "um", characteristic_length_um, 0, 1e4, 1, 0, 1.0, "length scale of the dimensionless equations"),
    I("solver", "max_events_per_period", max_events_per_period, 1, 100000000, 10000, "more events than this in one mesh period stop the run (chattering)"),
    I("solver", "tca_profile_points", tca_profile_points, 3, 2001, 15, "TCA: grid points along the pinion profile (roll length)"),
    I("solver", "tca_face_points", tca_face_points, 2, 2001, 21, "TCA: grid points across the face width of each half"),
    I("solver", "tca_positions_per_cycle", tca_positions_per_cycle, 2, 100000, 32, "TCA: pinion positions per mesh cycle (one pinion pitch)"),
    I("solver", "tca_cycles", tca_cycles, 1, 1000, 2, "TCA: mesh cycles computed"),
    E("solver", "tca_formulation", tca_formulation, 0, "separation|tangency|both",
      "TCA: (b) surface separation on the flank grid, (a) surface tangency and edge-contact systems, or both compared"),
    B("solver", "tca_refine", tca_refine, 1, "TCA: refine the grid minimum of the separation to the exact minimum (Newton)"),
    I("solver", "ltca_positions_per_cycle", ltca_positions_per_cycle, 2, 100000, 32,
      "LTCA: pinion positions per mesh cycle (one cycle is computed)"),
    I("solver", "ltca_face_slices", ltca_face_slices, 3, 1001, 21,
      "LTCA: transverse slices across the face of each half (one contact point per tooth pair and slice)"),

    /* [run] */
    I("run", "transient_periods", transient_periods, 0, 100000000, 300, "mesh periods discarded before recording"),
    I("run", "transient_max_periods", transient_max_periods, 0, 100000000, 0,
      "0: the transient is exactly transient_periods; N: extend it, period by period up to N, while the Poincare "
      "section is still converging to a period-n orbit (n <= 8) and has not settled within periodicity_tol "
      "(docs/sweeps.md)"),
    I("run", "record_periods", record_periods, 1, 100000000, 200, "mesh periods recorded"),
    E("run", "initial_condition", initial_condition, 0, "static|zero", "start at the static deflection under the mean load, or at rest undeflected"),
    I("run", "lyapunov_exponents", lyapunov_exponents, 0, 20, 1,
      "Lyapunov exponents computed over the recorded window: 0 none, 1 the largest, k the first k (tangent method)"),
    E("run", "lyapunov_method", lyapunov_method, 0, "tangent|two-trajectory",
      "variational equations with saltation at events, or two trajectories (Benettin; largest exponent only)"),
    D("run", "lyapunov_separation", "", lyapunov_separation, 0, 1e-2, 1, 0, 1e-6,
      "two-trajectory: initial and renormalised separation (dimensionless state norm); keep it far above the "
      "integration error of each trajectory (about rtol times the state)"),
    D("run", "periodicity_tol", "", periodicity_tol, 0, 0.1, 1, 0, NAN,
      "Poincare points closer than this (relative to the size of the orbit, 1 + the largest value of any state "
      "variable) are equal (derived: 100 solver.rtol, the error of a period of about a hundred steps each within "
      "rtol; 1e-6 with fixed steps)"),
    D("run", "chaos_threshold_per_period", "", chaos_threshold_per_period, 0, 1, 1, 0, 0.01,
      "largest Lyapunov exponent per mesh period above which a non-periodic motion is chaotic (|mle| below: quasi-periodic)"),
    D("run", "max_time_s", "s", max_time_s, 1, 1e12, 0, 0, 86400,
      "largest estimated run time, with the run's threads (geardyn check prints the estimate); a longer run is refused"),

    /* [output] */
    S("output", "directory", directory, "", "output directory (default: results/<case name>; --out overrides)"),
    I("output", "samples_per_period", samples_per_period, 4, 65536, 64, "uniform time-history samples per mesh period"),
    B("output", "time_history", time_history, 1, "write time_history.csv"),
    B("output", "event_log", event_log, 1, "write events.csv"),
    B("output", "plots", plots, 1, "draw PNG and SVG pictures with gnuplot when it is installed"),
    D("output", "max_bytes", "bytes", max_bytes, 1e3, 1e15, 0, 0, 2e9,
      "largest estimated memory or output files of a run (geardyn check prints the estimate); a larger run is refused"),
    S("output", "response_variable", response_variable, "lambda_L",
      "variable of the local analysis (time history, phase portrait, spectrum, Poincare section): lambda_L, "
      "lambda_R (mesh deflection), dte_L, dte_R (the _R ones with two meshes only), or a degree of freedom (y1L, "
      "z1L, y2L, z2L, qL, ..., q)"),
    D("output", "paint_thickness_um", "um", paint_thickness_um, 0, 1000, 1, 0, 6.32,
      "TCA: flank points whose separation from the mating flank stays below this form the contact pattern"),

    /* [sweep] (analysis = sweep; docs/sweeps.md) */
    S("sweep", "parameter", sweep_parameter, "", "swept numeric key, section.key (e.g. operating.speed_rpm)"),
    D("sweep", "from", "", sweep_from, -1e30, 1e30, 0, 0, NAN, "first value, in the unit of the swept key"),
    D("sweep", "to", "", sweep_to, -1e30, 1e30, 0, 0, NAN, "last value, in the unit of the swept key"),
    I("sweep", "points", sweep_points, 1, 100000, 41, "number of values from `from` to `to`, both included"),
    E("sweep", "spacing", sweep_spacing, 0, "linear|log", "spacing of the values"),
    E("sweep", "mode", sweep_mode, 0, "continuation|independent",
      "continuation: each point starts from the final state of the previous one; independent: all from the initial state"),
    E("sweep", "direction", sweep_direction, 2, "up|down|both",
      "continuation: increasing, decreasing parameter, or both (jumps and hysteresis show as two branches)"),
    S("sweep", "parameter2", sweep_parameter2, "", "second swept key for a regime map (empty: one-parameter sweep)"),
    D("sweep", "from2", "", sweep_from2, -1e30, 1e30, 0, 0, NAN, "first value of parameter2"),
    D("sweep", "to2", "", sweep_to2, -1e30, 1e30, 0, 0, NAN, "last value of parameter2"),
    I("sweep", "points2", sweep_points2, 1, 100000, 11, "number of values of parameter2"),
    E("sweep", "spacing2", sweep_spacing2, 0, "linear|log", "spacing of the values of parameter2"),
    S("sweep", "response", sweep_response, "",
      "Poincare responses, comma-separated: lambda_L, lambda_R (default; lambda_L with one mesh), lambda_dot_L, "
      "lambda_dot_R (the _R ones with two meshes only), DOF names, DOF_dot"),

    /* [continuation] (analysis = continuation; docs/continuation.md) */
    S("continuation", "parameter", cont_parameter, "",
      "continued numeric key, section.key (e.g. operating.speed_rpm)"),
    D("continuation", "from", "", cont_from, -1e30, 1e30, 0, 0, NAN,
      "lower bound of the parameter, in the unit of its key: a branch ends there"),
    D("continuation", "to", "", cont_to, -1e30, 1e30, 0, 0, NAN,
      "upper bound of the parameter, in the unit of its key: a branch ends there"),
    D("continuation", "start_value", "", cont_start_value, -1e30, 1e30, 0, 0, NAN,
      "the parameter's value at the starting orbit, in [from, to] (default: from with direction up, to with down, "
      "the middle with both)"),
    E("continuation", "direction", cont_direction, 2, "up|down|both",
      "from the starting orbit towards increasing, decreasing parameter, or both (two branches)"),
    D("continuation", "ds", "", cont_ds, 0, 1e6, 1, 0, 0.02,
      "first arclength step in the norm of (state / its size, parameter / (to - from)) (docs/continuation.md section 3)"),
    D("continuation", "ds_min", "", cont_ds_min, 0, 1e6, 1, 0, 1e-6,
      "smallest arclength step: a branch whose corrector fails at it ends"),
    D("continuation", "ds_max", "", cont_ds_max, 0, 1e6, 1, 0, 0.2, "largest arclength step"),
    D("continuation", "dp_max", "", cont_dp_max, 0, 1e30, 0, 0, 0,
      "largest change of the parameter in one step, in the unit of its key (0: (to - from) / 50)"),
    I("continuation", "max_points", cont_max_points, 2, 100000, 400, "points of one branch at most, its start included"),
    D("continuation", "newton_tol", "", cont_newton_tol, 0, 1e-2, 0, 0, 0,
      "an orbit is converged when the max-norm of the shooting residual (dimensionless state) is below this "
      "(0: what the integration resolves, solver.rtol times the orbit's largest state component plus solver.atol)"),
    I("continuation", "newton_max_iterations", cont_newton_max_iterations, 1, 100, 12,
      "Newton iterations of one correction at most (more: the step is halved)"),
    D("continuation", "locate_tol", "", cont_locate_tol, 0, 1, 0, 0, 0,
      "a bifurcation is located when its arclength bracket is below this (0: ten times newton_tol over the orbit's "
      "largest state component, what a corrected point resolves)"),
    I("continuation", "period", cont_period, 0, 16, 0,
      "mesh periods of the starting orbit (0: the smallest n up to 16 whose Poincare section repeats after the transient)"),
    E("continuation", "shooting", cont_shooting, 0, "multiple|single",
      "multiple: one shooting segment per mesh period (strongly unstable orbits converge); single: one segment"),
    E("continuation", "start", cont_start, 0, "attractor|state|sweep",
      "attractor: the orbit reached after run.transient_periods from run.initial_condition at start_value; "
      "state: the orbit near continuation.state; sweep: the orbit near the final state of a finished sweep's "
      "point (start_sweep, start_sweep_direction), the one nearest start_value"),
    S("continuation", "state", cont_state, "",
      "start = state: the dimensionless state at mesh phase 0, comma-separated (as summary.json writes it)"),
    S("continuation", "start_sweep", cont_start_sweep, "",
      "start = sweep: a finished sweep of this case's model in this parameter (its directory, relative to the "
      "working directory); its states.csv gives the start"),
    E("continuation", "start_sweep_direction", cont_start_sweep_direction, 0, "up|down|independent",
      "start = sweep: the sweep's branch whose point starts the continuation (the direction column of its tables)"),
    B("continuation", "branch_switching", cont_branch_switching, 1,
      "at each period doubling of any branch (a switched one too, up to 16 mesh periods), follow the orbit of "
      "twice the period born there, both ways"),
    I("continuation", "max_branches", cont_max_branches, 1, 1000, 32,
      "branches at most, those from the start and those switched to; a switching beyond it is listed under notes"),
    S("continuation", "overlay_sweep", cont_overlay_sweep, "",
      "a finished sweep's directory (as output.directory: relative to the working directory) whose points are drawn over the branches"),
    E("continuation", "response", cont_response, 0, "rms_accel|max_deflection|min_deflection|poincare|dynamic_load_factor",
      "the response drawn against the parameter: RMS mesh acceleration (m/s^2), largest or smallest mesh "
      "deflection lambda_L (um) on the orbit, lambda_L at mesh phase 0 (dimensionless, as a sweep's bifurcation.csv), "
      "or the dynamic load factor (the largest mesh force on the orbit over the static one, of the more loaded mesh)"),
    S("continuation", "parameter2", cont_parameter2, "",
      "a second numeric key, section.key: every fold, period doubling, Neimark-Sacker point and grazing of the "
      "branches is continued in (parameter, parameter2), both ways, into curves.csv (\"\": none; docs/continuation.md section 8)"),
    D("continuation", "parameter2_from", "", cont_from2, -1e30, 1e30, 0, 0, NAN,
      "lower bound of parameter2, in the unit of its key: a curve ends there"),
    D("continuation", "parameter2_to", "", cont_to2, -1e30, 1e30, 0, 0, NAN,
      "upper bound of parameter2, in the unit of its key: a curve ends there"),
    I("continuation", "curve_max_points", cont_curve_max_points, 2, 100000, 400,
      "points of one curve in one direction at most, its start included"),
    S("continuation", "curve_start", cont_curve_start, "",
      "an earlier continuation's bifurcations.csv (relative to the working directory), of this case: only the "
      "curve of its row curve_start_row is followed, both ways (\"\": every bifurcation of the branches)"),
    I("continuation", "curve_start_row", cont_curve_start_row, 1, 1000000, 1,
      "the row of curve_start whose bifurcation's curve is followed: 1 the first row after the header"),
    S("continuation", "curve_kinds", cont_curve_kinds, "fold, period-doubling, neimark-sacker, grazing",
      "the kinds of bifurcation of the branches continued in parameter2, comma-separated, each once (fold, "
      "period-doubling, neimark-sacker, grazing: a grazing is a contact change of the branches); a Neimark-Sacker "
      "curve's points cost about twice a fold's"),
    S("continuation", "overlay_map", cont_overlay_map, "",
      "a finished regime map (a sweep with parameter2) in parameter and parameter2 of this case's model, its "
      "directory (relative to the working directory): its cells coloured by motion under the curves, its regions named"),
    S("continuation", "overlay_curves", cont_overlay_curves, "",
      "an earlier continuation's directory with curves in parameter and parameter2 (any model: the case before a "
      "modification), its curves drawn thin and grey beside these, the keys where it differs in the key"),

    /* [basins] (analysis = basins; docs/basins.md) */
    S("basins", "x", bas_x, "lambda_L",
      "the section's first coordinate: lambda_L, lambda_R (the mesh deflection over half the backlash), lambda_dot_L, "
      "lambda_dot_R (its rate, half backlashes per unit of dimensionless time omega_n t), or a state component "
      "(y1L, ..., y1L_dot, dimensionless)"),
    S("basins", "y", bas_y, "lambda_dot_L", "the section's second coordinate (as x)"),
    D("basins", "x_from", "", bas_x_from, -1e30, 1e30, 0, 0, NAN,
      "lower end of the box in x, in x's unit (derived for a mesh deflection: -2, back contact)"),
    D("basins", "x_to", "", bas_x_to, -1e30, 1e30, 0, 0, NAN,
      "upper end of the box in x (derived for a mesh deflection: the static deflection + 2, drive contact)"),
    D("basins", "y_from", "", bas_y_from, -1e30, 1e30, 0, 0, NAN,
      "lower end of the box in y (derived for a rate: -(x_to - x_from) Omega, Omega the frequency ratio)"),
    D("basins", "y_to", "", bas_y_to, -1e30, 1e30, 0, 0, NAN, "upper end of the box in y (derived for a rate: the "
      "opposite of y_from)"),
    D("basins", "phase_deg", "deg", bas_phase_deg, 0, 360, 0, 1, 0,
      "mesh phase of the section: initial states and the stroboscopic map at this phase of the mesh cycle"),
    E("basins", "base", bas_base, 0, "static|state",
      "the state components off the section: at the static state, or at basins.state (an orbit's point)"),
    S("basins", "state", bas_state, "",
      "base = state: the dimensionless state at the section's phase, comma-separated (as branch.csv writes it)"),
    I("basins", "resolution", bas_resolution, 2, 20000, 100,
      "cells of the box along x (the picture's grid and the tessellation of the recurrences)"),
    I("basins", "resolution_y", bas_resolution_y, 0, 20000, 0, "cells of the box along y (0: resolution)"),
    B("basins", "picture", bas_picture, 1,
      "map every cell's centre (basins.csv and the picture; without parameter only)"),
    I("basins", "samples", bas_samples, 0, 1000000000, 10000,
      "initial states drawn uniformly in the box for the fractions (0: none), per parameter value"),
    I("basins", "seed", bas_seed, 0, 2147483647, 1, "seed of the random sample (GSL's Mersenne Twister)"),
    I("basins", "max_periods", bas_max_periods, 10, 100000000, 2000,
      "mesh periods of one trajectory at most: beyond, its state is labelled iteration-cap"),
    D("basins", "margin", "", bas_margin, 0, 10, 0, 0, 1,
      "the tessellation extends this many box widths beyond the box on every side; a trajectory outside it for "
      "consecutive_lost_steps periods is labelled left-box"),
    I("basins", "consecutive_recurrences", bas_consecutive_recurrences, 1, 1000000, 100,
      "map points in a row on cells the trajectory visited before: an attractor is found"),
    I("basins", "consecutive_attractor_steps", bas_consecutive_attractor_steps, 1, 1000000, 2,
      "map points in a row on one known attractor's cells: the trajectory goes there"),
    I("basins", "consecutive_basin_steps", bas_consecutive_basin_steps, 1, 1000000, 10,
      "map points in a row on cells whose initial states went to one attractor: the trajectory goes there "
      "(used when the section is the whole state space)"),
    I("basins", "consecutive_lost_steps", bas_consecutive_lost_steps, 0, 1000000, 20,
      "map points in a row outside the tessellation: left-box"),
    I("basins", "lyapunov_periods", bas_lyapunov_periods, 10, 10000000, 1000,
      "mesh periods over which a non-periodic attractor's largest Lyapunov exponent is measured"),
    D("basins", "newton_tol", "", bas_newton_tol, 1e-14, 1e-2, 0, 0, 1e-8,
      "a periodic attractor's orbit by shooting is converged when the residual's max-norm is below this "
      "(keep solver.rtol tighter)"),
    I("basins", "entropy_box_cells", bas_entropy_box_cells, 1, 1000, 5,
      "side of the boxes of the basin entropy, in cells of the picture"),
    S("basins", "continuation", bas_continuation, "",
      "a finished continuation's directory (relative to the working directory): its stable orbits seed the "
      "search, its orbits are marked on the picture and its branches drawn beside the fractions"),
    S("basins", "parameter", bas_parameter, "",
      "the fractions over a numeric key, section.key (e.g. operating.speed_rpm); empty: at the case's values"),
    D("basins", "from", "", bas_from, -1e30, 1e30, 0, 0, NAN, "first value of the parameter, in its key's unit"),
    D("basins", "to", "", bas_to, -1e30, 1e30, 0, 0, NAN, "last value of the parameter, in its key's unit"),
    I("basins", "points", bas_points, 2, 100000, 11, "values of the parameter from `from` to `to`, both included"),

    /* [workprecision] (analysis = work-precision; docs/accuracy.md) */
    S("workprecision", "families", wp_families, "rk4,erk2,erk3,erk4,erk5,erk6,erk7,erk8",
      "method families, comma-separated: rk4 (fixed steps), erk2 to erk8, dirk2 to dirk5 (over rtol)"),
    B("workprecision", "root_finding_off", wp_root_finding_off, 1,
      "also run every family with root finding off (contact modes from the state, events seen at step ends)"),
    I("workprecision", "rk4_steps_min", wp_rk4_steps_min, 4, 1000000, 16, "rk4: fewest steps per mesh period (doubled up to rk4_steps_max)"),
    I("workprecision", "rk4_steps_max", wp_rk4_steps_max, 4, 1000000, 1024, "rk4: most steps per mesh period"),
    D("workprecision", "rtol_loosest", "", wp_rtol_loosest, 1e-14, 0.1, 0, 0, 1e-3, "adaptive families: loosest rtol"),
    D("workprecision", "rtol_tightest", "", wp_rtol_tightest, 1e-14, 0.1, 0, 0, 1e-12, "adaptive families: tightest rtol"),
    I("workprecision", "rtols_per_decade", wp_rtols_per_decade, 1, 10, 1, "adaptive families: tolerances per decade"),
    D("workprecision", "atol_over_rtol", "", wp_atol_over_rtol, 1e-6, 1, 0, 0, 1e-2,
      "atol of every run = rtol times this (dimensionless state; the [solver] defaults have 1e-2)"),
    D("workprecision", "reference_rtol", "", wp_reference_rtol, 1e-14, 1e-6, 0, 0, 1e-13,
      "rtol of the reference and of its check (events located)"),
    D("workprecision", "reference_max_step_fraction", "", wp_reference_max_step_fraction, 0, 1, 1, 0, 0.002,
      "largest step of the reference and its check / mesh period: event times are located on ARKODE's interpolant "
      "(degree 5 at most), so they are only as accurate as the steps are short"),
    I("workprecision", "reference_order", wp_reference_order, 2, 8, 8, "explicit order of the reference"),
    I("workprecision", "check_order", wp_check_order, 2, 8, 6,
      "explicit order of the independent check of the reference (not 7, not reference_order)"),
    D("workprecision", "reference_max_error", "", wp_reference_max_error, 0, 1, 1, 0, 1e-9,
      "largest Poincare difference between the reference and its check for a converged reference"),
    I("workprecision", "horizon_periods", wp_horizon_periods, 1, 100000, 10,
      "short horizon: trajectory error of chaotic scenes, event times of chaotic scenes, and the order study"),
    B("workprecision", "order_study", wp_order_study, 1,
      "measure the convergence order of the Poincare points of every explicit family at fixed steps, events on and off"),
    I("workprecision", "order_steps_min", wp_order_steps_min, 4, 1000000, 4, "order study: fewest steps per mesh period"),
    I("workprecision", "order_steps_max", wp_order_steps_max, 4, 1000000, 1024, "order study: most steps per mesh period"),
    I("workprecision", "repeats", wp_repeats, 1, 100, 1, "timed repetitions of every run (the best is kept)"),
    I("workprecision", "max_steps_per_period", wp_max_steps_per_period, 10, 100000000, 20000,
      "budget: a run taking more steps per mesh period stops (over-budget) and the tighter settings of its family are skipped"),
    B("workprecision", "lyapunov", wp_lyapunov, 1,
      "chaotic scenes: error of the largest Lyapunov exponent (one more, untimed run per setting)"),
    E("workprecision", "scene_class", wp_scene_class, 0, "auto|periodic|chaotic",
      "which errors lead: Poincare points over the window (periodic) or the short horizon and statistics (chaotic); "
      "auto: from the reference's motion class"),

    /* [optimize] (analysis = optimize, compare-optimizers; docs/optimisation.md) */
    E("optimize", "algorithm", opt_algorithm, 0,
      "alo|gn_direct_l|gn_crs2_lm|gn_isres|gn_esch|ln_bobyqa|ln_cobyla|ln_sbplx|random|moalo|weighted-sum|"
      "eps-constraint",
      "optimize: the optimiser (alo: the Ant Lion Optimizer; gn_*/ln_*: NLopt's global and local methods; "
      "random: uniform random search; two objectives: moalo, the multi-objective ALO, weighted-sum and "
      "eps-constraint, scalar_algorithm on a grid of scalarised subproblems, or random)"),
    S("optimize", "optimizers", opt_optimizers, "alo,gn_direct_l,gn_crs2_lm,gn_isres,gn_esch,ln_bobyqa,ln_cobyla,ln_sbplx,random",
      "compare-optimizers: the optimisers compared, comma-separated (names as for algorithm)"),
    S("optimize", "objective", opt_objective, "gear-lte",
      "gear-lte (LTE amplitude of the modified pair over optimize.variables) or test functions sphere, rosenbrock, "
      "rastrigin, ackley, griewank, and zdt1, zdt2 of two objectives; compare-optimizers takes a comma-separated "
      "list"),
    L("optimize", "dimension", "", opt_dimensions, n_opt_dimensions, 1, 1000,
      "test functions: number of variables, a comma-separated list for compare-optimizers (default 6; gear-lte: the count of optimize.variables)"),
    I("optimize", "iterations", opt_iterations, 1, 10000000, 100,
      "ALO iterations after the initial population (the paper: 100); the budget is population (iterations + 1)"),
    I("optimize", "population", opt_population, 2, 100000, 30, "ALO: number of ants (= antlions); random search: batch size"),
    I("optimize", "seed", opt_seed, 0, 2147483647, 1, "seed of run 1; run r uses seed + r - 1 (the same seeds for every optimiser)"),
    I("optimize", "runs", opt_runs, 0, 100000, 0,
      "independent runs (0: 1 for optimize, which keeps the best; 10 for compare-optimizers)"),
    I("optimize", "budget_evals", opt_budget_evals, 0, 2000000000, 0,
      "objective evaluations of every run, strict (0: population (iterations + 1), ALO's count)"),
    D("optimize", "target", "", opt_target, 0, 1e30, 1, 0, NAN,
      "success: best - f_ref <= target, in the objective's unit (f_ref: 0 for test functions, the best value "
      "found in the comparison for gear-lte; default 1e-8, gear-lte 0.005 arcsec)"),
    D("optimize", "target_loosest", "", opt_target_loosest, 0, 1e30, 1, 0, NAN,
      "loosest target of the runtime distribution (targets log-spaced down to target; default 100, gear-lte 1 arcsec)"),
    I("optimize", "ecdf_targets", opt_ecdf_targets, 1, 1000, 51, "number of targets of the runtime distribution"),
    D("optimize", "shift", "", opt_shift, 0, 0.9, 0, 0, 0,
      "test functions: the minimiser of run r drawn uniformly from shift times the box (0: at the origin)"),
    S("optimize", "variables", opt_variables, "y1,y2,y3,y4,y5,y7",
      "gear-lte: the design variables, comma-separated: the paper's y1..y5, y7 (y6 = y5 unless y6 is listed), "
      "y6 (asymmetric lead relief), y8 (offset of the unmodified lead band), y9 (helix slope); a variable not "
      "listed keeps the case's [modification] value"),
    D("optimize", "root_relief_amount_min_um", "um", opt_root_amount_min_um, 0, 1000, 0, 0, 0, "gear-lte: lower bound of y1 (C_min)"),
    D("optimize", "root_relief_amount_max_um", "um", opt_root_amount_max_um, 0, 1000, 0, 0, NAN,
      "gear-lte: upper bound of y1 (C_max; derived: the larger of 12 um per mm of normal module and 4 static "
      "deflections plus twice the misalignment's mismatch across the face, docs/optimisation.md section 2)"),
    D("optimize", "root_relief_length_min_mm", "mm", opt_root_length_min_mm, 0, 1000, 0, 0, NAN,
      "gear-lte: lower bound of y2 (D_min; derived: 0.1 normal module)"),
    D("optimize", "root_relief_length_max_mm", "mm", opt_root_length_max_mm, 0, 1000, 0, 0, NAN,
      "gear-lte: upper bound of y2 (D_max; derived: 2.4 normal modules, at most the active profile)"),
    D("optimize", "tip_relief_amount_min_um", "um", opt_tip_amount_min_um, 0, 1000, 0, 0, 0, "gear-lte: lower bound of y3 (C_min)"),
    D("optimize", "tip_relief_amount_max_um", "um", opt_tip_amount_max_um, 0, 1000, 0, 0, NAN,
      "gear-lte: upper bound of y3 (C_max; derived as y1's)"),
    D("optimize", "tip_relief_length_min_mm", "mm", opt_tip_length_min_mm, 0, 1000, 0, 0, NAN,
      "gear-lte: lower bound of y4 (D_min; derived as y2's)"),
    D("optimize", "tip_relief_length_max_mm", "mm", opt_tip_length_max_mm, 0, 1000, 0, 0, NAN,
      "gear-lte: upper bound of y4 (D_max; derived as y2's)"),
    D("optimize", "lead_relief_min_um", "um", opt_lead_amount_min_um, 0, 1000, 0, 0, 0,
      "gear-lte: lower bound of y5 and y6, the lead relief at the face ends (S_min)"),
    D("optimize", "lead_relief_max_um", "um", opt_lead_amount_max_um, 0, 1000, 0, 0, NAN,
      "gear-lte: upper bound of y5 and y6 (S_max; derived as y1's)"),
    D("optimize", "lead_unmodified_length_min_mm", "mm", opt_lead_length_min_mm, 0, 5000, 0, 0, NAN,
      "gear-lte: lower bound of y7 (G_min; derived: a quarter of the pinion face of one half)"),
    D("optimize", "lead_unmodified_length_max_mm", "mm", opt_lead_length_max_mm, 0, 5000, 0, 0, NAN,
      "gear-lte: upper bound of y7 (G_max; derived: 0.95 of the pinion face of one half)"),
    D("optimize", "lead_unmodified_centre_min_mm", "mm", opt_lead_centre_min_mm, -2500, 2500, 0, 0, NAN,
      "gear-lte: lower bound of y8 (derived: -1/4 of the pinion face of one half)"),
    D("optimize", "lead_unmodified_centre_max_mm", "mm", opt_lead_centre_max_mm, -2500, 2500, 0, 0, NAN,
      "gear-lte: upper bound of y8 (derived: 1/4 of the pinion face of one half)"),
    D("optimize", "helix_slope_min_um", "um", opt_helix_slope_min_um, -1000, 1000, 0, 0, NAN,
      "gear-lte: lower bound of y9 (derived: -(the static deflection plus twice the misalignment's mismatch across "
      "the face))"),
    D("optimize", "helix_slope_max_um", "um", opt_helix_slope_max_um, -1000, 1000, 0, 0, NAN,
      "gear-lte: upper bound of y9 (derived: the static deflection plus twice the misalignment's mismatch)"),
    L("optimize", "torques_nm", "N m", opt_torques_nm, n_opt_torques, 0, 1e7,
      "gear-lte-range, gear-dynamic: the pinion torques, comma-separated, at most 8 (derived: operating.torque_nm)"),
    L("optimize", "torque_weights", "", opt_torque_weights, n_opt_torque_weights, 0, 1e30,
      "gear-lte-range, gear-dynamic: the duty weights of the torques, one each, a positive sum (derived: equal)"),
    E("optimize", "lte_range_combine", opt_lte_range_combine, 0, "max|mean",
      "gear-lte-range: the largest LTE amplitude of the torques, or their duty-weighted mean"),
    E("optimize", "dynamic_combine", opt_dynamic_combine, 0, "max|mean",
      "gear-dynamic: the torques' peaks combined: the largest (worst case), or their duty-weighted mean"),
    D("optimize", "speed_from_rpm", "rpm", opt_speed_from_rpm, 0, 100000, 1, 0, NAN,
      "gear-dynamic: the lowest speed of the range (derived: 0.8 operating.speed_rpm)"),
    D("optimize", "speed_to_rpm", "rpm", opt_speed_to_rpm, 0, 100000, 1, 0, NAN,
      "gear-dynamic: the highest speed of the range, above speed_from_rpm (derived: 1.2 operating.speed_rpm)"),
    E("optimize", "dynamic_response", opt_dynamic_response, 0, "rms_accel|dte_pp",
      "gear-dynamic: the response of the stable motion: the RMS mesh acceleration, or the peak-to-peak dynamic "
      "transmission error; of a herringbone's halves the larger"),
    E("optimize", "dynamic_model", opt_dynamic_model, 1, "torsional|torsional-lr|bta",
      "gear-dynamic: the model of the dynamics in the loop (derived: torsional-lr for a herringbone, torsional for "
      "a single pair)"),
    D("optimize", "dynamic_sweep_step_rpm", "rpm", opt_dynamic_sweep_step_rpm, 0, 100000, 1, 0, NAN,
      "gear-dynamic: the spacing of the short sweep where the period-1 orbit is unstable or lost (derived: a "
      "fiftieth of the speed range); its points run run.transient_periods and run.record_periods"),
    D("optimize", "harris_torque_from_nm", "N m", opt_harris_from_nm, 0, 1e7, 1, 0, NAN,
      "gear-lte-range, gear-dynamic: the least torque of the Harris map (the LTE amplitude over torque of the "
      "unmodified flank, the case's own and the optimum) after the optimum (derived: a tenth of the largest of "
      "torques_nm)"),
    D("optimize", "harris_torque_to_nm", "N m", opt_harris_to_nm, 0, 1e7, 1, 0, NAN,
      "gear-lte-range, gear-dynamic: the largest torque of the Harris map, above harris_torque_from_nm (derived: "
      "1.5 times the largest of torques_nm)"),
    I("optimize", "harris_torques", opt_harris_torques, 2, 100, 20,
      "gear-lte-range, gear-dynamic: the torques of the Harris map, evenly spaced from harris_torque_from_nm to "
      "harris_torque_to_nm (the objective's own torques are added)"),
    B("optimize", "robust", opt_robust, 0,
      "gear objectives: the robust variant, the robust_quantile of the objective over a Monte Carlo sample of "
      "misalignment and manufacturing deviations of the design variables (drawn from optimize.seed, the same for "
      "every candidate)"),
    I("optimize", "robust_samples", opt_robust_samples, 1, 100000, 20,
      "robust: the size of the Monte Carlo sample"),
    D("optimize", "robust_quantile", "", opt_robust_quantile, 0, 1, 1, 0, 0.9,
      "robust: the quantile of the sample's values that is the objective"),
    D("optimize", "robust_misalignment_tilt_arcmin", "arcmin", opt_robust_tilt_arcmin, 0, 60, 0, 0, 0.5,
      "robust: each tilt component of the axis (misalignment.axis_in_plane_arcmin, axis_cross_plane_arcmin) "
      "deviates uniformly within +- this"),
    D("optimize", "robust_misalignment_centre_distance_mm", "mm", opt_robust_centre_distance_mm, 0, 10, 0, 0, 0.05,
      "robust: the centre distance deviates uniformly within +- this"),
    D("optimize", "robust_deviation_um", "um", opt_robust_amount_um, 0, 1000, 0, 0, 2,
      "robust: each design variable in um (relief amounts y1, y3, y5, y6, helix slope y9) deviates uniformly "
      "within +- this"),
    D("optimize", "robust_deviation_mm", "mm", opt_robust_length_mm, 0, 1000, 0, 0, 0.5,
      "robust: each design variable in mm (relief lengths y2, y4, the unmodified lead band y7, y8) deviates "
      "uniformly within +- this"),
    S("optimize", "objective2", opt_objective2, "",
      "two objectives at once: gear-dynamic beside objective gear-lte or gear-lte-range (compare-optimizers: "
      "gear-lte), their Pareto front (empty: one objective; zdt1 and zdt2 have two of their own)"),
    I("optimize", "archive", opt_archive, 2, 100000, 100, "moalo: the size of its archive of non-dominated points"),
    E("optimize", "scalar_algorithm", opt_scalar_algorithm, 2,
      "alo|gn_direct_l|gn_crs2_lm|gn_isres|gn_esch|ln_bobyqa|ln_cobyla|ln_sbplx",
      "weighted-sum, eps-constraint: the NLopt method of each scalarised subproblem (alo is refused)"),
    I("optimize", "scalar_grid", opt_scalar_grid, 2, 10000, 8,
      "weighted-sum, eps-constraint: the subproblems (weights or epsilon levels), each on an equal share of the "
      "budget"),
    L("optimize", "hv_reference", "", opt_hv_reference, n_opt_hv_reference, 0, 1e30,
      "two objectives: the hypervolume's reference point, two numbers > 0 in the objectives' units (derived: 1.1, "
      "1.1 for zdt1 and zdt2; for the gear 1.1 times the unmodified flank's two objectives)"),
};

GD_API const gd_keyspec *gd_case_schema(size_t *n)
{
    if (n)
        *n = sizeof schema / sizeof schema[0];
    return schema;
}

GD_API const gd_keyspec *gd_case_find_key(const char *section, const char *key)
{
    for (size_t i = 0; i < sizeof schema / sizeof schema[0]; i++)
        if (strcmp(schema[i].section, section) == 0 && strcmp(schema[i].key, key) == 0)
            return &schema[i];
    return NULL;
}
