/* The case's [optimize] section: cross-key checks, derived defaults, and the lists it names
 * (docs/optimisation.md section 8). Messages name the key as `file:line: optimize.key: ...`. */
#include "opt_internal.h"
#include "../case/case_keys.h"
#include "geardyn/gd_geometry.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void derived(gd_case *c, const char *key)
{
    if (c->src)
        c->src[gd_case_key_index("optimize", key)] = GD_SRC_DERIVED;
}

/* Split a comma-separated list; each name stripped of blanks. Returns the count or -1 (too many). */
static int split(const char *list, char names[][48], int max)
{
    int n = 0;
    const char *p = list;
    while (*p) {
        const char *e = strchr(p, ',');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        while (len && (*p == ' ' || *p == '\t')) {
            p++;
            len--;
        }
        while (len && (p[len - 1] == ' ' || p[len - 1] == '\t'))
            len--;
        if (n == max)
            return -1;
        if (len >= 48)
            len = 47;
        memcpy(names[n], p, len);
        names[n][len] = 0;
        n++;
        if (!e)
            break;
        p = e + 1;
    }
    return n;
}

int gd_opt_case_optimizers(const gd_case *c, int *algs, int max)
{
    if (c->analysis == GD_ANALYSIS_OPTIMIZE) {
        if (max > 0)
            algs[0] = c->opt_algorithm;
        return 1;
    }
    char names[GD_OPT_NALGORITHMS + 1][48];
    int n = split(c->opt_optimizers, names, GD_OPT_NALGORITHMS + 1), k = 0;
    for (int i = 0; i < n && k < max; i++) {
        int a = gd_opt_algorithm_parse(names[i]);
        if (a >= 0)
            algs[k++] = a;
    }
    return k;
}

int gd_opt_case_objectives(const gd_case *c, int *objs, int max)
{
    char names[GD_OBJ_NOBJECTIVES + 1][48];
    int n = split(c->opt_objective, names, GD_OBJ_NOBJECTIVES + 1), k = 0;
    for (int i = 0; i < n && k < max; i++) {
        int o = gd_opt_objective_parse(names[i]);
        if (o >= 0)
            objs[k++] = o;
    }
    return k;
}

long gd_opt_case_budget(const gd_case *c)
{
    if (c->opt_budget_evals > 0)
        return c->opt_budget_evals;
    return (long)c->opt_population * ((long)c->opt_iterations + 1);
}

unsigned long gd_opt_run_seed(const gd_case *c, int r) { return (unsigned long)c->opt_seed + (unsigned long)r; }

unsigned long gd_opt_instance_seed(const gd_case *c, int r)
{
    /* a stream apart from the optimisers' (a 32-bit mix of the run seed) */
    unsigned long z = (gd_opt_run_seed(c, r) + 0x9e3779b9UL) & 0xffffffffUL;
    z = ((z ^ (z >> 16)) * 0x45d9f3bUL) & 0xffffffffUL;
    z = ((z ^ (z >> 16)) * 0x45d9f3bUL) & 0xffffffffUL;
    return z ^ (z >> 16);
}

/* The [optimize] bound keys of variable id (0..8: y1 .. y9). */
static const char *gear_key(int id, int upper)
{
    static const char *const keys[GD_OPT_GEAR_NVARS][2] = {
        {"root_relief_amount_min_um", "root_relief_amount_max_um"},
        {"root_relief_length_min_mm", "root_relief_length_max_mm"},
        {"tip_relief_amount_min_um", "tip_relief_amount_max_um"},
        {"tip_relief_length_min_mm", "tip_relief_length_max_mm"},
        {"lead_relief_min_um", "lead_relief_max_um"},
        {"lead_relief_min_um", "lead_relief_max_um"},
        {"lead_unmodified_length_min_mm", "lead_unmodified_length_max_mm"},
        {"lead_unmodified_centre_min_mm", "lead_unmodified_centre_max_mm"},
        {"helix_slope_min_um", "helix_slope_max_um"},
    };
    return keys[id][upper];
}

void gd_opt_case_gear_vars(const gd_case *c, gd_opt_gear_vars *v)
{
    gd_error e = {0};
    if (gd_opt_gear_vars_parse(c->opt_variables, v, &e) != GD_OK)
        gd_opt_gear_vars_paper(v);
}

/* The default bounds, scaled to the pair (docs/optimisation.md section 2): relief amounts up to the
 * larger of 12 um per mm of normal module (the paper's 60 um at 5 mm) and three static deflections
 * of one mesh under ISO 6336-1's stiffness plus twice the misalignment's mismatch across the face;
 * profile lengths from 0.1 to 2.4 normal modules (the paper's 0.5 to 12 mm), at most the active
 * profile; the unmodified lead band from a quarter to 0.95 of the pinion face (the paper's 10 to 38
 * of 40 mm), its middle within a quarter of the face either side; the helix slope within the
 * static deflection plus twice the mismatch either side. The paper's pair at the paper's load gets
 * the paper's bounds. */
static void derive_gear_bounds(gd_case *c, const gd_pair *pair)
{
    gd_geometry g;
    gd_error e = {0};
    if (gd_geometry_compute(pair, &g, &e) != GD_OK)
        return; /* the scene has refused it already */
    int meshes = pair->arrangement == GD_ARR_HERRINGBONE ? 2 : 1;
    double fn = c->torque_nm / (meshes * g.rb[0] * cos(g.beta_b));          /* N, one mesh */
    double delta_um = fn / gd_iso6336_mesh_stiffness(pair, &g) * 1e6;       /* static deflection */
    double tilt = hypot(pair->axis_in_plane_arcmin, pair->axis_cross_plane_arcmin) / 60.0 * M_PI / 180.0;
    double mismatch_um = tilt * g.b_contact * 1e6;                           /* across the face */
    double mn = pair->normal_module_mm, b1 = g.b[0] * 1e3, active = (g.rho_a[0] - g.rho_sap[0]) * 1e3;
    /* amounts rounded up to whole micrometres */
    double amount = ceil(fmax(12.0 * mn, 3.0 * delta_um + 2.0 * mismatch_um) - 1e-9);
    double lmin = 0.1 * mn, lmax = fmin(2.4 * mn, active), slope = ceil(delta_um + 2.0 * mismatch_um - 1e-9);
    gd_case_key_derive(c, "optimize", "root_relief_amount_max_um", &c->opt_root_amount_max_um, amount);
    gd_case_key_derive(c, "optimize", "tip_relief_amount_max_um", &c->opt_tip_amount_max_um, amount);
    gd_case_key_derive(c, "optimize", "lead_relief_max_um", &c->opt_lead_amount_max_um, amount);
    gd_case_key_derive(c, "optimize", "root_relief_length_min_mm", &c->opt_root_length_min_mm, lmin);
    gd_case_key_derive(c, "optimize", "root_relief_length_max_mm", &c->opt_root_length_max_mm, lmax);
    gd_case_key_derive(c, "optimize", "tip_relief_length_min_mm", &c->opt_tip_length_min_mm, lmin);
    gd_case_key_derive(c, "optimize", "tip_relief_length_max_mm", &c->opt_tip_length_max_mm, lmax);
    gd_case_key_derive(c, "optimize", "lead_unmodified_length_min_mm", &c->opt_lead_length_min_mm, 0.25 * b1);
    gd_case_key_derive(c, "optimize", "lead_unmodified_length_max_mm", &c->opt_lead_length_max_mm, 0.95 * b1);
    gd_case_key_derive(c, "optimize", "lead_unmodified_centre_min_mm", &c->opt_lead_centre_min_mm, -0.25 * b1);
    gd_case_key_derive(c, "optimize", "lead_unmodified_centre_max_mm", &c->opt_lead_centre_max_mm, 0.25 * b1);
    gd_case_key_derive(c, "optimize", "helix_slope_min_um", &c->opt_helix_slope_min_um, -slope);
    gd_case_key_derive(c, "optimize", "helix_slope_max_um", &c->opt_helix_slope_max_um, slope);
}

static gd_status check_gear(gd_case *c, const gd_pair *pair, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    gd_opt_gear_vars v;
    {
        gd_error e2 = {0};
        if (gd_opt_gear_vars_parse(c->opt_variables, &v, &e2) != GD_OK) {
            gd_case_key_where(c, "optimize", "variables", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.variables: %s", w, e2.msg);
        }
    }
    if (!(c->torque_nm > 0)) {
        snprintf(w, sizeof w, "%s", c->path[0] ? c->path : "case");
        return gd_error_set(err, GD_ERR_INPUT, "%s: operating.torque_nm: a pinion torque of %g N m for gear-lte "
                            "(valid: > 0, the loaded contact needs a load)", w, c->torque_nm);
    }
    derive_gear_bounds(c, pair);
    double lo[GD_OPT_GEAR_NVARS], hi[GD_OPT_GEAR_NVARS], active;
    gd_opt_gear_bounds(c, &v, lo, hi);
    /* bounds in order */
    for (int i = 0; i < v.n; i++)
        if (!(lo[i] < hi[i])) {
            int id = v.var[i];
            int up = gd_case_key_given(c, "optimize", gear_key(id, 1)) || !gd_case_key_given(c, "optimize", gear_key(id, 0));
            gd_case_key_where(c, "optimize", gear_key(id, up), w, sizeof w);
            const char *sym;
            gd_opt_gear_variable(id, NULL, &sym);
            (void)sym;
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.%s: the bounds of %s are [%g, %g] (valid: the "
                                "lower bound below the upper)", w, gear_key(id, up),
                                gd_opt_gear_variable(id, NULL, NULL), lo[i], hi[i]);
        }
    const char *bad = NULL;
    double xb[GD_OPT_GEAR_NVARS];
    gd_error e2 = {0};
    int corner = opt_gear_box(pair, &v, lo, hi, &active, &bad, xb, &e2);
    if (corner == -1)
        return GD_OK;
    if (corner < 0) {
        if (err)
            *err = e2;
        return gd_error_prefix(err, "%s: [optimize]", c->path[0] ? c->path : "case");
    }
    /* the bound responsible: the failing [modification] key's variable at this corner */
    int var = 0;
    for (int i = 0; bad && i < v.n; i++)
        if (strcmp(bad, gd_opt_gear_variable(v.var[i], NULL, NULL)) == 0)
            var = i;
    int up = corner >> var & 1;
    char at[512];
    size_t n = 0;
    for (int i = 0; i < v.n && n < sizeof at; i++) {
        const char *unit, *sym;
        gd_opt_gear_variable(v.var[i], &unit, &sym);
        n += (size_t)snprintf(at + n, sizeof at - n, "%s%s = %g %s", i ? ", " : "", sym, xb[i], unit);
    }
    gd_case_key_where(c, "optimize", gear_key(v.var[var], up), w, sizeof w);
    return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.%s: the box holds a modification that does not fit on the "
                        "pinion (%s; root + tip relief lengths are repaired to fit the %.4g mm of active profile): "
                        "modification.%s: %s", w, gear_key(v.var[var], up), at, active, bad ? bad : "?", e2.msg);
}

/* optimize.optimizers (compare-optimizers): known names, each at most once. */
static gd_status resolve_optimizers(const gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    char valid[512] = "";
    for (int a = 0; a < GD_OPT_NALGORITHMS; a++) {
        size_t u = strlen(valid);
        snprintf(valid + u, sizeof valid - u, "%s%s", a ? ", " : "", gd_opt_algorithm_name(a));
    }
    char names[GD_OPT_NALGORITHMS + 1][48];
    int n = split(c->opt_optimizers, names, GD_OPT_NALGORITHMS + 1);
    int seen[GD_OPT_NALGORITHMS] = {0};
    gd_case_key_where(c, "optimize", "optimizers", w, sizeof w);
    if (n < 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.optimizers: more than %d names (valid: each of %s at "
                            "most once)", w, GD_OPT_NALGORITHMS, valid);
    if (n == 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.optimizers: empty (valid: comma-separated, of %s)", w,
                            valid);
    for (int i = 0; i < n; i++) {
        int a = gd_opt_algorithm_parse(names[i]);
        if (a < 0)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.optimizers: unknown optimiser '%s' (valid: %s)", w,
                                names[i], valid);
        if (seen[a]++)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.optimizers: '%s' twice (valid: each at most once)",
                                w, names[i]);
    }
    return GD_OK;
}

/* What the objectives named include: the gear, test functions, Rosenbrock. */
typedef struct objective_kinds {
    int gear, tests, rosen;
    int objective;           /* the last named */
} objective_kinds;

/* The objectives a case can name: gear-lte, the test functions and zdt1, zdt2 (two objectives)
 * everywhere; gear-lte-range and gear-dynamic for optimize only. */
static int case_objective(int o, int compare)
{
    if (o == GD_OBJ_ZDT1 || o == GD_OBJ_ZDT2)
        return 1;
    if (o == GD_OBJ_GEAR_LTE_RANGE || o == GD_OBJ_GEAR_DYNAMIC)
        return !compare;
    return 1;
}

/* optimize.objective: known names, each at most once, one for optimize. */
static gd_status resolve_objectives(const gd_case *c, int compare, objective_kinds *ok, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    char valid[512] = "";
    for (int o = 0, k = 0; o < GD_OBJ_NOBJECTIVES; o++)
        if (case_objective(o, compare)) {
            size_t u = strlen(valid);
            snprintf(valid + u, sizeof valid - u, "%s%s", k++ ? ", " : "", gd_opt_objective_name(o));
        }
    char onames[GD_OBJ_NOBJECTIVES + 1][48];
    int no = split(c->opt_objective, onames, GD_OBJ_NOBJECTIVES + 1);
    ok->gear = ok->tests = ok->rosen = 0;
    ok->objective = -1;
    int seen[GD_OBJ_NOBJECTIVES] = {0};
    gd_case_key_where(c, "optimize", "objective", w, sizeof w);
    if (no <= 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective: %s (valid: %s%s)", w,
                            no < 0 ? "too many names" : "empty", compare ? "comma-separated, of " : "one of ", valid);
    if (!compare && no != 1)
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective: %d objectives for optimize (valid: one of "
                            "%s; compare-optimizers takes a list)", w, no, valid);
    for (int i = 0; i < no; i++) {
        int o = gd_opt_objective_parse(onames[i]);
        if (o >= 0 && !case_objective(o, compare) && case_objective(o, 0))
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective: '%s' for compare-optimizers (valid: %s; "
                                "%s is an objective of optimize)", w, onames[i], valid, onames[i]);
        if (o < 0 || !case_objective(o, compare))
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective: unknown objective '%s' (valid: %s)", w,
                                onames[i], valid);
        if (seen[o]++)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective: '%s' twice (valid: each at most once)",
                                w, onames[i]);
        ok->gear |= gd_opt_objective_is_gear(o);
        ok->tests |= !gd_opt_objective_is_gear(o);
        ok->rosen |= o == GD_OBJ_ROSENBROCK;
        ok->objective = o;
    }
    return GD_OK;
}

/* The torques and duty weights of gear-lte-range and gear-dynamic, the speed range and model of
 * gear-dynamic (docs/optimisation.md section 12); the dynamics in the loop need the candidate's
 * LTCA mesh stiffness. */
static gd_status resolve_load_speed(gd_case *c, const gd_pair *pair, int objective, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    const char *name = gd_opt_objective_name(objective);
    if (c->n_opt_torques == 0) {
        if (!(c->torque_nm > 0)) {
            gd_case_key_where(c, "optimize", "torques_nm", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.torques_nm: none, and operating.torque_nm is %g N m "
                                "(valid: 1 to %d torques > 0 N m, comma-separated)", w, c->torque_nm, GD_OPT_MAX_TORQUES);
        }
        c->opt_torques_nm[0] = c->torque_nm;
        c->n_opt_torques = 1;
        derived(c, "torques_nm");
    }
    gd_case_key_where(c, "optimize", "torques_nm", w, sizeof w);
    if (c->n_opt_torques > GD_OPT_MAX_TORQUES)
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.torques_nm: %d torques (valid: 1 to %d)", w,
                            c->n_opt_torques, GD_OPT_MAX_TORQUES);
    for (int k = 0; k < c->n_opt_torques; k++)
        if (!(c->opt_torques_nm[k] > 0))
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.torques_nm: a torque of %g N m (valid: > 0, the "
                                "loaded contact needs a load)", w, c->opt_torques_nm[k]);
    if (c->n_opt_torque_weights > 0) {
        gd_case_key_where(c, "optimize", "torque_weights", w, sizeof w);
        if (c->n_opt_torque_weights != c->n_opt_torques)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.torque_weights: %d weights for %d torques (valid: one "
                                "weight per torque of optimize.torques_nm)", w, c->n_opt_torque_weights,
                                c->n_opt_torques);
        double sum = 0;
        for (int k = 0; k < c->n_opt_torque_weights; k++)
            sum += c->opt_torque_weights[k];
        if (!(sum > 0))
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.torque_weights: the weights sum to %g (valid: >= 0 "
                                "each, a positive sum)", w, sum);
    }
    double tmax = 0; /* the Harris map after the optimum */
    for (int k = 0; k < c->n_opt_torques; k++)
        tmax = fmax(tmax, c->opt_torques_nm[k]);
    if (!isfinite(c->opt_harris_from_nm))
        gd_case_key_derive(c, "optimize", "harris_torque_from_nm", &c->opt_harris_from_nm, 0.1 * tmax);
    if (!isfinite(c->opt_harris_to_nm))
        gd_case_key_derive(c, "optimize", "harris_torque_to_nm", &c->opt_harris_to_nm, 1.5 * tmax);
    if (!(c->opt_harris_from_nm > 0 && c->opt_harris_from_nm < c->opt_harris_to_nm)) {
        const char *k = gd_case_key_given(c, "optimize", "harris_torque_to_nm") ? "harris_torque_to_nm"
                                                                                 : "harris_torque_from_nm";
        gd_case_key_where(c, "optimize", k, w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.%s: the Harris map's torques %g to %g N m (valid: 0 < "
                            "harris_torque_from_nm < harris_torque_to_nm)", w, k, c->opt_harris_from_nm,
                            c->opt_harris_to_nm);
    }
    if (objective != GD_OBJ_GEAR_DYNAMIC)
        return GD_OK;
    if (c->stiffness != GD_STIFF_LTCA) {
        gd_case_key_where(c, "excitation", "stiffness", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: excitation.stiffness: not ltca for %s (valid: ltca, so that the "
                            "candidate flank's loaded mesh stiffness drives the dynamics)", w, name);
    }
    if (!isfinite(c->opt_speed_from_rpm))
        gd_case_key_derive(c, "optimize", "speed_from_rpm", &c->opt_speed_from_rpm, 0.8 * c->speed_rpm);
    if (!isfinite(c->opt_speed_to_rpm))
        gd_case_key_derive(c, "optimize", "speed_to_rpm", &c->opt_speed_to_rpm, 1.2 * c->speed_rpm);
    if (!(c->opt_speed_from_rpm > 0 && c->opt_speed_from_rpm < c->opt_speed_to_rpm)) {
        const char *k = gd_case_key_given(c, "optimize", "speed_to_rpm") ? "speed_to_rpm" : "speed_from_rpm";
        gd_case_key_where(c, "optimize", k, w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.%s: the speed range %g to %g rpm (valid: 0 < "
                            "speed_from_rpm < speed_to_rpm)", w, k, c->opt_speed_from_rpm, c->opt_speed_to_rpm);
    }
    if (!isfinite(c->opt_dynamic_sweep_step_rpm))
        gd_case_key_derive(c, "optimize", "dynamic_sweep_step_rpm", &c->opt_dynamic_sweep_step_rpm,
                           (c->opt_speed_to_rpm - c->opt_speed_from_rpm) / 50);
    if (!(c->opt_dynamic_sweep_step_rpm > 0 &&
          c->opt_dynamic_sweep_step_rpm <= c->opt_speed_to_rpm - c->opt_speed_from_rpm)) {
        gd_case_key_where(c, "optimize", "dynamic_sweep_step_rpm", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.dynamic_sweep_step_rpm: %g rpm (valid: > 0 and at most "
                            "the speed range, %g rpm)", w, c->opt_dynamic_sweep_step_rpm,
                            c->opt_speed_to_rpm - c->opt_speed_from_rpm);
    }
    if (!gd_case_key_given(c, "optimize", "dynamic_model")) {
        c->opt_dynamic_model = pair->arrangement == GD_ARR_HERRINGBONE ? GD_MODEL_TORSIONAL_LR : GD_MODEL_TORSIONAL;
        derived(c, "dynamic_model");
    } else if (pair->arrangement != GD_ARR_HERRINGBONE && c->opt_dynamic_model == GD_MODEL_TORSIONAL_LR) {
        gd_case_key_where(c, "optimize", "dynamic_model", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.dynamic_model: torsional-lr for a single pair (valid: "
                            "torsional or bta; torsional-lr has a herringbone's two halves)", w);
    }
    return GD_OK;
}

/* optimize.dimension (default 6) and optimize.shift, against the objectives. */
static gd_status resolve_dimensions(gd_case *c, int compare, const objective_kinds *ok, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    gd_opt_gear_vars gv;
    gd_opt_case_gear_vars(c, &gv);
    int gear_only = ok->gear && !ok->tests;
    if (c->n_opt_dimensions == 0) {
        c->opt_dimensions[0] = gear_only ? gv.n : 6;
        c->n_opt_dimensions = 1;
        derived(c, "dimension");
    } else {
        gd_case_key_where(c, "optimize", "dimension", w, sizeof w);
        if (!compare && c->n_opt_dimensions != 1)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.dimension: %d values for optimize (valid: one; "
                                "compare-optimizers takes a list)", w, c->n_opt_dimensions);
        for (int i = 0; i < c->n_opt_dimensions; i++) {
            double d = c->opt_dimensions[i];
            if (d != floor(d) || (ok->rosen && d < 2))
                return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.dimension: %g (valid: whole numbers from %d to "
                                    "1000)", w, d, ok->rosen ? 2 : 1);
            for (int j = 0; j < i; j++)
                if (c->opt_dimensions[j] == d)
                    return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.dimension: %g twice (valid: each at most once)",
                                        w, d);
        }
        if (gear_only && (c->n_opt_dimensions != 1 || c->opt_dimensions[0] != gv.n))
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.dimension: gear-lte has the %d variables of "
                                "optimize.variables (valid: %d, or leave dimension out)", w, gv.n, gv.n);
    }
    if (ok->gear && c->opt_shift != 0) {
        gd_case_key_where(c, "optimize", "shift", w, sizeof w);
        if (!ok->tests)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.shift: %g for gear-lte (valid: 0; the shift moves the "
                                "minimiser of a test function)", w, c->opt_shift);
    }
    return GD_OK;
}

/* optimize.runs (default 1, or 10 to compare) and the budget: budget_evals or population
 * (iterations + 1), enough for ALO's two populations. */
static gd_status resolve_budget(gd_case *c, int compare, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    if (c->opt_runs == 0) {
        c->opt_runs = compare ? 10 : 1;
        derived(c, "runs");
    }
    if (gd_case_key_given(c, "optimize", "budget_evals") && gd_case_key_given(c, "optimize", "iterations")) {
        gd_case_key_where(c, "optimize", "budget_evals", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.budget_evals: give iterations or budget_evals, not both "
                            "(valid: one; the budget is population (iterations + 1))", w);
    }
    if (c->opt_budget_evals == 0) {
        long b = (long)c->opt_population * ((long)c->opt_iterations + 1);
        if (b > 2000000000L) {
            gd_case_key_where(c, "optimize", "iterations", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.iterations: a budget of %ld evaluations (valid: "
                                "population (iterations + 1) at most 2e9)", w, b);
        }
        c->opt_budget_evals = (int)b;
        derived(c, "budget_evals");
    }
    int algs[GD_OPT_NALGORITHMS];
    int na = gd_opt_case_optimizers(c, algs, GD_OPT_NALGORITHMS), alo = 0;
    for (int i = 0; i < na; i++)
        alo |= algs[i] == GD_OPT_ALO || algs[i] == GD_OPT_MOALO;
    if (alo && c->opt_budget_evals < 2 * c->opt_population) {
        const char *k = gd_case_key_given(c, "optimize", "budget_evals") ? "budget_evals" : "population";
        gd_case_key_where(c, "optimize", k, w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.%s: a budget of %d evaluations for ALO with %d ants "
                            "(valid: at least two populations, %d)", w, k, c->opt_budget_evals, c->opt_population,
                            2 * c->opt_population);
    }
    return GD_OK;
}

/* optimize.target and target_loosest (defaults by objective), in order. */
static gd_status resolve_targets(gd_case *c, const objective_kinds *ok, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    if (!isfinite(c->opt_target)) {
        c->opt_target = ok->gear && !ok->tests ? 0.005 : 1e-8;
        derived(c, "target");
    }
    if (!isfinite(c->opt_target_loosest)) {
        c->opt_target_loosest = ok->gear && !ok->tests ? 1.0 : 100.0;
        derived(c, "target_loosest");
    }
    if (c->opt_target_loosest < c->opt_target || (c->opt_ecdf_targets > 1 && !(c->opt_target_loosest > c->opt_target))) {
        const char *k = gd_case_key_given(c, "optimize", "target_loosest") ? "target_loosest" : "target";
        gd_case_key_where(c, "optimize", k, w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.%s: target_loosest %g is not above target %g (valid: "
                            "target_loosest > target)", w, k, c->opt_target_loosest, c->opt_target);
    }
    return GD_OK;
}

gd_status gd_opt_resolve_case(gd_case *c, const gd_pair *pair, gd_error *err)
{
    int compare = c->analysis == GD_ANALYSIS_COMPARE_OPTIMIZERS;
    objective_kinds ok;
    gd_status st = compare ? resolve_optimizers(c, err) : GD_OK;
    if (st == GD_OK)
        st = resolve_objectives(c, compare, &ok, err);
    if (st == GD_OK)
        st = resolve_dimensions(c, compare, &ok, err);
    if (st == GD_OK)
        st = resolve_budget(c, compare, err);
    if (st == GD_OK)
        st = resolve_targets(c, &ok, err);
    if (st == GD_OK)
        st = gd_opt_resolve_robust(c, compare, ok.gear, err);
    if (st == GD_OK)
        st = gd_opt_resolve_two(c, compare, err);
    if (st == GD_OK && ok.gear)
        st = check_gear(c, pair, err);
    const int dyn2 = strcmp(c->opt_objective2, "gear-dynamic") == 0; /* two objectives */
    if (st == GD_OK &&
        ((!compare && (ok.objective == GD_OBJ_GEAR_LTE_RANGE || ok.objective == GD_OBJ_GEAR_DYNAMIC)) || dyn2))
        st = resolve_load_speed(c, pair, dyn2 ? GD_OBJ_GEAR_DYNAMIC : ok.objective, err);
    return st;
}
