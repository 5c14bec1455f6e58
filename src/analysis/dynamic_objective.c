/* The dynamic objective of a flank (include/geardyn/gd_dynobj.h, docs/optimisation.md section 12):
 * at each torque, the period-1 orbit from the attractor at the lowest speed followed in the speed by
 * pseudo-arclength continuation (gd_continue); where it is unstable or the branch is lost, a short
 * sweep of plain integration from the last stable orbit; the largest value of the stable response,
 * refined between branch points by golden section on solved orbits; the peaks combined over the
 * torques. The candidate's flank enters through the case copy's [modification] and
 * [misalignment], so its LTCA stiffness, impact and error excitation are the model's
 * (gd_model_build, through the LTCA cache). */
#include "geardyn/gd_dynobj.h"
#include "geardyn/gd_periodic.h"
#include "geardyn/gd_response.h"
#include "geardyn/gd_scene.h"
#include "../case/case_keys.h"
#include "../core/clock.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const method_names[] = {"continuation", "continuation+sweep", "sweep"};
static const char *const measure_names[] = {"rms_accel", "dte_pp"};

GD_API const char *gd_dyn_method_name(int m) { return m >= 0 && m < 3 ? method_names[m] : NULL; }

GD_API const char *gd_dyn_measure_name(int m) { return m >= 0 && m < 2 ? measure_names[m] : NULL; }

GD_API void gd_dynobj_settings_from_case(const gd_case *c, gd_dynobj_settings *s)
{
    memset(s, 0, sizeof *s);
    s->ntorques = c->n_opt_torques;
    for (int k = 0; k < s->ntorques; k++) {
        s->torques_nm[k] = c->opt_torques_nm[k];
        s->weights[k] = c->n_opt_torque_weights ? c->opt_torque_weights[k] : 1.0;
    }
    s->combine = c->opt_dynamic_combine;
    s->speed_from_rpm = c->opt_speed_from_rpm;
    s->speed_to_rpm = c->opt_speed_to_rpm;
    s->measure = c->opt_dynamic_response;
    s->model = c->opt_dynamic_model;
    s->sweep_step_rpm = c->opt_dynamic_sweep_step_rpm;
    s->transient_periods = c->transient_periods;
    s->record_periods = c->record_periods;
}

/* ---- one torque ------------------------------------------------------------------------------ */

/* The working copy of one torque: the case (changed as the speed moves), the parameter, the
 * integrator options. */
typedef struct dyn_run {
    gd_case c;
    gd_case_param cp;
    gd_solver_opts o;
    const gd_dynobj_settings *s;
    const gd_stop_hook *stop;
    double scale;            /* rpm per unit of the dimensionless mesh frequency */
} dyn_run;

static gd_status add_point(gd_dyn_curve *cv, double speed, double value, int source, int stable, int period_n,
                           gd_error *err)
{
    if (cv->npts == cv->cap) {
        int cap = cv->cap ? 2 * cv->cap : 64;
        gd_dyn_point *p = realloc(cv->pt, sizeof *p * (size_t)cap);
        if (!p)
            return gd_error_set(err, GD_ERR_NOMEM, "dynamic objective: out of memory for the curve");
        cv->pt = p;
        cv->cap = cap;
    }
    cv->pt[cv->npts++] = (gd_dyn_point){speed, value, source, stable, period_n};
    return GD_OK;
}

static gd_status stopped(const dyn_run *r, gd_error *err)
{
    return gd_stop_asked(r->stop) ? gd_error_set(err, GD_ERR_INTERRUPTED, "dynamic objective: stopped") : GD_OK;
}

static int stop_progress(void *user, long done, long total)
{
    (void)done;
    (void)total;
    return gd_stop_asked(user);
}

/* The measure of a response result on a model of nmesh meshes: of a herringbone's two halves the
 * larger. Not the combined acceleration RMS((a_L + a_R) / 2): where the halves vibrate in antiphase
 * it cancels while each mesh does not, and an optimiser finds such flanks (the paper's pair: the
 * combined 5.8 m/s^2 at 5500 rpm, 500 N m, each half 267 and 272, as much as the unmodified pair's). */
static double measure_of(const dyn_run *r, const gd_response_result *rr, int nmesh)
{
    if (r->s->measure == GD_DYN_DTE_PP)
        return nmesh > 1 ? fmax(rr->dte_pp_um[0], rr->dte_pp_um[1]) : rr->dte_pp_um[0];
    return nmesh > 1 ? fmax(rr->rms_accel_mps2[0], rr->rms_accel_mps2[1]) : rr->rms_accel_mps2[0];
}

/* A response run at parameter p from the state y: transient periods, then record periods. The
 * measure, the period found and the final state (at mesh phase 0). */
static gd_status response_at(dyn_run *r, double p, const double *y, int transient, int record, double *value,
                             int *period_n, double *y_final, gd_error *err)
{
    gd_model m;
    gd_status st = gd_model_at_case_key(p, &m, &r->cp, err);
    gd_modes md;
    if (st == GD_OK)
        st = gd_model_consistent_modes(&m, 0.0, y, &md, err);
    if (st != GD_OK)
        return st;
    gd_response_opts ro;
    gd_response_opts_default(&ro);
    ro.y0 = y;
    ro.md0 = &md;
    r->c.transient_periods = transient;
    r->c.transient_max_periods = 0;
    r->c.record_periods = record;
    r->c.lyapunov_exponents = 0;
    gd_response_hooks hooks = {0};
    hooks.progress = stop_progress;
    gd_response_result rr;
    st = gd_response_run(&r->c, &m, &ro, &hooks, (void *)r->stop, &rr, err);
    if (st != GD_OK)
        return st;
    *value = measure_of(r, &rr, m.nmesh);
    if (period_n)
        *period_n = rr.period_n;
    if (y_final)
        memcpy(y_final, rr.y_final, sizeof(double) * (size_t)m.n);
    return GD_OK;
}

/* The measure of the orbit through y at p: one period integrated with samples. */
static gd_status orbit_measure(dyn_run *r, double p, const double *y, double *value, gd_error *err)
{
    return response_at(r, p, y, 0, 1, value, NULL, NULL, err);
}

/* The case of one torque at the lowest speed: the candidate's flank, the torque, the model in the
 * loop, resolved as a response. */
static gd_status prepare(dyn_run *r, const gd_case *base, const gd_pair *pair, double torque, gd_error *err)
{
    gd_status st = gd_case_copy(&r->c, base, err);
    if (st != GD_OK)
        return st;
    gd_case *c = &r->c;
    c->analysis = GD_ANALYSIS_RESPONSE;
    c->model = r->s->model;
    gd_pair_modification_to_case(pair, c);
    c->modification_apply = 1;
    c->axis_in_plane_arcmin = pair->axis_in_plane_arcmin;
    c->axis_cross_plane_arcmin = pair->axis_cross_plane_arcmin;
    c->centre_distance_error_mm = pair->centre_distance_error_mm;
    c->src[gd_case_key_index("operating", "power_kw")] = GD_SRC_DEFAULT; /* the torque is the list's */
    if ((st = gd_case_set_number(c, "operating.torque_nm", torque, err)) != GD_OK ||
        (st = gd_case_set_number(c, "operating.speed_rpm", r->s->speed_from_rpm, err)) != GD_OK ||
        (st = gd_case_check(c, err)) != GD_OK || (st = gd_scene_resolve(c, err)) != GD_OK)
        return st;
    gd_solver_opts_from_case(c, &r->o);
    return GD_OK;
}

/* The speed intervals the stable points of the branch cover: consecutive stable points; *n of them
 * into iv (2 per interval, rpm, increasing), merged. */
static int covered(const gd_branch *br, double scale, double *iv, int cap)
{
    int n = 0;
    for (int i = 0; i < br->npoints; i++) {
        const gd_po *a = &br->pt[i].orbit;
        if (!a->stable)
            continue;
        double lo = a->p * scale, hi = lo;
        if (i + 1 < br->npoints && br->pt[i + 1].orbit.stable) {
            double b = br->pt[i + 1].orbit.p * scale;
            lo = fmin(lo, b);
            hi = fmax(hi, b);
        }
        if (n < cap) {
            iv[2 * n] = lo;
            iv[2 * n + 1] = hi;
            n++;
        }
    }
    /* sort by the lower end and merge */
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && iv[2 * j] < iv[2 * (j - 1)]; j--) {
            double t0 = iv[2 * j], t1 = iv[2 * j + 1];
            iv[2 * j] = iv[2 * (j - 1)];
            iv[2 * j + 1] = iv[2 * (j - 1) + 1];
            iv[2 * (j - 1)] = t0;
            iv[2 * (j - 1) + 1] = t1;
        }
    int m = 0;
    for (int i = 0; i < n; i++) {
        if (m > 0 && iv[2 * i] <= iv[2 * (m - 1) + 1]) {
            iv[2 * (m - 1) + 1] = fmax(iv[2 * (m - 1) + 1], iv[2 * i + 1]);
        } else {
            iv[2 * m] = iv[2 * i];
            iv[2 * m + 1] = iv[2 * i + 1];
            m++;
        }
    }
    return m;
}

/* The stable branch point nearest the speed v (rpm), or -1. */
static int stable_point_at(const gd_branch *br, double scale, double v)
{
    int best = -1;
    double d = INFINITY;
    for (int i = 0; i < br->npoints; i++)
        if (br->pt[i].orbit.stable && fabs(br->pt[i].orbit.p * scale - v) < d) {
            d = fabs(br->pt[i].orbit.p * scale - v);
            best = i;
        }
    return best;
}

/* The short sweep of the gap (a, b) (rpm): grid points k (b - a) / m, the ends included where no
 * stable orbit covers them; from the state y0 (at a), each point from the state the one before ended
 * in. */
static gd_status sweep_gap(dyn_run *r, gd_dyn_curve *cv, double a, double b, int a_covered, int b_covered,
                           const double *y0, int n, gd_error *err)
{
    double h = r->s->sweep_step_rpm > 0 ? r->s->sweep_step_rpm : (r->s->speed_to_rpm - r->s->speed_from_rpm) / 50;
    int m = (int)ceil((b - a) / h - 1e-9);
    if (m < 1)
        m = 1;
    int k0 = a_covered ? 1 : 0, k1 = b_covered ? m - 1 : m;
    if (k1 < k0) { /* a gap narrower than the grid between two covered ends: its middle */
        k0 = k1 = 1;
        m = 2;
    }
    double y[GD_MAX_STATE];
    memcpy(y, y0, sizeof(double) * (size_t)n);
    for (int k = k0; k <= k1; k++) {
        gd_status st = stopped(r, err);
        if (st != GD_OK)
            return st;
        double v = a + (b - a) * k / m, value;
        int pn;
        st = response_at(r, v / r->scale, y, r->s->transient_periods, r->s->record_periods, &value, &pn, y, err);
        if (st != GD_OK)
            return gd_error_prefix(err, "the sweep at %.6g rpm", v);
        if ((st = add_point(cv, v, value, GD_DYN_SWEPT, 1, pn, err)) != GD_OK)
            return st;
        cv->swept_points++;
    }
    cv->swept_rpm += b - a;
    return GD_OK;
}

/* The orbit at p between the branch points i and j (p_i < p < p_j, both stable), solved from their
 * states interpolated linearly in p; its measure, or GD_ERR_SOLVER when shooting fails or the orbit
 * is unstable. */
static gd_status orbit_between(dyn_run *r, const gd_branch *br, int i, int j, const gd_po_opts *po, double p,
                               double *value, gd_error *err)
{
    const gd_po *a = &br->pt[i].orbit, *b = &br->pt[j].orbit;
    double w = (p - a->p) / (b->p - a->p), y[GD_MAX_STATE];
    for (int k = 0; k < a->n; k++)
        y[k] = (1 - w) * a->y[0][k] + w * b->y[0][k];
    gd_model m;
    gd_status st = gd_model_at_case_key(p, &m, &r->cp, err);
    gd_po orbit;
    if (st == GD_OK)
        st = gd_po_solve(&m, &r->o, po, y, &orbit, err);
    if (st == GD_OK && !orbit.stable)
        st = gd_error_set(err, GD_ERR_SOLVER, "unstable");
    if (st == GD_OK)
        st = orbit_measure(r, p, orbit.y[0], value, err);
    return st;
}

/* The largest value between the stable branch points i - 1 and i + 1 around the largest point i:
 * golden section in p on solved orbits (about 12 orbits to 1e-3 of the bracket); every orbit solved
 * is a refined point. A failure leaves the sampled peak. */
static gd_status refine_peak(dyn_run *r, const gd_branch *br, int i, const gd_po_opts *po, gd_dyn_curve *cv,
                             gd_error *err)
{
    double a = br->pt[i - 1].orbit.p, b = br->pt[i + 1].orbit.p;
    if (!(a < br->pt[i].orbit.p && br->pt[i].orbit.p < b))
        return GD_OK; /* a fold nearby: p not monotone */
    const double gr = (sqrt(5.0) - 1) / 2;
    double x1 = b - gr * (b - a), x2 = a + gr * (b - a), f1, f2;
    gd_error e2 = {0};
#define AT(x, f)                                                                                                   \
    do {                                                                                                           \
        gd_status s_ = stopped(r, err);                                                                            \
        if (s_ != GD_OK)                                                                                           \
            return s_;                                                                                             \
        int lo_ = (x) < br->pt[i].orbit.p ? i - 1 : i, hi_ = lo_ + 1;                                              \
        s_ = orbit_between(r, br, lo_, hi_, po, (x), &(f), &e2);                                                   \
        if (s_ == GD_ERR_INTERRUPTED || s_ == GD_ERR_NOMEM)                                                        \
            return s_ == GD_ERR_INTERRUPTED ? gd_error_set(err, s_, "dynamic objective: stopped") : s_;           \
        if (s_ != GD_OK)                                                                                           \
            return GD_OK;                                                                                          \
        if ((s_ = add_point(cv, (x) * r->scale, (f), GD_DYN_REFINED, 1, 1, err)) != GD_OK)                         \
            return s_;                                                                                             \
        cv->refined_points++;                                                                                      \
    } while (0)
    AT(x1, f1);
    AT(x2, f2);
    while (b - a > 1e-3 * (br->pt[i + 1].orbit.p - br->pt[i - 1].orbit.p)) {
        if (f1 > f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - gr * (b - a);
            AT(x1, f1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + gr * (b - a);
            AT(x2, f2);
        }
    }
#undef AT
    return GD_OK;
}

static gd_status one_torque(dyn_run *r, const gd_case *base, const gd_pair *pair, double torque, gd_dyn_curve *cv,
                            gd_error *err)
{
    const gd_dynobj_settings *s = r->s;
    memset(cv, 0, sizeof *cv);
    cv->torque_nm = torque;
    gd_status st = prepare(r, base, pair, torque, err);
    gd_model m0;
    if (st == GD_OK)
        st = gd_model_build(&r->c, &m0, err);
    if (st != GD_OK)
        return st;
    r->scale = s->speed_from_rpm / m0.Omega;
    r->cp = (gd_case_param){&r->c, "operating.speed_rpm", r->scale};
    const int n = m0.n;
    /* the attractor at the lowest speed */
    double y_att[GD_MAX_STATE];
    gd_modes md;
    if ((st = gd_initial_state(&r->c, &m0, y_att, &md, err)) != GD_OK)
        return st;
    if (s->transient_periods > 0 &&
        (st = gd_sim_period_map(&m0, &r->o, y_att, s->transient_periods, y_att, NULL, NULL, err)) != GD_OK)
        return gd_error_prefix(err, "the transient at %g rpm", s->speed_from_rpm);
    /* its period-1 orbit, followed up to the top speed */
    gd_cont_opts co;
    gd_cont_opts_default(&co);
    co.po.nper = 1;
    co.po.multiple = 1;
    co.po.tol = fmax(100 * r->c.rtol, 1e-10);
    co.p_min = s->speed_from_rpm / r->scale;
    co.p_max = s->speed_to_rpm / r->scale;
    co.ds = 1;
    co.ds_min = 1e-6;
    co.ds_max = 20;
    co.dp_max = (s->dp_max_rpm > 0 ? s->dp_max_rpm : (s->speed_to_rpm - s->speed_from_rpm) / 50) / r->scale;
    co.max_points = 400;
    co.direction = 1;
    co.locate_tol = 1e-4;
    if (r->stop)
        co.stop = *r->stop;
    gd_po start;
    gd_branch br = {0};
    gd_error e2 = {0};
    int have_branch = gd_po_solve(&m0, &r->o, &co.po, y_att, &start, &e2) == GD_OK;
    if (have_branch) {
        start.p = m0.Omega;
        st = gd_continue(gd_model_at_case_key, &r->cp, &r->o, &co, &start, &br, &e2);
        if (st == GD_ERR_INTERRUPTED || st == GD_ERR_NOMEM) {
            gd_branch_free(&br);
            if (err)
                *err = e2;
            return st;
        }
        have_branch = st == GD_OK && br.npoints > 0;
        snprintf(cv->branch_end, sizeof cv->branch_end, "%.150s", st == GD_OK ? br.end_reason : e2.msg);
    } else {
        snprintf(cv->branch_end, sizeof cv->branch_end, "no period-1 orbit at the start: %.110s", e2.msg);
    }
    st = GD_OK;
    /* every branch point measured */
    for (int i = 0; have_branch && i < br.npoints && st == GD_OK; i++) {
        double v;
        if ((st = stopped(r, err)) == GD_OK)
            st = orbit_measure(r, br.pt[i].orbit.p, br.pt[i].orbit.y[0], &v, err);
        if (st == GD_OK)
            st = add_point(cv, br.pt[i].orbit.p * r->scale, v, GD_DYN_BRANCH, br.pt[i].orbit.stable,
                           br.pt[i].orbit.nper, err);
    }
    cv->branch_points = have_branch ? br.npoints : 0;
    /* the gaps: the range less what the stable orbits cover */
    double iv[2 * 512];
    int niv = have_branch ? covered(&br, r->scale, iv, 512) : 0;
    double lo = s->speed_from_rpm, hi = s->speed_to_rpm, at = lo;
    int at_covered = 0;
    for (int k = 0; k <= niv && st == GD_OK; k++) {
        double b = k < niv ? iv[2 * k] : hi;
        if (b > at + 1e-9 * (hi - lo)) {
            /* from the stable orbit that ends the covered interval before, or the attractor at the start */
            int from = at_covered ? stable_point_at(&br, r->scale, at) : -1;
            st = sweep_gap(r, cv, at, b, at_covered, k < niv, from >= 0 ? br.pt[from].orbit.y[0] : y_att, n, err);
        }
        if (k < niv && iv[2 * k + 1] > at) {
            at = iv[2 * k + 1];
            at_covered = 1;
        }
    }
    /* the peak of the stable response, refined on the branch */
    if (st == GD_OK) {
        int ip = -1;
        cv->peak = -INFINITY;
        for (int i = 0; i < cv->npts; i++)
            if (cv->pt[i].stable && cv->pt[i].value > cv->peak) {
                cv->peak = cv->pt[i].value;
                cv->peak_speed_rpm = cv->pt[i].speed_rpm;
                ip = i;
            }
        if (ip >= 0 && ip < cv->branch_points && ip > 0 && ip + 1 < cv->branch_points && br.pt[ip - 1].orbit.stable &&
            br.pt[ip + 1].orbit.stable) {
            st = refine_peak(r, &br, ip, &co.po, cv, err);
            for (int i = cv->npts - cv->refined_points; i < cv->npts && st == GD_OK; i++)
                if (cv->pt[i].value > cv->peak) {
                    cv->peak = cv->pt[i].value;
                    cv->peak_speed_rpm = cv->pt[i].speed_rpm;
                }
        }
        if (ip < 0)
            st = gd_error_set(err, GD_ERR_SOLVER, "no stable response found between %g and %g rpm", lo, hi);
    }
    cv->method = !have_branch ? GD_DYN_SWEEP : cv->swept_points > 0 ? GD_DYN_CONT_SWEEP : GD_DYN_CONTINUATION;
    gd_branch_free(&br);
    return st;
}

GD_API void gd_dyn_result_free(gd_dyn_result *r)
{
    if (!r)
        return;
    for (int k = 0; k < r->ntorques; k++)
        free(r->curve[k].pt);
    memset(r, 0, sizeof *r);
}

GD_API gd_status gd_dyn_evaluate(const gd_case *c, const gd_dynobj_settings *s, const gd_pair *pair,
                                 const gd_stop_hook *stop, gd_dyn_result *r, gd_error *err)
{
    memset(r, 0, sizeof *r);
    if (s->ntorques < 1 || s->ntorques > GD_OPT_MAX_TORQUES)
        return gd_error_set(err, GD_ERR_INPUT, "dynamic objective: %d torques (valid: 1 to %d)", s->ntorques,
                            GD_OPT_MAX_TORQUES);
    if (!(s->speed_from_rpm > 0 && s->speed_from_rpm < s->speed_to_rpm))
        return gd_error_set(err, GD_ERR_INPUT, "dynamic objective: speeds %g to %g rpm (valid: 0 < from < to)",
                            s->speed_from_rpm, s->speed_to_rpm);
    double t0 = gd_clock_thread_cpu_s();
    dyn_run run;
    memset(&run, 0, sizeof run);
    run.s = s;
    run.stop = stop;
    gd_status st = GD_OK;
    double peaks[GD_OPT_MAX_TORQUES];
    for (int k = 0; k < s->ntorques && st == GD_OK; k++) {
        st = one_torque(&run, c, pair, s->torques_nm[k], &r->curve[k], err);
        r->ntorques = k + 1;
        gd_case_free(&run.c);
        memset(&run.c, 0, sizeof run.c);
        if (st != GD_OK)
            gd_error_prefix(err, "dynamic objective at %g N m", s->torques_nm[k]);
        peaks[k] = r->curve[k].peak;
    }
    if (st != GD_OK) {
        gd_dyn_result_free(r);
        return st;
    }
    r->value = gd_opt_combine_values(s->combine, s->ntorques, peaks, s->weights);
    r->cpu_s = gd_clock_thread_cpu_s() - t0;
    return GD_OK;
}

/* ---- the gear objective --------------------------------------------------------------------- */

struct gd_dynobj {
    gd_case c;
    gd_dynobj_settings s;
    gd_stop_hook stop;
    int has_stop;
};

static gd_status dynobj_eval(void *state, const gd_pair *pair, double *f, double *aux, gd_error *err)
{
    const gd_dynobj *d = state;
    gd_dyn_result r;
    gd_status st = gd_dyn_evaluate(&d->c, &d->s, pair, d->has_stop ? &d->stop : NULL, &r, err);
    if (st != GD_OK)
        return st;
    *f = r.value;
    for (int k = 0; k < r.ntorques; k++) {
        aux[2 * k] = r.curve[k].peak;
        aux[2 * k + 1] = r.curve[k].method;
    }
    gd_dyn_result_free(&r);
    return GD_OK;
}

GD_API gd_status gd_dynobj_create(const gd_case *c, const gd_dynobj_settings *s, const gd_stop_hook *stop,
                                  gd_dynobj **out, gd_error *err)
{
    *out = NULL;
    gd_dynobj *d = calloc(1, sizeof *d);
    if (!d)
        return gd_error_set(err, GD_ERR_NOMEM, "dynamic objective: out of memory");
    gd_status st = gd_case_copy(&d->c, c, err);
    if (st != GD_OK) {
        free(d);
        return st;
    }
    d->s = *s;
    if (stop) {
        d->stop = *stop;
        d->has_stop = 1;
    }
    *out = d;
    return GD_OK;
}

GD_API void gd_dynobj_free(gd_dynobj *d)
{
    if (!d)
        return;
    gd_case_free(&d->c);
    free(d);
}

/* Every evaluation builds its own case copies (gd_dyn_evaluate), so one gd_dynobj serves every
 * thread: the state is the objective itself. */
GD_API void gd_dynobj_objective(gd_dynobj *d, gd_opt_gear_objective *o)
{
    memset(o, 0, sizeof *o);
    snprintf(o->name, sizeof o->name, "gear-dynamic");
    o->naux = 2 * d->s.ntorques;
    o->eval = dynobj_eval;
    o->user = d;
}
