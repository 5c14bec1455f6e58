/* Tooth contact analysis (TCA) of a herringbone, helical or spur pair (docs/tca.md).
 *
 * Each helical half meshes as a helical pair. The fixed frame has its origin on the pinion axis in
 * the middle of the gear pair (the middle of the groove), z along the pinion axis, x from the
 * pinion axis to the gear axis. The pinion turns by phi1 about +z, the gear by phi2 about its own
 * axis in the opposite sense; phi1 = 0 puts tooth pair 0 of every half in nominal contact at the
 * pitch point in the middle of its face, and phi2 = (z1/z2) phi1 is the ideal (conjugate) motion.
 * The gear axis is tilted about the middle of the gear (in and across the plane of the axes) and
 * moved away by the centre-distance error.
 *
 * Two formulations (both with GSL multiroot solvers and analytic Jacobians):
 *  (b) surface separation: at every node of a grid on the pinion flank, the gear rotation that
 *      closes the gap there; the least is the transmission error (refined to the exact minimum of
 *      the flank, its edges or corners), the nodes within the paint thickness the contact pattern;
 *  (a) surface tangency: position and normal coincide (five equations, phi1 given), with the
 *      edge-contact systems of the pinion tip edge, the pinion end faces, the gear tip edge and the
 *      corners; singular for line contact, where (b) still works.
 * A tooth pair p is pinion tooth p with the gear tooth it meets (p = 0 at the pitch point at
 * phi1 = 0; p > 0 are the pairs ahead, further into the mesh). Angles in radians, lengths in metres. */
#ifndef GD_TCA_H
#define GD_TCA_H

#include "geardyn/gd_flank.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Where a contact lies on the boundary of the flanks (bits). */
typedef enum gd_edge_kind {
    GD_EDGE_PINION_ROOT = 1u << 0,   /* pinion flank at its involute form circle (the fillet begins) */
    GD_EDGE_PINION_TIP = 1u << 1,    /* pinion tip edge */
    GD_EDGE_PINION_END_LO = 1u << 2, /* pinion end face at the low end (z_min) of the half */
    GD_EDGE_PINION_END_HI = 1u << 3, /* pinion end face at the high end (z_max) */
    GD_EDGE_GEAR_ROOT = 1u << 4,
    GD_EDGE_GEAR_TIP = 1u << 5,      /* gear tip edge on the pinion flank */
    GD_EDGE_GEAR_END_LO = 1u << 6,
    GD_EDGE_GEAR_END_HI = 1u << 7,
    GD_EDGE_NKINDS = 8
} gd_edge_kind;
GD_API const char *gd_edge_kind_name(int bit_index);

typedef struct gd_tca gd_tca;

/* The contact-analysis settings of TCA (the case's [solver] tca_* keys). */
typedef struct gd_tca_settings {
    int profile_points, face_points; /* grid on the pinion flank: along the profile, across each half's face */
    int refine;                      /* 1: the grid minimum refined to the exact minimum (Newton) */
    int positions_per_cycle, cycles; /* gd_tca_run: pinion positions per mesh cycle, mesh cycles */
    int formulation;                 /* gd_tca_run: gd_tca_formulation (gd_case.h) */
    gd_stop_hook stop;               /* gd_tca_run: asked before each pinion position of each half */
} gd_tca_settings;

/* Every field the default of its case key ([solver] tca_*), no stop hook. */
GD_API gd_tca_settings gd_tca_settings_defaults(void);

/* The first contact of one half at one pinion position. */
typedef struct gd_tca_contact {
    double phi1;          /* pinion angle */
    double te;            /* transmission error phi2 - (z1/z2) phi1 (negative: the gear lags) */
    int pair;             /* tooth pair that touches first */
    double u1, z1;        /* pinion flank parameters (roll angle, axial from the middle of the half) */
    double u2, z2;        /* gear flank parameters */
    double pos[3];        /* contact point, fixed frame */
    double normal[3];     /* unit normal out of the pinion flank, fixed frame */
    double alpha_op;      /* transverse pressure angle of that normal (operating pressure angle) */
    unsigned edge;        /* gd_edge_kind bits of every first contact on a boundary (0: none) */
    int pairs_in_contact; /* tooth pairs touching within the contact tolerance */
    int iterations;       /* Newton iterations spent at this position */
    int converged;        /* (a): a valid contact was found; (b): always 1 */
} gd_tca_contact;

/* A point of a discretised instantaneous contact line, with the initial gap and the local
 * geometry LTCA needs: one point per tooth pair and face slice of the grid, where the
 * separation in that transverse slice is least. */
typedef struct gd_tca_line_point {
    int pair, slice;
    double u1, z1, u2, z2;
    double gap;                 /* separation along the normal from the half's first contact, >= 0 */
    double gap_nominal;         /* separation from the gear at its ideal position phi2 = (z1/z2) phi1: the
                                   common reference of both halves on one gear body (LTCA) */
    double pos[3], normal[3];   /* fixed frame; normal out of the pinion flank */
    double k1[2], dir1[2][3];   /* principal curvatures (convex > 0) and directions of the pinion flank */
    double k2[2], dir2[2][3];   /* of the gear flank (fixed frame) */
    unsigned edge;              /* the slice minimum lies on this boundary (gd_edge_kind bits) */
} gd_tca_line_point;

/* Workspace of one pair (every half): geometry, flanks, frames, the flank grid (set->profile_points,
 * set->face_points, set->refine), the Newton solvers. Create once, use for many positions; not
 * thread-safe (one per thread). */
GD_API gd_status gd_tca_create(const gd_pair *pair, const gd_tca_settings *set, gd_tca **out, gd_error *err);
GD_API void gd_tca_free(gd_tca *t);
GD_API int gd_tca_halves(const gd_tca *t);
GD_API const gd_geometry *gd_tca_geometry(const gd_tca *t);
/* body 0 pinion, 1 gear */
GD_API const gd_flank *gd_tca_flank(const gd_tca *t, int half, int body);
/* Axial position of the middle of the half in the fixed frame. */
GD_API double gd_tca_half_centre(const gd_tca *t, int half);
/* Operating transverse pressure angle of the ideal involute pair at the actual centre distance. */
GD_API double gd_tca_operating_pressure_angle(const gd_tca *t);

/* The first contact of half `half` at pinion angle phi1 by formulation (b) or (a)
 * (GD_TCA_SEPARATION or GD_TCA_TANGENCY). (b) also accumulates the separation topography of
 * gd_tca_topography. */
GD_API gd_status gd_tca_contact_at(gd_tca *t, int half, int formulation, double phi1, gd_tca_contact *out,
                                   gd_error *err);
/* The instantaneous contact lines of half `half` at phi1: per tooth pair and grid face slice, the
 * point of least separation if its gap is at most max_gap. The array stays valid until the next
 * call on t. */
GD_API gd_status gd_tca_lines_at(gd_tca *t, int half, double phi1, double max_gap, const gd_tca_line_point **pts,
                                 int *npts, gd_error *err);
/* Gap at one pinion flank point of tooth pair `pair`: the gear rotation that closes it (rad,
 * positive: open), and where it lands on the gear (radius and axial position in the gear's half
 * frame). Returns 0 if the point cannot meet the gear flank there (outside its radii or face). */
GD_API int gd_tca_gap(const gd_tca *t, int half, double phi1, int pair, double u1, double z1, double *gap,
                      double *r2, double *z2);
/* Fixed-frame position of the pinion flank point (u1, z1) of tooth pair `pair` at phi1. */
GD_API void gd_tca_pinion_point(const gd_tca *t, int half, double phi1, int pair, double u1, double z1, double x[3]);

/* Separation topography of the positions computed so far by (b): per grid node of the pinion
 * flank of tooth 0 (profile index i fastest), the least separation from the gear flank relative to
 * the instantaneous first contact (sep) and relative to the ideal conjugate gear position
 * (ease_off), m; NaN where the node never met the gear. rho: roll lengths of the profile nodes,
 * z: axial positions of the face nodes. */
GD_API void gd_tca_topography(const gd_tca *t, int half, int *nprof, int *nface, const double **rho, const double **z,
                              const double **sep, const double **ease_off);
GD_API void gd_tca_topography_reset(gd_tca *t);

/* The `tca` analysis: every half over set->cycles mesh cycles with set->positions_per_cycle
 * positions per cycle, by set->formulation. */
typedef struct gd_tca_result {
    int halves, npos, nprof, nface;
    double *phi1;                   /* npos */
    gd_tca_contact *contact[2];     /* npos per half: formulation (b), or (a) when tangency alone */
    double *gte_arcsec[2];          /* Eq. 10: relative to the first position, arc-seconds of the gear */
    double gte_pp_arcsec[2];
    double te_mean_arcsec[2];       /* mean of te (absolute lag relative to the ideal motion) */
    unsigned edge_kinds[2];         /* union over the positions */
    int edge_positions[2];          /* positions with edge contact */
    double pairs_mean[2];           /* mean number of tooth pairs in contact */
    int pairs_min[2], pairs_max[2];
    double alpha_op_mean;           /* mean operating pressure angle at the contacts, rad */
    /* formulation (a) beside (b) when both */
    gd_tca_contact *contact_a[2];
    int compared;                   /* positions where (a) found a contact */
    double max_diff_arcsec;         /* largest |te(a) - te(b)| there */
    /* topography (copies), nprof x nface per half */
    double *rho, *z;                /* node roll lengths and axial positions (m) */
    double *sep[2], *ease_off[2];
    double contact_ratio_transverse, contact_ratio_overlap;
    long iterations;
    double wall_s;
} gd_tca_result;

GD_API gd_status gd_tca_run(const gd_pair *pair, const gd_tca_settings *set, gd_tca_result *res, gd_error *err);
GD_API void gd_tca_result_free(gd_tca_result *r);

#ifdef __cplusplus
}
#endif
#endif
