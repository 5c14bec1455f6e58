/* LTCA contact problem (docs/ltca.md sections 3-5): over a mesh cycle of six cases (the paper's
 * pair with its errors, unmodified and with Table 2, floating and fixed pinion; a helical and a
 * spur pair) every position satisfies the conditions of Eq. 11 — load balance within 1e-9
 * relative (and the axial balance of a floating pinion), no negative load, no penetration beyond
 * 1e-9 mm, complementarity; the flexibility matrix is symmetric, positive definite and block
 * diagonal (tooth pairs uncoupled); the block active-set solver gives the loads of the dense
 * reference gd_contact_solve; with misalignment a fixed pinion's halves carry different loads,
 * a floating pinion's equal axial forces. */
#include "ltca_util.h"
#include "pair_util.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <stdlib.h>

static void check_cycle(const char *label, gd_case *c)
{
    gd_error e = {0};
    gd_ltca_result r;
    if (gd_ltca_run_opts(PAIR_OF(c), LTCA_SET_OF(c), 32, 0, &r, &e) != GD_OK) {
        tap_ok(0, "%s: %s", label, e.msg);
        return;
    }
    char name[256];
    snprintf(name, sizeof name, "%s: load balance over 32 positions (relative; axial too when floating)", label);
    TAP_CLOSE(r.max_balance, 0.0, 1e-9, name);
    snprintf(name, sizeof name, "%s: no negative load (least load, N)", label);
    tap_ok(r.min_load >= 0, "%s: %.3g", name, r.min_load);
    snprintf(name, sizeof name, "%s: no penetration beyond 1e-9 mm (largest, m)", label);
    TAP_CLOSE(r.max_penetration, 0.0, 1e-12, name);
    /* complementarity and the gap of every loaded point, from the stored points */
    double comp = 0, loaded_gap = 0;
    for (int i = 0; i < r.first[r.npos]; i++) {
        const gd_ltca_point *P = &r.points[i];
        comp = fmax(comp, fabs(P->load * P->deformed_gap));
        if (P->load > 0)
            loaded_gap = fmax(loaded_gap, fabs(P->deformed_gap));
    }
    snprintf(name, sizeof name, "%s: loaded points closed, |d| (m)", label);
    TAP_CLOSE(loaded_gap, 0.0, 1e-12, name);
    snprintf(name, sizeof name, "%s: complementarity max |p d| (N m)", label);
    TAP_CLOSE(comp, 0.0, 1e-12 * r.normal_force_n * 1e-3, name);
    printf("# %s: LTE %.4f arcsec p-p, stiffness %.4g / %.4g N/m, shares %.4f / %.4f, %ld iterations, "
           "residual %.2g m, %.1f ms\n", label, r.lte_pp_arcsec, r.stiffness_mean[0],
           r.halves > 1 ? r.stiffness_mean[1] : NAN, r.load_share[0], r.halves > 1 ? r.load_share[1] : NAN,
           r.iterations, r.max_residual, r.wall_s * 1e3);
    gd_ltca_result_free(&r);
}

/* L symmetric, positive definite (Cholesky), zero between tooth pairs; block and dense solvers agree */
static void check_matrix_and_solvers(const char *label, gd_case *c)
{
    gd_error e = {0};
    gd_ltca *w;
    if (gd_ltca_create(PAIR_OF(c), LTCA_SET_OF(c), &w, &e) != GD_OK) {
        tap_ok(0, "%s: %s", label, e.msg);
        return;
    }
    double asym = 0, cross = 0, dmin = INFINITY, pdiff = 0, zdiff = 0, fn = gd_ltca_normal_force(w, c->torque_nm);
    int pd = 1, nmax = 0, agree = 1;
    const double tau = 2 * M_PI / c->teeth_pinion;
    for (int k = 0; k < 8; k++) {
        gd_ltca_position pb, pd_;
        gd_ltca_use_dense_solver(w, 0);
        if (gd_ltca_solve_at(w, tau * k / 8, c->torque_nm, &pb, &e) != GD_OK) {
            tap_ok(0, "%s: %s", label, e.msg);
            break;
        }
        int n;
        const gd_ltca_point *pts = gd_ltca_points(w, &n);
        double *pblock = malloc(sizeof(double) * (size_t)n);
        for (int i = 0; i < n; i++)
            pblock[i] = pts[i].load;
        gd_contact_problem prob;
        gd_ltca_problem(w, &prob);
        nmax = n > nmax ? n : nmax;
        gsl_matrix *A = gsl_matrix_alloc((size_t)n, (size_t)n);
        for (int i = 0; i < n; i++) {
            dmin = fmin(dmin, prob.L[(size_t)i * n + i]);
            for (int j = 0; j < n; j++) {
                double v = prob.L[(size_t)i * n + j];
                gsl_matrix_set(A, (size_t)i, (size_t)j, v);
                asym = fmax(asym, fabs(v - prob.L[(size_t)j * n + i]));
                if (pts[i].half != pts[j].half || pts[i].pair != pts[j].pair)
                    cross = fmax(cross, fabs(v));
            }
        }
        gsl_error_handler_t *old = gsl_set_error_handler_off();
        pd &= gsl_linalg_cholesky_decomp1(A) == GSL_SUCCESS;
        gsl_set_error_handler(old);
        gsl_matrix_free(A);
        /* the same position again with the dense reference solver */
        gd_ltca_use_dense_solver(w, 1);
        if (gd_ltca_solve_at(w, tau * k / 8, c->torque_nm, &pd_, &e) != GD_OK) {
            tap_ok(0, "%s (dense): %s", label, e.msg);
            free(pblock);
            break;
        }
        pts = gd_ltca_points(w, &n);
        for (int i = 0; i < n; i++)
            pdiff = fmax(pdiff, fabs(pts[i].load - pblock[i]) / fn);
        zdiff = fmax(zdiff, fabs(pd_.approach - pb.approach) / fabs(pb.approach));
        agree &= pd_.loaded == pb.loaded;
        free(pblock);
    }
    gd_ltca_free(w);
    char name[256];
    snprintf(name, sizeof name, "%s: flexibility matrix symmetric (largest |L_ij - L_ji|, m/N)", label);
    TAP_CLOSE(asym, 0.0, 0.0, name);
    tap_ok(pd && dmin > 0, "%s: flexibility matrix positive definite (Cholesky at 8 positions, up to %d points; "
           "least diagonal %.3g m/N)", label, nmax, dmin);
    snprintf(name, sizeof name, "%s: points of different tooth pairs or halves uncoupled (largest entry)", label);
    TAP_CLOSE(cross, 0.0, 0.0, name);
    tap_ok(agree, "%s: block and dense solvers load the same points", label);
    snprintf(name, sizeof name, "%s: block solver loads = gd_contact_solve loads (max difference / F_n)", label);
    TAP_CLOSE(pdiff, 0.0, 1e-9, name);
    snprintf(name, sizeof name, "%s: and the same approach (relative)", label);
    TAP_CLOSE(zdiff, 0.0, 1e-9, name);
}

int main(void)
{
    gsl_set_error_handler_off();
    struct {
        const char *label;
        int flags;
        const char *extra[3];
    } cases[] = {
        {"paper unmodified, floating", LT_MIS, {NULL}},
        {"paper Table 2, floating", LT_MIS | LT_MOD, {NULL}},
        {"paper unmodified, fixed", LT_MIS | LT_FIXED, {NULL}},
        {"paper Table 2, fixed", LT_MIS | LT_MOD | LT_FIXED, {NULL}},
        {"helical Table 2 misaligned", LT_MIS | LT_MOD, {"gear.arrangement=helical", NULL}},
        {"spur aligned", 0, {"gear.arrangement=spur", "gear.helix_angle_deg=0", NULL}},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        gd_case c;
        if (lt_case(&c, cases[i].flags, cases[i].extra[0], cases[i].extra[1], cases[i].extra[2], NULL))
            continue;
        check_cycle(cases[i].label, &c);
        if (i == 1 || i == 2 || i == 5)
            check_matrix_and_solvers(cases[i].label, &c);
        gd_case_free(&c);
    }

    /* load sharing between the halves with a misalignment across the plane of the axes */
    gd_case cf, cl;
    if (!lt_case(&cf, LT_FIXED, "misalignment.axis_cross_plane_arcmin=0.1", NULL) &&
        !lt_case(&cl, 0, "misalignment.axis_cross_plane_arcmin=0.1", NULL)) {
        gd_error e = {0};
        gd_ltca_result rf, rl;
        if (gd_ltca_run_opts(PAIR_OF(&cf), LTCA_SET_OF(&cf), 16, 0, &rf, &e) == GD_OK &&
            gd_ltca_run_opts(PAIR_OF(&cl), LTCA_SET_OF(&cl), 16, 0, &rl, &e) == GD_OK) {
            printf("# delta_c = 0.1': fixed pinion shares %.4f / %.4f, floating %.4f / %.4f (axial shift %.3f um)\n",
                   rf.load_share[0], rf.load_share[1], rl.load_share[0], rl.load_share[1], rl.axial_shift[0] * 1e6);
            tap_ok(fabs(rf.load_share[0] - rf.load_share[1]) > 0.2,
                   "fixed pinion, 0.1' across the plane: the halves carry different loads (%.4f / %.4f)",
                   rf.load_share[0], rf.load_share[1]);
            TAP_CLOSE(rf.load_share[0] + rf.load_share[1], 1.0, 1e-9, "fixed pinion: the shares add up to 1");
            TAP_CLOSE(rl.load_share[0], 0.5, 1e-3, "floating pinion: equal axial forces make the shares equal (left)");
            tap_ok(fabs(rl.axial_shift[0]) > 1e-7, "floating pinion: it shifts axially to balance (%.3f um)",
                   rl.axial_shift[0] * 1e6);
            gd_ltca_result_free(&rf);
            gd_ltca_result_free(&rl);
        } else {
            tap_ok(0, "load sharing runs: %s", e.msg);
        }
        gd_case_free(&cf);
        gd_case_free(&cl);
    }
    return tap_done();
}
