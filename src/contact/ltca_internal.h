/* Internals of LTCA shared by src/contact/ltca_*.c (not installed). */
#ifndef GD_LTCA_INTERNAL_H
#define GD_LTCA_INTERNAL_H

#include "geardyn/gd_compliance.h"
#include "geardyn/gd_ltca.h"
#include "geardyn/gd_geometry.h"
#include "tca_internal.h"

#define LTCA_PAIR_OFFSET 32   /* pair labels -32 .. 31 in the warm-start bitmap */
#define LTCA_PAIR_SPAN 64

/* One body's tooth with what the assembly needs beyond gd_compliance.h. */
typedef struct ltca_body {
    gd_tooth tooth;
    double E1;               /* plane-strain modulus E' = E / (1 - nu^2) */
    double Sf;               /* root thickness 2 r_f sin(theta_f) */
    double fnd[4];           /* Sainsot's L*, M*, P*, Q* of this tooth (read back from gd_tooth_foundation) */
    double rshift;           /* radius of the virtual spur tooth minus the actual radius (same height) */
} ltca_body;

/* Per point, per body: the load point and the quantities of its influence coefficients. */
typedef struct ltca_pt_body {
    double x;                /* centre-line coordinate (the lower of two points sets the integrals) */
    double F[5];             /* cumulative integrals F0, F1, F2, S, N at the point's radius */
    double a, c, s;          /* bending moment coefficients a = cos x - sin h, cos, sin of the load angle */
    double U, C, T;          /* foundation: cos u_f / S_f, cos, sin */
    double lo, hi;           /* the point's slice (its cell of the face) in the body's axial coordinate (m) */
    double z0, z1;           /* the body's face in the same coordinate (m) */
    double ell;              /* decay length of the face kernel in the axial coordinate (m) */
} ltca_pt_body;

/* The block active-set solver of the LTCA contact problem (ltca_qp.c). */
typedef struct ltca_qp ltca_qp;
gd_status ltca_qp_alloc(int nmax, int bmax, int m, ltca_qp **out, gd_error *err);
void ltca_qp_free(ltca_qp *q);
/* Solve the QP of gd_contact.h with L block diagonal: nb blocks, block b holds points
 * bstart[b] .. bstart[b+1]-1 (entries of L outside the blocks are ignored: zero). Same method,
 * convergence criterion and report as gd_contact_solve. */
/* A feasible start for two freedoms: the least-gap point and the least-gap point that, with it,
 * carries f with positive loads (with the nearly parallel rows of G of the points of one half of a
 * floating pinion, mere independence of the rows gives a load of the wrong sign: the cold start
 * of gd_contact_solve fails there). Returns 1 and marks them, or 0. */
int ltca_qp_start(const gd_contact_problem *pb, unsigned char *loaded);
/* stop (may be NULL) is asked at every active-set iteration: a cold start on a fine face grid takes
 * seconds. */
gd_status ltca_qp_solve(ltca_qp *q, const gd_contact_problem *pb, int nb, const int *bstart,
                        const unsigned char *hint, const gd_stop_hook *stop, gd_contact_solution *sol,
                        gd_error *err);

struct gd_ltca {
    gd_tca *t;
    gd_geometry g;
    int halves, nslices, floating, m;
    ltca_body body[2];
    double cb;               /* cos(beta_b) */
    double cbeta;            /* cos(beta): normal-section strip of width dz / cos(beta) per axial dz */
    double hertz;            /* c_H cos(beta_b): Hertz compliance per unit axial width (m^2/N) */
    double Estar;            /* E / (2 (1 - nu^2)) for the Hertz pressure */
    double dz;               /* slice spacing (m) */
    double face[2][2][2];    /* [half][body] low and high end of the face (m, the body's half frame) */
    double rb2cb;            /* r_b2 cos(beta_b): gear angle -> normal approach */
    double window0, window;  /* gap window of the contact lines (m) */
    int dense;               /* use gd_contact_solve */
    /* the points of the current position */
    int n, cap, nb;
    gd_ltca_point *pts;
    ltca_pt_body *pb[2];
    double gstar[2];         /* first-contact gap of each half (m) */
    double nzmax[2];         /* largest |n_z| of each half's points */
    double nzlo[2], nzhi[2]; /* range of n_z of each half's points */
    int *bstart;
    double *L, *w, *G, *p, *d;
    double *kappa;           /* relative curvature across the contact line per point (1/m) */
    double f[GD_CONTACT_MAX_FREEDOMS];
    double z[GD_CONTACT_MAX_FREEDOMS];
    unsigned char *hint;     /* per point */
    unsigned char *prev;     /* warm-start bitmap [half][pair + offset][slice] */
    int have_prev;
    ltca_qp *qp;
    gd_contact_workspace *cws;
    int cws_n;
    gd_stop_hook stop;       /* the settings' (gd_ltca_settings.stop), asked inside a solve */
};

/* ltca_assemble.c */
gd_status ltca_collect(gd_ltca *w, double phi1, double window, gd_error *err);
void ltca_assemble(gd_ltca *w);
double ltca_influence(const ltca_pt_body *j, const ltca_pt_body *k, const ltca_body *b);
double ltca_kernel(const ltca_pt_body *j, const ltca_pt_body *k);
/* Hertz pressure and semi-width of line contact for a line load q (N/m) at point i. */
void ltca_hertz(const gd_ltca *w, int i, double q, double *p0, double *b);

#endif
