/* What the picture of a continuation's curves draws besides them (docs/continuation.md section 8):
 * continuation.overlay_map, a finished regime map (a sweep with parameter2) in the same two keys
 * of this case's model, whose cells go under the curves; continuation.overlay_curves, an earlier
 * continuation's curves.csv in the same two keys (the case before a modification), drawn beside
 * them. Each checked before any work, and read back for the picture. */
#include "output_internal.h"
#include "../case/case_keys.h"
#include "geardyn/gd_envelope.h"

#include <errno.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WHERE(key) (gd_case_key_where(c, "continuation", key, w, sizeof w), w)
#define NF_MAX 256

/* DIR/summary.json, the output of analysis `what`: its root into *out (NULL on a refusal). */
static gd_status load_summary(const gd_case *c, const char *key, const char *dir, const char *what, json_t **out,
                              gd_error *err)
{
    char w[GD_PATH_MAX + 32], path[GD_PATH_MAX + 32];
    snprintf(path, sizeof path, "%s/summary.json", dir);
    json_error_t je;
    json_t *root = json_load_file(path, 0, &je);
    *out = NULL;
    if (!root)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.%s: %s: %s (valid: the directory of a finished %s)",
                            WHERE(key), key, path, je.text, what);
    const char *an = json_string_value(json_object_get(root, "analysis"));
    if (!an || strcmp(an, what) != 0) {
        gd_status st = gd_error_set(err, GD_ERR_INPUT, "%s: continuation.%s: %s holds the output of %s, not of a %s "
                                    "(valid: the directory of a finished %s in %s and %s)", WHERE(key), key, dir,
                                    an ? an : "no analysis", what, what, c->cont_parameter, c->cont_parameter2);
        json_decref(root);
        return st;
    }
    *out = root;
    return GD_OK;
}

/* A table being read: the file at its next row, its header split into h (nh fields, held in head) and
 * a line's buffer; both buffers of 65536 bytes. */
typedef struct table {
    FILE *fp;
    char *head, *line, *h[NF_MAX];
    int nh;
} table;

static void close_table(table *t)
{
    if (t->fp)
        fclose(t->fp);
    free(t->head);
    free(t->line);
    memset(t, 0, sizeof *t);
}

/* The header of DIR/FILE split into h (nh fields; the line in head, of 65536 bytes); the file open
 * at its first row in *fp. */
static gd_status open_table(const gd_case *c, const char *key, const char *dir, const char *file, FILE **fp,
                            char *head, char **h, int *nh, gd_error *err)
{
    char w[GD_PATH_MAX + 32], path[GD_PATH_MAX + 32];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    *fp = fopen(path, "r");
    if (!*fp)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.%s: %s: %s (valid: the directory of a finished run "
                            "that wrote %s)", WHERE(key), key, path, strerror(errno), file);
    if (!fgets(head, 65536, *fp)) {
        fclose(*fp);
        *fp = NULL;
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.%s: %s is empty (valid: the %s of a finished run)",
                            WHERE(key), key, path, file);
    }
    *nh = gd_csv_split(head, h, NF_MAX);
    return GD_OK;
}

/* open_table with t's buffers (closed and freed again on failure) */
static gd_status table_open(const gd_case *c, const char *key, const char *dir, const char *file, table *t,
                            gd_error *err)
{
    memset(t, 0, sizeof *t);
    t->head = malloc(65536);
    t->line = malloc(65536);
    gd_status st = t->head && t->line ? open_table(c, key, dir, file, &t->fp, t->head, t->h, &t->nh, err)
                                      : gd_error_set(err, GD_ERR_NOMEM, "out of memory reading %s/%s", dir, file);
    if (st != GD_OK)
        close_table(t);
    return st;
}

static gd_status check_map(const gd_case *c, gd_overlay_map *m, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    const char *dir = c->cont_overlay_map;
    json_t *root;
    gd_status st0 = load_summary(c, "overlay_map", dir, "sweep", &root, err);
    if (st0 != GD_OK)
        return st0;
    json_t *sw = json_object_get(root, "sweep");
    const char *p1 = json_string_value(json_object_get(json_object_get(sw, "parameter"), "name"));
    const char *p2 = json_string_value(json_object_get(json_object_get(sw, "parameter2"), "name"));
    gd_status st = GD_OK;
    if (!p1 || !p2 || strcmp(p1, c->cont_parameter) != 0 || strcmp(p2, c->cont_parameter2) != 0)
        st = gd_error_set(err, GD_ERR_INPUT, "%s: continuation.overlay_map: the sweep in %s varies %s%s%s (valid: a "
                          "regime map, a sweep in sweep.parameter = %s and sweep.parameter2 = %s)", WHERE("overlay_map"),
                          dir, p1 ? p1 : "?", p2 ? " and " : " alone", p2 ? p2 : "", c->cont_parameter,
                          c->cont_parameter2);
    if (st == GD_OK)
        st = gd_contin_same_model_but(c, json_object_get(json_object_get(root, "case"), "parameters"), dir,
                                      "overlay_map", "sweep", c->cont_parameter2, err);
    json_decref(root);
    if (st != GD_OK)
        return st;
    table t;
    char *f[NF_MAX];
    st = table_open(c, "overlay_map", dir, "sweep.csv", &t, err);
    if (st != GD_OK)
        return st;
    FILE *fp = t.fp;
    char *line = t.line, **h = t.h;
    const int nh = t.nh;
    static const char *want[] = {"parameter", "parameter2", "direction", "motion", "impact_regime", "period_n",
                                 "status"};
    int col[7];
    for (int k = 0; k < 7 && st == GD_OK; k++)
        if ((col[k] = gd_csv_column(h, nh, want[k])) < 0)
            st = gd_error_set(err, GD_ERR_INPUT, "%s: continuation.overlay_map: %s/sweep.csv has no column %s "
                              "(valid: the sweep.csv of a regime map as written)", WHERE("overlay_map"), dir, want[k]);
    int cap = 0, row = 0;
    while (st == GD_OK && fgets(line, 65536, fp)) {
        row++;
        if (strspn(line, " \t\r\n") == strlen(line))
            continue;
        int nf = gd_csv_split(line, f, NF_MAX);
        char *e1, *e2;
        double x = nf == nh ? strtod(f[col[0]], &e1) : NAN, y = nf == nh ? strtod(f[col[1]], &e2) : NAN;
        if (nf != nh || *e1 || *e2 || !isfinite(x) || !isfinite(y)) {
            st = gd_error_set(err, GD_ERR_INPUT, "%s: continuation.overlay_map: row %d of %s/sweep.csv is not a point "
                              "of a regime map (valid: the sweep.csv of a regime map as written)",
                              WHERE("overlay_map"), row, dir);
            break;
        }
        if (!m)
            continue;
        if (m->n == cap) {
            cap = cap ? 2 * cap : 1024;
            gd_map_point *np = realloc(m->pt, sizeof *np * (size_t)cap);
            if (!np) {
                st = gd_error_set(err, GD_ERR_NOMEM, "out of memory reading %s/sweep.csv", dir);
                break;
            }
            m->pt = np;
        }
        gd_map_point *p = &m->pt[m->n++];
        p->x = x;
        p->y = y;
        const char *d = f[col[2]], *r = f[col[4]];
        p->dir = strcmp(d, "up") == 0 ? 0 : strcmp(d, "down") == 0 ? 1 : 2;
        p->regime = strcmp(f[col[6]], "done") != 0         ? -1
                    : strcmp(r, "no-impact") == 0          ? 0
                    : strcmp(r, "single-sided") == 0       ? 1
                    : strcmp(r, "double-sided") == 0       ? 2
                                                           : -1;
        snprintf(p->motion, sizeof p->motion, "%s", f[col[3]]);
        p->period = strncmp(p->motion, "period-", 7) == 0 ? atoi(p->motion + 7) : 0;
    }
    close_table(&t);
    return st;
}

static gd_status check_curves(const gd_case *c, gd_overlay_curves *o, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    const char *dir = c->cont_overlay_curves;
    json_t *root;
    gd_status st0 = load_summary(c, "overlay_curves", dir, "continuation", &root, err);
    if (st0 != GD_OK)
        return st0;
    json_t *res = json_object_get(root, "results");
    const char *p1 = json_string_value(json_object_get(res, "parameter"));
    const char *p2 = json_string_value(json_object_get(res, "parameter2"));
    gd_status st = GD_OK;
    if (!p1 || !p2 || strcmp(p1, c->cont_parameter) != 0 || strcmp(p2, c->cont_parameter2) != 0)
        st = gd_error_set(err, GD_ERR_INPUT, "%s: continuation.overlay_curves: the continuation in %s %s%s%s%s (valid: "
                          "curves in continuation.parameter = %s and parameter2 = %s)", WHERE("overlay_curves"), dir,
                          p2 ? "followed curves in " : "followed no curves: it varies ", p1 ? p1 : "?",
                          p2 ? " and " : " alone", p2 ? p2 : "", c->cont_parameter, c->cont_parameter2);
    if (st == GD_OK && o)
        o->ndiff = gd_contin_model_diff(c, json_object_get(json_object_get(root, "case"), "parameters"),
                                        c->cont_parameter2, o->diff, 3);
    json_decref(root);
    if (st != GD_OK)
        return st;
    table t;
    char *f[NF_MAX];
    st = table_open(c, "overlay_curves", dir, "curves.csv", &t, err);
    if (st != GD_OK)
        return st;
    FILE *fp = t.fp;
    char *line = t.line, **h = t.h;
    const int nh = t.nh;
    const char *d1 = strchr(c->cont_parameter, '.'), *d2 = strchr(c->cont_parameter2, '.');
    const char *want[] = {"curve", "kind", d1 ? d1 + 1 : c->cont_parameter, d2 ? d2 + 1 : c->cont_parameter2};
    int col[4];
    for (int k = 0; k < 4 && st == GD_OK; k++)
        if ((col[k] = gd_csv_column(h, nh, want[k])) < 0)
            st = gd_error_set(err, GD_ERR_INPUT, "%s: continuation.overlay_curves: %s/curves.csv has no column %s "
                              "(valid: the curves.csv of a continuation in %s and %s)", WHERE("overlay_curves"), dir,
                              want[k], c->cont_parameter, c->cont_parameter2);
    int cap = 0, row = 0;
    while (st == GD_OK && fgets(line, 65536, fp)) {
        row++;
        if (strspn(line, " \t\r\n") == strlen(line))
            continue;
        int nf = gd_csv_split(line, f, NF_MAX);
        char *e1 = "", *e2 = "";
        double x = nf == nh ? strtod(f[col[2]], &e1) : NAN, y = nf == nh ? strtod(f[col[3]], &e2) : NAN;
        const char *k = nf == nh ? f[col[1]] : "";
        int kind = strcmp(k, "fold") == 0              ? GD_CURVE_FOLD
                   : strcmp(k, "period-doubling") == 0 ? GD_CURVE_PERIOD_DOUBLING
                   : strcmp(k, "neimark-sacker") == 0  ? GD_CURVE_NEIMARK_SACKER
                   : strcmp(k, "grazing") == 0         ? GD_CURVE_GRAZING
                                                       : -1;
        if (nf != nh || *e1 || *e2 || !isfinite(x) || !isfinite(y) || kind < 0) {
            st = gd_error_set(err, GD_ERR_INPUT, "%s: continuation.overlay_curves: row %d of %s/curves.csv is not a "
                              "curve point (valid: the curves.csv of a continuation as written)",
                              WHERE("overlay_curves"), row, dir);
            break;
        }
        if (!o)
            continue;
        if (o->n == cap) {
            cap = cap ? 2 * cap : 1024;
            double *nx = realloc(o->x, sizeof(double) * (size_t)cap);
            if (nx)
                o->x = nx;
            double *ny = nx ? realloc(o->y, sizeof(double) * (size_t)cap) : NULL;
            if (ny)
                o->y = ny;
            int *nc = ny ? realloc(o->curve, sizeof(int) * (size_t)cap) : NULL;
            if (nc)
                o->curve = nc;
            int *nk = nc ? realloc(o->kind, sizeof(int) * (size_t)cap) : NULL;
            if (!nk) {
                st = gd_error_set(err, GD_ERR_NOMEM, "out of memory reading %s/curves.csv", dir);
                break;
            }
            o->kind = nk;
        }
        o->x[o->n] = x;
        o->y[o->n] = y;
        o->curve[o->n] = atoi(f[col[0]]);
        o->kind[o->n++] = kind;
    }
    close_table(&t);
    return st;
}

gd_status gd_contin_overlays_check(const gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    static const char *keys[] = {"overlay_map", "overlay_curves"};
    const char *vals[] = {c->cont_overlay_map, c->cont_overlay_curves};
    for (int i = 0; i < 2; i++)
        if (vals[i][0] && !c->cont_parameter2[0])
            return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.%s: given without continuation.parameter2 (valid: "
                                "set parameter2, the curves' second key, or leave %s out)", WHERE(keys[i]), keys[i],
                                keys[i]);
    gd_status st = c->cont_overlay_map[0] ? check_map(c, NULL, err) : GD_OK;
    if (st == GD_OK && c->cont_overlay_curves[0])
        st = check_curves(c, NULL, err);
    return st;
}

gd_status gd_contin_overlay_map_read(const gd_case *c, gd_overlay_map *m, gd_error *err)
{
    memset(m, 0, sizeof *m);
    return c->cont_overlay_map[0] ? check_map(c, m, err) : GD_OK;
}

gd_status gd_contin_overlay_curves_read(const gd_case *c, gd_overlay_curves *o, gd_error *err)
{
    memset(o, 0, sizeof *o);
    return c->cont_overlay_curves[0] ? check_curves(c, o, err) : GD_OK;
}

void gd_contin_overlay_free(gd_overlay_map *m, gd_overlay_curves *o)
{
    if (m) {
        free(m->pt);
        memset(m, 0, sizeof *m);
    }
    if (o) {
        free(o->x);
        free(o->y);
        free(o->curve);
        free(o->kind);
        memset(o, 0, sizeof *o);
    }
}
