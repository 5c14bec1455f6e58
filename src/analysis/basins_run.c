/* The `basins` analysis of a case (gd_basins.h, docs/basins.md section 6): the [basins] keys checked
 * (the box derived where not given), the section of the case's model at the section's mesh phase,
 * the picture's grid and the random sample mapped at the case's values or at each value of the
 * parameter (this rank's share), and a continuation's orbits at each value refined by shooting. The
 * matching of the attractors over the values is basins_match.c. */
#include "basins_internal.h"
#include "analysis_internal.h"
#include "geardyn/gd_scene.h"
#include "../case/case_keys.h"
#include "../core/clock.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#define WHERE(key) (gd_case_key_where(c, "basins", key, w, sizeof w), w)

/* The numbers of basins.state: *n of them into y; 0 when one is not a finite number. */
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

/* The parameter's value k of the case's grid (from and to exactly at the ends). */
static double value_at(const gd_case *c, int k)
{
    if (k == 0)
        return c->bas_from;
    if (k == c->bas_points - 1)
        return c->bas_to;
    return c->bas_from + (c->bas_to - c->bas_from) * (double)k / (double)(c->bas_points - 1);
}

/* The base state of model m: the static state or basins.state. */
static gd_status base_state(const gd_case *c, const gd_model *m, double *y, gd_error *err)
{
    if (c->bas_base == GD_BASINS_BASE_STATE) {
        int n;
        if (!parse_state(c->bas_state, y, &n) || n != m->n)
            return gd_error_set(err, GD_ERR_INPUT, "basins.state: not %d finite numbers", m->n);
        return GD_OK;
    }
    gd_modes md;
    return gd_model_static_state(m, y, &md, err);
}

/* The coordinate's kind: 0 a mesh deflection, 1 a mesh rate, 2 a state component. */
static int coord_kind(const char *name)
{
    if (strncmp(name, "lambda_dot_", 11) == 0)
        return 1;
    return strncmp(name, "lambda_", 7) == 0 ? 0 : 2;
}

/* The derived ends of the box: a deflection from -2 (back contact) to the base's deflection + 2 (at
 * least 3); a rate +-(the deflection box's width, or 5) Omega: a motion over the whole width at the mesh
 * frequency. */
static gd_status derive_box(gd_case *c, const gd_model *m, const double *base, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    static const char *from[2] = {"x_from", "y_from"}, *to[2] = {"x_to", "y_to"};
    const char *name[2] = {c->bas_x, c->bas_y};
    double *lo[2] = {&c->bas_x_from, &c->bas_y_from}, *hi[2] = {&c->bas_x_to, &c->bas_y_to};
    double width = 5.0;
    for (int pass = 0; pass < 2; pass++)
        for (int k = 0; k < 2; k++) {
            int kind = coord_kind(name[k]);
            if ((pass == 0) != (kind == 0))
                continue;
            if (kind == 2) {
                for (int e = 0; e < 2; e++)
                    if (!gd_case_key_given(c, "basins", e ? to[k] : from[k]))
                        return gd_error_set(err, GD_ERR_INPUT, "%s: basins.%s: missing for the state component %s "
                                            "(valid: the box's end in %s, dimensionless)", WHERE(e ? to[k] : from[k]),
                                            e ? to[k] : from[k], name[k], name[k]);
                continue;
            }
            double a, b;
            if (kind == 0) {
                gd_basin_section s;
                gd_error e2 = {0};
                double u = 1.0, v;
                if (gd_basin_section_named(&s, m, base, name[k], k ? c->bas_x : c->bas_y, 0, 1, 0, 1, 1, 1, &e2) == GD_OK)
                    gd_basin_section_coords(&s, base, &u, &v);
                a = -2.0;
                b = fmax(u, 1.0) + 2.0;
                width = b - a;
            } else {
                b = width * m->Omega;
                a = -b;
            }
            gd_case_key_derive(c, "basins", from[k], lo[k], a);
            gd_case_key_derive(c, "basins", to[k], hi[k], b);
        }
    for (int k = 0; k < 2; k++)
        if (!(*lo[k] < *hi[k]))
            return gd_error_set(err, GD_ERR_INPUT, "%s: basins.%s: %.10g is not above %s = %.10g (valid: an upper end "
                                "above the lower: a box that is not empty)", WHERE(to[k]), to[k], *hi[k], from[k],
                                *lo[k]);
    return GD_OK;
}

/* basins.parameter: a real-valued numeric key of another section, every value of the grid in its range. */
static gd_status check_parameter(gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32], range[160];
    const char *name = c->bas_parameter;
    const gd_keyspec *k = gd_case_key_dotted(name);
    if (!k || k->type != GD_KEY_DOUBLE || strcmp(k->section, "basins") == 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: basins.parameter: '%s' is not a real-valued numeric key of the case "
                            "(valid: section.key of a number, e.g. operating.speed_rpm, clearance.backlash_um)",
                            WHERE("parameter"), name);
    gd_case_key_range_text(k, range, sizeof range);
    static const char *bk[2] = {"from", "to"};
    double b[2] = {c->bas_from, c->bas_to};
    for (int i = 0; i < 2; i++) {
        if (!gd_case_key_given(c, "basins", bk[i]))
            return gd_error_set(err, GD_ERR_INPUT, "%s: basins.%s: missing (valid: the %s value of %s, %s)",
                                WHERE("parameter"), bk[i], i ? "last" : "first", name, range);
        if (!gd_case_key_in_range(k, b[i]))
            return gd_error_set(err, GD_ERR_INPUT, "%s: basins.%s: %s = %.10g is out of range (valid: %s)", WHERE(bk[i]),
                                bk[i], name, b[i], range);
    }
    if (c->bas_from == c->bas_to)
        return gd_error_set(err, GD_ERR_INPUT, "%s: basins.to: equal to from = %.10g (valid: another value, a range of "
                            "the parameter)", WHERE("to"), c->bas_from);
    if (gd_case_key_given(c, "basins", "picture") && c->bas_picture)
        return gd_error_set(err, GD_ERR_INPUT, "%s: basins.picture: on with a parameter (valid: off; the picture is "
                            "drawn at the case's values, without basins.parameter)", WHERE("picture"));
    return GD_OK;
}

GD_API gd_status gd_basins_check_case(gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    if (c->bas_resolution_y == 0)
        c->bas_resolution_y = c->bas_resolution;
    if (c->bas_base == GD_BASINS_BASE_STATE && !c->bas_state[0])
        return gd_error_set(err, GD_ERR_INPUT, "%s: basins.state: missing (valid: with base = state, the state's "
                            "dimensionless numbers, comma-separated)", WHERE("base"));
    if (c->bas_base != GD_BASINS_BASE_STATE && gd_case_key_given(c, "basins", "state"))
        return gd_error_set(err, GD_ERR_INPUT, "%s: basins.state: given with base = static (valid: set base = state, "
                            "or leave state out)", WHERE("state"));
    if (c->bas_newton_tol < c->rtol)
        return gd_error_set(err, GD_ERR_INPUT, "%s: basins.newton_tol: %g is below solver.rtol = %g (valid: newton_tol "
                            ">= %g, or a tighter solver.rtol)", WHERE("newton_tol"), c->bas_newton_tol, c->rtol, c->rtol);
    gd_status st = c->bas_parameter[0] ? check_parameter(c, err) : GD_OK;
    if (st != GD_OK)
        return st;
    int picture = c->bas_picture && !c->bas_parameter[0];
    if (!picture && c->bas_samples == 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: basins.samples: 0 without a picture: nothing to compute (valid: a "
                            "sample of 1 or more, or picture = on without parameter)", WHERE("samples"));
    if (picture && c->bas_entropy_box_cells > (c->bas_resolution < c->bas_resolution_y ? c->bas_resolution
                                                                                         : c->bas_resolution_y))
        return gd_error_set(err, GD_ERR_INPUT, "%s: basins.entropy_box_cells: %d above the picture's %d x %d cells "
                            "(valid: 1 to the smaller side)", WHERE("entropy_box_cells"), c->bas_entropy_box_cells,
                            c->bas_resolution, c->bas_resolution_y);
    gd_model m0, m;
    if ((st = gd_model_build(c, &m0, err)) != GD_OK)
        return st;
    gd_model_at_mesh_phase(&m0, c->bas_phase_deg * M_PI / 180.0, &m);
    if (c->bas_base == GD_BASINS_BASE_STATE) {
        double y[GD_MAX_STATE];
        int n;
        if (!parse_state(c->bas_state, y, &n) || n != m.n)
            return gd_error_set(err, GD_ERR_INPUT, "%s: basins.state: '%s' (valid: the %d finite numbers of this "
                                "model's dimensionless state, comma-separated)", WHERE("state"), c->bas_state, m.n);
    }
    double base[GD_MAX_STATE];
    if ((st = base_state(c, &m, base, err)) != GD_OK)
        return st;
    static const char *ck[2] = {"x", "y"};
    const char *cn[2] = {c->bas_x, c->bas_y};
    for (int k = 0; k < 2; k++) {
        gd_basin_section s;
        const char *other = coord_kind(cn[k]) == 2 ? (coord_kind(cn[1 - k]) == 2 ? NULL : cn[1 - k]) : NULL;
        /* each coordinate alone first (paired with a coordinate it is independent of), for a message naming it */
        if (gd_basin_section_named(&s, &m, base, cn[k], other ? other : cn[k], 0, 1, 0, 1, 1, 1, err) != GD_OK &&
            strstr(err ? err->msg : "", "is not one of") != NULL)
            return gd_error_prefix(err, "%s: basins.%s", WHERE(ck[k]), ck[k]);
        if (err)
            gd_error_clear(err);
    }
    if ((st = derive_box(c, &m, base, err)) != GD_OK)
        return st;
    gd_basin_section s;
    if (gd_basin_section_named(&s, &m, base, c->bas_x, c->bas_y, c->bas_x_from, c->bas_x_to, c->bas_y_from,
                               c->bas_y_to, c->bas_resolution, c->bas_resolution_y, err) != GD_OK)
        return gd_error_prefix(err, "%s: basins.y", WHERE("y"));
    return GD_OK;
}

/* ---- the run ---- */

typedef struct brun {
    gd_case c;               /* a copy, moved through the parameter's values */
    const gd_case *orig;
    gd_solver_opts o;
    gd_basin_opts bo;
    const gd_basins_hooks *h;
    long done, total;        /* initial states mapped, planned (progress) */
} brun;

static int on_progress(void *user, long done, long total)
{
    (void)total;
    brun *r = user;
    return r->h && r->h->progress ? r->h->progress(r->h->user, r->done + done, r->total) : 0;
}

/* The model (at the section's phase) and base state at parameter value v (NaN: the case's values). */
gd_status gd_basins_model_at(gd_case *cc, const gd_case *c, double v, gd_model *m, double *base, gd_error *err)
{
    gd_status st = GD_OK;
    if (c->bas_parameter[0] && isfinite(v)) {
        st = gd_case_set_number(cc, c->bas_parameter, v, err);
        if (st == GD_OK)
            st = gd_case_check(cc, err);
        if (st == GD_OK)
            st = gd_scene_resolve(cc, err);
        if (st != GD_OK)
            return gd_error_prefix(err, "the model at %s = %.10g", c->bas_parameter, v);
    }
    gd_model m0;
    if ((st = gd_model_build(cc, &m0, err)) != GD_OK)
        return st;
    gd_model_at_mesh_phase(&m0, c->bas_phase_deg * M_PI / 180.0, m);
    return base_state(c, m, base, err);
}

gd_status gd_basins_section_at(const gd_case *c, const gd_model *m, const double *base, gd_basin_section *s,
                               gd_error *err)
{
    return gd_basin_section_named(s, m, base, c->bas_x, c->bas_y, c->bas_x_from, c->bas_x_to, c->bas_y_from,
                                  c->bas_y_to, c->bas_resolution, c->bas_resolution_y, err);
}

void gd_basins_opts_of(const gd_case *c, const gd_basins_hooks *h, gd_basin_opts *bo)
{
    gd_basin_opts_default(bo);
    bo->consecutive_recurrences = c->bas_consecutive_recurrences;
    bo->consecutive_attractor_steps = c->bas_consecutive_attractor_steps;
    bo->consecutive_basin_steps = c->bas_consecutive_basin_steps;
    bo->consecutive_lost_steps = c->bas_consecutive_lost_steps;
    bo->max_periods = c->bas_max_periods;
    bo->margin = c->bas_margin;
    bo->lyapunov_periods = c->bas_lyapunov_periods;
    bo->chaos_threshold = c->chaos_threshold_per_period;
    bo->po.tol = c->bas_newton_tol;
    if (h) {
        bo->threads = h->threads;
        bo->stop = h->stop;
    }
}

/* A copy of the mapper's attractors (their points too) into point p. */
gd_status gd_basins_point_take(gd_basins_point *p, const gd_basin_mapper *mp, gd_error *err)
{
    const gd_attractor *att;
    int na = gd_basin_mapper_attractors(mp, &att);
    gd_attractor *a = calloc((size_t)(na > 0 ? na : 1), sizeof *a);
    long *cnt = calloc((size_t)(na > 0 ? na : 1), sizeof *cnt);
    int *id = calloc((size_t)(na > 0 ? na : 1), sizeof *id);
    if (!a || !cnt || !id) {
        free(a), free(cnt), free(id);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the attractors");
    }
    const int n = mp->m.n;
    for (int k = 0; k < na; k++) {
        a[k] = att[k];
        a[k].pts = malloc(sizeof(double) * (size_t)(att[k].npts > 0 ? att[k].npts : 1) * (size_t)n);
        if (!a[k].pts) {
            for (int j = 0; j < k; j++)
                free(a[j].pts);
            free(a), free(cnt), free(id);
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the attractors' points");
        }
        memcpy(a[k].pts, att[k].pts, sizeof(double) * (size_t)att[k].npts * (size_t)n);
        id[k] = k;
        if (k < p->natt)
            cnt[k] = p->count[k];
    }
    for (int k = 0; k < p->natt; k++)
        free(p->att[k].pts);
    free(p->att), free(p->count), free(p->id);
    p->att = a;
    p->count = cnt;
    p->id = id;
    p->natt = na;
    return GD_OK;
}

/* The tallies of the sample's labels into p. */
static void tally(gd_basins_point *p, const int *lab, long N)
{
    memset(p->special, 0, sizeof p->special);
    for (int a = 0; a < p->natt; a++)
        p->count[a] = 0;
    for (long k = 0; k < N; k++) {
        if (lab[k] >= 0 && lab[k] < p->natt)
            p->count[lab[k]]++;
        else if (lab[k] < 0 && lab[k] >= -GD_BASIN_NSPECIAL)
            p->special[-lab[k] - 1]++;
    }
    p->samples = N;
}

/* ---- a continuation's orbits at a value ---- */

/* The orbits of the continuation through value v, refined by shooting on the unshifted model at v (the
 * branch's states are at mesh phase 0) and carried to the section's phase; equal ones once. */
gd_status gd_basins_orbits_at(const gd_case *c, gd_case *cc, const gd_basins_known *known, double v,
                              const gd_solver_opts *o, const gd_basin_opts *bo, gd_basins_point *p, int *failed,
                              gd_error *err)
{
    *failed = 0;
    p->norbits = 0;
    free(p->orbits);
    p->orbits = NULL;
    if (!known || known->npoints < 2)
        return GD_OK;
    if (!isfinite(v) && gd_case_get_number(cc, known->parameter, &v, err) != GD_OK) /* the case's own value */
        return gd_error_prefix(err, "basins.continuation");
    gd_model m0;
    gd_status st = gd_model_build(cc, &m0, err);
    if (st != GD_OK)
        return st;
    const int n = known->n;
    if (n != m0.n)
        return gd_error_set(err, GD_ERR_INPUT, "basins.continuation: states of %d components for a model of %d", n,
                            m0.n);
    int cap = 0;
    double t_phase = c->bas_phase_deg * M_PI / 180.0 / m0.Omega;
    gd_model ms;
    gd_model_at_mesh_phase(&m0, c->bas_phase_deg * M_PI / 180.0, &ms);
    gd_basin_section sec;
    double base[GD_MAX_STATE];
    gd_modes md0;
    if (c->bas_base == GD_BASINS_BASE_STATE)
        base_state(c, &ms, base, NULL);
    else
        gd_model_static_state(&ms, base, &md0, NULL);
    if ((st = gd_basins_section_at(c, &ms, base, &sec, err)) != GD_OK)
        return st;
    for (long i = 0; i + 1 < known->npoints && st == GD_OK; i++) {
        if (known->branch[i] != known->branch[i + 1] || known->period[i] != known->period[i + 1])
            continue;
        double a = known->value[i], b = known->value[i + 1];
        if (!(v >= fmin(a, b) && v <= fmax(a, b)) || a == b)
            continue;
        int nper = known->period[i];
        if (nper < 1 || nper > GD_PO_MAX_PERIODS)
            continue;
        double y0[GD_MAX_STATE], s = (v - a) / (b - a);
        for (int q = 0; q < n; q++)
            y0[q] = known->y[i * n + q] + s * (known->y[(i + 1) * n + q] - known->y[i * n + q]);
        gd_po_opts po = bo->po;
        po.nper = nper;
        po.multiple = 1;
        gd_po orbit;
        gd_error e1 = {0};
        gd_status s2 = gd_po_solve(&m0, o, &po, y0, &orbit, &e1);
        if (s2 == GD_ERR_NOMEM) {
            *err = e1;
            return s2;
        }
        if (s2 != GD_OK) {
            (*failed)++;
            continue;
        }
        gd_basins_orbit ob;
        memset(&ob, 0, sizeof ob);
        ob.branch = known->branch[i];
        ob.period = nper;
        ob.stable = orbit.stable;
        ob.mu_max = orbit.mu_max;
        for (int k = 0; k < nper && s2 == GD_OK; k++) {
            memcpy(ob.pts[k], orbit.y[k], sizeof(double) * (size_t)n);
            if (t_phase > 0) { /* from mesh phase 0 to the section's */
                gd_sim *sim = NULL;
                gd_modes md;
                memset(&md, 0, sizeof md);
                md.from_state = !o->root_finding;
                s2 = gd_model_consistent_modes(&m0, 0.0, orbit.y[k], &md, &e1);
                if (s2 == GD_OK)
                    s2 = gd_sim_create(&m0, o, orbit.y[k], &md, &sim, &e1);
                if (s2 == GD_OK)
                    s2 = gd_sim_advance_to(sim, t_phase, &e1);
                if (s2 == GD_OK)
                    memcpy(ob.pts[k], gd_sim_state(sim), sizeof(double) * (size_t)n);
                gd_sim_free(sim);
            }
            gd_basin_section_coords(&sec, ob.pts[k], &ob.u[k], &ob.v[k]);
        }
        if (s2 != GD_OK) {
            (*failed)++;
            continue;
        }
        int dup = 0;
        for (int k = 0; k < p->norbits && !dup; k++)
            if (p->orbits[k].period == nper) {
                dup = 1;
                for (int j = 0; j < nper && dup; j++) {
                    double best = INFINITY;
                    for (int q = 0; q < nper; q++)
                        best = fmin(best, gd_basin_state_distance(ob.pts[j], p->orbits[k].pts[q], n));
                    dup = best <= bo->same_tol;
                }
            }
        if (dup)
            continue;
        if (p->norbits == cap) {
            cap = cap ? 2 * cap : 4;
            gd_basins_orbit *no = realloc(p->orbits, sizeof *no * (size_t)cap);
            if (!no)
                return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the continuation's orbits");
            p->orbits = no;
        }
        p->orbits[p->norbits++] = ob;
    }
    return GD_OK;
}

/* The continuation's stable orbits as seeds (not counted) into mapper mp. */
gd_status gd_basins_seed_orbits(gd_basin_mapper *mp, const gd_basins_point *p, gd_error *err)
{
    const int n = mp->m.n;
    for (int k = 0; k < p->norbits; k++) {
        if (!p->orbits[k].stable)
            continue;
        int lab;
        gd_status st = gd_basin_map(mp, p->orbits[k].pts[0], 1, 0, 1, &lab, err);
        if (st != GD_OK)
            return st;
        (void)n;
    }
    return GD_OK;
}

/* ---- one value ---- */

/* The sample: N states uniform in the box (GSL's Mersenne Twister from basins.seed). */
static gd_status sample_states(const gd_case *c, const gd_basin_section *s, double **y0, gd_error *err)
{
    long N = c->bas_samples;
    *y0 = malloc(sizeof(double) * (size_t)(N > 0 ? N : 1) * (size_t)s->n);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    if (!*y0 || !rng) {
        gsl_rng_free(rng);
        free(*y0);
        *y0 = NULL;
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a sample of %ld states", N);
    }
    gsl_rng_set(rng, (unsigned long)c->bas_seed);
    for (long k = 0; k < N; k++) {
        double u = gsl_rng_uniform(rng), v = gsl_rng_uniform(rng);
        gd_basin_section_state(s, s->lo[0] + u * (s->hi[0] - s->lo[0]), s->lo[1] + v * (s->hi[1] - s->lo[1]),
                               *y0 + (size_t)k * s->n);
    }
    gsl_rng_free(rng);
    return GD_OK;
}

/* Point k: its mapper, the picture (the case's values only) and the sample. */
static gd_status run_value(brun *r, const gd_basins_known *known, gd_basins_result *res, int k, gd_error *err)
{
    const gd_case *c = r->orig;
    gd_basins_point *p = &res->pt[k];
    double cpu0 = (double)clock() / CLOCKS_PER_SEC; /* the process's: every thread */
    gd_model m;
    double base[GD_MAX_STATE];
    gd_status st = gd_basins_model_at(&r->c, c, p->value, &m, base, err);
    gd_basin_section sec;
    if (st == GD_OK)
        st = gd_basins_section_at(c, &m, base, &sec, err);
    if (st != GD_OK)
        return st;
    if (k == 0 || !c->bas_parameter[0])
        res->sec = sec;
    gd_basin_mapper *mp = NULL;
    if ((st = gd_basin_mapper_create(&m, &r->o, &sec, &r->bo, &mp, err)) != GD_OK)
        return st;
    if (res->grid) {
        st = gd_basin_map_grid(mp, res->grid, err);
        r->done += (long)res->nx * res->ny;
    }
    double *y0 = NULL;
    int *lab = NULL;
    if (st == GD_OK && c->bas_samples > 0) {
        st = sample_states(c, &sec, &y0, err);
        lab = malloc(sizeof(int) * (size_t)c->bas_samples);
        if (st == GD_OK && !lab)
            st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for the sample's labels");
        if (st == GD_OK)
            st = gd_basin_map(mp, y0, c->bas_samples, 1, 0, lab, err);
        r->done += c->bas_samples;
    }
    if (st == GD_OK)
        st = gd_basins_point_take(p, mp, err);
    if (st == GD_OK && lab)
        tally(p, lab, c->bas_samples);
    free(y0);
    free(lab);
    if (st == GD_OK && !c->bas_parameter[0]) { /* the continuation's orbits: seeds and marks */
        int failed = 0;
        st = gd_basins_orbits_at(c, &r->c, known, p->value, &r->o, &r->bo, p, &failed, err);
        if (st == GD_OK && failed && res->nnotes < 8)
            snprintf(res->notes[res->nnotes++], GD_ERROR_MSG_MAX, "%d orbit%s of the continuation through this value "
                     "did not converge by shooting and %s not marked", failed, failed > 1 ? "s" : "",
                     failed > 1 ? "are" : "is");
        if (st == GD_OK)
            st = gd_basins_seed_orbits(mp, p, err);
        if (st == GD_OK)
            st = gd_basins_point_take(p, mp, err); /* seeded attractors join with no states */
    }
    p->periods = gd_basin_mapper_periods(mp);
    gd_basin_mapper_free(mp);
    p->cpu_s = (double)clock() / CLOCKS_PER_SEC - cpu0;
    p->done = st == GD_OK;
    return st;
}

/* The picture's tallies: cells and boundary cells per label, the basin entropy. */
static gd_status picture_stats(const gd_case *c, gd_basins_result *res, gd_error *err)
{
    const gd_basins_point *p = &res->pt[0];
    int nl = p->natt + GD_BASIN_NSPECIAL;
    res->grid_cells = calloc((size_t)nl, sizeof(long));
    res->grid_boundary = calloc((size_t)nl, sizeof(long));
    if (!res->grid_cells || !res->grid_boundary)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the picture's tallies");
    for (int l = 0; l < nl; l++) {
        int label = l < p->natt ? l : -(l - p->natt) - 1;
        gd_basin_boundary_cells(res->grid, res->nx, res->ny, label, &res->grid_boundary[l], &res->grid_cells[l]);
    }
    return gd_basin_entropy_of(res->grid, res->nx, res->ny, c->bas_entropy_box_cells, &res->entropy, err);
}

static void column_name(const char *coord, char *out, size_t len)
{
    int kind = coord_kind(coord);
    snprintf(out, len, "%s%s", coord, kind == 0 ? "_half_backlash" : kind == 1 ? "_half_backlash_per_tau" : "");
}

GD_API gd_status gd_basins_run(const gd_case *c, const gd_basins_known *known, const gd_basins_hooks *h,
                               gd_basins_result *res, gd_error *err)
{
    memset(res, 0, sizeof *res);
    double wall0 = gd_clock_wall_s();
    brun r;
    memset(&r, 0, sizeof r);
    gd_status st = gd_case_copy(&r.c, c, err);
    if (st != GD_OK)
        return st;
    r.c.analysis = GD_ANALYSIS_RESPONSE; /* the model at every value: no check of these keys again */
    r.orig = c;
    r.h = h;
    gd_solver_opts_from_case(c, &r.o);
    gd_basins_opts_of(c, h, &r.bo);
    r.bo.progress = on_progress;
    r.bo.progress_user = &r;
    res->z = 1.96;
#ifdef _OPENMP
    res->threads = h && h->threads > 0 ? h->threads : omp_get_max_threads();
#else
    res->threads = 1;
#endif
    snprintf(res->coord[0], sizeof res->coord[0], "%s", c->bas_x);
    snprintf(res->coord[1], sizeof res->coord[1], "%s", c->bas_y);
    column_name(c->bas_x, res->column[0], sizeof res->column[0]);
    column_name(c->bas_y, res->column[1], sizeof res->column[1]);
    res->phase_deg = c->bas_phase_deg;
    gd_model m;
    if ((st = gd_model_build(c, &m, err)) != GD_OK) {
        gd_case_free(&r.c);
        return st;
    }
    res->n = m.n;
    gd_state_names(&m, res->state_name);
    res->length_um = m.bc_m * 1e6;
    res->half_gap = m.nmesh > 0 ? m.clear[m.mesh_clear[0]].h : NAN;
    int nranks = h && h->nranks > 1 ? h->nranks : 1, rank = h ? h->rank : 0;
    if (c->bas_parameter[0]) {
        snprintf(res->parameter, sizeof res->parameter, "%s", c->bas_parameter);
        snprintf(res->unit, sizeof res->unit, "%s", gd_case_key_dotted(c->bas_parameter)->unit);
        res->npoints = c->bas_points;
    } else {
        res->npoints = 1;
    }
    res->pt = calloc((size_t)res->npoints, sizeof *res->pt);
    if (!res->pt)
        st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for the basins' values");
    for (int k = 0; k < res->npoints && st == GD_OK; k++)
        res->pt[k].value = c->bas_parameter[0] ? value_at(c, k) : NAN;
    if (st == GD_OK && !c->bas_parameter[0] && c->bas_picture) {
        res->nx = c->bas_resolution;
        res->ny = c->bas_resolution_y;
        res->grid = malloc(sizeof(int) * (size_t)res->nx * (size_t)res->ny);
        if (!res->grid)
            st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for a picture of %d x %d cells", res->nx, res->ny);
    }
    long per_value = (long)res->nx * res->ny + c->bas_samples;
    for (int k = 0; k < res->npoints; k++)
        if (k % nranks == rank)
            r.total += per_value;
    for (int k = 0; k < res->npoints && st == GD_OK; k++)
        if (k % nranks == rank)
            st = run_value(&r, known, res, k, err);
    if (st == GD_OK && res->grid)
        st = picture_stats(c, res, err);
    if (st == GD_OK && c->bas_parameter[0] && nranks == 1)
        st = gd_basins_match(c, known, h, res, err);
    if (st == GD_OK && !c->bas_parameter[0])
        res->nids = res->pt[0].natt;
    gd_case_free(&r.c);
    res->wall_s = gd_clock_wall_s() - wall0;
    if (st != GD_OK)
        gd_basins_result_free(res);
    return st;
}

GD_API void gd_basins_result_free(gd_basins_result *res)
{
    for (int k = 0; res->pt && k < res->npoints; k++) {
        gd_basins_point *p = &res->pt[k];
        for (int a = 0; a < p->natt; a++)
            free(p->att[a].pts);
        free(p->att);
        free(p->id);
        free(p->count);
        free(p->orbits);
    }
    free(res->pt);
    free(res->grid);
    free(res->grid_cells);
    free(res->grid_boundary);
    res->pt = NULL;
    res->grid = NULL;
    res->grid_cells = res->grid_boundary = NULL;
    res->npoints = 0;
}

GD_API void gd_basins_known_free(gd_basins_known *k)
{
    if (!k)
        return;
    free(k->branch);
    free(k->period);
    free(k->stable);
    free(k->value);
    free(k->y);
    memset(k, 0, sizeof *k);
}

GD_API void gd_basins_fraction(const gd_basins_result *res, int k, int label, gd_basin_fraction *f)
{
    const gd_basins_point *p = &res->pt[k];
    long cnt = label >= 0 ? (label < p->natt ? p->count[label] : 0)
             : (label >= -GD_BASIN_NSPECIAL ? p->special[-label - 1] : 0);
    gd_basin_fraction_of(cnt, p->samples, res->z, f);
}
