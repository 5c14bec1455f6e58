/* The `work-precision` analysis on the command line (docs/accuracy.md): the grid as it runs,
 * the work-precision diagrams (work_precision.png/.svg) and the summary lines. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void fmt_err(char *buf, size_t len, double v)
{
    if (isfinite(v))
        snprintf(buf, len, "%.2e", v);
    else
        snprintf(buf, len, "-");
}

int cli_workprec_start(void *user, const char *what, const char *label, int index, int total)
{
    cli_progress *o = user;
    if (o->quiet)
        return 0;
    if (strcmp(what, "grid") != 0 && strcmp(what, "order") != 0)
        printf("  %s: %s\n", what, label);
    else if (o->tty)
        fprintf(stderr, "\rgeardyn: %s %d/%d: %-40s", what, index + 1, total, label);
    fflush(stdout);
    return 0;
}

int cli_workprec_done(void *user, const char *what, const gd_wp_run *r, const gd_wp_result *res)
{
    cli_progress *o = user;
    if (o->quiet || strcmp(what, "grid") != 0)
        return 0;
    if (o->tty)
        fprintf(stderr, "\r%80s\r", "");
    char a[16], b[16], c[16], d[16];
    fmt_err(a, sizeof a, res->ref.chaotic ? r->err_short : r->err_poincare);
    fmt_err(b, sizeof b, r->err_rms);
    fmt_err(c, sizeof c, r->err_events);
    fmt_err(d, sizeof d, r->err_mle);
    if (r->status == GD_WP_OK)
        printf("  %-22s %8.3f s %9.1f RHS/period %7ld events   %s %s  rms %s  events %s%s%s\n", r->label, r->cpu_s,
               (double)r->rhs_evals / (double)r->periods, r->events, res->ref.chaotic ? "short" : "poincare", a, b, c,
               isfinite(r->err_mle) ? "  mle " : "", isfinite(r->err_mle) ? d : "");
    else
        printf("  %-22s %s%s%s\n", r->label, gd_wp_status_name(r->status), r->message[0] ? ": " : "", r->message);
    fflush(stdout);
    return 0;
}

void cli_workprec_announce(const char *dir, const gd_case *c)
{
    printf("%s: work-precision of %s, %d transient + %d recorded mesh periods\n", dir, c->title[0] ? c->title : c->path,
           c->transient_periods, c->record_periods);
}

void cli_workprec_after_run(const cli_progress *p, gd_status st)
{
    (void)st;
    if (p->tty)
        fprintf(stderr, "\r%80s\r", "");
}

static void sb_val(gd_gnuplot_script *b, double v)
{
    if (isfinite(v))
        gd_gnuplot_printf(b, " %.6g", v);
    else
        gd_gnuplot_printf(b, " ?");
}

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

/* Whether family f has a point that can be drawn on log axes with y <= 10 (gnuplot stops the
 * whole script on a plot with no valid point). */
static int drawable(const gd_wp_result *res, int f, int xcol, int ycol)
{
    for (int i = 0; i < res->nruns; i++) {
        const gd_wp_run *r = &res->runs[i];
        if (r->family != f || r->status != GD_WP_OK)
            continue;
        double x = column(r, xcol, res->ref.chaotic), y = column(r, ycol, res->ref.chaotic);
        if (isfinite(x) && x > 0 && isfinite(y) && y > 0 && y <= 10)
            return 1;
    }
    return 0;
}

/* A string for a gnuplot single-quoted enhanced-text label: '_' and '^' literal, ' doubled. */
static void gp_escape(const char *s, char *out, size_t len)
{
    size_t k = 0;
    for (; *s && k + 3 < len; s++) {
        if (*s == '_' || *s == '^' || *s == '{' || *s == '}' || *s == '@' || *s == '&' || *s == '~')
            out[k++] = '\\';
        else if (*s == '\'')
            out[k++] = '\'';
        out[k++] = *s;
    }
    out[k] = '\0';
}

/* Twelve colours that stay apart (a family and its root-finding-off twin share one). */
static const char *const palette[12] = {"#9400d3", "#009e73", "#56b4e9", "#e69f00", "#f0e442", "#0072b2",
                                         "#e51e10", "#000000", "#a0522d", "#ff69b4", "#808000", "#00ced1"};

/* The data blocks of the script: $Fi per family (the columns of column()), $Ok per order study. */
static void script_data(gd_gnuplot_script *b, const gd_wp_result *res)
{
    int chaotic = res->ref.chaotic;
    for (int f = 0; f < res->nfamilies; f++) {
        gd_gnuplot_printf(b, "$F%d << EOD\n", f);
        for (int i = 0; i < res->nruns; i++) {
            const gd_wp_run *r = &res->runs[i];
            if (r->family != f || r->status != GD_WP_OK)
                continue;
            sb_val(b, r->cpu_s);
            sb_val(b, (double)r->rhs_evals / (double)r->periods);
            sb_val(b, clampe(chaotic ? r->err_short : r->err_poincare));
            sb_val(b, clampe(r->err_rms));
            sb_val(b, clampe(r->err_events));
            sb_val(b, clampe(r->err_mle));
            gd_gnuplot_printf(b, "\n");
        }
        gd_gnuplot_printf(b, "EOD\n");
    }
    for (int k = 0; k < res->norders; k++) {
        gd_gnuplot_printf(b, "$O%d << EOD\n", k);
        const gd_wp_order *O = &res->orders[k];
        for (int l = 0; l < O->nlevels; l++)
            if (isfinite(O->err[l]))
                gd_gnuplot_printf(b, "%d %.6g\n", O->steps[l], clampe(O->err[l]));
        gd_gnuplot_printf(b, "EOD\n");
    }
}

/* The error panels: one line per family (root finding off dashed). */
static void script_error_panels(gd_gnuplot_script *b, const gd_case *c, const gd_wp_result *res, const char *primary)
{
    int chaotic = res->ref.chaotic;
    int pairs = c->wp_root_finding_off;
    struct {
        int xcol, ycol;
        const char *xl, *yl;
    } panels[] = {
        {1, 3, "CPU time (s)", primary},
        {2, 3, "RHS evaluations per mesh period", primary},
        {1, 4, "CPU time (s)", "RMS acceleration, relative error"},
        {1, 5, "CPU time (s)", chaotic ? "event time error (periods), horizon" : "event time error (periods)"},
        {1, 6, "CPU time (s)", "largest Lyapunov exponent error (per period)"},
    };
    int np = chaotic && c->wp_lyapunov ? 5 : 4;
    for (int p = 0; p < np; p++) {
        /* a run that went unstable has errors of 1e20: keep the axes on the accurate ones */
        gd_gnuplot_printf(b, "set xlabel '%s'\nset ylabel '%s'\nset title '%s'\nset yrange [*:10]\n", panels[p].xl,
                          panels[p].yl, panels[p].yl);
        gd_gnuplot_printf(b, "plot ");
        int drawn = 0;
        for (int f = 0; f < res->nfamilies; f++) {
            const gd_wp_family *F = &res->families[f];
            if (!drawable(res, f, panels[p].xcol, panels[p].ycol))
                continue;
            const char *color = palette[(pairs ? f / 2 : f) % 12];
            gd_gnuplot_printf(b, "%s$F%d using %d:%d with linespoints lc rgb '%s' dt %d pt %d ps 0.8 title '%s'",
                              drawn++ ? ", " : "", f, panels[p].xcol, panels[p].ycol, color, F->root_finding ? 1 : 2,
                              F->root_finding ? 7 : 6, F->name);
        }
        if (!drawn)
            gd_gnuplot_printf(b, "'-' using 1:2 with points pt -1 title 'no finite error'\n1 1\ne\n");
        else if (panels[p].ycol == 3)
            gd_gnuplot_printf(b, ", %.6g with lines lc rgb '#888888' dt 3 title 'reference floor'\n", res->ref.floor);
        else
            gd_gnuplot_printf(b, "\n");
    }
}

/* The order study panel: events located (solid) or not (dashed). */
static void script_order_panel(gd_gnuplot_script *b, const gd_case *c, const gd_wp_result *res)
{
    int pairs = c->wp_root_finding_off;
    gd_gnuplot_printf(b, "set xlabel 'steps per mesh period (fixed step)'\nset ylabel 'error, first %ld periods'\n"
                         "set title 'Order study: events located (solid) or not (dashed)'\nplot ",
                      res->horizon_periods);
    int drawn = 0;
    for (int k = 0; k < res->norders; k++) {
        const gd_wp_order *O = &res->orders[k];
        const gd_wp_family *F = &res->families[O->family];
        int ok = 0;
        for (int l = 0; l < O->nlevels; l++)
            ok |= isfinite(O->err[l]) && O->err[l] <= 10;
        if (!ok)
            continue;
        const char *color = palette[(pairs ? O->family / 2 : O->family) % 12];
        char ord[32];
        if (isfinite(O->order))
            snprintf(ord, sizeof ord, "%.2f", O->order);
        else
            snprintf(ord, sizeof ord, "-");
        gd_gnuplot_printf(b, "%s$O%d using 1:2 with linespoints lc rgb '%s' dt %d pt %d ps 0.8 title '%s: %s'",
                          drawn++ ? ", " : "", k, color, F->root_finding ? 1 : 2, F->root_finding ? 7 : 6, F->name,
                          ord);
    }
    if (!drawn)
        gd_gnuplot_printf(b, "'-' using 1:2 with points pt -1 title 'no finite error'\n1 1\ne");
    gd_gnuplot_printf(b, "\n");
}

/* The diagrams: error against CPU time (and RHS evaluations), one line per family (root
 * finding off dashed), and the order study. */
static gd_status draw(const char *dir, const gd_case *c, const gd_wp_result *res, gd_error *err)
{
    gd_gnuplot_script b = {0};
    int chaotic = res->ref.chaotic;
    script_data(&b, res);
    static const char *fmt[2][3] = {{"pngcairo size 1500,1400 font ',10'", "png", ".png"},
                                    {"svg size 1500,1400 dynamic font 'sans,10'", "svg", ".svg"}};
    char title[600], refm[200];
    gp_escape(c->title[0] ? c->title : c->path, title, sizeof title);
    gp_escape(res->ref.method, refm, sizeof refm);
    char primary[128];
    if (chaotic)
        snprintf(primary, sizeof primary, "trajectory error, first %ld periods", res->horizon_periods);
    else
        snprintf(primary, sizeof primary, "Poincare points error, %ld periods", res->window_periods);
    for (int fm = 0; fm < 2; fm++) {
        gd_gnuplot_printf(&b, "set terminal %s\nset output '.work_precision%s.tmp'\n", fmt[fm][0], fmt[fm][2]);
        gd_gnuplot_printf(&b, "set datafile missing '?'\nset grid\nset logscale xy\nset format y '10^{%%L}'\n"
                              "set key outside right top vertical font ',8'\n"
                              "set multiplot layout 3,2 title '%s: %s (%s), reference %s, floor %.1e'\n",
                          title, res->ref.motion, chaotic ? "chaotic" : "periodic", refm, res->ref.floor);
        script_error_panels(&b, c, res, primary);
        if (res->norders > 0)
            script_order_panel(&b, c, res);
        gd_gnuplot_printf(&b, "unset multiplot\nunset output\n");
    }
    if (b.bad) {
        free(b.p);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the gnuplot script");
    }
    static const char *names[] = {"work_precision"};
    gd_status st = gd_gnuplot_draw(dir, b.p, names, 1, err);
    free(b.p);
    return st;
}

void cli_workprec_pictures(const cli_case_args *a, const gd_case *c, const void *result, gd_run_dir *out,
                           const char **note)
{
    const gd_workprec_outcome *r = result;
    if (gd_gnuplot_wanted(c->plots, note)) {
        gd_error perr = {0};
        gd_status pst = draw(gd_run_dir_stage(out), c, &r->res, &perr);
        static const char *pics[] = {"work_precision.png", "work_precision.svg"};
        gd_gnuplot_drawn(pst, &perr, pics, 2, out);
    }
}

void cli_workprec_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    (void)dir;
    const gd_wp_result *res = &((const gd_workprec_outcome *)result)->res;
    if (!res->ref.converged)
        fprintf(stderr, "geardyn: warning: the reference has not converged: it differs from its check (%s) by %.3g, "
                "above workprecision.reference_max_error = %g; errors below that are not resolved\n",
                res->ref.check_method, res->ref.chaotic ? res->ref.check_short : res->ref.check_poincare,
                c->wp_reference_max_error);
    if (a->quiet)
        return;
    printf("reference %s: %s (%s), RMS %.6g m/s^2, %ld events; check %s differs by %.3g (Poincare), %.3g "
           "(short horizon), %.3g (RMS)\n",
           res->ref.method, res->ref.motion, res->ref.chaotic ? "chaotic" : "periodic", res->ref.rms_accel_mps2,
           res->ref.events, res->ref.check_method, res->ref.check_poincare, res->ref.check_short, res->ref.check_rms);
    if (res->norders > 0) {
        printf("convergence order of the Poincare points (fixed steps, first %ld periods):\n", res->horizon_periods);
        for (int i = 0; i < res->norders; i++) {
            const gd_wp_order *O = &res->orders[i];
            printf("  %-14s nominal %d, measured %s", res->families[O->family].name, O->nominal,
                   isfinite(O->order) ? "" : "-");
            if (isfinite(O->order))
                printf("%.2f (steps %d to %d); %.2f over steps %d to %d", O->order, O->steps[O->fit_from],
                       O->steps[O->fit_to], O->order_range, O->steps[O->range_from], O->steps[O->fit_to]);
            printf("\n");
        }
    }
    static const double targets[] = {1e-3, 1e-6, 1e-8};
    for (int ev = 0; ev < 2; ev++)
        for (int k = 0; k < 3; k++) {
            int i = gd_workprec_cheapest(res, targets[k], ev);
            printf("cheapest at error %.0e%s: ", targets[k], ev ? " with the event times too" : "");
            if (i >= 0)
                printf("%s, %.1f us per mesh period\n", res->runs[i].label,
                       1e6 * res->runs[i].cpu_s / (double)res->runs[i].periods);
            else
                printf("none reached it\n");
        }
    printf("  %.1f s in all\n", res->wall_s);
}
