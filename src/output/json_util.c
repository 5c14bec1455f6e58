/* The parts of summary.json every analysis shares: the resolved case and the atomic write. */
#include "json_util.h"

#include <math.h>
#include <stdio.h>

#include "geardyn/gd_output.h"

json_t *gd_json_num(double v) { return isfinite(v) ? json_real(v) : json_null(); }

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

gd_status gd_json_write(const char *dir, const char *name, json_t *root, gd_error *err)
{
    gd_atomic_file f;
    gd_status st = gd_atomic_open(&f, dir, name, err);
    if (st == GD_OK) {
        if (json_dumpf(root, f.fp, JSON_INDENT(2) | JSON_PRESERVE_ORDER | JSON_REAL_PRECISION(12)) != 0) {
            gd_atomic_abort(&f);
            st = gd_error_set(err, GD_ERR_IO, "%s: cannot write JSON", f.path);
        } else {
            fputc('\n', f.fp);
            st = gd_atomic_commit(&f, err);
        }
    }
    json_decref(root);
    return st;
}
