/* Benchmark: TCA of one full mesh cycle of both halves of the paper's herringbone pair, 64 pinion
 * positions per half, default flank grid (15 x 21), with each formulation: (b) surface separation
 * and (a) surface tangency, on the paper's two cases (cases/paper/tca-unmodified.ini and
 * tca-modified.ini: delta 0.5', dE 0.1 mm, without and with the Table 2 modification).
 * Timed twice: positions on a workspace created once (what LTCA inside an optimiser does) and the
 * whole gd_tca_run (workspace creation, topography and GTE included).
 * Usage: bench_tca [repeats]  (best of the repeats is reported) */
#include "geardyn/geardyn.h"

#include <gsl/gsl_errno.h>
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
    const char *base[] = {"scene.analysis=tca", "misalignment.axis_in_plane_arcmin=-0.35355339",
                          "misalignment.axis_cross_plane_arcmin=0.35355339", "misalignment.centre_distance_error_mm=0.1",
                          "solver.tca_positions_per_cycle=64", "solver.tca_cycles=1"};
    const char *mod[] = {"modification.root_relief_amount_um=25", "modification.root_relief_length_mm=1.5",
                         "modification.tip_relief_amount_um=35", "modification.tip_relief_length_mm=2.5",
                         "modification.lead_relief_inner_um=25", "modification.lead_relief_outer_um=25",
                         "modification.lead_unmodified_length_mm=35"};
    for (int i = 0; i < 6; i++)
        if (gd_case_set(c, base[i], i, err) != GD_OK)
            return 1;
    for (int i = 0; modified && i < 7; i++)
        if (gd_case_set(c, mod[i], 6 + i, err) != GD_OK)
            return 1;
    return gd_case_resolve(c, err) != GD_OK;
}

static int bench(const char *label, int modified, int formulation, int repeats)
{
    gd_case c;
    gd_error err = {0};
    if (make(&c, modified, &err)) {
        fprintf(stderr, "%s: %s\n", label, err.msg);
        return 1;
    }
    const gd_pair pair = gd_pair_from_case(&c);
    gd_tca_settings set = gd_tca_settings_from_case(&c);
    gd_tca *t;
    if (gd_tca_create(&pair, &set, &t, &err) != GD_OK) {
        fprintf(stderr, "%s: %s\n", label, err.msg);
        return 1;
    }
    double best = 1e300, pp[2] = {0, 0};
    long conv = 0, total = 0;
    for (int r = 0; r < repeats; r++) {
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
        conv = total = 0;
        double t0 = now();
        for (int h = 0; h < 2; h++)
            for (int k = 0; k < 64; k++) {
                gd_tca_contact ct;
                if (gd_tca_contact_at(t, h, formulation, k * (2 * M_PI / 30) / 64, &ct, &err) != GD_OK) {
                    fprintf(stderr, "%s: %s\n", label, err.msg);
                    return 1;
                }
                total++;
                if (ct.converged) {
                    conv++;
                    lo[h] = ct.te < lo[h] ? ct.te : lo[h];
                    hi[h] = ct.te > hi[h] ? ct.te : hi[h];
                }
            }
        double dt = now() - t0;
        if (dt < best)
            best = dt;
        for (int h = 0; h < 2; h++)
            pp[h] = (hi[h] - lo[h]) * 206264.806;
    }
    gd_tca_free(t);
    /* the whole analysis */
    double best_run = 1e300;
    set.formulation = formulation == GD_TCA_TANGENCY ? GD_TCA_TANGENCY : GD_TCA_SEPARATION;
    for (int r = 0; r < repeats; r++) {
        gd_tca_result res;
        double t0 = now();
        if (gd_tca_run(&pair, &set, &res, &err) != GD_OK) {
            fprintf(stderr, "%s: %s\n", label, err.msg);
            return 1;
        }
        double dt = now() - t0;
        if (dt < best_run)
            best_run = dt;
        gd_tca_result_free(&res);
    }
    printf("%-44s %8.2f ms  %7.1f us/position  gd_tca_run %8.2f ms  GTE p-p %.4f / %.4f arcsec  %ld/%ld contacts\n",
           label, best * 1e3, best * 1e6 / 128, best_run * 1e3, pp[0], pp[1], conv, total);
    gd_case_free(&c);
    return 0;
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    int repeats = argc > 1 ? atoi(argv[1]) : 5;
    printf("geardyn %s TCA: one mesh cycle, 64 positions per half, both halves, grid 15 x 21, best of %d\n",
           GD_VERSION_STRING, repeats);
    int rc = 0;
    rc |= bench("(b) separation, unmodified, delta, dE", 0, GD_TCA_SEPARATION, repeats);
    rc |= bench("(b) separation, Table 2, delta, dE", 1, GD_TCA_SEPARATION, repeats);
    rc |= bench("(a) tangency, unmodified, delta, dE", 0, GD_TCA_TANGENCY, repeats);
    rc |= bench("(a) tangency, Table 2, delta, dE", 1, GD_TCA_TANGENCY, repeats);
    return rc;
}
