/* The error type: recording, prefixing and naming of gd_status codes. */
#include "geardyn/gd_error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* The status of the last error this thread recorded (gd_error_set), so that gd_error_prefix keeps
 * the code when the caller passed no gd_error: `return gd_error_prefix(err, ...)` right after a
 * failed call, err NULL, returns the status that call set. Thread-local: a sweep's threads fail
 * independently. GD_OK: nothing recorded (or cleared by gd_error_clear). */
static _Thread_local gd_status last_status = GD_OK;

GD_API gd_status gd_error_set(gd_error *err, gd_status code, const char *fmt, ...)
{
    last_status = code;
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        err->code = code;
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
    }
    return code;
}

GD_API gd_status gd_error_prefix(gd_error *err, const char *fmt, ...)
{
    if (!err) /* nothing to prefix: the status of the error being prefixed is this thread's last */
        return last_status != GD_OK ? last_status : GD_ERR_INTERNAL;
    char head[GD_ERROR_MSG_MAX], old[GD_ERROR_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(head, sizeof head, fmt, ap);
    va_end(ap);
    memcpy(old, err->msg, sizeof old);
    old[sizeof old - 1] = '\0'; /* a message that filled the buffer stays a string */
    snprintf(err->msg, sizeof err->msg, "%s: %s", head, old);
    return err->code;
}

GD_API void gd_error_clear(gd_error *err)
{
    last_status = GD_OK;
    if (err) {
        err->code = GD_OK;
        err->msg[0] = '\0';
    }
}

GD_API const char *gd_status_name(gd_status code)
{
    switch (code) {
    case GD_OK: return "ok";
    case GD_ERR_INPUT: return "bad input";
    case GD_ERR_GEOMETRY: return "impossible geometry";
    case GD_ERR_NOMEM: return "out of memory";
    case GD_ERR_IO: return "input/output error";
    case GD_ERR_SOLVER: return "solver failure";
    case GD_ERR_GSL: return "GSL failure";
    case GD_ERR_NLOPT: return "NLopt failure";
    case GD_ERR_CHATTER: return "chattering (events without progress)";
    case GD_ERR_PHYSICS: return "outside the model's physics";
    case GD_ERR_INTERNAL: return "internal error";
    case GD_ERR_INTERRUPTED: return "interrupted";
    }
    return "unknown error";
}

GD_API int gd_status_exit_code(gd_status code)
{
    if (code == GD_OK)
        return 0;
    if (code == GD_ERR_INPUT || code == GD_ERR_GEOMETRY)
        return 2;
    return 1;
}
