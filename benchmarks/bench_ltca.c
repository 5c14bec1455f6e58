/* Benchmark: LTCA of one mesh cycle of the paper's herringbone pair (Table 1, 500 N m,
 * delta 0.5', dE 0.1 mm; cases/paper/ltca-unmodified.ini and ltca-modified.ini): 32 pinion
 * positions, both halves, default discretisation (ltca_face_slices = 21), floating pinion.
 * Timed three ways: the positions on a workspace created once (what an optimiser evaluating
 * thousands of modifications does per evaluation, less one workspace), the same with the dense
 * reference solver (gd_contact_solve), and the whole gd_ltca_run_opts without the mesh-in search
 * (workspace creation included). The aim is below 50 ms per cycle.
 * Usage: bench_ltca [repeats]  (best of the repeats is reported) */
#include "geardyn/geardyn.h"
#include "geardyn/gd_ltca.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int make(gd_case *c, int modified, gd_error *err)
{
    gd_case_init(c, err);
    const char *base[] = {"scene.analysis=ltca", "misalignment.axis_in_plane_arcmin=-0.35355339",
                          "misalignment.axis_cross_plane_arcmin=0.35355339", "misalignment.centre_distance_error_mm=0.1",
                          "operating.torque_nm=500"};
    const char *mod[] = {"modification.root_relief_amount_um=25", "modification.root_relief_length_mm=1.5",
                         "modification.tip_relief_amount_um=35", "modification.tip_relief_length_mm=2.5",
                         "modification.lead_relief_inner_um=25", "modification.lead_relief_outer_um=25",
                         "modification.lead_unmodified_length_mm=35"};
    for (int i = 0; i < 5; i++)
        if (gd_case_set(c, base[i], i, err) != GD_OK)
            return 1;
    for (int i = 0; modified && i < 7; i++)
        if (gd_case_set(c, mod[i], 5 + i, err) != GD_OK)
            return 1;
    return gd_case_resolve(c, err) != GD_OK;
}

static int bench(const char *label, int modified, int repeats)
{
    gd_case c;
    gd_error err = {0};
    if (make(&c, modified, &err)) {
        fprintf(stderr, "%s: %s\n", label, err.msg);
        return 1;
    }
    const int npos = c.ltca_positions_per_cycle;
    const gd_pair pair = gd_pair_from_case(&c);
    const gd_ltca_settings set = gd_ltca_settings_from_case(&c);
    double best[2] = {1e300, 1e300}, pp = 0;
    long iters[2] = {0, 0}, points = 0;
    for (int dense = 0; dense < 2; dense++) {
        gd_ltca *w;
        if (gd_ltca_create(&pair, &set, &w, &err) != GD_OK) {
            fprintf(stderr, "%s: %s\n", label, err.msg);
            return 1;
        }
        gd_ltca_use_dense_solver(w, dense);
        const double tau = 2 * M_PI / c.teeth_pinion;
        for (int r = 0; r < repeats; r++) {
            double lo = 1e300, hi = -1e300;
            iters[dense] = points = 0;
            double t0 = now();
            for (int k = 0; k < npos; k++) {
                gd_ltca_position p;
                if (gd_ltca_solve_at(w, tau * k / npos, c.torque_nm, &p, &err) != GD_OK) {
                    fprintf(stderr, "%s: %s\n", label, err.msg);
                    return 1;
                }
                lo = fmin(lo, p.lte);
                hi = fmax(hi, p.lte);
                iters[dense] += p.iterations;
                points += p.npoints;
            }
            double dt = now() - t0;
            best[dense] = fmin(best[dense], dt);
            pp = (hi - lo) * 180 * 3600 / M_PI;
        }
        gd_ltca_free(w);
    }
    double run = 1e300;
    for (int r = 0; r < repeats; r++) {
        gd_ltca_result res;
        double t0 = now();
        if (gd_ltca_run_opts(&pair, &set, 0, 0, &res, &err) != GD_OK) {
            fprintf(stderr, "%s: %s\n", label, err.msg);
            return 1;
        }
        run = fmin(run, now() - t0);
        gd_ltca_result_free(&res);
    }
    printf("%-10s %d positions: %6.2f ms (block solver), %6.2f ms (dense gd_contact_solve), gd_ltca_run %6.2f ms; "
           "%.1f points, %.2f / %.2f active-set iterations per position (block / dense); LTE %.4f arcsec p-p\n",
           label, npos, best[0] * 1e3, best[1] * 1e3, run * 1e3, (double)points / npos, (double)iters[0] / npos,
           (double)iters[1] / npos, pp);
    gd_case_free(&c);
    return 0;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 5;
    if (repeats < 1)
        repeats = 1;
    int rc = bench("unmodified", 0, repeats);
    rc |= bench("Table 2", 1, repeats);
    return rc;
}
