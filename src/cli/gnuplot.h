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

/* The command line's drawer of a run's pictures (gd_output.h: gd_draw_fn; user unused): with script
 * NULL GD_OK when gnuplot is on the PATH, else an error whose message is the run's note; otherwise
 * gd_gnuplot_draw. */
gd_status cli_gnuplot_drawer(void *user, const char *dir, const char *script, const char *const *names, int nnames,
                             gd_error *err);

#endif
