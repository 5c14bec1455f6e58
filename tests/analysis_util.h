/* Helpers for the analysis tests: a torsional Kahraman & Singh oscillator by its
 * dimensionless parameters. */
#ifndef GD_ANALYSIS_UTIL_H
#define GD_ANALYSIS_UTIL_H

#include "geardyn/geardyn.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static inline void au_die(const gd_error *e)
{
    printf("Bail out! %s\n", e->msg);
    exit(1);
}

/* ERK5 to rtol 1e-11, atol 1e-13, root finding on: the options of the smooth systems with known
 * multipliers that the curve tests follow */
static inline void au_smooth_opts(gd_solver_opts *o)
{
    memset(o, 0, sizeof *o);
    o->method = GD_METHOD_ERK;
    o->order = 5;
    o->rtol = 1e-11;
    o->atol = 1e-13;
    o->max_step_fraction = 1.0;
    o->max_events_per_period = 10;
    o->max_separated_periods = 10;
    o->root_finding = 1;
}

static inline void au_set(gd_case *c, const char *kv)
{
    gd_error e = {0};
    if (gd_case_set(c, kv, 0, &e) != GD_OK)
        au_die(&e);
}

static inline void au_num(gd_case *c, const char *k, double v)
{
    gd_error e = {0};
    if (gd_case_set_number(c, k, v, &e) != GD_OK)
        au_die(&e);
}

/* K&S form: x'' + 2 zeta x' + (1 + alpha cos Omega t) f(x) = Fm + ea Omega^2 sin Omega t with
 * backlash b = 1 (lengths in half backlashes). Other keys may follow in `extra`. */
static inline void au_ks_case(gd_case *c, gd_model *m, double alpha, double zeta, double Fm, double ea, double Omega,
                              const char *const *extra)
{
    gd_error e = {0};
    gd_case_init(c, &e);
    c->speed_rpm = 4000, c->torque_nm = 500; /* the paper's operating point: a case must give one */
    au_set(c, "scene.model=torsional");
    au_set(c, "clearance.backlash_um=2");
    au_set(c, "solver.characteristic_length_um=1");
    if (alpha > 0) {
        char buf[64];
        au_set(c, "excitation.stiffness=harmonic");
        snprintf(buf, sizeof buf, "excitation.stiffness_harmonics=%.17g", alpha);
        au_set(c, buf);
    } else {
        au_set(c, "excitation.stiffness=constant");
    }
    au_num(c, "damping.mesh_damping_ratio", zeta);
    au_num(c, "excitation.ste_amplitude_um", ea);
    for (; extra && *extra; extra++)
        au_set(c, *extra);
    if (gd_case_resolve(c, &e) != GD_OK)
        au_die(&e);
    if (gd_model_build(c, m, &e) != GD_OK)
        au_die(&e);
    double fm = m->F0[0] / m->mass[0] / c->torque_nm, om = m->Omega / c->speed_rpm;
    au_num(c, "operating.torque_nm", Fm / fm);
    au_num(c, "operating.speed_rpm", Omega / om);
    if (gd_case_resolve(c, &e) != GD_OK || gd_model_build(c, m, &e) != GD_OK)
        au_die(&e);
}

#endif
