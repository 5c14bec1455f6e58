/* Periodic orbits of a gear model and their continuation (docs/continuation.md).
 *
 * An orbit of n mesh periods is a fixed point of the n-fold stroboscopic map. It is found by
 * Newton shooting: single shooting over the n periods, or multiple shooting with one segment per
 * mesh period, whose Jacobian blocks are the monodromy matrices of the segments
 * (gd_sim_period_map: variational equations with a saltation matrix at every located contact
 * event). Its stability comes from the Floquet multipliers, the eigenvalues of the monodromy
 * matrix of the whole orbit (for several segments, from the block-cyclic matrix of the segments,
 * GSL's nonsymmetric eigensolver). Pseudo-arclength continuation follows an orbit in a numeric
 * parameter p, with an adaptive step in a norm that scales the state and the parameter, and
 * locates between its points, by GSL's Brent solver in the arclength, the folds (the tangent's
 * parameter component changes sign), branch points (the determinant of the bordered Jacobian
 * changes sign), period doublings (a real multiplier passes -1), Neimark-Sacker points (a complex
 * pair crosses the unit circle) and changes of the contact sequence (grazing: an extremum of a
 * clearance coordinate crosses its boundary). */
#ifndef GD_PERIODIC_H
#define GD_PERIODIC_H

#include "geardyn/gd_sim.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GD_PO_MAX_PERIODS 16

typedef struct gd_po_opts {
    int nper;                /* period of the orbit in mesh periods, 1 .. GD_PO_MAX_PERIODS */
    int multiple;            /* 1: one shooting segment per mesh period; 0: one segment of nper periods */
    double tol;              /* converged when the max-norm of the shooting residual (dimensionless state) is below
                              * tol; 0: what the integration resolves, rtol Y + atol for the orbit's state of
                              * max-norm Y (at least 1) */
    int max_iter;            /* Newton iterations at most */
    double dp_rel;           /* step of the central difference of the residual in p, relative to 1 + |p|; 0: the
                              * cube root of the integration's rtol */
} gd_po_opts;

/* nper 1, multiple shooting, tol 0 (derived), 12 iterations, dp_rel 0 (derived) */
GD_API void gd_po_opts_default(gd_po_opts *po);

typedef struct gd_po {
    int n, nper, nseg;       /* state size, mesh periods, shooting segments */
    double p;                /* the parameter (continuation) */
    double y[GD_PO_MAX_PERIODS][GD_MAX_STATE]; /* the state at t = 0 of each segment (y[0]: the orbit's
                                                * Poincare point at mesh phase 0) */
    double M[GD_MAX_STATE * GD_MAX_STATE];     /* monodromy of the whole orbit (n x n, row-major) */
    double mu_re[GD_MAX_STATE], mu_im[GD_MAX_STATE]; /* Floquet multipliers, largest modulus first */
    double mu_max;           /* the largest modulus */
    int stable;              /* mu_max < 1 */
    int iterations;          /* Newton iterations (linear solves) of the last correction */
    double residual;         /* max-norm of the shooting residual at the solution */
    long events[GD_MAX_CLEAR]; /* located events per orbit period, by clearance */
} gd_po;

/* The eigenvalues of the n x n matrix M (row-major), sorted by decreasing modulus. */
GD_API gd_status gd_floquet(const double *M, int n, double *mu_re, double *mu_im, gd_error *err);

/* The Floquet multipliers of the product M_{K-1} ... M_1 M_0 of K segment monodromies (n x n each,
 * row-major, consecutive in Mk; K at most GD_PO_MAX_PERIODS), sorted by decreasing modulus, from the
 * eigenvalues of the block-cyclic matrix of the segments: accurate to the segments' own rounding,
 * where the explicit product's eigenvalues carry errors of about eps |mu_max|. M (may be NULL): the
 * product. */
GD_API gd_status gd_floquet_segments(const double *Mk, int K, int n, double *M, double *mu_re, double *mu_im,
                                     gd_error *err);

/* The orbit of po->nper mesh periods of model m near the state y0 at t = 0 (the guesses of the
 * other segments are the images of y0). */
GD_API gd_status gd_po_solve(const gd_model *m, const gd_solver_opts *o, const gd_po_opts *po, const double *y0,
                             gd_po *orbit, gd_error *err);

/* The model at parameter value p (into *m). */
typedef gd_status (*gd_model_at_fn)(double p, gd_model *m, void *ctx, gd_error *err);

/* A gd_model_at_fn whose parameter is the dimensionless mesh frequency Omega: ctx is the
 * const gd_model * whose copy gets Omega and the mesh period 2 pi / Omega. Exact for a model in
 * which nothing else depends on the speed; a model with a mesh-in impact pulse (whose phase width
 * does) is refused. */
GD_API gd_status gd_model_at_mesh_frequency(double Omega, gd_model *m, void *ctx, gd_error *err);

/* A gd_model_at_fn whose parameter sets a numeric case key: the key takes the value scale * p, the
 * case is resolved and the model built again at every call (LTCA excitations come from their
 * cache), so every speed-dependent part of the model follows (the mesh-in pulse among them).
 * ctx: a gd_case_param; the case is changed, so one continuation at a time may use it. */
typedef struct gd_case_param {
    gd_case *c;
    const char *key;         /* "operating.speed_rpm", "operating.torque_nm", ... */
    double scale;            /* key value per unit of p (for the speed: rpm per unit of Omega) */
} gd_case_param;
GD_API gd_status gd_model_at_case_key(double p, gd_model *m, void *ctx, gd_error *err);

typedef struct gd_cont_opts {
    gd_po_opts po;
    double p_min, p_max;     /* the branch ends when p leaves [p_min, p_max] */
    /* The arclength is measured in the norm |(y_0, ..., y_{nseg-1}, p)|^2 = sum_k |y_k|^2 / (nseg Y^2) +
     * p^2 / R^2: the state over its scale Y, averaged over the segments (single and multiple shooting
     * alike), and the parameter over its range R. */
    double y_scale;          /* Y; 0: the max-norm of the starting orbit's states (its nper Poincare points), at
                              * least 1 */
    double p_scale;          /* R; 0: p_max - p_min when finite, else max(1, |p|) at the start */
    double ds, ds_min, ds_max; /* arclength step in that norm: first, smallest, largest */
    double dp_max;           /* largest change of p in one step; 0: a fiftieth of the parameter's scale R (so that
                              * no step skips more than 2 % of the range where the state hardly moves) */
    int max_points;          /* branch points at most (the start included) */
    int direction;           /* +1: set out towards increasing p; -1 decreasing */
    double locate_tol;       /* a bifurcation is located when its arclength bracket is below this; 0: ten times
                              * the shooting tolerance over Y (what a corrected point resolves) */
    int contact_by_events;   /* 1: contact changes by bisection of the event count only (the fallback of the
                              * extremum's distance; for comparison and tests) */
    gd_stop_hook stop;       /* asked before each new point: nonzero ends gd_continue with GD_ERR_INTERRUPTED */
} gd_cont_opts;

/* multiple shooting of 1 period, p in [0, inf), scales derived, ds 0.02 in [1e-6, 0.2], dp_max R / 50,
 * 400 points, +1, tolerances derived, never stopped */
GD_API void gd_cont_opts_default(gd_cont_opts *co);

typedef enum gd_bif_kind {
    GD_BIF_FOLD = 0,           /* saddle-node: the tangent's parameter component changes sign */
    GD_BIF_PERIOD_DOUBLING = 1, /* a real multiplier passes -1 */
    GD_BIF_CONTACT_CHANGE = 2, /* the events of a clearance per orbit change in number: a contact appears or
                                * disappears (through a grazing, where the orbit touches the boundary) */
    GD_BIF_NEIMARK_SACKER = 3, /* a complex pair of multipliers crosses the unit circle */
    GD_BIF_BRANCH_POINT = 4    /* another branch of the same period crosses: the determinant of the Jacobian
                                * bordered by the tangent changes sign (a branch of twice the period at the
                                * period doubling of the orbit of half its period ends there instead) */
} gd_bif_kind;
GD_API const char *gd_bif_kind_name(int kind);

/* How a bifurcation's location ended. */
typedef enum gd_bif_location {
    GD_LOC_LOCATED = 0,      /* the test function's zero bracketed to locate_tol, the function small there */
    GD_LOC_BRACKET = 1,      /* a trial point found no orbit: the bracket reached, wider than locate_tol */
    GD_LOC_JUMP = 2,         /* the test function changes sign by a jump inside the bracket, not through zero */
    GD_LOC_EVENTS = 3        /* a contact change where no followed extremum crossed a boundary: the event count
                              * bisected (where the event detection sees the change) */
} gd_bif_location;
GD_API const char *gd_bif_location_name(int location);

typedef struct gd_bifurcation {
    int kind;                /* gd_bif_kind */
    int clearance;           /* the clearance of a contact change (index into model->clear), else -1 */
    double p;                /* parameter of the reported point: the end of the final bracket with the smaller
                              * test function (after a bisection of the event count: its middle) */
    double p_lo, p_hi;       /* parameter at the ends of the final bracket (p_lo: the end towards the branch
                              * point before it, so p_lo > p_hi on a branch running to lower p) */
    double mu_re, mu_im;     /* the critical multiplier at that point (PD: nearest -1; NS: the complex one with
                              * positive imaginary part nearest the unit circle; else nearest 1) */
    double y[GD_MAX_STATE];  /* Poincare point at that point */
    int after;               /* index of the branch point before which it lies */
    int corrections;         /* corrected points its location took (0 when not located by gd_continue) */
    int location;            /* gd_bif_location */
} gd_bifurcation;

typedef enum gd_branch_end {
    GD_END_BOUND = 0,        /* p left [p_min, p_max] */
    GD_END_BUDGET = 1,       /* max_points reached */
    GD_END_STEP = 2,         /* no convergence at the smallest step */
    GD_END_CLOSED = 3,       /* back at its first orbit (or that orbit shifted by whole segments): a closed
                              * curve, followed once round */
    GD_END_HALF = 4,         /* its orbit became one of half the period repeated: the branch crossed a period
                              * doubling of that orbit onto the branch it was born from (multiple shooting) */
    GD_END_DOUBLING = 5      /* the next step passed the vertex of a period doubling of the orbit of half the
                              * period (a branch point, beyond which the branch runs back as its own image
                              * shifted by half the period): the branch ends at its last point before it,
                              * vertex_p the vertex's parameter */
} gd_branch_end;

typedef struct gd_cont_point {
    gd_po orbit;             /* orbit.p: the parameter */
    double tangent_p;        /* parameter component of the unit tangent (its sign changes at a fold) */
    double ds;               /* the step that reached this point */
} gd_cont_point;

typedef struct gd_branch {
    int npoints, cap;
    gd_cont_point *pt;
    int nbif, bif_cap;
    gd_bifurcation *bif;
    int end;                 /* gd_branch_end */
    char end_reason[GD_ERROR_MSG_MAX];
    char end_detail[GD_ERROR_MSG_MAX]; /* why the corrector failed (no orbit at the bound, or at the smallest
                                        * step): the solver's message, "" otherwise */
    int closed_shift;        /* GD_END_CLOSED: the mesh periods by which the orbit it came back to is its first
                              * one shifted (0: the first orbit itself) */
    int closed_reversed;     /* GD_END_CLOSED: that shifted orbit passed the other way (the curve is symmetric
                              * under the shift: what follows mirrors the branch's other direction) */
    int closed_point;        /* GD_END_CLOSED: the point it came back to (0: its first; a later one when the branch
                              * entered a closed curve, as at a branch point onto another branch) */
    long newton_iterations;  /* over all points, located bifurcations included */
    long corrections;        /* corrector runs (accepted, rejected, and the location's) */
    long chord_iterations;   /* iterations with a kept Jacobian and plain segment maps (no monodromy) that
                              * came before the Newton iterations */
#define GD_BRANCH_NOTES 8
    int nnotes;              /* what a location found and did not keep (a modulus passing 1 with no complex
                              * multiplier on the unit circle at the located point) */
    char notes[GD_BRANCH_NOTES][256];
    int notes_dropped;       /* notes beyond GD_BRANCH_NOTES */
    double vertex_p;         /* GD_END_DOUBLING: the vertex's parameter, from a parabola through the last points */
    double vertex_y[GD_MAX_STATE]; /* and the state there, about: the last point's mean of y_0 and y_{nper/2} */
    double y_scale, p_scale; /* the scales of the arclength (gd_cont_opts), as used */
    double tol, locate_tol;  /* the shooting and location tolerances, as used */
} gd_branch;

/* Follow the orbit start (solved by gd_po_solve or a branch point; start->p its parameter) in p,
 * one direction (co->direction). br is filled (free with gd_branch_free). */
GD_API gd_status gd_continue(gd_model_at_fn model_at, void *ctx, const gd_solver_opts *o, const gd_cont_opts *co,
                             const gd_po *start, gd_branch *br, gd_error *err);
GD_API void gd_branch_free(gd_branch *br);

/* Branch switching at the period doubling b of a branch of orbits of po->nper mesh periods: the
 * orbit of 2 po->nper periods born there, by shooting at b->p + dp (then b->p - dp, then both at dp/8)
 * from the bifurcation's orbit moved by +-eps Y along the eigenvector of its multiplier -1 (Y the
 * orbit's state scale, its max-norm but at least 1; sqrt(1/8) of that at dp/8). An orbit is accepted
 * only when it is the one born at the doubling: not the period-nper orbit again, its two halves
 * (its states at phase 0 and nper periods later) about the period-nper orbit at that parameter (their
 * mean within their distance of it), and its amplitude growing as the square root of the
 * distance to the doubling (the orbit shot again at a quarter of the distance has 0.35 to 0.7 of
 * the amplitude). GD_ERR_SOLVER when no trial finds it. out->p is its parameter. */
GD_API gd_status gd_po_period_doubled(gd_model_at_fn model_at, void *ctx, const gd_solver_opts *o,
                                      const gd_po_opts *po, const gd_bifurcation *b, double dp, double eps,
                                      gd_po *out, gd_error *err);

#ifdef __cplusplus
}
#endif
#endif
