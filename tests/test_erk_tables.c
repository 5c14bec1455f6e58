/* Every explicit method geardyn offers integrates at its nominal order.
 *
 * SUNDIALS 6.4.1's ERKStep reuses the last stage as the next first stage whenever
 * c[s-1] = 1, FSAL or not; classical RK4 and ARKODE_VERNER_8_5_6 then run at order 3.
 * geardyn appends an exact FSAL stage (src/dynamics/compat/erk_fsal.c). This test measures the
 * order on a smooth linear gear response (torsional model in permanent contact) with
 * fixed steps N, 2N, 4N: p = log2(|y_N - y_2N| / |y_2N - y_4N|). */
#include "geardyn/geardyn.h"
#include "tap.h"

#include <string.h>

static double end_state(const char *table, int method, int steps, int order)
{
    gd_case c;
    gd_error err = {0};
    gd_case_init(&c, &err);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    const char *sets[] = {"scene.model=torsional", "clearance.backlash_um=0", "excitation.stiffness=harmonic",
                          "excitation.stiffness_harmonics=0.2", "operating.torque_nm=20000"};
    for (size_t i = 0; i < sizeof sets / sizeof sets[0]; i++)
        gd_case_set(&c, sets[i], (int)i, &err);
    if (gd_case_resolve(&c, &err) != GD_OK)
        return NAN;
    gd_model m;
    gd_model_build(&c, &m, &err);
    gd_solver_opts o;
    gd_solver_opts_from_case(&c, &o);
    o.method = method;
    o.order = order;
    snprintf(o.table, sizeof o.table, "%s", table ? table : "");
    o.fixed_step = 1;
    o.steps_per_period = steps;
    o.root_finding = 0;
    double y[GD_MAX_STATE];
    gd_modes md;
    gd_initial_state(&c, &m, y, &md, &err);
    y[1] = 3.0; /* a velocity kick, so the free response is present too */
    gd_sim *s;
    if (gd_sim_create(&m, &o, y, &md, &s, &err) != GD_OK) {
        printf("# %s\n", err.msg);
        return NAN;
    }
    double out = NAN;
    for (int k = 0; k < 3; k++)
        if (gd_sim_period(s, &err) != GD_OK)
            goto done;
    out = gd_sim_state(s)[0];
done:
    gd_sim_free(s);
    gd_case_free(&c);
    return out;
}

int main(void)
{
    struct { const char *table; int method, order; int n; } cases[] = {
        {NULL, GD_METHOD_RK4, 4, 16},
        {"ARKODE_HEUN_EULER_2_1_2", GD_METHOD_ERK, 2, 64},
        {"ARKODE_BOGACKI_SHAMPINE_4_2_3", GD_METHOD_ERK, 3, 32},
        {"ARKODE_ZONNEVELD_5_3_4", GD_METHOD_ERK, 4, 16},
        {"ARKODE_DORMAND_PRINCE_7_4_5", GD_METHOD_ERK, 5, 32},
        {"ARKODE_VERNER_8_5_6", GD_METHOD_ERK, 6, 10},
        {"ARKODE_SAYFY_ABURUB_6_3_4", GD_METHOD_ERK, 4, 16},
        {"ARKODE_ARK436L2SA_ERK_6_3_4", GD_METHOD_ERK, 4, 16},
        {"ARKODE_ARK548L2SA_ERK_8_4_5", GD_METHOD_ERK, 5, 40},
        {"ARKODE_FEHLBERG_13_7_8", GD_METHOD_ERK, 8, 6},
        /* Verner's pairs, which geardyn adds before SUNDIALS 7.3 (src/dynamics/compat/erk_verner.c) */
        {"ARKODE_VERNER_10_6_7", GD_METHOD_ERK, 7, 8},
        {"ARKODE_VERNER_13_7_8", GD_METHOD_ERK, 8, 6},
        {"ARKODE_VERNER_16_8_9", GD_METHOD_ERK, 9, 5},
        /* solver.order alone: 7 and 8 are Verner's */
        {"", GD_METHOD_ERK, 7, 8},
        {"", GD_METHOD_ERK, 8, 6},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        int n = cases[i].n;
        double a = end_state(cases[i].table, cases[i].method, n, cases[i].order);
        double b = end_state(cases[i].table, cases[i].method, 2 * n, cases[i].order);
        double c = end_state(cases[i].table, cases[i].method, 4 * n, cases[i].order);
        double p = log2(fabs(a - b) / fabs(b - c));
        tap_ok(isfinite(p) && p > cases[i].order - 0.35, "%s: measured order %.3f, nominal %d (differences %.3g, %.3g)",
               cases[i].table ? (cases[i].table[0] ? cases[i].table : "solver.order") : "classical RK4", p, cases[i].order, fabs(a - b), fabs(b - c));
    }
    return tap_done();
}
