/* The `sweep` analysis: the grid, the chains, and running them in parallel (OpenMP). */
#include "geardyn/gd_sweep.h"
#include "analysis_internal.h"
#include "geardyn/gd_scene.h"
#include "geardyn/gd_version.h"
#include "../case/case_keys.h"
#include "../core/hash.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

GD_API const char *gd_sweep_branch_name(int branch)
{
    static const char *names[] = {"up", "down", "independent"};
    return branch >= 0 && branch <= 2 ? names[branch] : "?";
}

/* ---- the case's [sweep] keys ---- */

/* Value i of an axis as spaced, before a whole-number key rounds it. */
static double axis_raw_value(const gd_case *c, int axis, int i)
{
    int n = axis ? c->sweep_points2 : c->sweep_points;
    double a = axis ? c->sweep_from2 : c->sweep_from, b = axis ? c->sweep_to2 : c->sweep_to;
    int log_sp = (axis ? c->sweep_spacing2 : c->sweep_spacing) == GD_SWEEP_LOG;
    double v;
    if (n <= 1 || i <= 0)
        v = a;
    else if (i >= n - 1)
        v = b;
    else {
        double f = (double)i / (double)(n - 1);
        v = log_sp ? exp(log(a) + f * (log(b) - log(a))) : a + f * (b - a);
    }
    return v;
}

double gd_sweep_axis_value(const gd_case *c, int axis, int i)
{
    double v = axis_raw_value(c, axis, i);
    const gd_keyspec *k = gd_case_key_dotted(axis ? c->sweep_parameter2 : c->sweep_parameter);
    if (k && k->type == GD_KEY_INT)
        v = floor(v + 0.5);
    return v;
}

/* Parse the response list against a model. */
static gd_status parse_responses(const char *spec, const gd_model *m, gd_sweep_response *out, int *nout,
                                 char *bad, size_t badlen)
{
    char buf[256];
    snprintf(buf, sizeof buf, "%s", spec[0] ? spec : "lambda_L, lambda_R");
    int n = 0;
    char *save = NULL;
    for (char *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        while (*tok == ' ' || *tok == '\t')
            tok++;
        for (char *e = tok + strlen(tok); e > tok && (e[-1] == ' ' || e[-1] == '\t');)
            *--e = '\0';
        if (n == GD_SWEEP_MAX_RESPONSES) {
            snprintf(bad, badlen, "more than %d responses", GD_SWEEP_MAX_RESPONSES);
            return GD_ERR_INPUT;
        }
        gd_sweep_response r;
        memset(&r, 0, sizeof r);
        r.kind = -1;
        int rmesh = m->nmesh > 1 ? 1 : 0;
        if (strcmp(tok, "lambda_L") == 0 || strcmp(tok, "lambda") == 0)
            r.kind = GD_RESP_MESH, r.index = 0;
        else if (strcmp(tok, "lambda_R") == 0)
            r.kind = GD_RESP_MESH, r.index = rmesh;
        else if (strcmp(tok, "lambda_dot_L") == 0 || strcmp(tok, "lambda_dot") == 0)
            r.kind = GD_RESP_MESH_RATE, r.index = 0;
        else if (strcmp(tok, "lambda_dot_R") == 0)
            r.kind = GD_RESP_MESH_RATE, r.index = rmesh;
        else {
            size_t l = strlen(tok);
            int rate = l > 4 && strcmp(tok + l - 4, "_dot") == 0;
            for (int i = 0; i < m->ndof; i++) {
                size_t dl = strlen(m->dof_name[i]);
                if ((rate ? l - 4 == dl : l == dl) && strncmp(tok, m->dof_name[i], dl) == 0) {
                    r.kind = GD_RESP_STATE;
                    r.index = rate ? m->ndof + i : i;
                }
            }
        }
        if (r.kind < 0 || strlen(tok) >= sizeof r.name) {
            char valid[512] = "lambda_L, lambda_R, lambda_dot_L, lambda_dot_R";
            for (int i = 0; i < m->ndof; i++) {
                size_t u = strlen(valid);
                snprintf(valid + u, sizeof valid - u, ", %s", m->dof_name[i]);
            }
            size_t u = strlen(valid);
            snprintf(valid + u, sizeof valid - u, " and DOF_dot");
            snprintf(bad, badlen, "unknown response '%s' for this model (valid: %s)", tok, valid);
            return GD_ERR_INPUT;
        }
        for (int j = 0; j < n; j++)
            if (strcmp(out[j].name, tok) == 0) {
                snprintf(bad, badlen, "response '%s' given twice", tok);
                return GD_ERR_INPUT;
            }
        snprintf(r.name, sizeof r.name, "%s", tok);
        out[n++] = r;
    }
    if (n == 0) {
        snprintf(bad, badlen, "no response named");
        return GD_ERR_INPUT;
    }
    *nout = n;
    return GD_OK;
}

static gd_status check_axis(const gd_case *c, int axis, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    const char *kp = axis ? "parameter2" : "parameter", *kf = axis ? "from2" : "from", *kt = axis ? "to2" : "to";
    const char *ks = axis ? "spacing2" : "spacing";
    const char *name = axis ? c->sweep_parameter2 : c->sweep_parameter;
    double from = axis ? c->sweep_from2 : c->sweep_from, to = axis ? c->sweep_to2 : c->sweep_to;
    int points = axis ? c->sweep_points2 : c->sweep_points;
    int spacing = axis ? c->sweep_spacing2 : c->sweep_spacing;
    gd_case_key_where(c, "sweep", kp, w, sizeof w);
    if (!name[0])
        return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.parameter: missing (valid: a numeric key as section.key, "
                            "e.g. operating.speed_rpm)", w);
    double cur;
    gd_error e2 = {0};
    if (gd_case_get_number(c, name, &cur, &e2) != GD_OK)
        return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.%s: '%s' is not a numeric case key: %s", w, kp, name,
                            e2.msg);
    const gd_keyspec *k = gd_case_key_dotted(name);
    if (!k || strcmp(k->section, "sweep") == 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.%s: '%s' cannot be swept (valid: a numeric key of "
                            "another section)", w, kp, name);
    char range[160];
    gd_case_key_range_text(k, range, sizeof range);
    /* a missing bound is named at the line of its parameter */
    if (!gd_case_key_given(c, "sweep", kf) || !isfinite(from)) {
        gd_case_key_where(c, "sweep", gd_case_key_given(c, "sweep", kf) ? kf : kp, w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.%s: missing (valid: the first value of %s, %s)", w, kf,
                            name, range);
    }
    if (!gd_case_key_given(c, "sweep", kt) || !isfinite(to)) {
        gd_case_key_where(c, "sweep", gd_case_key_given(c, "sweep", kt) ? kt : kp, w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.%s: missing (valid: the last value of %s, %s)", w, kt,
                            name, range);
    }
    if (spacing == GD_SWEEP_LOG && !(from > 0 && to > 0)) {
        gd_case_key_where(c, "sweep", ks, w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.%s: log spacing from %g to %g (valid: positive from and "
                            "to for log spacing)", w, ks, from, to);
    }
    /* the ends first (the message names the value given), then every value between */
    for (int q = 0; q < points + 2; q++) {
        int i = q == 0 ? 0 : q == 1 ? points - 1 : q - 2;
        double v = gd_sweep_axis_value(c, axis, i);
        if (!gd_case_key_in_range(k, v)) {
            gd_case_key_where(c, "sweep", i == 0 ? kf : kt, w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.%s: %s = %.10g is out of range (valid: %s)", w,
                                i == 0 ? kf : kt, name, v, range);
        }
    }
    /* a whole-number key is swept over whole numbers only: a grid that would be rounded is refused */
    for (int i = 0; k->type == GD_KEY_INT && i < points; i++) {
        double v = axis_raw_value(c, axis, i);
        if (fabs(v - floor(v + 0.5)) > 1e-9 * fmax(1.0, fabs(v))) {
            gd_case_key_where(c, "sweep", axis ? "points2" : "points", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.%s: value %d of the whole-number key %s would be "
                                "%.6g, rounded to %.0f (valid: from, to and points giving whole numbers: linear "
                                "spacing with (to - from) / (points - 1) whole)", w, axis ? "points2" : "points",
                                i + 1, name, v, floor(v + 0.5));
        }
    }
    return GD_OK;
}

gd_status gd_sweep_check_case(const gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    gd_status st = check_axis(c, 0, err);
    if (st != GD_OK)
        return st;
    if (c->sweep_parameter2[0]) {
        if ((st = check_axis(c, 1, err)) != GD_OK)
            return st;
        if (strcmp(c->sweep_parameter2, c->sweep_parameter) == 0) {
            gd_case_key_where(c, "sweep", "parameter2", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.parameter2: '%s' is already sweep.parameter (valid: "
                                "another numeric key, or empty)", w, c->sweep_parameter2);
        }
    } else {
        static const char *k2[] = {"from2", "to2", "points2", "spacing2"};
        for (int i = 0; i < 4; i++)
            if (gd_case_key_given(c, "sweep", k2[i])) {
                gd_case_key_where(c, "sweep", k2[i], w, sizeof w);
                return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.%s: given without sweep.parameter2 (valid: set "
                                    "parameter2 for a regime map, or leave %s out)", w, k2[i], k2[i]);
            }
    }
    /* the responses exist in this model (when it builds; if not, the caller reports why) */
    gd_model m;
    gd_error e2 = {0};
    if (gd_model_build(c, &m, &e2) == GD_OK) {
        gd_sweep_response r[GD_SWEEP_MAX_RESPONSES];
        int n;
        char bad[700];
        if (parse_responses(c->sweep_response, &m, r, &n, bad, sizeof bad) != GD_OK) {
            gd_case_key_where(c, "sweep", "response", w, sizeof w);
            return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.response: %s", w, bad);
        }
    }
    return GD_OK;
}

/* ---- the plan ---- */

static uint64_t fingerprint(const gd_case *c)
{
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    uint64_t h = gd_fnv1a_str(GD_FNV1A_OFFSET_BASIS, "geardyn sweep " GD_VERSION_STRING "\n");
    static const char *skip[] = {"output.directory", "output.time_history", "output.event_log", "output.plots",
                                 "scene.title"};
    for (size_t i = 0; i < n; i++) {
        char name[200], val[1300];
        snprintf(name, sizeof name, "%s.%s", s[i].section, s[i].key);
        int skipped = 0;
        for (size_t j = 0; j < sizeof skip / sizeof skip[0]; j++)
            skipped |= strcmp(name, skip[j]) == 0;
        if (skipped)
            continue;
        if (s[i].type == GD_KEY_DOUBLE)
            snprintf(val, sizeof val, "%.17g", *(const double *)((const char *)c + s[i].offset));
        else
            gd_case_format_value(c, i, val, sizeof val);
        h = gd_fnv1a_str(h, name);
        h = gd_fnv1a_str(h, "=");
        h = gd_fnv1a_str(h, val);
        h = gd_fnv1a_str(h, "\n");
    }
    return h;
}

GD_API void gd_sweep_plan_free(gd_sweep_plan *p)
{
    if (!p)
        return;
    free(p->values[0]);
    free(p->values[1]);
    free(p->chains);
    free(p->slot_info);
    p->values[0] = p->values[1] = NULL;
    p->chains = NULL;
    p->slot_info = NULL;
}

static gd_status point_case(const gd_case *base, const gd_sweep_plan *p, int i1, int i2, gd_case *out, gd_model *m,
                            gd_error *err);

/* The grid: the values of each axis (one value on an unused second axis), names and units. */
static gd_status plan_grid(const gd_case *c, gd_sweep_plan *p, gd_error *err)
{
    for (int a = 0; a < 2; a++) {
        const char *name = a ? c->sweep_parameter2 : c->sweep_parameter;
        p->npoints[a] = a < p->naxes ? (a ? c->sweep_points2 : c->sweep_points) : 1;
        p->spacing[a] = a ? c->sweep_spacing2 : c->sweep_spacing;
        p->values[a] = calloc((size_t)p->npoints[a], sizeof(double));
        if (!p->values[a])
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the sweep grid");
        if (a < p->naxes) {
            snprintf(p->parameter[a], sizeof p->parameter[a], "%s", name);
            const gd_keyspec *k = gd_case_key_dotted(name);
            snprintf(p->unit[a], sizeof p->unit[a], "%s", k ? k->unit : "");
            for (int i = 0; i < p->npoints[a]; i++)
                p->values[a][i] = gd_sweep_axis_value(c, a, i);
        }
    }
    return GD_OK;
}

/* The chains and slots: per row of parameter2, the up chain before the down chain
 * (continuation), or one chain per point (independent). */
static gd_status plan_chains(const gd_case *c, gd_sweep_plan *p, gd_error *err)
{
    int n1 = p->npoints[0], n2 = p->npoints[1];
    int cont = p->mode == GD_SWEEP_CONTINUATION;
    int nbr = cont ? (p->direction == GD_SWEEP_BOTH ? 2 : 1) : 1;
    long nslots = (long)n1 * n2 * nbr;
    if (nslots > 10000000L)
        return gd_error_set(err, GD_ERR_INPUT, "%s: [sweep]: %ld points (valid: at most 10000000)",
                            c->path[0] ? c->path : "case", nslots);
    p->nslots = (int)nslots;
    p->nchains = cont ? n2 * nbr : n1 * n2;
    p->chains = calloc((size_t)p->nchains, sizeof *p->chains);
    p->slot_info = calloc((size_t)p->nslots * 4, sizeof(int));
    if (!p->chains || !p->slot_info)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the sweep plan");
    /* "up" walks increasing values of the parameter, whichever way from and to are given */
    int ascending = p->values[0][0] <= p->values[0][n1 - 1];
    int nc = 0, slot = 0;
    for (int row = 0; row < n2; row++) {
        if (cont) {
            for (int b = 0; b < 2; b++) {
                if (!(p->direction == GD_SWEEP_BOTH || p->direction == b))
                    continue;
                gd_sweep_chain *ch = &p->chains[nc];
                ch->branch = b;
                ch->row = row;
                ch->first = slot;
                ch->count = n1;
                for (int k = 0; k < n1; k++) {
                    int up_index = ascending ? k : n1 - 1 - k;
                    int i1 = b == GD_BRANCH_UP ? up_index : n1 - 1 - up_index;
                    int *si = &p->slot_info[4 * slot++];
                    si[0] = nc, si[1] = k, si[2] = i1, si[3] = row;
                }
                nc++;
            }
        } else {
            for (int i1 = 0; i1 < n1; i1++) {
                gd_sweep_chain *ch = &p->chains[nc];
                ch->branch = GD_BRANCH_INDEPENDENT;
                ch->row = row;
                ch->first = slot;
                ch->count = 1;
                int *si = &p->slot_info[4 * slot++];
                si[0] = nc, si[1] = 0, si[2] = i1, si[3] = row;
                nc++;
            }
        }
    }
    return GD_OK;
}

void gd_state_names(const gd_model *m, char name[][16])
{
    for (int j = 0; j < m->ndof; j++) {
        snprintf(name[j], 16, "%s", m->dof_name[j]);
        snprintf(name[m->ndof + j], 16, "%s_dot", m->dof_name[j]);
    }
}

/* The model's state size, its names and the responses, from the base case's model. */
static gd_status plan_model(const gd_case *c, gd_sweep_plan *p, gd_error *err)
{
    gd_model m;
    gd_status st = gd_model_build(c, &m, err);
    if (st != GD_OK)
        return st;
    p->n = m.n;
    p->nclear = m.nclear;
    p->nmesh = m.nmesh;
    gd_state_names(&m, p->state_name);
    char bad[700];
    if (parse_responses(c->sweep_response, &m, p->resp, &p->nresp, bad, sizeof bad) != GD_OK) {
        char w[GD_PATH_MAX + 32];
        gd_case_key_where(c, "sweep", "response", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.response: %s", w, bad);
    }
    return GD_OK;
}

/* Every grid point resolves and builds: refuse now rather than fail points later. */
static gd_status plan_check_points(const gd_case *c, const gd_sweep_plan *p, gd_error *err)
{
    for (int i2 = 0; i2 < p->npoints[1]; i2++)
        for (int i1 = 0; i1 < p->npoints[0]; i1++) {
            gd_case pc;
            gd_model pm;
            gd_status st = point_case(c, p, i1, i2, &pc, &pm, err);
            if (st != GD_OK) {
                if (st != GD_ERR_NOMEM) {
                    char w[GD_PATH_MAX + 32];
                    gd_case_key_where(c, "sweep", "parameter", w, sizeof w);
                    gd_error_prefix(err, "%s: sweep.parameter", w);
                }
                return st;
            }
            gd_case_free(&pc);
        }
    return GD_OK;
}

GD_API gd_status gd_sweep_plan_create(const gd_case *c, gd_sweep_plan *p, gd_error *err)
{
    memset(p, 0, sizeof *p);
    gd_status st = gd_sweep_check_case(c, err);
    if (st != GD_OK)
        return st;
    p->naxes = c->sweep_parameter2[0] ? 2 : 1;
    p->mode = c->sweep_mode;
    p->direction = c->sweep_direction;
    if ((st = plan_grid(c, p, err)) == GD_OK && (st = plan_chains(c, p, err)) == GD_OK &&
        (st = plan_model(c, p, err)) == GD_OK) {
        p->npoincare = (long)c->record_periods + 1;
        p->periodicity_tol = c->periodicity_tol;
        p->fingerprint = fingerprint(c);
        st = plan_check_points(c, p, err);
    }
    if (st != GD_OK)
        gd_sweep_plan_free(p);
    return st;
}

GD_API gd_status gd_sweep_points_create(const gd_sweep_plan *p, gd_sweep_point **pts, gd_error *err)
{
    gd_sweep_point *a = calloc((size_t)p->nslots, sizeof *a);
    if (!a)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for %d sweep points", p->nslots);
    for (int s = 0; s < p->nslots; s++) {
        const int *si = &p->slot_info[4 * s];
        a[s].slot = s;
        a[s].chain = si[0];
        a[s].pos = si[1];
        a[s].branch = p->chains[si[0]].branch;
        a[s].idx[0] = si[2];
        a[s].idx[1] = si[3];
        a[s].value[0] = p->values[0][si[2]];
        a[s].value[1] = p->naxes > 1 ? p->values[1][si[3]] : 0.0;
        gd_sweep_point_clear(&a[s]);
    }
    *pts = a;
    return GD_OK;
}

double gd_sweep_point_dlf(const gd_sweep_point *pt)
{
    return fmax(pt->dynamic_load_factor[0], pt->dynamic_load_factor[1]);
}

void gd_sweep_point_clear(gd_sweep_point *pt)
{
    free(pt->poincare);
    pt->poincare = NULL;
    pt->npoincare = 0;
    pt->status = GD_POINT_PENDING;
    pt->error_code = 0;
    pt->error[0] = '\0';
    pt->motion[0] = '\0';
    for (int i = 0; i < 3; i++) {
        pt->rms_accel_mps2[i] = NAN;
        pt->impact_regime[i] = 0;
    }
    pt->dynamic_load_factor[0] = pt->dynamic_load_factor[1] = NAN;
    pt->mle_per_period = pt->mle_per_s = NAN;
    pt->period_n = pt->poincare_distinct = 0;
    pt->steps = pt->rhs_evals = pt->events = 0;
    pt->wall_s = 0;
    memset(pt->y_final, 0, sizeof pt->y_final);
    memset(&pt->md_final, 0, sizeof pt->md_final);
}

GD_API void gd_sweep_points_free(const gd_sweep_plan *p, gd_sweep_point *pts)
{
    if (!pts)
        return;
    for (int s = 0; s < p->nslots; s++)
        free(pts[s].poincare);
    free(pts);
}

GD_API int gd_sweep_pending(const gd_sweep_plan *p, const gd_sweep_point *pts)
{
    int n = 0;
    for (int s = 0; s < p->nslots; s++)
        n += pts[s].status == GD_POINT_PENDING;
    return n;
}

/* ---- hysteresis ---- */

/* Whether every point of the settled half of a's Poincare samples lies within tol (relative to
 * the orbit's size, 1 + the largest |value| of either) of one of the settled half of b's. */
static int cloud_within(const gd_sweep_point *a, const gd_sweep_point *b, int nresp, double tol)
{
    double scale = 0;
    for (long k = 0; k < a->npoincare * nresp; k++)
        scale = fmax(scale, fabs(a->poincare[k]));
    for (long k = 0; k < b->npoincare * nresp; k++)
        scale = fmax(scale, fabs(b->poincare[k]));
    scale += 1.0;
    for (long i = a->npoincare / 2; i < a->npoincare; i++) {
        int near = 0;
        for (long j = b->npoincare / 2; j < b->npoincare && !near; j++) {
            double d = 0;
            for (int r = 0; r < nresp; r++)
                d = fmax(d, fabs(a->poincare[i * nresp + r] - b->poincare[j * nresp + r]));
            near = d <= tol * scale;
        }
        if (!near)
            return 0;
    }
    return 1;
}

/* Whether the up point u and the down point d at one grid value are two different motions: both
 * done, and the combined RMS acceleration differs by more than 5 % of the larger, or the motion
 * class differs and the Poincare points do not coincide (one orbit classed twice, one point still
 * converging to it, is one motion). */
static int branches_differ(const gd_sweep_plan *p, const gd_sweep_point *u, const gd_sweep_point *d)
{
    if (u->status != GD_POINT_DONE || d->status != GD_POINT_DONE)
        return 0;
    double a = u->rms_accel_mps2[2], b = d->rms_accel_mps2[2];
    if (fabs(a - b) > 0.05 * fmax(fabs(a), fabs(b)))
        return 1;
    if (strcmp(u->motion, d->motion) == 0)
        return 0;
    if (!u->poincare || !d->poincare || u->npoincare < 2 || d->npoincare < 2 || p->nresp < 1)
        return 1;
    double tol = 10.0 * (p->periodicity_tol > 0 ? p->periodicity_tol : 1e-6);
    return !(cloud_within(u, d, p->nresp, tol) && cloud_within(d, u, p->nresp, tol));
}

/* The intervals of one row (chains cu up, cd down), appended to iv[*niv..]. su, sd: scratch
 * of npoints[0] slots each, the slot of every grid index on either branch. */
static void row_hysteresis(const gd_sweep_plan *p, const gd_sweep_point *pts, const gd_sweep_chain *cu,
                           const gd_sweep_chain *cd, int *su, int *sd, gd_sweep_interval *iv, int *niv)
{
    int n1 = p->npoints[0];
    int ascending = p->values[0][0] <= p->values[0][n1 - 1];
    for (int k = 0; k < n1; k++) {
        su[pts[cu->first + k].idx[0]] = cu->first + k;
        sd[pts[cd->first + k].idx[0]] = cd->first + k;
    }
    /* walk the grid in increasing parameter order; an interval closes at the first equal point */
    int start = -1;
    for (int q = 0; q <= n1; q++) {
        int i = q < n1 ? (ascending ? q : n1 - 1 - q) : -1;
        int d = q < n1 && branches_differ(p, &pts[su[i]], &pts[sd[i]]);
        if (d && start < 0)
            start = q;
        if (!d && start >= 0) {
            gd_sweep_interval *h = &iv[(*niv)++];
            h->row = cu->row;
            h->from = ascending ? start : n1 - 1 - start;
            h->to = ascending ? q - 1 : n1 - q;
            h->points = q - start;
            start = -1;
        }
    }
}

GD_API gd_status gd_sweep_hysteresis(const gd_sweep_plan *p, const gd_sweep_point *pts, gd_sweep_interval **iv,
                                     int *niv, gd_error *err)
{
    *iv = NULL;
    *niv = 0;
    if (p->mode != GD_SWEEP_CONTINUATION || p->direction != GD_SWEEP_BOTH || p->nchains < 2)
        return GD_OK;
    int n1 = p->npoints[0];
    /* at most one interval per two grid points of each pair of chains */
    size_t cap = (size_t)(p->nchains / 2) * (size_t)((n1 + 1) / 2);
    gd_sweep_interval *out = malloc(sizeof *out * cap);
    int *su = malloc(sizeof(int) * (size_t)n1), *sd = malloc(sizeof(int) * (size_t)n1);
    if (!out || !su || !sd) {
        free(out);
        free(su);
        free(sd);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the hysteresis intervals");
    }
    int n = 0;
    for (int ch = 0; ch + 1 < p->nchains; ch += 2)
        row_hysteresis(p, pts, &p->chains[ch], &p->chains[ch + 1], su, sd, out, &n);
    free(su);
    free(sd);
    if (n == 0) {
        free(out);
        out = NULL;
    }
    *iv = out;
    *niv = n;
    return GD_OK;
}

static gd_status point_case(const gd_case *base, const gd_sweep_plan *p, int i1, int i2, gd_case *out, gd_model *m,
                            gd_error *err)
{
    gd_status st = gd_case_copy(out, base, err);
    if (st != GD_OK)
        return st;
    out->analysis = GD_ANALYSIS_RESPONSE; /* the copy is one response run */
    int idx[2] = {i1, i2};
    char at[600] = "";
    for (int a = 0; a < p->naxes; a++) {
        size_t u = strlen(at);
        snprintf(at + u, sizeof at - u, "%s%s = %.10g", a ? ", " : "at ", p->parameter[a], p->values[a][idx[a]]);
    }
    size_t nkeys;
    const gd_keyspec *schema = gd_case_schema(&nkeys);
    for (int a = 0; a < p->naxes && st == GD_OK; a++) {
        st = gd_case_set_number(out, p->parameter[a], p->values[a][idx[a]], err);
        /* the swept key is given where sweep.parameter is (what messages name) */
        const gd_keyspec *k = gd_case_key_dotted(p->parameter[a]);
        size_t from = gd_case_key_index("sweep", a ? "parameter2" : "parameter");
        if (st == GD_OK && k) {
            out->src[k - schema] = base->src[from] == GD_SRC_FILE ? GD_SRC_FILE : GD_SRC_SET;
            out->src_line[k - schema] = base->src_line[from];
        }
    }
    /* resolved as gd_case_resolve resolves a response (which has no checks of its own) */
    if (st == GD_OK)
        st = gd_case_check(out, err);
    if (st == GD_OK)
        st = gd_scene_resolve(out, err);
    if (st == GD_OK)
        st = gd_model_build(out, m, err);
    if (st != GD_OK) {
        gd_error_prefix(err, "%s", at);
        gd_case_free(out);
    }
    return st;
}

GD_API gd_status gd_sweep_point_case(const gd_case *base, const gd_sweep_plan *p, int slot, gd_case *out,
                                     gd_model *m, gd_error *err)
{
    if (slot < 0 || slot >= p->nslots)
        return gd_error_set(err, GD_ERR_INPUT, "sweep slot %d (valid: 0 to %d)", slot, p->nslots - 1);
    return point_case(base, p, p->slot_info[4 * slot + 2], p->slot_info[4 * slot + 3], out, m, err);
}

gd_status gd_sweep_start_state(const gd_case *c, const gd_model *m, const gd_sweep_point *prev, double *y0,
                                      gd_modes *md0, gd_error *err)
{
    if (!prev || prev->status != GD_POINT_DONE)
        return gd_initial_state(c, m, y0, md0, err);
    memset(y0, 0, sizeof(double) * GD_MAX_STATE);
    memcpy(y0, prev->y_final, sizeof(double) * (size_t)m->n);
    *md0 = prev->md_final;
    return gd_model_consistent_modes(m, 0.0, y0, md0, err);
}

void gd_sweep_responses(const gd_sweep_plan *p, const gd_model *m, double t_s, const double *y, double *out)
{
    double t = t_s * m->omega_n;
    gd_modes md;
    memset(&md, 0, sizeof md);
    for (int r = 0; r < p->nresp; r++) {
        const gd_sweep_response *rs = &p->resp[r];
        if (rs->kind == GD_RESP_STATE) {
            out[r] = y[rs->index];
        } else {
            double x, xd;
            gd_model_clearance(m, m->mesh_clear[rs->index < m->nmesh ? rs->index : 0], t, y, &md, &x, &xd);
            out[r] = rs->kind == GD_RESP_MESH ? x : xd;
        }
    }
}

/* ---- running ---- */

GD_API void gd_sweep_opts_default(gd_sweep_opts *o)
{
    memset(o, 0, sizeof *o);
    o->nranks = 1;
    gd_response_opts_default(&o->response);
}

typedef struct point_ctx {
    const gd_sweep_plan *p;
    const gd_model *m;
    const gd_sweep_opts *o;
    atomic_int *stop;
    double *pc;
    long count;
} point_ctx;

static int on_poincare(void *user, long period, double t_s, const double *y)
{
    point_ctx *x = user;
    (void)period;
    if (x->count < x->p->npoincare)
        gd_sweep_responses(x->p, x->m, t_s, y, x->pc + x->count * x->p->nresp);
    x->count++;
    return 0;
}

static int on_progress(void *user, long done, long total)
{
    point_ctx *x = user;
    (void)done, (void)total;
    if (atomic_load(x->stop))
        return 1;
    return x->o->should_stop && x->o->should_stop(x->o->user);
}

static int fatal_code(gd_status st)
{
    return st == GD_ERR_NOMEM || st == GD_ERR_INTERNAL || st == GD_ERR_IO || st == GD_ERR_INTERRUPTED;
}

/* Run one point; GD_OK when it is done or failed (recorded in pts[slot]), else an error
 * of the sweep (interrupted, out of memory). */
static gd_status run_point(const gd_case *base, const gd_sweep_plan *p, gd_sweep_point *pts, int slot,
                           const gd_sweep_opts *o, atomic_int *stop, gd_error *err)
{
    gd_sweep_point *pt = &pts[slot];
    const gd_sweep_point *prev = pt->pos > 0 && p->mode == GD_SWEEP_CONTINUATION ? &pts[slot - 1] : NULL;
    gd_sweep_point_clear(pt);
    gd_case c;
    gd_model m;
    gd_error e = {0};
    gd_status st = gd_sweep_point_case(base, p, slot, &c, &m, &e);
    if (st != GD_OK) {
        if (fatal_code(st)) {
            *err = e;
            return st;
        }
        pt->status = GD_POINT_FAILED;
        pt->error_code = st;
        snprintf(pt->error, sizeof pt->error, "%s", e.msg);
        snprintf(pt->motion, sizeof pt->motion, "failed");
        return GD_OK;
    }
    double y0[GD_MAX_STATE];
    gd_modes md0;
    gd_response_result *res = malloc(sizeof *res);
    double *pc = malloc(sizeof(double) * (size_t)p->npoincare * (size_t)p->nresp);
    if (!res || !pc) {
        free(res);
        free(pc);
        gd_case_free(&c);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a sweep point");
    }
    st = gd_sweep_start_state(&c, &m, prev, y0, &md0, &e);
    if (st == GD_OK) {
        gd_response_opts ro = o->response;
        ro.y0 = y0;
        ro.md0 = &md0;
        point_ctx x = {p, &m, o, stop, pc, 0};
        gd_response_hooks hooks = {NULL, on_poincare, NULL, on_progress};
        st = gd_response_run(&c, &m, &ro, &hooks, &x, res, &e);
        if (st == GD_OK && x.count != p->npoincare)
            st = gd_error_set(&e, GD_ERR_INTERNAL, "%ld Poincare points, expected %ld", x.count, p->npoincare);
    }
    gd_case_free(&c);
    if (st != GD_OK && fatal_code(st)) {
        free(res);
        free(pc);
        *err = e;
        return st;
    }
    if (st != GD_OK) {
        free(pc);
        pt->status = GD_POINT_FAILED;
        pt->error_code = st;
        snprintf(pt->error, sizeof pt->error, "%s", e.msg);
        snprintf(pt->motion, sizeof pt->motion, "failed");
        pt->steps = res->stats.steps;
        pt->rhs_evals = res->stats.rhs_evals;
        pt->events = res->stats.events;
        pt->wall_s = res->wall_s;
        free(res);
        return GD_OK;
    }
    pt->status = GD_POINT_DONE;
    for (int i = 0; i < 3; i++) {
        pt->rms_accel_mps2[i] = res->rms_accel_mps2[i];
        pt->impact_regime[i] = res->impact_regime[i];
    }
    pt->dynamic_load_factor[0] = res->dynamic_load_factor[0];
    pt->dynamic_load_factor[1] = res->dynamic_load_factor[1];
    pt->mle_per_period = res->n_lyapunov > 0 ? res->mle_per_period : NAN;
    pt->mle_per_s = res->n_lyapunov > 0 ? res->mle_per_s : NAN;
    snprintf(pt->motion, sizeof pt->motion, "%s", res->motion);
    for (char *q = pt->motion; *q; q++)
        if (*q == ' ' || *q == ',' || *q == '\t')
            *q = '_';
    pt->period_n = res->period_n;
    pt->poincare_distinct = res->poincare_distinct;
    pt->steps = res->stats.steps;
    pt->rhs_evals = res->stats.rhs_evals;
    pt->events = res->stats.events;
    pt->transient_periods = res->transient_periods;
    pt->wall_s = res->wall_s;
    pt->npoincare = p->npoincare;
    pt->poincare = pc;
    memcpy(pt->y_final, res->y_final, sizeof pt->y_final);
    pt->md_final = res->md_final;
    free(res);
    return GD_OK;
}

GD_API gd_status gd_sweep_run(const gd_case *base, const gd_sweep_plan *p, gd_sweep_point *pts,
                              const gd_sweep_opts *o, gd_error *err)
{
    gd_sweep_opts dflt;
    if (!o) {
        gd_sweep_opts_default(&dflt);
        o = &dflt;
    }
    int nranks = o->nranks > 0 ? o->nranks : 1, rank = o->rank;
    int *units = malloc(sizeof(int) * (size_t)(p->nchains > 0 ? p->nchains : 1));
    if (!units)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the sweep");
    int nunits = 0;
    for (int ch = 0; ch < p->nchains; ch++) {
        if (ch % nranks != rank)
            continue;
        const gd_sweep_chain *c = &p->chains[ch];
        int pending = 0;
        for (int k = 0; k < c->count; k++)
            pending |= pts[c->first + k].status == GD_POINT_PENDING;
        if (pending)
            units[nunits++] = ch;
    }
    atomic_int stop = 0;
    /* (a mutex, not a named omp critical: that would export a symbol without the gd_ prefix) */
    pthread_mutex_t done_lock = PTHREAD_MUTEX_INITIALIZER, fatal_lock = PTHREAD_MUTEX_INITIALIZER;
    gd_status fatal = GD_OK;
    gd_error fatal_err = {0};
    int nt = 1;
#ifdef _OPENMP
    nt = o->threads > 0 ? o->threads : omp_get_max_threads();
#endif
    if (nt > nunits)
        nt = nunits > 0 ? nunits : 1;
#pragma omp parallel for schedule(dynamic, 1) num_threads(nt)
    for (int u = 0; u < nunits; u++) {
        const gd_sweep_chain *ch = &p->chains[units[u]];
        for (int k = 0; k < ch->count; k++) {
            if (atomic_load(&stop))
                break;
            int slot = ch->first + k;
            if (pts[slot].status != GD_POINT_PENDING)
                continue;
            gd_error e = {0};
            gd_status st = run_point(base, p, pts, slot, o, &stop, &e);
            if (st == GD_OK && o->point_done) {
                pthread_mutex_lock(&done_lock);
                st = o->point_done(o->user, p, &pts[slot], &e);
                pthread_mutex_unlock(&done_lock);
            }
            if (st != GD_OK) {
                pthread_mutex_lock(&fatal_lock);
                if (fatal == GD_OK || (fatal == GD_ERR_INTERRUPTED && st != GD_ERR_INTERRUPTED)) {
                    fatal = st;
                    fatal_err = e;
                }
                pthread_mutex_unlock(&fatal_lock);
                atomic_store(&stop, 1);
                if (st == GD_ERR_INTERRUPTED)
                    gd_sweep_point_clear(&pts[slot]);
                break;
            }
        }
    }
    free(units);
    pthread_mutex_destroy(&done_lock);
    pthread_mutex_destroy(&fatal_lock);
    if (fatal != GD_OK) {
        if (err)
            *err = fatal_err;
        if (fatal == GD_ERR_INTERRUPTED)
            return gd_error_set(err, GD_ERR_INTERRUPTED, "sweep interrupted");
        return fatal;
    }
    return GD_OK;
}
