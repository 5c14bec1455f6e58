/* TCA of aligned pairs (docs/tca.md, section 8), facts any correct TCA reproduces (Litvin):
 * 1. Aligned, unmodified (Table 1 herringbone): the GTE is identically zero (below 1e-6 arcsec);
 *    the instantaneous contact lines are straight, lie in the plane of action and are inclined at
 *    the base helix angle; the number of tooth pairs in contact is floor or ceil of the total
 *    contact ratio and averages it; the contact reaches the tooth ends (the paper's Fig. 9).
 * 2. Centre-distance error only (dE = 0.1 mm): the GTE is still zero; the operating pressure angle
 *    of every contact normal is acos(a cos(alpha_t) / (a + dE)); the contact lines lie in the moved
 *    plane of action (not in the nominal one); the gear lags by the constant angle
 *    (1 + z1/z2)(inv alpha' - inv alpha_t) the opened flanks need.
 * 3. Profile relief only, aligned: the transmission error equals the relief of the pair in contact
 *    turned into gear rotation, computed here independently as the first contact of the transverse
 *    sections (a planar involute problem written out again, with the relief moved along the
 *    generating line and the gear tip and form circles as limits): a spur pair, and the Table 1
 *    helical pair (a 10 mm face: on a wider face part of every contact line crosses the unmodified
 *    band and the TE stays zero) whose transverse section at z is the section z = 0 at pinion
 *    angle phi + k z. */
#include "geardyn/geardyn.h"
#include "pair_util.h"
#include "tap.h"

#include <gsl/gsl_errno.h>
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

static gd_tca_result run(const gd_case *c)
{
    gd_tca_result r;
    gd_error err = {0};
    if (gd_tca_run(PAIR_OF(c), TCA_SET_OF(c), &r, &err) != GD_OK) {
        printf("Bail out! %s\n", err.msg);
        exit(1);
    }
    return r;
}

/* ---- the planar involute pair, written out again (transverse section) ---------------------- */
typedef struct plane {
    double rb1, rb2, eta1, eta2, aw, a, ratio, tau1, tau2;
    double u1min, u1max, r2min, r2max;   /* pinion roll domain; gear radii of its flank */
    double rho_c, y1, y2, rho_g, y3, y4, cbb; /* relief (normal amounts, roll lengths) */
    double k1, b;                         /* twist rate and face of the helical pair (k1 = 0: spur) */
} plane;

static double relief_t(const plane *p, double u)
{
    double rho = p->rb1 * u, h = 0;
    if (p->y1 > 0 && rho < p->rho_c)
        h = p->y1 * pow((p->rho_c - rho) / p->y2, 2);
    else if (p->y3 > 0 && rho > p->rho_g)
        h = p->y3 * pow((rho - p->rho_g) / p->y4, 2);
    return h / p->cbb;
}

/* gap (gear rotation that closes it) of pinion roll u at pinion angle phi; 0 if not on the gear */
static int gap2d(const plane *p, double phi, double u, double *gap)
{
    double psi = -p->eta1 - u;
    double er[2] = {cos(psi), sin(psi)}, et[2] = {-sin(psi), cos(psi)};
    double h = relief_t(p, u);
    double x = p->rb1 * (er[0] + u * et[0]) - h * et[0], y = p->rb1 * (er[1] + u * et[1]) - h * et[1];
    double th1 = phi + p->eta1 + inv(p->aw); /* pinion phase: pitch-point contact at phi = 0 */
    double X = cos(th1) * x - sin(th1) * y, Y = sin(th1) * x + cos(th1) * y;
    double qx = X - p->a, qy = Y;
    double rot = -(M_PI + p->eta2 + inv(p->aw) - p->ratio * phi);
    double Qx = cos(rot) * qx - sin(rot) * qy, Qy = sin(rot) * qx + cos(rot) * qy;
    double r = hypot(Qx, Qy);
    if (r < p->r2min || r > p->r2max)
        return 0;
    double thf = -p->eta2 - inv(acos(p->rb2 / r));
    *gap = atan2(Qy, Qx) - thf;
    return 1;
}

/* least gap over the pinion roll at pinion angle phi (scan, then golden section and the feasible
 * boundary by bisection) */
static double min_over_u(const plane *p, double phi)
{
    enum { N = 300 };
    double best = INFINITY, ub = 0;
    int ib = -1, ok[N + 1];
    double g[N + 1], us[N + 1];
    for (int i = 0; i <= N; i++) {
        us[i] = p->u1min + (p->u1max - p->u1min) * i / N;
        ok[i] = gap2d(p, phi, us[i], &g[i]);
        if (ok[i] && g[i] < best) {
            best = g[i];
            ib = i;
            ub = us[i];
        }
    }
    if (ib < 0)
        return INFINITY;
    double lo = us[ib > 0 ? ib - 1 : 0], hi = us[ib < N ? ib + 1 : N];
    /* feasible limits next to the best sample */
    for (int s = 0; s < 2; s++) {
        int nb = s == 0 ? ib - 1 : ib + 1;
        if (nb < 0 || nb > N || ok[nb])
            continue;
        double a = us[ib], b = us[nb], gg;
        for (int it = 0; it < 200; it++) {
            double m = 0.5 * (a + b);
            if (gap2d(p, phi, m, &gg))
                a = m;
            else
                b = m;
        }
        gap2d(p, phi, a, &gg);
        if (gg < best) {
            best = gg;
            ub = a;
        }
        if (s == 0)
            lo = a;
        else
            hi = a;
    }
    /* golden section inside [lo, hi] */
    const double gr = 0.5 * (sqrt(5.0) - 1);
    double c = hi - gr * (hi - lo), d = lo + gr * (hi - lo), gc, gd;
    if (!gap2d(p, phi, c, &gc))
        gc = INFINITY;
    if (!gap2d(p, phi, d, &gd))
        gd = INFINITY;
    for (int it = 0; it < 200 && hi - lo > 1e-14; it++) {
        if (gc < gd) {
            hi = d; d = c; gd = gc; c = hi - gr * (hi - lo);
            if (!gap2d(p, phi, c, &gc)) gc = INFINITY;
        } else {
            lo = c; c = d; gc = gd; d = lo + gr * (hi - lo);
            if (!gap2d(p, phi, d, &gd)) gd = INFINITY;
        }
    }
    double gm;
    if (gap2d(p, phi, 0.5 * (lo + hi), &gm) && gm < best)
        best = gm;
    (void)ub;
    return best;
}

/* transmission error at pinion angle phi: least over the pairs and, for a helical pair, over the
 * face (the section at z is the section z = 0 at pinion angle phi + k1 z) */
static double te_expected(const plane *p, double phi)
{
    double best = INFINITY;
    for (int m = -4; m <= 4; m++) {
        double ph = phi + m * p->tau1;
        if (p->k1 == 0) {
            best = fmin(best, min_over_u(p, ph));
            continue;
        }
        double w = fabs(p->k1) * p->b / 2;
        enum { NZ = 80 };
        double gb = INFINITY, sb = 0;
        for (int j = 0; j <= NZ; j++) {
            double s = ph - w + 2 * w * j / NZ, gg = min_over_u(p, s);
            if (gg < gb) {
                gb = gg;
                sb = s;
            }
        }
        if (!isfinite(gb))
            continue;
        double lo = fmax(ph - w, sb - 2 * w / NZ), hi = fmin(ph + w, sb + 2 * w / NZ);
        const double gr = 0.5 * (sqrt(5.0) - 1);
        double c = hi - gr * (hi - lo), d = lo + gr * (hi - lo);
        double gc = min_over_u(p, c), gd = min_over_u(p, d);
        for (int it = 0; it < 100 && hi - lo > 1e-13; it++) {
            if (gc < gd) {
                hi = d; d = c; gd = gc; c = hi - gr * (hi - lo); gc = min_over_u(p, c);
            } else {
                lo = c; c = d; gc = gd; d = lo + gr * (hi - lo); gd = min_over_u(p, d);
            }
        }
        gb = fmin(gb, fmin(min_over_u(p, 0.5 * (lo + hi)), fmin(min_over_u(p, ph - w), min_over_u(p, ph + w))));
        best = fmin(best, gb);
    }
    return -best;
}

static void plane_init(plane *p, int z1, int z2, double beta_deg, double y1, double y2, double y3, double y4,
                       double b)
{
    double mn = 5e-3, beta = beta_deg * M_PI / 180, an = 20 * M_PI / 180;
    double mt = mn / cos(beta), at = atan(tan(an) / cos(beta));
    double r1 = z1 * mt / 2, r2 = z2 * mt / 2;
    p->rb1 = r1 * cos(at);
    p->rb2 = r2 * cos(at);
    double st = M_PI * mt / 2;
    p->eta1 = M_PI / z1 - (st / (2 * r1) + inv(at));
    p->eta2 = M_PI / z2 - (st / (2 * r2) + inv(at));
    p->aw = at;
    p->a = r1 + r2;
    p->ratio = (double)z1 / z2;
    p->tau1 = 2 * M_PI / z1;
    p->tau2 = 2 * M_PI / z2;
    double ra1 = r1 + mn, ra2 = r2 + mn;
    double rho_form1 = r1 * sin(at) - mn / sin(at), rho_form2 = r2 * sin(at) - mn / sin(at);
    p->u1min = rho_form1 / p->rb1;
    p->u1max = sqrt(ra1 * ra1 - p->rb1 * p->rb1) / p->rb1;
    p->r2min = hypot(p->rb2, rho_form2);
    p->r2max = ra2;
    double rho_sap = p->a * sin(at) - sqrt(ra2 * ra2 - p->rb2 * p->rb2);
    p->y1 = y1;
    p->y2 = y2;
    p->rho_c = rho_sap + y2;
    p->y3 = y3;
    p->y4 = y4;
    p->rho_g = p->rb1 * p->u1max - y4;
    p->cbb = cos(asin(sin(beta) * cos(an)));
    p->k1 = tan(beta) / r1;
    p->b = b;
}

int main(void)
{
    gsl_set_error_handler_off();
    const double deg = M_PI / 180;
    /* reference geometry of Table 1 */
    double mn = 5e-3, beta = 33.27 * deg, an = 20 * deg;
    double mt = mn / cos(beta), at = atan(tan(an) / cos(beta));
    double r1 = 15 * mt, r2 = 36 * mt, rb1 = r1 * cos(at), rb2 = r2 * cos(at), a = r1 + r2;
    double bb = atan(tan(beta) * cos(at));
    double ga1 = sqrt(pow(r1 + mn, 2) - rb1 * rb1), ga2 = sqrt(pow(r2 + mn, 2) - rb2 * rb2);
    double pbt = M_PI * mt * cos(at);
    double eps_g = (ga1 + ga2 - a * sin(at)) / pbt + 40e-3 * sin(beta) / (M_PI * mn);

    /* 1. aligned, unmodified */
    {
        const char *s[] = {"solver.tca_positions_per_cycle=64", "solver.tca_cycles=2"};
        gd_case c = make_case(s, 2);
        gd_tca_result r = run(&c);
        double worst = 0;
        int pairs_ok = 1;
        double pmean = 0;
        unsigned ends = 0;
        for (int h = 0; h < r.halves; h++)
            for (int k = 0; k < r.npos; k++) {
                worst = fmax(worst, fabs(r.gte_arcsec[h][k]));
                int np = r.contact[h][k].pairs_in_contact;
                if (np != (int)floor(eps_g) && np != (int)ceil(eps_g))
                    pairs_ok = 0;
                pmean += (double)np / (r.npos * r.halves);
                ends |= r.contact[h][k].edge;
            }
        TAP_CLOSE(worst, 0, 1e-6, "aligned unmodified: largest |GTE| over 2 cycles, both halves (arcsec)");
        TAP_CLOSE(r.contact[0][0].te * ARCSEC, 0, 1e-6, "aligned unmodified: absolute transmission error (arcsec)");
        tap_ok(pairs_ok, "pairs in contact are always floor or ceil of the total contact ratio %.4f", eps_g);
        TAP_CLOSE(pmean, eps_g, 2.0 / 64, "mean number of pairs in contact equals the total contact ratio");
        tap_ok((ends & (GD_EDGE_PINION_END_LO | GD_EDGE_PINION_END_HI)) != 0,
               "the contact lines reach the tooth ends (edge bits %#x; the paper's Fig. 9)", ends);
        gd_tca_result_free(&r);

        /* contact lines */
        gd_tca *t;
        gd_error err = {0};
        gd_tca_create(PAIR_OF(&c), TCA_SET_OF(&c), &t, &err);
        double dplane = 0, dline = 0, dangle = 0;
        int nlines = 0, npts = 0;
        double np_[3] = {cos(at), -sin(at), 0};
        for (int h = 0; h < 2; h++)
            for (int k = 0; k < 8; k++) {
                const gd_tca_line_point *pts;
                int n;
                if (gd_tca_lines_at(t, h, k * (2 * M_PI / 30) / 8, 1e-9, &pts, &n, &err) != GD_OK) {
                    printf("Bail out! %s\n", err.msg);
                    return 1;
                }
                npts += n;
                for (int i = 0; i < n; i++)
                    dplane = fmax(dplane, fabs(np_[0] * pts[i].pos[0] + np_[1] * pts[i].pos[1] - rb1));
                /* per pair: straight, at the base helix angle to the axis */
                for (int pr = -4; pr <= 4; pr++) {
                    int first = -1, last = -1, cnt = 0;
                    for (int i = 0; i < n; i++)
                        if (pts[i].pair == pr) {
                            if (first < 0)
                                first = i;
                            last = i;
                            cnt++;
                        }
                    if (cnt < 3)
                        continue;
                    nlines++;
                    double v[3], L2 = 0;
                    for (int d = 0; d < 3; d++) {
                        v[d] = pts[last].pos[d] - pts[first].pos[d];
                        L2 += v[d] * v[d];
                    }
                    for (int i = 0; i < n; i++) {
                        if (pts[i].pair != pr)
                            continue;
                        double w[3], tt = 0, d2 = 0;
                        for (int d = 0; d < 3; d++) {
                            w[d] = pts[i].pos[d] - pts[first].pos[d];
                            tt += w[d] * v[d] / L2;
                        }
                        for (int d = 0; d < 3; d++)
                            d2 += pow(w[d] - tt * v[d], 2);
                        dline = fmax(dline, sqrt(d2));
                    }
                    dangle = fmax(dangle, fabs(acos(fabs(v[2]) / sqrt(L2)) - bb));
                }
            }
        tap_ok(nlines >= 16 && npts > 100, "contact lines found (%d lines, %d points)", nlines, npts);
        TAP_CLOSE(dplane, 0, 1e-9, "contact lines lie in the plane of action (largest distance, m)");
        TAP_CLOSE(dline, 0, 1e-9, "contact lines are straight (largest distance from the chord, m)");
        TAP_CLOSE(dangle, 0, 1e-9, "contact lines are inclined at the base helix angle to the axis (rad)");
        gd_tca_free(t);
        gd_case_free(&c);
    }

    /* 2. centre-distance error only */
    {
        double dE = 0.1e-3;
        const char *s[] = {"misalignment.centre_distance_error_mm=0.1", "solver.tca_positions_per_cycle=32"};
        gd_case c = make_case(s, 2);
        gd_tca_result r = run(&c);
        double aop = acos(a * cos(at) / (a + dE));
        double worst = 0, wa = 0, wte = 0;
        double te_exp = -(1 + 30.0 / 72) * (inv(aop) - inv(at));
        for (int h = 0; h < r.halves; h++)
            for (int k = 0; k < r.npos; k++) {
                worst = fmax(worst, fabs(r.gte_arcsec[h][k]));
                wa = fmax(wa, fabs(r.contact[h][k].alpha_op - aop));
                wte = fmax(wte, fabs(r.contact[h][k].te - te_exp));
            }
        TAP_CLOSE(worst, 0, 1e-6, "centre-distance error only: largest |GTE| (arcsec)");
        TAP_CLOSE(wa, 0, 1e-9, "operating pressure angle of every contact normal = acos(a cos(alpha_t)/(a + dE)) (rad)");
        TAP_CLOSE(r.alpha_op_mean * 180 / M_PI, aop * 180 / M_PI, 1e-7, "operating pressure angle reported (deg)");
        TAP_CLOSE(wte * ARCSEC, 0, 1e-6, "constant lag (1 + z1/z2)(inv alpha' - inv alpha_t) of the opened flanks (arcsec)");
        gd_tca_result_free(&r);
        gd_tca *t;
        gd_error err = {0};
        gd_tca_create(PAIR_OF(&c), TCA_SET_OF(&c), &t, &err);
        double dmoved = 0, dnominal = INFINITY;
        double nm[3] = {cos(aop), -sin(aop), 0}, nn[3] = {cos(at), -sin(at), 0};
        for (int k = 0; k < 4; k++) {
            const gd_tca_line_point *pts;
            int n;
            gd_tca_lines_at(t, 0, k * (2 * M_PI / 30) / 4, 1e-9, &pts, &n, &err);
            for (int i = 0; i < n; i++) {
                dmoved = fmax(dmoved, fabs(nm[0] * pts[i].pos[0] + nm[1] * pts[i].pos[1] - rb1));
                dnominal = fmin(dnominal, fabs(nn[0] * pts[i].pos[0] + nn[1] * pts[i].pos[1] - rb1));
            }
        }
        TAP_CLOSE(dmoved, 0, 1e-9, "contact lines lie in the plane of action at the operating pressure angle (m)");
        tap_ok(dnominal > 1e-6, "and off the nominal plane of action (nearest %.3g m)", dnominal);
        gd_tca_free(t);
        gd_case_free(&c);
    }

    /* 3. profile relief only, aligned: spur, then the Table 1 helical pair */
    for (int helical = 0; helical < 2; helical++) {
        plane p;
        double y1 = 15e-6, y2 = 6e-3, y3 = 20e-6, y4 = 8e-3;
        if (helical) {
            y1 = 25e-6; y2 = 9e-3; y3 = 35e-6; y4 = 11e-3;
        }
        plane_init(&p, 30, 72, helical ? 33.27 : 0, y1, y2, y3, y4, helical ? 10e-3 : 40e-3);
        if (!helical)
            p.k1 = 0;
        char b1[64], b2[64], b3[64], b4[64];
        snprintf(b1, sizeof b1, "modification.root_relief_amount_um=%g", y1 * 1e6);
        snprintf(b2, sizeof b2, "modification.root_relief_length_mm=%g", y2 * 1e3);
        snprintf(b3, sizeof b3, "modification.tip_relief_amount_um=%g", y3 * 1e6);
        snprintf(b4, sizeof b4, "modification.tip_relief_length_mm=%g", y4 * 1e3);
        const char *spur[] = {b1, b2, b3, b4, "gear.arrangement=spur", "gear.helix_angle_deg=0",
                              "solver.tca_positions_per_cycle=16", "solver.tca_cycles=1"};
        /* a narrow helical pair (overlap ratio 0.35): on the 40 mm face some part of every contact
         * line crosses the unmodified band and the TE stays zero */
        const char *hel[] = {b1, b2, b3, b4, "gear.arrangement=helical", "gear.face_width_pinion_mm=10",
                             "gear.face_width_gear_mm=12", "solver.tca_positions_per_cycle=16", "solver.tca_cycles=1"};
        gd_case c = helical ? make_case(hel, 9) : make_case(spur, 8);
        gd_tca_result r = run(&c);
        double worst = 0, lo = INFINITY, hi = -INFINITY;
        for (int k = 0; k < r.npos; k++) {
            double e = te_expected(&p, r.phi1[k]);
            worst = fmax(worst, fabs(r.contact[0][k].te - e) * ARCSEC);
            lo = fmin(lo, e);
            hi = fmax(hi, e);
        }
        char name[160];
        snprintf(name, sizeof name, "%s, profile relief only: largest |TE - relief turned into gear rotation| over %d "
                 "positions (arcsec; expected TE spans %.4g arcsec)", helical ? "helical Table 1 pair" : "spur pair",
                 r.npos, (hi - lo) * ARCSEC);
        TAP_CLOSE(worst, 0, 1e-6, name);
        tap_ok((hi - lo) * ARCSEC > 0.1, "%s: the relief does change the TE (%.4g arcsec p-p)",
               helical ? "helical" : "spur", (hi - lo) * ARCSEC);
        TAP_CLOSE(r.gte_pp_arcsec[0], (hi - lo) * ARCSEC, 1e-6, "GTE peak-to-peak equals the expected one");
        gd_tca_result_free(&r);
        gd_case_free(&c);
    }
    return tap_done();
}
