/* The output directory of a run: every file of a run is opened and committed here, and the names
 * committed (or added, like the pictures drawn into it) make the list that summary.json gives.
 * Where the files wait, the lock and the publication are the stage's (stage.c): a failed or
 * interrupted run leaves the previous result (docs/robustness.md).
 *
 * A run directory may also keep the bytes of every file it commits (gd_run_dir_keep), or hold
 * them only in memory (gd_run_dir_open_memory): a writer then writes into a memory stream, whose
 * bytes are copied into the file on disk (when there is one) at commit, so that what is kept is
 * exactly what the file holds. A sub-directory's kept files join its parent's at its publication,
 * under "sub/". */
#include "output_internal.h"
#include "stage.h"

#include <stdlib.h>
#include <string.h>

#define RUN_DIR_MAX_FILES 64
#define RUN_DIR_MAX_OPEN 8

typedef struct kept_file {
    char *name;
    char *data;
    size_t len;
} kept_file;

struct gd_run_dir {
    char path[GD_PATH_MAX];
    gd_stage stage;                          /* DIR locked, the stage made: valid when made */
    int made;
    int published;
    int disk;                                /* 0: in memory only (gd_run_dir_open_memory) */
    int keep;                                /* committed files are kept in memory */
    gd_run_dir *parent;                      /* gd_run_dir_open_sub of a keeping parent */
    char sub[256];
    gd_atomic_file open[RUN_DIR_MAX_OPEN];   /* files being written (on disk) */
    FILE *mem[RUN_DIR_MAX_OPEN];             /* their memory streams (keep) */
    char *mbuf[RUN_DIR_MAX_OPEN];
    size_t mlen[RUN_DIR_MAX_OPEN];
    char name[RUN_DIR_MAX_OPEN][256];
    char files[RUN_DIR_MAX_FILES][256];      /* committed or added, in that order */
    const char *list[RUN_DIR_MAX_FILES];
    int nfiles;
    kept_file *kept;                         /* keep: the committed files' bytes (and those of subs) */
    int nkept, capkept;
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
    d->disk = 1;
    *out = d;
    return GD_OK;
}

GD_API gd_status gd_run_dir_open_memory(const char *name, gd_run_dir **out, gd_error *err)
{
    *out = NULL;
    gd_run_dir *d = calloc(1, sizeof *d);
    if (!d)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    snprintf(d->path, sizeof d->path, "%s", name);
    d->keep = 1;
    *out = d;
    return GD_OK;
}

GD_API void gd_run_dir_keep(gd_run_dir *d) { d->keep = 1; }

GD_API gd_status gd_run_dir_open_sub(gd_run_dir *parent, const char *sub, gd_run_dir **out, gd_error *err)
{
    *out = NULL;
    char path[GD_PATH_MAX + 320];
    gd_status st = gd_run_dir_make(parent, err); /* on disk, the sub-directory is made in the parent's stage */
    if (st != GD_OK)
        return st;
    snprintf(path, sizeof path, "%s/%s", parent->disk ? parent->stage.path : parent->path, sub);
    if (parent->disk)
        st = gd_run_dir_open(path, out, err);
    else
        st = gd_run_dir_open_memory(path, out, err);
    if (st != GD_OK)
        return st;
    if (parent->keep) {
        (*out)->keep = 1;
        (*out)->parent = parent;
        snprintf((*out)->sub, sizeof (*out)->sub, "%s", sub);
    }
    return GD_OK;
}

GD_API const char *gd_run_dir_path(const gd_run_dir *d) { return d->path; }

GD_API const char *gd_run_dir_stage(const gd_run_dir *d)
{
    if (!d->disk)
        return NULL;
    return d->made && !d->published ? d->stage.path : d->path;
}

GD_API gd_status gd_run_dir_make(gd_run_dir *d, gd_error *err)
{
    if (d->made || !d->disk)
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
    while (k < RUN_DIR_MAX_OPEN && (d->open[k].fp || d->mem[k]))
        k++;
    if (k == RUN_DIR_MAX_OPEN)
        return gd_error_set(err, GD_ERR_INTERNAL, "%s/%s: more than %d files open at once", d->path, name,
                            RUN_DIR_MAX_OPEN);
    gd_status st = gd_run_dir_make(d, err);
    if (st == GD_OK && d->disk)
        st = gd_atomic_open(&d->open[k], name[0] == '.' ? d->path : d->stage.path, name, err);
    if (st != GD_OK)
        return st;
    if (d->keep) {
        d->mbuf[k] = NULL;
        d->mlen[k] = 0;
        d->mem[k] = open_memstream(&d->mbuf[k], &d->mlen[k]);
        if (!d->mem[k]) {
            gd_atomic_abort(&d->open[k]);
            return gd_error_set(err, GD_ERR_NOMEM, "%s/%s: out of memory for the file", d->path, name);
        }
    }
    snprintf(d->name[k], sizeof d->name[k], "%s", name);
    *fp = d->keep ? d->mem[k] : d->open[k].fp;
    return GD_OK;
}

static int slot_of(const gd_run_dir *d, const FILE *fp)
{
    for (int k = 0; k < RUN_DIR_MAX_OPEN; k++)
        if (fp && (d->open[k].fp == fp || d->mem[k] == fp))
            return k;
    return -1;
}

/* Drop the memory stream of slot k and its bytes. */
static void mem_abort(gd_run_dir *d, int k)
{
    if (d->mem[k])
        fclose(d->mem[k]);
    free(d->mbuf[k]);
    d->mem[k] = NULL;
    d->mbuf[k] = NULL;
    d->mlen[k] = 0;
}

/* Keep data (taken) under prefix/name. */
static gd_status keep_file(gd_run_dir *d, const char *prefix, const char *name, char *data, size_t len,
                           gd_error *err)
{
    if (d->nkept == d->capkept) {
        int cap = d->capkept ? 2 * d->capkept : 16;
        kept_file *k = realloc(d->kept, sizeof *k * (size_t)cap);
        if (!k) {
            free(data);
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
        }
        d->kept = k;
        d->capkept = cap;
    }
    size_t n = strlen(prefix) + strlen(name) + 2;
    char *full = malloc(n);
    if (!full) {
        free(data);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    }
    snprintf(full, n, "%s%s%s", prefix, prefix[0] ? "/" : "", name);
    d->kept[d->nkept++] = (kept_file){full, data, len};
    return GD_OK;
}

/* Close the memory stream of slot k, copy its bytes into the file on disk (when there is one) and
 * keep them. */
static gd_status mem_commit(gd_run_dir *d, int k, gd_error *err)
{
    int bad = fclose(d->mem[k]) != 0;
    d->mem[k] = NULL;
    char *data = d->mbuf[k];
    size_t len = d->mlen[k];
    d->mbuf[k] = NULL;
    d->mlen[k] = 0;
    if (bad) {
        free(data);
        gd_atomic_abort(&d->open[k]);
        return gd_error_set(err, GD_ERR_NOMEM, "%s/%s: out of memory for the file", d->path, d->name[k]);
    }
    if (d->open[k].fp && len && fwrite(data, 1, len, d->open[k].fp) != len) {
        free(data);
        return gd_error_set(err, GD_ERR_IO, "%s: write failed", d->open[k].path);
    }
    return keep_file(d, "", d->name[k], data, len, err);
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
    gd_status st = d->mem[k] ? mem_commit(d, k, err) : GD_OK;
    if (d->disk) {
        if (st == GD_OK)
            st = gd_atomic_commit(&d->open[k], err);
        else
            gd_atomic_abort(&d->open[k]);
    }
    if (st == GD_OK)
        st = gd_run_dir_add(d, d->name[k], err);
    return st;
}

GD_API void gd_run_dir_discard(gd_run_dir *d, FILE *fp)
{
    int k = slot_of(d, fp);
    if (k >= 0) {
        mem_abort(d, k);
        gd_atomic_abort(&d->open[k]);
    }
}

GD_API const char *gd_run_dir_data(const gd_run_dir *d, const char *name, size_t *len)
{
    for (int i = 0; i < d->nkept; i++)
        if (strcmp(d->kept[i].name, name) == 0) {
            if (len)
                *len = d->kept[i].len;
            return d->kept[i].data ? d->kept[i].data : "";
        }
    return NULL;
}

GD_API const char *const *gd_run_dir_files(const gd_run_dir *d, int *n)
{
    *n = d->nfiles;
    return d->list;
}

/* A sub-directory's kept files join its parent's, under "sub/" (taken from d). */
static gd_status keep_in_parent(gd_run_dir *d, gd_error *err)
{
    gd_status st = GD_OK;
    for (int i = 0; i < d->nkept; i++) {
        if (st == GD_OK)
            st = keep_file(d->parent, d->sub, d->kept[i].name, d->kept[i].data, d->kept[i].len, err);
        else
            free(d->kept[i].data);
        free(d->kept[i].name);
    }
    d->nkept = 0;
    return st;
}

GD_API gd_status gd_run_dir_publish(gd_run_dir *d, gd_error *err)
{
    if (d->published)
        return GD_OK;
    gd_status st = GD_OK;
    if (d->made)
        st = gd_stage_publish(&d->stage, d->list, d->nfiles, err);
    if (st == GD_OK && d->parent)
        st = keep_in_parent(d, err);
    d->published = st == GD_OK && (d->made || !d->disk);
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
    for (int k = 0; k < RUN_DIR_MAX_OPEN; k++) {
        mem_abort(d, k);
        gd_atomic_abort(&d->open[k]);
    }
    if (d->made)
        gd_stage_close(&d->stage, d->published);
    for (int i = 0; i < d->nkept; i++) {
        free(d->kept[i].name);
        free(d->kept[i].data);
    }
    free(d->kept);
    free(d);
}
