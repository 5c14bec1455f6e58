/* The gear problem of the paper's section 4 (Eq. 13): the peak-to-peak loaded transmission error
 * of the modified pair (LTCA, Eq. 12) over the paper's x = [y1, y2, y3, y4, y5, y7], y6 = y5, or
 * any of y1 .. y9 (asymmetric lead relief y6, y8 and the helix slope y9 besides the paper's)
 * (docs/optimisation.md section 2).
 *
 * One evaluation = one LTCA workspace for the modified flank (gd_ltca_create: the TCA workspace
 * holds the flank, and the API has no call that changes the modification of an existing
 * workspace) and the settings' positions over one mesh cycle, exactly as gd_ltca_run solves them
 * (same positions, same order, same warm starts: the same amplitude to the last bit). Each
 * concurrent caller has its own copy of the pair (state), so evaluations run in parallel. */
#include "opt_internal.h"
#include "geardyn/gd_flank.h"
#include "geardyn/gd_geometry.h"
#include "geardyn/gd_ltca.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ARCSEC (180.0 * 3600.0 / M_PI)

#define NCONS 3 /* at most: y2 + y4 <= the active profile; the unmodified lead band on the face (two rows) */

/* The problem: the pair it modifies (the case's, with the case's own modification in the variables
 * not optimised), the variables, the box and its constraints, the objectives and the robust sample. */
struct gd_opt_gear {
    gd_pair pair;
    gd_opt_gear_vars vars;
    gd_ltca_settings set;
    double lower[GD_OPT_GEAR_NVARS], upper[GD_OPT_GEAR_NVARS];
    double A[NCONS * GD_OPT_GEAR_NVARS], b[NCONS];
    int ncons;
    double active_mm;
    double anchor[GD_OPT_GEAR_NVARS];  /* of the repair (the box's centre or lower corner) */
    gd_opt_lte_range lte;              /* the objective without gd_opt_gear_set_objectives: LTE at set's torque */
    int nobj, naux;
    gd_opt_gear_objective obj[2];
    gd_opt_robust rb;
    double *dev;                       /* rb.samples x (3 + vars.n) */
};

/* What one evaluation needs besides the problem: its own copy of the pair and each objective's
 * state. */
typedef struct gear_state {
    const gd_opt_gear *g;
    gd_pair pair;
    void *os[2];
    double *vals;                      /* robust: the values of the sample */
    double *keep;                      /* robust, when not NULL: nobj x samples, each objective's values in the
                                          sample's order (opt_gear_value_of_pair_samples) */
    double aux[GD_OPT_MAX_AUX];
} gear_state;

static const char *const var_key[GD_OPT_GEAR_NVARS] = {
    "root_relief_amount_um", "root_relief_length_mm", "tip_relief_amount_um", "tip_relief_length_mm",
    "lead_relief_inner_um", "lead_relief_outer_um", "lead_unmodified_length_mm", "lead_unmodified_centre_mm",
    "helix_slope_um"};
static const char *const var_unit[GD_OPT_GEAR_NVARS] = {"um", "mm", "um", "mm", "um", "um", "mm", "mm", "um"};
static const char *const var_symbol[GD_OPT_GEAR_NVARS] = {"y1", "y2", "y3", "y4", "y5", "y6", "y7", "y8", "y9"};

GD_API const char *gd_opt_gear_variable(int id, const char **unit, const char **symbol)
{
    if (id < 0 || id >= GD_OPT_GEAR_NVARS)
        return NULL;
    if (unit)
        *unit = var_unit[id];
    if (symbol)
        *symbol = var_symbol[id];
    return var_key[id];
}

GD_API void gd_opt_gear_vars_paper(gd_opt_gear_vars *v)
{
    static const int paper[GD_OPT_GEAR_DIM] = {0, 1, 2, 3, 4, 6};
    memset(v, 0, sizeof *v);
    v->n = GD_OPT_GEAR_DIM;
    memcpy(v->var, paper, sizeof paper);
}

GD_API gd_status gd_opt_gear_vars_parse(const char *list, gd_opt_gear_vars *v, gd_error *err)
{
    memset(v, 0, sizeof *v);
    int seen[GD_OPT_GEAR_NVARS] = {0};
    const char *p = list;
    while (*p) {
        while (*p == ' ' || *p == '\t')
            p++;
        const char *e = p;
        while (*e && *e != ',')
            e++;
        size_t len = (size_t)(e - p);
        while (len && (p[len - 1] == ' ' || p[len - 1] == '\t'))
            len--;
        int id = -1;
        for (int k = 0; k < GD_OPT_GEAR_NVARS; k++)
            if (strlen(var_symbol[k]) == len && strncmp(p, var_symbol[k], len) == 0)
                id = k;
        if (id < 0)
            return gd_error_set(err, GD_ERR_INPUT, "unknown variable '%.*s' (valid: y1 .. y9, comma-separated, "
                                "each at most once)", (int)(len < 40 ? len : 40), p);
        if (seen[id]++)
            return gd_error_set(err, GD_ERR_INPUT, "'%s' twice (valid: each variable at most once)", var_symbol[id]);
        v->var[v->n++] = id;
        if (!*e)
            break;
        p = e + 1;
    }
    if (v->n == 0)
        return gd_error_set(err, GD_ERR_INPUT, "no variable (valid: y1 .. y9, comma-separated)");
    return GD_OK;
}

/* The [modification] field of variable id (0..8: y1..y9). */
static double *var_field(gd_pair *p, int id)
{
    double *f[GD_OPT_GEAR_NVARS] = {&p->root_relief_amount_um, &p->root_relief_length_mm, &p->tip_relief_amount_um,
                                    &p->tip_relief_length_mm, &p->lead_relief_inner_um, &p->lead_relief_outer_um,
                                    &p->lead_unmodified_length_mm, &p->lead_unmodified_centre_mm, &p->helix_slope_um};
    return f[id];
}

static int vars_index(const gd_opt_gear_vars *v, int id)
{
    for (int k = 0; k < v->n; k++)
        if (v->var[k] == id)
            return k;
    return -1;
}

GD_API void gd_opt_gear_apply(const gd_opt_gear_vars *v, gd_pair *pair, const double *x)
{
    for (int k = 0; k < v->n; k++)
        *var_field(pair, v->var[k]) = x[k];
    int k5 = vars_index(v, 4);
    if (k5 >= 0 && vars_index(v, 5) < 0) /* the paper's symmetric lead relief: y6 = y5 */
        pair->lead_relief_outer_um = x[k5];
}

GD_API void gd_opt_gear_from_pair(const gd_opt_gear_vars *v, const gd_pair *pair, double *x)
{
    gd_pair p = *pair;
    for (int k = 0; k < v->n; k++)
        x[k] = *var_field(&p, v->var[k]);
}

GD_API void gd_opt_gear_table2(gd_pair *pair)
{
    pair->root_relief_amount_um = 25;
    pair->root_relief_length_mm = 1.5;
    pair->tip_relief_amount_um = 35;
    pair->tip_relief_length_mm = 2.5;
    pair->lead_relief_inner_um = 25;
    pair->lead_relief_outer_um = 25;
    pair->lead_unmodified_length_mm = 35;
    pair->lead_unmodified_centre_mm = 0;
    pair->helix_slope_um = 0;
}

GD_API int gd_opt_gear_is_paper_pair(const gd_pair *p)
{
    return p->arrangement == GD_ARR_HERRINGBONE && p->normal_module_mm == 5 && p->teeth_pinion == 30 &&
           p->teeth_gear == 72 && p->helix_angle_deg == 33.27 && p->normal_pressure_angle_deg == 20 &&
           p->profile_shift_pinion == 0 && p->profile_shift_gear == 0 && p->addendum_coefficient == 1 &&
           p->dedendum_coefficient == 1.25 && p->face_width_pinion_mm == 40 && p->face_width_gear_mm == 44;
}

GD_API gd_status gd_opt_gear_lte_pp(const gd_pair *pair, const gd_ltca_settings *set, double *lte_pp, gd_error *err)
{
    *lte_pp = NAN;
    int npos = set->positions_per_cycle;
    if (npos < 2)
        return gd_error_set(err, GD_ERR_INPUT, "gear-lte: %d LTCA positions per cycle (valid: >= 2)", npos);
    if (!(set->torque_nm > 0))
        return gd_error_set(err, GD_ERR_INPUT, "gear-lte: a pinion torque of %g N m (valid: > 0)", set->torque_nm);
    gd_ltca *w;
    gd_status st = gd_ltca_create(pair, set, &w, err);
    if (st != GD_OK)
        return st;
    const double tau = 2 * M_PI / (double)pair->teeth_pinion; /* as TCA's tau1 */
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < npos && st == GD_OK; k++) {
        double phi1 = tau * k / npos;
        gd_ltca_position pos;
        st = gd_stop_asked(&set->stop) ? gd_error_set(err, GD_ERR_INTERRUPTED, "gear-lte: stopped")
                                       : gd_ltca_solve_at(w, phi1, set->torque_nm, &pos, err);
        if (st == GD_OK) {
            double v = pos.lte * ARCSEC;
            lo = fmin(lo, v);
            hi = fmax(hi, v);
        }
    }
    gd_ltca_free(w);
    if (st == GD_OK)
        *lte_pp = hi - lo;
    return st;
}

/* ---- the problem ---------------------------------------------------------------------------- */

static void state_free(void *state)
{
    gear_state *s = state;
    if (!s)
        return;
    for (int k = 0; k < s->g->nobj; k++)
        if (s->g->obj[k].state_alloc && s->g->obj[k].state_free)
            s->g->obj[k].state_free(s->os[k]);
    free(s->vals);
    free(s);
}

static gd_status state_alloc(void *user, void **state, gd_error *err)
{
    const gd_opt_gear *g = user;
    gear_state *s = calloc(1, sizeof *s);
    if (!s)
        return gd_error_set(err, GD_ERR_NOMEM, "gear problem: out of memory");
    s->g = g;
    s->pair = g->pair;
    gd_status st = GD_OK;
    if (g->rb.samples > 0 && !(s->vals = malloc(sizeof(double) * (size_t)g->rb.samples)))
        st = gd_error_set(err, GD_ERR_NOMEM, "gear problem: out of memory");
    for (int k = 0; k < g->nobj && st == GD_OK; k++) {
        if (g->obj[k].state_alloc)
            st = g->obj[k].state_alloc(g->obj[k].user, &s->os[k], err);
        else
            s->os[k] = g->obj[k].user;
    }
    if (st != GD_OK) {
        state_free(s);
        return st;
    }
    *state = s;
    return GD_OK;
}

/* "y1..y5, y7 = 25 um, 1.5 mm, ..." of the point y, for messages */
static void point_text(const gd_opt_gear_vars *v, const double *y, char *buf, size_t len)
{
    size_t n = 0;
    for (int k = 0; k < v->n && n < len; k++)
        n += (size_t)snprintf(buf + n, len - n, "%s%s", k ? ", " : "", var_symbol[v->var[k]]);
    for (int k = 0; k < v->n && n < len; k++)
        n += (size_t)snprintf(buf + n, len - n, "%s%g %s", k ? ", " : " = ", y[k], var_unit[v->var[k]]);
}

/* The box and constraints of g as a problem (for the repair of a deviated point). */
static void box_problem(const gd_opt_gear *g, gd_opt_problem *p)
{
    memset(p, 0, sizeof *p);
    p->dim = g->vars.n;
    p->lower = g->lower;
    p->upper = g->upper;
    p->ncons = g->ncons;
    p->A = g->A;
    p->b = g->b;
}

/* The pair of sample j of the robust variant at the point y: the deviated variables, kept in the
 * box and repaired, and the deviated misalignment. */
static void sample_pair(const gd_opt_gear *g, const gd_pair *base, int j, const double *y, gd_pair *pair)
{
    const int nv = g->vars.n;
    const double *d = g->dev + (size_t)j * (size_t)(3 + nv);
    double yd[GD_OPT_GEAR_NVARS];
    for (int k = 0; k < nv; k++) {
        double v = y[k] + d[3 + k];
        yd[k] = v < g->lower[k] ? g->lower[k] : v > g->upper[k] ? g->upper[k] : v;
    }
    gd_opt_problem box;
    box_problem(g, &box);
    gd_opt_repair(&box, g->anchor, yd, yd);
    *pair = *base;
    gd_opt_gear_apply(&g->vars, pair, yd);
    pair->axis_in_plane_arcmin += d[0];
    pair->axis_cross_plane_arcmin += d[1];
    pair->centre_distance_error_mm += d[2];
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The quantile q of n values (sorted in place): linear between the order statistics, as GSL's
 * gsl_stats_quantile_from_sorted_data. */
static double quantile(double *v, int n, double q)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    double pos = q * (n - 1);
    int i = (int)floor(pos);
    double delta = pos - i;
    return i + 1 < n ? (1 - delta) * v[i] + delta * v[i + 1] : v[n - 1];
}

/* The objectives at y (the variables applied to the pair base) into f, the recorded numbers into aux. */
static gd_status gear_values_on(gear_state *s, const gd_pair *base, const double *y, double *f, double *aux,
                                gd_error *err)
{
    const gd_opt_gear *g = s->g;
    int na = 0;
    gd_status st = GD_OK;
    for (int k = 0; k < g->nobj && st == GD_OK; k++) {
        const gd_opt_gear_objective *o = &g->obj[k];
        s->pair = *base;
        gd_opt_gear_apply(&g->vars, &s->pair, y);
        if (g->rb.samples == 0) {
            st = o->eval(s->os[k], &s->pair, &f[k], aux + na, err);
            na += o->naux;
            continue;
        }
        double nominal;
        st = o->eval(s->os[k], &s->pair, &nominal, aux + na + 1, err);
        aux[na] = nominal;
        for (int j = 0; j < g->rb.samples && st == GD_OK; j++) {
            sample_pair(g, base, j, y, &s->pair);
            st = o->eval(s->os[k], &s->pair, &s->vals[j], s->aux, err);
            if (st != GD_OK)
                gd_error_prefix(err, "robust sample %d", j + 1);
        }
        if (st == GD_OK && s->keep)
            memcpy(s->keep + (size_t)k * (size_t)g->rb.samples, s->vals, sizeof(double) * (size_t)g->rb.samples);
        if (st == GD_OK)
            f[k] = quantile(s->vals, g->rb.samples, g->rb.quantile);
        na += 1 + o->naux;
    }
    if (st != GD_OK) {
        char at[512];
        point_text(&g->vars, y, at, sizeof at);
        return gd_error_prefix(err, "%s at %s", g->obj[0].name, at);
    }
    return GD_OK;
}

static gd_status gear_values(gear_state *s, const double *y, double *f, double *aux, gd_error *err)
{
    return gear_values_on(s, &s->g->pair, y, f, aux, err);
}

static gd_status gear_evalv(void *state, const double *y, double *f, gd_error *err)
{
    gear_state *s = state;
    return gear_values(s, y, f, f + s->g->nobj, err);
}

static gd_status gear_eval(void *state, const double *y, double *f, gd_error *err)
{
    gear_state *s = state;
    return gear_values(s, y, f, s->aux, err);
}

GD_API gd_status gd_opt_gear_value(const gd_opt_gear *g, const double *x, double *f, double *aux, gd_error *err)
{
    void *state;
    gd_status st = state_alloc((void *)g, &state, err);
    if (st != GD_OK)
        return st;
    gear_state *s = state;
    st = gear_values(s, x, f, aux ? aux : s->aux, err);
    state_free(state);
    return st;
}

GD_API gd_status gd_opt_gear_value_of_pair(const gd_opt_gear *g, const gd_pair *pair, double *f, double *aux,
                                           gd_error *err)
{
    void *state;
    gd_status st = state_alloc((void *)g, &state, err);
    if (st != GD_OK)
        return st;
    gear_state *s = state;
    double y[GD_OPT_GEAR_NVARS];
    gd_opt_gear_from_pair(&g->vars, pair, y);
    st = gear_values_on(s, pair, y, f, aux ? aux : s->aux, err);
    state_free(state);
    return st;
}

gd_status opt_gear_value_of_pair_samples(const gd_opt_gear *g, const gd_pair *pair, double *f, double *aux,
                                         double *samples, gd_error *err)
{
    void *state;
    gd_status st = state_alloc((void *)g, &state, err);
    if (st != GD_OK)
        return st;
    gear_state *s = state;
    s->keep = g->rb.samples > 0 ? samples : NULL;
    double y[GD_OPT_GEAR_NVARS];
    gd_opt_gear_from_pair(&g->vars, pair, y);
    st = gear_values_on(s, pair, y, f, aux ? aux : s->aux, err);
    state_free(state);
    return st;
}

GD_API int gd_opt_gear_nobj(const gd_opt_gear *g) { return g->nobj; }

GD_API int gd_opt_gear_naux(const gd_opt_gear *g) { return g->naux; }

GD_API const gd_pair *gd_opt_gear_pair(const gd_opt_gear *g) { return &g->pair; }

GD_API int gd_opt_gear_robust_sample(const gd_opt_gear *g, const double **dev)
{
    if (dev)
        *dev = g->dev;
    return g->rb.samples;
}

GD_API gd_status gd_opt_gear_set_objectives(gd_opt_gear *g, int nobj, const gd_opt_gear_objective *obj,
                                            const gd_opt_robust *rb, gd_error *err)
{
    if (nobj < 1 || nobj > 2)
        return gd_error_set(err, GD_ERR_INPUT, "gear problem: %d objectives (valid: 1 or 2)", nobj);
    int naux = 0, robust = rb && rb->samples > 0;
    for (int k = 0; k < nobj; k++) {
        if (!obj[k].eval || obj[k].naux < 0)
            return gd_error_set(err, GD_ERR_INPUT, "gear problem: objective %d has no evaluation", k + 1);
        naux += obj[k].naux + robust;
    }
    if (naux > GD_OPT_MAX_AUX)
        return gd_error_set(err, GD_ERR_INPUT, "gear problem: %d recorded numbers (valid: at most %d)", naux,
                            GD_OPT_MAX_AUX);
    if (rb && rb->samples < 0)
        return gd_error_set(err, GD_ERR_INPUT, "gear problem: a Monte Carlo sample of %d (valid: >= 1, or 0: not "
                            "robust)", rb->samples);
    if (robust && !(rb->quantile >= 0 && rb->quantile <= 1))
        return gd_error_set(err, GD_ERR_INPUT, "gear problem: the quantile %g (valid: 0 < q <= 1)", rb->quantile);
    double *dev = NULL;
    const int nv = g->vars.n;
    if (robust) {
        dev = malloc(sizeof(double) * (size_t)rb->samples * (size_t)(3 + nv));
        gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
        if (!dev || !rng) {
            free(dev);
            gsl_rng_free(rng);
            return gd_error_set(err, GD_ERR_NOMEM, "gear problem: out of memory for the Monte Carlo sample");
        }
        gsl_rng_set(rng, rb->seed);
        for (int j = 0; j < rb->samples; j++) {
            double *d = dev + (size_t)j * (size_t)(3 + nv);
            d[0] = rb->tilt_arcmin * (2.0 * gsl_rng_uniform(rng) - 1.0);
            d[1] = rb->tilt_arcmin * (2.0 * gsl_rng_uniform(rng) - 1.0);
            d[2] = rb->centre_distance_mm * (2.0 * gsl_rng_uniform(rng) - 1.0);
            for (int k = 0; k < nv; k++) {
                int length = strcmp(var_unit[g->vars.var[k]], "mm") == 0;
                d[3 + k] = (length ? rb->length_mm : rb->amount_um) * (2.0 * gsl_rng_uniform(rng) - 1.0);
            }
        }
        gsl_rng_free(rng);
    }
    free(g->dev);
    g->dev = dev;
    memset(&g->rb, 0, sizeof g->rb);
    if (robust) {
        g->rb = *rb;
        if (g->rb.quantile == 0)
            g->rb.quantile = 0.9;
    }
    g->nobj = nobj;
    g->naux = naux;
    memcpy(g->obj, obj, sizeof *obj * (size_t)nobj);
    return GD_OK;
}

GD_API void gd_opt_gear_problem(gd_opt_gear *g, gd_opt_problem *p)
{
    box_problem(g, p);
    if (g->nobj == 1 && g->naux == 0) {
        p->eval = gear_eval;
    } else {
        p->evalv = gear_evalv;
        p->nobj = g->nobj;
        p->naux = g->naux;
    }
    p->state_alloc = state_alloc;
    p->state_free = state_free;
    p->user = g;
}

GD_API double gd_opt_gear_active_profile_mm(const gd_opt_gear *g) { return g->active_mm; }

GD_API const gd_opt_gear_vars *gd_opt_gear_vars_of(const gd_opt_gear *g) { return &g->vars; }

GD_API void gd_opt_gear_free(gd_opt_gear *g)
{
    if (!g)
        return;
    free(g->dev);
    free(g);
}

GD_API void gd_opt_gear_bounds(const gd_case *c, const gd_opt_gear_vars *v, double *lo, double *hi)
{
    const double L[GD_OPT_GEAR_NVARS] = {c->opt_root_amount_min_um, c->opt_root_length_min_mm,
                                         c->opt_tip_amount_min_um, c->opt_tip_length_min_mm,
                                         c->opt_lead_amount_min_um, c->opt_lead_amount_min_um,
                                         c->opt_lead_length_min_mm, c->opt_lead_centre_min_mm,
                                         c->opt_helix_slope_min_um};
    const double H[GD_OPT_GEAR_NVARS] = {c->opt_root_amount_max_um, c->opt_root_length_max_mm,
                                         c->opt_tip_amount_max_um, c->opt_tip_length_max_mm,
                                         c->opt_lead_amount_max_um, c->opt_lead_amount_max_um,
                                         c->opt_lead_length_max_mm, c->opt_lead_centre_max_mm,
                                         c->opt_helix_slope_max_um};
    for (int k = 0; k < v->n; k++) {
        lo[k] = L[v->var[k]];
        hi[k] = H[v->var[k]];
    }
}

/* The linear constraints A y <= b of the variables v, the modification not optimised taken from
 * the pair (moved to the right side): y2 + y4 <= the active profile (when y2 or y4 is a variable);
 * y7/2 + y8 <= b/2 and y7/2 - y8 <= b/2, the unmodified lead band on the face (when y8 is a
 * variable or the pair's y8 is not 0, and y7 or y8 is a variable). Returns the rows. */
static int gear_constraints(const gd_opt_gear_vars *v, const gd_pair *pair, double active_mm, double face_mm,
                            double *A, double *b)
{
    double coef[NCONS][GD_OPT_GEAR_NVARS] = {{0}}, rhs[NCONS] = {active_mm, 0.5 * face_mm, 0.5 * face_mm};
    coef[0][1] = coef[0][3] = 1.0;
    coef[1][6] = 0.5;
    coef[1][7] = 1.0;
    coef[2][6] = 0.5;
    coef[2][7] = -1.0;
    int band = vars_index(v, 7) >= 0 || pair->lead_unmodified_centre_mm != 0.0;
    gd_pair p = *pair;
    int n = 0;
    for (int r = 0; r < NCONS; r++) {
        if (r > 0 && !band)
            break;
        int any = 0;
        double rr = rhs[r];
        for (int id = 0; id < GD_OPT_GEAR_NVARS; id++) {
            if (coef[r][id] == 0.0)
                continue;
            if (vars_index(v, id) >= 0)
                any = 1;
            else
                rr -= coef[r][id] * *var_field(&p, id);
        }
        if (!any)
            continue;
        for (int k = 0; k < v->n; k++)
            A[n * v->n + k] = coef[r][v->var[k]];
        b[n++] = rr;
    }
    return n;
}

int opt_gear_box(const gd_pair *pair, const gd_opt_gear_vars *v, const double *lower, const double *upper,
                 double *active_mm, const char **bad_key, double *xbad, gd_error *err)
{
    gd_geometry g;
    if (gd_geometry_compute(pair, &g, err) != GD_OK)
        return -2;
    *active_mm = (g.rho_a[0] - g.rho_sap[0]) * 1e3;
    double A[NCONS * GD_OPT_GEAR_NVARS], b[NCONS];
    gd_opt_problem p = {0};
    p.dim = v->n;
    p.lower = lower;
    p.upper = upper;
    p.ncons = gear_constraints(v, pair, *active_mm, g.b[0] * 1e3, A, b);
    p.A = A;
    p.b = b;
    p.eval = gear_eval; /* only checked for presence */
    double anchor[GD_OPT_GEAR_NVARS];
    if (gd_opt_problem_check(&p, anchor, err) != GD_OK)
        return -3;
    gd_pair t = *pair;
    for (int corner = 0; corner < 1 << v->n; corner++) {
        double y[GD_OPT_GEAR_NVARS];
        for (int i = 0; i < v->n; i++)
            y[i] = corner >> i & 1 ? upper[i] : lower[i];
        gd_opt_repair(&p, anchor, y, y);
        gd_opt_gear_apply(v, &t, y);
        if (gd_modification_check(&t, &g, bad_key, err) != GD_OK) {
            memcpy(xbad, y, sizeof(double) * (size_t)v->n);
            return corner;
        }
    }
    return -1;
}

GD_API gd_status gd_opt_gear_create(const gd_pair *pair, const gd_ltca_settings *set, const gd_opt_gear_vars *v,
                                    const double *lower, const double *upper, gd_opt_gear **out, gd_error *err)
{
    *out = NULL;
    if (v->n < 1 || v->n > GD_OPT_GEAR_NVARS)
        return gd_error_set(err, GD_ERR_INPUT, "gear-lte: %d variables (valid: 1 to %d)", v->n, GD_OPT_GEAR_NVARS);
    gd_opt_gear *g = calloc(1, sizeof *g);
    if (!g)
        return gd_error_set(err, GD_ERR_NOMEM, "gear-lte: out of memory");
    g->pair = *pair;
    g->vars = *v;
    g->set = *set;
    memcpy(g->lower, lower, sizeof(double) * (size_t)v->n);
    memcpy(g->upper, upper, sizeof(double) * (size_t)v->n);
    const char *bad = NULL;
    double xb[GD_OPT_GEAR_NVARS];
    int corner = opt_gear_box(pair, v, g->lower, g->upper, &g->active_mm, &bad, xb, err);
    if (corner != -1) {
        free(g);
        if (corner >= 0) {
            char at[512];
            point_text(v, xb, at, sizeof at);
            return gd_error_prefix(err, "gear-lte: the box of [optimize] holds a modification that does not fit "
                                   "(%s): modification.%s", at, bad ? bad : "?");
        }
        return gd_error_prefix(err, "gear-lte");
    }
    gd_geometry geo;
    if (gd_geometry_compute(pair, &geo, err) != GD_OK) {
        free(g);
        return gd_error_prefix(err, "gear-lte");
    }
    g->ncons = gear_constraints(v, pair, g->active_mm, geo.b[0] * 1e3, g->A, g->b);
    gd_opt_problem box;
    box_problem(g, &box);
    box.eval = gear_eval; /* only checked for presence */
    gd_status st = gd_opt_problem_check(&box, g->anchor, err);
    if (st != GD_OK) {
        free(g);
        return gd_error_prefix(err, "gear-lte");
    }
    /* the objective until gd_opt_gear_set_objectives: the LTE amplitude at the settings' torque */
    g->lte.set = *set;
    g->lte.n = 1;
    g->lte.torques_nm[0] = set->torque_nm;
    g->lte.weights[0] = 1.0;
    g->lte.combine = GD_OPT_COMBINE_MAX;
    gd_opt_lte_range_objective(&g->lte, &g->obj[0]);
    g->obj[0].naux = 0;
    snprintf(g->obj[0].name, sizeof g->obj[0].name, "gear-lte");
    g->nobj = 1;
    *out = g;
    return GD_OK;
}

/* ---- gear-lte-range ------------------------------------------------------------------------- */

GD_API double gd_opt_combine_values(int combine, int n, const double *v, const double *w)
{
    if (combine == GD_OPT_COMBINE_MAX) {
        double m = -INFINITY;
        for (int k = 0; k < n; k++)
            m = fmax(m, v[k]);
        return m;
    }
    double sw = 0, s = 0;
    for (int k = 0; k < n; k++) {
        s += w[k] * v[k];
        sw += w[k];
    }
    return s / sw;
}

GD_API gd_status gd_opt_lte_range_value(const gd_opt_lte_range *r, const gd_pair *pair, double *f, double *each,
                                        gd_error *err)
{
    double v[GD_OPT_MAX_TORQUES];
    if (r->n < 1 || r->n > GD_OPT_MAX_TORQUES)
        return gd_error_set(err, GD_ERR_INPUT, "gear-lte-range: %d torques (valid: 1 to %d)", r->n, GD_OPT_MAX_TORQUES);
    for (int k = 0; k < r->n; k++) {
        gd_ltca_settings set = r->set;
        set.torque_nm = r->torques_nm[k];
        gd_status st = gd_opt_gear_lte_pp(pair, &set, &v[k], err);
        if (st != GD_OK)
            return r->n > 1 ? gd_error_prefix(err, "at %g N m", r->torques_nm[k]) : st;
        if (each)
            each[k] = v[k];
    }
    *f = gd_opt_combine_values(r->combine, r->n, v, r->weights);
    return GD_OK;
}

static gd_status lte_range_eval(void *state, const gd_pair *pair, double *f, double *aux, gd_error *err)
{
    const gd_opt_lte_range *r = state;
    return gd_opt_lte_range_value(r, pair, f, aux, err);
}

GD_API void gd_opt_lte_range_objective(const gd_opt_lte_range *r, gd_opt_gear_objective *o)
{
    memset(o, 0, sizeof *o);
    snprintf(o->name, sizeof o->name, "%s", r->n > 1 ? "gear-lte-range" : "gear-lte");
    o->naux = r->n;
    o->eval = lte_range_eval;
    o->user = (void *)r;
}
