/* The pictures of `response`: the four-panel figure of the local analysis (plot_local.c), the
 * time history and the phase portrait with the Poincare section of output.response_variable. */
#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Draw time_history.png (the variable of the local analysis over the last periods, and on a
 * herringbone the same variable of the other half) and phase.png (its phase portrait and
 * Poincare points), both of output.response_variable as response.png. */
static void draw(const gd_plotter *pl, const gd_case *c, const gd_response_outcome *ro)
{
    const gd_local *L = &ro->local;
    const gd_response_result *r = &ro->res;
    int halves = ro->model.nmesh;
    gd_local_view v;
    gd_plot_local_view_of(c, ro, 1050, &v);
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
        gd_qty q;
        gd_qty_column(base, halves, &q);
        snprintf(q.unit, sizeof q.unit, "µm");
        gd_qty_label(&q, v.xlabel, sizeof v.xlabel);
    }
    char motion[200], title[300], more[400] = "";
    gd_plot_local_motion(r, motion, sizeof motion);
    if (other[0])
        snprintf(more, sizeof more, ", 'time_history.csv' using (column('t_s')*1e3):(column('t_s')*1e3 >= %.12g ? "
                 "column('%s') : 1/0) with lines lw 1.3 dt 2 lc rgb '%s' title '%s'", v.t_from_ms - 1e-9, other,
                 gd_colour[5], gd_half_words(side == 'L', halves));
    gd_plot_script s = {0};
    gd_plot_local_blocks(&s, ro, &v);
    for (int f = 0; f < 2; f++) {
        gd_fig_begin(&s, f, 1200, 700, "time_history");
        snprintf(title, sizeof title, "Time history, the last %d mesh period%s: %s", v.shown, v.shown == 1 ? "" : "s",
                 motion);
        gd_plot_printf(&s, "set key outside top center horizontal\n");
        gd_plot_local_time_panel(&s, &v, title, other[0] ? gd_half_words(side == 'R', halves) : NULL,
                             other[0] ? more : NULL);
        gd_fig_end(&s, 0);
        gd_fig_begin(&s, f, 1000, 800, "phase");
        char pt[300];
        if (r->poincare_distinct == 1)
            snprintf(pt, sizeof pt, "Phase portrait and Poincaré section (%s; %zu returns to one point)", r->motion,
                     L->np);
        else
            snprintf(pt, sizeof pt, "Phase portrait and Poincaré section (%s; %zu returns, %d distinct)", r->motion,
                     L->np, r->poincare_distinct);
        gd_plot_printf(&s, "set key outside top center horizontal\n");
        gd_plot_local_phase_panel(&s, ro, &v, pt, 2);
        gd_fig_end(&s, 0);
    }
    static const char *names[] = {"time_history", "phase"};
    gd_plot_draw(pl, &s, names, 2, "pictures not drawn");
}
void gd_plot_response(const gd_plotter *p, const gd_case *c, const gd_response_outcome *r)
{
    if (c->plots && gd_plot_can(p))
        gd_plot_local_draw(p, c, r);
    if (gd_plot_wanted(p, c->plots && c->time_history))
        draw(p, c, r);
}
