/* Writing results: the output directory of a run, through which every file of a run is written,
 * and reading an event log back. The standard files themselves are written by the rows of the
 * table of analyses (gd_analysis.h: write, summary). */
#ifndef GD_OUTPUT_H
#define GD_OUTPUT_H

#include <stdio.h>

#include "geardyn/gd_sweep.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The output directory of a run. Every file of a run is opened and committed through it: a file
 * is written under a temporary name and renamed on commit (a reader never sees a half-written
 * file), and the names committed, in order, with those added by gd_run_dir_add (pictures drawn
 * into the stage by other means), are the list summary.json gives. The directory DIR is made
 * (mkdir -p) and locked (flock; a second run into it is refused) at the first file, and the
 * files are written into its stage, PARENT/.NAME.geardyn-stage beside DIR. gd_run_dir_publish
 * exchanges the stage and DIR in one step (renameat2 RENAME_EXCHANGE) when the set has a
 * summary.json: the previous result's files the new set lacks are gone, DIR's other entries (a
 * user's files, the sweep's journal) stay. Where an exchange cannot be (gd_run_dir_fallback says
 * why) the stage is DIR/.staging and the files are moved in one by one, summary.json last, after
 * the previous summary.json and its files the new set lacks are removed; a set without
 * summary.json (an export) is always moved in that way and removes nothing. Closing an
 * unpublished run removes the stage and leaves DIR as it was. A name that starts with '.' is a
 * working file of the run (the sweep's journal), written in DIR itself, and is not listed. */
typedef struct gd_run_dir gd_run_dir;

GD_API gd_status gd_run_dir_open(const char *dir, gd_run_dir **out, gd_error *err);
/* A run directory in memory only: the files are kept (gd_run_dir_data) and nothing touches the
 * disk; name is what messages call it. Publishing it only marks it published. */
GD_API gd_status gd_run_dir_open_memory(const char *name, gd_run_dir **out, gd_error *err);
/* Keep the bytes of every file committed from now on in memory as well (call before the first
 * file): the writers write into memory, and at commit the bytes go into the file, so that what
 * gd_run_dir_data gives is what the file holds. */
GD_API void gd_run_dir_keep(gd_run_dir *d);
/* The directory sub of d (a run of its own, published into d's stage, or kept in memory with d):
 * when d keeps its files, so does sub, and at sub's publication its files join d's kept files as
 * "sub/NAME". The caller lists "sub/" in d (gd_run_dir_add) and closes sub before d. */
GD_API gd_status gd_run_dir_open_sub(gd_run_dir *d, const char *sub, gd_run_dir **out, gd_error *err);
/* The bytes of a committed file of a keeping run directory (NAME or "sub/NAME"), *len its length;
 * NULL when d kept no such file. Valid until gd_run_dir_close. */
GD_API const char *gd_run_dir_data(const gd_run_dir *d, const char *name, size_t *len);
/* Discards the files still open and the stage when not published, unlocks and frees d; NULL is
 * allowed. */
GD_API void gd_run_dir_close(gd_run_dir *d);
GD_API const char *gd_run_dir_path(const gd_run_dir *d);
/* Where the run's files are written before gd_run_dir_publish (pictures are drawn there); NULL for
 * a run directory in memory. */
GD_API const char *gd_run_dir_stage(const gd_run_dir *d);
/* Make and lock the directory now (the first gd_run_dir_create does it otherwise). */
GD_API gd_status gd_run_dir_make(gd_run_dir *d, gd_error *err);
/* A new file name of the run, open for writing in *fp until gd_run_dir_commit or _discard. */
GD_API gd_status gd_run_dir_create(gd_run_dir *d, const char *name, FILE **fp, gd_error *err);
GD_API gd_status gd_run_dir_commit(gd_run_dir *d, FILE *fp, gd_error *err);
GD_API void gd_run_dir_discard(gd_run_dir *d, FILE *fp);
/* A file written into the stage by other means joins the list. */
GD_API gd_status gd_run_dir_add(gd_run_dir *d, const char *name, gd_error *err);
/* Publish the listed files of the stage (see above). */
GD_API gd_status gd_run_dir_publish(gd_run_dir *d, gd_error *err);
/* NULL when the set is published in one step (or nothing is made yet), else why its files are
 * moved in one by one ("it is the working directory", "it is a mount point", ...). */
GD_API const char *gd_run_dir_fallback(const gd_run_dir *d);
/* The files of the run so far, in order (valid until the next call on d). */
GD_API const char *const *gd_run_dir_files(const gd_run_dir *d, int *n);

/* The pictures of a run. The library writes the gnuplot script of an analysis's pictures and asks
 * a drawer its caller gives (gd_run_env.draw) to turn it into pictures; it never spawns a process
 * itself, so a run without a drawer has no pictures (its notes say so). The drawer is called with
 * dir, the run's stage (the script reads the run's tables by their names there), the script, and
 * the stems names[0..nnames-1] of the pictures it writes, each as .NAME.png.tmp and .NAME.svg.tmp
 * in dir: it runs the script in dir and, when it succeeded and every picture is whole (a PNG to
 * its IEND chunk, an SVG to its closing tag), moves them to NAME.png and NAME.svg, removing the
 * temporary files either way; any other outcome is an error whose message says why. Called with
 * script NULL it says whether it can draw at all: GD_OK, or an error whose message is the note
 * ("gnuplot is not installed: ..."). The command line's drawer runs gnuplot (src/cli/gnuplot.c),
 * the Python module's too (python/geardyn/_draw.py). */
typedef gd_status (*gd_draw_fn)(void *user, const char *dir, const char *script, const char *const *names,
                                int nnames, gd_error *err);
/* What a note of a run is about: no pictures at all (pictures wanted, but no drawer or it cannot
 * draw; the text says why), or some pictures not drawn (the text names them and says why). */
enum { GD_NOTE_NO_PICTURES = 1, GD_NOTE_PICTURES_FAILED = 2 };
/* A note of a run for its caller (gd_run_env.note): kind (above) and a line of text. */
typedef void (*gd_note_fn)(void *user, int kind, const char *text);

/* Summary of an event log file (geardyn events). */
typedef struct gd_eventlog_filter {
    double t_from_s, t_to_s;  /* window (inclusive); +-inf for all */
    char clearance[32];       /* "" for all */
    char kind[32];            /* "" for all */
    int recorded_only;
} gd_eventlog_filter;

/* The filter that selects every event (no window, every clearance and kind): start from it. */
GD_API gd_eventlog_filter gd_eventlog_filter_all(void);

typedef struct gd_eventlog_summary {
    long rows, selected;
    int nclear;
    char clear_name[16][24];
    long count[16][4];        /* per clearance and kind */
    double vmin[16], vmax[16], vsum[16], vsum2[16]; /* |relative velocity| at contacts, m/s */
    long ncontacts[16];
    double t_first_s, t_last_s; /* of the selected events */
    double log_t_min_s, log_t_max_s; /* of every event of the log (+inf, -inf: none) */
    long log_period_min, log_period_max; /* their mesh periods */
    int regime[16];           /* per mesh clearance: gd_impact_regime from the events */
} gd_eventlog_summary;

/* Read an event log, filter it, summarise it; rows that pass the filter are copied to
 * out_csv when not NULL (with the header). A time window (t_from_s, t_to_s not both infinite)
 * that can select nothing is refused (GD_ERR_INPUT, saying what the log holds): from at or after
 * to, a window wholly before the log's first event or after its last, any window on an empty log. */
GD_API gd_status gd_eventlog_summarise(const char *path, const gd_eventlog_filter *flt, FILE *out_csv,
                                       gd_eventlog_summary *sum, gd_error *err);
/* The same with the selected rows (and the header) as CSV text in *csv (malloc'd: gd_free), *len
 * its bytes; flt NULL selects every row, sum may be NULL. */
GD_API gd_status gd_eventlog_select(const char *path, const gd_eventlog_filter *flt, char **csv, size_t *len,
                                    gd_eventlog_summary *sum, gd_error *err);

/* ---- the sweep's journal ----
 * What a program that distributes the points of a sweep (over processes, over MPI ranks) or
 * resumes an interrupted one needs: the command line's --resume and MPI driver use these. */
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

/* The journal of a sweep in its run directory, DIR/.sweep.journal, as geardyn run and gd_job keep
 * it: a header naming the sweep, then one record per finished point, appended and synced as the
 * point finishes; removed (close with remove) once the final files are published, kept when the
 * run is interrupted or fails, so that a resumed run gives the files of an uninterrupted one.
 * open: the directory made and locked (gd_run_dir_make), the temporary files of an earlier run
 * killed while writing removed; with resume the journal read back into pts (gd_sweep_journal_load;
 * the row then runs only the points it lacks) and written back without its damaged lines, without
 * resume a new one. append and point may be called from any thread. */
typedef struct gd_sweep_journal gd_sweep_journal;
GD_API gd_status gd_sweep_journal_open(gd_run_dir *out, const gd_sweep_plan *p, gd_sweep_point *pts, int resume,
                                       gd_sweep_journal **j, gd_error *err);
/* One record (gd_sweep_record_format's line, e.g. from another MPI rank), synced to disk. */
GD_API gd_status gd_sweep_journal_append(gd_sweep_journal *j, const char *line, size_t len, gd_error *err);
/* The record of the finished point pt, appended. */
GD_API gd_status gd_sweep_journal_point(gd_sweep_journal *j, const gd_sweep_plan *p, const gd_sweep_point *pt,
                                        gd_error *err);
/* The journal as read back or started (header and records; for the other MPI ranks). */
GD_API const char *gd_sweep_journal_text(const gd_sweep_journal *j, size_t *len);
/* What open found, as geardyn run says it after "geardyn: " ("" when nothing): "resuming: K of N
 * points already done", "note: no journal in DIR: the sweep starts from the beginning", "note: DIR
 * held an unfinished sweep; starting over (--resume continues one)". */
GD_API const char *gd_sweep_journal_note(const gd_sweep_journal *j);
GD_API const char *gd_sweep_journal_path(const gd_sweep_journal *j);
/* Close; remove: the journal's file too. NULL allowed. */
GD_API void gd_sweep_journal_close(gd_sweep_journal *j, int remove);

#ifdef __cplusplus
}
#endif
#endif
