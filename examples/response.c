/* Example: one response run from C, the physics path.
 *
 *   example_response CASE.ini [section.key=value ...]
 *
 * Loads a case file, applies the assignments as `geardyn run --set` does, resolves the case
 * (derived geometry and values, checks), builds the dimensionless model and integrates it with
 * gd_response_run: a transient, then the recorded window. A sample hook receives every uniform
 * sample of the window; here it sums the squared mesh acceleration, so that the program computes
 * the RMS acceleration of the left mesh itself and prints it beside the library's. No file is
 * written (`geardyn run` writes the same run's files through the table of analyses: see sweep.c).
 *
 * Prints `name = value` lines. The test `example_response` (tests/test_examples.py) runs
 * `geardyn run` on the same case and checks these against its summary.json. */
#include <geardyn/geardyn.h>

#include <math.h>
#include <stdio.h>

/* What the sample hook accumulates. */
typedef struct window {
    long n;
    double sum_a2; /* sum of the squared relative mesh acceleration of the left mesh (m/s^2)^2 */
} window;

/* Called for every sample of the recorded window; nonzero would stop the run. */
static int on_sample(void *user, const gd_sample *s)
{
    window *w = user;
    w->n++;
    w->sum_a2 += s->accel_mps2[0] * s->accel_mps2[0];
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: %s CASE.ini [section.key=value ...]\n", argv[0]);
        return 2;
    }
    gd_error err = {0};
    gd_case c;
    gd_model m;
    gd_response_result res;
    window w = {0, 0.0};
    gd_response_hooks hooks = {.sample = on_sample};

    /* Every fallible call returns a gd_status and fills err with a message naming its cause. */
    gd_status st = gd_case_init(&c, &err);            /* the schema's defaults */
    if (st == GD_OK)
        st = gd_case_load(&c, argv[1], &err);         /* the case file */
    for (int i = 2; st == GD_OK && i < argc; i++)
        st = gd_case_set(&c, argv[i], i - 2, &err);   /* as --set, in order */
    if (st == GD_OK)
        st = gd_case_resolve(&c, &err);               /* case checks, scene, the analysis's keys */
    if (st == GD_OK)
        st = gd_model_build(&c, &m, &err);            /* torsional, torsional-lr or bta */
    if (st == GD_OK)
        st = gd_response_run(&c, &m, NULL, &hooks, &w, &res, &err);
    if (st != GD_OK) {
        fprintf(stderr, "%s: %s\n", argv[1], err.msg);
        gd_case_free(&c);
        return gd_status_exit_code(st);
    }

    printf("motion = %s\n", res.motion);
    printf("impact_regime = %s\n", gd_impact_regime_name(res.impact_regime[2]));
    printf("rms_accel_mps2 = %.17g\n", res.rms_accel_mps2[2]);           /* combined, (a_L + a_R)/2 */
    printf("rms_accel_left_mps2 = %.17g\n", res.rms_accel_mps2[0]);
    printf("rms_accel_left_from_samples_mps2 = %.17g\n", sqrt(w.sum_a2 / (double)w.n));
    printf("samples = %ld\n", w.n);
    printf("dte_rms_left_um = %.17g\n", res.dte_rms_um[0]);
    printf("steps = %ld\n", res.stats.steps);
    printf("rhs_evals = %ld\n", res.stats.rhs_evals);
    gd_case_free(&c);
    return 0;
}
