/* The journal of a sweep in its run directory (gd_output.h: gd_sweep_journal): DIR/.sweep.journal,
 * a header naming the sweep, then one checksummed record per finished point, appended and synced
 * to disk as the point finishes. Resuming reads it back (dropping a line torn by a kill), rewrites
 * it without the damaged lines, and the row runs only the points it lacks; once the final files
 * are published the journal is removed, so an interrupted and resumed sweep gives the same files
 * as an uninterrupted one. The command line and gd_job (the Python module) both journal through
 * this; the command line's MPI ranks send their records to rank 0, which appends them here. */
#include "geardyn/gd_output.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define JOURNAL ".sweep.journal"

struct gd_sweep_journal {
    int fd;
    char path[GD_PATH_MAX + 32];
    char *text;              /* the journal as read back or started */
    size_t tlen;
    char note[GD_PATH_MAX + 200];
    pthread_mutex_t io;
};

/* Temporary files of an earlier run killed while writing its final files. */
static void remove_stale_temporaries(const char *dir)
{
    static const char *prefixes[] = {".sweep.csv.tmp-", ".bifurcation.csv.tmp-", ".summary.json.tmp-",
                                     "." JOURNAL ".tmp-", ".bifurcation.png.tmp", ".bifurcation.svg.tmp",
                                     ".regime_map.png.tmp", ".regime_map.svg.tmp"};
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        for (size_t i = 0; i < sizeof prefixes / sizeof prefixes[0]; i++)
            if (strncmp(e->d_name, prefixes[i], strlen(prefixes[i])) == 0) {
                char path[GD_PATH_MAX + 300];
                snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
                unlink(path);
                break;
            }
    closedir(d);
}

static gd_status start(gd_sweep_journal *j, gd_run_dir *out, const gd_sweep_plan *p, gd_sweep_point *pts,
                       int resume, gd_error *err)
{
    const char *dir = gd_run_dir_path(out);
    gd_status st = gd_run_dir_make(out, err);
    if (st != GD_OK)
        return st;
    remove_stale_temporaries(dir);
    snprintf(j->path, sizeof j->path, "%s/%s", dir, JOURNAL);
    int exists = access(j->path, F_OK) == 0;
    if (resume) {
        int loaded = 0, ignored = 0;
        st = gd_sweep_journal_load(j->path, p, pts, &j->text, &j->tlen, &loaded, &ignored, err);
        if (st != GD_OK)
            return st;
        if (!exists)
            snprintf(j->note, sizeof j->note, "note: no journal in %s: the sweep starts from the beginning", dir);
        else
            snprintf(j->note, sizeof j->note, "resuming: %d of %d points already done%s", loaded, p->nslots,
                     ignored ? " (a torn or unusable journal line was dropped)" : "");
    } else {
        char header[300];
        gd_sweep_journal_header(p, header, sizeof header);
        j->tlen = strlen(header);
        j->text = malloc(j->tlen + 1);
        if (!j->text)
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
        memcpy(j->text, header, j->tlen + 1);
        if (exists)
            snprintf(j->note, sizeof j->note,
                     "note: %s held an unfinished sweep; starting over (--resume continues one)", dir);
    }
    FILE *fp;
    if ((st = gd_run_dir_create(out, JOURNAL, &fp, err)) != GD_OK)
        return st;
    if (fwrite(j->text, 1, j->tlen, fp) != j->tlen) {
        gd_run_dir_discard(out, fp);
        return gd_error_set(err, GD_ERR_IO, "%s: cannot write", j->path);
    }
    if ((st = gd_run_dir_commit(out, fp, err)) != GD_OK)
        return st;
    j->fd = open(j->path, O_WRONLY | O_APPEND | O_CLOEXEC);
    if (j->fd < 0)
        return gd_error_set(err, GD_ERR_IO, "%s: cannot open: %s", j->path, strerror(errno));
    return GD_OK;
}

GD_API gd_status gd_sweep_journal_open(gd_run_dir *out, const gd_sweep_plan *p, gd_sweep_point *pts, int resume,
                                       gd_sweep_journal **journal, gd_error *err)
{
    *journal = NULL;
    gd_sweep_journal *j = calloc(1, sizeof *j);
    if (!j)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    j->fd = -1;
    pthread_mutex_init(&j->io, NULL);
    gd_status st = start(j, out, p, pts, resume, err);
    if (st != GD_OK) {
        gd_sweep_journal_close(j, 0);
        return st;
    }
    *journal = j;
    return GD_OK;
}

GD_API gd_status gd_sweep_journal_append(gd_sweep_journal *j, const char *line, size_t len, gd_error *err)
{
    gd_status st = GD_OK;
    pthread_mutex_lock(&j->io);
    size_t off = 0;
    while (off < len && st == GD_OK) {
        ssize_t w = write(j->fd, line + off, len - off);
        if (w < 0 && errno != EINTR)
            st = gd_error_set(err, GD_ERR_IO, "%s: cannot append: %s", j->path, strerror(errno));
        else if (w > 0)
            off += (size_t)w;
    }
    if (st == GD_OK && fdatasync(j->fd) != 0 && errno != EINVAL)
        st = gd_error_set(err, GD_ERR_IO, "%s: cannot sync: %s", j->path, strerror(errno));
    pthread_mutex_unlock(&j->io);
    return st;
}

GD_API gd_status gd_sweep_journal_point(gd_sweep_journal *j, const gd_sweep_plan *p, const gd_sweep_point *pt,
                                        gd_error *err)
{
    char *line;
    size_t len;
    gd_status st = gd_sweep_record_format(p, pt, &line, &len, err);
    if (st != GD_OK)
        return st;
    st = gd_sweep_journal_append(j, line, len, err);
    free(line);
    return st;
}

GD_API const char *gd_sweep_journal_text(const gd_sweep_journal *j, size_t *len)
{
    if (len)
        *len = j->tlen;
    return j->text;
}

GD_API const char *gd_sweep_journal_note(const gd_sweep_journal *j) { return j->note; }

GD_API const char *gd_sweep_journal_path(const gd_sweep_journal *j) { return j->path; }

GD_API void gd_sweep_journal_close(gd_sweep_journal *j, int remove)
{
    if (!j)
        return;
    if (j->fd >= 0)
        close(j->fd);
    if (remove && j->path[0])
        unlink(j->path);
    pthread_mutex_destroy(&j->io);
    free(j->text);
    free(j);
}
