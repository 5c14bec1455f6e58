/* GSL's error handler, set off once by the library (internal). */
#ifndef GD_GSL_QUIET_H
#define GD_GSL_QUIET_H

/* Make sure GSL reports errors by return code instead of calling abort(): on the first call in
 * the process, replace GSL's default handler (the one that aborts) by gsl_set_error_handler_off's
 * handler; a handler the host program installed itself is left alone. Thread-safe and cheap after
 * the first call (pthread_once). Every public function that calls GSL itself, or creates an
 * object whose later calls do, calls this first: see gsl_quiet.c for the list. */
__attribute__((visibility("hidden"))) void gd_gsl_quiet(void);

#endif
