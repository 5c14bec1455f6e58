/* The stroboscopic map of a whole number of mesh periods and its Jacobian, the monodromy matrix:
 * one fresh integrator from t = 0 (the excitation is periodic in the mesh period, so every
 * segment of a multiple-shooting orbit starts there), with the tangent vectors set to the
 * identity and carried without renormalisation through every event and its saltation matrix
 * (sim_events.c). docs/continuation.md derives it. gd_sim_orbit_gaps runs the same orbit plain
 * with the gap watch on (sim_events.c). */
#include "sim_internal.h"
#include "sim_probe.h"
#include "../core/hash.h"

#include <string.h>

/* A simulation from y0 at t = 0 with its modes consistent with y0 (from the state when events are not
 * located) and n_tangent tangent vectors. */
static gd_status sim_from(const gd_model *m, const gd_solver_opts *o, const double *y0, int n_tangent, gd_sim **s,
                          gd_error *err)
{
    gd_solver_opts oo = *o;
    oo.n_tangent = n_tangent;
    gd_modes md;
    memset(&md, 0, sizeof md);
    md.from_state = !o->root_finding;
    gd_status status = gd_model_consistent_modes(m, 0.0, y0, &md, err);
    *s = NULL;
    return status == GD_OK ? gd_sim_create(m, &oo, y0, &md, s, err) : status;
}

GD_API gd_status gd_sim_period_map(const gd_model *m, const gd_solver_opts *o, const double *y0, int nper,
                                   double *y1, double *M, gd_sim_stats *st, gd_error *err)
{
    if (nper < 1)
        return gd_error_set(err, GD_ERR_INPUT, "a map of %d mesh periods (valid: 1 or more)", nper);
    if (M && !o->root_finding && m->nclear > 0)
        return gd_error_set(err, GD_ERR_INPUT, "the monodromy matrix needs root finding (solver.root_finding = on): "
                            "without located events there is no saltation matrix at a contact change");
    gd_sim *s = NULL;
    gd_status status = sim_from(m, o, y0, M ? m->n : 0, &s, err);
    if (status == GD_OK && M) {
        double I[GD_MAX_STATE * GD_MAX_STATE] = {0};
        for (int i = 0; i < m->n; i++)
            I[i * m->n + i] = 1.0;
        status = gd_sim_set_tangent(s, I, err);
    }
    for (int p = 0; p < nper && status == GD_OK; p++)
        status = gd_sim_period(s, err);
    if (status == GD_OK) {
        memcpy(y1, gd_sim_state(s), sizeof(double) * (size_t)m->n);
        if (M)
            gd_sim_get_tangent(s, M);
        if (st)
            gd_sim_get_stats(s, st);
    }
    gd_sim_free(s);
    return status;
}

GD_API gd_status gd_sim_orbit_gaps(const gd_model *m, const gd_solver_opts *o, const double *y0, int nper,
                                   gd_gap_extrema *g, gd_error *err)
{
    if (nper < 1)
        return gd_error_set(err, GD_ERR_INPUT, "a run of %d mesh periods (valid: 1 or more)", nper);
    gd_sim *s = NULL;
    gd_status status = sim_from(m, o, y0, 0, &s, err);
    if (status == GD_OK)
        gd_sim_watch_gaps(s, g);
    for (int p = 0; p < nper && status == GD_OK; p++)
        status = gd_sim_period(s, err);
    gd_sim_free(s);
    return status;
}

/* the event hook of gd_sim_map_probe: the counts of the fingerprint */
static int probe_event(gd_sim *s, const gd_event *ev, void *user)
{
    (void)s;
    gd_map_probe *pr = user;
    if (ev->kind >= 0 && ev->kind < GD_EV_NKINDS)
        pr->kcount[ev->clearance][ev->kind]++;
    pr->nevents++;
    pr->events[ev->clearance]++;
    return 0;
}

gd_status gd_sim_map_probe(const gd_model *m, const gd_solver_opts *o, const double *y0, int nper, gd_map_probe *pr,
                           gd_error *err)
{
    const int n = m->n, k = pr->ntan;
    if (nper < 1)
        return gd_error_set(err, GD_ERR_INPUT, "a map of %d mesh periods (valid: 1 or more)", nper);
    if (k < 0 || k > n || (!pr->V && k != 0 && k != n))
        return gd_error_set(err, GD_ERR_INPUT, "%d tangent vectors without their directions (valid: 0, or %d for the "
                            "monodromy)", k, n);
    if (k > 0 && !o->root_finding && m->nclear > 0)
        return gd_error_set(err, GD_ERR_INPUT, "tangent vectors through contact events need root finding "
                            "(solver.root_finding = on)");
    if (pr->t_probe > nper * m->period)
        return gd_error_set(err, GD_ERR_INPUT, "a probe at t = %.9g beyond the run of %d periods", pr->t_probe, nper);
    pr->seq = GD_FNV1A_OFFSET_BASIS;
    pr->nevents = 0;
    memset(pr->events, 0, sizeof pr->events);
    memset(pr->kcount, 0, sizeof pr->kcount);
    gd_solver_opts oo = *o;
    oo.n_tangent = k;
    gd_modes md;
    memset(&md, 0, sizeof md);
    md.from_state = !o->root_finding;
    gd_status status = gd_model_consistent_modes(m, 0.0, y0, &md, err);
    if (status == GD_OK && pr->hold.on && (pr->hold.t0 <= 0.0 || pr->hold.t0 > pr->hold.t1) && pr->hold.t1 >= 0.0)
        md.mode[pr->hold.clearance] = pr->hold.mode;
    gd_sim *s = NULL;
    if (status == GD_OK)
        status = gd_sim_create(m, &oo, y0, &md, &s, err);
    if (status == GD_OK && pr->hold.on) {
        s->hold_on = 1;
        s->hold_clear = pr->hold.clearance;
        s->hold_root = 2 * pr->hold.clearance + (pr->hold.side ? 1 : 0);
        s->hold_t0 = pr->hold.t0;
        s->hold_t1 = pr->hold.t1;
    }
    if (status == GD_OK && k > 0) {
        double I[GD_MAX_STATE * GD_MAX_STATE] = {0};
        if (!pr->V)
            for (int i = 0; i < n; i++)
                I[i * n + i] = 1.0;
        status = gd_sim_set_tangent(s, pr->V ? pr->V : I, err);
    }
    if (status == GD_OK) {
        gd_sim_set_hooks(s, NULL, probe_event, pr);
        if (pr->gaps)
            gd_sim_watch_gaps(s, pr->gaps);
    }
    int probed = !(pr->t_probe >= 0);
    for (int p = 0; p < nper && status == GD_OK; p++) {
        double tend = (p + 1) * m->period;
        if (!probed && pr->t_probe <= tend) {
            if (pr->t_probe > p * m->period)
                status = gd_sim_advance_to(s, pr->t_probe, err);
            if (status == GD_OK) {
                memcpy(pr->yp, gd_sim_state(s), sizeof(double) * (size_t)n);
                if (k > 0)
                    gd_sim_get_tangent(s, pr->Tp);
                pr->mdp = *gd_sim_modes(s);
            }
            probed = 1;
        }
        if (status == GD_OK)
            status = gd_sim_period(s, err);
    }
    if (status == GD_OK) {
        memcpy(pr->y1, gd_sim_state(s), sizeof(double) * (size_t)n);
        if (k > 0)
            gd_sim_get_tangent(s, pr->T1);
        pr->seq = gd_fnv1a(pr->seq, pr->kcount, sizeof pr->kcount);
    }
    gd_sim_free(s);
    return status;
}
