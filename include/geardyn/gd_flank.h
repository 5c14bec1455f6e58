/* Tooth flank surfaces for contact analysis (docs/geometry.md).
 *
 * A flank is the drive-side flank of tooth 0 of one helical half, in the body frame of that
 * half: z along the axis, measured from the middle of the half's face; the x axis is the centre
 * line of the tooth space bounded below by the flank, at z = 0. Parameters:
 *   u  the involute roll angle of the transverse section (roll length rho = r_b u),
 *   z  the axial position.
 * The pinion flank carries the form-ground 3D modification of the paper (section 2, Eq. 1-6):
 * the transverse profile moved along its generating line by the profile relief, carried along
 * the screw motion of the helix with the grinding wheel's radial feed l(z) for the lead relief:
 *   r(u, z) = Rz(k z) [ P(u) - H_t(u) e_t(psi) - l(z) e_x ] + z e_z,  psi = -eta_b - u,
 * with P(u) = r_b (e_r(psi) + u e_t(psi)) the involute and k the twist rate of the helix
 * (k = hand tan(beta) / r, hand +1 right, -1 left; k = 0 for spur; the pinion's helix slope
 * modification adds dk to it, docs/geometry.md). The gear flank is the
 * unmodified involute helicoid of the same form. Everything is closed form, with first and
 * second derivatives, so that Newton solves have analytic Jacobians. Lengths in metres. */
#ifndef GD_FLANK_H
#define GD_FLANK_H

#include "geardyn/gd_geometry.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gd_flank {
    int body;               /* 0 pinion, 1 gear */
    int hand;               /* +1 right, -1 left, 0 spur */
    double rb;              /* base radius */
    double k;               /* twist rate of the helix, rad/m (tan(beta_b) = |k| rb) */
    double eta_b;           /* half space width angle at the base circle */
    double cos_bb, sin_bb;  /* base helix angle */
    double u_min, u_max;    /* roll angle domain: involute form circle .. tip circle */
    double z_min, z_max;    /* face of the half, axial, from the middle of the face */
    double u_ref;           /* roll angle at the reference circle, tan(alpha_t) */
    /* profile relief, normal amounts (m) over transverse roll lengths (m):
     * H_n(rho) = root_amount ((rho_c - rho)/root_len)^2 below rho_c = rho_sap + root_len,
     *            tip_amount ((rho - rho_g)/tip_len)^2 above rho_g = rho_a - tip_len, zero between */
    double rho_c, root_amount, root_len;
    double rho_g, tip_amount, tip_len;
    /* lead relief: radial feed of the wheel l(z) = a_lo (z_lo - z)^2 below z_lo,
     * a_hi (z - z_hi)^2 above z_hi, zero between (paper Eq. 3 with h = p phi = z) */
    double z_lo, z_hi, a_lo, a_hi;
    /* helix slope modification (y9): the part dk of the twist rate k that turns the flank by dk z
     * about the axis, a normal deviation -r_b cos(beta_b) dk z uniform over the profile (0: none) */
    double dk;
    int modified;           /* any nonzero relief (profile or lead; the helix slope is in k) */
} gd_flank;

/* Point and derivatives of a flank at (u, z), body frame of the half. */
typedef struct gd_flank_eval {
    double r[3];
    double ru[3], rz[3];             /* order >= 1 */
    double ruu[3], ruz[3], rzz[3];   /* order >= 2 */
} gd_flank_eval;

/* Whether the pair's modification fits on the pinion flank: a relief amount needs a length, the
 * root and tip relief lengths must fit on the active profile, the unmodified lead length on the
 * face, and no relief may take away half the tooth thickness. On failure GD_ERR_INPUT with the
 * problem and the valid range, and *bad_key names the [modification] key (gd_scene_resolve adds
 * the file and line). */
GD_API gd_status gd_modification_check(const gd_pair *pair, const gd_geometry *g, const char **bad_key, gd_error *err);
/* The pinion flank of half `half` (0 left, 1 right) with the pair's modification (checked). */
GD_API gd_status gd_flank_pinion(const gd_pair *pair, const gd_geometry *g, int half, gd_flank *f, gd_error *err);
/* The gear flank of half `half`: unmodified involute helicoid, opposite hand to the pinion. */
GD_API gd_status gd_flank_gear(const gd_pair *pair, const gd_geometry *g, int half, gd_flank *f, gd_error *err);
/* Hand (+1 right, -1 left, 0 spur) of the pinion helix in half `half`. */
GD_API int gd_flank_pinion_hand(const gd_pair *pair, int half);

/* order 0: position; 1: and first derivatives; 2: and second derivatives. */
GD_API void gd_flank_eval_at(const gd_flank *f, double u, double z, int order, gd_flank_eval *e);
/* Unit normal pointing out of the tooth material (needs order >= 1). */
GD_API void gd_flank_normal(const gd_flank_eval *e, double n[3]);
/* Principal curvatures k[0] <= k[1] (1/m, positive where the flank is convex, i.e. bends away
 * from the outward normal) and their unit directions (needs order 2). */
GD_API void gd_flank_curvature(const gd_flank_eval *e, double k[2], double dir[2][3]);

/* The prescribed relief at (u, z): profile relief normal to the flank (m) and radial feed l(z) (m). */
GD_API void gd_flank_relief(const gd_flank *f, double u, double z, double *profile_normal, double *lead_feed);
/* First-order normal deviation produced by a unit radial feed at roll angle u:
 * cos(beta_b) sin(eta_b + u) (docs/geometry.md: the projection of the feed on the normal). */
GD_API double gd_flank_feed_projection(const gd_flank *f, double u);

#ifdef __cplusplus
}
#endif
#endif
