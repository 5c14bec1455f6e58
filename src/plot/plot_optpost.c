/* The pictures after an optimisation over load and speed (docs/optimisation.md section 12):
 * response_over_speed (gear-dynamic: one panel per torque, the response curve of the unmodified
 * flank, the case's own and the optimum, stable solid and unstable dashed, the swept points and the
 * largest value of each marked) and lte_over_torque (the Harris map: the LTE amplitude of the three
 * flanks over torque, the objective's torques marked). */
#include "figure.h"
#include "geardyn/gd_optpost.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const int flank_colour[GD_OPTPOST_NFLANKS] = {0, 1, 4}; /* gd_colour: black, orange, blue */
static const int flank_point[GD_OPTPOST_NFLANKS] = {7, 5, 9};

/* The case's flank is the unmodified one (a case without modification): drawn once. */
static int case_is_unmodified(const gd_optpost *p)
{
    for (int i = 0; i < p->nharris; i++)
        if (p->harris_lte_pp_arcsec[1][i] != p->harris_lte_pp_arcsec[0][i])
            return 0;
    return 1;
}

/* The case's modification is the paper's Table 2 (the paper's pair). */
static int case_is_table2(const gd_optimize_outcome *o)
{
    if (!o->paper)
        return 0;
    for (int i = 0; i < o->dim; i++)
        if (o->case_value[i] != o->table2[i])
            return 0;
    return 1;
}

static void flank_title(const gd_optimize_outcome *o, int j, int same, char *buf, size_t n)
{
    if (j == 0)
        snprintf(buf, n, "unmodified%s", same ? ", as the case is" : "");
    else if (j == 1)
        snprintf(buf, n, "the case''s modification%s", case_is_table2(o) ? " (published with the paper''s pair)" : "");
    else
        snprintf(buf, n, "optimum");
}

#define W 1250
#define H 620

/* One panel row per model (the loop's, then bta when the loop's is not bta), one panel per torque;
 * the key below the panels. */
static void response_picture(gd_plot_script *s, const gd_case *c, const gd_optimize_outcome *o, const gd_optpost *p,
                             int svg, int same)
{
    const int nt = p->curve[0].ntorques, nrow = p->bta_separate ? 2 : 1;
    const int dte = c->opt_dynamic_response == GD_DYN_DTE_PP;
    const int h = nrow == 2 ? 1000 : H;
    gd_fig_begin(s, svg, W, h, "response_over_speed");
    /* the panels between x0 and x1, y0 and y1 of the screen */
    const double x0 = 0.07, x1 = 0.985, gap = 0.05, y0 = nrow == 2 ? 0.15 : 0.24, y1 = nrow == 2 ? 0.895 : 0.83;
    const double vgap = 0.09, pw = (x1 - x0 - gap * (nt - 1)) / nt, ph = (y1 - y0 - vgap * (nrow - 1)) / nrow;
    static const char *const model_words[] = {"torsional model", "torsional model of the two halves",
                                              "bending-torsion-axial model"}; /* as sweep.png */
    if (nrow == 2)
        gd_plot_printf(s, "set multiplot title \"The response over speed at each torque of the objective: above on the "
                          "optimisation's %s, below on the %s\\nsolid: stable period-1 orbits, dashed: unstable "
                          "ones, circles: swept attractors, diamond: the largest stable value\"\n",
                       model_words[c->opt_dynamic_model], model_words[GD_MODEL_BTA]);
    else
        gd_plot_printf(s, "set multiplot title \"The response over speed at each torque of the objective, on the %s\\n"
                          "solid: stable period-1 orbits, dashed: unstable ones, circles: swept attractors, diamond: "
                          "the largest stable value\"\n",
                       model_words[c->opt_dynamic_model]);
    for (int row = 0; row < nrow; row++)
        for (int k = 0; k < nt; k++) {
            const gd_dyn_result *res = row == 0 ? p->curve : p->on_bta;
            /* the stretches of each flank: consecutive branch points, stable when both are; a blank
             * line between stretches, so that a dashed line keeps its pattern along its stretch */
            for (int j = 0; j < GD_OPTPOST_NFLANKS; j++) {
                const gd_dyn_curve *cv = &res[j].curve[k];
                for (int st = 0; st < 2; st++) {
                    gd_plot_printf(s, "$SEG%d_%d_%d_%d << EOD\nx,y\n", row, k, j, st);
                    int open = 0;
                    for (int i = 0; i + 1 < cv->branch_points; i++) {
                        int both = cv->pt[i].stable && cv->pt[i + 1].stable;
                        if (both != st) {
                            open = 0;
                            continue;
                        }
                        if (!open)
                            gd_plot_printf(s, "\n%.12g,%.12g\n", cv->pt[i].speed_rpm, cv->pt[i].value);
                        gd_plot_printf(s, "%.12g,%.12g\n", cv->pt[i + 1].speed_rpm, cv->pt[i + 1].value);
                        open = 1;
                    }
                    gd_plot_printf(s, "EOD\n");
                }
                gd_plot_printf(s, "$SW%d_%d_%d << EOD\nx,y\n", row, k, j);
                for (int i = 0; i < cv->npts; i++)
                    if (cv->pt[i].source == GD_DYN_SWEPT)
                        gd_plot_printf(s, "%.12g,%.12g\n", cv->pt[i].speed_rpm, cv->pt[i].value);
                gd_plot_printf(s, "EOD\n$PK%d_%d_%d << EOD\nx,y\n%.12g,%.12g\nEOD\n", row, k, j, cv->peak_speed_rpm,
                               cv->peak);
            }
            const double top = y1 - row * (ph + vgap);
            gd_plot_printf(s, "set lmargin at screen %g\nset rmargin at screen %g\nset bmargin at screen %g\n"
                              "set tmargin at screen %g\n",
                           x0 + k * (pw + gap), x0 + k * (pw + gap) + pw, top - ph, top);
            gd_plot_printf(s, "set title 'pinion torque %g N m%s'\nset xlabel 'pinion speed (rpm)'\n",
                           res[0].curve[k].torque_nm, nrow == 2 ? (row == 0 ? ", in the optimisation" : ", on bta") : "");
            if (k == 0)
                gd_plot_printf(s, "set ylabel '%s'\n", dte ? "peak-to-peak dynamic transmission error (µm)"
                                                             : "RMS mesh acceleration (m/s²)");
            else
                gd_plot_printf(s, "unset ylabel\n");
            gd_plot_printf(s, "set xtics %g\n",
                           gd_nice_step(c->opt_speed_to_rpm - c->opt_speed_from_rpm, nt > 2 ? 3 : 5));
            int with_key = row == nrow - 1 && k == 0;
            if (with_key)
                gd_plot_printf(s, "set key at screen 0.5,%g center center horizontal Left reverse maxrows 1 "
                                  "samplen 2.5 spacing %g width 1\n", nrow == 2 ? 0.05 : 0.07, GD_KEY_SPACING(svg, 1.2));
            else
                gd_plot_printf(s, "unset key\n");
            gd_plot_printf(s, "plot ");
            const char *sep = "";
            for (int j = 0; j < GD_OPTPOST_NFLANKS; j++) {
                if (j == 1 && same)
                    continue;
                const char *col = gd_colour[flank_colour[j]];
                char title[160];
                flank_title(o, j, same, title, sizeof title);
                for (int st = 1; st >= 0; st--) {
                    gd_plot_printf(s, "%s$SEG%d_%d_%d_%d using 1:2 with lines lw %g dt %s lc rgb '%s' notitle", sep, row,
                                   k, j, st, j == 2 ? 2.5 : 1.8, st ? "1" : "(5,4)", col);
                    sep = ", \\\n  ";
                }
                gd_plot_printf(s, "%s$SW%d_%d_%d using 1:2 with points pt 6 ps 0.8 lc rgb '%s' notitle", sep, row, k, j,
                               col);
                gd_plot_printf(s, "%s$PK%d_%d_%d using 1:2 with points pt 13 ps 1.6 lc rgb '%s' notitle", sep, row, k,
                               j, col);
                if (with_key)
                    gd_plot_printf(s, "%s1/0 with linespoints pt 13 ps 1.6 lw %g lc rgb '%s' title '%s'", sep,
                                   j == 2 ? 2.5 : 1.8, col, title);
            }
            if (with_key)
                gd_plot_printf(s, "%s1/0 with lines lw 1.8 dt (5,4) lc rgb '#000000' title 'unstable'", sep);
            gd_plot_printf(s, "\n");
        }
    gd_fig_end(s, 1);
}

static void lte_picture(gd_plot_script *s, const gd_case *c, const gd_optimize_outcome *o, const gd_optpost *p,
                        int svg, int same)
{
    (void)c;
    gd_fig_begin(s, svg, W, 680, "lte_over_torque");
    gd_plot_printf(s, "set title 'Peak-to-peak loaded transmission error over the pinion torque (the Harris map)'\n"
                      "set xlabel 'pinion torque (N m)'\nset ylabel 'peak-to-peak loaded transmission error "
                      "(arcsec)'\nset key outside below center horizontal maxrows 2 height 1.5 spacing %g\n",
                   GD_KEY_SPACING(svg, 1.2));
    static const char *const col_names[GD_OPTPOST_NFLANKS] = {"lte_unmodified_arcsec", "lte_case_arcsec",
                                                               "lte_optimum_arcsec"};
    gd_plot_printf(s, "plot ");
    const char *sep = "";
    for (int j = 0; j < GD_OPTPOST_NFLANKS; j++) {
        if (j == 1 && same)
            continue;
        char title[160];
        flank_title(o, j, same, title, sizeof title);
        gd_plot_printf(s, "%s'lte_over_torque.csv' using 'torque_nm':'%s' with linespoints pt %d ps 0.7 lw %g "
                          "lc rgb '%s' title '%s'",
                       sep, col_names[j], flank_point[j], j == 2 ? 2.5 : 1.8, gd_colour[flank_colour[j]], title);
        sep = ", \\\n  ";
    }
    for (int j = 0; j < GD_OPTPOST_NFLANKS; j++) {
        if (j == 1 && same)
            continue;
        gd_plot_printf(s, "%s'lte_over_torque.csv' using 'torque_nm':(column('objective_torque') == 1 ? "
                          "column('%s') : 1/0) with points pt 6 ps 2.2 lw 1.5 lc rgb '%s' %s",
                       sep, col_names[j], gd_colour[flank_colour[j]],
                       j == 0 ? "title 'the torques of the objective'" : "notitle");
    }
    gd_plot_printf(s, "\n");
    gd_fig_end(s, 0);
}

void gd_plot_optpost(const gd_plotter *pl, const gd_case *c, const gd_optimize_outcome *o)
{
    const gd_optpost *p = o->post;
    if (!p || !gd_plot_wanted(pl, c->plots))
        return;
    static const char *const names[2] = {"lte_over_torque", "response_over_speed"};
    int same = case_is_unmodified(p);
    gd_plot_script s = {0};
    for (int svg = 0; svg < 2; svg++) {
        lte_picture(&s, c, o, p, svg, same);
        if (p->dynamic)
            response_picture(&s, c, o, p, svg, same);
    }
    gd_plot_draw(pl, &s, names, p->dynamic ? 2 : 1, "pictures not drawn");
}
