/* The `response` analysis on the command line: tables, event log, pictures, summary.json. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct run_out {
    const gd_model *m;
    gd_atomic_file th, pc, ev;
    int want_th, want_ev;
    int progress;
    long last_pct;
    cli_local local;
    int local_failed;
} run_out;

static int on_sample(void *user, const gd_sample *s)
{
    run_out *o = user;
    const gd_model *m = o->m;
    double vx, vxd;
    cli_variable_value(m, &o->local.var, s->t_s * m->omega_n, s->y, &vx, &vxd);
    o->local_failed |= cli_local_add_sample(&o->local, s->t_s, vx, vxd);
    if (!o->want_th)
        return 0;
    FILE *fp = o->th.fp;
    fprintf(fp, "%.12g,%ld", s->t_s, s->period);
    for (int j = 0; j < 2; j++)
        fprintf(fp, ",%.9g,%.9g,%.9g,%.9g,%.9g", s->lambda_um[j], s->lambda_dot_mps[j], s->accel_mps2[j],
                s->dte_um[j], s->force_n[j]);
    double um = m->bc_m * 1e6;
    for (int i = 0; i < m->ndof; i++)
        fprintf(fp, ",%.9g", s->y[i] * um);
    fputc('\n', fp);
    return 0;
}

static int on_poincare(void *user, long period, double t_s, const double *y)
{
    run_out *o = user;
    const gd_model *m = o->m;
    gd_modes md;
    memset(&md, 0, sizeof md);
    double t = t_s * m->omega_n;
    double vx, vxd;
    cli_variable_value(m, &o->local.var, t, y, &vx, &vxd);
    o->local_failed |= cli_local_add_poincare(&o->local, vx, vxd);
    fprintf(o->pc.fp, "%ld,%.12g", period, t_s);
    for (int j = 0; j < 2; j++) {
        int c = m->mesh_clear[j < m->nmesh ? j : 0];
        double x, xd;
        gd_model_clearance(m, c, t, y, &md, &x, &xd);
        fprintf(o->pc.fp, ",%.12g,%.12g", x, xd);
    }
    for (int i = 0; i < m->n; i++)
        fprintf(o->pc.fp, ",%.12g", y[i]);
    fputc('\n', o->pc.fp);
    return 0;
}

static int on_event(void *user, const gd_event *ev, int recording)
{
    run_out *o = user;
    if (o->want_ev)
        gd_eventlog_row(o->ev.fp, o->m, ev, recording);
    return 0;
}

static int on_progress(void *user, long done, long total)
{
    run_out *o = user;
    if (!o->progress)
        return 0;
    long pct = done * 100 / total;
    if (pct != o->last_pct || done == total) {
        fprintf(stderr, "\rgeardyn: %ld/%ld mesh periods (%ld%%)%s", done, total, pct, done == total ? "\n" : "");
        o->last_pct = pct;
    }
    return 0;
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
                     ", '%s/time_history.csv' every ::1 using ($1*1e3):($1 >= %.12g ? $8 : 1/0) with lines lw 1.5 "
                     "dt 2 title 'right half'", dir, t_from);
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '%s/.time_history%s.tmp'\n"
            "set title 'Relative mesh displacement, last %d mesh periods (%s, %s)'\n"
            "set xlabel 't (ms)'\nset ylabel 'mesh deflection {/Symbol l} (um)'\n"
            "plot '%s/time_history.csv' every ::1 using ($1*1e3):($1 >= %.12g ? $3 : 1/0) with lines lw 1.5 title '%s'%s\n"
            "unset output\n",
            fmt[f][0], dir, fmt[f][2], shown, r->motion, gd_impact_regime_name(r->impact_regime[2]), dir, t_from,
            two ? "left half" : "mesh", right);
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '%s/.phase%s.tmp'\n"
            "set title 'Phase portrait and Poincare section (%s, %d distinct points)'\n"
            "set xlabel 'mesh deflection {/Symbol l}_L (um)'\nset ylabel 'd{/Symbol l}_L/dt (m/s)'\n"
            "plot '%s/time_history.csv' every ::1 using 3:4 with lines lw 0.8 lc rgb '#7799cc' title 'trajectory', "
            "'%s/poincare.csv' every ::1 using ($3*%.12g):($4*%.12g) with points pt 7 ps 1.2 lc rgb '#cc2222' title 'Poincare'\n"
            "unset output\n",
            fmt[f][0], dir, fmt[f][2], r->motion, r->poincare_distinct, dir, dir, m->bc_m * 1e6,
            m->bc_m * m->omega_n);
    }
    static const char *names[] = {"time_history", "phase"};
    return gd_gnuplot_draw(dir, script, names, 2, err);
}

int run_response(const cli_case_args *a, gd_case *cp, const char *dir)
{
    gd_case c = *cp;
    gd_error err = {0};
    gd_model m;
    if (gd_model_build(&c, &m, &err) != GD_OK)
        return cli_fail(&err);
    run_out o;
    memset(&o, 0, sizeof o);
    if (cli_variable_resolve(&c, &m, &o.local.var, &err))
        return cli_fail(&err);
    if (gd_mkdir_p(dir, &err) != GD_OK)
        return cli_fail(&err);
    o.m = &m;
    o.want_th = c.time_history;
    o.want_ev = c.event_log;
    o.progress = !a->quiet && isatty(2);
    o.last_pct = -1;
    const char *files[24];
    int nfiles = 0;
    gd_status st = gd_atomic_open(&o.pc, dir, "poincare.csv", &err);
    if (st == GD_OK && o.want_th)
        st = gd_atomic_open(&o.th, dir, "time_history.csv", &err);
    if (st == GD_OK && o.want_ev)
        st = gd_atomic_open(&o.ev, dir, "events.csv", &err);
    if (st != GD_OK)
        goto fail;
    fprintf(o.pc.fp, "period,t_s,lambda_L,lambda_dot_L,lambda_R,lambda_dot_R");
    for (int i = 0; i < m.n; i++)
        fprintf(o.pc.fp, ",%s%s", m.dof_name[i % m.ndof], i < m.ndof ? "" : "_dot");
    fprintf(o.pc.fp, "\n");
    if (o.want_th) {
        fprintf(o.th.fp, "t_s,period");
        for (int j = 0; j < 2; j++) {
            char h = j ? 'R' : 'L';
            fprintf(o.th.fp, ",lambda_%c_um,lambda_dot_%c_mps,accel_%c_mps2,dte_%c_um,force_%c_n", h, h, h, h, h);
        }
        for (int i = 0; i < m.ndof; i++)
            fprintf(o.th.fp, ",%s_um", m.dof_name[i]);
        fprintf(o.th.fp, "\n");
    }
    if (o.want_ev)
        gd_eventlog_header(o.ev.fp);
    gd_response_hooks hooks = {on_sample, on_poincare, on_event, on_progress};
    gd_response_result res;
    st = gd_response_run(&c, &m, NULL, &hooks, &o, &res, &err);
    if (st != GD_OK)
        goto fail;
    st = gd_atomic_commit(&o.pc, &err);
    files[nfiles++] = "poincare.csv";
    if (st == GD_OK && o.want_th) {
        st = gd_atomic_commit(&o.th, &err);
        files[nfiles++] = "time_history.csv";
    }
    if (st == GD_OK && o.want_ev) {
        st = gd_atomic_commit(&o.ev, &err);
        files[nfiles++] = "events.csv";
    }
    if (st != GD_OK)
        goto fail;
    if (o.local_failed) {
        st = gd_error_set(&err, GD_ERR_NOMEM, "out of memory for the local analysis");
        goto fail;
    }
    st = cli_local_write(dir, &c, &m, &res, &o.local, files, &nfiles, c.plots && gd_gnuplot_available(), &err);
    if (st != GD_OK)
        goto fail;
    const char *note = NULL;
    if (gd_gnuplot_wanted(c.plots && o.want_th, &note)) {
        gd_error perr = {0};
        gd_status pst = draw(dir, &c, &m, &res, &perr);
        static const char *pics[] = {"time_history.png", "time_history.svg", "phase.png", "phase.svg"};
        gd_gnuplot_drawn(pst, &perr, pics, 4, files, &nfiles);
    }
    files[nfiles++] = "summary.json";
    st = gd_summary_write_response(dir, &c, &m, &res, files, nfiles, &err);
    if (st != GD_OK)
        goto fail;
    if (note && !a->quiet)
        fprintf(stderr, "geardyn: note: %s\n", note);
    cli_local_free(&o.local);
    if (!a->quiet) {
        printf("%s: %s, %s, RMS mesh acceleration %.6g m/s^2 (left %.6g, right %.6g)\n", dir, res.motion,
               gd_impact_regime_name(res.impact_regime[2]), res.rms_accel_mps2[2], res.rms_accel_mps2[0],
               res.rms_accel_mps2[1]);
        printf("  %ld steps, %ld RHS evaluations, %ld events, %.3f s\n", res.stats.steps, res.stats.rhs_evals,
               res.stats.events, res.wall_s);
    }
    return 0;
fail:
    cli_local_free(&o.local);
    gd_atomic_abort(&o.pc);
    gd_atomic_abort(&o.th);
    gd_atomic_abort(&o.ev);
    if (o.progress)
        fputc('\n', stderr);
    return cli_fail(&err);
}
