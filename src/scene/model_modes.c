/* The modal analysis of a case's model (docs/model.md section 9.7): linearised at the static
 * operating point (meshes in drive-side contact, bearings on the side the load puts them), the
 * mirror of a herringbone's halves, the springs named as the case names them, and the pinion
 * speeds at which the mesh frequency and its harmonics meet each natural frequency. */
#include "geardyn/gd_scene.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The mirror of a herringbone's halves (docs/model.md section 7.3): qL <-> qR in torsional-lr;
 * (y, z, q) of half L <-> (y, -z, q) of half R in bta (the hand sign changes with the half). */
static int herringbone_mirror(const gd_model *m, gd_modal_mirror *mir)
{
    if (m->nmesh != 2)
        return 0;
    if (m->kind == GD_MODEL_TORSIONAL_LR && m->ndof == 2) {
        *mir = (gd_modal_mirror){{1, 0}, {1.0, 1.0}};
        return 1;
    }
    if (m->kind != GD_MODEL_BTA || m->ndof != 10)
        return 0;
    for (int i = 0; i < 10; i++) {
        mir->dof[i] = (i + 5) % 10;
        mir->sign[i] = (i % 5 == 1 || i % 5 == 3) ? -1.0 : 1.0;
    }
    return 1;
}

/* bta's springs of K0 by what they are: the radial and axial supports of each body and half, the
 * groove shafts between the halves (a radial support with a clearance is the clearance
 * "bearing-1L" itself; the same name when it is a linear spring). */
static void name_springs(const gd_model *m, gd_modal *md)
{
    if (m->kind != GD_MODEL_BTA)
        return;
    for (int e = 0; e < md->nelem; e++) {
        gd_modal_element *el = &md->elem[e];
        int half = el->i / 5, role = el->i % 5;
        const char *sfx = m->nmesh == 1 ? "" : half ? "R" : "L";
        if (el->kind == GD_MODAL_GROUND && role < 4)
            snprintf(el->name, sizeof el->name, "%s-%d%s", role % 2 ? "axial" : "bearing", role / 2 + 1, sfx);
        else if (el->kind == GD_MODAL_COUPLING && el->j == el->i + 5 && (role == 1 || role == 3))
            snprintf(el->name, sizeof el->name, "groove-%d", role / 2 + 1);
    }
}

GD_API gd_status gd_scene_modes(const gd_case *c, const gd_model *m, gd_modal *out, gd_error *err)
{
    double y[GD_MAX_STATE];
    gd_modes md;
    memset(&md, 0, sizeof md);
    gd_status st = gd_model_static_state(m, y, &md, err);
    if (st != GD_OK)
        return gd_error_prefix(err, "modal analysis");
    for (int j = 0; j < m->nmesh; j++) /* drive-side contact even where the load leaves the flanks just touching */
        md.mode[m->mesh_clear[j]] = 1;
    gd_modal_mirror mir;
    st = gd_modal_analyse(m, &md, herringbone_mirror(m, &mir) ? &mir : NULL, out, err);
    if (st != GD_OK)
        return st;
    name_springs(m, out);
    for (int k = 0; k < out->nmodes; k++)
        for (int h = 0; h < GD_MODAL_HARMONICS; h++)
            out->resonance_rpm[k][h] = 60.0 * out->freq_hz[k] / ((h + 1) * c->teeth_pinion);
    return GD_OK;
}
