/* Cases for the LTCA tests: the paper's pair (Table 1) with its installation errors and the
 * Table 2 modification, and variations. */
#ifndef GD_LTCA_UTIL_H
#define GD_LTCA_UTIL_H

#include "geardyn/geardyn.h"
#include "tap.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

enum { LT_MIS = 1, LT_MOD = 2, LT_FIXED = 4 };

/* flags: LT_MIS the paper's delta 0.5' and dE 0.1 mm, LT_MOD the Table 2 modification, LT_FIXED
 * an axially fixed pinion; then NULL-terminated "section.key=value" overrides. Returns 0 on
 * success (and prints a failed TAP line otherwise). */
static inline int lt_case(gd_case *c, int flags, ...)
{
    gd_error e = {0};
    gd_case_init(c, &e);
    c->speed_rpm = 4000, c->torque_nm = 500; /* the paper's operating point: a case must give one */
    static const char *mis[] = {"misalignment.axis_in_plane_arcmin=-0.35355339",
                                "misalignment.axis_cross_plane_arcmin=0.35355339",
                                "misalignment.centre_distance_error_mm=0.1"};
    static const char *mod[] = {"modification.root_relief_amount_um=25", "modification.root_relief_length_mm=1.5",
                                "modification.tip_relief_amount_um=35", "modification.tip_relief_length_mm=2.5",
                                "modification.lead_relief_inner_um=25", "modification.lead_relief_outer_um=25",
                                "modification.lead_unmodified_length_mm=35"};
    int k = 0, bad = 0;
    bad |= gd_case_set(c, "scene.analysis=ltca", k++, &e) != GD_OK;
    for (int i = 0; i < 3 && (flags & LT_MIS); i++)
        bad |= gd_case_set(c, mis[i], k++, &e) != GD_OK;
    for (int i = 0; i < 7 && (flags & LT_MOD); i++)
        bad |= gd_case_set(c, mod[i], k++, &e) != GD_OK;
    if (flags & LT_FIXED)
        bad |= gd_case_set(c, "support.pinion_axial=fixed", k++, &e) != GD_OK;
    va_list ap;
    va_start(ap, flags);
    for (const char *s; (s = va_arg(ap, const char *)) != NULL;)
        bad |= gd_case_set(c, s, k++, &e) != GD_OK;
    va_end(ap);
    if (!bad)
        bad = gd_case_resolve(c, &e) != GD_OK;
    if (bad)
        tap_ok(0, "case: %s", e.msg);
    return bad;
}

static inline double lt_arcsec(double rad) { return rad * 180.0 * 3600.0 / M_PI; }

#endif
