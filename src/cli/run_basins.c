/* The `basins` analysis on the command line: the progress line, signals, the parameter's values spread
 * over MPI ranks (each rank maps its values, rank 0 gathers their points as records, matches the
 * attractors over the values and writes the files: the same files as one process) and the lines
 * on stdout; the pictures are the library's (src/plot/plot_basins.c). */
#include "cli.h"
#include "sweep_mpi.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

typedef struct basins_cli {
    cli_progress base;       /* first: the user of the common hooks (cli_run_env) */
    const cli_case_args *a;
    int rank, size;
    double t0, last;
    int ranks_done, remote_interrupted, remote_failed, bad_record;
    char remote_msg[1200];
    gd_basins_result *res;   /* rank 0 while it gathers */
    gd_error rec_err;
    int decided, rc;
} basins_cli;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int on_progress(void *user, long done, long total)
{
    basins_cli *s = user;
    if (cli_signal_caught())
        return 1;
    if (!s->base.tty || s->rank != 0)
        return 0;
    double t = now();
    if (done < total && t - s->last < 0.25)
        return 0;
    s->last = t;
    double el = t - s->t0, rate = el > 0 ? (double)done / el : 0;
    char eta[64] = "";
    if (done < total && rate > 0) {
        double sec = (double)(total - done) / rate;
        snprintf(eta, sizeof eta, sec < 90 ? ", %.0f s left" : ", %.0f min left", sec < 90 ? sec : sec / 60);
    }
    fprintf(stderr, "\rgeardyn: basins %ld/%ld initial states (%ld%%), %.3g per s%s   %s", done, total,
            total ? done * 100 / total : 100, rate, eta, done == total ? "\n" : "");
    fflush(stderr);
    return 0;
}

void cli_basins_after_run(const cli_progress *p, gd_status st)
{
    if (p->tty && st != GD_OK)
        fputc('\n', stderr);
}

/* ---- MPI: the points of the other ranks ---- */

static int on_record(void *user, int source, const char *line, size_t len)
{
    basins_cli *s = user;
    if (gd_basins_record_parse(s->res, line, len, &s->rec_err) != GD_OK) {
        s->bad_record = 1;
        snprintf(s->remote_msg, sizeof s->remote_msg, "rank %d sent a bad record: %s", source, s->rec_err.msg);
        return 1;
    }
    return 0;
}

static void on_rank_done(void *user, int source, int status, const char *msg)
{
    basins_cli *s = user;
    s->ranks_done++;
    if (status == 1)
        s->remote_interrupted = 1;
    if (status == 2 && !s->remote_failed) {
        s->remote_failed = 1;
        snprintf(s->remote_msg, sizeof s->remote_msg, "rank %d: %s", source, msg);
    }
}

static gd_status on_end(void *user, gd_basins_result *res, gd_status st, gd_error *err)
{
    basins_cli *s = user;
    if (s->rank != 0) {
        for (int k = 0; st == GD_OK && k < res->npoints; k++) {
            if (!res->pt[k].done)
                continue;
            char *line;
            size_t len;
            st = gd_basins_record_format(res, k, &line, &len, err);
            if (st == GD_OK && cli_mpi_send_record(line, len) != 0)
                st = gd_error_set(err, GD_ERR_IO, "MPI: cannot send a value's basins to rank 0");
            free(line);
        }
        cli_mpi_send_done(st == GD_OK ? 0 : st == GD_ERR_INTERRUPTED ? 1 : 2, st == GD_OK ? "" : err->msg);
        s->decided = 1; /* rank 0 writes; the exit status comes from it */
        return GD_ERR_INTERRUPTED;
    }
    if (st != GD_OK && st != GD_ERR_INTERRUPTED) {
        fprintf(stderr, "geardyn: %s\n", err->msg);
        cli_mpi_abort(1);
    }
    s->res = res;
    cli_mpi_handlers h = {on_record, on_rank_done, s};
    while (s->ranks_done < s->size - 1)
        if (cli_mpi_poll(1, &h)) {
            fprintf(stderr, "geardyn: %s\n", s->remote_msg);
            cli_mpi_abort(1);
        }
    if (st != GD_OK)
        return st;
    if (s->remote_interrupted || cli_signal_caught())
        return gd_error_set(err, GD_ERR_INTERRUPTED, "interrupted");
    if (s->remote_failed)
        return gd_error_set(err, GD_ERR_SOLVER, "%s", s->remote_msg);
    return GD_OK;
}

/* ---- lines ---- */

void cli_basins_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    const gd_basins_result *res = result;
    if (a->quiet)
        return;
    long periods = 0;
    double cpu = 0;
    for (int k = 0; k < res->npoints; k++)
        periods += res->pt[k].periods, cpu += res->pt[k].cpu_s;
    printf("%s: basins in (%s, %s) at mesh phase %g deg%s%s: %ld mesh periods, %.1f s (%.1f s CPU), %d thread%s\n", dir,
           res->coord[0], res->coord[1], res->phase_deg, res->parameter[0] ? ", over " : "", res->parameter,
           periods, res->wall_s, cpu, res->threads, res->threads == 1 ? "" : "s");
    for (int k = 0; k < res->npoints; k++) {
        const gd_basins_point *p = &res->pt[k];
        if (res->parameter[0])
            printf("  %s = %.6g %s:\n", res->parameter, p->value, res->unit);
        for (int t = 0; t < p->natt; t++) {
            const gd_attractor *at = &p->att[t];
            printf("    attractor %d: %s", p->id[t], at->name);
            if (at->impact_regime >= 0)
                printf(", %s", gd_impact_regime_name(at->impact_regime));
            if (at->kind == GD_ATT_PERIODIC)
                printf(", |mu_max| %.4f", at->orbit.mu_max);
            else
                printf(", largest Lyapunov exponent %.4g per mesh period", at->mle_per_period);
            if (c->bas_samples > 0) {
                gd_basin_fraction f;
                gd_basins_fraction(res, k, t, &f);
                printf(": fraction %.4f +- %.4f (Wilson %.4f to %.4f)", f.p, f.se, f.wilson_lo, f.wilson_hi);
            }
            printf("%s\n", at->seeded ? " (found from a seed only)" : "");
        }
        for (int l = -1; l >= -GD_BASIN_NSPECIAL && c->bas_samples > 0; l--)
            if (p->special[-l - 1])
                printf("    %s: %ld of %ld\n", gd_basin_label_name(l), p->special[-l - 1], p->samples);
        for (int r = 0; r < p->norbits && !res->parameter[0]; r++)
            printf("    continuation's orbit, branch %d, period %d, %s (|mu_max| %.4f), at (%.6g, %.6g)\n",
                   p->orbits[r].branch, p->orbits[r].period, p->orbits[r].stable ? "stable" : "unstable",
                   p->orbits[r].mu_max, p->orbits[r].u[0], p->orbits[r].v[0]);
    }
    if (res->grid)
        printf("  picture %d x %d: basin entropy S_b %.4f, boundary basin entropy S_bb %.4f (%s ln 2 = 0.6931: %s)\n",
               res->nx, res->ny, res->entropy.sb, res->entropy.sbb, res->entropy.fractal ? ">" : "<=",
               res->entropy.fractal ? "fractal boundary" : "no evidence of a fractal boundary");
    for (int i = 0; i < res->nnotes; i++)
        printf("  note: %s\n", res->notes[i]);
}

int run_basins(const cli_case_args *a, gd_case *c, const char *dir)
{
    basins_cli s;
    memset(&s, 0, sizeof s);
    gd_run_env env;
    cli_run_env(&s.base, a, &env); /* env.user: &s.base, which is &s */
    s.a = a;
    s.rank = cli_mpi_rank();
    s.size = cli_mpi_size();
    s.t0 = now();
    if (s.size > 1 && !c->bas_parameter[0]) { /* one value: rank 0 maps it all */
        int rc = 0;
        if (s.rank == 0) {
            gd_error err = {0};
            env.basins_progress = on_progress;
            gd_status st = gd_analysis_run_in(gd_analysis_find(GD_ANALYSIS_BASINS), c, &env, dir, &err);
            rc = st == GD_OK ? 0 : cli_signal_caught() ? cli_interrupted(dir) : cli_fail(&err);
        }
        return cli_mpi_bcast_int(rc);
    }
    env.threads = a->threads;
    if (s.size > 1 && a->threads == 0 && !getenv("OMP_NUM_THREADS")) {
        long np = sysconf(_SC_NPROCESSORS_ONLN) / cli_mpi_local_size();
        env.threads = np > 1 ? (int)np : 1;
    }
    if (s.size > 1 && !cli_mpi_threads_ok())
        env.threads = 1;
    env.rank = s.rank;
    env.nranks = s.size;
    env.basins_progress = on_progress;
    env.basins_end = s.size > 1 ? on_end : NULL;
    gd_error err = {0};
    gd_status st = gd_analysis_run_in(gd_analysis_find(GD_ANALYSIS_BASINS), c, &env, dir, &err);
    int rc = s.decided ? s.rc : st == GD_OK ? 0 : cli_signal_caught() ? cli_interrupted(dir) : cli_fail(&err);
    if (s.size > 1)
        rc = cli_mpi_bcast_int(rc);
    return rc;
}
