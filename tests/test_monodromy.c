/* The monodromy matrix from the variational equations (gd_sim_period_map: tangent vectors from
 * the identity, a saltation matrix at every located event, no renormalisation) against a
 * finite-difference monodromy: each state component perturbed by +-h, one mesh period integrated
 * with events, central differences. Four impacting orbits, settled from the case's start:
 *   torsional, single-sided: Kahraman & Singh as shipped (cases/validation/kahraman-singh.ini);
 *   torsional, double-sided: the same oscillator at Omega 3 thrown across the backlash (A = 4);
 *   bta, single-sided: cases/accuracy/period1-7000rpm.ini (both halves separate, bearings rattle);
 *   bta, double-sided: cases/accuracy/rattle-4000rpm.ini (drive and back flanks of both meshes).
 * The one-period map is smooth where the sequence of events does not change (each crossing is
 * transversal), so the central difference converges as h^2 and is limited by the integration
 * error over h; at rtol 1e-12 and h = 1e-5 both are far below the tolerance 1e-6 checked, which is
 * relative to the largest entry of M. Each case also checks that the period it differentiates
 * contains the events it is meant to (drive-side separations, back-side contacts). Two more cases
 * damp the mesh in contact only, so that the vector field jumps at each event and the saltation
 * matrix differs from the identity; one more has a mesh-in pulse that acts only in drive-side
 * contact (it switches with the contact inside its phases), and one damps the bearings only while
 * their journals touch. An orbit of two mesh periods (Kahraman & Singh at Omega 1.3, damping
 * in contact only): its monodromy of two periods, from the map of two periods and as the product of
 * the one-period monodromies of its two shooting segments, against the finite differences of the map
 * of two periods. Without root finding the monodromy is refused (GD_ERR_INPUT). */
#include "analysis_util.h"
#include "tap.h"
#include "geardyn/gd_scene.h"

#include <string.h>

static void load(gd_case *c, gd_model *m, const char *rel, const char *const *sets)
{
    gd_error e = {0};
    const char *src = getenv("GEARDYN_SOURCE");
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", src ? src : ".", rel);
    if (gd_case_init(c, &e) != GD_OK || gd_case_load(c, path, &e) != GD_OK)
        au_die(&e);
    for (int i = 0; sets && sets[i]; i++)
        au_set(c, sets[i]);
    if (gd_case_resolve(c, &e) != GD_OK || gd_model_build(c, m, &e) != GD_OK)
        au_die(&e);
}

/* the state after `transient` periods from the case's initial condition */
static void settle(const gd_case *c, const gd_model *m, const gd_solver_opts *o, int transient, double *y)
{
    gd_error e = {0};
    gd_modes md;
    if (gd_initial_state(c, m, y, &md, &e) != GD_OK)
        au_die(&e);
    if (gd_sim_period_map(m, o, y, transient, y, NULL, NULL, &e) != GD_OK)
        au_die(&e);
}

static void compare(const char *name, const gd_model *m, const gd_solver_opts *o, const double *y0, int need_back)
{
    gd_error e = {0};
    const int n = m->n;
    double y1[GD_MAX_STATE], M[GD_MAX_STATE * GD_MAX_STATE], yp[GD_MAX_STATE], ym[GD_MAX_STATE], y[GD_MAX_STATE];
    gd_sim_stats st;
    if (gd_sim_period_map(m, o, y0, 1, y1, M, &st, &e) != GD_OK)
        au_die(&e);
    double mmax = 0, dmax = 0;
    for (int i = 0; i < n * n; i++)
        mmax = fmax(mmax, fabs(M[i]));
    for (int j = 0; j < n; j++) {
        double h = 1e-5 * (1.0 + fabs(y0[j]));
        memcpy(y, y0, sizeof(double) * (size_t)n);
        y[j] = y0[j] + h;
        if (gd_sim_period_map(m, o, y, 1, yp, NULL, NULL, &e) != GD_OK)
            au_die(&e);
        y[j] = y0[j] - h;
        if (gd_sim_period_map(m, o, y, 1, ym, NULL, NULL, &e) != GD_OK)
            au_die(&e);
        for (int i = 0; i < n; i++)
            dmax = fmax(dmax, fabs((yp[i] - ym[i]) / (2.0 * h) - M[i * n + j]));
    }
    printf("# %s: n %d, %ld events in the period (%ld separations, %ld back contacts), max |M| %.4g\n", name, n,
           st.events, st.events_by_kind[GD_EV_SEPARATION], st.events_by_kind[GD_EV_BACK_CONTACT], mmax);
    int ok_events = st.events_by_kind[GD_EV_SEPARATION] > 0 &&
                    (need_back ? st.events_by_kind[GD_EV_BACK_CONTACT] > 0
                               : st.events_by_kind[GD_EV_BACK_CONTACT] == 0 || m->nclear > m->nmesh);
    tap_ok(ok_events, "%s: the period has %s impacts (%ld separations, %ld back contacts)", name,
           need_back ? "double-sided" : "single-sided", st.events_by_kind[GD_EV_SEPARATION],
           st.events_by_kind[GD_EV_BACK_CONTACT]);
    char label[200];
    snprintf(label, sizeof label, "%s: max |M - M_fd| / max |M|", name);
    TAP_CLOSE(dmax / mmax, 0.0, 1e-6, label);
}

typedef struct pulse_events {
    const gd_model *m;
    long in, all;
} pulse_events;

static int count_event(gd_sim *s, const gd_event *ev, void *user)
{
    (void)s;
    pulse_events *p = user;
    p->all++;
    p->in += gd_model_pulse_after(p->m, 0, ev->t) != 0; /* the pulse (gated) in its phases there */
    return 0;
}

/* contact events of one period from y0 at which the pulse of mesh 0 is in its phases: there the
 * gated pulse switches with the contact and the saltation matrix carries its jump */
static long events_in_pulse(const gd_model *m, const gd_solver_opts *o, const double *y0, long *all)
{
    gd_error e = {0};
    gd_modes md;
    memset(&md, 0, sizeof md);
    if (gd_model_consistent_modes(m, 0.0, y0, &md, &e) != GD_OK)
        au_die(&e);
    gd_sim *s;
    if (gd_sim_create(m, o, y0, &md, &s, &e) != GD_OK)
        au_die(&e);
    pulse_events p = {m, 0, 0};
    gd_sim_set_hooks(s, NULL, count_event, &p);
    if (gd_sim_period(s, &e) != GD_OK)
        au_die(&e);
    gd_sim_free(s);
    *all = p.all;
    return p.in;
}

/* The monodromy of nper periods from y0 against central differences of the map of nper periods:
 * from gd_sim_period_map when Mgiven is NULL, else Mgiven. */
static void compare_n(const char *name, const gd_model *m, const gd_solver_opts *o, const double *y0, int nper,
                      const double *Mgiven)
{
    gd_error e = {0};
    const int n = m->n;
    double y1[GD_MAX_STATE], M[GD_MAX_STATE * GD_MAX_STATE], yp[GD_MAX_STATE], ym[GD_MAX_STATE], y[GD_MAX_STATE];
    if (Mgiven)
        memcpy(M, Mgiven, sizeof(double) * (size_t)(n * n));
    else if (gd_sim_period_map(m, o, y0, nper, y1, M, NULL, &e) != GD_OK)
        au_die(&e);
    double mmax = 0, dmax = 0;
    for (int i = 0; i < n * n; i++)
        mmax = fmax(mmax, fabs(M[i]));
    for (int j = 0; j < n; j++) {
        double h = 1e-5 * (1.0 + fabs(y0[j]));
        memcpy(y, y0, sizeof(double) * (size_t)n);
        y[j] = y0[j] + h;
        if (gd_sim_period_map(m, o, y, nper, yp, NULL, NULL, &e) != GD_OK)
            au_die(&e);
        y[j] = y0[j] - h;
        if (gd_sim_period_map(m, o, y, nper, ym, NULL, NULL, &e) != GD_OK)
            au_die(&e);
        for (int i = 0; i < n; i++)
            dmax = fmax(dmax, fabs((yp[i] - ym[i]) / (2.0 * h) - M[i * n + j]));
    }
    char label[200];
    snprintf(label, sizeof label, "%s: max |M - M_fd| / max |M| (max |M| %.4g)", name, mmax);
    TAP_CLOSE(dmax / mmax, 0.0, 1e-6, label);
}

int main(void)
{
    const char *tight[] = {"solver.rtol=1e-12", "solver.atol=1e-14", NULL};
    gd_case c;
    gd_model m;
    gd_solver_opts o;
    double y[GD_MAX_STATE];

    load(&c, &m, "cases/validation/kahraman-singh.ini", tight);
    gd_solver_opts_from_case(&c, &o);
    settle(&c, &m, &o, 200, y);
    compare("torsional, single-sided (K&S, Omega 1.2)", &m, &o, y, 0);
    gd_case_free(&c);

    {
        const double Omega = 3.0, A = 4.0;
        double H = Omega * Omega / hypot(1.0 - Omega * Omega, 2.0 * 0.05 * Omega);
        const char *sets[] = {"excitation.ste_phase_deg=90", "solver.rtol=1e-12", "solver.atol=1e-14", NULL};
        au_ks_case(&c, &m, 0.0, 0.05, 0.1, A / H, Omega, sets);
        gd_solver_opts_from_case(&c, &o);
        settle(&c, &m, &o, 200, y);
        compare("torsional, double-sided (K&S, Omega 3, A 4)", &m, &o, y, 1);
        gd_case_free(&c);
    }

    load(&c, &m, "cases/accuracy/period1-7000rpm.ini", tight);
    gd_solver_opts_from_case(&c, &o);
    settle(&c, &m, &o, 100, y);
    compare("bta, single-sided (period1-7000rpm)", &m, &o, y, 0);
    gd_case_free(&c);

    load(&c, &m, "cases/accuracy/rattle-4000rpm.ini", tight);
    gd_solver_opts_from_case(&c, &o);
    settle(&c, &m, &o, 100, y);
    compare("bta, double-sided (rattle-4000rpm)", &m, &o, y, 1);
    gd_case_free(&c);

    /* damping in contact only: the vector field jumps at every event and the saltation matrices
     * are not the identity (without them these two differ by 7e-3 and 2e-3) */
    const char *contact[] = {"solver.rtol=1e-12", "solver.atol=1e-14", "damping.mesh_damping_mode=contact", NULL};
    load(&c, &m, "cases/validation/kahraman-singh.ini", contact);
    gd_solver_opts_from_case(&c, &o);
    settle(&c, &m, &o, 200, y);
    compare("torsional, single-sided, damping in contact only", &m, &o, y, 0);
    gd_case_free(&c);
    load(&c, &m, "cases/accuracy/rattle-4000rpm.ini", contact);
    gd_solver_opts_from_case(&c, &o);
    settle(&c, &m, &o, 100, y);
    compare("bta, double-sided, damping in contact only", &m, &o, y, 1);
    gd_case_free(&c);

    /* a mesh-in impact pulse that acts only in drive-side contact: the force jumps by the pulse at
     * each contact and separation inside its phases (half of each period here), and the saltation
     * matrices carry that jump */
    {
        load(&c, &m, "cases/validation/kahraman-singh.ini", tight);
        gd_error e = {0};
        double F = 0.5 * m.F0[0] / m.mass[0] * m.k_ref * m.bc_m, Tm = 1.0 / m.mesh_freq_hz;
        if (gd_model_set_impact(&m, 0, F, 2.0 * M_PI * 0.3, 0.5 * Tm, &e) != GD_OK)
            au_die(&e);
        m.mesh[0].imp_contact_only = 1;
        gd_solver_opts_from_case(&c, &o);
        settle(&c, &m, &o, 200, y);
        long all, in = events_in_pulse(&m, &o, y, &all);
        tap_ok(in > 0, "gated pulse: %ld of the period's %ld events fall inside the pulse's phases", in, all);
        compare("torsional, single-sided, a pulse gated by drive-side contact", &m, &o, y, 0);
        gd_case_free(&c);
    }
    /* the bearing damper in contact only: its force jumps at every bearing contact and separation */
    const char *bearing[] = {"solver.rtol=1e-12", "solver.atol=1e-14", "damping.bearing_damping_mode=contact",
                             "damping.support_damping_ratio=0.05", NULL};
    load(&c, &m, "cases/accuracy/rattle-4000rpm.ini", bearing);
    gd_solver_opts_from_case(&c, &o);
    settle(&c, &m, &o, 100, y);
    compare("bta, double-sided, bearing damping in contact only", &m, &o, y, 1);
    gd_case_free(&c);
    /* an orbit of two mesh periods: the map of two periods, and the product of the two one-period
     * monodromies of its multiple-shooting segments, both against the finite differences of the
     * map of two periods (K&S at Omega 1.3, past the period doubling: impacting, damping in contact
     * only so that its saltation matrices are not the identity) */
    {
        const char *sets[] = {"excitation.ste_phase_deg=90", "solver.rtol=1e-12", "solver.atol=1e-14",
                              "damping.mesh_damping_mode=contact", NULL};
        au_ks_case(&c, &m, 0.0, 0.05, 0.1, 0.1, 1.3, sets);
        gd_solver_opts_from_case(&c, &o);
        settle(&c, &m, &o, 400, y);
        gd_po_opts po;
        gd_po_opts_default(&po);
        po.nper = 2;
        gd_po orbit;
        gd_error e = {0};
        if (gd_po_solve(&m, &o, &po, y, &orbit, &e) != GD_OK)
            au_die(&e);
        double y2[GD_MAX_STATE], d = 0;
        if (gd_sim_period_map(&m, &o, orbit.y[0], 1, y2, NULL, NULL, &e) != GD_OK)
            au_die(&e);
        for (int i = 0; i < m.n; i++)
            d = fmax(d, fabs(y2[i] - orbit.y[0][i]));
        tap_ok(orbit.nseg == 2 && d > 1e-3 && orbit.events[0] >= 2, "K&S at Omega 1.3: an impacting orbit of two mesh "
               "periods (|P y - y| %.3g, %ld events)", d, orbit.events[0]);
        compare_n("two periods of the period-2 orbit, the map of two periods", &m, &o, orbit.y[0], 2, NULL);
        compare_n("two periods of the period-2 orbit, the product of its segments' monodromies", &m, &o, orbit.y[0],
                  2, orbit.M);
        gd_case_free(&c);
    }

    /* a monodromy needs located events: without root finding the map refuses it */
    {
        load(&c, &m, "cases/validation/kahraman-singh.ini", tight);
        gd_solver_opts_from_case(&c, &o);
        o.root_finding = 0;
        double y1[GD_MAX_STATE], M[GD_MAX_STATE * GD_MAX_STATE];
        gd_error e = {0};
        settle(&c, &m, &o, 10, y);
        gd_status st = gd_sim_period_map(&m, &o, y, 1, y1, M, NULL, &e);
        tap_ok(st == GD_ERR_INPUT && strstr(e.msg, "root finding"), "without root finding the monodromy is refused "
               "(%s)", e.msg);
        gd_case_free(&c);
    }
    return tap_done();
}
