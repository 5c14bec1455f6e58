/* Internal: the pieces every summary.json writer shares (not exported). */
#ifndef GD_JSON_UTIL_H
#define GD_JSON_UTIL_H

#include <jansson.h>

#include "geardyn/gd_case.h"
#include "geardyn/gd_modal.h"
#include "geardyn/gd_model.h"
#include "geardyn/gd_optimize.h"
#include "geardyn/gd_output.h"

/* A finite number, or null. */
json_t *gd_json_num(double v);
/* The resolved case: section -> key -> {value, unit, source}. */
json_t *gd_json_case(const gd_case *c);
/* The opening of every summary.json: geardyn_version, analysis, then (when key is not NULL) the
 * case's value of [section] key under the key's name ("model": "bta"), then the case (path and
 * gd_json_case). */
json_t *gd_json_root(const gd_case *c, const char *analysis, const char *section, const char *key);
/* {"left", "right"} of the two helical halves, each value times scale (right null with one half). */
json_t *gd_json_halves_num(const double v[2], int halves, double scale);
json_t *gd_json_halves_int(const int v[2], int halves);
/* The names of the edge-contact kinds set in bits (gd_edge_kind_name). */
json_t *gd_json_edge_names(unsigned bits);
/* derived.modal of a dynamic run: the modes of the case's model (summary_modes.c), or their error. */
json_t *gd_modal_json(const gd_case *c, const gd_modal *md);
/* "derived" of a dynamic run: the pair's geometry (when it computes) and the model's scales
 * (summary_json.c). */
json_t *gd_json_response_derived(const gd_case *c, const gd_model *m);
/* The files an analysis wrote, as an array (summary.json's "files"). */
json_t *gd_json_files(const char *const *files, int nfiles);
/* Write root as the file name of the run's directory (through gd_run_dir_create/commit) and
 * release it. */
gd_status gd_json_write(gd_run_dir *d, const char *name, json_t *root, gd_error *err);
/* summary.json: root with "files" set to every file of the run so far and summary.json itself. */
gd_status gd_json_write_summary(gd_run_dir *d, json_t *root, gd_error *err);
/* results.robust of an optimize run with optimize.robust (robust_tables.c). */
json_t *gd_optimize_robust_json(const gd_opt_robust_report *r);

#endif
