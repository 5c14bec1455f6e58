/* The `response` analysis of one operating point. */
#include "geardyn/gd_response.h"
#include "geardyn/gd_scene.h"
#include "../core/clock.h"
#include "../dynamics/model_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

GD_API const char *gd_impact_regime_name(int regime)
{
    static const char *names[] = {"no-impact", "single-sided", "double-sided"};
    return regime >= 0 && regime <= 2 ? names[regime] : "?";
}

GD_API void gd_response_opts_default(gd_response_opts *o)
{
    memset(o, 0, sizeof *o);
    o->periodicity_tol = 0; /* 0: the case's run.periodicity_tol */
    o->max_period = 64;
}

GD_API gd_status gd_initial_state(const gd_case *c, const gd_model *m, double *y, gd_modes *md, gd_error *err)
{
    memset(md, 0, sizeof *md);
    memset(y, 0, sizeof(double) * GD_MAX_STATE);
    if (c->initial_condition == GD_INIT_STATIC)
        return gd_model_static_state(m, y, md, err);
    return gd_model_consistent_modes(m, 0.0, y, md, err);
}

typedef struct run_ctx {
    const gd_model *m;
    const gd_response_hooks *hooks;
    void *user;
    double t_record;         /* dimensionless time where recording starts */
    double dt_sample;
    long next_sample;        /* index of the next uniform sample */
    long nsamples;           /* total samples in the window */
    /* accumulators */
    double sum_a2[3];
    double sum_dte[2], sum_dte2[2], dte_min[2], dte_max[2];
    double lam_min[2], lam_max[2], force_max[2];
    long count;
    int visited[GD_MAX_MESH][3];
    long rec_events, rec_by_kind[GD_EV_NKINDS];
    gd_status st;
    gd_error hook_err;
    double sec;              /* seconds per dimensionless time unit */
    double len_um;           /* micrometres per dimensionless length */
} run_ctx;

static void mesh_quantities(const gd_model *m, double t, double s0, double c0, const double *y, const double *ydot,
                            const gd_modes *md, int j, double *lam, double *lamd, double *acc, double *force)
{
    int c = m->mesh_clear[j];
    const gd_clearance *cl = &m->clear[c];
    double e, ed, edd;
    gd_model_error_sc(m, j, t, s0, c0, md, &e, &ed, &edd); /* as gd_model_error, with sincos(Omega t) given */
    double x = 0, v = 0, a = 0;
    for (int q = 0; q < cl->nw; q++) {
        x += cl->wval[q] * y[cl->widx[q]];
        v += cl->wval[q] * y[m->ndof + cl->widx[q]];
        a += cl->wval[q] * ydot[m->ndof + cl->widx[q]];
    }
    *lam = x - e;
    *lamd = v - ed;
    *acc = a - edd;
    int mode = md->from_state ? gd_model_mode_of(m, c, *lam) : md->mode[c];
    double kf = gd_model_stiffness(m, j, t, md);
    double f = mode > 0 ? cl->k * kf * (*lam - cl->h) : mode < 0 ? cl->k * kf * (*lam + cl->h) : 0.0;
    if (!cl->damp_contact_only || mode != 0)
        f += cl->c * *lamd;
    *force = f + gd_model_pulse_force(m, j, t, md, mode);
}

static int on_step(gd_sim *s, double t0, double t1, void *user)
{
    run_ctx *r = user;
    const gd_model *m = r->m;
    while (r->next_sample < r->nsamples) {
        double ts = r->t_record + (double)r->next_sample * r->dt_sample;
        if (ts > t1)
            break;
        if (ts < t0) { /* only possible for the very first sample, at the window start */
            r->next_sample++;
            continue;
        }
        double y[GD_MAX_STATE], yd[GD_MAX_STATE];
        if (gd_sim_dense(s, ts, y, &r->hook_err) != GD_OK) {
            r->st = r->hook_err.code;
            return 1;
        }
        gd_sim_rhs(s, ts, y, yd);
        /* the integrator's local time differs from ts by whole periods: excitations are periodic */
        gd_sample smp;
        memset(&smp, 0, sizeof smp);
        smp.t_s = ts * r->sec;
        smp.period = (long)floor(ts / m->period + 1e-12);
        smp.y = y;
        const gd_modes *md = gd_sim_modes(s);
        double acc_mean = 0, s0, c0;
        sincos(m->Omega * ts, &s0, &c0); /* one for both meshes */
        double lam = 0, lamd = 0, acc = 0, force = 0;
        for (int j = 0; j < 2; j++) {
            int jj = j < m->nmesh ? j : 0;
            if (j == 0 || jj != 0) /* one mesh (torsional): its quantities serve both columns */
                mesh_quantities(m, ts, s0, c0, y, yd, md, jj, &lam, &lamd, &acc, &force);
            int qidx = m->q_dof[jj];
            smp.lambda_um[j] = lam * r->len_um;
            smp.lambda_dot_mps[j] = lamd * r->len_um * 1e-6 / r->sec;
            smp.accel_mps2[j] = acc * r->len_um * 1e-6 / (r->sec * r->sec);
            smp.force_n[j] = force * m->k_ref * m->bc_m * m->force_share; /* per helical half */
            smp.dte_um[j] = y[qidx] * r->len_um / m->dte_scale;
            acc_mean += 0.5 * smp.accel_mps2[j];
            r->sum_a2[j] += smp.accel_mps2[j] * smp.accel_mps2[j];
            r->sum_dte[j] += smp.dte_um[j];
            r->sum_dte2[j] += smp.dte_um[j] * smp.dte_um[j];
            if (r->count == 0 || smp.dte_um[j] < r->dte_min[j]) r->dte_min[j] = smp.dte_um[j];
            if (r->count == 0 || smp.dte_um[j] > r->dte_max[j]) r->dte_max[j] = smp.dte_um[j];
            if (r->count == 0 || smp.lambda_um[j] < r->lam_min[j]) r->lam_min[j] = smp.lambda_um[j];
            if (r->count == 0 || smp.lambda_um[j] > r->lam_max[j]) r->lam_max[j] = smp.lambda_um[j];
            if (r->count == 0 || smp.force_n[j] > r->force_max[j]) r->force_max[j] = smp.force_n[j];
        }
        r->sum_a2[2] += acc_mean * acc_mean;
        r->count++;
        r->next_sample++;
        if (r->hooks && r->hooks->sample && r->hooks->sample(r->user, &smp))
            return 1;
    }
    return 0;
}

static int on_event(gd_sim *s, const gd_event *ev, void *user)
{
    run_ctx *r = user;
    int recording = ev->t >= r->t_record;
    if (recording) {
        r->rec_events++;
        r->rec_by_kind[ev->kind]++;
        const gd_clearance *cl = &r->m->clear[ev->clearance];
        if (cl->kind == GD_CLR_MESH)
            r->visited[cl->mesh][ev->new_mode + 1] = 1;
    }
    (void)s;
    if (r->hooks && r->hooks->event)
        return r->hooks->event(r->user, ev, recording);
    return 0;
}

/* The adaptive transient (run.transient_max_periods): after run.transient_periods, keep
 * integrating while the stroboscopic points are still converging to a period-n orbit
 * (n <= SETTLE_PMAX) and have not yet settled within the periodicity tolerance.
 * D_p is the largest distance between points p periods apart in the last SETTLE_W points
 * (the measure gd_poincare_period uses). Converging to a period-n orbit, D_p decays
 * geometrically for every multiple p of n and for no other p; so the period is the
 * smallest p whose D_p decays (or is already within the tolerance), judged from D_p now,
 * SETTLE_L/2 and SETTLE_L periods ago. (Taking the smallest D_p instead would stop a
 * slow spiral of a weakly damped mode near 1/p of the mesh frequency at a false period p.)
 * The transient is extended only while that decay reaches the tolerance within the
 * allowed periods; chaotic and quasi-periodic motion does not decay and costs nothing
 * beyond the fixed transient. */
#define SETTLE_PMAX 8
#define SETTLE_W (2 * SETTLE_PMAX + 1)
#define SETTLE_L 32

typedef struct settle_ctx {
    double pts[SETTLE_W][GD_MAX_STATE];
    double dist[SETTLE_L + 1][SETTLE_PMAX + 1];
    long npts, ndist;
    int n;
} settle_ctx;

static void settle_distances(const settle_ctx *sc, double *d)
{
    double scale = 0.0; /* the size of the orbit, as gd_poincare_period measures it */
    for (int k = 0; k < SETTLE_W; k++)
        for (int i = 0; i < sc->n; i++)
            scale = fmax(scale, fabs(sc->pts[k][i]));
    scale += 1.0;
    for (int p = 1; p <= SETTLE_PMAX; p++) {
        d[p] = 0.0;
        for (int k = 0; k < SETTLE_W; k++) /* ring order does not matter for a max over all pairs p apart */
            for (int i = 0; i < sc->n; i++) {
                int kk = (int)((sc->npts - SETTLE_W + k) % SETTLE_W), kp = (int)((sc->npts - SETTLE_W + k + p) % SETTLE_W);
                if (k + p < SETTLE_W)
                    d[p] = fmax(d[p], fabs(sc->pts[kk][i] - sc->pts[kp][i]) / scale);
            }
    }
}

/* Record the state at the end of a transient period; return whether the transient should
 * go on given that `left` more periods are allowed. */
static int settle_extend(settle_ctx *sc, const double *y, double tol, long left)
{
    memcpy(sc->pts[sc->npts % SETTLE_W], y, sizeof(double) * (size_t)sc->n);
    sc->npts++;
    if (sc->npts < SETTLE_W)
        return left > 0;
    double *d = sc->dist[sc->ndist % (SETTLE_L + 1)];
    settle_distances(sc, d);
    sc->ndist++;
    if (left <= 0)
        return 0;
    if (sc->ndist <= SETTLE_L)
        return 1; /* not yet enough history to judge the decay */
    const double *dh = sc->dist[(sc->ndist - 1 - SETTLE_L / 2) % (SETTLE_L + 1)];
    const double *d0 = sc->dist[(sc->ndist - 1 - SETTLE_L) % (SETTLE_L + 1)];
    for (int p = 1; p <= SETTLE_PMAX; p++) {
        if (d[p] <= tol)
            return 0; /* settled on period p */
        double r1 = log(dh[p] / d0[p]) / (SETTLE_L / 2), r2 = log(d[p] / dh[p]) / (SETTLE_L / 2);
        if (r1 < -1e-4 && r2 < -1e-4) /* decaying: converging to a period dividing p */
            return log(tol / d[p]) / fmax(r1, r2) <= (double)left;
    }
    return 0; /* nothing converges: chaotic, quasi-periodic, or a period above SETTLE_PMAX */
}

/* One response run: its simulators, the adaptive transient, the Poincare points of the
 * window and the two-trajectory exponent's sum. */
typedef struct resp_run {
    const gd_case *c;
    const gd_model *m;
    const gd_response_hooks *hooks;
    void *user;
    gd_solver_opts so;
    gd_sim *s, *s2;          /* the trajectory and its two-trajectory companion (or NULL) */
    settle_ctx *sc;          /* the adaptive transient (or NULL) */
    double *pts;             /* the Poincare points of the window */
    long npts;
    long ntrans, max_trans, total;
    double ptol, d0, lsum, lt0;
    run_ctx r;
} resp_run;

/* The companion trajectory of the two-trajectory exponent: displaced by d0 along a fixed
 * generic direction. */
static gd_status companion_create(const gd_model *m, const gd_solver_opts *so, const double *y0,
                                  const gd_modes *md0, double d0, gd_sim **s2, gd_error *err)
{
    double y2[GD_MAX_STATE], nrm = 0;
    for (int i = 0; i < m->n; i++) {
        y2[i] = sin(1.0 + 2.3 * i);
        nrm += y2[i] * y2[i];
    }
    for (int i = 0; i < m->n; i++)
        y2[i] = y0[i] + d0 * y2[i] / sqrt(nrm);
    gd_modes md2 = *md0;
    gd_status st = gd_model_consistent_modes(m, 0.0, y2, &md2, err);
    if (st == GD_OK)
        st = gd_sim_create(m, so, y2, &md2, s2, err);
    return st;
}

/* The simulators from the start state (opts->y0 or the case's), the sampling of the window
 * and the buffers. Nothing to free on failure. */
static gd_status response_setup(resp_run *x, const gd_response_opts *opts, gd_error *err)
{
    const gd_case *c = x->c;
    const gd_model *m = x->m;
    double y0[GD_MAX_STATE];
    gd_modes md0;
    gd_status st;
    if (opts->y0) {
        memcpy(y0, opts->y0, sizeof(double) * (size_t)m->n);
        md0 = *opts->md0;
    } else if ((st = gd_initial_state(c, m, y0, &md0, err)) != GD_OK)
        return st;
    gd_solver_opts_from_case(c, &x->so);
    int two = c->lyapunov_exponents > 0 && c->lyapunov_method == GD_LYAP_TWO_TRAJECTORY;
    x->so.n_tangent = two ? 0 : (c->lyapunov_exponents < m->n ? c->lyapunov_exponents : m->n);
    if ((st = gd_sim_create(m, &x->so, y0, &md0, &x->s, err)) != GD_OK)
        return st;
    x->d0 = c->lyapunov_separation;
    if (two && (st = companion_create(m, &x->so, y0, &md0, x->d0, &x->s2, err)) != GD_OK) {
        gd_sim_free(x->s);
        return st;
    }
    x->r.m = m;
    x->r.hooks = x->hooks;
    x->r.user = x->user;
    x->ntrans = c->transient_periods;
    x->max_trans = c->transient_max_periods > x->ntrans ? c->transient_max_periods : x->ntrans;
    x->ptol = opts->periodicity_tol > 0 ? opts->periodicity_tol : c->periodicity_tol;
    if (x->max_trans > x->ntrans && !(x->sc = calloc(1, sizeof *x->sc))) {
        gd_sim_free(x->s);
        gd_sim_free(x->s2);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the adaptive transient");
    }
    if (x->sc)
        x->sc->n = m->n;
    x->r.t_record = (double)x->ntrans * m->period;
    x->r.dt_sample = m->period / c->samples_per_period;
    x->r.nsamples = (long)c->record_periods * c->samples_per_period;
    x->r.sec = 1.0 / m->omega_n;
    x->r.len_um = m->bc_m * 1e6;
    gd_sim_set_hooks(x->s, on_step, on_event, &x->r);
    x->total = x->ntrans + c->record_periods;
    x->pts = malloc(sizeof(double) * (size_t)m->n * (size_t)(c->record_periods + 1));
    if (!x->pts) {
        free(x->sc);
        gd_sim_free(x->s);
        gd_sim_free(x->s2);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for %d Poincare points", c->record_periods);
    }
    return GD_OK;
}

/* Keep the state at the end of period k (the window's Poincare point) and hand it to the hook. */
static gd_status window_point(resp_run *x, long k, gd_error *err)
{
    const double *y = gd_sim_state(x->s);
    memcpy(x->pts + x->npts * x->m->n, y, sizeof(double) * (size_t)x->m->n);
    x->npts++;
    if (x->hooks && x->hooks->poincare && x->hooks->poincare(x->user, k, gd_sim_time(x->s) * x->r.sec, y))
        return gd_error_set(err, GD_ERR_INTERRUPTED, "stopped by the Poincare hook");
    return GD_OK;
}

/* The start of the recorded window (after period k = ntrans - 1): the exponents start, the
 * contact modes held now count as visited, the first Poincare point and the first sample. */
static gd_status window_open(resp_run *x, long k, gd_error *err)
{
    const gd_model *m = x->m;
    gd_sim *s = x->s;
    if (x->so.n_tangent > 0)
        gd_sim_lyapunov_start(s);
    x->lsum = 0.0;
    x->lt0 = gd_sim_time(s);
    const gd_modes *md = gd_sim_modes(s);
    for (int j = 0; j < m->nmesh; j++)
        x->r.visited[j][md->mode[m->mesh_clear[j]] + 1] = 1;
    gd_status st = window_point(x, k, err);
    if (st != GD_OK)
        return st;
    /* the sample at the very start of the window */
    on_step(s, gd_sim_time(s), gd_sim_time(s), &x->r);
    if (x->c->exact_samples) /* samples on step ends: the method's states, not the interpolant's */
        gd_sim_set_sample_grid(s, x->r.t_record, x->r.dt_sample);
    return GD_OK;
}

/* Period k of the companion trajectory: its separation from the trajectory (summed in the
 * window), then renormalised to d0 along the same direction. */
static gd_status companion_period(resp_run *x, long k, gd_error *err)
{
    const gd_model *m = x->m;
    gd_status st = gd_sim_period(x->s2, err);
    if (st != GD_OK) {
        gd_error_prefix(err, "two-trajectory Lyapunov exponent, companion trajectory");
        return st;
    }
    const double *ya = gd_sim_state(x->s), *yb = gd_sim_state(x->s2);
    double d = 0, y2[GD_MAX_STATE];
    for (int i = 0; i < m->n; i++)
        d += (yb[i] - ya[i]) * (yb[i] - ya[i]);
    d = sqrt(d);
    if (!(d > 0) || !isfinite(d))
        return gd_error_set(err, GD_ERR_SOLVER, "two-trajectory Lyapunov exponent: the trajectories %s",
                            d > 0 ? "diverged" : "coincide");
    if (k >= x->ntrans)
        x->lsum += log(d / x->d0);
    for (int i = 0; i < m->n; i++)
        y2[i] = ya[i] + (yb[i] - ya[i]) * x->d0 / d;
    return gd_sim_set_state(x->s2, y2, err);
}

/* Integrate the transient (extended while the section still converges) and the window. */
static gd_status response_periods(resp_run *x, gd_error *err)
{
    gd_status st = GD_OK;
    for (long k = 0; k < x->total; k++) {
        if (k == x->ntrans && (st = window_open(x, k, err)) != GD_OK)
            return st;
        st = gd_sim_period(x->s, err);
        if (st != GD_OK) {
            if (x->r.st != GD_OK) {
                st = x->r.st;
                if (err)
                    *err = x->r.hook_err;
            }
            return st;
        }
        if (x->s2 && (st = companion_period(x, k, err)) != GD_OK)
            return st;
        if (k < x->ntrans && x->sc &&
            settle_extend(x->sc, gd_sim_state(x->s), x->ptol, k + 1 < x->ntrans ? 1 : x->max_trans - x->ntrans) &&
            k + 1 == x->ntrans) {
            x->ntrans++; /* one more transient period: the section is still converging */
            x->total++;
            x->r.t_record = (double)x->ntrans * x->m->period;
        }
        if (k >= x->ntrans && (st = window_point(x, k + 1, err)) != GD_OK)
            return st;
        if (x->hooks && x->hooks->progress && x->hooks->progress(x->user, k + 1, x->total))
            return gd_error_set(err, GD_ERR_INTERRUPTED, "interrupted");
    }
    return st;
}

/* The results of a completed run from the accumulators, the Poincare points and the
 * exponents. */
static void response_results(const resp_run *x, const gd_response_opts *opts, gd_response_result *res)
{
    const gd_model *m = x->m;
    const run_ctx *r = &x->r;
    double nrm = r->count > 0 ? 1.0 / (double)r->count : 0.0;
    for (int i = 0; i < 3; i++)
        res->rms_accel_mps2[i] = sqrt(r->sum_a2[i] * nrm);
    for (int j = 0; j < 2; j++) {
        double mean = r->sum_dte[j] * nrm;
        res->dte_mean_um[j] = mean;
        res->dte_rms_um[j] = sqrt(fmax(0.0, r->sum_dte2[j] * nrm - mean * mean));
        res->dte_pp_um[j] = r->dte_max[j] - r->dte_min[j];
        res->lambda_min_um[j] = r->lam_min[j];
        res->lambda_max_um[j] = r->lam_max[j];
        res->force_max_n[j] = r->count > 0 ? r->force_max[j] : NAN;
        res->dynamic_load_factor[j] = m->static_load_n > 0 ? res->force_max_n[j] / m->static_load_n : NAN;
    }
    /* the last point closes the window; periodicity is judged over all of them */
    res->poincare_count = x->npts;
    res->transient_periods = x->ntrans;
    res->period_n = gd_poincare_period(x->pts, x->npts, m->n, x->ptol, opts->max_period);
    res->poincare_distinct =
        res->period_n > 0 ? res->period_n : gd_poincare_distinct(x->pts, x->npts, m->n, x->ptol);
    int worst = 0;
    for (int j = 0; j < 2; j++) {
        int jj = j < m->nmesh ? j : 0;
        int reg = r->visited[jj][0] ? GD_IMPACT_DOUBLE : r->visited[jj][1] ? GD_IMPACT_SINGLE : GD_IMPACT_NONE;
        res->impact_regime[j] = reg;
        if (reg > worst)
            worst = reg;
    }
    res->impact_regime[2] = worst;
    res->record_events = r->rec_events;
    memcpy(res->record_events_by_kind, r->rec_by_kind, sizeof r->rec_by_kind);
    if (x->so.n_tangent > 0) {
        res->n_lyapunov = gd_sim_lyapunov(x->s, res->lyapunov, NULL);
    } else if (x->s2) {
        res->n_lyapunov = 1;
        res->lyapunov[0] = x->lsum / (gd_sim_time(x->s) - x->lt0);
    }
    if (res->n_lyapunov > 0) {
        res->mle_per_period = res->lyapunov[0] * m->period;
        res->mle_per_s = res->lyapunov[0] * m->omega_n;
    } else {
        res->mle_per_period = res->mle_per_s = NAN;
    }
    gd_motion_classify(res->period_n, res->n_lyapunov > 0, res->mle_per_period, x->c->chaos_threshold_per_period,
                       res->motion, sizeof res->motion);
    memcpy(res->y_final, gd_sim_state(x->s), sizeof(double) * (size_t)m->n);
    res->md_final = *gd_sim_modes(x->s);
}

GD_API gd_status gd_response_run(const gd_case *c, const gd_model *m, const gd_response_opts *opts,
                                 const gd_response_hooks *hooks, void *user, gd_response_result *res, gd_error *err)
{
    double w0 = gd_clock_wall_s();
    memset(res, 0, sizeof *res);
    gd_response_opts dflt;
    if (!opts) {
        gd_response_opts_default(&dflt);
        opts = &dflt;
    }
    resp_run x;
    memset(&x, 0, sizeof x);
    x.c = c;
    x.m = m;
    x.hooks = hooks;
    x.user = user;
    gd_status st = response_setup(&x, opts, err);
    if (st != GD_OK)
        return st;
    st = response_periods(&x, err);
    if (st == GD_OK)
        response_results(&x, opts, res);
    gd_sim_get_stats(x.s, &res->stats);
    gd_sim_free(x.s);
    gd_sim_free(x.s2);
    free(x.pts);
    free(x.sc);
    res->wall_s = gd_clock_wall_s() - w0;
    return st;
}
