/* The robust variant of an optimize run (docs/optimisation.md section 12): its Monte Carlo sample with
 * the objective of the unmodified flank, the case's own and the optimum at every sample (robust.csv),
 * and its block of summary.json (results.robust). */
#include "output_internal.h"

#include "json_util.h"
#include "geardyn/gd_dynobj.h"

#include <jansson.h>
#include <stdio.h>
#include <string.h>

static const char *const flank[3] = {"unmodified", "case", "optimum"};

/* The objective's unit as a column's suffix. */
static const char *unit_suffix(const gd_case *c, const gd_optimize_outcome *o)
{
    if (o->objective == GD_OBJ_GEAR_DYNAMIC)
        return c->opt_dynamic_response == GD_DYN_DTE_PP ? "um" : "mps2";
    return "arcsec";
}

gd_status gd_optimize_write_robust(gd_run_dir *d, const gd_case *c, const gd_optimize_outcome *o, gd_error *err)
{
    const gd_opt_robust_report *r = o->robust;
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "robust.csv", &fp, err);
    if (st != GD_OK)
        return st;
    /* a deviation column per design variable: its key with the unit moved after "deviation" */
    fprintf(fp, "flank,sample,axis_in_plane_deviation_arcmin,axis_cross_plane_deviation_arcmin,"
            "centre_distance_deviation_mm");
    for (int k = 0; k < r->nvars; k++) {
        const char *unit;
        const char *key = gd_opt_gear_variable(o->vars.var[k], &unit, NULL);
        size_t n = strlen(key) - strlen(unit) - 1; /* the key without _um / _mm */
        fprintf(fp, ",%.*s_deviation_%s", (int)n, key, unit);
    }
    fprintf(fp, ",objective_%s\n", unit_suffix(c, o));
    const int m = 3 + r->nvars;
    for (int j = 0; j < 3; j++)
        for (int s = 0; s < r->settings.samples; s++) {
            fprintf(fp, "%s,%d", flank[j], s + 1);
            for (int k = 0; k < m; k++)
                fprintf(fp, ",%.10g", r->dev[(size_t)s * (size_t)m + (size_t)k]);
            fprintf(fp, ",%.17g\n", r->values[j][s]);
        }
    return gd_run_dir_commit(d, fp, err);
}

json_t *gd_optimize_robust_json(const gd_opt_robust_report *r)
{
    json_t *o = json_object();
    json_object_set_new(o, "samples", json_integer(r->settings.samples));
    json_object_set_new(o, "quantile", gd_json_num(r->settings.quantile));
    json_object_set_new(o, "sample_seed", json_integer((json_int_t)r->settings.seed));
    json_object_set_new(o, "misalignment_tilt_arcmin", gd_json_num(r->settings.tilt_arcmin));
    json_object_set_new(o, "misalignment_centre_distance_mm", gd_json_num(r->settings.centre_distance_mm));
    json_object_set_new(o, "deviation_um", gd_json_num(r->settings.amount_um));
    json_object_set_new(o, "deviation_mm", gd_json_num(r->settings.length_mm));
    for (int j = 0; j < 3; j++) {
        json_t *f = json_object();
        json_object_set_new(f, "robust", gd_json_num(r->robust[j]));
        json_object_set_new(f, "nominal", gd_json_num(r->nominal[j]));
        json_object_set_new(o, flank[j], f);
    }
    return o;
}
