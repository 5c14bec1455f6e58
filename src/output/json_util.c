/* The parts of summary.json every analysis shares: the resolved case and the atomic write. */
#include "json_util.h"

#include <math.h>
#include <stdio.h>

#include "output_internal.h"
#include "geardyn/gd_version.h"
#include "../case/case_keys.h"

json_t *gd_json_num(double v) { return isfinite(v) ? json_real(v) : json_null(); }

json_t *gd_json_halves_num(const double v[2], int halves, double scale)
{
    json_t *o = json_object();
    json_object_set_new(o, "left", gd_json_num(v[0] * scale));
    json_object_set_new(o, "right", halves > 1 ? gd_json_num(v[1] * scale) : json_null());
    return o;
}

json_t *gd_json_halves_int(const int v[2], int halves)
{
    json_t *o = json_object();
    json_object_set_new(o, "left", json_integer(v[0]));
    json_object_set_new(o, "right", halves > 1 ? json_integer(v[1]) : json_null());
    return o;
}

json_t *gd_json_edge_names(unsigned bits)
{
    json_t *a = json_array();
    for (int k = 0; k < GD_EDGE_NKINDS; k++)
        if (bits & (1u << k))
            json_array_append_new(a, json_string(gd_edge_kind_name(k)));
    return a;
}

json_t *gd_json_files(const char *const *files, int nfiles)
{
    json_t *fl = json_array();
    for (int i = 0; i < nfiles; i++)
        json_array_append_new(fl, json_string(files[i]));
    return fl;
}

json_t *gd_json_case(const gd_case *c)
{
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    json_t *root = json_object();
    for (size_t i = 0; i < n; i++) {
        json_t *sec = json_object_get(root, s[i].section);
        if (!sec) {
            sec = json_object();
            json_object_set_new(root, s[i].section, sec);
        }
        json_t *e = json_object();
        const void *fp = (const char *)c + s[i].offset;
        switch (s[i].type) {
        case GD_KEY_DOUBLE: json_object_set_new(e, "value", gd_json_num(*(const double *)fp)); break;
        case GD_KEY_INT: json_object_set_new(e, "value", json_integer(*(const int *)fp)); break;
        case GD_KEY_BOOL: json_object_set_new(e, "value", json_boolean(*(const int *)fp)); break;
        case GD_KEY_DLIST: {
            json_t *a = json_array();
            int cnt = *(const int *)((const char *)c + s[i].count_offset);
            for (int j = 0; j < cnt; j++)
                json_array_append_new(a, json_real(((const double *)fp)[j]));
            json_object_set_new(e, "value", a);
            break;
        }
        default: {
            char buf[1200];
            gd_case_format_value(c, i, buf, sizeof buf);
            json_object_set_new(e, "value", json_string(buf));
        }
        }
        json_object_set_new(e, "unit", json_string(s[i].unit));
        int line;
        gd_source src = gd_case_source(c, i, &line);
        char where[64];
        if (src == GD_SRC_FILE)
            snprintf(where, sizeof where, "file:%d", line);
        else if (src == GD_SRC_SET)
            snprintf(where, sizeof where, "--set #%d", line);
        else
            snprintf(where, sizeof where, "%s", gd_source_name(src));
        json_object_set_new(e, "source", json_string(where));
        json_object_set_new(sec, s[i].key, e);
    }
    return root;
}

json_t *gd_json_root(const gd_case *c, const char *analysis, const char *section, const char *key)
{
    json_t *root = json_object();
    json_object_set_new(root, "geardyn_version", json_string(GD_VERSION_STRING));
    json_object_set_new(root, "analysis", json_string(analysis));
    if (key) {
        char val[1200];
        gd_case_format_value(c, gd_case_key_index(section, key), val, sizeof val);
        json_object_set_new(root, key, json_string(val));
    }
    json_t *cs = json_object();
    json_object_set_new(cs, "path", json_string(c->path));
    json_object_set_new(cs, "parameters", gd_json_case(c));
    json_object_set_new(root, "case", cs);
    return root;
}

gd_status gd_json_write(gd_run_dir *d, const char *name, json_t *root, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, name, &fp, err);
    if (st == GD_OK && json_dumpf(root, fp, JSON_INDENT(2) | JSON_PRESERVE_ORDER | JSON_REAL_PRECISION(12)) != 0) {
        gd_run_dir_discard(d, fp);
        st = gd_error_set(err, GD_ERR_IO, "%s/%s: cannot write JSON", gd_run_dir_path(d), name);
    } else if (st == GD_OK) {
        fputc('\n', fp);
        st = gd_run_dir_commit(d, fp, err);
    }
    json_decref(root);
    return st;
}

gd_status gd_json_write_summary(gd_run_dir *d, json_t *root, gd_error *err)
{
    int n;
    const char *const *files = gd_run_dir_files(d, &n);
    json_t *fl = gd_json_files(files, n);
    json_array_append_new(fl, json_string("summary.json"));
    json_object_set_new(root, "files", fl);
    return gd_json_write(d, "summary.json", root, err);
}
