/* Internal: the writers of the standard files, called by the rows of the table of analyses
 * (src/run/); a C user writes them through a row's write and summary (gd_analysis.h). */
#ifndef GD_OUTPUT_INTERNAL_H
#define GD_OUTPUT_INTERNAL_H

#include <stdio.h>

#include "geardyn/gd_output.h"
#include "geardyn/gd_response.h"
#include "geardyn/gd_sweep.h"
#include "geardyn/gd_workprec.h"
#include "geardyn/gd_tca.h"
#include "geardyn/gd_ltca.h"
#include "geardyn/gd_optimize.h"
#include "geardyn/gd_optpost.h"
#include "geardyn/gd_continuation.h"
#include "geardyn/gd_scene.h"
#include "geardyn/gd_basins.h"

/* A file written under a temporary name and renamed into place on commit (gd_run_dir keeps one
 * per open file). */
typedef struct gd_atomic_file {
    FILE *fp;
    char path[1200];
    char tmp[1240];
} gd_atomic_file;

gd_status gd_atomic_open(gd_atomic_file *f, const char *dir, const char *name, gd_error *err);
gd_status gd_atomic_commit(gd_atomic_file *f, gd_error *err);
void gd_atomic_abort(gd_atomic_file *f);
/* mkdir -p */
gd_status gd_mkdir_p(const char *dir, gd_error *err);
/* The comma-separated fields of line (the project's own CSV: no quoting) into f, at most max; their
 * number. The line is cut in place, its end of line dropped. */
int gd_csv_split(char *line, char **f, int max);
/* The index of the field name among f[0..nf), -1 when absent. */
int gd_csv_column(char *const *f, int nf, const char *name);

/* geardyn check's values as JSON text (malloc'd): the case c (resolved as check resolves it), the
 * derived values of its model m, its modes and the run's cost (check_json.c). */
gd_status gd_check_json_text(const gd_case *c, const gd_model *m, const gd_run_cost *cost, char **text,
                             gd_error *err);

/* The event log: one CSV row per event (header with units). */
void gd_eventlog_header(FILE *fp);
void gd_eventlog_row(FILE *fp, const gd_model *m, const gd_event *ev, int recording);

/* ---- response ---- */
/* time_history.csv and poincare.csv, written row by row while the response runs. */
void gd_time_history_header(FILE *fp, const gd_model *m);
void gd_time_history_row(FILE *fp, const gd_model *m, const gd_sample *s);
void gd_poincare_header(FILE *fp, const gd_model *m);
void gd_poincare_row(FILE *fp, const gd_model *m, long period, double t_s, const double *y);
/* variable.csv, variable_poincare.csv and spectrum.csv of the local analysis. */
gd_status gd_local_write_tables(gd_run_dir *d, const gd_local *L, double mesh_freq_hz, gd_error *err);
/* summary.json of a response run: the resolved case (value, unit, source of every key), the
 * derived geometry and model scales, the modes of the model (derived.modal, gd_scene_modes), solver
 * statistics and the results. Each summary writer lists the files of d and itself. */
gd_status gd_summary_write_response(gd_run_dir *d, const gd_case *c, const gd_model *m, const gd_modal *modes,
                                    const gd_response_result *r, gd_error *err);

/* ---- tca ---- */
/* gte.csv, contact_path.csv (rb: the base radii, m) and separation_left/right.csv. */
gd_status gd_tca_write_tables(gd_run_dir *d, const gd_case *c, const gd_tca_result *r, const double rb[2],
                              gd_error *err);
/* stable keys: results.gte_pp_arcsec.left/right, results.edge_contact.left/right,
 * results.contact_ratio_transverse, results.contact_ratio_overlap,
 * results.operating_pressure_angle_deg */
gd_status gd_summary_write_tca(gd_run_dir *d, const gd_case *c, const gd_tca_result *r, gd_error *err);

/* ---- ltca ---- */
/* lte.csv, load_distribution.csv, pair_loads.csv. */
gd_status gd_ltca_write_tables(gd_run_dir *d, const gd_ltca_result *r, gd_error *err);
/* stable keys: results.lte_pp_arcsec, results.mean_mesh_stiffness_n_per_m.left/right,
 * results.load_share.left/right */
gd_status gd_summary_write_ltca(gd_run_dir *d, const gd_case *c, const gd_ltca_result *r, gd_error *err);

/* ---- optimize and compare-optimizers ---- */
/* optimum.csv, convergence.csv and (the gear) lte.csv of an optimize run. */
gd_status gd_optimize_write_optimum(gd_run_dir *d, const gd_optimize_outcome *o, gd_error *err);
gd_status gd_optimize_write_convergence(gd_run_dir *d, const gd_optimize_outcome *o, gd_error *err);
gd_status gd_optimize_write_lte(gd_run_dir *d, const gd_optimize_outcome *o, gd_error *err);
/* After an optimisation over load and speed (gd_optpost.h, optpost_output.c): response_over_speed.csv
 * (gear-dynamic) and lte_over_torque.csv; results.objective_on_bta, results.response_over_speed
 * (gear-dynamic) and results.lte_over_torque added to res. */
gd_status gd_optpost_write_tables(gd_run_dir *d, const gd_case *c, const gd_optpost *p, gd_error *err);
struct json_t;
void gd_optpost_summary(struct json_t *res, const gd_case *c, const gd_optpost *p);
/* robust.csv: the robust variant's sample and each flank's objective at every sample (robust_tables.c). */
gd_status gd_optimize_write_robust(gd_run_dir *d, const gd_case *c, const gd_optimize_outcome *o, gd_error *err);
/* Two objectives (pareto_tables.c): pareto.csv, evaluations.csv, and summary.json. */
gd_status gd_pareto_write(gd_run_dir *d, const gd_optimize_outcome *o, gd_error *err);
gd_status gd_summary_write_pareto(gd_run_dir *d, const gd_case *c, const gd_optimize_outcome *o, gd_error *err);
/* runs.csv, statistics.csv, convergence.csv, ecdf.csv and best_points.csv of a comparison. */
gd_status gd_compare_write_tables(gd_run_dir *d, const gd_compare_outcome *C, gd_error *err);
gd_status gd_summary_write_optimize(gd_run_dir *d, const gd_case *c, const gd_opt_optimize_summary *s,
                                    gd_error *err);
/* One summary over every problem compared (each with the same optimisers, runs and budget); adds
 * the runtime distribution pooled over the problems at 1 %, 10 % and 100 % of the budget. */
gd_status gd_summary_write_compare(gd_run_dir *d, const gd_case *c, const gd_opt_compare_problem *pb, int nproblems,
                                   int threads, gd_error *err);

/* ---- work-precision ---- */
/* work_precision.csv, and order_study.csv and orders.csv when there is an order study. */
gd_status gd_workprec_write_tables(gd_run_dir *d, const gd_wp_result *res, gd_error *err);
gd_status gd_summary_write_workprec(gd_run_dir *d, const gd_case *c, const gd_model *m, const gd_wp_result *res,
                                    gd_error *err);

/* ---- sweep ---- */
/* sweep.csv and bifurcation.csv from the points in slot order. */
gd_status gd_sweep_write_tables(gd_run_dir *d, const gd_sweep_plan *p, const gd_sweep_point *pts, gd_error *err);
/* states.csv: every point's final state (at mesh phase 0), its period and status, in slot order. */
gd_status gd_sweep_write_states(gd_run_dir *d, const gd_sweep_plan *p, const gd_sweep_point *pts, gd_error *err);
/* the settings, failed points, motion tallies, branches and the hysteresis intervals
 * (gd_sweep_hysteresis); derived.modal: the modes of the case's model at its own values */
gd_status gd_sweep_write_summary(gd_run_dir *d, const gd_case *c, const gd_modal *modes, const gd_sweep_plan *p,
                                 const gd_sweep_point *pts, gd_error *err);

/* ---- continuation ---- */
/* branch.csv (every branch point) and bifurcations.csv (every located bifurcation). */
gd_status gd_contin_write_tables(gd_run_dir *d, const gd_contin_result *res, gd_error *err);
/* continuation.start = sweep: the point of the finished sweep continuation.start_sweep in the direction
 * start_sweep_direction nearest the start value (inside [from, to], done), after checking that the
 * directory holds a finished one-parameter sweep in the continued key, of this case's model (every
 * key of the model equal but the continued one and derived values), listing states.csv. Refusals
 * are GD_ERR_INPUT naming the key. */
gd_status gd_contin_sweep_start(const gd_case *c, gd_contin_start *s, gd_error *err);
/* The resolved case of an earlier run (summary.json's case.parameters, in dir) against c, key by key
 * over the model's keys but the continued one: GD_ERR_INPUT naming continuation.KEY and the first
 * key that differs ("the WHAT in DIR is of another model"). */
struct json_t;
gd_status gd_contin_same_model(const gd_case *c, struct json_t *their_case, const char *dir, const char *key,
                               const char *what, gd_error *err);
/* The same, skipping skip2 too (continuation.overlay_map: a regime map in both keys). */
gd_status gd_contin_same_model_but(const gd_case *c, struct json_t *their_case, const char *dir, const char *key,
                                   const char *what, const char *skip2, gd_error *err);
/* The model's keys (but the continued one and skip2) whose value in an earlier run's case differs
 * from c's: their number, the first max of them into d (values as text: numbers as %.10g). */
typedef struct gd_model_diff {
    char key[128], mine[256], theirs[256];
} gd_model_diff;
int gd_contin_model_diff(const gd_case *c, struct json_t *their_case, const char *skip2, gd_model_diff *d, int max);

/* The curves' picture's overlays (continuation.overlay_map, overlay_curves; docs/continuation.md
 * section 8), checked before any work: overlay_map a finished sweep with parameter2 (a regime map) in
 * continuation.parameter and parameter2, of this case's model but those two keys, its sweep.csv
 * readable; overlay_curves an earlier continuation's output in the same two keys with its
 * curves.csv (any model: the case before a modification). Refusals are GD_ERR_INPUT naming the file,
 * line and key. */
gd_status gd_contin_overlays_check(const gd_case *c, gd_error *err);
/* A regime map's points read back (sweep.csv of continuation.overlay_map). */
typedef struct gd_map_point {
    double x, y;       /* the two keys' values */
    int dir;           /* 0 up, 1 down, 2 independent */
    int regime;        /* 0 no-impact (in contact), 1 single-sided, 2 double-sided; -1 not done */
    int period;        /* the motion's period in mesh periods (period-n), 0 not periodic */
    char motion[32];   /* sweep.csv's motion */
} gd_map_point;
typedef struct gd_overlay_map {
    gd_map_point *pt;
    int n;
} gd_overlay_map;
gd_status gd_contin_overlay_map_read(const gd_case *c, gd_overlay_map *m, gd_error *err);
/* An earlier run's curves read back (curves.csv of continuation.overlay_curves): point i of curve
 * curve[i] of kind kind[i] (gd_curve_kind) at (x[i], y[i]); the model keys where that run differs
 * from this case (ndiff of them, the first 3 in diff). */
typedef struct gd_overlay_curves {
    double *x, *y;
    int *curve, *kind;
    int n, ndiff;
    gd_model_diff diff[3];
} gd_overlay_curves;
gd_status gd_contin_overlay_curves_read(const gd_case *c, gd_overlay_curves *o, gd_error *err);
void gd_contin_overlay_free(gd_overlay_map *m, gd_overlay_curves *o);
/* The regions of the curves' plane named from the run, without a regime map (curve_regions.c;
 * docs/continuation.md section 8): the intervals of the branches' line parameter2 = value2 between
 * consecutive bifurcations of any branch, each named by the stable orbits of the branches over it
 * ("in contact or single-sided", "single-sided (period 2)"); an interval where a branch's points
 * disagree in stability or impact regime, or with no stable orbit, is not among them. x, y: where
 * the label's centre goes (the picture places it, on the line: y = value2; drawn 0 when it found no
 * room), from, to: the interval (keys' units); orbits: "period:regime:count;..."; evidence: the
 * branch points that tell. */
#define GD_REGIONS_MAX 48
typedef struct gd_curve_region {
    char label[256], orbits[256];
    double x, y, from, to;
    int drawn;
    char evidence[1024];
} gd_curve_region;
typedef struct gd_curve_regions {
    int n;
    gd_curve_region r[GD_REGIONS_MAX];
} gd_curve_regions;
/* from, to: the range of the parameter (continuation.from, to) */
void gd_contin_regions_name(const gd_contin_result *res, double from, double to, double value2, gd_curve_regions *rg);
/* regions.csv: one row per named region (docs/continuation.md section 8) */
gd_status gd_contin_write_regions(gd_run_dir *d, const gd_contin_result *res, const gd_curve_regions *rg,
                                  gd_error *err);
/* continuation.curve_start: row curve_start_row of an earlier continuation's bifurcations.csv, checked
 * to be a fold, period doubling or grazing (a contact change of a clearance), located, in [from, to],
 * of this case's model and state (its summary.json beside it: a continuation in the same key, every
 * model key equal but the continued one). Refusals are GD_ERR_INPUT naming the file, line and key. */
gd_status gd_contin_curve_row_read(const gd_case *c, gd_contin_curve_row *row, gd_error *err);
/* derived.modal: the modes of the case's model at its own values */
gd_status gd_contin_write_summary(gd_run_dir *d, const gd_case *c, const gd_modal *modes, const gd_contin_result *res,
                                  gd_error *err);

/* ---- basins ---- */
/* basins.csv (the picture), attractors.csv, fractions.csv (with a sample), attractor_points.csv and
 * continuation_orbits.csv (with basins.continuation). */
gd_status gd_basins_write_tables(gd_run_dir *d, const gd_case *c, const gd_basins_result *res, gd_error *err);
/* derived.modal: the modes of the case's model at its own values */
gd_status gd_summary_write_basins(gd_run_dir *d, const gd_case *c, const gd_modal *modes, const gd_basins_result *res,
                                  gd_error *err);
/* basins.continuation: the points of a finished continuation of this case's model (in basins.parameter when
 * there is one). Refusals are GD_ERR_INPUT naming the key. */
gd_status gd_basins_read_continuation(const gd_case *c, gd_basins_known *k, gd_error *err);

#endif
