/* A periodic orbit at a fixed parameter: Newton shooting from a guess (shooting.c), its Floquet
 * multipliers (floquet.c), and the model at a parameter value (a mesh frequency, or a case key
 * with the model built again). */
#include "shooting.h"
#include "geardyn/gd_scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

GD_API void gd_po_opts_default(gd_po_opts *po)
{
    memset(po, 0, sizeof *po);
    po->nper = 1;
    po->multiple = 1;
    po->tol = 0.0;
    po->max_iter = 12;
    po->dp_rel = 0.0;
}

/* the model of gd_po_solve: the one given, whatever p */
static gd_status model_fixed(double p, gd_model *m, void *ctx, gd_error *err)
{
    (void)p;
    (void)err;
    *m = *(const gd_model *)ctx;
    return GD_OK;
}

GD_API gd_status gd_po_solve(const gd_model *m, const gd_solver_opts *o, const gd_po_opts *po, const double *y0,
                             gd_po *orbit, gd_error *err)
{
    gd_shoot sh;
    gd_status st = gd_shoot_init(&sh, model_fixed, (void *)m, o, m->n, po, err);
    if (st != GD_OK)
        return st;
    double u[GD_PO_MAX_PERIODS * GD_MAX_STATE + 1];
    memcpy(u, y0, sizeof(double) * (size_t)m->n);
    for (int k = 1; k < sh.nseg && st == GD_OK; k++) /* the other segments start on the images of y0 */
        st = gd_sim_period_map(m, o, u + (k - 1) * m->n, sh.per_seg, u + k * m->n, NULL, NULL, err);
    u[sh.N] = m->Omega;
    int iters = 0;
    double tol = po->tol > 0 ? po->tol : gd_po_tol_derived(o, gd_po_state_scale(u, sh.N));
    if (st == GD_OK)
        st = gd_shoot_correct(&sh, u, NULL, NULL, tol, po->max_iter, &iters, err);
    if (st == GD_OK)
        st = gd_shoot_orbit(&sh, u, orbit, err);
    if (st == GD_OK)
        orbit->iterations = iters;
    gd_shoot_free(&sh);
    return st;
}

GD_API gd_status gd_model_at_mesh_frequency(double Omega, gd_model *m, void *ctx, gd_error *err)
{
    const gd_model *base = ctx;
    if (!(Omega > 0) || !isfinite(Omega))
        return gd_error_set(err, GD_ERR_INPUT, "mesh frequency Omega = %g (valid: above 0)", Omega);
    for (int j = 0; j < base->nmesh; j++)
        if (base->mesh[j].nimp > 0)
            return gd_error_set(err, GD_ERR_INPUT,
                                "the mesh-in impact of mesh %d lasts a fixed time, so its phase width depends on the "
                                "speed: a model of another mesh frequency must be built from the case", j);
    *m = *base;
    m->Omega = Omega;
    m->period = 2.0 * M_PI / Omega;
    m->mesh_freq_hz = Omega * m->omega_n / (2.0 * M_PI);
    return GD_OK;
}

GD_API gd_status gd_model_at_case_key(double p, gd_model *m, void *ctx, gd_error *err)
{
    const gd_case_param *a = ctx;
    gd_status st = gd_case_set_number(a->c, a->key, a->scale * p, err);
    /* resolved as gd_case_resolve resolves a response: the analysis's own keys do not change */
    if (st == GD_OK)
        st = gd_case_check(a->c, err);
    if (st == GD_OK)
        st = gd_scene_resolve(a->c, err);
    if (st == GD_OK)
        st = gd_model_build(a->c, m, err);
    return st == GD_OK ? GD_OK : gd_error_prefix(err, "the model at %s = %.9g", a->key, a->scale * p);
}
