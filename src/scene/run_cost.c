/* The cost of a run estimated from its case and model before any work, and the derived values
 * checked against their limits (gd_scene.h). Every constant below was measured on this project's
 * machine (docs/performance.md, "The cost estimate"; benchmarks/bench_cost.py compares the
 * estimate with the runs of every shipped case):
 *   - integration steps per mesh period of ERK order 8 at rtol 1e-8: about 20 (w/Omega)^0.78,
 *     w the highest natural frequency of the model over the mesh one's scale omega_n (the model's
 *     stiffest mode, all contacts closed), within a factor of 2.1 of the steps counted on the
 *     quickstart pair (bta, torsional, torsional-lr) and the guide's spur and helical pairs from
 *     100 to 7000 rpm; lower orders and tighter tolerances take more, as (8/p)^4 (1e-8/rtol)^(1/(p+1));
 *   - 1.5 us of CPU per step of ERK order 8 (the compiled RHS, release SUNDIALS), scaled by the
 *     stages of the method; a Lyapunov tangent vector adds 40 % per step; DIRK steps 5.5 times;
 *   - the files: 254 bytes per time-history row of the 10-DOF model, 36 per row of variable.csv,
 *     19 per value of poincare.csv, about 3 events of 78 bytes per clearance and mesh period;
 *   - gnuplot: about 0.15 s a picture set and 0.11 ms per time-history row drawn;
 *   - LTCA: 3.4e-6 N + 5.8e-12 N^3 s per position of N contact points (an objective evaluation of
 *     32 positions of 168 points takes 16 ms; 41, 81, 161 and 301 face slices of the paper's pair
 *     39 ms, 0.11 s, 0.54 s and 4.4 s; 24 MB at 401 slices: one dense system per half and
 *     position); TCA 52 us per position of a 15 x 21 grid;
 *   - an optimiser comparison writes about 2 kB per optimiser run and problem, and its pictures
 *     reread the whole table per optimiser and panel (29 s for 10 problems of 9 x 15 runs). */
#include "geardyn/gd_scene.h"
#include "geardyn/gd_geometry.h"
#include "../case/case_keys.h"

#include "../core/gsl_quiet.h"

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define STEP_S 1.5e-6    /* CPU per step of ERK order 8 (13 stages) */
#define PICTURE_S 0.15   /* CPU of gnuplot for a small picture set */

/* ---- the integration ------------------------------------------------------------------------- */

/* The highest natural frequency of the model over omega_n: the square root of the largest
 * eigenvalue of M^-1 K with every clearance closed (the linearisation at rest, damping aside).
 * It sets the steps of a stable explicit method and of an accurate one at low speed. */
static double highest_frequency(const gd_model *m)
{
    int nd = m->ndof;
    if (m->custom || nd < 1)
        return 1.0;
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    gd_modes md;
    memset(&md, 0, sizeof md);
    for (int c = 0; c < m->nclear; c++)
        md.mode[c] = 1;
    gsl_matrix *A = gsl_matrix_alloc((size_t)nd, (size_t)nd);
    gsl_vector_complex *ev = gsl_vector_complex_alloc((size_t)nd);
    gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc((size_t)nd);
    double wmax = 1.0;
    if (A && ev && w) {
        for (int i = 0; i < nd; i++) {
            double y[GD_MAX_STATE] = {0}, v[GD_MAX_STATE] = {0}, out[GD_MAX_STATE];
            v[i] = 1.0;
            gd_model_tangent(m, 0.0, y, v, out, &md);
            for (int j = 0; j < nd; j++)
                gsl_matrix_set(A, (size_t)j, (size_t)i, -out[nd + j]);
        }
        if (gsl_eigen_nonsymm(A, ev, w) == GSL_SUCCESS) {
            double lmax = 0;
            for (int i = 0; i < nd; i++)
                lmax = fmax(lmax, gsl_vector_complex_get(ev, (size_t)i).dat[0]);
            if (lmax > 0 && isfinite(lmax))
                wmax = sqrt(lmax);
        }
    }
    gsl_eigen_nonsymm_free(w);
    gsl_vector_complex_free(ev);
    gsl_matrix_free(A);
    return wmax;
}

/* Stages of the ERK table of each order (gd_erk_default_table). */
static int erk_stages(int order)
{
    static const int stages[] = {0, 1, 2, 4, 5, 6, 8, 10, 13};
    return order >= 1 && order <= 8 ? stages[order] : 13;
}

/* Integration steps per mesh period of an adaptive explicit method of order p at rtol. */
static double adaptive_steps(double w, double Omega, int p, double rtol, double max_step_fraction)
{
    double base = 20.0 * pow(w / fmax(Omega, 1e-300), 0.78);
    double order = pow(8.0 / p, 4.0) * pow(1e-8 / rtol, 1.0 / (p + 1.0));
    return fmax(1.0 / max_step_fraction, base * order);
}

/* Steps per mesh period of the case's own solver, and the CPU of one. */
static void solver_steps(const gd_case *c, const gd_model *m, double w, double *steps, double *step_s)
{
    int p = c->order > 0 ? c->order : 8;
    if (c->method == GD_METHOD_RK4) {
        *steps = c->steps_per_period;
        *step_s = STEP_S * (0.3 + 0.7 * 4 / 13.0);
    } else if (c->fixed_step) {
        *steps = c->steps_per_period;
        *step_s = STEP_S * (0.3 + 0.7 * erk_stages(p) / 13.0);
    } else if (c->method == GD_METHOD_DIRK) {
        *steps = 16.0 * adaptive_steps(w, m->Omega, 8, c->rtol, c->max_step_fraction);
        *step_s = 5.5 * STEP_S;
    } else {
        *steps = adaptive_steps(w, m->Omega, p, c->rtol, c->max_step_fraction);
        *step_s = STEP_S * (0.3 + 0.7 * erk_stages(p) / 13.0);
    }
}

/* Transient periods a response runs: the fixed ones and, when the transient is adaptive, 30 % of the
 * extension it may take (settled orbits stop early, chaotic ones take it all; the shipped sweeps
 * average about that). */
static double transient_periods(const gd_case *c)
{
    double extra = c->transient_max_periods > c->transient_periods ? c->transient_max_periods - c->transient_periods : 0;
    return c->transient_periods + 0.3 * extra;
}

/* ---- LTCA and TCA ------------------------------------------------------------------------------ */

/* Contact points of one LTCA position: the face slices of every tooth pair that can be in contact,
 * on each half. */
static double ltca_points(const gd_case *c)
{
    gd_geometry g;
    gd_error e = {0};
    double pairs = 3;
    const gd_pair pair = gd_pair_from_case(c);
    if (gd_geometry_compute(&pair, &g, &e) == GD_OK && isfinite(g.eps_alpha))
        pairs = ceil(g.eps_alpha + g.eps_beta) + 1;
    return (double)c->ltca_face_slices * pairs * (c->arrangement == GD_ARR_HERRINGBONE ? 2 : 1);
}

/* CPU of one LTCA of npos positions (and the mesh-in search: about 30 positions more). */
static double ltca_seconds(const gd_case *c, double npos, int mesh_in)
{
    double N = ltca_points(c);
    return 3e-3 + (npos + (mesh_in ? 30 : 0)) * (3.4e-6 * N + 5.8e-12 * N * N * N);
}

/* The keys of the LTCA's inputs: a sweep of one of them computes an LTCA per point. */
static int changes_ltca(const char *key)
{
    static const char *const prefixes[] = {"gear.", "modification.", "misalignment.", "operating.torque_nm",
                                           "operating.power_kw", "solver.ltca_", "solver.tca_", "support.pinion_axial"};
    for (size_t i = 0; i < sizeof prefixes / sizeof prefixes[0]; i++)
        if (strncmp(key, prefixes[i], strlen(prefixes[i])) == 0)
            return 1;
    return 0;
}

static double tca_seconds(const gd_case *c)
{
    double grid = (double)c->tca_profile_points * c->tca_face_points / 315.0;
    double per = 52e-6 * grid * (c->tca_formulation == GD_TCA_BOTH ? 1.8 : c->tca_formulation == GD_TCA_TANGENCY ? 0.8 : 1);
    return 0.01 + (double)c->tca_positions_per_cycle * c->tca_cycles * (c->arrangement == GD_ARR_HERRINGBONE ? 2 : 1) * per;
}

/* ---- the analyses ---------------------------------------------------------------------------- */

/* Items of a comma-separated list. */
static int list_items(const char *s)
{
    int n = 0, in = 0;
    for (; *s; s++) {
        if (*s == ',')
            in = 0;
        else if (*s != ' ' && !in)
            in = 1, n++;
    }
    return n;
}

/* One response run: its CPU (integration, samples, time history) and its files. */
static void response_cost(const gd_case *c, const gd_model *m, double w, double *cpu, double *bytes, double *steps)
{
    double per, step_s;
    solver_steps(c, m, w, &per, &step_s);
    double periods = transient_periods(c) + c->record_periods;
    double rows = (double)c->record_periods * c->samples_per_period;
    double cols = 2 + 5 * (m->nmesh > 1 ? 2 : 1) + m->ndof;
    *steps = periods * per;
    *cpu = *steps * step_s * (1 + 0.4 * c->lyapunov_exponents) + rows * 0.3e-6;
    *bytes = rows * 36 + (c->record_periods + 1) * 19.0 * m->n;  /* variable.csv, poincare.csv */
    if (c->time_history) {
        *bytes += rows * 11.5 * cols;
        *cpu += rows * 0.4e-6 * cols;
    }
    if (c->event_log)
        *bytes += periods * 3 * 78.0 * m->nclear;
}

/* Sweep points (all runs) and the runs that can go at once. */
static double sweep_runs(const gd_case *c, double *parallel)
{
    double rows = c->sweep_parameter2[0] ? c->sweep_points2 : 1, pts = c->sweep_points;
    if (c->sweep_mode == 1) { /* independent */
        *parallel = rows * pts;
        return rows * pts;
    }
    double dirs = c->sweep_direction == 2 ? 2 : 1;
    *parallel = rows * dirs;
    return rows * pts * dirs;
}

/* A work-precision study: the transient, the reference and its check, every family over its
 * settings (a setting over max_steps_per_period costs about one period and ends its family), the
 * order study over the horizon. */
static double workprec_seconds(const gd_case *c, const gd_model *m, double w)
{
    double per, step_s;
    solver_steps(c, m, w, &per, &step_s);
    double W = c->record_periods, H = fmin(c->wp_horizon_periods, W), cap = c->wp_max_steps_per_period;
    double s = c->transient_periods * per * step_s;
    s += W * STEP_S * fmax(1 / c->wp_reference_max_step_fraction,
                           adaptive_steps(w, m->Omega, c->wp_reference_order, c->wp_reference_rtol, 1));
    s += W * STEP_S * fmax(1 / c->wp_reference_max_step_fraction,
                           adaptive_steps(w, m->Omega, c->wp_check_order, c->wp_reference_rtol, 1));
    char buf[256];
    snprintf(buf, sizeof buf, "%s", c->wp_families);
    double grid = 0, order = 0;
    char *save = NULL;
    for (char *tok = strtok_r(buf, ", ", &save); tok; tok = strtok_r(NULL, ", ", &save)) {
        int rk4 = strcmp(tok, "rk4") == 0, dirk = strncmp(tok, "dirk", 4) == 0;
        int p = rk4 ? 4 : atoi(tok + (dirk ? 4 : 3));
        if (p < 2 || p > 8)
            p = 4;
        double st = rk4 ? STEP_S * (0.3 + 0.7 * 4 / 13.0) : dirk ? 5.5 * STEP_S : STEP_S * (0.3 + 0.7 * erk_stages(p) / 13.0);
        if (rk4) {
            for (double k = c->wp_rk4_steps_min; k <= c->wp_rk4_steps_max; k *= 2)
                grid += W * k * st;
        } else {
            int nl = (int)floor(log10(c->wp_rtol_loosest / c->wp_rtol_tightest) * c->wp_rtols_per_decade + 1e-9) + 1;
            for (int i = 0; i < nl; i++) {
                double r = c->wp_rtol_loosest * pow(10.0, -(double)i / c->wp_rtols_per_decade);
                double k = adaptive_steps(w, m->Omega, dirk ? 8 : p, r, c->max_step_fraction) * (dirk ? 16 : 1);
                if (k > cap) { /* over budget: about a period, then the family's tighter settings are skipped */
                    grid += cap * st;
                    break;
                }
                grid += W * k * st;
            }
        }
        if (c->wp_order_study && !dirk)
            for (double k = c->wp_order_steps_min; k <= c->wp_order_steps_max; k *= 2)
                order += H * k * st;
    }
    double variants = c->wp_root_finding_off ? 2 : 1;
    return s + grid * variants * c->wp_repeats * (c->wp_lyapunov ? 1.5 : 1) + order * variants;
}

/* Evaluations of the objective of an optimisation or a comparison, per problem. */
static double opt_budget(const gd_case *c)
{
    return c->opt_budget_evals > 0 ? c->opt_budget_evals : (double)c->opt_population * (c->opt_iterations + 1);
}

/* The dynamic objective's part of an evaluation: per torque an LTCA and the period-1 orbits
 * followed over the speed range (gear-dynamic: about 53 orbits over 2500 rpm on the paper's pair,
 * each about 35 mesh periods of the model's steps with its monodromy, as a continuation's point;
 * docs/optimisation.md section 12 measured 0.47-0.51 s of CPU for three torques). */
static double dynamic_eval_seconds(const gd_case *c, const gd_model *m, double w, double ltca, int ntq)
{
    /* the orbits are those of optimize.dynamic_model at the middle of the speed range */
    gd_case one = *c;
    one.model = c->opt_dynamic_model;
    one.speed_rpm = 0.5 * (c->opt_speed_from_rpm + c->opt_speed_to_rpm);
    gd_model *dm = malloc(sizeof *dm);
    gd_error e = {0};
    if (dm && gd_model_build(&one, dm, &e) == GD_OK)
        m = dm;
    double per, step_s;
    solver_steps(&one, m, m == dm ? highest_frequency(dm) : w, &per, &step_s);
    double orbits = 53 * fmax(0.4, fabs(c->opt_speed_to_rpm - c->opt_speed_from_rpm) / 2500.0);
    double s = ntq * (ltca + orbits * 35 * per * step_s * (1 + 0.4 * m->n));
    free(dm);
    return s;
}

/* One evaluation of a gear objective: an LTCA on a fresh workspace (gear-lte), one per torque
 * (gear-lte-range), or the dynamic objective's (gear-dynamic), and with two objectives
 * (optimize.objective2 = gear-dynamic) the dynamic objective's besides. 0 when the objective is
 * not the gear's. */
static double gear_eval_seconds(const gd_case *c, const gd_model *m, double w)
{
    double ltca = ltca_seconds(c, c->ltca_positions_per_cycle, 0) - 3e-3 + 2.6e-3;
    int ntq = c->n_opt_torques > 0 ? c->n_opt_torques : 1;
    double s = 0;
    if (strstr(c->opt_objective, "gear-dynamic"))
        s = dynamic_eval_seconds(c, m, w, ltca, ntq);
    else if (strstr(c->opt_objective, "gear-lte-range"))
        s = ntq * ltca;
    else if (strstr(c->opt_objective, "gear-lte"))
        s = ltca;
    if (s > 0 && strstr(c->opt_objective2, "gear-dynamic"))
        s += dynamic_eval_seconds(c, m, w, ltca, ntq);
    return s;
}

/* What optimize computes after the optimum over load and speed (docs/optimisation.md section 12):
 * the Harris map, an LTCA for each of 3 flanks at 20 torques and the objective's, and for
 * gear-dynamic the 3 flanks evaluated again on the loop's model and on bta. */
static double optpost_seconds(const gd_case *c, const gd_model *m, double w)
{
    int dyn = strstr(c->opt_objective, "gear-dynamic") != NULL;
    if (!dyn && !strstr(c->opt_objective, "gear-lte-range"))
        return 0;
    int ntq = c->n_opt_torques > 0 ? c->n_opt_torques : 1;
    double s = 3 * (20 + ntq) * (ltca_seconds(c, c->ltca_positions_per_cycle, 0) - 3e-3 + 2.6e-3);
    if (dyn) {
        gd_case bta = *c;
        bta.opt_dynamic_model = GD_MODEL_BTA;
        s += 3 * gear_eval_seconds(c, m, w) + 3 * gear_eval_seconds(&bta, m, w);
    }
    return s;
}

/* An optimisation or a comparison: CPU and the evaluations that can go at once. */
static double optimize_seconds(const gd_case *c, const gd_model *m, double w, double *parallel, double *bytes)
{
    double eval = gear_eval_seconds(c, m, w);
    if (c->analysis == GD_ANALYSIS_OPTIMIZE) {
        double runs = c->opt_runs > 0 ? c->opt_runs : 1, evals = runs * opt_budget(c);
        *parallel = c->opt_population;
        /* convergence.csv; for the gear the three flanks' LTCA and TCA with their pictures */
        int flanks = eval > 0 && !c->opt_objective2[0] ? 3 : 1;
        *bytes = evals * 120 + flanks * 2e6;
        return evals * eval + optpost_seconds(c, m, w) +
               flanks * (ltca_seconds(c, c->ltca_positions_per_cycle, 1) + tca_seconds(c) + 4 * PICTURE_S) +
               2 * PICTURE_S;
    }
    int gear = eval > 0;
    int objectives = list_items(c->opt_objective), nfun = objectives - gear;
    int dims = c->n_opt_dimensions > 0 ? c->n_opt_dimensions : 1;
    double problems = gear + (double)nfun * dims;
    double runs = c->opt_runs > 0 ? c->opt_runs : 10, algs = list_items(c->opt_optimizers);
    double per_problem = algs * runs * opt_budget(c);
    *parallel = algs * runs;
    *bytes = problems * algs * runs * 2000 + 3e5;
    /* the pictures reread the whole table per optimiser and panel: about the square of the problems */
    double pictures = 0.29 * problems * problems * per_problem / (9 * 15 * 10000.0);
    return per_problem * (gear * eval + nfun * dims * 1.7e-6) + pictures + 2 * PICTURE_S;
}

/* A continuation: the transient to the start, then each branch's points, each about 17 mesh
 * periods of the orbit's multiple with the monodromy (0.4 n per period for its n tangent vectors). */
static double contin_seconds(const gd_case *c, const gd_model *m, double w, double *bytes)
{
    double per, step_s;
    solver_steps(c, m, w, &per, &step_s);
    double branches = (c->cont_direction == 2 ? 2 : 1) + (c->cont_branch_switching ? 2 : 0);
    branches = fmin(branches, c->cont_max_branches);
    double points = branches * fmin(c->cont_max_points, 60);
    double nper = c->cont_period > 0 ? c->cont_period : 1;
    *bytes = points * (40.0 + 3 * m->n) * 14 + 1e5;
    return transient_periods(c) * per * step_s + points * 17 * nper * per * step_s * (1 + 0.4 * m->n) + 2 * PICTURE_S;
}

/* Basins: every initial state (the picture's cells and the random sample, at each value of the
 * parameter) a trajectory until the recurrences stop it, the states spread over the threads. On a
 * full section (a one-coordinate model: basin hits on) a trajectory ends after about 14 mesh periods
 * (12 on the shipped Kahraman & Singh picture, 14 on its sample), on a larger state (no basin hits)
 * after about 90 (89 on the paper's pair at 4750 rpm), at most basins.max_periods (docs/basins.md
 * section 9). The memory: the tessellation (4 bytes a cell), the picture's labels and the sample's
 * states; the files: basins.csv 33 bytes a cell, the attractors and fractions about 2 kB a value. */
static double basins_cost(const gd_case *c, const gd_model *m, double w, gd_run_cost *cost, double *parallel,
                          double *files, double *window)
{
    double per, step_s;
    solver_steps(c, m, w, &per, &step_s);
    double ry = c->bas_resolution_y ? c->bas_resolution_y : c->bas_resolution, m2 = 1.0 + 2.0 * c->bas_margin;
    double cells = c->bas_picture && !c->bas_parameter[0] ? (double)c->bas_resolution * ry : 0.0;
    double values = c->bas_parameter[0] ? c->bas_points : 1;
    cost->points = (cells + c->bas_samples) * values;
    cost->periods = fmin(m->n == 2 ? 14 : 90, c->bas_max_periods);
    cost->steps = cost->points * cost->periods * per;
    *parallel = cost->points;
    *window = 4.0 * (c->bas_resolution * m2) * (ry * m2) + 4.0 * cells + (8.0 * m->n + 4.0) * c->bas_samples +
              16.0 * c->bas_max_periods;
    *files = 33.0 * cells + values * 2000.0 + 1.5e5; /* summary.json about 35 kB, the pictures about 110 kB */
    return cost->steps * step_s + (c->plots ? 2 * PICTURE_S + 2e-6 * cells : 0);
}

/* The case's fixed step against its method's stability region (gd_run_cost's step_ fields). */
static void step_stability(const gd_case *c, const gd_model *m, gd_run_cost *cost)
{
    cost->step_amplification = cost->step_mode_hz = NAN;
    gd_solver_opts o;
    gd_solver_opts_from_case(c, &o);
    if (m->custom || !(o.method == GD_METHOD_RK4 || (o.method == GD_METHOD_ERK && o.fixed_step)))
        return;
    double y[GD_MAX_STATE];
    gd_modes md;
    gd_step_stability sb;
    gd_error e = {0};
    if (gd_model_static_state(m, y, &md, &e) != GD_OK || gd_sim_step_stability(m, &o, y, &md, &sb, &e) != GD_OK)
        return; /* not judged */
    cost->step_amplification = sb.amplification;
    cost->step_mode_hz = sb.freq_hz;
    cost->stable_steps_per_period = sb.min_steps_per_period;
}

GD_API void gd_run_cost_estimate(const gd_case *c, const gd_model *m, int threads, gd_run_cost *cost)
{
    memset(cost, 0, sizeof *cost);
    step_stability(c, m, cost);
    double w = highest_frequency(m);
    double run_cpu = 0, run_bytes = 0, run_steps = 0, parallel = 1, cpu = 0, files = 0, window = 0;
    int ltca = c->stiffness == GD_STIFF_LTCA || c->impact || (c->ste_source == GD_STE_LTCA && c->error_excitation);
    cost->ltca_unknowns = ltca || c->analysis == GD_ANALYSIS_LTCA || c->analysis == GD_ANALYSIS_OPTIMIZE ||
                          (c->analysis == GD_ANALYSIS_COMPARE_OPTIMIZERS && strstr(c->opt_objective, "gear-lte"))
                        ? ltca_points(c) : 0;
    double dyn_ltca = ltca ? ltca_seconds(c, c->ltca_positions_per_cycle, c->impact) : 0;
    double rows = (double)c->record_periods * c->samples_per_period;
    switch (c->analysis) {
    case GD_ANALYSIS_RESPONSE:
        response_cost(c, m, w, &run_cpu, &run_bytes, &run_steps);
        cost->points = 1;
        cost->periods = transient_periods(c) + c->record_periods;
        cost->steps = run_steps;
        cpu = run_cpu + dyn_ltca + (c->plots ? 3 * PICTURE_S + 1.1e-4 * rows : 0);
        files = run_bytes + 1e6;
        window = rows * 48 + (c->record_periods + 1) * (8.0 * m->n + 16);
        break;
    case GD_ANALYSIS_SWEEP: { /* no time history per point: its Poincare points and a table row */
        gd_case one = *c;
        one.time_history = one.event_log = 0;
        response_cost(&one, m, w, &run_cpu, &run_bytes, &run_steps);
        cost->points = sweep_runs(c, &parallel);
        cost->periods = transient_periods(c) + c->record_periods;
        cost->steps = cost->points * run_steps;
        int per_point = ltca && (changes_ltca(c->sweep_parameter) || (c->sweep_parameter2[0] && changes_ltca(c->sweep_parameter2)));
        double bif_rows = cost->points * (c->record_periods + 1);
        cpu = cost->points * (run_cpu - rows * 0.3e-6) + (per_point ? cost->points / 2 + 1 : 1) * dyn_ltca +
              (c->plots ? 2 * PICTURE_S + 2e-5 * bif_rows : 0);
        files = cost->points * ((c->record_periods + 1) * 40.0 + 400) + 1e6;
        window = (c->record_periods + 1) * 8.0 * m->n * 4;
        break;
    }
    case GD_ANALYSIS_LTCA:
        cpu = ltca_seconds(c, c->ltca_positions_per_cycle, 1) + (c->plots ? 2 * PICTURE_S : 0);
        files = c->ltca_positions_per_cycle * (cost->ltca_unknowns * 110.0 + 200) + 3e5;
        break;
    case GD_ANALYSIS_TCA:
        cpu = tca_seconds(c) + (c->plots ? 2 * PICTURE_S : 0);
        files = (double)c->tca_profile_points * c->tca_face_points * (c->arrangement == GD_ARR_HERRINGBONE ? 2 : 1) * 60 +
                (double)c->tca_positions_per_cycle * c->tca_cycles * 300 + 3e5;
        break;
    case GD_ANALYSIS_OPTIMIZE:
    case GD_ANALYSIS_COMPARE_OPTIMIZERS:
        cpu = optimize_seconds(c, m, w, &parallel, &files);
        break;
    case GD_ANALYSIS_WORK_PRECISION:
        cpu = workprec_seconds(c, m, w) + (c->plots ? 3 * PICTURE_S : 0);
        files = 6e5 + 2e4 * list_items(c->wp_families);
        break;
    case GD_ANALYSIS_CONTINUATION:
        cpu = contin_seconds(c, m, w, &files) + dyn_ltca;
        break;
    case GD_ANALYSIS_BASINS:
        cpu = basins_cost(c, m, w, cost, &parallel, &files, &window) + dyn_ltca;
        break;
    default:
        break;
    }
    double per_half = cost->ltca_unknowns / (c->arrangement == GD_ARR_HERRINGBONE ? 2 : 1);
    cost->memory_bytes = window + 8.0 * per_half * per_half;
    cost->disk_bytes = files;
    cost->threads = threads > 0 ? threads : 1;
    cost->cpu_seconds = cpu;
    cost->seconds = cpu / fmax(1.0, fmin(cost->threads, parallel));
    cost->time_class = cost->seconds < 10 ? "seconds" : cost->seconds < 600 ? "minutes"
                     : cost->seconds < 36000 ? "hours" : "days or more";
}

/* The slowest speed a run integrates: the case's, or the lowest end of a sweep of the speed. */
static double slowest_speed(const gd_case *c, const char **key)
{
    double n = c->speed_rpm;
    *key = NULL;
    for (int axis = 0; c->analysis == GD_ANALYSIS_SWEEP && axis < 2; axis++)
        if (strcmp(axis ? c->sweep_parameter2 : c->sweep_parameter, "operating.speed_rpm") == 0) {
            double lo = fmin(axis ? c->sweep_from2 : c->sweep_from, axis ? c->sweep_to2 : c->sweep_to);
            if (lo < n || (lo == n && !gd_case_key_given(c, "operating", "speed_rpm"))) { /* the sweep's own speed */
                n = lo;
                *key = lo == (axis ? c->sweep_from2 : c->sweep_from) ? (axis ? "from2" : "from")
                                                                      : (axis ? "to2" : "to");
            }
        }
    return n;
}

/* "3.2e+08 s (10 years)": a time in seconds and in the largest unit that reads well. */
static void format_duration(double s, char *buf, size_t len)
{
    static const struct { double s; const char *unit; } units[] = {
        {365.25 * 86400, "years"}, {86400, "days"}, {3600, "hours"}, {60, "minutes"}};
    for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
        if (s >= 2 * units[i].s) {
            snprintf(buf, len, "%.2g s (%.2g %s)", s, s / units[i].s, units[i].unit);
            return;
        }
    snprintf(buf, len, "%.2g s", s);
}

GD_API void gd_run_cost_format(const gd_run_cost *cost, char *buf, size_t len)
{
    char wall[64], cpu[64];
    format_duration(cost->seconds, wall, sizeof wall);
    format_duration(cost->cpu_seconds, cpu, sizeof cpu);
    if (cost->threads > 1 && cost->cpu_seconds > 1.05 * cost->seconds)
        snprintf(buf, len, "about %s on %d threads (%s of CPU)", wall, cost->threads, cpu);
    else
        snprintf(buf, len, "about %s", wall);
}

/* What the estimate of a run too long comes from, named by its keys. */
static void time_sources(const gd_case *c, const gd_model *m, const gd_run_cost *cost, char *buf, size_t len)
{
    buf[0] = '\0';
    if (c->analysis == GD_ANALYSIS_BASINS)
        snprintf(buf, len, "%.3g integration steps: %.4g initial states (basins.resolution = %d, resolution_y = %d, "
                 "picture = %s, samples = %d, points = %d) of about %.3g mesh periods (at most basins.max_periods = %d) "
                 "at about %.3g steps each (from solver.method, solver.rtol, solver.max_step_fraction = %g and the "
                 "frequency ratio %.3g of operating.speed_rpm = %g)", cost->steps, cost->points, c->bas_resolution,
                 c->bas_resolution_y ? c->bas_resolution_y : c->bas_resolution, c->bas_picture ? "on" : "off",
                 c->bas_samples, c->bas_parameter[0] ? c->bas_points : 1, cost->periods, c->bas_max_periods,
                 cost->steps / fmax(cost->points * cost->periods, 1), c->max_step_fraction, m->Omega, c->speed_rpm);
    else if (cost->steps > 0)
        snprintf(buf, len, "%.3g integration steps: %.4g runs of %.4g mesh periods at about %.3g steps each (from "
                 "solver.method, solver.rtol, solver.max_step_fraction = %g and the frequency ratio %.3g of "
                 "operating.speed_rpm = %g)", cost->steps, cost->points, cost->periods,
                 cost->steps / fmax(cost->points * cost->periods, 1), c->max_step_fraction, m->Omega, c->speed_rpm);
    else if (c->analysis == GD_ANALYSIS_OPTIMIZE || c->analysis == GD_ANALYSIS_COMPARE_OPTIMIZERS)
        snprintf(buf, len, "the objective evaluations of optimize.iterations = %d, optimize.population = %d, "
                 "optimize.runs = %d, optimize.budget_evals = %d", c->opt_iterations, c->opt_population, c->opt_runs,
                 c->opt_budget_evals);
    else if (c->analysis == GD_ANALYSIS_TCA)
        snprintf(buf, len, "solver.tca_positions_per_cycle = %d, solver.tca_cycles = %d, a grid of %d x %d",
                 c->tca_positions_per_cycle, c->tca_cycles, c->tca_profile_points, c->tca_face_points);
    else
        snprintf(buf, len, "the work of scene.analysis");
    if (cost->ltca_unknowns > 0) {
        size_t u = strlen(buf);
        snprintf(buf + u, len - u, "; LTCA of %.0f contact points a position (solver.ltca_face_slices = %d), "
                 "solver.ltca_positions_per_cycle = %d", cost->ltca_unknowns, c->ltca_face_slices,
                 c->ltca_positions_per_cycle);
    }
}

/* What the files (disk) or the memory of a run too large come from, named by its keys. */
static void bytes_sources(const gd_case *c, const gd_run_cost *cost, int disk, char *buf, size_t len)
{
    char ltca[96] = "";
    if (cost->ltca_unknowns > 0)
        snprintf(ltca, sizeof ltca, "%ssolver.ltca_face_slices = %d", disk ? ", " : "", c->ltca_face_slices);
    if (!disk && cost->points == 0)
        snprintf(buf, len, "%s", ltca);
    else if (c->analysis == GD_ANALYSIS_RESPONSE || c->analysis == GD_ANALYSIS_SWEEP || !disk)
        snprintf(buf, len, "run.record_periods = %d, output.samples_per_period = %d, output.time_history = %s, "
                 "output.event_log = %s%s", c->record_periods, c->samples_per_period, c->time_history ? "on" : "off",
                 c->event_log ? "on" : "off", ltca);
    else if (c->analysis == GD_ANALYSIS_LTCA)
        snprintf(buf, len, "the loads of %.0f contact points at solver.ltca_positions_per_cycle = %d positions%s",
                 cost->ltca_unknowns, c->ltca_positions_per_cycle, ltca);
    else if (c->analysis == GD_ANALYSIS_TCA)
        snprintf(buf, len, "solver.tca_positions_per_cycle = %d, solver.tca_cycles = %d, a grid of %d x %d",
                 c->tca_positions_per_cycle, c->tca_cycles, c->tca_profile_points, c->tca_face_points);
    else if (c->analysis == GD_ANALYSIS_OPTIMIZE || c->analysis == GD_ANALYSIS_COMPARE_OPTIMIZERS)
        snprintf(buf, len, "the runs and evaluations of optimize.iterations = %d, optimize.population = %d, "
                 "optimize.runs = %d, optimize.budget_evals = %d", c->opt_iterations, c->opt_population, c->opt_runs,
                 c->opt_budget_evals);
    else if (c->analysis == GD_ANALYSIS_CONTINUATION)
        snprintf(buf, len, "continuation.max_points = %d, continuation.max_branches = %d", c->cont_max_points,
                 c->cont_max_branches);
    else
        snprintf(buf, len, "the tables of scene.analysis");
}

GD_API gd_status gd_run_cost_check(const gd_case *c, const gd_model *m, const gd_run_cost *cost, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    const char *sweep_key;
    double speed = slowest_speed(c, &sweep_key);
    if (sweep_key && cost->points > 0 && !(m->Omega * speed / c->speed_rpm >= 1e-4)) {
        gd_case_key_where(c, "sweep", sweep_key, w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.%s: at operating.speed_rpm = %g rpm the mesh frequency is "
                            "%.3g of the natural frequency %.4g Hz, a run would not end (valid: a mesh frequency of at "
                            "least 1e-4 of the natural one: speed_rpm >= %.3g)", w, sweep_key, speed,
                            m->Omega * speed / c->speed_rpm, m->omega_n / (2 * M_PI), c->speed_rpm * 1e-4 / m->Omega);
    }
    if (cost->points > 0 && !(m->Omega >= 1e-4)) {
        gd_case_key_where(c, "operating", "speed_rpm", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: operating.speed_rpm: the mesh frequency %.3g Hz "
                            "(operating.speed_rpm = %g rpm times gear.teeth_pinion = %d over 60) is %.3g of the "
                            "natural frequency %.4g Hz, a run would not end (valid: a mesh frequency of at least "
                            "1e-4 of the natural one: speed_rpm >= %.3g)", w, m->mesh_freq_hz, c->speed_rpm,
                            c->teeth_pinion, m->Omega, m->omega_n / (2 * M_PI), c->speed_rpm * 1e-4 / m->Omega);
    }
    if (c->analysis == GD_ANALYSIS_BASINS && (cost->disk_bytes > c->max_bytes || cost->memory_bytes > c->max_bytes)) {
        int disk = cost->disk_bytes > c->max_bytes;
        gd_case_key_where(c, "output", "max_bytes", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: output.max_bytes: the basins would %s about %.3g bytes (from "
                            "basins.resolution = %d, resolution_y = %d, margin = %g, samples = %d, max_periods = %d), "
                            "above output.max_bytes = %.4g (valid: raise output.max_bytes, or fewer cells or samples)",
                            w, disk ? "write" : "hold in memory", disk ? cost->disk_bytes : cost->memory_bytes,
                            c->bas_resolution, c->bas_resolution_y ? c->bas_resolution_y : c->bas_resolution,
                            c->bas_margin, c->bas_samples, c->bas_max_periods, c->max_bytes);
    }
    if (cost->disk_bytes > c->max_bytes || cost->memory_bytes > c->max_bytes) {
        int disk = cost->disk_bytes > c->max_bytes;
        char from[1200];
        bytes_sources(c, cost, disk, from, sizeof from);
        gd_case_key_where(c, "output", "max_bytes", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: output.max_bytes: the run would %s about %.3g bytes (from %s), "
                            "above output.max_bytes = %.4g (valid: raise output.max_bytes, or shorten the run)", w,
                            disk ? "write" : "hold in memory", disk ? cost->disk_bytes : cost->memory_bytes, from,
                            c->max_bytes);
    }
    if (!(cost->seconds <= c->max_time_s)) {
        char est[160], lim[64], from[1200];
        gd_run_cost_format(cost, est, sizeof est);
        format_duration(c->max_time_s, lim, sizeof lim);
        time_sources(c, m, cost, from, sizeof from);
        gd_case_key_where(c, "run", "max_time_s", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: run.max_time_s: the run is estimated at %s, from %s; above "
                            "run.max_time_s = %s (valid: raise run.max_time_s, or make the run shorter)", w, est, from,
                            lim);
    }
    return GD_OK;
}
