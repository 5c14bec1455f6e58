/* continuation.curve_start: one row of an earlier continuation's bifurcations.csv read back as the
 * start of one curve in two parameters (docs/continuation.md section 8), after checking that it is
 * a bifurcation of this case: a fold, period doubling or grazing, located, in [from, to], its file
 * of this model's state, and the run beside it a continuation of this case in the same key. */
#include "output_internal.h"
#include "../analysis/analysis_internal.h"
#include "../case/case_keys.h"
#include "geardyn/gd_envelope.h"

#include <errno.h>
#include <jansson.h>
#include <libgen.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WHERE(key) (gd_case_key_where(c, "continuation", key, w, sizeof w), w)
#define NF_MAX (GD_MAX_STATE + 64)

/* The run beside the file: a continuation in this case's key, of this case's model. */
static gd_status check_run(const gd_case *c, const char *dir, gd_error *err)
{
    char w[GD_PATH_MAX + 32], path[GD_PATH_MAX + 32];
    snprintf(path, sizeof path, "%s/summary.json", dir);
    json_error_t je;
    json_t *root = json_load_file(path, 0, &je);
    if (!root)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start: %s: %s (valid: the bifurcations.csv of "
                            "a finished continuation, its summary.json beside it)", WHERE("curve_start"), path, je.text);
    const char *an = json_string_value(json_object_get(root, "analysis"));
    const char *par = json_string_value(json_object_get(json_object_get(root, "results"), "parameter"));
    gd_status st = GD_OK;
    if (!an || strcmp(an, "continuation") != 0)
        st = gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start: %s holds the output of %s, not of a "
                          "continuation (valid: the bifurcations.csv of a continuation in %s)", WHERE("curve_start"),
                          dir, an ? an : "no analysis", c->cont_parameter);
    else if (!par || strcmp(par, c->cont_parameter) != 0)
        st = gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start: the continuation in %s varies %s (valid: a "
                          "continuation in continuation.parameter = %s)", WHERE("curve_start"), dir, par ? par : "?",
                          c->cont_parameter);
    else
        st = gd_contin_same_model(c, json_object_get(json_object_get(root, "case"), "parameters"), dir, "curve_start",
                                  "continuation", err);
    json_decref(root);
    return st;
}

/* The row's fields f (nf of them; found: whether row curve_start_row exists among the r rows) into *row. */
typedef struct cols {
    int kind, nper, value, clearance, location, y[GD_MAX_STATE];
} cols;

static gd_status parse_row(const gd_case *c, const gd_model *mp, char names[][16], int nh, char **f, int nf, int found,
                           int r, const cols *k, const char *key, gd_contin_curve_row *row, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    const char *path = c->cont_curve_start;
    const gd_model m = *mp;
    int ck = k->kind, cn = k->nper, cv = k->value, cc = k->clearance, cl = k->location;
    const int *cy = k->y;
    const char *rowkey = gd_case_key_given(c, "continuation", "curve_start_row") ? "curve_start_row" : "curve_start";
    if (!found)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start_row: %d, but %s has %d row%s (valid: 1 to "
                            "%d)", WHERE(gd_case_key_given(c, "continuation", "curve_start_row") ? "curve_start_row"
                                                                                                 : "curve_start"),
                            c->cont_curve_start_row, path, r, r == 1 ? "" : "s", r);
    if (nf != nh)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start_row: row %d of %s has %d fields, its "
                            "header %d (valid: a row of a bifurcations.csv as written)", WHERE("curve_start"),
                            c->cont_curve_start_row, path, nf, nh);
    const char *kind = f[ck], *clr = f[cc];
    row->clearance = -1;
    if (strcmp(kind, "fold") == 0)
        row->kind = GD_CURVE_FOLD;
    else if (strcmp(kind, "period-doubling") == 0)
        row->kind = GD_CURVE_PERIOD_DOUBLING;
    else if (strcmp(kind, "neimark-sacker") == 0)
        row->kind = GD_CURVE_NEIMARK_SACKER;
    else if (strcmp(kind, "contact-change") == 0 && clr[0]) {
        row->kind = GD_CURVE_GRAZING;
        for (int i = 0; i < m.nclear; i++)
            if (strcmp(m.clear[i].name, clr) == 0)
                row->clearance = i;
        if (row->clearance < 0)
            return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start_row: row %d of %s is a grazing of "
                                "%s, which this model has no clearance of (valid: a continuation of this case's model)",
                                WHERE(rowkey), c->cont_curve_start_row, path, clr);
    } else
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start_row: row %d of %s is a %s%s, which has no "
                            "curve (valid: a row of kind fold, period-doubling, neimark-sacker, or contact-change of a clearance)",
                            WHERE(rowkey), c->cont_curve_start_row, path, kind,
                            strcmp(kind, "contact-change") == 0 ? " of no clearance" : "");
    char bad[128];
    if (!(gd_contin_curve_kinds(c->cont_curve_kinds, bad, sizeof bad) & (1u << row->kind)))
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_kinds: '%s' leaves out the %s of row %d of %s "
                            "(valid: a list that names %s, or leave curve_kinds out)", WHERE("curve_kinds"),
                            c->cont_curve_kinds, gd_curve_kind_name(row->kind), c->cont_curve_start_row, path,
                            gd_curve_kind_name(row->kind));
    if (strcmp(f[cl], "located") != 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start_row: row %d of %s: its %s was not located "
                            "(location %s) (valid: a located bifurcation)", WHERE("curve_start"),
                            c->cont_curve_start_row, path, kind, f[cl]);
    char *end;
    row->value = strtod(f[cv], &end);
    row->nper = atoi(f[cn]);
    if (*end || !isfinite(row->value) || row->nper < 1 || row->nper > GD_PO_MAX_PERIODS)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start_row: row %d of %s: %s = '%s', period_n = "
                            "'%s' (valid: a number, and 1 to %d mesh periods)", WHERE("curve_start"),
                            c->cont_curve_start_row, path, key, f[cv], f[cn], GD_PO_MAX_PERIODS);
    if (!(row->value >= fmin(c->cont_from, c->cont_to) && row->value <= fmax(c->cont_from, c->cont_to)))
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start_row: row %d of %s: its %s at %s = %.10g "
                            "lies outside [from, to] = [%.10g, %.10g] (valid: a bifurcation inside the range)",
                            WHERE(rowkey), c->cont_curve_start_row, path, kind, c->cont_parameter, row->value,
                            c->cont_from, c->cont_to);
    row->n = m.n;
    for (int j = 0; j < m.n; j++) {
        row->y[j] = strtod(f[cy[j]], &end);
        if (*end || !isfinite(row->y[j]))
            return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start_row: row %d of %s: %s = '%s' (valid: "
                                "a finite number)", WHERE(rowkey), c->cont_curve_start_row, path, names[j],
                                f[cy[j]]);
    }
    char dir[GD_PATH_MAX];
    snprintf(dir, sizeof dir, "%s", path);
    gd_status st = check_run(c, dirname(dir), err);
    if (st == GD_OK)
        snprintf(row->source, sizeof row->source, "%s row %d: %s%s%s at %s = %.10g", path, c->cont_curve_start_row,
                 kind, row->clearance >= 0 ? " of " : "", row->clearance >= 0 ? clr : "", key, row->value);
    return st;
}

gd_status gd_contin_curve_row_read(const gd_case *c, gd_contin_curve_row *row, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    const char *path = c->cont_curve_start;
    memset(row, 0, sizeof *row);
    gd_model m;
    gd_status st = gd_model_build(c, &m, err);
    if (st != GD_OK)
        return st;
    char names[GD_MAX_STATE][16];
    gd_state_names(&m, names);
    FILE *fp = fopen(path, "r");
    if (!fp)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start: %s: %s (valid: the bifurcations.csv of "
                            "a finished continuation)", WHERE("curve_start"), path, strerror(errno));
    char *line = malloc(65536), *head = malloc(65536);
    if (!line || !head) {
        free(line);
        free(head);
        fclose(fp);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory reading %s", path);
    }
    char *h[NF_MAX], *f[NF_MAX], key[300];
    const char *dot = strchr(c->cont_parameter, '.');
    snprintf(key, sizeof key, "%s", dot ? dot + 1 : c->cont_parameter);
    int nh = 0, ck = -1, cn = -1, cv = -1, cc = -1, cl = -1, cy[GD_MAX_STATE];
    if (!fgets(head, 65536, fp))
        st = gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start: %s is empty (valid: the bifurcations.csv "
                          "of a finished continuation)", WHERE("curve_start"), path);
    if (st == GD_OK) {
        nh = gd_csv_split(head, h, NF_MAX);
        ck = gd_csv_column(h, nh, "kind");
        cn = gd_csv_column(h, nh, "period_n");
        cv = gd_csv_column(h, nh, key);
        cc = gd_csv_column(h, nh, "clearance");
        cl = gd_csv_column(h, nh, "location");
        if (ck < 0 || cn < 0 || cc < 0 || cl < 0 || gd_csv_column(h, nh, "branch") != 0)
            st = gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start: %s is not a bifurcations.csv (no "
                              "column kind, period_n, clearance or location) (valid: the bifurcations.csv of a "
                              "finished continuation)", WHERE("curve_start"), path);
        else if (cv < 0)
            st = gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start: %s has no column %s (valid: the "
                              "bifurcations.csv of a continuation in %s)", WHERE("curve_start"), path, key,
                              c->cont_parameter);
    }
    for (int j = 0; j < m.n && st == GD_OK; j++)
        if ((cy[j] = gd_csv_column(h, nh, names[j])) < 0)
            st = gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start: %s has no column %s of this model's "
                              "state (valid: a continuation of this case's model)", WHERE("curve_start"), path,
                              names[j]);
    int r = 0, nf = 0, found = 0;
    while (st == GD_OK && fgets(line, 65536, fp)) {
        if (strspn(line, " \t\r\n") == strlen(line))
            continue;
        if (++r == c->cont_curve_start_row) { /* (f points into line: read no further) */
            nf = gd_csv_split(line, f, NF_MAX);
            found = 1;
            break;
        }
    }
    fclose(fp);
    if (st == GD_OK) {
        cols kc = {ck, cn, cv, cc, cl, {0}};
        memcpy(kc.y, cy, sizeof kc.y);
        st = parse_row(c, &m, names, nh, f, nf, found, r, &kc, key, row, err);
    }
    free(line);
    free(head);
    return st;
}
