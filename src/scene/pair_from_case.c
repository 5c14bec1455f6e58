/* A case's gear pair and the settings of its contact analyses: the values of its keys copied into
 * the structures geometry, TCA and LTCA take (gd_pair.h, gd_tca.h, gd_ltca.h); and a modified
 * pair's modification back into a case (the optimum's own outputs). */
#include "geardyn/gd_scene.h"

GD_API gd_pair gd_pair_from_case(const gd_case *c)
{
    return (gd_pair){
        .normal_module_mm = c->normal_module_mm,
        .helix_angle_deg = c->helix_angle_deg,
        .normal_pressure_angle_deg = c->normal_pressure_angle_deg,
        .teeth_pinion = c->teeth_pinion,
        .teeth_gear = c->teeth_gear,
        .profile_shift_pinion = c->profile_shift_pinion,
        .profile_shift_gear = c->profile_shift_gear,
        .addendum_coefficient = c->addendum_coefficient,
        .dedendum_coefficient = c->dedendum_coefficient,
        .face_width_pinion_mm = c->face_width_pinion_mm,
        .face_width_gear_mm = c->face_width_gear_mm,
        .groove_width_mm = c->groove_width_mm,
        .bore_diameter_pinion_mm = c->bore_diameter_pinion_mm,
        .bore_diameter_gear_mm = c->bore_diameter_gear_mm,
        .rim_inner_diameter_pinion_mm = c->rim_inner_diameter_pinion_mm,
        .rim_inner_diameter_gear_mm = c->rim_inner_diameter_gear_mm,
        .web_thickness_pinion_mm = c->web_thickness_pinion_mm,
        .web_thickness_gear_mm = c->web_thickness_gear_mm,
        .hub_diameter_pinion_mm = c->hub_diameter_pinion_mm,
        .hub_diameter_gear_mm = c->hub_diameter_gear_mm,
        .hub_length_pinion_mm = c->hub_length_pinion_mm,
        .hub_length_gear_mm = c->hub_length_gear_mm,
        .youngs_modulus_gpa = c->youngs_modulus_gpa,
        .poisson_ratio = c->poisson_ratio,
        .density_kg_per_m3 = c->density_kg_per_m3,
        .arrangement = c->arrangement,
        .pinion_hand = c->pinion_hand,
        .root_relief_amount_um = c->root_relief_amount_um,
        .root_relief_length_mm = c->root_relief_length_mm,
        .tip_relief_amount_um = c->tip_relief_amount_um,
        .tip_relief_length_mm = c->tip_relief_length_mm,
        .lead_relief_inner_um = c->lead_relief_inner_um,
        .lead_relief_outer_um = c->lead_relief_outer_um,
        .lead_unmodified_length_mm = c->lead_unmodified_length_mm,
        .lead_unmodified_centre_mm = c->lead_unmodified_centre_mm,
        .helix_slope_um = c->helix_slope_um,
        .axis_in_plane_arcmin = c->axis_in_plane_arcmin,
        .axis_cross_plane_arcmin = c->axis_cross_plane_arcmin,
        .centre_distance_error_mm = c->centre_distance_error_mm,
    };
}

GD_API void gd_pair_modification_to_case(const gd_pair *pair, gd_case *c)
{
    c->root_relief_amount_um = pair->root_relief_amount_um;
    c->root_relief_length_mm = pair->root_relief_length_mm;
    c->tip_relief_amount_um = pair->tip_relief_amount_um;
    c->tip_relief_length_mm = pair->tip_relief_length_mm;
    c->lead_relief_inner_um = pair->lead_relief_inner_um;
    c->lead_relief_outer_um = pair->lead_relief_outer_um;
    c->lead_unmodified_length_mm = pair->lead_unmodified_length_mm;
    c->lead_unmodified_centre_mm = pair->lead_unmodified_centre_mm;
    c->helix_slope_um = pair->helix_slope_um;
}

GD_API gd_tca_settings gd_tca_settings_from_case(const gd_case *c)
{
    return (gd_tca_settings){
        .profile_points = c->tca_profile_points,
        .face_points = c->tca_face_points,
        .refine = c->tca_refine,
        .positions_per_cycle = c->tca_positions_per_cycle,
        .cycles = c->tca_cycles,
        .formulation = c->tca_formulation,
    };
}

GD_API gd_ltca_settings gd_ltca_settings_from_case(const gd_case *c)
{
    return (gd_ltca_settings){
        .torque_nm = c->torque_nm,
        .pinion_axial = c->pinion_axial,
        .positions_per_cycle = c->ltca_positions_per_cycle,
        .face_slices = c->ltca_face_slices,
        .profile_points = c->tca_profile_points,
        .refine = c->tca_refine,
    };
}
