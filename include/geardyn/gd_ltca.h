/* Loaded tooth contact analysis (LTCA) of a herringbone, helical or spur pair (docs/ltca.md).
 *
 * At each pinion position the instantaneous contact lines of every tooth pair of every half come
 * from TCA (gd_tca_lines_at: one point per tooth pair and transverse slice, with its gap from the
 * gear at its ideal position), the normal flexibility matrix from the tooth and contact compliance
 * (gd_compliance.h), and the loads from the exact solution of the contact problem (the paper's
 * Eq. 11, gd_contact.h): no penetration, no tension, the torque balanced by the gear rotation and,
 * for an axially floating herringbone pinion, equal axial forces on the two halves.
 *
 * Conventions (as TCA, docs/tca.md): fixed frame with z along the pinion axis; the pinion angle
 * phi1 = 0 puts tooth pair 0 of every half at the pitch point in the middle of its face, so
 * **phase 0 of the mesh cycle is pinion angle 0 of TCA**, and positions k = 0 .. npos-1 of a
 * cycle are phi1 = k tau1 / npos (tau1 = 2 pi / z1). Loads in N along the contact normal,
 * approaches and gaps in m along the normal, angles in rad unless the name says otherwise; the
 * loaded transmission error is the lag of the gear behind its ideal position (negative, as TCA's
 * te), Eq. 12. Half 0 is the left half (the only one of a helical or spur pair), 1 the right. */
#ifndef GD_LTCA_H
#define GD_LTCA_H

#include <stdint.h>

#include "geardyn/gd_contact.h"
#include "geardyn/gd_tca.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One discretised contact point of a position, loaded or not. */
typedef struct gd_ltca_point {
    int half, pair, slice;
    double u1, z1;           /* pinion flank: roll angle, axial position from the middle of the half */
    double u2, z2;           /* gear flank (its half frame) */
    double rho1;             /* pinion roll length r_b1 u1 (m) */
    double width;            /* axial width of the point's slice (m): the face spacing, half at the ends */
    double gap;              /* initial gap w from the gear at its ideal position (m; the common reference) */
    double load;             /* normal load p (N) */
    double deformed_gap;     /* d = w + (L p)_i - (G z)_i >= 0 (m) */
    double line_load;        /* load per unit length of contact line, p cos(beta_b) / width (N/m) */
    double pressure;         /* largest Hertz pressure of line contact (Pa); 0 when unloaded */
    double hertz_half_width; /* semi-width of the Hertz strip (m) */
    double pos[3], normal[3];/* fixed frame; normal out of the pinion flank */
    unsigned edge;           /* gd_edge_kind bits: the point lies on a boundary of the flanks */
} gd_ltca_point;

/* The loaded state of one pinion position. */
typedef struct gd_ltca_position {
    double phi1;
    double torque_nm;        /* pinion torque over both halves */
    double approach;         /* rigid normal approach of the gear rotation, z_0 (m) */
    double axial_shift;      /* axial shift of a floating pinion along +z (m); 0 when fixed */
    double lte;              /* loaded transmission error of the gear, -z_0 / (r_b2 cos beta_b) (rad), Eq. 12 */
    double load[2];          /* normal load of each half (N) */
    double approach_half[2]; /* loaded normal approach of each half (m): z_0 + n_z z_1 at its points */
    double geometric[2];     /* geometric approach of each half: its first-contact gap (m), = -te r_b2 cos beta_b */
    double stiffness[2];     /* mesh stiffness of each half, Eq. 14: load / (approach - geometric) (N/m; 0 unloaded) */
    int pairs_loaded[2];     /* tooth pairs carrying load */
    double max_pressure[2];  /* Pa */
    /* edge loading (docs/ltca.md section 4): the face-end bits of a loaded end where the flanks meet
     * first (its gap, the profile relief aside, the least of its contact line's loaded points, the
     * others higher by more than GD_LTCA_EDGE_MARGIN of the line's deflection: the load concentrates
     * on the end), and the tip and root bits of loaded points on a tip edge or the form circle off the
     * nominal path (corner contact, GD_LTCA_CORNER_GAP); edge_ratio: the largest line load of a loaded face end over its contact line's
     * mean (0 when no end is loaded) */
    unsigned edge_loaded[2];
    double edge_ratio[2];
    int npoints, loaded;     /* points of the problem, points carrying load */
    int iterations;          /* active-set iterations */
    double residual;         /* the solver's largest violation of the contact conditions (m) */
    double balance;          /* |sum p - F_n| / F_n */
    double window;           /* gap window of the contact lines taken (m, above each half's first contact) */
} gd_ltca_position;

typedef struct gd_ltca gd_ltca;

/* A face end is edge-loaded when the initial gaps of its contact line's loaded points rise from it by
 * more than this fraction of the line's mean elastic deflection (an aligned pair of unmodified flanks:
 * 1e-6 of it). */
#define GD_LTCA_EDGE_MARGIN 0.10
/* A loaded point on a tip edge or form circle is a corner contact, off the nominal path of contact,
 * when its initial gap above the half's first contact, the profile relief aside, exceeds this (m). */
#define GD_LTCA_CORNER_GAP 1e-9
/* The gd_edge_kind bits of the face ends, and of the tips and form circles. */
#define GD_EDGE_FACE_ENDS 0xCCu
#define GD_EDGE_TIPS_ROOTS 0x33u

/* The load, the pinion's axial support and the discretisation of LTCA (the case's
 * operating.torque_nm, support.pinion_axial and [solver] ltca_* and tca_* keys). */
typedef struct gd_ltca_settings {
    double torque_nm;        /* pinion torque over both halves (> 0): the load of gd_ltca_run and the
                                excitations; gd_ltca_create sizes its first gap window by it */
    int pinion_axial;        /* gd_pinion_axial (gd_case.h): floating or fixed */
    int positions_per_cycle; /* pinion positions per mesh cycle */
    int face_slices;         /* slices per half: the face grid of the TCA under it */
    int profile_points;      /* the profile grid of the TCA under it */
    int refine;              /* the TCA's refinement of the grid minimum */
    gd_stop_hook stop;       /* gd_ltca_run, _run_opts and what calls them: asked before each position
                                solved (not part of the LTCA's cache key: it does not change the result) */
} gd_ltca_settings;

/* Workspace of one pair: TCA workspace, tooth compliance tables, matrices; create once, solve
 * many positions (not thread-safe: one per thread). set->face_slices sets the slices per half (the
 * TCA face grid), set->pinion_axial the axial support of the pinion; the torque of a solve is its
 * argument (set->torque_nm only sizes the first gap window). */
GD_API gd_status gd_ltca_create(const gd_pair *pair, const gd_ltca_settings *set, gd_ltca **out, gd_error *err);
GD_API void gd_ltca_free(gd_ltca *w);
/* Solve one position under a pinion torque (N m, > 0). The points stay valid until the next
 * solve on w (gd_ltca_points). The previous solve's loaded set is the warm start. */
GD_API gd_status gd_ltca_solve_at(gd_ltca *w, double phi1, double torque_nm, gd_ltca_position *out, gd_error *err);
GD_API const gd_ltca_point *gd_ltca_points(const gd_ltca *w, int *npoints);
/* The contact problem of the last solve (pointers into w): L (n x n), w, G (n x m), f. */
GD_API void gd_ltca_problem(const gd_ltca *w, gd_contact_problem *pb);
/* Use gd_contact_solve (dense KKT, the reference) instead of the block active-set solver that
 * exploits the block-diagonal L (one block per tooth pair); both solve the same QP exactly. */
GD_API void gd_ltca_use_dense_solver(gd_ltca *w, int on);
GD_API int gd_ltca_halves(const gd_ltca *w);
/* The underlying TCA workspace (for the geometric transmission error at the same positions). */
GD_API gd_tca *gd_ltca_tca(gd_ltca *w);
/* Total normal force of the mesh for a pinion torque, T1 / (r_b1 cos beta_b) (N). */
GD_API double gd_ltca_normal_force(const gd_ltca *w, double torque_nm);

/* Mesh-in impact of one half (paper section 5.2): under load the incoming tooth pair touches
 * before its theoretical start of contact, off the line of action. */
typedef struct gd_ltca_impact {
    int found;               /* 0: no pair entered over the cycle (then the rest is NaN) */
    double phi1;             /* pinion angle of the mesh-in, in [0, tau1) (rad) */
    double phase;            /* phi1 / tau1, in [0, 1) */
    int pair;                /* the incoming tooth pair at that angle */
    double pos[3], normal[3];/* the mesh-in point (fixed frame) and the pinion flank normal there */
    double rho1, z1;         /* its pinion roll length and axial position (m) */
    unsigned edge;           /* gd_edge_kind bits of the point (the gear tip edge, typically) */
    double offset_loa;       /* distance of the point from the ideal plane of action (m) */
    double rho_sap;          /* the pinion's theoretical start of contact roll length (m), for comparison */
    double vs_per_omega;     /* relative normal velocity of the flanks there per unit pinion speed,
                                (v1 - v2) . n / omega1 (m/s per rad/s), > 0 approaching */
    double delta_m;          /* loaded mesh deflection of the half at mesh-in (m): how early the pair meets */
    double ks;               /* secant stiffness of the incoming pair at delta_m (N/m) */
    double fit_c, fit_n;     /* F = fit_c delta^fit_n fitted to the incoming pair's load-approach curve */
} gd_ltca_impact;

/* The `ltca` analysis: [solver] ltca_positions_per_cycle positions over one mesh cycle. */
typedef struct gd_ltca_result {
    int halves, npos, nslices, floating;
    double torque_nm, normal_force_n;
    double *phi1;                 /* npos */
    double *lte_arcsec;           /* Eq. 12: loaded transmission error of the gear body (lag, negative) */
    double *gte_arcsec[2];        /* TCA's te of each half at the same positions (lag, negative) */
    double *lte_half_arcsec[2];   /* each half's loaded approach as a gear angle (lag, negative) */
    double *load[2];              /* normal load of each half (N) */
    double *stiffness[2];         /* Eq. 14 (N/m) */
    double *max_pressure[2];      /* Pa */
    double *axial_shift;          /* m */
    int *pairs_loaded[2];
    unsigned *edge_loaded[2];
    double *edge_ratio[2];        /* gd_ltca_position.edge_ratio */
    double lte_pp_arcsec, lte_mean_arcsec;
    double gte_pp_arcsec[2];
    double stiffness_mean[2], stiffness_min[2], stiffness_max[2];
    double load_share[2];         /* mean over the positions of the half's share of the normal load */
    double load_share_min[2], load_share_max[2];
    double pressure_max[2];       /* over the cycle */
    unsigned edge_kinds[2];       /* union of edge_loaded */
    int edge_positions[2];        /* positions with edge loading at a face end */
    int tip_positions[2];         /* positions with contact on a tip edge or form circle */
    double edge_load_max[2];      /* largest share of a half's load carried by the points of edge_loaded at one position */
    double edge_ratio_max[2];     /* the largest edge_ratio over the positions */
    double pairs_mean[2];
    /* every point of every position (loaded or not), position k at points[first[k] .. first[k+1]) */
    gd_ltca_point *points;
    int *first;
    gd_ltca_impact impact[2];     /* only with gd_ltca_run_opts(..., with_impact = 1) */
    uint64_t cache_key;
    /* solver statistics and the checks of the contact conditions over all positions */
    long iterations;
    double max_residual, max_balance, max_penetration, min_load;
    double window_max;
    double wall_s;
} gd_ltca_result;

/* Every position of one mesh cycle (set->positions_per_cycle) under set->torque_nm, with the mesh-in
 * of each half. */
GD_API gd_status gd_ltca_run(const gd_pair *pair, const gd_ltca_settings *set, gd_ltca_result *r, gd_error *err);
/* As gd_ltca_run with npos positions (<= 0: set->positions_per_cycle) and, with with_impact, the
 * mesh-in of each half (extra solves near the entry of the incoming pair). */
GD_API gd_status gd_ltca_run_opts(const gd_pair *pair, const gd_ltca_settings *set, int npos, int with_impact,
                                  gd_ltca_result *r, gd_error *err);
GD_API void gd_ltca_result_free(gd_ltca_result *r);

/* ---- excitations of the dynamic model (docs/ltca.md section 8) -------------------------------- */

/* Mesh stiffness of each half (Eq. 14, N/m along the normal) at npos equally spaced pinion
 * positions over one mesh cycle (phase 0 = TCA's pinion angle 0), the loaded transmission error
 * (arcsec, may be NULL), and the mean stiffness of each half (may be NULL). k_right may be NULL,
 * and is not written for a helical or spur pair (one half). Torque set->torque_nm. */
GD_API gd_status gd_ltca_mesh_stiffness(const gd_pair *pair, const gd_ltca_settings *set, int npos, double *k_left,
                                        double *k_right, double *lte_arcsec, double k_mean[2], gd_error *err);

/* Everything the dynamic model takes from LTCA in one run. */
typedef struct gd_ltca_excitation {
    int halves, npos;
    double *phi1;            /* npos: k tau1 / npos */
    double *k[2];            /* npos per half (k[1] NULL for one half) */
    double k_mean[2];
    double *lte_arcsec;      /* npos */
    double *lte_half_arcsec[2]; /* npos per half: each half's loaded approach as a gear angle (lag, negative;
                                   [1] NULL for one half) */
    double lte_pp_arcsec;
    double load_share[2];
    gd_ltca_impact impact[2];
    uint64_t key;            /* gd_ltca_cache_key(pair, set, npos) */
} gd_ltca_excitation;

GD_API gd_status gd_ltca_excitation_compute(const gd_pair *pair, const gd_ltca_settings *set, int npos,
                                            gd_ltca_excitation *x, gd_error *err);
GD_API void gd_ltca_excitation_free(gd_ltca_excitation *x);
/* 64-bit hash (FNV-1a) of every value LTCA depends on: the pair's geometry and material (all of
 * gd_pair but the density), its modification and misalignment, and every field of the settings
 * but positions_per_cycle, with npos (<= 0: set->positions_per_cycle). Equal keys: the same LTCA (a
 * sweep over speed at constant torque reuses it). */
GD_API uint64_t gd_ltca_cache_key(const gd_pair *pair, const gd_ltca_settings *set, int npos);
/* The bytes gd_ltca_cache_key hashes, in order: every value above, each after the name of its
 * case key ("gear.teeth_pinion"), field by field (no padding bytes), and npos; exactly what
 * determines the LTCA, so that equal bytes mean the same LTCA even where two hashes collide.
 * Written to buf as far as they fit in cap (buf may be NULL with cap 0); returns their count (call
 * once with cap 0 for the size). */
GD_API size_t gd_ltca_cache_key_bytes(const gd_pair *pair, const gd_ltca_settings *set, int npos, unsigned char *buf,
                                      size_t cap);

#ifdef __cplusplus
}
#endif
#endif
