/* Writing results: atomic files, summary.json, CSV tables, the event log, pictures. */
#ifndef GD_OUTPUT_H
#define GD_OUTPUT_H

#include <stdio.h>

#include "geardyn/gd_response.h"
#include "geardyn/gd_sweep.h"
#include "geardyn/gd_workprec.h"
#include "geardyn/gd_tca.h"
#include "geardyn/gd_ltca.h"
#include "geardyn/gd_optimize.h"

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

/* ---- tca ---- */
/* The summary.json of a tca run (stable keys: results.gte_pp_arcsec.left/right,
 * results.edge_contact.left/right, results.contact_ratio_transverse, results.contact_ratio_overlap,
 * results.operating_pressure_angle_deg). */
GD_API gd_status gd_summary_write_tca(const char *dir, const gd_case *c, const gd_tca_result *r,
                                      const char *const *files, int nfiles, gd_error *err);

/* ---- ltca ---- */
/* The summary.json of an ltca run (stable keys: results.lte_pp_arcsec,
 * results.mean_mesh_stiffness_n_per_m.left/right, results.load_share.left/right). */
GD_API gd_status gd_summary_write_ltca(const char *dir, const gd_case *c, const gd_ltca_result *r,
                                       const char *const *files, int nfiles, gd_error *err);

/* ---- optimize ---- */
GD_API gd_status gd_summary_write_optimize(const char *dir, const gd_case *c, const gd_opt_optimize_summary *s,
                                           const char *const *files, int nfiles, gd_error *err);

/* ---- compare ---- */
/* One summary over every problem compared (each with the same optimisers, runs and budget); adds
 * the runtime distribution pooled over the problems at 1 %, 10 % and 100 % of the budget. */
GD_API gd_status gd_summary_write_compare(const char *dir, const gd_case *c, const gd_opt_compare_problem *pb,
                                          int nproblems, const char *const *files, int nfiles, int threads,
                                          gd_error *err);

/* ---- workprec ---- */
/* summary.json of a work-precision run (written atomically into dir). */
GD_API gd_status gd_summary_write_workprec(const char *dir, const gd_case *c, const gd_model *m,
                                           const gd_wp_result *res, const char *const *files, int nfiles,
                                           gd_error *err);

/* ---- sweep journal ---- */
/* Journal records: one text line per point ending in a CRC-32, e.g. for a journal file or a
 * message between MPI ranks. format: a malloc'd line with its '\n' (free it). */
GD_API gd_status gd_sweep_record_format(const gd_sweep_plan *p, const gd_sweep_point *pt, char **line, size_t *len,
                                        gd_error *err);
/* Parse one record (with or without its '\n') into pts[slot]; GD_ERR_INPUT for a torn,
 * corrupt or foreign record. *slot gets the slot. */
GD_API gd_status gd_sweep_record_parse(const gd_sweep_plan *p, const char *line, size_t len, gd_sweep_point *pts,
                                       int *slot, gd_error *err);
/* The first line of a journal (identifies the sweep by its fingerprint). */
GD_API void gd_sweep_journal_header(const gd_sweep_plan *p, char *buf, size_t len);

/* Read a journal: every intact record of this sweep is loaded into pts (points after a
 * missing one in a continuation chain are dropped, they depend on it); a torn or corrupt
 * line (the last one after a kill) is ignored. *text (malloc'd) receives the header and the
 * kept lines, to be written back as the journal. A missing file or one with a torn header
 * gives no points; a journal of another sweep is GD_ERR_INPUT. */
GD_API gd_status gd_sweep_journal_load(const char *path, const gd_sweep_plan *p, gd_sweep_point *pts, char **text,
                                       size_t *text_len, int *loaded, int *ignored, gd_error *err);

/* ---- sweep tables ---- */
/* The final files, atomically, from the points in slot order: sweep.csv, bifurcation.csv
 * and summary.json (which lists files[0..nfiles-1] as the files of the run). */
GD_API gd_status gd_sweep_write_tables(const char *dir, const gd_sweep_plan *p, const gd_sweep_point *pts,
                                       gd_error *err);
/* summary.json of a sweep: the settings, failed points, motion tallies, branches and the
 * hysteresis intervals (gd_sweep_hysteresis). */
GD_API gd_status gd_sweep_write_summary(const char *dir, const gd_case *c, const gd_sweep_plan *p,
                                        const gd_sweep_point *pts, const char *const *files, int nfiles,
                                        gd_error *err);

#ifdef __cplusplus
}
#endif
#endif
