/* Example: a sweep from C through the table of analyses.
 *
 *   example_sweep CASE.ini OUT_DIR [section.key=value ...]
 *
 * The case must be a sweep (`[scene] analysis = sweep`, a [sweep] section). The program finds the
 * row of the case's analysis in the library's table (gd_analysis_find) and runs all of it in
 * OUT_DIR with gd_analysis_run_in: the points, then sweep.csv, bifurcation.csv, states.csv and
 * summary.json, the tables `geardyn run CASE.ini --out OUT_DIR` writes (the command line adds, through hooks of
 * its own, the pictures drawn by gnuplot and the journal of --resume). What the caller wants to
 * see or steer goes through the hooks of a gd_run_env: here `sweep_point`, called as each point
 * finishes, counts them, and `done`, called with the result before it is freed, reads the
 * gd_sweep_outcome: the plan (the swept values) and every point (RMS acceleration, motion class,
 * impact regime, steps).
 *
 * Prints one line per point and branch, in the order of sweep.csv. The test `example_sweep`
 * (tests/test_examples.py) checks every point of an independent sweep against a `geardyn run` of
 * the response at the same parameter value. */
#include <geardyn/geardyn.h>

#include <stdio.h>

typedef struct progress {
    int finished;
} progress;

/* Called once per finished point, never by two threads at a time. */
static gd_status on_point(void *user, const gd_sweep_plan *p, const gd_sweep_point *pt, gd_error *err)
{
    (void)p, (void)pt, (void)err;
    ((progress *)user)->finished++;
    return GD_OK;
}

/* Called after summary.json is written, with the row's result (for a sweep a gd_sweep_outcome). */
static void on_done(void *user, const gd_case *c, const void *result, gd_run_dir *out)
{
    const gd_sweep_outcome *o = result;
    const gd_sweep_plan *p = &o->plan;
    printf("# %d points finished, files in %s\n", ((progress *)user)->finished, gd_run_dir_path(out));
    printf("# %s (%s), direction, rms_accel_mps2, motion, impact_regime, steps\n", p->parameter[0], p->unit[0]);
    for (int i = 0; i < p->nslots; i++) {
        const gd_sweep_point *pt = &o->pts[i];
        printf("%.17g %s %.17g %s %s %ld\n", pt->value[0], gd_sweep_branch_name(pt->branch), pt->rms_accel_mps2[2],
               pt->motion, gd_impact_regime_name(pt->impact_regime[2]), pt->steps);
    }
    (void)c;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: %s CASE.ini OUT_DIR [section.key=value ...]\n", argv[0]);
        return 2;
    }
    gd_error err = {0};
    gd_case c;
    gd_status st = gd_case_init(&c, &err);
    if (st == GD_OK)
        st = gd_case_load(&c, argv[1], &err);
    for (int i = 3; st == GD_OK && i < argc; i++)
        st = gd_case_set(&c, argv[i], i - 3, &err);
    if (st == GD_OK)
        st = gd_case_resolve(&c, &err);   /* includes the sweep's own checks ([sweep] keys) */
    if (st == GD_OK && c.analysis != GD_ANALYSIS_SWEEP)
        st = gd_error_set(&err, GD_ERR_INPUT, "scene.analysis is not sweep");

    progress prog = {0};
    gd_run_env env = {0};          /* every hook NULL: nothing shown, nothing stopped */
    env.user = &prog;
    env.threads = 0;               /* the OpenMP default; the results do not depend on it */
    env.sweep_point = on_point;
    env.done = on_done;
    if (st == GD_OK)
        st = gd_analysis_run_in(gd_analysis_find(c.analysis), &c, &env, argv[2], &err);
    if (st != GD_OK)
        fprintf(stderr, "%s: %s\n", argv[1], err.msg);
    gd_case_free(&c);
    return gd_status_exit_code(st);
}
