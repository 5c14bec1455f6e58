/* The four-panel figure of the local analysis of one operating point (the paper's Figs. 16-42):
 * the chosen response variable's time history, phase portrait, amplitude spectrum and Poincare
 * section, drawn from the tables the response row wrote. */
#include "cli.h"

#include <stdio.h>

/* The four panels (PNG and SVG), drawn under temporary names then renamed; a failure is a note. */
void cli_local_draw(const gd_case *c, const gd_response_outcome *ro, gd_run_dir *out)
{
    const char *dir = gd_run_dir_stage(out);
    const gd_model *m = &ro->model;
    const gd_response_result *r = &ro->res;
    const gd_local *L = &ro->local;
    int shown = c->record_periods < 20 ? c->record_periods : 20;
    double t_end = L->n ? L->t[L->n - 1] : 0, t_from = t_end - shown / m->mesh_freq_hz;
    double fmax_order = c->samples_per_period / 2.0 < 10 ? c->samples_per_period / 2.0 : 10;
    static const char *fmt[2][2] = {{"pngcairo size 1400,1000 font ',11'", ".png"},
                                    {"svg size 1400,1000 dynamic font 'sans,11'", ".svg"}};
    char script[8192];
    int n = 0;
    const char *v = L->name;
    double floor_amp = L->spec_amax > 0 ? 1e-6 * L->spec_amax : 1e-12;
    /* the Poincare section in the axes of the phase portrait (a zoom onto a converged point
     * would only show the integration noise) */
    double xlo = 0, xhi = 0, vlo = 0, vhi = 0;
    for (size_t i = 0; i < L->n; i++) {
        if (i == 0 || L->x[i] < xlo) xlo = L->x[i];
        if (i == 0 || L->x[i] > xhi) xhi = L->x[i];
        if (i == 0 || L->xd[i] < vlo) vlo = L->xd[i];
        if (i == 0 || L->xd[i] > vhi) vhi = L->xd[i];
    }
    double px = 0.05 * (xhi - xlo) + 1e-9, pv = 0.05 * (vhi - vlo) + 1e-12;
    xlo -= px;
    xhi += px;
    vlo -= pv;
    vhi += pv;
    for (int k = 0; k < 2; k++) {
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '.response%s.tmp'\nset datafile separator ','\n"
            "set multiplot layout 2,2 title '%s: %s, %s, largest Lyapunov exponent %.4g per mesh period'\n"
            "set grid\nunset key\n"
            "set title 'Time history (last %d mesh periods)'\nset xlabel 't (ms)'\nset ylabel '%s (um)'\n"
            "set xrange [%.12g:%.12g]\n"
            "plot 'variable.csv' every ::1 using ($1*1e3):($1 >= %.12g ? $2 : 1/0) with lines lw 1.2\n"
            "set xrange [*:*]\n"
            "set title 'Phase portrait'\nset xlabel '%s (um)'\nset ylabel 'rate (m/s)'\n"
            "plot 'variable.csv' every ::1 using 2:3 with lines lw 0.6 lc rgb '#4477aa', "
            "'variable_poincare.csv' every ::1 using 1:2 with points pt 7 ps 0.8 lc rgb '#cc2222'\n"
            "set title 'Amplitude spectrum (Hann window)'\nset xlabel 'order of the mesh frequency (%.6g Hz)'\n"
            "set ylabel 'amplitude (um)'\nset xrange [0:%g]\nset x2tics\nset x2label 'frequency (Hz)'\n"
            "set link x2 via x*%.12g inverse x/%.12g\nset logscale y\nset format y '%%g'\nset yrange [%.6g:*]\n"
            "plot 'spectrum.csv' every ::1 using 2:($3 > %.6g ? $3 : %.6g) with impulses lw 1.5\n"
            "unset logscale y\nset yrange [*:*]\nunset x2tics\nunset x2label\nunset link x2\nset xrange [*:*]\n"
            "set xrange [%.9g:%.9g]\nset yrange [%.9g:%.9g]\n"
            "set title 'Poincare section (%d distinct points)'\nset xlabel '%s (um)'\nset ylabel 'rate (m/s)'\n"
            "plot 'variable_poincare.csv' every ::1 using 1:2 with points pt 7 ps 0.8 lc rgb '#cc2222'\n"
            "unset multiplot\nunset output\nset xrange [*:*]\nset yrange [*:*]\n",
            fmt[k][0], fmt[k][1], v, r->motion, gd_impact_regime_name(r->impact_regime[2]),
            r->n_lyapunov ? r->mle_per_period : 0.0 / 0.0, shown, v, 1e3 * t_from, 1e3 * t_end, t_from, v,
            m->mesh_freq_hz, fmax_order, m->mesh_freq_hz, m->mesh_freq_hz, floor_amp, floor_amp, floor_amp,
            xlo, xhi, vlo, vhi, r->poincare_distinct, v);
    }
    gd_error perr = {0};
    static const char *names[] = {"response"};
    if (gd_gnuplot_draw(dir, script, names, 1, &perr) == GD_OK) {
        gd_run_dir_add(out, "response.png", NULL);
        gd_run_dir_add(out, "response.svg", NULL);
    } else {
        fprintf(stderr, "geardyn: note: the four-panel picture was not drawn: %s\n", perr.msg);
    }
}

