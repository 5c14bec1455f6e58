/* The one error type of libgeardyn.
 *
 * Every fallible call takes a gd_error* (may be NULL) as its last argument and
 * returns a gd_status. GSL, SUNDIALS and NLopt return codes are translated at the
 * boundary into these codes with a message naming the call. The library never
 * prints and never exits: the caller decides what to do with the message. */
#ifndef GD_ERROR_H
#define GD_ERROR_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(GD_BUILDING_LIB)
#define GD_API __attribute__((visibility("default")))
#else
#define GD_API
#endif

typedef enum gd_status {
    GD_OK = 0,
    GD_ERR_INPUT = 1,     /* bad case file, option or argument: exit status 2 */
    GD_ERR_GEOMETRY = 2,  /* impossible or unsafe gear geometry (also bad input) */
    GD_ERR_NOMEM = 3,
    GD_ERR_IO = 4,        /* reading or writing a file */
    GD_ERR_SOLVER = 5,    /* SUNDIALS failure (step, convergence, root finding) */
    GD_ERR_GSL = 6,       /* GSL failure */
    GD_ERR_NLOPT = 7,     /* NLopt failure */
    GD_ERR_CHATTER = 8,   /* a run of events with no progress in time */
    GD_ERR_PHYSICS = 9,   /* the model leaves its domain (e.g. endless separation at zero load) */
    GD_ERR_INTERNAL = 10, /* a broken invariant: a bug */
    GD_ERR_INTERRUPTED = 11
} gd_status;

#define GD_ERROR_MSG_MAX 1024

typedef struct gd_error {
    gd_status code;
    char msg[GD_ERROR_MSG_MAX];
} gd_error;

/* Record an error (the single place to put a breakpoint on). Returns code.
 * A NULL err is allowed: the code is still returned, and in both cases recorded as this thread's
 * last status (for gd_error_prefix with err NULL). */
GD_API gd_status gd_error_set(gd_error *err, gd_status code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* Prefix the message already in err with more context ("while ...: "); returns err->code. With
 * err NULL there is no message, but the status is kept: the status this thread last recorded with
 * gd_error_set (GD_ERR_INTERNAL when none since gd_error_clear), so that `return gd_error_prefix(err,
 * ...)` right after a failed call returns that call's status whether or not err is NULL. */
GD_API gd_status gd_error_prefix(gd_error *err, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
/* Reset err (may be NULL) to GD_OK and forget this thread's last recorded status. */
GD_API void gd_error_clear(gd_error *err);
GD_API const char *gd_status_name(gd_status code);
/* The command-line exit status for an error code: 2 for bad input, 1 otherwise. */
GD_API int gd_status_exit_code(gd_status code);

/* Free memory the library allocated for the caller (text it returns: "free it"); NULL allowed. */
GD_API void gd_free(void *p);

/* A caller's way to stop a long computation early (a signal, a user's cancel): should_stop(user)
 * is asked between units of work (a contact position, an objective evaluation), possibly from
 * several threads at once; nonzero ends the computation with GD_ERR_INTERRUPTED and no result.
 * should_stop NULL: never stopped. */
typedef struct gd_stop_hook {
    int (*should_stop)(void *user);
    void *user;
} gd_stop_hook;

/* Whether h (may be NULL) asks to stop now. */
static inline int gd_stop_asked(const gd_stop_hook *h)
{
    return h && h->should_stop && h->should_stop(h->user) != 0;
}

#ifdef __cplusplus
}
#endif
#endif
