/* Benchmark: one evaluation of the dynamic objective gear-dynamic (docs/optimisation.md section
 * 12) on cases/paper/optimize-dynamic.ini: the paper's pair, three torques (250, 500, 750 N m),
 * 3000-5500 rpm, torsional-lr, each flank's LTCA stiffness and error. Each repeat evaluates a flank
 * of its own (the Table 2 tip relief plus 0.1 um per repeat, so that the LTCA cache never answers),
 * and reports the process CPU time (LTCA's threads included) and the wall time, and how each
 * torque's curve was found.
 * Usage: bench_dynobj [repeats]   (GEARDYN_SOURCE: the source tree) */
#include "geardyn/geardyn.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 3;
    const char *src = getenv("GEARDYN_SOURCE");
    char path[4096];
    snprintf(path, sizeof path, "%s/cases/paper/optimize-dynamic.ini", src ? src : ".");
    gd_case c;
    gd_error e = {0};
    if (gd_case_init(&c, &e) != GD_OK || gd_case_load(&c, path, &e) != GD_OK || gd_case_resolve(&c, &e) != GD_OK) {
        fprintf(stderr, "bench_dynobj: %s\n", e.msg);
        return 1;
    }
    gd_dynobj_settings s;
    gd_dynobj_settings_from_case(&c, &s);
    printf("gear-dynamic on %s: %d torques, %g-%g rpm, model %d\n", path, s.ntorques, s.speed_from_rpm,
           s.speed_to_rpm, s.model);
    for (int r = 0; r < repeats; r++) {
        gd_pair pair = gd_pair_from_case(&c);
        pair.tip_relief_amount_um += 0.1 * (r + 1);
        gd_dyn_result res;
        double c0 = now(CLOCK_PROCESS_CPUTIME_ID), w0 = now(CLOCK_MONOTONIC);
        if (gd_dyn_evaluate(&c, &s, &pair, NULL, &res, &e) != GD_OK) {
            fprintf(stderr, "bench_dynobj: %s\n", e.msg);
            return 1;
        }
        double cpu = now(CLOCK_PROCESS_CPUTIME_ID) - c0, wall = now(CLOCK_MONOTONIC) - w0;
        printf("repeat %d: %.4g m/s^2, cpu %.3f s, wall %.3f s;", r + 1, res.value, cpu, wall);
        for (int k = 0; k < res.ntorques; k++)
            printf(" %g N m: %s (%d orbits, %d swept, %d refined)", res.curve[k].torque_nm,
                   gd_dyn_method_name(res.curve[k].method), res.curve[k].branch_points, res.curve[k].swept_points,
                   res.curve[k].refined_points);
        printf("\n");
        gd_dyn_result_free(&res);
    }
    gd_case_free(&c);
    return 0;
}
