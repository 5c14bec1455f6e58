/* The cost of a run estimated from its case and model before any work, and the derived values
 * checked against their limits (gd_scene.h). The per-item sizes are measured on the files the
 * writers produce (cases/quickstart.ini: 254 bytes per time-history row of the 10-DOF model, 36 per
 * row of variable.csv, 19 per value of poincare.csv, about 3 events of 78 bytes per clearance and
 * mesh period, 7.6 us per step of the 10-DOF model) and on the LTCA of
 * cases/paper/local-speed-1500rpm.ini with 21, 201 and 401 face slices (0.34 s, 2.8 s, 21 s; 24 MB at
 * 401: one dense system per half and position). */
#include "geardyn/gd_scene.h"
#include "geardyn/gd_geometry.h"
#include "../case/case_keys.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static double dynamic_points(const gd_case *c)
{
    switch (c->analysis) {
    case GD_ANALYSIS_RESPONSE: return 1;
    case GD_ANALYSIS_SWEEP:
        return (double)c->sweep_points * (c->sweep_parameter2[0] ? c->sweep_points2 : 1) *
               (c->sweep_direction == 2 ? 2 : 1);
    case GD_ANALYSIS_BASINS: /* every initial state a run: the picture's cells and the sample, at each value */
        return ((c->bas_picture && !c->bas_parameter[0] ? (double)c->bas_resolution *
                 (c->bas_resolution_y ? c->bas_resolution_y : c->bas_resolution) : 0.0) + c->bas_samples) *
               (c->bas_parameter[0] ? c->bas_points : 1);
    default: return 0;
    }
}

/* Contact points of one LTCA position: the face slices of every tooth pair that can be in contact,
 * on each half. */
static double ltca_unknowns(const gd_case *c)
{
    if (!(c->stiffness == GD_STIFF_LTCA || c->impact || c->analysis == GD_ANALYSIS_LTCA ||
          (c->ste_source == GD_STE_LTCA && c->error_excitation)))
        return 0;
    gd_geometry g;
    gd_error e = {0};
    double pairs = 3;
    const gd_pair pair = gd_pair_from_case(c);
    if (gd_geometry_compute(&pair, &g, &e) == GD_OK && isfinite(g.eps_alpha))
        pairs = ceil(g.eps_alpha + g.eps_beta) + 1;
    return (double)c->ltca_face_slices * pairs * (c->arrangement == GD_ARR_HERRINGBONE ? 2 : 1);
}

GD_API void gd_run_cost_estimate(const gd_case *c, const gd_model *m, gd_run_cost *cost)
{
    double spp = c->samples_per_period, rec = c->record_periods;
    double trans = c->transient_max_periods > c->transient_periods ? c->transient_max_periods : c->transient_periods;
    cost->points = dynamic_points(c);
    cost->periods = trans + rec;
    double per_period = c->method == GD_METHOD_RK4 || c->fixed_step ? c->steps_per_period
                      : fmax(1.0 / c->max_step_fraction, 170.0 / fmax(m->Omega, 1e-300));
    cost->steps = cost->points * cost->periods * per_period;
    double rows = rec * spp, cols = 2 + 5 * m->nmesh + m->ndof;
    double window = rows * 48 + (rec + 1) * (8.0 * m->n + 16);  /* samples, spectrum, Poincare points */
    double files = rows * 36 + (rec + 1) * 19.0 * m->n + 1e6;  /* variable.csv, poincare.csv, summary, pictures */
    if (c->time_history)
        files += rows * 11.5 * cols;
    if (c->event_log)
        files += cost->periods * 3 * 78.0 * m->nclear;
    if (c->analysis == GD_ANALYSIS_SWEEP) {  /* no time history per point: its Poincare points and a table row */
        window = (rec + 1) * 8.0 * m->n * 4;
        files = cost->points * ((rec + 1) * 40.0 + 400) + 1e6;
    } else if (c->analysis == GD_ANALYSIS_BASINS) {
        /* a trajectory ends after about 20 mesh periods (12 on the shipped Kahraman & Singh picture, 22 on
         * the Duffing samples: docs/basins.md section 9); the tessellation (4 bytes a cell), the picture's
         * labels and the sample's states; basins.csv 33 bytes a cell, fractions.csv a row per attractor */
        double ry = c->bas_resolution_y ? c->bas_resolution_y : c->bas_resolution, m2 = 1.0 + 2.0 * c->bas_margin;
        double cells = c->bas_picture && !c->bas_parameter[0] ? (double)c->bas_resolution * ry : 0.0;
        cost->periods = 20;
        window = 4.0 * (c->bas_resolution * m2) * (ry * m2) + 4.0 * cells + (8.0 * m->n + 4.0) * c->bas_samples +
                 16.0 * c->bas_max_periods;
        files = 33.0 * cells + (c->bas_parameter[0] ? c->bas_points : 1) * 2000.0 + 1e6;
    } else if (cost->points == 0)
        window = files = 0;
    cost->ltca_unknowns = ltca_unknowns(c);
    double N = cost->ltca_unknowns;
    double per_half = N / (c->arrangement == GD_ARR_HERRINGBONE ? 2 : 1);
    cost->memory_bytes = window + 8.0 * per_half * per_half;
    cost->disk_bytes = files;
    double positions = c->ltca_positions_per_cycle * (c->impact ? 2.0 : 1.0);
    cost->seconds = cost->steps * 0.8e-6 * m->ndof + positions * (2.4e-5 * N + 7.8e-12 * N * N * N);
    if (c->analysis == GD_ANALYSIS_BASINS && c->model != GD_MODEL_BTA && !(c->method == GD_METHOD_RK4 || c->fixed_step)) {
        /* the torsional models take about 10 steps per natural period, not bta's 170 (Kahraman & Singh at
         * Omega 0.65, rtol 1e-8: 15.4 steps per mesh period) */
        cost->steps = cost->points * cost->periods * fmax(1.0 / c->max_step_fraction, 10.0 / fmax(m->Omega, 1e-300));
        cost->seconds = cost->steps * 0.8e-6 * m->ndof + positions * (2.4e-5 * N + 7.8e-12 * N * N * N);
    }
    cost->time_class = cost->seconds < 10 ? "seconds" : cost->seconds < 600 ? "minutes"
                     : cost->seconds < 36000 ? "hours" : "days or more";
}

/* The slowest speed a run integrates: the case's, or the lowest end of a sweep of the speed. */
static double slowest_speed(const gd_case *c, const char **key)
{
    double n = c->speed_rpm;
    *key = NULL;
    for (int axis = 0; c->analysis == GD_ANALYSIS_SWEEP && axis < 2; axis++)
        if (strcmp(axis ? c->sweep_parameter2 : c->sweep_parameter, "operating.speed_rpm") == 0) {
            double lo = fmin(axis ? c->sweep_from2 : c->sweep_from, axis ? c->sweep_to2 : c->sweep_to);
            if (lo < n || (lo == n && !gd_case_key_given(c, "operating", "speed_rpm"))) { /* the sweep's own speed */
                n = lo;
                *key = lo == (axis ? c->sweep_from2 : c->sweep_from) ? (axis ? "from2" : "from")
                                                                      : (axis ? "to2" : "to");
            }
        }
    return n;
}

GD_API gd_status gd_run_cost_check(const gd_case *c, const gd_model *m, const gd_run_cost *cost, gd_error *err)
{
    char w[GD_PATH_MAX + 32];
    const char *sweep_key;
    double speed = slowest_speed(c, &sweep_key);
    if (sweep_key && cost->points > 0 && !(m->Omega * speed / c->speed_rpm >= 1e-4)) {
        gd_case_key_where(c, "sweep", sweep_key, w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: sweep.%s: at operating.speed_rpm = %g rpm the mesh frequency is "
                            "%.3g of the natural frequency %.4g Hz, a run would not end (valid: a mesh frequency of at "
                            "least 1e-4 of the natural one: speed_rpm >= %.3g)", w, sweep_key, speed,
                            m->Omega * speed / c->speed_rpm, m->omega_n / (2 * M_PI), c->speed_rpm * 1e-4 / m->Omega);
    }
    if (cost->points > 0 && !(m->Omega >= 1e-4)) {
        gd_case_key_where(c, "operating", "speed_rpm", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: operating.speed_rpm: the mesh frequency %.3g Hz "
                            "(operating.speed_rpm = %g rpm times gear.teeth_pinion = %d over 60) is %.3g of the "
                            "natural frequency %.4g Hz, a run would not end (valid: a mesh frequency of at least "
                            "1e-4 of the natural one: speed_rpm >= %.3g)", w, m->mesh_freq_hz, c->speed_rpm,
                            c->teeth_pinion, m->Omega, m->omega_n / (2 * M_PI), c->speed_rpm * 1e-4 / m->Omega);
    }
    if (c->analysis == GD_ANALYSIS_BASINS && (cost->disk_bytes > c->max_bytes || cost->memory_bytes > c->max_bytes)) {
        int disk = cost->disk_bytes > c->max_bytes;
        gd_case_key_where(c, "output", "max_bytes", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: output.max_bytes: the basins would %s about %.3g bytes (from "
                            "basins.resolution = %d, resolution_y = %d, margin = %g, samples = %d, max_periods = %d), "
                            "above output.max_bytes = %.4g (valid: raise output.max_bytes, or fewer cells or samples)",
                            w, disk ? "write" : "hold in memory", disk ? cost->disk_bytes : cost->memory_bytes,
                            c->bas_resolution, c->bas_resolution_y ? c->bas_resolution_y : c->bas_resolution,
                            c->bas_margin, c->bas_samples, c->bas_max_periods, c->max_bytes);
    }
    if (cost->disk_bytes > c->max_bytes || cost->memory_bytes > c->max_bytes) {
        int disk = cost->disk_bytes > c->max_bytes;
        char ltca[64] = "";
        if (cost->ltca_unknowns > 0)
            snprintf(ltca, sizeof ltca, ", solver.ltca_face_slices = %d", c->ltca_face_slices);
        gd_case_key_where(c, "output", "max_bytes", w, sizeof w);
        return gd_error_set(err, GD_ERR_INPUT, "%s: output.max_bytes: the run would %s about %.3g bytes (from "
                            "run.record_periods = %d, output.samples_per_period = %d, output.time_history = %s, "
                            "output.event_log = %s%s), above output.max_bytes = %.4g (valid: raise output.max_bytes, "
                            "or shorten the run)", w, disk ? "write" : "hold in memory",
                            disk ? cost->disk_bytes : cost->memory_bytes, c->record_periods, c->samples_per_period,
                            c->time_history ? "on" : "off", c->event_log ? "on" : "off",
                            ltca, c->max_bytes);
    }
    return GD_OK;
}
