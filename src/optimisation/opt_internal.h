/* Internals of the optimisers (src/optimisation/, not installed): the normalised box and the
 * counting wrapper every optimiser goes through (problem.c). */
#ifndef GD_OPT_INTERNAL_H
#define GD_OPT_INTERNAL_H

#include "geardyn/gd_optimize.h"

#include <gsl/gsl_rng.h>
#include <pthread.h>

/* The non-dominated points of a run with two objectives, sorted by f1 increasing (f2 decreasing;
 * pareto.c). */
typedef struct opt_front {
    int n, cap, dim;
    double ref[2];                  /* the hypervolume's reference point */
    double hv;                      /* the area the points dominate within ref, updated by every insertion */
    double *y;                      /* n x dim (dim 0: no points kept, only their values) */
    double *f;                      /* n x 2 */
} opt_front;

void opt_front_free(opt_front *F);
/* Insert (y, f) unless a point of F dominates or equals it; the points it dominates go. 1: inserted, 0:
 * dominated, -1: out of memory. */
int opt_front_insert(opt_front *F, const double *y, const double f[2]);
/* The area F dominates within F->ref, summed afresh (F->hv is the running sum). */
double opt_front_hv(const opt_front *F);

/* How the wrapper turns two objectives into the one value a single-objective optimiser sees
 * (scalarise.c): none, a weighted sum, an epsilon-constraint. */
enum { OPT_SC_NONE = 0, OPT_SC_WEIGHTED = 1, OPT_SC_EPS = 2 };

/* The wrapper of one run. Optimisers see x in [-1, 1]^dim; the wrapper maps x to the box, repairs
 * the linear constraints, evaluates, counts, records. */
typedef struct opt_ctx {
    const gd_opt_problem *p;
    int dim;
    double *centre, *half, *anchor; /* dim each */
    double *yrec;                   /* dim: the physical point of the evaluation being recorded */
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
    /* evalv problems */
    int nobj, naux, nf;             /* nf = nobj + naux values per evaluation (1 for eval) */
    double *fbuf;                   /* nstates x nf scratch */
    double *fv_hist;                /* budget x nf when keep */
    /* two objectives: the front of every evaluation, its hypervolume after each */
    opt_front front;
    double hv_ref[2];
    double *hv_hist;                /* budget when keep */
    /* the scalarisation of two objectives the optimiser sees (scalarise.c) */
    int sc_kind;
    double sc_w, sc_eps;
    void (*progress)(void *user, long evaluations, long budget);
    void *progress_user;
} opt_ctx;

gd_status opt_ctx_init(opt_ctx *c, const gd_opt_problem *p, long budget, int nstates, int keep, gd_error *err);
/* The objectives' count of a problem (1 for eval) and the values of an evaluation (nobj + naux). */
int opt_problem_nobj(const gd_opt_problem *p);
int opt_problem_nf(const gd_opt_problem *p);
void opt_ctx_free(opt_ctx *c);
/* Normalised x (clamped to [-1, 1]) -> the repaired physical point. */
void opt_to_physical(const opt_ctx *c, const double *x, double *y);
/* Evaluate the n normalised points X (n x dim) with `threads` threads, as many as the budget
 * allows (*m of them, in index order); f[i] = +inf for the rest. Records every evaluation in
 * index order, so the history does not depend on the thread count. Both evaluators ask c->stop
 * before each evaluation: stopped, GD_ERR_INTERRUPTED. f[i] is the value the optimiser sees (the
 * objective, or its scalarisation); fv (NULL: not wanted) gets every evaluation's nf values. */
gd_status opt_eval_batch(opt_ctx *c, const double *X, int n, double *f, double *fv, int threads, int *m,
                         gd_error *err);
/* The value a single-objective optimiser sees of the nf values fv: the objective, or with two the
 * scalarisation of c->sc_kind on the objectives divided by the reference point (an infeasible point
 * of an epsilon-constraint is OPT_EPS_INFEASIBLE plus its excess: after every feasible one). */
#define OPT_EPS_INFEASIBLE 1e6
double opt_scalar(const opt_ctx *c, const double *fv);
/* Evaluate one normalised point on state 0 (serial callers: NLopt). Returns 1 in *done when the
 * budget was already used (nothing evaluated). */
gd_status opt_eval_one(opt_ctx *c, const double *x, double *f, int *done, gd_error *err);

/* the optimisers (alo.c, nlopt_runner.c, random_search.c): run to the budget on c */
gd_status opt_alo(opt_ctx *c, const gd_opt_settings *s, gd_opt_result *r, gd_error *err);
gd_status opt_nlopt(opt_ctx *c, const gd_opt_settings *s, gd_opt_result *r, gd_error *err);
gd_status opt_random(opt_ctx *c, const gd_opt_settings *s, gd_opt_result *r, gd_error *err);
gd_status opt_moalo(opt_ctx *c, const gd_opt_settings *s, gd_opt_result *r, gd_error *err);
/* weighted-sum and eps-constraint: the subproblems one after the other, each an NLopt run of
 * s->scalar_algorithm on its share of the budget (scalarise.c) */
gd_status opt_scalarised(opt_ctx *c, const gd_opt_settings *s, gd_opt_result *r, gd_error *err);

/* ALO's random walks (alo.c), shared with MOALO: eight steps of a walk from one byte. */
typedef struct walk_byte {
    signed char sum, lo, hi;
} walk_byte;
void opt_walk_table(walk_byte tab[256]);
/* A walk of T fair +-1 steps drawn from rng, min-max normalised into [c, d]: its value at step t. */
double opt_walk(gsl_rng *rng, const walk_byte *tab, int T, int t, double c, double d);

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

/* gd_opt_gear_value_of_pair, and with the robust variant each objective's value at every sample of
 * its Monte Carlo sample (samples: nobj x gd_opt_gear_robust_sample, in the sample's order). */
gd_status opt_gear_value_of_pair_samples(const gd_opt_gear *g, const gd_pair *pair, double *f, double *aux,
                                         double *samples, gd_error *err);

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
/* The robust variant of the case's gear objectives (optimize.robust and robust_*; samples 0 when off;
 * robust_case.c), and its checks beyond the keys' ranges (called by gd_opt_resolve_case). */
void gd_opt_case_robust(const gd_case *c, gd_opt_robust *rb);
gd_status gd_opt_resolve_robust(const gd_case *c, int compare, int gear, gd_error *err);
/* Two objectives at once (pareto_case.c): the objectives of an optimize run (2 with optimize.objective2 or
 * zdt1, zdt2; else 1), and the checks of objective2, the optimiser, the reference point. */
int gd_opt_case_nobj(const gd_case *c);
gd_status gd_opt_resolve_two(gd_case *c, int compare, gd_error *err);

#endif
