/* The pictures of the basins (docs/basins.md section 6), drawn by gnuplot from the run's tables:
 *
 *   basins.png, .svg     (at the case's values) each cell of the section coloured by the attractor its
 *                        initial state goes to, the attractors' points at the section's phase on it, and
 *                        the continuation's orbits there (basins.continuation): stable ones circled,
 *                        unstable ones crossed;
 *   fractions.png, .svg  (over a parameter) the fraction of the sample on each attractor against the
 *                        parameter with its Wilson interval, under the largest mesh deflection of each
 *                        attractor beside the continuation's branches (solid stable, dashed unstable).
 *
 * The attractors' colours are the Okabe-Ito palette, distinguishable with every common colour-vision
 * deficiency; the outcomes that are no attractor are greys and black. */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const palette[8] = {"#E69F00", "#56B4E9", "#009E73", "#0072B2",
                                       "#D55E00", "#CC79A7", "#F0E442", "#7F3C8D"};
/* diverged, left-box, iteration-cap, integration-failed */
static const char *const special_colour[GD_BASIN_NSPECIAL] = {"#000000", "#9E9E9E", "#5A5A5A", "#B0004C"};

static const char *id_colour(int id)
{
    return id >= 0 ? palette[id % 8] : special_colour[(-id - 1) % GD_BASIN_NSPECIAL];
}

/* A gnuplot function of a label giving one colour channel (shift 16: red, 8: green, 0: blue). */
static void colour_function(gd_gnuplot_script *s, const char *name, int shift, int nids)
{
    gd_gnuplot_printf(s, "%s(l) = ", name);
    for (int id = -GD_BASIN_NSPECIAL; id < nids; id++) {
        unsigned rgb = (unsigned)strtoul(id_colour(id) + 1, NULL, 16);
        gd_gnuplot_printf(s, "l == %d ? %u : ", id, (rgb >> shift) & 0xFF);
    }
    gd_gnuplot_printf(s, "255\n");
}

/* The attractor's legend text: its name, its impact regime, its fraction. */
static void attractor_title(const gd_basins_result *res, const gd_case *c, int a, char *out, size_t len)
{
    const gd_basins_point *p = &res->pt[0];
    const gd_attractor *t = &p->att[a];
    char frac[64] = "";
    if (c->bas_samples > 0) {
        gd_basin_fraction f;
        gd_basins_fraction(res, 0, a, &f);
        snprintf(frac, sizeof frac, ": %.3f +- %.3f", f.p, f.se);
    }
    snprintf(out, len, "attractor %d, %s%s%s%s%s", p->id[a], t->name, t->impact_regime >= 0 ? ", " : "",
             t->impact_regime >= 0 ? gd_impact_regime_name(t->impact_regime) : "", t->seeded ? " (seed only)" : "",
             frac);
}

static void plot_basins(gd_gnuplot_script *s, const gd_case *c, const gd_basins_result *res, const char *term,
                        const char *ext)
{
    const gd_basins_point *p = &res->pt[0];
    const gd_basin_section *sec = &res->sec;
    gd_gnuplot_printf(s, "set terminal %s\nset output '.basins%s.tmp'\n", term, ext);
    char ent[200] = "";
    if (res->grid)
        snprintf(ent, sizeof ent, "basin entropy S_b %.3f, S_bb %.3f (%s ln 2: %s)", res->entropy.sb, res->entropy.sbb,
                 res->entropy.fractal ? ">" : "<=", res->entropy.fractal ? "a fractal boundary" : "not shown fractal");
    gd_gnuplot_printf(s, "set title \"%s%sbasins at mesh phase %g deg, %d x %d initial states\\n%s\" noenhanced\n",
                      c->title, c->title[0] ? "\\n" : "", res->phase_deg, res->nx, res->ny, ent);
    gd_gnuplot_printf(s, "set xlabel '%s' noenhanced\nset ylabel '%s' noenhanced\n", res->column[0], res->column[1]);
    gd_gnuplot_printf(s, "set xrange [%.12g:%.12g]\nset yrange [%.12g:%.12g]\nset key outside right top noenhanced "
                         "box opaque\nset tics out\nunset grid\n", sec->lo[0], sec->hi[0], sec->lo[1], sec->hi[1]);
    gd_gnuplot_printf(s, "plot 'basins.csv' every ::1 using 3:4:(red($6)):(green($6)):(blue($6)) with rgbimage "
                         "notitle");
    for (int a = 0; a < p->natt; a++) {
        char title[200];
        attractor_title(res, c, a, title, sizeof title);
        gd_gnuplot_printf(s, ", \\\n  NaN with boxes fs solid 1.0 lc rgb '%s' title '%s'", id_colour(p->id[a]), title);
    }
    static const char *names[GD_BASIN_NSPECIAL] = {"diverged", "left the box", "iteration cap", "integration failed"};
    for (int l = 0; l < GD_BASIN_NSPECIAL; l++)
        if (res->grid_cells && res->grid_cells[p->natt + l] > 0)
            gd_gnuplot_printf(s, ", \\\n  NaN with boxes fs solid 1.0 lc rgb '%s' title '%s (%ld cells)'",
                              special_colour[l], names[l], res->grid_cells[p->natt + l]);
    gd_gnuplot_printf(s, ", \\\n  'attractor_points.csv' every ::1 using 3:4 with points pt 7 ps 1.6 lc rgb 'white' "
                         "notitle, \\\n  'attractor_points.csv' every ::1 using 3:4 with points pt 7 ps 1.0 lc rgb "
                         "'black' title 'attractors at the section'");
    if (c->bas_continuation[0]) {
        gd_gnuplot_printf(s, ", \\\n  'continuation_orbits.csv' every ::1 using 6:($3 == 1 ? $7 : 1/0) with points pt 6 "
                             "ps 2.4 lw 2 lc rgb 'black' title 'stable orbit of the continuation', \\\n"
                             "  'continuation_orbits.csv' every ::1 using 6:($3 == 0 ? $7 : 1/0) with points pt 2 ps "
                             "2.0 lw 3 lc rgb 'white' notitle, \\\n"
                             "  'continuation_orbits.csv' every ::1 using 6:($3 == 0 ? $7 : 1/0) with points pt 2 ps "
                             "2.0 lw 1.5 lc rgb 'black' title 'unstable orbit of the continuation'");
    }
    gd_gnuplot_printf(s, "\nunset output\n");
}

/* The parameter's column: the key without its section. */
static const char *key_column(const gd_basins_result *res)
{
    const char *dot = strchr(res->parameter, '.');
    return dot ? dot + 1 : res->parameter;
}

static void plot_fractions(gd_gnuplot_script *s, const gd_case *c, const gd_basins_result *res, const char *cont,
                           const char *term, const char *ext)
{
    const char *key = key_column(res);
    double lo = fmin(c->bas_from, c->bas_to), hi = fmax(c->bas_from, c->bas_to);
    gd_gnuplot_printf(s, "set terminal %s\nset output '.fractions%s.tmp'\n", term, ext);
    gd_gnuplot_printf(s, "set multiplot layout 2,1 title \"%s%sthe motion a start settles on, over %s\" noenhanced\n",
                      c->title, c->title[0] ? "\\n" : "", res->parameter);
    gd_gnuplot_printf(s, "set xrange [%.12g:%.12g]\nset grid\nset key outside right top noenhanced\n"
                         "set lmargin at screen 0.08\nset rmargin at screen 0.78\n", lo, hi);
    /* top: the largest mesh deflection of every attractor beside the continuation's branches */
    gd_gnuplot_printf(s, "set title '%s' noenhanced\nset xlabel ''\nset ylabel 'largest mesh deflection lambda_L (um)' "
                         "noenhanced\n", cont ? "attractors (points) and the orbits of the continuation (solid stable, "
                                                "dashed unstable)" : "attractors");
    gd_gnuplot_printf(s, "plot ");
    const char *sep = "";
    if (cont) {
        /* branch.csv: branch, period_n, point, key, p, stable, mu_max, 2n multipliers, then rms (3), lambda_min_L */
        int col = 8 + 2 * res->n + 4;
        for (int stable = 1; stable >= 0; stable--) {
            gd_gnuplot_printf(s, "%sk1 = -1, x1 = 0, y1 = 0, s1 = 0, '%s/branch.csv' every ::1 using (x0 = x1, x1 = $4, "
                                 "y0 = y1, y1 = $%d, k0 = k1, k1 = $1, s0 = s1, s1 = $6, k0 == k1 && (s0 == 1 && s1 == 1) "
                                 "== %d ? x0 : 1/0):(y0):(x1 - x0):(y1 - y0) with vectors nohead lw 1.5 dt %d lc rgb "
                                 "'#404040' %s",
                              sep, cont, col, stable, stable ? 1 : 2,
                              stable ? "title 'continuation, stable'" : "title 'continuation, unstable'");
            sep = ", \\\n  ";
        }
    }
    for (int id = 0; id < res->nids; id++) {
        gd_gnuplot_printf(s, "%s'attractors.csv' every ::1 using 1:($2 == %d ? $20 : 1/0) with linespoints pt 7 ps 1.2 "
                             "lw 1 lc rgb '%s' title 'attractor %d'", sep, id, id_colour(id), id);
        sep = ", \\\n  ";
    }
    gd_gnuplot_printf(s, "\n");
    /* bottom: the fractions with their Wilson intervals */
    gd_gnuplot_printf(s, "set title 'fraction of %ld random initial states (Wilson 95 %% intervals)'\n"
                         "set xlabel '%s (%s)' noenhanced\nset ylabel 'fraction'\nset yrange [-0.02:1.02]\n",
                      (long)c->bas_samples, key, res->unit);
    gd_gnuplot_printf(s, "plot ");
    sep = "";
    for (int id = 0; id < res->nids; id++) {
        gd_gnuplot_printf(s, "%s'fractions.csv' every ::1 using 1:($2 == %d ? $7 : 1/0):9:10 with yerrorlines pt 7 "
                             "ps 0.9 lw 1.5 lc rgb '%s' title 'attractor %d'", sep, id, id_colour(id), id);
        sep = ", \\\n  ";
    }
    for (int l = -1; l >= -GD_BASIN_NSPECIAL; l--) {
        long any = 0;
        for (int k = 0; k < res->npoints; k++)
            any += res->pt[k].special[-l - 1];
        if (any)
            gd_gnuplot_printf(s, "%s'fractions.csv' every ::1 using 1:($2 == %d ? $7 : 1/0) with linespoints pt 4 ps 0.9 "
                                 "lc rgb '%s' title '%s'", sep, l, special_colour[-l - 1], gd_basin_label_name(l));
    }
    gd_gnuplot_printf(s, "\nunset multiplot\nunset output\n");
}

gd_status cli_basins_draw(const char *dir, const gd_case *c, const gd_basins_result *res, gd_error *err)
{
    gd_gnuplot_script s = {0};
    gd_gnuplot_printf(&s, "set datafile separator ','\nset datafile missing 'NaN'\n");
    int nids = res->nids;
    for (int k = 0; k < res->npoints; k++)
        for (int a = 0; a < res->pt[k].natt; a++)
            nids = res->pt[k].id[a] + 1 > nids ? res->pt[k].id[a] + 1 : nids;
    colour_function(&s, "red", 16, nids);
    colour_function(&s, "green", 8, nids);
    colour_function(&s, "blue", 0, nids);
    const char *name;
    char *cont = NULL;
    if (res->parameter[0]) {
        /* gnuplot runs in dir: the continuation's directory by its absolute path */
        if (c->bas_continuation[0] && !(cont = realpath(c->bas_continuation, NULL))) {
            free(s.p);
            return gd_error_set(err, GD_ERR_IO, "%s: basins.continuation: %s", c->bas_continuation, strerror(errno));
        }
        plot_fractions(&s, c, res, cont, "pngcairo size 1200,1100 font ',11'", ".png");
        plot_fractions(&s, c, res, cont, "svg size 1200,1100 dynamic font 'sans,11'", ".svg");
        name = "fractions";
    } else {
        plot_basins(&s, c, res, "pngcairo size 1300,900 font ',11'", ".png");
        plot_basins(&s, c, res, "svg size 1300,900 dynamic font 'sans,11'", ".svg");
        name = "basins";
    }
    free(cont);
    if (s.bad) {
        free(s.p);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the basins' gnuplot script");
    }
    gd_status st = gd_gnuplot_draw(dir, s.p, &name, 1, err);
    free(s.p);
    return st;
}
