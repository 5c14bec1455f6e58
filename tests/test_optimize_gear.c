/* The gear problem (docs/optimisation.md section 2): the objective is exactly the LTE amplitude of
 * the `ltca` analysis (two code paths, bit for bit); the constraint's right side is the active
 * profile of ISO 21771 (recomputed here); a corner of the box whose relief lengths do not fit is
 * repaired, not refused; evaluations in parallel give the run of one thread; a box holding a
 * modification that does not fit is refused with the key of the responsible bound; the helix slope
 * y9 alone finds the slope that cancels a tilt of the gear axis. TAP output. */
#include "geardyn/geardyn.h"
#include "pair_util.h"
#include "ltca_util.h"
#include "tap.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

typedef struct spy {
    double max_sum;          /* largest y2 + y4 given to the objective */
} spy;

/* on the gear box: maximise y2 + y4, which drives every optimiser into the constraint */
static gd_status spy_eval(void *state, const double *y, double *f, gd_error *err)
{
    (void)err;
    spy *s = state;
    s->max_sum = fmax(s->max_sum, y[1] + y[3]);
    *f = -(y[1] + y[3]);
    return GD_OK;
}

/* The gear problem of a case: its pair, its LTCA settings, its [optimize] bounds. */
static gd_status gear_create(const gd_case *c, gd_opt_gear **g, gd_error *e)
{
    double lower[GD_OPT_GEAR_NVARS], upper[GD_OPT_GEAR_NVARS];
    gd_opt_gear_vars v;
    gd_opt_gear_vars_paper(&v);
    gd_opt_gear_bounds(c, &v, lower, upper);
    return gd_opt_gear_create(PAIR_OF(c), LTCA_SET_OF(c), &v, lower, upper, g, e);
}

/* The helix slope y9 as the one design variable (optimize.variables = y9) on the guide's unmodified
 * single-helical pair with its gear axis tilted 1' across the plane of the axes: the optimum of the
 * loaded TE lies at the slope that cancels the tilt geometrically, delta_c b cos(beta_b)
 * cos(alpha_wt) (10.23 um; tests/test_tca_misaligned.c), within 0.5 um, and lowers the LTE. */
static void helix_slope(void)
{
    gd_error e = {0};
    gd_case c;
    const char *sets[] = {"scene.analysis=optimize", "gear.arrangement=helical", "gear.normal_module_mm=3.5",
                          "gear.teeth_pinion=21", "gear.teeth_gear=67", "gear.helix_angle_deg=20",
                          "gear.profile_shift_pinion=0.3", "gear.profile_shift_gear=-0.1",
                          "gear.face_width_pinion_mm=40", "gear.face_width_gear_mm=38",
                          "misalignment.axis_cross_plane_arcmin=1", "operating.torque_nm=350",
                          "optimize.variables=y9", "solver.ltca_positions_per_cycle=32", NULL};
    gd_case_init(&c, &e);
    for (int i = 0; sets[i]; i++)
        gd_case_set(&c, sets[i], i + 1, &e);
    gd_opt_gear_vars v;
    gd_opt_gear *g = NULL;
    double lo[GD_OPT_GEAR_NVARS], hi[GD_OPT_GEAR_NVARS];
    if (gd_case_resolve(&c, &e) != GD_OK || gd_opt_gear_vars_parse(c.opt_variables, &v, &e) != GD_OK) {
        tap_ok(0, "helix slope problem: %s", e.msg);
        gd_case_free(&c);
        return;
    }
    gd_opt_gear_bounds(&c, &v, lo, hi);
    tap_ok(v.n == 1 && v.var[0] == 8 && lo[0] == -hi[0] && hi[0] > 20,
           "optimize.variables = y9: one variable, bounds [%g, %g] um derived from the pair", lo[0], hi[0]);
    if (gd_opt_gear_create(PAIR_OF(&c), LTCA_SET_OF(&c), &v, lo, hi, &g, &e) != GD_OK) {
        tap_ok(0, "helix slope problem: %s", e.msg);
        gd_case_free(&c);
        return;
    }
    gd_opt_problem p;
    gd_opt_gear_problem(g, &p);
    gd_opt_settings s;
    gd_opt_settings_default(&s);
    s.algorithm = GD_OPT_GN_DIRECT_L;
    s.budget = 40;
    gd_opt_result r;
    double f0;
    gd_opt_gear_lte_pp(PAIR_OF(&c), LTCA_SET_OF(&c), &f0, &e);
    if (gd_opt_run(&p, &s, &r, &e) == GD_OK) {
        gd_geometry geo;
        gd_geometry_compute(PAIR_OF(&c), &geo, &e);
        double cancel = M_PI / (180 * 60) * geo.b[0] * cos(geo.beta_b) * cos(geo.alpha_wt) * 1e6;
        TAP_CLOSE(r.y[0], cancel, 0.5, "the helix slope of the least LTE (um) against the geometric cancellation "
                  "delta_c b cos(beta_b) cos(alpha_wt)");
        tap_ok(r.f < 0.8 * f0, "it lowers the LTE from %.4g to %.4g arcsec", f0, r.f);
        gd_opt_result_free(&r);
    } else {
        tap_ok(0, "DIRECT-L on y9: %s", e.msg);
    }
    gd_opt_gear_free(g);
    gd_case_free(&c);
}

int main(void)
{
    gsl_set_error_handler_off();
    gd_error e = {0};
    gd_case c;
    if (lt_case(&c, LT_MIS | LT_MOD, "solver.ltca_positions_per_cycle=12", (const char *)NULL))
        return tap_done();
    /* the objective at Table 2 against the ltca analysis */
    double f;
    gd_ltca_result r;
    if (gd_opt_gear_lte_pp(PAIR_OF(&c), LTCA_SET_OF(&c), &f, &e) == GD_OK &&
        gd_ltca_run_opts(PAIR_OF(&c), LTCA_SET_OF(&c), 0, 0, &r, &e) == GD_OK) {
        tap_ok(f == r.lte_pp_arcsec, "objective at Table 2 = LTE amplitude of gd_ltca_run: %.15g vs %.15g arcsec", f,
               r.lte_pp_arcsec);
        gd_ltca_result_free(&r);
    } else {
        tap_ok(0, "LTE amplitude: %s", e.msg);
    }
    double x[6], t2[6];
    gd_opt_gear_vars paper;
    gd_opt_gear_vars_paper(&paper);
    gd_opt_gear_from_pair(&paper, PAIR_OF(&c), x);
    {
        gd_pair t = *PAIR_OF(&c);
        gd_opt_gear_table2(&t);
        gd_opt_gear_from_pair(&paper, &t, t2);
    }
    tap_ok(memcmp(x, t2, sizeof x) == 0, "the Table 2 case holds x = [y1, y2, y3, y4, y5, y7] = Table 2");

    /* the problem: bounds of [optimize], the constraint y2 + y4 <= rho_a1 - rho_SAP1 */
    gd_case_set(&c, "scene.analysis=optimize", 90, &e);
    gd_case_set(&c, "optimize.root_relief_length_max_mm=12", 91, &e);
    gd_case_set(&c, "optimize.tip_relief_length_max_mm=14", 92, &e);
    gd_opt_gear *g = NULL;
    if (gd_case_resolve(&c, &e) != GD_OK || gear_create(&c, &g, &e) != GD_OK) {
        tap_ok(0, "gear problem: %s", e.msg);
        gd_case_free(&c);
        return tap_done();
    }
    gd_geometry geo;
    gd_geometry_compute(PAIR_OF(&c), &geo, &e);
    /* roll length of the tip and of the start of active profile from the radii (ISO 21771) */
    double rho_a = sqrt(geo.ra[0] * geo.ra[0] - geo.rb[0] * geo.rb[0]);
    double rho_a2 = sqrt(geo.ra[1] * geo.ra[1] - geo.rb[1] * geo.rb[1]);
    double rho_sap = geo.a * sin(geo.alpha_wt) - rho_a2;
    TAP_CLOSE(gd_opt_gear_active_profile_mm(g), (rho_a - rho_sap) * 1e3, 1e-9,
              "constraint: y2 + y4 <= active profile rho_a1 - (a sin alpha_wt - rho_a2) (mm)");
    gd_opt_problem p;
    gd_opt_gear_problem(g, &p);
    tap_ok(p.dim == 6 && p.ncons == 1 && p.A[1] == 1 && p.A[3] == 1 && p.A[0] == 0 && p.upper[1] == 12 &&
           p.upper[3] == 14 && p.lower[5] == 10 && p.upper[5] == 38, "the box of [optimize] and the one constraint row");

    /* the corner with both relief lengths at their upper bounds (26 mm > the active profile): repaired */
    {
        double anchor[6], y[6] = {60, 12, 60, 14, 60, 38}, z[6];
        gd_opt_problem_check(&p, anchor, &e);
        gd_opt_repair(&p, anchor, y, z);
        void *state;
        p.state_alloc(p.user, &state, &e);
        double fz = NAN;
        gd_status st = p.eval(state, z, &fz, &e);
        p.state_free(state);
        tap_ok(st == GD_OK && z[1] + z[3] <= gd_opt_gear_active_profile_mm(g) && isfinite(fz),
               "corner y2 = 12, y4 = 14 mm: repaired to %.4f + %.4f = %.4f mm on the %.4f mm profile, LTE %.4g arcsec",
               z[1], z[3], z[1] + z[3], gd_opt_gear_active_profile_mm(g), fz);
    }
    /* ALO on the gear, 1 and 2 threads: the same run (two populations of 4) */
    {
        gd_opt_settings s;
        gd_opt_settings_default(&s);
        s.algorithm = GD_OPT_ALO;
        s.population = 4;
        s.budget = 12;
        s.seed = 3;
        s.keep_history = 1;
        gd_opt_result a, b;
        s.threads = 1;
        gd_status sa = gd_opt_run(&p, &s, &a, &e);
        s.threads = 2;
        gd_status sb = sa == GD_OK ? gd_opt_run(&p, &s, &b, &e) : sa;
        if (sa == GD_OK && sb == GD_OK) {
            tap_ok(a.evaluations == 12 && b.evaluations == 12 &&
                   memcmp(a.f_history, b.f_history, 12 * sizeof(double)) == 0 && memcmp(a.y, b.y, 6 * sizeof(double)) == 0,
                   "ALO on gear-lte, 12 evaluations: 1 and 2 threads identical (best %.6g arcsec)", a.f);
            double y2y4 = a.y[1] + a.y[3];
            tap_ok(y2y4 <= gd_opt_gear_active_profile_mm(g), "its optimum fits: y2 + y4 = %.4f mm", y2y4);
            gd_opt_result_free(&a);
            gd_opt_result_free(&b);
        } else {
            tap_ok(0, "ALO on gear-lte: %s", e.msg);
        }
    }
    /* every optimiser sees the repaired problem: driven toward y2 + y4 > the profile, none evaluates
     * a point beyond it, and each ends on it */
    for (int alg = 0; alg < GD_OPT_NALGORITHMS; alg++) {
        if (!(gd_opt_algorithm_objectives(alg) & 1))
            continue; /* two objectives only: test_optimize_moalo.c */
        spy sp = {0};
        gd_opt_problem q = p;
        q.eval = spy_eval;
        q.state_alloc = NULL;
        q.state_free = NULL;
        q.user = &sp;
        gd_opt_settings s;
        gd_opt_settings_default(&s);
        s.algorithm = alg;
        s.budget = 400;
        s.population = 10;
        s.seed = 2;
        gd_opt_result a;
        double act = gd_opt_gear_active_profile_mm(g);
        if (gd_opt_run(&q, &s, &a, &e) == GD_OK) {
            tap_ok(sp.max_sum <= act && -a.f > act - 0.05,
                   "%s maximising y2 + y4 on the gear box: largest evaluated %.6f <= %.6f mm, best %.6f",
                   gd_opt_algorithm_name(alg), sp.max_sum, act, -a.f);
            gd_opt_result_free(&a);
        } else {
            tap_ok(0, "%s: %s", gd_opt_algorithm_name(alg), e.msg);
        }
    }
    gd_opt_gear_free(g);

    /* a box holding a modification that does not fit: y7 up to 40 mm = the face, with lead relief */
    {
        gd_error e2 = {0};
        gd_case_set(&c, "optimize.lead_unmodified_length_max_mm=40", 93, &e);
        gd_status st = gd_case_resolve(&c, &e2);
        tap_ok(st == GD_ERR_INPUT && strstr(e2.msg, "optimize.lead_unmodified_length_max_mm") &&
               strstr(e2.msg, "modification.lead_unmodified_length_mm"),
               "a box with y7 = 40 mm (no room for the lead relief) is refused: %s", e2.msg);
    }
    gd_case_free(&c);
    helix_slope();
    return tap_done();
}
