/* The stroboscopic map of a whole number of mesh periods and its Jacobian, the monodromy matrix:
 * one fresh integrator from t = 0 (the excitation is periodic in the mesh period, so every
 * segment of a multiple-shooting orbit starts there), with the tangent vectors set to the
 * identity and carried without renormalisation through every event and its saltation matrix
 * (sim_events.c). docs/continuation.md derives it. gd_sim_orbit_gaps runs the same orbit plain
 * with the gap watch on (sim_events.c). */
#include "sim_internal.h"

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
