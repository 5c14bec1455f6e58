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
 *  - a run that fails before its first file (an unknown response variable) leaves no directory. */
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
    if (tap_failed == 0)
        nftw(tmp, remove_entry, 16, FTW_DEPTH | FTW_PHYS); /* kept for a look when a check failed */
    return tap_done();
}
