/* Where a key's value came from, its range and the names of its values (src/case/case_keys.h). */
#include "case_keys.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

size_t gd_case_key_index(const char *section, const char *key)
{
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    return (size_t)(gd_case_find_key(section, key) - s);
}

int gd_case_key_given(const gd_case *c, const char *section, const char *key)
{
    gd_source s = gd_case_source(c, gd_case_key_index(section, key), NULL);
    return s == GD_SRC_FILE || s == GD_SRC_SET;
}

void gd_case_key_where(const gd_case *c, const char *section, const char *key, char *buf, size_t len)
{
    int line = 0;
    gd_source s = gd_case_source(c, gd_case_key_index(section, key), &line);
    if (s == GD_SRC_FILE)
        snprintf(buf, len, "%s:%d", c->path, line);
    else if (s == GD_SRC_SET)
        snprintf(buf, len, "--set #%d", line);
    else
        snprintf(buf, len, "%s", c->path[0] ? c->path : "case");
}

int gd_case_key_in_range(const gd_keyspec *k, double v)
{
    if (!isfinite(v))
        return 0;
    if (k->min_open ? !(v > k->min) : !(v >= k->min))
        return 0;
    if (k->max_open ? !(v < k->max) : !(v <= k->max))
        return 0;
    return 1;
}

void gd_case_key_derive(gd_case *c, const char *section, const char *key, double *field, double value)
{
    size_t i = gd_case_key_index(section, key);
    if (c->src[i] == GD_SRC_FILE || c->src[i] == GD_SRC_SET)
        return;
    *field = value;
    c->src[i] = GD_SRC_DERIVED;
}

const char *gd_case_key_choice(const char *section, const char *key, int value, char *buf, size_t len)
{
    const char *p = value >= 0 ? gd_case_find_key(section, key)->choices : NULL;
    for (int j = 0; j < value && p; j++) {
        p = strchr(p, '|');
        if (p)
            p++;
    }
    snprintf(buf, len, "%.*s", p ? (int)strcspn(p, "|") : 1, p ? p : "?");
    return buf;
}

const gd_keyspec *gd_case_key_dotted(const char *name)
{
    char buf[256];
    snprintf(buf, sizeof buf, "%s", name);
    char *dot = strchr(buf, '.');
    if (!dot)
        return NULL;
    *dot = '\0';
    return gd_case_find_key(buf, dot + 1);
}

void gd_case_key_range_text(const gd_keyspec *k, char *buf, size_t len)
{
    if (k->type == GD_KEY_INT)
        snprintf(buf, len, "a whole number in [%.0f, %.0f]", k->min, k->max);
    else
        snprintf(buf, len, "a number in %s%g, %g%s%s%s", k->min_open ? "(" : "[", k->min, k->max,
                 k->max_open ? ")" : "]", k->unit[0] ? " " : "", k->unit);
}
