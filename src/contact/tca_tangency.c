/* Formulation (a), surface tangency (docs/tca.md, section 6; Litvin & Fuentes ch. 9 and 15): the
 * pinion and gear flanks share a point and a normal, r1 = r2 and n1 = n2 (five independent
 * equations in u1, z1, u2, z2, phi2 with phi1 given), and the edge-contact systems in which one
 * surface parameter sits on a boundary (pinion tip edge, pinion end faces, gear tip edge, gear end
 * faces: position plus the edge tangent perpendicular to the other surface's normal) or two do
 * (corners). Each system is solved by GSL's hybridsj with its analytic Jacobian from the ideal
 * involute contact as the starting point; the contact is the valid solution with the least gap. */
#include "tca_internal.h"
#include "geardyn/gd_geometry.h"

#include <math.h>
#include <string.h>

#define TAN_SEEDS 5

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static void ez_cross(const double a[3], double c[3])
{
    c[0] = -a[1];
    c[1] = a[0];
    c[2] = 0;
}

/* A stratum: which surface parameters are free. Fixed ones take the given values. */
typedef struct stratum {
    int free_u1, free_z1, free_u2, free_z2;
    double u1, z1, u2, z2;   /* fixed values (and starting values of the free ones) */
    unsigned bits;           /* gd_edge_kind of the stratum */
} stratum;

typedef struct tan_ctx {
    gd_tca *t;
    int half, pair;
    double phi1, phi2n;
    const stratum *s;
    double scale[2];         /* of the tangency conditions */
    int ncond;
} tan_ctx;

/* unpack the unknowns (metres: rho1 = rb1 u1, z1, rho2 = rb2 u2, z2, psi = rb2 (phi2 - phi2n)) */
static void unpack(const tan_ctx *c, const double *x, double *u1, double *z1, double *u2, double *z2, double *dphi,
                   int idx[5])
{
    const stratum *s = c->s;
    double rb1 = c->t->h[c->half].f1.rb, rb2 = c->t->h[c->half].f2.rb;
    int k = 0;
    for (int i = 0; i < 5; i++)
        idx[i] = -1;
    *u1 = s->u1; *z1 = s->z1; *u2 = s->u2; *z2 = s->z2;
    if (s->free_u1) { idx[0] = k; *u1 = x[k++] / rb1; }
    if (s->free_z1) { idx[1] = k; *z1 = x[k++]; }
    if (s->free_u2) { idx[2] = k; *u2 = x[k++] / rb2; }
    if (s->free_z2) { idx[3] = k; *z2 = x[k++]; }
    idx[4] = k;
    *dphi = x[k] / rb2;
}

static int sys_tangency(const double *x, void *p, double *f, double *J)
{
    tan_ctx *c = p;
    gd_tca *t = c->t;
    const stratum *s = c->s;
    double u1, z1, u2, z2, dphi;
    int idx[5];
    unpack(c, x, &u1, &z1, &u2, &z2, &dphi, idx);
    int n = idx[4] + 1;
    const double rb1 = t->h[c->half].f1.rb, rb2 = t->h[c->half].f2.rb;
    if (!(u1 > 0 && u2 > 0))
        return 1;
    tca_pose P;
    tca_pose_at(t, c->half, c->phi1, c->phi2n + dphi, c->pair, &P);
    gd_flank_eval e1, e2;
    gd_flank_eval_at(&t->h[c->half].f1, u1, z1, 2, &e1);
    gd_flank_eval_at(&t->h[c->half].f2, u2, z2, 2, &e2);
    double Q[3], t1u[3], t1z[3], t1uu[3], t1uz[3], t1zz[3];
    tca_mat_vec(P.A, e1.r, Q);
    for (int i = 0; i < 3; i++)
        Q[i] += P.c[i];
    tca_mat_vec(P.A, e1.ru, t1u);
    tca_mat_vec(P.A, e1.rz, t1z);
    tca_mat_vec(P.A, e1.ruu, t1uu);
    tca_mat_vec(P.A, e1.ruz, t1uz);
    tca_mat_vec(P.A, e1.rzz, t1zz);
    for (int i = 0; i < n * n; i++)
        J[i] = 0;
    double dQ[3];
    ez_cross(Q, dQ);
    for (int i = 0; i < 3; i++) {
        f[i] = Q[i] - e2.r[i];
        if (idx[0] >= 0) J[i * n + idx[0]] = t1u[i] / rb1;
        if (idx[1] >= 0) J[i * n + idx[1]] = t1z[i];
        if (idx[2] >= 0) J[i * n + idx[2]] = -e2.ru[i] / rb2;
        if (idx[3] >= 0) J[i * n + idx[3]] = -e2.rz[i];
        J[i * n + idx[4]] = dQ[i] / rb2;
    }
    int nfree_p = s->free_u1 + s->free_z1, nfree_g = s->free_u2 + s->free_z2;
    int row = 3;
    if (nfree_g == 2) {
        /* each free pinion tangent is perpendicular to the gear normal N2 = x2_u x x2_z */
        double N2[3], N2u[3], N2z[3], a[3], b[3];
        cross(e2.ru, e2.rz, N2);
        cross(e2.ruu, e2.rz, a);
        cross(e2.ru, e2.ruz, b);
        for (int i = 0; i < 3; i++) N2u[i] = a[i] + b[i];
        cross(e2.ruz, e2.rz, a);
        cross(e2.ru, e2.rzz, b);
        for (int i = 0; i < 3; i++) N2z[i] = a[i] + b[i];
        for (int q = 0; q < 2; q++) {
            if (!(q == 0 ? s->free_u1 : s->free_z1))
                continue;
            const double *tp = q == 0 ? t1u : t1z;
            const double *tpu = q == 0 ? t1uu : t1uz;
            const double *tpz = q == 0 ? t1uz : t1zz;
            double sc = c->scale[row - 3], dt[3];
            f[row] = sc * tca_dot3(tp, N2);
            if (idx[0] >= 0) J[row * n + idx[0]] = sc * tca_dot3(tpu, N2) / rb1;
            if (idx[1] >= 0) J[row * n + idx[1]] = sc * tca_dot3(tpz, N2);
            J[row * n + idx[2]] = sc * tca_dot3(tp, N2u) / rb2;
            J[row * n + idx[3]] = sc * tca_dot3(tp, N2z);
            ez_cross(tp, dt);
            J[row * n + idx[4]] = sc * tca_dot3(dt, N2) / rb2;
            row++;
        }
    } else if (nfree_p == 2 && nfree_g == 1) {
        /* the free gear tangent is perpendicular to the pinion normal N1 = A (x1_u x x1_z) */
        double N1[3], N1u[3], N1z[3], a[3], b[3], dN[3];
        cross(t1u, t1z, N1);
        cross(t1uu, t1z, a);
        cross(t1u, t1uz, b);
        for (int i = 0; i < 3; i++) N1u[i] = a[i] + b[i];
        cross(t1uz, t1z, a);
        cross(t1u, t1zz, b);
        for (int i = 0; i < 3; i++) N1z[i] = a[i] + b[i];
        int gu = s->free_u2;
        const double *tq = gu ? e2.ru : e2.rz;
        const double *tqq = gu ? e2.ruu : e2.rzz;
        double sc = c->scale[0];
        f[row] = sc * tca_dot3(tq, N1);
        J[row * n + idx[0]] = sc * tca_dot3(tq, N1u) / rb1;
        J[row * n + idx[1]] = sc * tca_dot3(tq, N1z);
        J[row * n + (gu ? idx[2] : idx[3])] = sc * tca_dot3(tqq, N1) / (gu ? rb2 : 1.0);
        ez_cross(N1, dN);
        J[row * n + idx[4]] = sc * tca_dot3(tq, dN) / rb2;
        row++;
    }
    return row == n ? 0 : 1;
}

/* Solve one stratum; on success the candidate's gap (phi2n - phi2) and parameters. */
static gd_status solve_stratum(gd_tca *t, int half, int pair, double phi1, const stratum *s0, double *gap,
                               stratum *sol, int *ok, int *iters, gd_error *err)
{
    *ok = 0;
    const gd_flank *f1 = &t->h[half].f1, *f2 = &t->h[half].f2;
    tan_ctx c = {t, half, pair, phi1, tca_phi2_nominal(t, phi1), s0, {1, 1}, 0};
    double x[5];
    int n = 0;
    if (s0->free_u1) x[n++] = s0->u1 * f1->rb;
    if (s0->free_z1) x[n++] = s0->z1;
    if (s0->free_u2) x[n++] = s0->u2 * f2->rb;
    if (s0->free_z2) x[n++] = s0->z2;
    x[n++] = 0;
    if (n < 3)
        return GD_OK;
    /* scale the tangency conditions to cosines at the start */
    {
        gd_flank_eval e1, e2;
        gd_flank_eval_at(f1, s0->u1, s0->z1, 1, &e1);
        gd_flank_eval_at(f2, s0->u2, s0->z2, 1, &e2);
        double N1[3], N2[3];
        cross(e1.ru, e1.rz, N1);
        cross(e2.ru, e2.rz, N2);
        int nfree_g = s0->free_u2 + s0->free_z2;
        if (nfree_g == 2) {
            int r = 0;
            if (s0->free_u1) c.scale[r++] = 1.0 / (sqrt(tca_dot3(e1.ru, e1.ru)) * sqrt(tca_dot3(N2, N2)));
            if (s0->free_z1) c.scale[r++] = 1.0 / (sqrt(tca_dot3(e1.rz, e1.rz)) * sqrt(tca_dot3(N2, N2)));
        } else {
            const double *tq = s0->free_u2 ? e2.ru : e2.rz;
            c.scale[0] = 1.0 / (sqrt(tca_dot3(tq, tq)) * sqrt(tca_dot3(N1, N1)));
        }
    }
    int conv, it;
    gd_status st = tca_newton(t, n, sys_tangency, &c, x, 1e-13, 100, &conv, &it, err);
    *iters += it;
    if (st != GD_OK || !conv)
        return st;
    double u1, z1, u2, z2, dphi;
    int idx[5];
    unpack(&c, x, &u1, &z1, &u2, &z2, &dphi, idx);
    const double eps = 1e-9;
    if (f1->rb * (u1 - f1->u_min) < -eps || f1->rb * (u1 - f1->u_max) > eps || z1 < f1->z_min - eps ||
        z1 > f1->z_max + eps || f2->rb * (u2 - f2->u_min) < -eps || f2->rb * (u2 - f2->u_max) > eps ||
        z2 < f2->z_min - eps || z2 > f2->z_max + eps)
        return GD_OK;
    *sol = *s0;
    sol->u1 = u1;
    sol->z1 = z1;
    sol->u2 = u2;
    sol->z2 = z2;
    *gap = -dphi;
    *ok = 1;
    return GD_OK;
}

/* The ideal involute contact of one tooth pair at a position, from which the seeds are placed:
 * u_c(z) = phi + k1 z + off is the pinion roll parameter of the ideal contact line. */
typedef struct seed_ctx {
    const gd_flank *f1, *f2;
    double span1, face1;     /* pinion roll span and face width */
    double Lp;               /* length of the line of action between the base circles */
    double off;
    double phi, k1;
    double uc0;              /* u_c(0) */
} seed_ctx;

static double seed_uc(const seed_ctx *c, double z) { return c->phi + c->k1 * (z) + c->off; }

/* Interior seeds: spread along the part of the ideal contact line that lies on the flank (a
 * modified flank can have a local minimum of the gap near each end of its unmodified zone; the
 * least of the solutions is the contact). */
static int seeds_interior(const seed_ctx *c, stratum *list, int ns)
{
    const gd_flank *f1 = c->f1, *f2 = c->f2;
    const double phi = c->phi, k1 = c->k1, off = c->off, Lp = c->Lp, span1 = c->span1, face1 = c->face1;
    double za = f1->z_min, zb = f1->z_max;
    if (k1 != 0) {
        double z1 = (f1->u_min - phi - off) / k1, z2 = (f1->u_max - phi - off) / k1;
        za = fmax(za, fmin(z1, z2));
        zb = fmin(zb, fmax(z1, z2));
    } else if (!(c->uc0 > f1->u_min && c->uc0 < f1->u_max)) {
        zb = za - 1;
    }
    if (!(zb > za))
        return ns;
    for (int q = 0; q < TAN_SEEDS; q++) {
        double z = za + (zb - za) * (q + 0.5) / TAN_SEEDS;
        double u = fmin(fmax(seed_uc(c, z), f1->u_min), f1->u_max);
        double rho2 = Lp - f1->rb * u;
        stratum s = {1, 1, 1, 1, u, z, rho2 / f2->rb, z, 0};
        list[ns++] = s;
    }
    /* where the ideal line crosses into a relief zone, and the corners of the
     * unmodified zone: the local minima of a flank with unmodified bands sit there */
    double inset = 1e-4;
    double ub[2] = {f1->root_amount > 0 ? (f1->rho_c - inset) / f1->rb : NAN,
                    f1->tip_amount > 0 ? (f1->rho_g + inset) / f1->rb : NAN};
    double zbd[2] = {f1->a_lo > 0 ? f1->z_lo - inset : NAN, f1->a_hi > 0 ? f1->z_hi + inset : NAN};
    for (int q = 0; q < 2; q++) {
        if (isfinite(ub[q]) && k1 != 0) {
            double z = (ub[q] - phi - off) / k1;
            if (z > za && z < zb) {
                stratum s = {1, 1, 1, 1, ub[q], z, (Lp - f1->rb * ub[q]) / f2->rb, z, 0};
                list[ns++] = s;
            }
        }
        if (isfinite(zbd[q]) && zbd[q] > za && zbd[q] < zb) {
            double u = fmin(fmax(seed_uc(c, zbd[q]), f1->u_min), f1->u_max);
            stratum s = {1, 1, 1, 1, u, zbd[q], (Lp - f1->rb * u) / f2->rb, zbd[q], 0};
            list[ns++] = s;
        }
    }
    for (int q = 0; q < 4; q++) {
        double u = ub[q & 1], z = zbd[q >> 1];
        if (!isfinite(u))
            u = q & 1 ? f1->u_max - 0.02 * span1 : f1->u_min + 0.02 * span1;
        if (!isfinite(z))
            z = q >> 1 ? f1->z_max - 0.02 * face1 : f1->z_min + 0.02 * face1;
        if (!(isfinite(ub[q & 1]) || isfinite(zbd[q >> 1])))
            continue;
        if (fabs(seed_uc(c, z) - u) > 0.15 * span1)
            continue;
        stratum s = {1, 1, 1, 1, u, z, (Lp - f1->rb * u) / f2->rb, z, 0};
        list[ns++] = s;
    }
    return ns;
}

/* Edge seeds of the pinion: its tip edge, its end faces and their corners with the tip. */
static int seeds_pinion_edges(const seed_ctx *c, stratum *list, int ns)
{
    const gd_flank *f1 = c->f1, *f2 = c->f2;
    const double phi = c->phi, k1 = c->k1, off = c->off, Lp = c->Lp, span1 = c->span1, face1 = c->face1;
    double zend[2] = {f1->z_min, f1->z_max};
    /* pinion tip edge */
    if (k1 != 0) {
        double z = (f1->u_max - phi - off) / k1;
        if (z > f1->z_min - 0.1 * face1 && z < f1->z_max + 0.1 * face1) {
            z = fmin(fmax(z, f1->z_min), f1->z_max);
            stratum s = {0, 1, 1, 1, f1->u_max, z, (Lp - f1->rb * f1->u_max) / f2->rb, z,
                         tca_edge_bit(TCA_C_P_TIP)};
            list[ns++] = s;
        }
    } else if (fabs(c->uc0 - f1->u_max) < 0.1 * span1) {
        stratum s = {0, 1, 1, 1, f1->u_max, 0, (Lp - f1->rb * f1->u_max) / f2->rb, 0, tca_edge_bit(TCA_C_P_TIP)};
        list[ns++] = s;
    }
    /* pinion end faces, and their corners with the pinion tip */
    for (int e = 0; e < 2; e++) {
        double u = seed_uc(c, zend[e]);
        if (u > f1->u_min - 0.05 * span1 && u < f1->u_max + 0.1 * span1) {
            double uu = fmin(fmax(u, f1->u_min), f1->u_max);
            stratum s = {1, 0, 1, 1, uu, zend[e], (Lp - f1->rb * uu) / f2->rb, zend[e],
                         tca_edge_bit(e ? TCA_C_P_HI : TCA_C_P_LO)};
            list[ns++] = s;
        }
        if (fabs(u - f1->u_max) < 0.1 * span1) {
            stratum s = {0, 0, 1, 1, f1->u_max, zend[e], (Lp - f1->rb * f1->u_max) / f2->rb, zend[e],
                         tca_edge_bit(TCA_C_P_TIP) | tca_edge_bit(e ? TCA_C_P_HI : TCA_C_P_LO)};
            list[ns++] = s;
        }
    }
    return ns;
}

/* Edge seeds of the gear: its tip edge and its crossings with the pinion end faces, and the gear
 * end faces where they cross the pinion face (a gear narrower than the pinion). */
static int seeds_gear_edges(const seed_ctx *c, stratum *list, int ns)
{
    const gd_flank *f1 = c->f1, *f2 = c->f2;
    const double phi = c->phi, k1 = c->k1, off = c->off, Lp = c->Lp, span1 = c->span1, face1 = c->face1;
    double zend[2] = {f1->z_min, f1->z_max};
    /* gear tip edge, and its crossings with the pinion end faces */
    {
        double u1 = (Lp - f2->rb * f2->u_max) / f1->rb;
        double z = k1 != 0 ? (u1 - phi - off) / k1 : 0;
        if ((k1 != 0 && z > f1->z_min - 0.1 * face1 && z < f1->z_max + 0.1 * face1) ||
            (k1 == 0 && fabs(c->uc0 - u1) < 0.1 * span1)) {
            z = fmin(fmax(z, f1->z_min), f1->z_max);
            stratum s = {1, 1, 0, 1, u1, z, f2->u_max, z, tca_edge_bit(TCA_C_G_TIP)};
            list[ns++] = s;
        }
        for (int e = 0; e < 2; e++) {
            if (fabs(seed_uc(c, zend[e]) - u1) < 0.1 * span1) {
                stratum s = {1, 0, 0, 1, u1, zend[e], f2->u_max, zend[e],
                             tca_edge_bit(TCA_C_G_TIP) | tca_edge_bit(e ? TCA_C_P_HI : TCA_C_P_LO)};
                list[ns++] = s;
            }
        }
    }
    /* gear end faces where they cross the pinion face (a gear narrower than the pinion) */
    {
        double gz[2] = {f2->z_min, f2->z_max};
        for (int e = 0; e < 2; e++) {
            if (gz[e] < f1->z_min - 1e-9 || gz[e] > f1->z_max + 1e-9)
                continue;
            double u = fmin(fmax(seed_uc(c, gz[e]), f1->u_min), f1->u_max);
            stratum s = {1, 1, 1, 0, u, gz[e], (Lp - f1->rb * u) / f2->rb, gz[e],
                         tca_edge_bit(e ? TCA_C_G_HI : TCA_C_G_LO)};
            list[ns++] = s;
        }
    }
    return ns;
}

#define TAN_MAX_PAIRS 64
#define TAN_MAX_CAND (TAN_MAX_PAIRS * (TAN_SEEDS + 24))

/* The solutions of all strata of all candidate pairs at one position. */
typedef struct tan_result {
    double best_gap;
    stratum best_s;
    int best_pair, iters, any;
    double cand_gap[TAN_MAX_CAND];
    unsigned cand_bits[TAN_MAX_CAND];
    int ncand;
    double pair_min[TAN_MAX_PAIRS];
} tan_result;

/* Solve the strata of pair m and keep the least gap. */
static gd_status solve_pair_strata(gd_tca *t, int half, double phi1, int m, int lo, const stratum *list, int ns,
                                   tan_result *r, gd_error *err)
{
    for (int q = 0; q < ns; q++) {
        double gap;
        stratum sol;
        int ok;
        gd_status st = solve_stratum(t, half, m, phi1, &list[q], &gap, &sol, &ok, &r->iters, err);
        if (st != GD_OK)
            return st;
        if (!ok)
            continue;
        r->any = 1;
        if (r->ncand < TAN_MAX_CAND) {
            r->cand_gap[r->ncand] = gap;
            r->cand_bits[r->ncand] = sol.bits;
            r->ncand++;
        }
        if (gap < r->pair_min[m - lo])
            r->pair_min[m - lo] = gap;
        if (gap < r->best_gap) {
            r->best_gap = gap;
            r->best_s = sol;
            r->best_pair = m;
        }
    }
    return GD_OK;
}

/* The contact from the least of the solutions, its edge flags and the pairs in contact. */
static void fill_tangency_contact(const gd_tca *t, int half, double phi1, int lo, int hi, const tan_result *r,
                                  gd_tca_contact *out)
{
    memset(out, 0, sizeof *out);
    out->phi1 = phi1;
    out->iterations = r->iters;
    if (!r->any) {
        out->te = NAN;
        out->converged = 0;
        return;
    }
    tca_fill_contact(t, half, phi1, r->best_pair, r->best_s.u1, r->best_s.z1, -r->best_gap, out);
    out->u2 = r->best_s.u2;
    out->z2 = r->best_s.z2;
    out->iterations = r->iters;
    out->converged = 1;
    unsigned edge = 0;
    for (int i = 0; i < r->ncand; i++)
        if (r->cand_gap[i] <= r->best_gap + t->tol_edge)
            edge |= r->cand_bits[i];
    out->edge = edge;
    out->pairs_in_contact = 0;
    for (int m = lo; m <= hi && m - lo < TAN_MAX_PAIRS; m++)
        if (r->pair_min[m - lo] <= r->best_gap + t->tol_contact)
            out->pairs_in_contact++;
}

gd_status tca_tangency(gd_tca *t, int half, double phi1, gd_tca_contact *out, gd_error *err)
{
    const gd_flank *f1 = &t->h[half].f1, *f2 = &t->h[half].f2;
    const gd_geometry *g = &t->g;
    seed_ctx c = {f1, f2, f1->u_max - f1->u_min, f1->z_max - f1->z_min, (g->rb[0] + g->rb[1]) * tan(t->alpha_op),
                  gd_involute(g->alpha_wt) + t->alpha_op, 0, 0, 0};
    int lo, hi;
    tca_pair_range(t, half, phi1, &lo, &hi);
    tan_result r;
    r.best_gap = INFINITY;
    r.best_s = (stratum){0};
    r.best_pair = 0;
    r.iters = 0;
    r.any = 0;
    r.ncand = 0;
    for (int m = lo; m <= hi && m - lo < TAN_MAX_PAIRS; m++) {
        r.pair_min[m - lo] = INFINITY;
        c.phi = phi1 + m * t->tau1;
        c.k1 = f1->k;
        /* the ideal contact line: where does it cross the flank? */
        c.uc0 = seed_uc(&c, 0);
        stratum list[TAN_SEEDS + 24];
        int ns = seeds_interior(&c, list, 0);
        ns = seeds_pinion_edges(&c, list, ns);
        ns = seeds_gear_edges(&c, list, ns);
        gd_status st = solve_pair_strata(t, half, phi1, m, lo, list, ns, &r, err);
        if (st != GD_OK)
            return st;
    }
    fill_tangency_contact(t, half, phi1, lo, hi, &r, out);
    return GD_OK;
}
