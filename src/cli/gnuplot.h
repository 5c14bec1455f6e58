/* Pictures through gnuplot: only the command line spawns a process. */
#ifndef GD_CLI_GNUPLOT_H
#define GD_CLI_GNUPLOT_H

#include "geardyn/gd_error.h"

/* 1 when gnuplot is on the PATH. */
int gd_gnuplot_available(void);
/* Run gnuplot on a script in dir, quietly. */
gd_status gd_gnuplot_run(const char *dir, const char *script, gd_error *err);

#endif
