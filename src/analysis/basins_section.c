/* The plane of initial states of a gear model named by its coordinates (docs/basins.md section 1): a
 * mesh deflection over half its backlash and its rate, moved by the mesh's torsional coordinate, or
 * any state component by name; the other components held at a base state. And the model whose
 * stroboscopic map starts at another mesh phase. */
#include "basins_internal.h"
#include "analysis_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

GD_API void gd_model_at_mesh_phase(const gd_model *m, double phase_rad, gd_model *out)
{
    *out = *m;
    if (phase_rad == 0.0)
        return;
    for (int j = 0; j < out->nmesh; j++) {
        gd_mesh_excitation *x = &out->mesh[j];
        x->phase += phase_rad;
        x->cph = cos(x->phase);
        x->sph = sin(x->phase);
    }
}

/* A coordinate: the deflection (rate 0) or rate (rate 1) of mesh `mesh`, or state component `index`. */
typedef struct coord {
    int mesh, rate, index;
} coord;

static gd_status parse_coord(const gd_model *m, const char *name, coord *c, gd_error *err)
{
    c->mesh = c->index = -1;
    c->rate = 0;
    static const char *mesh_names[4] = {"lambda_L", "lambda_R", "lambda_dot_L", "lambda_dot_R"};
    for (int k = 0; k < 4; k++)
        if (strcmp(name, mesh_names[k]) == 0) {
            c->mesh = k % 2;
            c->rate = k / 2;
            if (m->custom || c->mesh >= m->nmesh)
                return gd_error_set(err, GD_ERR_INPUT, "the section coordinate %s: the model has %d mesh%s (valid: "
                                    "lambda_L, lambda_dot_L%s, or a state component)", name, m->custom ? 0 : m->nmesh,
                                    m->nmesh == 1 ? "" : "es", m->nmesh > 1 ? ", lambda_R, lambda_dot_R" : "");
            return GD_OK;
        }
    char names[GD_MAX_STATE][16];
    if (!m->custom) {
        gd_state_names(m, names);
        for (int k = 0; k < m->n; k++)
            if (strcmp(name, names[k]) == 0) {
                c->index = k;
                return GD_OK;
            }
    }
    char list[GD_MAX_STATE * 16 + 64] = "";
    for (int k = 0; !m->custom && k < m->n; k++) {
        size_t u = strlen(list);
        snprintf(list + u, sizeof list - u, "%s%s", k ? ", " : "", names[k]);
    }
    return gd_error_set(err, GD_ERR_INPUT, "the section coordinate '%s' is not one of this model's (valid: lambda_L%s, "
                        "their rates lambda_dot_L%s, or a state component: %s)", name, m->nmesh > 1 ? ", lambda_R" : "",
                        m->nmesh > 1 ? ", lambda_dot_R" : "", list);
}

/* dir and proj of coordinate c; *offset: its value at the zero state (minus the error at t = 0 over h). */
static gd_status coord_vectors(const gd_model *m, const coord *c, double *dir, double *proj, double *offset,
                               gd_error *err)
{
    memset(dir, 0, sizeof(double) * GD_MAX_STATE);
    memset(proj, 0, sizeof(double) * GD_MAX_STATE);
    *offset = 0.0;
    if (c->index >= 0) {
        dir[c->index] = proj[c->index] = 1.0;
        return GD_OK;
    }
    const gd_clearance *cl = &m->clear[m->mesh_clear[c->mesh]];
    int q = m->q_dof[c->mesh];
    double wq = 0.0;
    for (int k = 0; k < cl->nw; k++) {
        proj[cl->widx[k] + (c->rate ? m->ndof : 0)] = cl->wval[k] / cl->h;
        if (cl->widx[k] == q)
            wq = cl->wval[k];
    }
    if (wq == 0.0 || !(cl->h > 0))
        return gd_error_set(err, GD_ERR_INPUT, "the mesh %s has no torsional coordinate or no backlash to move its "
                            "deflection by (valid: a mesh with backlash)", cl->name);
    dir[q + (c->rate ? m->ndof : 0)] = cl->h / wq;
    gd_modes md;
    memset(&md, 0, sizeof md);
    md.from_state = 1;
    double e, ed;
    gd_model_error(m, c->mesh, 0.0, &md, &e, &ed, NULL);
    *offset = -(c->rate ? ed : e) / cl->h;
    return GD_OK;
}

GD_API gd_status gd_basin_section_named(gd_basin_section *s, const gd_model *m, const double *base, const char *x,
                                        const char *y, double x_lo, double x_hi, double y_lo, double y_hi,
                                        int cells_x, int cells_y, gd_error *err)
{
    coord c[2];
    gd_status st = parse_coord(m, x, &c[0], err);
    if (st == GD_OK)
        st = parse_coord(m, y, &c[1], err);
    if (st != GD_OK)
        return st;
    memset(s, 0, sizeof *s);
    s->n = m->n;
    double off[2];
    for (int k = 0; k < 2 && st == GD_OK; k++)
        st = coord_vectors(m, &c[k], s->dir[k], s->proj[k], &off[k], err);
    if (st != GD_OK)
        return st;
    for (int k = 0; k < 2; k++)
        for (int j = 0; j < 2; j++) {
            double d = 0.0;
            for (int q = 0; q < m->n; q++)
                d += s->proj[k][q] * s->dir[j][q];
            if (!(fabs(d - (k == j)) < 1e-12))
                return gd_error_set(err, GD_ERR_INPUT, "the section coordinates %s and %s move the same state "
                                    "component (valid: two independent coordinates, e.g. lambda_L and lambda_dot_L)",
                                    x, y);
        }
    /* the origin: base moved along the directions to coordinates (0, 0), so that proj . origin = -offset and
     * proj . (y - origin) is the coordinate of y (the error's offset included) */
    memcpy(s->origin, base, sizeof(double) * (size_t)m->n);
    for (int k = 0; k < 2; k++) {
        double v = off[k];
        for (int q = 0; q < m->n; q++)
            v += s->proj[k][q] * base[q];
        for (int q = 0; q < m->n; q++)
            s->origin[q] -= v * s->dir[k][q];
    }
    s->lo[0] = x_lo, s->hi[0] = x_hi, s->lo[1] = y_lo, s->hi[1] = y_hi;
    s->cells[0] = cells_x, s->cells[1] = cells_y;
    s->full = m->n == 2;
    return GD_OK;
}
