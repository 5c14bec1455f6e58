/* Reading case files (inih) and --set assignments into a gd_case, strictly. */
#include "geardyn/gd_case.h"
#include "case_keys.h"
#include "case_text.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <ini.h>

GD_API const char *gd_source_name(gd_source s)
{
    switch (s) {
    case GD_SRC_DEFAULT: return "default";
    case GD_SRC_FILE: return "file";
    case GD_SRC_SET: return "--set";
    case GD_SRC_DERIVED: return "derived";
    }
    return "?";
}

static void *field(gd_case *c, const gd_keyspec *k) { return (char *)c + k->offset; }
static const void *cfield(const gd_case *c, const gd_keyspec *k) { return (const char *)c + k->offset; }

/* capacity of a string key's field */
static size_t string_cap(const gd_keyspec *k)
{
    if (k->offset == offsetof(gd_case, directory) || k->offset == offsetof(gd_case, cont_overlay_sweep) ||
        k->offset == offsetof(gd_case, cont_curve_start) ||
        k->offset == offsetof(gd_case, cont_overlay_map) || k->offset == offsetof(gd_case, cont_overlay_curves) ||
        k->offset == offsetof(gd_case, cont_start_sweep))
        return GD_PATH_MAX;
    if (k->offset == offsetof(gd_case, cont_state))
        return sizeof ((gd_case *)0)->cont_state;
    if (k->offset == offsetof(gd_case, table))
        return 128;
    if (k->offset == offsetof(gd_case, response_variable))
        return 32;
    return 256;
}

static void set_default(gd_case *c, const gd_keyspec *k)
{
    switch (k->type) {
    case GD_KEY_DOUBLE: *(double *)field(c, k) = k->def; break;
    case GD_KEY_INT:
    case GD_KEY_ENUM:
    case GD_KEY_BOOL: *(int *)field(c, k) = (int)k->def; break;
    case GD_KEY_STRING: snprintf((char *)field(c, k), string_cap(k), "%s", k->choices ? k->choices : ""); break;
    case GD_KEY_DLIST: *(int *)((char *)c + k->count_offset) = 0; break;
    }
}

GD_API gd_status gd_case_init(gd_case *c, gd_error *err)
{
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    memset(c, 0, sizeof *c);
    c->src = calloc(n, 1);
    c->src_line = calloc(n, sizeof(int));
    if (!c->src || !c->src_line) {
        gd_case_free(c);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory initialising a case");
    }
    for (size_t i = 0; i < n; i++)
        set_default(c, &s[i]);
    return GD_OK;
}

GD_API void gd_case_free(gd_case *c)
{
    if (!c)
        return;
    free(c->src);
    free(c->src_line);
    c->src = NULL;
    c->src_line = NULL;
}

GD_API gd_status gd_case_copy(gd_case *dst, const gd_case *src, gd_error *err)
{
    size_t n;
    gd_case_schema(&n);
    *dst = *src;
    dst->src = malloc(n);
    dst->src_line = malloc(n * sizeof(int));
    if (!dst->src || !dst->src_line) {
        gd_case_free(dst);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory copying a case");
    }
    memcpy(dst->src, src->src, n);
    memcpy(dst->src_line, src->src_line, n * sizeof(int));
    return GD_OK;
}

/* Levenshtein distance, for did-you-mean suggestions. */
static size_t edit_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    if (la > 63 || lb > 63)
        return 64;
    size_t d[64][64];
    for (size_t i = 0; i <= la; i++) d[i][0] = i;
    for (size_t j = 0; j <= lb; j++) d[0][j] = j;
    for (size_t i = 1; i <= la; i++)
        for (size_t j = 1; j <= lb; j++) {
            size_t sub = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
            size_t del = d[i - 1][j] + 1, ins = d[i][j - 1] + 1;
            d[i][j] = sub < del ? (sub < ins ? sub : ins) : (del < ins ? del : ins);
        }
    return d[la][lb];
}

static void list_sections(char *buf, size_t len)
{
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    buf[0] = '\0';
    const char *last = "";
    for (size_t i = 0; i < n; i++)
        if (strcmp(s[i].section, last) != 0) {
            size_t used = strlen(buf);
            snprintf(buf + used, len - used, "%s[%s]", used ? " " : "", s[i].section);
            last = s[i].section;
        }
}

static int section_exists(const char *section)
{
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    for (size_t i = 0; i < n; i++)
        if (strcmp(s[i].section, section) == 0)
            return 1;
    return 0;
}

static gd_status unknown_key(const char *where, const char *section, const char *key, gd_error *err)
{
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    if (!section_exists(section)) {
        char secs[512];
        list_sections(secs, sizeof secs);
        const char *best = NULL;
        size_t bd = 99;
        for (size_t i = 0; i < n; i++) {
            size_t d = edit_distance(section, s[i].section);
            if (d < bd) { bd = d; best = s[i].section; }
        }
        if (best && bd <= 3)
            return gd_error_set(err, GD_ERR_INPUT, "%s: [%s]: unknown section, did you mean [%s]? (valid: %s)",
                                where, section, best, secs);
        return gd_error_set(err, GD_ERR_INPUT, "%s: [%s]: unknown section (valid: %s)", where, section, secs);
    }
    /* the best match in the same section (a key it begins, as speed for speed_rpm, counts as a
     * near match); a key of another section only when none of this section is near */
    const gd_keyspec *best = NULL, *other = NULL;
    size_t bd = 99, od = 99, limit = 4 + strlen(key) / 6;
    for (size_t i = 0; i < n; i++) {
        size_t d = edit_distance(key, s[i].key);
        if (strcmp(section, s[i].section) == 0) {
            if (key[0] && strncmp(s[i].key, key, strlen(key)) == 0 && d > 1)
                d = 1;
            if (d < bd) { bd = d; best = &s[i]; }
        } else if (d < od) { od = d; other = &s[i]; }
    }
    if (!(best && bd <= limit) && other && od + 2 <= limit) {
        best = other;
        bd = od;
    }
    char keys[2048] = "";
    for (size_t i = 0; i < n; i++)
        if (strcmp(s[i].section, section) == 0) {
            size_t used = strlen(keys);
            snprintf(keys + used, sizeof keys - used, "%s%s", used ? ", " : "", s[i].key);
        }
    if (best && bd <= limit)
        return gd_error_set(err, GD_ERR_INPUT, "%s: %s: unknown key in [%s], did you mean %s.%s? (valid: %s)",
                            where, key, section, best->section, best->key, keys);
    return gd_error_set(err, GD_ERR_INPUT, "%s: %s: unknown key in [%s] (valid: %s)", where, key, section, keys);
}

static void describe_range(const gd_keyspec *k, char *buf, size_t len)
{
    switch (k->type) {
    case GD_KEY_ENUM:
    case GD_KEY_BOOL: {
        snprintf(buf, len, "one of ");
        size_t used = strlen(buf);
        for (const char *p = k->choices; *p && used + 2 < len; p++)
            buf[used++] = (*p == '|') ? ',' : *p;
        buf[used] = '\0';
        if (k->type == GD_KEY_BOOL)
            snprintf(buf + used, len - used, " (also true/false, yes/no, 1/0)");
        break;
    }
    case GD_KEY_STRING: snprintf(buf, len, "text"); break;
    case GD_KEY_INT:
        snprintf(buf, len, "a whole number in [%.0f, %.0f]", k->min, k->max);
        break;
    case GD_KEY_DOUBLE:
    case GD_KEY_DLIST:
        snprintf(buf, len, "%s%s%s%g, %g%s%s%s", k->type == GD_KEY_DLIST ? "comma-separated numbers, each " : "",
                 "a finite number in ", k->min_open ? "(" : "[", k->min, k->max, k->max_open ? ")" : "]",
                 k->unit[0] ? " " : "", k->unit);
        break;
    }
}

/* A number as case files write it: decimal, an optional fraction and exponent (no hexadecimal,
 * which strtod would take), or inf / nan, which the caller refuses as not finite. Returns NULL and
 * sets *v, or the problem. */
static const char *parse_number(const char *s, double *v)
{
    while (isspace((unsigned char)*s)) s++;
    const char *p = s;
    if (*p == '+' || *p == '-')
        p++;
    int digits = 0;
    while (isdigit((unsigned char)*p)) { p++; digits++; }
    if (*p == '.')
        for (p++; isdigit((unsigned char)*p); p++) digits++;
    if (digits && (*p == 'e' || *p == 'E')) {
        const char *q = p + 1;
        if (*q == '+' || *q == '-')
            q++;
        if (isdigit((unsigned char)*q)) {
            while (isdigit((unsigned char)*q)) q++;
            p = q;
        }
    }
    while (isspace((unsigned char)*p)) p++;
    int word = !digits && (strncasecmp(s + (*s == '+' || *s == '-'), "inf", 3) == 0 ||
                           strncasecmp(s + (*s == '+' || *s == '-'), "nan", 3) == 0);
    if ((!digits || *p) && !word)
        return "not a number:";
    char *end;
    errno = 0;
    *v = strtod(s, &end);
    while (isspace((unsigned char)*end)) end++;
    if (*end)
        return "not a number:";
    if (errno == ERANGE)
        return fabs(*v) > 1.0 ? "out of the range of a double (above 1.8e308 in magnitude):"
                              : "out of the range of a double (below 2.2e-308 in magnitude, not zero):";
    return NULL;
}

static gd_status bad_value(const char *where, const gd_keyspec *k, const char *value, const char *problem, gd_error *err)
{
    char range[512];
    describe_range(k, range, sizeof range);
    if (!where)
        return gd_error_set(err, GD_ERR_INPUT, "%s.%s: %s '%s' (valid: %s)", k->section, k->key, problem, value,
                            range);
    return gd_error_set(err, GD_ERR_INPUT, "%s: %s.%s: %s '%s' (valid: %s)", where, k->section, k->key, problem,
                        value, range);
}

/* A comma-separated list: every element a number in range, none empty ("0.1,,0.05" and a trailing
 * comma are refused, not read as two values). */
static gd_status store_list(gd_case *c, const gd_keyspec *k, const char *value, const char *where, gd_error *err)
{
    double *arr = field(c, k), v;
    int count = 0;
    char buf[512];
    if (strlen(value) >= sizeof buf)
        return bad_value(where, k, value, "too long:", err);
    snprintf(buf, sizeof buf, "%s", value);
    if (strspn(buf, " \t") == strlen(buf))
        return bad_value(where, k, value, "empty list:", err);
    for (char *tok = buf, *comma; tok; tok = comma ? comma + 1 : NULL) {
        comma = strchr(tok, ',');
        if (comma)
            *comma = '\0';
        const char *problem = parse_number(tok, &v);
        char what[160];
        if (count == GD_MAX_HARMONICS)
            return bad_value(where, k, value, "more than 8 values:", err);
        if (!problem && !gd_case_key_in_range(k, v))
            problem = "out of range:";
        if (problem) {
            const char *t = tok;
            while (isspace((unsigned char)*t)) t++;
            snprintf(what, sizeof what, "%s element %d %s in", *t ? "bad" : "empty", count + 1,
                     *t ? problem : "(two commas, or one at an end)");
            return bad_value(where, k, value, what, err);
        }
        arr[count++] = v;
    }
    *(int *)((char *)c + k->count_offset) = count;
    return GD_OK;
}

/* Store value (text) into key k; where = "file:line" or "--set". */
static gd_status store(gd_case *c, const gd_keyspec *k, const char *value, const char *where, gd_error *err)
{
    double v;
    const char *problem;
    switch (k->type) {
    case GD_KEY_DOUBLE:
        if ((problem = parse_number(value, &v)))
            return bad_value(where, k, value, problem, err);
        if (!isfinite(v))
            return bad_value(where, k, value, "not finite:", err);
        if (!gd_case_key_in_range(k, v))
            return bad_value(where, k, value, "out of range:", err);
        *(double *)field(c, k) = v;
        return GD_OK;
    case GD_KEY_INT:
        if ((problem = parse_number(value, &v)) && strncmp(problem, "out of", 6) == 0)
            return bad_value(where, k, value, problem, err);
        if (problem || v != floor(v))
            return bad_value(where, k, value, "not a whole number:", err);
        if (!gd_case_key_in_range(k, v))
            return bad_value(where, k, value, "out of range:", err);
        *(int *)field(c, k) = (int)v;
        return GD_OK;
    case GD_KEY_BOOL: {
        static const char *yes[] = {"on", "true", "yes", "1"}, *no[] = {"off", "false", "no", "0"};
        for (int i = 0; i < 4; i++) {
            if (strcmp(value, yes[i]) == 0) { *(int *)field(c, k) = 1; return GD_OK; }
            if (strcmp(value, no[i]) == 0) { *(int *)field(c, k) = 0; return GD_OK; }
        }
        return bad_value(where, k, value, "not a switch:", err);
    }
    case GD_KEY_ENUM: {
        int idx = 0;
        const char *p = k->choices;
        size_t vl = strlen(value);
        while (*p) {
            const char *bar = strchr(p, '|');
            size_t l = bar ? (size_t)(bar - p) : strlen(p);
            if (l == vl && strncmp(p, value, l) == 0) {
                *(int *)field(c, k) = idx;
                return GD_OK;
            }
            idx++;
            p += l + (bar ? 1 : 0);
        }
        return bad_value(where, k, value, "unknown choice", err);
    }
    case GD_KEY_STRING: {
        char *dst = field(c, k);
        size_t cap = string_cap(k);
        if (strlen(value) >= cap)
            return bad_value(where, k, value, "too long:", err);
        snprintf(dst, cap, "%s", value);
        return GD_OK;
    }
    case GD_KEY_DLIST:
        return store_list(c, k, value, where, err);
    }
    return gd_error_set(err, GD_ERR_INTERNAL, "bad key type");
}

typedef struct load_ctx {
    gd_case *c;
    gd_error *err;
    const char *next;  /* the rest of the checked text (case_text.h): one line per line of the file */
    int line;
    int failed;
    char section[GD_CASE_MAX_LINE + 1]; /* the section being read, its header's line, its keys so far */
    int section_line, section_keys;
} load_ctx;

/* A section header followed by no key before the next header or the end of the file is refused:
 * it would leave every key of the section at its default while the file seems to set them. */
static int section_empty(load_ctx *ctx)
{
    if (ctx->section_line == 0 || ctx->section_keys > 0)
        return 0;
    gd_error_set(ctx->err, GD_ERR_INPUT, "%s:%d: [%s]: section has no keys (valid: key = value lines under the "
                 "header, or no header)", ctx->c->path, ctx->section_line, ctx->section);
    ctx->failed = 1;
    return 1;
}

/* inih's stream reader: one line of the checked text per call, so ctx->line is the file's line.
 * A section header is checked here, where it is seen, so that an empty [section] is checked too;
 * the section it ends, or the end of the file, must have had a key. */
static char *reader(char *str, int num, void *stream)
{
    load_ctx *ctx = stream;
    if (ctx->failed)
        return NULL;
    if (!*ctx->next) {
        section_empty(ctx);
        return NULL;
    }
    size_t l = strcspn(ctx->next, "\n") + 1;  /* at most GD_CASE_MAX_LINE + 1 < num */
    if (l >= (size_t)num)
        l = (size_t)num - 1;
    memcpy(str, ctx->next, l);
    str[l] = '\0';
    ctx->next += l;
    ctx->line++;
    if (str[0] == '[') {
        char name[GD_CASE_MAX_LINE + 1];
        snprintf(name, sizeof name, "%.*s", (int)strcspn(str + 1, "]"), str + 1);
        if (!section_exists(name)) {
            char where[GD_PATH_MAX + 32];
            snprintf(where, sizeof where, "%s:%d", ctx->c->path, ctx->line);
            unknown_key(where, name, "", ctx->err);
            ctx->failed = 1;
            return NULL;
        }
        if (section_empty(ctx))
            return NULL;
        snprintf(ctx->section, sizeof ctx->section, "%s", name);
        ctx->section_line = ctx->line;
        ctx->section_keys = 0;
    }
    return str;
}

static int handler(void *user, const char *section, const char *name, const char *value)
{
    load_ctx *ctx = user;
    if (ctx->failed)
        return 0;
    char where[GD_PATH_MAX + 32];
    snprintf(where, sizeof where, "%s:%d", ctx->c->path, ctx->line);
    ctx->failed = 1;
    if (!section[0]) {
        gd_error_set(ctx->err, GD_ERR_INPUT, "%s: %s: key before any [section] header (valid: a [section] line "
                     "first)", where, name);
        return 0;
    }
    const gd_keyspec *k = gd_case_find_key(section, name);
    if (!k) {
        unknown_key(where, section, name, ctx->err);
        return 0;
    }
    size_t n, i;
    const gd_keyspec *s = gd_case_schema(&n);
    i = (size_t)(k - s);
    if (ctx->c->src[i] == GD_SRC_FILE) {
        gd_error_set(ctx->err, GD_ERR_INPUT, "%s: %s.%s: given twice (first at line %d)", where, section, name,
                     ctx->c->src_line[i]);
        return 0;
    }
    if (store(ctx->c, k, value, where, ctx->err) != GD_OK)
        return 0;
    ctx->failed = 0;
    ctx->section_keys++;
    ctx->c->src[i] = GD_SRC_FILE;
    ctx->c->src_line[i] = ctx->line;
    return 1;
}

/* inih over the checked text (case_text.h) of the case file path; frees text. */
static gd_status parse_text(gd_case *c, const char *path, char *text, gd_error *err)
{
    snprintf(c->path, sizeof c->path, "%s", path);
    load_ctx ctx = {.c = c, .err = err, .next = text};
    int rc = ini_parse_stream(reader, &ctx, handler, &ctx);
    free(text);
    if (ctx.failed)
        return GD_ERR_INPUT;
    if (rc != 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s:%d: syntax error (expected [section] or key = value)", path,
                            rc > 0 ? rc : ctx.line);
    return GD_OK;
}

GD_API gd_status gd_case_load(gd_case *c, const char *path, gd_error *err)
{
    if (strlen(path) >= GD_PATH_MAX)
        return gd_error_set(err, GD_ERR_INPUT, "%s: path too long", path);
    char *text;
    gd_status st = gd_case_text_read(path, &text, err);
    if (st != GD_OK)
        return st;
    return parse_text(c, path, text, err);
}

GD_API gd_status gd_case_load_text(gd_case *c, const char *text, size_t len, const char *name, gd_error *err)
{
    if (strlen(name) >= GD_PATH_MAX)
        return gd_error_set(err, GD_ERR_INPUT, "%s: name too long", name);
    char *checked;
    gd_status st = gd_case_text_normalise(name, text, len, &checked, err);
    if (st != GD_OK)
        return st;
    return parse_text(c, name, checked, err);
}

GD_API gd_case *gd_case_new(gd_error *err)
{
    gd_case *c = malloc(sizeof *c);
    if (!c) {
        gd_error_set(err, GD_ERR_NOMEM, "out of memory");
        return NULL;
    }
    if (gd_case_init(c, err) != GD_OK) {
        free(c);
        return NULL;
    }
    return c;
}

GD_API gd_case *gd_case_dup(const gd_case *src, gd_error *err)
{
    gd_case *c = malloc(sizeof *c);
    if (!c) {
        gd_error_set(err, GD_ERR_NOMEM, "out of memory");
        return NULL;
    }
    if (gd_case_copy(c, src, err) != GD_OK) {
        free(c);
        return NULL;
    }
    return c;
}

GD_API void gd_case_delete(gd_case *c)
{
    if (!c)
        return;
    gd_case_free(c);
    free(c);
}

GD_API gd_status gd_case_set(gd_case *c, const char *assignment, int set_index, gd_error *err)
{
    char buf[1024];
    if (strlen(assignment) >= sizeof buf)
        return gd_error_set(err, GD_ERR_INPUT, "--set %s: too long", assignment);
    snprintf(buf, sizeof buf, "%s", assignment);
    char *eq = strchr(buf, '=');
    char *dot = strchr(buf, '.');
    if (!eq || !dot || dot > eq)
        return gd_error_set(err, GD_ERR_INPUT, "--set %s: expected section.key=value", assignment);
    *eq = '\0';
    *dot = '\0';
    char *section = buf, *key = dot + 1, *value = eq + 1;
    /* trim */
    while (*value == ' ') value++;
    for (char *e = value + strlen(value); e > value && isspace((unsigned char)e[-1]); ) *--e = '\0';
    for (char *e = key + strlen(key); e > key && isspace((unsigned char)e[-1]); ) *--e = '\0';
    char where[64];
    snprintf(where, sizeof where, "--set #%d", set_index + 1);
    const gd_keyspec *k = gd_case_find_key(section, key);
    if (!k)
        return unknown_key(where, section, key, err);
    gd_status st = store(c, k, value, where, err);
    if (st != GD_OK)
        return st;
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    size_t i = (size_t)(k - s);
    c->src[i] = GD_SRC_SET;
    c->src_line[i] = set_index + 1;
    return GD_OK;
}

static const gd_keyspec *find_dotted(const char *name, gd_error *err)
{
    char buf[256];
    snprintf(buf, sizeof buf, "%s", name);
    char *dot = strchr(buf, '.');
    if (!dot) {
        gd_error_set(err, GD_ERR_INPUT, "%s: expected section.key", name);
        return NULL;
    }
    *dot = '\0';
    const gd_keyspec *k = gd_case_find_key(buf, dot + 1);
    if (!k) {
        unknown_key("parameter", buf, dot + 1, err);
        return NULL;
    }
    return k;
}

GD_API gd_status gd_case_get_number(const gd_case *c, const char *name, double *value, gd_error *err)
{
    const gd_keyspec *k = find_dotted(name, err);
    if (!k)
        return GD_ERR_INPUT;
    if (k->type == GD_KEY_DOUBLE)
        *value = *(const double *)cfield(c, k);
    else if (k->type == GD_KEY_INT)
        *value = *(const int *)cfield(c, k);
    else
        return gd_error_set(err, GD_ERR_INPUT, "%s: not a numeric key", name);
    return GD_OK;
}

GD_API gd_status gd_case_set_number(gd_case *c, const char *name, double value, gd_error *err)
{
    const gd_keyspec *k = find_dotted(name, err);
    if (!k)
        return GD_ERR_INPUT;
    if (k->type != GD_KEY_DOUBLE && k->type != GD_KEY_INT)
        return gd_error_set(err, GD_ERR_INPUT, "%s: not a numeric key", name);
    if (k->type == GD_KEY_INT && value != floor(value))
        return bad_value(NULL, k, "fractional", "not a whole number:", err);
    if (!gd_case_key_in_range(k, value)) {
        char txt[64];
        snprintf(txt, sizeof txt, "%.17g", value);
        return bad_value(NULL, k, txt, "out of range:", err);
    }
    if (k->type == GD_KEY_DOUBLE)
        *(double *)field(c, k) = value;
    else
        *(int *)field(c, k) = (int)value;
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    c->src[k - s] = GD_SRC_SET;
    return GD_OK;
}

GD_API gd_status gd_case_get_list(const gd_case *c, const char *name, double *values, int max, int *n,
                                  gd_error *err)
{
    const gd_keyspec *k = find_dotted(name, err);
    if (!k)
        return GD_ERR_INPUT;
    if (k->type != GD_KEY_DLIST)
        return gd_error_set(err, GD_ERR_INPUT, "%s: not a list of numbers", name);
    int count = *(const int *)((const char *)c + k->count_offset);
    const double *arr = cfield(c, k);
    for (int j = 0; j < count && j < max; j++)
        values[j] = arr[j];
    *n = count;
    return GD_OK;
}

GD_API void gd_case_format_value(const gd_case *c, size_t i, char *buf, size_t len)
{
    size_t n;
    const gd_keyspec *k = &gd_case_schema(&n)[i];
    switch (k->type) {
    case GD_KEY_DOUBLE: snprintf(buf, len, "%.10g", *(const double *)cfield(c, k)); break;
    case GD_KEY_INT: snprintf(buf, len, "%d", *(const int *)cfield(c, k)); break;
    case GD_KEY_BOOL: snprintf(buf, len, "%s", *(const int *)cfield(c, k) ? "on" : "off"); break;
    case GD_KEY_ENUM: gd_case_key_choice(k->section, k->key, *(const int *)cfield(c, k), buf, len); break;
    case GD_KEY_STRING: snprintf(buf, len, "%s", (const char *)cfield(c, k)); break;
    case GD_KEY_DLIST: {
        const double *arr = cfield(c, k);
        int count = *(const int *)((const char *)c + k->count_offset);
        buf[0] = '\0';
        for (int j = 0; j < count; j++) {
            size_t used = strlen(buf);
            snprintf(buf + used, len - used, "%s%.10g", j ? ", " : "", arr[j]);
        }
        break;
    }
    }
}

GD_API gd_source gd_case_source(const gd_case *c, size_t i, int *line)
{
    if (line)
        *line = c->src_line[i];
    return (gd_source)c->src[i];
}
