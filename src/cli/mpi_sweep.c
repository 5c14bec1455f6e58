/* MPI for the command line (built with -Dmpi=enabled): start-up, and the messages of a
 * distributed sweep. Every rank computes its share of the work units; each finished point
 * travels to rank 0 as its journal record, as soon as it is finished; rank 0 journals it
 * and writes the final files. */
#include "sweep_mpi.h"

#include <limits.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { TAG_RECORD = 701, TAG_DONE = 702 };

static int g_on = 0, g_rank = 0, g_size = 1, g_local = 1, g_threads_ok = 1;

int cli_mpi_init(int *argc, char ***argv)
{
    static const char *vars[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE", "MPI_LOCALNRANKS"};
    int launched = 0;
    for (size_t i = 0; i < sizeof vars / sizeof vars[0]; i++)
        launched |= getenv(vars[i]) != NULL;
    if (!launched)
        return 0;
    int provided = MPI_THREAD_SINGLE;
    if (MPI_Init_thread(argc, argv, MPI_THREAD_SERIALIZED, &provided) != MPI_SUCCESS) {
        fprintf(stderr, "geardyn: MPI_Init_thread failed\n");
        return 1;
    }
    g_on = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &g_size);
    g_threads_ok = provided >= MPI_THREAD_SERIALIZED;
    const char *ls = getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
    if (!ls)
        ls = getenv("MPI_LOCALNRANKS");
    g_local = ls ? atoi(ls) : 1;
    if (g_local < 1)
        g_local = 1;
    return 0;
}

void cli_mpi_finalize(void)
{
    if (g_on) {
        g_on = 0;
        MPI_Finalize();
    }
}

int cli_mpi_rank(void) { return g_rank; }
int cli_mpi_size(void) { return g_size; }
int cli_mpi_local_size(void) { return g_local; }
int cli_mpi_threads_ok(void) { return g_threads_ok; }

int cli_mpi_bcast_text(char **buf, size_t *len)
{
    if (!g_on || g_size == 1)
        return 0;
    unsigned long long n = g_rank == 0 ? (unsigned long long)*len : 0;
    if (MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD) != MPI_SUCCESS)
        return 1;
    if (g_rank != 0) {
        *buf = malloc((size_t)n + 1);
        if (!*buf)
            return 1;
        *len = (size_t)n;
    }
    for (unsigned long long off = 0; off < n;) {
        int chunk = n - off > (unsigned long long)(INT_MAX / 2) ? INT_MAX / 2 : (int)(n - off);
        if (MPI_Bcast(*buf + off, chunk, MPI_CHAR, 0, MPI_COMM_WORLD) != MPI_SUCCESS)
            return 1;
        off += (unsigned long long)chunk;
    }
    (*buf)[n] = '\0';
    return 0;
}

int cli_mpi_bcast_int(int v)
{
    if (!g_on || g_size == 1)
        return v;
    MPI_Bcast(&v, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return v;
}

int cli_mpi_send_record(const char *line, size_t len)
{
    if (len > (size_t)INT_MAX)
        return 1;
    return MPI_Send(line, (int)len, MPI_CHAR, 0, TAG_RECORD, MPI_COMM_WORLD) != MPI_SUCCESS;
}

int cli_mpi_send_done(int status, const char *msg)
{
    char buf[1200];
    snprintf(buf, sizeof buf, "%d %s", status, msg ? msg : "");
    return MPI_Send(buf, (int)strlen(buf) + 1, MPI_CHAR, 0, TAG_DONE, MPI_COMM_WORLD) != MPI_SUCCESS;
}

int cli_mpi_poll(int block, const cli_mpi_handlers *h)
{
    if (!g_on || g_size == 1)
        return 0;
    for (int first = 1;; first = 0) {
        MPI_Status s;
        int flag = 0;
        if (block && first) {
            MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &s);
            flag = 1;
        } else {
            MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &s);
        }
        if (!flag)
            return 0;
        int cnt = 0;
        MPI_Get_count(&s, MPI_CHAR, &cnt);
        char *buf = malloc((size_t)cnt + 1);
        if (!buf)
            return 1;
        MPI_Recv(buf, cnt, MPI_CHAR, s.MPI_SOURCE, s.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        buf[cnt] = '\0';
        int rc = 0;
        if (s.MPI_TAG == TAG_RECORD) {
            rc = h->record(h->user, s.MPI_SOURCE, buf, (size_t)cnt);
        } else if (s.MPI_TAG == TAG_DONE) {
            int status = atoi(buf);
            const char *msg = strchr(buf, ' ');
            h->done(h->user, s.MPI_SOURCE, status, msg ? msg + 1 : "");
        }
        free(buf);
        if (rc)
            return rc;
    }
}

void cli_mpi_abort(int code)
{
    if (g_on)
        MPI_Abort(MPI_COMM_WORLD, code);
    exit(code);
}
