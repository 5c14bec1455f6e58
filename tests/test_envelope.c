/* Curves of folds, period doublings and grazings of periodic orbits in two parameters
 * (gd_curve_follow, gd_envelope.h; docs/continuation.md section 8) on the Kahraman & Singh oscillator
 * with constant stiffness: zeta 0.05, F_m 0.1, in the plane of the mesh frequency Omega and the
 * excitation amplitude F_a (operating.speed_rpm and excitation.ste_amplitude_um through
 * gd_model_at_case_keys), started from the bifurcations of the one-parameter branch in Omega at
 * F_a 0.1 (Omega 0.5 .. 1.5), F_a 0.05 .. 0.2.
 *
 * 1. Closed form: the grazing curve of the non-impacting orbit is where its linear amplitude
 *    F_a Omega^2 / |1 - Omega^2 + 2 i zeta Omega| reaches F_m: at every point of both directions
 *    |F_a Omega^2 - F_m sqrt((1 - Omega^2)^2 + (2 zeta Omega)^2)| < 1e-8.
 * 2. Liouville: for one degree of freedom det M = exp(-2 zeta 2 pi / Omega) (the saltation matrices of
 *    the continuous dead-zone force are the identity), so on a fold curve tr M = 1 + det M and on a
 *    period-doubling curve tr M = -(1 + det M): at every point of the two fold curves and the
 *    period-doubling curve, both directions, to 1e-8; the critical multiplier is +1 (-1) to 1e-8.
 * 3. Consistency: one-parameter continuations in Omega at F_a 0.05, 0.08, 0.12, 0.14 and 0.16 find the
 *    grazing, the two folds and (from F_a 0.09 on) the period doubling where the curves, followed from
 *    F_a 0.1 to a bound at that F_a (the curve's point on the bound is corrected there), cross it: to
 *    1e-8 relative in Omega.
 * 4. No curve ends on a change of its orbit's contact events inside the box: the lower fold curve runs
 *    down to F_a 0.05 (an event that crosses the start of the orbit rotates the order of its events
 *    and is no contact change; a fingerprint of the events in their order ended it at F_a 0.051). */
#include "analysis_util.h"
#include "tap.h"
#include "geardyn/gd_envelope.h"

#include <math.h>
#include <string.h>

static const double ZETA = 0.05, FM = 0.1, FA0 = 0.1;
static const char *SETS[] = {"excitation.ste_phase_deg=90", "solver.rtol=1e-10", "solver.atol=1e-12", NULL};

/* the one-parameter branch from the attractor at Omega 0.5, F_a = fa, up to 1.5 */
static void branch_at(double fa, gd_branch *br)
{
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    gd_error e = {0};
    au_ks_case(&c, &m, 0.0, ZETA, FM, fa, 0.5, SETS);
    gd_solver_opts_from_case(&c, &o);
    double y[GD_MAX_STATE];
    gd_modes md;
    if (gd_initial_state(&c, &m, y, &md, &e) != GD_OK || gd_sim_period_map(&m, &o, y, 300, y, NULL, NULL, &e) != GD_OK)
        au_die(&e);
    gd_cont_opts co;
    gd_cont_opts_default(&co);
    co.p_min = 0.5;
    co.p_max = 1.5;
    co.ds_max = 0.05;
    gd_po start;
    if (gd_po_solve(&m, &o, &co.po, y, &start, &e) != GD_OK ||
        gd_continue(gd_model_at_mesh_frequency, &m, &o, &co, &start, br, &e) != GD_OK)
        au_die(&e);
    gd_case_free(&c);
}

/* the bifurcations of a branch by name: grazing (the first contact change), upper fold (above it),
 * lower fold (below it), period doubling (the highest in Omega: from F_a 0.16 on the branch has a
 * second one near Omega 0.63, on another curve); NULL when absent */
typedef struct named {
    const gd_bifurcation *b[4];
} named;
enum { GRAZE = 0, FOLD_HI = 1, FOLD_LO = 2, PD = 3 };
static const char *NAME[] = {"grazing", "upper fold", "lower fold", "period doubling"};

static named name_bifs(const gd_branch *br)
{
    named nb = {{NULL, NULL, NULL, NULL}};
    for (int i = 0; i < br->nbif; i++) {
        const gd_bifurcation *b = &br->bif[i];
        if (b->kind == GD_BIF_CONTACT_CHANGE && !nb.b[GRAZE])
            nb.b[GRAZE] = b;
        else if (b->kind == GD_BIF_PERIOD_DOUBLING && (!nb.b[PD] || b->p > nb.b[PD]->p))
            nb.b[PD] = b;
    }
    for (int i = 0; i < br->nbif && nb.b[GRAZE]; i++) {
        const gd_bifurcation *b = &br->bif[i];
        if (b->kind == GD_BIF_FOLD && b->p > nb.b[GRAZE]->p && !nb.b[FOLD_HI])
            nb.b[FOLD_HI] = b;
        else if (b->kind == GD_BIF_FOLD && b->p < nb.b[GRAZE]->p && !nb.b[FOLD_LO])
            nb.b[FOLD_LO] = b;
    }
    return nb;
}

static const int CURVE_OF[4] = {GD_CURVE_GRAZING, GD_CURVE_FOLD, GD_CURVE_FOLD, GD_CURVE_PERIOD_DOUBLING};

/* the curve of bifurcation b (of branch br at F_a 0.1) in direction dir, F_a in [lo, hi] */
static void follow(gd_case_param2 *pp, const gd_solver_opts *o, const gd_bifurcation *b, int kind, int dir, double lo,
                   double hi, gd_curve *cv)
{
    gd_error e = {0};
    gd_curve_opts co;
    gd_curve_opts_default(&co);
    co.p_min[0] = 0.5;
    co.p_max[0] = 1.5;
    co.p_min[1] = lo;
    co.p_max[1] = hi;
    co.direction = dir;
    gd_curve_start s;
    memset(&s, 0, sizeof s);
    s.kind = kind;
    s.nper = 1;
    s.clearance = kind == GD_CURVE_GRAZING ? b->clearance : -1;
    s.p1 = b->p;
    s.p2 = FA0;
    memcpy(s.y, b->y, sizeof s.y);
    if (gd_curve_follow(gd_model_at_case_keys, pp, o, &co, &s, cv, &e) != GD_OK)
        au_die(&e);
}

int main(void)
{
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    au_ks_case(&c, &m, 0.0, ZETA, FM, FA0, 0.5, SETS);
    gd_solver_opts_from_case(&c, &o);
    const double om = m.Omega / c.speed_rpm; /* Omega per rpm */
    gd_case_param2 pp = {&c, "operating.speed_rpm", "excitation.ste_amplitude_um", 1.0 / om, 1.0};
    gd_branch br;
    branch_at(FA0, &br);
    named nb = name_bifs(&br);
    tap_ok(nb.b[GRAZE] && nb.b[FOLD_HI] && nb.b[FOLD_LO] && nb.b[PD],
           "the branch at F_a 0.1 has a grazing, two folds and a period doubling (%d bifurcations)", br.nbif);
    if (!(nb.b[GRAZE] && nb.b[FOLD_HI] && nb.b[FOLD_LO] && nb.b[PD]))
        return tap_done();

    /* 1 and 2: every point of every curve, both directions over the whole box */
    for (int k = 0; k < 4; k++)
        for (int dir = -1; dir <= 1; dir += 2) {
            gd_curve cv;
            follow(&pp, &o, nb.b[k], CURVE_OF[k], dir, 0.05, 0.2, &cv);
            double worst = 0, worst_det = 0, worst_mu = 0;
            for (int i = 0; i < cv.npoints; i++) {
                const gd_po *q = &cv.pt[i].orbit;
                double Om = q->p, fa = cv.pt[i].p2;
                if (k == GRAZE) {
                    double r = fa * Om * Om - FM * sqrt(pow(1 - Om * Om, 2) + pow(2 * ZETA * Om, 2));
                    worst = fmax(worst, fabs(r));
                    continue;
                }
                double tr = q->M[0] + q->M[3], det = q->M[0] * q->M[3] - q->M[1] * q->M[2];
                double s = CURVE_OF[k] == GD_CURVE_FOLD ? 1.0 : -1.0;
                worst = fmax(worst, fabs(tr - s * (1.0 + det)));
                worst_det = fmax(worst_det, fabs(det - exp(-2.0 * ZETA * 2.0 * M_PI / Om)));
                double dmu = INFINITY; /* the multiplier nearest s */
                for (int j = 0; j < q->n; j++)
                    dmu = fmin(dmu, hypot(q->mu_re[j] - s, q->mu_im[j]));
                worst_mu = fmax(worst_mu, dmu);
            }
            const gd_curve_point *z = &cv.pt[cv.npoints - 1];
            printf("# %s curve %s: %d points to (%.8f, %.8f), %ld corrections, %ld Newton iterations: %s\n", NAME[k],
                   dir > 0 ? "up" : "down", cv.npoints, z->orbit.p, z->p2, cv.corrections, cv.newton_iterations,
                   cv.end_reason);
            tap_ok(cv.end != GD_CEND_CONTACT, "%s curve %s: no contact change ends it (%s)", NAME[k],
                   dir > 0 ? "up" : "down", gd_curve_end_name(cv.end));
            tap_ok(cv.npoints >= 10, "%s curve %s: %d points (%s)", NAME[k], dir > 0 ? "up" : "down", cv.npoints,
                   gd_curve_end_name(cv.end));
            if (k == GRAZE) {
                TAP_CLOSE(worst, 0.0, 1e-8, "grazing curve: F_a Omega^2 - F_m sqrt((1 - Omega^2)^2 + (2 zeta Omega)^2) "
                          "at every point");
            } else {
                tap_ok(worst < 1e-8, "%s curve %s: tr M %s (1 + det M) to %.2g at every point (Liouville)", NAME[k],
                       dir > 0 ? "up" : "down", CURVE_OF[k] == GD_CURVE_FOLD ? "=" : "= -", worst);
                tap_ok(worst_det < 1e-8, "%s curve %s: det M = exp(-4 pi zeta / Omega) to %.2g", NAME[k],
                       dir > 0 ? "up" : "down", worst_det);
                tap_ok(worst_mu < 1e-8, "%s curve %s: a multiplier at %s1 to %.2g at every point", NAME[k],
                       dir > 0 ? "up" : "down", CURVE_OF[k] == GD_CURVE_FOLD ? "+" : "-", worst_mu);
            }
            gd_curve_free(&cv);
        }

    /* 3: one-parameter runs at five values of F_a against the curves' points on the bound F_a */
    const double fas[] = {0.05, 0.08, 0.12, 0.14, 0.16};
    for (int f = 0; f < 5; f++) {
        gd_branch b2;
        branch_at(fas[f], &b2);
        named n2 = name_bifs(&b2);
        for (int k = 0; k < 4; k++) {
            if (k == PD && fas[f] < 0.09)
                continue; /* the period doubling leaves Omega 1.5 below F_a 0.081 */
            if (!n2.b[k]) {
                tap_ok(0, "F_a %.2f: the one-parameter branch has its %s", fas[f], NAME[k]);
                continue;
            }
            gd_curve cv;
            int dir = fas[f] > FA0 ? 1 : -1;
            follow(&pp, &o, nb.b[k], CURVE_OF[k], dir, dir > 0 ? 0.05 : fas[f], dir > 0 ? fas[f] : 0.2, &cv);
            const gd_curve_point *z = &cv.pt[cv.npoints - 1];
            double rel = fabs(z->orbit.p - n2.b[k]->p) / n2.b[k]->p;
            tap_ok(cv.end == GD_CEND_BOUND && fabs(z->p2 - fas[f]) < 1e-12 && rel < 1e-8,
                   "F_a %.2f: the %s of the one-parameter run at Omega %.10f, the curve's %.10f (rel %.2g; %s)", fas[f],
                   NAME[k], n2.b[k]->p, z->orbit.p, rel, cv.end_reason);
            gd_curve_free(&cv);
        }
        gd_branch_free(&b2);
    }
    gd_branch_free(&br);
    gd_case_free(&c);
    return tap_done();
}
