/* The scene: the one place a case becomes physics. Its gear pair and the contact-analysis
 * settings of TCA and LTCA (gd_pair_from_case, gd_tca_settings_from_case,
 * gd_ltca_settings_from_case), its geometry and the values derived from it (gd_scene_resolve, the
 * second step of gd_case_resolve), the dimensionless dynamic model with its LTCA excitations
 * (gd_model_build) and its modal analysis (gd_scene_modes), and the solver options of its [solver]
 * section. */
#ifndef GD_SCENE_H
#define GD_SCENE_H

#include "geardyn/gd_case.h"
#include "geardyn/gd_ltca.h"
#include "geardyn/gd_modal.h"
#include "geardyn/gd_model.h"
#include "geardyn/gd_pair.h"
#include "geardyn/gd_tca.h"
#include "geardyn/gd_sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The case's gear pair: [gear] design data, [modification] (as the case holds it: resolve the case
 * first for modification.apply = false to give zero amounts) and [misalignment]. */
GD_API gd_pair gd_pair_from_case(const gd_case *c);
/* The pair's modification (the seven amounts and lengths) into the case's [modification]. */
GD_API void gd_pair_modification_to_case(const gd_pair *pair, gd_case *c);
/* The case's [solver] tca_* keys. */
GD_API gd_tca_settings gd_tca_settings_from_case(const gd_case *c);
/* The case's operating.torque_nm (resolved from the power when not given), support.pinion_axial
 * and [solver] ltca_positions_per_cycle, ltca_face_slices, tca_profile_points and tca_refine. */
GD_API gd_ltca_settings gd_ltca_settings_from_case(const gd_case *c);

/* Geometry and what follows from it: bodies (masses, inertias, equivalent mass), the limits of
 * the modification, the operating contact ratio, the mesh stiffness (ISO 6336 or LTCA), the groove
 * shaft stiffness, the rectangular stiffness's high fraction; each derived unless given. */
GD_API gd_status gd_scene_resolve(gd_case *c, gd_error *err);

/* The dimensionless model (torsional, torsional-lr, bta) of a resolved case, with the case's LTCA
 * stiffness and mesh-in impact when it asks for them. */
GD_API gd_status gd_model_build(const gd_case *c, gd_model *m, gd_error *err);
/* Apply the case's LTCA stiffness (stiffness = ltca) and impact (impact = on) to a built model. */
GD_API gd_status gd_model_apply_ltca(const gd_case *c, gd_model *m, gd_error *err);

/* What a run of a resolved case will cost, estimated from its keys and its built model before
 * any work (docs/performance.md, "The cost estimate", gives the model and how close it comes on
 * the shipped cases: benchmarks/bench_cost.py): the integration steps (from the model's highest
 * natural frequency and the frequency ratio, the method, rtol and max_step_fraction), the LTCA,
 * TCA, optimiser evaluations and continuation points, the pictures, the memory the recorded window
 * holds and the bytes of every file the analysis writes. threads: the threads the run will use
 * (its sweep points, optimiser evaluations and runs go in parallel); <= 0: 1. */
typedef struct gd_run_cost {
    double points;           /* dynamic runs (sweep points, 1 for a response; 0: none of its own) */
    double periods;          /* mesh periods integrated per run */
    double steps;            /* integration steps, all runs */
    double memory_bytes;     /* held at once by the recorded window (and the LTCA matrices) */
    double disk_bytes;       /* written: every table, summary.json and the pictures */
    double ltca_unknowns;    /* contact points of one LTCA position (0: no LTCA) */
    double cpu_seconds;      /* CPU time, all threads and gnuplot's */
    double seconds;          /* wall time with `threads` threads on an otherwise idle machine */
    int threads;             /* the threads assumed */
    const char *time_class;  /* of seconds: "seconds", "minutes", "hours", "days or more" */
    /* the case's fixed step (solver.method = rk4, or erk with solver.fixed_step) against its method's
     * stability region on the model linearised at its static operating point (gd_sim_step_stability):
     * the largest |R(h lambda)|, the mode attaining it, and the fewest stable steps per mesh period;
     * an adaptive or implicit solver: NaN, NaN, 0 */
    double step_amplification;
    double step_mode_hz;
    long stable_steps_per_period;
} gd_run_cost;
GD_API void gd_run_cost_estimate(const gd_case *c, const gd_model *m, int threads, gd_run_cost *cost);
/* "about 3.2e+08 s (10 years) on 2 threads (6.4e+08 s (20 years) of CPU)" */
GD_API void gd_run_cost_format(const gd_run_cost *cost, char *buf, size_t len);
/* The derived values checked before any work: a mesh frequency at least 1e-4 of the natural one
 * (a slower run would never end), memory and files within output.max_bytes, the estimated time
 * within run.max_time_s. The messages name the keys the value comes from; GD_ERR_INPUT. */
GD_API gd_status gd_run_cost_check(const gd_case *c, const gd_model *m, const gd_run_cost *cost, gd_error *err);

/* The modal analysis of the model m of the resolved case c (docs/model.md section 9.7): m linearised
 * at its static operating point (gd_model_static_state: every mesh in drive-side contact at its
 * mean stiffness, every bearing with a clearance on the side the load puts it, or open), undamped;
 * a herringbone's modes marked symmetric or antisymmetric; bta's springs named (bearing-1L,
 * axial-2R, groove-1, ...); the resonance speeds from c's pinion teeth. Runs no LTCA: the
 * stiffness is m's. */
GD_API gd_status gd_scene_modes(const gd_case *c, const gd_model *m, gd_modal *out, gd_error *err);

/* The integrator options of the case's [solver] section. */
GD_API void gd_solver_opts_from_case(const gd_case *c, gd_solver_opts *o);

#ifdef __cplusplus
}
#endif
#endif
