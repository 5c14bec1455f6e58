/* Convergence of the GTE as the flank grid and the angular step are refined (docs/tca.md,
 * section 7), on a point-contact case (Table 1 herringbone, crowned in profile and lead,
 * misaligned, with a centre-distance error):
 * 1. Without the Newton refinement the transmission error is the least gap over the grid nodes:
 *    its error against the refined (exact) minimum falls as the grid spacing h is halved, at the
 *    order of a sampled smooth minimum, h^2 (the observed order is printed).
 * 2. With the refinement every grid gives the same transmission error (grid independence).
 * 3. The GTE peak-to-peak sampled at N positions per mesh cycle converges as N doubles; its
 *    extremes sit at the changes of tooth pair, where the GTE has a corner, so the order is 1. */
#include "geardyn/geardyn.h"
#include "pair_util.h"
#include "tap.h"

#include <gsl/gsl_errno.h>
#include <stdlib.h>
#include <string.h>

#define ARCSEC (180.0 * 3600.0 / M_PI)

static const char *crown[] = {"modification.root_relief_amount_um=15", "modification.root_relief_length_mm=11",
                              "modification.tip_relief_amount_um=20", "modification.tip_relief_length_mm=11.5",
                              "modification.lead_relief_inner_um=15", "modification.lead_relief_outer_um=15",
                              "modification.lead_unmodified_length_mm=0", "misalignment.axis_in_plane_arcmin=0.3",
                              "misalignment.axis_cross_plane_arcmin=-0.4", "misalignment.centre_distance_error_mm=0.05",
                              "solver.tca_cycles=1"};

static gd_tca_result run_with(int np, int nz, int npos, int refine)
{
    gd_case c;
    gd_error err = {0};
    gd_case_init(&c, &err);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    int n = (int)(sizeof crown / sizeof crown[0]);
    for (int i = 0; i < n; i++)
        gd_case_set(&c, crown[i], i + 1, &err);
    char a[64], b[64], d[64], e[64];
    snprintf(a, sizeof a, "solver.tca_profile_points=%d", np);
    snprintf(b, sizeof b, "solver.tca_face_points=%d", nz);
    snprintf(d, sizeof d, "solver.tca_positions_per_cycle=%d", npos);
    snprintf(e, sizeof e, "solver.tca_refine=%s", refine ? "on" : "off");
    gd_case_set(&c, a, 20, &err);
    gd_case_set(&c, b, 21, &err);
    gd_case_set(&c, d, 22, &err);
    gd_case_set(&c, e, 23, &err);
    gd_tca_result r;
    if (gd_case_resolve(&c, &err) != GD_OK || gd_tca_run(PAIR_OF(&c), TCA_SET_OF(&c), &r, &err) != GD_OK) {
        printf("Bail out! %s\n", err.msg);
        exit(1);
    }
    gd_case_free(&c);
    return r;
}

int main(void)
{
    gsl_set_error_handler_off();
    enum { NG = 4 };
    int np[NG] = {6, 11, 21, 41}, nz[NG] = {9, 17, 33, 65};
    gd_tca_result exact = run_with(15, 21, 16, 1);
    /* 1. grid minimum without refinement */
    double errs[NG];
    for (int q = 0; q < NG; q++) {
        gd_tca_result r = run_with(np[q], nz[q], 16, 0);
        double s = 0;
        for (int h = 0; h < r.halves; h++)
            for (int k = 0; k < r.npos; k++)
                s += fabs(r.contact[h][k].te - exact.contact[h][k].te) * ARCSEC / (r.npos * r.halves);
        errs[q] = s;
        gd_tca_result_free(&r);
    }
    int decreasing = 1;
    for (int q = 1; q < NG; q++)
        if (!(errs[q] < errs[q - 1]))
            decreasing = 0;
    tap_ok(decreasing, "grid minimum: the mean TE error falls as the grid is refined (%.4g, %.4g, %.4g, %.4g arcsec)",
           errs[0], errs[1], errs[2], errs[3]);
    double order = log2(errs[NG - 2] / errs[NG - 1]);
    double order_mid = log2(errs[NG - 3] / errs[NG - 2]);
    printf("# grid orders: %.3f (%dx%d -> %dx%d), %.3f (%dx%d -> %dx%d)\n", order_mid, np[1], nz[1], np[2], nz[2],
           order, np[2], nz[2], np[3], nz[3]);
    TAP_CLOSE(order, 2.0, 0.5, "grid minimum: observed order of convergence in the grid spacing");
    /* 2. refined: grid independence */
    double worst = 0;
    for (int q = 0; q < NG; q++) {
        gd_tca_result r = run_with(np[q], nz[q], 16, 1);
        for (int h = 0; h < r.halves; h++)
            for (int k = 0; k < r.npos; k++)
                worst = fmax(worst, fabs(r.contact[h][k].te - exact.contact[h][k].te) * ARCSEC);
        gd_tca_result_free(&r);
    }
    TAP_CLOSE(worst, 0, 1e-6, "refined: the same TE on every grid from 6x9 to 41x65 (largest difference, arcsec)");
    gd_tca_result_free(&exact);
    /* 3. angular step */
    enum { NS = 5 };
    int npos[NS] = {8, 16, 32, 64, 128};
    double pp[NS][2];
    gd_tca_result ref = run_with(15, 21, 2048, 1);
    for (int q = 0; q < NS; q++) {
        gd_tca_result r = run_with(15, 21, npos[q], 1);
        for (int h = 0; h < 2; h++)
            pp[q][h] = fabs(r.gte_pp_arcsec[h] - ref.gte_pp_arcsec[h]);
        gd_tca_result_free(&r);
    }
    for (int h = 0; h < 2; h++) {
        int dec = 1;
        for (int q = 1; q < NS; q++)
            if (!(pp[q][h] <= pp[q - 1][h]))
                dec = 0;
        tap_ok(dec, "%s half: the GTE peak-to-peak error falls as the angular step is halved (%.3g %.3g %.3g %.3g %.3g "
               "arcsec against %.6g at 2048 positions)", h ? "right" : "left", pp[0][h], pp[1][h], pp[2][h], pp[3][h],
               pp[4][h], ref.gte_pp_arcsec[h]);
        double o = log2((pp[1][h] + pp[2][h]) / (pp[3][h] + pp[4][h])) / 2;
        printf("# %s half: angular step order %.3f\n", h ? "right" : "left", o);
        TAP_CLOSE(o, 1.0, 0.4, "observed order in the angular step (corners of the GTE at the tooth changes)");
    }
    gd_tca_result_free(&ref);
    return tap_done();
}
