/* GSL's error handler, set off once by the library.
 *
 * GSL's default error handler prints and calls abort(); libgeardyn checks the return code of every
 * GSL call and turns it into a gd_status, so a library user must never get that abort. The handler
 * is process-global. Two ways to set it:
 *
 *  - a constructor (__attribute__((constructor))): runs when the library is loaded, so it changes
 *    the host program's GSL behaviour even if the host never asks the library for anything (a
 *    program that links libgeardyn only to read case files, or a plugin host that loads it), and
 *    before the host's own start-up code;
 *  - gd_gsl_quiet() at the start of the public functions that reach GSL (chosen): the handler
 *    changes only when the library is about to use GSL, i.e. when the host has asked for that work.
 *
 * Polite in one more way: only GSL's default handler (NULL, the one that aborts) is replaced. A host
 * that installed a handler of its own, before or after its first call into the library, keeps it
 * (and with it the responsibility for what it does; the library still checks every return code).
 *
 * It must run before the first GSL call that can fail, in every path. Because it is once per
 * process, it suffices to call it in the public functions that call GSL themselves or create the
 * object that later calls need (any other public function that reaches GSL either goes through one
 * of them or works on such an object): gd_geometry_compute, gd_tooth_init, gd_tooth_init_beam,
 * gd_contact_workspace_alloc, gd_contact_solve, gd_tca_create, gd_model_set_stiffness_table,
 * gd_model_static_state, gd_modal_analyse, gd_sim_create, gd_amplitude_spectrum, gd_opt_run, gd_opt_compare,
 * gd_opt_testfn_init. tests/test_gsl_handler.c checks it. */
#include "gsl_quiet.h"

#include <gsl/gsl_errno.h>
#include <pthread.h>

static pthread_once_t once = PTHREAD_ONCE_INIT;

static void quiet_once(void)
{
    gsl_error_handler_t *prev = gsl_set_error_handler_off();
    if (prev != NULL) /* the host's own handler: give it back */
        gsl_set_error_handler(prev);
}

void gd_gsl_quiet(void)
{
    pthread_once(&once, quiet_once);
}
