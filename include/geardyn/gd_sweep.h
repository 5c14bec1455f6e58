/* Sweeps (`analysis = sweep`): one case key, or two for a regime map, varied over a grid,
 * every grid point a `response` run (gd_response.h).
 *
 * Modes: continuation (each point starts from the final state of the previous point of its
 * chain; a chain runs up or down the first parameter at one value of the second, so that
 * jumps and hysteresis show as two branches) and independent (every point from the case's
 * initial state). The work units are the chains (continuation) or the points (independent);
 * they run in parallel with OpenMP, and over MPI ranks when the caller distributes them
 * (gd_sweep_opts.rank, .nranks). Every point is computed by the same deterministic code
 * from the same inputs whatever the thread or rank, so results do not depend on either.
 *
 * A finished point is handed to the caller at once (gd_sweep_opts.point_done) and can be
 * written as one self-checking text record (gd_sweep_record_format) that holds everything
 * the final files and a continuation need; a journal of such records is read back by
 * gd_sweep_journal_load to resume an interrupted sweep. The final tables and summary.json
 * (the sweep row of gd_analysis.h) are written from the point array in slot order, so neither
 * the thread count, the ranks nor an interruption change them. */
#ifndef GD_SWEEP_H
#define GD_SWEEP_H

#include <stdint.h>

#include "geardyn/gd_response.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum gd_sweep_spacing { GD_SWEEP_LINEAR = 0, GD_SWEEP_LOG = 1 } gd_sweep_spacing;
typedef enum gd_sweep_mode { GD_SWEEP_CONTINUATION = 0, GD_SWEEP_INDEPENDENT = 1 } gd_sweep_mode;
typedef enum gd_sweep_direction { GD_SWEEP_UP = 0, GD_SWEEP_DOWN = 1, GD_SWEEP_BOTH = 2 } gd_sweep_direction;
/* The branch a result belongs to: the `direction` column of the tables. */
typedef enum gd_sweep_branch { GD_BRANCH_UP = 0, GD_BRANCH_DOWN = 1, GD_BRANCH_INDEPENDENT = 2 } gd_sweep_branch;
GD_API const char *gd_sweep_branch_name(int branch);

/* Status of a point. */
typedef enum gd_sweep_status { GD_POINT_PENDING = 0, GD_POINT_DONE = 1, GD_POINT_FAILED = 2 } gd_sweep_status;

#define GD_SWEEP_MAX_RESPONSES 8

/* A response sampled at every Poincare point: the dimensionless mesh deflection
 * lambda = w.x - e(t) of a mesh or its rate, or a state variable. */
typedef enum gd_sweep_response_kind { GD_RESP_MESH = 0, GD_RESP_MESH_RATE = 1, GD_RESP_STATE = 2 } gd_sweep_response_kind;
typedef struct gd_sweep_response {
    char name[24];           /* column name in bifurcation.csv */
    int kind;                /* gd_sweep_response_kind */
    int index;               /* mesh index, or index into the state */
} gd_sweep_response;

/* A chain: the points run one after the other from one state (continuation), or a single
 * point (independent). Its points are the slots first .. first + count - 1. */
typedef struct gd_sweep_chain {
    int branch;              /* gd_sweep_branch */
    int row;                 /* index along parameter2 (0 for a one-parameter sweep) */
    int first, count;
} gd_sweep_chain;

typedef struct gd_sweep_plan {
    int naxes;               /* 1: parameter only; 2: a regime map over parameter and parameter2 */
    char parameter[2][256];  /* "section.key" */
    char unit[2][32];
    int npoints[2];
    double *values[2];       /* npoints[a] values of axis a, from `from` to `to` */
    int mode, direction, spacing[2];
    int nchains;
    gd_sweep_chain *chains;  /* in output order: rows of parameter2, then up before down */
    int nslots;              /* results: one per point and branch */
    int nresp;
    gd_sweep_response resp[GD_SWEEP_MAX_RESPONSES];
    int n, nclear, nmesh;    /* state size, clearances and meshes of the model */
    char state_name[GD_MAX_STATE][16]; /* y1L, ..., y1L_dot: the columns of states.csv */
    long npoincare;          /* Poincare samples per point: record_periods + 1 */
    double periodicity_tol;  /* run.periodicity_tol of the case (the hysteresis's test of two equal motions) */
    uint64_t fingerprint;    /* of every input that changes a result, and the version */
    int *slot_info;          /* 4 x nslots: chain, position in the chain, index along each axis */
} gd_sweep_plan;

/* One result. The first fields come from the plan (gd_sweep_points_create). */
typedef struct gd_sweep_point {
    int slot, chain, pos, branch, idx[2];
    double value[2];         /* the swept values (value[1] unused for one parameter) */
    /* result */
    int status;              /* gd_sweep_status */
    int error_code;          /* gd_status of a failed point */
    char error[256];
    double rms_accel_mps2[3];    /* left, right, combined */
    double dynamic_load_factor[2]; /* left, right: gd_response_result.dynamic_load_factor */
    double mle_per_period, mle_per_s; /* NaN when not computed */
    char motion[32];             /* gd_response_result.motion, or "failed" */
    int period_n, poincare_distinct;
    int impact_regime[3];        /* left, right, combined */
    long steps, rhs_evals, events;
    long transient_periods;      /* run before the window (run.transient_max_periods may extend it) */
    double wall_s;               /* not written to any output file */
    long npoincare;              /* 0 for a failed point */
    double *poincare;            /* npoincare x nresp (row-major) */
    double y_final[GD_MAX_STATE];
    gd_modes md_final;
} gd_sweep_point;


GD_API gd_status gd_sweep_plan_create(const gd_case *c, gd_sweep_plan *p, gd_error *err);
GD_API void gd_sweep_plan_free(gd_sweep_plan *p);
/* An array of plan->nslots points, all pending, with their slot, chain and values. */
GD_API gd_status gd_sweep_points_create(const gd_sweep_plan *p, gd_sweep_point **pts, gd_error *err);
GD_API void gd_sweep_points_free(const gd_sweep_plan *p, gd_sweep_point *pts);

/* The case and model of a slot: a deep copy of the base case with the swept keys set,
 * resolved again (derived values follow unless pinned), and its model. Free out with
 * gd_case_free. */
GD_API gd_status gd_sweep_point_case(const gd_case *base, const gd_sweep_plan *p, int slot, gd_case *out,
                                     gd_model *m, gd_error *err);

typedef struct gd_sweep_opts {
    int threads;             /* OpenMP threads (0: the OpenMP default) */
    int rank, nranks;        /* run the work units u with u % nranks == rank (0, 1: all) */
    gd_response_opts response;
    /* Called once per finished point (done or failed), at once, never by two threads at a
     * time; non-GD_OK stops the sweep with that error. */
    gd_status (*point_done)(void *user, const gd_sweep_plan *p, const gd_sweep_point *pt, gd_error *err);
    /* Polled about once per mesh period by every computing thread (possibly at the same
     * time); nonzero stops the sweep: points in progress are abandoned (left pending). */
    int (*should_stop)(void *user);
    void *user;
} gd_sweep_opts;

GD_API void gd_sweep_opts_default(gd_sweep_opts *o);

/* Run every pending point of this rank's work units. Points already done (resumed) are
 * skipped; a continuation chain resumes after its last done point. A point that fails
 * (solver, chattering, endless separation) is recorded as failed and its chain goes on
 * from the initial condition. Returns GD_ERR_INTERRUPTED when stopped by should_stop, the
 * error of point_done, or an error that is not a point's (out of memory). */
GD_API gd_status gd_sweep_run(const gd_case *base, const gd_sweep_plan *p, gd_sweep_point *pts,
                              const gd_sweep_opts *o, gd_error *err);

/* Points not yet done or failed. */
GD_API int gd_sweep_pending(const gd_sweep_plan *p, const gd_sweep_point *pts);

/* A hysteresis interval: consecutive values of the first parameter, in increasing order, at
 * which the up and down branches of one row differ (both points done, and the motion class
 * differs or the combined RMS acceleration by more than 5 % of the larger). */
typedef struct gd_sweep_interval {
    int row;                 /* index along parameter2 (0 for a one-parameter sweep) */
    int from, to;            /* indices into plan->values[0] of the smallest and largest value */
    int points;              /* grid points in the interval */
} gd_sweep_interval;

/* The hysteresis intervals of a continuation sweep in both directions, row by row, each row
 * in increasing parameter order: *iv (malloc'd, free it; NULL when none) and *niv. Any other
 * sweep has none. An interval is a run of grid values where the up and down points are two
 * different motions: their combined RMS accelerations differ by more than 5 % of the larger, or
 * their motion classes differ and their Poincare points do not coincide (in the settled half of
 * each window every point of one within 10 periodicity_tol of the orbit's size of a point of the
 * other: one orbit, one still converging to it, is one motion). Pending and failed points never
 * differ. */
GD_API gd_status gd_sweep_hysteresis(const gd_sweep_plan *p, const gd_sweep_point *pts, gd_sweep_interval **iv,
                                     int *niv, gd_error *err);


/* The result of the sweep row of the table of analyses (gd_analysis.h): the plan and every point. */
typedef struct gd_sweep_outcome {
    gd_sweep_plan plan;
    gd_sweep_point *pts;
    gd_modal modes;          /* the modes of the case's model at its own values (modes.failed: why none) */
} gd_sweep_outcome;

#ifdef __cplusplus
}
#endif
#endif
