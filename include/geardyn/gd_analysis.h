/* The table of analyses: every value of [scene] analysis is one row, which checks the analysis's
 * own keys, runs it, writes its standard files and frees its result. A case is resolved in three
 * steps, always in this order: the cross-key checks that need no physics (gd_case_check), the
 * scene (gd_scene_resolve: geometry and what follows from it) and the row's own checks.
 *
 * Running an analysis from C, in a directory of one's own (gd_analysis_run_in does all of it):
 *
 *     const gd_analysis_type *a = gd_analysis_find(c.analysis);   (c resolved)
 *     gd_run_dir *out;  void *res;  gd_run_env env = {0};
 *     gd_run_dir_open("results/x", &out, &err);
 *     a->run(&c, &env, out, &res, &err);      streaming files (time_history.csv ...) as it runs
 *     a->write(&c, res, out, &err);           the tables (CSV)
 *     a->pictures(&c, res, out, &env);        through env.draw, if any (gd_output.h: gd_draw_fn)
 *     ... pictures of one's own: gd_run_dir_add(out, "picture.png", &err)
 *     a->summary(&c, res, out, &err);         summary.json, listing every file of out
 *     gd_run_dir_publish(out, &err);          the set moved from the stage into results/x
 *     ... read the result (gd_response_outcome, gd_tca_result, ...: below)
 *     a->free(res);  gd_run_dir_close(out);
 *
 * The command line runs every analysis through gd_analysis_run_in (src/cli/cmd_run_dispatch.c);
 * docs/architecture.md says how to add a row. */
#ifndef GD_ANALYSIS_H
#define GD_ANALYSIS_H

#include "geardyn/gd_case.h"
#include "geardyn/gd_output.h"
#include "geardyn/gd_response.h"
#include "geardyn/gd_sweep.h"
#include "geardyn/gd_workprec.h"
#include "geardyn/gd_ltca.h"
#include "geardyn/gd_optimize.h"
#include "geardyn/gd_continuation.h"
#include "geardyn/gd_scene.h"
#include "geardyn/gd_basins.h"

#ifdef __cplusplus
extern "C" {
#endif

struct gd_compare_entry;

/* What the caller of a run provides: threads, and the hooks through which progress is shown
 * and a run is stopped (every hook may be NULL; user is passed to each). */
typedef struct gd_run_env {
    void *user;
    int threads;             /* 0: the OpenMP default */
    /* response: mesh periods integrated of total; nonzero stops the run (GD_ERR_INTERRUPTED) */
    int (*progress)(void *user, long done, long total);
    /* work-precision: before and after each integration (gd_workprec.h) */
    gd_wp_hooks workprec;
    /* optimize: after each of the runs runs (from its own seed) */
    void (*optimize_run)(void *user, int run, int runs, unsigned long seed, const gd_opt_result *r);
    /* continuation: after each branch followed (of those planned so far); nonzero stops the run */
    int (*continuation_branch)(void *user, int branches_done, int branches_planned);
    /* compare-optimizers: after each problem compared (struct gd_compare_entry below) */
    void (*compare_problem)(void *user, const struct gd_compare_entry *q, const gd_opt_compare_settings *s);
    /* sweep: this process's share of the work units (rank of nranks; 0 of 0 or 1: all), and the
     * callbacks of gd_sweep_opts (gd_sweep.h: point_done, should_stop). sweep_start is called
     * once the points exist, before any is run (a resume fills those already done); sweep_end
     * after this process's share with its status. A status other than GD_OK from either ends
     * the run with that status. */
    int rank, nranks;
    gd_status (*sweep_start)(void *user, const gd_sweep_plan *p, gd_sweep_point *pts, gd_run_dir *out,
                             gd_error *err);
    gd_status (*sweep_point)(void *user, const gd_sweep_plan *p, const gd_sweep_point *pt, gd_error *err);
    /* every run: asked before the set is published; nonzero ends the run with
     * GD_ERR_INTERRUPTED and nothing published (the command line's signals) */
    int (*should_stop)(void *user);
    gd_status (*sweep_end)(void *user, const gd_sweep_plan *p, const gd_sweep_point *pts, gd_status st,
                           gd_error *err);
    /* the pictures of an analysis an analysis runs inside its own directory (optimize: the
     * optimum's LTCA and TCA in optimum/ and optimum-tca/), drawn between its write and summary
     * and added to sub with gd_run_dir_add */
    void (*pictures)(void *user, const gd_case *c, const void *result, gd_run_dir *sub);
    /* gd_analysis_run_in: after run (its status), and after summary.json with the result */
    void (*ran)(void *user, const gd_case *c, gd_status st);
    void (*done)(void *user, const gd_case *c, const void *result, gd_run_dir *out);
    /* basins: initial states mapped of those planned on this process; nonzero stops the run */
    int (*basins_progress)(void *user, long done, long total);
    /* basins over a parameter on several processes (rank of nranks above): after this process's values,
     * with its status. Rank 0 reads the other ranks' points into res (gd_basins_record_parse) and returns
     * GD_OK to go on to the matching and the files; another rank sends its points and returns any other
     * status (its run ends without files). */
    gd_status (*basins_end)(void *user, gd_basins_result *res, gd_status st, gd_error *err);
    /* every run with output.plots on, into a directory: the drawer that turns the analysis's gnuplot
     * script into its pictures (gd_output.h: gd_draw_fn; NULL: no pictures, and a note says so) */
    gd_draw_fn draw;
    /* the run's notes (gd_output.h: gd_note_fn): no pictures and why, pictures not drawn and why */
    gd_note_fn note;
    /* optimize: after every evaluation recorded, those done of all its runs' budgets (a stop goes
     * through the run's stop hook) */
    void (*optimize_progress)(void *user, long done, long total);
} gd_run_env;

typedef struct gd_analysis_type {
    int id;                  /* gd_analysis, the value of scene.analysis */
    const char *name;        /* as the case file writes it */
    const char *what;        /* one line */
    /* The checks and derived defaults of the analysis's own keys, after the scene is resolved;
     * NULL when it has none. Messages name the case file line. */
    gd_status (*check_case)(gd_case *c, gd_error *err);
    /* Compute the analysis of a resolved case into *result (free it with free); the files that
     * stream while it runs (time_history.csv, events.csv, poincare.csv) are committed to out. */
    gd_status (*run)(const gd_case *c, const gd_run_env *env, gd_run_dir *out, void **result, gd_error *err);
    /* The tables of the result (CSV) into out. */
    gd_status (*write)(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err);
    /* summary.json: the case, the results and every file out holds, itself last. */
    gd_status (*summary)(const gd_case *c, const void *result, gd_run_dir *out, gd_error *err);
    void (*free)(void *result);
    /* The pictures of the result (when c->plots), drawn by env->draw into out's stage between write
     * and summary and added to out's files; never fails the run: what is not drawn is a note
     * (env->note). NULL: an analysis without pictures. */
    void (*pictures)(const gd_case *c, const void *result, gd_run_dir *out, const gd_run_env *env);
} gd_analysis_type;

/* The results of the rows (what run gives as *result): response: gd_response_outcome
 * (gd_response.h); sweep: gd_sweep_outcome (gd_sweep.h); tca: gd_tca_result (gd_tca.h); ltca:
 * gd_ltca_result (gd_ltca.h); optimize: gd_optimize_outcome, compare-optimizers:
 * gd_compare_outcome (gd_optimize.h); work-precision: gd_workprec_outcome (gd_workprec.h); basins:
 * gd_basins_result (gd_basins.h). */

/* All rows, in the order of the gd_analysis values. */
GD_API const gd_analysis_type *gd_analysis_types(size_t *n);
/* The row of an analysis, or NULL when this build has none. */
GD_API const gd_analysis_type *gd_analysis_find(int id);

/* The whole of an analysis in the directory dir: run, write, the pictures (the row's pictures through
 * env->draw, then env->pictures), summary,
 * then env->done with the result, which is freed; env->ran after run. This is `geardyn run`
 * without its printing. */
GD_API gd_status gd_analysis_run_in(const gd_analysis_type *a, const gd_case *c, const gd_run_env *env,
                                    const char *dir, gd_error *err);
/* The same in a run directory the caller opened (and closes): one kept in memory
 * (gd_run_dir_open_memory) or keeping its files (gd_run_dir_keep), whose bytes the caller then
 * reads with gd_run_dir_data. */
GD_API gd_status gd_analysis_run_dir(const gd_analysis_type *a, const gd_case *c, const gd_run_env *env,
                                     gd_run_dir *out, gd_error *err);

/* Fill the derived values (unless pinned) and check consistency and ranges across keys: the
 * case's own checks, the scene, the analysis's. Call once after load and sets. */
GD_API gd_status gd_case_resolve(gd_case *c, gd_error *err);

/* Every check geardyn run makes before any work, in its order, so that a program gets the same
 * refusal with the same message: c resolved without LTCA (gd_case.ltca_deferred), its model built,
 * the run's cost on `threads` threads (0: gd_threads_default) estimated into *cost (may be NULL)
 * and checked (gd_run_cost_check); then, unless
 * check_only, c itself resolved and its model built (which computes the case's LTCA when it asks
 * for it). check_only: c becomes the case resolved without LTCA, as geardyn check shows it. On a
 * refusal c may be partly resolved: free it. */
GD_API gd_status gd_case_prepare(gd_case *c, int check_only, int threads, gd_run_cost *cost,
                                 gd_error *err);
/* What geardyn check shows of c (loaded, not resolved), as JSON text in *json (gd_free it):
 * {"analysis", "case": {"path", "parameters"}, "derived": {"geometry", "model", "modal",
 * "mesh_stiffness_estimated"}, "cost": {...}}; the refusals of gd_case_prepare. */
GD_API gd_status gd_case_check_json(const gd_case *c, char **json, gd_error *err);

/* The threads of a run whose gd_run_env.threads is 0: OpenMP's default for a new thread
 * (OMP_NUM_THREADS, else the processors), 1 without OpenMP. */
GD_API int gd_threads_default(void);
/* The OpenMP version libgeardyn was built with (_OPENMP, yyyymm), 0 without OpenMP. */
GD_API int gd_openmp_version(void);

#ifdef __cplusplus
}
#endif
#endif
