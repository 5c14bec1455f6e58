/* summary.json's derived.modal of a dynamic run: the natural frequencies of the case's model, their
 * resonance speeds, shapes and strain-energy shares (gd_scene_modes; docs/model.md section 9.7). */
#include "output_internal.h"

#include "json_util.h"
#include "../case/case_keys.h"

#include <jansson.h>
#include <math.h>

/* Where the mean mesh stiffness of the linearisation came from. */
static const char *stiffness_source(const gd_case *c)
{
    if (c->stiffness == GD_STIFF_LTCA)
        return c->ltca_deferred ? "iso6336 (estimate; the run takes ltca)" : "ltca";
    int line;
    gd_source s = gd_case_source(c, gd_case_key_index("excitation", "mesh_stiffness_n_per_m"), &line);
    return s == GD_SRC_DERIVED ? "iso6336" : gd_source_name(s);
}

static json_t *shape_json(const gd_modal *md, const double *shape)
{
    json_t *o = json_object();
    for (int i = 0; i < md->ndof; i++)
        json_object_set_new(o, md->dof_name[i], gd_json_num(shape[i]));
    return o;
}

static json_t *mode_json(const gd_modal *md, int k)
{
    static const char *const harm[GD_MODAL_HARMONICS] = {"main", "1/2", "1/3", "1/4"};
    json_t *o = json_object();
    json_object_set_new(o, "mode", json_integer(k + 1));
    json_object_set_new(o, "frequency_hz", gd_json_num(md->freq_hz[k]));
    json_t *r = json_object();
    for (int h = 0; h < GD_MODAL_HARMONICS; h++)
        json_object_set_new(r, harm[h], gd_json_num(md->resonance_rpm[k][h]));
    json_object_set_new(o, "resonance_rpm", r);
    json_object_set_new(o, "halves", md->mirrored ? json_string(gd_modal_halves(md, k)) : json_null());
    json_object_set_new(o, "shape", shape_json(md, md->shape[k]));
    json_t *sh = json_object();
    for (int e = 0; e < md->nelem; e++)
        json_object_set_new(sh, md->elem[e].name, gd_json_num(md->share[k][e]));
    json_object_set_new(o, "strain_energy_share", sh);
    return o;
}

json_t *gd_modal_json(const gd_case *c, const gd_modal *md)
{
    json_t *o = json_object();
    if (md->failed[0]) {
        json_object_set_new(o, "error", json_string(md->failed));
        return o;
    }
    json_object_set_new(o, "linearisation",
                        json_string("static operating point: every mesh in drive-side contact at its mean stiffness, "
                                    "every bearing on the side the load puts it; undamped"));
    json_t *k = json_array();
    for (int j = 0; j < md->nmesh; j++)
        json_array_append_new(k, gd_json_num(md->mesh_stiffness_n_per_m[j]));
    json_object_set_new(o, "mesh_stiffness_n_per_m", k);
    json_object_set_new(o, "mesh_stiffness_source", json_string(stiffness_source(c)));
    json_t *rig = json_array();
    for (int r = 0; r < md->nrigid; r++)
        json_array_append_new(rig, shape_json(md, md->rigid_shape[r]));
    json_object_set_new(o, "rigid_body_modes", rig);
    json_t *modes = json_array();
    for (int m = 0; m < md->nmodes; m++)
        json_array_append_new(modes, mode_json(md, m));
    json_object_set_new(o, "modes", modes);
    return o;
}
