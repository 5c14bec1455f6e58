/* The `continuation` analysis (include/geardyn/gd_continuation.h): the [continuation] keys
 * checked, the starting orbit (the attractor after the transient, its period found from the
 * Poincare section, a given state, or a finished sweep's point handed in by the caller), its
 * branches in one or both directions, the branches of twice the period at the period doublings
 * of every branch (the cascade, up to GD_PO_MAX_PERIODS), each followed both ways, and one
 * period of every orbit integrated with samples for what the tables and the picture show. */
#include "geardyn/gd_continuation.h"
#include "geardyn/gd_response.h"
#include "geardyn/gd_sweep.h"
#include "geardyn/gd_scene.h"
#include "../case/case_keys.h"
#include "../core/clock.h"
#include "analysis_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define WHERE(key) (gd_case_key_where(c, "continuation", key, w, sizeof w), w)

/* The numbers of continuation.state: *n of them into y (at most GD_MAX_STATE); 0 when one is
 * not a finite number. */
static int parse_state(const char *s, double *y, int *n)
{
    *n = 0;
    const char *p = s;
    while (*p) {
        char *end;
        double v = strtod(p, &end);
        if (end == p || !isfinite(v) || *n == GD_MAX_STATE)
            return 0;
        y[(*n)++] = v;
        p = end + strspn(end, " \t");
        if (*p == ',')
            p++;
        else if (*p)
            return 0;
    }
    return *n > 0;
}

/* The parameter: a real-valued key of another section, bounds in its range, from < to. */
static gd_status check_parameter(gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32], range[160];
    const char *name = c->cont_parameter;
    if (!name[0])
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.parameter: missing (valid: a real-valued numeric "
                            "key as section.key, e.g. operating.speed_rpm)", WHERE("parameter"));
    const gd_keyspec *k = gd_case_key_dotted(name);
    if (!k || k->type != GD_KEY_DOUBLE || strcmp(k->section, "continuation") == 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.parameter: '%s' is not a real-valued numeric key "
                            "of the case (valid: section.key of a number, e.g. operating.speed_rpm, "
                            "clearance.backlash_um)", WHERE("parameter"), name);
    gd_case_key_range_text(k, range, sizeof range);
    static const char *bk[2] = {"from", "to"};
    double b[2] = {c->cont_from, c->cont_to};
    for (int i = 0; i < 2; i++) {
        if (!gd_case_key_given(c, "continuation", bk[i]))
            return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.%s: missing (valid: the %s bound of %s, %s)",
                                WHERE("parameter"), bk[i], i ? "upper" : "lower", name, range);
        if (!gd_case_key_in_range(k, b[i]))
            return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.%s: %s = %.10g is out of range (valid: %s)",
                                WHERE(bk[i]), bk[i], name, b[i], range);
    }
    if (!(c->cont_from < c->cont_to))
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.to: %.10g is not above from = %.10g (valid: from < "
                            "to)", WHERE("to"), c->cont_to, c->cont_from);
    double v = c->cont_start_value;
    if (gd_case_key_given(c, "continuation", "start_value") && !(v >= c->cont_from && v <= c->cont_to))
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.start_value: %.10g is outside the bounds (valid: "
                            "from %.10g to %.10g)", WHERE("start_value"), v, c->cont_from, c->cont_to);
    return GD_OK;
}

/* The steps, the start state and the overlay. */
static gd_status check_settings(gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    if (c->cont_ds_min > c->cont_ds_max)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.ds_min: %g is above ds_max = %g (valid: ds_min <= "
                            "ds <= ds_max)", WHERE("ds_min"), c->cont_ds_min, c->cont_ds_max);
    if (c->cont_ds < c->cont_ds_min || c->cont_ds > c->cont_ds_max)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.ds: %g is outside [ds_min, ds_max] = [%g, %g] "
                            "(valid: ds_min <= ds <= ds_max)", WHERE("ds"), c->cont_ds, c->cont_ds_min,
                            c->cont_ds_max);
    if (!c->root_finding) {
        gd_case_key_where(c, "solver", "root_finding", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: solver.root_finding: off with analysis = continuation: the "
                            "monodromy matrices need the saltation matrix at every located contact event (valid: "
                            "root_finding = on)", w);
    }
    /* the residual is an absolute error of the dimensionless state, as solver.atol is */
    if (c->cont_newton_tol > 0 && c->cont_newton_tol < c->atol)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.newton_tol: %g is below solver.atol = %g, the absolute "
                            "error the integration allows in the same dimensionless state (valid: newton_tol >= %g, 0 "
                            "to derive it from the solver's tolerances, or a smaller solver.atol)", WHERE("newton_tol"),
                            c->cont_newton_tol, c->atol, c->atol);
    static const char *start_name[] = {"attractor", "state", "sweep"};
    if (c->cont_start == GD_CONT_START_SWEEP && !c->cont_start_sweep[0])
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.start_sweep: missing (valid: with start = sweep, "
                            "the directory of a finished sweep in %s)", WHERE("start"), c->cont_parameter);
    static const char *sweep_keys[] = {"start_sweep", "start_sweep_direction"};
    for (int i = 0; i < 2 && c->cont_start != GD_CONT_START_SWEEP; i++)
        if (gd_case_key_given(c, "continuation", sweep_keys[i]))
            return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.%s: given with start = %s (valid: set start = "
                                "sweep, or leave %s out)", WHERE(sweep_keys[i]), sweep_keys[i],
                                start_name[c->cont_start], sweep_keys[i]);
    if (c->cont_start == GD_CONT_START_STATE) {
        double y[GD_MAX_STATE];
        int n;
        gd_model m;
        gd_error e2 = {0};
        if (!parse_state(c->cont_state, y, &n))
            return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.state: '%s' (valid: with start = state, the "
                                "state's %s finite numbers, comma-separated)", WHERE("state"), c->cont_state,
                                "dimensionless");
        if (gd_model_build(c, &m, &e2) == GD_OK && n != m.n)
            return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.state: %d numbers (valid: the %d of this "
                                "model's state)", WHERE("state"), n, m.n);
    } else if (gd_case_key_given(c, "continuation", "state")) {
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.state: given with start = %s (valid: set "
                            "start = state, or leave state out)", WHERE("state"), start_name[c->cont_start]);
    }
    if (c->cont_overlay_sweep[0]) {
        if (c->cont_response == GD_CONT_RESP_MAX_DEFLECTION || c->cont_response == GD_CONT_RESP_MIN_DEFLECTION)
            return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.overlay_sweep: a sweep has no deflection "
                                "extremes to draw (valid: response = rms_accel, poincare or dynamic_load_factor with an overlay)",
                                WHERE("overlay_sweep"));
        char f[GD_PATH_MAX + 32];
        struct stat sb;
        snprintf(f, sizeof f, "%s/%s", c->cont_overlay_sweep,
                 c->cont_response == GD_CONT_RESP_POINCARE ? "bifurcation.csv" : "sweep.csv");
        if (stat(f, &sb) != 0 || !S_ISREG(sb.st_mode))
            return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.overlay_sweep: no %s (valid: the directory of "
                                "a finished sweep)", WHERE("overlay_sweep"), f);
    }
    return GD_OK;
}

GD_API gd_status gd_contin_check_case(gd_case *c, gd_error *err)
{
    gd_status st = check_parameter(c, err);
    if (st == GD_OK)
        st = check_settings(c, err);
    return st == GD_OK ? gd_contin_check_curves(c, err) : st;
}

double gd_contin_start_value(const gd_case *c)
{
    if (gd_case_key_given(c, "continuation", "start_value"))
        return c->cont_start_value;
    return c->cont_direction == GD_SWEEP_UP ? c->cont_from
         : c->cont_direction == GD_SWEEP_DOWN ? c->cont_to : 0.5 * (c->cont_from + c->cont_to);
}

GD_API double gd_contin_value(const gd_contin_result *res, double p) { return p * res->scale; }

GD_API void gd_contin_result_free(gd_contin_result *res)
{
    for (int b = 0; b < res->nbranches; b++) {
        gd_branch_free(&res->branch[b].br);
        free(res->branch[b].meas);
        free(res->branch[b].bif_meas);
    }
    free(res->branch);
    res->branch = NULL;
    res->nbranches = res->branch_cap = 0;
    for (int i = 0; i < res->ncurves; i++)
        gd_curve_free(&res->curve[i].cv);
    free(res->curve);
    res->curve = NULL;
    res->ncurves = 0;
}

/* The run: the case (changed as the parameter moves), its model at the start and the options. */
typedef struct crun {
    gd_case c;
    gd_case_param cp;
    gd_solver_opts o;
    gd_cont_opts co;
    gd_contin_result *res;
    int max_branches;            /* continuation.max_branches */
} crun;

/* One period (nper mesh periods) of the orbit through y at parameter p, integrated with samples. */
static gd_status measure(crun *r, double p, const double *y, int nper, gd_contin_measure *out, gd_error *err)
{
    gd_model m;
    gd_status st = gd_model_at_case_key(p, &m, &r->cp, err);
    if (st != GD_OK)
        return st;
    gd_modes md;
    if ((st = gd_model_consistent_modes(&m, 0.0, y, &md, err)) != GD_OK)
        return st;
    gd_response_opts ro;
    gd_response_opts_default(&ro);
    ro.y0 = y;
    ro.md0 = &md;
    ro.max_period = 1;
    r->c.transient_periods = 0;
    r->c.transient_max_periods = 0;
    r->c.record_periods = nper;
    r->c.lyapunov_exponents = 0;
    gd_response_result rr;
    if ((st = gd_response_run(&r->c, &m, &ro, NULL, NULL, &rr, err)) != GD_OK)
        return st;
    memcpy(out->rms_accel_mps2, rr.rms_accel_mps2, sizeof out->rms_accel_mps2);
    memcpy(out->lambda_min_um, rr.lambda_min_um, sizeof out->lambda_min_um);
    memcpy(out->lambda_max_um, rr.lambda_max_um, sizeof out->lambda_max_um);
    memcpy(out->dynamic_load_factor, rr.dynamic_load_factor, sizeof out->dynamic_load_factor);
    out->impact_regime = rr.impact_regime[2];
    double x, xd;
    gd_model_clearance(&m, m.mesh_clear[0], 0.0, y, &md, &x, &xd);
    out->lambda_poincare = x;
    return GD_OK;
}

static gd_status measure_branch(crun *r, gd_contin_branch *b, gd_error *err)
{
    b->meas = calloc((size_t)b->br.npoints + 1, sizeof *b->meas);
    b->bif_meas = calloc((size_t)b->br.nbif + 1, sizeof *b->bif_meas);
    if (!b->meas || !b->bif_meas)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the measures of a branch");
    gd_status st = GD_OK;
    for (int i = 0; i < b->br.npoints && st == GD_OK; i++)
        st = measure(r, b->br.pt[i].orbit.p, b->br.pt[i].orbit.y[0], b->nper, &b->meas[i], err);
    for (int i = 0; i < b->br.nbif && st == GD_OK; i++)
        st = measure(r, b->br.bif[i].p, b->br.bif[i].y, b->nper, &b->bif_meas[i], err);
    return st;
}

/* The attractor after run.transient_periods from run.initial_condition, and its period (given,
 * or the smallest n up to GD_PO_MAX_PERIODS whose Poincare section repeats). */
static gd_status attractor(crun *r, const gd_model *m, double *y, gd_error *err)
{
    gd_modes md;
    gd_status st = gd_initial_state(&r->c, m, y, &md, err);
    if (st == GD_OK && r->c.transient_periods > 0)
        st = gd_sim_period_map(m, &r->o, y, r->c.transient_periods, y, NULL, NULL, err);
    if (st != GD_OK || r->res->nper_start > 0)
        return st;
    enum { NPTS = 2 * GD_PO_MAX_PERIODS + 1 };
    double *pts = malloc(sizeof(double) * NPTS * (size_t)m->n);
    if (!pts)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the Poincare section");
    memcpy(pts, y, sizeof(double) * (size_t)m->n);
    for (int k = 1; k < NPTS && st == GD_OK; k++)
        st = gd_sim_period_map(m, &r->o, pts + (k - 1) * m->n, 1, pts + k * m->n, NULL, NULL, err);
    int n = st == GD_OK ? gd_poincare_period(pts, NPTS, m->n, r->c.periodicity_tol, GD_PO_MAX_PERIODS) : 0;
    free(pts);
    if (st != GD_OK)
        return st;
    if (n < 1)
        return gd_error_set(err, GD_ERR_SOLVER, "the continuation's start: the Poincare section after %d mesh "
                            "periods repeats with no period up to %d (run.periodicity_tol %g): set "
                            "continuation.period, or a longer run.transient_periods", r->c.transient_periods,
                            GD_PO_MAX_PERIODS, r->c.periodicity_tol);
    r->res->nper_start = n;
    r->res->period_found = 1;
    return GD_OK;
}

/* The case copy, its model at the start value, the scale and the options. */
static gd_status setup(crun *r, const gd_case *c, const gd_contin_start *start, gd_model *m, gd_error *err)
{
    gd_contin_result *res = r->res;
    gd_status st = gd_case_copy(&r->c, c, err);
    if (st != GD_OK)
        return st;
    r->c.analysis = GD_ANALYSIS_RESPONSE; /* the model at every parameter value: no check of these keys again */
    double v0 = start ? start->value : gd_contin_start_value(c);
    res->start_value = v0;
    snprintf(res->parameter, sizeof res->parameter, "%s", c->cont_parameter);
    snprintf(res->unit, sizeof res->unit, "%s", gd_case_key_dotted(c->cont_parameter)->unit);
    /* resolved as gd_case_resolve resolves a response: the analysis's own keys do not change */
    if ((st = gd_case_set_number(&r->c, c->cont_parameter, v0, err)) != GD_OK ||
        (st = gd_case_check(&r->c, err)) != GD_OK || (st = gd_scene_resolve(&r->c, err)) != GD_OK ||
        (st = gd_model_build(&r->c, m, err)) != GD_OK)
        return st;
    if (strcmp(c->cont_parameter, "operating.speed_rpm") == 0)
        res->scale = v0 / m->Omega; /* p is the dimensionless mesh frequency */
    else
        res->scale = fmax(fabs(c->cont_from), fabs(c->cont_to)) > 0 ? fmax(fabs(c->cont_from), fabs(c->cont_to)) : 1.0;
    r->cp = (gd_case_param){&r->c, res->parameter, res->scale};
    res->n = m->n;
    res->nclear = m->nclear;
    res->nmesh = m->nmesh;
    for (int j = 0; j < m->nclear; j++)
        snprintf(res->clear_name[j], sizeof res->clear_name[j], "%s", m->clear[j].name);
    gd_state_names(m, res->state_name);
    gd_solver_opts_from_case(&r->c, &r->o);
    gd_cont_opts_default(&r->co);
    r->co.po.multiple = c->cont_shooting == GD_SHOOT_MULTIPLE;
    r->co.po.tol = c->cont_newton_tol;
    r->co.po.max_iter = c->cont_newton_max_iterations;
    r->co.p_min = c->cont_from / res->scale;
    r->co.p_max = c->cont_to / res->scale;
    r->co.p_scale = r->co.p_max - r->co.p_min; /* every branch, those switched to included: the whole range */
    r->co.ds = c->cont_ds;
    r->co.ds_min = c->cont_ds_min;
    r->co.ds_max = c->cont_ds_max;
    r->co.dp_max = c->cont_dp_max / res->scale;
    r->co.max_points = c->cont_max_points;
    r->co.locate_tol = c->cont_locate_tol;
    res->nper_start = c->cont_period;
    return GD_OK;
}

/* Room for one more branch in res->branch. */
static gd_status grow(gd_contin_result *res, gd_error *err)
{
    if (res->nbranches < res->branch_cap)
        return GD_OK;
    int cap = res->branch_cap ? 2 * res->branch_cap : 4;
    gd_contin_branch *b = realloc(res->branch, sizeof *b * (size_t)cap);
    if (!b)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for %d branches", cap);
    res->branch = b;
    res->branch_cap = cap;
    return GD_OK;
}

/* A note of summary.json (at most GD_CONTIN_NOTES): fmt holds one %.10g (value) and one %s (why). */
static void note(gd_contin_result *res, const char *fmt, double value, const char *why)
{
    if (res->nnotes < GD_CONTIN_NOTES)
        snprintf(res->notes[res->nnotes++], GD_ERROR_MSG_MAX, fmt, value, why);
    else
        res->notes_dropped++;
}

/* How branch b ended, with the parameter in the key's unit (and p); co: its options (bounds in p). */
static void end_reason(const gd_contin_result *res, const gd_cont_opts *co, gd_contin_branch *b)
{
    const gd_branch *br = &b->br;
    double p = br->pt[br->npoints - 1].orbit.p, bound = b->direction > 0 ? co->p_max : co->p_min;
    const char *k = res->parameter, *sp = res->unit[0] ? " " : "";
    char *o = b->end_reason;
    size_t n = sizeof b->end_reason;
    if (br->end == GD_END_DOUBLING && b->joins >= 0 && b->joins == b->parent && b->joins_p == b->born_p)
        snprintf(o, n, "back at the period doubling of branch %d it was born at, %s = %.10g%s%s (p = %.9g), from "
                 "%.10g%s%s", b->joins, k, gd_contin_value(res, b->joins_p), sp, res->unit, b->joins_p,
                 gd_contin_value(res, p), sp, res->unit);
    else if (br->end == GD_END_DOUBLING && b->joins >= 0)
        snprintf(o, n, "at the period doubling of branch %d at %s = %.10g%s%s (p = %.9g), which it joins, from "
                 "%.10g%s%s", b->joins, k, gd_contin_value(res, b->joins_p), sp, res->unit, b->joins_p,
                 gd_contin_value(res, p), sp, res->unit);
    else if (br->end == GD_END_DOUBLING)
        snprintf(o, n, "at a period doubling of the orbit of half its period near %s = %.10g%s%s (p = %.9g), on no "
                 "branch followed, from %.10g%s%s", k, gd_contin_value(res, br->vertex_p), sp, res->unit, br->vertex_p,
                 gd_contin_value(res, p), sp, res->unit);
    else if (br->end == GD_END_BOUND && !br->end_detail[0])
        snprintf(o, n, "the bound %s = %.10g%s%s reached (p = %.9g)", k, gd_contin_value(res, p), sp, res->unit, p);
    else if (br->end == GD_END_BOUND)
        snprintf(o, n, "no orbit at the bound %s = %.10g%s%s (p = %.9g): the branch ends at %.10g%s%s (p = %.9g): "
                 "%s", k, gd_contin_value(res, bound), sp, res->unit, bound, gd_contin_value(res, p), sp, res->unit,
                 p, br->end_detail);
    else if (br->end == GD_END_CLOSED && br->closed_point > 0)
        snprintf(o, n, "closed: back at the orbit of its point %d (%s = %.10g%s%s)%s%s at %s = %.10g%s%s (p = %.9g): "
                 "a closed curve from there on, followed once round", br->closed_point, k,
                 gd_contin_value(res, br->pt[br->closed_point].orbit.p), sp, res->unit,
                 br->closed_shift ? ", shifted by whole mesh periods" : "", br->closed_reversed ? ", passed the other "
                 "way" : "", k, gd_contin_value(res, p), sp, res->unit, p);
    else if (br->end == GD_END_CLOSED && br->closed_shift)
        snprintf(o, n, "closed: back at its first orbit shifted by %d mesh period%s (the same orbit)%s at %s = "
                 "%.10g%s%s (p = %.9g)", br->closed_shift, br->closed_shift > 1 ? "s" : "", br->closed_reversed ?
                 ", passed the other way: the rest mirrors the branch's other direction" : "", k,
                 gd_contin_value(res, p), sp, res->unit, p);
    else if (br->end == GD_END_CLOSED)
        snprintf(o, n, "closed: back at its first orbit at %s = %.10g%s%s (p = %.9g)", k, gd_contin_value(res, p), sp,
                 res->unit, p);
    else if (br->end == GD_END_HALF)
        snprintf(o, n, "its orbit became the orbit of half the period repeated at %s = %.10g%s%s (p = %.9g): the branch "
                 "crossed a period doubling of that orbit onto the branch it was born from", k, gd_contin_value(res, p),
                 sp, res->unit, p);
    else if (br->end == GD_END_BUDGET)
        snprintf(o, n, "%d points reached at %s = %.10g%s%s (p = %.9g)", br->npoints, k, gd_contin_value(res, p),
                 sp, res->unit, p);
    else
        snprintf(o, n, "no convergence at the smallest step %.3g from %s = %.10g%s%s (p = %.9g): %s", co->ds_min,
                 k, gd_contin_value(res, p), sp, res->unit, p, br->end_detail);
}

/* The tolerance in p within which two period doublings (or a doubling and the vertex of a branch of
 * twice the period) are the same: a hundred times its bracket, at least 1e-6 of the range. */
static double same_doubling_tol(const crun *r, const gd_bifurcation *bf)
{
    return fmax(100.0 * fabs(bf->p_hi - bf->p_lo), 1e-6 * (r->co.p_max - r->co.p_min));
}

/* Branch b ended at the vertex of a period doubling of the orbit of half its period: which branch's
 * doubling. Of the period doublings of the branches of half the period within 1 % of the range of the
 * vertex's estimate and whose orbit lies within a tenth of the state's scale of the vertex's, the
 * nearest in the parameter (the estimate from the last points is good to a fraction of their
 * distance from the vertex, unless the branch folds near it). */
static void find_joined(const crun *r, gd_contin_branch *b)
{
    const gd_contin_result *res = r->res;
    double pv = b->br.vertex_p, best = INFINITY;
    b->joins = -1;
    b->joins_p = NAN;
    for (int j = 0; j < res->nbranches; j++) {
        if (2 * res->branch[j].nper != b->nper)
            continue;
        for (int i = 0; i < res->branch[j].br.nbif; i++) {
            const gd_bifurcation *bf = &res->branch[j].br.bif[i];
            double dy = 0;
            for (int k = 0; k < res->n; k++)
                dy = fmax(dy, fabs(bf->y[k] - b->br.vertex_y[k]));
            if (bf->kind == GD_BIF_PERIOD_DOUBLING && fabs(bf->p - pv) <= 0.01 * (r->co.p_max - r->co.p_min) &&
                dy <= 0.1 * b->br.y_scale && fabs(bf->p - pv) < best) {
                best = fabs(bf->p - pv);
                b->joins = j;
                b->joins_p = bf->p;
            }
        }
    }
}

/* A branch from the orbit start, of start->nper periods, in direction dir, p kept in [lo, hi];
 * parent, born_p: the branch and the period doubling it was switched at (-1, NAN for a start
 * branch). */
static gd_status follow(crun *r, const gd_po *start, int dir, int parent, double born_p, double lo, double hi,
                        gd_error *err)
{
    gd_contin_result *res = r->res;
    gd_status st = grow(res, err);
    if (st != GD_OK)
        return st;
    gd_contin_branch *b = &res->branch[res->nbranches];
    memset(b, 0, sizeof *b);
    b->nper = start->nper;
    b->direction = dir;
    b->parent = parent;
    b->born_p = born_p;
    b->joins = -1;
    b->joins_p = NAN;
    gd_cont_opts co = r->co;
    co.po.nper = start->nper;
    co.direction = dir;
    co.p_min = lo;
    co.p_max = hi;
    st = gd_continue(gd_model_at_case_key, &r->cp, &r->o, &co, start, &b->br, err);
    res->corrections += b->br.corrections;
    res->newton_iterations += b->br.newton_iterations;
    if (st == GD_OK) {
        if (b->br.end == GD_END_DOUBLING)
            find_joined(r, b);
        end_reason(res, &co, b);
        st = measure_branch(r, b, err);
    }
    if (st != GD_OK) { /* no branch: its memory goes (a switched one's failure is a note) */
        gd_branch_free(&b->br);
        free(b->meas);
        free(b->bif_meas);
        return st;
    }
    for (int i = 0; i < b->br.nnotes; i++) { /* what the locations noted */
        char why[GD_ERROR_MSG_MAX];
        snprintf(why, sizeof why, "%s", b->br.notes[i]);
        note(res, "branch %.0f: %s", res->nbranches, why);
    }
    res->notes_dropped += b->br.notes_dropped;
    res->nbranches++;
    return GD_OK;
}

/* The orbit of twice the period at the period doubling bf of branch ib, followed both ways: away
 * from the doubling, and back towards it, where it ends at the doubling's vertex (the branch point
 * at which it meets the orbit it was born from, gd_continue's end period-doubling). The way back
 * is kept within dp beyond its start (in case the vertex is passed unnoticed and the branch runs
 * back as its own image) and dp beyond the doubling. */
static gd_status switch_at(crun *r, int ib, const gd_bifurcation *bf, gd_error *err)
{
    gd_contin_result *res = r->res;
    const int nper = res->branch[ib].nper;
    if (res->nbranches + 2 > r->max_branches) {
        note(res, "no branch switching at the period doubling at %.10g: %s", gd_contin_value(res, bf->p),
             "continuation.max_branches reached");
        return GD_OK;
    }
    gd_po_opts po = r->co.po;
    po.nper = nper;
    double dp = 0.01 * (r->co.p_max - r->co.p_min);
    gd_po p2;
    gd_error e2 = {0};
    if (gd_po_period_doubled(gd_model_at_case_key, &r->cp, &r->o, &po, bf, dp, 0.05, &p2, &e2) != GD_OK) {
        note(res, "no orbit of twice the period found at the period doubling at %.10g: %s",
             gd_contin_value(res, bf->p), e2.msg);
        return GD_OK;
    }
    int away = p2.p > bf->p ? +1 : -1;
    double lo = away > 0 ? bf->p - dp : p2.p - dp, hi = away > 0 ? p2.p + dp : bf->p + dp;
    gd_status st = follow(r, &p2, away, ib, bf->p, r->co.p_min, r->co.p_max, &e2);
    if (st == GD_OK)
        st = follow(r, &p2, -away, ib, bf->p, fmax(lo, r->co.p_min), fmin(hi, r->co.p_max), &e2);
    if (st == GD_ERR_NOMEM || st == GD_ERR_INTERRUPTED)
        return gd_error_set(err, st, "%s", e2.msg);
    if (st != GD_OK) /* the doubled orbit found, but no branch from it: the others go on */
        note(res, "the branch of twice the period switched to at the period doubling at %.10g: %s",
             gd_contin_value(res, bf->p), e2.msg);
    return GD_OK;
}

/* Whether the orbit of twice the period at the period doubling i of branch ib is followed already:
 * a doubling at the same parameter was switched at before (on an earlier branch, or earlier on this
 * one: a branch that closes on itself meets its doublings again), or a branch of twice the period
 * ends at it (a closed curve of doubled orbits joining two doublings is followed once). */
static int doubled_before(const crun *r, int ib, int i)
{
    const gd_contin_result *res = r->res;
    const gd_bifurcation *bf = &res->branch[ib].br.bif[i];
    double tol = same_doubling_tol(r, bf);
    for (int b = 0; b <= ib; b++)
        for (int j = 0; j < (b < ib ? res->branch[b].br.nbif : i); j++) {
            const gd_bifurcation *o = &res->branch[b].br.bif[j];
            if (res->branch[b].nper == res->branch[ib].nper && o->kind == GD_BIF_PERIOD_DOUBLING &&
                fabs(o->p - bf->p) <= tol)
                return 1;
        }
    for (int b = 0; b < res->nbranches; b++)
        if (res->branch[b].nper == 2 * res->branch[ib].nper && res->branch[b].joins == ib &&
            fabs(res->branch[b].joins_p - bf->p) <= tol)
            return 1;
    return 0;
}

/* The branches of twice the period at the period doublings of branch ib. */
static gd_status switch_branches(crun *r, int ib, gd_error *err)
{
    if (2 * r->res->branch[ib].nper > GD_PO_MAX_PERIODS)
        return GD_OK;
    gd_status st = GD_OK;
    for (int i = 0; i < r->res->branch[ib].br.nbif && st == GD_OK; i++) {
        gd_bifurcation bf = r->res->branch[ib].br.bif[i]; /* a copy: res->branch moves as it grows */
        if (bf.kind == GD_BIF_PERIOD_DOUBLING && !doubled_before(r, ib, i))
            st = switch_at(r, ib, &bf, err);
    }
    return st;
}

static gd_status run_branches(crun *r, const gd_case *c, const gd_po *start, gd_contin_progress_fn progress,
                              void *user, gd_error *err)
{
    gd_contin_result *res = r->res;
    int dirs[2], nd = 0;
    if (c->cont_direction != GD_SWEEP_UP)
        dirs[nd++] = -1;
    if (c->cont_direction != GD_SWEEP_DOWN)
        dirs[nd++] = +1;
    gd_status st = GD_OK;
    for (int i = 0; i < nd && i < r->max_branches && st == GD_OK; i++) {
        st = follow(r, start, dirs[i], -1, NAN, r->co.p_min, r->co.p_max, err);
        if (st == GD_OK && progress && progress(user, res->nbranches, nd))
            st = gd_error_set(err, GD_ERR_INTERRUPTED, "the continuation was stopped");
    }
    /* every branch, those switched to included (res->nbranches grows): the period-doubling cascade;
     * the progress counts the branches followed, so it is told when a switching adds some */
    for (int ib = 0; ib < res->nbranches && st == GD_OK && c->cont_branch_switching; ib++) {
        int before = res->nbranches;
        st = switch_branches(r, ib, err);
        if (st == GD_OK && res->nbranches > before && progress && progress(user, res->nbranches, res->nbranches))
            st = gd_error_set(err, GD_ERR_INTERRUPTED, "the continuation was stopped");
    }
    return st;
}

GD_API gd_status gd_contin_run(const gd_case *c, const gd_contin_start *from, gd_contin_progress_fn progress,
                               void *user, const gd_stop_hook *stop, gd_contin_result *res, gd_error *err)
{
    return gd_contin_run_curve(c, from, NULL, progress, user, stop, res, err);
}

GD_API gd_status gd_contin_run_curve(const gd_case *c, const gd_contin_start *from, const gd_contin_curve_row *row,
                                     gd_contin_progress_fn progress, void *user, const gd_stop_hook *stop,
                                     gd_contin_result *res, gd_error *err)
{
    memset(res, 0, sizeof *res);
    double t0 = gd_clock_thread_cpu_s();
    crun r;
    memset(&r, 0, sizeof r);
    r.res = res;
    r.max_branches = c->cont_max_branches;
    if (!from && c->cont_start == GD_CONT_START_SWEEP)
        return gd_error_set(err, GD_ERR_INPUT, "continuation.start = sweep: the sweep's point is read from %s by the "
                            "continuation row (gd_analysis_run_in), or given as gd_contin_start", c->cont_start_sweep);
    gd_model m;
    gd_status st = setup(&r, c, from, &m, err);
    if (stop)
        r.co.stop = *stop;
    double y[GD_MAX_STATE];
    if (st == GD_OK && from && from->n != m.n)
        st = gd_error_set(err, GD_ERR_INPUT, "the continuation's start (%s): %d state components, the model has %d",
                          from->source, from->n, m.n);
    if (st == GD_OK && from) {
        memcpy(y, from->y, sizeof y);
        snprintf(res->start_source, sizeof res->start_source, "%s", from->source);
        if (res->nper_start == 0)
            res->nper_start = from->nper > 0 ? from->nper : 1;
        res->period_found = c->cont_period == 0 && from->nper > 0;
    } else if (st == GD_OK && c->cont_start == GD_CONT_START_STATE) {
        int n;
        parse_state(c->cont_state, y, &n);
        if (res->nper_start == 0)
            res->nper_start = 1;
    } else if (st == GD_OK) {
        st = attractor(&r, &m, y, err);
    }
    gd_po start;
    if (st == GD_OK) {
        gd_po_opts po = r.co.po;
        po.nper = res->nper_start;
        st = gd_po_solve(&m, &r.o, &po, y, &start, err);
        if (st != GD_OK)
            gd_error_prefix(err, "the starting orbit of %d mesh periods at %s = %.10g", po.nper, c->cont_parameter,
                            res->start_value);
        start.p = res->start_value / res->scale;
    }
    if (st == GD_OK)
        st = run_branches(&r, c, &start, progress, user, err);
    if (st == GD_OK)
        st = gd_contin_curves(c, &r.c, &r.o, &r.co, row, res, err);
    res->cpu_s = gd_clock_thread_cpu_s() - t0;
    if (r.c.src)
        gd_case_free(&r.c);
    if (st != GD_OK)
        gd_contin_result_free(res);
    return st;
}
