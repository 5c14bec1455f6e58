/* The TCA workspace (frames, flanks, grid, solvers) and the `tca` analysis over the pinion
 * positions of both halves: transmission error (paper Eq. 10), contact path, edge contact,
 * contact pattern and separation topography (docs/tca.md). */
#include "tca_internal.h"
#include "../core/gsl_quiet.h"
#include "geardyn/gd_case.h" /* the enums of arrangement and formulation */
#include "geardyn/gd_geometry.h"
#include "geardyn/gd_ltca.h" /* the key of the memo of lines */
#include "../core/clock.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define ARCSEC (180.0 * 3600.0 / M_PI)
#define MAX_PAIRS_WS 64

GD_API const char *gd_edge_kind_name(int bit_index)
{
    static const char *names[GD_EDGE_NKINDS] = {"pinion_root", "pinion_tip", "pinion_end_lo", "pinion_end_hi",
                                                "gear_root",   "gear_tip",   "gear_end_lo",   "gear_end_hi"};
    return bit_index >= 0 && bit_index < GD_EDGE_NKINDS ? names[bit_index] : "?";
}

GD_API void gd_tca_free(gd_tca *t)
{
    if (!t)
        return;
    for (int n = 0; n <= TCA_MAX_N; n++) {
        if (t->solver[n])
            gsl_multiroot_fdfsolver_free(t->solver[n]);
        if (t->xv[n])
            gsl_vector_free(t->xv[n]);
    }
    for (int h = 0; h < 2; h++) {
        free(t->h[h].x1);
        free(t->h[h].sep);
        free(t->h[h].ease);
    }
    free(t->rho);
    free(t->z);
    free(t->gbuf);
    free(t->fbuf);
    free(t->sg);
    free(t->sf);
    free(t->lines);
    free(t->lines_pre);
    free(t->memo_key);
    free(t);
}

GD_API void gd_tca_topography_reset(gd_tca *t)
{
    int nn = t->nprof * t->nface;
    for (int h = 0; h < t->halves; h++)
        for (int n = 0; n < nn; n++)
            t->h[h].sep[n] = t->h[h].ease[n] = NAN;
}

/* Frames of the pair: phase offsets, gear centre with the centre-distance error, the misalignment
 * rotation of the gear axis, pitches, operating pressure angle and the gap tolerances. */
static void set_frames(gd_tca *t, const gd_pair *pair, const gd_tca_settings *set)
{
    const gd_geometry *g = &t->g;
    t->theta1 = g->eta_b[0] + gd_involute(g->alpha_wt);
    t->theta2 = g->eta_b[1] + gd_involute(g->alpha_wt);
    double dE = pair->centre_distance_error_mm * 1e-3;
    t->C[0] = g->a + dE;
    t->C[1] = 0;
    t->C[2] = 0;
    const double arcmin = M_PI / (180.0 * 60.0);
    double di = pair->axis_in_plane_arcmin * arcmin, dc = pair->axis_cross_plane_arcmin * arcmin;
    /* M = Rx(dc) Ry(di) */
    double ci = cos(di), si = sin(di), cc = cos(dc), sc = sin(dc);
    double Ry[9] = {ci, 0, si, 0, 1, 0, -si, 0, ci};
    double Rx[9] = {1, 0, 0, 0, cc, -sc, 0, sc, cc};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            t->M[3 * i + j] = Rx[3 * i] * Ry[j] + Rx[3 * i + 1] * Ry[3 + j] + Rx[3 * i + 2] * Ry[6 + j];
    t->ratio = (double)g->z[0] / g->z[1];
    t->tau1 = 2 * M_PI / g->z[0];
    t->tau2 = 2 * M_PI / g->z[1];
    double cw = (g->rb[0] + g->rb[1]) / (g->a + dE);
    t->alpha_op = acos(fmin(1.0, cw));
    t->refine = set->refine;
    t->tol_edge = t->tol_contact = 1e-9 / (g->rb[1] * cos(g->beta_b));
}

/* The grid on the pinion flank, uniform in roll length and in face position, the node buffers of
 * the pairs and the node positions of each half. */
static gd_status make_grid(gd_tca *t, const gd_tca_settings *set, gd_error *err)
{
    t->nprof = set->profile_points;
    t->nface = set->face_points;
    int nn = t->nprof * t->nface;
    const gd_flank *f1 = &t->h[0].f1;
    t->rho = malloc((size_t)t->nprof * sizeof *t->rho);
    t->z = malloc((size_t)t->nface * sizeof *t->z);
    double span = f1->u_max - f1->u_min;
    double width = (span + 2 * (0.15 * span + 1e-3) + fabs(f1->k) * (f1->z_max - f1->z_min)) / t->tau1 + 3;
    int maxpairs = (int)fmin(ceil(width), MAX_PAIRS_WS);
    t->maxpairs = maxpairs;
    t->gbuf = malloc((size_t)maxpairs * nn * sizeof *t->gbuf);
    t->fbuf = malloc((size_t)maxpairs * nn);
    t->sg = malloc((size_t)t->nprof * sizeof *t->sg);
    t->sf = malloc((size_t)t->nprof);
    if (!t->rho || !t->z || !t->gbuf || !t->fbuf || !t->sg || !t->sf)
        return gd_error_set(err, GD_ERR_NOMEM, "TCA: out of memory for a %d x %d grid", t->nprof, t->nface);
    for (int i = 0; i < t->nprof; i++)
        t->rho[i] = f1->rb * (f1->u_min + span * i / (t->nprof - 1));
    for (int j = 0; j < t->nface; j++)
        t->z[j] = f1->z_min + (f1->z_max - f1->z_min) * j / (t->nface - 1);
    t->rho[t->nprof - 1] = f1->rb * f1->u_max;
    t->z[t->nface - 1] = f1->z_max;
    for (int h = 0; h < t->halves; h++) {
        tca_half *H = &t->h[h];
        H->x1 = malloc((size_t)3 * nn * sizeof *H->x1);
        H->sep = malloc((size_t)nn * sizeof *H->sep);
        H->ease = malloc((size_t)nn * sizeof *H->ease);
        if (!H->x1 || !H->sep || !H->ease)
            return gd_error_set(err, GD_ERR_NOMEM, "TCA: out of memory for the flank grid");
        for (int j = 0; j < t->nface; j++)
            for (int i = 0; i < t->nprof; i++) {
                gd_flank_eval e;
                gd_flank_eval_at(&H->f1, t->rho[i] / H->f1.rb, t->z[j], 0, &e);
                memcpy(H->x1 + 3 * ((size_t)j * t->nprof + i), e.r, sizeof e.r);
            }
    }
    return GD_OK;
}

/* GSL's hybridsj solvers for 1 to TCA_MAX_N unknowns. */
static gd_status alloc_solvers(gd_tca *t, gd_error *err)
{
    for (int n = 1; n <= TCA_MAX_N; n++) {
        t->solver[n] = gsl_multiroot_fdfsolver_alloc(gsl_multiroot_fdfsolver_hybridsj, (size_t)n);
        t->xv[n] = gsl_vector_alloc((size_t)n);
        if (!t->solver[n] || !t->xv[n])
            return gd_error_set(err, GD_ERR_GSL, "gsl_multiroot_fdfsolver_alloc (hybridsj, %d unknowns) failed", n);
    }
    return GD_OK;
}

GD_API gd_status gd_tca_create(const gd_pair *pair, const gd_tca_settings *set, gd_tca **out, gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    *out = NULL;
    gd_tca *t = calloc(1, sizeof *t);
    if (!t)
        return gd_error_set(err, GD_ERR_NOMEM, "TCA: out of memory");
    gd_status st = gd_geometry_compute(pair, &t->g, err);
    if (st != GD_OK) {
        gd_tca_free(t);
        return st;
    }
    const gd_geometry *g = &t->g;
    if (pair->arrangement == GD_ARR_SPUR && pair->helix_angle_deg != 0) {
        gd_tca_free(t);
        return gd_error_set(err, GD_ERR_INPUT, "gear.helix_angle_deg: %g with arrangement = spur (valid: 0)",
                            pair->helix_angle_deg);
    }
    t->halves = pair->arrangement == GD_ARR_HERRINGBONE ? 2 : 1;
    for (int h = 0; h < t->halves; h++) {
        st = gd_flank_pinion(pair, g, h, &t->h[h].f1, err);
        if (st == GD_OK)
            st = gd_flank_gear(pair, g, h, &t->h[h].f2, err);
        if (st != GD_OK) {
            gd_tca_free(t);
            return st;
        }
        double zc = 0.5 * (pair->groove_width_mm * 1e-3 + g->b[0]);
        t->h[h].zc = t->halves == 1 ? 0 : (h == 0 ? -zc : zc);
    }
    set_frames(t, pair, set);
    st = make_grid(t, set, err);
    if (st != GD_OK) {
        gd_tca_free(t);
        return st;
    }
    gd_tca_topography_reset(t);
    st = alloc_solvers(t, err);
    if (st != GD_OK) {
        gd_tca_free(t);
        return st;
    }
    /* the pair's key in the memo of lines (tca_lines_memo.c): every value TCA reads is among those the
     * LTCA's key holds (gd_ltca_cache_key_bytes), its load left at 0; out of memory, no memo */
    gd_ltca_settings ks;
    memset(&ks, 0, sizeof ks);
    ks.face_slices = set->face_points;
    ks.profile_points = set->profile_points;
    ks.refine = set->refine;
    const size_t len = gd_ltca_cache_key_bytes(pair, &ks, 1, NULL, 0);
    t->memo_key = malloc(len);
    if (t->memo_key)
        t->memo_len = gd_ltca_cache_key_bytes(pair, &ks, 1, t->memo_key, len);
    *out = t;
    return GD_OK;
}

GD_API int gd_tca_halves(const gd_tca *t) { return t->halves; }
GD_API const gd_geometry *gd_tca_geometry(const gd_tca *t) { return &t->g; }
GD_API const gd_flank *gd_tca_flank(const gd_tca *t, int half, int body)
{
    return body == 0 ? &t->h[half].f1 : &t->h[half].f2;
}
GD_API double gd_tca_half_centre(const gd_tca *t, int half) { return t->h[half].zc; }
GD_API double gd_tca_operating_pressure_angle(const gd_tca *t) { return t->alpha_op; }

GD_API gd_status gd_tca_contact_at(gd_tca *t, int half, int formulation, double phi1, gd_tca_contact *out,
                                   gd_error *err)
{
    if (half < 0 || half >= t->halves)
        return gd_error_set(err, GD_ERR_INPUT, "TCA: half %d of a pair with %d", half, t->halves);
    memset(out, 0, sizeof *out);
    if (formulation == GD_TCA_TANGENCY)
        return tca_tangency(t, half, phi1, out, err);
    return tca_separation(t, half, phi1, out, err);
}

GD_API gd_status gd_tca_lines_at(gd_tca *t, int half, double phi1, double max_gap, const gd_tca_line_point **pts,
                                 int *npts, gd_error *err)
{
    *pts = NULL;
    *npts = 0;
    if (half < 0 || half >= t->halves)
        return gd_error_set(err, GD_ERR_INPUT, "TCA: half %d of a pair with %d", half, t->halves);
    gd_status st = tca_lines(t, half, phi1, max_gap, err);
    if (st != GD_OK)
        return st;
    *pts = t->lines;
    *npts = t->nlines;
    return GD_OK;
}

GD_API int gd_tca_gap(const gd_tca *t, int half, double phi1, int pair, double u1, double z1, double *gap, double *r2,
                      double *z2)
{
    tca_pose P;
    tca_pose_at(t, half, phi1, tca_phi2_nominal(t, phi1), pair, &P);
    tca_local L;
    tca_local_eval(t, half, &P, u1, z1, 0, &L);
    *gap = L.g;
    *r2 = L.R;
    *z2 = L.Z;
    return L.ok && tca_feasible(t, half, &L, 1e-12) == 0;
}

GD_API void gd_tca_pinion_point(const gd_tca *t, int half, double phi1, int pair, double u1, double z1, double x[3])
{
    gd_flank_eval e;
    gd_flank_eval_at(&t->h[half].f1, u1, z1, 0, &e);
    tca_fixed_point(t, half, phi1, pair, e.r, x);
}

GD_API void gd_tca_topography(const gd_tca *t, int half, int *nprof, int *nface, const double **rho, const double **z,
                              const double **sep, const double **ease_off)
{
    *nprof = t->nprof;
    *nface = t->nface;
    *rho = t->rho;
    *z = t->z;
    *sep = t->h[half].sep;
    *ease_off = t->h[half].ease;
}

GD_API void gd_tca_result_free(gd_tca_result *r)
{
    if (!r)
        return;
    free(r->phi1);
    free(r->rho);
    free(r->z);
    for (int h = 0; h < 2; h++) {
        free(r->contact[h]);
        free(r->contact_a[h]);
        free(r->gte_arcsec[h]);
        free(r->sep[h]);
        free(r->ease_off[h]);
    }
    memset(r, 0, sizeof *r);
}

/* The arrays of the result for npos positions of every half; 0 when out of memory. */
static int alloc_result(const gd_tca *t, const gd_tca_settings *set, int npos, gd_tca_result *r)
{
    int nn = t->nprof * t->nface;
    r->halves = t->halves;
    r->npos = npos;
    r->nprof = t->nprof;
    r->nface = t->nface;
    r->phi1 = malloc((size_t)npos * sizeof *r->phi1);
    r->rho = malloc((size_t)t->nprof * sizeof *r->rho);
    r->z = malloc((size_t)t->nface * sizeof *r->z);
    int ok = r->phi1 && r->rho && r->z;
    for (int h = 0; h < t->halves && ok; h++) {
        r->contact[h] = calloc((size_t)npos, sizeof *r->contact[h]);
        r->gte_arcsec[h] = malloc((size_t)npos * sizeof *r->gte_arcsec[h]);
        r->sep[h] = malloc((size_t)nn * sizeof *r->sep[h]);
        r->ease_off[h] = malloc((size_t)nn * sizeof *r->ease_off[h]);
        ok = r->contact[h] && r->gte_arcsec[h] && r->sep[h] && r->ease_off[h];
        if (ok && set->formulation == GD_TCA_BOTH) {
            r->contact_a[h] = calloc((size_t)npos, sizeof *r->contact_a[h]);
            ok = r->contact_a[h] != NULL;
        }
    }
    return ok;
}

/* The contact of half h at position k by the formulation of the settings (separation always, for the
 * topography), and with both the largest difference of their transmission errors. */
static gd_status contact_at_position(gd_tca *t, const gd_tca_settings *set, int h, int k, gd_tca_result *r,
                                     gd_error *err)
{
    gd_tca_contact cb;
    gd_status st = tca_separation(t, h, r->phi1[k], &cb, err);
    if (st != GD_OK)
        return st;
    if (set->formulation == GD_TCA_TANGENCY) {
        st = tca_tangency(t, h, r->phi1[k], &r->contact[h][k], err);
        if (st != GD_OK)
            return st;
        if (!r->contact[h][k].converged)
            return gd_error_set(err, GD_ERR_SOLVER, "TCA (a): no contact found at phi1 = %.6g deg (%s half): the "
                                "tangency systems are singular for line contact; use tca_formulation = separation",
                                r->phi1[k] * 180 / M_PI, h ? "right" : "left");
    } else {
        r->contact[h][k] = cb;
        if (set->formulation == GD_TCA_BOTH) {
            st = tca_tangency(t, h, r->phi1[k], &r->contact_a[h][k], err);
            if (st != GD_OK)
                return st;
            if (r->contact_a[h][k].converged) {
                double d = fabs(r->contact_a[h][k].te - cb.te) * ARCSEC;
                if (d > r->max_diff_arcsec)
                    r->max_diff_arcsec = d;
                r->compared++;
            }
        }
    }
    return GD_OK;
}

/* Every position of half h: the contacts, edge kinds, pairs in contact, the transmission error
 * and the topography; the operating pressure angles summed into *asum, *acount. */
static gd_status run_half(gd_tca *t, const gd_tca_settings *set, int h, int npos, gd_tca_result *r, double *asum,
                          long *acount, gd_error *err)
{
    int nn = t->nprof * t->nface;
    r->pairs_min[h] = 1 << 30;
    double psum = 0;
    for (int k = 0; k < npos; k++) {
        if (gd_stop_asked(&set->stop))
            return gd_error_set(err, GD_ERR_INTERRUPTED, "TCA: stopped at position %d of %d", k + 1, npos);
        gd_status st = contact_at_position(t, set, h, k, r, err);
        if (st != GD_OK)
            return st;
        const gd_tca_contact *ck = &r->contact[h][k];
        r->edge_kinds[h] |= ck->edge;
        if (ck->edge)
            r->edge_positions[h]++;
        psum += ck->pairs_in_contact;
        if (ck->pairs_in_contact < r->pairs_min[h])
            r->pairs_min[h] = ck->pairs_in_contact;
        if (ck->pairs_in_contact > r->pairs_max[h])
            r->pairs_max[h] = ck->pairs_in_contact;
        *asum += ck->alpha_op;
        (*acount)++;
    }
    r->pairs_mean[h] = psum / npos;
    double lo = INFINITY, hi = -INFINITY, mean = 0;
    for (int k = 0; k < npos; k++) {
        double te = r->contact[h][k].te;
        r->gte_arcsec[h][k] = (te - r->contact[h][0].te) * ARCSEC;
        lo = fmin(lo, r->gte_arcsec[h][k]);
        hi = fmax(hi, r->gte_arcsec[h][k]);
        mean += te * ARCSEC / npos;
    }
    r->gte_pp_arcsec[h] = hi - lo;
    r->te_mean_arcsec[h] = mean;
    memcpy(r->sep[h], t->h[h].sep, (size_t)nn * sizeof *r->sep[h]);
    memcpy(r->ease_off[h], t->h[h].ease, (size_t)nn * sizeof *r->ease_off[h]);
    return GD_OK;
}

GD_API gd_status gd_tca_run(const gd_pair *pair, const gd_tca_settings *set, gd_tca_result *r, gd_error *err)
{
    memset(r, 0, sizeof *r);
    double t0 = gd_clock_wall_s();
    gd_tca *t;
    gd_status st = gd_tca_create(pair, set, &t, err);
    if (st != GD_OK)
        return st;
    int npos = set->positions_per_cycle * set->cycles;
    if (!alloc_result(t, set, npos, r)) {
        gd_tca_free(t);
        gd_tca_result_free(r);
        return gd_error_set(err, GD_ERR_NOMEM, "TCA: out of memory for %d positions", npos);
    }
    memcpy(r->rho, t->rho, (size_t)t->nprof * sizeof *r->rho);
    memcpy(r->z, t->z, (size_t)t->nface * sizeof *r->z);
    for (int k = 0; k < npos; k++)
        r->phi1[k] = t->tau1 * k / set->positions_per_cycle;
    double asum = 0;
    long acount = 0;
    for (int h = 0; h < t->halves; h++) {
        st = run_half(t, set, h, npos, r, &asum, &acount, err);
        if (st != GD_OK) {
            gd_tca_free(t);
            gd_tca_result_free(r);
            return st;
        }
    }
    r->alpha_op_mean = acount ? asum / acount : NAN;
    {
        const gd_geometry *g = &t->g;
        double ga = sqrt(g->ra[0] * g->ra[0] - g->rb[0] * g->rb[0]) + sqrt(g->ra[1] * g->ra[1] - g->rb[1] * g->rb[1]);
        double aop = t->C[0];
        r->contact_ratio_transverse = (ga - aop * sin(t->alpha_op)) / g->pbt;
        r->contact_ratio_overlap = g->eps_beta;
    }
    r->iterations = t->iterations;
    r->wall_s = gd_clock_wall_s() - t0;
    gd_tca_free(t);
    return GD_OK;
}
