/* The modal analysis of a model linearised in held contact modes: its stiffness matrix assembled
 * from the model's springs, the undamped modes by GSL's generalized symmetric-definite eigensolver,
 * rigid-body modes kept apart, symmetric and antisymmetric modes of a mirror-symmetric system, and
 * the share of each spring in each mode's strain energy (docs/model.md section 9.7). */
#include "geardyn/gd_modal.h"
#include "../core/gsl_quiet.h"

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* An eigenvalue at most this fraction of the largest is a rigid-body mode: rounding in the
 * eigensolver leaves about 1e-16 n of the largest on an exact zero. */
#define RIGID_TOL 1e-9
/* Eigenvalues closer than this fraction of the largest are one (degenerate) frequency. */
#define CLUSTER_TOL 1e-8

GD_API double gd_modal_mean_stiffness(const gd_model *m, int j)
{
    const gd_mesh_excitation *x = &m->mesh[j];
    switch (x->kind) {
    case GD_STIFF_HARMONIC:
    case GD_STIFF_TABLE:
        return x->mean; /* the cosines average to 0 over a cycle */
    case GD_STIFF_RECTANGULAR:
        return x->rect_frac * x->rect_high + (1.0 - x->rect_frac) * x->rect_low;
    default:
        return 1.0;
    }
}

/* The linearised stiffness of clearance c in mode md (0 when open). */
static double clearance_k(const gd_model *m, int c, const gd_modes *md)
{
    const gd_clearance *cl = &m->clear[c];
    if (md->mode[c] == 0)
        return 0.0;
    return cl->k * (cl->kind == GD_CLR_MESH ? gd_modal_mean_stiffness(m, cl->mesh) : 1.0);
}

GD_API gd_status gd_modal_stiffness(const gd_model *m, const gd_modes *md, double *K, gd_error *err)
{
    if (m->custom)
        return gd_error_set(err, GD_ERR_INPUT, "modal analysis: a custom system has no springs to analyse");
    const int nd = m->ndof;
    memset(K, 0, sizeof(double) * (size_t)nd * (size_t)nd);
    for (int q = 0; q < m->nk; q++)
        K[m->K0[q].i * nd + m->K0[q].j] += m->K0[q].v;
    for (int c = 0; c < m->nclear; c++) {
        const gd_clearance *cl = &m->clear[c];
        double k = clearance_k(m, c, md);
        for (int p = 0; p < cl->nw; p++)
            for (int q = 0; q < cl->nw; q++)
                K[cl->widx[p] * nd + cl->widx[q]] += k * cl->wval[p] * cl->wval[q];
    }
    double kmax = 0.0, asym = 0.0;
    for (int i = 0; i < nd * nd; i++)
        kmax = fmax(kmax, fabs(K[i]));
    for (int i = 0; i < nd; i++)
        for (int j = 0; j < i; j++)
            asym = fmax(asym, fabs(K[i * nd + j] - K[j * nd + i]));
    if (!isfinite(kmax) || asym > 1e-12 * kmax)
        return gd_error_set(err, GD_ERR_INTERNAL, "modal analysis: the stiffness matrix is not symmetric (%g of %g)",
                            asym, kmax);
    return GD_OK;
}

static void elem_name(gd_modal_element *e, const gd_model *m)
{
    if (e->kind == GD_MODAL_CLEARANCE)
        snprintf(e->name, sizeof e->name, "%s", m->clear[e->clear].name);
    else if (e->kind == GD_MODAL_GROUND)
        snprintf(e->name, sizeof e->name, "k(%s)", m->dof_name[e->i]);
    else
        snprintf(e->name, sizeof e->name, "k(%s,%s)", m->dof_name[e->i], m->dof_name[e->j]);
}

/* The springs of the model: every clearance, then K0 written exactly as springs to ground and
 * between pairs of DOFs, x.K0.x = sum_i g_i x_i^2 + sum_{i<j} (-K0_ij) (x_i - x_j)^2 with
 * g_i = sum_j K0_ij (the row sum). */
static gd_status elements(const gd_model *m, const gd_modes *md, gd_modal *out, gd_error *err)
{
    const int nd = m->ndof;
    double K0[GD_MAX_DOF * GD_MAX_DOF] = {0}, kmax = 0.0;
    for (int q = 0; q < m->nk; q++)
        K0[m->K0[q].i * nd + m->K0[q].j] += m->K0[q].v;
    for (int i = 0; i < nd * nd; i++)
        kmax = fmax(kmax, fabs(K0[i]));
    int n = 0;
    for (int c = 0; c < m->nclear; c++)
        out->elem[n++] = (gd_modal_element){GD_MODAL_CLEARANCE, c, -1, -1, clearance_k(m, c, md), ""};
    for (int i = 0; i < nd; i++) {
        double g = 0.0;
        for (int j = 0; j < nd; j++)
            g += K0[i * nd + j];
        if (fabs(g) > 1e-14 * kmax) {
            if (n == GD_MODAL_MAX_ELEM)
                return gd_error_set(err, GD_ERR_INTERNAL, "modal analysis: more than %d springs", GD_MODAL_MAX_ELEM);
            out->elem[n++] = (gd_modal_element){GD_MODAL_GROUND, -1, i, -1, g, ""};
        }
    }
    for (int i = 0; i < nd; i++)
        for (int j = i + 1; j < nd; j++)
            if (K0[i * nd + j] != 0.0) {
                if (n == GD_MODAL_MAX_ELEM)
                    return gd_error_set(err, GD_ERR_INTERNAL, "modal analysis: more than %d springs", GD_MODAL_MAX_ELEM);
                out->elem[n++] = (gd_modal_element){GD_MODAL_COUPLING, -1, i, j, -K0[i * nd + j], ""};
            }
    out->nelem = n;
    for (int e = 0; e < n; e++)
        elem_name(&out->elem[e], m);
    return GD_OK;
}

/* Strain energy of element e for the displacement phi. */
static double elem_strain(const gd_model *m, const gd_modal_element *e, const double *phi)
{
    double d;
    if (e->kind == GD_MODAL_CLEARANCE) {
        const gd_clearance *cl = &m->clear[e->clear];
        d = 0.0;
        for (int q = 0; q < cl->nw; q++)
            d += cl->wval[q] * phi[cl->widx[q]];
    } else if (e->kind == GD_MODAL_GROUND) {
        d = phi[e->i];
    } else {
        d = phi[e->i] - phi[e->j];
    }
    return 0.5 * e->k * d * d;
}

/* Whether the mirror maps K and M onto themselves (P K P = K, P M P = M, P an involution). */
static int mirror_keeps(const gd_model *m, const gd_modal_mirror *mir, const double *K)
{
    const int nd = m->ndof;
    double kmax = 0.0;
    for (int i = 0; i < nd * nd; i++)
        kmax = fmax(kmax, fabs(K[i]));
    for (int i = 0; i < nd; i++) {
        int pi = mir->dof[i];
        if (pi < 0 || pi >= nd || mir->dof[pi] != i || fabs(mir->sign[i]) != 1.0 || mir->sign[pi] != mir->sign[i])
            return 0;
        if (fabs(m->mass[pi] - m->mass[i]) > 1e-12 * fabs(m->mass[i]))
            return 0;
        for (int j = 0; j < nd; j++) {
            int pj = mir->dof[j];
            if (fabs(mir->sign[i] * mir->sign[j] * K[pi * nd + pj] - K[i * nd + j]) > 1e-12 * kmax)
                return 0;
        }
    }
    return 1;
}

/* phi.M.(P phi) for columns a and b of V */
static double mirror_product(const gd_model *m, const gd_modal_mirror *mir, const gsl_matrix *V, size_t a, size_t b)
{
    double s = 0.0;
    for (int i = 0; i < m->ndof; i++)
        s += gsl_matrix_get(V, (size_t)i, a) * m->mass[i] * mir->sign[i] * gsl_matrix_get(V, (size_t)mir->dof[i], b);
    return s;
}

/* Within each cluster of equal eigenvalues, the basis that diagonalises the mirror (its eigenvalues
 * +1 and -1): the symmetric and antisymmetric modes of that frequency. V is M-orthonormal. */
static gd_status split_clusters(const gd_model *m, const gd_modal_mirror *mir, const gsl_vector *eval, gsl_matrix *V,
                                gd_error *err)
{
    const size_t nd = (size_t)m->ndof;
    double lmax = fmax(fabs(gsl_vector_get(eval, nd - 1)), fabs(gsl_vector_get(eval, 0)));
    size_t a = 0;
    while (a < nd) {
        size_t b = a + 1;
        while (b < nd && gsl_vector_get(eval, b) - gsl_vector_get(eval, b - 1) <= CLUSTER_TOL * lmax)
            b++;
        size_t d = b - a;
        if (d > 1) {
            gsl_matrix *S = gsl_matrix_alloc(d, d), *U = gsl_matrix_alloc(d, d), *W = gsl_matrix_alloc(nd, d);
            gsl_vector *s = gsl_vector_alloc(d);
            gsl_eigen_symmv_workspace *ws = gsl_eigen_symmv_alloc(d);
            int rc = (S && U && W && s && ws) ? GSL_SUCCESS : GSL_ENOMEM;
            if (rc == GSL_SUCCESS) {
                for (size_t p = 0; p < d; p++)
                    for (size_t q = 0; q < d; q++)
                        gsl_matrix_set(S, p, q, 0.5 * (mirror_product(m, mir, V, a + p, a + q) +
                                                       mirror_product(m, mir, V, a + q, a + p)));
                rc = gsl_eigen_symmv(S, s, U, ws);
            }
            if (rc == GSL_SUCCESS)
                rc = gsl_eigen_symmv_sort(s, U, GSL_EIGEN_SORT_VAL_DESC);
            if (rc == GSL_SUCCESS) {
                for (size_t i = 0; i < nd; i++)
                    for (size_t q = 0; q < d; q++) {
                        double v = 0.0;
                        for (size_t p = 0; p < d; p++)
                            v += gsl_matrix_get(V, i, a + p) * gsl_matrix_get(U, p, q);
                        gsl_matrix_set(W, i, q, v);
                    }
                for (size_t i = 0; i < nd; i++)
                    for (size_t q = 0; q < d; q++)
                        gsl_matrix_set(V, i, a + q, gsl_matrix_get(W, i, q));
            }
            gsl_matrix_free(S);
            gsl_matrix_free(U);
            gsl_matrix_free(W);
            gsl_vector_free(s);
            gsl_eigen_symmv_free(ws);
            if (rc != GSL_SUCCESS)
                return gd_error_set(err, rc == GSL_ENOMEM ? GD_ERR_NOMEM : GD_ERR_GSL,
                                    "modal analysis: the mirror within %zu equal frequencies: gsl_eigen_symmv: %s", d,
                                    gsl_strerror(rc));
        }
        a = b;
    }
    return GD_OK;
}

/* phi scaled so that its largest component (the first of equal ones) is +1. */
static void scale_shape(const double *phi, int nd, double *out)
{
    int imax = 0;
    for (int i = 1; i < nd; i++)
        if (fabs(phi[i]) > fabs(phi[imax]) * (1.0 + 1e-12))
            imax = i;
    double s = phi[imax] != 0.0 ? 1.0 / phi[imax] : 0.0;
    for (int i = 0; i < nd; i++)
        out[i] = phi[i] * s;
}

/* The modes from the eigenpairs: rigid ones apart, the elastic ones with their strain energies. */
static void fill_modes(const gd_model *m, const gd_modal_mirror *mir, const gsl_vector *eval, const gsl_matrix *V,
                       gd_modal *out)
{
    const int nd = m->ndof;
    double lmax = fmax(gsl_vector_get(eval, (size_t)nd - 1), 0.0);
    for (int k = 0; k < nd; k++) {
        double lam = gsl_vector_get(eval, (size_t)k), phi[GD_MAX_DOF], nrm = 0.0;
        for (int i = 0; i < nd; i++) {
            phi[i] = gsl_matrix_get(V, (size_t)i, (size_t)k);
            nrm += m->mass[i] * phi[i] * phi[i];
        }
        nrm = sqrt(nrm);
        for (int i = 0; i < nd; i++)
            phi[i] /= nrm; /* phi.M.phi = 1 */
        if (lam <= RIGID_TOL * lmax) {
            scale_shape(phi, nd, out->rigid_shape[out->nrigid++]);
            continue;
        }
        int r = out->nmodes++;
        out->lambda[r] = lam;
        out->freq_hz[r] = sqrt(lam) * m->omega_n / (2.0 * M_PI);
        scale_shape(phi, nd, out->shape[r]);
        double sum = 0.0;
        for (int e = 0; e < out->nelem; e++) {
            out->strain[r][e] = elem_strain(m, &out->elem[e], phi);
            sum += out->strain[r][e];
        }
        for (int e = 0; e < out->nelem; e++)
            out->share[r][e] = sum > 0 ? out->strain[r][e] / sum : 0.0;
        out->mirror_corr[r] = NAN;
        if (mir) {
            double c = 0.0;
            for (int i = 0; i < nd; i++)
                c += phi[i] * m->mass[i] * mir->sign[i] * phi[mir->dof[i]];
            out->mirror_corr[r] = c;
        }
        for (int h = 0; h < GD_MODAL_HARMONICS; h++)
            out->resonance_rpm[r][h] = NAN;
    }
}

GD_API gd_status gd_modal_analyse(const gd_model *m, const gd_modes *md, const gd_modal_mirror *mirror,
                                  gd_modal *out, gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    memset(out, 0, sizeof *out);
    double K[GD_MAX_DOF * GD_MAX_DOF];
    gd_status st = gd_modal_stiffness(m, md, K, err);
    if (st != GD_OK)
        return st;
    const int nd = m->ndof;
    out->ndof = nd;
    for (int i = 0; i < nd; i++)
        memcpy(out->dof_name[i], m->dof_name[i], sizeof out->dof_name[i]);
    for (int c = 0; c < m->nclear; c++)
        out->contact[c] = md->mode[c];
    out->nmesh = m->nmesh;
    for (int j = 0; j < m->nmesh; j++)
        out->mesh_stiffness_n_per_m[j] = m->k_ref * gd_modal_mean_stiffness(m, j);
    st = elements(m, md, out, err);
    if (st != GD_OK)
        return st;
    for (int i = 0; i < nd; i++)
        if (!(m->mass[i] > 0) || !isfinite(m->mass[i]))
            return gd_error_set(err, GD_ERR_INTERNAL, "modal analysis: mass %g of %s", m->mass[i], m->dof_name[i]);
    const gd_modal_mirror *mir = mirror && mirror_keeps(m, mirror, K) ? mirror : NULL;
    out->mirrored = mir != NULL;

    gsl_matrix *A = gsl_matrix_alloc((size_t)nd, (size_t)nd), *B = gsl_matrix_calloc((size_t)nd, (size_t)nd),
               *V = gsl_matrix_alloc((size_t)nd, (size_t)nd);
    gsl_vector *eval = gsl_vector_alloc((size_t)nd);
    gsl_eigen_gensymmv_workspace *ws = gsl_eigen_gensymmv_alloc((size_t)nd);
    int rc = (A && B && V && eval && ws) ? GSL_SUCCESS : GSL_ENOMEM;
    const char *call = "gsl_eigen_gensymmv_alloc";
    if (rc == GSL_SUCCESS) {
        for (int i = 0; i < nd; i++) {
            for (int j = 0; j < nd; j++) /* the mean of K and K^T: symmetric to the last bit */
                gsl_matrix_set(A, (size_t)i, (size_t)j, 0.5 * (K[i * nd + j] + K[j * nd + i]));
            gsl_matrix_set(B, (size_t)i, (size_t)i, m->mass[i]);
        }
        call = "gsl_eigen_gensymmv";
        rc = gsl_eigen_gensymmv(A, B, eval, V, ws);
    }
    if (rc == GSL_SUCCESS) {
        call = "gsl_eigen_gensymmv_sort";
        rc = gsl_eigen_gensymmv_sort(eval, V, GSL_EIGEN_SORT_VAL_ASC);
    }
    if (rc != GSL_SUCCESS)
        st = gd_error_set(err, rc == GSL_ENOMEM ? GD_ERR_NOMEM : GD_ERR_GSL, "modal analysis: %s: %s", call,
                          gsl_strerror(rc));
    if (st == GD_OK && mir)
        st = split_clusters(m, mir, eval, V, err);
    if (st == GD_OK)
        fill_modes(m, mir, eval, V, out);
    gsl_matrix_free(A);
    gsl_matrix_free(B);
    gsl_matrix_free(V);
    gsl_vector_free(eval);
    gsl_eigen_gensymmv_free(ws);
    return st;
}
