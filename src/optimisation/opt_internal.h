/* Internals of the optimisers (src/optimisation/, not installed): the normalised box and the
 * counting wrapper every optimiser goes through (problem.c). */
#ifndef GD_OPT_INTERNAL_H
#define GD_OPT_INTERNAL_H

#include "geardyn/gd_optimize.h"

#include <pthread.h>

/* The wrapper of one run. Optimisers see x in [-1, 1]^dim; the wrapper maps x to the box, repairs
 * the linear constraints, evaluates, counts, records. */
typedef struct opt_ctx {
    const gd_opt_problem *p;
    int dim;
    double *centre, *half, *anchor; /* dim each */
    long budget, count;
    double best_f;
    double *best_y;                 /* dim: physical, repaired */
    long best_at;
    int keep;
    double *f_hist, *best_hist;     /* budget each when keep */
    int nstates;
    void **states;                  /* one per thread */
    double *ybuf;                   /* nstates x dim scratch */
    gd_status st;                   /* first failure of the objective */
    gd_error err;
    gd_stop_hook stop;              /* asked before each evaluation (gd_opt_settings.stop) */
} opt_ctx;

gd_status opt_ctx_init(opt_ctx *c, const gd_opt_problem *p, long budget, int nstates, int keep, gd_error *err);
void opt_ctx_free(opt_ctx *c);
/* Normalised x (clamped to [-1, 1]) -> the repaired physical point. */
void opt_to_physical(const opt_ctx *c, const double *x, double *y);
/* Evaluate the n normalised points X (n x dim) with `threads` threads, as many as the budget
 * allows (*m of them, in index order); f[i] = +inf for the rest. Records every evaluation in
 * index order, so the history does not depend on the thread count. Both evaluators ask c->stop
 * before each evaluation: stopped, GD_ERR_INTERRUPTED. */
gd_status opt_eval_batch(opt_ctx *c, const double *X, int n, double *f, int threads, int *m, gd_error *err);
/* Evaluate one normalised point on state 0 (serial callers: NLopt). Returns 1 in *done when the
 * budget was already used (nothing evaluated). */
gd_status opt_eval_one(opt_ctx *c, const double *x, double *f, int *done, gd_error *err);

/* the optimisers (alo.c, nlopt_runner.c, random_search.c): run to the budget on c */
gd_status opt_alo(opt_ctx *c, const gd_opt_settings *s, gd_opt_result *r, gd_error *err);
gd_status opt_nlopt(opt_ctx *c, const gd_opt_settings *s, gd_opt_result *r, gd_error *err);
gd_status opt_random(opt_ctx *c, const gd_opt_settings *s, gd_opt_result *r, gd_error *err);

/* The gear box [lower, upper] of the variables v on the pair (gear_objective.c): the constraint's
 * right side (the active profile), and the first corner of the box (bit i: variable i at its upper
 * bound) that fails gd_modification_check once repaired, with the failing [modification] key and
 * the repaired corner; -1 if every corner fits, -2 / -3 if the geometry or the problem is bad (err
 * set). */
int opt_gear_box(const gd_pair *pair, const gd_opt_gear_vars *v, const double *lower, const double *upper,
                 double *active_mm, const char **bad_key, double *xbad, gd_error *err);

/* threads to use for a request (0: the OpenMP default), at least 1 */
int opt_threads(int requested);

/* The failure a parallel loop over n items reports: the one at the lowest index, so that the
 * error does not depend on the threads. index = n while none failed. */
typedef struct opt_first_failure {
    pthread_mutex_t lock;
    int index;
    gd_status st;
    gd_error err;
} opt_first_failure;

void opt_first_failure_init(opt_first_failure *f, int n);
/* Item i failed with st and e (thread-safe). */
void opt_first_failure_note(opt_first_failure *f, int i, gd_status st, const gd_error *e);
void opt_first_failure_destroy(opt_first_failure *f);

/* ---- the case's [optimize] section ---- */
/* Cross-key checks and derived defaults of [optimize] (called by gd_case_resolve for the two
 * analyses): the optimizer and objective lists, dimensions, bounds, budget, targets; for the gear
 * objective, that the box fits on the case's pair (gd_pair_from_case of the resolved case). */
gd_status gd_opt_resolve_case(gd_case *c, const gd_pair *pair, gd_error *err);
/* The case's optimizers list (compare-optimizers) or its algorithm (optimize): count, <= max. */
int gd_opt_case_optimizers(const gd_case *c, int *algs, int max);
/* The case's objectives (gd_opt_objective), count <= max. */
int gd_opt_case_objectives(const gd_case *c, int *objs, int max);
/* The case's gear variables (optimize.variables, checked by gd_opt_resolve_case; the paper's six
 * if the list does not parse). */
void gd_opt_case_gear_vars(const gd_case *c, gd_opt_gear_vars *v);
/* The evaluation budget of one run: budget_evals, or population (iterations + 1). */
long gd_opt_case_budget(const gd_case *c);
/* Seed of run r (seed + r) and of the problem instance of run r (a different stream). */
unsigned long gd_opt_run_seed(const gd_case *c, int r);
unsigned long gd_opt_instance_seed(const gd_case *c, int r);

#endif
