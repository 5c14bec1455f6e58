/* What geardyn check shows, as JSON text for a program (gd_case_check_json): the resolved case,
 * the derived geometry and model scales as a dynamic run's summary.json gives them, the model's
 * modes and the estimated cost of the run. */
#include "output_internal.h"
#include "geardyn/gd_scene.h"

#include "json_util.h"

#include <stdlib.h>
#include <string.h>

gd_status gd_check_json_text(const gd_case *c, const gd_model *m, const gd_run_cost *cost, char **text,
                             gd_error *err)
{
    *text = NULL;
    json_t *root = json_object();
    char val[64];
    size_t n;
    const gd_keyspec *s0 = gd_case_schema(&n), *k = gd_case_find_key("scene", "analysis");
    gd_case_format_value(c, (size_t)(k - s0), val, sizeof val);
    json_object_set_new(root, "analysis", json_string(val));
    json_t *cs = json_object();
    json_object_set_new(cs, "path", json_string(c->path));
    json_object_set_new(cs, "parameters", gd_json_case(c));
    json_object_set_new(root, "case", cs);
    json_t *der = gd_json_response_derived(c, m);
    gd_modal md;
    gd_error e = {0};
    if (gd_scene_modes(c, m, &md, &e) != GD_OK) {
        memset(&md, 0, sizeof md);
        snprintf(md.failed, sizeof md.failed, "%s", e.msg[0] ? e.msg : "modal analysis failed");
    }
    json_object_set_new(der, "modal", gd_modal_json(c, &md));
    json_object_set_new(der, "mesh_stiffness_estimated", json_boolean(c->stiffness == GD_STIFF_LTCA && c->ltca_deferred));
    json_object_set_new(root, "derived", der);
    json_t *co = json_object();
    json_object_set_new(co, "time_class", json_string(cost->time_class ? cost->time_class : ""));
    json_object_set_new(co, "seconds", gd_json_num(cost->seconds));
    json_object_set_new(co, "points", gd_json_num(cost->points));
    json_object_set_new(co, "periods", gd_json_num(cost->periods));
    json_object_set_new(co, "steps", gd_json_num(cost->steps));
    json_object_set_new(co, "memory_bytes", gd_json_num(cost->memory_bytes));
    json_object_set_new(co, "disk_bytes", gd_json_num(cost->disk_bytes));
    json_object_set_new(co, "ltca_unknowns", gd_json_num(cost->ltca_unknowns));
    json_object_set_new(co, "max_bytes", gd_json_num(c->max_bytes));
    json_object_set_new(co, "step_amplification", gd_json_num(cost->step_amplification));
    json_object_set_new(co, "step_mode_hz", gd_json_num(cost->step_mode_hz));
    json_object_set_new(co, "stable_steps_per_period", json_integer(cost->stable_steps_per_period));
    json_object_set_new(root, "cost", co);
    *text = json_dumps(root, JSON_INDENT(2) | JSON_PRESERVE_ORDER | JSON_REAL_PRECISION(17));
    json_decref(root);
    if (!*text)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the check's JSON");
    return GD_OK;
}
