/* The error type (gd_error.h):
 *  1. gd_error_set records code and message, and returns the code, with or without a gd_error;
 *  2. gd_error_prefix keeps the status: with a gd_error its code and "prefix: message"; with NULL
 *     the status this thread last recorded (GD_ERR_INTERNAL when nothing was recorded since
 *     gd_error_clear), so that `return gd_error_prefix(err, ...)` after a failed call returns
 *     that call's status either way;
 *  3. the last status is per thread;
 *  4. messages truncated at GD_ERROR_MSG_MAX stay NUL-terminated, prefixed or not. */
#include "geardyn/gd_error.h"
#include "tap.h"

#include <pthread.h>
#include <string.h>

/* a library-style call chain: the inner call fails, the outer one prefixes and returns */
static gd_status inner(gd_error *err, gd_status code) { return gd_error_set(err, code, "cannot open %s", "x.csv"); }
static gd_status outer(gd_error *err, gd_status code)
{
    gd_status st = inner(err, code);
    if (st != GD_OK)
        return gd_error_prefix(err, "writing the %s", "tables");
    return GD_OK;
}

static void *other_thread(void *arg)
{
    (void)arg;
    static gd_status seen[2];
    seen[0] = gd_error_prefix(NULL, "fresh thread"); /* nothing recorded in this thread */
    gd_error_set(NULL, GD_ERR_SOLVER, "solver");
    seen[1] = gd_error_prefix(NULL, "after a solver failure");
    return seen;
}

int main(void)
{
    /* 1. set */
    gd_error e = {0};
    tap_ok(gd_error_set(&e, GD_ERR_GEOMETRY, "bad %d", 7) == GD_ERR_GEOMETRY && e.code == GD_ERR_GEOMETRY &&
               strcmp(e.msg, "bad 7") == 0,
           "gd_error_set: returns and records the code and the message (\"%s\")", e.msg);
    tap_ok(gd_error_set(NULL, GD_ERR_NOMEM, "x") == GD_ERR_NOMEM, "gd_error_set(NULL, ...) returns the code");

    /* 2. prefix with a gd_error */
    gd_error_clear(&e);
    tap_ok(e.code == GD_OK && e.msg[0] == '\0', "gd_error_clear: GD_OK and an empty message");
    gd_status st = outer(&e, GD_ERR_IO);
    tap_ok(st == GD_ERR_IO && e.code == GD_ERR_IO, "prefix with a gd_error: the code is kept (%s)", gd_status_name(st));
    tap_ok(strcmp(e.msg, "writing the tables: cannot open x.csv") == 0, "prefix with a gd_error: \"prefix: message\" (\"%s\")",
           e.msg);
    gd_error_prefix(&e, "run %d", 2);
    tap_ok(strcmp(e.msg, "run 2: writing the tables: cannot open x.csv") == 0 && e.code == GD_ERR_IO,
           "prefixes nest, outermost first (\"%s\")", e.msg);

    /* 2. prefix without a gd_error: the status of the error being prefixed */
    gd_error_set(NULL, GD_ERR_IO, "cannot write");
    tap_ok(gd_error_prefix(NULL, "while %s", "writing") == GD_ERR_IO,
           "gd_error_set(NULL, GD_ERR_IO) then gd_error_prefix(NULL) returns GD_ERR_IO");
    tap_ok(outer(NULL, GD_ERR_GSL) == GD_ERR_GSL, "a call chain with err NULL returns the inner status (GSL failure)");
    tap_ok(outer(NULL, GD_ERR_PHYSICS) == GD_ERR_PHYSICS, "... and the next failure its own (outside the physics)");
    gd_error_set(&e, GD_ERR_NLOPT, "nlopt");
    tap_ok(gd_error_prefix(NULL, "p") == GD_ERR_NLOPT, "a status recorded into a gd_error counts too");
    gd_error_clear(NULL);
    tap_ok(gd_error_prefix(NULL, "p") == GD_ERR_INTERNAL,
           "after gd_error_clear nothing is recorded: gd_error_prefix(NULL) is GD_ERR_INTERNAL (a bug: nothing failed)");

    /* 3. per thread */
    gd_error_set(NULL, GD_ERR_INPUT, "input");
    pthread_t th;
    gd_status *seen = NULL;
    if (pthread_create(&th, NULL, other_thread, NULL) == 0 && pthread_join(th, (void **)&seen) == 0 && seen) {
        tap_ok(seen[0] == GD_ERR_INTERNAL && seen[1] == GD_ERR_SOLVER,
               "another thread sees only its own status (%s, then %s)", gd_status_name(seen[0]),
               gd_status_name(seen[1]));
    } else {
        tap_ok(0, "thread");
    }
    tap_ok(gd_error_prefix(NULL, "p") == GD_ERR_INPUT, "and this thread's status is untouched by it");

    /* 4. truncation */
    char big[3 * GD_ERROR_MSG_MAX];
    memset(big, 'a', sizeof big - 1);
    big[sizeof big - 1] = '\0';
    gd_error_set(&e, GD_ERR_INPUT, "%s", big);
    tap_ok(strlen(e.msg) == GD_ERROR_MSG_MAX - 1 && e.msg[GD_ERROR_MSG_MAX - 1] == '\0',
           "a long message is cut at GD_ERROR_MSG_MAX - 1 characters and NUL-terminated (%zu)", strlen(e.msg));
    gd_error_prefix(&e, "context");
    tap_ok(strlen(e.msg) == GD_ERROR_MSG_MAX - 1 && strncmp(e.msg, "context: aaa", 12) == 0,
           "prefixing a full message: the prefix first, cut at the end, NUL-terminated (%zu)", strlen(e.msg));
    gd_error_prefix(&e, "%s", big);
    tap_ok(strlen(e.msg) == GD_ERROR_MSG_MAX - 1 && e.code == GD_ERR_INPUT,
           "a prefix longer than the buffer: still a string of GD_ERROR_MSG_MAX - 1, code kept");
    gd_error junk;
    memset(&junk, 'z', sizeof junk); /* a message never set: no terminating NUL anywhere */
    junk.code = GD_ERR_IO;
    tap_ok(gd_error_prefix(&junk, "p") == GD_ERR_IO && strlen(junk.msg) == GD_ERROR_MSG_MAX - 1,
           "prefixing an unterminated message reads no further than its buffer");
    return tap_done();
}
