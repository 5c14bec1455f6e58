/* The dynamic objective (gear-dynamic, gd_dynobj.h, docs/optimisation.md section 12) on the spur
 * pair of cases/guide/spur.ini with a tip relief, torsional model, LTCA stiffness and error:
 *  - continuation against brute force: at 120 N m over 3000-6000 rpm (a softening resonance with
 *    two folds and a coexisting high branch) the objective, the largest RMS mesh acceleration of
 *    every stable period-1 orbit, equals the largest of a sweep up and down the same speeds (61
 *    points, 50 rpm apart, 300 + 100 periods each) to within the sweep's grid: no swept value above
 *    it (1e-3), and it no higher than the sweep's largest plus that value's smaller change to a
 *    neighbour on its branch (a smooth peak between grid points rises above the larger of the two
 *    by less than the fall to the other side);
 *  - the torques combined: the largest and the duty-weighted mean of two torques equal those of
 *    the torques evaluated one at a time, bit for bit;
 *  - the flank enters: through the gear problem (variables y3, y4 applied to the case's pair) the
 *    objective equals gd_dyn_evaluate of the same flank, and the unmodified flank differs;
 *  - the objective is a function of the flank alone: 1 and 2 threads of random search on it give
 *    the same values;
 *  - the report after the optimum (gd_optpost.h), on 2 threads: each flank's curve and its largest
 *    stable value equal gd_dyn_evaluate of that flank on one thread, bit for bit; its value on bta
 *    equals a direct gd_dyn_evaluate on bta; the ranking is that of the values; the Harris map at
 *    the objective's torque equals gd_opt_gear_lte_pp there and holds 20 more torques from a tenth
 *    to 1.5 times it. TAP output. */
#include "geardyn/geardyn.h"
#include "physics_util.h"
#include "tap.h"

static const char *spur[] = {
    "scene.model=torsional", "gear.arrangement=spur", "gear.normal_module_mm=3", "gear.teeth_pinion=25",
    "gear.teeth_gear=60", "gear.helix_angle_deg=0", "gear.profile_shift_pinion=0.2", "gear.profile_shift_gear=-0.2",
    "gear.face_width_pinion_mm=30", "gear.face_width_gear_mm=30", "gear.bore_diameter_pinion_mm=30",
    "gear.bore_diameter_gear_mm=60", "operating.speed_rpm=4500", "operating.torque_nm=120",
    "clearance.backlash_um=80", "excitation.stiffness=ltca", "excitation.ste=ltca", "run.transient_periods=300",
    "run.record_periods=100", "modification.tip_relief_amount_um=10", "modification.tip_relief_length_mm=2", NULL};

static void spur_case(gd_case *c, const char *analysis, const char *const *extra)
{
    const char *sets[64];
    int n = 0;
    sets[n++] = analysis;
    for (int i = 0; spur[i]; i++)
        sets[n++] = spur[i];
    for (int i = 0; extra && extra[i]; i++)
        sets[n++] = extra[i];
    sets[n] = NULL;
    pu_case(c, sets);
}

static void settings(const gd_case *c, gd_dynobj_settings *s, int nt, const double *torques, const double *w)
{
    gd_dynobj_settings_from_case(c, s);
    s->ntorques = nt;
    for (int k = 0; k < nt; k++) {
        s->torques_nm[k] = torques[k];
        s->weights[k] = w ? w[k] : 1.0;
    }
    s->speed_from_rpm = 3000;
    s->speed_to_rpm = 6000;
    s->model = GD_MODEL_TORSIONAL;
    s->measure = GD_DYN_RMS_ACCEL;
}

static void against_sweep(void)
{
    gd_error e = {0};
    gd_case c;
    spur_case(&c, "scene.analysis=response", NULL);
    gd_dynobj_settings s;
    const double t120 = 120;
    settings(&c, &s, 1, &t120, NULL);
    gd_pair pair = gd_pair_from_case(&c);
    gd_dyn_result r;
    PU_CHECK(gd_dyn_evaluate(&c, &s, &pair, NULL, &r, &e), &e);
    const gd_dyn_curve *cv = &r.curve[0];
    int unstable = 0;
    for (int i = 0; i < cv->npts; i++)
        unstable += !cv->pt[i].stable;
    tap_ok(cv->branch_points > 20 && unstable > 0,
           "continuation: %d branch points, %d unstable (folds), %d swept, %d refined; %s", cv->branch_points,
           unstable, cv->swept_points, cv->refined_points, cv->branch_end);

    const char *ex[] = {"sweep.parameter=operating.speed_rpm", "sweep.from=3000", "sweep.to=6000", "sweep.points=61",
                        "sweep.mode=continuation", "sweep.direction=both", NULL};
    gd_case cs;
    spur_case(&cs, "scene.analysis=sweep", ex);
    gd_sweep_plan p;
    PU_CHECK(gd_sweep_plan_create(&cs, &p, &e), &e);
    gd_sweep_point *pts;
    PU_CHECK(gd_sweep_points_create(&p, &pts, &e), &e);
    gd_sweep_opts o;
    gd_sweep_opts_default(&o);
    o.threads = 2;
    PU_CHECK(gd_sweep_run(&cs, &p, pts, &o, &e), &e);
    int best = -1, failed = 0;
    for (int i = 0; i < p.nslots; i++) {
        failed += pts[i].status != GD_POINT_DONE;
        if (pts[i].status == GD_POINT_DONE && (best < 0 || pts[i].rms_accel_mps2[2] > pts[best].rms_accel_mps2[2]))
            best = i;
    }
    double S = pts[best].rms_accel_mps2[2], rise = INFINITY;
    /* the smaller change to a neighbour of the largest on its own chain (the other side may be a jump) */
    for (int d = -1; d <= 1; d += 2) {
        int j = best + d;
        if (j >= 0 && j < p.nslots && pts[j].chain == pts[best].chain && pts[j].status == GD_POINT_DONE)
            rise = fmin(rise, S - pts[j].rms_accel_mps2[2]);
    }
    tap_ok(failed == 0, "sweep: %d points, none failed", p.nslots);
    tap_ok(S <= r.value * (1 + 1e-3),
           "no swept value above the objective: sweep %.6g m/s^2 at %.0f rpm (%s, %s), objective %.6g at %.1f rpm", S,
           pts[best].value[0], gd_sweep_branch_name(pts[best].branch), pts[best].motion, r.value, cv->peak_speed_rpm);
    tap_ok(r.value <= S + rise, "the objective %.6g within the grid of the sweep's largest %.6g (+ %.4g)", r.value, S,
           rise);
    gd_sweep_points_free(&p, pts);
    gd_sweep_plan_free(&p);
    gd_case_free(&cs);
    gd_dyn_result_free(&r);
    gd_case_free(&c);
}

static void combined(void)
{
    gd_error e = {0};
    gd_case c;
    spur_case(&c, "scene.analysis=response", NULL);
    gd_pair pair = gd_pair_from_case(&c);
    const double T[2] = {60, 120}, W[2] = {3, 1};
    double one[2];
    for (int k = 0; k < 2; k++) {
        gd_dynobj_settings s;
        settings(&c, &s, 1, &T[k], NULL);
        gd_dyn_result r;
        PU_CHECK(gd_dyn_evaluate(&c, &s, &pair, NULL, &r, &e), &e);
        one[k] = r.value;
        gd_dyn_result_free(&r);
    }
    gd_dynobj_settings s;
    settings(&c, &s, 2, T, W);
    gd_dyn_result r;
    PU_CHECK(gd_dyn_evaluate(&c, &s, &pair, NULL, &r, &e), &e);
    tap_ok(r.value == fmax(one[0], one[1]) && r.curve[0].peak == one[0] && r.curve[1].peak == one[1],
           "worst case of 60 and 120 N m: %.6g = max(%.6g, %.6g)", r.value, one[0], one[1]);
    gd_dyn_result_free(&r);
    s.combine = GD_OPT_COMBINE_MEAN;
    PU_CHECK(gd_dyn_evaluate(&c, &s, &pair, NULL, &r, &e), &e);
    tap_ok(fabs(r.value - (3 * one[0] + one[1]) / 4) <= 1e-12 * r.value,
           "duty-weighted mean with weights 3, 1: %.6g = (3 x %.6g + %.6g) / 4", r.value, one[0], one[1]);
    gd_dyn_result_free(&r);
    gd_case_free(&c);
}

static void through_the_gear_problem(void)
{
    gd_error e = {0};
    gd_case c;
    const char *ex[] = {"optimize.objective=gear-dynamic", "optimize.variables=y3,y4", "optimize.torques_nm=120",
                        "optimize.speed_from_rpm=3000", "optimize.speed_to_rpm=6000", "optimize.budget_evals=4",
                        "optimize.population=2", "optimize.algorithm=random", NULL};
    spur_case(&c, "scene.analysis=optimize", ex);
    tap_ok(c.opt_dynamic_model == GD_MODEL_TORSIONAL && c.n_opt_torques == 1,
           "the case: dynamic_model derived torsional for a spur pair, one torque");
    gd_dynobj_settings s;
    gd_dynobj_settings_from_case(&c, &s);
    gd_dynobj *d;
    PU_CHECK(gd_dynobj_create(&c, &s, NULL, &d, &e), &e);
    gd_opt_gear_objective obj;
    gd_dynobj_objective(d, &obj);
    gd_opt_gear_vars v;
    PU_CHECK(gd_opt_gear_vars_parse("y3,y4", &v, &e), &e);
    double lo[GD_OPT_GEAR_NVARS], hi[GD_OPT_GEAR_NVARS];
    gd_opt_gear_bounds(&c, &v, lo, hi);
    gd_pair pair = gd_pair_from_case(&c);
    gd_ltca_settings set = gd_ltca_settings_from_case(&c);
    gd_opt_gear *g;
    PU_CHECK(gd_opt_gear_create(&pair, &set, &v, lo, hi, &g, &e), &e);
    PU_CHECK(gd_opt_gear_set_objectives(g, 1, &obj, NULL, &e), &e);
    const double x[2] = {20, 3};
    double f, aux[GD_OPT_MAX_AUX];
    PU_CHECK(gd_opt_gear_value(g, x, &f, aux, &e), &e);
    gd_pair t = pair;
    t.tip_relief_amount_um = 20;
    t.tip_relief_length_mm = 3;
    gd_dyn_result r;
    PU_CHECK(gd_dyn_evaluate(&c, &s, &t, NULL, &r, &e), &e);
    tap_ok(f == r.value && aux[0] == r.curve[0].peak && aux[1] == r.curve[0].method,
           "the gear problem's y3 = 20 um, y4 = 3 mm: %.6g m/s^2 = gd_dyn_evaluate of that flank (%s)", f,
           gd_dyn_method_name((int)aux[1]));
    gd_dyn_result_free(&r);
    t.tip_relief_amount_um = t.tip_relief_length_mm = 0;
    PU_CHECK(gd_dyn_evaluate(&c, &s, &t, NULL, &r, &e), &e);
    tap_ok(fabs(r.value - f) > 0.01 * f, "the unmodified flank differs: %.6g against %.6g m/s^2", r.value, f);
    gd_dyn_result_free(&r);

    /* random search, 1 and 2 threads: the same values */
    gd_opt_problem p;
    gd_opt_gear_problem(g, &p);
    double vals[2][6];
    for (int th = 1; th <= 2; th++) {
        gd_opt_settings os;
        gd_opt_settings_default(&os);
        os.algorithm = GD_OPT_RANDOM;
        os.budget = 6;
        os.population = 2;
        os.threads = th;
        os.seed = 5;
        os.keep_history = 1;
        gd_opt_result res;
        PU_CHECK(gd_opt_run(&p, &os, &res, &e), &e);
        for (int k = 0; k < 6; k++)
            vals[th - 1][k] = res.f_history ? res.f_history[k] : NAN;
        gd_opt_result_free(&res);
    }
    tap_ok(memcmp(vals[0], vals[1], sizeof vals[0]) == 0 && isfinite(vals[0][0]),
           "random search on gear-dynamic: 1 and 2 threads evaluate the same 6 values (first %.6g)", vals[0][0]);
    gd_opt_gear_free(g);
    gd_dynobj_free(d);
    gd_case_free(&c);
}

/* The largest value of the stable points of a curve. */
static double stable_max(const gd_dyn_curve *cv)
{
    double m = -INFINITY;
    for (int i = 0; i < cv->npts; i++)
        if (cv->pt[i].stable)
            m = fmax(m, cv->pt[i].value);
    return m;
}

static void after_the_optimum(void)
{
    gd_error e = {0};
    gd_case c;
    const char *ex[] = {"optimize.objective=gear-dynamic", "optimize.variables=y3,y4", "optimize.torques_nm=120",
                        "optimize.speed_from_rpm=3000", "optimize.speed_to_rpm=6000", "optimize.budget_evals=4",
                        "optimize.population=2", "optimize.algorithm=random", NULL};
    spur_case(&c, "scene.analysis=optimize", ex);
    gd_pair pairs[GD_OPTPOST_NFLANKS];
    for (int j = 0; j < GD_OPTPOST_NFLANKS; j++)
        pairs[j] = gd_pair_from_case(&c); /* the case's: tip relief 10 um over 2 mm */
    pairs[0].tip_relief_amount_um = pairs[0].tip_relief_length_mm = 0;
    pairs[2].tip_relief_amount_um = 20;
    pairs[2].tip_relief_length_mm = 3;
    gd_optpost p;
    PU_CHECK(gd_optpost_compute(&c, GD_OBJ_GEAR_DYNAMIC, pairs, 2, NULL, &p, &e), &e);
    gd_dynobj_settings s;
    gd_dynobj_settings_from_case(&c, &s);
    int same = 1, peaks = 1;
    for (int j = 0; j < GD_OPTPOST_NFLANKS; j++) {
        gd_dyn_result r;
        PU_CHECK(gd_dyn_evaluate(&c, &s, &pairs[j], NULL, &r, &e), &e);
        same &= r.value == p.curve[j].value && r.curve[0].npts == p.curve[j].curve[0].npts;
        for (int i = 0; same && i < r.curve[0].npts; i++) { /* field by field: the struct has padding */
            const gd_dyn_point *a = &r.curve[0].pt[i], *b = &p.curve[j].curve[0].pt[i];
            same &= a->speed_rpm == b->speed_rpm && a->value == b->value && a->source == b->source &&
                    a->stable == b->stable && a->period_n == b->period_n;
        }
        peaks &= stable_max(&p.curve[j].curve[0]) == p.curve[j].value && p.curve[j].curve[0].peak == p.curve[j].value;
        gd_dyn_result_free(&r);
    }
    tap_ok(same, "the three flanks' curves on 2 threads = gd_dyn_evaluate of each on one, point for point "
                 "(%.6g, %.6g, %.6g m/s^2)", p.curve[0].value, p.curve[1].value, p.curve[2].value);
    tap_ok(peaks, "each curve's largest stable point is the objective, bit for bit (%d, %d, %d points)",
           p.curve[0].curve[0].npts, p.curve[1].curve[0].npts, p.curve[2].curve[0].npts);
    s.model = GD_MODEL_BTA;
    gd_dyn_result r;
    PU_CHECK(gd_dyn_evaluate(&c, &s, &pairs[2], NULL, &r, &e), &e);
    tap_ok(p.bta_separate && r.value == p.on_bta[2].value && r.value != p.curve[2].value,
           "the optimum on bta: %.6g m/s^2 = gd_dyn_evaluate on bta, against %.6g on torsional", p.on_bta[2].value,
           p.curve[2].value);
    gd_dyn_result_free(&r);
    int ranks = 1;
    for (int i = 0; i < GD_OPTPOST_NFLANKS; i++)
        for (int j = 0; j < GD_OPTPOST_NFLANKS; j++)
            if (i != j)
                ranks &= (p.curve[i].value < p.curve[j].value) == (p.rank_loop[i] < p.rank_loop[j]) &&
                         (p.on_bta[i].value < p.on_bta[j].value) == (p.rank_bta[i] < p.rank_bta[j]);
    int agree = 1;
    for (int j = 0; j < GD_OPTPOST_NFLANKS; j++)
        agree &= p.rank_loop[j] == p.rank_bta[j];
    tap_ok(ranks && agree == p.same_ranking, "the rankings follow the values (the same on bta: %s; bta %.6g, %.6g, "
           "%.6g m/s^2)", p.same_ranking ? "yes" : "no", p.on_bta[0].value, p.on_bta[1].value, p.on_bta[2].value);
    int at = -1, grid = 0;
    for (int i = 0; i < p.nharris; i++) {
        if (p.harris_objective[i])
            at = i;
        grid += fabs(p.harris_torque_nm[i] - 120 * (0.1 + 1.4 * grid / 19.0)) < 1e-9 && !p.harris_objective[i];
    }
    gd_ltca_settings set = gd_ltca_settings_from_case(&c);
    set.torque_nm = 120;
    int lte_same = at >= 0;
    double v[GD_OPTPOST_NFLANKS] = {0};
    for (int j = 0; j < GD_OPTPOST_NFLANKS && lte_same; j++) {
        PU_CHECK(gd_opt_gear_lte_pp(&pairs[j], &set, &v[j], &e), &e);
        lte_same &= v[j] == p.harris_lte_pp_arcsec[j][at];
    }
    tap_ok(p.nharris == 21 && grid == 20 && lte_same,
           "the Harris map: 20 torques from 12 to 180 N m and the objective's 120 N m, where it is gd_opt_gear_lte_pp "
           "(%.6g, %.6g, %.6g arcsec)", v[0], v[1], v[2]);
    gd_optpost_free(&p);
    gd_case_free(&c);
}

int main(void)
{
    against_sweep();
    combined();
    through_the_gear_problem();
    after_the_optimum();
    return tap_done();
}
