/* Internal to the continuation (continuation.c: the branch; cont_tests.c: the test functions at a
 * point; cont_locate.c: their sign changes between two points, located). docs/continuation.md
 * section 3. */
#ifndef GD_CONT_INTERNAL_H
#define GD_CONT_INTERNAL_H

#include "shooting.h"

#define UMAX GD_SHOOT_UMAX

typedef struct cont {
    gd_shoot sh;
    const gd_cont_opts *co;
    gd_branch *br;
    double tol;              /* the shooting tolerance: co->po.tol, or derived from the integration's */
    double locate_tol;       /* co->locate_tol, or derived from tol */
    double Y, R;             /* the scales of the state and of the parameter in the arclength */
    double dp_max;           /* co->dp_max, or a fiftieth of R */
} cont;

/* A point of the branch: the unknowns, the unit tangent (weighted norm), the orbit, the branch-point
 * test, and the extrema of the clearance coordinates over the orbit (times as phases of the orbit,
 * in [0, 1)). */
typedef struct cpoint {
    double u[UMAX], t[UMAX];
    gd_po po;
    int bp_sign;
    double bp_log;
    int gaps_ok;
    gd_gap_extrema g;
    int half_ok;             /* an even period: dh holds y_0 - y_{nper/2}, the orbit's antisymmetric part */
    double dh[GD_MAX_STATE];
} cpoint;

/* the weighted inner product of the arclength */
double cont_dot(const cont *c, const double *a, const double *b);

/* One corrected point q at arclength s from a (predictor a.u + s a.t, the arclength condition along
 * a.t), Newton from guess when given; *iters its Newton iterations. q's gaps are not computed. */
gd_status cont_step(cont *c, const cpoint *a, double s, const double *guess, cpoint *q, int *iters, gd_error *err);

/* The extrema of q's orbit (gd_sim_orbit_gaps), once. */
gd_status cont_gaps(cont *c, cpoint *q, gd_error *err);

/* The test functions at a point (cont_tests.c) */
double cont_fold_test(const cont *c, const cpoint *q);
double cont_pd_test(const gd_po *po);
double cont_det_test(const gd_po *po, double s);
/* |mu_(j)| - 1 for the multiplier of the j-th largest modulus */
double cont_modulus_test(const gd_po *po, int j);
/* the branch-point test as a continuous function: D / exp(ref) */
double cont_bp_test(const cpoint *q, double ref);
/* the complex multiplier (positive imaginary part) nearest the unit circle; 0 when there is none */
int cont_ns_multiplier(const gd_po *po, double *re, double *im);
/* the multiplier nearest target */
void cont_critical_multiplier(const gd_po *po, double target, double *re, double *im);
/* For an orbit of an even period: q->dh = y_0 - y_{nper/2}, its state at phase 0 less the state half
 * its period later (from the segments with multiple shooting, else by a plain map of nper/2 periods):
 * zero on the orbit of half the period repeated, and of opposite sign on the two sides of the vertex
 * of a period doubling of that orbit. Nothing for an odd period. */
gd_status cont_half(cont *c, cpoint *q, gd_error *err);

/* A contact change followed on one extremum: the extremum of kind `sign` (+1 maximum, -1 minimum) of
 * clearance clr, against the boundary b (+h or -h), at the phase `phase` of the orbit. */
typedef struct gap_ref {
    int clr, sign;
    double phase, b;
} gap_ref;
/* The extremum of q nearest r (its kind, nearest phase): its distance to r's boundary and its phase;
 * NAN when q's orbit has none of that kind. */
double cont_gap_value(const gd_gap_extrema *g, const gap_ref *r, double *phase);
/* The extrema of clearance clr followed from a to b (each matched to the nearest of its kind in
 * phase, both ways) that crossed a boundary: up to max of them into r; their number. */
int cont_gap_crossings(const gd_gap_extrema *ga, const gd_gap_extrema *gb, int clr, gap_ref *r, int max);

/* Every sign change of a test function between a and b (at arclength ds from a along a.t),
 * located and recorded on the branch. */
gd_status cont_detect(cont *c, const cpoint *a, const cpoint *b, double ds, gd_error *err);

#endif
