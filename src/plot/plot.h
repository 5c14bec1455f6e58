/* Internal: the pictures of a run. Each analysis builds gnuplot scripts that read the run's tables
 * by their columns' names (plot_NAME.c) and hands them to the drawer its caller gave
 * (gd_output.h: gd_draw_fn); the library spawns no process, so without a drawer there are no
 * pictures and the run's notes say so. */
#ifndef GD_PLOT_PLOT_H
#define GD_PLOT_PLOT_H

#include "geardyn/gd_continuation.h"
#include "geardyn/gd_dynobj.h"
#include "geardyn/gd_basins.h"
#include "geardyn/gd_case.h"
#include "geardyn/gd_ltca.h"
#include "geardyn/gd_optimize.h"
#include "geardyn/gd_output.h"
#include "geardyn/gd_response.h"
#include "geardyn/gd_sweep.h"
#include "geardyn/gd_tca.h"
#include "geardyn/gd_workprec.h"
#include "quantity.h"

#include "../core/strbuf.h"

#include <stddef.h>

/* A gnuplot script growing in memory (src/core/strbuf.h): gd_plot_printf appends to p (n
 * characters, NUL terminated); when memory runs out bad is set and nothing more is appended. Start
 * from {0}; free(p) when done. */
typedef gd_strbuf gd_plot_script;
void gd_plot_printf(gd_plot_script *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Where a run's pictures go: the caller's drawer and notes (NULL: none) and the run's directory,
 * into whose stage they are drawn. */
typedef struct gd_plotter {
    gd_draw_fn draw;
    gd_note_fn note;
    void *user;
    gd_run_dir *out;
} gd_plotter;

/* 1 when there is a drawer, it says it can draw and the run has a directory on disk to draw
 * into; nothing noted. */
int gd_plot_can(const gd_plotter *p);
/* 1 when pictures are wanted (want) and gd_plot_can; 0 otherwise, with a note
 * (GD_NOTE_NO_PICTURES) when they are wanted but there is no drawer or it cannot draw. */
int gd_plot_wanted(const gd_plotter *p, int want);
/* Draw the script s (freed here) into the stage of p->out: it writes each picture of names[] as
 * .NAME.png.tmp and .NAME.svg.tmp, which the drawer moves into place when whole; then NAME.png and
 * NAME.svg join the run's files. On failure a note (GD_NOTE_PICTURES_FAILED) "failed: why". */
gd_status gd_plot_draw(const gd_plotter *p, gd_plot_script *s, const char *const *names, int nnames,
                       const char *failed);

/* The note (GD_NOTE_PICTURES_FAILED) "failed: err's message" of pictures that could not be drawn. */
void gd_plot_fail(const gd_plotter *p, const char *failed, const gd_error *err);

/* The pictures of each analysis (each only when c->plots and gd_plot_wanted). */
void gd_plot_response(const gd_plotter *p, const gd_case *c, const gd_response_outcome *r);
void gd_plot_sweep(const gd_plotter *p, const gd_case *c, const gd_sweep_outcome *o);
void gd_plot_tca(const gd_plotter *p, const gd_case *c, const gd_tca_result *r);
void gd_plot_ltca(const gd_plotter *p, const gd_case *c, const gd_ltca_result *r);
void gd_plot_optimize(const gd_plotter *p, const gd_case *c, const gd_optimize_outcome *o);
/* after an optimisation over load and speed (o->post): response_over_speed and lte_over_torque (plot_optpost.c) */
void gd_plot_optpost(const gd_plotter *p, const gd_case *c, const gd_optimize_outcome *o);
/* two objectives: the Pareto front (pareto.png, .svg; plot_pareto.c) */
void gd_plot_pareto(const gd_plotter *p, const gd_case *c, const gd_optimize_outcome *o);
void gd_plot_compare(const gd_plotter *p, const gd_case *c, const gd_compare_outcome *o);
void gd_plot_workprec(const gd_plotter *p, const gd_case *c, const gd_workprec_outcome *o);
void gd_plot_continuation(const gd_plotter *p, const gd_case *c, const gd_contin_result *r);
void gd_plot_basins(const gd_plotter *p, const gd_case *c, const gd_basins_result *r);
/* the continuation's curves in two parameters (curves.png, .svg; plot_curves.c), drawn by gd_plot_continuation */
void gd_plot_curves(const gd_plotter *p, const gd_case *c, const gd_contin_result *res);
/* The regions of the curves' plane named from the run (without continuation.overlay_map; with it
 * none), placed as curves.png draws them (plot_curves.c): what regions.csv writes. */
struct gd_curve_regions;
gd_status gd_plot_curve_regions(const gd_case *c, const gd_contin_result *res, struct gd_curve_regions *rg,
                                gd_error *err);

/* The four-panel figure of the local analysis (response.png, response.svg; plot_local.c). */
void gd_plot_local_draw(const gd_plotter *p, const gd_case *c, const gd_response_outcome *r);
/* How the local analysis's variable is drawn, for response.png and for time_history.png and
 * phase.png: its quantity and rate, the window of the time history (the last periods, as many as
 * a panel width_px wide shows readably), the ranges of the phase plane. */
typedef struct gd_local_view {
    gd_qty x, v;
    char xlabel[256], vlabel[256];
    size_t i0, p0;            /* first samples of the time window and of the phase portrait */
    int shown;                /* mesh periods of the time window */
    double t_from_ms, t_end_ms;
    double xlo, xhi, vlo, vhi;
} gd_local_view;
void gd_plot_local_view_of(const gd_case *c, const gd_response_outcome *ro, double width_px, gd_local_view *v);
/* the data blocks $TH (time window) and $PH (phase portrait): samples and the curve through them */
void gd_plot_local_blocks(gd_plot_script *s, const gd_response_outcome *ro, const gd_local_view *v);
/* the time history panel ($TH) with key entry key (NULL: no key) and more plots after it (more:
 * ", ..." or NULL) */
void gd_plot_local_time_panel(gd_plot_script *s, const gd_local_view *v, const char *title, const char *key,
                              const char *more);
/* the phase portrait panel ($PH), with the Poincare points when with_poincare (2: with a key) */
void gd_plot_local_phase_panel(gd_plot_script *s, const gd_response_outcome *ro, const gd_local_view *v,
                               const char *title, int with_poincare);
/* "period-1, single-sided impacts, largest Lyapunov exponent -0.213 per mesh period" */
void gd_plot_local_motion(const gd_response_result *r, char *buf, size_t len);

#endif
