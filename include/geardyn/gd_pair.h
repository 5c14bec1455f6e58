/* A gear pair as the physics sees it: the design data of ISO 21771 (the [gear] keys without the
 * masses and inertias the scene derives), the form-ground modification of the pinion flank
 * ([modification], all zero for an unmodified flank: the scene resolves modification.apply = false
 * to zero amounts) and the misalignment of the gear axis ([misalignment]). Geometry, flanks,
 * tooth compliance, ISO 6336, TCA and LTCA take a gd_pair; gd_pair_from_case (gd_scene.h) makes
 * one from a case. Field names and units are those of the case's keys (`geardyn check` lists them). */
#ifndef GD_PAIR_H
#define GD_PAIR_H

#include "geardyn/gd_error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gd_pair {
    /* design (ISO 21771) */
    double normal_module_mm, helix_angle_deg, normal_pressure_angle_deg;
    int teeth_pinion, teeth_gear;
    double profile_shift_pinion, profile_shift_gear, addendum_coefficient, dedendum_coefficient;
    double face_width_pinion_mm, face_width_gear_mm; /* of one helical half */
    double groove_width_mm;                          /* relief groove between the halves */
    double bore_diameter_pinion_mm, bore_diameter_gear_mm;
    /* the blank (gd_body_of_mesh): rim inner diameter (0: a solid blank), web thickness (with a rim),
     * hub diameter (0: none) and length (NaN: the body's width) */
    double rim_inner_diameter_pinion_mm, rim_inner_diameter_gear_mm, web_thickness_pinion_mm, web_thickness_gear_mm;
    double hub_diameter_pinion_mm, hub_diameter_gear_mm, hub_length_pinion_mm, hub_length_gear_mm;
    double youngs_modulus_gpa, poisson_ratio, density_kg_per_m3;
    int arrangement;         /* gd_arrangement (gd_case.h): herringbone, helical or spur */
    int pinion_hand;         /* gd_hand (gd_case.h) of the pinion helix in the left half */
    /* modification of the pinion flank (docs/geometry.md): amounts normal to the flank, profile
     * lengths as transverse roll lengths, lead lengths along the axis */
    double root_relief_amount_um, root_relief_length_mm, tip_relief_amount_um, tip_relief_length_mm; /* y1..y4 */
    double lead_relief_inner_um, lead_relief_outer_um, lead_unmodified_length_mm;                 /* y5, y6, y7 */
    double lead_unmodified_centre_mm, helix_slope_um;                                           /* y8, y9 */
    /* misalignment of the gear axis about the middle of the gear, and centre-distance error */
    double axis_in_plane_arcmin, axis_cross_plane_arcmin, centre_distance_error_mm;
} gd_pair;

#ifdef __cplusplus
}
#endif
#endif
