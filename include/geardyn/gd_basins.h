/* Basins of attraction on the exact stroboscopic map (docs/basins.md).
 *
 * Initial states on a plane of the state space (a section: two coordinates moved, the others held)
 * are mapped, one mesh period at a time by the event-exact simulator (gd_sim_period), to the
 * attractor they settle on. Attractors are found by the recurrence method of Datseris & Wagemakers
 * (Chaos 32, 2022; Attractors.jl's AttractorsViaRecurrences): the plane is tessellated into cells
 * and every trajectory runs a finite-state machine over the cells its points fall in (searching;
 * an attractor found after a number of consecutive recurrences to cells it visited before; an
 * attractor hit after consecutive points on a known attractor's cells; a basin hit after
 * consecutive points on cells whose own initial state went to one attractor; lost after
 * consecutive points outside the tessellation). Only a trajectory's initial cell is labelled with
 * its outcome. A found attractor is refined by Newton shooting (gd_po_solve) when it is periodic
 * (period, Floquet multipliers, impact regime) and otherwise measured by its largest Lyapunov
 * exponent (chaotic, quasi-periodic). Divergence, leaving the tessellated box and the iteration
 * cap are labels of their own.
 *
 * Initial states are mapped in batches of a fixed size; within a batch every trajectory reads the
 * cells as they were before the batch and the batch's outcomes are merged in the order of the
 * states, so the result is the same for any number of OpenMP threads. */
#ifndef GD_BASINS_H
#define GD_BASINS_H

#include "geardyn/gd_periodic.h"
#include "geardyn/gd_response.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The outcomes that are no attractor (attractors are labelled 0, 1, ...). */
typedef enum gd_basin_label {
    GD_BASIN_DIVERGED = -1,  /* a state component above opts.horizon, or not finite */
    GD_BASIN_LEFT_BOX = -2,  /* more than opts.consecutive_lost_steps points in a row outside the tessellation */
    GD_BASIN_CAP = -3,       /* opts.max_periods mesh periods without a decision */
    GD_BASIN_FAILED = -4     /* the integration failed (chattering, a solver error) */
} gd_basin_label;
#define GD_BASIN_NSPECIAL 4
/* "diverged", "left-box", "iteration-cap", "integration-failed"; NULL for an attractor's label */
GD_API const char *gd_basin_label_name(int label);

/* A plane of initial states: the state of section coordinates (u, v) is
 * origin + u dir[0] + v dir[1], and a state y has the coordinates proj[k] . (y - origin)
 * (proj[k] . dir[j] = 1 when k = j, else 0). The box [lo, hi] is divided into cells[0] x cells[1]
 * cells: the picture's grid and the tessellation of the recurrences, which extends
 * opts.margin box widths beyond the box on every side. */
typedef struct gd_basin_section {
    int n;                   /* state size */
    double origin[GD_MAX_STATE];
    double dir[2][GD_MAX_STATE];
    double proj[2][GD_MAX_STATE];
    double lo[2], hi[2];
    int cells[2];
    int full;                /* 1: the plane is the whole state space (n = 2 and dir spans it): the section
                              * coordinates of a state determine it, so a basin hit is exact to the cell */
} gd_basin_section;

/* The plane of state components i and j through base (the other components held at base's):
 * u = y[i], v = y[j]. */
GD_API gd_status gd_basin_section_plane(gd_basin_section *s, int n, const double *base, int i, int j,
                                        double u_lo, double u_hi, double v_lo, double v_hi, int cells_u,
                                        int cells_v, gd_error *err);
/* The plane of a gear model by the names of its coordinates: lambda_L, lambda_R (a mesh's clearance
 * coordinate over its half gap h: the mesh deflection over half the backlash, at t = 0), lambda_dot_L,
 * lambda_dot_R (its rate over h, per unit of dimensionless time), moved by the mesh's torsional
 * coordinate; or a state component by its name (y1L, ..., y1L_dot; docs/basins.md section 1). The
 * other components are base's. */
GD_API gd_status gd_basin_section_named(gd_basin_section *s, const gd_model *m, const double *base, const char *x,
                                        const char *y, double x_lo, double x_hi, double y_lo, double y_hi,
                                        int cells_x, int cells_y, gd_error *err);
/* A copy of m whose time origin is mesh phase phase_rad (every mesh's phase shifted): its stroboscopic
 * map from t = 0 is m's from t = phase_rad / Omega. */
GD_API void gd_model_at_mesh_phase(const gd_model *m, double phase_rad, gd_model *out);
/* The state of section coordinates (u, v), and the coordinates of a state. */
GD_API void gd_basin_section_state(const gd_basin_section *s, double u, double v, double *y);
GD_API void gd_basin_section_coords(const gd_basin_section *s, const double *y, double *u, double *v);

typedef struct gd_basin_opts {
    int consecutive_recurrences;     /* 100: points in a row on cells the trajectory visited before: found */
    int consecutive_attractor_steps; /* 2: points in a row on one known attractor's cells: hit */
    int consecutive_basin_steps;     /* 10: points in a row on cells labelled with one attractor's basin: hit */
    int consecutive_lost_steps;      /* 20: points in a row outside the tessellation: left the box */
    int basin_hits;                  /* -1 (default): on when the section is the whole state space (full); 0 off */
    long max_periods;                /* 2000: mesh periods of one trajectory at most (the iteration cap) */
    double horizon;                  /* 1e6: a state component above it diverged (the state's own units) */
    double margin;                   /* 1: the tessellation extends this many box widths beyond the box */
    int max_period;                  /* 16: the longest period tried by shooting (GD_PO_MAX_PERIODS at most) */
    gd_po_opts po;                   /* shooting (tol, iterations; nper and multiple set per orbit) */
    double same_tol;                 /* 1e-6: two periodic attractors are one when every point of one lies within
                                      * same_tol (1 + |y|) (max-norm) of a point of the other */
    int lyapunov_periods;            /* 1000: mesh periods over which a non-periodic attractor's largest
                                      * Lyapunov exponent is measured (its cells are those of these points) */
    double chaos_threshold;          /* 0.01: largest Lyapunov exponent per mesh period above which it is
                                      * chaotic (below -threshold: not-periodic, else quasi-periodic) */
    int batch;                       /* 128: initial states mapped with the cells frozen (not the thread count) */
    int threads;                     /* 0: the OpenMP default */
    gd_stop_hook stop;               /* asked between trajectories and periods: stops with GD_ERR_INTERRUPTED */
    /* after every batch: states done of total; nonzero stops with GD_ERR_INTERRUPTED */
    int (*progress)(void *user, long done, long total);
    void *progress_user;
} gd_basin_opts;

GD_API void gd_basin_opts_default(gd_basin_opts *o);

typedef enum gd_attractor_kind {
    GD_ATT_PERIODIC = 0, GD_ATT_CHAOTIC = 1, GD_ATT_QUASI_PERIODIC = 2, GD_ATT_NOT_PERIODIC = 3
} gd_attractor_kind;
/* "periodic", "chaotic", "quasi-periodic", "not-periodic" */
GD_API const char *gd_attractor_kind_name(int kind);

typedef struct gd_attractor {
    int kind;                /* gd_attractor_kind */
    int period;              /* mesh periods of a periodic attractor (0 otherwise) */
    gd_po orbit;             /* periodic: the orbit by shooting, its Floquet multipliers (orbit.mu_*) and
                              * events per period by clearance; otherwise zero */
    double mle_per_period;   /* non-periodic: the largest Lyapunov exponent per mesh period; periodic:
                              * ln |mu_max| / period */
    int impact_regime;       /* gear models: gd_impact_regime of the first mesh on the attractor; -1 custom */
    double x_min, x_max;     /* gear models: extremes of the first mesh's clearance coordinate over the
                              * attractor (dimensionless, as the model's clearance coordinate); NaN custom */
    int npts;                /* points of the attractor at the section phase (n each) */
    double *pts;             /* periodic: the period's points, orbit.y[0..period); else the points of the
                              * Lyapunov run */
    int seeded;              /* 1: found from a seed (gd_basin_map with count_as_seed), no initial state of
                              * the sample went to it */
    char name[32];           /* "period-1", "chaotic", ... */
} gd_attractor;

typedef struct gd_basin_mapper gd_basin_mapper;

/* A mapper for model m (its stroboscopic map starts at t = 0: a section at another mesh phase is
 * a model with the mesh phases shifted) with the solver options o (n_tangent ignored). */
GD_API gd_status gd_basin_mapper_create(const gd_model *m, const gd_solver_opts *o, const gd_basin_section *sec,
                                        const gd_basin_opts *bo, gd_basin_mapper **out, gd_error *err);
GD_API void gd_basin_mapper_free(gd_basin_mapper *mp);
/* Map count states y0 (n each, row-major) to their labels (an attractor's index, or a gd_basin_label),
 * in batches (OpenMP). label_cells: label each state's initial cell with its outcome (the picture's
 * grid and the random sample do; seeds do not). seeds: attractors found only by these states are
 * marked seeded. */
GD_API gd_status gd_basin_map(gd_basin_mapper *mp, const double *y0, long count, int label_cells, int seeds,
                              int *labels, gd_error *err);
/* The states of the cells of the picture's grid, cell (i, j) at index j cells[0] + i (the cells' centres). */
GD_API gd_status gd_basin_map_grid(gd_basin_mapper *mp, int *labels, gd_error *err);
/* The attractors found so far (valid until the next call that maps states). */
GD_API int gd_basin_mapper_attractors(const gd_basin_mapper *mp, const gd_attractor **att);
/* Add a known attractor (as gd_basin_mapper_attractors gave it, of another mapper of the same model
 * and section): its cells become that attractor's; returns its index, or -1 when it is one already
 * there (*index then names it). */
GD_API gd_status gd_basin_mapper_add(gd_basin_mapper *mp, const gd_attractor *a, int *index, gd_error *err);
/* Mesh periods integrated by the mapper so far (every trajectory, shooting and Lyapunov runs apart). */
GD_API long gd_basin_mapper_periods(const gd_basin_mapper *mp);

/* A fraction of count in total: p = count / total, its standard error sqrt(p (1 - p) / total) and
 * the Wilson score interval at z standard deviations (z = 1.96: 95 %). */
typedef struct gd_basin_fraction {
    long count, total;
    double p, se, wilson_lo, wilson_hi;
} gd_basin_fraction;
GD_API void gd_basin_fraction_of(long count, long total, double z, gd_basin_fraction *f);

/* Basin entropy of a grid of labels (Daza, Wagemakers, Georgeot, Guery-Odelin & Sanjuan, Sci. Rep. 6,
 * 31416, 2016): the grid covered by boxes of box x box cells (boxes that do not fit dropped), S_i =
 * sum_j p_ij ln(1 / p_ij) over the labels j of box i; S_b the mean over all boxes, S_bb the mean over
 * the boxes with S_i > 0 (the boundary boxes). S_bb > ln 2 is a sufficient condition for a fractal
 * boundary. */
typedef struct gd_basin_entropy {
    int box;
    long boxes, boundary_boxes;
    double sb, sbb;
    int fractal;             /* sbb > ln 2 */
} gd_basin_entropy;
GD_API gd_status gd_basin_entropy_of(const int *labels, int nx, int ny, int box, gd_basin_entropy *e,
                                     gd_error *err);
/* The cells of label `label` with a 4-neighbour of another label (its boundary cells), and all its cells. */
GD_API void gd_basin_boundary_cells(const int *labels, int nx, int ny, int label, long *boundary, long *cells);

/* ---- the analysis `basins` of a case (docs/basins.md section 6) ---- */

/* The orbits of a finished continuation (its branch.csv, read by the row `basins`): every branch
 * point with the continued key's value and the state at mesh phase 0. */
typedef struct gd_basins_known {
    char parameter[256];     /* the continued key, "section.key" */
    int n;                   /* state size */
    long npoints;
    int *branch, *period, *stable;
    double *value;           /* the key's value */
    double *y;               /* npoints x n */
} gd_basins_known;

/* A continuation's orbit at a value of the parameter, refined there by shooting: a mark on the picture
 * (an unstable one on a basin boundary) or a seed (a stable one). */
typedef struct gd_basins_orbit {
    int branch, period, stable;
    double mu_max;
    double pts[GD_PO_MAX_PERIODS][GD_MAX_STATE]; /* its points at the section's phase */
    double u[GD_PO_MAX_PERIODS], v[GD_PO_MAX_PERIODS]; /* their section coordinates */
} gd_basins_orbit;

/* The attractors and fractions at one value of the parameter (the case's own without a parameter). */
typedef struct gd_basins_point {
    double value;            /* the parameter in its key's unit (NaN without a parameter) */
    int done;                /* computed (or read from another rank's record) */
    int natt;
    gd_attractor *att;       /* as the mapper found them (points owned here) */
    int *id;                 /* per attractor: its id across the values (gd_basins_match; the index without a
                              * parameter) */
    long *count;             /* per attractor: states of the sample that went to it */
    long special[GD_BASIN_NSPECIAL]; /* states labelled diverged, left-box, iteration-cap, integration-failed */
    long samples;
    long periods;            /* mesh periods integrated by the mapper at this value */
    double cpu_s;
    int norbits;
    gd_basins_orbit *orbits; /* the continuation's orbits at this value (those that converged) */
} gd_basins_point;

typedef struct gd_basins_result {
    char parameter[256];     /* "" without a parameter */
    char unit[32];
    int n;
    char state_name[GD_MAX_STATE][16];
    char coord[2][32];       /* basins.x, basins.y */
    char column[2][64];      /* their columns, with the unit in the name */
    gd_basin_section sec;    /* the section at the case's values (the first value with a parameter) */
    double phase_deg;
    /* the picture (no parameter, basins.picture): label of cell (i, j) at grid[j nx + i] */
    int nx, ny;
    int *grid;
    gd_basin_entropy entropy;
    long *grid_cells, *grid_boundary; /* per label: point 0's attractors, then the GD_BASIN_NSPECIAL labels */
    int npoints;
    gd_basins_point *pt;
    int nids;                /* attractor ids over the values */
    char notes[8][GD_ERROR_MSG_MAX];
    int nnotes;
    double z;                /* the Wilson interval's z (1.96) */
    double length_um;        /* the model's characteristic length (a dimensionless length times it: um) */
    double half_gap;         /* h of the first mesh (dimensionless; NaN for a custom system) */
    int threads;
    double wall_s;
} gd_basins_result;

/* The run's hooks: progress (initial states mapped of all planned on this rank; nonzero stops), the
 * stop hook, the threads, and this process's share of the parameter's values (value k is computed by
 * rank k mod nranks; 0 or 1 ranks: all). */
typedef struct gd_basins_hooks {
    int (*progress)(void *user, long done, long total);
    void *user;
    gd_stop_hook stop;
    int threads;
    int rank, nranks;
} gd_basins_hooks;

/* Check the [basins] keys of a resolved case (gd_case_resolve calls it through the table of analyses):
 * the coordinates exist in the model, the box is finite and not empty (derived where not given), the
 * parameter is a real-valued key; messages name the file, line, key and valid range. */
GD_API gd_status gd_basins_check_case(gd_case *c, gd_error *err);
/* Run the basins of a resolved case into *res (free with gd_basins_result_free). known (may be NULL):
 * a continuation's orbits. Without a parameter: the picture, the fractions, the continuation's stable
 * orbits as seeds and all its orbits as marks. With one: this rank's values, then (one rank) the
 * matching of gd_basins_match. */
GD_API gd_status gd_basins_run(const gd_case *c, const gd_basins_known *known, const gd_basins_hooks *h,
                               gd_basins_result *res, gd_error *err);
/* With a parameter, once every value is done: from the first value to the last, the attractors of the
 * value before are followed into this value's (an orbit continued by shooting that is one of its
 * attractors; else the attractor its points go to, mapped as seeds, which may find an attractor the
 * sample missed), the continuation's stable orbits are mapped as seeds, and every attractor gets its id
 * (the one it continues, or a new one). Seeds count nothing. */
GD_API gd_status gd_basins_match(const gd_case *c, const gd_basins_known *known, const gd_basins_hooks *h,
                                 gd_basins_result *res, gd_error *err);
GD_API void gd_basins_result_free(gd_basins_result *res);
GD_API void gd_basins_known_free(gd_basins_known *k);
/* The fraction of label `label` (an attractor's index or a gd_basin_label) at point k. */
GD_API void gd_basins_fraction(const gd_basins_result *res, int k, int label, gd_basin_fraction *f);

/* One value's point as a line of text (everything gd_basins_match and the files need, reals to 17
 * digits: it reads back bit for bit) for a program that spreads the values over processes; *line
 * malloc'd, ending in a newline. */
GD_API gd_status gd_basins_record_format(const gd_basins_result *res, int k, char **line, size_t *len,
                                         gd_error *err);
/* Read such a line into its point of res (planned by gd_basins_run on any rank). */
GD_API gd_status gd_basins_record_parse(gd_basins_result *res, const char *line, size_t len, gd_error *err);

#ifdef __cplusplus
}
#endif
#endif
