/* The defaults a C caller starts from (gd_pair_defaults, gd_tca_settings_defaults,
 * gd_ltca_settings_defaults, gd_solver_opts_defaults, gd_eventlog_filter_all) are what a case that
 * gives none of the keys resolves to: every field against gd_pair_from_case, gd_tca_settings_from_case,
 * gd_ltca_settings_from_case and gd_solver_opts_from_case of a case with only its operating point
 * (speed and torque) given, resolved as `geardyn run` resolves it. The LTCA settings have no load
 * (NaN, which gd_ltca_run refuses); gd_opt_settings_default is the [optimize] keys' ALO run. */
#include "geardyn/geardyn.h"
#include "tap.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static gd_error err;

#define CHECK(call)                                                                                                \
    do {                                                                                                           \
        gd_status st_ = (call);                                                                                    \
        if (st_ != GD_OK) {                                                                                        \
            printf("Bail out! %s:%d: %s: %s\n", __FILE__, __LINE__, #call, err.msg);                               \
            exit(1);                                                                                               \
        }                                                                                                          \
    } while (0)

/* equal as values: NaN equals NaN (a default that is "not given") */
static int same(double a, double b) { return a == b || (isnan(a) && isnan(b)); }

#define FIELD(a, b, f) tap_ok(same((double)(a).f, (double)(b).f), "%s: %.17g, the case's %.17g", #f, (double)(a).f, \
                              (double)(b).f)

int main(void)
{
    gd_case c;
    CHECK(gd_case_init(&c, &err));
    CHECK(gd_case_set(&c, "operating.speed_rpm=4000", 1, &err));
    CHECK(gd_case_set(&c, "operating.torque_nm=500", 2, &err));
    CHECK(gd_case_resolve(&c, &err));

    const gd_pair p = gd_pair_defaults(), q = gd_pair_from_case(&c);
    FIELD(p, q, normal_module_mm);
    FIELD(p, q, helix_angle_deg);
    FIELD(p, q, normal_pressure_angle_deg);
    FIELD(p, q, teeth_pinion);
    FIELD(p, q, teeth_gear);
    FIELD(p, q, profile_shift_pinion);
    FIELD(p, q, profile_shift_gear);
    FIELD(p, q, addendum_coefficient);
    FIELD(p, q, dedendum_coefficient);
    FIELD(p, q, face_width_pinion_mm);
    FIELD(p, q, face_width_gear_mm);
    FIELD(p, q, groove_width_mm);
    FIELD(p, q, bore_diameter_pinion_mm);
    FIELD(p, q, bore_diameter_gear_mm);
    FIELD(p, q, youngs_modulus_gpa);
    FIELD(p, q, poisson_ratio);
    FIELD(p, q, density_kg_per_m3);
    FIELD(p, q, arrangement);
    FIELD(p, q, pinion_hand);
    FIELD(p, q, root_relief_amount_um);
    FIELD(p, q, root_relief_length_mm);
    FIELD(p, q, tip_relief_amount_um);
    FIELD(p, q, tip_relief_length_mm);
    FIELD(p, q, lead_relief_inner_um);
    FIELD(p, q, lead_relief_outer_um);
    FIELD(p, q, lead_unmodified_length_mm);
    FIELD(p, q, axis_in_plane_arcmin);
    FIELD(p, q, axis_cross_plane_arcmin);
    FIELD(p, q, centre_distance_error_mm);
    /* the default pair is a pair: its geometry computes */
    gd_geometry g;
    tap_ok(gd_geometry_compute(&p, &g, &err) == GD_OK && g.eps_alpha > 1, "the default pair's geometry (eps_alpha %g)",
           g.eps_alpha);

    const gd_tca_settings t = gd_tca_settings_defaults(), u = gd_tca_settings_from_case(&c);
    FIELD(t, u, profile_points);
    FIELD(t, u, face_points);
    FIELD(t, u, refine);
    FIELD(t, u, positions_per_cycle);
    FIELD(t, u, cycles);
    FIELD(t, u, formulation);
    tap_ok(!t.stop.should_stop, "TCA settings: no stop hook");

    const gd_ltca_settings l = gd_ltca_settings_defaults(), m = gd_ltca_settings_from_case(&c);
    FIELD(l, m, pinion_axial);
    FIELD(l, m, positions_per_cycle);
    FIELD(l, m, face_slices);
    FIELD(l, m, profile_points);
    FIELD(l, m, refine);
    tap_ok(isnan(l.torque_nm) && !l.stop.should_stop, "LTCA settings: no load (%g), no stop hook", l.torque_nm);
    gd_ltca_result r;
    gd_error e = {0};
    tap_ok(gd_ltca_run(&p, &l, &r, &e) == GD_ERR_INPUT && strstr(e.msg, "torque"),
           "gd_ltca_run refuses the defaults until a load is set: %s", e.msg);

    const gd_solver_opts s = gd_solver_opts_defaults();
    gd_solver_opts o;
    gd_solver_opts_from_case(&c, &o);
    FIELD(s, o, method);
    FIELD(s, o, order);
    tap_ok(strcmp(s.table, o.table) == 0, "table: '%s', the case's '%s'", s.table, o.table);
    FIELD(s, o, rtol);
    FIELD(s, o, atol);
    FIELD(s, o, steps_per_period);
    FIELD(s, o, fixed_step);
    FIELD(s, o, root_finding);
    FIELD(s, o, grazing_watch);
    FIELD(s, o, max_step_fraction);
    FIELD(s, o, max_events_per_period);
    FIELD(s, o, max_separated_periods);
    FIELD(s, o, n_tangent);
    FIELD(s, o, refine_events);
    FIELD(s, o, interp_degree);
    FIELD(s, o, library_vector_ops);
    FIELD(s, o, generic_rhs);
    FIELD(s, o, ungated_roots);
    FIELD(s, o, arkode_dense);

    /* ALO as [optimize] runs it by default: iterations + 1 populations of population ants */
    gd_opt_settings a;
    gd_opt_settings_default(&a);
    tap_ok(a.algorithm == c.opt_algorithm && a.population == c.opt_population && a.seed == (unsigned long)c.opt_seed &&
           a.budget == (long)(c.opt_iterations + 1) * c.opt_population,
           "gd_opt_settings_default: ALO, %d ants, seed %lu, %ld evaluations; the case's %d ants, seed %d, %d "
           "iterations", a.population, a.seed, a.budget, c.opt_population, c.opt_seed, c.opt_iterations);

    /* the filter that selects every event of a log */
    char path[] = "/tmp/geardyn-test-defaults-XXXXXX";
    int fd = mkstemp(path);
    FILE *fp = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!fp) {
        printf("Bail out! cannot write a temporary event log\n");
        return 1;
    }
    fprintf(fp, "t_s,period,phase,clearance,kind,direction,rel_velocity_mps,x_um,recording,located\n"
                "-0.5,0,0.5,mesh,contact,1,0.1,0,0,1\n0.25,1,0.5,mesh-L,separation,-1,-0.1,0,1,1\n"
                "1e300,9,0.5,bearing-1L,back-contact,1,0.2,0,1,0\n");
    fclose(fp);
    const gd_eventlog_filter f = gd_eventlog_filter_all();
    gd_eventlog_summary sum;
    gd_status st = gd_eventlog_summarise(path, &f, NULL, &sum, &err);
    unlink(path);
    tap_ok(st == GD_OK && sum.rows == 3 && sum.selected == 3, "gd_eventlog_filter_all selects every event: %ld of %ld",
           sum.selected, sum.rows);

    gd_case_free(&c);
    printf("1..%d\n", tap_n);
    return tap_failed ? 1 : 0;
}
