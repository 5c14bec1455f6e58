/* The `response` analysis on the command line: the progress line, the pictures of the time
 * history and the phase portrait with the Poincare section of output.response_variable, and the
 * summary lines. */
#include "cli.h"
#include "figure.h"

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

/* Draw time_history.png (the variable of the local analysis over the last periods, and on a
 * herringbone the same variable of the other half) and phase.png (its phase portrait and
 * Poincare points), both of output.response_variable as response.png. */
static gd_status draw(const char *dir, const gd_case *c, const gd_response_outcome *ro, gd_error *err)
{
    const gd_local *L = &ro->local;
    const gd_response_result *r = &ro->res;
    int halves = ro->model.nmesh;
    cli_local_view v;
    cli_local_view_of(c, ro, 1050, &v);
    /* the other half's column of time_history.csv: lambda_L -> lambda_R_um, y1L -> y1R_um */
    char other[48] = "";
    size_t ln = strlen(L->name);
    char side = ln ? L->name[ln - 1] : 0;
    if (halves > 1 && (side == 'L' || side == 'R')) {
        snprintf(other, sizeof other, "%.*s%c_um", (int)(ln - 1), L->name, side == 'L' ? 'R' : 'L');
    }
    if (other[0]) {
        /* both halves drawn: the quantity without a side, each half in the key */
        char base[48];
        snprintf(base, sizeof base, "%.*s", (int)(ln - 1), L->name);
        if (base[0] && base[strlen(base) - 1] == '_')
            base[strlen(base) - 1] = '\0';
        cli_qty q;
        cli_qty_column(base, halves, &q);
        snprintf(q.unit, sizeof q.unit, "µm");
        cli_qty_label(&q, v.xlabel, sizeof v.xlabel);
    }
    char motion[200], title[300], more[400] = "";
    cli_local_motion(r, motion, sizeof motion);
    if (other[0])
        snprintf(more, sizeof more, ", 'time_history.csv' using (column('t_s')*1e3):(column('t_s')*1e3 >= %.12g ? "
                 "column('%s') : 1/0) with lines lw 1.3 dt 2 lc rgb '%s' title '%s'", v.t_from_ms - 1e-9, other,
                 cli_colour[5], cli_half_words(side == 'L', halves));
    gd_gnuplot_script s = {0};
    cli_local_blocks(&s, ro, &v);
    for (int f = 0; f < 2; f++) {
        cli_fig_begin(&s, f, 1200, 700, "time_history");
        snprintf(title, sizeof title, "Time history, the last %d mesh period%s: %s", v.shown, v.shown == 1 ? "" : "s",
                 motion);
        gd_gnuplot_printf(&s, "set key outside top center horizontal\n");
        cli_local_time_panel(&s, &v, title, other[0] ? cli_half_words(side == 'R', halves) : NULL,
                             other[0] ? more : NULL);
        cli_fig_end(&s, 0);
        cli_fig_begin(&s, f, 1000, 800, "phase");
        char pt[300];
        if (r->poincare_distinct == 1)
            snprintf(pt, sizeof pt, "Phase portrait and Poincaré section (%s; %zu returns to one point)", r->motion,
                     L->np);
        else
            snprintf(pt, sizeof pt, "Phase portrait and Poincaré section (%s; %zu returns, %d distinct)", r->motion,
                     L->np, r->poincare_distinct);
        gd_gnuplot_printf(&s, "set key outside top center horizontal\n");
        cli_local_phase_panel(&s, ro, &v, pt, 2);
        cli_fig_end(&s, 0);
    }
    if (s.bad) {
        free(s.p);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the gnuplot script");
    }
    static const char *names[] = {"time_history", "phase"};
    gd_status st = gd_gnuplot_draw(dir, s.p, names, 2, err);
    free(s.p);
    return st;
}

void cli_response_pictures(const cli_case_args *a, const gd_case *c, const void *result, gd_run_dir *out,
                           const char **note)
{
    const gd_response_outcome *r = result;
    if (c->plots && gd_gnuplot_available())
        cli_local_draw(c, r, out);
    if (gd_gnuplot_wanted(c->plots && c->time_history, note)) {
        gd_error perr = {0};
        gd_status pst = draw(gd_run_dir_stage(out), c, r, &perr);
        static const char *pics[] = {"time_history.png", "time_history.svg", "phase.png", "phase.svg"};
        gd_gnuplot_drawn(pst, &perr, pics, 4, out);
    }
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
