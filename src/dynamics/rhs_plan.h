/* Internal: the right-hand side of a gear model compiled for one set of held contact modes.
 *
 * Between two events the contact modes are fixed, and with them every clearance except the
 * meshes is a linear spring and damper: the bearing contacts fold into the constant stiffness and
 * damping, and the mass scaling into every coefficient. What is left per evaluation is a diagonal,
 * a short list of off-diagonal coefficients and one rank-one term per mesh (its stiffness and
 * error vary with time). gd_sim builds the plan when the modes change and evaluates the RHS and
 * the tangent map with it: the same function as gd_model_rhs and gd_model_tangent, in a different
 * order of the floating-point operations (the results agree to rounding, tests/test_rhs_plan.c),
 * at about a third of the instructions (docs/performance.md). */
#ifndef GD_RHS_PLAN_H
#define GD_RHS_PLAN_H

#include "geardyn/gd_model.h"

#include <stdint.h>
#include <string.h>

typedef struct gd_plan_coef {
    int i, j; /* acceleration i, state component j (0..n-1: positions, then velocities) */
    double v;
} gd_plan_coef;

/* the accelerations in blocks of four lanes, zeros beyond the degrees of freedom */
#define GD_PLAN_W (((GD_MAX_DOF) + 3) / 4 * 4)

/* The excitation of mesh j with its half's phase folded into the coefficients (built once per
 * model: it does not depend on the modes), in the sine and cosine (s0, c0) of Omega t:
 * stiffness factor mean + sum_h A_h cos(h Omega t) - B_h sin(h Omega t) (harmonic and tabulated),
 * error e_m + P s0 + Q c0, its rate Omega (P c0 - Q s0). */
typedef struct gd_plan_excitation {
    int kind, nh;
    double mean, A[GD_MESH_HARMONICS], B[GD_MESH_HARMONICS];
    double em, P, Q;
    int ne;                  /* a tabulated error: + sum EA_h cos(h Omega t) - EB_h sin(h Omega t) */
    double EA[GD_MESH_HARMONICS], EB[GD_MESH_HARMONICS];
} gd_plan_excitation;

void gd_plan_excitation_build(gd_plan_excitation *ex, const gd_model *m);

typedef struct gd_plan_mesh {
    int j;                    /* mesh index */
    double w[GD_PLAN_W];      /* weights of its coordinate x = w . q - e(t) over the degrees of freedom */
    double u[GD_PLAN_W];      /* w / mass: how its force moves the accelerations */
    double ks, hs, cs;        /* stiffness (0 when open), held half gap with the side's sign, damping */
    int nimp;                 /* pulses that can act in the held mode (0: none, or gated off by the mode) */
    double imp_force[GD_MAX_PULSE]; /* each mesh-in impact pulse's force while it is in its phases */
} gd_plan_mesh;

typedef struct gd_rhs_plan gd_rhs_plan;
/* the evaluation compiled for the processor (tangent: J v instead of f), chosen when the plan is built */
typedef void (*gd_rhs_plan_fn)(const gd_rhs_plan *p, const gd_model *m, double t, double s0, double c0,
                               const double *y, double *out, const gd_modes *md, int tangent);

struct gd_rhs_plan {
    int valid;
    gd_rhs_plan_fn fn;
    int mode[GD_MAX_CLEAR];   /* the modes it was built for */
    int nd, noff, nmesh;
    double b[GD_PLAN_W];      /* constant accelerations (static load, bearing contacts' offsets) */
    double kd[GD_PLAN_W], cd[GD_PLAN_W];            /* diagonal stiffness and damping over mass */
    gd_plan_coef off[2 * GD_MAX_DOF * GD_MAX_DOF]; /* the rest of the constant linear part */
    gd_plan_mesh mesh[GD_MAX_MESH];
    const gd_plan_excitation *ex; /* the model's, one per mesh (gd_plan_excitation_build) */
};

/* 1 when the plan applies: a gear model (not a custom system) with modes held between events. */
static inline int gd_rhs_plan_applies(const gd_model *m, const gd_modes *md)
{
    return !m->custom && !md->from_state;
}

/* 1 when p was built for the modes of md. Asked at every stage: the modes compared as whole
 * 64-bit words (three loads each) rather than by a call of memcmp or a loop over the clearances. */
_Static_assert(sizeof(((gd_modes *)0)->mode) == 3 * sizeof(uint64_t), "the modes are three words");
static inline uint64_t gd_plan_word(const int *mode, int k)
{
    uint64_t w;
    memcpy(&w, (const char *)mode + k * sizeof w, sizeof w);
    return w;
}
static inline int gd_rhs_plan_current(const gd_rhs_plan *p, const gd_modes *md)
{
    uint64_t d = (gd_plan_word(p->mode, 0) ^ gd_plan_word(md->mode, 0)) |
                 (gd_plan_word(p->mode, 1) ^ gd_plan_word(md->mode, 1)) |
                 (gd_plan_word(p->mode, 2) ^ gd_plan_word(md->mode, 2));
    return p->valid && d == 0;
}

/* ex: gd_plan_excitation_build of m, one per mesh; it must outlive the plan */
void gd_rhs_plan_build(gd_rhs_plan *p, const gd_model *m, const gd_modes *md, const gd_plan_excitation *ex);
/* ydot = f(t, y), with the sine and cosine (s0, c0) of Omega t (model_internal.h) */
static inline void gd_rhs_plan_rhs(const gd_rhs_plan *p, const gd_model *m, double t, double s0, double c0,
                                   const double *restrict y, double *restrict ydot, const gd_modes *md)
{
    p->fn(p, m, t, s0, c0, y, ydot, md, 0);
}
/* out = J(t, y) v */
static inline void gd_rhs_plan_tangent(const gd_rhs_plan *p, const gd_model *m, double t, double s0, double c0,
                                       const double *restrict v, double *restrict out, const gd_modes *md)
{
    p->fn(p, m, t, s0, c0, v, out, md, 1);
}

#endif
