/* The two TCA formulations against each other and the gap against a Newton solve
 * (docs/tca.md, sections 5 and 6):
 * 1. A point-contact case (Table 1 herringbone, profile crowned over the whole active profile and
 *    lead crowned over the whole face, misaligned both ways and with a centre-distance error):
 *    (a) surface tangency and (b) surface separation give the same transmission error within
 *    1e-3 arcsec at every position of both halves, at the same contact point.
 * 2. The paper's Table 2 case with delta = 0.5' and dE = 0.1 mm, where the gap has several local
 *    minima on each flank: the same agreement.
 * 3. The gap of (b), the gear rotation that closes it in closed form, equals the gear rotation a
 *    Newton solve of r_gear(u2, z2, phi2) = r_pinion finds (GSL hybridsj here, with the gear placed
 *    by the frames documented in docs/tca.md written out again). */
#include "geardyn/geardyn.h"
#include "pair_util.h"
#include "tap.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>
#include <stdlib.h>
#include <string.h>

#define ARCSEC (180.0 * 3600.0 / M_PI)

static double inv(double a) { return tan(a) - a; }

static gd_case make_case(const char *const *sets, int n)
{
    gd_case c;
    gd_error err = {0};
    gd_case_init(&c, &err);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    for (int i = 0; i < n; i++)
        if (gd_case_set(&c, sets[i], i + 1, &err) != GD_OK) {
            printf("Bail out! %s\n", err.msg);
            exit(1);
        }
    if (gd_case_resolve(&c, &err) != GD_OK) {
        printf("Bail out! %s\n", err.msg);
        exit(1);
    }
    return c;
}

static void compare(const char *label, const char *const *sets, int n)
{
    gd_case c = make_case(sets, n);
    gd_tca *t;
    gd_error err = {0};
    if (gd_tca_create(PAIR_OF(&c), TCA_SET_OF(&c), &t, &err) != GD_OK) {
        printf("Bail out! %s\n", err.msg);
        exit(1);
    }
    double worst = 0, worst_pt = 0;
    int conv = 1, npos = 0, same_pair = 1;
    for (int h = 0; h < gd_tca_halves(t); h++)
        for (int k = 0; k < 16; k++) {
            double phi = k * (2 * M_PI / 30) / 16;
            gd_tca_contact a, b;
            if (gd_tca_contact_at(t, h, GD_TCA_SEPARATION, phi, &b, &err) != GD_OK ||
                gd_tca_contact_at(t, h, GD_TCA_TANGENCY, phi, &a, &err) != GD_OK) {
                printf("Bail out! %s\n", err.msg);
                exit(1);
            }
            npos++;
            if (!a.converged) {
                conv = 0;
                continue;
            }
            worst = fmax(worst, fabs(a.te - b.te) * ARCSEC);
            if (a.pair != b.pair)
                same_pair = 0;
            else
                for (int d = 0; d < 3; d++)
                    worst_pt = fmax(worst_pt, fabs(a.pos[d] - b.pos[d]));
        }
    tap_ok(conv, "%s: (a) finds a contact at all %d positions", label, npos);
    char name[200];
    snprintf(name, sizeof name, "%s: largest |TE(a) - TE(b)| (arcsec)", label);
    TAP_CLOSE(worst, 0, 1e-3, name);
    tap_ok(same_pair, "%s: the same tooth pair touches first", label);
    snprintf(name, sizeof name, "%s: the same contact point (largest coordinate difference, m)", label);
    TAP_CLOSE(worst_pt, 0, 1e-6, name);
    gd_tca_free(t);
    gd_case_free(&c);
}

/* ---- 3. the gap by Newton ---------------------------------------------------------------------- */
typedef struct nctx {
    const gd_flank *f2;
    double X[3], C[3], M[9], theta2, zc, pair_tau2;
} nctx;

static void gear_point(const nctx *n, double u2, double z2, double phi2, double X[3], double J[9])
{
    gd_flank_eval e;
    gd_flank_eval_at(n->f2, u2, z2, 1, &e);
    double ang = M_PI + n->theta2 - (phi2 + n->pair_tau2), ca = cos(ang), sa = sin(ang);
    double v[3] = {ca * e.r[0] - sa * e.r[1], sa * e.r[0] + ca * e.r[1], e.r[2] + n->zc};
    double vu[3] = {ca * e.ru[0] - sa * e.ru[1], sa * e.ru[0] + ca * e.ru[1], e.ru[2]};
    double vz[3] = {ca * e.rz[0] - sa * e.rz[1], sa * e.rz[0] + ca * e.rz[1], e.rz[2]};
    double vp[3] = {v[1], -v[0], 0}; /* d/dphi2 of Rz(ang) x: -(J Rz x) */
    for (int i = 0; i < 3; i++) {
        X[i] = n->C[i] + n->M[3 * i] * v[0] + n->M[3 * i + 1] * v[1] + n->M[3 * i + 2] * v[2];
        J[3 * i + 0] = n->M[3 * i] * vu[0] + n->M[3 * i + 1] * vu[1] + n->M[3 * i + 2] * vu[2];
        J[3 * i + 1] = n->M[3 * i] * vz[0] + n->M[3 * i + 1] * vz[1] + n->M[3 * i + 2] * vz[2];
        J[3 * i + 2] = n->M[3 * i] * vp[0] + n->M[3 * i + 1] * vp[1] + n->M[3 * i + 2] * vp[2];
    }
}

static int nf(const gsl_vector *x, void *p, gsl_vector *f)
{
    nctx *n = p;
    double X[3], J[9];
    gear_point(n, gsl_vector_get(x, 0), gsl_vector_get(x, 1), gsl_vector_get(x, 2), X, J);
    for (int i = 0; i < 3; i++)
        gsl_vector_set(f, i, X[i] - n->X[i]);
    return GSL_SUCCESS;
}

static int ndf(const gsl_vector *x, void *p, gsl_matrix *Jm)
{
    nctx *n = p;
    double X[3], J[9];
    gear_point(n, gsl_vector_get(x, 0), gsl_vector_get(x, 1), gsl_vector_get(x, 2), X, J);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            gsl_matrix_set(Jm, i, j, J[3 * i + j]);
    return GSL_SUCCESS;
}

static int nfdf(const gsl_vector *x, void *p, gsl_vector *f, gsl_matrix *J)
{
    nf(x, p, f);
    return ndf(x, p, J);
}

int main(void)
{
    gsl_set_error_handler_off();
    const char *crown[] = {"modification.root_relief_amount_um=15", "modification.root_relief_length_mm=11",
                           "modification.tip_relief_amount_um=20", "modification.tip_relief_length_mm=11.5",
                           "modification.lead_relief_inner_um=15", "modification.lead_relief_outer_um=15",
                           "modification.lead_unmodified_length_mm=0", "misalignment.axis_in_plane_arcmin=0.3",
                           "misalignment.axis_cross_plane_arcmin=-0.4", "misalignment.centre_distance_error_mm=0.05"};
    compare("crowned point contact", crown, 10);
    const char *table2[] = {"modification.root_relief_amount_um=25", "modification.root_relief_length_mm=1.5",
                            "modification.tip_relief_amount_um=35", "modification.tip_relief_length_mm=2.5",
                            "modification.lead_relief_inner_um=25", "modification.lead_relief_outer_um=25",
                            "modification.lead_unmodified_length_mm=35", "misalignment.axis_in_plane_arcmin=-0.35355339",
                            "misalignment.axis_cross_plane_arcmin=0.35355339",
                            "misalignment.centre_distance_error_mm=0.1"};
    compare("Table 2, delta 0.5', dE 0.1 mm", table2, 10);

    /* 3. the closed-form gap against Newton */
    {
        gd_case c = make_case(crown, 10);
        gd_tca *t;
        gd_error err = {0};
        gd_tca_create(PAIR_OF(&c), TCA_SET_OF(&c), &t, &err);
        const gd_geometry *g = gd_tca_geometry(t);
        const double am = M_PI / (180 * 60);
        double di = 0.3 * am, dc = -0.4 * am;
        double Ry[9] = {cos(di), 0, sin(di), 0, 1, 0, -sin(di), 0, cos(di)};
        double Rx[9] = {1, 0, 0, 0, cos(dc), -sin(dc), 0, sin(dc), cos(dc)};
        nctx n;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                n.M[3 * i + j] = Rx[3 * i] * Ry[j] + Rx[3 * i + 1] * Ry[3 + j] + Rx[3 * i + 2] * Ry[6 + j];
        n.C[0] = g->a + 0.05e-3;
        n.C[1] = n.C[2] = 0;
        n.theta2 = g->eta_b[1] + inv(g->alpha_wt);
        gsl_multiroot_fdfsolver *s = gsl_multiroot_fdfsolver_alloc(gsl_multiroot_fdfsolver_hybridsj, 3);
        gsl_vector *x = gsl_vector_alloc(3);
        double worst = 0;
        int solved = 0, tried = 0;
        srand(7);
        for (int q = 0; q < 200; q++) {
            int half = q % 2, pair = (q / 2) % 3 - 1;
            double phi1 = (rand() / (double)RAND_MAX) * 2 * M_PI / 30;
            const gd_flank *f1 = gd_tca_flank(t, half, 0);
            double u1 = f1->u_min + (f1->u_max - f1->u_min) * rand() / (double)RAND_MAX;
            double z1 = f1->z_min + (f1->z_max - f1->z_min) * rand() / (double)RAND_MAX;
            double gap, r2, z2;
            if (!gd_tca_gap(t, half, phi1, pair, u1, z1, &gap, &r2, &z2))
                continue;
            tried++;
            n.f2 = gd_tca_flank(t, half, 1);
            n.zc = gd_tca_half_centre(t, half);
            n.pair_tau2 = pair * 2 * M_PI / 72;
            gd_tca_pinion_point(t, half, phi1, pair, u1, z1, n.X);
            gsl_multiroot_function_fdf F = {nf, ndf, nfdf, 3, &n};
            double phi2n = phi1 * 30.0 / 72;
            gsl_vector_set(x, 0, sqrt(r2 * r2 - pow(n.f2->rb, 2)) / n.f2->rb * 0.999);
            gsl_vector_set(x, 1, z2 + 1e-4);
            gsl_vector_set(x, 2, phi2n);
            if (gsl_multiroot_fdfsolver_set(s, &F, x) != GSL_SUCCESS)
                continue;
            int st = GSL_CONTINUE;
            for (int it = 0; it < 100 && st == GSL_CONTINUE; it++) {
                if (gsl_multiroot_fdfsolver_iterate(s) != GSL_SUCCESS)
                    break;
                st = gsl_multiroot_test_residual(s->f, 1e-14);
            }
            if (st != GSL_SUCCESS)
                continue;
            solved++;
            double phi2 = gsl_vector_get(s->x, 2);
            worst = fmax(worst, fabs((phi2n - phi2) - gap));
        }
        tap_ok(solved == tried && solved > 100, "Newton solved the gap of %d of %d pinion points", solved, tried);
        TAP_CLOSE(worst, 0, 1e-12, "closed-form gap = gear rotation from the Newton solve (largest difference, rad)");
        gsl_vector_free(x);
        gsl_multiroot_fdfsolver_free(s);
        gd_tca_free(t);
        gd_case_free(&c);
    }
    return tap_done();
}
