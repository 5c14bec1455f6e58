/* The output directory of a run: every file of a run is opened and committed here, and the names
 * committed (or added, like the pictures drawn into it) make the list that summary.json gives.
 * The directory is locked for the run (flock); the run's files are staged in DIR/.staging
 * and moved into DIR together by gd_run_dir_publish, so that a failed or interrupted run leaves
 * the previous result (docs/robustness.md). */
#include "output_internal.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <jansson.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#define RUN_DIR_MAX_FILES 64
#define RUN_DIR_MAX_OPEN 8

struct gd_run_dir {
    char path[GD_PATH_MAX];
    char stage[GD_PATH_MAX + 32];            /* path/.staging, where the run's files are written */
    int made;                                /* the directory exists, is locked and has the stage */
    int dir_fd;                              /* path, open and locked while the run lasts */
    int published;
    gd_atomic_file open[RUN_DIR_MAX_OPEN];   /* files being written */
    char name[RUN_DIR_MAX_OPEN][256];
    char files[RUN_DIR_MAX_FILES][256];      /* committed or added, in that order */
    const char *list[RUN_DIR_MAX_FILES];
    int nfiles;
};

static int remove_entry(const char *p, const struct stat *sb, int flag, struct FTW *f)
{
    (void)sb, (void)flag, (void)f;
    remove(p);
    return 0;
}

/* rm -r path (a stage, or a directory of a previous result); nothing when it is absent */
static void remove_tree(const char *path)
{
    struct stat sb;
    if (lstat(path, &sb) != 0)
        return;
    if (S_ISDIR(sb.st_mode))
        nftw(path, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
    else
        unlink(path);
}

/* What a killed run left (the lock is held: no run is writing): its stage and gnuplot scripts. */
static void remove_stale(const char *dir)
{
    DIR *dp = opendir(dir);
    if (!dp)
        return;
    struct dirent *e;
    while ((e = readdir(dp)) != NULL)
        if (strncmp(e->d_name, ".staging", 8) == 0 || strncmp(e->d_name, ".plot-", 6) == 0) {
            char p[GD_PATH_MAX + 300];
            snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
            remove_tree(p);
        }
    closedir(dp);
}

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
    d->dir_fd = -1;
    *out = d;
    return GD_OK;
}

GD_API const char *gd_run_dir_path(const gd_run_dir *d) { return d->path; }

GD_API const char *gd_run_dir_stage(const gd_run_dir *d) { return d->made ? d->stage : d->path; }

GD_API gd_status gd_run_dir_make(gd_run_dir *d, gd_error *err)
{
    if (d->made)
        return GD_OK;
    gd_status st = gd_mkdir_p(d->path, err);
    if (st != GD_OK)
        return st;
    d->dir_fd = open(d->path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (d->dir_fd < 0)
        return gd_error_set(err, GD_ERR_IO, "%s: cannot open: %s", d->path, strerror(errno));
    if (flock(d->dir_fd, LOCK_EX | LOCK_NB) != 0) {
        close(d->dir_fd);
        d->dir_fd = -1;
        return gd_error_set(err, GD_ERR_IO, "%s: another geardyn run is writing into this directory (wait for it "
                            "to end, or choose another --out)", d->path);
    }
    remove_stale(d->path);
    /* one name: the lock makes this run the only one staging here, and a fixed name keeps the
     * paths gnuplot writes into an SVG the same from run to run */
    snprintf(d->stage, sizeof d->stage, "%s/.staging", d->path);
    if (mkdir(d->stage, 0777) != 0)
        return gd_error_set(err, GD_ERR_IO, "%s: cannot create: %s", d->stage, strerror(errno));
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
        st = gd_atomic_open(&d->open[k], name[0] == '.' ? d->path : d->stage, name, err);
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

static int in_set(const gd_run_dir *d, const char *name)
{
    for (int i = 0; i < d->nfiles; i++)
        if (strcmp(d->files[i], name) == 0)
            return 1;
    return 0;
}

/* The files of the previous result (its summary.json's list) that the new set does not have go
 * first, and its summary.json with them, so that the directory never shows a mix of two sets
 * under one summary.json. */
static void remove_previous(const gd_run_dir *d)
{
    char p[GD_PATH_MAX + 300];
    snprintf(p, sizeof p, "%s/summary.json", d->path);
    json_t *root = json_load_file(p, 0, NULL);
    json_t *files = root ? json_object_get(root, "files") : NULL;
    size_t i;
    json_t *v;
    json_array_foreach(files, i, v) {
        const char *name = json_string_value(v);
        if (!name || !name[0] || name[0] == '.' || strstr(name, "..") || name[0] == '/' || in_set(d, name))
            continue;
        snprintf(p, sizeof p, "%s/%s", d->path, name);
        remove_tree(p);
    }
    json_decref(root);
    snprintf(p, sizeof p, "%s/summary.json", d->path);
    unlink(p);
}

/* Move one file (or directory, "name/") of the stage into place; a directory of the previous
 * result is first moved into the stage, which goes at the end. */
static gd_status move_into_place(gd_run_dir *d, const char *name, gd_error *err)
{
    char from[GD_PATH_MAX + 300], to[GD_PATH_MAX + 300], old[GD_PATH_MAX + 300];
    size_t l = strlen(name);
    int isdir = l > 0 && name[l - 1] == '/';
    snprintf(from, sizeof from, "%s/%.*s", d->stage, (int)(isdir ? l - 1 : l), name);
    snprintf(to, sizeof to, "%s/%.*s", d->path, (int)(isdir ? l - 1 : l), name);
    if (isdir) {
        snprintf(old, sizeof old, "%s/.previous-%.*s", d->stage, (int)(l - 1), name);
        rename(to, old);
    }
    if (rename(from, to) != 0)
        return gd_error_set(err, GD_ERR_IO, "%s: cannot move into place: %s", to, strerror(errno));
    return GD_OK;
}

GD_API gd_status gd_run_dir_publish(gd_run_dir *d, gd_error *err)
{
    if (!d->made || d->published)
        return GD_OK;
    int summary = in_set(d, "summary.json");
    if (summary)
        remove_previous(d);
    gd_status st = GD_OK;
    for (int i = 0; i < d->nfiles && st == GD_OK; i++)
        if (strcmp(d->files[i], "summary.json") != 0)
            st = move_into_place(d, d->files[i], err);
    if (st == GD_OK && summary)
        st = move_into_place(d, "summary.json", err);
    if (st == GD_OK)
        fsync(d->dir_fd);
    remove_tree(d->stage);
    d->published = st == GD_OK;
    return st;
}

GD_API void gd_run_dir_close(gd_run_dir *d)
{
    if (!d)
        return;
    for (int k = 0; k < RUN_DIR_MAX_OPEN; k++)
        gd_atomic_abort(&d->open[k]);
    if (d->made && !d->published)
        remove_tree(d->stage);
    if (d->dir_fd >= 0)
        close(d->dir_fd); /* and its lock */
    free(d);
}
