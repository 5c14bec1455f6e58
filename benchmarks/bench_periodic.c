/* Benchmark: periodic orbits and their continuation (gd_periodic.h, docs/continuation.md).
 *   1. bta, cases/accuracy/period1-7000rpm.ini (n = 20, period-1, single-sided impacts, the
 *      bearings rattling): one mesh period plain against the same period with the monodromy (20
 *      tangent vectors): CPU and RHS evaluations each.
 *   2. The same orbit by Newton shooting from the state after the transient, and a continuation
 *      of it in the mesh frequency (points, Newton iterations per correction, CPU per point)
 *      against a brute-force sweep point (300 transient and 200 recorded periods).
 *   3. The paper's bta model (cases/paper/sweep-speed.ini) continued in the speed from 3000 to
 *      5500 rpm: points, bifurcations and the corrected points their location took, Newton
 *      iterations, CPU per point against a sweep point.
 *   4. The Kahraman & Singh curve, alpha 0, Omega 0.5 to 1.5 (tests/test_continuation.c): CPU.
 * Usage: bench_periodic [repeats] (best of the repeats). CPU time (getrusage) is the figure to quote
 * on a shared machine; instruction counts under valgrind --tool=callgrind are steadier still. */
#include "geardyn/geardyn.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

static double cpu(void)
{
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return (double)u.ru_utime.tv_sec + 1e-6 * (double)u.ru_utime.tv_usec + (double)u.ru_stime.tv_sec +
           1e-6 * (double)u.ru_stime.tv_usec;
}

static void die(const gd_error *e)
{
    fprintf(stderr, "bench_periodic: %s\n", e->msg);
    exit(1);
}

static void load(gd_case *c, gd_model *m, const char *rel, const char *const *sets)
{
    gd_error e = {0};
    const char *src = getenv("GEARDYN_SOURCE");
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", src ? src : ".", rel);
    if (gd_case_init(c, &e) != GD_OK || gd_case_load(c, path, &e) != GD_OK)
        die(&e);
    for (int i = 0; sets && sets[i]; i++)
        if (gd_case_set(c, sets[i], i, &e) != GD_OK)
            die(&e);
    if (gd_case_resolve(c, &e) != GD_OK || gd_model_build(c, m, &e) != GD_OK)
        die(&e);
}

static void bta(int repeats)
{
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    gd_error e = {0};
    load(&c, &m, "cases/accuracy/period1-7000rpm.ini", NULL);
    gd_solver_opts_from_case(&c, &o);
    double y[GD_MAX_STATE], y1[GD_MAX_STATE], M[GD_MAX_STATE * GD_MAX_STATE];
    gd_modes md;
    if (gd_initial_state(&c, &m, y, &md, &e) != GD_OK)
        die(&e);
    double t0 = cpu();
    if (gd_sim_period_map(&m, &o, y, c.transient_periods, y, NULL, NULL, &e) != GD_OK)
        die(&e);
    double t_transient = (cpu() - t0) / c.transient_periods;
    double best_plain = INFINITY, best_mono = INFINITY;
    gd_sim_stats sp, sm;
    for (int r = 0; r < repeats; r++) {
        t0 = cpu();
        for (int k = 0; k < 20; k++)
            if (gd_sim_period_map(&m, &o, y, 1, y1, NULL, &sp, &e) != GD_OK)
                die(&e);
        best_plain = fmin(best_plain, (cpu() - t0) / 20);
        t0 = cpu();
        for (int k = 0; k < 20; k++)
            if (gd_sim_period_map(&m, &o, y, 1, y1, M, &sm, &e) != GD_OK)
                die(&e);
        best_mono = fmin(best_mono, (cpu() - t0) / 20);
    }
    printf("bta 7000 rpm (n = %d, rtol %g): one period plain %.3g ms CPU, %ld RHS evaluations, %ld steps; with the "
           "monodromy %.3g ms, %ld RHS evaluations (of 21 vectors), %ld steps: ratio %.2f\n", m.n, o.rtol,
           1e3 * best_plain, sp.rhs_evals, sp.steps, 1e3 * best_mono, sm.rhs_evals, sm.steps, best_mono / best_plain);
    gd_po_opts po;
    gd_po_opts_default(&po);
    gd_po orbit;
    t0 = cpu();
    if (gd_po_solve(&m, &o, &po, y, &orbit, &e) != GD_OK)
        die(&e);
    double t_solve = cpu() - t0;
    double sweep_point = 500 * t_transient;
    printf("bta 7000 rpm: shooting from the transient's end: %d Newton iterations, %.3g ms CPU; mu_max %.6f; a sweep "
           "point (500 periods at %.3g ms) %.3g ms: ratio %.3f\n", orbit.iterations, 1e3 * t_solve, orbit.mu_max,
           1e3 * t_transient, 1e3 * sweep_point, t_solve / sweep_point);
    gd_cont_opts co;
    gd_cont_opts_default(&co);
    co.max_points = 15;
    co.direction = -1;
    gd_branch br;
    t0 = cpu();
    if (gd_continue(gd_model_at_mesh_frequency, &m, &o, &co, &orbit, &br, &e) != GD_OK)
        die(&e);
    double t_cont = cpu() - t0;
    printf("bta continuation from Omega %.5g down: %d points to Omega %.5g, %ld corrections, %.2f Newton iterations "
           "per correction, %.3g ms CPU per point: %.3f of a sweep point; %d bifurcations; end: %s\n", m.Omega,
           br.npoints, br.pt[br.npoints - 1].orbit.p, br.corrections,
           (double)br.newton_iterations / (double)br.corrections, 1e3 * t_cont / br.npoints,
           t_cont / br.npoints / sweep_point, br.nbif, br.end_reason);
    gd_branch_free(&br);
    gd_case_free(&c);
}

/* corrected points per located bifurcation */
static double per_bifurcation(const gd_branch *br)
{
    long n = 0;
    for (int i = 0; i < br->nbif; i++)
        n += br->bif[i].corrections;
    return br->nbif ? (double)n / br->nbif : 0.0;
}

/* the paper's bta model in the speed, 3000 to 5500 rpm (tests/test_continuation_bta.c) */
static void bta_paper(void)
{
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    gd_error e = {0};
    const char *sets[] = {"operating.speed_rpm=3000", NULL};
    load(&c, &m, "cases/paper/sweep-speed.ini", sets);
    gd_solver_opts_from_case(&c, &o);
    gd_case_param cp = {&c, "operating.speed_rpm", 3000.0 / m.Omega};
    double y[GD_MAX_STATE];
    gd_modes md;
    double t0 = cpu();
    if (gd_initial_state(&c, &m, y, &md, &e) != GD_OK || gd_sim_period_map(&m, &o, y, 500, y, NULL, NULL, &e))
        die(&e);
    double t_period = (cpu() - t0) / 500;
    gd_cont_opts co;
    gd_cont_opts_default(&co);
    co.p_min = 3000.0 / cp.scale;
    co.p_max = 5500.0 / cp.scale;
    gd_po start;
    gd_branch br;
    t0 = cpu();
    if (gd_po_solve(&m, &o, &co.po, y, &start, &e) != GD_OK ||
        gd_continue(gd_model_at_case_key, &cp, &o, &co, &start, &br, &e) != GD_OK)
        die(&e);
    double t = cpu() - t0;
    printf("bta paper case, 3000 to 5500 rpm: %d points, %d bifurcations (%.1f corrections each), %ld corrections, "
           "%.2f Newton iterations per correction, %.2f per point, %.2f chord iterations per correction, %.3g s CPU, "
           "%.3g ms per point: %.3f of a sweep point (500 periods of %.3g ms)\n", br.npoints, br.nbif,
           per_bifurcation(&br), br.corrections, (double)br.newton_iterations / (double)br.corrections,
           (double)br.newton_iterations / br.npoints, (double)br.chord_iterations / (double)br.corrections, t,
           1e3 * t / br.npoints, t / br.npoints / (500 * t_period), 1e3 * t_period);
    gd_branch_free(&br);
    gd_case_free(&c);
}

static void ks(int repeats)
{
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    gd_error e = {0};
    const char *sets[] = {"excitation.stiffness=constant", "operating.speed_rpm=1591.5494309189535", NULL};
    load(&c, &m, "cases/validation/kahraman-singh.ini", sets); /* Omega 0.5 */
    gd_solver_opts_from_case(&c, &o);
    double best = INFINITY;
    gd_branch br = {0};
    for (int r = 0; r < repeats; r++) {
        gd_branch_free(&br);
        double y[GD_MAX_STATE];
        gd_modes md;
        double t0 = cpu();
        if (gd_initial_state(&c, &m, y, &md, &e) != GD_OK || gd_sim_period_map(&m, &o, y, 300, y, NULL, NULL, &e))
            die(&e);
        gd_cont_opts co;
        gd_cont_opts_default(&co);
        co.p_min = 0.5;
        co.p_max = 1.5;
        co.ds_max = 0.05;
        gd_po start;
        if (gd_po_solve(&m, &o, &co.po, y, &start, &e) != GD_OK ||
            gd_continue(gd_model_at_mesh_frequency, &m, &o, &co, &start, &br, &e) != GD_OK)
            die(&e);
        best = fmin(best, cpu() - t0);
    }
    printf("K&S alpha 0, Omega %.3g to 1.5 (rtol %g): %d points, %d bifurcations (%.1f corrections each), %ld "
           "corrections, %.2f Newton iterations per correction, %.3g s CPU (300 transient periods included)\n",
           m.Omega, o.rtol, br.npoints, br.nbif, per_bifurcation(&br), br.corrections,
           (double)br.newton_iterations / (double)br.corrections, best);
    gd_branch_free(&br);
    gd_case_free(&c);
}

/* the multipliers of K segment monodromies of n x n from the block-cyclic matrix (gd_floquet_segments)
 * against the eigenvalues of their explicit product, for the largest shooting system (K 16, n 20) and
 * smaller ones */
static void multipliers(int repeats)
{
    static const int sizes[][2] = {{2, 20}, {4, 20}, {8, 20}, {16, 20}, {16, 2}};
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        const int K = sizes[k][0], n = sizes[k][1];
        double *Mk = malloc(sizeof(double) * (size_t)(K * n * n)), M[GD_MAX_STATE * GD_MAX_STATE];
        double re[GD_MAX_STATE], im[GD_MAX_STATE];
        unsigned s = 12345;
        for (int i = 0; i < K * n * n; i++) {
            s = s * 1103515245u + 12345u;
            Mk[i] = (double)(s >> 8) / (double)(1u << 24) - 0.5;
        }
        gd_error e = {0};
        double best_c = INFINITY, best_p = INFINITY;
        for (int r = 0; r < repeats; r++) {
            double t0 = cpu();
            if (gd_floquet_segments(Mk, K, n, M, re, im, &e) != GD_OK)
                die(&e);
            best_c = fmin(best_c, cpu() - t0);
            t0 = cpu();
            if (gd_floquet(M, n, re, im, &e) != GD_OK)
                die(&e);
            best_p = fmin(best_p, cpu() - t0);
        }
        printf("multipliers of %d segments of %d x %d: from the block-cyclic matrix %.3g ms CPU, of the explicit "
               "product %.3g ms\n", K, n, n, 1e3 * best_c, 1e3 * best_p);
        free(Mk);
    }
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 3;
    multipliers(repeats);
    bta(repeats);
    bta_paper();
    ks(repeats);
    return 0;
}
