/* The `continuation` analysis (docs/continuation.md): the periodic orbits of a case followed in one
 * numeric case key by pseudo-arclength continuation (gd_periodic.h), from the attractor after the
 * case's transient, from a given state or from a finished sweep's point, in one or both
 * directions, with branch switching at the period doublings of every branch; every branch point with its Floquet multipliers and what one period of the
 * orbit integrated with samples gives (RMS mesh acceleration, extremes of the mesh deflections).
 *
 * gd_contin_run computes (case -> result), gd_contin_result_free frees; the row `continuation` of
 * the table of analyses (gd_analysis.h) writes branch.csv, bifurcations.csv and summary.json (with
 * continuation.parameter2 also curves.csv, codim2.csv and regions.csv). */
#ifndef GD_CONTINUATION_H
#define GD_CONTINUATION_H

#include "geardyn/gd_case.h"
#include "geardyn/gd_periodic.h"
#include "geardyn/gd_envelope.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What one period of a branch point's orbit gives (integrated with output.samples_per_period
 * samples per mesh period). */
typedef struct gd_contin_measure {
    double rms_accel_mps2[3];    /* left, right, combined, as a sweep's rms_accel_mps2 */
    double lambda_min_um[2], lambda_max_um[2]; /* mesh deflections of the left and right half */
    double lambda_poincare;      /* lambda_L at mesh phase 0 (dimensionless, as a sweep's bifurcation.csv) */
    double dynamic_load_factor[2]; /* left, right: the largest mesh force on the orbit over the static one */
    int impact_regime;           /* the meshes' worst gd_impact_regime on the orbit (a sweep's impact_regime) */
} gd_contin_measure;

typedef struct gd_contin_branch {
    int nper;                    /* mesh periods of its orbits */
    int direction;               /* +1: set out towards increasing parameter, -1 decreasing */
    int parent;                  /* the branch whose period doubling it was switched from, -1 for a start branch */
    double born_p;               /* p of that period doubling (NAN for a start branch) */
    int joins;                   /* br.end GD_END_DOUBLING: the branch (of half the period) whose period doubling it
                                  * ends at, -1 when none or no branch followed has it */
    double joins_p;              /* p of that doubling (NAN when none) */
    gd_branch br;                /* points, bifurcations, end (gd_periodic.h); p = value / scale */
    char end_reason[GD_ERROR_MSG_MAX + 256]; /* how it ended, the parameter in the key's unit (and p) */
    gd_contin_measure *meas;     /* one per point */
    gd_contin_measure *bif_meas; /* one per bifurcation */
} gd_contin_branch;

/* A curve of fold, period-doubling or grazing points continued in (parameter, parameter2) from a
 * bifurcation of a branch (docs/continuation.md section 8). */
typedef struct gd_contin_curve {
    int branch, bif;             /* the branch and its bifurcation the curve starts from (-1: curve_start's row) */
    int direction;               /* +1: set out towards increasing parameter2, -1 decreasing */
    gd_curve cv;                 /* its points: orbit.p = value / scale, p2 = value2 / scale2 */
} gd_contin_curve;

typedef struct gd_contin_result {
    char parameter[256];         /* "section.key" */
    char unit[32];               /* of the key ("" when dimensionless) */
    double scale;                /* key value per unit of the continuation parameter p */
    int n, nclear, nmesh;        /* state size, clearances and meshes of the model */
    char clear_name[GD_MAX_CLEAR][24];
    char state_name[GD_MAX_STATE][16]; /* y1L, ..., y1L_dot: the degrees of freedom, then their rates */
    int nper_start;              /* the starting orbit's period */
    int period_found;            /* 1: nper_start found from the Poincare section after the transient */
    double start_value;          /* the parameter at the start, in the key's unit */
    char start_source[GD_PATH_MAX + 96]; /* start = sweep: which point of which sweep ("" otherwise) */
    int nbranches, branch_cap;   /* branches (at most continuation.max_branches) and the array's size */
    gd_contin_branch *branch;    /* the start's branches (down before up), then those switched to, in order */
#define GD_CONTIN_NOTES 32
    char notes[GD_CONTIN_NOTES][GD_ERROR_MSG_MAX]; /* branch switchings that found no doubled orbit or were beyond
                                                    * max_branches; what a location found that is no bifurcation */
    int nnotes;
    int notes_dropped;           /* notes beyond GD_CONTIN_NOTES */
    long corrections, newton_iterations;
    double cpu_s;
    /* continuation.parameter2: the curves (none when it is "") */
    char parameter2[256], unit2[32];
    char curve_start[GD_PATH_MAX + 96]; /* the one curve's start (continuation.curve_start), "" for all */
    double scale2;               /* key value per unit of p2 */
    int ncurves;
    gd_contin_curve *curve;      /* from each fold, period doubling and grazing, down then up in parameter2 */
    long curve_corrections;
    double curve_cpu_s;
} gd_contin_result;

/* Check the [continuation] keys of a resolved case (gd_case_resolve calls it through the table
 * of analyses); messages name the file, line, key and valid range. */
GD_API gd_status gd_contin_check_case(gd_case *c, gd_error *err);

/* Progress: after each branch, the branches done of those planned so far; nonzero stops the run
 * (GD_ERR_INTERRUPTED). */
typedef int (*gd_contin_progress_fn)(void *user, int branches_done, int branches_planned);

/* A starting orbit given by the caller: its state at mesh phase 0 near the parameter value. */
typedef struct gd_contin_start {
    double value;                /* the parameter, in the key's unit, inside [from, to] */
    int nper;                    /* mesh periods of the orbit (0: continuation.period, or 1) */
    int n;                       /* the state's size: the model's */
    double y[GD_MAX_STATE];      /* the dimensionless state at mesh phase 0 */
    char source[GD_PATH_MAX + 96]; /* what it is, for summary.json ("sweep DIR, up, speed_rpm = 3000") */
} gd_contin_start;

/* The start of one curve in two parameters (continuation.curve_start): a fold, period doubling or
 * grazing of an earlier run's bifurcations.csv, of this case. */
typedef struct gd_contin_curve_row {
    int kind;                    /* gd_curve_kind */
    int nper;                    /* mesh periods of the orbit */
    int clearance;               /* a grazing's clearance (index into the model's), else -1 */
    double value;                /* the parameter, in the key's unit */
    int n;                       /* the state's size: the model's */
    double y[GD_MAX_STATE];      /* the orbit's state at mesh phase 0 */
    char source[GD_PATH_MAX + 96]; /* what it is, for summary.json ("FILE row 2: fold at speed_rpm = ...") */
} gd_contin_curve_row;

/* Run the continuation of a resolved case into *res (free with gd_contin_result_free). start:
 * NULL for start = attractor or state; required for start = sweep (the row `continuation` reads
 * it from the sweep's states.csv), and used instead of the case's start when given. stop (may be
 * NULL): asked before each point of every branch; a stop ends the run with GD_ERR_INTERRUPTED and
 * no result. */
GD_API gd_status gd_contin_run(const gd_case *c, const gd_contin_start *start, gd_contin_progress_fn progress,
                               void *user, const gd_stop_hook *stop, gd_contin_result *res, gd_error *err);
/* The same, with continuation.parameter2 following only the curve of row (NULL: every bifurcation's). */
GD_API gd_status gd_contin_run_curve(const gd_case *c, const gd_contin_start *start, const gd_contin_curve_row *row,
                                     gd_contin_progress_fn progress, void *user, const gd_stop_hook *stop,
                                     gd_contin_result *res, gd_error *err);
GD_API void gd_contin_result_free(gd_contin_result *res);

/* The parameter of a branch point or bifurcation in the key's unit. */
GD_API double gd_contin_value(const gd_contin_result *res, double p);

#ifdef __cplusplus
}
#endif
#endif
