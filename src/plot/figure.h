/* What every picture shares: the terminals (PNG and SVG at the same pixel sizes), the common
 * style, the colour sets (Okabe-Ito, viridis), ranges with margins and round ticks, annotation
 * labels placed without collisions, and a smooth curve through sampled values and rates. The words
 * of the labels come from quantity.h. */
#ifndef GD_PLOT_FIGURE_H
#define GD_PLOT_FIGURE_H

#include "plot.h"
#include "quantity.h"

#include <stddef.h>

/* pngcairo takes its font size in points and draws 1.25 pixels a point; the SVG gets the same
 * size in pixels, so that the two pictures have one layout (and the SVG read back by the tests
 * is the PNG a reader sees). */
#define GD_FIG_PT 10.0
#define GD_FIG_PX (1.25 * GD_FIG_PT)

/* The line height of a key with spacing s, as a 'spacing' for the terminal: the SVG terminal's
 * line is 1.5 times its font size (18.75 px), pngcairo's that of its font (15.55 px); the SVG's
 * keys are set to the PNG's lines, or gnuplot breaks a long key into columns there and not in the
 * PNG (and drops the columns that leave the picture). */
#define GD_KEY_SPACING(svg, s) ((svg) ? (s) * 15.55 / 18.75 : (s))

/* Begin picture NAME (written as .NAME.png.tmp or .NAME.svg.tmp) of w x h pixels: terminal,
 * UTF-8, the common style (grid, border, no key box, autoscaled ranges fixed to the data with
 * margins of 4 % in x and 7 % in y, so that nothing sits on a frame). */
void gd_fig_begin(gd_plot_script *s, int svg, int w, int h, const char *name);
/* End the picture (and a multiplot if one is open). */
void gd_fig_end(gd_plot_script *s, int multiplot);

/* The Okabe & Ito colour set without its yellow (too light on white): black, orange, sky blue,
 * bluish green, blue, vermillion, reddish purple; distinct for colour-blind readers. */
#define GD_NCOLOURS 7
extern const char *const gd_colour[GD_NCOLOURS];
/* A line of series i of n: a colour of gd_colour, then the same colours dashed; dash type 1
 * solid. */
void gd_series_style(int i, const char **colour, int *dash);
/* viridis at t in [0, 1] as "#rrggbb" */
void gd_viridis(double t, char out[8]);
/* 'set palette defined (...)' of viridis from t0 to t1 (a part that stays dark enough on white) */
void gd_palette_viridis(gd_plot_script *s, double t0, double t1);

/* A round tick step: 1, 2, 2.5 or 5 times a power of ten, about span / n. */
double gd_nice_step(double span, int n);
/* [lo, hi] widened by frac of its span on each side (log: of its decades); a zero span gets a
 * round one. */
void gd_pad(double lo, double hi, double frac, int logscale, double *a, double *b);

/* The frame of the flank panel of half h of halves (TCA's and LTCA's pictures): both of one width,
 * the colour bar beside the last. */
void gd_flank_panel(gd_plot_script *s, int h, int halves);

/* The ticks of a log axis ("x", "y") over [lo, hi]: 1, 2 and 5 times the powers of ten when it
 * spans less than two decades, else the powers of ten, written 10^{k}. */
void gd_log_tics(gd_plot_script *s, const char *axis, double lo, double hi);

/* Annotation labels at points of a frame (pixels, y down): each label of w x h pixels is put
 * beside its point where it covers no other label, no point of pts and stays inside the frame;
 * keep is 0 for a label that has no such place. */
typedef struct gd_fig_label {
    double x, y;        /* the point (pixels) */
    double w, h;        /* the label's size (pixels) */
    double lx, ly;      /* where the label's centre goes (pixels) */
    int keep;
} gd_fig_label;
void gd_place_labels(gd_fig_label *l, int n, double fx0, double fy0, double fx1, double fy1, const double *pts,
                      int npts);
/* The width in pixels of text s at the pictures' font (an estimate: DejaVu Sans's average widths). */
double gd_text_width(const char *s, double px);

/* A data block $NAME of columns "t x v": the samples t[i], x[i], v[i] (i from i0 to i1 - 1) in the
 * units drawn, with points between them on the cubic Hermite interpolant of x (slope v *
 * dxdt_per_v) and of v (slopes from central differences), as many as the curve of (x, v) turns
 * (a sampled orbit drawn as a curve, not as the polygon of its samples). Returns the points. */
size_t gd_hermite_block(gd_plot_script *s, const char *name, const double *t, const double *x, const double *v,
                         size_t i0, size_t i1, double dxdt_per_v);

#endif
