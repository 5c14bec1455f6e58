/* The pictures of `sweep`: the bifurcation diagram of one swept key, the regime map of two. */
#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The branches of a sweep as drawn: continuation up in blue open circles and a wide line under
 * down's vermillion dots and thin line, so that both show where they coincide (Okabe-Ito). */
static const char *branch_colour[] = {"#0072B2", "#D55E00", "#000000"};
static const char *branch_point[] = {"pt 6 ps 0.8", "pt 7 ps 0.45", "pt 7 ps 0.5"};
static const char *branch_line[] = {"pt 6 ps 0.8 lw 2.5", "pt 7 ps 0.45 lw 1", "pt 7 ps 0.5 lw 1.2"};
static const char *branch_key[] = {"continuation up", "continuation down", "independent points"};

/* The swept parameter as the axes name it. */
static void param_label(const gd_sweep_plan *p, int a, char *buf, size_t len)
{
    gd_qty q;
    gd_qty_key(p->parameter[a], &q);
    gd_qty_label(&q, buf, len);
}

/* The range of axis a of the plan, widened by frac (log: of its decades). */
static void param_range(const gd_sweep_plan *p, int a, double frac, double *lo, double *hi)
{
    double v0 = p->values[a][0], v1 = p->values[a][p->npoints[a] - 1];
    gd_pad(fmin(v0, v1), fmax(v0, v1), frac, p->spacing[a] == GD_SWEEP_LOG, lo, hi);
}

/* The y range of the Poincare panel (values times scale): the range of every point, unless one
 * parameter value reaches so far beyond all others that they would be squashed into a third of
 * the panel; then the range of the others, and that value's points beyond it drawn as markers on
 * the panel's edge with their extreme value. *off gets the index of that value (-1: none). */
static void poincare_range(const gd_sweep_plan *p, const gd_sweep_point *pts, double scale, double *lo, double *hi,
                           int *off, double *off_x, double *off_v)
{
    int nv = p->npoints[0];
    double *cl = malloc(sizeof(double) * (size_t)nv * 2);
    *off = -1;
    *lo = INFINITY;
    *hi = -INFINITY;
    if (!cl)
        return;
    for (int i = 0; i < nv; i++)
        cl[2 * i] = INFINITY, cl[2 * i + 1] = -INFINITY;
    for (int s = 0; s < p->nslots; s++) {
        const gd_sweep_point *pt = &pts[s];
        for (long k = 0; k < pt->npoincare; k++) {
            double y = pt->poincare[k * p->nresp] * scale;
            if (!isfinite(y))
                continue;
            cl[2 * pt->idx[0]] = fmin(cl[2 * pt->idx[0]], y);
            cl[2 * pt->idx[0] + 1] = fmax(cl[2 * pt->idx[0] + 1], y);
        }
    }
    for (int i = 0; i < nv; i++)
        if (cl[2 * i] <= cl[2 * i + 1]) {
            *lo = fmin(*lo, cl[2 * i]);
            *hi = fmax(*hi, cl[2 * i + 1]);
        }
    int used = 0;
    for (int i = 0; i < nv; i++)
        used += cl[2 * i] <= cl[2 * i + 1];
    if (used >= 5 && *hi > *lo) {
        int best = -1;
        double blo = 0, bhi = 0;
        for (int j = 0; j < nv; j++) {
            if (!(cl[2 * j] <= cl[2 * j + 1]))
                continue;
            double l = INFINITY, h = -INFINITY;
            for (int i = 0; i < nv; i++)
                if (i != j && cl[2 * i] <= cl[2 * i + 1]) {
                    l = fmin(l, cl[2 * i]);
                    h = fmax(h, cl[2 * i + 1]);
                }
            if (best < 0 || h - l < bhi - blo)
                best = j, blo = l, bhi = h;
        }
        if (best >= 0 && bhi - blo < (*hi - *lo) / 3) {
            *off = best;
            *off_x = p->values[0][best];
            *off_v = fabs(cl[2 * best] - blo) > fabs(cl[2 * best + 1] - bhi) ? cl[2 * best] : cl[2 * best + 1];
            *lo = blo;
            *hi = bhi;
        }
    }
    free(cl);
}

/* The sweep's model for a title. */
static const char *model_words(const gd_case *c)
{
    static const char *w[] = {"torsional model", "torsional model of the two halves", "bending-torsion-axial model"};
    return c->model >= 0 && c->model <= 2 ? w[c->model] : "model";
}

/* Fig. 15 of the paper: the Poincare points, the largest Lyapunov exponent and the RMS
 * acceleration stacked on one parameter axis; up and down in two colours. */
static void script_bifurcation(gd_plot_script *b, const gd_case *c, const gd_sweep_plan *p,
                               const gd_sweep_point *pts, const int *has, int mle, int svg)
{
    int panels = mle ? 4 : 3, h = 180 + 300 * panels;
    double x0, x1;
    param_range(p, 0, 0.025, &x0, &x1);
    char xl[256], title[512], q0[256];
    param_label(p, 0, xl, sizeof xl);
    gd_qty par;
    gd_qty_key(p->parameter[0], &par);
    gd_gp_text(par.name, q0, sizeof q0);
    snprintf(title, sizeof title, "Sweep of the %s (%s, %s)", q0, model_words(c),
             p->mode == GD_SWEEP_CONTINUATION ? "continuation" : "independent points");
    /* the Poincare samples of the first response, in the tables' dimensionless units: lengths
     * times the characteristic length, rates as they are */
    gd_qty r;
    gd_qty_column(p->resp[0].name, p->nmesh, &r);
    double scale = 1;
    if (strcmp(r.unit, "µm") == 0)
        scale = c->characteristic_length_um;
    else
        snprintf(r.unit, sizeof r.unit, "-");
    if (strcmp(r.unit, "-") == 0) {
        size_t l = strlen(r.name);
        snprintf(r.name + l, sizeof r.name - l, " over b_c ω_n");
    }
    size_t l = strlen(r.name);
    snprintf(r.name + l, sizeof r.name - l, " at the Poincaré section");
    char yl[300];
    gd_qty_label(&r, yl, sizeof yl);
    double ylo, yhi, off_x = 0, off_v = 0;
    int off;
    poincare_range(p, pts, scale, &ylo, &yhi, &off, &off_x, &off_v);
    double ya, yb;
    gd_pad(ylo, yhi, 0.07, 0, &ya, &yb);
    gd_fig_begin(b, svg, 1200, h, "bifurcation");
    double top = 1 - 95.0 / h, bottom = 70.0 / h;
    gd_plot_printf(b, "set multiplot layout %d,1 margins 0.1,0.96,%.4f,%.4f spacing 0,0.025 title '%s'\n", panels,
                      bottom, top, title);
    gd_plot_printf(b, "set xrange [%.12g:%.12g]\n%sset format x ''\nunset xlabel\n", x0, x1,
                      p->spacing[0] == GD_SWEEP_LOG ? "set logscale x\n" : "");
    /* the key above the panels, right */
    gd_plot_printf(b, "set key at screen 0.96,%.4f right top horizontal samplen 1.5\n", 1 - 48.0 / h);
    gd_plot_printf(b, "set ylabel '%s'\nset yrange [%.9g:%.9g]\n", yl, ya, yb);
    char rc[80];
    snprintf(rc, sizeof rc, "column('%s')*%.12g", p->resp[0].name, scale);
    double edge = 0;
    if (off >= 0) {
        /* the points of that value beyond the range: a triangle on the edge they lie beyond,
         * labelled with their extreme value */
        edge = off_v < ylo ? ya + 0.035 * (yb - ya) : yb - 0.035 * (yb - ya);
        gd_plot_printf(b, "set label 1 '%.3g%s%s' at %.12g,%.12g offset 1.3,0 left front\n", off_v,
                          strcmp(r.unit, "-") ? " " : "", strcmp(r.unit, "-") ? r.unit : "", off_x, edge);
    }
    /* the points inside the range (its ends widened by a millionth: the table's digits are
     * fewer than those the range was found with) */
    double tol = 1e-6 * (yhi - ylo > 0 ? yhi - ylo : 1);
    gd_plot_printf(b, "plot ");
    int first = 1;
    for (int br = 0; br < 3; br++)
        if (has[br]) {
            gd_plot_printf(b, "%s'bifurcation.csv' using 'parameter':(strcol('direction') eq '%s' && %s >= %.12g && "
                                 "%s <= %.12g ? %s : 1/0) with points %s lc rgb '%s' title '%s'",
                              first ? "" : ", ", gd_sweep_branch_name(br), rc, ylo - tol, rc, yhi + tol, rc,
                              branch_point[br], branch_colour[br], branch_key[br]);
            first = 0;
        }
    if (off >= 0)
        gd_plot_printf(b, ", 'bifurcation.csv' using 'parameter':(abs(column('parameter') - %.12g) < %.6g && "
                             "(%s < %.12g || %s > %.12g) ? %.12g : 1/0) with points pt %d ps 1.3 lc rgb '#000000' "
                             "title 'beyond the axis'",
                          off_x, 1e-9 * fmax(1, fabs(off_x)), rc, ylo - tol, rc, yhi + tol, edge, off_v < ylo ? 11 : 9);
    gd_plot_printf(b, "\nunset label 1\nunset key\nset yrange [*:*]\n");
    /* sweep.csv's columns: the exponent, the RMS acceleration, the dynamic load factor (the larger
     * of the meshes') */
    const char *what[3] = {"largest Lyapunov exponent (per mesh period)", "RMS mesh acceleration (m/s²)",
                           "dynamic load factor (-)"};
    const char *col[3] = {"mle", "rms_accel_mps2", "dynamic_load_factor"};
    for (int q = mle ? 0 : 1; q < 3; q++) {
        if (q == 2)
            gd_plot_printf(b, "unset xzeroaxis\nset format x '%% h'\nset xlabel '%s'\n", xl);
        else if (q == 0)
            gd_plot_printf(b, "set xzeroaxis lt -1 lw 0.8\n");
        else
            gd_plot_printf(b, "unset xzeroaxis\n");
        gd_plot_printf(b, "set ylabel '%s'\nplot ", what[q]);
        first = 1;
        for (int br = 0; br < 3; br++)
            if (has[br]) {
                gd_plot_printf(b, "%s'sweep.csv' using 'parameter':(strcol('direction') eq '%s' ? column('%s') : 1/0) "
                                     "with linespoints %s lc rgb '%s' notitle",
                                  first ? "" : ", ", gd_sweep_branch_name(br), col[q], branch_line[br], branch_colour[br]);
                first = 0;
            }
        gd_plot_printf(b, "\n");
    }
    gd_fig_end(b, 1);
}

/* The motion classes of a regime map, in the order of its key, and their colours (Okabe-Ito and
 * a wine for the long periods; told apart by colour-blind readers). */
enum { CL_P1, CL_P2, CL_P3, CL_P4, CL_PN, CL_QUASI, CL_NOTP, CL_CHAOS, CL_FAILED, CL_N };
static const char *class_name[CL_N] = {"period-1", "period-2", "period-3", "period-4", "period-5 or more",
                                       "quasi-periodic", "not periodic (not settled)", "chaotic", "failed"};
static const int class_rgb[CL_N] = {0x0072B2, 0x56B4E9, 0x009E73, 0xCC79A7, 0x882255,
                                    0xE69F00, 0xBBBBBB, 0xD55E00, 0x000000};

static int motion_class(const gd_sweep_point *pt)
{
    if (pt->status != GD_POINT_DONE)
        return CL_FAILED;
    if (strcmp(pt->motion, "chaotic") == 0)
        return CL_CHAOS;
    if (strcmp(pt->motion, "quasi-periodic") == 0)
        return CL_QUASI;
    if (strncmp(pt->motion, "period-", 7) == 0) {
        int n = atoi(pt->motion + 7);
        return n >= 1 && n <= 4 ? CL_P1 + n - 1 : CL_PN;
    }
    return CL_NOTP;
}

/* The edges of the cells of axis a: each value's cell reaches half-way (geometrically on a log
 * axis) to its neighbours, the first and the last stop at the swept range's ends. */
static void cell_edges(const gd_sweep_plan *p, int a, int i, double *lo, double *hi)
{
    int n = p->npoints[a];
    const double *v = p->values[a];
    int lg = p->spacing[a] == GD_SWEEP_LOG;
    double prev = i > 0 ? (lg ? sqrt(v[i - 1] * v[i]) : 0.5 * (v[i - 1] + v[i])) : v[0];
    double next = i + 1 < n ? (lg ? sqrt(v[i + 1] * v[i]) : 0.5 * (v[i + 1] + v[i])) : v[n - 1];
    *lo = fmin(prev, next);
    *hi = fmax(prev, next);
    if (n == 1) {
        double d = fabs(v[0]) * 0.05 + 0.5;
        *lo = v[0] - d;
        *hi = v[0] + d;
    }
}

/* The regime map: motion class and largest Lyapunov exponent over the two parameters, one row
 * of panels per branch, drawn from the plan's points as cells that tile the swept ranges. */
static void script_map(gd_plot_script *b, const gd_sweep_plan *p, const gd_sweep_point *pts, const int *has,
                       int svg)
{
    int rows = has[0] + has[1] + has[2];
    int present[CL_N] = {0};
    int nm = 0;
    double *am = malloc(sizeof(double) * (size_t)(p->nslots > 0 ? p->nslots : 1));
    for (int s = 0; s < p->nslots; s++) {
        present[motion_class(&pts[s])] = 1;
        if (am && pts[s].status == GD_POINT_DONE && isfinite(pts[s].mle_per_period))
            am[nm++] = fabs(pts[s].mle_per_period);
    }
    /* the exponent's colour scale: to the 90th percentile of |exponent| (one column of chaos
     * does not wash the others out); larger values get the scale's end colour */
    double mle_abs = 0;
    if (nm > 0) {
        for (int i = 1; i < nm; i++)
            for (int j = i; j > 0 && am[j - 1] > am[j]; j--) {
                double t = am[j];
                am[j] = am[j - 1];
                am[j - 1] = t;
            }
        mle_abs = am[(int)floor(0.9 * (nm - 1))];
        if (!(mle_abs > 0))
            mle_abs = am[nm - 1];
    }
    free(am);
    if (!(mle_abs > 0))
        mle_abs = 0.01;
    double step = gd_nice_step(mle_abs, 2);
    mle_abs = ceil(mle_abs / step * (1 - 1e-9)) * step;
    /* the cells */
    for (int br = 0; br < 3; br++) {
        if (!has[br])
            continue;
        gd_plot_printf(b, "$MAP%d << EOD\nx,y,xlo,xhi,ylo,yhi,rgb,mle\n", br);
        for (int s = 0; s < p->nslots; s++) {
            const gd_sweep_point *pt = &pts[s];
            if (pt->branch != br)
                continue;
            double xl, xh, yl, yh;
            cell_edges(p, 0, pt->idx[0], &xl, &xh);
            cell_edges(p, 1, pt->idx[1], &yl, &yh);
            double e = pt->status == GD_POINT_DONE && isfinite(pt->mle_per_period) ? pt->mle_per_period : NAN;
            if (isfinite(e))
                e = fmax(-mle_abs, fmin(mle_abs, e));
            gd_plot_printf(b, "%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%d,", pt->value[0], pt->value[1], xl, xh, yl, yh,
                              class_rgb[motion_class(pt)]);
            if (isfinite(e))
                gd_plot_printf(b, "%.9g\n", e);
            else
                gd_plot_printf(b, "NaN\n");
        }
        gd_plot_printf(b, "EOD\n");
    }
    int W = 1300, H = 110 + 520 * rows;
    gd_fig_begin(b, svg, W, H, "regime_map");
    char xl[256], yl[256], q0[256], q1[256], title[600];
    param_label(p, 0, xl, sizeof xl);
    param_label(p, 1, yl, sizeof yl);
    gd_qty a0, a1;
    gd_qty_key(p->parameter[0], &a0);
    gd_qty_key(p->parameter[1], &a1);
    gd_gp_text(a0.name, q0, sizeof q0);
    gd_gp_text(a1.name, q1, sizeof q1);
    snprintf(title, sizeof title, "Regime map over the %s and the %s", q0, q1);
    double x0 = fmin(p->values[0][0], p->values[0][p->npoints[0] - 1]), x1 = fmax(p->values[0][0], p->values[0][p->npoints[0] - 1]);
    double y0 = fmin(p->values[1][0], p->values[1][p->npoints[1] - 1]), y1 = fmax(p->values[1][0], p->values[1][p->npoints[1] - 1]);
    if (p->npoints[0] == 1)
        cell_edges(p, 0, 0, &x0, &x1);
    if (p->npoints[1] == 1)
        cell_edges(p, 1, 0, &y0, &y1);
    gd_plot_printf(b, "set multiplot title '%s'\nset offsets 0,0,0,0\nset tics out\nset grid noxtics noytics\n", title);
    gd_plot_printf(b, "set xrange [%.12g:%.12g]\nset yrange [%.12g:%.12g]\nset xlabel '%s'\nset ylabel '%s'\n%s%s",
                      x0, x1, y0, y1, xl, yl, p->spacing[0] == GD_SWEEP_LOG ? "set logscale x\n" : "",
                      p->spacing[1] == GD_SWEEP_LOG ? "set logscale y\n" : "");
    double rh = (1 - 60.0 / H) / rows;
    int row = 0;
    for (int br = 0; br < 3; br++) {
        if (!has[br])
            continue;
        double top = 1 - 60.0 / H - row * rh, bot = top - rh;
        /* the motion: the classes that occur, in the key beside the panel */
        gd_plot_printf(b, "set lmargin at screen 0.075\nset rmargin at screen 0.395\nset tmargin at screen %.4f\n"
                             "set bmargin at screen %.4f\n", top - 40.0 / H, bot + 75.0 / H);
        gd_plot_printf(b, "set title 'motion (%s)'\nset key at screen 0.405,%.4f left top vertical Left reverse samplen 1.2 "
                             "spacing 1.2\nunset colorbox\n", branch_key[br], top - 40.0 / H);
        gd_plot_printf(b, "plot $MAP%d using 1:2:3:4:5:6:7 with boxxyerror fs solid 1.0 noborder lc rgb variable notitle",
                          br);
        for (int k = 0; k < CL_N; k++)
            if (present[k] && row == 0)
                gd_plot_printf(b, ", 1/0 with boxes fs solid 1.0 noborder lc rgb '#%06X' title '%s'", class_rgb[k],
                                  class_name[k]);
        gd_plot_printf(b, "\nunset key\n");
        /* the largest Lyapunov exponent */
        gd_plot_printf(b, "set lmargin at screen 0.62\nset rmargin at screen 0.885\n");
        gd_plot_printf(b, "set title 'largest Lyapunov exponent (%s)'\nset colorbox user origin screen 0.9,%.4f "
                             "size screen 0.018,%.4f\nset cbrange [%.6g:%.6g]\nset cbtics %.6g out\n"
                             "set cblabel 'largest Lyapunov exponent (per mesh period)' offset 1.5,0\n"
                             "set palette defined (-1 '#2166AC', -0.5 '#92C5DE', 0 '#F7F7F7', 0.5 '#F4A582', 1 '#B2182B')\n",
                          branch_key[br], bot + 75.0 / H, rh - 115.0 / H, -mle_abs, mle_abs, step);
        gd_plot_printf(b, "plot $MAP%d using 1:2:3:4:5:6:8 with boxxyerror fs solid 1.0 noborder lc palette notitle\n",
                          br);
        row++;
    }
    gd_fig_end(b, 1);
}

/* Draw the picture: the bifurcation diagram of one key, the regime map of two. */
static void draw(const gd_plotter *pl, const gd_case *c, const gd_sweep_plan *p, const gd_sweep_point *pts)
{
    int has[3] = {0, 0, 0}, mle = 0;
    for (int s = 0; s < p->nslots; s++) {
        has[pts[s].branch] = 1;
        if (pts[s].status == GD_POINT_DONE && isfinite(pts[s].mle_per_period))
            mle = 1;
    }
    gd_plot_script b = {0};
    const char *stem = p->naxes > 1 ? "regime_map" : "bifurcation";
    for (int f = 0; f < 2; f++) {
        if (p->naxes > 1)
            script_map(&b, p, pts, has, f);
        else
            script_bifurcation(&b, c, p, pts, has, mle, f);
    }
    gd_plot_draw(pl, &b, &stem, 1, "pictures not drawn");
}

void gd_plot_sweep(const gd_plotter *p, const gd_case *c, const gd_sweep_outcome *o)
{
    if (gd_plot_wanted(p, c->plots))
        draw(p, c, &o->plan, o->pts);
}
