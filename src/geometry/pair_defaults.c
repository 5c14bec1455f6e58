/* The defaults of a gd_pair (gd_pair.h): those of the case keys its fields copy, read from the
 * schema, so that a pair from gd_pair_defaults is the pair of a case that gives none of them. */
#include "geardyn/gd_pair.h"
#include "geardyn/gd_case.h"

static double def(const char *section, const char *key) { return gd_case_find_key(section, key)->def; }

GD_API gd_pair gd_pair_defaults(void)
{
    return (gd_pair){
        .normal_module_mm = def("gear", "normal_module_mm"),
        .helix_angle_deg = def("gear", "helix_angle_deg"),
        .normal_pressure_angle_deg = def("gear", "normal_pressure_angle_deg"),
        .teeth_pinion = (int)def("gear", "teeth_pinion"),
        .teeth_gear = (int)def("gear", "teeth_gear"),
        .profile_shift_pinion = def("gear", "profile_shift_pinion"),
        .profile_shift_gear = def("gear", "profile_shift_gear"),
        .addendum_coefficient = def("gear", "addendum_coefficient"),
        .dedendum_coefficient = def("gear", "dedendum_coefficient"),
        .face_width_pinion_mm = def("gear", "face_width_pinion_mm"),
        .face_width_gear_mm = def("gear", "face_width_gear_mm"),
        .groove_width_mm = def("gear", "groove_width_mm"),
        .bore_diameter_pinion_mm = def("gear", "bore_diameter_pinion_mm"),
        .bore_diameter_gear_mm = def("gear", "bore_diameter_gear_mm"),
        .youngs_modulus_gpa = def("gear", "youngs_modulus_gpa"),
        .poisson_ratio = def("gear", "poisson_ratio"),
        .density_kg_per_m3 = def("gear", "density_kg_per_m3"),
        .arrangement = (int)def("gear", "arrangement"),
        .pinion_hand = (int)def("gear", "pinion_hand"),
        .root_relief_amount_um = def("modification", "root_relief_amount_um"),
        .root_relief_length_mm = def("modification", "root_relief_length_mm"),
        .tip_relief_amount_um = def("modification", "tip_relief_amount_um"),
        .tip_relief_length_mm = def("modification", "tip_relief_length_mm"),
        .lead_relief_inner_um = def("modification", "lead_relief_inner_um"),
        .lead_relief_outer_um = def("modification", "lead_relief_outer_um"),
        .lead_unmodified_length_mm = def("modification", "lead_unmodified_length_mm"),
        .axis_in_plane_arcmin = def("misalignment", "axis_in_plane_arcmin"),
        .axis_cross_plane_arcmin = def("misalignment", "axis_cross_plane_arcmin"),
        .centre_distance_error_mm = def("misalignment", "centre_distance_error_mm"),
    };
}
