/* The loaded contact problem of LTCA (the paper's Eq. 11), solved exactly.
 *
 * n contact points with initial gaps w (m), a symmetric positive definite normal flexibility
 * matrix L (m/N: deflection at i under a unit load at k), and m rigid-body freedoms (the
 * approach of the bodies, and for a floating herringbone pinion its axial shift) that move
 * point i by (G z)_i along the normal. Find the loads p (N) and the freedoms z with
 *   d = w + L p - G z >= 0,  p >= 0,  p_i d_i = 0   (no penetration, no tension, contact law)
 *   G^T p = f                                       (equilibrium of the freedoms)
 * These are the optimality conditions of the strictly convex quadratic programme
 *   min 1/2 p^T L p + w^T p   subject to   p >= 0,  G^T p = f,
 * whose solution is unique; z are the multipliers of the equality constraints. It is solved by
 * a primal active-set method (Lawson & Hanson's NNLS generalised to equality constraints):
 * finite, and exact up to rounding. Convergence: every loaded point has d_i = 0 to the
 * solver's equation accuracy and every unloaded point has d_i >= -tol, with
 * tol = 1e-12 (max |w| + max |L p|). */
#ifndef GD_CONTACT_H
#define GD_CONTACT_H

#include "geardyn/gd_error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GD_CONTACT_MAX_FREEDOMS 4

typedef struct gd_contact_problem {
    int n, m;
    const double *L;   /* n x n, row-major, symmetric positive definite */
    const double *w;   /* n */
    const double *G;   /* n x m, row-major */
    const double *f;   /* m */
} gd_contact_problem;

typedef struct gd_contact_solution {
    double *p;         /* n (caller's storage) */
    double *d;         /* n: deformed gaps (caller's storage) */
    double z[GD_CONTACT_MAX_FREEDOMS];
    int loaded;        /* points carrying load */
    int iterations;
    double residual;   /* max violation of the conditions above, m (or N for the equilibrium) */
} gd_contact_solution;

typedef struct gd_contact_workspace gd_contact_workspace;

GD_API gd_status gd_contact_workspace_alloc(int nmax, int m, gd_contact_workspace **out, gd_error *err);
GD_API void gd_contact_workspace_free(gd_contact_workspace *ws);
/* Solve; loaded_hint (may be NULL) marks points to start from as loaded (warm start: the
 * previous position's loaded set); without it the start is the points of least gap. */
GD_API gd_status gd_contact_solve(const gd_contact_problem *pb, const unsigned char *loaded_hint,
                                  gd_contact_workspace *ws, gd_contact_solution *sol, gd_error *err);

#ifdef __cplusplus
}
#endif
#endif
