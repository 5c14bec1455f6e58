/* Internal to libgeardyn (the two-parameter continuation of src/analysis/ uses it): the map of whole
 * mesh periods with what a defining system of a bifurcation curve needs beyond gd_sim_period_map
 * (docs/continuation.md section 8): any number of tangent vectors (the monodromy, or its product with
 * a few directions), the state and the tangent vectors at one time inside the run (a grazing's), a
 * fingerprint of the contact events (their counts by clearance and kind), and a held side of one
 * clearance over a window of time, where the vector field of the held mode is continued and no event
 * is located (the grazing orbit built on the side where the contact does not happen). */
#ifndef GD_SIM_PROBE_H
#define GD_SIM_PROBE_H

#include "geardyn/gd_sim.h"

#include <stdint.h>

/* A held side: root function `side` (0: x - h, 1: x + h) of clearance `clearance` reports no crossing
 * while the time (dimensionless, from the start of the run) lies in [t0, t1] (t0 > t1: a window that
 * wraps round the orbit, t >= t0 or t <= t1), and the clearance's mode is not switched from the state
 * there; a run whose window holds t = 0 starts in `mode`. */
typedef struct gd_sim_hold {
    int on, clearance, side, mode;
    double t0, t1;
} gd_sim_hold;

typedef struct gd_map_probe {
    /* in */
    int ntan;                /* tangent vectors: 0 none; with V NULL and ntan = n the monodromy (identity) */
    const double *V;         /* n x ntan (row-major): the directions the tangents start from, or NULL */
    double t_probe;          /* >= 0: the state and tangents at this time too (inside [0, nper T]); < 0: none */
    gd_sim_hold hold;
    gd_gap_extrema *gaps;    /* not NULL: the extrema of the clearance coordinates over the run (gd_sim_watch_gaps) */
    /* out */
    double y1[GD_MAX_STATE];                 /* the state after nper periods */
    double T1[GD_MAX_STATE * GD_MAX_STATE];  /* the tangents there (n x ntan, row-major) */
    double yp[GD_MAX_STATE];                 /* the state at t_probe */
    double Tp[GD_MAX_STATE * GD_MAX_STATE];  /* the tangents there */
    gd_modes mdp;                            /* the modes there */
    uint64_t seq;            /* FNV-1a of the events' counts by clearance and kind: the same when the order of the
                              * orbit's cycle of events only rotates (an event crossing the run's start), changed
                              * when a contact appears or goes (a grazing) */
    long kcount[GD_MAX_CLEAR][GD_EV_NKINDS];
    long nevents;
    long events[GD_MAX_CLEAR];               /* by clearance */
} gd_map_probe;

/* The map of nper mesh periods from y0 at t = 0 with pr's tangents, probe and hold (the same
 * integration, events and saltation as gd_sim_period_map). */
gd_status gd_sim_map_probe(const gd_model *m, const gd_solver_opts *o, const double *y0, int nper, gd_map_probe *pr,
                           gd_error *err);

#endif
