/* A run of the analysis of a case, as geardyn run does it, for a program that cannot fill a
 * gd_run_env with C function pointers or does not know the size of the library's structures: a
 * foreign-function interface such as geardyn's Python module (python/geardyn, docs/python.md).
 * Everything crosses as an opaque pointer, numbers and text:
 *
 *     gd_job *j;
 *     gd_job_new(c, NULL, 0, &j, &err);        c: a loaded case (gd_case_new, gd_case_load, gd_case_set)
 *     gd_job_run(j, &err);                     blocks; from any thread, while another thread may
 *                                              read gd_job_progress and call gd_job_stop
 *     gd_job_file(j, "summary.json", &len);    the bytes of every file of the run
 *     gd_job_free(j);
 *
 * The run is gd_case_prepare (the checks and messages of geardyn run, before any work) then the
 * analysis's row of the table (gd_analysis_run_dir) in a run directory that keeps its files in
 * memory: without a directory nothing touches the disk; with one the files are also written and
 * published there as geardyn run publishes them (stage, lock, one-step exchange; a failed or
 * stopped run leaves the previous result or nothing), with its pictures when the caller gives a
 * drawer (gd_job_set_draw: the library spawns no process; the Python module's runs gnuplot as the
 * command line does). */
#ifndef GD_JOB_H
#define GD_JOB_H

#include "geardyn/gd_analysis.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct gd_job gd_job;

/* A run of c's analysis (c is copied: loaded and set, not resolved); dir NULL: the files are kept
 * in memory only; threads as gd_run_env.threads (0: gd_threads_default). */
GD_API gd_status gd_job_new(const gd_case *c, const char *dir, int threads, gd_job **job, gd_error *err);
/* Prepare the case and run its analysis (once). GD_ERR_INTERRUPTED when stopped. */
GD_API gd_status gd_job_run(gd_job *j, gd_error *err);
/* The drawer of the run's pictures (gd_output.h: gd_draw_fn), called with user from the thread of
 * gd_job_run; set before gd_job_run. Without one a run into a directory draws no pictures and its
 * notes say so; a run in memory only draws none and says nothing. */
GD_API void gd_job_set_draw(gd_job *j, gd_draw_fn draw, void *user);
/* A sweep: continue the journal an interrupted run into the same directory left (geardyn run
 * --resume): the points it holds are not run again, and the files are those of an uninterrupted
 * run. Set before gd_job_run; a run into a directory only. Every sweep into a directory keeps the
 * journal DIR/.sweep.journal while it runs (gd_sweep_journal) and leaves it when stopped. */
GD_API void gd_job_set_resume(gd_job *j, int resume);
/* The notes of the run so far (gd_run_env.note: no pictures and why, pictures not drawn and why),
 * one a line, each once; "" when none. Valid until gd_job_free; not while gd_job_run runs. */
GD_API const char *gd_job_notes(const gd_job *j);
/* Ask the run to stop (any thread, any time, also before gd_job_run): it ends with
 * GD_ERR_INTERRUPTED at the next unit of work it asks (a mesh period, a sweep point, a contact
 * position, an objective evaluation) and publishes nothing. */
GD_API void gd_job_stop(gd_job *j);
/* The run's progress so far: *done of *total units (total 0: not known), and the unit ("mesh
 * periods", "points", "runs", "branches", "problems", or a work-precision phase: "reference",
 * "check", "grid", "order", "transient"; "" before any). Any thread. */
GD_API const char *gd_job_progress(const gd_job *j, long *done, long *total);
/* After a successful gd_job_run: the bytes of the run's file name (as summary.json lists it;
 * "optimum/summary.json" for a file of a sub-directory), *len its length; NULL when the run has
 * no such file. Valid until gd_job_free. */
GD_API const char *gd_job_file(const gd_job *j, const char *name, size_t *len);
/* Frees the job and its files, unlocks its directory; NULL allowed. Not while gd_job_run runs. */
GD_API void gd_job_free(gd_job *j);

#ifdef __cplusplus
}
#endif
#endif
