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
 * The words and units of the axes come from quantity.h, the frames and colours from figure.h: the
 * attractors in the Okabe-Ito colours (without black, which marks their points), the outcomes that
 * are no attractor in black, greys and crimson. */
#include "figure.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* diverged, left-box, iteration-cap, integration-failed */
static const char *const special_colour[GD_BASIN_NSPECIAL] = {"#000000", "#9E9E9E", "#5A5A5A", "#B0004C"};
static const char *const special_words[GD_BASIN_NSPECIAL] = {"diverged", "left the box", "reached the iteration cap",
                                                             "integration failed"};

static const char *id_colour(int id)
{
    return id >= 0 ? gd_colour[1 + id % (GD_NCOLOURS - 1)] : special_colour[(-id - 1) % GD_BASIN_NSPECIAL];
}

/* A gnuplot function of a label giving one colour channel (shift 16: red, 8: green, 0: blue). */
static void colour_function(gd_plot_script *s, const char *name, int shift, int nids)
{
    gd_plot_printf(s, "%s(l) = ", name);
    for (int id = -GD_BASIN_NSPECIAL; id < nids; id++) {
        unsigned rgb = (unsigned)strtoul(id_colour(id) + 1, NULL, 16);
        gd_plot_printf(s, "l == %d ? %u : ", id, (rgb >> shift) & 0xFF);
    }
    gd_plot_printf(s, "255\n");
}

/* The meshes of the model: a herringbone's state names its right half's coordinates (y1R, qR). */
static int halves_of(const gd_basins_result *res)
{
    for (int i = 0; i < res->n; i++) {
        size_t l = strlen(res->state_name[i]);
        if (l > 1 && (res->state_name[i][l - 1] == 'R' || strstr(res->state_name[i], "R_")))
            return 2;
    }
    return 1;
}

/* The axis label of a section coordinate's column: a mesh deflection or its rate in half backlashes
 * (quantity.h), a state component in the model's dimensionless units. */
static void coord_label(const char *column, int halves, char *out, size_t len)
{
    gd_qty q;
    if (strstr(column, "_half_backlash")) {
        gd_qty_column(column, halves, &q);
        gd_qty_label(&q, out, len);
        return;
    }
    char t[80];
    gd_gp_text(column, t, sizeof t);
    snprintf(out, len, "state component %s (-)", t);
}

static const char *regime_words(int r)
{
    static const char *w[] = {"no impacts", "single-sided impacts", "double-sided impacts"};
    return r >= 0 && r <= 2 ? w[r] : "";
}

/* The attractor's key entry: its name, its impact regime, its share of the sample. */
static void attractor_title(const gd_basins_result *res, const gd_case *c, int a, char *out, size_t len)
{
    const gd_basins_point *p = &res->pt[0];
    const gd_attractor *t = &p->att[a];
    char frac[80] = "", words[160];
    if (c->bas_samples > 0) {
        gd_basin_fraction f;
        gd_basins_fraction(res, 0, a, &f);
        snprintf(frac, sizeof frac, "; %.3f ± %.3f", f.p, f.se);
    }
    snprintf(words, sizeof words, "attractor %d: %s%s%s%s%s", p->id[a], t->name, t->impact_regime >= 0 ? ", " : "",
             regime_words(t->impact_regime), t->seeded ? " (from a seed only)" : "", frac);
    gd_gp_text(words, out, len);
}

#define BH 800

static void plot_basins(gd_plot_script *s, int svg, const gd_case *c, const gd_basins_result *res)
{
    const gd_basins_point *p = &res->pt[0];
    const gd_basin_section *sec = &res->sec;
    int halves = halves_of(res);
    /* the key's width: its longest entry (plain text, as wide as drawn) */
    char keytitle[120] = "";
    if (c->bas_samples > 0)
        snprintf(keytitle, sizeof keytitle, "attractor; share of %ld random states", (long)c->bas_samples);
    double keyw = fmax(gd_text_width(keytitle, GD_FIG_PX), gd_text_width("unstable orbit of the continuation", GD_FIG_PX));
    for (int a = 0; a < p->natt; a++) {
        char tt[240];
        attractor_title(res, c, a, tt, sizeof tt);
        keyw = fmax(keyw, gd_text_width(tt, GD_FIG_PX));
    }
    int BW = (int)(100 + 640 + 25 + 40 + keyw + 25);
    gd_fig_begin(s, svg, BW, BH, "basins");
    char title[400] = "", ent[300] = "", xl[200], yl[200];
    if (c->title[0])
        gd_gp_title(c->title, title, sizeof title);
    if (res->grid)
        snprintf(ent, sizeof ent, "; basin entropy S_b %.3f, S_{bb} %.3f (%s ln 2: %s)", res->entropy.sb,
                 res->entropy.sbb, res->entropy.fractal ? ">" : "≤",
                 res->entropy.fractal ? "a fractal boundary" : "no evidence of a fractal boundary");
    gd_plot_printf(s, "set multiplot title '%s%sbasins at mesh phase %g°, %d × %d initial states%s'\n", title,
                      title[0] ? "' . \"\\n\" . '" : "", res->phase_deg, res->nx, res->ny, ent);
    coord_label(res->column[0], halves, xl, sizeof xl);
    coord_label(res->column[1], halves, yl, sizeof yl);
    gd_plot_printf(s, "set xlabel '%s'\nset ylabel '%s'\n", xl, yl);
    /* the frame: the box (the cells fill it); the key to its right */
    double l = 100, r = 740, t = 100, b = BH - 75;
    gd_plot_printf(s, "set lmargin at screen %.5f\nset rmargin at screen %.5f\nset tmargin at screen %.5f\n"
                         "set bmargin at screen %.5f\n", l / BW, r / BW, 1 - t / BH, 1 - b / BH);
    gd_plot_printf(s, "set xrange [%.12g:%.12g]\nset yrange [%.12g:%.12g]\nunset grid\nset tics out\n"
                         "set xtics %g\nset ytics %g\n", sec->lo[0], sec->hi[0], sec->lo[1], sec->hi[1],
                      gd_nice_step(sec->hi[0] - sec->lo[0], 6), gd_nice_step(sec->hi[1] - sec->lo[1], 6));
    gd_plot_printf(s, "set key at screen %.5f,%.5f left top vertical Left reverse samplen 2 spacing %.4f title '%s'\n",
                      (r + 25) / BW, 1 - t / BH, GD_KEY_SPACING(svg, 1.3), keytitle);
    gd_plot_printf(s, "plot 'basins.csv' using '%s':'%s':(red(column('label'))):(green(column('label'))):"
                         "(blue(column('label'))) with rgbimage notitle",
                      res->column[0], res->column[1]);
    for (int a = 0; a < p->natt; a++) {
        char tt[240];
        attractor_title(res, c, a, tt, sizeof tt);
        gd_plot_printf(s, ", \\\n  1/0 with boxes fs solid 1.0 noborder lc rgb '%s' title '%s'", id_colour(p->id[a]),
                          tt);
    }
    for (int k = 0; k < GD_BASIN_NSPECIAL; k++)
        if (res->grid_cells && res->grid_cells[p->natt + k] > 0)
            gd_plot_printf(s, ", \\\n  1/0 with boxes fs solid 1.0 noborder lc rgb '%s' title '%s (%ld cells)'",
                              special_colour[k], special_words[k], res->grid_cells[p->natt + k]);
    /* the continuation's orbits under the attractors' points (a stable orbit's circle around its point) */
    if (c->bas_continuation[0])
        gd_plot_printf(s, ", \\\n  'continuation_orbits.csv' using '%s':(column('stable') == 1 ? column('%s') : 1/0) "
                             "with points pt 6 ps 2.4 lw 2 lc rgb 'black' title 'stable orbit of the continuation', \\\n"
                             "  '' using '%s':(column('stable') == 0 ? column('%s') : 1/0) with points pt 2 ps 2.0 "
                             "lw 3 lc rgb 'white' notitle, \\\n"
                             "  '' using '%s':(column('stable') == 0 ? column('%s') : 1/0) with points pt 2 ps 2.0 "
                             "lw 1.5 lc rgb 'black' title 'unstable orbit of the continuation'",
                          res->column[0], res->column[1], res->column[0], res->column[1], res->column[0],
                          res->column[1]);
    gd_plot_printf(s, ", \\\n  'attractor_points.csv' using '%s':'%s' with points pt 7 ps 1.6 lc rgb 'white' "
                         "notitle, \\\n  '' using '%s':'%s' with points pt 7 ps 1.0 lc rgb 'black' title "
                         "'the attractors'' points at the section'",
                      res->column[0], res->column[1], res->column[0], res->column[1]);
    gd_plot_printf(s, "\n");
    gd_fig_end(s, 1);
}

/* The parameter's column in the tables: the key without its section. */
static const char *key_column(const gd_basins_result *res)
{
    const char *dot = strchr(res->parameter, '.');
    return dot ? dot + 1 : res->parameter;
}

/* An attractor id's name and impact regime over the values: "period-1, no impacts", or "period-1,
 * no impacts, then single-sided impacts" where they change. */
static void id_words(const gd_basins_result *res, int id, char *out, size_t len)
{
    char first[96] = "", last[96] = "";
    for (int k = 0; k < res->npoints; k++)
        for (int a = 0; a < res->pt[k].natt; a++)
            if (res->pt[k].id[a] == id) {
                const gd_attractor *t = &res->pt[k].att[a];
                char *w = first[0] ? last : first;
                snprintf(w, sizeof first, "%s%s%s", t->name, t->impact_regime >= 0 ? ", " : "",
                         regime_words(t->impact_regime));
            }
    if (!first[0])
        snprintf(out, len, "attractor %d", id);
    else if (!last[0] || strcmp(first, last) == 0)
        snprintf(out, len, "attractor %d: %s", id, first);
    else if (strncmp(first, last, strcspn(first, ",")) == 0 && strchr(last, ','))
        snprintf(out, len, "attractor %d: %s, then%s", id, first, strchr(last, ',') + 1);
    else
        snprintf(out, len, "attractor %d: %s, then %s", id, first, last);
}

#define FH 940

static void plot_fractions(gd_plot_script *s, int svg, const gd_case *c, const gd_basins_result *res,
                           const char *cont)
{
    const char *key = key_column(res);
    int halves = halves_of(res);
    double lo = fmin(c->bas_from, c->bas_to), hi = fmax(c->bas_from, c->bas_to), x0, x1;
    gd_pad(lo, hi, 0.03, 0, &x0, &x1);
    gd_qty pq, lq;
    gd_qty_key(res->parameter, &pq);
    gd_qty_column("lambda_max_L_um", halves, &lq);
    char xl[200], yl[200], title[400] = "", pname[140];
    gd_qty_label(&pq, xl, sizeof xl);
    gd_qty_label(&lq, yl, sizeof yl);
    gd_gp_text(pq.name, pname, sizeof pname);
    if (c->title[0])
        gd_gp_title(c->title, title, sizeof title);
    /* the width: the frames, then the key (its longest entry) */
    double keyw = gd_text_width("continuation, unstable", GD_FIG_PX);
    for (int id = 0; id < res->nids; id++) {
        char w[160];
        id_words(res, id, w, sizeof w);
        keyw = fmax(keyw, gd_text_width(w, GD_FIG_PX));
    }
    keyw = fmax(keyw, gd_text_width("starts that reached the iteration cap", GD_FIG_PX));
    int FW = (int)(100 + 740 + 25 + 45 + keyw + 25);
    gd_fig_begin(s, svg, FW, FH, "fractions");
    gd_plot_printf(s, "set multiplot title '%s%sthe motion a start settles on, against the %s'\n", title,
                      title[0] ? "' . \"\\n\" . '" : "", pname);
    double l = 100, r = 840, top = 95, gap = 95, ph = (FH - top - 75 - gap) / 2.0;
    gd_plot_printf(s, "set xrange [%.12g:%.12g]\nset lmargin at screen %.5f\nset rmargin at screen %.5f\n", x0, x1,
                      l / FW, r / FW);
    /* top: the largest mesh deflection of every attractor beside the continuation's branches; the
     * one key of the picture beside it */
    gd_plot_printf(s, "set tmargin at screen %.5f\nset bmargin at screen %.5f\n", 1 - top / FH,
                      1 - (top + ph) / FH);
    gd_plot_printf(s, "set title '%s'\nset xlabel '%s'\nset ylabel '%s'\n",
                      cont ? "each attractor''s largest mesh deflection (points) and the continuation''s orbits "
                             "(solid: stable, dashed: unstable)"
                           : "each attractor''s largest mesh deflection",
                      xl, yl);
    gd_plot_printf(s, "set key at screen %.5f,%.5f left top vertical Left reverse samplen 3 spacing %.4f\n",
                      (r + 25) / FW, 1 - top / FH, GD_KEY_SPACING(svg, 1.3));
    gd_plot_printf(s, "plot ");
    const char *sep = "";
    if (cont) {
        /* branch.csv: a segment between two consecutive points of a branch, solid when both are stable */
        for (int stable = 1; stable >= 0; stable--) {
            gd_plot_printf(s, "%sk1 = -1, x1 = 0, y1 = 0, s1 = 0, '%s/branch.csv' using (x0 = x1, x1 = column('%s'), "
                                 "y0 = y1, y1 = column('lambda_max_L_um'), k0 = k1, k1 = column('branch'), s0 = s1, "
                                 "s1 = column('stable'), k0 == k1 && (s0 == 1 && s1 == 1) == %d && x0 >= %.12g && x1 <= %.12g && x1 >= %.12g && x0 <= %.12g ? x0 : 1/0):(y0):"
                                 "(x1 - x0):(y1 - y0) with vectors nohead lw 1.5 dt %d lc rgb '#404040' title '%s'",
                              sep, cont, key, stable, x0, x1, x0, x1, stable ? 1 : 2,
                              stable ? "continuation, stable" : "continuation, unstable");
            sep = ", \\\n  ";
        }
    }
    for (int id = 0; id < res->nids; id++) {
        char w[160], tw[200];
        id_words(res, id, w, sizeof w);
        gd_gp_text(w, tw, sizeof tw);
        gd_plot_printf(s, "%s'attractors.csv' using '%s':(column('attractor') == %d ? column('lambda_max_L_um') : "
                             "1/0) with linespoints pt 7 ps 1.2 lw 1.3 lc rgb '%s' title '%s'",
                          sep, key, id, id_colour(id), tw);
        sep = ", \\\n  ";
    }
    int any[GD_BASIN_NSPECIAL] = {0};
    for (int k = 0; k < res->npoints; k++)
        for (int l2 = 0; l2 < GD_BASIN_NSPECIAL; l2++)
            any[l2] |= res->pt[k].special[l2] > 0;
    for (int l2 = 0; l2 < GD_BASIN_NSPECIAL; l2++)
        if (any[l2])
            gd_plot_printf(s, "%s1/0 with linespoints pt 4 ps 0.9 lw 1.3 lc rgb '%s' title 'starts that %s'", sep,
                              special_colour[l2], special_words[l2]);
    gd_plot_printf(s, "\n");
    /* bottom: the fractions with their Wilson intervals, in the top's colours (no key of its own) */
    gd_plot_printf(s, "unset key\nset tmargin at screen %.5f\nset bmargin at screen %.5f\n",
                      1 - (top + ph + gap) / FH, 1 - (top + 2 * ph + gap) / FH);
    gd_plot_printf(s, "set title 'share of %ld random initial states on each attractor, with its Wilson "
                         "%.0f %% interval'\nset xlabel '%s'\nset ylabel 'fraction of the initial states (-)'\n"
                         "set yrange [-0.05:1.05]\nset ytics 0.2\n",
                      (long)c->bas_samples, 100 * erf(res->z / sqrt(2.0)), xl);
    gd_plot_printf(s, "plot ");
    sep = "";
    for (int id = 0; id < res->nids; id++) {
        gd_plot_printf(s, "%s'fractions.csv' using '%s':(column('attractor') == %d ? column('fraction') : 1/0):"
                             "'wilson_lo':'wilson_hi' with yerrorlines pt 7 ps 0.9 lw 1.3 lc rgb '%s' notitle",
                          sep, key, id, id_colour(id));
        sep = ", \\\n  ";
    }
    for (int l2 = 0; l2 < GD_BASIN_NSPECIAL; l2++)
        if (any[l2])
            gd_plot_printf(s, "%s'fractions.csv' using '%s':(column('attractor') == %d ? column('fraction') : 1/0) "
                                 "with linespoints pt 4 ps 0.9 lw 1.3 lc rgb '%s' notitle",
                              sep, key, -l2 - 1, special_colour[l2]);
    gd_plot_printf(s, "\n");
    gd_fig_end(s, 1);
}

static void draw(const gd_plotter *pl, const gd_case *c, const gd_basins_result *res)
{
    gd_plot_script s = {0};
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
            gd_error e = {0};
            gd_error_set(&e, GD_ERR_IO, "%s: basins.continuation: %s", c->bas_continuation, strerror(errno));
            gd_plot_fail(pl, "pictures not drawn", &e);
            return;
        }
        for (int svg = 0; svg < 2; svg++)
            plot_fractions(&s, svg, c, res, cont);
        name = "fractions";
    } else {
        for (int svg = 0; svg < 2; svg++)
            plot_basins(&s, svg, c, res);
        name = "basins";
    }
    free(cont);
    gd_plot_draw(pl, &s, &name, 1, "pictures not drawn");
}

void gd_plot_basins(const gd_plotter *p, const gd_case *c, const gd_basins_result *r)
{
    if (gd_plot_wanted(p, c->plots))
        draw(p, c, r);
}
