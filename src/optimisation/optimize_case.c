/* The case's [optimize] section: cross-key checks, derived defaults, and the lists it names
 * (docs/optimisation.md section 8). Messages name the key as `file:line: optimize.key: ...`. */
#include "opt_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static size_t key_index(const char *key)
{
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    return (size_t)(gd_case_find_key("optimize", key) - s);
}

static int given(const gd_case *c, const char *key)
{
    gd_source s = gd_case_source(c, key_index(key), NULL);
    return s == GD_SRC_FILE || s == GD_SRC_SET;
}

static void where(const gd_case *c, const char *key, char *buf, size_t len)
{
    int line = 0;
    gd_source s = gd_case_source(c, key_index(key), &line);
    if (s == GD_SRC_FILE)
        snprintf(buf, len, "%s:%d", c->path, line);
    else if (s == GD_SRC_SET)
        snprintf(buf, len, "--set #%d", line);
    else
        snprintf(buf, len, "%s", c->path[0] ? c->path : "case");
}

static void derived(gd_case *c, const char *key)
{
    if (c->src)
        c->src[key_index(key)] = GD_SRC_DERIVED;
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

GD_API int gd_opt_case_optimizers(const gd_case *c, int *algs, int max)
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

GD_API int gd_opt_case_objectives(const gd_case *c, int *objs, int max)
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

GD_API long gd_opt_case_budget(const gd_case *c)
{
    if (c->opt_budget_evals > 0)
        return c->opt_budget_evals;
    return (long)c->opt_population * ((long)c->opt_iterations + 1);
}

GD_API unsigned long gd_opt_run_seed(const gd_case *c, int r) { return (unsigned long)c->opt_seed + (unsigned long)r; }

GD_API unsigned long gd_opt_instance_seed(const gd_case *c, int r)
{
    /* a stream apart from the optimisers' (a 32-bit mix of the run seed) */
    unsigned long z = (gd_opt_run_seed(c, r) + 0x9e3779b9UL) & 0xffffffffUL;
    z = ((z ^ (z >> 16)) * 0x45d9f3bUL) & 0xffffffffUL;
    z = ((z ^ (z >> 16)) * 0x45d9f3bUL) & 0xffffffffUL;
    return z ^ (z >> 16);
}

static const char *gear_key(int i, int upper)
{
    static const char *const keys[6][2] = {
        {"root_relief_amount_min_um", "root_relief_amount_max_um"},
        {"root_relief_length_min_mm", "root_relief_length_max_mm"},
        {"tip_relief_amount_min_um", "tip_relief_amount_max_um"},
        {"tip_relief_length_min_mm", "tip_relief_length_max_mm"},
        {"lead_relief_min_um", "lead_relief_max_um"},
        {"lead_unmodified_length_min_mm", "lead_unmodified_length_max_mm"},
    };
    return keys[i][upper];
}

static gd_status check_gear(gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    double lo[6], hi[6], active;
    /* bounds in order */
    {
        double l[6], h[6];
        l[0] = c->opt_root_amount_min_um, h[0] = c->opt_root_amount_max_um;
        l[1] = c->opt_root_length_min_mm, h[1] = c->opt_root_length_max_mm;
        l[2] = c->opt_tip_amount_min_um, h[2] = c->opt_tip_amount_max_um;
        l[3] = c->opt_tip_length_min_mm, h[3] = c->opt_tip_length_max_mm;
        l[4] = c->opt_lead_amount_min_um, h[4] = c->opt_lead_amount_max_um;
        l[5] = c->opt_lead_length_min_mm, h[5] = c->opt_lead_length_max_mm;
        for (int i = 0; i < 6; i++)
            if (!(l[i] < h[i])) {
                int up = given(c, gear_key(i, 1)) || !given(c, gear_key(i, 0));
                where(c, gear_key(i, up), w, sizeof w);
                return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.%s: the bounds of %s are [%g, %g] (valid: the "
                                    "lower bound below the upper)", w, gear_key(i, up), gd_opt_gear_variable(i, NULL, NULL),
                                    l[i], h[i]);
            }
    }
    if (!(c->torque_nm > 0)) {
        snprintf(w, sizeof w, "%s", c->path[0] ? c->path : "case");
        return gd_error_set(err, GD_ERR_INPUT, "%s: operating.torque_nm: a pinion torque of %g N m for gear-lte "
                            "(valid: > 0, the loaded contact needs a load)", w, c->torque_nm);
    }
    const char *bad = NULL;
    double xb[6];
    gd_error e2 = {0};
    int corner = opt_gear_box(c, lo, hi, &active, &bad, xb, &e2);
    if (corner == -1)
        return GD_OK;
    if (corner < 0) {
        if (err)
            *err = e2;
        return gd_error_prefix(err, "%s: [optimize]", c->path[0] ? c->path : "case");
    }
    /* the bound responsible: the failing [modification] key's variable at this corner */
    int var = 0;
    if (bad) {
        for (int i = 0; i < 6; i++)
            if (strcmp(bad, gd_opt_gear_variable(i, NULL, NULL)) == 0)
                var = i;
        if (strcmp(bad, "lead_relief_outer_um") == 0)
            var = 4;
    }
    int up = corner >> var & 1;
    where(c, gear_key(var, up), w, sizeof w);
    return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.%s: the box holds a modification that does not fit on the "
                        "pinion (y1..y5, y7 = %g um, %g mm, %g um, %g mm, %g um, %g mm; root + tip relief lengths "
                        "are repaired to fit the %.4g mm of active profile): modification.%s: %s", w,
                        gear_key(var, up), xb[0], xb[1], xb[2], xb[3], xb[4], xb[5], active, bad ? bad : "?", e2.msg);
}

GD_API gd_status gd_opt_resolve_case(gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    int compare = c->analysis == GD_ANALYSIS_COMPARE_OPTIMIZERS;
    char valid[512] = "";
    /* optimisers */
    if (compare) {
        for (int a = 0; a < GD_OPT_NALGORITHMS; a++) {
            size_t u = strlen(valid);
            snprintf(valid + u, sizeof valid - u, "%s%s", a ? ", " : "", gd_opt_algorithm_name(a));
        }
        char names[GD_OPT_NALGORITHMS + 1][48];
        int n = split(c->opt_optimizers, names, GD_OPT_NALGORITHMS + 1);
        int seen[GD_OPT_NALGORITHMS] = {0};
        where(c, "optimizers", w, sizeof w);
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
    }
    /* objectives */
    valid[0] = 0;
    for (int o = 0; o < GD_OBJ_NOBJECTIVES; o++) {
        size_t u = strlen(valid);
        snprintf(valid + u, sizeof valid - u, "%s%s", o ? ", " : "", gd_opt_objective_name(o));
    }
    char onames[GD_OBJ_NOBJECTIVES + 1][48];
    int no = split(c->opt_objective, onames, GD_OBJ_NOBJECTIVES + 1);
    int gear = 0, tests = 0, rosen = 0;
    {
        int seen[GD_OBJ_NOBJECTIVES] = {0};
        where(c, "objective", w, sizeof w);
        if (no <= 0)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective: %s (valid: %s%s)", w,
                                no < 0 ? "too many names" : "empty", compare ? "comma-separated, of " : "one of ", valid);
        if (!compare && no != 1)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective: %d objectives for optimize (valid: one of "
                                "%s; compare-optimizers takes a list)", w, no, valid);
        for (int i = 0; i < no; i++) {
            int o = gd_opt_objective_parse(onames[i]);
            if (o < 0)
                return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective: unknown objective '%s' (valid: %s)", w,
                                    onames[i], valid);
            if (seen[o]++)
                return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.objective: '%s' twice (valid: each at most once)",
                                    w, onames[i]);
            gear |= o == GD_OBJ_GEAR_LTE;
            tests |= o != GD_OBJ_GEAR_LTE;
            rosen |= o == GD_OBJ_ROSENBROCK;
        }
    }
    /* dimensions */
    if (c->n_opt_dimensions == 0) {
        c->opt_dimensions[0] = 6;
        c->n_opt_dimensions = 1;
        derived(c, "dimension");
    } else {
        where(c, "dimension", w, sizeof w);
        if (!compare && c->n_opt_dimensions != 1)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.dimension: %d values for optimize (valid: one; "
                                "compare-optimizers takes a list)", w, c->n_opt_dimensions);
        for (int i = 0; i < c->n_opt_dimensions; i++) {
            double d = c->opt_dimensions[i];
            if (d != floor(d) || (rosen && d < 2))
                return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.dimension: %g (valid: whole numbers from %d to "
                                    "1000)", w, d, rosen ? 2 : 1);
            for (int j = 0; j < i; j++)
                if (c->opt_dimensions[j] == d)
                    return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.dimension: %g twice (valid: each at most once)",
                                        w, d);
        }
        if (gear && !tests && (c->n_opt_dimensions != 1 || c->opt_dimensions[0] != 6))
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.dimension: gear-lte has 6 variables, y1..y5 and y7 "
                                "(valid: 6, or leave dimension out)", w);
    }
    if (gear && c->opt_shift != 0) {
        where(c, "shift", w, sizeof w);
        if (!tests)
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.shift: %g for gear-lte (valid: 0; the shift moves the "
                                "minimiser of a test function)", w, c->opt_shift);
    }
    /* runs, budget */
    if (c->opt_runs == 0) {
        c->opt_runs = compare ? 10 : 1;
        derived(c, "runs");
    }
    if (given(c, "budget_evals") && given(c, "iterations")) {
        where(c, "budget_evals", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.budget_evals: give iterations or budget_evals, not both "
                            "(valid: one; the budget is population (iterations + 1))", w);
    }
    if (c->opt_budget_evals == 0) {
        long b = (long)c->opt_population * ((long)c->opt_iterations + 1);
        if (b > 2000000000L) {
            where(c, "iterations", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.iterations: a budget of %ld evaluations (valid: "
                                "population (iterations + 1) at most 2e9)", w, b);
        }
        c->opt_budget_evals = (int)b;
        derived(c, "budget_evals");
    }
    int algs[GD_OPT_NALGORITHMS];
    int na = gd_opt_case_optimizers(c, algs, GD_OPT_NALGORITHMS), alo = 0;
    for (int i = 0; i < na; i++)
        alo |= algs[i] == GD_OPT_ALO;
    if (alo && c->opt_budget_evals < 2 * c->opt_population) {
        where(c, given(c, "budget_evals") ? "budget_evals" : "population", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.%s: a budget of %d evaluations for ALO with %d ants "
                            "(valid: at least two populations, %d)", w, given(c, "budget_evals") ? "budget_evals" :
                            "population", c->opt_budget_evals, c->opt_population, 2 * c->opt_population);
    }
    /* targets */
    if (!isfinite(c->opt_target)) {
        c->opt_target = gear && !tests ? 0.005 : 1e-8;
        derived(c, "target");
    }
    if (!isfinite(c->opt_target_loosest)) {
        c->opt_target_loosest = gear && !tests ? 1.0 : 100.0;
        derived(c, "target_loosest");
    }
    if (c->opt_target_loosest < c->opt_target || (c->opt_ecdf_targets > 1 && !(c->opt_target_loosest > c->opt_target))) {
        where(c, given(c, "target_loosest") ? "target_loosest" : "target", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: optimize.%s: target_loosest %g is not above target %g (valid: "
                            "target_loosest > target)", w, given(c, "target_loosest") ? "target_loosest" : "target",
                            c->opt_target_loosest, c->opt_target);
    }
    if (gear)
        return check_gear(c, err);
    return GD_OK;
}
