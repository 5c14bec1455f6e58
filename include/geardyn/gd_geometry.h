/* Involute helical gear geometry per ISO 21771 (derived values of a gear pair). */
#ifndef GD_GEOMETRY_H
#define GD_GEOMETRY_H

#include "geardyn/gd_pair.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Lengths in metres, angles in radians. Index 0 pinion, 1 gear. */
typedef struct gd_geometry {
    double mn, mt;          /* normal and transverse module */
    double alpha_n, alpha_t, alpha_wt; /* normal, transverse, working transverse pressure angle */
    double beta, beta_b;    /* reference and base helix angle */
    int z[2];
    double x[2];
    double r[2], rb[2], ra[2], rf[2], rw[2];  /* reference, base, tip, root, working pitch radii */
    double a0, a;           /* reference and working centre distance */
    double pbt, pn;         /* transverse base pitch, normal pitch */
    double eps_alpha, eps_beta, eps_gamma; /* transverse, overlap, total contact ratio */
    double b[2];            /* face width of one half */
    double b_contact;       /* common (contact) face width of one half */
    double r_sap[2];        /* start of active profile radii */
    double tip_thickness_n[2]; /* normal tooth thickness at the tip circle (arc, m) */
    /* Transverse roll lengths rho = sqrt(r^2 - rb^2) (docs/geometry.md): tip, start of active
     * profile, and the involute form circle (lowest point of the generated involute: below it
     * lies the fillet). Index 0 pinion, 1 gear. */
    double rho_a[2], rho_sap[2], rho_form[2];
    double r_form[2];        /* involute form circle radius */
    double psi_b[2];         /* half tooth thickness angle at the base circle, s_t/(2r) + inv(alpha_t) */
    double eta_b[2];         /* half space width angle at the base circle, pi/z - psi_b */
    double pbn;              /* normal base pitch p_bt cos(beta_b) */
    const char *bad_key;     /* on GD_ERR_GEOMETRY: the [gear] key most responsible */
} gd_geometry;

GD_API gd_status gd_geometry_compute(const gd_pair *pair, gd_geometry *g, gd_error *err);
/* Involute function inv(a) = tan a - a and its inverse (Newton, GSL-free closed loop). */
GD_API double gd_involute(double a);

/* The blank of a body in metres: coaxial annuli, each over its own axial length, that meet without
 * overlap. The rim with the teeth runs from r_rim to the reference radius over the face (and to the
 * root radius over the groove of a herringbone); the web from r_hub to r_rim over its thickness; the
 * hub from r_bore to r_hub over its length. Without a rim (rim_inner_diameter 0) r_rim = r_hub and
 * the web is 0 long: a solid blank over the face; without a hub r_hub = r_bore. */
typedef struct gd_blank {
    double r_bore, r_hub, r_rim;  /* m */
    double web, hub_length;       /* axial lengths of the web and the hub, m (0: none) */
    double groove, width;         /* the relief groove (0 in a single pair) and the body's width, m */
} gd_blank;
GD_API void gd_body_blank(const gd_pair *pair, const gd_geometry *g, int which, gd_blank *b);
/* Mass and polar inertia of the part of body `which` (0 pinion, 1 gear) that carries one mesh: the
 * annuli of its blank (gd_blank: the teeth as a cylinder of the reference radius over the face,
 * the rim, web and hub), steel of pair->density_kg_per_m3. A herringbone half carries its half's
 * teeth, half the groove (a cylinder of the root radius) and half the web and hub; a spur or
 * single-helical pair is its whole body (docs/model.md section 9.2). */
GD_API void gd_body_of_mesh(const gd_pair *pair, const gd_geometry *g, int which, double *mass_kg, double *inertia_kgm2);
/* Mean mesh stiffness of one mesh (a herringbone's half, a single pair) along the tooth normal,
 * N/m, from ISO 6336-1
 * (method B: c' and c_gamma_alpha times the contact face width, transverse), divided by
 * cos^2(beta_b) to refer it to the normal direction (docs/model.md). */
GD_API double gd_iso6336_mesh_stiffness(const gd_pair *pair, const gd_geometry *g);
/* Every factor of gd_iso6336_mesh_stiffness (docs/model.md section 5.1), so that a reader can
 * redo the calculation: k = c_gamma_alpha b / cos^2(beta_b), c_gamma_alpha = c' (0.75 eps_alpha
 * + 0.25) (times 0.9 below eps_alpha 1.2), c' = c'_th C_M C_R C_B cos(beta), c'_th = 1 / q'
 * from the virtual numbers of teeth z_n = z / (cos^2(beta_b) cos(beta)). */
typedef struct gd_iso6336_terms {
    double zn[2];            /* virtual numbers of teeth, pinion and gear */
    double q_prime;          /* q' (mm um / N) */
    double c_th;             /* c'_th = 1 / q' (N / (mm um)) */
    double c_m, c_r, c_b;    /* C_M (solid blanks 0.8), C_R (1), basic rack factor C_B */
    double cos_beta;         /* cos of the reference helix angle */
    double c_prime;          /* single stiffness c' (N / (mm um)) */
    double eps_alpha;        /* transverse contact ratio */
    double eps_factor;       /* 0.75 eps_alpha + 0.25, times 0.9 below eps_alpha 1.2 */
    double c_gamma_alpha;    /* mesh stiffness per unit face width, transverse (N / (mm um)) */
    double face_width_mm;    /* b: the common face width of the mesh (the narrower body's) */
    double cos2_beta_b;      /* cos^2 of the base helix angle: transverse to normal */
    double k_n_per_m;        /* the result, along the normal (N/m) */
} gd_iso6336_terms;
GD_API void gd_iso6336_mesh_stiffness_terms(const gd_pair *pair, const gd_geometry *g, gd_iso6336_terms *t);
/* Axial stiffness of a groove shaft: E pi rf^2 / groove width (N/m). */
GD_API double gd_groove_shaft_stiffness(const gd_pair *pair, const gd_geometry *g, int which);

#ifdef __cplusplus
}
#endif
#endif
