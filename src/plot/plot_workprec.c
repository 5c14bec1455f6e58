/* The pictures of `work-precision` (docs/accuracy.md): the work-precision diagrams. */
#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


static double clampe(double v) { return isfinite(v) ? fmax(v, 1e-16) : NAN; }

/* The value of column col (1-based, as in the data blocks of draw) of a run. */
static double column(const gd_wp_run *r, int col, int chaotic)
{
    switch (col) {
    case 1: return r->cpu_s;
    case 2: return (double)r->rhs_evals / (double)r->periods;
    case 3: return clampe(chaotic ? r->err_short : r->err_poincare);
    case 4: return clampe(r->err_rms);
    case 5: return clampe(r->err_events);
    default: return clampe(r->err_mle);
    }
}

/* A point drawn on log axes: positive, and an error of 10 at most (a run that went unstable has
 * errors of 1e20: left out, the axes kept on the accurate ones). */
static int drawn(double x, double y)
{
    return isfinite(x) && x > 0 && isfinite(y) && y > 0 && y <= 10;
}

/* A family of methods as a picture names it: "ERK order 5", "RK4 (fixed steps)", and its twin
 * ", events not located". */
static void family_words(const gd_wp_family *F, char *buf, size_t len)
{
    const char *kind = F->method == GD_METHOD_RK4 ? "RK4"
                     : F->method == GD_METHOD_DIRK ? "DIRK order"
                                                   : F->fixed ? "ERK, fixed steps, order" : "ERK order";
    if (F->method == GD_METHOD_RK4)
        snprintf(buf, len, "%s%s", kind, F->root_finding ? "" : ", events not located");
    else
        snprintf(buf, len, "%s %d%s", kind, F->order, F->root_finding ? "" : ", events not located");
}

/* The base family of f (a family and its root-finding-off twin share colour and marker): the
 * index of its method and order among the distinct ones, in the order of the families. */
static int base_index(const gd_wp_result *res, int f)
{
    int k = 0;
    for (int g = 0; g < f; g++) {
        const gd_wp_family *G = &res->families[g];
        int seen = 0;
        for (int h = 0; h < g; h++)
            seen |= res->families[h].method == G->method && res->families[h].order == G->order &&
                    res->families[h].fixed == G->fixed;
        if (seen)
            continue;
        if (G->method == res->families[f].method && G->order == res->families[f].order &&
            G->fixed == res->families[f].fixed)
            return k;
        k++;
    }
    return k;
}

/* filled markers whose open twin is the next lower type (root finding off); six of them against the
 * seven colours, so that no two of 42 families share colour and marker */
static const int markers[] = {7, 5, 9, 11, 13, 15};

/* The data blocks of the script: $Fi per family (the columns of column()), $Ok per order study. */
static void script_data(gd_plot_script *b, const gd_wp_result *res)
{
    int chaotic = res->ref.chaotic;
    for (int f = 0; f < res->nfamilies; f++) {
        gd_plot_printf(b, "$F%d << EOD\ncpu,rhs,e3,e4,e5,e6\n", f);
        for (int i = 0; i < res->nruns; i++) {
            const gd_wp_run *r = &res->runs[i];
            if (r->family != f || r->status != GD_WP_OK)
                continue;
            for (int col = 1; col <= 6; col++) {
                double v = column(r, col, chaotic);
                if (col >= 3 && !drawn(1, v))
                    v = NAN;
                gd_plot_printf(b, col > 1 ? ",%.6g" : "%.6g", v);
            }
            gd_plot_printf(b, "\n");
        }
        gd_plot_printf(b, "EOD\n");
    }
    for (int k = 0; k < res->norders; k++) {
        gd_plot_printf(b, "$O%d << EOD\nsteps,err\n", k);
        const gd_wp_order *O = &res->orders[k];
        for (int l = 0; l < O->nlevels; l++)
            if (drawn(O->steps[l], clampe(O->err[l])))
                gd_plot_printf(b, "%d,%.6g\n", O->steps[l], clampe(O->err[l]));
        gd_plot_printf(b, "EOD\n");
    }
}

/* The log ranges of a panel: its points, padded. */
static void panel_ranges(const gd_wp_result *res, int xcol, int ycol, double *x0, double *x1, double *y0, double *y1)
{
    double xl = INFINITY, xh = -INFINITY, yl = INFINITY, yh = -INFINITY;
    for (int i = 0; i < res->nruns; i++) {
        const gd_wp_run *r = &res->runs[i];
        if (r->status != GD_WP_OK)
            continue;
        double x = column(r, xcol, res->ref.chaotic), y = column(r, ycol, res->ref.chaotic);
        if (drawn(x, y)) {
            xl = fmin(xl, x);
            xh = fmax(xh, x);
            yl = fmin(yl, y);
            yh = fmax(yh, y);
        }
    }
    if (ycol == 3 && res->ref.floor > 0) {
        yl = fmin(yl, res->ref.floor);
        yh = fmax(yh, res->ref.floor);
    }
    if (!(xh >= xl))
        xl = xh = 1;
    if (!(yh >= yl))
        yl = yh = 1;
    gd_pad(xl, xh, 0.05, 1, x0, x1);
    gd_pad(yl, yh, 0.07, 1, y0, y1);
}

/* The diagrams: error against CPU time (and RHS evaluations), one line per family (root
 * finding off dashed), the order study, and one key for all in a cell of its own. */
static void draw(const gd_plotter *pl, const gd_case *c, const gd_wp_result *res)
{
    gd_plot_script b = {0};
    int chaotic = res->ref.chaotic;
    script_data(&b, res);
    char title[600], refm[200], what[160];
    if (c->title[0])
        gd_gp_title(c->title, title, sizeof title);
    else
        gd_gp_text(c->path, title, sizeof title);
    /* the reference: its method without the table's code name */
    snprintf(refm, sizeof refm, "%s", res->ref.method);
    char *paren = strchr(refm, '(');
    char *close = paren ? strchr(paren, ')') : NULL;
    if (paren && close)
        memmove(paren > refm && paren[-1] == ' ' ? paren - 1 : paren, close + 1, strlen(close + 1) + 1);
    char *eq = strstr(refm, "rtol=");
    if (eq)
        eq[4] = ' ';
    if (strcmp(res->ref.motion, chaotic ? "chaotic" : "periodic") == 0 || strncmp(res->ref.motion, "period", 6) == 0)
        snprintf(what, sizeof what, "%s", res->ref.motion);
    else
        snprintf(what, sizeof what, "%s, treated as %s", res->ref.motion, chaotic ? "chaotic" : "periodic");
    char ytraj[160], ttraj[160];
    if (chaotic) {
        snprintf(ytraj, sizeof ytraj, "error of the trajectory, first %ld periods (-)", res->horizon_periods);
        snprintf(ttraj, sizeof ttraj, "the trajectory over the first %ld periods", res->horizon_periods);
    } else {
        snprintf(ytraj, sizeof ytraj, "error of the Poincaré points, %ld periods (-)", res->window_periods);
        snprintf(ttraj, sizeof ttraj, "the Poincaré points of %ld periods", res->window_periods);
    }
    struct {
        int xcol, ycol;
        const char *xl, *yl;
        char t[200];
    } panels[6];
    int np = chaotic && c->wp_lyapunov ? 5 : 4;
    for (int p = 0; p < 5; p++) {
        panels[p].xcol = p == 1 ? 2 : 1;
        panels[p].ycol = p < 2 ? 3 : p + 2;
        panels[p].xl = p == 1 ? "RHS evaluations per mesh period" : "CPU time (s)";
    }
    panels[0].yl = panels[1].yl = ytraj;
    snprintf(panels[0].t, sizeof panels[0].t, "%s against CPU time", ttraj);
    snprintf(panels[1].t, sizeof panels[1].t, "%s against RHS evaluations", ttraj);
    panels[2].yl = "relative error of the RMS acceleration (-)";
    snprintf(panels[2].t, sizeof panels[2].t, "the RMS mesh acceleration");
    panels[3].yl = chaotic ? "error of the event times, short horizon (mesh periods)" : "error of the event times (mesh periods)";
    snprintf(panels[3].t, sizeof panels[3].t, "the times of the contact events");
    panels[4].yl = "error of the largest Lyapunov exponent (per mesh period)";
    snprintf(panels[4].t, sizeof panels[4].t, "the largest Lyapunov exponent");
    int norder = res->norders > 0;
    int cells = np + norder, cols = 2, rows = (cells + 1 + 1) / 2; /* + the key's cell */
    int key_own_column = 0;
    if (cells % 2 == 0) { /* no free cell: the key in a column of its own */
        rows = cells / 2;
        key_own_column = 1;
    }
    double pw = 640, ph = 440, keyw = gd_text_width("method (solid: events located; dashed: not)", GD_FIG_PX);
    for (int f = 0; f < res->nfamilies; f++) {
        char words[120];
        family_words(&res->families[f], words, sizeof words);
        keyw = fmax(keyw, gd_text_width(words, GD_FIG_PX) + gd_text_width("; order 0.00", GD_FIG_PX) + 60);
    }
    int Wd = (int)(cols * pw + 30 + (key_own_column ? keyw + 30 : 0)), Hd = (int)(rows * ph + 70);
    /* the key in one column (gnuplot would break it into columns at the height of the panel it is
     * set in, running off the picture), the picture tall enough for it: its title and an entry
     * per family and for the reference's floor, 18.75 px a line at spacing 1 */
    int nkey = res->nfamilies + (res->ref.floor > 0);
    double key_top = key_own_column ? 100 : 70 + (cells / 2) * ph + 30;
    Hd = (int)fmax(Hd, key_top + (nkey + 1) * 18.75 * 1.15 + 20);
    for (int fm = 0; fm < 2; fm++) {
        gd_fig_begin(&b, fm, Wd, Hd, "work_precision");
        gd_plot_printf(&b, "set multiplot title '%s: %s; reference %s, its floor %.1e'\n", title, what, refm,
                          res->ref.floor);
        gd_plot_printf(&b, "set logscale xy\n");
        for (int cell = 0; cell < cells; cell++) {
            int col = cell % 2, row = cell / 2;
            double l = (30 + col * pw + 95) / Wd, r = (30 + (col + 1) * pw - 25) / Wd;
            double t = 1 - (70 + row * ph + 30) / Hd, bt = 1 - (70 + (row + 1) * ph - 75) / Hd;
            gd_plot_printf(&b, "set lmargin at screen %.5f\nset rmargin at screen %.5f\nset tmargin at screen %.5f\n"
                                  "set bmargin at screen %.5f\n", l, r, t, bt);
            gd_plot_printf(&b, "unset key\n");
            int pr = cell < np ? cell : -1;
            double x0, x1, y0, y1;
            if (pr >= 0) {
                panel_ranges(res, panels[pr].xcol, panels[pr].ycol, &x0, &x1, &y0, &y1);
                gd_plot_printf(&b, "set xlabel '%s'\nset ylabel '%s'\nset title 'Error of %s'\n", panels[pr].xl,
                                  panels[pr].yl, panels[pr].t);
            } else {
                double sl = INFINITY, sh = -INFINITY, el = INFINITY, eh = -INFINITY;
                for (int k = 0; k < res->norders; k++)
                    for (int lv = 0; lv < res->orders[k].nlevels; lv++) {
                        double e = clampe(res->orders[k].err[lv]);
                        if (drawn(res->orders[k].steps[lv], e)) {
                            sl = fmin(sl, res->orders[k].steps[lv]);
                            sh = fmax(sh, res->orders[k].steps[lv]);
                            el = fmin(el, e);
                            eh = fmax(eh, e);
                        }
                    }
                if (!(sh >= sl))
                    sl = sh = el = eh = 1;
                gd_pad(sl, sh, 0.05, 1, &x0, &x1);
                gd_pad(el, eh, 0.07, 1, &y0, &y1);
                gd_plot_printf(&b, "set xlabel 'steps per mesh period (fixed steps)'\nset ylabel 'error of the "
                                      "Poincaré points, first %ld periods (-)'\nset title 'Order study: the error "
                                      "against the step'\n", res->horizon_periods);
            }
            gd_plot_printf(&b, "set xrange [%.6g:%.6g]\nset yrange [%.6g:%.6g]\n", x0, x1, y0, y1);
            gd_log_tics(&b, "x", x0, x1);
            gd_log_tics(&b, "y", y0, y1);
            gd_plot_printf(&b, "plot ");
            int first = 1;
            for (int f = 0; f < res->nfamilies; f++) {
                const gd_wp_family *F = &res->families[f];
                int bi = base_index(res, f);
                const char *colour = gd_colour[bi % GD_NCOLOURS];
                int pt = markers[bi % 6] - (F->root_finding ? 0 : 1);
                if (pr >= 0) {
                    gd_plot_printf(&b, "%s$F%d using %d:%d with linespoints lc rgb '%s' lw 1.3 dt %d pt %d ps 0.9 ",
                                      first ? "" : ", ", f, panels[pr].xcol, panels[pr].ycol, colour,
                                      F->root_finding ? 1 : 2, pt);
                } else {
                    int k = 0;
                    while (k < res->norders && res->orders[k].family != f)
                        k++;
                    if (k == res->norders)
                        continue;
                    gd_plot_printf(&b, "%s$O%d using 1:2 with linespoints lc rgb '%s' lw 1.3 dt %d pt %d ps 0.9 ",
                                      first ? "" : ", ", k, colour, F->root_finding ? 1 : 2, pt);
                }
                gd_plot_printf(&b, "notitle");
                first = 0;
            }
            if (first)
                gd_plot_printf(&b, "1/0 notitle");
            if (pr >= 0 && panels[pr].ycol == 3 && res->ref.floor > 0)
                gd_plot_printf(&b, ", %.6g with lines lc rgb '#777777' dt 3 lw 1.2 notitle", res->ref.floor);
            gd_plot_printf(&b, "\n");
        }
        /* the key: an empty plot of its own over the key's place, as tall as the key (gnuplot breaks a
         * key into columns at the height of the plot it belongs to, and a panel is shorter) */
        double kx = key_own_column ? 30 + cols * pw + 10 : 30 + (cells % 2) * pw + 60;
        gd_plot_printf(&b, "set lmargin at screen %.5f\nset rmargin at screen %.5f\nset tmargin at screen %.5f\n"
                           "set bmargin at screen %.5f\n", kx / Wd, fmin(kx + keyw, Wd - 5.0) / Wd, 1 - key_top / Hd,
                       10.0 / Hd);
        gd_plot_printf(&b, "unset border\nunset tics\nunset grid\nunset xlabel\nunset ylabel\nunset title\n"
                           "unset logscale\nset xrange [0:1]\nset yrange [0:1]\n");
        gd_plot_printf(&b, "set key at screen %.5f,%.5f left top vertical Left reverse samplen 3 spacing %.4f "
                           "title 'method (solid: events located; dashed: not)'\nplot ",
                       kx / Wd, 1 - key_top / Hd, GD_KEY_SPACING(fm, 1.15));
        for (int f = 0; f < res->nfamilies; f++) {
            const gd_wp_family *F = &res->families[f];
            int bi = base_index(res, f);
            char words[120], key[200];
            family_words(F, words, sizeof words);
            /* the measured order in the key, when there is one */
            snprintf(key, sizeof key, "%s", words);
            for (int k = 0; k < res->norders; k++)
                if (res->orders[k].family == f && isfinite(res->orders[k].order)) {
                    size_t u = strlen(key);
                    snprintf(key + u, sizeof key - u, "; order %.2f", res->orders[k].order);
                }
            gd_plot_printf(&b, "%s1/0 with linespoints lc rgb '%s' lw 1.3 dt %d pt %d ps 0.9 title '%s'", f ? ", " : "",
                           gd_colour[bi % GD_NCOLOURS], F->root_finding ? 1 : 2,
                           markers[bi % 6] - (F->root_finding ? 0 : 1), key);
        }
        if (res->ref.floor > 0)
            gd_plot_printf(&b, "%s1/0 with lines lc rgb '#777777' dt 3 lw 1.2 title 'the reference''s floor'",
                           res->nfamilies ? ", " : "");
        else if (res->nfamilies == 0)
            gd_plot_printf(&b, "1/0 notitle");
        gd_plot_printf(&b, "\n");
        gd_fig_end(&b, 1);
    }
    static const char *names[] = {"work_precision"};
    gd_plot_draw(pl, &b, names, 1, "pictures not drawn");
}
void gd_plot_workprec(const gd_plotter *p, const gd_case *c, const gd_workprec_outcome *o)
{
    if (gd_plot_wanted(p, c->plots))
        draw(p, c, &o->res);
}
