/* Evaluating the dimensionless model: excitations, right-hand side, Jacobian, root
 * functions, energy and the static state. The RHS, Jacobian and roots allocate nothing. */
#include "geardyn/gd_model.h"
#include "../core/gsl_quiet.h"
#include "model_internal.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fft_real.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <string.h>

static inline void mesh_eval(const gd_model *m, int j, double t, const gd_modes *md, double *kf, double *e,
                             double *ed, double *edd)
{
    double s0, c0;
    sincos(m->Omega * t, &s0, &c0);
    mesh_eval_sc(m, j, t, s0, c0, md, kf, e, ed, edd);
}

GD_API double gd_model_stiffness(const gd_model *m, int j, double t, const gd_modes *md)
{
    const gd_mesh_excitation *x = &m->mesh[j];
    switch (x->kind) {
    case GD_STIFF_HARMONIC:
    case GD_STIFF_TABLE: {
        double ph = mesh_phase(m, j, t), s = x->mean;
        for (int h = 0; h < x->nh; h++)
            s += x->a[h] * cos((h + 1) * ph + x->phi[h]);
        return s;
    }
    case GD_STIFF_RECTANGULAR: {
        int level = md->from_state ? rect_level_at(x, mesh_phase(m, j, t)) : md->rect_level[j];
        return level ? x->rect_high : x->rect_low;
    }
    default:
        return 1.0;
    }
}

GD_API void gd_model_error(const gd_model *m, int j, double t, const gd_modes *md, double *e, double *edot,
                           double *eddot)
{
    mesh_eval(m, j, t, md, NULL, e, edot, eddot);
}

void gd_model_error_sc(const gd_model *m, int j, double t, double s0, double c0, const gd_modes *md, double *e,
                       double *edot, double *eddot)
{
    mesh_eval_sc(m, j, t, s0, c0, md, NULL, e, edot, eddot);
}

static inline void coord(const gd_clearance *cl, const double *y, int ndof, double *x, double *v)
{
    double a = 0, b = 0;
    for (int q = 0; q < cl->nw; q++) {
        a += cl->wval[q] * y[cl->widx[q]];
        b += cl->wval[q] * y[ndof + cl->widx[q]];
    }
    *x = a;
    *v = b;
}

GD_API void gd_model_clearance(const gd_model *m, int c, double t, const double *y, const gd_modes *md, double *x,
                               double *xdot)
{
    const gd_clearance *cl = &m->clear[c];
    coord(cl, y, m->ndof, x, xdot);
    if (cl->kind == GD_CLR_MESH) {
        double e, ed;
        gd_model_error(m, cl->mesh, t, md, &e, &ed, NULL);
        *x -= e;
        *xdot -= ed;
    }
}

GD_API void gd_model_clearances(const gd_model *m, double t, const double *y, const gd_modes *md, double *x,
                                double *xdot)
{
    double s0 = 0.0, c0 = 1.0;
    if (m->nmesh > 0)
        sincos(m->Omega * t, &s0, &c0);
    gd_model_clearances_sc(m, t, s0, c0, y, md, x, xdot);
}

void gd_model_clearances_sc(const gd_model *m, double t, double s0, double c0, const double *y, const gd_modes *md,
                            double *x, double *xdot)
{
    double e[GD_MAX_MESH], ed[GD_MAX_MESH];
    for (int j = 0; j < m->nmesh; j++)
        mesh_eval_sc(m, j, t, s0, c0, md, NULL, &e[j], &ed[j], NULL);
    for (int c = 0; c < m->nclear; c++) {
        const gd_clearance *cl = &m->clear[c];
        coord(cl, y, m->ndof, &x[c], &xdot[c]);
        if (cl->kind == GD_CLR_MESH) {
            x[c] -= e[cl->mesh];
            xdot[c] -= ed[cl->mesh];
        }
    }
}

GD_API int gd_model_mode_of(const gd_model *m, int c, double x) { return model_mode_of(m, c, x); }

/* Force of clearance c along -w (dimensionless) and the current stiffness factor. */
static inline double clear_force(const gd_model *m, int c, double x, double v, double kfac, int mode)
{
    const gd_clearance *cl = &m->clear[c];
    double f = 0.0;
    if (mode > 0)
        f = cl->k * kfac * (x - cl->h);
    else if (mode < 0)
        f = cl->k * kfac * (x + cl->h);
    if (!cl->damp_contact_only || mode != 0)
        f += cl->c * v;
    return f;
}

GD_API void gd_model_custom(gd_model *m, const gd_custom_system *sys, double period)
{
    memset(m, 0, sizeof *m);
    m->custom = sys;
    m->n = sys->n;
    m->ndof = sys->n;
    m->period = period;
    m->Omega = 2.0 * M_PI / period;
    m->omega_n = 1.0;
    m->bc_m = 1.0;
    m->m_ref = m->k_ref = 1.0;
    m->dte_scale = m->force_share = 1.0;
}

/* sin and cos of Omega t (0 and 1 without meshes: nothing reads them) */
static inline void phase_sc(const gd_model *m, double t, double *s0, double *c0)
{
    *s0 = 0.0, *c0 = 1.0;
    if (m->nmesh > 0)
        sincos(m->Omega * t, s0, c0);
}

GD_API void gd_model_tangent(const gd_model *m, double t, const double *y, const double *v, double *out,
                             const gd_modes *md)
{
    double s0, c0;
    phase_sc(m, t, &s0, &c0);
    gd_model_tangent_sc(m, t, s0, c0, y, v, out, md);
}

void gd_model_tangent_sc(const gd_model *m, double t, double s0, double c0, const double *y, const double *v,
                         double *out, const gd_modes *md)
{
    if (m->custom) {
        m->custom->tangent(t, y, v, out, m->custom->ctx);
        return;
    }
    const int nd = m->ndof;
    const double *dv = v + nd;
    double *da = out + nd;
    double kf[GD_MAX_MESH];
    for (int j = 0; j < m->nmesh; j++)
        mesh_eval_sc(m, j, t, s0, c0, md, &kf[j], &(double){0}, NULL, NULL);
    for (int i = 0; i < nd; i++) {
        out[i] = dv[i];
        da[i] = 0.0;
    }
    for (int q = 0; q < m->nk; q++)
        da[m->K0[q].i] -= m->K0[q].v * v[m->K0[q].j];
    for (int q = 0; q < m->nc; q++)
        da[m->C0[q].i] -= m->C0[q].v * dv[m->C0[q].j];
    for (int c = 0; c < m->nclear; c++) {
        const gd_clearance *cl = &m->clear[c];
        int mode;
        if (md->from_state) {
            double x, xd;
            gd_model_clearance(m, c, t, y, md, &x, &xd);
            mode = gd_model_mode_of(m, c, x);
        } else {
            mode = md->mode[c];
        }
        double ks = mode != 0 ? cl->k * (cl->kind == GD_CLR_MESH ? kf[cl->mesh] : 1.0) : 0.0;
        double cs = (!cl->damp_contact_only || mode != 0) ? cl->c : 0.0;
        if (ks == 0.0 && cs == 0.0)
            continue;
        double dx = 0, dxd = 0;
        for (int q = 0; q < cl->nw; q++) {
            dx += cl->wval[q] * v[cl->widx[q]];
            dxd += cl->wval[q] * dv[cl->widx[q]];
        }
        double f = ks * dx + cs * dxd;
        for (int q = 0; q < cl->nw; q++)
            da[cl->widx[q]] -= cl->wval[q] * f;
    }
    for (int i = 0; i < nd; i++)
        da[i] *= m->inv_mass[i];
}

GD_API double gd_model_pulse_force(const gd_model *m, int j, double t, const gd_modes *md, int mode)
{
    return pulse_force(m, j, t, md, mode);
}

GD_API int gd_model_pulse_after(const gd_model *m, int j, double t)
{
    const gd_mesh_excitation *x = &m->mesh[j];
    return pulse_at(x, mesh_phase(m, j, t) + 1e-9);
}

GD_API void gd_model_rhs(const gd_model *m, double t, const double *y, double *ydot, const gd_modes *md)
{
    double s0, c0;
    phase_sc(m, t, &s0, &c0);
    gd_model_rhs_sc(m, t, s0, c0, y, ydot, md);
}

void gd_model_rhs_sc(const gd_model *m, double t, double s0, double c0, const double *y, double *ydot,
                     const gd_modes *md)
{
    if (m->custom) {
        m->custom->rhs(t, y, ydot, m->custom->ctx);
        return;
    }
    const int nd = m->ndof;
    const double *v = y + nd;
    /* the forces add up in a local array (it cannot alias the model or the state: the compiler
     * keeps the model's fields in registers), in the same order as always */
    double a[GD_MAX_DOF];
    double kf[GD_MAX_MESH], e[GD_MAX_MESH], ed[GD_MAX_MESH];
    for (int j = 0; j < m->nmesh; j++)
        mesh_eval_sc(m, j, t, s0, c0, md, &kf[j], &e[j], &ed[j], NULL);
    for (int i = 0; i < nd; i++)
        a[i] = m->F0[i];
    for (int q = 0; q < m->nk; q++)
        a[m->K0[q].i] -= m->K0[q].v * y[m->K0[q].j];
    for (int q = 0; q < m->nc; q++)
        a[m->C0[q].i] -= m->C0[q].v * v[m->C0[q].j];
    for (int c = 0; c < m->nclear; c++) {
        const gd_clearance *cl = &m->clear[c];
        double x, xd;
        coord(cl, y, nd, &x, &xd);
        double kfac = 1.0;
        if (cl->kind == GD_CLR_MESH) {
            x -= e[cl->mesh];
            xd -= ed[cl->mesh];
            kfac = kf[cl->mesh];
        }
        int mode = md->from_state ? gd_model_mode_of(m, c, x) : md->mode[c];
        double f = clear_force(m, c, x, xd, kfac, mode);
        if (cl->kind == GD_CLR_MESH)
            f += pulse_force(m, cl->mesh, t, md, mode);
        for (int q = 0; q < cl->nw; q++)
            a[cl->widx[q]] -= cl->wval[q] * f;
    }
    for (int i = 0; i < nd; i++) {
        ydot[i] = v[i];
        ydot[nd + i] = a[i] * m->inv_mass[i];
    }
}

GD_API void gd_model_jacobian(const gd_model *m, double t, const double *y, double *J, const gd_modes *md)
{
    if (m->custom) {
        m->custom->jacobian(t, y, J, m->custom->ctx);
        return;
    }
    const int nd = m->ndof, n = m->n;
    memset(J, 0, sizeof(double) * (size_t)n * (size_t)n);
    for (int i = 0; i < nd; i++)
        J[i * n + nd + i] = 1.0;
    for (int q = 0; q < m->nk; q++)
        J[(nd + m->K0[q].i) * n + m->K0[q].j] -= m->K0[q].v;
    for (int q = 0; q < m->nc; q++)
        J[(nd + m->C0[q].i) * n + nd + m->C0[q].j] -= m->C0[q].v;
    for (int c = 0; c < m->nclear; c++) {
        const gd_clearance *cl = &m->clear[c];
        double x, xd;
        gd_model_clearance(m, c, t, y, md, &x, &xd);
        int mode = md->from_state ? gd_model_mode_of(m, c, x) : md->mode[c];
        double kfac = cl->kind == GD_CLR_MESH ? gd_model_stiffness(m, cl->mesh, t, md) : 1.0;
        double ks = mode != 0 ? cl->k * kfac : 0.0;
        double cs = (!cl->damp_contact_only || mode != 0) ? cl->c : 0.0;
        for (int p = 0; p < cl->nw; p++)
            for (int q = 0; q < cl->nw; q++) {
                double ww = cl->wval[p] * cl->wval[q];
                J[(nd + cl->widx[p]) * n + cl->widx[q]] -= ks * ww;
                J[(nd + cl->widx[p]) * n + nd + cl->widx[q]] -= cs * ww;
            }
    }
    for (int i = 0; i < nd; i++)
        for (int j = 0; j < n; j++)
            J[(nd + i) * n + j] *= m->inv_mass[i];
}

GD_API void gd_model_roots(const gd_model *m, double t, const double *y, double *g, const gd_modes *md)
{
    double s0, c0;
    phase_sc(m, t, &s0, &c0);
    gd_model_roots_sc(m, t, s0, c0, y, g, md);
}

void gd_model_roots_sc(const gd_model *m, double t, double s0, double c0, const double *y, double *g,
                       const gd_modes *md)
{
    double e[GD_MAX_MESH];
    for (int j = 0; j < m->nmesh; j++)
        mesh_eval_sc(m, j, t, s0, c0, md, NULL, &e[j], NULL, NULL);
    for (int c = 0; c < m->nclear; c++) {
        const gd_clearance *cl = &m->clear[c];
        double x = 0;
        for (int q = 0; q < cl->nw; q++)
            x += cl->wval[q] * y[cl->widx[q]];
        if (cl->kind == GD_CLR_MESH)
            x -= e[cl->mesh];
        g[2 * c] = x - cl->h;
        g[2 * c + 1] = x + cl->h;
    }
}

GD_API double gd_model_energy(const gd_model *m, double t, const double *y, const gd_modes *md)
{
    const int nd = m->ndof;
    double E = 0;
    for (int i = 0; i < nd; i++)
        E += 0.5 * m->mass[i] * y[nd + i] * y[nd + i] - m->F0[i] * y[i];
    for (int q = 0; q < m->nk; q++)
        E += 0.5 * y[m->K0[q].i] * m->K0[q].v * y[m->K0[q].j];
    for (int c = 0; c < m->nclear; c++) {
        const gd_clearance *cl = &m->clear[c];
        double x, xd;
        gd_model_clearance(m, c, t, y, md, &x, &xd);
        double kfac = cl->kind == GD_CLR_MESH ? gd_model_stiffness(m, cl->mesh, t, md) : 1.0;
        double d = x > cl->h ? x - cl->h : (x < -cl->h ? x + cl->h : 0.0);
        E += 0.5 * cl->k * kfac * d * d;
    }
    return E;
}

/* first edge of a periodic on/off pattern (edges at fractions e0, e1 of the cycle) strictly after
 * t, or +inf */
static double next_edge(const gd_model *m, int j, double t, double e0, double e1)
{
    const gd_mesh_excitation *x = &m->mesh[j];
    double ph = (m->Omega * t + x->phase) / (2.0 * M_PI);
    double k = floor(ph), tiny = 1e-12 * (fabs(t) + m->period), best = INFINITY;
    for (int cyc = -1; cyc <= 2; cyc++) {
        double cand[2] = {k + cyc + e0, k + cyc + e1};
        for (int q = 0; q < 2; q++) {
            /* the edge computed back from the phase can land on or before t: skip it, never the next */
            double tc = (2.0 * M_PI * cand[q] - x->phase) / m->Omega;
            if (tc > t + tiny && tc < best)
                best = tc;
        }
    }
    return best;
}

GD_API double gd_model_next_discontinuity(const gd_model *m, double t, const gd_modes *md)
{
    (void)md;
    double best = INFINITY;
    for (int j = 0; j < m->nmesh; j++) {
        const gd_mesh_excitation *x = &m->mesh[j];
        if (x->kind == GD_STIFF_RECTANGULAR)
            best = fmin(best, next_edge(m, j, t, 0.0, x->rect_frac));
        for (int k = 0; k < x->nimp; k++) {
            double e0 = x->imp_phase[k] / (2.0 * M_PI);
            best = fmin(best, next_edge(m, j, t, e0 - floor(e0), e0 - floor(e0) + x->imp_width[k] / (2.0 * M_PI)));
        }
    }
    return best;
}

GD_API int gd_model_rect_level_after(const gd_model *m, int j, double t, const gd_modes *md)
{
    (void)md;
    const gd_mesh_excitation *x = &m->mesh[j];
    double f = mesh_phase(m, j, t) / (2.0 * M_PI) + 1e-9;
    f -= floor(f);
    return f < x->rect_frac;
}

/* Static equilibrium under F0 with the meshes in drive-side contact at mean stiffness.
 * The bearings start on the side a linear solve (no clearance) puts them, then their
 * modes are corrected until every spring in contact pushes (never pulls). */
GD_API gd_status gd_model_static_state(const gd_model *m, double *y, gd_modes *md, gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    const int nd = m->ndof;
    int modes[GD_MAX_CLEAR];
    double hsave[GD_MAX_CLEAR];
    for (int c = 0; c < m->nclear; c++) {
        modes[c] = 1;
        hsave[c] = m->clear[c].h;
    }
    gsl_matrix *A = gsl_matrix_alloc((size_t)nd, (size_t)nd), *V = gsl_matrix_alloc((size_t)nd, (size_t)nd);
    gsl_vector *b = gsl_vector_alloc((size_t)nd), *S = gsl_vector_alloc((size_t)nd),
               *w = gsl_vector_alloc((size_t)nd), *x = gsl_vector_alloc((size_t)nd);
    gd_status st = GD_OK;
    if (!A || !V || !b || !S || !w || !x) {
        st = gd_error_set(err, GD_ERR_NOMEM, "static state: out of memory");
        goto done;
    }
    int converged = 0;
    for (int iter = 0; iter < 50 && !converged; iter++) {
        gsl_matrix_set_zero(A);
        for (int i = 0; i < nd; i++)
            gsl_vector_set(b, (size_t)i, m->F0[i]);
        for (int q = 0; q < m->nk; q++)
            *gsl_matrix_ptr(A, (size_t)m->K0[q].i, (size_t)m->K0[q].j) += m->K0[q].v;
        for (int c = 0; c < m->nclear; c++) {
            const gd_clearance *cl = &m->clear[c];
            if (modes[c] == 0)
                continue;
            /* first pass: bearings as plain springs, to learn which side they load */
            double h = (iter == 0 && cl->kind != GD_CLR_MESH) ? 0.0 : hsave[c];
            double em = cl->kind == GD_CLR_MESH ? m->mesh[cl->mesh].e_m : 0.0;
            for (int p = 0; p < cl->nw; p++) {
                for (int q = 0; q < cl->nw; q++)
                    *gsl_matrix_ptr(A, (size_t)cl->widx[p], (size_t)cl->widx[q]) += cl->k * cl->wval[p] * cl->wval[q];
                *gsl_vector_ptr(b, (size_t)cl->widx[p]) += cl->k * cl->wval[p] * (em + modes[c] * h);
            }
        }
        /* minimum-norm solution: an axially floating body has a free rigid mode */
        int rc = gsl_linalg_SV_decomp(A, V, S, w);
        if (rc == GSL_SUCCESS) {
            double smax = gsl_vector_get(S, 0);
            for (size_t i = 0; i < (size_t)nd; i++)
                if (gsl_vector_get(S, i) < 1e-12 * smax)
                    gsl_vector_set(S, i, 0.0);
            rc = gsl_linalg_SV_solve(A, V, S, b, x);
        }
        if (rc != GSL_SUCCESS) {
            st = gd_error_set(err, GD_ERR_GSL, "static state: gsl_linalg_SV: %s", gsl_strerror(rc));
            goto done;
        }
        memset(y, 0, sizeof(double) * (size_t)m->n);
        for (int i = 0; i < nd; i++)
            y[i] = gsl_vector_get(x, (size_t)i);
        int changed = 0;
        for (int c = 0; c < m->nclear; c++) {
            if (m->clear[c].kind == GD_CLR_MESH)
                continue;
            double xc, vc;
            gd_model_clearance(m, c, 0.0, y, md, &xc, &vc);
            int nm;
            if (iter == 0)
                nm = xc > 0 ? 1 : xc < 0 ? -1 : 0;
            else if (modes[c] != 0)
                nm = modes[c] * xc > hsave[c] ? modes[c] : 0; /* a contact that would pull opens */
            else
                nm = gd_model_mode_of(m, c, xc);
            if (nm != modes[c] || iter == 0) {
                changed |= nm != modes[c];
                modes[c] = nm;
            }
        }
        converged = iter > 0 && !changed;
    }
    if (!converged) {
        st = gd_error_set(err, GD_ERR_PHYSICS, "static state: no consistent set of bearing contacts was found");
        goto done;
    }
    for (int c = 0; c < m->nclear; c++)
        md->mode[c] = modes[c];
    st = gd_model_consistent_modes(m, 0.0, y, md, err);
done:
    gsl_matrix_free(A);
    gsl_matrix_free(V);
    gsl_vector_free(b);
    gsl_vector_free(S);
    gsl_vector_free(w);
    gsl_vector_free(x);
    return st;
}

GD_API gd_status gd_model_consistent_modes(const gd_model *m, double t, const double *y, gd_modes *md, gd_error *err)
{
    double yd[GD_MAX_STATE];
    int from_state = md->from_state;
    md->from_state = 0;
    for (int c = 0; c < m->nclear; c++) {
        double x, v;
        gd_model_clearance(m, c, t, y, md, &x, &v);
        double h = m->clear[c].h, tiny = 1e-12 * (1.0 + h);
        int on_hi = fabs(x - h) <= tiny, on_lo = fabs(x + h) <= tiny;
        if (!on_hi && !on_lo) {
            md->mode[c] = gd_model_mode_of(m, c, x);
            continue;
        }
        /* on a boundary: the side the motion leaves to. The velocity decides unless it is
         * so small (a rounding residue, e.g. of e'(0) = e_r Omega cos(pi/2)) that the
         * acceleration carries the point out of the +-tiny band first: x - x0 = v s +
         * a s^2 / 2 is dominated by the velocity only if v^2 > 2 tiny |a|. */
        gd_model_rhs(m, t, y, yd, md);
        double a = 0;
        for (int q = 0; q < m->clear[c].nw; q++)
            a += m->clear[c].wval[q] * yd[m->ndof + m->clear[c].widx[q]];
        if (m->clear[c].kind == GD_CLR_MESH) {
            double e, ed, edd;
            gd_model_error(m, m->clear[c].mesh, t, md, &e, &ed, &edd);
            a -= edd;
        }
        double d = v * v > 2.0 * tiny * fabs(a) ? v : a;
        if (on_hi && on_lo) /* zero gap */
            md->mode[c] = d >= 0 ? 1 : -1;
        else if (on_hi)
            md->mode[c] = d >= 0 ? 1 : 0;
        else
            md->mode[c] = d <= 0 ? -1 : 0;
    }
    md->from_state = from_state;
    (void)err;
    return GD_OK;
}

GD_API gd_status gd_model_set_stiffness_table(gd_model *m, int j, const double *k, int n, gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    if (j < 0 || j >= m->nmesh)
        return gd_error_set(err, GD_ERR_INTERNAL, "stiffness table for mesh %d of %d", j, m->nmesh);
    if (n < 2 || n % 2 || n > 2 * GD_MESH_HARMONICS)
        return gd_error_set(err, GD_ERR_INPUT, "stiffness table of %d samples (valid: even, 2 to %d)", n,
                            2 * GD_MESH_HARMONICS);
    double buf[2 * GD_MESH_HARMONICS];
    for (int i = 0; i < n; i++) {
        if (!(k[i] > 0) || !isfinite(k[i]))
            return gd_error_set(err, GD_ERR_PHYSICS, "stiffness table of mesh %d: sample %d is %g N/m (valid: positive)",
                                j, i, k[i]);
        buf[i] = k[i] / m->k_ref;
    }
    gsl_fft_real_wavetable *tab = gsl_fft_real_wavetable_alloc((size_t)n);
    gsl_fft_real_workspace *ws = gsl_fft_real_workspace_alloc((size_t)n);
    int rc = (tab && ws) ? gsl_fft_real_transform(buf, 1, (size_t)n, tab, ws) : GSL_ENOMEM;
    gsl_fft_real_wavetable_free(tab);
    gsl_fft_real_workspace_free(ws);
    if (rc != GSL_SUCCESS)
        return gd_error_set(err, GD_ERR_GSL, "stiffness table: gsl_fft_real_transform: %s", gsl_strerror(rc));
    gd_mesh_excitation *x = &m->mesh[j];
    x->kind = GD_STIFF_TABLE;
    x->mean = buf[0] / n;
    x->nh = n / 2;
    for (int h = 1; h <= n / 2; h++) {
        double re = 2 * h == n ? buf[n - 1] : buf[2 * h - 1], im = 2 * h == n ? 0.0 : buf[2 * h];
        double scale = 2 * h == n ? 1.0 / n : 2.0 / n; /* the Nyquist term appears once */
        x->a[h - 1] = scale * sqrt(re * re + im * im);
        x->phi[h - 1] = atan2(im, re); /* Re(X e^{i h th}) = |X| cos(h th + arg X) */
        x->cphi[h - 1] = cos(x->phi[h - 1]);
        x->sphi[h - 1] = sin(x->phi[h - 1]);
    }
    return GD_OK;
}

GD_API gd_status gd_model_add_impact(gd_model *m, int j, double force_n, double phase_rad, double duration_s,
                                     gd_error *err)
{
    if (j < 0 || j >= m->nmesh)
        return gd_error_set(err, GD_ERR_INTERNAL, "impact for mesh %d of %d", j, m->nmesh);
    gd_mesh_excitation *x = &m->mesh[j];
    if (x->nimp >= GD_MAX_PULSE)
        return gd_error_set(err, GD_ERR_INTERNAL, "a pulse more than %d on mesh %d", GD_MAX_PULSE, j);
    double width = duration_s * m->omega_n * m->Omega; /* seconds -> radians of mesh phase */
    if (width > 2.0 * M_PI && width < 2.0 * M_PI * (1.0 + 1e-12)) /* a whole period, up to its rounding */
        width = 2.0 * M_PI;
    if (!(width >= 0) || width > 2.0 * M_PI || !isfinite(force_n))
        return gd_error_set(err, GD_ERR_PHYSICS, "impact pulse of %g s at %g N: it must last at most a mesh period "
                            "(%g s)", duration_s, force_n, 2.0 * M_PI / (m->omega_n * m->Omega));
    if (width == 0.0) /* no pulse */
        return GD_OK;
    int k = x->nimp++;
    x->imp_force[k] = force_n / (m->k_ref * m->bc_m);
    x->imp_phase[k] = phase_rad - 2.0 * M_PI * floor(phase_rad / (2.0 * M_PI));
    x->imp_width[k] = width;
    return GD_OK;
}

GD_API gd_status gd_model_set_error_table(gd_model *m, int j, const double *e_m, int n, gd_error *err)
{
    gd_gsl_quiet();
    if (j < 0 || j >= m->nmesh)
        return gd_error_set(err, GD_ERR_INTERNAL, "error table for mesh %d of %d", j, m->nmesh);
    if (n < 2 || n % 2 || n > 2 * GD_MESH_HARMONICS)
        return gd_error_set(err, GD_ERR_INPUT, "error table of %d samples (valid: even, 2 to %d)", n,
                            2 * GD_MESH_HARMONICS);
    double buf[2 * GD_MESH_HARMONICS];
    for (int i = 0; i < n; i++) {
        if (!isfinite(e_m[i]))
            return gd_error_set(err, GD_ERR_PHYSICS, "error table of mesh %d: sample %d is %g m (valid: finite)", j, i,
                                e_m[i]);
        buf[i] = e_m[i] / m->bc_m;
    }
    gsl_fft_real_wavetable *tab = gsl_fft_real_wavetable_alloc((size_t)n);
    gsl_fft_real_workspace *ws = gsl_fft_real_workspace_alloc((size_t)n);
    int rc = (tab && ws) ? gsl_fft_real_transform(buf, 1, (size_t)n, tab, ws) : GSL_ENOMEM;
    gsl_fft_real_wavetable_free(tab);
    gsl_fft_real_workspace_free(ws);
    if (rc != GSL_SUCCESS)
        return gd_error_set(err, GD_ERR_GSL, "error table: gsl_fft_real_transform: %s", gsl_strerror(rc));
    gd_mesh_excitation *x = &m->mesh[j];
    x->ne = n / 2;
    for (int h = 1; h <= n / 2; h++) { /* the mean (buf[0]) is left out */
        double re = 2 * h == n ? buf[n - 1] : buf[2 * h - 1], im = 2 * h == n ? 0.0 : buf[2 * h];
        double scale = 2 * h == n ? 1.0 / n : 2.0 / n;
        x->ea[h - 1] = scale * sqrt(re * re + im * im);
        x->ephi[h - 1] = atan2(im, re);
        x->cephi[h - 1] = cos(x->ephi[h - 1]);
        x->sephi[h - 1] = sin(x->ephi[h - 1]);
    }
    return GD_OK;
}

GD_API gd_status gd_model_set_impact(gd_model *m, int j, double force_n, double phase_rad, double duration_s,
                                     gd_error *err)
{
    if (j < 0 || j >= m->nmesh)
        return gd_error_set(err, GD_ERR_INTERNAL, "impact for mesh %d of %d", j, m->nmesh);
    m->mesh[j].nimp = 0;
    return gd_model_add_impact(m, j, force_n, phase_rad, duration_s, err);
}

/* d/dt of the stiffness factor of mesh j: the harmonic series differentiated term by term
 * (a rectangular or constant factor is constant between the stops at its edges) */
static double stiffness_rate(const gd_model *m, int j, double t)
{
    const gd_mesh_excitation *x = &m->mesh[j];
    if (x->kind != GD_STIFF_HARMONIC && x->kind != GD_STIFF_TABLE)
        return 0.0;
    double ph = mesh_phase(m, j, t), r = 0.0;
    for (int h = 0; h < x->nh; h++)
        r -= x->a[h] * (double)(h + 1) * sin((h + 1) * ph + x->phi[h]);
    return r * m->Omega;
}

GD_API int gd_model_jerk(const gd_model *m, double t, const double *y, const double *acc, double *jerk,
                         const gd_modes *md)
{
    if (m->custom)
        return -1;
    const int nd = m->ndof;
    /* along the state: the tangent map applied to the motion (v, acc) */
    double yd[GD_MAX_STATE], out[GD_MAX_STATE];
    memcpy(yd, y + nd, sizeof(double) * (size_t)nd);
    memcpy(yd + nd, acc, sizeof(double) * (size_t)nd);
    double s0, c0; /* one sine and cosine of Omega t for the tangent map and the excitation */
    phase_sc(m, t, &s0, &c0);
    gd_model_tangent_sc(m, t, s0, c0, y, yd, out, md);
    /* along the time: the mesh clearances' stiffness factor and error move with t (x_c = w.q - e,
     * so dx/dt = -e', dxdot/dt = -e''); F0 and the impact pulses are constant between the stops
     * at their edges */
    double da[GD_MAX_DOF] = {0};
    double kf[GD_MAX_MESH], e[GD_MAX_MESH], ed[GD_MAX_MESH], edd[GD_MAX_MESH];
    for (int j = 0; j < m->nmesh; j++)
        mesh_eval_sc(m, j, t, s0, c0, md, &kf[j], &e[j], &ed[j], &edd[j]);
    for (int c = 0; c < m->nclear; c++) {
        const gd_clearance *cl = &m->clear[c];
        if (cl->kind != GD_CLR_MESH)
            continue;
        const int j = cl->mesh;
        double x = -e[j];
        for (int q = 0; q < cl->nw; q++)
            x += cl->wval[q] * y[cl->widx[q]];
        int mode = md->from_state ? gd_model_mode_of(m, c, x) : md->mode[c];
        double ft = 0.0; /* the explicit time derivative of clear_force */
        if (mode != 0)
            ft = cl->k * (stiffness_rate(m, j, t) * (x - (mode > 0 ? cl->h : -cl->h)) - kf[j] * ed[j]);
        if (!cl->damp_contact_only || mode != 0)
            ft -= cl->c * edd[j];
        for (int q = 0; q < cl->nw; q++)
            da[cl->widx[q]] -= cl->wval[q] * ft;
    }
    for (int i = 0; i < nd; i++)
        jerk[i] = out[nd + i] + da[i] * m->inv_mass[i];
    return 0;
}
