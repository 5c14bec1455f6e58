/* The defining systems of the curves of codimension-one bifurcations of periodic orbits in two
 * parameters (curve_internal.h, docs/continuation.md section 8), built on the shooting equations:
 *
 *   fold, period doubling: the minimally augmented system of Govaerts, the orbit's residual r and the
 *     scalar g of [[M - s I, b], [c^T, 0]] [v; g] = [0; 1] (s = +1, -1), whose derivatives are
 *     g_z = -w^T (dM/dz) v with w the left solution; dM/dy_k in the direction of the segment's image of v
 *     is one extra monodromy per segment (the second derivative of the flow is symmetric), dM/dp v a
 *     single tangent vector at p +- dp;
 *   Neimark-Sacker: r and two entries of the 2 x 2 Schur complement G of
 *     [[M^2 - 2 kappa M + I, V], [W^T, 0]], G_ij,z = -Psi_i^T (M_z M + M M_z - 2 kappa M_z) X_j, kappa an
 *     unknown (G_ij,kappa = 2 Psi_i^T M X_j), with four extra monodromies (the directions X_1, X_2, M X_1,
 *     M X_2);
 *   grazing: r and, at the phase phi of the orbit's period, x_c - b = 0 and dx_c/dt = 0 for the clearance
 *     coordinate x_c, the orbit integrated with the clearance's mode held around the touch (no event
 *     there: the side where the contact does not happen), the derivatives from the tangents at the
 *     touch.
 *
 * Every finite difference keeps the contact-event sequence of the point it differentiates: one that
 * would change it is taken from the other side, and where both would, the Jacobian is refused (a
 * parameter's difference after trying smaller steps, as one whose one-sided halves disagree: a jump of
 * the model). */
#include "curve_internal.h"
#include "shooting.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

gd_status csys_init(csys *S, gd_model_at2_fn model_at, void *ctx, const gd_solver_opts *o, int kind, int n,
                    const gd_po_opts *po, gd_error *err)
{
    memset(S, 0, sizeof *S);
    if (po->nper < 1 || po->nper > GD_PO_MAX_PERIODS)
        return gd_error_set(err, GD_ERR_INPUT, "an orbit of %d mesh periods (valid: 1 to %d)", po->nper,
                            GD_PO_MAX_PERIODS);
    S->model_at = model_at;
    S->ctx = ctx;
    S->o = *o;
    S->kind = kind;
    S->n = n;
    S->nper = po->nper;
    S->nseg = po->multiple ? po->nper : 1;
    S->per_seg = po->nper / S->nseg;
    S->N = S->nseg * n;
    S->ne = kind == GD_CURVE_NEIMARK_SACKER || kind == GD_CURVE_GRAZING;
    S->D = S->N + 2 + S->ne;
    S->dp_rel = po->dp_rel > 0 ? po->dp_rel : cbrt(o->rtol);
    for (int i = 0; i < S->D; i++)
        S->w[i] = 1.0;
    S->gclr = -1;
    S->jump_q = -1;
    S->sus_q = -1;
    S->J = malloc(sizeof(double) * (size_t)(S->D - 1) * (size_t)S->D);
    if (!S->J)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a curve's Jacobian");
    return GD_OK;
}

void csys_free(csys *S)
{
    free(S->J);
    S->J = NULL;
}

double csys_t_graze(const csys *S, double phi)
{
    return (phi - floor(phi)) * S->nper * S->m.period;
}

/* x = A^-1 B for a dim x dim matrix A (row-major, destroyed) and nrhs right-hand sides B (dim x nrhs,
 * row-major, replaced by x), by GSL's LU decomposition */
static gd_status lu_solve(int dim, double *A, double *B, int nrhs, gd_error *err)
{
    gsl_matrix_view Am = gsl_matrix_view_array(A, (size_t)dim, (size_t)dim);
    gsl_permutation *perm = gsl_permutation_alloc((size_t)dim);
    gsl_vector *x = gsl_vector_alloc((size_t)dim);
    if (!perm || !x) {
        gsl_permutation_free(perm);
        gsl_vector_free(x);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a bordered system");
    }
    int signum, rc = gsl_linalg_LU_decomp(&Am.matrix, perm, &signum);
    for (int j = 0; j < nrhs && rc == GSL_SUCCESS; j++) {
        gsl_vector_view col = gsl_vector_view_array_with_stride(B + j, (size_t)nrhs, (size_t)dim);
        rc = gsl_linalg_LU_solve(&Am.matrix, perm, &col.vector, x);
        if (rc == GSL_SUCCESS)
            gsl_vector_memcpy(&col.vector, x);
    }
    gsl_permutation_free(perm);
    gsl_vector_free(x);
    if (rc != GSL_SUCCESS)
        return gd_error_set(err, GD_ERR_GSL, "a bordered system: gsl_linalg_LU: %s", gsl_strerror(rc));
    return GD_OK;
}

/* C = A B for n x n row-major matrices (C distinct from A and B) */
static void matmul(int n, const double *A, const double *B, double *C)
{
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double s = 0;
            for (int k = 0; k < n; k++)
                s += A[i * n + k] * B[k * n + j];
            C[i * n + j] = s;
        }
}

static void matvec(int n, const double *A, const double *x, double *y)
{
    for (int i = 0; i < n; i++) {
        double s = 0;
        for (int k = 0; k < n; k++)
            s += A[i * n + k] * x[k];
        y[i] = s;
    }
}

static void matTvec(int n, const double *A, const double *x, double *y)
{
    for (int i = 0; i < n; i++) {
        double s = 0;
        for (int k = 0; k < n; k++)
            s += A[k * n + i] * x[k];
        y[i] = s;
    }
}

/* The held window of a grazing curve in the local time of segment k (a run of per_seg periods): the
 * times within ghalf of the orbit's period of the touch */
void csys_hold_for(const csys *S, int k, double phi, gd_sim_hold *h)
{
    memset(h, 0, sizeof *h);
    if (S->kind != GD_CURVE_GRAZING)
        return;
    const double P = S->nper * S->m.period, Ts = S->per_seg * S->m.period, s0 = k * Ts;
    double hw = S->ghalf * P, a = csys_t_graze(S, phi) - hw - s0;
    double t0 = a - floor(a / P) * P, t1 = t0 + 2.0 * hw;
    h->clearance = S->gclr;
    h->side = S->gside;
    h->mode = S->gmode;
    if (t0 < Ts) {
        h->on = 1;
        h->t0 = t0;
        h->t1 = t1 > P ? t1 - P : t1; /* (a wrapped window when the run is the whole orbit) */
    } else if (t1 - P > 0) {
        h->on = 1;
        h->t0 = 0.0;
        h->t1 = t1 - P;
    }
}

/* One segment's run from y0 with ntan tangent vectors (the directions V, or the identity), the touch's
 * probe when it lies in the segment, and the grazing's held window. */
static gd_status seg_run(csys *S, const gd_model *m, int k, const double *y0, double phi, int ntan, const double *V,
                         gd_map_probe *pr, gd_gap_extrema *gaps, gd_error *err)
{
    memset(pr, 0, sizeof *pr);
    pr->ntan = ntan;
    pr->V = V;
    pr->t_probe = -1.0;
    pr->gaps = gaps;
    if (S->kind == GD_CURVE_GRAZING) {
        const double Ts = S->per_seg * m->period, tg = (phi - floor(phi)) * S->nper * m->period;
        int kg = (int)floor(tg / Ts);
        if (kg >= S->nseg)
            kg = S->nseg - 1;
        if (kg == k)
            pr->t_probe = fmin(fmax(tg - k * Ts, 0.0), Ts);
        csys_hold_for(S, k, phi, &pr->hold);
    }
    return gd_sim_map_probe(m, &S->o, y0, S->per_seg, pr, err);
}

/* ---- the defining equations at the last evaluation's monodromy ---- */

/* fold, period doubling: [[M - s I, b], [c^T, 0]] [v; g] = [0; 1] and its transpose for w */
static gd_status fold_pd_g(csys *S, gd_error *err)
{
    const int n = S->n, d = n + 1;
    const double s = S->kind == GD_CURVE_FOLD ? 1.0 : -1.0;
    double A[(GD_MAX_STATE + 1) * (GD_MAX_STATE + 1)], x[GD_MAX_STATE + 1];
    for (int t = 0; t < 2; t++) {
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++)
                A[i * d + j] = (t ? S->M[j * n + i] : S->M[i * n + j]) - (i == j ? s : 0.0);
            A[i * d + n] = t ? S->c[i] : S->b[i];
            A[n * d + i] = t ? S->b[i] : S->c[i];
            x[i] = 0.0;
        }
        A[n * d + n] = 0.0;
        x[n] = 1.0;
        gd_status st = lu_solve(d, A, x, 1, err);
        if (st != GD_OK)
            return st;
        memcpy(t ? S->wl : S->v, x, sizeof(double) * (size_t)n);
        if (!t)
            S->g = x[n];
    }
    return GD_OK;
}

/* B = M^2 - 2 kappa M + I */
static void ns_matrix(const csys *S, double kappa, double *B)
{
    const int n = S->n;
    matmul(n, S->M, S->M, B);
    for (int i = 0; i < n * n; i++)
        B[i] -= 2.0 * kappa * S->M[i];
    for (int i = 0; i < n; i++)
        B[i * n + i] += 1.0;
}

/* Neimark-Sacker: [[B, V], [W^T, 0]] [X; G] = [0; I2] and its transpose for Psi */
static gd_status ns_g(csys *S, double kappa, gd_error *err)
{
    const int n = S->n, d = n + 2;
    double B[NN], A[(GD_MAX_STATE + 2) * (GD_MAX_STATE + 2)], x[(GD_MAX_STATE + 2) * 2];
    ns_matrix(S, kappa, B);
    for (int t = 0; t < 2; t++) {
        memset(A, 0, sizeof(double) * (size_t)(d * d));
        memset(x, 0, sizeof(double) * (size_t)(d * 2));
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++)
                A[i * d + j] = t ? B[j * n + i] : B[i * n + j];
            for (int q = 0; q < 2; q++) {
                A[i * d + n + q] = t ? S->W[i * 2 + q] : S->V[i * 2 + q];
                A[(n + q) * d + i] = t ? S->V[i * 2 + q] : S->W[i * 2 + q];
            }
        }
        x[n * 2 + 0] = 1.0;
        x[(n + 1) * 2 + 1] = 1.0;
        gd_status st = lu_solve(d, A, x, 2, err);
        if (st != GD_OK)
            return st;
        memcpy(t ? S->Psi : S->X, x, sizeof(double) * (size_t)(n * 2));
        if (!t)
            memcpy(S->G, x + n * 2, sizeof(double) * 4);
    }
    return GD_OK;
}

/* The rows of the clearance coordinate and of its rate in the state (x_c = row_x . y - e(t)). */
static void clearance_rows(const gd_model *m, int c, double *rx, double *rv)
{
    memset(rx, 0, sizeof(double) * (size_t)m->n);
    memset(rv, 0, sizeof(double) * (size_t)m->n);
    const gd_clearance *cl = &m->clear[c];
    for (int q = 0; q < cl->nw; q++) {
        rx[cl->widx[q]] += cl->wval[q];
        rv[m->ndof + cl->widx[q]] += cl->wval[q];
    }
}

/* the clearance coordinate, rate and acceleration at the touch */
static void graze_values(csys *S, double tau)
{
    const gd_model *m = &S->m;
    gd_model_clearance(m, S->gclr, tau, S->yg, &S->mdg, &S->xg, &S->xdg);
    double f[GD_MAX_STATE], rx[GD_MAX_STATE], rv[GD_MAX_STATE], acc = 0;
    gd_model_rhs(m, tau, S->yg, f, &S->mdg);
    clearance_rows(m, S->gclr, rx, rv);
    for (int i = 0; i < m->n; i++)
        acc += rv[i] * f[i];
    const gd_clearance *cl = &m->clear[S->gclr];
    if (cl->kind == GD_CLR_MESH) {
        double e, ed, edd;
        gd_model_error(m, cl->mesh, tau, &S->mdg, &e, &ed, &edd);
        acc -= edd;
    }
    S->xddg = acc;
}

/* ---- the Jacobian ---- */

/* The extra runs of the Jacobian: nd directions d (at segment 0) and their images R_k d at the starts of
 * the segments; the monodromies moved along R_k d (dM[di][k] = (M_k(y_k + eps R_k d) - M_k) / eps, the
 * symmetric second derivative of the flow), and the parameter derivatives of the segment ends and of
 * the tangents started from R_k d. */
typedef struct jacx {
    int nd;
    double Rd[4][GD_PO_MAX_PERIODS][GD_MAX_STATE];
    double *dM;              /* [nd][nseg][n n] */
    double dy[2][GD_PO_MAX_PERIODS * GD_MAX_STATE]; /* d y_end / dp_q */
    double dT[2][4][GD_PO_MAX_PERIODS][GD_MAX_STATE]; /* d (M_k R_k d) / dp_q */
    double dxg[2], dxdg[2];  /* grazing: d x_c / dp_q, d xdot_c / dp_q at the touch */
} jacx;

/* left vectors a at the segments' ends: lam_k = M_{K-1}^T ... M_{k+1}^T a */
static void left_images(const csys *S, const double *a, double lam[][GD_MAX_STATE])
{
    const int n = S->n, K = S->nseg;
    memcpy(lam[K - 1], a, sizeof(double) * (size_t)n);
    for (int k = K - 2; k >= 0; k--)
        matTvec(n, S->Mk + (size_t)(k + 1) * n * n, lam[k + 1], lam[k]);
}

/* row (length N + 2: Y, p1, p2) += coef d/d(Y, p) [a^T M(Y, p) d_di] */
static void add_bilinear(const csys *S, const jacx *x, double coef, const double *a, int di, double *row)
{
    const int n = S->n, K = S->nseg, N = S->N;
    double lam[GD_PO_MAX_PERIODS][GD_MAX_STATE];
    left_images(S, a, lam);
    for (int k = 0; k < K; k++) {
        const double *dM = x->dM + ((size_t)di * K + k) * n * n;
        for (int j = 0; j < n; j++) {
            double s = 0;
            for (int i = 0; i < n; i++)
                s += lam[k][i] * dM[i * n + j];
            row[k * n + j] += coef * s;
        }
        for (int q = 0; q < 2; q++) {
            double s = 0;
            for (int i = 0; i < n; i++)
                s += lam[k][i] * x->dT[q][di][k][i];
            row[N + q] += coef * s;
        }
    }
}

/* The state's size in the max-norm, at least 1 */
static double vnorm(const double *y, int n)
{
    double s = 0;
    for (int i = 0; i < n; i++)
        s = fmax(s, fabs(y[i]));
    return s;
}

static gd_status seq_refused(csys *S, const char *what, gd_error *err)
{
    S->seq_changed = 1;
    return gd_error_set(err, GD_ERR_SOLVER, "the finite difference %s changes the contact sequence on both sides: "
                        "the orbit is at a grazing", what);
}

/* The directional runs: dM along R_k d for each direction (one-sided, taken from the side that keeps
 * the segment's contact sequence). */
static gd_status dir_runs(csys *S, const double *u, jacx *x, gd_error *err)
{
    const int n = S->n, K = S->nseg;
    const double phi = S->ne && S->kind == GD_CURVE_GRAZING ? u[S->N + 2] : 0.0;
    /* a fold curve's cusp coefficient is this derivative applied once more: a central difference
     * (eps = 0.3 rtol^(1/3): truncation and the integration's noise balanced; one-sided at sqrt(rtol)
     * the cusp moved 1.1e-7 relative between rtol 1e-9 and 1e-11, now 6e-9), one more run; else
     * one-sided, one extra run */
    const int central = S->kind == GD_CURVE_FOLD;
    for (int di = 0; di < x->nd; di++)
        for (int k = 0; k < K; k++) {
            const double *y = u + k * n, *d = x->Rd[di][k], *Mk = S->Mk + (size_t)k * n * n;
            double dn = vnorm(d, n), sc = fmax(1.0, vnorm(y, n)) / (dn > 0 ? dn : 1.0);
            double *dM = x->dM + ((size_t)di * K + k) * n * n;
            double T[2][GD_MAX_STATE * GD_MAX_STATE];
            int ok[2] = {0, 0};
            for (int side = 0; side < 2; side++) {
                double e = (central ? 0.3 * cbrt(S->o.rtol) : sqrt(S->o.rtol)) * sc * (side ? -1.0 : 1.0), yy[GD_MAX_STATE];
                for (int i = 0; i < n; i++)
                    yy[i] = y[i] + e * d[i];
                gd_map_probe pr;
                gd_status st = seg_run(S, &S->m, k, yy, phi, n, NULL, &pr, NULL, err);
                if (st != GD_OK)
                    return st;
                if (pr.seq == S->seq[k]) {
                    ok[side] = 1;
                    memcpy(T[side], pr.T1, sizeof(double) * (size_t)n * n);
                    if (!central)
                        break;
                }
            }
            if (ok[0] && ok[1]) {
                const double e = 0.3 * cbrt(S->o.rtol) * sc;
                for (int i = 0; i < n * n; i++)
                    dM[i] = (T[0][i] - T[1][i]) / (2.0 * e);
                continue;
            }
            if (!ok[0] && !ok[1])
                return seq_refused(S, "in the state", err);
            /* one side only: one-sided, from that side at sqrt(rtol) (the other changes the events) */
            const int side = ok[0] ? 0 : 1;
            double e = sqrt(S->o.rtol) * sc * (side ? -1.0 : 1.0), yy[GD_MAX_STATE];
            if (central) {
                for (int i = 0; i < n; i++)
                    yy[i] = y[i] + e * d[i];
                gd_map_probe pr;
                gd_status st = seg_run(S, &S->m, k, yy, phi, n, NULL, &pr, NULL, err);
                if (st != GD_OK)
                    return st;
                if (pr.seq != S->seq[k])
                    return seq_refused(S, "in the state", err);
                memcpy(T[side], pr.T1, sizeof(double) * (size_t)n * n);
            }
            for (int i = 0; i < n * n; i++)
                dM[i] = (T[side][i] - Mk[i]) / e;
        }
    return GD_OK;
}

/* Whether the central difference of the segment ends at p +- dp looks across a jump of the model: its
 * one-sided differences (against the point's own ends) disagree by more than half the larger, beyond the
 * integration's noise. A smooth residual differs between them by its curvature times dp only. */
static int one_sided_disagree(const csys *S, double yv[2][GD_PO_MAX_PERIODS][GD_MAX_STATE], const double *u,
                              double dp)
{
    const int n = S->n, K = S->nseg;
    double mism = 0, size = 0, ymax = 0;
    for (int k = 0; k < K; k++)
        for (int i = 0; i < n; i++) {
            double base = S->F[k * n + i] + u[((k + 1) % K) * n + i];
            double fw = (yv[0][k][i] - base) / dp, bw = (base - yv[1][k][i]) / dp;
            mism = fmax(mism, fabs(fw - bw));
            size = fmax(size, fmax(fabs(fw), fabs(bw)));
            ymax = fmax(ymax, fabs(base));
        }
    const double noise = 100.0 * (S->o.rtol * (1.0 + ymax) + S->o.atol) / dp;
    return mism > 0.5 * size + noise;
}

/* The parameter runs: the segment ends, the tangents from R_k d and the touch at p_q +- dp. A difference
 * that changes the contact sequence on both sides, or whose one-sided halves disagree (the model jumps
 * within dp: the mesh-in impact of an LTCA excitation when its first touch moves to another point of the
 * flank), is taken again at an eighth of the step, down to DP_SHRINKS times; then the Jacobian is
 * refused (S->jump_q set for a jump). */
#define DP_SHRINKS 4
static gd_status par_runs(csys *S, const double *u, jacx *x, gd_error *err)
{
    const int n = S->n, K = S->nseg, N = S->N, nd = x->nd;
    const double phi = S->kind == GD_CURVE_GRAZING ? u[N + 2] : 0.0;
    S->jump_q = -1;
    for (int q = 0; q < 2; q++) {
        double p = u[N + q], dp = S->dp_rel * (1.0 + fabs(p));
        double yv[2][GD_PO_MAX_PERIODS][GD_MAX_STATE], Tv[2][4][GD_PO_MAX_PERIODS][GD_MAX_STATE], xg[2], xdg[2];
        int ok[2] = {1, 1};
        for (int shrink = 0;; shrink++, dp *= 0.125) {
            ok[0] = ok[1] = 1;
            for (int side = 0; side < 2; side++) {
                double pp[2] = {u[N], u[N + 1]};
                pp[q] = p + (side ? -dp : dp);
                gd_model m;
                gd_error e1 = {0};
                gd_status st = S->model_at(pp[0], pp[1], &m, S->ctx, &e1);
                if (st == GD_ERR_INPUT) { /* beyond the model's validity: from the other side */
                    ok[side] = 0;
                    continue;
                }
                if (st != GD_OK)
                    return gd_error_set(err, st, "%s", e1.msg);
                gd_model keep = S->m;
                S->m = m; /* (the held window's times follow the model's period) */
                for (int k = 0; k < K && ok[side]; k++) {
                    double V[GD_MAX_STATE * 4];
                    for (int i = 0; i < n; i++)
                        for (int di = 0; di < nd; di++)
                            V[i * nd + di] = x->Rd[di][k][i];
                    /* more directions than the state has (Neimark-Sacker on n < 4): the whole monodromy, applied */
                    const int whole = nd > n;
                    gd_map_probe pr;
                    st = seg_run(S, &m, k, u + k * n, phi, whole ? n : nd, whole ? NULL : nd ? V : NULL, &pr, NULL, err);
                    if (st != GD_OK) {
                        S->m = keep;
                        return st;
                    }
                    if (pr.seq != S->seq[k]) {
                        ok[side] = 0;
                        break;
                    }
                    memcpy(yv[side][k], pr.y1, sizeof(double) * (size_t)n);
                    for (int di = 0; di < nd; di++)
                        if (whole)
                            matvec(n, pr.T1, x->Rd[di][k], Tv[side][di][k]);
                        else
                            for (int i = 0; i < n; i++)
                                Tv[side][di][k][i] = pr.T1[i * nd + di];
                    if (pr.t_probe >= 0) {
                        gd_model_clearance(&m, S->gclr, pr.t_probe, pr.yp, &pr.mdp, &xg[side], &xdg[side]);
                    }
                }
                S->m = keep;
            }
            const int jump = ok[0] && ok[1] && one_sided_disagree(S, yv, u, dp);
            if (jump) { /* a jump of the model within dp of p, perhaps (or a steep residual): kept for csys_find_jump */
                S->sus_q = q;
                S->sus_dp = dp;
                memcpy(S->sus_u, u, sizeof(double) * (size_t)S->D);
            }
            if ((ok[0] || ok[1]) && !jump)
                break;
            if (shrink == DP_SHRINKS) {
                if (!jump)
                    return seq_refused(S, "in a parameter", err);
                S->jump_q = q;
                S->jump_p = p;
                S->jump_dp = dp;
                return gd_error_set(err, GD_ERR_SOLVER, "the model is discontinuous in parameter %d within %.3g of %.10g: "
                                    "the one-sided differences of the orbit's residual disagree at every step down to that",
                                    q + 1, dp, p);
            }
        }
        /* central, or one-sided against the point itself */
        double h = ok[0] && ok[1] ? 2.0 * dp : dp;
        for (int k = 0; k < K; k++) {
            for (int i = 0; i < n; i++) {
                double base = S->F[k * n + i] + u[((k + 1) % K) * n + i];
                double hi = ok[0] ? yv[0][k][i] : base, lo = ok[1] ? yv[1][k][i] : base;
                x->dy[q][k * n + i] = (hi - lo) / h;
            }
            for (int di = 0; di < nd; di++) {
                double base[GD_MAX_STATE];
                matvec(n, S->Mk + (size_t)k * n * n, x->Rd[di][k], base);
                for (int i = 0; i < n; i++) {
                    double hi = ok[0] ? Tv[0][di][k][i] : base[i], lo = ok[1] ? Tv[1][di][k][i] : base[i];
                    x->dT[q][di][k][i] = (hi - lo) / h;
                }
            }
        }
        if (S->kind == GD_CURVE_GRAZING) {
            double hi = ok[0] ? xg[0] : S->xg, lo = ok[1] ? xg[1] : S->xg;
            x->dxg[q] = (hi - lo) / h;
            hi = ok[0] ? xdg[0] : S->xdg, lo = ok[1] ? xdg[1] : S->xdg;
            x->dxdg[q] = (hi - lo) / h;
        }
    }
    return GD_OK;
}

static gd_status jacobian(csys *S, const double *u, gd_error *err)
{
    const int n = S->n, K = S->nseg, N = S->N, D = S->D, NE = D - 1;
    jacx *x = calloc(1, sizeof *x);
    if (!x)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a curve's Jacobian");
    double MX[2][GD_MAX_STATE];
    if (S->kind == GD_CURVE_FOLD || S->kind == GD_CURVE_PERIOD_DOUBLING) {
        x->nd = 1;
        memcpy(x->Rd[0][0], S->v, sizeof(double) * (size_t)n);
    } else if (S->kind == GD_CURVE_NEIMARK_SACKER) {
        x->nd = 4;
        for (int j = 0; j < 2; j++) {
            for (int i = 0; i < n; i++)
                x->Rd[j][0][i] = S->X[i * 2 + j];
            matvec(n, S->M, x->Rd[j][0], MX[j]);
            memcpy(x->Rd[2 + j][0], MX[j], sizeof(double) * (size_t)n);
        }
    }
    for (int di = 0; di < x->nd; di++)
        for (int k = 1; k < K; k++)
            matvec(n, S->Mk + (size_t)(k - 1) * n * n, x->Rd[di][k - 1], x->Rd[di][k]);
    gd_status st = GD_OK;
    if (x->nd) {
        x->dM = malloc(sizeof(double) * (size_t)x->nd * K * n * n);
        if (!x->dM)
            st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for a curve's Jacobian");
        if (st == GD_OK)
            st = dir_runs(S, u, x, err);
    }
    if (st == GD_OK)
        st = par_runs(S, u, x, err);
    if (st != GD_OK) {
        free(x->dM);
        free(x);
        return st;
    }
    double *J = S->J;
    memset(J, 0, sizeof(double) * (size_t)NE * D);
    for (int k = 0; k < K; k++) {
        const double *Mk = S->Mk + (size_t)k * n * n;
        int kn = ((k + 1) % K) * n;
        for (int i = 0; i < n; i++) {
            double *row = J + (size_t)(k * n + i) * D;
            for (int j = 0; j < n; j++)
                row[k * n + j] = Mk[i * n + j];
            row[kn + i] -= 1.0;
            row[N] = x->dy[0][k * n + i];
            row[N + 1] = x->dy[1][k * n + i];
        }
    }
    double *r1 = J + (size_t)N * D, *r2 = NE > N + 1 ? J + (size_t)(N + 1) * D : NULL;
    if (S->kind == GD_CURVE_FOLD || S->kind == GD_CURVE_PERIOD_DOUBLING) {
        add_bilinear(S, x, -1.0, S->wl, 0, r1);
        /* the fold's quadratic coefficient w^T D^2 P[v, v] / (w^T v): D^2 P[v, v] = sum_k L_k D^2 phi_k[R_k v, R_k v] */
        double lam[GD_PO_MAX_PERIODS][GD_MAX_STATE], a = 0, wv = 0;
        left_images(S, S->wl, lam);
        for (int k = 0; k < K; k++) {
            double t[GD_MAX_STATE];
            matvec(n, x->dM + (size_t)k * n * n, x->Rd[0][k], t);
            for (int i = 0; i < n; i++)
                a += lam[k][i] * t[i];
        }
        for (int i = 0; i < n; i++)
            wv += S->wl[i] * S->v[i];
        S->cusp = a / wv;
    } else if (S->kind == GD_CURVE_NEIMARK_SACKER) {
        double kappa = u[N + 2], psi0[GD_MAX_STATE], mtpsi[GD_MAX_STATE];
        for (int i = 0; i < n; i++)
            psi0[i] = S->Psi[i * 2 + 0];
        matTvec(n, S->M, psi0, mtpsi);
        for (int j = 0; j < 2; j++) {
            double *row = j ? r2 : r1;
            /* G_0j,z = -[D(Psi_0, M X_j) - 2 kappa D(Psi_0, X_j) + D(M^T Psi_0, X_j)] */
            add_bilinear(S, x, -1.0, psi0, 2 + j, row);
            add_bilinear(S, x, 2.0 * kappa, psi0, j, row);
            add_bilinear(S, x, -1.0, mtpsi, j, row);
            double s = 0;
            for (int i = 0; i < n; i++)
                s += psi0[i] * MX[j][i];
            row[N + 2] = 2.0 * s;
        }
    } else { /* grazing */
        double rx[GD_MAX_STATE], rv[GD_MAX_STATE];
        clearance_rows(&S->m, S->gclr, rx, rv);
        for (int j = 0; j < n; j++) {
            double sx = 0, sv = 0;
            for (int i = 0; i < n; i++) {
                sx += rx[i] * S->Phig[i * n + j];
                sv += rv[i] * S->Phig[i * n + j];
            }
            r1[S->kg * n + j] = sx;
            r2[S->kg * n + j] = sv;
        }
        double P = S->nper * S->m.period;
        r1[N] = x->dxg[0], r1[N + 1] = x->dxg[1], r1[N + 2] = S->xdg * P;
        r2[N] = x->dxdg[0], r2[N + 1] = x->dxdg[1], r2[N + 2] = S->xddg * P;
    }
    free(x->dM);
    free(x);
    S->jac_ok = 1;
    return GD_OK;
}

/* The orbit's residual at the state of u with parameter q at p (the other parameter as in u); ok 0 when the
 * model is not valid there. The contact sequence may differ from the curve's: the contact forces are
 * continuous in the state, so a sequence that changes with p bends the residual (a kink) but does not
 * make it jump, and on the far side of a jump of the model the sequence at u's state usually differs. */
static gd_status residual_at(csys *S, const double *u, int q, double p, double *r, int *ok, gd_error *err)
{
    const int n = S->n, K = S->nseg, N = S->N;
    double pp[2] = {u[N], u[N + 1]};
    pp[q] = p;
    gd_model m;
    gd_error e1 = {0};
    *ok = 0;
    gd_status st = S->model_at(pp[0], pp[1], &m, S->ctx, &e1);
    if (st == GD_ERR_INPUT)
        return GD_OK;
    if (st != GD_OK)
        return gd_error_set(err, st, "%s", e1.msg);
    gd_model keep = S->m;
    S->m = m;
    const double phi = S->kind == GD_CURVE_GRAZING ? u[N + 2] : 0.0;
    for (int k = 0; k < K && st == GD_OK; k++) {
        gd_map_probe pr;
        st = seg_run(S, &m, k, u + k * n, phi, 0, NULL, &pr, NULL, err);
        if (st != GD_OK)
            break;
        for (int i = 0; i < n; i++)
            r[k * n + i] = pr.y1[i] - u[((k + 1) % K) * n + i];
    }
    S->m = keep;
    *ok = st == GD_OK;
    return st;
}

static double diff_norm(int N, const double *a, const double *b)
{
    double d = 0;
    for (int i = 0; i < N; i++)
        d = fmax(d, fabs(a[i] - b[i]));
    return d;
}

/* Bisection for a jump of the model in parameter q within [lo, hi], the orbit's residual at the state of
 * u, down to w_end: the half whose ends differ more is kept. A jump keeps its size however narrow the
 * bracket; a smooth residual's difference halves with it, so the jump is found when the ends still
 * differ, at the end, by a quarter of what they did four halvings before and by more than the
 * integration's noise. */
static gd_status bisect_jump(csys *S, const double *u, int q, double lo, double hi, double w_end,
                             int *found, double *pj, double *width, gd_error *err)
{
    const int N = S->N;
    double rlo[CMAX], rhi[CMAX], rmid[CMAX], hist[4];
    int ok_lo, ok_hi, ok_mid, k = 0;
    *found = 0;
    gd_status st = residual_at(S, u, q, lo, rlo, &ok_lo, err);
    if (st == GD_OK)
        st = residual_at(S, u, q, hi, rhi, &ok_hi, err);
    if (st != GD_OK || !ok_lo || !ok_hi)
        return st;
    double ymax = 0;
    for (int i = 0; i < N; i++)
        ymax = fmax(ymax, fabs(u[i]));
    const double noise = 100.0 * (S->o.rtol * (1.0 + ymax) + S->o.atol);
    while (hi - lo > w_end) {
        hist[k++ % 4] = diff_norm(N, rlo, rhi);
        const double mid = 0.5 * (lo + hi);
        st = residual_at(S, u, q, mid, rmid, &ok_mid, err);
        if (st != GD_OK || !ok_mid)
            return st;
        if (diff_norm(N, rlo, rmid) >= diff_norm(N, rmid, rhi)) {
            hi = mid;
            memcpy(rhi, rmid, sizeof(double) * (size_t)N);
        } else {
            lo = mid;
            memcpy(rlo, rmid, sizeof(double) * (size_t)N);
        }
    }
    const double d1 = diff_norm(N, rlo, rhi);
    if (k >= 4 && d1 > 0.25 * hist[k % 4] && d1 > noise) {
        *found = 1;
        *pj = 0.5 * (lo + hi);
        *width = hi - lo;
    }
    return GD_OK;
}

gd_status csys_find_jump(csys *S, int *q, double *pj, double *width, int *found, gd_error *err)
{
    *found = 0;
    if (S->sus_q < 0)
        return GD_OK;
    const int N = S->N;
    const double p0 = S->sus_u[N + S->sus_q];
    *q = S->sus_q;
    return bisect_jump(S, S->sus_u, S->sus_q, p0 - S->sus_dp, p0 + S->sus_dp,
                       S->dp_rel * (1.0 + fabs(p0)) / 4096.0, found, pj, width, err);
}

gd_status csys_find_jump_between(csys *S, const double *u, int q, double p0, double p1, double *pj, double *width,
                                 int *found, gd_error *err)
{
    *found = 0;
    if (!S->seq_set || p0 == p1)
        return GD_OK;
    const double w_end = S->dp_rel * (1.0 + fabs(p0)) / 4096.0;
    gd_status st = bisect_jump(S, u, q, fmin(p0, p1), fmax(p0, p1), w_end, found, pj, width, err);
    /* the bisection keeps the half whose ends differ more, so with several jumps between p0 and p1 it finds
     * one of them: the one nearest p0 is sought between p0 and the last found, until there is none */
    for (int k = 0; k < 8 && st == GD_OK && *found; k++) {
        const double end = *pj + (p1 > p0 ? -1.0 : 1.0) * *width;
        if ((end - p0) * (p1 - p0) <= 0)
            break;
        int near = 0;
        double pn, wn;
        st = bisect_jump(S, u, q, fmin(p0, end), fmax(p0, end), w_end, &near, &pn, &wn, err);
        if (st != GD_OK || !near)
            break;
        *pj = pn;
        *width = wn;
    }
    return st;
}

gd_status csys_eval(csys *S, const double *u, int jac, gd_error *err)
{
    const int n = S->n, K = S->nseg, N = S->N;
    S->jac_ok = 0;
    S->seq_changed = 0;
    S->jump_q = -1;
    S->have_M = 0;
    gd_status st = S->model_at(u[N], u[N + 1], &S->m, S->ctx, err);
    if (st != GD_OK)
        return st;
    const int graze = S->kind == GD_CURVE_GRAZING, need_M = !graze || jac;
    const double phi = graze ? u[N + 2] : 0.0;
    memset(S->events, 0, sizeof S->events);
    for (int k = 0; k < K; k++) {
        gd_map_probe pr;
        st = seg_run(S, &S->m, k, u + k * n, phi, need_M ? n : 0, NULL, &pr, NULL, err);
        if (st != GD_OK)
            return st;
        const double *next = u + ((k + 1) % K) * n;
        for (int i = 0; i < n; i++)
            S->F[k * n + i] = pr.y1[i] - next[i];
        if (need_M)
            memcpy(S->Mk + (size_t)k * n * n, pr.T1, sizeof(double) * (size_t)(n * n));
        S->seq[k] = pr.seq;
        for (int c = 0; c < S->m.nclear; c++)
            S->events[c] += pr.events[c];
        if (pr.t_probe >= 0) {
            S->kg = k;
            memcpy(S->yg, pr.yp, sizeof(double) * (size_t)n);
            memcpy(S->Phig, pr.Tp, sizeof(double) * (size_t)(n * n));
            S->mdg = pr.mdp;
            graze_values(S, pr.t_probe);
        }
    }
    if (S->seq_set)
        for (int k = 0; k < K; k++)
            S->seq_changed |= S->seq[k] != S->seq_ref[k];
    double mnorm = 0;
    if (need_M) {
        double T[NN];
        memcpy(S->M, S->Mk, sizeof(double) * (size_t)(n * n));
        for (int k = 1; k < K; k++) {
            matmul(n, S->Mk + (size_t)k * n * n, S->M, T);
            memcpy(S->M, T, sizeof(double) * (size_t)(n * n));
        }
        S->have_M = 1;
        for (int i = 0; i < n; i++) {
            double s = 0;
            for (int j = 0; j < n; j++)
                s += fabs(S->M[i * n + j]);
            mnorm = fmax(mnorm, s);
        }
    }
    if (S->kind == GD_CURVE_FOLD || S->kind == GD_CURVE_PERIOD_DOUBLING) {
        st = fold_pd_g(S, err);
        S->F[N] = S->g;
        S->rtol_g = 10.0 * S->o.rtol * (1.0 + mnorm) + S->o.atol;
    } else if (S->kind == GD_CURVE_NEIMARK_SACKER) {
        st = ns_g(S, u[N + 2], err);
        S->F[N] = S->G[0];
        S->F[N + 1] = S->G[1];
        S->rtol_g = 10.0 * S->o.rtol * (1.0 + mnorm) * (1.0 + mnorm) + S->o.atol;
    } else {
        if (!(S->kg >= 0 && S->kg < K))
            return gd_error_set(err, GD_ERR_INTERNAL, "the grazing's probe lies in no segment");
        S->F[N] = S->xg - (S->gside ? -S->m.clear[S->gclr].h : S->m.clear[S->gclr].h);
        S->F[N + 1] = S->xdg;
        S->rtol_g = 0.0;
    }
    if (st == GD_OK && jac)
        st = jacobian(S, u, err);
    return st;
}

/* The real basis of the plane spanned by the columns of X (n x 2) in which M acts as the rotation-scaling
 * [[alpha, beta], [-beta, alpha]] (its pair alpha +- i beta complex; otherwise X as it is) */
static void ns_basis(int n, const double *M, const double *X, double *Vout)
{
    double XtX[4] = {0}, XtMX[4] = {0}, MX[GD_MAX_STATE * 2];
    for (int j = 0; j < 2; j++) {
        double col[GD_MAX_STATE], mc[GD_MAX_STATE];
        for (int i = 0; i < n; i++)
            col[i] = X[i * 2 + j];
        matvec(n, M, col, mc);
        for (int i = 0; i < n; i++)
            MX[i * 2 + j] = mc[i];
    }
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++)
            for (int i = 0; i < n; i++) {
                XtX[a * 2 + b] += X[i * 2 + a] * X[i * 2 + b];
                XtMX[a * 2 + b] += X[i * 2 + a] * MX[i * 2 + b];
            }
    double det = XtX[0] * XtX[3] - XtX[1] * XtX[2];
    double R[4] = {(XtX[3] * XtMX[0] - XtX[1] * XtMX[2]) / det, (XtX[3] * XtMX[1] - XtX[1] * XtMX[3]) / det,
                   (-XtX[2] * XtMX[0] + XtX[0] * XtMX[2]) / det, (-XtX[2] * XtMX[1] + XtX[0] * XtMX[3]) / det};
    double tr = R[0] + R[3], dt = R[0] * R[3] - R[1] * R[2], disc = tr * tr / 4.0 - dt;
    double P[4] = {1, 0, 0, 1};
    if (disc < 0 && isfinite(disc) && fabs(R[1]) > 0) {
        /* the eigenvector z = (r12, lambda - r11) of lambda = alpha + i beta: P = [Re z, Im z] */
        double alpha = tr / 2.0, beta = sqrt(-disc);
        P[0] = R[1], P[1] = 0.0, P[2] = alpha - R[0], P[3] = beta;
    }
    double scale = 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < 2; j++) {
            Vout[i * 2 + j] = X[i * 2 + 0] * P[0 * 2 + j] + X[i * 2 + 1] * P[1 * 2 + j];
            scale += Vout[i * 2 + j] * Vout[i * 2 + j];
        }
    scale = sqrt(scale / 2.0);
    for (int i = 0; i < 2 * n; i++)
        Vout[i] /= scale > 0 ? scale : 1.0;
}

/* W from the left basis Psi (n x 2) with W^T V = I */
static void ns_left(int n, const double *V, const double *Psi, double *Wout)
{
    double A[4] = {0};
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++)
            for (int i = 0; i < n; i++)
                A[a * 2 + b] += Psi[i * 2 + a] * V[i * 2 + b]; /* Psi^T V */
    double det = A[0] * A[3] - A[1] * A[2];
    /* Q = (Psi^T V)^-T: W = Psi Q, W^T V = Q^T Psi^T V = I */
    double inv[4] = {A[3] / det, -A[1] / det, -A[2] / det, A[0] / det}, Q[4] = {inv[0], inv[2], inv[1], inv[3]};
    for (int i = 0; i < n; i++)
        for (int j = 0; j < 2; j++)
            Wout[i * 2 + j] = Psi[i * 2 + 0] * Q[0 * 2 + j] + Psi[i * 2 + 1] * Q[1 * 2 + j];
}

void csys_refresh_borders(csys *S, const double *M, const double *v, const double *wl, const double *X,
                          const double *Psi)
{
    const int n = S->n;
    if (S->kind == GD_CURVE_FOLD || S->kind == GD_CURVE_PERIOD_DOUBLING) {
        double nv = 0, nw = 0;
        for (int i = 0; i < n; i++)
            nv += v[i] * v[i], nw += wl[i] * wl[i];
        nv = sqrt(nv), nw = sqrt(nw);
        if (!(nv > 0 && nw > 0 && isfinite(nv) && isfinite(nw)))
            return;
        for (int i = 0; i < n; i++)
            S->c[i] = v[i] / nv, S->b[i] = wl[i] / nw;
    } else if (S->kind == GD_CURVE_NEIMARK_SACKER) {
        double V[GD_MAX_STATE * 2], W[GD_MAX_STATE * 2];
        ns_basis(n, M, X, V);
        ns_left(n, V, Psi, W);
        for (int i = 0; i < 2 * n; i++)
            if (!isfinite(V[i]) || !isfinite(W[i]))
                return;
        memcpy(S->V, V, sizeof V);
        memcpy(S->W, W, sizeof W);
    }
}

/* The orbit's monodromy at u (into S->M; the borders do not enter it) */
static gd_status monodromy_at(csys *S, const double *u, gd_error *err)
{
    const int n = S->n, K = S->nseg, N = S->N;
    gd_status st = S->model_at(u[N], u[N + 1], &S->m, S->ctx, err);
    for (int k = 0; k < K && st == GD_OK; k++) {
        gd_map_probe pr;
        st = seg_run(S, &S->m, k, u + k * n, S->ne ? u[N + 2] : 0.0, n, NULL, &pr, NULL, err);
        if (st == GD_OK)
            memcpy(S->Mk + (size_t)k * n * n, pr.T1, sizeof(double) * (size_t)(n * n));
    }
    if (st != GD_OK)
        return st;
    double T[NN];
    memcpy(S->M, S->Mk, sizeof(double) * (size_t)(n * n));
    for (int k = 1; k < K; k++) {
        matmul(n, S->Mk + (size_t)k * n * n, S->M, T);
        memcpy(S->M, T, sizeof(double) * (size_t)(n * n));
    }
    S->have_M = 1;
    return GD_OK;
}

gd_status csys_start_borders(csys *S, const double *u, gd_error *err)
{
    const int n = S->n;
    if (S->kind == GD_CURVE_GRAZING)
        return GD_OK;
    gd_status st = monodromy_at(S, u, err);
    if (st != GD_OK)
        return st;
    double A[NN];
    if (S->kind == GD_CURVE_NEIMARK_SACKER) {
        ns_matrix(S, u[S->N + 2], A);
    } else {
        const double s = S->kind == GD_CURVE_FOLD ? 1.0 : -1.0;
        memcpy(A, S->M, sizeof(double) * (size_t)(n * n));
        for (int i = 0; i < n; i++)
            A[i * n + i] -= s;
    }
    gsl_matrix_view Am = gsl_matrix_view_array(A, (size_t)n, (size_t)n);
    gsl_matrix *Vm = gsl_matrix_alloc((size_t)n, (size_t)n);
    gsl_vector *sv = gsl_vector_alloc((size_t)n), *work = gsl_vector_alloc((size_t)n);
    int rc = Vm && sv && work ? gsl_linalg_SV_decomp(&Am.matrix, Vm, sv, work) : GSL_ENOMEM;
    if (rc == GSL_SUCCESS) {
        /* A holds U: the left singular vectors; Vm the right ones; the smallest singular values last */
        if (S->kind == GD_CURVE_NEIMARK_SACKER) {
            double X[GD_MAX_STATE * 2], Psi[GD_MAX_STATE * 2];
            for (int i = 0; i < n; i++)
                for (int j = 0; j < 2; j++) {
                    X[i * 2 + j] = gsl_matrix_get(Vm, (size_t)i, (size_t)(n - 2 + j));
                    Psi[i * 2 + j] = A[i * n + (n - 2 + j)];
                }
            ns_basis(n, S->M, X, S->V);
            ns_left(n, S->V, Psi, S->W);
        } else {
            for (int i = 0; i < n; i++) {
                S->c[i] = gsl_matrix_get(Vm, (size_t)i, (size_t)(n - 1));
                S->b[i] = A[i * n + (n - 1)];
            }
        }
    }
    gsl_matrix_free(Vm);
    gsl_vector_free(sv);
    gsl_vector_free(work);
    if (rc != GSL_SUCCESS)
        return gd_error_set(err, GD_ERR_GSL, "the first borders: gsl_linalg_SV_decomp: %s", gsl_strerror(rc));
    return GD_OK;
}
