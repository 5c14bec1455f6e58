/* The local analysis of one operating point: the chosen response variable's samples, Poincare
 * points and amplitude spectrum (the tables and the four-panel figure of the paper's Figs.
 * 16-42 are drawn from these). */
#include "analysis_internal.h"
#include "geardyn/gd_spectrum.h"
#include "../case/case_keys.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { VAR_LAMBDA, VAR_DTE, VAR_DOF };

gd_status gd_local_resolve(const gd_case *c, const gd_model *m, gd_local *v, gd_error *err)
{
    memset(v, 0, sizeof *v);
    const char *name = c->response_variable[0] ? c->response_variable : "lambda_L";
    snprintf(v->name, sizeof v->name, "%s", name);
    int two = m->nmesh > 1; /* the right mesh's variables exist with two meshes only */
    if (strcmp(name, "lambda_L") == 0 || strcmp(name, "dte_L") == 0 ||
        (two && (strcmp(name, "lambda_R") == 0 || strcmp(name, "dte_R") == 0))) {
        v->kind = name[0] == 'l' ? VAR_LAMBDA : VAR_DTE;
        v->index = name[strlen(name) - 1] == 'R' ? 1 : 0;
        return GD_OK;
    }
    for (int i = 0; i < m->ndof; i++)
        if (strcmp(name, m->dof_name[i]) == 0) {
            v->kind = VAR_DOF;
            v->index = i;
            return GD_OK;
        }
    char valid[512];
    snprintf(valid, sizeof valid, "%s", two ? "lambda_L, lambda_R, dte_L, dte_R" : "lambda_L, dte_L");
    for (int i = 0; i < m->ndof; i++) {
        size_t l = strlen(valid);
        snprintf(valid + l, sizeof valid - l, ", %s", m->dof_name[i]);
    }
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    int line = 0;
    gd_source src = gd_case_source(c, (size_t)(gd_case_find_key("output", "response_variable") - s), &line);
    char where[GD_PATH_MAX + 32];
    if (src == GD_SRC_FILE)
        snprintf(where, sizeof where, "%s:%d", c->path, line);
    else
        snprintf(where, sizeof where, "--set #%d", line);
    return gd_error_set(err, GD_ERR_INPUT, "%s: output.response_variable: '%s' is not a variable of this model "
                        "(valid: %s)", where, name, valid);
}

/* value (um) and rate (m/s) of the variable at dimensionless time t in state y */
void gd_local_value(const gd_model *m, const gd_local *v, double t, const double *y, double *x, double *xdot)
{
    gd_modes md;
    memset(&md, 0, sizeof md);
    double um = m->bc_m * 1e6, mps = m->bc_m * m->omega_n;
    if (v->kind == VAR_LAMBDA) {
        gd_model_clearance(m, m->mesh_clear[v->index], t, y, &md, x, xdot);
    } else if (v->kind == VAR_DTE) {
        *x = y[m->q_dof[v->index]] / m->dte_scale;
        *xdot = y[m->ndof + m->q_dof[v->index]] / m->dte_scale;
    } else {
        *x = y[v->index];
        *xdot = y[m->ndof + v->index];
    }
    *x *= um;
    *xdot *= mps;
}

int gd_local_add_sample(gd_local *L, double t_s, double x, double xdot)
{
    if (L->n == L->cap) {
        size_t cap = L->cap ? 2 * L->cap : 4096;
        double *nt = realloc(L->t, cap * sizeof(double)), *nx = nt ? realloc(L->x, cap * sizeof(double)) : NULL;
        double *nv = nx ? realloc(L->xd, cap * sizeof(double)) : NULL;
        if (nt) L->t = nt;
        if (nx) L->x = nx;
        if (!nv)
            return 1;
        L->xd = nv;
        L->cap = cap;
    }
    L->t[L->n] = t_s;
    L->x[L->n] = x;
    L->xd[L->n] = xdot;
    L->n++;
    return 0;
}

int gd_local_add_poincare(gd_local *L, double x, double xdot)
{
    if (L->np == L->pcap) {
        size_t cap = L->pcap ? 2 * L->pcap : 256;
        double *a = realloc(L->px, cap * sizeof(double)), *b = a ? realloc(L->pxd, cap * sizeof(double)) : NULL;
        if (a) L->px = a;
        if (!b)
            return 1;
        L->pxd = b;
        L->pcap = cap;
    }
    L->px[L->np] = x;
    L->pxd[L->np] = xdot;
    L->np++;
    return 0;
}

gd_status gd_local_spectrum(gd_local *L, double dt_s, gd_error *err)
{
    size_t nf = L->n / 2 + 1;
    L->freq_hz = malloc(nf * sizeof(double));
    L->amp_um = malloc(nf * sizeof(double));
    if (!L->freq_hz || !L->amp_um)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the spectrum");
    gd_status st = gd_amplitude_spectrum(L->x, L->n, dt_s, L->freq_hz, L->amp_um, err);
    if (st != GD_OK)
        return st;
    L->nfreq = nf;
    L->spec_amax = 0;
    for (size_t k = 0; k < nf; k++)
        if (L->amp_um[k] > L->spec_amax)
            L->spec_amax = L->amp_um[k];
    return GD_OK;
}

void gd_local_free(gd_local *L)
{
    free(L->t);
    free(L->x);
    free(L->xd);
    free(L->px);
    free(L->pxd);
    free(L->freq_hz);
    free(L->amp_um);
    memset(L, 0, sizeof *L);
}
