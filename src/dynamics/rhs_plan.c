/* The right-hand side and tangent map of a gear model compiled for the held contact modes
 * (rhs_plan.h): built once per change of modes, evaluated at every stage. The accelerations are
 * computed four lanes at a time (GCC and Clang vector extension: two SSE2 registers per block,
 * one AVX register where the processor has it, chosen at run time). */
#include "rhs_plan.h"
#include "model_internal.h"

#include <string.h>

static gd_rhs_plan_fn plan_fn(void); /* the evaluation for this processor (below) */

void gd_plan_excitation_build(gd_plan_excitation *ex, const gd_model *m)
{
    for (int j = 0; j < m->nmesh; j++) {
        const gd_mesh_excitation *x = &m->mesh[j];
        gd_plan_excitation *q = &ex[j];
        memset(q, 0, sizeof *q);
        q->kind = x->kind;
        q->nh = x->kind == GD_STIFF_HARMONIC || x->kind == GD_STIFF_TABLE ? x->nh : 0;
        q->mean = x->mean;
        for (int h = 0; h < q->nh; h++) { /* cos(h (Omega t + phase) + phi_h) */
            double ang = (h + 1) * x->phase + x->phi[h];
            q->A[h] = x->a[h] * cos(ang);
            q->B[h] = x->a[h] * sin(ang);
        }
        double psi = x->phase + x->e_phi; /* sin(Omega t + phase + e_phi) */
        q->em = x->e_m;
        q->P = x->e_r * cos(psi);
        q->Q = x->e_r * sin(psi);
        q->ne = x->ne;
        for (int h = 0; h < q->ne; h++) { /* ea_h cos(h (Omega t + phase) + ephi_h) */
            double ang = (h + 1) * x->phase + x->ephi[h];
            q->EA[h] = x->ea[h] * cos(ang);
            q->EB[h] = x->ea[h] * sin(ang);
        }
    }
}

/* stiffness factor (when kf), error and its rate of mesh j */
static inline __attribute__((always_inline)) void excitation(const gd_plan_excitation *q, const gd_model *m, int j,
                                                             const gd_modes *md, double s0, double c0, double *kf,
                                                             double *e, double *ed)
{
    if (kf) {
        if (q->nh > 0) {
            double k = q->mean + (q->A[0] * c0 - q->B[0] * s0), sk = s0, ck = c0;
            for (int h = 1; h < q->nh; h++) {
                double sn = sk * c0 + ck * s0, cn = ck * c0 - sk * s0;
                sk = sn, ck = cn;
                k += q->A[h] * ck - q->B[h] * sk;
            }
            *kf = k;
        } else if (q->kind == GD_STIFF_RECTANGULAR) {
            *kf = md->rect_level[j] ? m->mesh[j].rect_high : m->mesh[j].rect_low;
        } else {
            *kf = q->kind == GD_STIFF_HARMONIC || q->kind == GD_STIFF_TABLE ? q->mean : 1.0;
        }
    }
    if (e)
        *e = q->em + (q->P * s0 + q->Q * c0);
    if (ed)
        *ed = m->Omega * (q->P * c0 - q->Q * s0);
    if (q->ne > 0) {
        double sk = s0, ck = c0, v = 0, v1 = 0;
        for (int h = 0; h < q->ne; h++) {
            v += q->EA[h] * ck - q->EB[h] * sk;
            v1 -= (double)(h + 1) * (q->EA[h] * sk + q->EB[h] * ck);
            double sn = sk * c0 + ck * s0, cn = ck * c0 - sk * s0;
            sk = sn, ck = cn;
        }
        if (e)
            *e += v;
        if (ed)
            *ed += m->Omega * v1;
    }
}

void gd_rhs_plan_build(gd_rhs_plan *p, const gd_model *m, const gd_modes *md, const gd_plan_excitation *ex)
{
    const int nd = m->ndof;
    double K[GD_MAX_DOF][GD_MAX_DOF] = {{0}}, C[GD_MAX_DOF][GD_MAX_DOF] = {{0}}, F[GD_MAX_DOF];
    memset(p, 0, sizeof *p);
    p->nd = nd;
    memcpy(p->mode, md->mode, sizeof p->mode);
    for (int i = 0; i < nd; i++)
        F[i] = m->F0[i];
    for (int q = 0; q < m->nk; q++)
        K[m->K0[q].i][m->K0[q].j] += m->K0[q].v;
    for (int q = 0; q < m->nc; q++)
        C[m->C0[q].i][m->C0[q].j] += m->C0[q].v;
    for (int c = 0; c < m->nclear; c++) {
        const gd_clearance *cl = &m->clear[c];
        int mode = md->mode[c];
        double ks = mode != 0 ? cl->k : 0.0;
        double hs = mode > 0 ? cl->h : (mode < 0 ? -cl->h : 0.0);
        double cs = (!cl->damp_contact_only || mode != 0) ? cl->c : 0.0;
        if (cl->kind == GD_CLR_MESH) {
            /* the mesh force k s(t) (x - hs) + c xdot + pulse, x = w . q - e(t), stays a rank-one term */
            gd_plan_mesh *pm = &p->mesh[p->nmesh++];
            pm->j = cl->mesh;
            for (int q = 0; q < cl->nw; q++) {
                pm->w[cl->widx[q]] += cl->wval[q];
                pm->u[cl->widx[q]] += cl->wval[q] * m->inv_mass[cl->widx[q]];
            }
            pm->ks = ks, pm->hs = hs, pm->cs = cs;
            /* the pulses, unless they act only in drive-side contact and the mode is another */
            const gd_mesh_excitation *x = &m->mesh[cl->mesh];
            pm->nimp = x->imp_contact_only && mode <= 0 ? 0 : x->nimp;
            for (int k = 0; k < pm->nimp; k++)
                pm->imp_force[k] = x->imp_force[k];
            continue;
        }
        /* a bearing: the force k (x - hs) + c xdot along w is linear in the state */
        for (int a = 0; a < cl->nw; a++) {
            F[cl->widx[a]] += ks * hs * cl->wval[a];
            for (int b = 0; b < cl->nw; b++) {
                K[cl->widx[a]][cl->widx[b]] += ks * cl->wval[a] * cl->wval[b];
                C[cl->widx[a]][cl->widx[b]] += cs * cl->wval[a] * cl->wval[b];
            }
        }
    }
    for (int i = 0; i < nd; i++) {
        double im = m->inv_mass[i];
        p->b[i] = F[i] * im;
        p->kd[i] = K[i][i] * im;
        p->cd[i] = C[i][i] * im;
        for (int j = 0; j < nd; j++) {
            if (j != i && K[i][j] != 0.0)
                p->off[p->noff++] = (gd_plan_coef){i, j, K[i][j] * im};
            if (j != i && C[i][j] != 0.0)
                p->off[p->noff++] = (gd_plan_coef){i, nd + j, C[i][j] * im};
        }
    }
    p->ex = ex;
    p->fn = plan_fn();
    p->valid = 1;
}

/* v4 values pass only between always-inlined static functions: no ABI is involved */
#pragma GCC diagnostic ignored "-Wpsabi"
typedef double v4 __attribute__((vector_size(32)));
#define NB (GD_PLAN_W / 4)
#define LD(p) (__extension__({ v4 r_; memcpy(&r_, (p), sizeof r_); r_; }))
#define ST(p, a) (__extension__({ v4 a_ = (a); memcpy((p), &a_, sizeof a_); }))

static inline double hsum(v4 a) { return (a[0] + a[1]) + (a[2] + a[3]); }

/* Block k of four of x[0..nd), zeros past nd (nd a constant where it is inlined: the partial
 * block is a narrow load, not a trip through memory) */
static inline __attribute__((always_inline)) v4 ldb(const double *x, int k, int nd)
{
    int r = nd - 4 * k;
    if (r >= 4)
        return LD(x + 4 * k);
    v4 z = {0};
    if (r > 0)
        z[0] = x[4 * k];
    if (r > 1)
        z[1] = x[4 * k + 1];
    if (r > 2)
        z[2] = x[4 * k + 2];
    return z;
}

static inline __attribute__((always_inline)) void stb(double *x, int k, int nd, v4 a)
{
    int r = nd - 4 * k;
    if (r >= 4) {
        ST(x + 4 * k, a);
        return;
    }
    for (int l = 0; l < r; l++)
        x[4 * k + l] = a[l];
}

/* acc = b - kd q - cd qd - (sum over meshes) u f, f from (x, xdot) = (w . q - e, w . qd - edot);
 * then the off-diagonal list; ydot = (qd, acc). tangent: the tangent map (no constant term, no
 * excitation, no pulse). Inlined with nd a constant for the models' sizes (the blocks' loops
 * unrolled, the accumulators in registers) and once with nd from the plan. */
static inline __attribute__((always_inline)) void eval(const gd_rhs_plan *p, const gd_model *m, double t,
                                                       double s0, double c0, const double *y, double *ydot,
                                                       const gd_modes *md, int tangent, int nd)
{
    const int nb = (nd + 3) / 4;
    const double *qd = y + nd;
    double *acc = ydot + nd;
    v4 a[NB] = {{0}}, vq[NB] = {{0}}, vqd[NB] = {{0}};
#pragma GCC unroll 4
    for (int k = 0; k < nb; k++) {
        vq[k] = ldb(y, k, nd);
        vqd[k] = ldb(qd, k, nd);
        stb(ydot, k, nd, vqd[k]);
        a[k] = -LD(p->kd + 4 * k) * vq[k] - LD(p->cd + 4 * k) * vqd[k];
        if (!tangent)
            a[k] += LD(p->b + 4 * k);
    }
#pragma GCC unroll 2
    for (int r = 0; r < GD_MAX_MESH; r++) {
        if (r >= p->nmesh)
            break;
        const gd_plan_mesh *pm = &p->mesh[r];
        if (tangent && pm->ks == 0.0 && pm->cs == 0.0)
            continue;
        v4 sx = {0}, sv = {0};
#pragma GCC unroll 4
        for (int k = 0; k < nb; k++) {
            v4 w = LD(pm->w + 4 * k);
            sx += w * vq[k];
            sv += w * vqd[k];
        }
        double x = hsum(sx), xd = hsum(sv), kf = 0.0, f;
        const gd_plan_excitation *q = &p->ex[pm->j];
        if (tangent) {
            if (pm->ks != 0.0)
                excitation(q, m, pm->j, md, s0, c0, &kf, NULL, NULL);
            f = pm->ks * kf * x + pm->cs * xd;
        } else {
            double e, ed;
            excitation(q, m, pm->j, md, s0, c0, pm->ks != 0.0 ? &kf : NULL, &e, &ed);
            f = pm->ks * kf * (x - e - pm->hs) + pm->cs * (xd - ed);
            if (pm->nimp > 0 && md->pulse_on[pm->j]) { /* pulse_force with the modes held */
                int on = md->pulse_on[pm->j];
                if (on & 1)
                    f += pm->imp_force[0];
                if (pm->nimp > 1 && (on & 2))
                    f += pm->imp_force[1];
            }
        }
        v4 fv = {f, f, f, f};
#pragma GCC unroll 4
        for (int k = 0; k < nb; k++)
            a[k] -= LD(pm->u + 4 * k) * fv;
    }
#pragma GCC unroll 4
    for (int k = 0; k < nb; k++)
        stb(acc, k, nd, a[k]);
    const gd_plan_coef *off = p->off;
    for (int o = 0; o < p->noff; o++)
        acc[off[o].i] -= off[o].v * y[off[o].j];
}

/* the sizes of the gear models (bta 10, torsional-lr 2, torsional 1) inlined with constant nd */
static inline __attribute__((always_inline)) void dispatch(const gd_rhs_plan *p, const gd_model *m, double t,
                                                           double s0, double c0, const double *y, double *ydot,
                                                           const gd_modes *md, int tangent)
{
    switch (p->nd) {
    case 10:
        eval(p, m, t, s0, c0, y, ydot, md, tangent, 10);
        break;
    case 2:
        eval(p, m, t, s0, c0, y, ydot, md, tangent, 2);
        break;
    case 1:
        eval(p, m, t, s0, c0, y, ydot, md, tangent, 1);
        break;
    default:
        eval(p, m, t, s0, c0, y, ydot, md, tangent, p->nd);
    }
}

/* tangent a constant in each branch: two copies of each size, without the unused terms */
static inline __attribute__((always_inline)) void both(const gd_rhs_plan *p, const gd_model *m, double t, double s0,
                                                       double c0, const double *y, double *out, const gd_modes *md,
                                                       int tangent)
{
    if (tangent)
        dispatch(p, m, t, s0, c0, y, out, md, 1);
    else
        dispatch(p, m, t, s0, c0, y, out, md, 0);
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define GD_PLAN_AVX 1
__attribute__((target("avx"))) static void both_avx(const gd_rhs_plan *p, const gd_model *m, double t, double s0,
                                                    double c0, const double *y, double *out, const gd_modes *md,
                                                    int tangent)
{
    both(p, m, t, s0, c0, y, out, md, tangent);
}
#endif

static void both_sse2(const gd_rhs_plan *p, const gd_model *m, double t, double s0, double c0, const double *y,
                      double *out, const gd_modes *md, int tangent)
{
    both(p, m, t, s0, c0, y, out, md, tangent);
}

/* four lanes in one AVX register where the processor has it, else two SSE2 registers (asked once
 * per plan, not at every evaluation) */
static gd_rhs_plan_fn plan_fn(void)
{
#ifdef GD_PLAN_AVX
    if (__builtin_cpu_supports("avx"))
        return both_avx;
#endif
    return both_sse2;
}
