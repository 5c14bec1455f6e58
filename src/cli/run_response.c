/* The `response` analysis on the command line: the progress line, the pictures of the time
 * history and the phase portrait with the Poincare section, and the summary lines. */
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

/* Draw the time history and the phase portrait with the Poincare section (PNG and SVG). */
static gd_status draw(const char *dir, const gd_case *c, const gd_model *m, const gd_response_result *r,
                      gd_error *err)
{
    int shown = c->record_periods < 20 ? c->record_periods : 20;
    double t_end = (c->transient_periods + c->record_periods) * m->period / m->omega_n;
    double t_from = t_end - shown * m->period / m->omega_n;
    int two = m->nmesh > 1;
    char script[8192];
    int n = 0;
    static const char *fmt[2][3] = {{"pngcairo size 1200,800 font ',11'", "png", ".png"},
                                    {"svg size 1200,800 dynamic font 'sans,11'", "svg", ".svg"}};
    n += snprintf(script + n, sizeof script - n,
                  "set datafile separator ','\nset grid\nset key outside top center horizontal\n");
    for (int f = 0; f < 2; f++) {
        char right[600] = "";
        if (two)
            snprintf(right, sizeof right,
                     ", 'time_history.csv' every ::1 using ($1*1e3):($1 >= %.12g ? $8 : 1/0) with lines lw 1.5 "
                     "dt 2 title 'right half'", t_from);
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '.time_history%s.tmp'\n"
            "set title 'Relative mesh displacement, last %d mesh periods (%s, %s)'\n"
            "set xlabel 't (ms)'\nset ylabel 'mesh deflection {/Symbol l} (um)'\n"
            "plot 'time_history.csv' every ::1 using ($1*1e3):($1 >= %.12g ? $3 : 1/0) with lines lw 1.5 title '%s'%s\n"
            "unset output\n",
            fmt[f][0], fmt[f][2], shown, r->motion, gd_impact_regime_name(r->impact_regime[2]), t_from,
            two ? "left half" : "mesh", right);
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '.phase%s.tmp'\n"
            "set title 'Phase portrait and Poincare section (%s, %d distinct points)'\n"
            "set xlabel 'mesh deflection {/Symbol l}_L (um)'\nset ylabel 'd{/Symbol l}_L/dt (m/s)'\n"
            "plot 'time_history.csv' every ::1 using 3:4 with lines lw 0.8 lc rgb '#7799cc' title 'trajectory', "
            "'poincare.csv' every ::1 using ($3*%.12g):($4*%.12g) with points pt 7 ps 1.2 lc rgb '#cc2222' title 'Poincare'\n"
            "unset output\n",
            fmt[f][0], fmt[f][2], r->motion, r->poincare_distinct, m->bc_m * 1e6,
            m->bc_m * m->omega_n);
    }
    static const char *names[] = {"time_history", "phase"};
    return gd_gnuplot_draw(dir, script, names, 2, err);
}

void cli_response_pictures(const cli_case_args *a, const gd_case *c, const void *result, gd_run_dir *out,
                           const char **note)
{
    const gd_response_outcome *r = result;
    if (c->plots && gd_gnuplot_available())
        cli_local_draw(c, r, out);
    if (gd_gnuplot_wanted(c->plots && c->time_history, note)) {
        gd_error perr = {0};
        gd_status pst = draw(gd_run_dir_stage(out), c, &r->model, &r->res, &perr);
        static const char *pics[] = {"time_history.png", "time_history.svg", "phase.png", "phase.svg"};
        gd_gnuplot_drawn(pst, &perr, pics, 4, out);
    }
}

void cli_response_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    (void)c;
    const gd_response_result *res = &((const gd_response_outcome *)result)->res;
    if (a->quiet)
        return;
    printf("%s: %s, %s, RMS mesh acceleration %.6g m/s^2 (left %.6g, right %.6g)\n", dir, res->motion,
           gd_impact_regime_name(res->impact_regime[2]), res->rms_accel_mps2[2], res->rms_accel_mps2[0],
           res->rms_accel_mps2[1]);
    const gd_model *m = &((const gd_response_outcome *)result)->model;
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
