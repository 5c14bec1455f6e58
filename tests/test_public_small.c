/* Small public accessors and results that nothing else in the library or the command line calls:
 * 1. gd_flank_relief: the profile relief equals the case's root and tip amounts at the start of
 *    active profile and at the tip and is zero between; the lead feed times
 *    gd_flank_feed_projection at the reference roll angle equals the inner and outer lead amounts
 *    at the ends of the face (docs/geometry.md); the feed projection equals the component of the
 *    flank's outward normal along the feed, the space centre line e_x turned with the helix.
 * 2. gd_tca_operating_pressure_angle of a profile-shifted pair against ISO 21771,
 *    inv(a_wt) = inv(a_t) + 2 (x1+x2) tan(a_n)/(z1+z2), solved by bisection here.
 * 3. gd_tca_topography: the grid spans the pinion flank, is all NaN after a reset, and after
 *    separation-formulation positions holds separations >= 0 and ease-off >= separation.
 * 4. gd_ltca_halves: 2 for a herringbone pair, 1 for a single helical pair, equal to its TCA's.
 * 5. gd_sim_model returns the model given to gd_sim_create; gd_sim_period_index counts periods. */
#include "geardyn/geardyn.h"
#include "pair_util.h"
#include "tap.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CHECK(call)                                                                                                \
    do {                                                                                                           \
        gd_status st_ = (call);                                                                                    \
        if (st_ != GD_OK) {                                                                                        \
            printf("Bail out! %s:%d: %s: %s\n", __FILE__, __LINE__, #call, err.msg);                               \
            exit(1);                                                                                               \
        }                                                                                                          \
    } while (0)

static gd_error err;

static void make_case(gd_case *c, const char *const *sets, int n)
{
    CHECK(gd_case_init(c, &err));
    c->speed_rpm = 4000, c->torque_nm = 500; /* the paper's operating point: a case must give one */
    for (int i = 0; i < n; i++)
        CHECK(gd_case_set(c, sets[i], i + 1, &err));
    CHECK(gd_case_resolve(c, &err));
}

/* inverse involute by bisection on gd_involute */
static double inv_inv(double t)
{
    double lo = 0, hi = 1.4;
    for (int i = 0; i < 200; i++) {
        double m = 0.5 * (lo + hi);
        if (gd_involute(m) < t)
            lo = m;
        else
            hi = m;
    }
    return 0.5 * (lo + hi);
}

static void flank_relief(void)
{
    const char *sets[] = {"gear.arrangement=helical", "modification.root_relief_amount_um=10",
                          "modification.root_relief_length_mm=2", "modification.tip_relief_amount_um=15",
                          "modification.tip_relief_length_mm=3", "modification.lead_relief_inner_um=8",
                          "modification.lead_relief_outer_um=12", "modification.lead_unmodified_length_mm=20"};
    gd_case c;
    make_case(&c, sets, 8);
    gd_geometry g;
    CHECK(gd_geometry_compute(PAIR_OF(&c), &g, &err));
    gd_flank f;
    CHECK(gd_flank_pinion(PAIR_OF(&c), &g, 0, &f, &err));
    double rb = g.rb[0], h, l;
    gd_flank_relief(&f, g.rho_sap[0] / rb, 0, &h, &l);
    TAP_CLOSE(h, 10e-6, 1e-12, "root relief at the start of active profile = y1");
    TAP_CLOSE(l, 0, 0, "no lead feed in the middle of the face");
    gd_flank_relief(&f, g.rho_a[0] / rb, 0, &h, &l);
    TAP_CLOSE(h, 15e-6, 1e-12, "tip relief at the tip = y3");
    gd_flank_relief(&f, (g.rho_a[0] - 3e-3) / rb, 0, &h, &l);
    TAP_CLOSE(h, 0, 1e-15, "tip relief ends y4 below the tip");
    gd_flank_relief(&f, (g.rho_sap[0] + 2e-3) / rb, 0, &h, &l);
    TAP_CLOSE(h, 0, 1e-15, "root relief ends y2 above the start of active profile");
    double uref = tan(g.alpha_t), b = g.b[0];
    double proj = gd_flank_feed_projection(&f, uref);
    gd_flank_relief(&f, uref, -0.5 * b, &h, &l);
    TAP_CLOSE(l * proj, 8e-6, 1e-12, "lead feed x projection at the inner end (-z) = y5");
    gd_flank_relief(&f, uref, 0.5 * b, &h, &l);
    TAP_CLOSE(l * proj, 12e-6, 1e-12, "lead feed x projection at the outer end (+z) = y6");
    gd_flank_relief(&f, uref, 0.5 * 20e-3, &h, &l);
    TAP_CLOSE(l, 0, 1e-15, "lead feed zero at the end of the unmodified length");
    /* to first order: the projection is the unmodified flank's outward normal along the feed */
    gd_case c0;
    make_case(&c0, sets, 1);
    gd_flank f0;
    CHECK(gd_flank_pinion(PAIR_OF(&c0), &g, 0, &f0, &err));
    tap_ok(!f0.modified && f.modified, "flank without and with modification");
    double worst = 0;
    for (int i = 0; i <= 10; i++) {
        double u = f.u_min + (f.u_max - f.u_min) * i / 10.0, z = -0.5 * b + b * i / 10.0;
        gd_flank_eval e;
        gd_flank_eval_at(&f0, u, z, 1, &e);
        double n[3];
        gd_flank_normal(&e, n);
        /* the feed moves the space along its centre line, e_x turned with the helix by k z */
        double ang = f.k * z, along = n[0] * cos(ang) + n[1] * sin(ang);
        worst = fmax(worst, fabs(fabs(along) - gd_flank_feed_projection(&f, u)));
    }
    TAP_CLOSE(worst, 0, 1e-9, "feed projection = |n . e_x(z)| (space centre line) over the flank");
    gd_case_free(&c0);
    gd_case_free(&c);
}

static void operating_pressure_angle(void)
{
    const char *sets[] = {"gear.profile_shift_pinion=0.4", "gear.profile_shift_gear=-0.1", "gear.teeth_pinion=19"};
    gd_case c;
    make_case(&c, sets, 3);
    gd_tca *t;
    CHECK(gd_tca_create(PAIR_OF(&c), TCA_SET_OF(&c), &t, &err));
    const double d2r = M_PI / 180;
    double an = 20 * d2r, beta = 33.27 * d2r, at = atan(tan(an) / cos(beta));
    double awt = inv_inv(gd_involute(at) + 2 * (0.4 - 0.1) * tan(an) / (19 + 72));
    TAP_CLOSE(gd_tca_operating_pressure_angle(t), awt, 1e-10, "operating pressure angle of a shifted pair (ISO 21771)");
    gd_tca_free(t);
    gd_case_free(&c);
}

static void topography(void)
{
    gd_case c;
    make_case(&c, NULL, 0);
    gd_tca *t;
    CHECK(gd_tca_create(PAIR_OF(&c), TCA_SET_OF(&c), &t, &err));
    const gd_geometry *g = gd_tca_geometry(t);
    const gd_flank *f1 = gd_tca_flank(t, 0, 0);
    gd_tca_topography_reset(t);
    int np, nf;
    const double *rho, *z, *sep, *ease;
    gd_tca_topography(t, 0, &np, &nf, &rho, &z, &sep, &ease);
    tap_ok(np > 2 && nf > 2, "topography grid %d x %d", np, nf);
    int nan_all = 1;
    for (int n = 0; n < np * nf; n++)
        nan_all &= isnan(sep[n]) && isnan(ease[n]);
    tap_ok(nan_all, "topography all NaN after a reset");
    TAP_CLOSE(rho[np - 1], g->rho_a[0], 1e-12, "last profile node at the pinion tip");
    TAP_CLOSE(rho[0], f1->rb * f1->u_min, 1e-12, "first profile node at the lowest flank roll length");
    TAP_CLOSE(z[0], -0.5 * g->b[0], 1e-12, "first face node at one end of the face");
    TAP_CLOSE(z[nf - 1], 0.5 * g->b[0], 1e-12, "last face node at the other end");
    int mono = 1;
    for (int i = 1; i < np; i++)
        mono &= rho[i] > rho[i - 1];
    for (int j = 1; j < nf; j++)
        mono &= z[j] > z[j - 1];
    tap_ok(mono, "grid increasing");
    double tau1 = 2 * M_PI / g->z[0];
    for (int k = 0; k < 8; k++) {
        gd_tca_contact out;
        CHECK(gd_tca_contact_at(t, 0, GD_TCA_SEPARATION, tau1 * k / 8.0, &out, &err));
    }
    gd_tca_topography(t, 0, &np, &nf, &rho, &z, &sep, &ease);
    int finite = 0, ok_sep = 1, ok_ease = 1;
    double smin = INFINITY;
    for (int n = 0; n < np * nf; n++) {
        if (!isfinite(sep[n]))
            continue;
        finite++;
        smin = fmin(smin, sep[n]);
        ok_sep &= sep[n] >= -1e-12;
        ok_ease &= isfinite(ease[n]) && ease[n] >= sep[n] - 1e-12;
    }
    tap_ok(finite > np * nf / 4, "nodes met over a pitch: %d of %d", finite, np * nf);
    tap_ok(ok_sep, "separation >= 0 (least %.3g m)", smin);
    tap_ok(smin < 5e-6, "some node comes within 5 um of the first contact (%.3g m)", smin);
    tap_ok(ok_ease, "ease-off >= separation (the first contact gap is >= 0)");
    gd_tca_free(t);
    gd_case_free(&c);
}

static void ltca_halves(void)
{
    for (int k = 0; k < 2; k++) {
        const char *sets[] = {"gear.arrangement=helical"};
        gd_case c;
        make_case(&c, sets, k);
        gd_ltca *w;
        CHECK(gd_ltca_create(PAIR_OF(&c), LTCA_SET_OF(&c), &w, &err));
        tap_ok(gd_ltca_halves(w) == 2 - k, "gd_ltca_halves of a %s pair: %d", k ? "helical" : "herringbone",
               gd_ltca_halves(w));
        tap_ok(gd_ltca_halves(w) == gd_tca_halves(gd_ltca_tca(w)), "equal to its TCA workspace's halves");
        gd_ltca_free(w);
        gd_case_free(&c);
    }
}

static void sim_accessors(void)
{
    const char *sets[] = {"scene.model=torsional", "excitation.stiffness=constant", "scene.error_excitation=off"};
    gd_case c;
    make_case(&c, sets, 3);
    gd_model m;
    CHECK(gd_model_build(&c, &m, &err));
    gd_solver_opts o;
    gd_solver_opts_from_case(&c, &o);
    double y[GD_MAX_STATE] = {0};
    gd_modes md = {0};
    CHECK(gd_initial_state(&c, &m, y, &md, &err));
    gd_sim *s;
    CHECK(gd_sim_create(&m, &o, y, &md, &s, &err));
    const gd_model *sm = gd_sim_model(s);
    int same = sm && sm->kind == m.kind && sm->ndof == m.ndof && sm->n == m.n && sm->period == m.period &&
               sm->Omega == m.Omega && sm->nmesh == m.nmesh && sm->nclear == m.nclear;
    for (int i = 0; same && i < m.ndof; i++)
        same = sm->mass[i] == m.mass[i] && sm->F0[i] == m.F0[i];
    tap_ok(same, "gd_sim_model returns the model given to gd_sim_create");
    tap_ok(gd_sim_period_index(s) == 0, "period index 0 at the start");
    for (int k = 1; k <= 3; k++) {
        CHECK(gd_sim_period(s, &err));
        tap_ok(gd_sim_period_index(s) == k, "period index %ld after %d periods", gd_sim_period_index(s), k);
    }
    TAP_CLOSE(gd_sim_time(s), 3 * gd_sim_model(s)->period, 1e-9, "time after 3 periods = 3 x the model's period");
    gd_sim_free(s);
    gd_case_free(&c);
}

int main(void)
{
    gsl_set_error_handler_off();
    flank_relief();
    operating_pressure_angle();
    topography();
    ltca_halves();
    sim_accessors();
    return tap_done();
}
