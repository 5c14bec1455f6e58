/* Optimisation (`analysis = optimize`, `analysis = compare-optimizers`; docs/optimisation.md).
 *
 * A problem is an objective over a box of real variables y (in the problem's own units) with
 * optional linear constraints A y <= b. Every optimiser works in the box normalised to the
 * symmetric cube [-1, 1]^d (y = centre + half-width * x) and sees the same objective
 * F(R(y)): R is the repair of the linear constraints, the point where the segment from a
 * strictly feasible anchor to y leaves the feasible set (y itself when it is feasible). So the
 * constraints are handled the same way for every optimiser, no optimiser needs constraint
 * support of its own, and every point evaluated, recorded or returned is feasible.
 *
 * A counting wrapper sits between every optimiser and the objective: it counts every
 * evaluation exactly, never evaluates beyond the budget (NLopt's maxeval is not strict: the
 * wrapper stops NLopt with nlopt_force_stop at the budget), keeps the best point it has seen
 * (an optimiser's own answer is not trusted: COBYLA may return its last point), and records the
 * value of every evaluation and the best so far against the evaluation number.
 *
 * Optimisers: the Ant Lion Optimizer (Mirjalili, Adv. Eng. Softw. 83 (2015) 80-98; the
 * published algorithm, with the departures from the reference code documented in
 * docs/optimisation.md), NLopt's GN_DIRECT_L, GN_CRS2_LM, GN_ISRES, GN_ESCH and the local
 * LN_BOBYQA, LN_COBYLA, LN_SBPLX from seeded random starts (multistart within the budget), and
 * uniform random search as the floor any method must beat. Random numbers come from GSL's
 * MT19937 (and NLopt's own generator, seeded with nlopt_srand before every start); the
 * population of ALO and random search is drawn serially and evaluated in parallel (OpenMP), so
 * results do not depend on the thread count. */
#ifndef GD_OPTIMIZE_H
#define GD_OPTIMIZE_H

#include "geardyn/gd_case.h"
#include "geardyn/gd_ltca.h"
#include "geardyn/gd_pair.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- optimisers ------------------------------------------------------------------------------ */

typedef enum gd_opt_algorithm {
    GD_OPT_ALO = 0,
    GD_OPT_GN_DIRECT_L = 1,
    GD_OPT_GN_CRS2_LM = 2,
    GD_OPT_GN_ISRES = 3,
    GD_OPT_GN_ESCH = 4,
    GD_OPT_LN_BOBYQA = 5,
    GD_OPT_LN_COBYLA = 6,
    GD_OPT_LN_SBPLX = 7,
    GD_OPT_RANDOM = 8,
    GD_OPT_MOALO = 9,          /* two objectives: the multi-objective Ant Lion Optimizer */
    GD_OPT_WEIGHTED_SUM = 10,  /* two objectives: NLopt (scalar_algorithm) on weighted sums over a grid */
    GD_OPT_EPS_CONSTRAINT = 11, /* two objectives: NLopt (scalar_algorithm) on epsilon-constraints over a grid */
    GD_OPT_NALGORITHMS = 12
} gd_opt_algorithm;

/* "alo", "gn_direct_l", "gn_crs2_lm", "gn_isres", "gn_esch", "ln_bobyqa", "ln_cobyla", "ln_sbplx",
 * "random", "moalo", "weighted-sum", "eps-constraint" (the [optimize] algorithm / optimizers names);
 * NULL for an unknown index. */
GD_API const char *gd_opt_algorithm_name(int algorithm);
/* Index of a name, or -1. */
GD_API int gd_opt_algorithm_parse(const char *name);
/* Local NLopt methods (restarted from seeded random points until the budget is used). */
GD_API int gd_opt_algorithm_is_local(int algorithm);
/* Algorithms whose run does not depend on the seed (GN_DIRECT_L). */
GD_API int gd_opt_algorithm_is_deterministic(int algorithm);
/* What an algorithm can minimise: 1 a single objective (ALO, NLopt, random search), 2 a pair of
 * objectives (MOALO, the scalarisations, random search), 3 both (random search). */
GD_API int gd_opt_algorithm_objectives(int algorithm);

/* ---- problems ---------------------------------------------------------------------------------- */

/* The objective at y (a feasible point in the problem's units). `state` is the caller's own: one
 * per concurrent caller (see state_alloc), so an objective with a workspace is thread-safe. */
typedef gd_status (*gd_opt_eval_fn)(void *state, const double *y, double *f, gd_error *err);
/* The objectives at y: f[0 .. nobj - 1], then naux numbers the wrapper records with every evaluation
 * (what the evaluation did: the dynamic objective's choice of continuation or sweep). */
typedef gd_status (*gd_opt_evalv_fn)(void *state, const double *y, double *f, gd_error *err);

#define GD_OPT_MAX_AUX 40
typedef struct gd_opt_problem {
    int dim;
    const double *lower, *upper;  /* dim each, lower < upper */
    int ncons;                    /* linear constraints A y <= b (0: none) */
    const double *A;              /* ncons x dim, row-major */
    const double *b;              /* ncons */
    const double *anchor;         /* strictly feasible point of the repair (NULL: the centre of the box if it is
                                     strictly feasible, else the lower corner) */
    gd_opt_eval_fn eval;          /* one objective (NULL when evalv is given) */
    gd_opt_evalv_fn evalv;        /* nobj objectives and naux recorded numbers (used when not NULL) */
    int nobj;                     /* evalv: 1 or 2 objectives */
    int naux;                     /* evalv: recorded numbers after the objectives, 0 .. GD_OPT_MAX_AUX */
    /* one state per concurrent caller (NULL: every caller is given `user`) */
    gd_status (*state_alloc)(void *user, void **state, gd_error *err);
    void (*state_free)(void *state);
    void *user;
} gd_opt_problem;

/* Check a problem (dimension, bounds, the anchor strictly feasible) and give the anchor used
 * (anchor may be NULL). GD_ERR_INPUT with the reason otherwise. */
GD_API gd_status gd_opt_problem_check(const gd_opt_problem *p, double *anchor, gd_error *err);
/* The repair R(y) of a point of the box: y when A y <= b, else anchor + s (y - anchor) with the
 * largest s in [0, 1) that satisfies every constraint (times 1 - 1e-12, so strictly inside). */
GD_API void gd_opt_repair(const gd_opt_problem *p, const double *anchor, const double *y, double *out);
/* Whether y lies in the box and satisfies A y <= b, both to tol (relative to the half-width of
 * each variable and to 1 + |b_i|). */
GD_API int gd_opt_feasible(const gd_opt_problem *p, const double *y, double tol);

/* ---- one run ----------------------------------------------------------------------------------- */

typedef struct gd_opt_settings {
    int algorithm;           /* gd_opt_algorithm */
    long budget;             /* objective evaluations, strict (>= 1; ALO needs 2 populations) */
    unsigned long seed;
    int population;          /* ALO: ants = antlions (>= 2); random search: batch size. 0: 30 */
    int threads;             /* threads evaluating a population (ALO, random): 0 the OpenMP default, 1 serial */
    double local_xtol;       /* local NLopt methods: xtol_abs in the normalised box (0: 1e-8) */
    double local_step;       /* local NLopt methods: initial step in the normalised box (0: 0.25) */
    int keep_history;        /* record every evaluation (f_history, best_history) */
    gd_stop_hook stop;       /* asked before each objective evaluation (from the threads evaluating a
                                population); stopped: GD_ERR_INTERRUPTED, no result */
    /* two objectives (docs/optimisation.md section 13) */
    int archive;             /* MOALO: the archive's size (0: 100) */
    int scalar_algorithm;    /* weighted-sum, eps-constraint: the NLopt method of every subproblem (0: gn_crs2_lm) */
    int scalar_grid;         /* weighted-sum, eps-constraint: subproblems (0: 8) */
    double hv_ref[2];        /* the hypervolume's reference point; the scalarisations divide each objective by it
                                (every objective here is >= 0) */
    /* after every evaluation recorded (serially, in evaluation order): the evaluations so far */
    void (*progress)(void *user, long evaluations, long budget);
    void *progress_user;
} gd_opt_settings;

GD_API void gd_opt_settings_default(gd_opt_settings *s);

typedef struct gd_opt_result {
    int dim, algorithm;
    double *y;               /* the best point evaluated (feasible, problem units) */
    double f;                /* its value */
    long evaluations;        /* objective evaluations made, exactly; <= budget */
    long best_at;            /* the evaluation (1-based) that found y */
    double *f_history;       /* keep_history: value of evaluation k + 1, k < evaluations */
    double *best_history;    /* keep_history: best value after evaluation k + 1 */
    int iterations;          /* ALO: iterations after the initial population (T) */
    int starts;              /* NLopt: nlopt_optimize calls; random: batches */
    int nlopt_code;          /* NLopt: the last return code (0 otherwise) */
    int roundoff_stops;      /* NLopt: starts that ended with NLOPT_ROUNDOFF_LIMITED (a local start ends; not an error) */
    double wall_s;
    /* evalv problems */
    int nobj, naux;
    double *fv_history;      /* keep_history: evaluations x (nobj + naux), every evaluation's values */
    /* two objectives: the non-dominated points of every evaluation (f1 increasing), the hypervolume they
     * dominate within the reference point after each evaluation, and MOALO's own archive */
    int nfront;
    double *front_y, *front_f; /* nfront x dim, nfront x 2 */
    double hv;               /* of the front */
    double *hv_history;      /* keep_history: after evaluation k + 1 */
    int narchive;            /* MOALO: its archive at the end (its front), else 0 */
    double *archive_y, *archive_f;
    double archive_hv;
} gd_opt_result;

/* Minimise p's objective with s.algorithm within s.budget evaluations. The result is the best
 * point the wrapper saw. Errors of the objective and negative NLopt return codes (other than
 * our own forced stop and ROUNDOFF_LIMITED) stop the run with their message. */
GD_API gd_status gd_opt_run(const gd_opt_problem *p, const gd_opt_settings *s, gd_opt_result *r, gd_error *err);
GD_API void gd_opt_result_free(gd_opt_result *r);

/* ALO: the ratio I(t) that shrinks the random walks at iteration t of T (t = 1 .. T):
 * 1 while t <= T/10, then 1 + 10^w t / T with w = 2, 3, 4, 5, 6 once t exceeds 10, 50, 75, 90
 * and 95 % of T (Mirjalili 2015, Eq. 2.10-2.11, as the reference code). */
GD_API double gd_alo_ratio(int t, int T);
/* ALO: iterations T for a budget (N + N T <= budget), 0 if the budget is below 2 N. */
GD_API int gd_alo_iterations(long budget, int population);

/* ---- two objectives -------------------------------------------------------------------------- */

/* The hypervolume (area) dominated by the n points f (n x 2, any order, dominated points allowed)
 * within the reference point ref: the area of the union of the boxes [f_i, ref]. */
GD_API double gd_opt_hypervolume(const double *f, int n, const double ref[2]);
/* The non-dominated points of f (n x 2): their indices into idx, ordered by f1 increasing (f2 then
 * decreasing); equal points count once (the first). Returns their count. */
GD_API int gd_opt_nondominated(const double *f, int n, int *idx);

/* ---- objectives ------------------------------------------------------------------------------- */

typedef enum gd_opt_objective {
    GD_OBJ_GEAR_LTE = 0,     /* LTE amplitude of the modified pair (arcsec), six modification parameters */
    GD_OBJ_SPHERE = 1,
    GD_OBJ_ROSENBROCK = 2,
    GD_OBJ_RASTRIGIN = 3,
    GD_OBJ_ACKLEY = 4,
    GD_OBJ_GRIEWANK = 5,
    GD_OBJ_ZDT1 = 6,         /* two objectives (Zitzler, Deb & Thiele 2000): convex front f2 = 1 - sqrt(f1) */
    GD_OBJ_ZDT2 = 7,         /* two objectives: concave front f2 = 1 - f1^2 */
    GD_OBJ_GEAR_LTE_RANGE = 8, /* LTE amplitude over a list of torques: the largest or the duty-weighted mean */
    GD_OBJ_GEAR_DYNAMIC = 9, /* the dynamic response over a speed range at each torque of a list (analysis layer) */
    GD_OBJ_NOBJECTIVES = 10
} gd_opt_objective;

/* "gear-lte", "sphere", "rosenbrock", "rastrigin", "ackley", "griewank", "zdt1", "zdt2",
 * "gear-lte-range", "gear-dynamic"; NULL for an unknown index. */
GD_API const char *gd_opt_objective_name(int objective);
GD_API int gd_opt_objective_parse(const char *name);
/* The gear objectives (gear-lte, gear-lte-range, gear-dynamic). */
GD_API int gd_opt_objective_is_gear(int objective);
/* Objectives of a test problem: 2 for ZDT1 and ZDT2, 1 for the others. */
GD_API int gd_opt_objective_count(int objective);

/* Test functions (GD_OBJ_SPHERE .. GD_OBJ_GRIEWANK), each with its minimum 0 at x = o (o NULL:
 * the origin; Rosenbrock is translated so that its minimiser is o rather than (1, ..., 1)):
 *   sphere      sum z_i^2                                              z = x - o, box [-100, 100]
 *   rosenbrock  sum_{i<d} 100 (z_{i+1} - z_i^2)^2 + (z_i - 1)^2         z = x - o + 1, box [-30, 30]
 *   rastrigin   10 d + sum (z_i^2 - 10 cos 2 pi z_i)                   box [-5.12, 5.12]
 *   ackley      -20 exp(-0.2 sqrt(mean z_i^2)) - exp(mean cos 2 pi z_i) + 20 + e   box [-32, 32]
 *   griewank    1 + sum z_i^2 / 4000 - prod cos(z_i / sqrt(i))          box [-600, 600]
 * (the domains of Mirjalili 2015, Table 1-2). */
GD_API double gd_opt_function_value(int objective, int dim, const double *o, const double *x);
GD_API void gd_opt_function_domain(int objective, double *lower, double *upper);

/* ZDT1 and ZDT2 on [0, 1]^d (d >= 2): f1 = x1, g = 1 + 9 sum_{i>1} x_i / (d - 1), f2 = g (1 - sqrt(f1/g))
 * (ZDT1) or g (1 - (f1/g)^2) (ZDT2); the Pareto set is x_i = 0 for i > 1. */
GD_API void gd_opt_zdt_value(int objective, int dim, const double *x, double f[2]);
/* The hypervolume of the true front of ZDT1 (ref^2 - 1/3 for a square reference (r, r), r >= 1) and ZDT2
 * (r^2 - 2/3), for any reference point with both coordinates >= 1. */
GD_API double gd_opt_zdt_front_hv(int objective, const double ref[2]);

/* An instance of a test function in dimension dim: with shift s in [0, 0.9] its minimiser o is
 * drawn uniformly from s times the box (GSL MT19937 seeded with instance_seed; s = 0: the
 * origin). ZDT1 and ZDT2 take no shift. */
typedef struct gd_opt_testfn {
    int objective, dim;
    double *lower, *upper, *optimum;
} gd_opt_testfn;

GD_API gd_status gd_opt_testfn_init(gd_opt_testfn *t, int objective, int dim, double shift,
                                    unsigned long instance_seed, gd_error *err);
GD_API void gd_opt_testfn_problem(gd_opt_testfn *t, gd_opt_problem *p);
GD_API void gd_opt_testfn_free(gd_opt_testfn *t);

/* The gear problem of the paper's section 4 (Eq. 13): minimise the peak-to-peak loaded
 * transmission error (LTCA, Eq. 12, arcsec over one mesh cycle at set->positions_per_cycle) of
 * the pair, under set->torque_nm, with its misalignment, over some of the nine modification
 * variables y1 .. y9 in the [modification] units (um and mm): the paper's x = [y1, y2, y3, y4, y5,
 * y7] (y6 = y5, symmetric lead relief; gd_opt_gear_vars_paper), or any list of y1 .. y9 (y6 the
 * lead relief at the other end, y8 the offset of the unmodified lead band, y9 the helix slope:
 * asymmetric lead relief and the helix-slope correction of a misalignment); a variable not listed
 * keeps the pair's own value. Within the bounds [lower, upper] (gd_opt_gear_bounds: the case's
 * [optimize] bounds) and the linear constraints y2 + y4 <= the active profile of the pinion (roll
 * length from the start of active profile to the tip) and, with y8, |y8| + y7/2 <= half the face.
 * Every point of the box, once repaired, passes gd_modification_check (checked on the 2^n
 * corners at creation; the checks are monotone in each variable). One LTCA workspace per
 * evaluation: the workspace holds the modified flank. */
#define GD_OPT_GEAR_DIM 6       /* the paper's variables y1..y5, y7 */
#define GD_OPT_GEAR_NVARS 9     /* y1 .. y9 */
typedef struct gd_opt_gear gd_opt_gear;

/* The design variables: variable k is y(var[k] + 1) ([modification] key gd_opt_gear_variable(var[k])). */
typedef struct gd_opt_gear_vars {
    int n;
    int var[GD_OPT_GEAR_NVARS];
} gd_opt_gear_vars;

/* The paper's six: y1, y2, y3, y4, y5, y7. */
GD_API void gd_opt_gear_vars_paper(gd_opt_gear_vars *v);
/* A comma-separated list of symbols y1 .. y9 (optimize.variables), each at most once. */
GD_API gd_status gd_opt_gear_vars_parse(const char *list, gd_opt_gear_vars *v, gd_error *err);
GD_API gd_status gd_opt_gear_create(const gd_pair *pair, const gd_ltca_settings *set, const gd_opt_gear_vars *v,
                                    const double *lower, const double *upper, gd_opt_gear **out, gd_error *err);
GD_API void gd_opt_gear_problem(gd_opt_gear *g, gd_opt_problem *p);
GD_API void gd_opt_gear_free(gd_opt_gear *g);
GD_API const gd_opt_gear_vars *gd_opt_gear_vars_of(const gd_opt_gear *g);
/* Roll length of the pinion's active profile (mm): the right side of y2 + y4 <= it. */
GD_API double gd_opt_gear_active_profile_mm(const gd_opt_gear *g);
/* Variable id (0..8, y1 .. y9): its [modification] key, unit and symbol. */
GD_API const char *gd_opt_gear_variable(int id, const char **unit, const char **symbol);
/* x (the variables of v) -> the pair's modification (y6 = y5 when y5 is listed and y6 is not), and back. */
GD_API void gd_opt_gear_apply(const gd_opt_gear_vars *v, gd_pair *pair, const double *x);
GD_API void gd_opt_gear_from_pair(const gd_opt_gear_vars *v, const gd_pair *pair, double *x);
/* The objective for the pair's own modification: LTE peak-to-peak (arcsec). */
GD_API gd_status gd_opt_gear_lte_pp(const gd_pair *pair, const gd_ltca_settings *set, double *lte_pp_arcsec,
                                    gd_error *err);
/* The paper's optimum (Table 2) as the pair's modification: 25 um, 1.5 mm, 35 um, 2.5 mm, 25 um, 25 um,
 * 35 mm (y8 = y9 = 0). */
GD_API void gd_opt_gear_table2(gd_pair *pair);
/* Whether the pair is the paper's (Table 1): herringbone, normal module 5 mm, 30 / 72 teeth, helix
 * 33.27 deg, normal pressure angle 20 deg, no profile shift, addendum 1 and dedendum 1.25, faces 40
 * and 44 mm per half. Only then does the optimisation show the paper's Table 2 and its LTE beside
 * the case's own modification. */
GD_API int gd_opt_gear_is_paper_pair(const gd_pair *pair);
/* The case's [optimize] bounds of the variables v, in their order. */
GD_API void gd_opt_gear_bounds(const gd_case *c, const gd_opt_gear_vars *v, double *lower, double *upper);

/* ---- what the gear problem minimises (docs/optimisation.md sections 1 and 13) ---- */

/* A gear objective: a number of the modified pair, smaller is better, and naux numbers it records
 * with every evaluation. One state per concurrent caller (state_alloc NULL: every caller gets user).
 * The optimisers see it through the gear problem, which applies the candidate's variables to the
 * pair first: an objective computed in a higher layer (the dynamic response, gd_dynobj.h) is such
 * a callback, so the optimisers never see what it computes. */
typedef struct gd_opt_gear_objective {
    char name[32];           /* "gear-lte", "gear-lte-range", "gear-dynamic" */
    int naux;                /* recorded numbers, 0 .. GD_OPT_MAX_AUX / 2 - 1 */
    gd_status (*eval)(void *state, const gd_pair *pair, double *f, double *aux, gd_error *err);
    gd_status (*state_alloc)(void *user, void **state, gd_error *err);
    void (*state_free)(void *state);
    void *user;
} gd_opt_gear_objective;

/* How the values at several torques (or over a speed range at each) become one: the largest (worst
 * case) or the duty-weighted mean sum w_k f_k / sum w_k. */
typedef enum gd_opt_combine { GD_OPT_COMBINE_MAX = 0, GD_OPT_COMBINE_MEAN = 1 } gd_opt_combine;
#define GD_OPT_MAX_TORQUES 8

/* gear-lte-range: the LTE amplitude (gd_opt_gear_lte_pp) at each torque, combined (gear-lte is the
 * case of one torque). Records the amplitude at each torque (naux = n). */
typedef struct gd_opt_lte_range {
    gd_ltca_settings set;    /* its torque_nm is replaced by each of torques_nm */
    int n;
    double torques_nm[GD_OPT_MAX_TORQUES];
    double weights[GD_OPT_MAX_TORQUES]; /* >= 0, a positive sum (mean) */
    int combine;             /* gd_opt_combine */
} gd_opt_lte_range;
/* The objective (user = r, which must outlive it). */
GD_API void gd_opt_lte_range_objective(const gd_opt_lte_range *r, gd_opt_gear_objective *o);
/* Its value for a pair, and the amplitude at each torque (each: n values, may be NULL). */
GD_API gd_status gd_opt_lte_range_value(const gd_opt_lte_range *r, const gd_pair *pair, double *f, double *each,
                                        gd_error *err);
/* The combination of n values v with weights w. */
GD_API double gd_opt_combine_values(int combine, int n, const double *v, const double *w);

/* The robust variant of every objective: its quantile (0.9 by default) over a Monte Carlo sample of
 * the pair's misalignment and of manufacturing deviations of the design variables, drawn once from
 * GSL's MT19937 seeded with seed (serially, before any evaluation: the same sample for every
 * candidate, whatever the threads). Sample s deviates the two tilt components of the axis (arcmin),
 * the centre distance (mm) and each design variable (amounts y1, y3, y5, y6, y9 by amount_um,
 * lengths y2, y4, y7, y8 by length_mm), each uniform in [-range, range]; a deviated variable is
 * kept in the box of [optimize] and the linear constraints are repaired, so every deviated flank
 * fits. Records, per objective, its value at the nominal flank before its own numbers. */
typedef struct gd_opt_robust {
    int samples;             /* 0: not robust */
    unsigned long seed;
    double quantile;         /* 0 < q <= 1 (0: 0.9) */
    double tilt_arcmin, centre_distance_mm, amount_um, length_mm;
} gd_opt_robust;

/* The objectives of the gear problem (one or two) and its robust variant (NULL or samples = 0:
 * none); without a call, the LTE amplitude at the LTCA settings' torque. The objectives' users must
 * outlive g. */
GD_API gd_status gd_opt_gear_set_objectives(gd_opt_gear *g, int nobj, const gd_opt_gear_objective *obj,
                                            const gd_opt_robust *robust, gd_error *err);
/* The Monte Carlo sample: its size, and dev (samples x (3 + the variables' count): in-plane and
 * cross-plane tilt deviations in arcmin, the centre-distance deviation in mm, then each variable's
 * deviation in its unit). */
GD_API int gd_opt_gear_robust_sample(const gd_opt_gear *g, const double **dev);
/* The objectives (and recorded numbers) of the pair with the variables x, as an optimiser's
 * evaluation computes them (for the reports of a run: the unmodified flank, the case's, an optimum):
 * f[nobj], aux[gd_opt_gear_naux]. */
GD_API gd_status gd_opt_gear_value(const gd_opt_gear *g, const double *x, double *f, double *aux, gd_error *err);
/* The same for any flank: the pair's own modification (and misalignment, deviated by the robust
 * sample as the candidates'). */
GD_API gd_status gd_opt_gear_value_of_pair(const gd_opt_gear *g, const gd_pair *pair, double *f, double *aux,
                                           gd_error *err);
GD_API int gd_opt_gear_nobj(const gd_opt_gear *g);
GD_API int gd_opt_gear_naux(const gd_opt_gear *g);
/* The pair the gear problem modifies (the case's, with its own modification in the variables not
 * optimised). */
GD_API const gd_pair *gd_opt_gear_pair(const gd_opt_gear *g);


/* ---- comparison -------------------------------------------------------------------------------- */

typedef struct gd_opt_compare_settings {
    int nalgs;
    int algs[GD_OPT_NALGORITHMS];
    int runs;                /* runs per algorithm (run r uses seed + r and problem instance r) */
    unsigned long seed;
    long budget;             /* the same for every algorithm */
    int population;          /* ALO ants (and random search batch) */
    double local_xtol, local_step;
    double f_ref;            /* the reference value: the known minimum, or NaN for the best value of the comparison */
    double target;           /* success: best - f_ref <= target (> 0) */
    double target_loosest;   /* ECDF targets log-spaced from target_loosest down to target */
    int ntargets;            /* >= 1 (1: the target only) */
    int threads;             /* runs in parallel over (algorithm, run); 0 the OpenMP default */
    gd_stop_hook stop;       /* every run's gd_opt_settings.stop */
    /* two objectives: every run's value is the hypervolume shortfall hv_ref[0] hv_ref[1] - HV (the area of the
     * reference box its front does not dominate), its history after each evaluation; the runs' settings */
    double hv_ref[2];
    int archive, scalar_algorithm, scalar_grid; /* 0: the defaults of gd_opt_settings_default */
} gd_opt_compare_settings;

typedef struct gd_opt_compare_run {
    int alg, run;
    unsigned long seed;
    double f;                /* final best value */
    double *y;               /* its point (dim) */
    long evaluations;
    long evals_to_target;    /* first evaluation with best - f_ref <= target; -1 never */
    long *hits;              /* per ECDF target (loosest first): first evaluation reaching it, -1 never */
    double *best_history;    /* budget entries: best after evaluation k + 1 (the final best after the run ended) */
    int starts;
    double wall_s;
} gd_opt_compare_run;

typedef struct gd_opt_alg_stats {
    int alg;
    double best, q1, median, q3, worst, mean; /* final best values over the runs */
    int successes;
    double success_rate;
    double evals_to_target_median;  /* over the successful runs (NaN: none) */
    double ert;              /* expected running time: evaluations of all runs (to success or the end) / successes (NaN: none) */
    double wall_mean_s, wall_total_s;
} gd_opt_alg_stats;

typedef struct gd_opt_compare_result {
    int nalgs, runs, dim;
    long budget;
    double f_ref;            /* the known minimum, or the best value found by any run */
    int f_ref_known;
    double target;
    int ntargets;
    double *targets;         /* ntargets precisions, loosest first */
    gd_opt_compare_run *run; /* nalgs * runs, algorithm-major (in the order of settings.algs) */
    gd_opt_alg_stats *stats; /* nalgs */
    double wall_s;
} gd_opt_compare_result;

/* Run every algorithm `runs` times on problems[r] (the instance of run r; the same instance for
 * every algorithm) with the same budget and seeds, in parallel over (algorithm, run). Every run
 * is computed by the same deterministic code whatever the thread, so everything except the wall
 * times is independent of the thread count. */
GD_API gd_status gd_opt_compare(const gd_opt_problem *const *problems, const gd_opt_compare_settings *s,
                                gd_opt_compare_result *r, gd_error *err);
GD_API void gd_opt_compare_result_free(gd_opt_compare_result *r);
/* Quartiles (q[0] 25 %, q[1] median, q[2] 75 %) of best - f_ref over the runs of algorithm index
 * a (into settings.algs) after `evals` evaluations. */
GD_API void gd_opt_compare_quartiles(const gd_opt_compare_result *r, int a, long evals, double q[3]);
/* Runtime distribution (COCO/BBOB): the fraction of (run, target) pairs of algorithm index a
 * reached within `evals` evaluations, pooled over nres comparisons (the same algorithms). */
GD_API double gd_opt_compare_ecdf(const gd_opt_compare_result *const *r, int nres, int a, long evals);

/* ---- summary.json ------------------------------------------------------------------------------ */

/* optimize with two objectives (optimize.objective2, or zdt1 / zdt2): the runs, the front of the best
 * (the largest hypervolume), and for the gear the two objectives of the unmodified flank and the
 * case's own. */
typedef struct gd_opt_pareto_report {
    int objective, objective2;   /* objective2: gear-dynamic, or the objective itself for zdt1 / zdt2 */
    int gear, dim, runs, best;
    gd_opt_result *res;          /* runs */
    double hv_ref[2];
    int hv_ref_derived;          /* 1.1 times the unmodified flank's (gear) or 1.1, 1.1 (zdt) */
    double flank_f[2][2];        /* gear: the unmodified flank's and the case's own two objectives */
    double true_front_hv;        /* zdt1 / zdt2: the true front's hypervolume within hv_ref (else NaN) */
    char column[2][48];          /* the objectives' columns with their units (lte_pp_arcsec, f1, ...) */
    char label[2][96];           /* their names on a picture, with the unit */
} gd_opt_pareto_report;

/* optimize with optimize.robust: the Monte Carlo sample, and for the unmodified flank, the case's own
 * and the optimum (0, 1, 2) the robust objective (the quantile), the nominal one and the value of
 * every sample. */
typedef struct gd_opt_robust_report {
    gd_opt_robust settings;
    int nvars;
    const double *dev;       /* samples x (3 + nvars), gd_opt_gear_robust_sample */
    double robust[3], nominal[3];
    double *values[3];       /* samples each, in the sample's order */
} gd_opt_robust_report;

typedef struct gd_opt_optimize_summary {
    int objective, dim, algorithm, runs, threads;
    long budget;
    const char *const *names;     /* dim variable names (with units in the name) */
    const double *lower, *upper;  /* bounds */
    const gd_opt_result *best;    /* the best run */
    int best_run;
    const double *run_f;          /* runs: final value of each run */
    const double *true_optimum;   /* test functions: the minimiser (NULL otherwise) */
    /* gear-lte: LTE amplitudes (arcsec) of the unmodified pair, the case's own modification, the
     * optimum, and (the paper's pair only, else NaN) the paper's Table 2 */
    double lte_unmodified, lte_case, lte_optimum, lte_table2;
    const gd_opt_gear_vars *vars; /* gear-lte: the variables (names[i] is the key of vars->var[i]) */
    const double *case_value;     /* gear-lte: the case's own value of each variable */
    const double *table2;         /* gear-lte, the paper's pair: Table 2's value of each variable (else NULL) */
    const char *const *no_effect; /* gear-lte: per variable NULL, or why it has no effect at the optimum */
    double active_profile_mm;
    /* gear-lte-range, gear-dynamic: the objective's unit; its value for the unmodified flank, the
     * case's own and the optimum (0, 1, 2), with its recorded numbers (gd_opt_gear_naux: per torque,
     * the LTE amplitude, or the dynamic peak and how its curve was found, gd_dyn_method) */
    const char *objective_unit;
    int ntorques;
    const double *torques_nm;
    double objective_of[3];
    const double *aux_of[3];
    const void *post;             /* gear-lte-range, gear-dynamic: the gd_optpost (gd_optpost.h) of the three flanks */
    /* the best run's progress: the relative fall of its best value over the last tenth of its
     * evaluations; converged = that fall is at most 1e-3 */
    double last_tenth_improvement;
    int converged;
    double wall_s;
    const gd_opt_robust_report *robust; /* optimize.robust (else NULL) */
} gd_opt_optimize_summary;


typedef struct gd_opt_compare_problem {
    int objective, dim;
    double shift;
    int nobj;                /* 2: the values are hypervolume shortfalls within hv_ref */
    double hv_ref[2];
    const gd_opt_compare_result *res;
} gd_opt_compare_problem;


/* ---- the results of the optimize and compare-optimizers rows (gd_analysis.h) ---- */

/* optimize: the runs of the case's [optimize] algorithm on its first objective, the best kept;
 * for the gear, the LTE of the unmodified pair, the case's own modification, the optimum and, for
 * the paper's pair, the paper's Table 2. */
#define GD_OPTIMIZE_MAXDIM 1000 /* the schema's largest dimension */
typedef struct gd_optimize_outcome {
    int objective, dim, gear, runs;
    gd_opt_result *res;      /* runs */
    int best;
    double *run_f;           /* runs: each run's best */
    char names[GD_OPTIMIZE_MAXDIM][48];
    const char *name_ptr[GD_OPTIMIZE_MAXDIM];
    double lower[GD_OPTIMIZE_MAXDIM], upper[GD_OPTIMIZE_MAXDIM];
    const double *reference; /* the case's own value of each variable (gear) or the true minimiser */
    gd_opt_gear_vars vars;   /* gear: the variables */
    gd_pair pair;            /* gear: the case's pair with its own modification */
    double case_value[GD_OPT_GEAR_NVARS]; /* gear: the case's own modification in the variables */
    double table2[GD_OPT_GEAR_NVARS];     /* gear, the paper's pair: Table 2 in the variables */
    int paper;               /* gear: the pair is the paper's (gd_opt_gear_is_paper_pair) */
    gd_ltca_result lte[4];   /* gear: unmodified, the case's modification, optimum, Table 2 (the paper's pair) */
    char no_effect[GD_OPT_GEAR_NVARS][96]; /* gear: "" or why the variable has no effect at the optimum */
    const char *no_effect_ptr[GD_OPT_GEAR_NVARS];
    double last_tenth_improvement; /* the best run: relative fall of the best value over its last tenth */
    int converged;           /* that fall at most 1e-3 */
    double active_mm;
    gd_opt_settings settings;
    int threads;
    double wall_s;           /* the runs' wall time summed */
    gd_opt_gear *gear_problem;
    gd_opt_testfn tf;
    /* gear-lte-range, gear-dynamic: the objective's own state (freed by user_free) and its value
     * (with its recorded numbers) for the unmodified flank, the case's own and the optimum */
    gd_opt_lte_range lte_range;
    void *user;
    void (*user_free)(void *user);
    double objective_of[3];
    double aux_of[3][GD_OPT_MAX_AUX];
    void *post;              /* gear-lte-range, gear-dynamic: a gd_optpost (gd_optpost.h), the row's to free */
    gd_opt_robust_report *robust; /* optimize.robust (else NULL); objective_of is then robust, aux_of the nominal
                                     objective's own numbers */
    gd_opt_pareto_report *pareto; /* two objectives (else NULL): the rest of the outcome is then only the problem's */
} gd_optimize_outcome;

/* compare-optimizers: every optimiser of the case on every objective (and dimension). */
#define GD_COMPARE_MAX 64
typedef struct gd_compare_entry {
    int objective, dim;
    double shift;
    int nobj;                   /* 2: two objectives (zdt1, zdt2, or gear-lte with optimize.objective2) */
    double hv_ref[2];           /* two objectives: the hypervolume's reference point */
    void *dyn;                  /* gear-lte with objective2: the dynamic objective's state (gd_dynobj) */
    gd_opt_gear *gear;
    gd_opt_testfn *tf;          /* runs instances */
    gd_opt_problem *pb;         /* runs */
    const gd_opt_problem **pp;  /* runs */
    gd_opt_compare_result res;
} gd_compare_entry;

typedef struct gd_compare_outcome {
    int n;
    gd_compare_entry p[GD_COMPARE_MAX];
    int runs;
    long *grid;                 /* evaluation counts of the convergence and ECDF tables */
    int ngrid;
    gd_opt_compare_settings settings;
    int threads;
    double wall_s;              /* the problems' wall time summed */
} gd_compare_outcome;

#ifdef __cplusplus
}
#endif
#endif
