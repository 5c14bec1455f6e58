/* The `response` analysis on the command line: the progress line, the pictures of the time
 * history and the phase portrait with the Poincare section of output.response_variable, and the
 * summary lines. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int cli_response_progress(void *user, long done, long total)
{
    cli_progress *o = user;
    if (cli_signal_caught())
        return 1;
    if (!o->tty)
        return 0;
    long pct = done * 100 / total;
    if (pct != o->last_pct || done == total) {
        fprintf(stderr, "\rgeardyn: %ld/%ld mesh periods (%ld%%)%s", done, total, pct, done == total ? "\n" : "");
        o->last_pct = pct;
    }
    return 0;
}

void cli_response_after_run(const cli_progress *p, gd_status st)
{
    if (p->tty && st != GD_OK)
        fputc('\n', stderr);
}

void cli_response_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    (void)c;
    const gd_response_outcome *o = result;
    const gd_response_result *res = &o->res;
    if (a->quiet)
        return;
    printf("%s: %s, %s, RMS mesh acceleration %.6g m/s^2", dir, res->motion,
           gd_impact_regime_name(res->impact_regime[2]), res->rms_accel_mps2[2]);
    if (o->model.nmesh > 1) /* the meshes' own; one mesh is the combined */
        printf(" (left %.6g, right %.6g)", res->rms_accel_mps2[0], res->rms_accel_mps2[1]);
    printf("\n");
    const gd_model *m = &o->model;
    if (m->nmesh > 1 && res->dynamic_load_factor[0] != res->dynamic_load_factor[1])
        printf("  dynamic load factor left %.4g, right %.4g (largest mesh force %.5g N, %.5g N; static %.5g N)\n",
               res->dynamic_load_factor[0], res->dynamic_load_factor[1], res->force_max_n[0], res->force_max_n[1],
               m->static_load_n);
    else
        printf("  dynamic load factor %.4g (largest mesh force %.5g N, static %.5g N)\n", res->dynamic_load_factor[0],
               res->force_max_n[0], m->static_load_n);
    printf("  %ld steps, %ld RHS evaluations, %ld events, %.3f s\n", res->stats.steps, res->stats.rhs_evals,
           res->stats.events, res->wall_s);
}
