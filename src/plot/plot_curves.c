/* The picture of a continuation's curves in two parameters (curves.png, .svg; continuation.parameter2):
 * every curve in the plane of the two keys, one colour and dash per kind (fold, period doubling,
 * grazing), the bifurcation each starts from marked, the codimension-two points of codim2.csv marked
 * and labelled (CP, FF, GF, ...: gd_codim2_label), the box of the two ranges dotted grey inside a
 * margin (a curve ends on the box). Drawn by gnuplot from curves.csv, in the style of figure.h.
 * With continuation.overlay_map a finished regime map's cells go under the curves, coloured by the
 * motion (in contact, single-sided, double-sided; period 1 or not), each cell split in two where the
 * sweeps up and down end on different motions, and each region of one motion large enough for its
 * name is named inside it; without a map the regions the run names (output/curve_regions.c: the
 * stable orbits of the branches between consecutive bifurcations on their line) are named on that
 * line, and placed here for regions.csv too (gd_plot_curve_regions); with
 * continuation.overlay_curves an earlier run's curves are drawn thin and grey beside these, the keys
 * where that run differs named in the key. */
#include "figure.h"
#include "../output/output_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CW 1200
#define CH 760

/* The layout with an overlay: a wider picture, the frame at fixed fractions (the regions' names
 * are placed in pixels), the key beside it. */
#define OW 1400
#define OH 800
#define OX0 0.075
#define OX1 0.70
#define OY0 0.10
#define OY1 0.87

/* The motion of a regime map's cell, in the colours of its background: the contact regime (in
 * contact, single-sided, double-sided) by hue, period 1 pale and any other motion deeper (pale
 * enough that the curves stay legible over them; told apart by colour-blind readers). */
enum { RG_N = 6 };
static const char *const rg_colour[RG_N] = {"#EEEEEE", "#C6DFF4", "#FBE6A8", "#C4C4C4", "#86B6E3", "#E8BE5A"};
static const char *const rg_regime[3] = {"in contact", "single-sided", "double-sided"};

static int rg_class(const gd_map_point *p)
{
    return p->regime < 0 ? -1 : p->regime + (p->period == 1 ? 0 : 3);
}

/* The motion's name in a region's label: "single-sided", "single-sided, period 2", ... */
static void rg_name(const gd_map_point *p, char *out, size_t len)
{
    const char *m = p->motion;
    if (p->period == 1)
        snprintf(out, len, "%s", rg_regime[p->regime]);
    else if (p->period > 1)
        snprintf(out, len, "%s, period %d", rg_regime[p->regime], p->period);
    else
        snprintf(out, len, "%s, %s", rg_regime[p->regime], strcmp(m, "chaotic") == 0          ? "chaotic"
                                                           : strcmp(m, "quasi-periodic") == 0 ? "quasi-periodic"
                                                                                              : "not periodic");
}

/* The map as a grid: the distinct values of each key, sorted; cell (i, j) holds the point of the
 * sweep up (or independent) and of the sweep down. */
typedef struct grid {
    double *xv, *yv;
    int nx, ny;
    int *up, *down; /* index into the map's points, -1 none */
} grid;

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static int distinct(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    int k = 0;
    for (int i = 0; i < n; i++)
        if (k == 0 || fabs(v[i] - v[k - 1]) > 1e-9 * fmax(fabs(v[i]), 1e-300))
            v[k++] = v[i];
    return k;
}

static int find_value(const double *v, int n, double x)
{
    int best = 0;
    for (int i = 1; i < n; i++)
        if (fabs(v[i] - x) < fabs(v[best] - x))
            best = i;
    return best;
}

static int grid_build(const gd_overlay_map *m, grid *g)
{
    memset(g, 0, sizeof *g);
    if (m->n == 0)
        return 0;
    g->xv = malloc(sizeof(double) * (size_t)m->n);
    g->yv = malloc(sizeof(double) * (size_t)m->n);
    if (!g->xv || !g->yv)
        return 0;
    for (int i = 0; i < m->n; i++) {
        g->xv[i] = m->pt[i].x;
        g->yv[i] = m->pt[i].y;
    }
    g->nx = distinct(g->xv, m->n);
    g->ny = distinct(g->yv, m->n);
    size_t nc = (size_t)g->nx * (size_t)g->ny;
    g->up = malloc(sizeof(int) * nc);
    g->down = malloc(sizeof(int) * nc);
    if (!g->up || !g->down)
        return 0;
    for (size_t k = 0; k < nc; k++)
        g->up[k] = g->down[k] = -1;
    for (int i = 0; i < m->n; i++) {
        size_t k = (size_t)find_value(g->yv, g->ny, m->pt[i].y) * (size_t)g->nx +
                   (size_t)find_value(g->xv, g->nx, m->pt[i].x);
        if (m->pt[i].dir == 1)
            g->down[k] = i;
        else
            g->up[k] = i;
    }
    for (size_t k = 0; k < nc; k++) { /* one direction only: both halves alike */
        if (g->up[k] < 0)
            g->up[k] = g->down[k];
        if (g->down[k] < 0)
            g->down[k] = g->up[k];
    }
    return 1;
}

static void grid_free(grid *g)
{
    free(g->xv);
    free(g->yv);
    free(g->up);
    free(g->down);
}

/* Cell i's edges along values v (n of them): half-way to its neighbours, the ends at the end values. */
static void edges(const double *v, int n, int i, double *lo, double *hi)
{
    *lo = i > 0 ? 0.5 * (v[i - 1] + v[i]) : v[0];
    *hi = i + 1 < n ? 0.5 * (v[i] + v[i + 1]) : v[n - 1];
    if (n == 1) {
        *lo = v[0] - 0.5;
        *hi = v[0] + 0.5;
    }
}

/* The motion a cell is named by: the point's of each sweep (up, down); two cells are of one region
 * when both motions are alike. */
static int same_motion(const gd_overlay_map *m, int a, int b)
{
    if (a < 0 || b < 0)
        return a == b;
    const gd_map_point *p = &m->pt[a], *q = &m->pt[b];
    return p->regime == q->regime && strcmp(p->motion, q->motion) == 0;
}

static int same_cell(const gd_overlay_map *m, const grid *g, size_t a, size_t b)
{
    return same_motion(m, g->up[a], g->up[b]) && same_motion(m, g->down[a], g->down[b]);
}

/* The picture's frame in pixels and its data ranges. */
typedef struct frame_px {
    double x0, x1, y0, y1;     /* the ranges */
    double px0, px1, py0, py1; /* the frame (pixels, y down: py0 the top) */
} frame_px;

static double to_px(const frame_px *f, double x) { return f->px0 + (x - f->x0) / (f->x1 - f->x0) * (f->px1 - f->px0); }
static double to_py(const frame_px *f, double y) { return f->py0 + (f->y1 - y) / (f->y1 - f->y0) * (f->py1 - f->py0); }

/* Whether the segment a-b (pixels) comes within the box [bx0, bx1] x [by0, by1]. */
static int seg_hits(double ax, double ay, double bx, double by, double bx0, double by0, double bx1, double by1)
{
    double len = hypot(bx - ax, by - ay);
    int n = 1 + (int)(len / 2);
    for (int k = 0; k <= n; k++) {
        double x = ax + (bx - ax) * k / n, y = ay + (by - ay) * k / n;
        if (x >= bx0 && x <= bx1 && y >= by0 && y <= by1)
            return 1;
    }
    return 0;
}

/* Obstacles of the regions' names: every curve drawn (polylines, pixels) and each marker with its
 * label. */
typedef struct obstacles {
    double *x, *y; /* polyline points; a NAN breaks a line */
    int n, cap;
} obstacles;

static void obs_add(obstacles *o, double x, double y)
{
    if (o->n == o->cap) {
        int cap = o->cap ? 2 * o->cap : 1024;
        double *nx = realloc(o->x, sizeof(double) * (size_t)cap);
        if (nx)
            o->x = nx;
        double *ny = nx ? realloc(o->y, sizeof(double) * (size_t)cap) : NULL;
        if (!ny)
            return;
        o->y = ny;
        o->cap = cap;
    }
    o->x[o->n] = x;
    o->y[o->n++] = y;
}

static int obs_hit(const obstacles *o, double bx0, double by0, double bx1, double by1)
{
    for (int i = 0; i + 1 < o->n; i++)
        if (isfinite(o->x[i]) && isfinite(o->x[i + 1]) &&
            seg_hits(o->x[i], o->y[i], o->x[i + 1], o->y[i + 1], bx0, by0, bx1, by1))
            return 1;
    for (int i = 0; i < o->n; i++) /* a lone point (a marker's box's corners are lines of their own) */
        if (isfinite(o->x[i]) && (i == 0 || !isfinite(o->x[i - 1])) && (i + 1 == o->n || !isfinite(o->x[i + 1])) &&
            o->x[i] >= bx0 && o->x[i] <= bx1 && o->y[i] >= by0 && o->y[i] <= by1)
            return 1;
    return 0;
}

/* The regions' names: each region (cells of one motion, four-connected) is named once, at the
 * cell nearest its centre whose name's box lies inside the region's cells, inside the frame and
 * clear of every obstacle; a region too small or too crossed for its name stays unnamed. */
static void region_labels(gd_plot_script *s, const gd_overlay_map *m, const grid *g, const frame_px *f,
                          const obstacles *ob, int *nlabel)
{
    size_t nc = (size_t)g->nx * (size_t)g->ny;
    int *comp = malloc(sizeof(int) * nc), *stack = malloc(sizeof(int) * nc);
    if (!comp || !stack) {
        free(comp);
        free(stack);
        return;
    }
    for (size_t k = 0; k < nc; k++)
        comp[k] = -1;
    int ncomp = 0;
    for (size_t k0 = 0; k0 < nc; k0++) {
        if (comp[k0] >= 0 || g->up[k0] < 0 || m->pt[g->up[k0]].regime < 0 || m->pt[g->down[k0]].regime < 0)
            continue;
        /* the region of cell k0 */
        int top = 0;
        stack[top++] = (int)k0;
        comp[k0] = ncomp;
        double sx = 0, sy = 0;
        int cnt = 0;
        while (top > 0) {
            int k = stack[--top], i = k % g->nx, j = k / g->nx;
            sx += to_px(f, g->xv[i]);
            sy += to_py(f, g->yv[j]);
            cnt++;
            int nb[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
            for (int q = 0; q < 4; q++) {
                int a = nb[q][0], b = nb[q][1];
                if (a < 0 || b < 0 || a >= g->nx || b >= g->ny)
                    continue;
                size_t kk = (size_t)b * (size_t)g->nx + (size_t)a;
                if (comp[kk] < 0 && same_cell(m, g, k0, kk)) {
                    comp[kk] = ncomp;
                    stack[top++] = (int)kk;
                }
            }
        }
        /* its name */
        char a[80], b[80], text[170];
        rg_name(&m->pt[g->up[k0]], a, sizeof a);
        rg_name(&m->pt[g->down[k0]], b, sizeof b);
        if (strcmp(a, b) == 0)
            snprintf(text, sizeof text, "%s", a);
        else
            snprintf(text, sizeof text, "%s or %s", a, b);
        double w = gd_text_width(text, GD_FIG_PX) + 10, h = 1.5 * GD_FIG_PX;
        double cx = sx / cnt, cy = sy / cnt, best = INFINITY;
        int bi = -1;
        for (size_t k = 0; k < nc; k++) {
            if (comp[k] != ncomp)
                continue;
            int i = (int)(k % (size_t)g->nx), j = (int)(k / (size_t)g->nx);
            double xl, xh, yl, yh;
            edges(g->xv, g->nx, i, &xl, &xh);
            edges(g->yv, g->ny, j, &yl, &yh);
            double px = to_px(f, 0.5 * (xl + xh)), py = to_py(f, 0.5 * (yl + yh));
            double bx0 = px - w / 2, bx1 = px + w / 2, by0 = py - h / 2, by1 = py + h / 2;
            /* inside the frame and the map's cells */
            if (bx0 < fmax(f->px0, to_px(f, g->xv[0])) + 4 || bx1 > fmin(f->px1, to_px(f, g->xv[g->nx - 1])) - 4 ||
                by0 < fmax(f->py0, to_py(f, g->yv[g->ny - 1])) + 4 || by1 > fmin(f->py1, to_py(f, g->yv[0])) - 4)
                continue;
            double d = hypot(px - cx, py - cy);
            if (d >= best)
                continue;
            /* every cell the box touches is of the region */
            int inside = 1, i0 = i, i1 = i, j0 = j, j1 = j; /* the cells the box may touch */
            while (i0 > 0 && to_px(f, g->xv[i0]) > bx0)
                i0--;
            while (i1 + 1 < g->nx && to_px(f, g->xv[i1]) < bx1)
                i1++;
            while (j0 > 0 && to_py(f, g->yv[j0]) < by1)
                j0--;
            while (j1 + 1 < g->ny && to_py(f, g->yv[j1]) > by0)
                j1++;
            for (int jj = j0; jj <= j1 && inside; jj++)
                for (int ii = i0; ii <= i1 && inside; ii++) {
                    double cxl, cxh, cyl, cyh;
                    edges(g->xv, g->nx, ii, &cxl, &cxh);
                    edges(g->yv, g->ny, jj, &cyl, &cyh);
                    double qx0 = to_px(f, cxl), qx1 = to_px(f, cxh), qy0 = to_py(f, cyh), qy1 = to_py(f, cyl);
                    if (qx1 > bx0 && qx0 < bx1 && qy1 > by0 && qy0 < by1 &&
                        comp[(size_t)jj * (size_t)g->nx + (size_t)ii] != ncomp)
                        inside = 0;
                }
            if (!inside || obs_hit(ob, bx0, by0, bx1, by1))
                continue;
            best = d;
            bi = (int)k;
        }
        if (bi >= 0) {
            char t[400];
            gd_gp_text(text, t, sizeof t);
            int i = bi % g->nx, j = bi / g->nx;
            double xl, xh, yl, yh;
            edges(g->xv, g->nx, i, &xl, &xh);
            edges(g->yv, g->ny, j, &yl, &yh);
            gd_plot_printf(s, "set label %d '%s' at %.12g, %.12g center front tc rgb '#222222'\n", ++*nlabel, t,
                           0.5 * (xl + xh), 0.5 * (yl + yh));
        }
        ncomp++;
    }
    free(comp);
    free(stack);
}

/* The map's cells as data blocks $RG0 .. $RG5 (xlo xhi ylo yhi per half cell), one per colour;
 * present[k]: whether colour k has cells. Each cell's left half is the sweep up's, its right half
 * the sweep down's. */
static void map_blocks(gd_plot_script *s, const gd_overlay_map *m, const grid *g, int *present)
{
    for (int k = 0; k < RG_N; k++) {
        present[k] = 0;
        gd_plot_printf(s, "$RG%d << EOD\nx,y,xlo,xhi,ylo,yhi\n", k);
        for (int j = 0; j < g->ny; j++)
            for (int i = 0; i < g->nx; i++) {
                size_t c = (size_t)j * (size_t)g->nx + (size_t)i;
                double xl, xh, yl, yh;
                edges(g->xv, g->nx, i, &xl, &xh);
                edges(g->yv, g->ny, j, &yl, &yh);
                int split = g->up[c] >= 0 && rg_class(&m->pt[g->up[c]]) != rg_class(&m->pt[g->down[c]]);
                for (int half = 0; half < 2; half++) {
                    int pi = half ? g->down[c] : g->up[c];
                    if (pi < 0 || rg_class(&m->pt[pi]) != k || (half && !split))
                        continue;
                    double a = split && half ? g->xv[i] : xl, b = split && !half ? g->xv[i] : xh;
                    gd_plot_printf(s, "%.12g,%.12g,%.12g,%.12g,%.12g,%.12g\n", 0.5 * (a + b), 0.5 * (yl + yh), a, b, yl,
                                   yh);
                    present[k] = 1;
                }
            }
        gd_plot_printf(s, "EOD\n");
    }
}

/* The earlier run's curves as data blocks $OLD0 .. $OLD3 (by kind: fold, period doubling,
 * Neimark-Sacker, grazing), a blank line between curves; present[k] as above. */
static void old_blocks(gd_plot_script *s, const gd_overlay_curves *o, int *present)
{
    for (int k = 0; k < 4; k++) {
        present[k] = 0;
        int last = -1;
        gd_plot_printf(s, "$OLD%d << EOD\nx,y\n", k);
        for (int i = 0; i < o->n; i++) {
            if (o->kind[i] != k)
                continue;
            if (o->curve[i] != last && present[k])
                gd_plot_printf(s, "\n");
            last = o->curve[i];
            gd_plot_printf(s, "%.12g,%.12g\n", o->x[i], o->y[i]);
            present[k] = 1;
        }
        gd_plot_printf(s, "EOD\n");
    }
}

/* The words of the earlier run's curves in the key (one line): where its model differs from this
 * case's, the first key with both values. */
static void old_words(const gd_overlay_curves *o, const char *dir, char *out, size_t len)
{
    if (o->ndiff == 0) {
        const char *b = strrchr(dir, '/');
        snprintf(out, len, "thin grey: the curves of %s", b && b[1] ? b + 1 : dir);
        return;
    }
    gd_qty q;
    gd_qty_key(o->diff[0].key, &q);
    int unit = q.unit[0] && strcmp(q.unit, "-") != 0;
    int n = snprintf(out, len, "thin grey: at %s %s%s%s (%s here)", q.name, o->diff[0].theirs, unit ? " " : "",
                     unit ? q.unit : "", o->diff[0].mine);
    if (o->ndiff > 1 && n < (int)len)
        snprintf(out + n, len - (size_t)n, " and %d more key%s", o->ndiff - 1, o->ndiff == 2 ? "" : "s");
}

/* The layout without an overlay: the frame at fixed fractions too (the regions' names are placed in
 * pixels), the key and the codimension-two points' words below it. */
#define NX0 0.08
#define NX1 0.975
#define NY0 0.20
#define NY1 0.87

/* The picture's size, data ranges and frame: over (a map or an earlier run's curves) the wider
 * layout with the key beside the frame. */
/* The range of one axis: the box's, padded; but where what is drawn (the curves, their points, the
 * branches' line, an earlier run's curves: [d0, d1]) covers less than 60 % of the box, the data's, padded
 * by 6 % and within the padded box, so that the data fill the axes (the paper's pair in torque: curves to
 * 2667 N m in a box to 4800 N m). */
static void axis_range(double b0, double b1, double d0, double d1, double pad, double *a0, double *a1)
{
    gd_pad(b0, b1, pad, 0, a0, a1);
    if (!(d1 >= d0) || !(d1 - d0 < 0.6 * (b1 - b0)))
        return;
    double e0, e1;
    gd_pad(d0, d1 > d0 ? d1 : d0 + 0.01 * (b1 - b0), 0.06, 0, &e0, &e1);
    *a0 = fmax(*a0, e0);
    *a1 = fmin(*a1, e1);
}

/* The extent of what the picture draws without a map: every curve's points and codimension-two points,
 * the branches' line at y2, an earlier run's curves. */
static void data_extent(const gd_contin_result *res, const gd_overlay_curves *o, double y2, double *x0, double *x1,
                        double *y0, double *y1)
{
    *x0 = *y0 = INFINITY;
    *x1 = *y1 = -INFINITY;
#define GD_TAKE(X, Y)                                                                                                 \
    do {                                                                                                               \
        const double tx = (X), ty = (Y);                                                                               \
        if (isfinite(tx) && isfinite(ty)) {                                                                            \
            *x0 = fmin(*x0, tx), *x1 = fmax(*x1, tx);                                                                  \
            *y0 = fmin(*y0, ty), *y1 = fmax(*y1, ty);                                                                  \
        }                                                                                                              \
    } while (0)
    for (int i = 0; res && i < res->ncurves; i++) {
        const gd_curve *cv = &res->curve[i].cv;
        for (int k = 0; k < cv->npoints; k++)
            GD_TAKE(gd_contin_value(res, cv->pt[k].orbit.p), cv->pt[k].p2 * res->scale2);
        for (int k = 0; k < cv->nc2; k++)
            GD_TAKE(gd_contin_value(res, cv->c2[k].p1), cv->c2[k].p2 * res->scale2);
    }
    for (int i = 0; o && i < o->n; i++)
        GD_TAKE(o->x[i], o->y[i]);
#undef GD_TAKE
    if (isfinite(y2)) {
        *y0 = fmin(*y0, y2);
        *y1 = fmax(*y1, y2);
    }
}

static void layout(const gd_case *c, const gd_overlay_map *m, const grid *g, int over, const gd_contin_result *res,
                   const gd_overlay_curves *o, double y2, frame_px *f, int *W, int *H)
{
    double x0, x1, y0, y1, d[4] = {NAN, NAN, NAN, NAN};
    if (!(m && m->n > 0)) /* (over a map, the map's cells set the frame) */
        data_extent(res, o, y2, &d[0], &d[1], &d[2], &d[3]);
    axis_range(fmin(c->cont_from, c->cont_to), fmax(c->cont_from, c->cont_to), d[0], d[1], 0.03, &x0, &x1);
    axis_range(fmin(c->cont_from2, c->cont_to2), fmax(c->cont_from2, c->cont_to2), d[2], d[3], 0.04, &y0, &y1);
    if (m && m->n > 0) { /* the map's cells fill the frame where they reach */
        x0 = fmin(x0, fmax(g->xv[0], x0 - 0.5 * (x1 - x0)));
        x1 = fmax(x1, fmin(g->xv[g->nx - 1], x1 + 0.5 * (x1 - x0)));
        y0 = fmin(y0, fmax(g->yv[0], y0 - 0.5 * (y1 - y0)));
        y1 = fmax(y1, fmin(g->yv[g->ny - 1], y1 + 0.5 * (y1 - y0)));
    }
    *W = over ? OW : CW;
    *H = over ? OH : CH;
    if (over)
        *f = (frame_px){x0, x1, y0, y1, OX0 * OW, OX1 * OW, (1 - OY1) * OH, (1 - OY0) * OH};
    else
        *f = (frame_px){x0, x1, y0, y1, NX0 * CW, NX1 * CW, (1 - NY1) * CH, (1 - NY0) * CH};
}

/* The codimension-two points' labels: one per point (the same point found from two curves, or
 * points of different kinds at one place, share one label: "CP", "GF, DG"), and points closer than
 * a label's size (7 % of the x range, 4 % of the y range) share one, which would overlap. */
typedef struct c2_label {
    double x, y;
    char text[40];
} c2_label;
#define C2_LABELS 64

static int c2_labels(const gd_contin_result *res, const frame_px *f, c2_label *lab, int *present, int *nc2)
{
    int nl = 0;
    double dx = 0.07 * (f->x1 - f->x0), dy = 0.04 * (f->y1 - f->y0);
    *nc2 = 0;
    for (int i = 0; i < res->ncurves; i++)
        for (int j = 0; j < res->curve[i].cv.nc2; j++) {
            const gd_codim2 *c2 = &res->curve[i].cv.c2[j];
            double x = gd_contin_value(res, c2->p1), y = c2->p2 * res->scale2;
            const char *t = gd_codim2_label(c2->kind);
            (*nc2)++;
            if (present)
                present[c2->kind] = 1;
            int l = 0;
            while (l < nl && !(fabs(lab[l].x - x) < dx && fabs(lab[l].y - y) < dy))
                l++;
            if (l == nl) {
                if (nl == C2_LABELS)
                    continue;
                lab[nl].x = x;
                lab[nl].y = y;
                snprintf(lab[nl++].text, sizeof lab[0].text, "%s", t);
            } else if (!strstr(lab[l].text, t) && strlen(lab[l].text) + strlen(t) + 3 < sizeof lab[l].text) {
                strcat(lab[l].text, ", ");
                strcat(lab[l].text, t);
            }
        }
    return nl;
}

/* A box (pixels) as obstacles: its four sides and two diagonals (another box overlaps it exactly
 * when one of them enters that box). */
static void obs_box(obstacles *ob, double x0, double y0, double x1, double y1)
{
    double cx[5] = {x0, x1, x1, x0, x0}, cy[5] = {y0, y0, y1, y1, y0};
    for (int k = 0; k < 5; k++)
        obs_add(ob, cx[k], cy[k]);
    obs_add(ob, NAN, NAN);
    obs_add(ob, x0, y0);
    obs_add(ob, x1, y1);
    obs_add(ob, NAN, NAN);
    obs_add(ob, x0, y1);
    obs_add(ob, x1, y0);
    obs_add(ob, NAN, NAN);
}

/* What a region's name must not cover: every curve drawn (this run's and the earlier one's), each
 * start's dot and each codimension-two point with its label. */
static void curve_obstacles(const gd_contin_result *res, const gd_overlay_curves *o, const frame_px *f,
                            const c2_label *lab, int nl, obstacles *ob)
{
    for (int i = 0; i < res->ncurves; i++) {
        const gd_curve *cv = &res->curve[i].cv;
        for (int j = 0; j < cv->npoints; j++)
            obs_add(ob, to_px(f, gd_contin_value(res, cv->pt[j].orbit.p)), to_py(f, cv->pt[j].p2 * res->scale2));
        obs_add(ob, NAN, NAN);
        if (cv->npoints > 0) { /* the start's dot */
            double px = to_px(f, gd_contin_value(res, cv->pt[0].orbit.p)), py = to_py(f, cv->pt[0].p2 * res->scale2);
            obs_box(ob, px - 6, py - 6, px + 6, py + 6);
        }
    }
    for (int i = 0; o && i < o->n; i++) {
        if (i > 0 && (o->curve[i] != o->curve[i - 1] || o->kind[i] != o->kind[i - 1]))
            obs_add(ob, NAN, NAN);
        obs_add(ob, to_px(f, o->x[i]), to_py(f, o->y[i]));
    }
    obs_add(ob, NAN, NAN);
    for (int l = 0; l < nl; l++) { /* the marker and its label */
        double px = to_px(f, lab[l].x), py = to_py(f, lab[l].y);
        obs_box(ob, px - 14, py - 28, px + 14 + gd_text_width(lab[l].text, GD_FIG_PX) + 10, py + 14);
    }
}

/* A region's name in one line, or in two (split at the " or " nearest its middle, else after its
 * ";" or before its parenthesis): into a and b ("" for one line). */
static void split_name(const char *t, int two, char *a, char *b, size_t len)
{
    snprintf(a, len, "%s", t);
    b[0] = 0;
    if (!two)
        return;
    size_t n = strlen(t), best = 0;
    for (const char *p = strstr(t, " or "); p; p = strstr(p + 1, " or ")) {
        size_t at = (size_t)(p - t) + 3; /* after "or" */
        if (best == 0 || fabs((double)at - 0.5 * (double)n) < fabs((double)best - 0.5 * (double)n))
            best = at;
    }
    if (best == 0) {
        const char *p = strstr(t, "; ");
        if (!p)
            p = strchr(t, '(');
        if (!p || p == t)
            return;
        best = (size_t)(p - t) + (*p == ';') - (*p == '(');
    }
    snprintf(a, len, "%.*s", (int)best, t);
    snprintf(b, len, "%s", t + best + 1);
}

static double name_width(const char *a, const char *b)
{
    return fmax(gd_text_width(a, GD_FIG_PX), b[0] ? gd_text_width(b, GD_FIG_PX) : 0) + 10;
}

/* The regions named from the run (no map; curve_regions.c) placed: each name centred on the
 * branches' line inside its interval (the stable orbits are known there exactly), in one line or
 * two, where its box lies inside the frame and its interval and covers no curve, start,
 * codimension-two point or other name; nearest the interval's middle. A name with no such place is
 * not drawn (drawn 0). */
static void place_regions(const frame_px *f, obstacles *ob, gd_curve_regions *rg)
{
    for (int i = 0; i < rg->n; i++) {
        gd_curve_region *r = &rg->r[i];
        double pa = to_px(f, r->from), pb = to_px(f, r->to), py = to_py(f, r->y);
        if (pa > pb) {
            double t = pa;
            pa = pb;
            pb = t;
        }
        for (int two = 0; two < 2 && !r->drawn; two++) {
            char a[256], b[256];
            split_name(r->label, two, a, b, sizeof a);
            if (two && !b[0])
                break;
            double w = name_width(a, b), h = (b[0] ? 2.6 : 1.5) * GD_FIG_PX;
            double lo = fmax(pa + 3, f->px0 + 4) + w / 2, hi = fmin(pb - 3, f->px1 - 4) - w / 2;
            if (lo > hi || py - h / 2 < f->py0 + 4 || py + h / 2 > f->py1 - 4)
                continue;
            double mid = 0.5 * (lo + hi);
            for (int s = 0; s <= (int)((hi - lo) / 2) + 1; s++) {
                int found = 0;
                for (int sign = -1; sign <= 1 && !found; sign += 2) {
                    double px = fmin(hi, fmax(lo, mid + sign * 2.0 * s));
                    if (!obs_hit(ob, px - w / 2, py - h / 2, px + w / 2, py + h / 2)) {
                        r->x = f->x0 + (px - f->px0) / (f->px1 - f->px0) * (f->x1 - f->x0);
                        r->drawn = 1 + two;
                        obs_box(ob, px - w / 2, py - h / 2, px + w / 2, py + h / 2);
                        found = 1;
                    }
                }
                if (found)
                    break;
            }
        }
    }
}

/* The value of parameter2 on the branches' line: the case's, where every curve starts. */
static double line_value2(const gd_case *c, const gd_contin_result *res)
{
    for (int i = 0; i < res->ncurves; i++)
        if (res->curve[i].cv.npoints > 0 && res->curve[i].branch >= 0)
            return res->curve[i].cv.pt[0].p2 * res->scale2;
    return res->ncurves > 0 && res->curve[0].cv.npoints > 0 ? res->curve[0].cv.pt[0].p2 * res->scale2
                                                           : 0.5 * (c->cont_from2 + c->cont_to2);
}

/* The regions named from the run, placed as the picture draws them (no map; with one, none). */
static void regions_of(const gd_case *c, const gd_contin_result *res, const gd_overlay_curves *o,
                       gd_curve_regions *rg)
{
    memset(rg, 0, sizeof *rg);
    if (c->cont_overlay_map[0] || res->ncurves == 0)
        return;
    frame_px f;
    int W, H;
    layout(c, NULL, NULL, o && o->n > 0, res, o, line_value2(c, res), &f, &W, &H);
    gd_contin_regions_name(res, c->cont_from, c->cont_to, line_value2(c, res), rg);
    c2_label lab[C2_LABELS];
    int nc2, nl = c2_labels(res, &f, lab, NULL, &nc2);
    obstacles ob = {0};
    curve_obstacles(res, o, &f, lab, nl, &ob);
    place_regions(&f, &ob, rg);
    free(ob.x);
    free(ob.y);
}

gd_status gd_plot_curve_regions(const gd_case *c, const gd_contin_result *res, gd_curve_regions *rg, gd_error *err)
{
    memset(rg, 0, sizeof *rg);
    gd_overlay_curves o;
    gd_status st = gd_contin_overlay_curves_read(c, &o, err);
    if (st != GD_OK)
        return st;
    regions_of(c, res, &o, rg);
    gd_contin_overlay_free(NULL, &o);
    return GD_OK;
}

static void plot_one(gd_plot_script *s, int svg, const gd_case *c, const gd_contin_result *res,
                     const gd_overlay_map *m, const grid *g, const gd_overlay_curves *o, const gd_curve_regions *rg)
{
    int over = (m && m->n > 0) || (o && o->n > 0);
    gd_qty q1, q2;
    gd_qty_key(res->parameter, &q1);
    gd_qty_key(res->parameter2, &q2);
    char xl[200], yl[200], title[400] = "", n1[140], n2[140];
    gd_qty_label(&q1, xl, sizeof xl);
    gd_qty_label(&q2, yl, sizeof yl);
    gd_gp_text(q1.name, n1, sizeof n1);
    gd_gp_text(q2.name, n2, sizeof n2);
    if (c->title[0])
        gd_gp_title(c->title, title, sizeof title);
    frame_px f;
    int W, H;
    layout(c, m, g, over, res, o, res->ncurves > 0 ? line_value2(c, res) : NAN, &f, &W, &H);
    gd_fig_begin(s, svg, W, H, "curves");
    int rg_present[RG_N] = {0}, old_present[4] = {0};
    if (m && m->n > 0)
        map_blocks(s, m, g, rg_present);
    if (o && o->n > 0)
        old_blocks(s, o, old_present);
    static const char *c2_words[] = {"cusp", "fold-flip", "resonance 1:1", "resonance 1:2", "resonance 1:3",
                                     "resonance 1:4", "grazing on a fold",
                                     "grazing on a period doubling", "grazing on a Neimark-Sacker point",
                                     "double grazing"};
    int c2_present[GD_C2_DOUBLE_GRAZING + 1] = {0}, nc2 = 0;
    c2_label lab[C2_LABELS];
    int nl = c2_labels(res, &f, lab, c2_present, &nc2);
    for (int l = 0; l < nl; l++)
        gd_plot_printf(s, "set label %d '%s' at %.12g, %.12g offset character 1.2, 0.9 left front\n", l + 1,
                          lab[l].text, lab[l].x, lab[l].y);
    int nlabel = nl;
    if (m && m->n > 0) {
        /* the regions' names from the map's cells */
        obstacles ob = {0};
        curve_obstacles(res, o, &f, lab, nl, &ob);
        region_labels(s, m, g, &f, &ob, &nlabel);
        free(ob.x);
        free(ob.y);
    }
    int named = 0;
    for (int i = 0; rg && i < rg->n; i++) {
        const gd_curve_region *r = &rg->r[i];
        if (!r->drawn)
            continue;
        char a[256], b[256], ta[600], tb[600];
        split_name(r->label, r->drawn == 2, a, b, sizeof a);
        gd_gp_text(a, ta, sizeof ta);
        gd_gp_text(b, tb, sizeof tb);
        gd_plot_printf(s, "set label %d '%s%s%s' at %.12g, %.12g center front tc rgb '#222222'%s\n", ++nlabel,
                       ta, b[0] ? "' . \"\\n\" . '" : "", tb, r->x, r->y, b[0] ? " offset 0, 0.5" : "");
        named++;
    }
    char sub[600] = "";
    if (m && m->n > 0) {
        char d[GD_PATH_MAX], dt[GD_PATH_MAX + 64];
        const char *b = strrchr(c->cont_overlay_map, '/');
        snprintf(d, sizeof d, "%s", b && b[1] ? b + 1 : c->cont_overlay_map);
        gd_gp_text(d, dt, sizeof dt);
        snprintf(sub, sizeof sub, "' . \"\\n\" . 'over the regime map %s (a cell split in two: the sweep up, left, and "
                 "down, right, end on different motions)", dt);
    } else if (named > 0) {
        char v[64], u[64];
        snprintf(v, sizeof v, "%.6g", rg->r[0].y);
        gd_gp_text(q2.unit[0] && strcmp(q2.unit, "-") != 0 ? q2.unit : "", u, sizeof u);
        snprintf(sub, sizeof sub, "' . \"\\n\" . 'regions named on the line of the branch at %s = %s%s%s, by its stable "
                 "orbits", n2, v, u[0] ? " " : "", u);
    }
    /* the kinds drawn, in the order of gd_curve_kind, named in the title */
    static const char *kind_plural[4] = {"folds", "period doublings", "Neimark-Sacker points", "grazings"};
    int kind_present[4] = {0}, nkinds = 0;
    for (int i = 0; i < res->ncurves; i++)
        if (res->curve[i].cv.kind >= 0 && res->curve[i].cv.kind < 4 && !kind_present[res->curve[i].cv.kind]++)
            nkinds++;
    char kinds_text[120] = "";
    for (int k = 0, seen = 0; k < 4; k++)
        if (kind_present[k]) {
            size_t n = strlen(kinds_text);
            snprintf(kinds_text + n, sizeof kinds_text - n, "%s%s", seen == 0 ? "" : seen == nkinds - 1 ? " and " : ", ",
                     kind_plural[k]);
            seen++;
        }
    gd_plot_printf(s, "set title '%s%s%s against the %s and the %s%s'\n", title, title[0] ? "' . \"\\n\" . '" : "",
                   kinds_text, n1, n2, sub);
    gd_plot_printf(s, "set xlabel '%s'\nset ylabel '%s'\nset offsets 0, 0, 0, 0\n"
                         "set xrange [%.12g:%.12g]\nset yrange [%.12g:%.12g]\n",
                      xl, yl, f.x0, f.x1, f.y0, f.y1);
    if (over)
        gd_plot_printf(s, "set lmargin at screen %.4f\nset rmargin at screen %.4f\nset bmargin at screen %.4f\n"
                          "set tmargin at screen %.4f\nset key at screen %.4f, screen %.4f left top vertical Left reverse "
                          "samplen 3 spacing %.4f width -2\nset grid front\n",
                       OX0, OX1, OY0, OY1, OX1 + 0.02, OY1, GD_KEY_SPACING(svg, 1.25));
    else
        gd_plot_printf(s, "set lmargin at screen %.4f\nset rmargin at screen %.4f\nset bmargin at screen %.4f\n"
                          "set tmargin at screen %.4f\n"
                          "set key at screen 0.5, screen 0.045 center bottom horizontal samplen 3 spacing %.4f\n",
                       NX0, NX1, NY0, NY1, GD_KEY_SPACING(svg, 1.2));
    if (nc2 > 0) {
        /* the codimension-two points' abbreviations, a line of their own under the key (in the key
         * they made its rows longer than the picture) */
        char words[600];
        int n = 0, first = 1;
        for (int k = 0; k <= GD_C2_DOUBLE_GRAZING && n < (int)sizeof words; k++)
            if (c2_present[k]) {
                n += snprintf(words + n, sizeof words - (size_t)n, "%s%s %s", first ? "" : ", ", gd_codim2_label(k),
                              c2_words[k]);
                first = 0;
            }
        gd_plot_printf(s, "set label %d '%s' at screen %.4f, screen 0.012 %s front\n", ++nlabel, words,
                       over ? OX0 : 0.5, over ? "left" : "center");
    }
    /* the box of the two ranges, where the curves end */
    gd_plot_printf(s, "set object 1 rect from %.12g, %.12g to %.12g, %.12g %s clip fs empty border lc rgb "
                         "'#999999' dt 3 lw 1\n",
                      fmin(c->cont_from, c->cont_to), fmin(c->cont_from2, c->cont_to2), fmax(c->cont_from, c->cont_to),
                      fmax(c->cont_from2, c->cont_to2), m && m->n > 0 ? "front" : "behind");
    /* by gd_curve_kind: fold: orange, solid; period doubling: blue, dashed; Neimark-Sacker: vermillion,
     * dash-dot; grazing: bluish green, dotted (Okabe-Ito) */
    static const struct { const char *label; int colour, dt; } kinds[4] = {
        {"fold", 1, 1}, {"period doubling", 4, 2}, {"Neimark-Sacker", 5, 4}, {"grazing", 3, 3}};
    gd_plot_printf(s, "plot ");
    const char *sep = "";
    /* under the curves: the map's cells, then the earlier run's curves */
    for (int k = 0; k < RG_N; k++)
        if (rg_present[k]) {
            char name[80];
            snprintf(name, sizeof name, "%s%s", rg_regime[k % 3], k < 3 ? ", period 1" : ", other motion");
            gd_plot_printf(s, "%s$RG%d using 1:2:3:4:5:6 with boxxyerror fs solid 1.0 noborder lc rgb '%s' title '%s'",
                           sep, k, rg_colour[k], name);
            sep = ", \\\n  ";
        }
    int first_old = 1;
    for (int k = 0; k < 4; k++)
        if (old_present[k]) {
            char words[600] = "", wt[800];
            if (first_old) {
                old_words(o, c->cont_overlay_curves, words, sizeof words);
                gd_gp_text(words, wt, sizeof wt);
            }
            int dt = k == GD_CURVE_FOLD ? 1 : k == GD_CURVE_PERIOD_DOUBLING ? 2 : k == GD_CURVE_GRAZING ? 3 : 4;
            gd_plot_printf(s, "%s$OLD%d using 1:2 with lines lw 1.4 dt %d lc rgb '#808080' %s%s%s", sep, k, dt,
                           first_old ? "title '" : "notitle", first_old ? wt : "", first_old ? "'" : "");
            first_old = 0;
            sep = ", \\\n  ";
        }
    for (int i = 0; i < res->ncurves; i++) {
        int k = res->curve[i].cv.kind >= 0 && res->curve[i].cv.kind < 4 ? res->curve[i].cv.kind : GD_CURVE_GRAZING;
        gd_plot_printf(s, "%s'curves.csv' using 7:($1 == %d ? $8 : 1/0) with lines lw 2.2 dt %d lc rgb '%s' notitle",
                          sep, i, kinds[k].dt, gd_colour[kinds[k].colour]);
        sep = ", \\\n  ";
    }
    for (int k = 0; k < 4; k++)
        if (kind_present[k]) /* the key names the kinds drawn */
            gd_plot_printf(s, "%s1/0 with lines lw 2.2 dt %d lc rgb '%s' title '%s'", sep, kinds[k].dt,
                          gd_colour[kinds[k].colour], kinds[k].label);
    gd_plot_printf(s, "%s'curves.csv' using 7:($6 == 0 ? $8 : 1/0) with points pt 7 ps 1.1 lc rgb '%s' "
                         "title 'start: a bifurcation of a branch'",
                      sep, gd_colour[0]);
    if (nc2 > 0) /* the codimension-two points: an open diamond larger than the starts, drawn after them */
        gd_plot_printf(s, "%s'codim2.csv' using 6:7 with points pt 12 ps 2.2 lw 2 lc rgb '%s' title "
                          "'codimension-two point'", sep, gd_colour[0]);
    gd_plot_printf(s, "\n");
    gd_fig_end(s, 0);
}

void gd_plot_curves(const gd_plotter *p, const gd_case *c, const gd_contin_result *res)
{
    if (res->ncurves == 0)
        return;
    gd_error e = {0};
    gd_overlay_map m;
    gd_overlay_curves o;
    grid g = {0};
    gd_status st = gd_contin_overlay_map_read(c, &m, &e);
    if (st == GD_OK)
        st = gd_contin_overlay_curves_read(c, &o, &e);
    else
        memset(&o, 0, sizeof o);
    if (st == GD_OK && m.n > 0 && !grid_build(&m, &g))
        st = gd_error_set(&e, GD_ERR_NOMEM, "out of memory drawing the regime map under the curves");
    if (st != GD_OK) {
        grid_free(&g);
        gd_contin_overlay_free(&m, &o);
        gd_plot_fail(p, "pictures not drawn", &e);
        return;
    }
    gd_curve_regions *rg = malloc(sizeof *rg);
    if (rg)
        regions_of(c, res, &o, rg);
    gd_plot_script s = {0};
    plot_one(&s, 0, c, res, &m, &g, &o, rg);
    plot_one(&s, 1, c, res, &m, &g, &o, rg);
    free(rg);
    grid_free(&g);
    gd_contin_overlay_free(&m, &o);
    static const char *names[] = {"curves"};
    gd_plot_draw(p, &s, names, 1, "pictures not drawn");
}
