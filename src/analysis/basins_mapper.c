/* The recurrence mapper of the basins (gd_basins.h, docs/basins.md section 2): the tessellation of
 * the section's box, the finite-state machine of one trajectory on the exact stroboscopic map, and
 * the batches in which initial states are mapped (OpenMP over the states of a batch, the cells
 * frozen during it, the outcomes merged in the states' order: the same result for any number of
 * threads). */
#include "basins_internal.h"

#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#define FOUND INT_MAX        /* a trajectory's outcome: a new attractor (the candidate) */

GD_API const char *gd_basin_label_name(int label)
{
    switch (label) {
    case GD_BASIN_DIVERGED: return "diverged";
    case GD_BASIN_LEFT_BOX: return "left-box";
    case GD_BASIN_CAP: return "iteration-cap";
    case GD_BASIN_FAILED: return "integration-failed";
    default: return NULL;
    }
}

GD_API void gd_basin_opts_default(gd_basin_opts *o)
{
    memset(o, 0, sizeof *o);
    o->consecutive_recurrences = 100;
    o->consecutive_attractor_steps = 2;
    o->consecutive_basin_steps = 10;
    o->consecutive_lost_steps = 20;
    o->basin_hits = -1;
    o->max_periods = 2000;
    o->horizon = 1e6;
    o->margin = 1.0;
    o->max_period = GD_PO_MAX_PERIODS;
    gd_po_opts_default(&o->po);
    o->same_tol = 1e-6;
    o->lyapunov_periods = 1000;
    o->chaos_threshold = 0.01;
    o->batch = 128;
}

/* ---- the section ---- */

GD_API gd_status gd_basin_section_plane(gd_basin_section *s, int n, const double *base, int i, int j,
                                        double u_lo, double u_hi, double v_lo, double v_hi, int cells_u,
                                        int cells_v, gd_error *err)
{
    if (n < 1 || n > GD_MAX_STATE || i < 0 || i >= n || j < 0 || j >= n || i == j)
        return gd_error_set(err, GD_ERR_INPUT, "a section of state components %d and %d of %d (valid: two different "
                            "components of 0 to %d)", i, j, n, n - 1);
    memset(s, 0, sizeof *s);
    s->n = n;
    memcpy(s->origin, base, sizeof(double) * (size_t)n);
    s->origin[i] = s->origin[j] = 0.0;
    s->dir[0][i] = s->proj[0][i] = 1.0;
    s->dir[1][j] = s->proj[1][j] = 1.0;
    s->lo[0] = u_lo, s->hi[0] = u_hi, s->lo[1] = v_lo, s->hi[1] = v_hi;
    s->cells[0] = cells_u, s->cells[1] = cells_v;
    s->full = n == 2;
    return GD_OK;
}

GD_API void gd_basin_section_state(const gd_basin_section *s, double u, double v, double *y)
{
    for (int k = 0; k < s->n; k++)
        y[k] = s->origin[k] + u * s->dir[0][k] + v * s->dir[1][k];
}

GD_API void gd_basin_section_coords(const gd_basin_section *s, const double *y, double *u, double *v)
{
    double a = 0.0, b = 0.0;
    for (int k = 0; k < s->n; k++) {
        double d = y[k] - s->origin[k];
        a += s->proj[0][k] * d;
        b += s->proj[1][k] * d;
    }
    *u = a;
    *v = b;
}

int gd_basin_cell_of(const gd_basin_mapper *mp, const double *y)
{
    double u, v;
    gd_basin_section_coords(&mp->sec, y, &u, &v);
    double fi = floor((u - mp->sec.lo[0]) / mp->du) + mp->mx, fj = floor((v - mp->sec.lo[1]) / mp->dv) + mp->my;
    if (!(fi >= 0 && fi < mp->tx && fj >= 0 && fj < mp->ty))
        return -1;
    return (int)fj * mp->tx + (int)fi;
}

double gd_basin_state_distance(const double *a, const double *b, int n)
{
    double d = 0.0, s = 0.0;
    for (int k = 0; k < n; k++) {
        d = fmax(d, fabs(a[k] - b[k]));
        s = fmax(s, fabs(b[k]));
    }
    return d / (1.0 + s);
}

/* ---- create, free, attractors ---- */

static gd_status check_section(const gd_basin_section *s, int n, gd_error *err)
{
    if (s->n != n)
        return gd_error_set(err, GD_ERR_INPUT, "a section of states of size %d for a model of state size %d", s->n,
                            n);
    for (int k = 0; k < 2; k++) {
        if (!(isfinite(s->lo[k]) && isfinite(s->hi[k]) && s->lo[k] < s->hi[k]))
            return gd_error_set(err, GD_ERR_INPUT, "the section's box in coordinate %d is [%g, %g] (valid: finite, "
                                "lower below upper)", k + 1, s->lo[k], s->hi[k]);
        if (s->cells[k] < 1 || s->cells[k] > 100000)
            return gd_error_set(err, GD_ERR_INPUT, "%d cells along coordinate %d of the section (valid: 1 to 100000)",
                                s->cells[k], k + 1);
    }
    for (int k = 0; k < 2; k++)
        for (int j = 0; j < 2; j++) {
            double d = 0.0;
            for (int q = 0; q < n; q++)
                d += s->proj[k][q] * s->dir[j][q];
            if (!(fabs(d - (k == j ? 1.0 : 0.0)) < 1e-9))
                return gd_error_set(err, GD_ERR_INPUT, "the section's projection %d gives %g on direction %d (valid: "
                                    "%d)", k + 1, d, j + 1, k == j);
        }
    return GD_OK;
}

GD_API gd_status gd_basin_mapper_create(const gd_model *m, const gd_solver_opts *o, const gd_basin_section *sec,
                                        const gd_basin_opts *bo, gd_basin_mapper **out, gd_error *err)
{
    *out = NULL;
    gd_status st = check_section(sec, m->n, err);
    if (st != GD_OK)
        return st;
    if (bo->consecutive_recurrences < 1 || bo->consecutive_attractor_steps < 1 || bo->consecutive_basin_steps < 1 ||
        bo->consecutive_lost_steps < 0 || bo->max_periods < 1 || bo->batch < 1 || !(bo->margin >= 0) ||
        bo->max_period < 1 || bo->max_period > GD_PO_MAX_PERIODS || bo->lyapunov_periods < 1)
        return gd_error_set(err, GD_ERR_INPUT, "basin options out of range (counts of at least 1, margin >= 0, "
                            "max_period 1 to %d)", GD_PO_MAX_PERIODS);
    double tcells = ((double)sec->cells[0] + 2.0 * ceil(bo->margin * sec->cells[0])) *
                    ((double)sec->cells[1] + 2.0 * ceil(bo->margin * sec->cells[1]));
    if (tcells > 1e9)
        return gd_error_set(err, GD_ERR_INPUT, "a tessellation of %.3g cells (valid: at most 1e9: fewer cells or a "
                            "smaller margin)", tcells);
    gd_basin_mapper *mp = calloc(1, sizeof *mp);
    if (!mp)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the basin mapper");
    mp->m = *m;
    mp->o = *o;
    mp->o.n_tangent = 0;
    mp->sec = *sec;
    mp->bo = *bo;
    mp->mx = (int)ceil(bo->margin * sec->cells[0]);
    mp->my = (int)ceil(bo->margin * sec->cells[1]);
    mp->tx = sec->cells[0] + 2 * mp->mx;
    mp->ty = sec->cells[1] + 2 * mp->my;
    mp->du = (sec->hi[0] - sec->lo[0]) / sec->cells[0];
    mp->dv = (sec->hi[1] - sec->lo[1]) / sec->cells[1];
    for (int k = 0; k < m->n; k++)
        mp->state_cell = fmax(mp->state_cell, fmax(fabs(sec->dir[0][k]) * mp->du, fabs(sec->dir[1][k]) * mp->dv));
    mp->basin_hits = bo->basin_hits < 0 ? sec->full : bo->basin_hits;
    mp->cell = calloc((size_t)mp->tx * (size_t)mp->ty, sizeof(int));
    if (!mp->cell) {
        int tx = mp->tx, ty = mp->ty;
        free(mp);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a tessellation of %d x %d cells", tx, ty);
    }
    *out = mp;
    return GD_OK;
}

GD_API void gd_basin_mapper_free(gd_basin_mapper *mp)
{
    if (!mp)
        return;
    for (int a = 0; a < mp->natt; a++) {
        free(mp->att[a].pts);
        free(mp->att_cells[a]);
    }
    free(mp->att);
    free(mp->att_cells);
    free(mp->att_ncells);
    free(mp->cell);
    free(mp);
}

GD_API int gd_basin_mapper_attractors(const gd_basin_mapper *mp, const gd_attractor **att)
{
    *att = mp->att;
    return mp->natt;
}

GD_API long gd_basin_mapper_periods(const gd_basin_mapper *mp) { return mp->periods; }

/* Append attractor a (its pts and cells taken over) and label its cells. */
static gd_status register_attractor(gd_basin_mapper *mp, gd_attractor *a, int *cells, int ncells, gd_error *err)
{
    if (mp->natt == mp->att_cap) {
        int cap = mp->att_cap ? 2 * mp->att_cap : 8;
        gd_attractor *na = realloc(mp->att, sizeof *na * (size_t)cap);
        if (na)
            mp->att = na;
        int **nc = realloc(mp->att_cells, sizeof *nc * (size_t)cap);
        if (nc)
            mp->att_cells = nc;
        int *nn = realloc(mp->att_ncells, sizeof *nn * (size_t)cap);
        if (nn)
            mp->att_ncells = nn;
        if (!na || !nc || !nn)
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the attractors");
        mp->att_cap = cap;
    }
    int k = mp->natt++;
    mp->att[k] = *a;
    mp->att_cells[k] = cells;
    mp->att_ncells[k] = ncells;
    for (int q = 0; q < ncells; q++) {
        int v = mp->cell[cells[q]];
        if (v <= 0 || (v & 1)) /* nothing, a special outcome's or a basin's: the attractor's now */
            mp->cell[cells[q]] = BASIN_CELL_ATT(k);
    }
    return GD_OK;
}

GD_API gd_status gd_basin_mapper_add(gd_basin_mapper *mp, const gd_attractor *a, int *index, gd_error *err)
{
    int *cells = malloc(sizeof(int) * (size_t)(a->npts > 0 ? a->npts : 1));
    if (!cells)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for an attractor's cells");
    int nc = 0;
    for (int q = 0; q < a->npts; q++) {
        int c = gd_basin_cell_of(mp, a->pts + (size_t)q * mp->m.n);
        int dup = 0;
        for (int r = 0; r < nc && !dup; r++)
            dup = cells[r] == c;
        if (c >= 0 && !dup)
            cells[nc++] = c;
    }
    for (int k = 0; k < mp->natt; k++)
        if (gd_basin_same(mp, a, cells, nc, k)) {
            free(cells);
            *index = k;
            return GD_OK;
        }
    gd_attractor copy = *a;
    copy.pts = malloc(sizeof(double) * (size_t)(a->npts > 0 ? a->npts : 1) * (size_t)mp->m.n);
    if (!copy.pts) {
        free(cells);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for an attractor's points");
    }
    memcpy(copy.pts, a->pts, sizeof(double) * (size_t)a->npts * (size_t)mp->m.n);
    *index = mp->natt;
    gd_status st = register_attractor(mp, &copy, cells, nc, err);
    if (st != GD_OK) {
        free(copy.pts);
        free(cells);
    }
    return st;
}

/* ---- one trajectory ---- */

/* A thread's scratch: the cells the trajectory visited (open addressing; keys are cell + 1) and the
 * map's last points. */
typedef struct traj_ws {
    int *keys;
    unsigned cap;            /* a power of 2 */
    int *list;
    long nlist;
    double *hist;            /* the last hcap points, a ring */
    int hcap;
} traj_ws;

/* 1 when the cell was visited before, else 0 after inserting it (-1: the set is full) */
static int visit(traj_ws *w, int cell)
{
    unsigned h = ((unsigned)cell * 2654435761u) & (w->cap - 1);
    for (unsigned probe = 0; probe < w->cap; probe++) {
        int k = w->keys[h];
        if (k == cell + 1)
            return 1;
        if (k == 0) {
            w->keys[h] = cell + 1;
            w->list[w->nlist++] = (int)h;
            return 0;
        }
        h = (h + 1) & (w->cap - 1);
    }
    return -1;
}

static void visited_clear(traj_ws *w)
{
    for (long q = 0; q < w->nlist; q++)
        w->keys[w->list[q]] = 0;
    w->nlist = 0;
}

typedef struct traj_out {
    int label;               /* an attractor's index (a hit), a gd_basin_label or FOUND */
    int init_cell;           /* the initial state's tessellation cell (-1 outside) */
    gd_attractor cand;       /* FOUND: the candidate */
    int *cells, ncells;      /* FOUND: its cells */
    long periods;
} traj_out;

/* The trajectory from y0 through the finite-state machine (docs/basins.md section 2). GD_OK with
 * out->label set; GD_ERR_NOMEM and GD_ERR_INTERRUPTED end the mapping. */
static gd_status trajectory(const gd_basin_mapper *mp, traj_ws *w, const double *y0, traj_out *out, gd_error *err)
{
    const gd_basin_opts *bo = &mp->bo;
    const int n = mp->m.n;
    memset(out, 0, sizeof *out);
    out->init_cell = gd_basin_cell_of(mp, y0);
    gd_modes md;
    memset(&md, 0, sizeof md);
    md.from_state = !mp->o.root_finding;
    gd_error e1 = {0};
    gd_sim *s = NULL;
    gd_status st = gd_model_consistent_modes(&mp->m, 0.0, y0, &md, &e1);
    if (st == GD_OK)
        st = gd_sim_create(&mp->m, &mp->o, y0, &md, &s, &e1);
    if (st == GD_ERR_NOMEM) {
        *err = e1;
        return st;
    }
    if (st != GD_OK) {
        out->label = GD_BASIN_FAILED;
        return GD_OK;
    }
    int rec = 0, att_label = -1, att_run = 0, bas_label = -1, bas_run = 0, lost = 0, nhist = 0;
    const double *y = y0;
    for (long k = 0;; k++) {
        /* the point y = P^k(y0) */
        double ymax = 0.0;
        for (int q = 0; q < n; q++)
            ymax = fmax(ymax, fabs(y[q]));
        if (!(ymax <= bo->horizon)) {
            out->label = GD_BASIN_DIVERGED;
            break;
        }
        memcpy(w->hist + (size_t)(nhist % w->hcap) * n, y, sizeof(double) * (size_t)n);
        nhist++;
        int c = gd_basin_cell_of(mp, y);
        if (c < 0) {
            rec = att_run = bas_run = 0;
            if (++lost > bo->consecutive_lost_steps) {
                out->label = GD_BASIN_LEFT_BOX;
                break;
            }
        } else {
            lost = 0;
            int v = mp->cell[c];
            int a = v >= 2 && !(v & 1) ? (v - 2) / 2 : -1;
            /* a known attractor's cell; off the section plane (n > 2) the state must also lie within two
             * cells of one of its points */
            if (a >= 0 && !mp->sec.full && mp->att[a].kind == GD_ATT_PERIODIC) {
                int near = 0;
                for (int q = 0; q < mp->att[a].npts && !near; q++) {
                    const double *z = mp->att[a].pts + (size_t)q * n;
                    double d = 0.0;
                    for (int r = 0; r < n; r++)
                        d = fmax(d, fabs(y[r] - z[r]));
                    near = d <= 2.0 * mp->state_cell;
                }
                if (!near)
                    a = -1;
            }
            if (a >= 0) {
                att_run = a == att_label ? att_run + 1 : 1;
                att_label = a;
                if (att_run >= bo->consecutive_attractor_steps) {
                    out->label = a;
                    break;
                }
            } else {
                att_run = 0;
            }
            int b = mp->basin_hits && v >= 3 && (v & 1) ? (v - 3) / 2 : -1;
            if (b >= 0) {
                bas_run = b == bas_label ? bas_run + 1 : 1;
                bas_label = b;
                if (bas_run >= bo->consecutive_basin_steps) {
                    out->label = b;
                    break;
                }
            } else {
                bas_run = 0;
            }
            int seen = visit(w, c);
            if (seen < 0) {
                out->label = GD_BASIN_CAP;
                break;
            }
            rec = seen ? rec + 1 : 0;
            if (rec >= bo->consecutive_recurrences) {
                out->label = FOUND;
                break;
            }
        }
        if (k >= bo->max_periods) {
            out->label = GD_BASIN_CAP;
            break;
        }
        if (gd_stop_asked(&bo->stop)) {
            gd_sim_free(s);
            visited_clear(w);
            return gd_error_set(err, GD_ERR_INTERRUPTED, "interrupted");
        }
        st = gd_sim_period(s, &e1);
        out->periods++;
        if (st == GD_ERR_NOMEM || st == GD_ERR_INTERRUPTED) {
            gd_sim_free(s);
            visited_clear(w);
            *err = e1;
            return st;
        }
        if (st != GD_OK) {
            out->label = GD_BASIN_FAILED;
            break;
        }
        y = gd_sim_state(s);
    }
    visited_clear(w);
    if (out->label == FOUND) {
        /* the points in the ring, oldest first */
        int nh = nhist < w->hcap ? nhist : w->hcap;
        double *h = malloc(sizeof(double) * (size_t)nh * (size_t)n);
        if (!h) {
            gd_sim_free(s);
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a trajectory's points");
        }
        for (int q = 0; q < nh; q++)
            memcpy(h + (size_t)q * n, w->hist + (size_t)((nhist - nh + q) % w->hcap) * n, sizeof(double) * (size_t)n);
        long extra = 0;
        st = gd_basin_classify(mp, y, h, nh, &out->cand, &out->cells, &out->ncells, &extra, &e1);
        free(h);
        out->periods += extra;
        if (st == GD_ERR_NOMEM || st == GD_ERR_INTERRUPTED) {
            gd_sim_free(s);
            *err = e1;
            return st;
        }
        if (st != GD_OK) { /* the classification's own integration failed */
            free(out->cand.pts);
            free(out->cells);
            out->cand.pts = NULL;
            out->cells = NULL;
            out->label = GD_BASIN_FAILED;
        }
    }
    gd_sim_free(s);
    return GD_OK;
}

/* ---- batches ---- */

static gd_status ws_init(traj_ws *w, const gd_basin_mapper *mp, gd_error *err)
{
    memset(w, 0, sizeof *w);
    unsigned cap = 64;
    long need = 2 * (mp->bo.max_periods + 2);
    while ((long)cap < need && cap < (1u << 30))
        cap <<= 1;
    w->cap = cap;
    w->keys = calloc(cap, sizeof(int));
    w->list = malloc(sizeof(int) * cap);
    w->hcap = 2 * mp->bo.max_period + 2;
    w->hist = malloc(sizeof(double) * (size_t)w->hcap * (size_t)mp->m.n);
    if (!w->keys || !w->list || !w->hist)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a trajectory's cells (%u)", cap);
    return GD_OK;
}

static void ws_free(traj_ws *w)
{
    free(w->keys);
    free(w->list);
    free(w->hist);
}

/* The outcomes of a batch into the mapper, in the states' order: candidates become attractors
 * (or the one they are), the initial cells get their labels. */
static gd_status merge(gd_basin_mapper *mp, traj_out *o, long cnt, int label_cells, int seeds, int *labels,
                       gd_error *err)
{
    gd_status st = GD_OK;
    for (long q = 0; q < cnt; q++) {
        traj_out *t = &o[q];
        mp->periods += t->periods;
        if (t->label == FOUND && st == GD_OK) {
            int k = -1;
            for (int a = 0; a < mp->natt && k < 0; a++)
                if (gd_basin_same(mp, &t->cand, t->cells, t->ncells, a))
                    k = a;
            if (k < 0) {
                k = mp->natt;
                t->cand.seeded = seeds;
                st = register_attractor(mp, &t->cand, t->cells, t->ncells, err);
                if (st == GD_OK)
                    t->cand.pts = NULL, t->cells = NULL; /* the mapper's now */
            } else if (!seeds) {
                mp->att[k].seeded = 0;
            }
            t->label = k;
        } else if (t->label >= 0 && !seeds) {
            mp->att[t->label].seeded = 0;
        }
        free(t->cand.pts);
        free(t->cells);
        t->cand.pts = NULL;
        t->cells = NULL;
        labels[q] = t->label;
        if (label_cells && t->init_cell >= 0 && mp->cell[t->init_cell] == 0)
            mp->cell[t->init_cell] = t->label >= 0 ? BASIN_CELL_BASIN(t->label) : t->label;
    }
    return st;
}

GD_API gd_status gd_basin_map(gd_basin_mapper *mp, const double *y0, long count, int label_cells, int seeds,
                              int *labels, gd_error *err)
{
    const gd_basin_opts *bo = &mp->bo;
    int nt = 1;
#ifdef _OPENMP
    nt = bo->threads > 0 ? bo->threads : omp_get_max_threads();
#endif
    if (nt > bo->batch)
        nt = bo->batch;
    traj_ws *ws = calloc((size_t)nt, sizeof *ws);
    traj_out *out = calloc((size_t)bo->batch, sizeof *out);
    gd_status st = ws && out ? GD_OK : gd_error_set(err, GD_ERR_NOMEM, "out of memory for the basin batches");
    for (int t = 0; t < nt && st == GD_OK; t++)
        st = ws_init(&ws[t], mp, err);
    const int n = mp->m.n;
    for (long first = 0; first < count && st == GD_OK; first += bo->batch) {
        long cnt = count - first < bo->batch ? count - first : bo->batch;
        atomic_int failed = 0;
        gd_status fst = GD_OK;
        gd_error ferr = {0};
        pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
#pragma omp parallel for schedule(dynamic, 1) num_threads(nt)
        for (long q = 0; q < cnt; q++) {
            if (atomic_load(&failed))
                continue;
            int tid = 0;
#ifdef _OPENMP
            tid = omp_get_thread_num();
#endif
            gd_error e = {0};
            gd_status s2 = trajectory(mp, &ws[tid], y0 + (size_t)(first + q) * n, &out[q], &e);
            if (s2 != GD_OK) {
                pthread_mutex_lock(&lock);
                if (fst == GD_OK || (fst == GD_ERR_INTERRUPTED && s2 != GD_ERR_INTERRUPTED)) {
                    fst = s2;
                    ferr = e;
                }
                pthread_mutex_unlock(&lock);
                atomic_store(&failed, 1);
            }
        }
        pthread_mutex_destroy(&lock);
        if (fst != GD_OK) {
            for (long q = 0; q < cnt; q++) {
                free(out[q].cand.pts);
                free(out[q].cells);
            }
            if (err)
                *err = ferr;
            st = fst;
            break;
        }
        st = merge(mp, out, cnt, label_cells, seeds, labels + first, err);
        if (st == GD_OK && bo->progress && bo->progress(bo->progress_user, first + cnt, count))
            st = gd_error_set(err, GD_ERR_INTERRUPTED, "interrupted");
    }
    for (int t = 0; ws && t < nt; t++)
        ws_free(&ws[t]);
    free(ws);
    free(out);
    return st;
}

GD_API gd_status gd_basin_map_grid(gd_basin_mapper *mp, int *labels, gd_error *err)
{
    const int nx = mp->sec.cells[0], ny = mp->sec.cells[1], n = mp->m.n;
    double *y0 = malloc(sizeof(double) * (size_t)nx * (size_t)ny * (size_t)n);
    if (!y0)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the %d x %d initial states", nx, ny);
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++)
            gd_basin_section_state(&mp->sec, mp->sec.lo[0] + (i + 0.5) * mp->du, mp->sec.lo[1] + (j + 0.5) * mp->dv,
                                   y0 + ((size_t)j * nx + i) * n);
    gd_status st = gd_basin_map(mp, y0, (long)nx * ny, 1, 0, labels, err);
    free(y0);
    return st;
}
