/* Writing results: atomic files, summary.json, CSV tables, the event log, pictures. */
#ifndef GD_OUTPUT_H
#define GD_OUTPUT_H

#include <stdio.h>

#include "geardyn/gd_response.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A file written under a temporary name and renamed into place on commit, so that a
 * reader never sees a half-written file. */
typedef struct gd_atomic_file {
    FILE *fp;
    char path[1200];
    char tmp[1240];
} gd_atomic_file;

GD_API gd_status gd_atomic_open(gd_atomic_file *f, const char *dir, const char *name, gd_error *err);
GD_API gd_status gd_atomic_commit(gd_atomic_file *f, gd_error *err);
GD_API void gd_atomic_abort(gd_atomic_file *f);

/* mkdir -p */
GD_API gd_status gd_mkdir_p(const char *dir, gd_error *err);

/* The event log: one CSV row per event (header with units). */
GD_API void gd_eventlog_header(FILE *fp);
GD_API void gd_eventlog_row(FILE *fp, const gd_model *m, const gd_event *ev, int recording);

/* Summary of an event log file (geardyn events). */
typedef struct gd_eventlog_filter {
    double t_from_s, t_to_s;  /* window (inclusive); +-inf for all */
    char clearance[32];       /* "" for all */
    char kind[32];            /* "" for all */
    int recorded_only;
} gd_eventlog_filter;

typedef struct gd_eventlog_summary {
    long rows, selected;
    int nclear;
    char clear_name[16][24];
    long count[16][4];        /* per clearance and kind */
    double vmin[16], vmax[16], vsum[16], vsum2[16]; /* |relative velocity| at contacts, m/s */
    long ncontacts[16];
    double t_first_s, t_last_s;
    int regime[16];           /* per mesh clearance: gd_impact_regime from the events */
} gd_eventlog_summary;

/* Read an event log, filter it, summarise it; rows that pass the filter are copied to
 * out_csv when not NULL (with the header). */
GD_API gd_status gd_eventlog_summarise(const char *path, const gd_eventlog_filter *flt, FILE *out_csv,
                                       gd_eventlog_summary *sum, gd_error *err);

/* summary.json of a response run: the resolved case (value, unit, source of every key),
 * the derived geometry and model scales, solver statistics and the results. */
GD_API gd_status gd_summary_write_response(const char *dir, const gd_case *c, const gd_model *m,
                                           const gd_response_result *r, const char *const *files, int nfiles,
                                           gd_error *err);

/* Pictures through gnuplot; returns GD_OK and sets *drawn = 0 when gnuplot is missing. */
GD_API int gd_gnuplot_available(void);
GD_API gd_status gd_gnuplot_run(const char *dir, const char *script, gd_error *err);

#ifdef __cplusplus
}
#endif
#endif
