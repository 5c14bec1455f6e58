/* The picture of a continuation (continuation.png, .svg): the response against the parameter,
 * one colour per period of the orbits, a segment solid where both its points are stable and
 * dashed otherwise, a marker per bifurcation kind with labels placed where they collide with
 * nothing (close points of one kind share one label, "9 NS"), a key of what is visible, and a
 * finished sweep's points over the branches when the case names one
 * (continuation.overlay_sweep). Drawn from the result in memory, the numbers of branch.csv and
 * bifurcations.csv. */
#include "figure.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 1300
#define H 780
/* the frame, as fractions of the picture (fixed: the labels are placed in pixels) */
#define FX0 0.085
#define FX1 0.73
#define FY0 0.10
#define FY1 0.885

/* The response drawn: its value at a measure, its column of branch.csv and of a sweep's tables. */
typedef struct resp {
    int kind, nmesh;
    double scale;
    gd_qty q;
    char label[300];
    const char *sweep_file, *sweep_col;
} resp;

static double resp_value(const resp *r, const gd_contin_measure *m)
{
    switch (r->kind) {
    case GD_CONT_RESP_MAX_DEFLECTION: return m->lambda_max_um[0];
    case GD_CONT_RESP_MIN_DEFLECTION: return m->lambda_min_um[0];
    case GD_CONT_RESP_POINCARE: return m->lambda_poincare * r->scale;
    case GD_CONT_RESP_DYNAMIC_LOAD_FACTOR:
        return r->nmesh > 1 ? fmax(m->dynamic_load_factor[0], m->dynamic_load_factor[1]) : m->dynamic_load_factor[0];
    default: return m->rms_accel_mps2[2];
    }
}

static void resp_of(const gd_case *c, const gd_contin_result *res, resp *r)
{
    static const char *col[] = {"rms_accel_mps2", "lambda_max_L_um", "lambda_min_L_um", "lambda_L",
                                "dynamic_load_factor"};
    r->kind = c->cont_response >= 0 && c->cont_response <= 4 ? c->cont_response : 0;
    r->nmesh = res->nmesh;
    r->scale = r->kind == GD_CONT_RESP_POINCARE ? c->characteristic_length_um : 1;
    gd_qty_column(col[r->kind], res->nmesh, &r->q);
    if (r->kind == GD_CONT_RESP_POINCARE) {
        size_t l = strlen(r->q.name);
        snprintf(r->q.name + l, sizeof r->q.name - l, " at mesh phase 0");
    }
    gd_qty_label(&r->q, r->label, sizeof r->label);
    r->sweep_file = r->kind == GD_CONT_RESP_POINCARE ? "bifurcation.csv" : "sweep.csv";
    r->sweep_col = r->kind == GD_CONT_RESP_POINCARE                ? "lambda_L"
                   : r->kind == GD_CONT_RESP_DYNAMIC_LOAD_FACTOR ? "dynamic_load_factor"
                                                                 : "rms_accel_mps2";
}

/* The overlay sweep's points (parameter, response, up 1 / down 0): read from its table. */
typedef struct sweep_pts {
    double *x, *y;
    int *up;
    int n;
} sweep_pts;

static int split_csv(char *line, char **f, int max)
{
    int n = 0;
    char *s = line;
    while (n < max) {
        f[n++] = s;
        char *c = strchr(s, ',');
        if (!c)
            break;
        *c = '\0';
        s = c + 1;
    }
    char *e = f[n - 1] + strcspn(f[n - 1], "\r\n");
    *e = '\0';
    return n;
}

static gd_status read_sweep(const char *path, const char *col, double scale, sweep_pts *sp, gd_error *err)
{
    memset(sp, 0, sizeof *sp);
    FILE *f = fopen(path, "r");
    if (!f)
        return gd_error_set(err, GD_ERR_IO, "%s: continuation.overlay_sweep: %s", path, strerror(errno));
    char line[8192];
    char *fld[256];
    int ip = -1, id = -1, iv = -1, cap = 0;
    if (fgets(line, sizeof line, f)) {
        int n = split_csv(line, fld, 256);
        for (int i = 0; i < n; i++) {
            if (strcmp(fld[i], "parameter") == 0)
                ip = i;
            if (strcmp(fld[i], "direction") == 0)
                id = i;
            if (strcmp(fld[i], col) == 0)
                iv = i;
        }
    }
    while (ip >= 0 && id >= 0 && iv >= 0 && fgets(line, sizeof line, f)) {
        int n = split_csv(line, fld, 256);
        if (n <= ip || n <= id || n <= iv)
            continue;
        double x = strtod(fld[ip], NULL), y = strtod(fld[iv], NULL) * scale;
        if (!isfinite(x) || !isfinite(y))
            continue;
        if (sp->n == cap) {
            cap = cap ? 2 * cap : 256;
            double *nx = realloc(sp->x, sizeof(double) * (size_t)cap), *ny = nx ? realloc(sp->y, sizeof(double) * (size_t)cap) : NULL;
            int *nu = ny ? realloc(sp->up, sizeof(int) * (size_t)cap) : NULL;
            if (nx)
                sp->x = nx;
            if (ny)
                sp->y = ny;
            if (!nu) {
                fclose(f);
                return gd_error_set(err, GD_ERR_NOMEM, "out of memory reading the overlay sweep");
            }
            sp->up = nu;
        }
        sp->x[sp->n] = x;
        sp->y[sp->n] = y;
        sp->up[sp->n] = strcmp(fld[id], "down") != 0;
        sp->n++;
    }
    fclose(f);
    return GD_OK;
}

/* the kinds of bifurcation: marker (gnuplot point type and size), label, key entry. A branch point
 * usually sits on another bifurcation (the fold or period doubling it was found beside): it is an
 * open pentagon, larger than the filled markers and drawn after them, so both stay visible. */
static const struct {
    int kind, pt;
    double ps;
    const char *mark, *key;
} kinds[] = {
    {GD_BIF_FOLD, 7, 1.5, "F", "fold (F)"},
    {GD_BIF_PERIOD_DOUBLING, 5, 1.5, "PD", "period doubling (PD)"},
    {GD_BIF_NEIMARK_SACKER, 13, 1.5, "NS", "Neimark–Sacker (NS)"},
    {GD_BIF_CONTACT_CHANGE, 9, 1.5, "C", "contact change, grazing (C)"},
    {GD_BIF_BRANCH_POINT, 14, 2.6, "BP", "branch point (BP)"},
};
#define NKINDS 5

typedef struct frame {
    double x0, x1, y0, y1;   /* data */
    int logx;
} frame;

static double px_x(const frame *f, double x)
{
    return W * (FX0 + (FX1 - FX0) * (x - f->x0) / (f->x1 - f->x0));
}

static double px_y(const frame *f, double y)
{
    return H * (1 - (FY0 + (FY1 - FY0) * (y - f->y0) / (f->y1 - f->y0)));
}

/* Whether period nper draws a visible part: at least 20 pixels of its segments more than 3 pixels
 * from the segments of every other period (the others drawn over or under it). */
static int period_visible(const gd_contin_result *res, const resp *r, const frame *f, int nper)
{
    double seen = 0;
    for (int b = 0; b < res->nbranches; b++) {
        const gd_contin_branch *cb = &res->branch[b];
        if (cb->nper != nper)
            continue;
        for (int i = 0; i + 1 < cb->br.npoints; i++) {
            double ax = px_x(f, gd_contin_value(res, cb->br.pt[i].orbit.p)), ay = px_y(f, resp_value(r, &cb->meas[i]));
            double bx = px_x(f, gd_contin_value(res, cb->br.pt[i + 1].orbit.p)),
                   by = px_y(f, resp_value(r, &cb->meas[i + 1]));
            double len = hypot(bx - ax, by - ay);
            int steps = (int)ceil(len / 2) + 1;
            for (int k = 0; k < steps; k++) {
                double x = ax + (bx - ax) * k / steps, y = ay + (by - ay) * k / steps, dmin = INFINITY;
                for (int o = 0; o < res->nbranches && dmin > 3; o++) {
                    const gd_contin_branch *ob = &res->branch[o];
                    if (ob->nper == nper)
                        continue;
                    for (int j = 0; j + 1 < ob->br.npoints && dmin > 3; j++) {
                        double cx = px_x(f, gd_contin_value(res, ob->br.pt[j].orbit.p)),
                               cy = px_y(f, resp_value(r, &ob->meas[j]));
                        double dx = px_x(f, gd_contin_value(res, ob->br.pt[j + 1].orbit.p)) - cx,
                               dy = px_y(f, resp_value(r, &ob->meas[j + 1])) - cy;
                        double t = (dx * dx + dy * dy) > 0 ? ((x - cx) * dx + (y - cy) * dy) / (dx * dx + dy * dy) : 0;
                        t = t < 0 ? 0 : t > 1 ? 1 : t;
                        dmin = fmin(dmin, hypot(x - cx - t * dx, y - cy - t * dy));
                    }
                }
                if (dmin > 3)
                    seen += len / steps;
            }
        }
    }
    return seen >= 20;
}

static void plot_one(gd_plot_script *s, const char *overlay, const gd_case *c, const gd_contin_result *res,
                     const resp *r, const frame *f, const sweep_pts *sp, int svg)
{
    gd_fig_begin(s, svg, W, H, "continuation");
    gd_qty par;
    gd_qty_key(res->parameter, &par);
    char xl[256], title[900];
    gd_qty_label(&par, xl, sizeof xl);
    /* the case's title above what the picture shows */
    char pname[200];
    gd_gp_title(c->title, title, sizeof title);
    gd_gp_text(par.name, pname, sizeof pname);
    if (c->title[0])
        gd_plot_printf(s, "set title '%s'.\"\\n\".'", title);
    else
        gd_plot_printf(s, "set title '");
    gd_plot_printf(s, "Periodic orbits continued in the %s: solid stable, dashed unstable'\n", pname);
    gd_plot_printf(s, "set xlabel '%s'\nset ylabel '%s'\n", xl, r->label);
    gd_plot_printf(s, "set lmargin at screen %g\nset rmargin at screen %g\nset bmargin at screen %g\n"
                         "set tmargin at screen %g\n", FX0, FX1, FY0, FY1);
    gd_plot_printf(s, "set xrange [%.12g:%.12g]\nset yrange [%.12g:%.12g]\n", f->x0, f->x1, f->y0, f->y1);
    gd_plot_printf(s, "set key at screen %g,%g left top vertical Left reverse samplen 2.5 spacing 1.25\n",
                      FX1 + 0.025, FY1);
    /* the segments of each period, stable and not, as data blocks: x0, y0, dx, dy */
    int periods[64], np = 0;
    for (int b = 0; b < res->nbranches; b++) {
        int k = 0;
        while (k < np && periods[k] != res->branch[b].nper)
            k++;
        if (k == np && np < 64)
            periods[np++] = res->branch[b].nper;
    }
    for (int i = 1; i < np; i++)
        for (int j = i; j > 0 && periods[j - 1] > periods[j]; j--) {
            int t = periods[j];
            periods[j] = periods[j - 1];
            periods[j - 1] = t;
        }
    for (int k = 0; k < np; k++)
        for (int st = 0; st < 2; st++) {
            gd_plot_printf(s, "$SEG%d_%d << EOD\nx,y,dx,dy\n", periods[k], st);
            for (int b = 0; b < res->nbranches; b++) {
                const gd_contin_branch *cb = &res->branch[b];
                if (cb->nper != periods[k])
                    continue;
                for (int i = 0; i + 1 < cb->br.npoints; i++) {
                    int both = cb->br.pt[i].orbit.stable && cb->br.pt[i + 1].orbit.stable;
                    if (both != st)
                        continue;
                    double x0 = gd_contin_value(res, cb->br.pt[i].orbit.p), y0 = resp_value(r, &cb->meas[i]);
                    double x1 = gd_contin_value(res, cb->br.pt[i + 1].orbit.p), y1 = resp_value(r, &cb->meas[i + 1]);
                    gd_plot_printf(s, "%.12g,%.12g,%.12g,%.12g\n", x0, y0, x1 - x0, y1 - y0);
                }
            }
            gd_plot_printf(s, "EOD\n");
        }
    /* the bifurcations: a block per kind; their labels, close points of one kind sharing one */
    int nb = 0;
    for (int b = 0; b < res->nbranches; b++)
        nb += res->branch[b].br.nbif;
    double *bx = malloc(sizeof(double) * (size_t)(nb + 1)), *by = malloc(sizeof(double) * (size_t)(nb + 1));
    int *bk = malloc(sizeof(int) * (size_t)(nb + 1)), *bloc = malloc(sizeof(int) * (size_t)(nb + 1));
    int present[NKINDS] = {0};
    nb = 0;
    for (int b = 0; b < res->nbranches && bx && by && bk && bloc; b++)
        for (int i = 0; i < res->branch[b].br.nbif; i++) {
            const gd_bifurcation *bf = &res->branch[b].br.bif[i];
            for (int k = 0; k < NKINDS; k++)
                if (kinds[k].kind == bf->kind) {
                    bx[nb] = gd_contin_value(res, bf->p);
                    by[nb] = resp_value(r, &res->branch[b].bif_meas[i]);
                    bloc[nb] = bf->location == GD_LOC_LOCATED;
                    bk[nb++] = k;
                    present[k] = 1;
                }
        }
    for (int k = 0; k < NKINDS; k++) {
        gd_plot_printf(s, "$BIF%d << EOD\nx,y\n", k);
        for (int i = 0; i < nb; i++)
            if (bk[i] == k)
                gd_plot_printf(s, "%.12g,%.12g\n", bx[i], by[i]);
        gd_plot_printf(s, "EOD\n");
    }
    /* obstacles of the labels: the markers, the branches (a point every 4 pixels along them), the
     * sweep's points */
    int nobst = nb + sp->n;
    for (int b = 0; b < res->nbranches; b++) {
        const gd_contin_branch *cb = &res->branch[b];
        for (int i = 0; i + 1 < cb->br.npoints; i++) {
            double len = hypot(px_x(f, gd_contin_value(res, cb->br.pt[i + 1].orbit.p)) -
                                   px_x(f, gd_contin_value(res, cb->br.pt[i].orbit.p)),
                               px_y(f, resp_value(r, &cb->meas[i + 1])) - px_y(f, resp_value(r, &cb->meas[i])));
            nobst += (int)ceil(len / 4) + 1;
        }
        nobst += 1;
    }
    double *obst = malloc(sizeof(double) * 2 * (size_t)(nobst + 1));
    gd_fig_label *lab = malloc(sizeof(gd_fig_label) * (size_t)(nb + 1));
    char (*text)[24] = malloc(sizeof *text * (size_t)(nb + 1));
    int nl = 0;
    if (obst && lab && text && bx && bloc) {
        int o = 0;
        for (int i = 0; i < nb; i++) {
            obst[2 * o] = px_x(f, bx[i]);
            obst[2 * o++ + 1] = px_y(f, by[i]);
        }
        for (int b = 0; b < res->nbranches; b++) {
            const gd_contin_branch *cb = &res->branch[b];
            for (int i = 0; i < cb->br.npoints; i++) {
                double ax = px_x(f, gd_contin_value(res, cb->br.pt[i].orbit.p)), ay = px_y(f, resp_value(r, &cb->meas[i]));
                obst[2 * o] = ax;
                obst[2 * o++ + 1] = ay;
                if (i + 1 == cb->br.npoints)
                    break;
                double bx2 = px_x(f, gd_contin_value(res, cb->br.pt[i + 1].orbit.p)),
                       by2 = px_y(f, resp_value(r, &cb->meas[i + 1]));
                int k = (int)ceil(hypot(bx2 - ax, by2 - ay) / 4);
                for (int j = 1; j < k && o < nobst; j++) {
                    obst[2 * o] = ax + (bx2 - ax) * j / k;
                    obst[2 * o++ + 1] = ay + (by2 - ay) * j / k;
                }
            }
        }
        for (int i = 0; i < sp->n; i++) {
            obst[2 * o] = px_x(f, sp->x[i]);
            obst[2 * o++ + 1] = px_y(f, sp->y[i]);
        }
        /* groups: points of one kind and location status within 40 pixels of the group's last point,
         * in order of x; a point on another of the group (one bifurcation found from the two
         * branches that cross there) is counted once */
        int *order = malloc(sizeof(int) * (size_t)(nb + 1)), *used = calloc((size_t)nb + 1, sizeof(int));
        for (int i = 0; order && i < nb; i++)
            order[i] = i;
        for (int i = 1; order && i < nb; i++)
            for (int j = i; j > 0 && bx[order[j - 1]] > bx[order[j]]; j--) {
                int t = order[j];
                order[j] = order[j - 1];
                order[j - 1] = t;
            }
        for (int a = 0; order && used && a < nb; a++) {
            int i = order[a];
            if (used[i])
                continue;
            used[i] = 1;
            double sx = px_x(f, bx[i]), sy = px_y(f, by[i]), lx = sx, ly = sy;
            int cnt = 1;
            for (int z = a + 1; z < nb; z++) {
                int j = order[z];
                if (used[j] || bk[j] != bk[i] || bloc[j] != bloc[i])
                    continue;
                double jx = px_x(f, bx[j]), jy = px_y(f, by[j]);
                if (hypot(jx - lx, jy - ly) < 2) {
                    used[j] = 1;
                } else if (hypot(jx - lx, jy - ly) < 40) {
                    used[j] = 1;
                    sx += jx;
                    sy += jy;
                    lx = jx;
                    ly = jy;
                    cnt++;
                }
            }
            /* "?": not located to the tolerance (bifurcations.csv's location says how it ended) */
            if (cnt > 1)
                snprintf(text[nl], sizeof text[nl], "%d %s%s", cnt, kinds[bk[i]].mark, bloc[i] ? "" : "?");
            else
                snprintf(text[nl], sizeof text[nl], "%s%s", kinds[bk[i]].mark, bloc[i] ? "" : "?");
            lab[nl].x = sx / cnt;
            lab[nl].y = sy / cnt;
            lab[nl].w = gd_text_width(text[nl], GD_FIG_PX);
            lab[nl].h = GD_FIG_PX;
            nl++;
        }
        free(order);
        free(used);
        /* labels of different kinds on one point (a branch point on its fold) become one: "F, BP" */
        for (int i = 0; i < nl; i++)
            for (int j = i + 1; j < nl; j++)
                if (hypot(lab[j].x - lab[i].x, lab[j].y - lab[i].y) < 2 &&
                    strlen(text[i]) + strlen(text[j]) + 3 <= sizeof text[i]) {
                    strcat(text[i], ", ");
                    strcat(text[i], text[j]);
                    lab[i].w = gd_text_width(text[i], GD_FIG_PX);
                    for (int k = j; k + 1 < nl; k++) {
                        lab[k] = lab[k + 1];
                        memcpy(text[k], text[k + 1], sizeof text[k]);
                    }
                    nl--;
                    j--;
                }
        gd_place_labels(lab, nl, W * FX0, H * (1 - FY1), W * FX1, H * (1 - FY0), obst, o);
        for (int i = 0; i < nl; i++)
            if (lab[i].keep) {
                /* back to data: centre of the label, baseline a third of the height below it */
                double x = f->x0 + (lab[i].lx / W - FX0) / (FX1 - FX0) * (f->x1 - f->x0);
                double y = f->y0 + ((1 - lab[i].ly / H) - FY0) / (FY1 - FY0) * (f->y1 - f->y0);
                gd_plot_printf(s, "set label %d '%s' at %.12g,%.12g center front\n", i + 1, text[i], x, y);
            }
    }
    free(obst);
    free(lab);
    free(text);
    /* the plot: segments, key entries of the visible periods, markers, the sweep */
    gd_plot_printf(s, "plot ");
    const char *sep = "";
    for (int k = 0; k < np; k++) {
        const char *col = gd_colour[(k + 4) % GD_NCOLOURS];
        for (int st = 1; st >= 0; st--) {
            gd_plot_printf(s, "%s$SEG%d_%d using 1:2:3:4 with vectors nohead lw 2 dt %d lc rgb '%s' notitle", sep,
                              periods[k], st, st ? 1 : 2, col);
            sep = ", \\\n  ";
        }
        if (period_visible(res, r, f, periods[k]) || np == 1)
            gd_plot_printf(s, "%s1/0 with lines lw 2 lc rgb '%s' title 'period-%d orbits'", sep, col, periods[k]);
    }
    gd_plot_printf(s, "%s1/0 with lines lw 2 dt 2 lc rgb '#000000' title 'unstable'", sep);
    for (int k = 0; k < NKINDS; k++)
        if (present[k])
            gd_plot_printf(s, "%s$BIF%d using 1:2 with points pt %d ps %g lc rgb '#000000' title '%s'", sep, k,
                              kinds[k].pt, kinds[k].ps, kinds[k].key);
    if (overlay)
        gd_plot_printf(s, "%s'%s/%s' using 'parameter':(strcol('direction') eq 'down' ? 1/0 : column('%s')*%.12g) with "
                             "points pt 1 ps 1.1 lw 1.5 lc rgb '#555555' title 'sweep up', \\\n  '%s/%s' using 'parameter':"
                             "(strcol('direction') eq 'down' ? column('%s')*%.12g : 1/0) with points pt 2 ps 1 lw 1.5 "
                             "lc rgb '#555555' title 'sweep down'",
                          sep, overlay, r->sweep_file, r->sweep_col, r->scale, overlay, r->sweep_file, r->sweep_col,
                          r->scale);
    gd_plot_printf(s, "\n");
    gd_fig_end(s, 0);
    free(bx);
    free(by);
    free(bk);
    free(bloc);
}

/* continuation.png and .svg */
static void draw(const gd_plotter *pl, const gd_case *c, const gd_contin_result *res)
{
    if (res->nbranches == 0)
        return;
    gd_error e = {0}, *err = &e;
    /* gnuplot reads the overlay sweep, named relative to this process's working directory, by its
     * absolute path */
    char *overlay = NULL;
    if (c->cont_overlay_sweep[0] && !(overlay = realpath(c->cont_overlay_sweep, NULL))) {
        gd_error_set(err, GD_ERR_IO, "%s: continuation.overlay_sweep: %s", c->cont_overlay_sweep, strerror(errno));
        gd_plot_fail(pl, "pictures not drawn", err);
        return;
    }
    resp r;
    resp_of(c, res, &r);
    sweep_pts sp = {0};
    gd_status st = GD_OK;
    if (overlay) {
        char path[GD_PATH_MAX + 64];
        snprintf(path, sizeof path, "%s/%s", overlay, r.sweep_file);
        st = read_sweep(path, r.sweep_col, r.scale, &sp, err);
    }
    /* the frame: the bounds of the parameter and every value drawn, with margins */
    frame f = {0};
    double ylo = INFINITY, yhi = -INFINITY;
    for (int b = 0; b < res->nbranches; b++)
        for (int i = 0; i < res->branch[b].br.npoints; i++) {
            double y = resp_value(&r, &res->branch[b].meas[i]);
            if (isfinite(y)) {
                ylo = fmin(ylo, y);
                yhi = fmax(yhi, y);
            }
        }
    for (int i = 0; i < sp.n; i++)
        if (sp.x[i] >= fmin(c->cont_from, c->cont_to) && sp.x[i] <= fmax(c->cont_from, c->cont_to)) {
            ylo = fmin(ylo, sp.y[i]);
            yhi = fmax(yhi, sp.y[i]);
        }
    if (!(yhi >= ylo))
        ylo = yhi = 0;
    gd_pad(fmin(c->cont_from, c->cont_to), fmax(c->cont_from, c->cont_to), 0.025, 0, &f.x0, &f.x1);
    gd_pad(ylo, yhi, 0.07, 0, &f.y0, &f.y1);
    gd_plot_script s = {0};
    if (st == GD_OK)
        for (int svg = 0; svg < 2; svg++)
            plot_one(&s, overlay, c, res, &r, &f, &sp, svg);
    free(overlay);
    free(sp.x);
    free(sp.y);
    free(sp.up);
    if (st != GD_OK) {
        free(s.p);
        gd_plot_fail(pl, "pictures not drawn", err);
        return;
    }
    static const char *names[] = {"continuation"};
    gd_plot_draw(pl, &s, names, 1, "pictures not drawn");
}

void gd_plot_continuation(const gd_plotter *p, const gd_case *c, const gd_contin_result *res)
{
    if (gd_plot_wanted(p, c->plots)) {
        draw(p, c, res);
        gd_plot_curves(p, c, res);
    }
}
