/* Pictures through gnuplot: only the command line spawns a process. */
#ifndef GD_CLI_GNUPLOT_H
#define GD_CLI_GNUPLOT_H

#include "geardyn/gd_error.h"
#include "geardyn/gd_output.h"

#include <stddef.h>

/* 1 when gnuplot is on the PATH. */
int gd_gnuplot_available(void);
/* Run gnuplot on a script in dir, quietly, with dir its working directory: the script names the
 * files it reads and writes relative to dir. */
gd_status gd_gnuplot_run(const char *dir, const char *script, gd_error *err);
/* End the gnuplot that gd_gnuplot_run is waiting for, if any, and reap it (async-signal-safe: for
 * the handler that ends the process at once). Whatever way the process ends, its gnuplot ends with
 * it (gd_gnuplot_run starts it so); this makes sure it is gone before the process is. */
void gd_gnuplot_end_running(void);
/* gd_gnuplot_run on a script that writes each picture of names[] as .NAME.png.tmp and
 * .NAME.svg.tmp (in dir); when it succeeded and every picture is whole (a PNG to its IEND chunk, an SVG to
 * its </svg>) they move into place (NAME.png, NAME.svg), else the run gets a note. The temporary
 * files are removed either way. */
gd_status gd_gnuplot_draw(const char *dir, const char *script, const char *const *names, int nnames, gd_error *err);

/* The pictures of an analysis: 1 when they are wanted (plots) and gnuplot is there to draw them;
 * 0 otherwise, with *note set (for the end of the run) when only gnuplot is missing. */
int gd_gnuplot_wanted(int plots, const char **note);
/* After drawing (status st, error perr): the npics pictures join the run's files, or a note on
 * stderr says why there are none. */
void gd_gnuplot_drawn(gd_status st, const gd_error *perr, const char *const *pics, int npics, gd_run_dir *out);

/* A gnuplot script growing in memory: gd_gnuplot_printf appends to p (n characters, NUL
 * terminated); when memory runs out bad is set and nothing more is appended. Start from {0};
 * free(p) when done. */
typedef struct gd_gnuplot_script {
    char *p;
    size_t n, cap;
    int bad;
} gd_gnuplot_script;
void gd_gnuplot_printf(gd_gnuplot_script *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif
