/* Tooth and contact compliance for loaded tooth contact analysis (docs/ltca.md).
 *
 * Each tooth is a slice model in the transverse section: a cantilever of variable thickness
 * clamped at the root circle (Timoshenko beam: bending, shear, compression; the potential-energy
 * method of Yang & Lin 1987 and Tian 2004 with the involute thickness along the height, and the
 * fillet foundation of Sainsot, Velex & Duverger 2004), and a linear Hertzian contact compliance
 * (Yang & Sun 1985). Influence coefficients between two load points of one tooth follow from
 * Maxwell-Betti reciprocity (virtual work with unit loads along each point's contact normal), and
 * the face-width coupling is an exponential kernel, mirrored at the faces so that the end slices
 * are softer, whose decay length grows with the height of the load above the clamped root
 * section, as the spread of a point load on a thick (Mindlin) cantilever plate strip does
 * (docs/ltca.md section 2). Transverse slice compliances become normal ones by cos^2(beta_b). */
#ifndef GD_COMPLIANCE_H
#define GD_COMPLIANCE_H

#include "geardyn/gd_geometry.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GD_TOOTH_GRID 257

/* One body's tooth in the transverse section, ready for influence coefficients: the cumulative
 * integrals F_n(r) = int x^n / (E' I) dx (n = 0, 1, 2), S(r) = int 1 / (G A) dx and
 * N(r) = int 1 / (E' A) dx along the centre line from the root up to the section at radius r,
 * tabulated on a radius grid and interpolated by cubic splines (GSL); every influence coefficient
 * is then a short combination of them (no integral per coefficient). */
typedef struct gd_tooth {
    double E, nu;             /* Pa, - */
    double rb, rf, ra;        /* base, root, tip radius (m) */
    double psi_b;             /* half tooth-thickness angle at the base circle (< 0: a plain beam) */
    double beam_y;            /* the beam's half thickness */
    double x_root;            /* centre-line coordinate of the clamped section (m) */
    double theta_f;           /* half root angle: root thickness S_f = 2 r_f sin(theta_f) */
    double h_fi;              /* r_f / r_int (rim ratio of Sainsot's fit) */
    double r0, r1;            /* radius range of the tables */
    void *spline[5], *acc[5]; /* gsl_spline, gsl_interp_accel of F0, F1, F2, S, N */
    double height;            /* length of the cantilever: centre-line coordinate of the tip less x_root (m) */
} gd_tooth;

/* A load point on the flank: its radius and the quantities of the unit load there. */
typedef struct gd_load_point {
    double r;                 /* radius (m) */
    double x;                 /* centre-line coordinate of the point (projection) */
    double h;                 /* lateral distance of the point from the centre line */
    double cos_a, sin_a;      /* load angle alpha_1 to the perpendicular of the centre line */
} gd_load_point;

/* body 0 pinion, 1 gear */
GD_API gd_status gd_tooth_init(const gd_pair *pair, const gd_geometry *g, int body, gd_tooth *t, gd_error *err);
/* A tooth of constant half-thickness y from x_root to x_tip (a beam; for tests). */
GD_API gd_status gd_tooth_init_beam(gd_tooth *t, double E, double nu, double x_root, double x_tip, double y,
                                    gd_error *err);
GD_API void gd_tooth_free(gd_tooth *t);
GD_API void gd_load_point_at(const gd_tooth *t, double r, gd_load_point *p);
/* Deflection along the normal of point j under a unit normal load at point k, per unit width
 * of the slice (m^2/N): bending + shear + compression of the tooth. Symmetric in j, k. Not
 * thread-safe on one gd_tooth (the spline accelerators). */
GD_API double gd_tooth_influence(const gd_tooth *t, const gd_load_point *j, const gd_load_point *k);
/* Fillet-foundation compliance of a load at p (Sainsot et al. 2004), per unit width (m^2/N). */
GD_API double gd_tooth_foundation(const gd_tooth *t, const gd_load_point *p);
/* Linear Hertzian contact compliance of two steel flanks per unit contact length (m^2/N):
 * 4 (1 - nu^2) / (pi E) (Yang & Sun 1985). */
GD_API double gd_hertz_compliance(double E, double nu);
/* Face coupling kernel (1/m) between axial positions za, zb on a face [z0, z1] with decay length
 * ell: exp(-|za - zb|/ell)/(2 ell) plus its mirror images in both faces. */
GD_API double gd_face_kernel(double za, double zb, double z0, double z1, double ell);
/* The same for two points with their own decay lengths ell_a, ell_b: gd_face_kernel with the
 * root mean square of the two, sqrt((ell_a^2 + ell_b^2)/2) -- the nonstationary exponential
 * covariance of Paciorek & Schervish (2006) scaled to unit weight, positive definite for any
 * lengths; equal lengths give gd_face_kernel. */
GD_API double gd_face_kernel_pair(double za, double zb, double z0, double z1, double ell_a, double ell_b);
/* gd_face_kernel_pair averaged over two cells of the face, [alo, ahi] and [blo, bhi] (disjoint or
 * the same cell): 1 / ((ahi - alo)(bhi - blo)) times the double integral, in closed form. A load
 * spread uniformly over cell b, the deflection averaged over cell a: LTCA's slices. A uniform
 * line load over cells that tile the face gives unit weight at any ratio of the decay length to
 * the cell width (to e^{-(z1 - z0)/ell}: the images are the first ones only). */
GD_API double gd_face_kernel_cells(double alo, double ahi, double blo, double bhi, double z0, double z1, double ell_a,
                                   double ell_b);
/* Decay length of the face kernel along the tooth (m) for a load at p, at the height a of the load
 * above the clamped root section: ell = min(0.8 a, 0.4 height), with which the exponential kernel
 * reproduces the line-load stiffness of a clamped-free Mindlin plate strip of the tooth's own
 * thickness (docs/ltca.md section 2; tests/test_ltca_kernel.c checks it against the plate). */
GD_API double gd_tooth_spread(const gd_tooth *t, const gd_load_point *p);

#ifdef __cplusplus
}
#endif
#endif
