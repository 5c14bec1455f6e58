/* Kinematics of one tooth pair of one half: the frames, the misaligned gear axis, the gap of a
 * pinion flank point to the gear flank (the gear rotation that closes it) with its derivatives
 * (docs/tca.md, section 3), and the geometric fields of a contact at a pinion point. */
#include "tca_internal.h"

#include <math.h>

void tca_mat_vec(const double A[9], const double x[3], double y[3])
{
    y[0] = A[0] * x[0] + A[1] * x[1] + A[2] * x[2];
    y[1] = A[3] * x[0] + A[4] * x[1] + A[5] * x[2];
    y[2] = A[6] * x[0] + A[7] * x[1] + A[8] * x[2];
}

static void mat_mul(const double A[9], const double B[9], double C[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
}

static void rot_z(double a, double R[9])
{
    double c = cos(a), s = sin(a);
    R[0] = c; R[1] = -s; R[2] = 0;
    R[3] = s; R[4] = c; R[5] = 0;
    R[6] = 0; R[7] = 0; R[8] = 1;
}

static void transpose(const double A[9], double T[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            T[3 * j + i] = A[3 * i + j];
}

double tca_phi2_nominal(const gd_tca *t, double phi1) { return t->ratio * phi1; }

void tca_pose_at(const gd_tca *t, int half, double phi1, double phi2, int pair, tca_pose *P)
{
    double p1 = phi1 + pair * t->tau1 + t->theta1;
    double p2 = phi2 + pair * t->tau2;
    double R1[9], Rg[9], Mt[9], T[9];
    rot_z(p1, R1);
    rot_z(p2 - t->theta2 - M_PI, Rg);
    transpose(t->M, Mt);
    mat_mul(Rg, Mt, T);
    mat_mul(T, R1, P->A);
    double zc = t->h[half].zc;
    double d[3] = {-t->C[0], -t->C[1], zc - t->C[2]};
    tca_mat_vec(T, d, P->c);
    P->c[2] -= zc;
}

void tca_fixed_point(const gd_tca *t, int half, double phi1, int pair, const double x[3], double X[3])
{
    double R1[9];
    rot_z(phi1 + pair * t->tau1 + t->theta1, R1);
    double y[3] = {x[0], x[1], x[2] + t->h[half].zc};
    tca_mat_vec(R1, y, X);
}

void tca_fixed_vector(const gd_tca *t, double phi1, int pair, const double v[3], double V[3])
{
    double R1[9];
    rot_z(phi1 + pair * t->tau1 + t->theta1, R1);
    tca_mat_vec(R1, v, V);
}

void tca_gear_to_fixed(const gd_tca *t, int half, double phi2, int pair, const double v[3], int is_point, double V[3])
{
    double Rg[9], G[9];
    rot_z(M_PI + t->theta2 - (phi2 + pair * t->tau2), Rg);
    mat_mul(t->M, Rg, G);
    double y[3] = {v[0], v[1], v[2] + (is_point ? t->h[half].zc : 0)};
    tca_mat_vec(G, y, V);
    if (is_point)
        for (int i = 0; i < 3; i++)
            V[i] += t->C[i];
}

void tca_pair_range(const gd_tca *t, int half, double phi1, int *lo, int *hi)
{
    const gd_flank *f = &t->h[half].f1;
    double span = f->u_max - f->u_min;
    double margin = 0.15 * span + 1e-3;
    double tw = fabs(f->k) * 0.5 * (f->z_max - f->z_min);
    double ta = tan(t->alpha_op);
    double a = f->u_min - margin - ta - phi1 - tw, b = f->u_max + margin - ta - phi1 + tw;
    *lo = (int)ceil(a / t->tau1);
    *hi = (int)floor(b / t->tau1);
}

double tca_dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void tca_local_eval(const gd_tca *t, int half, const tca_pose *P, double u, double z, int order, tca_local *L)
{
    const gd_flank *f1 = &t->h[half].f1, *f2 = &t->h[half].f2;
    gd_flank_eval e;
    gd_flank_eval_at(f1, u, z, order, &e);
    double Q[3];
    tca_mat_vec(P->A, e.r, Q);
    Q[0] += P->c[0];
    Q[1] += P->c[1];
    Q[2] += P->c[2];
    double rb = f2->rb;
    double r2 = Q[0] * Q[0] + Q[1] * Q[1], r = sqrt(r2);
    L->u = u;
    L->z = z;
    L->R = r;
    L->Z = Q[2];
    L->ok = r > rb * (1 + 1e-12);
    if (!L->ok) {
        L->g = NAN;
        return;
    }
    double s = sqrt(r2 - rb * rb);
    L->g = atan2(Q[1] * rb - Q[0] * s, Q[0] * rb + Q[1] * s) + s / rb + f2->eta_b - f2->k * Q[2];
    if (order < 1)
        return;
    double rb1 = f1->rb;
    double Qu[3], Qz[3];
    tca_mat_vec(P->A, e.ru, Qu);
    tca_mat_vec(P->A, e.rz, Qz);
    /* gradients in Q */
    double Fp = s / (r * rb);
    double gr[3] = {Q[0] / r, Q[1] / r, 0};
    double gth[3] = {-Q[1] / r2, Q[0] / r2, 0};
    double gg[3] = {gth[0] + Fp * gr[0], gth[1] + Fp * gr[1], -f2->k};
    double gz[3] = {0, 0, 1};
    double gu = tca_dot3(gg, Qu), gzz1 = tca_dot3(gg, Qz);
    L->g_r = gu / rb1;
    L->g_z = gzz1;
    L->R_r = tca_dot3(gr, Qu) / rb1;
    L->R_z = tca_dot3(gr, Qz);
    L->Z_r = Qu[2] / rb1;
    L->Z_z = Qz[2];
    (void)gz;
    if (order < 2)
        return;
    double Quu[3], Quz[3], Qzz[3];
    tca_mat_vec(P->A, e.ruu, Quu);
    tca_mat_vec(P->A, e.ruz, Quz);
    tca_mat_vec(P->A, e.rzz, Qzz);
    double x = Q[0], y = Q[1], r4 = r2 * r2, r3 = r2 * r;
    /* Hessians (xy block) of theta, r and g in Q */
    double Ht[3] = {2 * x * y / r4, (y * y - x * x) / r4, -2 * x * y / r4}; /* xx, xy, yy */
    double Hr[3] = {y * y / r3, -x * y / r3, x * x / r3};
    double Fpp = rb / (s * r2);
    double Hg[3] = {Ht[0] + Fpp * gr[0] * gr[0] + Fp * Hr[0], Ht[1] + Fpp * gr[0] * gr[1] + Fp * Hr[1],
                    Ht[2] + Fpp * gr[1] * gr[1] + Fp * Hr[2]};
#define QF(H, a, b) ((H)[0] * (a)[0] * (b)[0] + (H)[1] * ((a)[0] * (b)[1] + (a)[1] * (b)[0]) + (H)[2] * (a)[1] * (b)[1])
    double guu = QF(Hg, Qu, Qu) + tca_dot3(gg, Quu);
    double guz = QF(Hg, Qu, Qz) + tca_dot3(gg, Quz);
    double gzz = QF(Hg, Qz, Qz) + tca_dot3(gg, Qzz);
    L->g_rr = guu / (rb1 * rb1);
    L->g_rz = guz / rb1;
    L->g_zz = gzz;
    L->R_rr = (QF(Hr, Qu, Qu) + tca_dot3(gr, Quu)) / (rb1 * rb1);
    L->R_rz = (QF(Hr, Qu, Qz) + tca_dot3(gr, Quz)) / rb1;
    L->R_zz = QF(Hr, Qz, Qz) + tca_dot3(gr, Qzz);
    L->Z_rr = Quu[2] / (rb1 * rb1);
    L->Z_rz = Quz[2] / rb1;
    L->Z_zz = Qzz[2];
#undef QF
}

static double gear_r_lo(const gd_flank *f2) { return f2->rb * sqrt(1 + f2->u_min * f2->u_min); }
static double gear_r_hi(const gd_flank *f2) { return f2->rb * sqrt(1 + f2->u_max * f2->u_max); }

void tca_constraint(const gd_tca *t, int half, const tca_local *L, int k, double *h, double *h_r, double *h_z,
                    double *h_rr, double *h_rz, double *h_zz)
{
    const gd_flank *f1 = &t->h[half].f1, *f2 = &t->h[half].f2;
    double sg = 1;
    *h_rr = *h_rz = *h_zz = 0;
    switch (k) {
    case TCA_C_P_ROOT: *h = f1->rb * (L->u - f1->u_min); *h_r = 1; *h_z = 0; return;
    case TCA_C_P_TIP: *h = f1->rb * (f1->u_max - L->u); *h_r = -1; *h_z = 0; return;
    case TCA_C_P_LO: *h = L->z - f1->z_min; *h_r = 0; *h_z = 1; return;
    case TCA_C_P_HI: *h = f1->z_max - L->z; *h_r = 0; *h_z = -1; return;
    case TCA_C_G_ROOT: *h = L->R - gear_r_lo(f2); break;
    case TCA_C_G_TIP: *h = gear_r_hi(f2) - L->R; sg = -1; break;
    case TCA_C_G_LO:
        *h = L->Z - f2->z_min;
        *h_r = L->Z_r; *h_z = L->Z_z; *h_rr = L->Z_rr; *h_rz = L->Z_rz; *h_zz = L->Z_zz;
        return;
    default:
        *h = f2->z_max - L->Z;
        *h_r = -L->Z_r; *h_z = -L->Z_z; *h_rr = -L->Z_rr; *h_rz = -L->Z_rz; *h_zz = -L->Z_zz;
        return;
    }
    *h_r = sg * L->R_r;
    *h_z = sg * L->R_z;
    *h_rr = sg * L->R_rr;
    *h_rz = sg * L->R_rz;
    *h_zz = sg * L->R_zz;
}

int tca_feasible(const gd_tca *t, int half, const tca_local *L, double tol)
{
    const gd_flank *f1 = &t->h[half].f1, *f2 = &t->h[half].f2;
    if (!L->ok)
        return 1 + TCA_C_G_ROOT;
    if (f1->rb * (L->u - f1->u_min) < -tol) return 1 + TCA_C_P_ROOT;
    if (f1->rb * (f1->u_max - L->u) < -tol) return 1 + TCA_C_P_TIP;
    if (L->z - f1->z_min < -tol) return 1 + TCA_C_P_LO;
    if (f1->z_max - L->z < -tol) return 1 + TCA_C_P_HI;
    if (L->R - gear_r_lo(f2) < -tol) return 1 + TCA_C_G_ROOT;
    if (gear_r_hi(f2) - L->R < -tol) return 1 + TCA_C_G_TIP;
    if (L->Z - f2->z_min < -tol) return 1 + TCA_C_G_LO;
    if (f2->z_max - L->Z < -tol) return 1 + TCA_C_G_HI;
    return 0;
}

unsigned tca_edge_bit(int constraint) { return 1u << constraint; }

/* The geometric fields of a contact from (pair, u1, z1) and the nominal gear rotation. */
void tca_fill_contact(const gd_tca *t, int half, double phi1, int pair, double u1, double z1, double te,
                      gd_tca_contact *out)
{
    const tca_half *H = &t->h[half];
    gd_flank_eval e;
    gd_flank_eval_at(&H->f1, u1, z1, 1, &e);
    double n[3];
    gd_flank_normal(&e, n);
    out->phi1 = phi1;
    out->te = te;
    out->pair = pair;
    out->u1 = u1;
    out->z1 = z1;
    tca_fixed_point(t, half, phi1, pair, e.r, out->pos);
    tca_fixed_vector(t, phi1, pair, n, out->normal);
    out->alpha_op = atan2(out->normal[0], out->normal[1]);
    tca_pose P;
    tca_pose_at(t, half, phi1, tca_phi2_nominal(t, phi1), pair, &P);
    tca_local L;
    tca_local_eval(t, half, &P, u1, z1, 0, &L);
    double rb2 = H->f2.rb;
    out->u2 = L.R > rb2 ? sqrt(L.R * L.R - rb2 * rb2) / rb2 : 0;
    out->z2 = L.Z;
}
