/* The dynamic model in dimensionless form (docs/model.md).
 *
 * All three levels (torsional, torsional-lr, bta) are one structure: a diagonal mass
 * matrix, linear springs and dampers (K0, C0), a constant load F0, and a list of
 * clearances. Clearance c has the coordinate x_c = w_c . x - e_c(t) (the mesh
 * deformation along the tooth normal, or a radial bearing displacement), a half gap
 * h_c and the dead-zone force k_c(t) f(x_c; h_c) + c_c dx_c/dt acting along -w_c.
 * Time is tau = omega_n t, lengths are over the characteristic length b_c.
 *
 * Contact modes (-1 back side, 0 gap, +1 drive side) are held in the state object and
 * flipped only at located roots; the right-hand side uses the held mode, never the sign
 * of the current state (unless root finding is off: then the mode follows the state). */
#ifndef GD_MODEL_H
#define GD_MODEL_H

#include "geardyn/gd_case.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GD_MAX_DOF 10
#define GD_MAX_STATE (2 * GD_MAX_DOF)
#define GD_MAX_CLEAR 6
#define GD_MAX_MESH 2
#define GD_MAX_NNZ 64
#define GD_MESH_HARMONICS 64 /* Fourier terms of a mesh stiffness (a tabulated LTCA stiffness of 128 samples) */
#define GD_MAX_PULSE 2       /* mesh-in impact pulses of one mesh */

typedef enum gd_clearance_kind { GD_CLR_MESH = 0, GD_CLR_BEARING = 1 } gd_clearance_kind;

typedef struct gd_clearance {
    int kind;                /* gd_clearance_kind */
    int mesh;                /* mesh index (GD_CLR_MESH) or -1 */
    int nw;
    int widx[6];
    double wval[6];          /* x_c = sum wval[j] x[widx[j]] - e_mesh(t) */
    double h;                /* half gap (dimensionless) */
    double k;                /* stiffness (dimensionless; times the mesh stiffness shape for a mesh) */
    double c;                /* damping coefficient (dimensionless) */
    int damp_contact_only;
    char name[24];           /* "mesh-L", "bearing-1L", ... */
} gd_clearance;

/* Mesh excitation of one half: stiffness shape s(phase) = mean + sum a_h cos(h phase + phi_h)
 * (harmonic and tabulated stiffness) or a rectangular wave, the error e(phase) = e_m + e_r
 * sin(phase + e_phi) + sum ea_h cos(h phase + ephi_h) (the sinusoid, or a tabulated error from
 * LTCA), and the mesh-in impact pulse. */
typedef struct gd_mesh_excitation {
    int kind;                /* gd_stiffness_kind */
    int nh;
    double mean;             /* mean of s (1 for the harmonic kind; the half's mean over k_ref for a table) */
    double a[GD_MESH_HARMONICS], phi[GD_MESH_HARMONICS];
    double rect_high, rect_low, rect_frac; /* levels relative to the mean, fraction at high */
    double phase;            /* half phase offset (rad of the mesh cycle) */
    double cph, sph;         /* its cosine and sine (precomputed: one sincos per time serves both meshes) */
    double e_m, e_r, e_phi;  /* dimensionless error mean, amplitude, phase */
    int ne;                  /* harmonics of a tabulated error (0: none) */
    double ea[GD_MESH_HARMONICS], ephi[GD_MESH_HARMONICS], cephi[GD_MESH_HARMONICS], sephi[GD_MESH_HARMONICS];
    /* precomputed: cos and sin of phi[h] and of e_phi (one sincos per evaluation) */
    double cphi[GD_MESH_HARMONICS], sphi[GD_MESH_HARMONICS], ce, se;
    /* mesh-in impacts (paper section 5.2): nimp force pulses, pulse k of height imp_force[k]
     * (dimensionless, along the mesh normal like the mesh force) for the phases [imp_phase[k],
     * imp_phase[k] + imp_width[k]) of every mesh cycle (two on the one mesh of a herringbone's
     * torsional model: each half's at its own phase); imp_contact_only: they act only while the
     * mesh's flanks touch on the drive side (contact mode +1), else whatever the contact */
    int nimp;
    double imp_force[GD_MAX_PULSE], imp_phase[GD_MAX_PULSE], imp_width[GD_MAX_PULSE];
    int imp_half[GD_MAX_PULSE]; /* the helical half each pulse comes from (0 left, 1 right; a single pair: 0) */
    int imp_contact_only;
} gd_mesh_excitation;

typedef struct gd_nz { int i, j; double v; } gd_nz;

/* A smooth ODE system given by callbacks, run through the same integrator, tangent
 * and Lyapunov machinery as the gear models (tests use it for the Lorenz system). */
typedef struct gd_custom_system {
    int n;
    void (*rhs)(double t, const double *y, double *ydot, void *ctx);
    /* out = J(t, y) v */
    void (*tangent)(double t, const double *y, const double *v, double *out, void *ctx);
    /* dense J (n x n, row-major), for implicit methods; may be NULL (then dirk is refused) */
    void (*jacobian)(double t, const double *y, double *J, void *ctx);
    void *ctx;
} gd_custom_system;

typedef struct gd_model {
    int kind;                /* gd_model_kind */
    int ndof, n;             /* degrees of freedom, state size 2 ndof */
    char dof_name[GD_MAX_DOF][8];
    double inv_mass[GD_MAX_DOF];
    double mass[GD_MAX_DOF];
    int nk, nc;
    gd_nz K0[GD_MAX_NNZ], C0[GD_MAX_NNZ];
    double F0[GD_MAX_DOF];
    int nclear, nmesh;
    gd_clearance clear[GD_MAX_CLEAR];
    gd_mesh_excitation mesh[GD_MAX_MESH];
    int mesh_clear[GD_MAX_MESH]; /* clearance index of each mesh */
    int q_dof[GD_MAX_MESH];  /* DOF of the torsional coordinate q_n = cos(beta_b)(r_b1 th1 - r_b2 th2) of each mesh */
    double dte_scale;        /* cos(beta_b): q_n / dte_scale is the transverse dynamic transmission error */
    double force_share;      /* share of one mesh of the pair in a model mesh force (herringbone torsional: 1/2, else 1) */
    double Omega;            /* dimensionless mesh frequency omega_m / omega_n */
    double period;           /* dimensionless mesh period 2 pi / Omega */
    /* scales */
    double bc_m;             /* characteristic length, m */
    double omega_n;          /* rad/s */
    double m_ref, k_ref;     /* kg, N/m */
    double mesh_freq_hz;
    double static_load_n;    /* normal force of one mesh (a herringbone's half, a single pair) at the mean torque */
    int damp_contact_only;
    const gd_custom_system *custom; /* non-NULL: a custom ODE instead of a gear model */
} gd_model;

/* A model that runs a custom ODE; period: the renormalisation and sampling interval. */
GD_API void gd_model_custom(gd_model *m, const gd_custom_system *sys, double period);

/* Held per-run state the RHS depends on besides (t, y). */
typedef struct gd_modes {
    int mode[GD_MAX_CLEAR];  /* -1, 0, +1 */
    int rect_level[GD_MAX_MESH]; /* 1 high, 0 low (rectangular stiffness) */
    int pulse_on[GD_MAX_MESH];   /* bit k set while the mesh-in impact pulse k of mesh j is in its phases */
    int from_state;          /* 1: modes follow the state at every call (root finding off) */
} gd_modes;


/* Excitation of mesh j at dimensionless time t (periodic: whole periods shifted out of t do not matter). */
GD_API double gd_model_stiffness(const gd_model *m, int j, double t, const gd_modes *md);
GD_API void gd_model_error(const gd_model *m, int j, double t, const gd_modes *md, double *e, double *edot,
                           double *eddot);
/* Clearance coordinate and its rate. */
GD_API void gd_model_clearance(const gd_model *m, int c, double t, const double *y, const gd_modes *md, double *x,
                               double *xdot);
/* All clearance coordinates and rates at once (one excitation evaluation per mesh); the same
 * values as gd_model_clearance for each c. */
GD_API void gd_model_clearances(const gd_model *m, double t, const double *y, const gd_modes *md, double *x,
                                double *xdot);
/* ydot = f(t, y) with the held modes. No allocation. */
GD_API void gd_model_rhs(const gd_model *m, double t, const double *y, double *ydot, const gd_modes *md);
/* Tangent (variational) right-hand side out = J(t, y) v in the held modes: the
 * linearisation of each contact mode, O(nonzeros), no allocation. */
GD_API void gd_model_tangent(const gd_model *m, double t, const double *y, const double *v, double *out,
                             const gd_modes *md);
/* The jerk of a built-in model: the time derivative of the accelerations along the solution,
 * d/dt f(t, y(t)) = df/dy (v, acc) + df/dt in the held modes, given the accelerations acc (the
 * velocity part of f at (t, y)). Fills jerk[0..ndof) and returns 0, or returns -1 for a custom
 * system. No allocation. */
GD_API int gd_model_jerk(const gd_model *m, double t, const double *y, const double *acc, double *jerk,
                         const gd_modes *md);
/* Dense Jacobian df/dy (n x n, row-major) in the held modes. */
GD_API void gd_model_jacobian(const gd_model *m, double t, const double *y, double *J, const gd_modes *md);
/* Root functions: 2 per clearance, x_c - h_c and x_c + h_c. */
GD_API void gd_model_roots(const gd_model *m, double t, const double *y, double *g, const gd_modes *md);
/* Contact mode a clearance coordinate implies. */
GD_API int gd_model_mode_of(const gd_model *m, int c, double x);
/* Total mechanical energy (dimensionless): kinetic + springs + dead zones - F0.x; exact
 * invariant when undamped, unforced and the stiffness is constant. */
GD_API double gd_model_energy(const gd_model *m, double t, const double *y, const gd_modes *md);
/* Static deflection under F0 with the meshes in drive-side contact and mean stiffness. */
GD_API gd_status gd_model_static_state(const gd_model *m, double *y, gd_modes *md, gd_error *err);
/* Modes consistent with (t, y): the dead zone the coordinate is in, and for a coordinate
 * exactly on a boundary the side its velocity (else acceleration) moves it to, so that
 * the motion never starts on a root ARKODE would ignore. */
GD_API gd_status gd_model_consistent_modes(const gd_model *m, double t, const double *y, gd_modes *md, gd_error *err);
/* Next time after t (strictly) where an excitation is discontinuous (rectangular edges),
 * or +inf when there is none. */
GD_API double gd_model_next_discontinuity(const gd_model *m, double t, const gd_modes *md);
/* Level (1 high / 0 low) of the rectangular stiffness of mesh j just after time t. */
GD_API int gd_model_rect_level_after(const gd_model *m, int j, double t, const gd_modes *md);
/* The impact pulse force of mesh j at time t (dimensionless; 0 when off) with the mesh's clearance in
 * contact mode `mode` (a pulse that acts only in drive-side contact is 0 in any other mode). */
GD_API double gd_model_pulse_force(const gd_model *m, int j, double t, const gd_modes *md, int mode);
/* The impact pulses of mesh j in their phases just after time t (bit k: pulse k). */
GD_API int gd_model_pulse_after(const gd_model *m, int j, double t);
/* A tabulated mesh stiffness of mesh j: n samples k_i (N/m) equally spaced over one mesh cycle
 * from mesh phase 0, turned into its trigonometric interpolant (GSL real FFT; n even, at most
 * 2 GD_MESH_HARMONICS): a smooth periodic function through every sample. */
GD_API gd_status gd_model_set_stiffness_table(gd_model *m, int j, const double *k_n_per_m, int n, gd_error *err);
/* A tabulated static transmission error of mesh j: n samples e_i (m, along the tooth normal, the
 * mesh coordinate's sense) equally spaced over one mesh cycle from mesh phase 0, turned into their
 * trigonometric interpolant without its mean (GSL real FFT; n even, at most 2 GD_MESH_HARMONICS),
 * added to the error's mean and sinusoid. */
GD_API gd_status gd_model_set_error_table(gd_model *m, int j, const double *e_m, int n, gd_error *err);
/* The mesh-in impact of mesh j: a pulse of force_n (N, along the mesh normal, the force the model's
 * mesh receives) starting at mesh phase phase_rad of every cycle and lasting duration_s (at most a
 * mesh period: a whole period is a force that never stops); it replaces the mesh's pulses. */
GD_API gd_status gd_model_set_impact(gd_model *m, int j, double force_n, double phase_rad, double duration_s,
                                     gd_error *err);
/* One more pulse on mesh j (at most GD_MAX_PULSE): the torsional model of a herringbone carries each
 * half's on its one mesh. */
GD_API gd_status gd_model_add_impact(gd_model *m, int j, double force_n, double phase_rad, double duration_s,
                                     gd_error *err);

#ifdef __cplusplus
}
#endif
#endif
