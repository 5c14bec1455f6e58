/* Internal to the curves of codimension-one bifurcations in two parameters (gd_envelope.h):
 * curve_system.c evaluates a curve's defining system and its Jacobian, curve.c follows it and
 * locates the codimension-two points on it. docs/continuation.md section 8 derives the systems.
 *
 * The unknowns are u = (Y, p1, p2[, e]): Y the states y_0 .. y_{nseg-1} at the starts of the
 * shooting segments, the two parameters and, for a Neimark-Sacker curve, kappa = cos theta or, for a
 * grazing curve, the phase phi of the touch in the orbit's period (t_g = phi nper T). The equations
 * are the shooting residual r (N = nseg n) and one (fold, period doubling) or two (Neimark-Sacker,
 * grazing) more. */
#ifndef GD_CURVE_INTERNAL_H
#define GD_CURVE_INTERNAL_H

#include "geardyn/gd_envelope.h"
#include "../dynamics/sim_probe.h"

#define CMAX (GD_PO_MAX_PERIODS * GD_MAX_STATE + 3) /* unknowns at most */
#define NN (GD_MAX_STATE * GD_MAX_STATE)

typedef struct csys {
    gd_model_at2_fn model_at;
    void *ctx;
    gd_solver_opts o;
    int kind;                /* gd_curve_kind */
    int n, nseg, per_seg, nper, N;
    int ne;                  /* extra unknowns: 1 for kappa or phi, else 0 */
    int D;                   /* unknowns N + 2 + ne; equations D - 1 */
    double dp_rel;           /* central differences in p: relative step */
    double w[CMAX];          /* weights of the arclength's inner product */
    /* borders: fold and period doubling [[M -+ I, b], [c^T, 0]]; Neimark-Sacker V, W (n x 2, row-major) */
    double b[GD_MAX_STATE], c[GD_MAX_STATE];
    double V[GD_MAX_STATE * 2], W[GD_MAX_STATE * 2];
    /* grazing: the clearance, its boundary (+h side 0, -h side 1), the extremum's kind, the held mode
     * and the half width of the held window as a fraction of the orbit's period */
    int gclr, gside, gkind, gmode;
    double ghalf;
    /* the contact-event sequence of the curve, per segment (set at the start) */
    int seq_set;
    uint64_t seq_ref[GD_PO_MAX_PERIODS];
    /* ---- the last evaluation ---- */
    gd_model m;              /* the model there */
    double F[CMAX];          /* the residual: r, then the defining equations */
    double Mk[GD_PO_MAX_PERIODS * NN]; /* segment monodromies (when computed) */
    double M[NN];            /* their product */
    int have_M;
    uint64_t seq[GD_PO_MAX_PERIODS];
    long events[GD_MAX_CLEAR];
    double g;                /* fold, period doubling */
    double v[GD_MAX_STATE], wl[GD_MAX_STATE]; /* right and left bordered null vectors */
    double X[GD_MAX_STATE * 2], Psi[GD_MAX_STATE * 2], G[4]; /* Neimark-Sacker */
    double yg[GD_MAX_STATE], Phig[NN]; /* grazing: the state and its Jacobian at the touch */
    gd_modes mdg;
    int kg;                  /* the segment of the touch */
    double xg, xdg, xddg;    /* the clearance coordinate, its rate and acceleration there */
    double cusp;             /* fold: w^T D^2 P[v, v] / (w^T v) (with the Jacobian) */
    double *J;               /* (D - 1) x D, row-major: the Jacobian of the last evaluation with jac */
    int jac_ok;
    int seq_changed;         /* the last evaluation's contact sequence differs from the curve's */
    int jump_q;              /* the last evaluation's Jacobian was refused: the model jumps in parameter jump_q
                              * (its one-sided differences disagree at every step tried), else -1 */
    double jump_p, jump_dp;  /* there: the parameter's value and the smallest step tried */
    int sus_q;               /* since it was last set to -1: a difference in parameter sus_q whose one-sided
                              * halves disagreed at sus_u, within sus_dp (a jump of the model there, perhaps) */
    double sus_dp, sus_u[CMAX];
    double rtol_g;           /* the defining equations' tolerance */
} csys;

gd_status csys_init(csys *S, gd_model_at2_fn model_at, void *ctx, const gd_solver_opts *o, int kind, int n,
                    const gd_po_opts *po, gd_error *err);
void csys_free(csys *S);
/* Evaluate the residual at u (with the Jacobian when jac). GD_ERR_SOLVER with S->seq_changed when the
 * contact sequence differs from the curve's (at u, or on both sides of a finite difference). */
gd_status csys_eval(csys *S, const double *u, int jac, gd_error *err);
/* Whether the model jumps within the last suspicion's window (sus_q, sus_u +- sus_dp): bisection of the
 * orbit's residual at the state of sus_u, down to 8^-4 of the parameter's difference, on the half whose
 * ends differ more; *found when the ends still differ by a quarter of what they did four halvings
 * before and more than the integration's noise (a jump of the model at *pj, to *width); otherwise a
 * smooth residual. */
gd_status csys_find_jump(csys *S, int *q, double *pj, double *width, int *found, gd_error *err);
/* The same between p0 and p1 of parameter q at the state of u (a point of the curve), the jump nearest
 * p0 when there are several. */
gd_status csys_find_jump_between(csys *S, const double *u, int q, double p0, double p1, double *pj, double *width,
                                 int *found, gd_error *err);
/* The borders from a point's null vectors (fold, period doubling: v, wl; Neimark-Sacker: X, Psi, and
 * its monodromy M for the real basis of the pair's plane). */
void csys_refresh_borders(csys *S, const double *M, const double *v, const double *wl, const double *X,
                          const double *Psi);
/* The held window of a grazing curve in the local time of segment k at the touch's phase phi (off for
 * other kinds). */
void csys_hold_for(const csys *S, int k, double phi, gd_sim_hold *h);
/* The first borders at u (its orbit's monodromy evaluated): the singular vectors of the smallest
 * singular values of M -+ I, or of M^2 - 2 kappa M + I. */
gd_status csys_start_borders(csys *S, const double *u, gd_error *err);
/* The time of the touch (from the start of the orbit) at phase phi of the model's orbit. */
double csys_t_graze(const csys *S, double phi);

#endif
