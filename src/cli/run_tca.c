/* The `tca` analysis on the command line: pictures of the contact pattern on the unrolled flank
 * and of the GTE, and the summary lines. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *half_name[2] = {"left", "right"};

/* Pictures: contact pattern on the unrolled flank of each half (face position across, roll length
 * up, separation in colour, the paint thickness as the edge of the dark pattern, the contact path
 * as points) and the GTE curves. */
static gd_status draw(const char *dir, const gd_case *c, const gd_tca_result *r, gd_error *err)
{
    static const char *fmt[2][2] = {{"pngcairo size 1400,640 font ',11'", ".png"},
                                    {"svg size 1400,640 dynamic font 'sans,11'", ".svg"}};
    double p = c->paint_thickness_um;
    char script[16384];
    int n = 0;
    n += snprintf(script + n, sizeof script - n, "set datafile separator ','\nset datafile missing 'NaN'\n");
    for (int fi = 0; fi < 2; fi++) {
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '.contact_pattern%s.tmp'\n"
            "set multiplot layout 1,%d title 'Contact pattern on the unrolled pinion flank (paint thickness %.3g um; "
            "black: path of the first contact)'\n"
            "set xlabel 'face position from the middle of the half (mm)'\nset ylabel 'roll length (mm)'\n"
            "set cbrange [0:%.6g]\nset cblabel 'least separation (um)'\n"
            "set palette defined (0 '#7f0000', %.6g '#d7301f', %.6g '#fdd49e', %.6g '#f7f7f7')\n"
            "set key off\nset grid front\n",
            fmt[fi][0], fmt[fi][1], r->halves, p, 8 * p, p, p * 1.0001, 8 * p);
        for (int h = 0; h < r->halves; h++)
            n += snprintf(script + n, sizeof script - n,
                "set title '%s half (GTE %.4g arcsec p-p%s)'\n"
                "plot 'separation_%s.csv' every ::1 using 1:2:($3 > %.6g ? %.6g : $3) with image, "
                "'contact_path.csv' every ::1 using (strcol(1) eq '%s' ? $5 : 1/0):4 with points pt 7 ps 0.5 lc rgb 'black'\n",
                half_name[h], r->gte_pp_arcsec[h], r->edge_kinds[h] ? ", edge contact" : "", half_name[h], 8 * p,
                8 * p, half_name[h]);
        n += snprintf(script + n, sizeof script - n, "unset multiplot\nunset output\n");
        n += snprintf(script + n, sizeof script - n,
            "set terminal %s\nset output '.gte%s.tmp'\nset title 'Geometric transmission error (Eq. 10)'\n"
            "set xlabel 'pinion angle (deg)'\nset ylabel 'GTE (arc-seconds of the gear)'\nset key on top right\n"
            "unset colorbox\nplot 'gte.csv' every ::1 using 1:2 with linespoints pt 7 ps 0.5 lw 1.5 title 'left half'",
            fmt[fi][0], fmt[fi][1]);
        if (r->halves > 1)
            n += snprintf(script + n, sizeof script - n,
                          ", 'gte.csv' every ::1 using 1:6 with linespoints pt 6 ps 0.5 lw 1.5 dt 2 title 'right half'");
        n += snprintf(script + n, sizeof script - n, "\nunset output\nset colorbox\n");
    }
    if (n >= (int)sizeof script)
        return gd_error_set(err, GD_ERR_INTERNAL, "gnuplot script too long");
    static const char *names[] = {"contact_pattern", "gte"};
    return gd_gnuplot_draw(dir, script, names, 2, err);
}

void cli_tca_pictures(const cli_case_args *a, const gd_case *c, const void *result, gd_run_dir *out,
                      const char **note)
{
    if (gd_gnuplot_wanted(c->plots, note)) {
        gd_error perr = {0};
        gd_status pst = draw(gd_run_dir_stage(out), c, result, &perr);
        static const char *pics[] = {"contact_pattern.png", "contact_pattern.svg", "gte.png", "gte.svg"};
        gd_gnuplot_drawn(pst, &perr, pics, 4, out);
    }
}

void cli_tca_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    const gd_tca_result *r = result;
    if (a->quiet)
        return;
    printf("%s: TCA, %d positions per half, GTE peak-to-peak", dir, r->npos);
    for (int h = 0; h < r->halves; h++)
        printf(" %s %.6g arcsec%s", half_name[h], r->gte_pp_arcsec[h], h + 1 < r->halves ? "," : "");
    printf("; edge contact");
    for (int h = 0; h < r->halves; h++)
        printf(" %s %s", half_name[h], r->edge_kinds[h] ? "yes" : "no");
    printf("\n  operating pressure angle %.6g deg, %ld Newton iterations, %.3f s\n", r->alpha_op_mean * 180 / M_PI,
           r->iterations, r->wall_s);
    if (c->tca_formulation == GD_TCA_BOTH)
        printf("  formulations (a) and (b): %d of %d positions compared, largest difference %.3g arcsec\n",
               r->compared, r->npos * r->halves, r->max_diff_arcsec);
}
