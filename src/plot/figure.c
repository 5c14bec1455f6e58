/* What every picture shares (figure.h). */
#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

const char *const gd_colour[GD_NCOLOURS] = {"#000000", "#E69F00", "#56B4E9", "#009E73",
                                              "#0072B2", "#D55E00", "#CC79A7"};

void gd_fig_begin(gd_plot_script *s, int svg, int w, int h, const char *name)
{
    gd_plot_printf(s, "reset\n");
    if (svg)
        gd_plot_printf(s, "set terminal svg size %d,%d dynamic enhanced font 'sans,%g'\n", w, h, GD_FIG_PX);
    else
        gd_plot_printf(s, "set terminal pngcairo size %d,%d enhanced font ',%g'\n", w, h, GD_FIG_PT);
    gd_plot_printf(s, "set encoding utf8\nset output '.%s.%s.tmp'\n", name, svg ? "svg" : "png");
    gd_plot_printf(s, "set datafile separator ','\nset datafile columnheaders\n"
                         "set datafile missing 'NaN'\nset grid lc rgb '#cccccc' lw 0.8 dt 1\n"
                         "set border lw 1\nset key noopaque nobox\nset autoscale fix\n"
                         "set offsets graph 0.04, graph 0.04, graph 0.07, graph 0.07\n");
}

void gd_fig_end(gd_plot_script *s, int multiplot)
{
    gd_plot_printf(s, "%sunset output\n", multiplot ? "unset multiplot\n" : "");
}

void gd_series_style(int i, const char **colour, int *dash)
{
    *colour = gd_colour[i % GD_NCOLOURS];
    *dash = 1 + (i / GD_NCOLOURS) % 4;
}

/* viridis (matplotlib), every tenth */
static const unsigned char viridis[11][3] = {
    {0x44, 0x01, 0x54}, {0x48, 0x24, 0x75}, {0x41, 0x44, 0x87}, {0x35, 0x5f, 0x8d}, {0x2a, 0x78, 0x8e}, {0x21, 0x91, 0x8c},
    {0x22, 0xa8, 0x84}, {0x44, 0xbf, 0x70}, {0x7a, 0xd1, 0x51}, {0xbd, 0xdf, 0x26}, {0xfd, 0xe7, 0x25}};

void gd_viridis(double t, char out[8])
{
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    int i = (int)floor(t * 10);
    if (i > 9)
        i = 9;
    double f = t * 10 - i;
    int c[3];
    for (int k = 0; k < 3; k++)
        c[k] = (int)lround(viridis[i][k] + f * (viridis[i + 1][k] - viridis[i][k]));
    snprintf(out, 8, "#%02x%02x%02x", c[0], c[1], c[2]);
}

void gd_palette_viridis(gd_plot_script *s, double t0, double t1)
{
    gd_plot_printf(s, "set palette defined (");
    for (int k = 0; k <= 8; k++) {
        char c[8];
        gd_viridis(t0 + (t1 - t0) * k / 8.0, c);
        gd_plot_printf(s, "%s%d '%s'", k ? ", " : "", k, c);
    }
    gd_plot_printf(s, ")\n");
}

double gd_nice_step(double span, int n)
{
    if (!(span > 0) || n < 1)
        return 1;
    double raw = span / n, p = pow(10, floor(log10(raw))), m = raw / p;
    double nice = m < 1.5 ? 1 : m < 2.25 ? 2 : m < 3.5 ? 2.5 : m < 7.5 ? 5 : 10;
    return nice * p;
}

void gd_pad(double lo, double hi, double frac, int logscale, double *a, double *b)
{
    if (logscale && lo > 0 && hi > 0) {
        double l0 = log10(lo), l1 = log10(hi), d = l1 - l0 > 0 ? l1 - l0 : 1;
        if (!(l1 - l0 > 0)) { /* one value: half a decade each side */
            l0 -= 0.5;
            l1 += 0.5;
            d = 1;
        }
        *a = pow(10, l0 - frac * d);
        *b = pow(10, l1 + frac * d);
        return;
    }
    double d = hi - lo;
    if (!(d > 0)) {
        d = fabs(lo) > 0 ? fabs(lo) * 0.2 : 1;
        *a = lo - d / 2;
        *b = hi + d / 2;
        return;
    }
    *a = lo - frac * d;
    *b = hi + frac * d;
}

double gd_text_width(const char *s, double px)
{
    double w = 0;
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if ((*p & 0xC0) == 0x80)
            continue; /* a continuation byte of UTF-8 */
        if (*p == ' ')
            w += 0.32;
        else if (strchr("il.,:;'|!", *p))
            w += 0.28;
        else if (strchr("frtIJ()[]-", *p))
            w += 0.4;
        else if (*p >= 'A' && *p <= 'Z')
            w += 0.72;
        else if (*p == 'm' || *p == 'w' || *p == 'M' || *p == 'W')
            w += 0.95;
        else
            w += 0.62;
    }
    return w * px;
}

static int box_hits(double ax0, double ay0, double ax1, double ay1, double bx0, double by0, double bx1, double by1)
{
    return ax0 < bx1 && bx0 < ax1 && ay0 < by1 && by0 < ay1;
}

void gd_place_labels(gd_fig_label *l, int n, double fx0, double fy0, double fx1, double fy1, const double *pts,
                      int npts)
{
    /* the places tried, nearest first: above, above right, above left, right, left, below ... */
    static const double cand[][2] = {{0, -1}, {0.7, -1}, {-0.7, -1}, {1, 0}, {-1, 0}, {0, 1}, {0.7, 1}, {-0.7, 1},
                                     {0, -2.2}, {1.2, -2.2}, {-1.2, -2.2}, {0, 2.2}};
    const double gap = 7, pad = 2;
    for (int i = 0; i < n; i++) {
        l[i].keep = 0;
        for (size_t c = 0; c < sizeof cand / sizeof cand[0] && !l[i].keep; c++) {
            double cx = l[i].x + cand[c][0] * (l[i].w / 2 + gap), cy = l[i].y + cand[c][1] * (l[i].h / 2 + gap);
            double x0 = cx - l[i].w / 2 - pad, x1 = cx + l[i].w / 2 + pad, y0 = cy - l[i].h / 2 - pad,
                   y1 = cy + l[i].h / 2 + pad;
            if (x0 < fx0 + 2 || x1 > fx1 - 2 || y0 < fy0 + 2 || y1 > fy1 - 2)
                continue;
            int hit = 0;
            for (int j = 0; j < i && !hit; j++)
                if (l[j].keep)
                    hit = box_hits(x0, y0, x1, y1, l[j].lx - l[j].w / 2 - pad, l[j].ly - l[j].h / 2 - pad,
                                   l[j].lx + l[j].w / 2 + pad, l[j].ly + l[j].h / 2 + pad);
            for (int k = 0; k < npts && !hit; k++)
                hit = pts[2 * k] > x0 - 3 && pts[2 * k] < x1 + 3 && pts[2 * k + 1] > y0 - 3 && pts[2 * k + 1] < y1 + 3;
            if (!hit) {
                l[i].lx = cx;
                l[i].ly = cy;
                l[i].keep = 1;
            }
        }
    }
}

/* cubic Hermite on [0, 1]: value at s of the ends p0, p1 with slopes m0, m1 (per unit s) */
static double hermite(double p0, double p1, double m0, double m1, double s)
{
    double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
}

size_t gd_hermite_block(gd_plot_script *s, const char *name, const double *t, const double *x, const double *v,
                         size_t i0, size_t i1, double dxdt_per_v)
{
    gd_plot_printf(s, "$%s << EOD\nt,x,v\n", name);
    if (i1 <= i0) {
        gd_plot_printf(s, "EOD\n");
        return 0;
    }
    double xl = x[i0], xh = x[i0], vl = v[i0], vh = v[i0];
    for (size_t i = i0; i < i1; i++) {
        xl = fmin(xl, x[i]);
        xh = fmax(xh, x[i]);
        vl = fmin(vl, v[i]);
        vh = fmax(vh, v[i]);
    }
    double sx = xh > xl ? 1 / (xh - xl) : 1, sv = vh > vl ? 1 / (vh - vl) : 1;
    size_t npts = 0;
    for (size_t i = i0; i < i1; i++) {
        gd_plot_printf(s, "%.10g,%.10g,%.10g\n", t[i], x[i], v[i]);
        npts++;
        if (i + 1 >= i1)
            break;
        double h = t[i + 1] - t[i];
        if (!(h > 0))
            continue;
        /* slopes of v: central differences (one-sided at the ends) */
        double a0 = i > i0 ? (v[i + 1] - v[i - 1]) / (t[i + 1] - t[i - 1]) : (v[i + 1] - v[i]) / h;
        double a1 = i + 2 < i1 ? (v[i + 2] - v[i]) / (t[i + 2] - t[i]) : (v[i + 1] - v[i]) / h;
        /* how far the curve (x, v) turns over the interval: the angle between its tangents at the
         * ends, in the axes normalised to the data's extent */
        double d0x = v[i] * dxdt_per_v * sx, d0v = a0 * sv, d1x = v[i + 1] * dxdt_per_v * sx, d1v = a1 * sv;
        double ang = fabs(atan2(d0x * d1v - d0v * d1x, d0x * d1x + d0v * d1v));
        int k = (int)ceil(ang / (4 * M_PI / 180));
        k = k < 1 ? 1 : k > 24 ? 24 : k;
        for (int j = 1; j < k; j++) {
            double u = (double)j / k;
            double xi = hermite(x[i], x[i + 1], v[i] * dxdt_per_v * h, v[i + 1] * dxdt_per_v * h, u);
            double vi = hermite(v[i], v[i + 1], a0 * h, a1 * h, u);
            gd_plot_printf(s, "%.10g,%.10g,%.10g\n", t[i] + u * h, xi, vi);
            npts++;
        }
    }
    gd_plot_printf(s, "EOD\n");
    return npts;
}

void gd_log_tics(gd_plot_script *s, const char *axis, double lo, double hi)
{
    if (!(lo > 0) || !(hi > lo))
        return;
    /* 1, 2 and 5 times the powers of ten over less than two decades, the powers alone beyond */
    static const double m125[] = {1, 2, 5};
    int few = hi / lo < 100;
    gd_plot_printf(s, "set %stics (", axis);
    int first = 1;
    for (int e = (int)floor(log10(lo)) - 1; e <= (int)ceil(log10(hi)); e++)
        for (int k = 0; k < (few ? 3 : 1); k++) {
            double v = m125[k] * pow(10, e);
            if (v < lo * (1 - 1e-9) || v > hi * (1 + 1e-9))
                continue;
            if (few)
                gd_plot_printf(s, "%s'%g' %.12g", first ? "" : ", ", v, v);
            else
                gd_plot_printf(s, "%s'10^{%d}' %.12g", first ? "" : ", ", e, v);
            first = 0;
        }
    gd_plot_printf(s, ")\n");
}

void gd_flank_panel(gd_plot_script *s, int h, int halves)
{
    double l = halves > 1 ? (h ? 0.525 : 0.06) : 0.11, r = halves > 1 ? (h ? 0.875 : 0.41) : 0.80;
    gd_plot_printf(s, "set lmargin at screen %.4f\nset rmargin at screen %.4f\nset tmargin at screen 0.86\n"
                         "set bmargin at screen 0.12\n", l, r);
    if (h + 1 < halves)
        gd_plot_printf(s, "unset colorbox\n");
    else
        gd_plot_printf(s, "set colorbox user origin screen %.4f,0.12 size screen 0.018,0.74\n", r + 0.015);
}
