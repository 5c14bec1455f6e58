/* Where a key's value came from, its range and the names of its values (src/case/case_keys.h). */
#include "case_keys.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

size_t gd_case_key_index(const char *section, const char *key)
{
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    return (size_t)(gd_case_find_key(section, key) - s);
}

int gd_case_key_given(const gd_case *c, const char *section, const char *key)
{
    gd_source s = gd_case_source(c, gd_case_key_index(section, key), NULL);
    return s == GD_SRC_FILE || s == GD_SRC_SET;
}

void gd_case_key_where(const gd_case *c, const char *section, const char *key, char *buf, size_t len)
{
    int line = 0;
    gd_source s = gd_case_source(c, gd_case_key_index(section, key), &line);
    if (s == GD_SRC_FILE)
        snprintf(buf, len, "%s:%d", c->path, line);
    else if (s == GD_SRC_SET)
        snprintf(buf, len, "--set #%d", line);
    else
        snprintf(buf, len, "%s", c->path[0] ? c->path : "case");
}

int gd_case_key_in_range(const gd_keyspec *k, double v)
{
    if (!isfinite(v))
        return 0;
    if (k->min_open ? !(v > k->min) : !(v >= k->min))
        return 0;
    if (k->max_open ? !(v < k->max) : !(v <= k->max))
        return 0;
    return 1;
}

void gd_case_key_derive(gd_case *c, const char *section, const char *key, double *field, double value)
{
    size_t i = gd_case_key_index(section, key);
    if (c->src[i] == GD_SRC_FILE || c->src[i] == GD_SRC_SET)
        return;
    *field = value;
    c->src[i] = GD_SRC_DERIVED;
}

const char *gd_case_key_choice(const char *section, const char *key, int value, char *buf, size_t len)
{
    const char *p = value >= 0 ? gd_case_find_key(section, key)->choices : NULL;
    for (int j = 0; j < value && p; j++) {
        p = strchr(p, '|');
        if (p)
            p++;
    }
    snprintf(buf, len, "%.*s", p ? (int)strcspn(p, "|") : 1, p ? p : "?");
    return buf;
}

const gd_keyspec *gd_case_key_dotted(const char *name)
{
    char buf[256];
    snprintf(buf, sizeof buf, "%s", name);
    char *dot = strchr(buf, '.');
    if (!dot)
        return NULL;
    *dot = '\0';
    return gd_case_find_key(buf, dot + 1);
}

void gd_case_key_range_text(const gd_keyspec *k, char *buf, size_t len)
{
    if (k->type == GD_KEY_INT)
        snprintf(buf, len, "a whole number in [%.0f, %.0f]", k->min, k->max);
    else
        snprintf(buf, len, "a number in %s%g, %g%s%s%s", k->min_open ? "(" : "[", k->min, k->max,
                 k->max_open ? ")" : "]", k->unit[0] ? " " : "", k->unit);
}

/* ---- the physical values a case takes from the schema's defaults ---- */

static int analysis_integrates(const gd_case *c)
{
    return c->analysis == GD_ANALYSIS_RESPONSE || c->analysis == GD_ANALYSIS_SWEEP ||
           c->analysis == GD_ANALYSIS_CONTINUATION || c->analysis == GD_ANALYSIS_WORK_PRECISION;
}

/* 1 when the case's analysis and model use the key (a key of a model, excitation or body the case
 * does not compute is not an assumption of its results). */
static int key_used(const gd_case *c, const char *sec, const char *key)
{
    const int dyn = analysis_integrates(c);
    const int single = c->arrangement != GD_ARR_HERRINGBONE, spur = c->arrangement == GD_ARR_SPUR;
    const int bta = c->model == GD_MODEL_BTA;
    const int gear_lte = (c->analysis == GD_ANALYSIS_OPTIMIZE || c->analysis == GD_ANALYSIS_COMPARE_OPTIMIZERS) &&
                         strstr(c->opt_objective, "gear-lte") != NULL;
    const int loaded = c->analysis == GD_ANALYSIS_LTCA || gear_lte ||
                       (dyn && (c->stiffness == GD_STIFF_LTCA || c->impact));
    const int contact = loaded || c->analysis == GD_ANALYSIS_TCA;
    /* the bodies' masses and inertias derived from the blank; the mesh stiffness from ISO 6336-1; the
     * groove shafts' stiffness from E A / L; the rectangular stiffness's high fraction from the
     * contact ratio */
    const int inertias = gd_case_key_given(c, "gear", "pinion_inertia_kgm2") &&
                         gd_case_key_given(c, "gear", "gear_inertia_kgm2");
    const int masses = gd_case_key_given(c, "gear", "pinion_mass_kg") && gd_case_key_given(c, "gear", "gear_mass_kg");
    const int bodies = dyn && (bta ? !(inertias && masses)
                                   : !(inertias || gd_case_key_given(c, "gear", "equivalent_mass_kg")));
    const int iso = dyn && c->stiffness != GD_STIFF_LTCA && !gd_case_key_given(c, "excitation", "mesh_stiffness_n_per_m");
    const int shafts = dyn && bta && !single && c->axial_coupling &&
                       !(gd_case_key_given(c, "support", "shaft_stiffness_pinion_n_per_m") &&
                         gd_case_key_given(c, "support", "shaft_stiffness_gear_n_per_m"));
    const int fraction = dyn && c->stiffness == GD_STIFF_RECTANGULAR &&
                         !gd_case_key_given(c, "excitation", "rectangular_high_fraction");
    if (strcmp(sec, "gear") == 0) {
        if (!dyn && !contact)
            return 0;
        if (strcmp(key, "helix_angle_deg") == 0)
            return !spur;
        if (strcmp(key, "groove_width_mm") == 0)
            return !single && (contact || bodies || shafts);
        if (strncmp(key, "bore_diameter_", 14) == 0)
            return bodies || loaded; /* the blank, and LTCA's tooth foundation clamped at the bore */
        if (strcmp(key, "density_kg_per_m3") == 0 || strstr(key, "diameter_") || strstr(key, "thickness_") ||
            strstr(key, "length_"))
            return bodies; /* the blank: rim, web and hub */
        if (strcmp(key, "youngs_modulus_gpa") == 0 || strcmp(key, "poisson_ratio") == 0)
            return loaded || iso || (shafts && key[0] == 'y');
        if (strncmp(key, "face_width_", 11) == 0)
            return contact || iso || bodies;
        if (strncmp(key, "profile_shift_", 14) == 0 || strstr(key, "dendum_coefficient"))
            return contact || iso || bodies || fraction;
        return 1; /* module, teeth, pressure angle: the base radii and the mesh frequency */
    }
    if (strcmp(sec, "modification") == 0 || strcmp(sec, "misalignment") == 0)
        return contact;
    if (!dyn)
        return 0;
    if (strcmp(sec, "clearance") == 0)
        return strcmp(key, "backlash_um") == 0 || (bta && c->bearing_clearance);
    if (strcmp(sec, "excitation") == 0) {
        if (strncmp(key, "stiffness_", 10) == 0)
            return c->stiffness == GD_STIFF_HARMONIC;
        if (strncmp(key, "rectangular_", 12) == 0)
            return c->stiffness == GD_STIFF_RECTANGULAR;
        if (strncmp(key, "ste_", 4) == 0)
            return c->error_excitation;
        if (strcmp(key, "impact_exponent") == 0)
            return c->impact;
        if (strcmp(key, "half_phase_deg") == 0)
            return !single && c->model != GD_MODEL_TORSIONAL && c->stiffness != GD_STIFF_LTCA;
        return 0; /* the mesh stiffness (derived) and the deviations (an alternative to ste_amplitude_um) */
    }
    if (strcmp(sec, "damping") == 0)
        return strcmp(key, "mesh_damping_ratio") == 0 || (bta && strcmp(key, "support_damping_ratio") == 0) ||
               (bta && !single && c->axial_coupling && strcmp(key, "shaft_damping_ratio") == 0);
    if (strcmp(sec, "support") == 0)
        return bta && (strncmp(key, "radial_", 7) == 0 ||
                       (strncmp(key, "axial_", 6) == 0 && c->axial_coupling && !spur) ||
                       (strcmp(key, "gravity_angle_deg") == 0 && c->gravity));
    return 0;
}

/* 1 when the case's sweep or continuation varies the key (its value is the analysis's). */
static int key_varied(const gd_case *c, const char *sec, const char *key)
{
    char name[160];
    snprintf(name, sizeof name, "%s.%s", sec, key);
    return (c->analysis == GD_ANALYSIS_SWEEP && (strcmp(c->sweep_parameter, name) == 0 ||
                                                 strcmp(c->sweep_parameter2, name) == 0)) ||
           (c->analysis == GD_ANALYSIS_CONTINUATION && strcmp(c->cont_parameter, name) == 0);
}

GD_API size_t gd_case_defaulted_keys(const gd_case *c, size_t *idx, size_t cap)
{
    static const char *const physical[] = {"gear", "modification", "misalignment", "clearance", "excitation",
                                           "damping", "support"};
    size_t n, count = 0;
    const gd_keyspec *s = gd_case_schema(&n);
    for (size_t i = 0; i < n; i++) {
        const gd_keyspec *k = &s[i];
        int phys = 0;
        for (size_t j = 0; j < sizeof physical / sizeof physical[0]; j++)
            phys |= strcmp(k->section, physical[j]) == 0;
        int absent;
        if (!phys || c->src[i] != GD_SRC_DEFAULT || !key_used(c, k->section, k->key) ||
            key_varied(c, k->section, k->key) || gd_case_key_unused(c, i, &absent))
            continue;
        if (k->type == GD_KEY_DOUBLE) {
            if (!isfinite(*(const double *)((const char *)c + k->offset)))
                continue; /* no value: a key derived or an alternative not taken */
        } else if (k->type == GD_KEY_DLIST) {
            if (*(const int *)((const char *)c + k->count_offset) == 0)
                continue;
        } else if (k->type != GD_KEY_INT) {
            continue; /* the switches and choices of the model: geardyn check lists them */
        }
        if (idx && count < cap)
            idx[count] = i;
        count++;
    }
    return count;
}
