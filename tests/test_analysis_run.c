/* A C program runs analyses with the library alone: the response and the tca rows of the table
 * (gd_analysis_find(...)->run, write, summary, free) in a temporary directory, linked against the
 * shared libgeardyn and its public headers only. The files are read back and checked against the
 * results the rows returned, which the library computed on its own paths:
 *  - response: time_history.csv has one row per recorded sample (record_periods x
 *    samples_per_period), and the RMS of its acceleration column is the result's RMS (computed
 *    from the samples inside the response run, before any formatting); variable.csv's lambda_L is
 *    time_history.csv's (two computations of the same deflection); the spectrum has n/2 + 1 lines;
 *  - tca (cases/paper/tca-modified.ini: a modified, misaligned pair, whose GTE is not zero):
 *    gte.csv has a row per position and its left GTE column spans gte_pp_arcsec;
 *  - both: summary.json's "files" are exactly the files the run's directory committed, in order,
 *    then summary.json, and every one of them exists;
 *  - a run that fails before its first file (an unknown response variable) leaves no directory;
 *  - kept files (gd_job, the Python module's way in): the tca case run as a job in memory keeps the
 *    bytes of the tables the directory above holds, and touches no disk; run as a job into a
 *    directory, every file there is byte for byte what the job kept (summary.json too); a
 *    sub-directory of a run in memory joins its parent's files as "sub/NAME"; a job stopped
 *    before it runs is interrupted and makes nothing. */
#include "geardyn/geardyn.h"
#include "tap.h"

#include <ftw.h>
#include <jansson.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define CHECK(call, err)                                                                                           \
    do {                                                                                                           \
        if ((call) != GD_OK) {                                                                                     \
            printf("Bail out! %s:%d: %s: %s\n", __FILE__, __LINE__, #call, (err)->msg);                            \
            exit(1);                                                                                               \
        }                                                                                                          \
    } while (0)

static void make_case(gd_case *c, const char *const *sets)
{
    gd_error e = {0};
    CHECK(gd_case_init(c, &e), &e);
    c->speed_rpm = 4000, c->torque_nm = 500; /* the paper's operating point: a case must give one */
    for (int i = 0; sets[i]; i++)
        CHECK(gd_case_set(c, sets[i], i, &e), &e);
    CHECK(gd_case_resolve(c, &e), &e);
}

/* Column col (0-based) of a CSV file with a header: values into v (at most max), the count. */
static long read_column(const char *path, int col, double *v, long max)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    char line[8192];
    long n = 0;
    if (!fgets(line, sizeof line, f)) {
        fclose(f);
        return -1;
    }
    while (fgets(line, sizeof line, f)) {
        char *p = line;
        for (int k = 0; k < col && p; k++) {
            p = strchr(p, ',');
            if (p)
                p++;
        }
        if (p && n < max)
            v[n] = strtod(p, NULL);
        n++;
    }
    fclose(f);
    return n;
}

static int exists(const char *dir, const char *name)
{
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    struct stat sb;
    return stat(path, &sb) == 0;
}

/* summary.json lists the files the run committed, in order, then itself; each exists. */
static void check_summary(const char *dir, const char *const *files, int n, const char *what)
{
    char path[2048];
    snprintf(path, sizeof path, "%s/summary.json", dir);
    json_error_t je;
    json_t *root = json_load_file(path, 0, &je);
    json_t *fl = root ? json_object_get(root, "files") : NULL;
    int same = fl && json_is_array(fl) && (int)json_array_size(fl) == n;
    for (int i = 0; same && i < n; i++)
        same = strcmp(json_string_value(json_array_get(fl, (size_t)i)), files[i]) == 0;
    tap_ok(same, "%s: summary.json lists the %d files of the run's directory in order", what, n);
    int all = n > 0 && strcmp(files[n - 1], "summary.json") == 0;
    for (int i = 0; i < n; i++)
        all &= exists(dir, files[i]);
    tap_ok(all, "%s: every listed file exists, summary.json last", what);
    json_decref(root);
}

/* The row of the case's analysis through run, write and summary in dir; the files committed. */
static void *run_row(const gd_analysis_type *a, const gd_case *c, const char *dir, gd_run_dir **out)
{
    gd_error e = {0};
    void *res = NULL;
    gd_run_env env;
    memset(&env, 0, sizeof env);
    CHECK(gd_run_dir_open(dir, out, &e), &e);
    CHECK(a->run(c, &env, *out, &res, &e), &e);
    CHECK(a->write(c, res, *out, &e), &e);
    CHECK(a->summary(c, res, *out, &e), &e);
    CHECK(gd_run_dir_publish(*out, &e), &e);
    return res;
}

static void response(const char *tmp)
{
    static const char *const sets[] = {"scene.analysis=response", "run.transient_periods=20",
                                       "run.record_periods=8", "output.samples_per_period=32", NULL};
    gd_case c;
    make_case(&c, sets);
    const gd_analysis_type *a = gd_analysis_find(GD_ANALYSIS_RESPONSE);
    tap_ok(a && a->run && a->write && a->summary && a->free, "response: the row has run, write, summary, free");
    char dir[1024];
    snprintf(dir, sizeof dir, "%s/response", tmp);
    gd_run_dir *out;
    gd_response_outcome *r = run_row(a, &c, dir, &out);

    long want = (long)c.record_periods * c.samples_per_period;
    double *acc = malloc(sizeof(double) * (size_t)(want + 16)), *lam = malloc(sizeof(double) * (size_t)(want + 16));
    double *var = malloc(sizeof(double) * (size_t)(want + 16));
    char path[2048];
    snprintf(path, sizeof path, "%s/time_history.csv", dir);
    long n = read_column(path, 4, acc, want + 16);    /* accel_L_mps2 */
    read_column(path, 2, lam, want + 16);             /* lambda_L_um */
    tap_ok(n == want && (size_t)n == r->local.n, "response: time_history.csv has %ld rows (%ld samples, local %zu)",
           n, want, r->local.n);
    double s2 = 0;
    for (long i = 0; i < n && i < want; i++)
        s2 += acc[i] * acc[i];
    TAP_REL(sqrt(s2 / (double)n), r->res.rms_accel_mps2[0], 1e-7, "response: RMS of time_history.csv accel_L = result");
    snprintf(path, sizeof path, "%s/variable.csv", dir);
    long nv = read_column(path, 1, var, want + 16);
    double dmax = 0;
    for (long i = 0; i < nv && i < n && i < want; i++)
        dmax = fmax(dmax, fabs(var[i] - lam[i]));
    tap_ok(nv == n && dmax <= 1e-6 * (1 + fabs(r->res.lambda_max_um[0])),
           "response: variable.csv lambda_L = time_history.csv lambda_L_um (%ld rows, largest difference %.3g um)",
           nv, dmax);
    snprintf(path, sizeof path, "%s/spectrum.csv", dir);
    long ns = read_column(path, 2, var, want + 16);
    tap_ok(ns == n / 2 + 1, "response: spectrum.csv has n/2 + 1 = %ld lines (%ld)", n / 2 + 1, ns);
    snprintf(path, sizeof path, "%s/poincare.csv", dir);
    long np = read_column(path, 0, var, want + 16);
    tap_ok(np == r->res.poincare_count && np >= c.record_periods,
           "response: poincare.csv has the %ld Poincare points of the result (%ld)", r->res.poincare_count, np);
    int nf;
    const char *const *files = gd_run_dir_files(out, &nf);
    check_summary(dir, files, nf, "response");
    a->free(r);
    gd_run_dir_close(out);
    free(acc);
    free(lam);
    free(var);

    /* a failure before the first file leaves nothing */
    gd_error e = {0};
    snprintf(dir, sizeof dir, "%s/refused", tmp);
    CHECK(gd_case_set(&c, "output.response_variable=nothing", 9, &e), &e);
    void *res = NULL;
    gd_run_env env;
    memset(&env, 0, sizeof env);
    CHECK(gd_run_dir_open(dir, &out, &e), &e);
    gd_status st = a->run(&c, &env, out, &res, &e);
    gd_run_dir_close(out);
    tap_ok(st == GD_ERR_INPUT && res == NULL && strstr(e.msg, "output.response_variable") && access(dir, F_OK) != 0,
           "response: an unknown variable is refused before any file, no directory made: %s", e.msg);
    gd_case_free(&c);
}

static void tca(const char *tmp)
{
    gd_case c;
    gd_error e = {0};
    char path[2048];
    const char *src = getenv("GEARDYN_SOURCE");
    snprintf(path, sizeof path, "%s/cases/paper/tca-modified.ini", src ? src : ".");
    CHECK(gd_case_init(&c, &e), &e);
    CHECK(gd_case_load(&c, path, &e), &e);
    CHECK(gd_case_resolve(&c, &e), &e);
    const gd_analysis_type *a = gd_analysis_find(GD_ANALYSIS_TCA);
    char dir[1024];
    snprintf(dir, sizeof dir, "%s/tca", tmp);
    gd_run_dir *out;
    gd_tca_result *r = run_row(a, &c, dir, &out);
    double g[4096];
    snprintf(path, sizeof path, "%s/gte.csv", dir);
    long n = read_column(path, 1, g, 4096);          /* gte_left_arcsec */
    double lo = INFINITY, hi = -INFINITY;
    for (long i = 0; i < n && i < 4096; i++)
        lo = fmin(lo, g[i]), hi = fmax(hi, g[i]);
    tap_ok(n == r->npos, "tca: gte.csv has a row per position (%ld, %d)", n, r->npos);
    TAP_CLOSE(hi - lo, r->gte_pp_arcsec[0], 1e-8 * (1 + r->gte_pp_arcsec[0]),
              "tca: peak-to-peak of gte.csv's left GTE = gte_pp_arcsec");
    int sep = exists(dir, "separation_left.csv") && (r->halves < 2 || exists(dir, "separation_right.csv"));
    tap_ok(sep && exists(dir, "contact_path.csv"), "tca: contact_path.csv and a separation table per half (%d)",
           r->halves);
    int nf;
    const char *const *files = gd_run_dir_files(out, &nf);
    check_summary(dir, files, nf, "tca");
    a->free(r);
    gd_run_dir_close(out);
    gd_case_free(&c);
}

/* The bytes of dir/name (malloc'd), *len; NULL when it cannot be read. */
static char *slurp(const char *dir, const char *name, size_t *len)
{
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *b = NULL;
    size_t cap = 0;
    *len = 0;
    for (;;) {
        if (*len == cap && !(b = realloc(b, cap = 2 * cap + 4096)))
            break;
        size_t r = fread(b + *len, 1, cap - *len, f);
        if (r == 0)
            break;
        *len += r;
    }
    fclose(f);
    return b;
}

/* The job's bytes of name are dir/name's. */
/* The pictures through a drawer (gd_run_env.draw): what a C program gets with none, with one that
 * draws and with one that fails. */
typedef struct drawer_log {
    int kinds[8], nnotes, calls, asked;
    char notes[8][GD_ERROR_MSG_MAX + 256];
    char names[8][64];
    int nnames, script_ok;
    int fail;
} drawer_log;

static void log_note(void *user, int kind, const char *text)
{
    drawer_log *l = user;
    if (l->nnotes < 8) {
        l->kinds[l->nnotes] = kind;
        snprintf(l->notes[l->nnotes++], sizeof l->notes[0], "%s", text);
    }
}

/* writes a whole PNG (signature .. IEND) and SVG (.. </svg>) for every name, as a drawer must */
static gd_status fake_draw(void *user, const char *dir, const char *script, const char *const *names, int nnames,
                           gd_error *err)
{
    drawer_log *l = user;
    if (!script) {
        l->asked++;
        return GD_OK;
    }
    l->calls++;
    if (l->fail)
        return gd_error_set(err, GD_ERR_IO, "the drawer failed on purpose");
    l->script_ok = strstr(script, "set terminal svg") && strstr(script, "set output '.gte.svg.tmp'") != NULL;
    for (int i = 0; i < nnames && l->nnames < 8; i++) {
        snprintf(l->names[l->nnames++], sizeof l->names[0], "%s", names[i]);
        char path[2048];
        snprintf(path, sizeof path, "%s/%s.png", dir, names[i]);
        FILE *f = fopen(path, "wb");
        if (f) {
            fwrite("\x89PNG\r\n\x1a\n\0\0\0\0IEND\xae\x42\x60\x82", 1, 20, f);
            fclose(f);
        }
        snprintf(path, sizeof path, "%s/%s.svg", dir, names[i]);
        f = fopen(path, "w");
        if (f) {
            fputs("<svg></svg>\n", f);
            fclose(f);
        }
    }
    return GD_OK;
}

static void drawer(const char *tmp)
{
    gd_case c;
    gd_error e = {0};
    char path[2048];
    const char *src = getenv("GEARDYN_SOURCE");
    snprintf(path, sizeof path, "%s/cases/paper/tca-modified.ini", src ? src : ".");
    CHECK(gd_case_init(&c, &e), &e);
    CHECK(gd_case_load(&c, path, &e), &e);
    CHECK(gd_case_set(&c, "output.plots=on", 0, &e), &e);
    CHECK(gd_case_resolve(&c, &e), &e);
    const gd_analysis_type *a = gd_analysis_find(GD_ANALYSIS_TCA);
    char dir[1024];
    for (int k = 0; k < 3; k++) { /* no drawer, one that draws, one that fails */
        drawer_log l;
        memset(&l, 0, sizeof l);
        l.fail = k == 2;
        gd_run_env env;
        memset(&env, 0, sizeof env);
        env.user = &l;
        env.note = log_note;
        env.draw = k ? fake_draw : NULL;
        snprintf(dir, sizeof dir, "%s/drawer%d", tmp, k);
        gd_status st = gd_analysis_run_in(a, &c, &env, dir, &e);
        int pics = exists(dir, "gte.png") + exists(dir, "gte.svg") + exists(dir, "contact_pattern.png") +
                   exists(dir, "contact_pattern.svg");
        size_t len = 0;
        char *sum = slurp(dir, "summary.json", &len);
        int listed = sum && strstr(sum, "\"gte.svg\"") != NULL;
        if (k == 0)
            tap_ok(st == GD_OK && pics == 0 && !listed && l.nnotes == 1 && l.kinds[0] == GD_NOTE_NO_PICTURES &&
                       strcmp(l.notes[0], "no drawer was given (gd_run_env.draw): no pictures") == 0,
                   "drawer: without one, no pictures and the note says so (%d notes: %s)", l.nnotes, l.notes[0]);
        else if (k == 1)
            tap_ok(st == GD_OK && pics == 4 && listed && l.nnotes == 0 && l.calls == 1 && l.asked >= 1 &&
                       l.script_ok && l.nnames == 2 && strcmp(l.names[0], "contact_pattern") == 0 &&
                       strcmp(l.names[1], "gte") == 0,
                   "drawer: asked first, then handed the script of contact_pattern and gte; the pictures drawn "
                   "are published and listed (%d of 4)", pics);
        else
            tap_ok(st == GD_OK && pics == 0 && !listed && l.nnotes == 1 && l.kinds[0] == GD_NOTE_PICTURES_FAILED &&
                       strcmp(l.notes[0], "pictures not drawn: the drawer failed on purpose") == 0,
                   "drawer: one that fails gives the note 'pictures not drawn: ...' and the run its files (%s)",
                   l.notes[0]);
        free(sum);
    }
    gd_case_free(&c);
}

static int same_bytes(const gd_job *j, const char *dir, const char *name)
{
    size_t n = 0, m = 0;
    const char *kept = gd_job_file(j, name, &n);
    char *disk = slurp(dir, name, &m);
    int same = kept && disk && n == m && memcmp(kept, disk, n) == 0;
    free(disk);
    return same;
}

static void kept(const char *tmp)
{
    gd_case c;
    gd_error e = {0};
    char path[2048], dir[1024], tdir[1024];
    const char *src = getenv("GEARDYN_SOURCE");
    snprintf(path, sizeof path, "%s/cases/paper/tca-modified.ini", src ? src : ".");
    snprintf(tdir, sizeof tdir, "%s/tca", tmp);
    CHECK(gd_case_init(&c, &e), &e);
    CHECK(gd_case_load(&c, path, &e), &e);
    static const char *const tables[] = {"gte.csv", "contact_path.csv", "separation_left.csv"};

    gd_job *j;
    CHECK(gd_job_new(&c, NULL, 1, &j, &e), &e);
    CHECK(gd_job_run(j, &e), &e);
    int same = 1;
    for (size_t i = 0; i < sizeof tables / sizeof tables[0]; i++)
        same &= same_bytes(j, tdir, tables[i]);
    size_t n;
    tap_ok(same && gd_job_file(j, "summary.json", &n) && n > 0 && !gd_job_file(j, "nothing.csv", &n) &&
           access("(memory)", F_OK) != 0,
           "kept: a job in memory keeps the bytes of the tables the run's directory holds, and writes nothing");
    long done, total;
    gd_job_progress(j, &done, &total);
    gd_job_free(j);

    snprintf(dir, sizeof dir, "%s/tca-kept", tmp);
    CHECK(gd_job_new(&c, dir, 1, &j, &e), &e);
    CHECK(gd_job_run(j, &e), &e);
    int nlisted = 0;
    size_t len;
    const char *sj = gd_job_file(j, "summary.json", &len);
    json_error_t je;
    json_t *root = sj ? json_loadb(sj, len, 0, &je) : NULL;
    json_t *fl = root ? json_object_get(root, "files") : NULL;
    same = fl && json_array_size(fl) > 3;
    for (size_t i = 0; same && i < json_array_size(fl); i++, nlisted++)
        same = same_bytes(j, dir, json_string_value(json_array_get(fl, i)));
    json_decref(root);
    tap_ok(same, "kept: a job into a directory writes there the %d files it keeps, byte for byte", nlisted);
    gd_job_free(j);

    gd_run_dir *m, *sub;
    FILE *fp;
    CHECK(gd_run_dir_open_memory("(memory)", &m, &e), &e);
    CHECK(gd_run_dir_open_sub(m, "optimum", &sub, &e), &e);
    CHECK(gd_run_dir_create(sub, "a.csv", &fp, &e), &e);
    fputs("x,y\n1,2\n", fp);
    CHECK(gd_run_dir_commit(sub, fp, &e), &e);
    int before = gd_run_dir_data(m, "optimum/a.csv", NULL) == NULL;
    CHECK(gd_run_dir_publish(sub, &e), &e);
    gd_run_dir_close(sub);
    const char *a = gd_run_dir_data(m, "optimum/a.csv", &len);
    tap_ok(before && a && len == 8 && memcmp(a, "x,y\n1,2\n", 8) == 0 && !gd_run_dir_data(m, "a.csv", NULL) &&
           !gd_run_dir_stage(m) && access("(memory)", F_OK) != 0,
           "kept: a sub-directory's file joins its parent's as optimum/a.csv when published");
    gd_run_dir_close(m);

    snprintf(dir, sizeof dir, "%s/stopped", tmp);
    CHECK(gd_job_new(&c, dir, 1, &j, &e), &e);
    gd_job_stop(j);
    gd_status st = gd_job_run(j, &e);
    tap_ok(st == GD_ERR_INTERRUPTED && access(dir, F_OK) != 0 && !gd_job_file(j, "summary.json", NULL),
           "kept: a job stopped before it runs is interrupted and makes nothing: %s", e.msg);
    gd_job_free(j);
    gd_case_free(&c);
}

static int remove_entry(const char *path, const struct stat *sb, int flag, struct FTW *ftw)
{
    (void)sb, (void)flag, (void)ftw;
    return remove(path);
}

int main(void)
{
    char tmp[] = "/tmp/geardyn-analysis-run-XXXXXX";
    if (!mkdtemp(tmp)) {
        printf("Bail out! mkdtemp failed\n");
        return 1;
    }
    response(tmp);
    tca(tmp);
    kept(tmp);
    drawer(tmp);
    if (tap_failed == 0)
        nftw(tmp, remove_entry, 16, FTW_DEPTH | FTW_PHYS); /* kept for a look when a check failed */
    return tap_done();
}
