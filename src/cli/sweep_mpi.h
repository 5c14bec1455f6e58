/* The MPI side of the command line (src/cli/mpi_sweep.c, built with -Dmpi=enabled), and
 * do-nothing stand-ins when geardyn is built without MPI, so that the callers need no
 * conditionals: one rank, rank 0.
 *
 * MPI is initialised only when the process was started by mpirun/mpiexec (the launcher's
 * environment is present); a plain `geardyn run` of an MPI build stays a serial program. */
#ifndef GD_CLI_SWEEP_MPI_H
#define GD_CLI_SWEEP_MPI_H

#include <stddef.h>

#include "geardyn/gd_version.h"

typedef struct cli_mpi_handlers {
    /* a record (a journal line) from another rank; nonzero: a fatal error on rank 0 */
    int (*record)(void *user, int source, const char *line, size_t len);
    /* a rank has finished its share: status 0 done, 1 interrupted, 2 failed (msg says why) */
    void (*done)(void *user, int source, int status, const char *msg);
    void *user;
} cli_mpi_handlers;

#if GD_HAVE_MPI
/* MPI_Init_thread (serialized) when started by an MPI launcher; 0 or an exit status. */
int cli_mpi_init(int *argc, char ***argv);
void cli_mpi_finalize(void);
int cli_mpi_rank(void);
int cli_mpi_size(void);
/* Ranks on this node (for the default thread count), and whether any thread may call MPI
 * one at a time (MPI_THREAD_SERIALIZED); if not, sweeps run one thread per rank. */
int cli_mpi_local_size(void);
int cli_mpi_threads_ok(void);
/* Rank 0's buffer to every rank (*buf malloc'd on the others). 0 on success. */
int cli_mpi_bcast_text(char **buf, size_t *len);
int cli_mpi_bcast_int(int v);
/* To rank 0: one record; the end of this rank's share. */
int cli_mpi_send_record(const char *line, size_t len);
int cli_mpi_send_done(int status, const char *msg);
/* Rank 0: handle the messages that have arrived; block: wait for at least one. */
int cli_mpi_poll(int block, const cli_mpi_handlers *h);
void cli_mpi_abort(int code);
#else
static inline int cli_mpi_init(int *argc, char ***argv) { (void)argc, (void)argv; return 0; }
static inline void cli_mpi_finalize(void) {}
static inline int cli_mpi_rank(void) { return 0; }
static inline int cli_mpi_size(void) { return 1; }
static inline int cli_mpi_local_size(void) { return 1; }
static inline int cli_mpi_threads_ok(void) { return 1; }
static inline int cli_mpi_bcast_text(char **buf, size_t *len) { (void)buf, (void)len; return 0; }
static inline int cli_mpi_bcast_int(int v) { return v; }
static inline int cli_mpi_send_record(const char *line, size_t len) { (void)line, (void)len; return 0; }
static inline int cli_mpi_send_done(int status, const char *msg) { (void)status, (void)msg; return 0; }
static inline int cli_mpi_poll(int block, const cli_mpi_handlers *h) { (void)block, (void)h; return 0; }
static inline void cli_mpi_abort(int code) { (void)code; }
#endif

#endif
