/* The gear pair and the contact-analysis settings of a case (gd_scene.h) as arguments: each
 * macro converts the case where it is called (after any change the test made to it) into a
 * temporary that lives to the end of the enclosing block. Header-only. */
#ifndef GD_PAIR_UTIL_H
#define GD_PAIR_UTIL_H

#include "geardyn/gd_scene.h"

#define PAIR_OF(c) ((const gd_pair[]){gd_pair_from_case(c)})
#define TCA_SET_OF(c) ((const gd_tca_settings[]){gd_tca_settings_from_case(c)})
#define LTCA_SET_OF(c) ((const gd_ltca_settings[]){gd_ltca_settings_from_case(c)})

#endif
