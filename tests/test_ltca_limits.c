/* LTCA limits and convergence (docs/ltca.md section 9):
 *  1. as the load tends to zero the loaded transmission error tends to the geometric one: for a
 *     fixed pinion the gear lags by the half that touches first, for a floating pinion (unmodified
 *     flanks, n_z = -+sin(beta_b) exactly) by the mean of the two; the difference falls in
 *     proportion to the torque down to the GTE of the sliced contact lines, which tends to TCA's
 *     exact GTE as the slicing is refined;
 *  2. the results converge as the face is sliced finer (11, 21, 41, 81 slices per half): the mean
 *     mesh stiffness and the mean LTE at 11, 21 and 41 slices against 81 (with the face kernel
 *     averaged over the slices a uniform line load is exact at any slicing, so what remains is the
 *     resolution of the line ends: small, and not a clean power of the spacing), and the
 *     LTE amplitude;
 *  3. the mean stiffness over the cycle does not depend on the number of positions. */
#include "ltca_util.h"
#include "pair_util.h"
#include "geardyn/gd_geometry.h"

#include <math.h>
#include <stdlib.h>

/* The zero-load limit. Per position: the GTE of TCA (exact first contact of each half) and the
 * discrete GTE of the sliced contact lines (least gap over the points of each half); the gear
 * then lags by the half that touches first (fixed pinion) or by the mean of the two halves
 * (floating pinion, unmodified flanks: n_z = -+sin(beta_b) exactly). Returns the largest
 * |LTE - discrete GTE| (arcsec), and the largest |discrete GTE - TCA GTE| in *dtca. */
static double lte_gap(gd_case *c, double torque, int floating, double *lte_pp, double *gte_pp, double *dtca)
{
    c->torque_nm = torque;
    gd_error e = {0};
    gd_ltca_result r;
    gd_geometry g;
    if (gd_geometry_compute(PAIR_OF(c), &g, &e) != GD_OK ||
        gd_ltca_run_opts(PAIR_OF(c), LTCA_SET_OF(c), 16, 0, &r, &e) != GD_OK) {
        tap_ok(0, "LTCA at %g N m: %s", torque, e.msg);
        return NAN;
    }
    double s = g.rb[1] * cos(g.beta_b), d = 0, lo = INFINITY, hi = -INFINITY;
    *dtca = 0;
    for (int k = 0; k < r.npos; k++) {
        double wmin[2] = {INFINITY, INFINITY};
        for (int i = r.first[k]; i < r.first[k + 1]; i++)
            wmin[r.points[i].half] = fmin(wmin[r.points[i].half], r.points[i].gap);
        double gd_[2], gt[2];
        for (int h = 0; h < 2; h++) {
            gd_[h] = -lt_arcsec(wmin[h] / s);
            gt[h] = r.gte_arcsec[h][k];
        }
        double gdisc = floating ? 0.5 * (gd_[0] + gd_[1]) : fmax(gd_[0], gd_[1]);
        double gtca = floating ? 0.5 * (gt[0] + gt[1]) : fmax(gt[0], gt[1]);
        d = fmax(d, fabs(r.lte_arcsec[k] - gdisc));
        *dtca = fmax(*dtca, fabs(gdisc - gtca));
        lo = fmin(lo, gtca);
        hi = fmax(hi, gtca);
    }
    *lte_pp = r.lte_pp_arcsec;
    *gte_pp = hi - lo;
    gd_ltca_result_free(&r);
    return d;
}

static void limit(const char *label, int flags)
{
    gd_case c;
    if (lt_case(&c, flags, NULL))
        return;
    int floating = !(flags & LT_FIXED);
    double T[5] = {500, 5, 0.05, 0.0005, 0.000005}, d[5], lp[5], gp[5], dt[5];
    for (int i = 0; i < 5; i++) {
        d[i] = lte_gap(&c, T[i], floating, &lp[i], &gp[i], &dt[i]);
        printf("# %s, %g N m: max |LTE - GTE of the slices| %.6g arcsec; LTE p-p %.6g, GTE p-p (TCA) %.6g\n", label,
               T[i], d[i], lp[i], gp[i]);
    }
    char name[256];
    snprintf(name, sizeof name, "%s: |LTE - GTE| falls in proportion to the torque once the loaded set is the first "
             "contact alone (ratio 5e-4 -> 5e-6 N m)", label);
    TAP_REL(d[4] / d[3], 0.01, 0.01, name);
    snprintf(name, sizeof name, "%s: at 5e-6 N m the LTE is the GTE of the sliced lines (arcsec)", label);
    TAP_CLOSE(d[4], 0.0, 1e-5, name);
    printf("# %s: the sliced lines' GTE differs from TCA's exact first contact by up to %.4f arcsec (21 slices: a "
           "tip-edge first contact between two slices)\n", label, dt[4]);
    /* with finer slices the sliced GTE tends to TCA's */
    double dts[3];
    int ns[3] = {21, 41, 81};
    for (int s = 0; s < 3; s++) {
        c.ltca_face_slices = ns[s];
        double a, b;
        lte_gap(&c, 0.0005, floating, &a, &b, &dts[s]);
    }
    printf("# %s: largest |sliced GTE - TCA GTE| at 21, 41, 81 slices: %.5f, %.5f, %.5f arcsec (order %.2f)\n", label,
           dts[0], dts[1], dts[2], log2(dts[0] / dts[1]));
    tap_ok(dts[1] < 0.7 * dts[0] && dts[2] < 0.7 * dts[1], "%s: the zero-load LTE tends to TCA's GTE as the slicing "
           "is refined (%.4f, %.4f, %.4f arcsec)", label, dts[0], dts[1], dts[2]);
    gd_case_free(&c);
}

int main(void)
{
    /* 1. zero-load limit: the paper's unmodified pair with its errors (its first contacts lie on
     * the face ends, at slices of every slicing) */
    limit("paper unmodified, fixed pinion", LT_MIS | LT_FIXED);
    limit("paper unmodified, floating pinion", LT_MIS);

    /* 2. slicing: Table 2 with the paper's errors, floating pinion, 8 positions */
    int ns[4] = {11, 21, 41, 81};
    double km[4], lm[4], lpp[4];
    for (int s = 0; s < 4; s++) {
        gd_case c;
        char set[64];
        snprintf(set, sizeof set, "solver.ltca_face_slices=%d", ns[s]);
        km[s] = lm[s] = lpp[s] = NAN;
        if (lt_case(&c, LT_MIS | LT_MOD, set, NULL))
            continue;
        gd_error e = {0};
        gd_ltca_result r;
        if (gd_ltca_run_opts(PAIR_OF(&c), LTCA_SET_OF(&c), 8, 0, &r, &e) == GD_OK) {
            km[s] = r.stiffness_mean[0];
            lm[s] = r.lte_mean_arcsec;
            lpp[s] = r.lte_pp_arcsec;
            printf("# %d slices: mean stiffness %.8g N/m, mean LTE %.8g arcsec, LTE p-p %.6g arcsec, %.1f ms\n", ns[s],
                   km[s], lm[s], lpp[s], r.wall_s * 1e3);
            gd_ltca_result_free(&r);
        } else {
            tap_ok(0, "%d slices: %s", ns[s], e.msg);
        }
        gd_case_free(&c);
    }
    double ek[3], el[3];
    for (int s = 0; s < 3; s++) {
        ek[s] = fabs(km[s] / km[3] - 1);
        el[s] = fabs(lm[s] - lm[3]);
    }
    printf("# against 81 slices: mean stiffness %.2e, %.2e, %.2e (relative); mean LTE %.4f, %.4f, %.4f arcsec; LTE p-p "
           "differences %.4f, %.4f, %.4f arcsec\n", ek[0], ek[1], ek[2], el[0], el[1], el[2], fabs(lpp[0] - lpp[1]),
           fabs(lpp[1] - lpp[2]), fabs(lpp[2] - lpp[3]));
    tap_ok(ek[1] < ek[0] && ek[2] < ek[0] && ek[1] < 1e-3, "mean mesh stiffness converges with the slicing: 21 and 41 "
           "slices closer to 81 than 11, 21 slices (the default) within 0.1 %% (%.2e, %.2e, %.2e)", ek[0], ek[1], ek[2]);
    tap_ok(el[1] < el[0] && el[2] < el[0] && el[1] < 0.01, "mean LTE converges with the slicing: 21 and 41 slices "
           "closer to 81 than 11, 21 slices within 0.01 arcsec (%.4f, %.4f, %.4f)", el[0], el[1], el[2]);
    tap_ok(fabs(lpp[2] - lpp[3]) < fabs(lpp[0] - lpp[1]), "LTE amplitude: the 41-81 difference is below the 11-21 "
           "one (%.4f < %.4f arcsec)", fabs(lpp[2] - lpp[3]), fabs(lpp[0] - lpp[1]));

    /* 3. positions: the mean stiffness over the cycle with 8, 16, 32, 64 positions */
    gd_case c;
    if (!lt_case(&c, LT_MIS | LT_MOD, NULL)) {
        double kp[4];
        int np[4] = {8, 16, 32, 64};
        for (int i = 0; i < 4; i++) {
            double k[2];
            gd_error e = {0};
            double *kl = malloc(sizeof(double) * (size_t)np[i]);
            if (gd_ltca_mesh_stiffness(PAIR_OF(&c), LTCA_SET_OF(&c), np[i], kl, NULL, NULL, k, &e) != GD_OK)
                tap_ok(0, "positions: %s", e.msg);
            kp[i] = k[0];
            free(kl);
        }
        printf("# positions 8, 16, 32, 64: mean stiffness %.8g, %.8g, %.8g, %.8g N/m\n", kp[0], kp[1], kp[2], kp[3]);
        double spread = (fmax(fmax(kp[0], kp[1]), fmax(kp[2], kp[3])) - fmin(fmin(kp[0], kp[1]), fmin(kp[2], kp[3]))) /
                        kp[3];
        TAP_CLOSE(spread, 0.0, 1e-3, "the cycle's mean stiffness does not depend on the number of positions (spread "
                  "over 8 to 64, relative)");
        gd_case_free(&c);
    }
    return tap_done();
}
