/* The `sweep` analysis on the command line: the journal and --resume, signals, the progress
 * line, MPI ranks and the final files (the pictures are the library's: src/plot/plot_sweep.c).
 *
 * The journal (DIR/.sweep.journal) is the library's (gd_sweep_journal, src/output/sweep_journal.c):
 * a header naming the sweep, then one checksummed record per finished point, appended and synced
 * as the point finishes; --resume reads it back and runs only the points it lacks. Here rank 0
 * appends the records of the other MPI ranks to it. At the end the final files are written
 * atomically from all the points in slot order and the journal is removed, so an interrupted and
 * resumed sweep gives the same files as an uninterrupted one, whatever the number of threads or
 * ranks. */
#include "cli.h"
#include "sweep_mpi.h"

#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>




typedef struct sweep_cli {
    cli_progress base;       /* first: the user of the common hooks (cli_run_env) */
    const cli_case_args *a;
    const gd_sweep_plan *p;
    gd_sweep_point *pts;
    int rank, size;
    gd_sweep_journal *jr;    /* the journal, rank 0 (the library's: gd_sweep_journal_open) */
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
    if (gd_sweep_journal_append(s->jr, line, len, &e) != GD_OK) {
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
        st = gd_sweep_journal_append(s->jr, line, len, err);
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

/* Rank 0: the output directory and the journal (read back with --resume, else new: the library's,
 * gd_sweep_journal_open); *text a copy of it for the other ranks. */
static gd_status prepare(sweep_cli *s, const cli_case_args *a, gd_run_dir *out, char **text, size_t *tlen,
                         gd_error *err)
{
    gd_status st = gd_sweep_journal_open(out, s->p, s->pts, a->resume, &s->jr, err);
    if (st != GD_OK)
        return st;
    snprintf(s->journal, sizeof s->journal, "%s", gd_sweep_journal_path(s->jr));
    const char *note = gd_sweep_journal_note(s->jr);
    if (note[0] && !a->quiet)
        fprintf(stderr, "geardyn: %s\n", note);
    const char *t = gd_sweep_journal_text(s->jr, tlen);
    if (!(*text = malloc(*tlen + 1)))
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    memcpy(*text, t, *tlen);
    (*text)[*tlen] = '\0';
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


/* ---- the end ---- */


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
    if (s->base.note[0] && !a->quiet)
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
    gd_sweep_journal_close(s->jr, 0); /* kept: removed once the files are published (on_done) */
    s->jr = NULL;
    int pending = gd_sweep_pending(p, pts);
    if (pending) {
        s->rc = conclude(s, pending, st, err);
        return st != GD_OK ? st : GD_ERR_INTERRUPTED;
    }
    s->decided = 0; /* the files: any failure from here is reported as usual */
    return GD_OK;
}

/* The notes of the pictures, as cli_note, but a sweep's pictures not drawn are said unless --quiet. */
static void on_note(void *user, int kind, const char *text)
{
    sweep_cli *s = user;
    if (kind == GD_NOTE_NO_PICTURES || !s->a->quiet)
        cli_note(user, kind, text);
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
    env->note = on_note;
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
    pthread_mutex_init(&s.io, NULL);
    sweep_env(&s, a, &env);
    s.threads = cli_threads(env.threads);
    gd_error err = {0};
    gd_status st = gd_analysis_run_in(gd_analysis_find(GD_ANALYSIS_SWEEP), c, &env, dir, &err);
    int rc = s.decided ? s.rc : st == GD_OK ? 0 : cli_signal_caught() ? cli_interrupted(dir) : cli_fail(&err);
    if (s.size > 1)
        rc = cli_mpi_bcast_int(rc);
    gd_sweep_journal_close(s.jr, 0);
    pthread_mutex_destroy(&s.io);
    free(s.text);
    return rc;
}
