/* Modal analysis of a model linearised about a held set of contact modes (docs/model.md section 9.7).
 *
 * Each clearance is taken as its contact mode says: a closed one (mode +1 or -1) as the linear
 * spring of its contact side, with the mesh stiffness at its mean over a mesh cycle; an open one
 * (mode 0) as no spring. Damping is ignored: the modes are those of the undamped system
 * K phi = omega^2 M phi, with K the springs of the model (K0 and the closed clearances) and M its
 * diagonal mass matrix, both dimensionless (docs/model.md section 6), solved by GSL's generalized
 * symmetric-definite eigensolver. Modes of zero frequency (a coordinate nothing holds, such as the
 * axial motion of a floating pinion) are the rigid-body modes: counted and kept apart. The strain
 * energy of an elastic mode is split over the springs of the model (the elements): each clearance,
 * and K0 split exactly into springs to ground and springs between two coordinates. */
#ifndef GD_MODAL_H
#define GD_MODAL_H

#include "geardyn/gd_model.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GD_MODAL_MAX_ELEM 24   /* springs of a model: 6 clearances, 10 to ground, the couplings */
#define GD_MODAL_HARMONICS 4   /* resonance speeds: h x mesh frequency = natural frequency, h = 1..4 */

typedef enum gd_modal_element_kind {
    GD_MODAL_CLEARANCE = 0,  /* clearance clear: k (w . x)^2 / 2 */
    GD_MODAL_GROUND = 1,     /* a spring of K0 from DOF i to ground: k x_i^2 / 2 */
    GD_MODAL_COUPLING = 2    /* a spring of K0 between DOFs i and j: k (x_i - x_j)^2 / 2 */
} gd_modal_element_kind;

typedef struct gd_modal_element {
    int kind;                /* gd_modal_element_kind */
    int clear;               /* clearance index (GD_MODAL_CLEARANCE), else -1 */
    int i, j;                /* DOFs (ground: j = -1; a clearance: -1, -1) */
    double k;                /* linearised stiffness, dimensionless (0: an open clearance) */
    char name[24];           /* the clearance's name; "k(y1L)", "k(z1L,z1R)" for K0 (gd_scene_modes names them) */
} gd_modal_element;

/* A mirror map of the coordinates, x_i -> sign[i] x_{dof[i]} (an involution: dof[dof[i]] = i), under
 * which a symmetric system is invariant (a herringbone's halves, docs/model.md section 7.3). */
typedef struct gd_modal_mirror {
    int dof[GD_MAX_DOF];
    double sign[GD_MAX_DOF];
} gd_modal_mirror;

typedef struct gd_modal {
    char failed[256];            /* why there is no modal analysis ("" when there is one; set by its caller) */
    int ndof;
    char dof_name[GD_MAX_DOF][8];
    int contact[GD_MAX_CLEAR];   /* the contact mode of each clearance the linearisation used */
    int nmesh;
    double mesh_stiffness_n_per_m[GD_MAX_MESH]; /* the mean stiffness of each mesh (a herringbone's half) */
    int nmodes;                  /* elastic modes, by ascending frequency */
    int nrigid;                  /* rigid-body (zero-frequency) modes, excluded from the above */
    double lambda[GD_MAX_DOF];   /* (omega / omega_n)^2 of each elastic mode */
    double freq_hz[GD_MAX_DOF];
    /* shapes over the DOFs, scaled so that the largest component is +1 */
    double shape[GD_MAX_DOF][GD_MAX_DOF];
    double rigid_shape[GD_MAX_DOF][GD_MAX_DOF];
    /* with a mirror P the system keeps, the correlation phi.M.P phi / phi.M.phi of each mode: +1
     * symmetric, -1 antisymmetric (modes of one frequency, which the eigensolver returns as any
     * basis of their space, are combined into such pairs); NaN without */
    int mirrored;                /* 1: the mirror given maps K and M onto themselves */
    double mirror_corr[GD_MAX_DOF];
    int nelem;
    gd_modal_element elem[GD_MODAL_MAX_ELEM];
    /* strain energy of element e in mode k, phi mass-normalised (phi.M.phi = 1): their sum over e
     * is lambda[k] / 2; share[k][e] = strain[k][e] / (lambda[k] / 2), summing to 1 over e */
    double strain[GD_MAX_DOF][GD_MODAL_MAX_ELEM];
    double share[GD_MAX_DOF][GD_MODAL_MAX_ELEM];
    /* pinion speeds (rpm) where h x the mesh frequency equals the natural frequency, h = 1..4:
     * the main resonance and the superharmonic ones at 1/2, 1/3, 1/4 of its speed (gd_scene_modes;
     * gd_modal_analyse leaves them NaN) */
    double resonance_rpm[GD_MAX_DOF][GD_MODAL_HARMONICS];
} gd_modal;

/* Mode k under the mirror: "symmetric" or "antisymmetric" (|correlation| above 0.999), "mixed", or
 * NULL when the system has no mirror. */
static inline const char *gd_modal_halves(const gd_modal *md, int k)
{
    if (!md->mirrored)
        return 0;
    return md->mirror_corr[k] > 0.999 ? "symmetric" : md->mirror_corr[k] < -0.999 ? "antisymmetric" : "mixed";
}

/* The linearised stiffness matrix (dimensionless, ndof x ndof, row-major) in the contact modes md:
 * K0 plus, for each closed clearance, its stiffness times its mesh's mean stiffness factor times
 * w w^T. */
GD_API gd_status gd_modal_stiffness(const gd_model *m, const gd_modes *md, double *K, gd_error *err);
/* The mean over a mesh cycle of the stiffness factor of mesh j (1 for a constant stiffness). */
GD_API double gd_modal_mean_stiffness(const gd_model *m, int j);
/* Frequencies, shapes and strain-energy shares of the model in the contact modes md; mirror may be
 * NULL. A custom system has no springs to analyse: GD_ERR_INPUT. */
GD_API gd_status gd_modal_analyse(const gd_model *m, const gd_modes *md, const gd_modal_mirror *mirror,
                                  gd_modal *out, gd_error *err);

#ifdef __cplusplus
}
#endif
#endif
