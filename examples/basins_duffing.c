/* Basins of attraction of a custom system through the public API: the forced Duffing oscillator
 *
 *     x'' + d x' + b x + x^3 = f cos t
 *
 * written as a gd_custom_system, its stroboscopic map over the forcing period 2 pi, and the fraction
 * of a uniform random sample of initial states (x, x') in a box that goes to each attractor, with
 * the recurrence mapper of gd_basins.h (docs/basins.md section 7). Two published cases:
 *
 *   twin   d = 0.15, b = -1, f = 0.2 on [-2.2, 2.2]^2: two attractors, one in each well, 0.511 (the
 *          right well's, reached from (1.8, 0) in the reference's integration) and 0.489 (the left
 *          well's, from (-0.8, 0)) (Attractors.jl's test suite, 1000 states)
 *   five   d = 0.08, b = 0, f = 0.2 on x in [-1, 1], x' in [-0.5, 1]: five attractors, 0.2027 (from
 *          (-0.21, 0.02): the small period-1 orbit), 0.495 ((1.05, 0.77): the large one), 0.0288
 *          ((-0.67, 0.02)), 0.0257 ((-0.46, 0.30)), 0.2478 ((-0.43, 0.12): period 3) (bSTAB's
 *          reference, 10 000 states, Stender & Hoffmann, Nonlinear Dyn. 107, 2022)
 *
 * bSTAB names each attractor by an initial state that reaches it (its template): the templates are
 * mapped after the sample as seeds, which counts nothing, and each reference value is set beside the
 * fraction of the attractor its template reaches. The twin-well attractors are named by their well
 * (the sign of x at the section), because (1.8, 0) lies in a region of fractal basins where the
 * attractor reached depends on the integrator's rounding (a change of 1e-9 takes it to either).
 *
 * Usage: example_basins_duffing twin|five [samples [threads]]   (default 10000 states, OpenMP's threads)
 * Prints `name = value` lines: the attractors, then per reference value
 *   fraction_K = p se reference reference_se, and the mesh periods integrated. */
#include "geardyn/geardyn.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct duffing { double d, b, f; } duffing;

static void rhs(double t, const double *y, double *yd, void *ctx)
{
    const duffing *p = ctx;
    yd[0] = y[1];
    yd[1] = -p->d * y[1] - p->b * y[0] - y[0] * y[0] * y[0] + p->f * cos(t);
}

static void tangent(double t, const double *y, const double *v, double *out, void *ctx)
{
    (void)t;
    const duffing *p = ctx;
    out[0] = v[1];
    out[1] = -p->d * v[1] - (p->b + 3.0 * y[0] * y[0]) * v[0];
}

typedef struct reference { double x0, v0, fraction; int well; } reference; /* well: +-1 (the sign of x), 0: by template */

int main(int argc, char **argv)
{
    const char *which = argc > 1 ? argv[1] : "twin";
    long N = argc > 2 ? atol(argv[2]) : 10000;
    int threads = argc > 3 ? atoi(argv[3]) : 0;
    int five = strcmp(which, "five") == 0;
    if (!five && strcmp(which, "twin") != 0) {
        fprintf(stderr, "usage: example_basins_duffing twin|five [samples [threads]]\n");
        return 2;
    }
    duffing par = five ? (duffing){0.08, 0.0, 0.2} : (duffing){0.15, -1.0, 0.2};
    static const reference twin_ref[] = {{1.8, 0.0, 0.511, 1}, {-0.8, 0.0, 0.489, -1}};
    static const reference five_ref[] = {{-0.21, 0.02, 0.2027, 0}, {1.05, 0.77, 0.495, 0}, {-0.67, 0.02, 0.0288, 0},
                                         {-0.46, 0.30, 0.0257, 0}, {-0.43, 0.12, 0.2478, 0}};
    const reference *ref = five ? five_ref : twin_ref;
    int nref = five ? 5 : 2;
    long ref_n = five ? 10000 : 1000; /* the sample the reference values come from */
    double lo[2] = {five ? -1.0 : -2.2, five ? -0.5 : -2.2}, hi[2] = {five ? 1.0 : 2.2, five ? 1.0 : 2.2};

    gd_custom_system sys = {2, rhs, tangent, NULL, &par};
    gd_model m;
    gd_model_custom(&m, &sys, 2.0 * M_PI);
    gd_solver_opts o;
    memset(&o, 0, sizeof o);
    o.method = GD_METHOD_ERK;
    o.order = 8;
    o.rtol = 1e-9;
    o.atol = 1e-9;
    o.root_finding = 1;
    o.refine_events = 1;
    o.max_step_fraction = 0.1;
    o.max_events_per_period = 10000;

    gd_error err = {0};
    gd_basin_section sec;
    const double base[2] = {0.0, 0.0};
    /* cells of 0.01 (twin: 0.022) in both coordinates; the tessellation one box width beyond the box */
    int cells[2] = {five ? 200 : 200, five ? 150 : 200};
    if (gd_basin_section_plane(&sec, 2, base, 0, 1, lo[0], hi[0], lo[1], hi[1], cells[0], cells[1], &err) != GD_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    gd_basin_opts bo;
    gd_basin_opts_default(&bo);
    bo.threads = threads;
    gd_basin_mapper *mp = NULL;
    if (gd_basin_mapper_create(&m, &o, &sec, &bo, &mp, &err) != GD_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }

    /* the sample: uniform in the box, GSL's Mersenne Twister from seed 1 */
    double *y0 = malloc(sizeof(double) * 2 * (size_t)(N + nref));
    int *lab = malloc(sizeof(int) * (size_t)(N + nref));
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    if (!y0 || !lab || !rng)
        return 1;
    gsl_rng_set(rng, 1);
    for (long k = 0; k < N; k++) {
        double u = gsl_rng_uniform(rng), v = gsl_rng_uniform(rng);
        y0[2 * k] = lo[0] + u * (hi[0] - lo[0]);
        y0[2 * k + 1] = lo[1] + v * (hi[1] - lo[1]);
    }
    gsl_rng_free(rng);
    for (int r = 0; r < nref; r++) {
        y0[2 * (N + r)] = ref[r].x0;
        y0[2 * (N + r) + 1] = ref[r].v0;
    }
    clock_t c0 = clock();
    struct timespec w0, w1;
    clock_gettime(CLOCK_MONOTONIC, &w0);
    gd_status st = gd_basin_map(mp, y0, N, 1, 0, lab, &err);
    if (st == GD_OK) /* the templates, not counted */
        st = gd_basin_map(mp, y0 + 2 * N, nref, 0, 1, lab + N, &err);
    clock_gettime(CLOCK_MONOTONIC, &w1);
    if (st != GD_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    const gd_attractor *att;
    int natt = gd_basin_mapper_attractors(mp, &att);
    printf("system = %s\nsamples = %ld\nattractors = %d\n", which, N, natt);
    for (int a = 0; a < natt; a++) {
        long cnt = 0;
        for (long k = 0; k < N; k++)
            cnt += lab[k] == a;
        printf("attractor_%d = %s, %ld states, |mu_max| %.6f, x' = %.6f at x = %.6f%s\n", a, att[a].name, cnt,
               att[a].kind == GD_ATT_PERIODIC ? att[a].orbit.mu_max : NAN, att[a].pts[1], att[a].pts[0],
               att[a].seeded ? ", seeded" : "");
    }
    for (int l = -1; l >= -GD_BASIN_NSPECIAL; l--) {
        long cnt = 0;
        for (long k = 0; k < N; k++)
            cnt += lab[k] == l;
        printf("%s = %ld\n", gd_basin_label_name(l), cnt);
    }
    for (int r = 0; r < nref; r++) {
        if (ref[r].well) /* the attractor in that well */
            for (int a = 0; a < natt; a++)
                if ((att[a].pts[0] > 0) == (ref[r].well > 0))
                    lab[N + r] = a;
        long cnt = 0;
        for (long k = 0; k < N; k++)
            cnt += lab[k] == lab[N + r];
        gd_basin_fraction f;
        gd_basin_fraction_of(cnt, N, 1.96, &f);
        printf("fraction_%d = %.6f %.6f %.6f %.6f   ; %s: attractor %d, Wilson [%.4f, %.4f]\n", r, f.p, f.se,
               ref[r].fraction, sqrt(ref[r].fraction * (1 - ref[r].fraction) / (double)ref_n),
               ref[r].well > 0 ? "the right well" : ref[r].well < 0 ? "the left well" : "the template's attractor",
               lab[N + r], f.wilson_lo, f.wilson_hi);
    }
    printf("mesh_periods = %ld\ncpu_s = %.2f\nwall_s = %.2f\n", gd_basin_mapper_periods(mp),
           (double)(clock() - c0) / CLOCKS_PER_SEC, (double)(w1.tv_sec - w0.tv_sec) + 1e-9 * (double)(w1.tv_nsec - w0.tv_nsec));
    gd_basin_mapper_free(mp);
    free(y0);
    free(lab);
    return 0;
}
