/* Internal: the model's evaluations with the sine and cosine of Omega t given by the caller.
 * Every evaluation at a time t needs sin(Omega t) and cos(Omega t) once (for all meshes and
 * harmonics); an integrator evaluates several times at the same t (stages of a Runge-Kutta step
 * with equal nodes, the root functions at the step end), so gd_sim keeps the last few and passes
 * them in. The results are those of gd_model_rhs, gd_model_roots and gd_model_tangent with the
 * same sincos values, to the bit (and those of gd_model_clearances). The excitation of a mesh is evaluated inline here, for these and
 * for the RHS compiled for the held modes (rhs_plan.h). */
#ifndef GD_MODEL_INTERNAL_H
#define GD_MODEL_INTERNAL_H

#include "geardyn/gd_model.h"

#include <math.h>

static inline double mesh_phase(const gd_model *m, int j, double t) { return m->Omega * t + m->mesh[j].phase; }

/* The contact mode of clearance c at coordinate x (+1 past h, -1 past -h, else 0): gd_model_mode_of,
 * inline for the checks made at every clearance after every step (sim_events.c). */
static inline int model_mode_of(const gd_model *m, int c, double x)
{
    double h = m->clear[c].h;
    return x > h ? 1 : (x < -h ? -1 : 0);
}

static inline int rect_level_at(const gd_mesh_excitation *x, double ph)
{
    double f = ph / (2.0 * M_PI);
    f -= floor(f);
    return f < x->rect_frac;
}

/* Stiffness factor, error and its rates of mesh j from the sine and cosine (s0, c0) of Omega t,
 * one sincos for all meshes: the half's phase offset by angle addition, harmonics by the
 * angle-addition recurrence, the error by the phase-shift identity. */
static inline __attribute__((always_inline)) void mesh_eval_sc(const gd_model *m, int j, double t, double s0, double c0, const gd_modes *md,
                                double *kf, double *e, double *ed, double *edd)
{
    const gd_mesh_excitation *x = &m->mesh[j];
    double th = mesh_phase(m, j, t);
    double s1 = s0, c1 = c0;
    if (x->phase != 0.0) {
        s1 = s0 * x->cph + c0 * x->sph;
        c1 = c0 * x->cph - s0 * x->sph;
    }
    if (kf) {
        if (x->kind == GD_STIFF_HARMONIC || x->kind == GD_STIFF_TABLE) {
            double sk = s1, ck = c1, k = x->mean;
            for (int h = 0; h < x->nh; h++) {
                k += x->a[h] * (ck * x->cphi[h] - sk * x->sphi[h]);
                double sn = sk * c1 + ck * s1, cn = ck * c1 - sk * s1;
                sk = sn;
                ck = cn;
            }
            *kf = k;
        } else if (x->kind == GD_STIFF_RECTANGULAR) {
            int level = md->from_state ? rect_level_at(x, th) : md->rect_level[j];
            *kf = level ? x->rect_high : x->rect_low;
        } else {
            *kf = 1.0;
        }
    }
    double se = s1 * x->ce + c1 * x->se, ce = c1 * x->ce - s1 * x->se; /* sin, cos of th + e_phi */
    *e = x->e_m + x->e_r * se;
    if (ed)
        *ed = x->e_r * m->Omega * ce;
    if (edd)
        *edd = -x->e_r * m->Omega * m->Omega * se;
    if (x->ne > 0) { /* a tabulated error: sum ea_h cos(h th + ephi_h) and its rates */
        double sk = s1, ck = c1, v = 0, v1 = 0, v2 = 0;
        for (int h = 0; h < x->ne; h++) {
            double co = ck * x->cephi[h] - sk * x->sephi[h], si = sk * x->cephi[h] + ck * x->sephi[h];
            double hh = (double)(h + 1);
            v += x->ea[h] * co;
            v1 -= hh * x->ea[h] * si;
            v2 -= hh * hh * x->ea[h] * co;
            double sn = sk * c1 + ck * s1, cn = ck * c1 - sk * s1;
            sk = sn;
            ck = cn;
        }
        *e += v;
        if (ed)
            *ed += m->Omega * v1;
        if (edd)
            *edd += m->Omega * m->Omega * v2;
    }
}

/* The pulses of x in their phases at mesh phase th (bit k: pulse k) */
static inline int pulse_at(const gd_mesh_excitation *x, double th)
{
    int on = 0;
    for (int k = 0; k < x->nimp; k++) {
        double f = (th - x->imp_phase[k]) / (2.0 * M_PI);
        f -= floor(f);
        on |= (f * 2.0 * M_PI < x->imp_width[k]) << k;
    }
    return on;
}

/* The force of the pulses of mesh j at t with the mesh's clearance in mode `mode`: a pulse acts in its
 * phases (held in md, or from t when the modes follow the state) and, when it is gated by contact,
 * only while the drive flanks touch (mode +1). */
static inline double pulse_force(const gd_model *m, int j, double t, const gd_modes *md, int mode)
{
    const gd_mesh_excitation *x = &m->mesh[j];
    if (x->nimp == 0 || (x->imp_contact_only && mode <= 0))
        return 0.0;
    int on = md->from_state ? pulse_at(x, mesh_phase(m, j, t)) : md->pulse_on[j];
    double f = 0.0;
    for (int k = 0; k < x->nimp; k++)
        if (on >> k & 1)
            f += x->imp_force[k];
    return f;
}


void gd_model_rhs_sc(const gd_model *m, double t, double s0, double c0, const double *y, double *ydot,
                     const gd_modes *md);
void gd_model_clearances_sc(const gd_model *m, double t, double s0, double c0, const double *y, const gd_modes *md,
                            double *x, double *xdot);
void gd_model_roots_sc(const gd_model *m, double t, double s0, double c0, const double *y, double *g,
                       const gd_modes *md);
void gd_model_tangent_sc(const gd_model *m, double t, double s0, double c0, const double *y, const double *v,
                         double *out, const gd_modes *md);
void gd_model_error_sc(const gd_model *m, int j, double t, double s0, double c0, const gd_modes *md, double *e,
                       double *edot, double *eddot);

#endif
