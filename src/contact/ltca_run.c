/* The `ltca` analysis over one mesh cycle (docs/ltca.md sections 4-8): loaded transmission error
 * (Eq. 12), mesh stiffness of each half (Eq. 14), load sharing between halves and tooth pairs,
 * contact pressure, edge loading; the mesh-in impact of each half; the excitations of the dynamic
 * model and their cache key. */
#include "ltca_internal.h"
#include "../core/clock.h"
#include "../core/hash.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define ARCSEC (180.0 * 3600.0 / M_PI)

GD_API void gd_ltca_result_free(gd_ltca_result *r)
{
    if (!r)
        return;
    free(r->phi1);
    free(r->lte_arcsec);
    free(r->axial_shift);
    for (int h = 0; h < 2; h++) {
        free(r->gte_arcsec[h]);
        free(r->lte_half_arcsec[h]);
        free(r->load[h]);
        free(r->stiffness[h]);
        free(r->max_pressure[h]);
        free(r->pairs_loaded[h]);
        free(r->edge_loaded[h]);
        free(r->edge_ratio[h]);
    }
    free(r->points);
    free(r->first);
    memset(r, 0, sizeof *r);
}

/* ---- mesh-in impact (section 7) --------------------------------------------------------------- */

#define TOUCH_TIE 1e-12 /* m: gaps closer than this touch together */

typedef struct entry_eval {
    double s;          /* the pair's least rigid gap w_i - (G z)_i (m): > 0 open, < 0 it carries load */
    int imin;          /* the point where it is least (-1: the pair has no point in the window) */
} entry_eval;

/* The incoming pair's least rigid gap: its gaps less the rigid approach, without its own
 * deflection. L is block diagonal, so while the pair is open this is its least deformed gap, and
 * once loaded it is minus its own deflection there: smooth across the touch, zero at it. */
static gd_status eval_entry(gd_ltca *w, double phi1, double torque, int half, int pair, gd_ltca_position *pos,
                            entry_eval *e, gd_error *err)
{
    gd_status st = gd_ltca_solve_at(w, phi1, torque, pos, err);
    if (st != GD_OK)
        return st;
    double smin = INFINITY;
    e->imin = -1;
    for (int i = 0; i < w->n; i++) {
        const gd_ltca_point *P = &w->pts[i];
        if (P->half != half || P->pair != pair)
            continue;
        double gz = w->z[0] + (w->m > 1 ? P->normal[2] * w->z[1] : 0.0);
        double s = w->w[i] - gz;
        if (s < smin) {
            smin = s;
            e->imin = i;
        }
    }
    e->s = e->imin >= 0 ? smin : w->window; /* outside the window: clearly open */
    if (e->imin < 0)
        return GD_OK;
    /* A line that touches along a stretch of the face at once (an aligned spur pair: every slice
     * within a picometre, rounding) has no first point: the middle of the stretch stands for it,
     * not its first slice, which sits on a face end and would read as a corner. */
    int first = -1, last = -1;
    for (int i = 0; i < w->n; i++) {
        const gd_ltca_point *P = &w->pts[i];
        if (P->half != half || P->pair != pair)
            continue;
        double gz = w->z[0] + (w->m > 1 ? P->normal[2] * w->z[1] : 0.0);
        if (w->w[i] - gz <= smin + TOUCH_TIE) {
            if (first < 0)
                first = i;
            last = i;
        } else if (first >= 0) {
            break; /* the stretch is contiguous; a second one elsewhere is not a tie of this one */
        }
    }
    if (first >= 0 && e->imin >= first && e->imin <= last)
        e->imin = first + (last - first) / 2;
    return GD_OK;
}

/* Load-approach curve of the incoming pair alone at its mesh-in geometry: a one-freedom contact
 * problem (gd_contact_solve) for forces F_j, giving its approach delta_j beyond first touch. */
static gd_status pair_curve(gd_ltca *w, int half, int pair, double fref, double *F, double *delta, int nf,
                            gd_error *err)
{
    int lo = -1, hi = -1;
    for (int b = 0; b < w->nb; b++) {
        int i = w->bstart[b];
        if (w->pts[i].half == half && w->pts[i].pair == pair) {
            lo = i;
            hi = w->bstart[b + 1];
        }
    }
    if (lo < 0)
        return gd_error_set(err, GD_ERR_INTERNAL, "LTCA mesh-in: the incoming pair has no points");
    int k = hi - lo;
    double *L = malloc(sizeof(double) * (size_t)(k * k + 4 * k));
    if (!L)
        return gd_error_set(err, GD_ERR_NOMEM, "LTCA mesh-in: out of memory");
    double *wv = L + k * k, *G = wv + k, *p = G + k, *d = p + k;
    double wmin = INFINITY;
    for (int a = 0; a < k; a++)
        wmin = fmin(wmin, w->w[lo + a]);
    for (int a = 0; a < k; a++) {
        for (int b = 0; b < k; b++)
            L[a * k + b] = w->L[(size_t)(lo + a) * (size_t)w->n + (size_t)(lo + b)];
        wv[a] = w->w[lo + a] - wmin;
        G[a] = 1.0;
    }
    gd_contact_workspace *ws;
    gd_status st = gd_contact_workspace_alloc(k, 1, &ws, err);
    for (int j = 0; j < nf && st == GD_OK; j++) {
        double f = fref * ldexp(1.0, -j);
        gd_contact_problem pb = {k, 1, L, wv, G, &f};
        gd_contact_solution sol = {0};
        sol.p = p;
        sol.d = d;
        st = gd_contact_solve(&pb, NULL, ws, &sol, err);
        F[j] = f;
        delta[j] = sol.z[0];
    }
    gd_contact_workspace_free(ws);
    free(L);
    return st;
}

/* The pair that comes into mesh over the cycle: the position kin where the least loaded pair
 * label of the half drops (at phi1 + tau every label is one less). *kin_out = -1: no regular entry. */
static gd_status entry_pair(const gd_ltca_result *r, int half, int *pair, int *kin_out, gd_error *err)
{
    int npos = r->npos;
    *kin_out = -1;
    /* the least loaded pair label of each position; at phi1 + tau every label is one less */
    int *pmin = malloc(sizeof(int) * (size_t)(npos + 1));
    if (!pmin)
        return gd_error_set(err, GD_ERR_NOMEM, "LTCA mesh-in: out of memory");
    for (int k = 0; k < npos; k++) {
        pmin[k] = 1 << 30;
        for (int i = r->first[k]; i < r->first[k + 1]; i++)
            if (r->points[i].half == half && r->points[i].load > 0 && r->points[i].pair < pmin[k])
                pmin[k] = r->points[i].pair;
    }
    pmin[npos] = pmin[0] - 1;
    int kin = -1;
    for (int k = 0; k < npos; k++)
        if (pmin[k] == 1 << 30) { /* a half that does not carry load at every position: no regular entry */
            free(pmin);
            return GD_OK;
        }
    for (int k = 1; k <= npos; k++)
        if (pmin[k] < pmin[k - 1]) {
            kin = k;
            break;
        }
    if (kin < 0) {
        free(pmin);
        return GD_OK;
    }
    *pair = pmin[kin];
    *kin_out = kin;
    free(pmin);
    return GD_OK;
}

/* The moment the pair touches, bracketed in [*a, *b] (*a: still open, *b: loaded). */
static gd_status bracket_touch(gd_ltca *w, double tau, int half, int pair, double torque, double *a_io,
                               double *b_io, gd_ltca_position *pos, gd_error *err)
{
    double a = *a_io, b = *b_io;
    entry_eval ea, eb, ec;
    gd_status st = eval_entry(w, a, torque, half, pair, pos, &ea, err);
    if (st == GD_OK)
        st = eval_entry(w, b, torque, half, pair, pos, &eb, err);
    if (st != GD_OK)
        return st;
    if (!(ea.s > 0) || eb.s > 0)
        return gd_error_set(err, GD_ERR_INTERNAL, "LTCA mesh-in: pair %d of the %s half does not enter between "
                            "%.9g and %.9g rad (%.3g, %.3g)", pair, half ? "right" : "left", a, b, ea.s, eb.s);
    /* Illinois regula falsi on s(phi1) to 1e-10 of the mesh cycle */
    double fa = ea.s, fb = eb.s;
    int side = 0;
    for (int it = 0; it < 100 && b - a > 1e-10 * tau; it++) {
        double c = b - fb * (b - a) / (fb - fa);
        if (!(c > a && c < b))
            c = 0.5 * (a + b);
        st = eval_entry(w, c, torque, half, pair, pos, &ec, err);
        if (st != GD_OK)
            return st;
        if (ec.s > 0) {
            a = c;
            fa = ec.s;
            if (side == -1)
                fb *= 0.5;
            side = -1;
        } else {
            b = c;
            fb = ec.s;
            if (side == 1)
                fa *= 0.5;
            side = 1;
        }
    }
    *a_io = a;
    *b_io = b;
    return GD_OK;
}

/* Where and how the pair meets: the mesh-in point P, the flanks' relative velocity there, its
 * offset from the ideal plane of action, and the start of active profile. */
static void impact_geometry(const gd_ltca *w, const gd_ltca_point *P, gd_ltca_impact *imp)
{
    const gd_tca *t = w->t;
    memcpy(imp->pos, P->pos, sizeof imp->pos);
    memcpy(imp->normal, P->normal, sizeof imp->normal);
    imp->rho1 = P->rho1;
    imp->z1 = P->z1;
    imp->edge = P->edge;
    /* relative velocity of the flanks at the point, rigid bodies at the nominal ratio:
     * v1 = omega1 e_z x X, v2 = -omega2 (M e_z) x (X - C), omega2 = (z1/z2) omega1 */
    const double *X = P->pos, *n = P->normal;
    double v1[3] = {-X[1], X[0], 0.0};
    double ag[3] = {t->M[2], t->M[5], t->M[8]};
    double XC[3] = {X[0] - t->C[0], X[1] - t->C[1], X[2] - t->C[2]};
    double v2[3] = {-(ag[1] * XC[2] - ag[2] * XC[1]) * t->ratio, -(ag[2] * XC[0] - ag[0] * XC[2]) * t->ratio,
                    -(ag[0] * XC[1] - ag[1] * XC[0]) * t->ratio};
    imp->vs_per_omega = (v1[0] - v2[0]) * n[0] + (v1[1] - v2[1]) * n[1] + (v1[2] - v2[2]) * n[2];
    /* the ideal plane of action: tangent to the pinion base cylinder at the angle +-alpha' on the
     * side the drive normals point to (their x component is negative when it is +alpha') */
    double nx = 0;
    for (int i = 0; i < w->n; i++)
        nx += w->pts[i].normal[0];
    double ang = nx < 0 ? t->alpha_op : -t->alpha_op;
    imp->offset_loa = X[0] * cos(ang) + X[1] * sin(ang) - w->g.rb[0];
    double aop = t->C[0];
    imp->rho_sap = aop * sin(t->alpha_op) - sqrt(w->g.ra[1] * w->g.ra[1] - w->g.rb[1] * w->g.rb[1]);
}

enum { NF = 10 }; /* solves on the incoming pair's load-approach curve */

/* k_s: secant stiffness of the incoming pair at delta_m, from its own load-approach curve, and the
 * power law fitted to that curve. */
static gd_status impact_stiffness(gd_ltca *w, const gd_ltca_result *r, int half, int pair, double torque,
                                  const gd_ltca_position *pos, gd_ltca_impact *imp, gd_error *err)
{
    double F[NF], D[NF];
    double pairs = r->pairs_mean[half] > 0 ? r->pairs_mean[half] : 1.0;
    double fref = 2.0 * pos->load[half] / pairs;
    if (!(fref > 0))
        fref = gd_ltca_normal_force(w, torque);
    for (int tries = 0; tries < 30; tries++) {
        gd_status st = pair_curve(w, half, pair, fref, F, D, NF, err);
        if (st != GD_OK)
            return gd_error_prefix(err, "LTCA mesh-in stiffness");
        if (D[0] >= imp->delta_m)
            break;
        fref *= 4.0;
    }
    /* power law F = c delta^n by least squares in the logarithms */
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int nv = 0;
    for (int j = 0; j < NF; j++)
        if (D[j] > 0) {
            double lx = log(D[j]), ly = log(F[j]);
            sx += lx;
            sy += ly;
            sxx += lx * lx;
            sxy += lx * ly;
            nv++;
        }
    if (nv >= 2) {
        imp->fit_n = (nv * sxy - sx * sy) / (nv * sxx - sx * sx);
        imp->fit_c = exp((sy - imp->fit_n * sx) / nv);
    }
    /* F(delta_m) by interpolation in the logarithms between the bracketing solves */
    double Fm = NAN;
    if (imp->delta_m > 0) {
        for (int j = 0; j + 1 < NF; j++)
            if (D[j + 1] > 0 && D[j + 1] <= imp->delta_m && imp->delta_m <= D[j]) {
                double s = (log(imp->delta_m) - log(D[j + 1])) / (log(D[j]) - log(D[j + 1]));
                Fm = exp(log(F[j + 1]) + s * (log(F[j]) - log(F[j + 1])));
                break;
            }
        if (!isfinite(Fm) && isfinite(imp->fit_c))
            Fm = imp->fit_c * pow(imp->delta_m, imp->fit_n);
        imp->ks = Fm / imp->delta_m;
    }
    return GD_OK;
}

static gd_status mesh_in(gd_ltca *w, const gd_ltca_result *r, int half, double torque, gd_ltca_impact *imp,
                         gd_error *err)
{
    memset(imp, 0, sizeof *imp);
    double nan = NAN;
    imp->phi1 = imp->phase = imp->rho1 = imp->z1 = imp->offset_loa = imp->vs_per_omega = nan;
    imp->delta_m = imp->ks = imp->fit_c = imp->fit_n = nan;
    const double tau = w->t->tau1;
    int npos = r->npos;
    int pair = 0, kin;
    gd_status st = entry_pair(r, half, &pair, &kin, err);
    if (st != GD_OK || kin < 0)
        return st;
    double a = r->phi1[kin - 1], b = kin < npos ? r->phi1[kin] : tau;
    gd_ltca_position pos;
    st = bracket_touch(w, tau, half, pair, torque, &a, &b, &pos, err);
    if (st != GD_OK)
        return st;
    /* the state just before the touch: the mesh-in point is the pair's least deformed gap */
    entry_eval ea;
    st = eval_entry(w, a, torque, half, pair, &pos, &ea, err);
    if (st != GD_OK)
        return st;
    if (ea.imin < 0)
        return gd_error_set(err, GD_ERR_INTERNAL, "LTCA mesh-in: lost the incoming pair");
    imp->found = 1;
    imp->phi1 = fmod(a, tau);
    if (imp->phi1 < 0)
        imp->phi1 += tau;
    imp->phase = imp->phi1 / tau;
    imp->pair = pair;
    impact_geometry(w, &w->pts[ea.imin], imp);
    /* how early the pair meets: the loaded deflection of the half at that moment */
    imp->delta_m = pos.approach_half[half] - pos.geometric[half];
    return impact_stiffness(w, r, half, pair, torque, &pos, imp, err);
}

/* ---- the analysis ------------------------------------------------------------------------------ */

/* The arrays of the result for H halves and npos positions; on failure the caller frees r. */
static gd_status result_alloc(gd_ltca_result *r, int H, int npos, gd_error *err)
{
    size_t N = (size_t)npos;
    r->phi1 = malloc(N * sizeof *r->phi1);
    r->lte_arcsec = malloc(N * sizeof *r->lte_arcsec);
    r->axial_shift = malloc(N * sizeof *r->axial_shift);
    r->first = malloc((N + 1) * sizeof *r->first);
    int ok = r->phi1 && r->lte_arcsec && r->axial_shift && r->first;
    for (int h = 0; h < H && ok; h++) {
        r->gte_arcsec[h] = malloc(N * sizeof(double));
        r->lte_half_arcsec[h] = malloc(N * sizeof(double));
        r->load[h] = malloc(N * sizeof(double));
        r->stiffness[h] = malloc(N * sizeof(double));
        r->max_pressure[h] = malloc(N * sizeof(double));
        r->pairs_loaded[h] = malloc(N * sizeof(int));
        r->edge_loaded[h] = malloc(N * sizeof(unsigned));
        r->edge_ratio[h] = malloc(N * sizeof(double));
        ok = r->gte_arcsec[h] && r->lte_half_arcsec[h] && r->load[h] && r->stiffness[h] && r->max_pressure[h] &&
             r->pairs_loaded[h] && r->edge_loaded[h] && r->edge_ratio[h];
    }
    if (!ok)
        return gd_error_set(err, GD_ERR_NOMEM, "LTCA: out of memory for %d positions", npos);
    return GD_OK;
}

/* Solve the contact at every position of the cycle, keeping its results and its points. */
static gd_status sweep_positions(gd_ltca *w, double torque_nm, const gd_stop_hook *stop, gd_ltca_result *r,
                                 gd_error *err)
{
    const int H = r->halves, npos = r->npos;
    int cap = 0, np = 0;
    const double tau = w->t->tau1;
    r->min_load = INFINITY;
    for (int k = 0; k < npos; k++) {
        if (gd_stop_asked(stop))
            return gd_error_set(err, GD_ERR_INTERRUPTED, "LTCA: stopped at position %d of %d", k + 1, npos);
        double phi1 = tau * k / npos;
        gd_ltca_position pos;
        gd_status st = gd_ltca_solve_at(w, phi1, torque_nm, &pos, err);
        if (st != GD_OK)
            return st;
        r->phi1[k] = phi1;
        r->lte_arcsec[k] = pos.lte * ARCSEC;
        r->axial_shift[k] = pos.axial_shift;
        for (int h = 0; h < H; h++) {
            r->gte_arcsec[h][k] = -pos.geometric[h] / w->rb2cb * ARCSEC;
            r->lte_half_arcsec[h][k] = -pos.approach_half[h] / w->rb2cb * ARCSEC;
            r->load[h][k] = pos.load[h];
            r->stiffness[h][k] = pos.stiffness[h];
            r->max_pressure[h][k] = pos.max_pressure[h];
            r->pairs_loaded[h][k] = pos.pairs_loaded[h];
            r->edge_loaded[h][k] = pos.edge_loaded[h];
            r->edge_ratio[h][k] = pos.edge_ratio[h];
        }
        r->iterations += pos.iterations;
        r->max_residual = fmax(r->max_residual, pos.residual);
        r->max_balance = fmax(r->max_balance, pos.balance);
        r->window_max = fmax(r->window_max, pos.window);
        /* keep the points */
        if (np + w->n > cap) {
            int nc = cap ? cap : 1024;
            while (nc < np + w->n)
                nc *= 2;
            gd_ltca_point *pp = realloc(r->points, (size_t)nc * sizeof *pp);
            if (!pp)
                return gd_error_set(err, GD_ERR_NOMEM, "LTCA: out of memory for the contact points");
            r->points = pp;
            cap = nc;
        }
        memcpy(r->points + np, w->pts, (size_t)w->n * sizeof *w->pts);
        r->first[k] = np;
        /* the contact conditions, checked again here (independent of the solver's report) */
        double axial = 0;
        for (int i = 0; i < w->n; i++) {
            const gd_ltca_point *P = &w->pts[i];
            r->max_penetration = fmax(r->max_penetration, -P->deformed_gap);
            r->min_load = fmin(r->min_load, P->load);
            axial += P->load * P->normal[2];
        }
        if (w->floating)
            r->max_balance = fmax(r->max_balance, fabs(axial) / r->normal_force_n);
        np += w->n;
    }
    r->first[npos] = np;
    return GD_OK;
}

/* Statistics over the cycle: of the transmission error, and of each half's stiffness, load share,
 * pressure and edge loading. */
static void cycle_statistics(gd_ltca_result *r)
{
    const int H = r->halves, npos = r->npos;
    double lo = INFINITY, hi = -INFINITY, mean = 0;
    for (int k = 0; k < npos; k++) {
        lo = fmin(lo, r->lte_arcsec[k]);
        hi = fmax(hi, r->lte_arcsec[k]);
        mean += r->lte_arcsec[k] / npos;
    }
    r->lte_pp_arcsec = hi - lo;
    r->lte_mean_arcsec = mean;
    for (int h = 0; h < H; h++) {
        double glo = INFINITY, ghi = -INFINITY, ks = 0, share = 0, pairs = 0;
        r->stiffness_min[h] = INFINITY;
        r->stiffness_max[h] = -INFINITY;
        r->load_share_min[h] = INFINITY;
        r->load_share_max[h] = -INFINITY;
        for (int k = 0; k < npos; k++) {
            glo = fmin(glo, r->gte_arcsec[h][k]);
            ghi = fmax(ghi, r->gte_arcsec[h][k]);
            ks += r->stiffness[h][k] / npos;
            r->stiffness_min[h] = fmin(r->stiffness_min[h], r->stiffness[h][k]);
            r->stiffness_max[h] = fmax(r->stiffness_max[h], r->stiffness[h][k]);
            double sh = r->load[h][k] / r->normal_force_n;
            share += sh / npos;
            r->load_share_min[h] = fmin(r->load_share_min[h], sh);
            r->load_share_max[h] = fmax(r->load_share_max[h], sh);
            r->pressure_max[h] = fmax(r->pressure_max[h], r->max_pressure[h][k]);
            unsigned el = r->edge_loaded[h][k];
            r->edge_kinds[h] |= el;
            r->edge_positions[h] += (el & GD_EDGE_FACE_ENDS) != 0;
            r->tip_positions[h] += (el & GD_EDGE_TIPS_ROOTS) != 0;
            r->edge_ratio_max[h] = fmax(r->edge_ratio_max[h], r->edge_ratio[h][k]);
            pairs += (double)r->pairs_loaded[h][k] / npos;
            double edge = 0;
            for (int i = r->first[k]; i < r->first[k + 1]; i++)
                if (r->points[i].half == h && (r->points[i].edge & el) && r->points[i].load > 0)
                    edge += r->points[i].load;
            if (r->load[h][k] > 0)
                r->edge_load_max[h] = fmax(r->edge_load_max[h], edge / r->load[h][k]);
        }
        r->gte_pp_arcsec[h] = ghi - glo;
        r->stiffness_mean[h] = ks;
        r->load_share[h] = share;
        r->pairs_mean[h] = pairs;
    }
}

GD_API gd_status gd_ltca_run_opts(const gd_pair *pair, const gd_ltca_settings *set, int npos, int with_impact,
                                  gd_ltca_result *r, gd_error *err)
{
    memset(r, 0, sizeof *r);
    double t0 = gd_clock_wall_s();
    if (npos <= 0)
        npos = set->positions_per_cycle;
    if (npos < 2)
        return gd_error_set(err, GD_ERR_INPUT, "LTCA: %d positions per mesh cycle (valid: >= 2)", npos);
    if (!(set->torque_nm > 0))
        return gd_error_set(err, GD_ERR_INPUT, "operating.torque_nm: %g N m for LTCA (valid: > 0)", set->torque_nm);
    gd_ltca *w;
    gd_status st = gd_ltca_create(pair, set, &w, err);
    if (st != GD_OK)
        return st;
    int H = w->halves;
    r->halves = H;
    r->npos = npos;
    r->nslices = w->nslices;
    r->floating = w->floating;
    r->torque_nm = set->torque_nm;
    r->normal_force_n = gd_ltca_normal_force(w, set->torque_nm);
    r->cache_key = gd_ltca_cache_key(pair, set, npos);
    st = result_alloc(r, H, npos, err);
    if (st == GD_OK)
        st = sweep_positions(w, set->torque_nm, &set->stop, r, err);
    if (st != GD_OK)
        goto fail;
    cycle_statistics(r);
    if (with_impact)
        for (int h = 0; h < H; h++) {
            st = gd_stop_asked(&set->stop) ? gd_error_set(err, GD_ERR_INTERRUPTED, "LTCA: stopped before the mesh-in")
                                           : mesh_in(w, r, h, set->torque_nm, &r->impact[h], err);
            if (st != GD_OK)
                goto fail;
        }
    r->wall_s = gd_clock_wall_s() - t0;
    gd_ltca_free(w);
    return GD_OK;
fail:
    gd_ltca_free(w);
    gd_ltca_result_free(r);
    return st;
}

GD_API gd_status gd_ltca_run(const gd_pair *pair, const gd_ltca_settings *set, gd_ltca_result *r, gd_error *err)
{
    return gd_ltca_run_opts(pair, set, 0, 1, r, err);
}

/* ---- excitations of the dynamic model ---------------------------------------------------------- */

GD_API gd_status gd_ltca_mesh_stiffness(const gd_pair *pair, const gd_ltca_settings *set, int npos, double *k_left,
                                        double *k_right, double *lte_arcsec, double k_mean[2], gd_error *err)
{
    if (npos < 2)
        return gd_error_set(err, GD_ERR_INPUT, "LTCA mesh stiffness: %d positions (valid: >= 2)", npos);
    gd_ltca_result r;
    gd_status st = gd_ltca_run_opts(pair, set, npos, 0, &r, err);
    if (st != GD_OK)
        return st;
    for (int k = 0; k < npos; k++) {
        if (k_left)
            k_left[k] = r.stiffness[0][k];
        if (k_right && r.halves > 1)
            k_right[k] = r.stiffness[1][k];
        if (lte_arcsec)
            lte_arcsec[k] = r.lte_arcsec[k];
    }
    if (k_mean) {
        k_mean[0] = r.stiffness_mean[0];
        k_mean[1] = r.halves > 1 ? r.stiffness_mean[1] : NAN;
    }
    gd_ltca_result_free(&r);
    return GD_OK;
}

GD_API void gd_ltca_excitation_free(gd_ltca_excitation *x)
{
    if (!x)
        return;
    free(x->phi1);
    free(x->k[0]);
    free(x->k[1]);
    free(x->lte_arcsec);
    free(x->lte_half_arcsec[0]);
    free(x->lte_half_arcsec[1]);
    memset(x, 0, sizeof *x);
}

GD_API gd_status gd_ltca_excitation_compute(const gd_pair *pair, const gd_ltca_settings *set, int npos,
                                            gd_ltca_excitation *x, gd_error *err)
{
    memset(x, 0, sizeof *x);
    if (npos < 2)
        return gd_error_set(err, GD_ERR_INPUT, "LTCA excitation: %d positions (valid: >= 2)", npos);
    gd_ltca_result r;
    gd_status st = gd_ltca_run_opts(pair, set, npos, 1, &r, err);
    if (st != GD_OK)
        return st;
    x->halves = r.halves;
    x->npos = npos;
    size_t N = (size_t)npos;
    x->phi1 = malloc(N * sizeof(double));
    x->lte_arcsec = malloc(N * sizeof(double));
    int ok = x->phi1 && x->lte_arcsec;
    for (int h = 0; h < r.halves && ok; h++) {
        x->k[h] = malloc(N * sizeof(double));
        x->lte_half_arcsec[h] = malloc(N * sizeof(double));
        ok = x->k[h] != NULL && x->lte_half_arcsec[h] != NULL;
    }
    if (!ok) {
        gd_ltca_result_free(&r);
        gd_ltca_excitation_free(x);
        return gd_error_set(err, GD_ERR_NOMEM, "LTCA excitation: out of memory");
    }
    memcpy(x->phi1, r.phi1, N * sizeof(double));
    memcpy(x->lte_arcsec, r.lte_arcsec, N * sizeof(double));
    for (int h = 0; h < r.halves; h++) {
        memcpy(x->k[h], r.stiffness[h], N * sizeof(double));
        memcpy(x->lte_half_arcsec[h], r.lte_half_arcsec[h], N * sizeof(double));
        x->k_mean[h] = r.stiffness_mean[h];
        x->load_share[h] = r.load_share[h];
        x->impact[h] = r.impact[h];
    }
    if (r.halves < 2)
        x->k_mean[1] = x->load_share[1] = NAN;
    x->lte_pp_arcsec = r.lte_pp_arcsec;
    x->key = r.cache_key;
    gd_ltca_result_free(&r);
    return GD_OK;
}

/* ---- cache key -------------------------------------------------------------------------------- */

/* The key's bytes as they are produced: hashed (FNV-1a, byte after byte, so the hash of the whole
 * is the hash of the pieces in turn) and copied to buf as far as cap goes; len counts them all. */
typedef struct key_sink {
    uint64_t h;
    unsigned char *buf;
    size_t cap, len;
} key_sink;

static void key_put(key_sink *k, const void *data, size_t len)
{
    k->h = gd_fnv1a(k->h, data, len);
    if (k->buf && k->len < k->cap)
        memcpy(k->buf + k->len, data, len < k->cap - k->len ? len : k->cap - k->len);
    k->len += len;
}

static void key_name(key_sink *k, const char *name) { key_put(k, name, strlen(name) + 1); }

static void key_double(key_sink *k, const char *name, double v)
{
    key_name(k, name);
    if (v == 0)
        v = 0; /* -0 and +0 alike */
    key_put(k, &v, sizeof v);
}

static void key_int(key_sink *k, const char *name, int v)
{
    key_name(k, name);
    key_put(k, &v, sizeof v);
}

/* Every value LTCA reads (gd_ltca_create, gd_tca_create, gd_tooth_init, gd_geometry_compute,
 * gd_flank_pinion and gd_flank_gear), one field at a time after the name of its case key. */
static void key_stream(const gd_pair *p, const gd_ltca_settings *s, int npos, key_sink *k)
{
    k->h = GD_FNV1A_OFFSET_BASIS;
    k->len = 0;
    key_put(k, "geardyn-ltca-1", 14);
    key_double(k, "gear.normal_module_mm", p->normal_module_mm);
    key_int(k, "gear.teeth_pinion", p->teeth_pinion);
    key_int(k, "gear.teeth_gear", p->teeth_gear);
    key_double(k, "gear.helix_angle_deg", p->helix_angle_deg);
    key_double(k, "gear.normal_pressure_angle_deg", p->normal_pressure_angle_deg);
    key_double(k, "gear.profile_shift_pinion", p->profile_shift_pinion);
    key_double(k, "gear.profile_shift_gear", p->profile_shift_gear);
    key_double(k, "gear.addendum_coefficient", p->addendum_coefficient);
    key_double(k, "gear.dedendum_coefficient", p->dedendum_coefficient);
    key_double(k, "gear.face_width_pinion_mm", p->face_width_pinion_mm);
    key_double(k, "gear.face_width_gear_mm", p->face_width_gear_mm);
    key_double(k, "gear.groove_width_mm", p->groove_width_mm);
    key_double(k, "gear.bore_diameter_pinion_mm", p->bore_diameter_pinion_mm);
    key_double(k, "gear.bore_diameter_gear_mm", p->bore_diameter_gear_mm);
    key_double(k, "gear.youngs_modulus_gpa", p->youngs_modulus_gpa);
    key_double(k, "gear.poisson_ratio", p->poisson_ratio);
    key_int(k, "gear.arrangement", p->arrangement);
    key_int(k, "gear.pinion_hand", p->pinion_hand);
    key_double(k, "modification.root_relief_amount_um", p->root_relief_amount_um);
    key_double(k, "modification.root_relief_length_mm", p->root_relief_length_mm);
    key_double(k, "modification.tip_relief_amount_um", p->tip_relief_amount_um);
    key_double(k, "modification.tip_relief_length_mm", p->tip_relief_length_mm);
    key_double(k, "modification.lead_relief_inner_um", p->lead_relief_inner_um);
    key_double(k, "modification.lead_relief_outer_um", p->lead_relief_outer_um);
    key_double(k, "modification.lead_unmodified_length_mm", p->lead_unmodified_length_mm);
    key_double(k, "modification.lead_unmodified_centre_mm", p->lead_unmodified_centre_mm);
    key_double(k, "modification.helix_slope_um", p->helix_slope_um);
    key_double(k, "misalignment.axis_in_plane_arcmin", p->axis_in_plane_arcmin);
    key_double(k, "misalignment.axis_cross_plane_arcmin", p->axis_cross_plane_arcmin);
    key_double(k, "misalignment.centre_distance_error_mm", p->centre_distance_error_mm);
    key_double(k, "operating.torque_nm", s->torque_nm);
    key_int(k, "support.pinion_axial", s->pinion_axial);
    key_int(k, "solver.tca_profile_points", s->profile_points);
    key_int(k, "solver.tca_refine", s->refine);
    key_int(k, "solver.ltca_face_slices", s->face_slices);
    int np = npos > 0 ? npos : s->positions_per_cycle;
    key_put(k, &np, sizeof np);
}

GD_API uint64_t gd_ltca_cache_key(const gd_pair *pair, const gd_ltca_settings *set, int npos)
{
    key_sink k = {0};
    key_stream(pair, set, npos, &k);
    return k.h;
}

GD_API size_t gd_ltca_cache_key_bytes(const gd_pair *pair, const gd_ltca_settings *set, int npos, unsigned char *buf,
                                      size_t cap)
{
    key_sink k = {.buf = buf, .cap = cap};
    key_stream(pair, set, npos, &k);
    return k.len;
}
