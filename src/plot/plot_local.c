/* The four-panel figure of the local analysis of one operating point (the paper's Figs. 16-42):
 * the chosen response variable's time history, phase portrait, amplitude spectrum and Poincare
 * section, drawn from the tables the response row wrote and from the samples in memory (the
 * curves through the samples). The time history and the phase portrait of time_history.png and
 * phase.png (plot_response.c) are drawn with the same view. */
#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The variable's quantity, the window of the time history and the axes of the phase plane. */
void gd_plot_local_view_of(const gd_case *c, const gd_response_outcome *ro, double width_px, gd_local_view *v)
{
    const gd_model *m = &ro->model;
    const gd_local *L = &ro->local;
    memset(v, 0, sizeof *v);
    int halves = m->nmesh;
    gd_qty_column(L->name, halves, &v->x);
    snprintf(v->x.unit, sizeof v->x.unit, "µm"); /* the samples are in um whatever the variable */
    char rate[64];
    snprintf(rate, sizeof rate, "%s_rate_mps", L->name);
    gd_qty_column(rate, halves, &v->v);
    gd_qty_label(&v->x, v->xlabel, sizeof v->xlabel);
    gd_qty_label(&v->v, v->vlabel, sizeof v->vlabel);
    /* the periods of the time history: enough for the motion's period (two of them), few enough
     * that the highest component of the spectrum within a third of the largest turns at most
     * every 16 pixels */
    double fm = m->mesh_freq_hz, amax = 0, kdom = 0.5;
    for (size_t k = 1; k < L->nfreq; k++)
        amax = fmax(amax, L->amp_um[k]);
    for (size_t k = 1; k < L->nfreq; k++)
        if (L->amp_um[k] >= amax / 3)
            kdom = fmax(kdom, L->freq_hz[k] / fm);
    int readable = (int)floor(width_px / (16.0 * kdom));
    int need = ro->res.period_n > 0 ? 2 * ro->res.period_n : 0;
    int shown = readable > 20 ? 20 : readable;
    if (shown < need)
        shown = need;
    if (shown < 1)
        shown = 1;
    if (shown > c->record_periods)
        shown = c->record_periods;
    v->shown = shown;
    double t_end = L->n ? L->t[L->n - 1] : 0;
    double t_from = t_end - shown / fm;
    v->i0 = 0;
    while (v->i0 + 1 < L->n && L->t[v->i0] < t_from - 1e-12 / fm)
        v->i0++;
    /* the phase plane: the last 40 periods at most (a period-n orbit is drawn over and over) */
    int phase_periods = c->record_periods < 40 ? c->record_periods : 40;
    double p_from = t_end - phase_periods / fm;
    v->p0 = 0;
    while (v->p0 + 1 < L->n && L->t[v->p0] < p_from - 1e-12 / fm)
        v->p0++;
    double xlo = INFINITY, xhi = -INFINITY, vlo = INFINITY, vhi = -INFINITY;
    for (size_t i = 0; i < L->n; i++) {
        xlo = fmin(xlo, L->x[i]);
        xhi = fmax(xhi, L->x[i]);
        vlo = fmin(vlo, L->xd[i]);
        vhi = fmax(vhi, L->xd[i]);
    }
    for (size_t i = 0; i < L->np; i++) {
        xlo = fmin(xlo, L->px[i]);
        xhi = fmax(xhi, L->px[i]);
        vlo = fmin(vlo, L->pxd[i]);
        vhi = fmax(vhi, L->pxd[i]);
    }
    if (!(xhi >= xlo))
        xlo = xhi = vlo = vhi = 0;
    gd_pad(xlo, xhi, 0.07, 0, &v->xlo, &v->xhi);
    gd_pad(vlo, vhi, 0.07, 0, &v->vlo, &v->vhi);
    v->t_from_ms = 1e3 * L->t[v->i0];
    v->t_end_ms = 1e3 * t_end;
    if (!(v->t_end_ms > v->t_from_ms))
        v->t_end_ms = v->t_from_ms + 1;
}

/* The data blocks of the view: $TH the time history's window, $PH the phase portrait's periods,
 * each the samples and the curve through them. */
void gd_plot_local_blocks(gd_plot_script *s, const gd_response_outcome *ro, const gd_local_view *v)
{
    const gd_local *L = &ro->local;
    /* t in ms, x in um, v in m/s: dx/dt in um/ms = 1e3 * v (m/s) */
    size_t n = L->n;
    double *t = malloc((n ? n : 1) * sizeof *t);
    if (!t) {
        s->bad = 1;
        return;
    }
    for (size_t i = 0; i < n; i++)
        t[i] = 1e3 * L->t[i];
    gd_hermite_block(s, "TH", t, L->x, L->xd, v->i0, n, 1e3);
    gd_hermite_block(s, "PH", t, L->x, L->xd, v->p0, n, 1e3);
    free(t);
}

/* The time history panel: the window of the last periods, over exactly that window. */
void gd_plot_local_time_panel(gd_plot_script *s, const gd_local_view *v, const char *title, const char *key,
                          const char *more)
{
    gd_plot_printf(s, "set title '%s'\nset xlabel 'time t (ms)'\nset ylabel '%s'\n", title, v->xlabel);
    gd_plot_printf(s, "set xrange [%.12g:%.12g]\nset yrange [*:*]\n", v->t_from_ms, v->t_end_ms);
    gd_plot_printf(s, "plot $TH using 1:2 with lines lw 1.3 lc rgb '%s' ", gd_colour[4]);
    if (key)
        gd_plot_printf(s, "title '%s'", key);
    else
        gd_plot_printf(s, "notitle");
    gd_plot_printf(s, "%s\n", more ? more : "");
    gd_plot_printf(s, "set xrange [*:*]\nset yrange [*:*]\n");
}

/* The phase portrait panel: the curve through the samples of the last periods and, when wanted,
 * the Poincare points over it. */
void gd_plot_local_phase_panel(gd_plot_script *s, const gd_response_outcome *ro, const gd_local_view *v,
                           const char *title, int with_poincare)
{
    (void)ro;
    gd_plot_printf(s, "set title '%s'\nset xlabel '%s'\nset ylabel '%s'\n", title, v->xlabel, v->vlabel);
    gd_plot_printf(s, "set xrange [%.9g:%.9g]\nset yrange [%.9g:%.9g]\n", v->xlo, v->xhi, v->vlo, v->vhi);
    gd_plot_printf(s, "plot $PH using 2:3 with lines lw 0.8 lc rgb '%s' %s", gd_colour[4],
                      with_poincare > 1 ? "title 'trajectory (the last periods)'" : "notitle");
    if (with_poincare)
        gd_plot_printf(s, ", 'variable_poincare.csv' using 1:2 with points pt 7 ps 0.7 lc rgb '%s' %s",
                          gd_colour[5], with_poincare > 1 ? "title 'Poincaré points'" : "notitle");
    gd_plot_printf(s, "\nset xrange [*:*]\nset yrange [*:*]\n");
}

/* "period-1, single-sided impacts, largest Lyapunov exponent -0.213 per mesh period" */
void gd_plot_local_motion(const gd_response_result *r, char *buf, size_t len)
{
    static const char *impacts[] = {"no impacts", "single-sided impacts", "double-sided impacts"};
    int reg = r->impact_regime[2];
    int k = snprintf(buf, len, "%s, %s", r->motion, reg >= 0 && reg <= 2 ? impacts[reg] : "impacts unknown");
    if (r->n_lyapunov && k > 0 && (size_t)k < len)
        snprintf(buf + k, len - (size_t)k, ", largest Lyapunov exponent %.3g per mesh period", r->mle_per_period);
}

/* The spectrum panel: impulses up to the order that holds the largest component and those near
 * it, a frequency axis of round values on top. */
static void spectrum_panel(gd_plot_script *s, const gd_case *c, const gd_response_outcome *ro,
                           const gd_local_view *v)
{
    const gd_local *L = &ro->local;
    double fm = ro->model.mesh_freq_hz, amax = 0, kmax = 0, klast = 0;
    for (size_t k = 1; k < L->nfreq; k++)
        if (L->amp_um[k] > amax) {
            amax = L->amp_um[k];
            kmax = L->freq_hz[k] / fm;
        }
    for (size_t k = 1; k < L->nfreq; k++)
        if (L->amp_um[k] >= 1e-2 * amax)
            klast = L->freq_hz[k] / fm;
    double nyq = c->samples_per_period / 2.0;
    double top = fmax(kmax + 2, klast + 1);
    if (top < 5)
        top = 5;
    double step = gd_nice_step(top, 8);
    top = ceil(top / step) * step;
    if (top > nyq)
        top = nyq;
    /* the components of a millionth of the largest and more, the axis down to a third of the
     * smallest of them drawn (so that each stands above the axis's end) */
    double cut = amax > 0 ? 1e-6 * amax : 1e-12, ytop = amax > 0 ? amax * 4 : 1, amin = amax > 0 ? amax : 1;
    for (size_t k = 1; k < L->nfreq && L->freq_hz[k] / fm <= top + 0.25; k++)
        if (L->amp_um[k] >= cut && L->amp_um[k] < amin)
            amin = L->amp_um[k];
    double floor_amp = amin / 3;
    char name[200];
    gd_gp_text(v->x.name, name, sizeof name);
    gd_plot_printf(s, "set title 'Amplitude spectrum of the %d recorded mesh periods (Hann window)'\n",
                      c->record_periods);
    gd_plot_printf(s, "set xlabel 'order of the mesh frequency f_m = %.4g Hz (-)'\n", fm);
    if (v->x.sym[0])
        gd_plot_printf(s, "set ylabel 'amplitude of %s (µm)'\n", v->x.sym);
    else
        gd_plot_printf(s, "set ylabel 'amplitude of the %s (µm)'\n", name);
    gd_plot_printf(s, "set xrange [%.6g:%.6g]\nset logscale y\nset format y '%s'\nset yrange [%.6g:%.6g]\n",
                      -0.5, top + 0.5, ytop / floor_amp >= 100 ? "10^{%L}" : "%g", floor_amp, ytop);
    double fstep = gd_nice_step(top * fm, 6);
    gd_plot_printf(s, "set link x2\nset x2tics out nomirror (");
    int first = 1;
    for (double f = 0; f <= top * fm * (1 + 1e-9); f += fstep) {
        gd_plot_printf(s, "%s'%.6g' %.12g", first ? "" : ", ", f, f / fm);
        first = 0;
    }
    gd_plot_printf(s, ")\nset xtics nomirror\nset x2label 'frequency f (Hz)'\n");
    gd_plot_printf(s, "plot 'spectrum.csv' using 'order':(column('amplitude_um') >= %.9g && column('order') <= %.6g ? "
                         "column('amplitude_um') : 1/0) with impulses lw 1.5 lc rgb '%s' notitle\n", cut,
                      top + 0.25, gd_colour[4]);
    gd_plot_printf(s, "unset logscale y\nset format y '%% h'\nset yrange [*:*]\nset xrange [*:*]\nunset x2tics\n"
                         "unset x2label\nunset link x2\nset xtics mirror\n");
}

void gd_plot_local_draw(const gd_plotter *pl, const gd_case *c, const gd_response_outcome *ro)
{
    const gd_response_result *r = &ro->res;
    const gd_local *L = &ro->local;
    gd_local_view v;
    gd_plot_local_view_of(c, ro, 600, &v);
    char motion[200], name[200], title[400];
    gd_plot_local_motion(r, motion, sizeof motion);
    gd_qty_label(&v.x, name, sizeof name);
    /* the variable's name, its unit off, its first letter up */
    char *paren = strrchr(name, '(');
    if (paren && paren > name)
        paren[-1] = '\0';
    if (name[0] >= 'a' && name[0] <= 'z')
        name[0] = (char)(name[0] - 'a' + 'A');
    snprintf(title, sizeof title, "%s: %s", name, motion);
    gd_plot_script s = {0};
    gd_plot_local_blocks(&s, ro, &v);
    char section[160];
    if (r->poincare_distinct == 1)
        snprintf(section, sizeof section, "Poincaré section at mesh phase 0: %zu returns to one point", L->np);
    else
        snprintf(section, sizeof section, "Poincaré section at mesh phase 0: %zu returns, %d distinct", L->np,
                 r->poincare_distinct);
    double pxl = INFINITY, pxh = -INFINITY, pvl = INFINITY, pvh = -INFINITY;
    for (size_t i = 0; i < L->np; i++) {
        pxl = fmin(pxl, L->px[i]);
        pxh = fmax(pxh, L->px[i]);
        pvl = fmin(pvl, L->pxd[i]);
        pvh = fmax(pvh, L->pxd[i]);
    }
    if (pxh > pxl && pvh > pvl) {
        gd_pad(pxl, pxh, 0.1, 0, &pxl, &pxh);
        gd_pad(pvl, pvh, 0.1, 0, &pvl, &pvh);
    }
    char thtitle[120];
    snprintf(thtitle, sizeof thtitle, "Time history, the last %d mesh period%s", v.shown, v.shown == 1 ? "" : "s");
    for (int k = 0; k < 2; k++) {
        gd_fig_begin(&s, k, 1400, 1000, "response");
        gd_plot_printf(&s, "set multiplot layout 2,2 title '%s'\n", title);
        gd_plot_local_time_panel(&s, &v, thtitle, NULL, NULL);
        gd_plot_local_phase_panel(&s, ro, &v, "Phase portrait, the last periods, and the Poincaré points", 1);
        spectrum_panel(&s, c, ro, &v);
        gd_plot_printf(&s, "set title '%s'\nset xlabel '%s'\nset ylabel '%s'\n", section, v.xlabel, v.vlabel);
        /* a cloud of points that spreads over a twentieth of the phase portrait at least: its own
         * extent; a few, or a tight cloud (a periodic orbit's, whose scatter is the integration's
         * noise, or a slowly converging one's): the axes of the phase portrait */
        if (r->poincare_distinct > 8 && pxh - pxl > 0.05 * (v.xhi - v.xlo) && pvh - pvl > 0.05 * (v.vhi - v.vlo))
            gd_plot_printf(&s, "set xrange [%.9g:%.9g]\nset yrange [%.9g:%.9g]\n", pxl, pxh, pvl, pvh);
        else
            gd_plot_printf(&s, "set xrange [%.9g:%.9g]\nset yrange [%.9g:%.9g]\n", v.xlo, v.xhi, v.vlo, v.vhi);
        gd_plot_printf(&s, "plot 'variable_poincare.csv' using 1:2 with points pt 7 ps 0.9 lc rgb '%s' notitle\n",
                          gd_colour[5]);
        gd_fig_end(&s, 1);
    }
    static const char *names[] = {"response"};
    gd_plot_draw(pl, &s, names, 1, "the four-panel picture was not drawn");
}
