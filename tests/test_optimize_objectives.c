/* The gear objectives of docs/optimisation.md sections 12 and 13: gear-lte-range is the largest or the
 * duty-weighted mean of the LTE amplitudes at its torques, each the LTE of gd_opt_gear_lte_pp, and
 * the gear problem records each torque's; the robust variant is the 0.9 quantile over its Monte
 * Carlo sample, recomputed here from the sample's deviations; the sample is a function of the seed
 * alone and a run of random search on the robust objective evaluates the same values with 1 and 2
 * threads. TAP output. */
#include "geardyn/geardyn.h"
#include "tap.h"

#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static gd_case C;

static int spur_case(void)
{
    gd_error e = {0};
    const char *sets[] = {"scene.analysis=optimize", "gear.arrangement=spur", "gear.normal_module_mm=3",
                          "gear.teeth_pinion=25", "gear.teeth_gear=60", "gear.helix_angle_deg=0",
                          "gear.profile_shift_pinion=0.2", "gear.profile_shift_gear=-0.2",
                          "gear.face_width_pinion_mm=30", "gear.face_width_gear_mm=30", "operating.torque_nm=100",
                          "solver.ltca_positions_per_cycle=16", "solver.ltca_face_slices=9",
                          "optimize.variables=y1,y2,y3,y4", "misalignment.axis_in_plane_arcmin=0.3", NULL};
    gd_case_init(&C, &e);
    for (int i = 0; sets[i]; i++)
        gd_case_set(&C, sets[i], i + 1, &e);
    if (gd_case_resolve(&C, &e) != GD_OK) {
        tap_ok(0, "the spur pair: %s", e.msg);
        return 0;
    }
    return 1;
}

static gd_opt_gear *gear(const gd_opt_gear_vars *v, gd_error *e)
{
    double lo[GD_OPT_GEAR_NVARS], hi[GD_OPT_GEAR_NVARS];
    gd_opt_gear_bounds(&C, v, lo, hi);
    gd_pair pair = gd_pair_from_case(&C);
    gd_ltca_settings set = gd_ltca_settings_from_case(&C);
    gd_opt_gear *g = NULL;
    if (gd_opt_gear_create(&pair, &set, v, lo, hi, &g, e) != GD_OK)
        return NULL;
    return g;
}

int main(void)
{
    if (!spur_case())
        return tap_done();
    gd_error e = {0};
    gd_opt_gear_vars v;
    gd_opt_gear_vars_parse(C.opt_variables, &v, &e);
    const double x[4] = {8, 3, 10, 3}; /* y1, y2, y3, y4 */
    gd_pair pair = gd_pair_from_case(&C);
    gd_opt_gear_apply(&v, &pair, x);
    gd_ltca_settings set = gd_ltca_settings_from_case(&C);

    /* ---- gear-lte-range: max and mean of the separate amplitudes ------------------------------ */
    gd_opt_lte_range R = {.set = set, .n = 3, .torques_nm = {50, 100, 150}, .weights = {1, 2, 1}};
    double each[3], sep[3];
    for (int k = 0; k < 3; k++) {
        gd_ltca_settings s = set;
        s.torque_nm = R.torques_nm[k];
        gd_opt_gear_lte_pp(&pair, &s, &sep[k], &e);
    }
    double fmax_, fmean;
    R.combine = GD_OPT_COMBINE_MAX;
    gd_opt_lte_range_value(&R, &pair, &fmax_, each, &e);
    R.combine = GD_OPT_COMBINE_MEAN;
    gd_opt_lte_range_value(&R, &pair, &fmean, NULL, &e);
    tap_ok(each[0] == sep[0] && each[1] == sep[1] && each[2] == sep[2], "each torque's amplitude is gear-lte's at "
           "that torque, bit for bit: %.6g, %.6g, %.6g arcsec", sep[0], sep[1], sep[2]);
    tap_ok(fmax_ == fmax(fmax(sep[0], sep[1]), sep[2]), "max: %.9g", fmax_);
    TAP_CLOSE(fmean, (sep[0] + 2 * sep[1] + sep[2]) / 4, 1e-15 * fmean, "duty-weighted mean 1:2:1");

    /* ---- the gear problem with gear-lte-range records each torque ---------------------------- */
    gd_opt_gear *g = gear(&v, &e);
    gd_opt_gear_objective obj;
    R.combine = GD_OPT_COMBINE_MAX;
    gd_opt_lte_range_objective(&R, &obj);
    if (!g || gd_opt_gear_set_objectives(g, 1, &obj, NULL, &e) != GD_OK) {
        tap_ok(0, "gear problem: %s", e.msg);
        return tap_done();
    }
    double f[1], aux[GD_OPT_MAX_AUX];
    gd_opt_gear_value(g, x, f, aux, &e);
    tap_ok(f[0] == fmax_ && aux[0] == sep[0] && aux[2] == sep[2] && gd_opt_gear_naux(g) == 3,
           "the problem's value and its three recorded amplitudes");

    /* ---- robust: the 0.9 quantile of the sample, recomputed ---------------------------------- */
    gd_opt_robust rb = {.samples = 7, .seed = 11, .quantile = 0.9, .tilt_arcmin = 0.5, .centre_distance_mm = 0.05,
                        .amount_um = 2, .length_mm = 0.5};
    gd_opt_gear_set_objectives(g, 1, &obj, &rb, &e);
    const double *dev;
    int ns = gd_opt_gear_robust_sample(g, &dev);
    double rf[1], raux[GD_OPT_MAX_AUX];
    gd_opt_gear_value(g, x, rf, raux, &e);
    double lo[4], hi[4];
    gd_opt_gear_bounds(&C, &v, lo, hi);
    double vals[7];
    int inside = 1;
    for (int j = 0; j < ns; j++) {
        const double *d = dev + j * (3 + v.n);
        gd_pair p = gd_pair_from_case(&C);
        double y[4];
        for (int k = 0; k < 4; k++) {
            y[k] = fmin(fmax(x[k] + d[3 + k], lo[k]), hi[k]);
            inside = inside && fabs(d[3 + k]) <= (k % 2 ? 0.5 : 2.0);
        }
        /* y2 + y4 = 6 mm stays far inside the active profile: no repair */
        gd_opt_gear_apply(&v, &p, y);
        p.axis_in_plane_arcmin += d[0];
        p.axis_cross_plane_arcmin += d[1];
        p.centre_distance_error_mm += d[2];
        inside = inside && fabs(d[0]) <= 0.5 && fabs(d[1]) <= 0.5 && fabs(d[2]) <= 0.05;
        gd_opt_lte_range_value(&R, &p, &vals[j], NULL, &e);
    }
    gsl_sort(vals, 1, 7);
    double q = gsl_stats_quantile_from_sorted_data(vals, 1, 7, 0.9);
    tap_ok(ns == 7 && inside, "the sample: 7 draws, every deviation within its range");
    TAP_CLOSE(rf[0], q, 1e-15 * q, "the robust value is the 0.9 quantile of the sample's values");
    tap_ok(raux[0] == fmax_ && raux[1] == sep[0], "it records the nominal value first (%.6g), then its amplitudes",
           raux[0]);

    /* the sample depends on the seed only */
    gd_opt_gear *g2 = gear(&v, &e);
    gd_opt_gear_set_objectives(g2, 1, &obj, &rb, &e);
    const double *dev2;
    gd_opt_gear_robust_sample(g2, &dev2);
    tap_ok(memcmp(dev, dev2, sizeof(double) * 7 * (3 + v.n)) == 0, "the same seed draws the same sample");
    rb.seed = 12;
    gd_opt_gear_set_objectives(g2, 1, &obj, &rb, &e);
    gd_opt_gear_robust_sample(g2, &dev2);
    tap_ok(memcmp(dev, dev2, sizeof(double) * 7 * (3 + v.n)) != 0, "another seed another");
    rb.seed = 11;

    /* ---- 1 and 2 threads: the same evaluations of the robust objective --------------------------- */
    double *hist[2] = {NULL, NULL};
    long nev[2] = {0, 0};
    int nf = 0;
    for (int t = 0; t < 2; t++) {
        gd_opt_gear *gt = gear(&v, &e);
        gd_opt_gear_set_objectives(gt, 1, &obj, &rb, &e);
        gd_opt_problem p;
        gd_opt_gear_problem(gt, &p);
        nf = p.nobj + p.naux;
        gd_opt_settings s;
        gd_opt_settings_default(&s);
        s.algorithm = GD_OPT_RANDOM;
        s.budget = 8;
        s.population = 4;
        s.threads = t + 1;
        s.keep_history = 1;
        gd_opt_result r;
        if (gd_opt_run(&p, &s, &r, &e) == GD_OK) {
            hist[t] = r.fv_history;
            r.fv_history = NULL;
            nev[t] = r.evaluations;
            gd_opt_result_free(&r);
        } else {
            tap_ok(0, "random search on the robust objective: %s", e.msg);
        }
        gd_opt_gear_free(gt);
    }
    tap_ok(hist[0] && hist[1] && nev[0] == 8 && nev[1] == 8 &&
           memcmp(hist[0], hist[1], sizeof(double) * 8 * (size_t)nf) == 0,
           "the robust objective's every value (%d per evaluation) with 1 and 2 threads, bit for bit", nf);
    free(hist[0]);
    free(hist[1]);
    gd_opt_gear_free(g);
    gd_opt_gear_free(g2);
    gd_case_free(&C);
    return tap_done();
}
