/* A finished continuation read back for the basins (basins.continuation): its summary.json (the
 * analysis, the continued key) and every point of its branch.csv (branch, period, stability, the key's
 * value and the state at mesh phase 0). Refusals are GD_ERR_INPUT naming the key. */
#include "output_internal.h"
#include "geardyn/gd_scene.h"
#include "../case/case_keys.h"
#include "../analysis/analysis_internal.h"

#include <errno.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WHERE(key) (gd_case_key_where(c, "basins", key, w, sizeof w), w)

static gd_status grow(gd_basins_known *k, long *cap, gd_error *err)
{
    if (k->npoints < *cap)
        return GD_OK;
    long nc = *cap ? 2 * *cap : 256;
    int *b = realloc(k->branch, sizeof(int) * (size_t)nc);
    if (b)
        k->branch = b;
    int *p = realloc(k->period, sizeof(int) * (size_t)nc);
    if (p)
        k->period = p;
    int *s = realloc(k->stable, sizeof(int) * (size_t)nc);
    if (s)
        k->stable = s;
    double *v = realloc(k->value, sizeof(double) * (size_t)nc);
    if (v)
        k->value = v;
    double *y = realloc(k->y, sizeof(double) * (size_t)nc * (size_t)k->n);
    if (y)
        k->y = y;
    if (!b || !p || !s || !v || !y)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a continuation's points");
    *cap = nc;
    return GD_OK;
}

gd_status gd_basins_read_continuation(const gd_case *c, gd_basins_known *k, gd_error *err)
{
    char w[GD_PATH_MAX + 32], path[GD_PATH_MAX + 32];
    const char *dir = c->bas_continuation;
    memset(k, 0, sizeof *k);
    snprintf(path, sizeof path, "%s/summary.json", dir);
    json_error_t je;
    json_t *root = json_load_file(path, 0, &je);
    if (!root)
        return gd_error_set(err, GD_ERR_INPUT, "%s: basins.continuation: %s: %s (valid: the directory of a finished "
                            "continuation)", WHERE("continuation"), path, je.text);
    const char *an = json_string_value(json_object_get(root, "analysis"));
    const char *par = json_string_value(json_object_get(json_object_get(root, "results"), "parameter"));
    gd_status st = GD_OK;
    if (!an || strcmp(an, "continuation") != 0 || !par)
        st = gd_error_set(err, GD_ERR_INPUT, "%s: basins.continuation: %s holds %s%s, not a continuation (valid: the "
                          "directory of a finished continuation)", WHERE("continuation"), dir, an ? "the analysis " : "no analysis",
                          an ? an : "");
    else if (c->bas_parameter[0] && strcmp(par, c->bas_parameter) != 0)
        st = gd_error_set(err, GD_ERR_INPUT, "%s: basins.continuation: %s continues %s, the basins vary %s (valid: a "
                          "continuation in basins.parameter)", WHERE("continuation"), dir, par, c->bas_parameter);
    else if (!gd_case_key_dotted(par))
        st = gd_error_set(err, GD_ERR_INPUT, "%s: basins.continuation: %s continues %s, no key of this version "
                          "(valid: a continuation of this case)", WHERE("continuation"), dir, par);
    if (st == GD_OK)
        snprintf(k->parameter, sizeof k->parameter, "%s", par);
    json_decref(root);
    if (st != GD_OK)
        return st;
    gd_model m;
    if ((st = gd_model_build(c, &m, err)) != GD_OK)
        return st;
    char names[GD_MAX_STATE][16];
    gd_state_names(&m, names);
    k->n = m.n;
    snprintf(path, sizeof path, "%s/branch.csv", dir);
    FILE *fp = fopen(path, "r");
    if (!fp)
        return gd_error_set(err, GD_ERR_INPUT, "%s: basins.continuation: %s: %s (valid: the directory of a finished "
                            "continuation)", WHERE("continuation"), path, strerror(errno));
    enum { MAXF = 512 };
    char *line = malloc(65536), *f[MAXF];
    if (!line) {
        fclose(fp);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a continuation's branch.csv");
    }
    int col_branch = -1, col_period = -1, col_stable = -1, col_value = -1, col_y[GD_MAX_STATE];
    const char *dot = strchr(k->parameter, '.'); /* (par went with the JSON) */
    char keycol[300];
    snprintf(keycol, sizeof keycol, "%s", dot ? dot + 1 : k->parameter);
    if (!fgets(line, 65536, fp)) {
        st = gd_error_set(err, GD_ERR_INPUT, "%s: basins.continuation: %s is empty (valid: a finished continuation's)",
                          WHERE("continuation"), path);
    } else {
        int nf = gd_csv_split(line, f, MAXF);
        for (int q = 0; q < m.n; q++)
            col_y[q] = -1;
        for (int i = 0; i < nf; i++) {
            if (strcmp(f[i], "branch") == 0)
                col_branch = i;
            else if (strcmp(f[i], "period_n") == 0)
                col_period = i;
            else if (strcmp(f[i], "stable") == 0)
                col_stable = i;
            else if (strcmp(f[i], keycol) == 0)
                col_value = i;
            for (int q = 0; q < m.n; q++)
                if (strcmp(f[i], names[q]) == 0)
                    col_y[q] = i;
        }
        int missing = col_branch < 0 || col_period < 0 || col_stable < 0 || col_value < 0;
        for (int q = 0; q < m.n; q++)
            missing |= col_y[q] < 0;
        if (missing)
            st = gd_error_set(err, GD_ERR_INPUT, "%s: basins.continuation: %s lacks a column of this model's (branch, "
                              "period_n, stable, %s, %s, ...) (valid: a continuation of this case's model)",
                              WHERE("continuation"), path, keycol, names[0]);
    }
    long cap = 0, row = 1;
    while (st == GD_OK && fgets(line, 65536, fp)) {
        row++;
        int nf = gd_csv_split(line, f, MAXF);
        if (nf <= col_value || nf <= col_branch || nf <= col_stable || nf <= col_period) {
            st = gd_error_set(err, GD_ERR_INPUT, "%s: basins.continuation: %s line %ld is short (valid: a finished "
                              "continuation's)", WHERE("continuation"), path, row);
            break;
        }
        if ((st = grow(k, &cap, err)) != GD_OK)
            break;
        long i = k->npoints;
        k->branch[i] = atoi(f[col_branch]);
        k->period[i] = atoi(f[col_period]);
        k->stable[i] = atoi(f[col_stable]);
        k->value[i] = strtod(f[col_value], NULL);
        int bad = !isfinite(k->value[i]);
        for (int q = 0; q < m.n; q++) {
            k->y[i * m.n + q] = col_y[q] < nf ? strtod(f[col_y[q]], NULL) : NAN;
            bad |= !isfinite(k->y[i * m.n + q]);
        }
        if (bad)
            st = gd_error_set(err, GD_ERR_INPUT, "%s: basins.continuation: %s line %ld has a value that is not a finite "
                              "number (valid: a finished continuation's)", WHERE("continuation"), path, row);
        else
            k->npoints++;
    }
    free(line);
    fclose(fp);
    if (st != GD_OK)
        gd_basins_known_free(k);
    return st;
}
