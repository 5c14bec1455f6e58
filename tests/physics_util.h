/* Helpers shared by the physics tests: building a case from "section.key=value" lines,
 * tuning a torsional case to given Kahraman & Singh numbers, and running a simulation
 * with a per-step callback. Header-only (each test is one translation unit). */
#ifndef GD_PHYSICS_UTIL_H
#define GD_PHYSICS_UTIL_H

#include "geardyn/gd_response.h"
#include "geardyn/gd_analysis.h"
#include "geardyn/gd_scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Abort the test program (TAP bail out) on an unexpected library error. */
#define PU_CHECK(call, err)                                                                                        \
    do {                                                                                                           \
        gd_status st_ = (call);                                                                                    \
        if (st_ != GD_OK) {                                                                                        \
            printf("Bail out! %s:%d: %s: %s\n", __FILE__, __LINE__, #call, (err)->msg);                            \
            exit(1);                                                                                               \
        }                                                                                                          \
    } while (0)

/* Initialise c with the defaults, apply the NULL-terminated list of assignments and resolve. */
static inline void pu_case(gd_case *c, const char *const *sets)
{
    gd_error e;
    memset(&e, 0, sizeof e);
    PU_CHECK(gd_case_init(c, &e), &e);
    c->speed_rpm = 4000, c->torque_nm = 500; /* the paper's operating point: a case must give one */
    for (int i = 0; sets && sets[i]; i++)
        PU_CHECK(gd_case_set(c, sets[i], i, &e), &e);
    PU_CHECK(gd_case_resolve(c, &e), &e);
}

static inline void pu_set(gd_case *c, const char *assignment)
{
    gd_error e;
    memset(&e, 0, sizeof e);
    PU_CHECK(gd_case_set(c, assignment, 99, &e), &e);
}

static inline void pu_set_number(gd_case *c, const char *name, double v)
{
    gd_error e;
    memset(&e, 0, sizeof e);
    PU_CHECK(gd_case_set_number(c, name, v, &e), &e);
}

static inline void pu_build(const gd_case *c, gd_model *m)
{
    gd_error e;
    memset(&e, 0, sizeof e);
    PU_CHECK(gd_model_build(c, m, &e), &e);
}

/* Set the torque and the speed so that the dimensionless static mesh load of one half
 * (F0 / mass of the mesh coordinate, i.e. F_m of Kahraman & Singh) and the dimensionless
 * mesh frequency Omega take the given values, then resolve again. Both are linear in
 * the torque and the speed respectively; the rest of the model does not depend on them. */
static inline void pu_tune(gd_case *c, double Fm, double Omega)
{
    gd_error e;
    memset(&e, 0, sizeof e);
    gd_model m;
    pu_build(c, &m);
    double fm_per_nm = m.F0[m.q_dof[0]] / m.mass[m.q_dof[0]] / c->torque_nm;
    double omega_per_rpm = m.Omega / c->speed_rpm;
    if (Fm > 0)
        pu_set_number(c, "operating.torque_nm", Fm / fm_per_nm);
    else
        pu_set_number(c, "operating.torque_nm", 0.0);
    pu_set_number(c, "operating.speed_rpm", Omega / omega_per_rpm);
    PU_CHECK(gd_case_resolve(c, &e), &e);
}

/* Mesh deflection lambda of mesh j (dimensionless) at absolute time t in state y. */
static inline double pu_lambda(const gd_model *m, int j, double t, const double *y, const gd_modes *md)
{
    double x, v;
    gd_model_clearance(m, m->mesh_clear[j], t, y, md, &x, &v);
    return x;
}

/* Uniform samples of the state over the periods [p0, p1) of a run, ns per period,
 * collected through the step hook with dense output. */
typedef struct pu_samples {
    const gd_model *m;
    double t0, dt;
    long next, count;
    int n;
    double *t;               /* count */
    double *y;               /* count x n */
    int failed;
} pu_samples;

static inline int pu_sample_hook(gd_sim *s, double t0, double t1, void *user)
{
    pu_samples *p = user;
    while (p->next < p->count) {
        double ts = p->t0 + (double)p->next * p->dt;
        if (ts > t1)
            break;
        if (ts < t0) { /* only at the very start */
            p->next++;
            continue;
        }
        gd_error e;
        if (gd_sim_dense(s, ts, p->y + p->next * p->n, &e) != GD_OK) {
            p->failed = 1;
            return 1;
        }
        p->t[p->next] = ts;
        p->next++;
    }
    return 0;
}

static inline void pu_samples_init(pu_samples *p, const gd_model *m, double t0, double dt, long count)
{
    memset(p, 0, sizeof *p);
    p->m = m;
    p->t0 = t0;
    p->dt = dt;
    p->count = count;
    p->n = m->n;
    p->t = calloc((size_t)count, sizeof(double));
    p->y = calloc((size_t)count * (size_t)m->n, sizeof(double));
    if (!p->t || !p->y) {
        printf("Bail out! out of memory\n");
        exit(1);
    }
}

static inline void pu_samples_free(pu_samples *p)
{
    free(p->t);
    free(p->y);
}

/* Run a simulation of nper mesh periods from (y0, md0) and sample periods [rec0, nper)
 * with ns samples per period (the first sample on the boundary of period rec0, the
 * state at the boundary itself is taken from the integrator). */
static inline void pu_run_sampled_ex(const gd_model *m, const gd_solver_opts *o, const double *y0, const gd_modes *md0,
                                     long nper, long rec0, int ns, int exact, pu_samples *p, gd_sim_stats *stats)
{
    gd_error e;
    memset(&e, 0, sizeof e);
    gd_sim *s = NULL;
    PU_CHECK(gd_sim_create(m, o, y0, md0, &s, &e), &e);
    pu_samples_init(p, m, (double)rec0 * m->period, m->period / ns, (nper - rec0) * ns);
    gd_sim_set_hooks(s, pu_sample_hook, NULL, p);
    if (exact) /* steps end on the sample times: the samples are the method's states */
        gd_sim_set_sample_grid(s, (double)rec0 * m->period, m->period / ns);
    for (long k = 0; k < nper; k++) {
        if (k == rec0 && p->count > 0) {
            memcpy(p->y, gd_sim_state(s), sizeof(double) * (size_t)m->n);
            p->t[0] = gd_sim_time(s);
            p->next = 1;
        }
        PU_CHECK(gd_sim_period(s, &e), &e);
    }
    if (p->failed || p->next != p->count) {
        printf("Bail out! sampling failed (%ld of %ld samples)\n", p->next, p->count);
        exit(1);
    }
    if (stats)
        gd_sim_get_stats(s, stats);
    gd_sim_free(s);
}

static inline void pu_run_sampled(const gd_model *m, const gd_solver_opts *o, const double *y0, const gd_modes *md0,
                                  long nper, long rec0, int ns, pu_samples *p, gd_sim_stats *stats)
{
    pu_run_sampled_ex(m, o, y0, md0, nper, rec0, ns, 0, p, stats);
}

#endif
