/* A run's pictures through its caller's drawer (plot.h): whether they are wanted and can be drawn,
 * the script handed over, the pictures listed with the run's files, the notes. */
#include "plot.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

static void note(const gd_plotter *p, int kind, const char *text)
{
    if (p->note)
        p->note(p->user, kind, text);
}

/* The stage of the run, or NULL when its files are kept in memory only (no directory to draw into). */
static const char *stage(const gd_plotter *p) { return p->out ? gd_run_dir_stage(p->out) : NULL; }

/* 0 with why set when there is no drawer or it cannot draw. */
static int able(const gd_plotter *p, gd_error *why)
{
    if (!p->draw) {
        gd_error_set(why, GD_ERR_IO, "no drawer was given (gd_run_env.draw): no pictures");
        return 0;
    }
    return p->draw(p->user, stage(p), NULL, NULL, 0, why) == GD_OK;
}

int gd_plot_can(const gd_plotter *p)
{
    gd_error why = {0};
    return stage(p) && able(p, &why);
}

int gd_plot_wanted(const gd_plotter *p, int want)
{
    if (!want || !stage(p))
        return 0;
    gd_error why = {0};
    if (!able(p, &why)) {
        note(p, GD_NOTE_NO_PICTURES, why.msg);
        return 0;
    }
    return 1;
}

gd_status gd_plot_draw(const gd_plotter *p, gd_plot_script *s, const char *const *names, int nnames,
                       const char *failed)
{
    gd_error err = {0};
    gd_status st = s->bad ? gd_error_set(&err, GD_ERR_NOMEM, "out of memory for the gnuplot script")
                          : p->draw(p->user, stage(p), s->p, names, nnames, &err);
    free(s->p);
    *s = (gd_plot_script){0};
    if (st == GD_OK) {
        for (int i = 0; i < nnames && st == GD_OK; i++)
            for (int e = 0; e < 2 && st == GD_OK; e++) {
                char name[300];
                snprintf(name, sizeof name, "%s.%s", names[i], e ? "svg" : "png");
                st = gd_run_dir_add(p->out, name, &err);
            }
    }
    if (st != GD_OK)
        gd_plot_fail(p, failed, &err);
    return st;
}

void gd_plot_fail(const gd_plotter *p, const char *failed, const gd_error *err)
{
    char text[sizeof err->msg + 200];
    snprintf(text, sizeof text, "%s: %s", failed, err->msg);
    note(p, GD_NOTE_PICTURES_FAILED, text);
}

void gd_plot_printf(gd_plot_script *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    gd_strbuf_vprintf(b, fmt, ap);
    va_end(ap);
}
