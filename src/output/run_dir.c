/* The output directory of a run: every file of a run is opened and committed here, and the names
 * committed (or added, like the pictures drawn into it) make the list that summary.json gives.
 * Where the files wait, the lock and the publication are the stage's (stage.c): a failed or
 * interrupted run leaves the previous result (docs/robustness.md). */
#include "output_internal.h"
#include "stage.h"

#include <stdlib.h>
#include <string.h>

#define RUN_DIR_MAX_FILES 64
#define RUN_DIR_MAX_OPEN 8

struct gd_run_dir {
    char path[GD_PATH_MAX];
    gd_stage stage;                          /* DIR locked, the stage made: valid when made */
    int made;
    int published;
    gd_atomic_file open[RUN_DIR_MAX_OPEN];   /* files being written */
    char name[RUN_DIR_MAX_OPEN][256];
    char files[RUN_DIR_MAX_FILES][256];      /* committed or added, in that order */
    const char *list[RUN_DIR_MAX_FILES];
    int nfiles;
};

GD_API gd_status gd_run_dir_open(const char *dir, gd_run_dir **out, gd_error *err)
{
    *out = NULL;
    if (strlen(dir) >= GD_PATH_MAX)
        return gd_error_set(err, GD_ERR_INPUT, "%s: output directory path too long (valid: < %d characters)", dir,
                            GD_PATH_MAX);
    gd_run_dir *d = calloc(1, sizeof *d);
    if (!d)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    snprintf(d->path, sizeof d->path, "%s", dir);
    *out = d;
    return GD_OK;
}

GD_API const char *gd_run_dir_path(const gd_run_dir *d) { return d->path; }

GD_API const char *gd_run_dir_stage(const gd_run_dir *d)
{
    return d->made && !d->published ? d->stage.path : d->path;
}

GD_API gd_status gd_run_dir_make(gd_run_dir *d, gd_error *err)
{
    if (d->made)
        return GD_OK;
    gd_status st = gd_stage_make(&d->stage, d->path, err);
    if (st != GD_OK) {
        gd_stage_close(&d->stage, 0);
        return st;
    }
    d->made = 1;
    return GD_OK;
}

/* A name starting with '.' is a working file of the run (the sweep's journal): it is written in
 * the directory itself, where it outlives an interrupted run; the others go to the stage. */
GD_API gd_status gd_run_dir_create(gd_run_dir *d, const char *name, FILE **fp, gd_error *err)
{
    *fp = NULL;
    int k = 0;
    while (k < RUN_DIR_MAX_OPEN && d->open[k].fp)
        k++;
    if (k == RUN_DIR_MAX_OPEN)
        return gd_error_set(err, GD_ERR_INTERNAL, "%s/%s: more than %d files open at once", d->path, name,
                            RUN_DIR_MAX_OPEN);
    gd_status st = gd_run_dir_make(d, err);
    if (st == GD_OK)
        st = gd_atomic_open(&d->open[k], name[0] == '.' ? d->path : d->stage.path, name, err);
    if (st != GD_OK)
        return st;
    snprintf(d->name[k], sizeof d->name[k], "%s", name);
    *fp = d->open[k].fp;
    return GD_OK;
}

static int slot_of(const gd_run_dir *d, const FILE *fp)
{
    for (int k = 0; k < RUN_DIR_MAX_OPEN; k++)
        if (fp && d->open[k].fp == fp)
            return k;
    return -1;
}

GD_API gd_status gd_run_dir_add(gd_run_dir *d, const char *name, gd_error *err)
{
    if (name[0] == '.')
        return GD_OK;
    if (d->nfiles == RUN_DIR_MAX_FILES)
        return gd_error_set(err, GD_ERR_INTERNAL, "%s: more than %d files in one run", d->path, RUN_DIR_MAX_FILES);
    snprintf(d->files[d->nfiles], sizeof d->files[d->nfiles], "%s", name);
    d->list[d->nfiles] = d->files[d->nfiles];
    d->nfiles++;
    return GD_OK;
}

GD_API gd_status gd_run_dir_commit(gd_run_dir *d, FILE *fp, gd_error *err)
{
    int k = slot_of(d, fp);
    if (k < 0)
        return gd_error_set(err, GD_ERR_INTERNAL, "%s: committing a file this run did not open", d->path);
    gd_status st = gd_atomic_commit(&d->open[k], err);
    if (st == GD_OK)
        st = gd_run_dir_add(d, d->name[k], err);
    return st;
}

GD_API void gd_run_dir_discard(gd_run_dir *d, FILE *fp)
{
    int k = slot_of(d, fp);
    if (k >= 0)
        gd_atomic_abort(&d->open[k]);
}

GD_API const char *const *gd_run_dir_files(const gd_run_dir *d, int *n)
{
    *n = d->nfiles;
    return d->list;
}

GD_API gd_status gd_run_dir_publish(gd_run_dir *d, gd_error *err)
{
    if (!d->made || d->published)
        return GD_OK;
    gd_status st = gd_stage_publish(&d->stage, d->list, d->nfiles, err);
    d->published = st == GD_OK;
    return st;
}

GD_API const char *gd_run_dir_fallback(const gd_run_dir *d)
{
    return d->made && d->stage.fallback[0] ? d->stage.fallback : NULL;
}

GD_API void gd_run_dir_close(gd_run_dir *d)
{
    if (!d)
        return;
    for (int k = 0; k < RUN_DIR_MAX_OPEN; k++)
        gd_atomic_abort(&d->open[k]);
    if (d->made)
        gd_stage_close(&d->stage, d->published);
    free(d);
}
