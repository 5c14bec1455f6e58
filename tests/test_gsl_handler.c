/* The library never lets GSL abort the process (src/core/gsl_quiet.c):
 *  1. a GSL error inside a library call comes back as a gd_status: gd_tooth_init_beam on an empty
 *     tooth (root = tip) makes gsl_spline_init signal "x values must be strictly increasing",
 *     which GSL's default handler turns into abort(); the library returns GD_ERR_GSL instead;
 *  2. each public function that reaches GSL first (gsl_quiet.c has the list), called first in a
 *     fresh process with GSL's default handler, leaves gsl_set_error_handler_off's handler set;
 *  3. a handler the host program installed itself is kept, and still sees the library's GSL
 *     errors (the library still gets the status back).
 * The handler is set once per process, so every check runs in a child of its own (fork) that
 * reports through its exit status: a child killed by SIGABRT is GSL's abort. */
#include "geardyn/gd_analysis.h"
#include "pair_util.h"
#include "geardyn/gd_compliance.h"
#include "geardyn/gd_contact.h"
#include "geardyn/gd_geometry.h"
#include "geardyn/gd_modal.h"
#include "geardyn/gd_model.h"
#include "geardyn/gd_optimize.h"
#include "geardyn/gd_sim.h"
#include "geardyn/gd_spectrum.h"
#include "geardyn/gd_tca.h"
#include "tap.h"

#include <gsl/gsl_errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* gsl_set_error_handler_off's handler (GSL does not name it): set it, read it back, restore */
static gsl_error_handler_t *gsl_off_handler(void)
{
    gsl_error_handler_t *was = gsl_set_error_handler_off();
    return gsl_set_error_handler(was);
}

static gsl_error_handler_t *current_handler(void)
{
    gsl_error_handler_t *h = gsl_set_error_handler(NULL);
    gsl_set_error_handler(h);
    return h;
}

/* run f in a child; its exit status 0 is success, anything else is described */
static void in_child(int (*f)(void), const char *what)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid < 0) {
        tap_ok(0, "%s: fork failed", what);
        return;
    }
    if (pid == 0) {
        int rc = f();
        fflush(stdout);
        _exit(rc);
    }
    int ws = 0;
    waitpid(pid, &ws, 0);
    if (WIFSIGNALED(ws))
        tap_ok(0, "%s: the process died of signal %d%s", what, WTERMSIG(ws),
               WTERMSIG(ws) == SIGABRT ? " (SIGABRT: GSL's default handler)" : "");
    else
        tap_ok(WIFEXITED(ws) && WEXITSTATUS(ws) == 0, "%s%s", what,
               WEXITSTATUS(ws) == 0 ? "" : WEXITSTATUS(ws) == 2 ? ": the call failed" : ": GSL's handler is not off");
}

/* ---- 1. a GSL error returns a status ------------------------------------------------------ */

static int bad_tooth(void)
{
    gsl_set_error_handler(NULL); /* GSL's default: print and abort */
    gd_tooth t;
    gd_error e = {0};
    gd_status st = gd_tooth_init_beam(&t, 210e9, 0.3, 0.01, 0.01, 0.002, &e); /* root = tip */
    printf("# empty tooth: %s (%s)\n", gd_status_name(st), e.msg);
    if (st == GD_OK)
        return 3;
    /* and again: once off, it stays off */
    st = gd_tooth_init_beam(&t, 210e9, 0.3, 0.02, 0.01, 0.002, &e); /* tip below the root */
    return st != GD_OK && st == e.code ? 0 : 3;
}

/* ---- 2. the entry points ------------------------------------------------------------------ */

static int handler_is_off(gd_status st, const gd_error *e)
{
    if (st != GD_OK) {
        printf("# %s\n", e->msg);
        return 2;
    }
    return current_handler() == gsl_off_handler() ? 0 : 1;
}

static int ep_tooth_beam(void)
{
    gd_tooth t;
    gd_error e = {0};
    gd_status st = gd_tooth_init_beam(&t, 210e9, 0.3, 0.0, 0.01, 0.002, &e);
    int rc = handler_is_off(st, &e);
    if (st == GD_OK)
        gd_tooth_free(&t);
    return rc;
}

static int ep_geometry(void)
{
    gd_case c;
    gd_geometry g;
    gd_error e = {0};
    gd_status st = gd_case_init(&c, &e);
    if (st == GD_OK)
        st = gd_geometry_compute(PAIR_OF(&c), &g, &e);
    gd_case_free(&c);
    return handler_is_off(st, &e);
}

static int ep_case_resolve(void)
{
    gd_case c;
    gd_error e = {0};
    gd_status st = gd_case_init(&c, &e);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    if (st == GD_OK)
        st = gd_case_resolve(&c, &e);
    gd_case_free(&c);
    return handler_is_off(st, &e);
}

static int ep_tca_create(void)
{
    gd_case c;
    gd_tca *t = NULL;
    gd_error e = {0};
    gd_status st = gd_case_init(&c, &e);
    if (st == GD_OK)
        st = gd_case_set(&c, "scene.analysis=tca", 0, &e);
    if (st == GD_OK)
        st = gd_tca_create(PAIR_OF(&c), TCA_SET_OF(&c), &t, &e);
    int rc = handler_is_off(st, &e);
    gd_tca_free(t);
    gd_case_free(&c);
    return rc;
}

static int ep_contact_workspace(void)
{
    gd_contact_workspace *ws = NULL;
    gd_error e = {0};
    gd_status st = gd_contact_workspace_alloc(4, 1, &ws, &e);
    int rc = handler_is_off(st, &e);
    gd_contact_workspace_free(ws);
    return rc;
}

static int ep_spectrum(void)
{
    double x[8] = {0, 1, 0, -1, 0, 1, 0, -1}, f[5], a[5];
    gd_error e = {0};
    return handler_is_off(gd_amplitude_spectrum(x, 8, 0.1, f, a, &e), &e);
}

static void decay(double t, const double *y, double *ydot, void *ctx)
{
    (void)t, (void)ctx;
    ydot[0] = -y[0];
}
static void decay_tangent(double t, const double *y, const double *v, double *out, void *ctx)
{
    (void)t, (void)y, (void)ctx;
    out[0] = -v[0];
}

static int ep_sim_create(void)
{
    gd_custom_system sys = {1, decay, decay_tangent, NULL, NULL};
    gd_model m;
    gd_model_custom(&m, &sys, 1.0);
    gd_solver_opts o;
    memset(&o, 0, sizeof o);
    o.method = GD_METHOD_ERK;
    o.order = 5;
    o.rtol = 1e-8;
    o.atol = 1e-10;
    o.max_step_fraction = 1.0;
    o.max_events_per_period = 10;
    o.max_separated_periods = 10;
    o.n_tangent = 1;
    double y0[1] = {1.0};
    gd_modes md = {0};
    gd_sim *s = NULL;
    gd_error e = {0};
    gd_status st = gd_sim_create(&m, &o, y0, &md, &s, &e);
    int rc = handler_is_off(st, &e);
    gd_sim_free(s);
    return rc;
}

static int ep_modal(void)
{
    gd_model m; /* one mass on one spring, built by hand: no other library call reaches GSL first */
    memset(&m, 0, sizeof m);
    m.ndof = 1;
    m.n = 2;
    m.mass[0] = m.inv_mass[0] = m.omega_n = 1.0;
    m.nk = 1;
    m.K0[0] = (gd_nz){0, 0, 4.0};
    gd_modes md = {0};
    gd_modal out;
    gd_error e = {0};
    return handler_is_off(gd_modal_analyse(&m, &md, NULL, &out, &e), &e);
}

static int ep_testfn(void)
{
    gd_opt_testfn t;
    gd_error e = {0};
    gd_status st = gd_opt_testfn_init(&t, GD_OBJ_SPHERE, 2, 0.5, 7, &e);
    int rc = handler_is_off(st, &e);
    if (st == GD_OK)
        gd_opt_testfn_free(&t);
    return rc;
}

static gd_status sphere(void *state, const double *y, double *f, gd_error *err)
{
    (void)state, (void)err;
    *f = y[0] * y[0] + y[1] * y[1];
    return GD_OK;
}
static const double lo[2] = {-1, -1}, hi[2] = {1, 1};
static const gd_opt_problem problem = {.dim = 2, .lower = lo, .upper = hi, .eval = sphere};

static int ep_opt_run(void)
{
    gd_opt_settings s;
    gd_opt_settings_default(&s);
    s.algorithm = GD_OPT_ALO;
    s.budget = 40;
    s.population = 4;
    s.threads = 1;
    gd_opt_result r;
    gd_error e = {0};
    gd_status st = gd_opt_run(&problem, &s, &r, &e);
    int rc = handler_is_off(st, &e);
    if (st == GD_OK)
        gd_opt_result_free(&r);
    return rc;
}

static int ep_opt_compare(void)
{
    gd_opt_compare_settings s = {.nalgs = 1, .algs = {GD_OPT_ALO}, .runs = 1, .seed = 1, .budget = 40,
                                 .population = 4, .f_ref = 0.0, .target = 1e-3, .target_loosest = 1.0,
                                 .ntargets = 1, .threads = 1};
    const gd_opt_problem *pp[1] = {&problem};
    gd_opt_compare_result r;
    gd_error e = {0};
    gd_status st = gd_opt_compare(pp, &s, &r, &e);
    int rc = handler_is_off(st, &e);
    if (st == GD_OK)
        gd_opt_compare_result_free(&r);
    return rc;
}

/* ---- 3. the host's own handler ----------------------------------------------------------- */

static int host_calls;
static void host_handler(const char *reason, const char *file, int line, int gsl_errno)
{
    (void)reason, (void)file, (void)line, (void)gsl_errno;
    host_calls++;
}

static int host_handler_kept(void)
{
    gsl_set_error_handler(host_handler);
    gd_tooth t;
    gd_error e = {0};
    gd_status st = gd_tooth_init_beam(&t, 210e9, 0.3, 0.01, 0.01, 0.002, &e);
    printf("# host handler: %s, called %d time(s)\n", gd_status_name(st), host_calls);
    if (st == GD_OK || host_calls < 1)
        return 2;
    return current_handler() == host_handler ? 0 : 1;
}

int main(void)
{
    in_child(bad_tooth, "a GSL error inside gd_tooth_init_beam returns a gd_status (no abort)");
    static const struct {
        int (*f)(void);
        const char *name;
    } ep[] = {
        {ep_tooth_beam, "gd_tooth_init_beam"},
        {ep_geometry, "gd_geometry_compute"},
        {ep_case_resolve, "gd_case_resolve"},
        {ep_tca_create, "gd_tca_create"},
        {ep_contact_workspace, "gd_contact_workspace_alloc"},
        {ep_spectrum, "gd_amplitude_spectrum"},
        {ep_sim_create, "gd_sim_create (a custom model)"},
        {ep_modal, "gd_modal_analyse (a model of the caller's)"},
        {ep_testfn, "gd_opt_testfn_init"},
        {ep_opt_run, "gd_opt_run (a problem of the caller's)"},
        {ep_opt_compare, "gd_opt_compare (a problem of the caller's)"},
    };
    for (size_t i = 0; i < sizeof ep / sizeof ep[0]; i++) {
        char what[160];
        snprintf(what, sizeof what, "%s, the first call of a process, sets GSL's handler off", ep[i].name);
        in_child(ep[i].f, what);
    }
    in_child(host_handler_kept, "a handler the host installed is kept and sees the library's GSL errors");
    /* and in this process, after all: the default handler is replaced at the first call */
    tap_ok(current_handler() == NULL, "this process has GSL's default handler before any library call");
    gd_tooth t;
    gd_error e = {0};
    tap_ok(gd_tooth_init_beam(&t, 210e9, 0.3, 0.01, 0.01, 0.002, &e) == GD_ERR_GSL,
           "gd_tooth_init_beam on an empty tooth: GD_ERR_GSL (%s)", e.msg);
    tap_ok(current_handler() == gsl_off_handler(), "and GSL's handler is now gsl_set_error_handler_off's");
    return tap_done();
}
