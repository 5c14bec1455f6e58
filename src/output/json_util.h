/* Internal: the pieces every summary.json writer shares (not exported). */
#ifndef GD_JSON_UTIL_H
#define GD_JSON_UTIL_H

#include <jansson.h>

#include "geardyn/gd_case.h"

/* A finite number, or null. */
json_t *gd_json_num(double v);
/* The resolved case: section -> key -> {value, unit, source}. */
json_t *gd_json_case(const gd_case *c);
/* Write root as dir/name atomically (temporary file, then rename) and release it. */
gd_status gd_json_write(const char *dir, const char *name, json_t *root, gd_error *err);

#endif
