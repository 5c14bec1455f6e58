/* The `continuation` analysis (include/geardyn/gd_continuation.h): the [continuation] keys
 * checked, the starting orbit (the attractor after the transient, its period found from the
 * Poincare section, or a given state), its branches in one or both directions, the branches of
 * twice the period at its period doublings, and one period of every orbit integrated with
 * samples for what the tables and the picture show. */
#include "geardyn/gd_continuation.h"
#include "geardyn/gd_response.h"
#include "geardyn/gd_sweep.h"
#include "geardyn/gd_scene.h"
#include "../case/case_keys.h"
#include "../core/clock.h"

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
    if (c->cont_newton_tol < c->rtol)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.newton_tol: %g is below solver.rtol = %g (valid: "
                            "newton_tol >= %g, or a tighter solver.rtol)", WHERE("newton_tol"), c->cont_newton_tol,
                            c->rtol, c->rtol);
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
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.state: given with start = attractor (valid: set "
                            "start = state, or leave state out)", WHERE("state"));
    }
    if (c->cont_overlay_sweep[0]) {
        if (c->cont_response == GD_CONT_RESP_MAX_DEFLECTION || c->cont_response == GD_CONT_RESP_MIN_DEFLECTION)
            return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.overlay_sweep: a sweep has no deflection "
                                "extremes to draw (valid: response = rms_accel or poincare with an overlay)",
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
    return st == GD_OK ? check_settings(c, err) : st;
}

GD_API double gd_contin_value(const gd_contin_result *res, double p) { return p * res->scale; }

GD_API void gd_contin_result_free(gd_contin_result *res)
{
    for (int b = 0; b < res->nbranches; b++) {
        gd_branch_free(&res->branch[b].br);
        free(res->branch[b].meas);
        free(res->branch[b].bif_meas);
    }
    res->nbranches = 0;
}

/* The run: the case (changed as the parameter moves), its model at the start and the options. */
typedef struct crun {
    gd_case c;
    gd_case_param cp;
    gd_solver_opts o;
    gd_cont_opts co;
    gd_contin_result *res;
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
static gd_status setup(crun *r, const gd_case *c, gd_model *m, gd_error *err)
{
    gd_contin_result *res = r->res;
    gd_status st = gd_case_copy(&r->c, c, err);
    if (st != GD_OK)
        return st;
    r->c.analysis = GD_ANALYSIS_RESPONSE; /* the model at every parameter value: no check of these keys again */
    double v0 = c->cont_start_value;
    if (!gd_case_key_given(c, "continuation", "start_value"))
        v0 = c->cont_direction == GD_SWEEP_UP ? c->cont_from
           : c->cont_direction == GD_SWEEP_DOWN ? c->cont_to : 0.5 * (c->cont_from + c->cont_to);
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
    for (int j = 0; j < m->ndof; j++) {
        snprintf(res->state_name[j], sizeof res->state_name[j], "%s", m->dof_name[j]);
        snprintf(res->state_name[m->ndof + j], sizeof res->state_name[j], "%s_dot", m->dof_name[j]);
    }
    gd_solver_opts_from_case(&r->c, &r->o);
    gd_cont_opts_default(&r->co);
    r->co.po.multiple = c->cont_shooting == GD_SHOOT_MULTIPLE;
    r->co.po.tol = c->cont_newton_tol;
    r->co.po.max_iter = c->cont_newton_max_iterations;
    r->co.p_min = c->cont_from / res->scale;
    r->co.p_max = c->cont_to / res->scale;
    r->co.ds = c->cont_ds;
    r->co.ds_min = c->cont_ds_min;
    r->co.ds_max = c->cont_ds_max;
    r->co.dp_max = c->cont_dp_max / res->scale;
    r->co.max_points = c->cont_max_points;
    r->co.locate_tol = c->cont_locate_tol;
    res->nper_start = c->cont_period;
    return GD_OK;
}

/* A branch from the orbit start, of start->nper periods, in direction dir. */
static gd_status follow(crun *r, const gd_po *start, int dir, int parent, gd_error *err)
{
    gd_contin_result *res = r->res;
    if (res->nbranches == GD_CONTIN_MAX_BRANCHES)
        return GD_OK;
    gd_contin_branch *b = &res->branch[res->nbranches];
    memset(b, 0, sizeof *b);
    b->nper = start->nper;
    b->direction = dir;
    b->parent = parent;
    gd_cont_opts co = r->co;
    co.po.nper = start->nper;
    co.direction = dir;
    gd_status st = gd_continue(gd_model_at_case_key, &r->cp, &r->o, &co, start, &b->br, err);
    if (st != GD_OK)
        return st;
    res->nbranches++;
    res->corrections += b->br.corrections;
    res->newton_iterations += b->br.newton_iterations;
    return measure_branch(r, b, err);
}

/* The branches of twice the period at the period doublings of branch ib. */
static gd_status switch_branches(crun *r, int ib, gd_error *err)
{
    gd_contin_result *res = r->res;
    const gd_contin_branch *b = &res->branch[ib];
    if (2 * b->nper > GD_PO_MAX_PERIODS)
        return GD_OK;
    gd_po_opts po = r->co.po;
    po.nper = b->nper;
    double dp = 0.01 * (r->co.p_max - r->co.p_min);
    for (int i = 0; i < b->br.nbif; i++) {
        const gd_bifurcation *bf = &res->branch[ib].br.bif[i];
        if (bf->kind != GD_BIF_PERIOD_DOUBLING || res->nbranches == GD_CONTIN_MAX_BRANCHES)
            continue;
        gd_po p2;
        gd_error e2 = {0};
        if (gd_po_period_doubled(gd_model_at_case_key, &r->cp, &r->o, &po, bf, dp, 0.05, &p2, &e2) != GD_OK) {
            if (res->nnotes < 4)
                snprintf(res->notes[res->nnotes++], GD_ERROR_MSG_MAX, "no orbit of %d periods found at the period "
                         "doubling at %.10g: %s", 2 * b->nper, gd_contin_value(res, bf->p), e2.msg);
            continue;
        }
        gd_status st = follow(r, &p2, p2.p > bf->p ? +1 : -1, ib, err);
        if (st != GD_OK)
            return st;
    }
    return GD_OK;
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
    for (int i = 0; i < nd && st == GD_OK; i++) {
        st = follow(r, start, dirs[i], -1, err);
        if (st == GD_OK && progress && progress(user, res->nbranches, nd))
            st = gd_error_set(err, GD_ERR_INTERRUPTED, "the continuation was stopped");
    }
    int primary = res->nbranches;
    for (int ib = 0; ib < primary && st == GD_OK && c->cont_branch_switching; ib++) {
        st = switch_branches(r, ib, err);
        if (st == GD_OK && progress && progress(user, res->nbranches, res->nbranches))
            st = gd_error_set(err, GD_ERR_INTERRUPTED, "the continuation was stopped");
    }
    return st;
}

GD_API gd_status gd_contin_run(const gd_case *c, gd_contin_progress_fn progress, void *user, gd_contin_result *res,
                               gd_error *err)
{
    memset(res, 0, sizeof *res);
    double t0 = gd_clock_thread_cpu_s();
    crun r;
    memset(&r, 0, sizeof r);
    r.res = res;
    gd_model m;
    gd_status st = setup(&r, c, &m, err);
    double y[GD_MAX_STATE];
    if (st == GD_OK && c->cont_start == GD_CONT_START_STATE) {
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
    res->cpu_s = gd_clock_thread_cpu_s() - t0;
    if (r.c.src)
        gd_case_free(&r.c);
    if (st != GD_OK)
        gd_contin_result_free(res);
    return st;
}
