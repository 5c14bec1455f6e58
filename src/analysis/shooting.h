/* Internal to the periodic-orbit files (periodic_orbit.c, continuation*.c, floquet.c): the shooting
 * system of an orbit of nper mesh periods in nseg segments, its Newton corrector (the parameter
 * fixed, or bordered by the pseudo-arclength condition) and the tangent of the solution curve. The
 * unknowns are u = (y_0, ..., y_{nseg-1}, p): the state at the start of each segment and the
 * parameter. */
#ifndef GD_SHOOTING_H
#define GD_SHOOTING_H

#include "geardyn/gd_periodic.h"

#define GD_SHOOT_UMAX (GD_PO_MAX_PERIODS * GD_MAX_STATE + 1)

typedef struct gd_shoot {
    gd_model_at_fn model_at;
    void *ctx;
    gd_solver_opts o;
    int n, nseg, per_seg, N; /* state size, segments, mesh periods per segment, N = nseg n */
    double dp_rel;           /* step of the central difference in p, relative to 1 + |p| */
    /* the weights of the arclength's inner product: <a, b> = sum w_i a_i b_i (1 for gd_po_solve; the
     * continuation's scaling of the state and the parameter, docs/continuation.md section 3) */
    double w[GD_SHOOT_UMAX];
    /* the last evaluation (gd_shoot_eval) */
    double r[GD_PO_MAX_PERIODS * GD_MAX_STATE];  /* r_k = P(y_k) - y_{k+1 mod nseg} */
    double rp[GD_PO_MAX_PERIODS * GD_MAX_STATE]; /* dr/dp (central difference) */
    double *Mk;                                  /* nseg monodromies of the segments, n x n each */
    long events[GD_MAX_CLEAR];                   /* events of the segments, by clearance */
    int jac_ok;              /* Mk and rp hold the last evaluation's Jacobian (with dr/dp) */
    int chord;               /* gd_shoot_correct (bordered) tries the chord iteration first */
    long chord_iterations;   /* chord iterations, over all corrections */
    /* the branch-point test of the last gd_shoot_tangent: D = det [dr/du; t^T] with t the tangent of
     * Euclidean length 1, as its sign and the logarithm of its modulus (docs/continuation.md) */
    int bp_sign;
    double bp_log;
} gd_shoot;

gd_status gd_shoot_init(gd_shoot *sh, gd_model_at_fn model_at, void *ctx, const gd_solver_opts *o, int n,
                        const gd_po_opts *po, gd_error *err);
void gd_shoot_free(gd_shoot *sh);
/* Residual and monodromies at u; with_p: also dr/dp. */
gd_status gd_shoot_eval(gd_shoot *sh, const double *u, int with_p, gd_error *err);
/* Newton from u (N + 1 values, in and out) until the max-norm of the residual is below tol: p
 * fixed (v NULL), or with the pseudo-arclength condition v . (u - u_pred) = 0 (the bordering row v
 * is the weighted tangent, so the condition holds to tol in the weighted norm: |g| below tol
 * sqrt(w_0)). *iters: linear solves with a new Jacobian. With sh->chord and the Jacobian of an
 * earlier evaluation at hand (bordered only), the chord iteration comes first: that Jacobian
 * kept, the residual from plain segment maps (no monodromy), while it contracts; Newton then
 * starts from the chord's iterate of smallest residual when that is below the residual it started
 * from (else from u as given). The last evaluation is at the returned u (with dr/dp when v is
 * given). */
gd_status gd_shoot_correct(gd_shoot *sh, double *u, const double *v, const double *u_pred, double tol, int max_iter,
                           int *iters, gd_error *err);
/* The tangent t of the solution curve at the last evaluation: [dr/dy dr/dp; v^T] t = [0; 1], of
 * length 1 in the weighted norm, oriented so that t . v > 0; and the branch-point test
 * (bp_sign, bp_log) of that point. */
gd_status gd_shoot_tangent(gd_shoot *sh, const double *v, double *t, gd_error *err);
/* The orbit at u from the last evaluation: its states, the monodromy of the whole orbit, the
 * Floquet multipliers and stability, the events. */
gd_status gd_shoot_orbit(const gd_shoot *sh, const double *u, gd_po *po, gd_error *err);

/* The scale of a state for the arclength and the tolerances: its max-norm, at least 1 (the state
 * is dimensionless: lengths over solver.characteristic_length_um). */
double gd_po_state_scale(const double *y, int n);
/* The tolerance of gd_po_opts.tol = 0: what the integration resolves of a state of scale Y, the
 * absolute error rtol Y + atol of its error control. */
double gd_po_tol_derived(const gd_solver_opts *o, double Y);

#endif
