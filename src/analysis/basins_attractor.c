/* What a trajectory of the basin mapper found (docs/basins.md section 3): its period from the map's
 * last points, the orbit refined by Newton shooting (gd_po_solve: stable, near the points) with its
 * Floquet multipliers, impact regime and deflection extremes; or, when no stable orbit of at most
 * max_period mesh periods is there, the largest Lyapunov exponent over a run on the attractor (the
 * tangent method of the simulator, with the saltation matrices at the events). And whether two
 * attractors are one. */
#include "basins_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

GD_API const char *gd_attractor_kind_name(int kind)
{
    static const char *names[] = {"periodic", "chaotic", "quasi-periodic", "not-periodic"};
    return kind >= 0 && kind < 4 ? names[kind] : "?";
}

void gd_basin_name(gd_attractor *a)
{
    if (a->kind == GD_ATT_PERIODIC)
        snprintf(a->name, sizeof a->name, "period-%d", a->period);
    else
        snprintf(a->name, sizeof a->name, "%s", gd_attractor_kind_name(a->kind));
}

/* The distinct tessellation cells of npts points (n each) into *cells (malloc'd). */
static gd_status cells_of(const gd_basin_mapper *mp, const double *pts, int npts, int **cells, int *ncells,
                          gd_error *err)
{
    *cells = malloc(sizeof(int) * (size_t)(npts > 0 ? npts : 1));
    *ncells = 0;
    if (!*cells)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for an attractor's cells");
    for (int q = 0; q < npts; q++) {
        int c = gd_basin_cell_of(mp, pts + (size_t)q * mp->m.n);
        int dup = c < 0;
        for (int r = 0; r < *ncells && !dup; r++)
            dup = (*cells)[r] == c;
        if (!dup)
            (*cells)[(*ncells)++] = c;
    }
    return GD_OK;
}

/* The extremes of the first mesh's clearance coordinate over the periodic orbit, and its impact regime
 * (the back side reached: double-sided; the gap: single-sided; neither: none), from the extrema of the
 * coordinate over one period of the orbit (gd_sim_orbit_gaps) and its value at the start. */
static gd_status orbit_regime(const gd_basin_mapper *mp, gd_attractor *a, gd_error *err)
{
    const gd_model *m = &mp->m;
    a->impact_regime = -1;
    a->x_min = a->x_max = NAN;
    if (m->custom || m->nmesh < 1)
        return GD_OK;
    int c = m->mesh_clear[0];
    gd_modes md;
    memset(&md, 0, sizeof md);
    md.from_state = 1;
    double x, xd;
    gd_model_clearance(m, c, 0.0, a->orbit.y[0], &md, &x, &xd);
    a->x_min = a->x_max = x;
    gd_gap_extrema *g = malloc(sizeof *g);
    if (!g)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for an orbit's extrema");
    gd_error e1 = {0};
    gd_status st = gd_sim_orbit_gaps(m, &mp->o, a->orbit.y[0], a->period, g, &e1);
    if (st == GD_OK)
        for (int q = 0; q < g->n[c]; q++) {
            a->x_min = fmin(a->x_min, g->x[c][q]);
            a->x_max = fmax(a->x_max, g->x[c][q]);
        }
    free(g);
    if (st == GD_ERR_NOMEM || st == GD_ERR_INTERRUPTED) {
        *err = e1;
        return st;
    }
    st = GD_OK; /* (more extrema than recorded: the extremes of those recorded) */
    double h = m->clear[c].h;
    a->impact_regime = a->x_min < -h ? GD_IMPACT_DOUBLE : a->x_min < h ? GD_IMPACT_SINGLE : GD_IMPACT_NONE;
    return st;
}

/* The periodic orbit of p mesh periods through y: stable, and each of the trajectory's last p points
 * within three cells (in the section coordinates) of one of its points. */
static int orbit_near(const gd_basin_mapper *mp, const gd_po *o, int p, const double *hist, int nhist)
{
    if (!o->stable || nhist < p)
        return 0;
    for (int j = 0; j < p; j++) {
        double u, v, best = INFINITY;
        gd_basin_section_coords(&mp->sec, hist + (size_t)(nhist - 1 - j) * mp->m.n, &u, &v);
        for (int q = 0; q < p; q++) {
            double ou, ov;
            gd_basin_section_coords(&mp->sec, o->y[q], &ou, &ov);
            best = fmin(best, fmax(fabs(ou - u) / mp->du, fabs(ov - v) / mp->dv));
        }
        if (!(best <= 3.0))
            return 0;
    }
    return 1;
}

/* Shooting for a stable orbit of p periods from y near the points; its least period; GD_OK and *ok. */
static gd_status shoot(const gd_basin_mapper *mp, const double *y, int p, const double *hist, int nhist,
                       gd_po *orbit, int *ok, gd_error *err)
{
    *ok = 0;
    gd_po_opts po = mp->bo.po;
    po.nper = p;
    po.multiple = 1;
    gd_error e1 = {0};
    gd_status st = gd_po_solve(&mp->m, &mp->o, &po, y, orbit, &e1);
    if (st == GD_ERR_NOMEM || st == GD_ERR_INTERRUPTED) {
        *err = e1;
        return st;
    }
    if (st != GD_OK || !orbit_near(mp, orbit, p, hist, nhist))
        return GD_OK;
    /* the least period: an orbit of p periods that repeats after q | p is the orbit of q */
    for (int q = 1; q < p; q++) {
        if (p % q)
            continue;
        int rep = 1;
        for (int j = 0; j < p && rep; j++)
            rep = gd_basin_state_distance(orbit->y[j], orbit->y[(j + q) % p], mp->m.n) <= mp->bo.same_tol;
        if (rep) {
            gd_po least;
            po.nper = q;
            st = gd_po_solve(&mp->m, &mp->o, &po, orbit->y[0], &least, &e1);
            if (st == GD_ERR_NOMEM) {
                *err = e1;
                return st;
            }
            if (st != GD_OK || !least.stable)
                return GD_OK;
            *orbit = least;
            break;
        }
    }
    *ok = 1;
    return GD_OK;
}

/* The modes of the first mesh visited on a non-periodic attractor, and the extremes of its coordinate
 * at the steps' ends. */
typedef struct lyap_watch {
    int clear;
    int visited[3];
    double x_min, x_max;
} lyap_watch;

static int on_event(gd_sim *s, const gd_event *ev, void *user)
{
    (void)s;
    lyap_watch *w = user;
    if (ev->clearance == w->clear)
        w->visited[ev->new_mode + 1] = 1;
    return 0;
}

static int on_step(gd_sim *s, double t0, double t1, void *user)
{
    (void)t0;
    lyap_watch *w = user;
    double x, xd;
    gd_model_clearance(gd_sim_model(s), w->clear, t1, gd_sim_state(s), gd_sim_modes(s), &x, &xd);
    w->x_min = fmin(w->x_min, x);
    w->x_max = fmax(w->x_max, x);
    return 0;
}

/* A non-periodic attractor: lyapunov_periods mesh periods from y with one tangent vector. */
static gd_status lyapunov_run(const gd_basin_mapper *mp, const double *y, gd_attractor *a, long *periods,
                              gd_error *err)
{
    const gd_model *m = &mp->m;
    const int n = m->n, np = mp->bo.lyapunov_periods;
    gd_solver_opts o = mp->o;
    o.n_tangent = 1;
    gd_modes md;
    memset(&md, 0, sizeof md);
    md.from_state = !o.root_finding;
    gd_sim *s = NULL;
    gd_status st = gd_model_consistent_modes(m, 0.0, y, &md, err);
    if (st == GD_OK)
        st = gd_sim_create(m, &o, y, &md, &s, err);
    if (st != GD_OK)
        return st;
    a->pts = malloc(sizeof(double) * (size_t)np * (size_t)n);
    if (!a->pts) {
        gd_sim_free(s);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for an attractor's points");
    }
    lyap_watch w = {0};
    w.clear = m->custom || m->nmesh < 1 ? -1 : m->mesh_clear[0];
    w.x_min = INFINITY, w.x_max = -INFINITY;
    if (w.clear >= 0) {
        w.visited[md.mode[w.clear] + 1] = 1;
        gd_sim_set_hooks(s, on_step, on_event, &w);
    }
    gd_sim_lyapunov_start(s);
    for (int k = 0; k < np && st == GD_OK; k++) {
        if (gd_stop_asked(&mp->bo.stop)) {
            st = gd_error_set(err, GD_ERR_INTERRUPTED, "interrupted");
            break;
        }
        st = gd_sim_period(s, err);
        (*periods)++;
        if (st == GD_OK)
            memcpy(a->pts + (size_t)k * n, gd_sim_state(s), sizeof(double) * (size_t)n);
    }
    if (st == GD_OK) {
        double ex[GD_MAX_STATE];
        int ne = gd_sim_lyapunov(s, ex, NULL);
        a->npts = np;
        a->mle_per_period = ne > 0 ? ex[0] * m->period : NAN;
        double thr = mp->bo.chaos_threshold;
        a->kind = !isfinite(a->mle_per_period) ? GD_ATT_NOT_PERIODIC
                : a->mle_per_period > thr ? GD_ATT_CHAOTIC
                : a->mle_per_period >= -thr ? GD_ATT_QUASI_PERIODIC : GD_ATT_NOT_PERIODIC;
        a->impact_regime = -1;
        a->x_min = a->x_max = NAN;
        if (w.clear >= 0) {
            a->impact_regime = w.visited[0] ? GD_IMPACT_DOUBLE : w.visited[1] ? GD_IMPACT_SINGLE : GD_IMPACT_NONE;
            a->x_min = w.x_min;
            a->x_max = w.x_max;
        }
    }
    gd_sim_free(s);
    return st;
}

gd_status gd_basin_classify(const gd_basin_mapper *mp, const double *y, const double *hist, int nhist,
                            gd_attractor *a, int **cells, int *ncells, long *periods, gd_error *err)
{
    const int n = mp->m.n;
    memset(a, 0, sizeof *a);
    *cells = NULL;
    *ncells = 0;
    /* the candidate periods: how far each point of the map is from the one p periods before */
    double d[GD_PO_MAX_PERIODS + 1], dmin = INFINITY;
    int pmax = mp->bo.max_period;
    for (int p = 1; p <= pmax; p++) {
        d[p] = INFINITY;
        if (2 * p > nhist)
            continue;
        d[p] = 0.0;
        for (int j = 0; j < p; j++)
            d[p] = fmax(d[p], gd_basin_state_distance(hist + (size_t)(nhist - 1 - j) * n,
                                                       hist + (size_t)(nhist - 1 - j - p) * n, n));
        dmin = fmin(dmin, d[p]);
    }
    int tried[3] = {0, 0, 0}, ntry = 0;
    for (int p = 1; p <= pmax && ntry == 0; p++) /* the least p as close as the closest */
        if (d[p] <= 4.0 * dmin + 1e-13)
            tried[ntry++] = p;
    for (int p = 1; p <= pmax; p++) /* the closest */
        if (d[p] == dmin && p != tried[0]) {
            tried[ntry++] = p;
            break;
        }
    gd_status st = GD_OK;
    int ok = 0;
    for (int t = 0; t < ntry && !ok && st == GD_OK; t++)
        st = shoot(mp, y, tried[t], hist, nhist, &a->orbit, &ok, err);
    if (st != GD_OK)
        return st;
    if (ok) {
        a->kind = GD_ATT_PERIODIC;
        a->period = a->orbit.nper;
        a->npts = a->period;
        a->pts = malloc(sizeof(double) * (size_t)a->period * (size_t)n);
        if (!a->pts)
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory for an attractor's points");
        for (int q = 0; q < a->period; q++)
            memcpy(a->pts + (size_t)q * n, a->orbit.y[q], sizeof(double) * (size_t)n);
        a->mle_per_period = log(a->orbit.mu_max) / a->period;
        st = orbit_regime(mp, a, err);
    } else {
        memset(&a->orbit, 0, sizeof a->orbit);
        st = lyapunov_run(mp, y, a, periods, err);
    }
    if (st == GD_OK)
        st = cells_of(mp, a->pts, a->npts, cells, ncells, err);
    if (st != GD_OK) {
        free(a->pts);
        a->pts = NULL;
        free(*cells);
        *cells = NULL;
        return st;
    }
    gd_basin_name(a);
    return GD_OK;
}

int gd_basin_same(const gd_basin_mapper *mp, const gd_attractor *c, const int *cells, int ncells, int k)
{
    const gd_attractor *a = &mp->att[k];
    if (c->kind == GD_ATT_PERIODIC && a->kind == GD_ATT_PERIODIC) {
        if (c->period != a->period)
            return 0;
        for (int q = 0; q < c->npts; q++) {
            double best = INFINITY;
            for (int r = 0; r < a->npts; r++)
                best = fmin(best, gd_basin_state_distance(c->pts + (size_t)q * mp->m.n, a->pts + (size_t)r * mp->m.n,
                                                          mp->m.n));
            if (!(best <= mp->bo.same_tol))
                return 0;
        }
        return 1;
    }
    for (int q = 0; q < ncells; q++)
        for (int r = 0; r < mp->att_ncells[k]; r++)
            if (cells[q] == mp->att_cells[k][r])
                return 1;
    return 0;
}
