/* A sweep's final states (states.csv): written with the sweep's tables, one row per point with the
 * swept values and the state (%.17g, so that they read back exactly) the point ended in (at the end of its recorded window, a whole number of mesh periods
 * from t = 0, so at mesh phase 0), and read back as the starting orbit of a continuation
 * (continuation.start = sweep, docs/continuation.md section 7) after checking that the sweep is
 * finished, in the continued key, and of this case's model. */
#include "output_internal.h"
#include "../analysis/analysis_internal.h"
#include "../case/case_keys.h"
#include "json_util.h"

#include <errno.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The column of axis a: the key's name without its section (its unit is in the name, as
 * speed_rpm), or section_key when both axes have the same key name. */
static void axis_column(const gd_sweep_plan *p, int a, char *out, size_t cap)
{
    const char *k = strchr(p->parameter[a], '.');
    const char *o = p->naxes > 1 ? strchr(p->parameter[1 - a], '.') : NULL;
    if (k && o && strcmp(k, o) == 0) {
        snprintf(out, cap, "%.*s_%s", (int)(k - p->parameter[a]), p->parameter[a], k + 1);
        return;
    }
    snprintf(out, cap, "%s", k ? k + 1 : p->parameter[a]);
}

gd_status gd_sweep_write_states(gd_run_dir *d, const gd_sweep_plan *p, const gd_sweep_point *pts, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "states.csv", &fp, err);
    if (st != GD_OK)
        return st;
    char col[2][300];
    for (int a = 0; a < p->naxes; a++)
        axis_column(p, a, col[a], sizeof col[a]);
    fprintf(fp, "%s,direction%s%s,period_n,status", col[0], p->naxes > 1 ? "," : "", p->naxes > 1 ? col[1] : "");
    for (int j = 0; j < p->n; j++)
        fprintf(fp, ",%s", p->state_name[j]);
    fputc('\n', fp);
    for (int s = 0; s < p->nslots; s++) {
        const gd_sweep_point *pt = &pts[s];
        int done = pt->status == GD_POINT_DONE;
        fprintf(fp, "%.17g,%s", pt->value[0], gd_sweep_branch_name(pt->branch));
        if (p->naxes > 1)
            fprintf(fp, ",%.17g", pt->value[1]);
        fprintf(fp, ",%d,%s", pt->period_n, done ? "done" : pt->status == GD_POINT_FAILED ? "failed" : "pending");
        for (int j = 0; j < p->n; j++) {
            if (done)
                fprintf(fp, ",%.17g", pt->y_final[j]);
            else
                fputs(",nan", fp);
        }
        fputc('\n', fp);
    }
    return gd_run_dir_commit(d, fp, err);
}

/* ---- read back as a continuation's start ---- */

#define WHERE(key) (gd_case_key_where(c, "continuation", key, w, sizeof w), w)

/* The keys that make the model: those of these sections (but the analysis and the title), and
 * the solver's length scale and TCA and LTCA grids. */
static int model_key(const char *section, const char *key)
{
    static const char *sections[] = {"scene", "gear", "modification", "misalignment", "operating", "clearance",
                                     "excitation", "damping", "support"};
    if (strcmp(section, "scene") == 0 && (strcmp(key, "analysis") == 0 || strcmp(key, "title") == 0))
        return 0;
    if (strcmp(section, "solver") == 0)
        return strcmp(key, "characteristic_length_um") == 0 || strncmp(key, "tca_", 4) == 0 ||
               strncmp(key, "ltca_", 5) == 0;
    for (size_t i = 0; i < sizeof sections / sizeof sections[0]; i++)
        if (strcmp(section, sections[i]) == 0)
            return 1;
    return 0;
}

/* Two values of summary.json: reals to the 12 digits it writes, the rest exactly. */
static int same_value(json_t *a, json_t *b)
{
    if (json_is_number(a) && json_is_number(b)) {
        double x = json_number_value(a), y = json_number_value(b);
        return fabs(x - y) <= 1e-10 * fmax(fabs(x), fabs(y));
    }
    if (json_is_array(a) && json_is_array(b) && json_array_size(a) == json_array_size(b)) {
        for (size_t i = 0; i < json_array_size(a); i++)
            if (!same_value(json_array_get(a, i), json_array_get(b, i)))
                return 0;
        return 1;
    }
    return json_equal(a, b);
}

/* A value of summary.json as text: numbers as %.10g, the rest as JSON (malloc'd). */
static char *value_text(json_t *v)
{
    if (json_is_number(v)) {
        char *t = malloc(32);
        if (t)
            snprintf(t, 32, "%.10g", json_number_value(v));
        return t;
    }
    return v ? json_dumps(v, JSON_ENCODE_ANY) : NULL;
}

static int derived(json_t *e)
{
    const char *s = json_string_value(json_object_get(e, "source"));
    return s && strcmp(s, "derived") == 0;
}

/* The sweep's resolved case against this one, key by key over the model's keys, except the
 * continued key (and skip2, when not NULL) and the values derived from others. */
gd_status gd_contin_same_model_but(const gd_case *c, json_t *sweep_case, const char *dir, const char *key,
                                   const char *what, const char *skip2, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    gd_model_diff d;
    if (gd_contin_model_diff(c, sweep_case, skip2, &d, 1) == 0)
        return GD_OK;
    return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.%s: the %s in %s is of another model: %s = %s there, %s "
                        "here (valid: a %s of this case, which may differ in %s%s%s only)", WHERE(key), key, what, dir,
                        d.key, d.theirs, d.mine, what, c->cont_parameter, skip2 ? " and " : "", skip2 ? skip2 : "");
}

gd_status gd_contin_same_model(const gd_case *c, json_t *sweep_case, const char *dir, const char *key,
                               const char *what, gd_error *err)
{
    return gd_contin_same_model_but(c, sweep_case, dir, key, what, NULL, err);
}

int gd_contin_model_diff(const gd_case *c, json_t *their_case, const char *skip2, gd_model_diff *d, int max)
{
    json_t *mine = gd_json_case(c);
    size_t n;
    const gd_keyspec *s = gd_case_schema(&n);
    int nd = 0;
    for (size_t i = 0; i < n; i++) {
        char name[200];
        snprintf(name, sizeof name, "%s.%s", s[i].section, s[i].key);
        if (!model_key(s[i].section, s[i].key) || strcmp(name, c->cont_parameter) == 0 ||
            (skip2 && strcmp(name, skip2) == 0))
            continue;
        json_t *a = json_object_get(json_object_get(mine, s[i].section), s[i].key);
        json_t *b = json_object_get(json_object_get(their_case, s[i].section), s[i].key);
        if (b && (derived(a) || derived(b)))
            continue;
        if (b && same_value(json_object_get(a, "value"), json_object_get(b, "value")))
            continue;
        if (nd < max) {
            char *va = value_text(json_object_get(a, "value"));
            char *vb = b ? value_text(json_object_get(b, "value")) : NULL;
            snprintf(d[nd].key, sizeof d[nd].key, "%s", name);
            snprintf(d[nd].mine, sizeof d[nd].mine, "%s", va ? va : "?");
            snprintf(d[nd].theirs, sizeof d[nd].theirs, "%s", b ? (vb ? vb : "?") : "(absent)");
            free(va);
            free(vb);
        }
        nd++;
    }
    json_decref(mine);
    return nd;
}

/* summary.json of DIR: a finished one-parameter sweep in the continued key, listing states.csv. */
static gd_status check_summary(const gd_case *c, json_t *root, const char *dir, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    const char *an = json_string_value(json_object_get(root, "analysis"));
    if (!an || strcmp(an, "sweep") != 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.start_sweep: %s holds the output of %s, not of a "
                            "sweep (valid: the directory of a finished sweep in %s)", WHERE("start_sweep"), dir,
                            an ? an : "no analysis", c->cont_parameter);
    json_t *sw = json_object_get(root, "sweep");
    const char *par = json_string_value(json_object_get(json_object_get(sw, "parameter"), "name"));
    if (!par || strcmp(par, c->cont_parameter) != 0 || !json_is_null(json_object_get(sw, "parameter2")))
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.start_sweep: the sweep in %s varies %s%s (valid: "
                            "a one-parameter sweep in continuation.parameter = %s)", WHERE("start_sweep"), dir,
                            par ? par : "?", json_is_null(json_object_get(sw, "parameter2")) ? "" : " and a second key",
                            c->cont_parameter);
    json_t *files = json_object_get(root, "files");
    int listed = 0;
    for (size_t i = 0; i < json_array_size(files); i++)
        listed |= json_is_string(json_array_get(files, i)) && strcmp(json_string_value(json_array_get(files, i)),
                                                                      "states.csv") == 0;
    if (!listed)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.start_sweep: the sweep in %s has no states.csv "
                            "(valid: a finished sweep that lists states.csv in its summary.json: run it again)",
                            WHERE("start_sweep"), dir);
    return gd_contin_same_model(c, json_object_get(json_object_get(root, "case"), "parameters"), dir, "start_sweep",
                                "sweep", err);
}

/* The columns of states.csv that a start needs: the key's, direction, period_n, status, and the
 * state's (every column after status, y[0] .. y[n - 1]). */
typedef struct states_cols {
    int value, direction, period, status, n;
} states_cols;

static gd_status find_columns(char **f, int nf, const char *key, states_cols *sc, const char *path, gd_error *err)
{
    const char *want[4] = {key, "direction", "period_n", "status"};
    int *at[4] = {&sc->value, &sc->direction, &sc->period, &sc->status};
    for (int k = 0; k < 4; k++) {
        *at[k] = -1;
        for (int i = 0; i < nf; i++)
            if (strcmp(f[i], want[k]) == 0)
                *at[k] = i;
        if (*at[k] < 0)
            return gd_error_set(err, GD_ERR_INPUT, "%s: no column %s (valid: the states.csv of a sweep in %s)", path,
                                want[k], key);
    }
    sc->n = nf - 1 - sc->status;
    if (sc->n < 1 || sc->n > GD_MAX_STATE)
        return gd_error_set(err, GD_ERR_INPUT, "%s: %d state columns after status (valid: 1 to %d)", path, sc->n,
                            GD_MAX_STATE);
    return GD_OK;
}

/* The row of states.csv in the chosen direction, done, inside [from, to], nearest the start value. */
static gd_status nearest_row(const gd_case *c, FILE *fp, const states_cols *sc, gd_contin_start *s,
                             const char *path, gd_error *err)
{
    const char *dirn = gd_sweep_branch_name(c->cont_start_sweep_direction);
    double v0 = gd_contin_start_value(c), best = INFINITY;
    char line[16384], *f[GD_MAX_STATE + 16];
    while (fgets(line, sizeof line, fp)) {
        int nf = gd_csv_split(line, f, GD_MAX_STATE + 16);
        if (nf != sc->status + 1 + sc->n || strcmp(f[sc->direction], dirn) != 0 || strcmp(f[sc->status], "done") != 0)
            continue;
        double v = strtod(f[sc->value], NULL);
        if (!(v >= c->cont_from && v <= c->cont_to) || !(fabs(v - v0) < best))
            continue;
        best = fabs(v - v0);
        s->value = v;
        s->nper = atoi(f[sc->period]);
        s->n = sc->n;
        for (int j = 0; j < sc->n; j++)
            s->y[j] = strtod(f[sc->status + 1 + j], NULL);
    }
    char w[GD_PATH_MAX + 32];
    if (!isfinite(best))
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.start_sweep_direction: %s has no finished %s point "
                            "between from = %.10g and to = %.10g (valid: a direction of the sweep with a point there)",
                            WHERE("start_sweep_direction"), path, dirn, c->cont_from, c->cont_to);
    if (s->nper == 0 && c->cont_period == 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.start_sweep: the sweep's %s point at %.10g is not "
                            "periodic (period_n 0) (valid: a periodic point, or continuation.period = the orbit's "
                            "mesh periods)", WHERE("start_sweep"), dirn, s->value);
    return GD_OK;
}

gd_status gd_contin_sweep_start(const gd_case *c, gd_contin_start *s, gd_error *err)
{
    char w[GD_PATH_MAX + 32], path[GD_PATH_MAX + 32];
    const char *dir = c->cont_start_sweep;
    memset(s, 0, sizeof *s);
    snprintf(path, sizeof path, "%s/summary.json", dir);
    json_error_t je;
    json_t *root = json_load_file(path, 0, &je);
    if (!root)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.start_sweep: %s: %s (valid: the directory of a "
                            "finished sweep)", WHERE("start_sweep"), path, je.text);
    gd_status st = check_summary(c, root, dir, err);
    json_decref(root);
    if (st != GD_OK)
        return st;
    snprintf(path, sizeof path, "%s/states.csv", dir);
    FILE *fp = fopen(path, "r");
    if (!fp)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.start_sweep: %s: %s (valid: the directory of a "
                            "finished sweep)", WHERE("start_sweep"), path, strerror(errno));
    char line[16384], *f[GD_MAX_STATE + 16], key[300];
    const char *dot = strchr(c->cont_parameter, '.');
    snprintf(key, sizeof key, "%s", dot ? dot + 1 : c->cont_parameter);
    states_cols sc;
    if (!fgets(line, sizeof line, fp))
        st = gd_error_set(err, GD_ERR_INPUT, "%s: empty (valid: the states.csv of a finished sweep)", path);
    else
        st = find_columns(f, gd_csv_split(line, f, GD_MAX_STATE + 16), key, &sc, path, err);
    if (st == GD_OK)
        st = nearest_row(c, fp, &sc, s, path, err);
    fclose(fp);
    if (st == GD_OK)
        snprintf(s->source, sizeof s->source, "sweep %s, %s, %s = %.10g", dir,
                 gd_sweep_branch_name(c->cont_start_sweep_direction), key, s->value);
    return st;
}
