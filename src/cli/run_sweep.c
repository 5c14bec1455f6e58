/* The `sweep` analysis on the command line: the journal and --resume, signals, the progress
 * line, MPI ranks, pictures and the final files.
 *
 * The journal (DIR/.sweep.journal) is the only file written while the sweep runs: a header
 * naming the sweep, then one checksummed record per finished point, appended and synced
 * to disk as the point finishes. --resume reads it back (dropping a line torn by a kill),
 * rewrites it without the damaged lines and runs only the points it lacks. At the end the
 * final files are written atomically from all the points in slot order and the journal is
 * removed, so an interrupted and resumed sweep gives the same files as an uninterrupted
 * one, whatever the number of threads or ranks. */
#include "cli.h"
#include "figure.h"
#include "sweep_mpi.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <time.h>
#include <unistd.h>


#define JOURNAL ".sweep.journal"


typedef struct sweep_cli {
    cli_progress base;       /* first: the user of the common hooks (cli_run_env) */
    const cli_case_args *a;
    const gd_sweep_plan *p;
    gd_sweep_point *pts;
    int rank, size;
    int fd;                  /* the journal, rank 0 */
    char journal[GD_PATH_MAX + 32];
    pthread_mutex_t io;      /* journal appends, the progress line and MPI calls */
    int progress;
    double t0, last_print;
    atomic_llong last_poll_ns;
    int total, done, done_at_start;
    int ranks_done, remote_interrupted, remote_failed;
    char remote_msg[1200];
    atomic_int fatal;        /* rank 0 could not journal a point */
    gd_error fatal_err;
    char *text;              /* the journal as read or started (rank 0), as broadcast (others) */
    size_t tlen;
    int threads;             /* for the summary line */
    double wall;
    int decided, rc;         /* the exit status is decided by the hooks (not to be cli_fail'ed) */
} sweep_cli;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void progress_line(sweep_cli *s, int final)
{
    if (!s->progress)
        return;
    double t = now();
    if (!final && t - s->last_print < 0.25 && s->done < s->total)
        return;
    s->last_print = t;
    int computed = s->done - s->done_at_start;
    double el = t - s->t0, rate = el > 0 ? computed / el : 0;
    char eta[64];
    int left = s->total - s->done;
    if (left == 0)
        snprintf(eta, sizeof eta, "done");
    else if (computed == 0 || !(rate > 0))
        snprintf(eta, sizeof eta, "time left unknown");
    else {
        double sec = left / rate;
        if (sec < 90)
            snprintf(eta, sizeof eta, "%.0f s left", sec);
        else if (sec < 5400)
            snprintf(eta, sizeof eta, "%.0f min left", sec / 60);
        else
            snprintf(eta, sizeof eta, "%.1f h left", sec / 3600);
    }
    fprintf(stderr, "\rgeardyn: sweep %d/%d points, %.3g points/s, %s   %s", s->done, s->total, rate, eta,
            final ? "\n" : "");
    fflush(stderr);
}

static gd_status journal_append(sweep_cli *s, const char *line, size_t len, gd_error *err)
{
    size_t off = 0;
    while (off < len) {
        ssize_t w = write(s->fd, line + off, len - off);
        if (w < 0) {
            if (errno == EINTR)
                continue;
            return gd_error_set(err, GD_ERR_IO, "%s: cannot append: %s", s->journal, strerror(errno));
        }
        off += (size_t)w;
    }
    if (fdatasync(s->fd) != 0 && errno != EINVAL)
        return gd_error_set(err, GD_ERR_IO, "%s: cannot sync: %s", s->journal, strerror(errno));
    return GD_OK;
}

/* a point of another rank, on rank 0 (the io lock is held) */
static int on_remote_record(void *user, int source, const char *line, size_t len)
{
    sweep_cli *s = user;
    int slot;
    gd_error e = {0};
    if (gd_sweep_record_parse(s->p, line, len, s->pts, &slot, &e) != GD_OK) {
        gd_error_set(&s->fatal_err, GD_ERR_INTERNAL, "rank %d sent a bad record: %s", source, e.msg);
        atomic_store(&s->fatal, 1);
        return 1;
    }
    if (journal_append(s, line, len, &e) != GD_OK) {
        s->fatal_err = e;
        atomic_store(&s->fatal, 1);
        return 1;
    }
    s->done++;
    progress_line(s, 0);
    return 0;
}

static void on_remote_done(void *user, int source, int status, const char *msg)
{
    sweep_cli *s = user;
    s->ranks_done++;
    if (status == 1)
        s->remote_interrupted = 1;
    if (status == 2 && !s->remote_failed) {
        s->remote_failed = 1;
        snprintf(s->remote_msg, sizeof s->remote_msg, "rank %d: %s", source, msg);
    }
}

static gd_status on_point(void *user, const gd_sweep_plan *p, const gd_sweep_point *pt, gd_error *err)
{
    sweep_cli *s = user;
    char *line;
    size_t len;
    gd_status st = gd_sweep_record_format(p, pt, &line, &len, err);
    if (st != GD_OK)
        return st;
    pthread_mutex_lock(&s->io);
    if (s->rank == 0) {
        st = journal_append(s, line, len, err);
        if (st == GD_OK) {
            s->done++;
            progress_line(s, 0);
        }
    } else if (cli_mpi_send_record(line, len) != 0) {
        st = gd_error_set(err, GD_ERR_IO, "MPI: cannot send a finished point to rank 0");
    }
    pthread_mutex_unlock(&s->io);
    free(line);
    return st;
}

static int should_stop(void *user)
{
    sweep_cli *s = user;
    if (cli_signal_caught() || atomic_load(&s->fatal))
        return 1;
    if (s->size > 1 && s->rank == 0) {
        /* rank 0 takes the other ranks' points while it computes (every 20 ms at most) */
        long long t = (long long)(now() * 1e9);
        if (t - atomic_load(&s->last_poll_ns) > 20000000LL && pthread_mutex_trylock(&s->io) == 0) {
            atomic_store(&s->last_poll_ns, t);
            cli_mpi_handlers h = {on_remote_record, on_remote_done, s};
            cli_mpi_poll(0, &h);
            pthread_mutex_unlock(&s->io);
        }
    }
    return atomic_load(&s->fatal);
}

/* Temporary files of an earlier run killed while writing its final files. */
static void remove_stale_temporaries(const char *dir)
{
    static const char *prefixes[] = {".sweep.csv.tmp-", ".bifurcation.csv.tmp-", ".summary.json.tmp-",
                                     "." JOURNAL ".tmp-", ".bifurcation.png.tmp", ".bifurcation.svg.tmp",
                                     ".regime_map.png.tmp", ".regime_map.svg.tmp"};
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        for (size_t i = 0; i < sizeof prefixes / sizeof prefixes[0]; i++)
            if (strncmp(e->d_name, prefixes[i], strlen(prefixes[i])) == 0) {
                char path[GD_PATH_MAX + 300];
                snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
                unlink(path);
                break;
            }
    closedir(d);
}

/* Rank 0: the output directory and the journal (read back with --resume, else new). */
static gd_status prepare(sweep_cli *s, const cli_case_args *a, gd_run_dir *out, char **text, size_t *tlen,
                         gd_error *err)
{
    const char *dir = gd_run_dir_path(out);
    gd_status st = gd_run_dir_make(out, err);
    if (st != GD_OK)
        return st;
    remove_stale_temporaries(dir);
    snprintf(s->journal, sizeof s->journal, "%s/%s", dir, JOURNAL);
    int exists = access(s->journal, F_OK) == 0;
    if (a->resume) {
        int loaded = 0, ignored = 0;
        st = gd_sweep_journal_load(s->journal, s->p, s->pts, text, tlen, &loaded, &ignored, err);
        if (st != GD_OK)
            return st;
        if (!a->quiet) {
            if (!exists)
                fprintf(stderr, "geardyn: note: no journal in %s: the sweep starts from the beginning\n", dir);
            else
                fprintf(stderr, "geardyn: resuming: %d of %d points already done%s\n", loaded, s->p->nslots,
                        ignored ? " (a torn or unusable journal line was dropped)" : "");
        }
    } else {
        char header[300];
        gd_sweep_journal_header(s->p, header, sizeof header);
        *tlen = strlen(header);
        *text = malloc(*tlen + 1);
        if (!*text)
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
        memcpy(*text, header, *tlen + 1);
        if (exists && !a->quiet)
            fprintf(stderr, "geardyn: note: %s held an unfinished sweep; starting over (--resume continues one)\n",
                    dir);
    }
    FILE *fp;
    if ((st = gd_run_dir_create(out, JOURNAL, &fp, err)) != GD_OK)
        return st;
    if (fwrite(*text, 1, *tlen, fp) != *tlen) {
        gd_run_dir_discard(out, fp);
        return gd_error_set(err, GD_ERR_IO, "%s: cannot write", s->journal);
    }
    if ((st = gd_run_dir_commit(out, fp, err)) != GD_OK)
        return st;
    s->fd = open(s->journal, O_WRONLY | O_APPEND | O_CLOEXEC);
    if (s->fd < 0)
        return gd_error_set(err, GD_ERR_IO, "%s: cannot open: %s", s->journal, strerror(errno));
    return GD_OK;
}

/* Other ranks: the journal rank 0 read, as text. */
static gd_status load_text(sweep_cli *s, const char *text, size_t len, gd_error *err)
{
    char header[300];
    gd_sweep_journal_header(s->p, header, sizeof header);
    size_t hl = strlen(header);
    if (len < hl || memcmp(text, header, hl) != 0)
        return gd_error_set(err, GD_ERR_INPUT, "rank %d does not see the same sweep as rank 0 (another case file, "
                            "or another geardyn?)", s->rank);
    for (size_t pos = hl; pos < len;) {
        const char *nl = memchr(text + pos, '\n', len - pos);
        size_t l = nl ? (size_t)(nl - (text + pos)) + 1 : len - pos;
        int slot;
        gd_status st = gd_sweep_record_parse(s->p, text + pos, l, s->pts, &slot, err);
        if (st != GD_OK)
            return st;
        pos += l;
    }
    return GD_OK;
}

/* ---- pictures ---- */

/* The branches of a sweep as drawn: continuation up in blue open circles and a wide line under
 * down's vermillion dots and thin line, so that both show where they coincide (Okabe-Ito). */
static const char *branch_colour[] = {"#0072B2", "#D55E00", "#000000"};
static const char *branch_point[] = {"pt 6 ps 0.8", "pt 7 ps 0.45", "pt 7 ps 0.5"};
static const char *branch_line[] = {"pt 6 ps 0.8 lw 2.5", "pt 7 ps 0.45 lw 1", "pt 7 ps 0.5 lw 1.2"};
static const char *branch_key[] = {"continuation up", "continuation down", "independent points"};

/* The swept parameter as the axes name it. */
static void param_label(const gd_sweep_plan *p, int a, char *buf, size_t len)
{
    cli_qty q;
    cli_qty_key(p->parameter[a], &q);
    cli_qty_label(&q, buf, len);
}

/* The range of axis a of the plan, widened by frac (log: of its decades). */
static void param_range(const gd_sweep_plan *p, int a, double frac, double *lo, double *hi)
{
    double v0 = p->values[a][0], v1 = p->values[a][p->npoints[a] - 1];
    cli_pad(fmin(v0, v1), fmax(v0, v1), frac, p->spacing[a] == GD_SWEEP_LOG, lo, hi);
}

/* The y range of the Poincare panel (values times scale): the range of every point, unless one
 * parameter value reaches so far beyond all others that they would be squashed into a third of
 * the panel; then the range of the others, and that value's points beyond it drawn as markers on
 * the panel's edge with their extreme value. *off gets the index of that value (-1: none). */
static void poincare_range(const gd_sweep_plan *p, const gd_sweep_point *pts, double scale, double *lo, double *hi,
                           int *off, double *off_x, double *off_v)
{
    int nv = p->npoints[0];
    double *cl = malloc(sizeof(double) * (size_t)nv * 2);
    *off = -1;
    *lo = INFINITY;
    *hi = -INFINITY;
    if (!cl)
        return;
    for (int i = 0; i < nv; i++)
        cl[2 * i] = INFINITY, cl[2 * i + 1] = -INFINITY;
    for (int s = 0; s < p->nslots; s++) {
        const gd_sweep_point *pt = &pts[s];
        for (long k = 0; k < pt->npoincare; k++) {
            double y = pt->poincare[k * p->nresp] * scale;
            if (!isfinite(y))
                continue;
            cl[2 * pt->idx[0]] = fmin(cl[2 * pt->idx[0]], y);
            cl[2 * pt->idx[0] + 1] = fmax(cl[2 * pt->idx[0] + 1], y);
        }
    }
    for (int i = 0; i < nv; i++)
        if (cl[2 * i] <= cl[2 * i + 1]) {
            *lo = fmin(*lo, cl[2 * i]);
            *hi = fmax(*hi, cl[2 * i + 1]);
        }
    int used = 0;
    for (int i = 0; i < nv; i++)
        used += cl[2 * i] <= cl[2 * i + 1];
    if (used >= 5 && *hi > *lo) {
        int best = -1;
        double blo = 0, bhi = 0;
        for (int j = 0; j < nv; j++) {
            if (!(cl[2 * j] <= cl[2 * j + 1]))
                continue;
            double l = INFINITY, h = -INFINITY;
            for (int i = 0; i < nv; i++)
                if (i != j && cl[2 * i] <= cl[2 * i + 1]) {
                    l = fmin(l, cl[2 * i]);
                    h = fmax(h, cl[2 * i + 1]);
                }
            if (best < 0 || h - l < bhi - blo)
                best = j, blo = l, bhi = h;
        }
        if (best >= 0 && bhi - blo < (*hi - *lo) / 3) {
            *off = best;
            *off_x = p->values[0][best];
            *off_v = fabs(cl[2 * best] - blo) > fabs(cl[2 * best + 1] - bhi) ? cl[2 * best] : cl[2 * best + 1];
            *lo = blo;
            *hi = bhi;
        }
    }
    free(cl);
}

/* The sweep's model for a title. */
static const char *model_words(const gd_case *c)
{
    static const char *w[] = {"torsional model", "torsional model of the two halves", "bending-torsion-axial model"};
    return c->model >= 0 && c->model <= 2 ? w[c->model] : "model";
}

/* Fig. 15 of the paper: the Poincare points, the largest Lyapunov exponent and the RMS
 * acceleration stacked on one parameter axis; up and down in two colours. */
static void script_bifurcation(gd_gnuplot_script *b, const gd_case *c, const gd_sweep_plan *p,
                               const gd_sweep_point *pts, const int *has, int mle, int svg)
{
    int panels = mle ? 4 : 3, h = 180 + 300 * panels;
    double x0, x1;
    param_range(p, 0, 0.025, &x0, &x1);
    char xl[256], title[512], q0[256];
    param_label(p, 0, xl, sizeof xl);
    cli_qty par;
    cli_qty_key(p->parameter[0], &par);
    cli_gp_text(par.name, q0, sizeof q0);
    snprintf(title, sizeof title, "Sweep of the %s (%s, %s)", q0, model_words(c),
             p->mode == GD_SWEEP_CONTINUATION ? "continuation" : "independent points");
    /* the Poincare samples of the first response, in the tables' dimensionless units: lengths
     * times the characteristic length, rates as they are */
    cli_qty r;
    cli_qty_column(p->resp[0].name, p->nmesh, &r);
    double scale = 1;
    if (strcmp(r.unit, "µm") == 0)
        scale = c->characteristic_length_um;
    else
        snprintf(r.unit, sizeof r.unit, "-");
    if (strcmp(r.unit, "-") == 0) {
        size_t l = strlen(r.name);
        snprintf(r.name + l, sizeof r.name - l, " over b_c ω_n");
    }
    size_t l = strlen(r.name);
    snprintf(r.name + l, sizeof r.name - l, " at the Poincaré section");
    char yl[300];
    cli_qty_label(&r, yl, sizeof yl);
    double ylo, yhi, off_x = 0, off_v = 0;
    int off;
    poincare_range(p, pts, scale, &ylo, &yhi, &off, &off_x, &off_v);
    double ya, yb;
    cli_pad(ylo, yhi, 0.07, 0, &ya, &yb);
    cli_fig_begin(b, svg, 1200, h, "bifurcation");
    double top = 1 - 95.0 / h, bottom = 70.0 / h;
    gd_gnuplot_printf(b, "set multiplot layout %d,1 margins 0.1,0.96,%.4f,%.4f spacing 0,0.025 title '%s'\n", panels,
                      bottom, top, title);
    gd_gnuplot_printf(b, "set xrange [%.12g:%.12g]\n%sset format x ''\nunset xlabel\n", x0, x1,
                      p->spacing[0] == GD_SWEEP_LOG ? "set logscale x\n" : "");
    /* the key above the panels, right */
    gd_gnuplot_printf(b, "set key at screen 0.96,%.4f right top horizontal samplen 1.5\n", 1 - 48.0 / h);
    gd_gnuplot_printf(b, "set ylabel '%s'\nset yrange [%.9g:%.9g]\n", yl, ya, yb);
    char rc[80];
    snprintf(rc, sizeof rc, "column('%s')*%.12g", p->resp[0].name, scale);
    double edge = 0;
    if (off >= 0) {
        /* the points of that value beyond the range: a triangle on the edge they lie beyond,
         * labelled with their extreme value */
        edge = off_v < ylo ? ya + 0.035 * (yb - ya) : yb - 0.035 * (yb - ya);
        gd_gnuplot_printf(b, "set label 1 '%.3g%s%s' at %.12g,%.12g offset 1.3,0 left front\n", off_v,
                          strcmp(r.unit, "-") ? " " : "", strcmp(r.unit, "-") ? r.unit : "", off_x, edge);
    }
    /* the points inside the range (its ends widened by a millionth: the table's digits are
     * fewer than those the range was found with) */
    double tol = 1e-6 * (yhi - ylo > 0 ? yhi - ylo : 1);
    gd_gnuplot_printf(b, "plot ");
    int first = 1;
    for (int br = 0; br < 3; br++)
        if (has[br]) {
            gd_gnuplot_printf(b, "%s'bifurcation.csv' using 'parameter':(strcol('direction') eq '%s' && %s >= %.12g && "
                                 "%s <= %.12g ? %s : 1/0) with points %s lc rgb '%s' title '%s'",
                              first ? "" : ", ", gd_sweep_branch_name(br), rc, ylo - tol, rc, yhi + tol, rc,
                              branch_point[br], branch_colour[br], branch_key[br]);
            first = 0;
        }
    if (off >= 0)
        gd_gnuplot_printf(b, ", 'bifurcation.csv' using 'parameter':(abs(column('parameter') - %.12g) < %.6g && "
                             "(%s < %.12g || %s > %.12g) ? %.12g : 1/0) with points pt %d ps 1.3 lc rgb '#000000' "
                             "title 'beyond the axis'",
                          off_x, 1e-9 * fmax(1, fabs(off_x)), rc, ylo - tol, rc, yhi + tol, edge, off_v < ylo ? 11 : 9);
    gd_gnuplot_printf(b, "\nunset label 1\nunset key\nset yrange [*:*]\n");
    /* sweep.csv's columns: the exponent, the RMS acceleration, the dynamic load factor (the larger
     * of the meshes') */
    const char *what[3] = {"largest Lyapunov exponent (per mesh period)", "RMS mesh acceleration (m/s²)",
                           "dynamic load factor (-)"};
    const char *col[3] = {"mle", "rms_accel_mps2", "dynamic_load_factor"};
    for (int q = mle ? 0 : 1; q < 3; q++) {
        if (q == 2)
            gd_gnuplot_printf(b, "unset xzeroaxis\nset format x '%% h'\nset xlabel '%s'\n", xl);
        else if (q == 0)
            gd_gnuplot_printf(b, "set xzeroaxis lt -1 lw 0.8\n");
        else
            gd_gnuplot_printf(b, "unset xzeroaxis\n");
        gd_gnuplot_printf(b, "set ylabel '%s'\nplot ", what[q]);
        first = 1;
        for (int br = 0; br < 3; br++)
            if (has[br]) {
                gd_gnuplot_printf(b, "%s'sweep.csv' using 'parameter':(strcol('direction') eq '%s' ? column('%s') : 1/0) "
                                     "with linespoints %s lc rgb '%s' notitle",
                                  first ? "" : ", ", gd_sweep_branch_name(br), col[q], branch_line[br], branch_colour[br]);
                first = 0;
            }
        gd_gnuplot_printf(b, "\n");
    }
    cli_fig_end(b, 1);
}

/* The motion classes of a regime map, in the order of its key, and their colours (Okabe-Ito and
 * a wine for the long periods; told apart by colour-blind readers). */
enum { CL_P1, CL_P2, CL_P3, CL_P4, CL_PN, CL_QUASI, CL_NOTP, CL_CHAOS, CL_FAILED, CL_N };
static const char *class_name[CL_N] = {"period-1", "period-2", "period-3", "period-4", "period-5 or more",
                                       "quasi-periodic", "not periodic (not settled)", "chaotic", "failed"};
static const int class_rgb[CL_N] = {0x0072B2, 0x56B4E9, 0x009E73, 0xCC79A7, 0x882255,
                                    0xE69F00, 0xBBBBBB, 0xD55E00, 0x000000};

static int motion_class(const gd_sweep_point *pt)
{
    if (pt->status != GD_POINT_DONE)
        return CL_FAILED;
    if (strcmp(pt->motion, "chaotic") == 0)
        return CL_CHAOS;
    if (strcmp(pt->motion, "quasi-periodic") == 0)
        return CL_QUASI;
    if (strncmp(pt->motion, "period-", 7) == 0) {
        int n = atoi(pt->motion + 7);
        return n >= 1 && n <= 4 ? CL_P1 + n - 1 : CL_PN;
    }
    return CL_NOTP;
}

/* The edges of the cells of axis a: each value's cell reaches half-way (geometrically on a log
 * axis) to its neighbours, the first and the last stop at the swept range's ends. */
static void cell_edges(const gd_sweep_plan *p, int a, int i, double *lo, double *hi)
{
    int n = p->npoints[a];
    const double *v = p->values[a];
    int lg = p->spacing[a] == GD_SWEEP_LOG;
    double prev = i > 0 ? (lg ? sqrt(v[i - 1] * v[i]) : 0.5 * (v[i - 1] + v[i])) : v[0];
    double next = i + 1 < n ? (lg ? sqrt(v[i + 1] * v[i]) : 0.5 * (v[i + 1] + v[i])) : v[n - 1];
    *lo = fmin(prev, next);
    *hi = fmax(prev, next);
    if (n == 1) {
        double d = fabs(v[0]) * 0.05 + 0.5;
        *lo = v[0] - d;
        *hi = v[0] + d;
    }
}

/* The regime map: motion class and largest Lyapunov exponent over the two parameters, one row
 * of panels per branch, drawn from the plan's points as cells that tile the swept ranges. */
static void script_map(gd_gnuplot_script *b, const gd_sweep_plan *p, const gd_sweep_point *pts, const int *has,
                       int svg)
{
    int rows = has[0] + has[1] + has[2];
    int present[CL_N] = {0};
    int nm = 0;
    double *am = malloc(sizeof(double) * (size_t)(p->nslots > 0 ? p->nslots : 1));
    for (int s = 0; s < p->nslots; s++) {
        present[motion_class(&pts[s])] = 1;
        if (am && pts[s].status == GD_POINT_DONE && isfinite(pts[s].mle_per_period))
            am[nm++] = fabs(pts[s].mle_per_period);
    }
    /* the exponent's colour scale: to the 90th percentile of |exponent| (one column of chaos
     * does not wash the others out); larger values get the scale's end colour */
    double mle_abs = 0;
    if (nm > 0) {
        for (int i = 1; i < nm; i++)
            for (int j = i; j > 0 && am[j - 1] > am[j]; j--) {
                double t = am[j];
                am[j] = am[j - 1];
                am[j - 1] = t;
            }
        mle_abs = am[(int)floor(0.9 * (nm - 1))];
        if (!(mle_abs > 0))
            mle_abs = am[nm - 1];
    }
    free(am);
    if (!(mle_abs > 0))
        mle_abs = 0.01;
    double step = cli_nice_step(mle_abs, 2);
    mle_abs = ceil(mle_abs / step * (1 - 1e-9)) * step;
    /* the cells */
    for (int br = 0; br < 3; br++) {
        if (!has[br])
            continue;
        gd_gnuplot_printf(b, "$MAP%d << EOD\nx,y,xlo,xhi,ylo,yhi,rgb,mle\n", br);
        for (int s = 0; s < p->nslots; s++) {
            const gd_sweep_point *pt = &pts[s];
            if (pt->branch != br)
                continue;
            double xl, xh, yl, yh;
            cell_edges(p, 0, pt->idx[0], &xl, &xh);
            cell_edges(p, 1, pt->idx[1], &yl, &yh);
            double e = pt->status == GD_POINT_DONE && isfinite(pt->mle_per_period) ? pt->mle_per_period : NAN;
            if (isfinite(e))
                e = fmax(-mle_abs, fmin(mle_abs, e));
            gd_gnuplot_printf(b, "%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%d,", pt->value[0], pt->value[1], xl, xh, yl, yh,
                              class_rgb[motion_class(pt)]);
            if (isfinite(e))
                gd_gnuplot_printf(b, "%.9g\n", e);
            else
                gd_gnuplot_printf(b, "NaN\n");
        }
        gd_gnuplot_printf(b, "EOD\n");
    }
    int W = 1300, H = 110 + 520 * rows;
    cli_fig_begin(b, svg, W, H, "regime_map");
    char xl[256], yl[256], q0[256], q1[256], title[600];
    param_label(p, 0, xl, sizeof xl);
    param_label(p, 1, yl, sizeof yl);
    cli_qty a0, a1;
    cli_qty_key(p->parameter[0], &a0);
    cli_qty_key(p->parameter[1], &a1);
    cli_gp_text(a0.name, q0, sizeof q0);
    cli_gp_text(a1.name, q1, sizeof q1);
    snprintf(title, sizeof title, "Regime map over the %s and the %s", q0, q1);
    double x0 = fmin(p->values[0][0], p->values[0][p->npoints[0] - 1]), x1 = fmax(p->values[0][0], p->values[0][p->npoints[0] - 1]);
    double y0 = fmin(p->values[1][0], p->values[1][p->npoints[1] - 1]), y1 = fmax(p->values[1][0], p->values[1][p->npoints[1] - 1]);
    if (p->npoints[0] == 1)
        cell_edges(p, 0, 0, &x0, &x1);
    if (p->npoints[1] == 1)
        cell_edges(p, 1, 0, &y0, &y1);
    gd_gnuplot_printf(b, "set multiplot title '%s'\nset offsets 0,0,0,0\nset tics out\nset grid noxtics noytics\n", title);
    gd_gnuplot_printf(b, "set xrange [%.12g:%.12g]\nset yrange [%.12g:%.12g]\nset xlabel '%s'\nset ylabel '%s'\n%s%s",
                      x0, x1, y0, y1, xl, yl, p->spacing[0] == GD_SWEEP_LOG ? "set logscale x\n" : "",
                      p->spacing[1] == GD_SWEEP_LOG ? "set logscale y\n" : "");
    double rh = (1 - 60.0 / H) / rows;
    int row = 0;
    for (int br = 0; br < 3; br++) {
        if (!has[br])
            continue;
        double top = 1 - 60.0 / H - row * rh, bot = top - rh;
        /* the motion: the classes that occur, in the key beside the panel */
        gd_gnuplot_printf(b, "set lmargin at screen 0.075\nset rmargin at screen 0.395\nset tmargin at screen %.4f\n"
                             "set bmargin at screen %.4f\n", top - 40.0 / H, bot + 75.0 / H);
        gd_gnuplot_printf(b, "set title 'motion (%s)'\nset key at screen 0.405,%.4f left top vertical Left reverse samplen 1.2 "
                             "spacing 1.2\nunset colorbox\n", branch_key[br], top - 40.0 / H);
        gd_gnuplot_printf(b, "plot $MAP%d using 1:2:3:4:5:6:7 with boxxyerror fs solid 1.0 noborder lc rgb variable notitle",
                          br);
        for (int k = 0; k < CL_N; k++)
            if (present[k] && row == 0)
                gd_gnuplot_printf(b, ", 1/0 with boxes fs solid 1.0 noborder lc rgb '#%06X' title '%s'", class_rgb[k],
                                  class_name[k]);
        gd_gnuplot_printf(b, "\nunset key\n");
        /* the largest Lyapunov exponent */
        gd_gnuplot_printf(b, "set lmargin at screen 0.62\nset rmargin at screen 0.885\n");
        gd_gnuplot_printf(b, "set title 'largest Lyapunov exponent (%s)'\nset colorbox user origin screen 0.9,%.4f "
                             "size screen 0.018,%.4f\nset cbrange [%.6g:%.6g]\nset cbtics %.6g out\n"
                             "set cblabel 'largest Lyapunov exponent (per mesh period)' offset 1.5,0\n"
                             "set palette defined (-1 '#2166AC', -0.5 '#92C5DE', 0 '#F7F7F7', 0.5 '#F4A582', 1 '#B2182B')\n",
                          branch_key[br], bot + 75.0 / H, rh - 115.0 / H, -mle_abs, mle_abs, step);
        gd_gnuplot_printf(b, "plot $MAP%d using 1:2:3:4:5:6:8 with boxxyerror fs solid 1.0 noborder lc palette notitle\n",
                          br);
        row++;
    }
    cli_fig_end(b, 1);
}

/* Draw the pictures; the names drawn join the run's files. */
static gd_status draw(gd_run_dir *out, const gd_case *c, const gd_sweep_plan *p, const gd_sweep_point *pts,
                      gd_error *err)
{
    const char *dir = gd_run_dir_stage(out);
    int has[3] = {0, 0, 0}, mle = 0;
    for (int s = 0; s < p->nslots; s++) {
        has[pts[s].branch] = 1;
        if (pts[s].status == GD_POINT_DONE && isfinite(pts[s].mle_per_period))
            mle = 1;
    }
    gd_gnuplot_script b = {0};
    const char *stem = p->naxes > 1 ? "regime_map" : "bifurcation";
    for (int f = 0; f < 2; f++) {
        if (p->naxes > 1)
            script_map(&b, p, pts, has, f);
        else
            script_bifurcation(&b, c, p, pts, has, mle, f);
    }
    if (b.bad) {
        free(b.p);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the gnuplot script");
    }
    gd_status st = gd_gnuplot_draw(dir, b.p, &stem, 1, err);
    free(b.p);
    static const char *png[] = {"bifurcation.png", "regime_map.png"}, *svg[] = {"bifurcation.svg", "regime_map.svg"};
    if (st == GD_OK) {
        gd_run_dir_add(out, p->naxes > 1 ? png[1] : png[0], NULL);
        gd_run_dir_add(out, p->naxes > 1 ? svg[1] : svg[0], NULL);
    }
    return st;
}

/* ---- the end ---- */

void cli_sweep_pictures(const cli_case_args *a, const gd_case *c, const void *result, gd_run_dir *out,
                        const char **note)
{
    const gd_sweep_outcome *o = result;
    if (gd_gnuplot_wanted(c->plots, note)) {
        gd_error perr = {0};
        if (draw(out, c, &o->plan, o->pts, &perr) != GD_OK && !a->quiet)
            fprintf(stderr, "geardyn: note: pictures not drawn: %s\n", perr.msg);
    }
}

/* Where a point of the summary lines lies: " at key = value unit" and, in a map, the second key; its
 * branch (up, down) unless the points are independent; and whether it is an end of the range
 * (the largest value found there may lie beyond it). */
static void print_where(const gd_sweep_plan *p, const gd_sweep_point *pt)
{
    printf(" at %s = %.6g %s", p->parameter[0], pt->value[0], p->unit[0]);
    if (p->naxes > 1)
        printf(", %s = %.6g %s", p->parameter[1], pt->value[1], p->unit[1]);
    if (pt->branch != GD_BRANCH_INDEPENDENT)
        printf(" (%s branch)", gd_sweep_branch_name(pt->branch));
    int end = 0;
    for (int a = 0; a < p->naxes; a++)
        end |= p->npoints[a] > 1 && (pt->idx[a] == 0 || pt->idx[a] == p->npoints[a] - 1);
    if (end)
        printf(", an end of the swept range: the largest may lie beyond it");
    printf("\n");
}

/* After summary.json: the journal goes; the summary lines. */
static void on_done(void *user, const gd_case *c, const void *result, gd_run_dir *out)
{
    (void)c;
    sweep_cli *s = user;
    const cli_case_args *a = s->a;
    const gd_sweep_outcome *o = result;
    const gd_sweep_plan *p = &o->plan;
    const char *dir = gd_run_dir_path(out);
    double wall = s->wall;
    int threads = s->threads;
    unlink(s->journal);
    if (s->base.note && !a->quiet)
        fprintf(stderr, "geardyn: note: %s\n", s->base.note);
    cli_publish_note(a, out);
    int failed = 0;
    char counts[512] = "";
    const char *seen[24];
    int cnt[24], nseen = 0;
    double lmax = -INFINITY, lmax_at = NAN;
    const gd_sweep_point *rmax = NULL, *dmax = NULL;
    for (int i = 0; i < p->nslots; i++) {
        const gd_sweep_point *pt = &o->pts[i];
        failed += pt->status == GD_POINT_FAILED;
        int k = 0;
        while (k < nseen && strcmp(seen[k], pt->motion) != 0)
            k++;
        if (k == nseen && nseen < 24) {
            seen[nseen] = pt->motion;
            cnt[nseen++] = 0;
        }
        if (k < nseen)
            cnt[k]++;
        if (pt->status == GD_POINT_DONE && (!rmax || pt->rms_accel_mps2[2] > rmax->rms_accel_mps2[2]))
            rmax = pt;
        double dlf = fmax(pt->dynamic_load_factor[0], pt->dynamic_load_factor[1]);
        if (pt->status == GD_POINT_DONE && isfinite(dlf) &&
            (!dmax || dlf > fmax(dmax->dynamic_load_factor[0], dmax->dynamic_load_factor[1])))
            dmax = pt;
        if (pt->status == GD_POINT_DONE && isfinite(pt->mle_per_period) && pt->mle_per_period > lmax)
            lmax = pt->mle_per_period, lmax_at = pt->value[0];
    }
    for (int k = 0; k < nseen; k++) {
        size_t u = strlen(counts);
        snprintf(counts + u, sizeof counts - u, "%s%s %d", k ? ", " : "", seen[k], cnt[k]);
    }
    if (!a->quiet) {
        const char *how = p->mode == GD_SWEEP_INDEPENDENT ? "independent points"
                        : p->direction == GD_SWEEP_BOTH   ? "continuation up and down"
                        : p->direction == GD_SWEEP_UP     ? "continuation up"
                                                          : "continuation down";
        printf("%s: sweep of %s%s%s, %d points (%s) in %.1f s, %d thread%s", dir, p->parameter[0],
               p->naxes > 1 ? " x " : "", p->naxes > 1 ? p->parameter[1] : "", p->nslots, how, wall, threads,
               threads == 1 ? "" : "s");
        if (s->size > 1)
            printf(" x %d ranks", s->size);
        printf("\n  motion: %s\n", counts);
        if (rmax) {
            printf("  largest RMS mesh acceleration %.6g m/s^2", rmax->rms_accel_mps2[2]);
            print_where(p, rmax);
        }
        if (dmax) {
            printf("  largest dynamic load factor %.4g", fmax(dmax->dynamic_load_factor[0], dmax->dynamic_load_factor[1]));
            print_where(p, dmax);
        }
        if (isfinite(lmax))
            printf("  largest Lyapunov exponent %.4g per mesh period at %s = %.6g %s\n", lmax, p->parameter[0],
                   lmax_at, p->unit[0]);
    }
    if (failed)
        fprintf(stderr, "geardyn: note: %d point%s failed (see the error column of sweep.csv)\n", failed,
                failed == 1 ? "" : "s");
}

/* ---- the phases of a sweep ---- */

/* Rank 0 prepares the directory and the journal; the others get what it read. Returns 1 when the
 * sweep can run, else 0 with *rc the exit status. */
static int share_journal(sweep_cli *s, const cli_case_args *a, gd_run_dir *out, char **text, size_t *tlen, int *rc,
                         gd_error *err)
{
    int ok = 1;
    if (s->rank == 0 && prepare(s, a, out, text, tlen, err) != GD_OK) {
        *rc = cli_fail(err);
        ok = 0;
    }
    if (s->size > 1) {
        ok = cli_mpi_bcast_int(ok);
        *rc = cli_mpi_bcast_int(*rc);
        if (ok && cli_mpi_bcast_text(text, tlen) != 0) {
            fprintf(stderr, "geardyn: rank %d: MPI broadcast of the journal failed\n", s->rank);
            cli_mpi_abort(1);
        }
        if (ok && s->rank != 0 && load_text(s, *text, *tlen, err) != GD_OK) {
            fprintf(stderr, "geardyn: rank %d: %s\n", s->rank, err->msg);
            cli_mpi_abort(1);
        }
    }
    return ok;
}

/* Under MPI after this rank's points (status st): the other ranks report to rank 0, which
 * journals their records until every rank is done. */
static void gather_ranks(sweep_cli *s, gd_status st, const gd_error *err)
{
    if (s->size > 1 && s->rank != 0) {
        int status = st == GD_OK ? 0 : st == GD_ERR_INTERRUPTED ? 1 : 2;
        cli_mpi_send_done(status, st == GD_OK ? "" : err->msg);
    } else if (s->size > 1) {
        if (st != GD_OK && st != GD_ERR_INTERRUPTED) {
            if (s->progress)
                fputc('\n', stderr);
            fprintf(stderr, "geardyn: %s; the finished points are kept: run again with --resume\n", err->msg);
            cli_mpi_abort(1);
        }
        cli_mpi_handlers h = {on_remote_record, on_remote_done, s};
        while (s->ranks_done < s->size - 1) {
            pthread_mutex_lock(&s->io);
            int prc = cli_mpi_poll(1, &h);
            pthread_mutex_unlock(&s->io);
            if (prc) {
                if (s->progress)
                    fputc('\n', stderr);
                fprintf(stderr, "geardyn: %s; the finished points are kept: run again with --resume\n",
                        s->fatal_err.msg);
                cli_mpi_abort(1);
            }
        }
    }
}

/* Rank 0 when points are pending (status st of this rank): why, and the exit status. */
static int conclude(sweep_cli *s, int pending, gd_status st, const gd_error *err)
{
    const gd_sweep_plan *plan = s->p;
    int sig = cli_signal_caught();
    if (sig || st == GD_ERR_INTERRUPTED || s->remote_interrupted) {
        fprintf(stderr, "geardyn: sweep interrupted%s%s%s: %d of %d points done and kept in %s; run the same "
                        "command with --resume to finish it\n",
                sig ? " (" : "", sig ? cli_signal_name(sig) : "", sig ? ")" : "", plan->nslots - pending,
                plan->nslots, s->journal);
        return sig ? 128 + sig : 1;
    }
    if (st != GD_OK || s->remote_failed) {
        fprintf(stderr, "geardyn: %s; %d of %d points done and kept: run again with --resume\n",
                st != GD_OK ? err->msg : s->remote_msg, plan->nslots - pending, plan->nslots);
        return st != GD_OK ? gd_status_exit_code(st) : 1;
    }
    fprintf(stderr, "geardyn: internal error: %d points were not run\n", pending);
    return 1;
}

/* Once the points exist: rank 0 prepares the directory and the journal (and reads it back with
 * --resume), the others get what it read; the clock starts. */
static gd_status on_start(void *user, const gd_sweep_plan *p, gd_sweep_point *pts, gd_run_dir *out, gd_error *err)
{
    sweep_cli *s = user;
    s->p = p;
    s->pts = pts;
    s->total = p->nslots;
    if (!share_journal(s, s->a, out, &s->text, &s->tlen, &s->rc, err)) {
        s->decided = 1; /* rank 0 said why */
        return GD_ERR_INTERRUPTED;
    }
    s->done = s->done_at_start = p->nslots - gd_sweep_pending(p, pts);
    s->progress = s->rank == 0 && !s->a->quiet && isatty(2);
    s->t0 = now();
    progress_line(s, 0);
    return GD_OK;
}

/* After this rank's points: the ranks gathered. The files are written (the
 * row goes on) only on rank 0 with every point done; otherwise the exit status is decided here. */
static gd_status on_end(void *user, const gd_sweep_plan *p, const gd_sweep_point *pts, gd_status st, gd_error *err)
{
    sweep_cli *s = user;
    gather_ranks(s, st, err);
    s->wall = now() - s->t0;
    s->decided = 1;
    if (s->rank != 0)
        return GD_ERR_INTERRUPTED; /* rank 0 writes; the exit status comes from it */
    progress_line(s, 1);
    if (s->fd >= 0)
        close(s->fd);
    s->fd = -1;
    int pending = gd_sweep_pending(p, pts);
    if (pending) {
        s->rc = conclude(s, pending, st, err);
        return st != GD_OK ? st : GD_ERR_INTERRUPTED;
    }
    s->decided = 0; /* the files: any failure from here is reported as usual */
    return GD_OK;
}

/* The sweep's part of the environment: threads (per rank under MPI), this rank, the callbacks. */
static void sweep_env(sweep_cli *s, const cli_case_args *a, gd_run_env *env)
{
    env->threads = a->threads;
    if (s->size > 1 && a->threads == 0 && !getenv("OMP_NUM_THREADS")) {
        long np = sysconf(_SC_NPROCESSORS_ONLN) / cli_mpi_local_size();
        env->threads = np > 1 ? (int)np : 1;
    }
    if (s->size > 1 && !cli_mpi_threads_ok())
        env->threads = 1;
    env->rank = s->rank;
    env->nranks = s->size;
    env->sweep_start = on_start;
    env->sweep_point = on_point;
    env->should_stop = should_stop;
    env->sweep_end = on_end;
    env->done = on_done;
}

int run_sweep(const cli_case_args *a, gd_case *c, const char *dir)
{
    sweep_cli s;
    memset(&s, 0, sizeof s);
    gd_run_env env;
    cli_run_env(&s.base, a, &env); /* env.user: &s.base, which is &s */
    s.a = a;
    s.rank = cli_mpi_rank();
    s.size = cli_mpi_size();
    s.fd = -1;
    pthread_mutex_init(&s.io, NULL);
    sweep_env(&s, a, &env);
    s.threads = cli_threads(env.threads);
    gd_error err = {0};
    gd_status st = gd_analysis_run_in(gd_analysis_find(GD_ANALYSIS_SWEEP), c, &env, dir, &err);
    int rc = s.decided ? s.rc : st == GD_OK ? 0 : cli_signal_caught() ? cli_interrupted(dir) : cli_fail(&err);
    if (s.size > 1)
        rc = cli_mpi_bcast_int(rc);
    if (s.fd >= 0)
        close(s.fd);
    pthread_mutex_destroy(&s.io);
    free(s.text);
    return rc;
}
