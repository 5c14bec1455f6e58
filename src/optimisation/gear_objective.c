/* The gear problem of the paper's section 4 (Eq. 13): the peak-to-peak loaded transmission error
 * of the modified pair (LTCA, Eq. 12) over x = [y1, y2, y3, y4, y5, y7], y6 = y5
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

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define ARCSEC (180.0 * 3600.0 / M_PI)

/* What one evaluation needs: the pair it modifies and the LTCA settings. */
typedef struct gear_state {
    gd_pair pair;
    gd_ltca_settings set;
} gear_state;

struct gd_opt_gear {
    gear_state s;
    double lower[GD_OPT_GEAR_DIM], upper[GD_OPT_GEAR_DIM];
    double A[GD_OPT_GEAR_DIM], b;
    double active_mm;
};

static const char *const var_key[GD_OPT_GEAR_DIM] = {"root_relief_amount_um", "root_relief_length_mm",
                                                    "tip_relief_amount_um", "tip_relief_length_mm",
                                                    "lead_relief_inner_um", "lead_unmodified_length_mm"};
static const char *const var_unit[GD_OPT_GEAR_DIM] = {"um", "mm", "um", "mm", "um", "mm"};
static const char *const var_symbol[GD_OPT_GEAR_DIM] = {"y1", "y2", "y3", "y4", "y5", "y7"};

GD_API const char *gd_opt_gear_variable(int i, const char **unit, const char **symbol)
{
    if (i < 0 || i >= GD_OPT_GEAR_DIM)
        return NULL;
    if (unit)
        *unit = var_unit[i];
    if (symbol)
        *symbol = var_symbol[i];
    return var_key[i];
}

GD_API void gd_opt_gear_apply(gd_pair *pair, const double *x)
{
    pair->root_relief_amount_um = x[0];
    pair->root_relief_length_mm = x[1];
    pair->tip_relief_amount_um = x[2];
    pair->tip_relief_length_mm = x[3];
    pair->lead_relief_inner_um = x[4];
    pair->lead_relief_outer_um = x[4];
    pair->lead_unmodified_length_mm = x[5];
}

GD_API void gd_opt_gear_from_pair(const gd_pair *pair, double *x)
{
    x[0] = pair->root_relief_amount_um;
    x[1] = pair->root_relief_length_mm;
    x[2] = pair->tip_relief_amount_um;
    x[3] = pair->tip_relief_length_mm;
    x[4] = pair->lead_relief_inner_um;
    x[5] = pair->lead_unmodified_length_mm;
}

GD_API void gd_opt_gear_table2(double *x)
{
    static const double t2[GD_OPT_GEAR_DIM] = {25, 1.5, 35, 2.5, 25, 35};
    memcpy(x, t2, sizeof t2);
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

static gd_status state_alloc(void *user, void **state, gd_error *err)
{
    gear_state *s = malloc(sizeof *s);
    if (!s)
        return gd_error_set(err, GD_ERR_NOMEM, "gear-lte: out of memory");
    *s = ((const gd_opt_gear *)user)->s;
    *state = s;
    return GD_OK;
}

static void state_free(void *state) { free(state); }

static gd_status gear_eval(void *state, const double *y, double *f, gd_error *err)
{
    gear_state *s = state;
    gd_opt_gear_apply(&s->pair, y);
    gd_status st = gd_opt_gear_lte_pp(&s->pair, &s->set, f, err);
    if (st != GD_OK)
        return gd_error_prefix(err, "gear-lte at y1..y5, y7 = %g um, %g mm, %g um, %g mm, %g um, %g mm", y[0], y[1],
                               y[2], y[3], y[4], y[5]);
    return GD_OK;
}

GD_API void gd_opt_gear_problem(gd_opt_gear *g, gd_opt_problem *p)
{
    memset(p, 0, sizeof *p);
    p->dim = GD_OPT_GEAR_DIM;
    p->lower = g->lower;
    p->upper = g->upper;
    p->ncons = 1;
    p->A = g->A;
    p->b = &g->b;
    p->eval = gear_eval;
    p->state_alloc = state_alloc;
    p->state_free = state_free;
    p->user = g;
}

GD_API double gd_opt_gear_active_profile_mm(const gd_opt_gear *g) { return g->active_mm; }

GD_API void gd_opt_gear_free(gd_opt_gear *g) { free(g); }

GD_API void gd_opt_gear_bounds(const gd_case *c, double lo[6], double hi[6])
{
    lo[0] = c->opt_root_amount_min_um;
    hi[0] = c->opt_root_amount_max_um;
    lo[1] = c->opt_root_length_min_mm;
    hi[1] = c->opt_root_length_max_mm;
    lo[2] = c->opt_tip_amount_min_um;
    hi[2] = c->opt_tip_amount_max_um;
    lo[3] = c->opt_tip_length_min_mm;
    hi[3] = c->opt_tip_length_max_mm;
    lo[4] = c->opt_lead_amount_min_um;
    hi[4] = c->opt_lead_amount_max_um;
    lo[5] = c->opt_lead_length_min_mm;
    hi[5] = c->opt_lead_length_max_mm;
}

int opt_gear_box(const gd_pair *pair, const double lower[6], const double upper[6], double *active_mm,
                 const char **bad_key, double *xbad, gd_error *err)
{
    gd_geometry g;
    if (gd_geometry_compute(pair, &g, err) != GD_OK)
        return -2;
    *active_mm = (g.rho_a[0] - g.rho_sap[0]) * 1e3;
    double A[GD_OPT_GEAR_DIM] = {0, 1, 0, 1, 0, 0}, b = *active_mm;
    gd_opt_problem p = {0};
    p.dim = GD_OPT_GEAR_DIM;
    p.lower = lower;
    p.upper = upper;
    p.ncons = 1;
    p.A = A;
    p.b = &b;
    p.eval = gear_eval;
    double anchor[GD_OPT_GEAR_DIM];
    if (gd_opt_problem_check(&p, anchor, err) != GD_OK)
        return -3;
    gd_pair t = *pair;
    for (int corner = 0; corner < 1 << GD_OPT_GEAR_DIM; corner++) {
        double y[GD_OPT_GEAR_DIM];
        for (int i = 0; i < GD_OPT_GEAR_DIM; i++)
            y[i] = corner >> i & 1 ? upper[i] : lower[i];
        gd_opt_repair(&p, anchor, y, y);
        gd_opt_gear_apply(&t, y);
        if (gd_modification_check(&t, &g, bad_key, err) != GD_OK) {
            memcpy(xbad, y, sizeof y);
            return corner;
        }
    }
    return -1;
}

GD_API gd_status gd_opt_gear_create(const gd_pair *pair, const gd_ltca_settings *set, const double lower[6],
                                    const double upper[6], gd_opt_gear **out, gd_error *err)
{
    *out = NULL;
    gd_opt_gear *g = calloc(1, sizeof *g);
    if (!g)
        return gd_error_set(err, GD_ERR_NOMEM, "gear-lte: out of memory");
    g->s.pair = *pair;
    g->s.set = *set;
    memcpy(g->lower, lower, sizeof g->lower);
    memcpy(g->upper, upper, sizeof g->upper);
    const char *bad = NULL;
    double xb[GD_OPT_GEAR_DIM];
    int corner = opt_gear_box(pair, g->lower, g->upper, &g->active_mm, &bad, xb, err);
    if (corner != -1) {
        free(g);
        if (corner >= 0)
            return gd_error_prefix(err, "gear-lte: the box of [optimize] holds a modification that does not fit "
                                   "(y1..y5, y7 = %g, %g, %g, %g, %g, %g): modification.%s", xb[0], xb[1], xb[2], xb[3],
                                   xb[4], xb[5], bad ? bad : "?");
        return gd_error_prefix(err, "gear-lte");
    }
    g->A[1] = g->A[3] = 1.0;
    g->b = g->active_mm;
    *out = g;
    return GD_OK;
}
