/* Internals of the contact analysis shared by the src/contact sources (not installed). */
#ifndef GD_TCA_INTERNAL_H
#define GD_TCA_INTERNAL_H

#include "geardyn/gd_tca.h"
#include "geardyn/gd_geometry.h"

#include <gsl/gsl_multiroots.h>

#define TCA_MAX_N 5

/* Rigid map of pinion flank points (half body frame) into the gear's half frame:
 * Q = A x + c. The gear's half frame is the gear body frame turned by pi about its axis, so that
 * the mesh lies near polar angle 0 (away from the branch cut of atan2). */
typedef struct tca_pose {
    double A[9];
    double c[3];
} tca_pose;

typedef struct tca_half {
    gd_flank f1, f2;         /* pinion and gear flank of tooth 0 */
    double zc;               /* axial position of the middle of the half, fixed frame */
    double *x1;              /* pinion grid node positions, 3 per node, profile index fastest */
    double *sep, *ease;      /* topography accumulators (min over positions), nodes */
} tca_half;

/* Gap of a pinion point and its derivatives with respect to (rho1, z1) (rho1 = rb1 u1), with the
 * mate's radius and axial position on the gear and their derivatives. */
typedef struct tca_local {
    int ok;                  /* mate outside the gear base cylinder: the gap is defined */
    double u, z;
    double g, g_r, g_z, g_rr, g_rz, g_zz;
    double R, R_r, R_z, R_rr, R_rz, R_zz;      /* mate radius */
    double Z, Z_r, Z_z, Z_rr, Z_rz, Z_zz;      /* mate axial position */
} tca_local;

/* A boundary of the feasible set of pinion points, h >= 0 feasible. */
enum {
    TCA_C_P_ROOT = 0, TCA_C_P_TIP = 1, TCA_C_P_LO = 2, TCA_C_P_HI = 3,
    TCA_C_G_ROOT = 4, TCA_C_G_TIP = 5, TCA_C_G_LO = 6, TCA_C_G_HI = 7, TCA_NC = 8
};

typedef int (*tca_fdf_fn)(const double *x, void *p, double *f, double *J);

struct gd_tca {
    gd_geometry g;
    int halves;
    tca_half h[2];
    double theta1, theta2;   /* phase offsets of pinion and gear (docs/tca.md) */
    double C[3];             /* gear centre (middle of the gear), fixed frame */
    double M[9];             /* misalignment rotation of the gear axis */
    double ratio;            /* z1 / z2 */
    double tau1, tau2;       /* angular pitches */
    double alpha_op;         /* operating transverse pressure angle of the ideal involutes */
    int nprof, nface;
    double *rho, *z;         /* grid node roll lengths and axial positions */
    int maxpairs;            /* pairs the node buffers hold */
    double *gbuf;            /* gap per node, maxpairs pairs */
    unsigned char *fbuf;     /* feasibility per node (0 ok, else 1 + violated constraint) */
    double *sg;              /* scratch: one slice of gaps (nprof) */
    unsigned char *sf;       /* scratch: one slice of feasibility (nprof) */
    int refine;
    double tol_edge;         /* gap tolerance for ties (rad) */
    double tol_contact;      /* gap tolerance for "in contact" (rad) */
    gsl_multiroot_fdfsolver *solver[TCA_MAX_N + 1];
    gsl_vector *xv[TCA_MAX_N + 1];
    long iterations;
    gd_tca_line_point *lines;
    double *lines_pre;       /* per line point: the grid value the prefilter tested (tca_lines.c) */
    int nlines, cap_lines;
    unsigned char *memo_key; /* the pair's key in the memo of lines (tca_lines_memo.c), NULL: none */
    size_t memo_len;
};

/* tca_pair.c: kinematics and the gap function */
void tca_pose_at(const gd_tca *t, int half, double phi1, double phi2, int pair, tca_pose *P);
double tca_phi2_nominal(const gd_tca *t, double phi1);
/* order 0: g, R, Z only; 1: and first derivatives; 2: and second */
void tca_local_eval(const gd_tca *t, int half, const tca_pose *P, double u, double z, int order, tca_local *L);
/* constraint value h_k >= 0 feasible, and its derivatives in (rho1, z1) */
void tca_constraint(const gd_tca *t, int half, const tca_local *L, int k, double *h, double *h_r, double *h_z,
                    double *h_rr, double *h_rz, double *h_zz);
/* 0 when feasible, else 1 + the first violated constraint */
int tca_feasible(const gd_tca *t, int half, const tca_local *L, double tol);
unsigned tca_edge_bit(int constraint);
void tca_mat_vec(const double A[9], const double x[3], double y[3]);
/* a . b of two 3-vectors */
double tca_dot3(const double a[3], const double b[3]);
void tca_fixed_point(const gd_tca *t, int half, double phi1, int pair, const double x[3], double X[3]);
void tca_fixed_vector(const gd_tca *t, double phi1, int pair, const double v[3], double V[3]);
/* Gear half-frame vector -> fixed frame (no translation), and gear half-frame point -> fixed frame. */
void tca_gear_to_fixed(const gd_tca *t, int half, double phi2, int pair, const double v[3], int is_point, double V[3]);
/* Candidate tooth pairs for a position: [*lo, *hi]. */
void tca_pair_range(const gd_tca *t, int half, double phi1, int *lo, int *hi);

/* tca_newton.c: GSL multiroot (hybridsj, analytic Jacobian) on n <= 5 unknowns; *conv = 1 when
 * converged to |dx| <= xtol (all unknowns in metres), 0 when it did not (no progress, bad
 * function, iteration limit): that is an outcome, not an error. GD_ERR_GSL only for a failure of
 * GSL itself. */
gd_status tca_newton(gd_tca *t, int n, tca_fdf_fn fn, void *p, double *x, double xtol, int maxit, int *conv,
                     int *iters, gd_error *err);

/* Formulation (b), surface separation: a candidate minimum of the gap of one pair on the pinion
 * flank, its position (u1, z1), gap g (gear rotation), the boundaries it lies on (edge bits) and
 * whether it is feasible. */
typedef struct tca_cand {
    double u, z, g;
    unsigned bits;
    int ok;
} tca_cand;

static inline void tca_keep_best(tca_cand *best, const tca_cand *c)
{
    if (c->ok && (!best->ok || c->g < best->g))
        *best = *c;
}

/* tca_line_min.c: the exact minimum along a line of the flank. */
/* Exact minimum over rho in the transverse slice z, within the feasible run of profile nodes that
 * holds node i0 (or the least node when i0 < 0). gv/fv: the pair's node values in this slice when
 * z is a grid slice, else NULL (computed here). Also the slope m' = dm/dz of the slice minimum
 * m(z) there (envelope theorem; along the boundary when the minimum sits on one) and, when the
 * minimum is interior or on a pinion profile edge, its curvature m'' (else NaN). */
gd_status tca_slice_min_hint(gd_tca *t, int half, const tca_pose *P, double z, const double *gv,
                             const unsigned char *fv, int i0, const double *gp, const unsigned char *fp, int jh,
                             double rho_hint, tca_cand *out, double *mp, double *mpp, int *iters, gd_error *err);
/* tca_slice_min_hint without a neighbouring slice's hint */
gd_status tca_slice_min_z(gd_tca *t, int half, const tca_pose *P, double z, const double *gv,
                          const unsigned char *fv, int i0, tca_cand *out, double *mp, double *mpp, int *iters,
                          gd_error *err);
/* Exact minimum in grid slice j from node i0 (the pair's node values gv, fv). */
gd_status tca_slice_min(gd_tca *t, int half, const tca_pose *P, int j, int i0, const double *gv,
                        const unsigned char *fv, tca_cand *out, int *iters, gd_error *err);
/* Exact minimum along a pinion profile line rho = const (the tip or root edge), starting at z0. */
gd_status tca_along_min(gd_tca *t, int half, const tca_pose *P, double rho, double z0, tca_cand *out, int *iters,
                        gd_error *err);
/* Exact minimum on the gear boundary k (tip, root or end face) crossing the pinion flank. */
gd_status tca_lagrange_min(gd_tca *t, int half, const tca_pose *P, int k, double rho0, double z0, tca_cand *out,
                           int *iters, gd_error *err);

/* tca_pair_min.c: the exact minimum of one pair over the flank, with the edges touched with it. */
typedef struct tca_pair_out {
    tca_cand best;
    unsigned tie_bits;       /* boundary bits of candidates within tol_edge of the pair minimum */
    double tie_g[8];
    unsigned tie_b[8];
    int ntie;
} tca_pair_out;
gd_status tca_refine_from_grid(gd_tca *t, int half, const tca_pose *P, const double *gv, const unsigned char *fv,
                               int i0, int j0, int all_edges, const tca_cand *pre, double pre_mp, tca_pair_out *po,
                               int *iters, gd_error *err);

/* tca_separation.c: one position; accumulate: into the topography; *gstar (may be NULL): the least gap */
gd_status tca_scan(gd_tca *t, int half, double phi1, int accumulate, gd_tca_contact *out,
                   double *gstar_out, gd_error *err);
gd_status tca_separation(gd_tca *t, int half, double phi1, gd_tca_contact *out, gd_error *err);
/* tca_lines.c: the contact lines of one position within max_gap of its contact (t->lines) */
gd_status tca_lines(gd_tca *t, int half, double phi1, double max_gap, gd_error *err);
/* Which slice minima are computed (pre: the slice's least grid gap above the contact, m) and which
 * points are kept (gap: the exact minimum's) within max_gap: one test, so that the lines within a
 * window are exactly the subset of those within a wider one. */
static inline int tca_lines_prefilter(double pre, double max_gap) { return !(pre > max_gap + 50e-6); }
static inline int tca_lines_keep(double pre, double gap, double max_gap)
{
    return tca_lines_prefilter(pre, max_gap) && !(gap > max_gap);
}

/* tca_lines_memo.c: the process-wide memo of lines. get: 1 when it held (t's pair, half, phi1) within
 * max_gap or wider (t->lines set), 0 when not, -1 out of memory (err set); put: keep lines computed
 * within window (best effort); active: whether t's lines are memoised. */
int tca_memo_get(gd_tca *t, int half, double phi1, double max_gap, gd_error *err);
void tca_memo_put(const gd_tca *t, int half, double phi1, double window, const gd_tca_line_point *pts,
                  const double *pre, int n);
int tca_memo_active(const gd_tca *t);
/* For the tests: switch the memo on or off (either way it is emptied), and the hits since. */
__attribute__((visibility("hidden"))) void gd_tca_memo_enable(int on);
__attribute__((visibility("hidden"))) long gd_tca_memo_hits(void);

/* tca_tangency.c: formulation (a) */
gd_status tca_tangency(gd_tca *t, int half, double phi1, gd_tca_contact *out, gd_error *err);

/* tca_pair.c: fill the geometric fields of a contact from (pair, u1, z1) and the gear rotation */
void tca_fill_contact(const gd_tca *t, int half, double phi1, int pair, double u1, double z1, double te,
                      gd_tca_contact *out);

#endif
