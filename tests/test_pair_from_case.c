/* A case becomes the physics' inputs (src/scene/pair_from_case.c):
 * 1. gd_pair_from_case: with every numeric key of the pair set to its own value, each field of the
 *    pair equals its key as the schema reads it (gd_case_get_number: through the schema's
 *    offsets, not the conversion's code), so no two fields are swapped; the enum fields follow
 *    their keys; the fields checked cover all of sizeof(gd_pair), so a field added to the pair
 *    and not to this table fails here.
 * 2. gd_tca_settings_from_case and gd_ltca_settings_from_case in the same way, with every field
 *    covered; their stop hook, which is the caller's and no key's, is left empty.
 * 3. gd_pair_modification_to_case writes the nine [modification] amounts and lengths of a pair
 *    into a case and nothing else: every other key keeps its value. */
#include "geardyn/gd_scene.h"
#include "tap.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct field {
    const char *key;         /* "section.key" */
    size_t off, size;        /* in the structure */
    int is_int;
} field;

#define F(type, key, member, is_int) {key, offsetof(type, member), sizeof(((type *)0)->member), is_int}

static const field pair_fields[] = {
    F(gd_pair, "gear.normal_module_mm", normal_module_mm, 0),
    F(gd_pair, "gear.helix_angle_deg", helix_angle_deg, 0),
    F(gd_pair, "gear.normal_pressure_angle_deg", normal_pressure_angle_deg, 0),
    F(gd_pair, "gear.teeth_pinion", teeth_pinion, 1),
    F(gd_pair, "gear.teeth_gear", teeth_gear, 1),
    F(gd_pair, "gear.profile_shift_pinion", profile_shift_pinion, 0),
    F(gd_pair, "gear.profile_shift_gear", profile_shift_gear, 0),
    F(gd_pair, "gear.addendum_coefficient", addendum_coefficient, 0),
    F(gd_pair, "gear.dedendum_coefficient", dedendum_coefficient, 0),
    F(gd_pair, "gear.face_width_pinion_mm", face_width_pinion_mm, 0),
    F(gd_pair, "gear.face_width_gear_mm", face_width_gear_mm, 0),
    F(gd_pair, "gear.groove_width_mm", groove_width_mm, 0),
    F(gd_pair, "gear.bore_diameter_pinion_mm", bore_diameter_pinion_mm, 0),
    F(gd_pair, "gear.bore_diameter_gear_mm", bore_diameter_gear_mm, 0),
    F(gd_pair, "gear.rim_inner_diameter_pinion_mm", rim_inner_diameter_pinion_mm, 0),
    F(gd_pair, "gear.rim_inner_diameter_gear_mm", rim_inner_diameter_gear_mm, 0),
    F(gd_pair, "gear.web_thickness_pinion_mm", web_thickness_pinion_mm, 0),
    F(gd_pair, "gear.web_thickness_gear_mm", web_thickness_gear_mm, 0),
    F(gd_pair, "gear.hub_diameter_pinion_mm", hub_diameter_pinion_mm, 0),
    F(gd_pair, "gear.hub_diameter_gear_mm", hub_diameter_gear_mm, 0),
    F(gd_pair, "gear.hub_length_pinion_mm", hub_length_pinion_mm, 0),
    F(gd_pair, "gear.hub_length_gear_mm", hub_length_gear_mm, 0),
    F(gd_pair, "gear.youngs_modulus_gpa", youngs_modulus_gpa, 0),
    F(gd_pair, "gear.poisson_ratio", poisson_ratio, 0),
    F(gd_pair, "gear.density_kg_per_m3", density_kg_per_m3, 0),
    F(gd_pair, "modification.root_relief_amount_um", root_relief_amount_um, 0),
    F(gd_pair, "modification.root_relief_length_mm", root_relief_length_mm, 0),
    F(gd_pair, "modification.tip_relief_amount_um", tip_relief_amount_um, 0),
    F(gd_pair, "modification.tip_relief_length_mm", tip_relief_length_mm, 0),
    F(gd_pair, "modification.lead_relief_inner_um", lead_relief_inner_um, 0),
    F(gd_pair, "modification.lead_relief_outer_um", lead_relief_outer_um, 0),
    F(gd_pair, "modification.lead_unmodified_length_mm", lead_unmodified_length_mm, 0),
    F(gd_pair, "modification.lead_unmodified_centre_mm", lead_unmodified_centre_mm, 0),
    F(gd_pair, "modification.helix_slope_um", helix_slope_um, 0),
    F(gd_pair, "misalignment.axis_in_plane_arcmin", axis_in_plane_arcmin, 0),
    F(gd_pair, "misalignment.axis_cross_plane_arcmin", axis_cross_plane_arcmin, 0),
    F(gd_pair, "misalignment.centre_distance_error_mm", centre_distance_error_mm, 0),
};
static const field tca_fields[] = {
    F(gd_tca_settings, "solver.tca_profile_points", profile_points, 1),
    F(gd_tca_settings, "solver.tca_face_points", face_points, 1),
    F(gd_tca_settings, "solver.tca_positions_per_cycle", positions_per_cycle, 1),
    F(gd_tca_settings, "solver.tca_cycles", cycles, 1),
};
static const field ltca_fields[] = {
    F(gd_ltca_settings, "operating.torque_nm", torque_nm, 0),
    F(gd_ltca_settings, "solver.ltca_positions_per_cycle", positions_per_cycle, 1),
    F(gd_ltca_settings, "solver.ltca_face_slices", face_slices, 1),
    F(gd_ltca_settings, "solver.tca_profile_points", profile_points, 1),
};
#define N(a) (sizeof a / sizeof a[0])

/* Key i of n gets a value of its own inside its valid range (an integer for an int key). */
static void set_distinct(gd_case *c, const field *f, size_t n, size_t first, size_t total, gd_error *e)
{
    for (size_t i = 0; i < n; i++) {
        char sec[32];
        const char *dot = strchr(f[i].key, '.');
        snprintf(sec, sizeof sec, "%.*s", (int)(dot - f[i].key), f[i].key);
        const gd_keyspec *k = gd_case_find_key(sec, dot + 1);
        double v = k->min + (fmin(k->max, k->min + 1000) - k->min) * (double)(first + i + 1) / (double)(total + 2);
        if (f[i].is_int)
            v = ceil(v);
        if (gd_case_set_number(c, f[i].key, v, e) != GD_OK)
            tap_ok(0, "set %s = %g: %s", f[i].key, v, e->msg);
    }
}

/* Every field equals its key; returns the bytes the fields cover. */
static size_t compare(const gd_case *c, const void *s, const field *f, size_t n, const char *what, gd_error *e)
{
    size_t bytes = 0;
    int bad = 0;
    for (size_t i = 0; i < n; i++) {
        double want = NAN, got;
        gd_case_get_number(c, f[i].key, &want, e);
        const char *p = (const char *)s + f[i].off;
        if (f[i].is_int)
            got = *(const int *)p;
        else
            got = *(const double *)p;
        if (got != want) {
            tap_ok(0, "%s: the field of %s is %.17g, the key %.17g", what, f[i].key, got, want);
            bad = 1;
        }
        bytes += f[i].size;
    }
    tap_ok(!bad, "%s: each of %zu numeric fields equals its own key (all values distinct)", what, n);
    return bytes;
}

static void conversions(void)
{
    gd_error e = {0};
    gd_case c;
    if (gd_case_init(&c, &e) != GD_OK) {
        tap_ok(0, "gd_case_init: %s", e.msg);
        return;
    }
    size_t total = N(pair_fields) + N(tca_fields) + N(ltca_fields);
    set_distinct(&c, pair_fields, N(pair_fields), 0, total, &e);
    set_distinct(&c, tca_fields, N(tca_fields), N(pair_fields), total, &e);
    set_distinct(&c, ltca_fields + 1, N(ltca_fields) - 2, N(pair_fields) + N(tca_fields), total, &e);
    set_distinct(&c, ltca_fields, 1, total - 1, total, &e); /* the torque */
    const char *enums[] = {"gear.arrangement=helical", "gear.pinion_hand=left", "solver.tca_formulation=both",
                           "solver.tca_refine=false", "support.pinion_axial=fixed"};
    for (size_t i = 0; i < N(enums); i++)
        if (gd_case_set(&c, enums[i], (int)i + 1, &e) != GD_OK)
            tap_ok(0, "%s: %s", enums[i], e.msg);

    const gd_pair p = gd_pair_from_case(&c);
    size_t bytes = compare(&c, &p, pair_fields, N(pair_fields), "gd_pair_from_case", &e);
    tap_ok(p.arrangement == GD_ARR_HELICAL && p.pinion_hand == GD_HAND_LEFT, "gd_pair_from_case: arrangement %d "
           "(helical %d), pinion hand %d (left %d)", p.arrangement, GD_ARR_HELICAL, p.pinion_hand, GD_HAND_LEFT);
    bytes += sizeof p.arrangement + sizeof p.pinion_hand;
    tap_ok(bytes == sizeof p, "gd_pair: the fields checked cover %zu of its %zu bytes", bytes, sizeof p);

    const gd_tca_settings t = gd_tca_settings_from_case(&c);
    bytes = compare(&c, &t, tca_fields, N(tca_fields), "gd_tca_settings_from_case", &e);
    tap_ok(t.formulation == GD_TCA_BOTH && t.refine == 0, "gd_tca_settings_from_case: formulation %d (both %d), "
           "refine %d (false)", t.formulation, GD_TCA_BOTH, t.refine);
    bytes += sizeof t.formulation + sizeof t.refine;
    tap_ok(!t.stop.should_stop && !t.stop.user, "gd_tca_settings_from_case: no stop hook (the caller's)");
    bytes += sizeof t.stop;
    tap_ok(bytes == sizeof t, "gd_tca_settings: the fields checked cover %zu of its %zu bytes", bytes, sizeof t);

    const gd_ltca_settings l = gd_ltca_settings_from_case(&c);
    bytes = compare(&c, &l, ltca_fields, N(ltca_fields), "gd_ltca_settings_from_case", &e);
    tap_ok(l.pinion_axial == GD_PINION_FIXED && l.refine == 0, "gd_ltca_settings_from_case: pinion_axial %d "
           "(fixed %d), refine %d (false)", l.pinion_axial, GD_PINION_FIXED, l.refine);
    bytes += sizeof l.pinion_axial + sizeof l.refine;
    tap_ok(!l.stop.should_stop && !l.stop.user, "gd_ltca_settings_from_case: no stop hook (the caller's)");
    bytes += sizeof l.stop;
    tap_ok(bytes <= sizeof l && sizeof l - bytes < sizeof(double), "gd_ltca_settings: the fields checked cover %zu "
           "of its %zu bytes (the rest is padding)", bytes, sizeof l);
    gd_case_free(&c);
}

static void modification_back(void)
{
    gd_error e = {0};
    gd_case c, d;
    if (gd_case_init(&c, &e) != GD_OK || gd_case_init(&d, &e) != GD_OK) {
        tap_ok(0, "gd_case_init: %s", e.msg);
        return;
    }
    gd_pair p = gd_pair_from_case(&c);
    const double y[9] = {11, 1.25, 13, 2.5, 17, 19, 23, -1.5, 3.25};
    p.root_relief_amount_um = y[0];
    p.root_relief_length_mm = y[1];
    p.tip_relief_amount_um = y[2];
    p.tip_relief_length_mm = y[3];
    p.lead_relief_inner_um = y[4];
    p.lead_relief_outer_um = y[5];
    p.lead_unmodified_length_mm = y[6];
    p.lead_unmodified_centre_mm = y[7];
    p.helix_slope_um = y[8];
    p.normal_module_mm = 7; /* not a modification: must not reach the case */
    gd_pair_modification_to_case(&p, &d);
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    int other = 0, mod = 0;
    for (size_t i = 0; i < n; i++) {
        char a[256], b[256];
        gd_case_format_value(&c, i, a, sizeof a);
        gd_case_format_value(&d, i, b, sizeof b);
        int changed = strcmp(a, b) != 0;
        if (strcmp(s[i].section, "modification") == 0 && strcmp(s[i].key, "apply") != 0)
            mod += changed;
        else if (changed) {
            other++;
            tap_ok(0, "%s.%s changed: %s -> %s", s[i].section, s[i].key, a, b);
        }
    }
    const gd_pair q = gd_pair_from_case(&d);
    const double back[9] = {q.root_relief_amount_um, q.root_relief_length_mm, q.tip_relief_amount_um,
                            q.tip_relief_length_mm, q.lead_relief_inner_um, q.lead_relief_outer_um,
                            q.lead_unmodified_length_mm, q.lead_unmodified_centre_mm, q.helix_slope_um};
    tap_ok(mod == 9 && memcmp(back, y, sizeof y) == 0, "gd_pair_modification_to_case: the 9 modification keys "
           "take the pair's values (%d changed)", mod);
    tap_ok(other == 0 && q.normal_module_mm == c.normal_module_mm, "gd_pair_modification_to_case: no other key "
           "changes (%d did)", other);
    gd_case_free(&c);
    gd_case_free(&d);
}

int main(void)
{
    gsl_set_error_handler_off();
    conversions();
    modification_back();
    return tap_done();
}
