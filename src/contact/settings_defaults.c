/* The defaults of gd_tca_settings and gd_ltca_settings (gd_tca.h, gd_ltca.h): those of the case keys
 * their fields copy, read from the schema; the load of LTCA has none (the caller gives it). */
#include "geardyn/gd_ltca.h"
#include "geardyn/gd_case.h"

#include <math.h>

static double def(const char *key) { return gd_case_find_key("solver", key)->def; }

GD_API gd_tca_settings gd_tca_settings_defaults(void)
{
    return (gd_tca_settings){
        .profile_points = (int)def("tca_profile_points"),
        .face_points = (int)def("tca_face_points"),
        .refine = (int)def("tca_refine"),
        .positions_per_cycle = (int)def("tca_positions_per_cycle"),
        .cycles = (int)def("tca_cycles"),
        .formulation = (int)def("tca_formulation"),
    };
}

GD_API gd_ltca_settings gd_ltca_settings_defaults(void)
{
    return (gd_ltca_settings){
        .torque_nm = NAN,
        .pinion_axial = (int)gd_case_find_key("support", "pinion_axial")->def,
        .positions_per_cycle = (int)def("ltca_positions_per_cycle"),
        .face_slices = (int)def("ltca_face_slices"),
        .profile_points = (int)def("tca_profile_points"),
        .refine = (int)def("tca_refine"),
    };
}
