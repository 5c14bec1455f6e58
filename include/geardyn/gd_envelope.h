/* Curves of codimension-one bifurcations of periodic orbits in two parameters, and the
 * codimension-two points on them (docs/continuation.md section 8).
 *
 * A fold, period doubling, Neimark-Sacker point or grazing of an orbit of n mesh periods, found by
 * a one-parameter continuation (gd_continue), is followed in the plane of two numeric parameters
 * (p1, p2) by pseudo-arclength continuation of a defining system built on the shooting equations of
 * the orbit (single or multiple shooting):
 *   fold, period doubling: the orbit and one scalar g of the bordered matrix [[M -+ I, b], [c^T, 0]]
 *     (minimally augmented; M the orbit's monodromy, b and c refreshed from the left and right null
 *     vectors at every accepted point; g's derivatives -w^T (dM/dz) v from one extra monodromy in the
 *     direction v);
 *   Neimark-Sacker: the orbit and two entries of the 2 x 2 bordered Schur complement of
 *     M^2 - 2 kappa M + I, kappa = cos(theta) an unknown;
 *   grazing: the orbit, and at an unknown time t_g the clearance coordinate's rate 0 and its value on
 *     the boundary, the orbit integrated with the clearance's mode held on the side where the contact
 *     does not happen.
 * The contact-event sequence of the orbit belongs to the curve: a finite difference that would change
 * it is taken from the other side, and a curve whose orbit would change it ends there, located (a
 * grazing met). Along each curve the codimension-two points are located by GSL's Brent solver on
 * continuous test functions: the cusp on a fold curve, fold-flip points, the strong resonances 1:1 to
 * 1:4 on a Neimark-Sacker curve, grazing curves meeting fold, period-doubling and Neimark-Sacker
 * curves, and double grazing. Checked by tests (tests/test_envelope.c, tests/cli/test_envelope_cli.sh):
 * fold, period-doubling, grazing and Neimark-Sacker curves, the strong resonances 1:3 and 1:4, the cusp
 * of the Kahraman & Singh fold curves; the other codimension-two points are not yet. */
#ifndef GD_ENVELOPE_H
#define GD_ENVELOPE_H

#include "geardyn/gd_periodic.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The model at the parameter values (p1, p2) (into *m). */
typedef gd_status (*gd_model_at2_fn)(double p1, double p2, gd_model *m, void *ctx, gd_error *err);

/* A gd_model_at2_fn whose parameters set two numeric case keys: key1 = scale1 p1, key2 = scale2 p2,
 * the case resolved and the model built again at every call (LTCA excitations from their cache).
 * ctx: a gd_case_param2; the case is changed, so one curve at a time may use it. */
typedef struct gd_case_param2 {
    gd_case *c;
    const char *key1, *key2;
    double scale1, scale2;
} gd_case_param2;
GD_API gd_status gd_model_at_case_keys(double p1, double p2, gd_model *m, void *ctx, gd_error *err);

typedef enum gd_curve_kind {
    GD_CURVE_FOLD = 0,             /* a multiplier +1 */
    GD_CURVE_PERIOD_DOUBLING = 1,  /* a multiplier -1 */
    GD_CURVE_NEIMARK_SACKER = 2,   /* a complex pair on the unit circle */
    GD_CURVE_GRAZING = 3           /* an extremum of a clearance coordinate on its boundary */
} gd_curve_kind;
GD_API const char *gd_curve_kind_name(int kind);

typedef enum gd_codim2_kind {
    GD_C2_CUSP = 0,                /* fold curve: the quadratic coefficient vanishes, two folds meet */
    GD_C2_FOLD_FLIP = 1,           /* multipliers +1 and -1 at once (fold meets period-doubling curve) */
    GD_C2_R1 = 2,                  /* Neimark-Sacker curve: strong resonance 1:1 (kappa = 1) */
    GD_C2_R2 = 3,                  /* 1:2 (kappa = -1) */
    GD_C2_R3 = 4,                  /* 1:3 (kappa = -1/2) */
    GD_C2_R4 = 5,                  /* 1:4 (kappa = 0) */
    GD_C2_GRAZING_FOLD = 6,        /* a grazing on a fold curve, or a fold on a grazing curve */
    GD_C2_GRAZING_PD = 7,          /* ... period doubling */
    GD_C2_GRAZING_NS = 8,          /* ... Neimark-Sacker */
    GD_C2_DOUBLE_GRAZING = 9       /* two extrema on their boundaries (two clearances, or both flanks) */
} gd_codim2_kind;
GD_API const char *gd_codim2_kind_name(int kind);
/* The short label of the picture: CP, FF, R1 .. R4, GF, GPD, GNS, DG. */
GD_API const char *gd_codim2_label(int kind);

/* A codimension-one point to start a curve from (a bifurcation of a one-parameter branch). */
typedef struct gd_curve_start {
    int kind;                /* gd_curve_kind */
    int nper;                /* mesh periods of the orbit */
    int clearance;           /* a grazing: the clearance (index into model->clear), else -1 */
    double p1, p2;           /* where */
    double y[GD_MAX_STATE];  /* the orbit's state at mesh phase 0 */
} gd_curve_start;

typedef struct gd_curve_opts {
    gd_po_opts po;           /* shooting: nper (from the start), multiple, tol, max_iter, dp_rel */
    double p_min[2], p_max[2]; /* the box: a curve ends when it leaves it */
    double y_scale;          /* the state's scale in the arclength (0: the start's, at least 1) */
    double p_scale[2];       /* the parameters' scales (0: the box's sides) */
    double ds, ds_min, ds_max; /* arclength steps in the norm |Y|^2 / (nseg y_scale^2) + sum (p_i / p_scale_i)^2 */
    double dp_max[2];        /* largest change of each parameter in one step (0: a fiftieth of its scale) */
    int max_points;          /* points of one direction at most, the start included */
    int direction;           /* +1: set out towards increasing p2 (or p1 where p2 cannot move); -1 decreasing */
    double locate_tol;       /* a codimension-two point's arclength bracket (0: ten times tol over y_scale) */
    gd_stop_hook stop;       /* asked before each point: nonzero ends with GD_ERR_INTERRUPTED */
    /* the words of the end reasons: parameter i is key[i] = value_scale[i] p_i unit[i]; the box's lower and
     * upper bound of parameter i are the keys bound_key[i][0], bound_key[i][1] (NULL: "p1", "p2", no unit,
     * scale 1, "the lower bound of p1") */
    struct {
        const char *key[2], *unit[2], *bound_key[2][2];
        double value_scale[2];
    } words;
} gd_curve_opts;

/* multiple shooting, scales and tolerances derived, ds 0.02 in [1e-6, 0.2], 400 points, +1 */
GD_API void gd_curve_opts_default(gd_curve_opts *co);

#define GD_CURVE_NTEST 8
/* The test functions every curve point carries (NAN where not defined for the kind). */
enum {
    GD_CT_CUSP = 0,          /* fold curve: w^T D^2 P[v, v], the fold's quadratic coefficient */
    GD_CT_FOLD = 1,          /* det(M - I) as its sign times the smallest |mu - 1| (not on fold curves) */
    GD_CT_PD = 2,            /* det(M + I) likewise (not on period-doubling curves) */
    GD_CT_R1 = 3,            /* Neimark-Sacker curve: kappa - 1 */
    GD_CT_R2 = 4,            /* kappa + 1 */
    GD_CT_R3 = 5,            /* kappa + 1/2 */
    GD_CT_R4 = 6,            /* kappa */
    GD_CT_NS = 7             /* grazing curve: the smallest ||mu| - 1| of a complex multiplier, signed */
};

typedef struct gd_curve_point {
    gd_po orbit;             /* orbit.p: p1; its multipliers and events */
    double p2;
    double kappa;            /* Neimark-Sacker: cos theta of the pair on the unit circle (else NAN) */
    double t_graze;          /* grazing: the time of the touch as a fraction of the orbit's period (else NAN) */
    double test[GD_CURVE_NTEST];
    double tangent_p[2];     /* the unit tangent's parameter components (both vanish at a cusp) */
    double ds;               /* the step that reached it */
} gd_curve_point;

typedef struct gd_codim2 {
    int kind;                /* gd_codim2_kind */
    double p1, p2;
    double p1_lo, p2_lo, p1_hi, p2_hi; /* the final bracket's ends */
    double mu_re, mu_im;     /* the critical multiplier (the resonance's, the second of a fold-flip ...) */
    double kappa;            /* on a Neimark-Sacker curve, else NAN */
    int clearance;           /* the clearance a grazing is met on (grazing-X, double grazing), else -1 */
    int point;               /* index of the curve point before which it lies */
    int location;            /* gd_bif_location */
    int ends_curve;          /* the curve ends here (a grazing met, a resonance 1:1 or 1:2) */
    double y[GD_MAX_STATE];
} gd_codim2;

typedef enum gd_curve_end {
    GD_CEND_BOUND = 0,       /* a parameter left the box */
    GD_CEND_BUDGET = 1,      /* max_points */
    GD_CEND_STEP = 2,        /* no convergence at the smallest step */
    GD_CEND_CLOSED = 3,      /* back at its first point: a closed curve */
    GD_CEND_CONTACT = 4,     /* the orbit's contact-event sequence would change (a grazing met) */
    GD_CEND_RESONANCE = 5,   /* Neimark-Sacker: the pair met on the real axis (1:1 or 1:2) */
    GD_CEND_INVALID = 6,     /* the model is not valid beyond (a key out of its range) */
    GD_CEND_INADMISSIBLE = 7, /* grazing: beyond, the orbit crosses the grazed boundary inside the touch's held
                               * window (another extremum past it, or the touch from the wrong side) */
    GD_CEND_DISCONTINUOUS = 8, /* the model jumps in a parameter there: the residual's one-sided differences
                                * disagree however small the difference (docs/continuation.md section 8) */
    GD_CEND_STALL = 9        /* no progress: GD_CURVE_STALL_POINTS points in a row at the smallest step, or
                              * GD_CURVE_CRAWL_POINTS in a row at steps below 100 ds_min that moved less than a
                              * hundredth of the box in both parameters */
} gd_curve_end;
/* consecutive points at the smallest step (below twice ds_min) that end a curve as GD_CEND_STALL */
#define GD_CURVE_STALL_POINTS 8
#define GD_CURVE_CRAWL_POINTS 20
GD_API const char *gd_curve_end_name(int end);

typedef struct gd_curve {
    int kind, nper, clearance;
    int graze_side;          /* grazing: 0 the boundary +h, 1 -h */
    int graze_extremum;      /* grazing: +1 a maximum, -1 a minimum touches */
    int npoints, cap;
    gd_curve_point *pt;
    int nc2, c2_cap;
    gd_codim2 *c2;
    int end;                 /* gd_curve_end */
    char end_reason[GD_ERROR_MSG_MAX];
    long corrections, newton_iterations;
    double y_scale, p_scale[2], tol, locate_tol;
} gd_curve;

/* Follow the curve of start's kind from start in one direction (co->direction). cv is filled (free
 * with gd_curve_free). */
GD_API gd_status gd_curve_follow(gd_model_at2_fn model_at, void *ctx, const gd_solver_opts *o, const gd_curve_opts *co,
                                 const gd_curve_start *start, gd_curve *cv, gd_error *err);
GD_API void gd_curve_free(gd_curve *cv);

#ifdef __cplusplus
}
#endif
#endif
