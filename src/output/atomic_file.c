/* Atomic output files (temporary name, fsync, rename) and output directories. */
#include "output_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A directory that cannot be, whatever the rights (a file in the way, a name too long), is bad
 * input (exit 2); a refused or failed creation is an I/O error. */
static gd_status mkdir_failed(const char *path, int e, gd_error *err)
{
    if (e == ENOTDIR || e == ENAMETOOLONG || e == EEXIST)
        return gd_error_set(err, GD_ERR_INPUT, "%s: cannot be a directory: %s (valid: a directory, or a path "
                            "where one can be created)", path, e == EEXIST ? "a file of that name exists"
                            : strerror(e));
    return gd_error_set(err, GD_ERR_IO, "%s: cannot create directory: %s", path, strerror(e));
}

/* mkdir -p; on a failure the directories this call made are removed again (deepest first), so that
 * a path that fails further on (NEW/../FILE/x) leaves nothing. */
gd_status gd_mkdir_p(const char *dir, gd_error *err)
{
    char buf[1200];
    if (strlen(dir) >= sizeof buf)
        return mkdir_failed(dir, ENAMETOOLONG, err);
    snprintf(buf, sizeof buf, "%s", dir);
    char failed[1200] = "";
    size_t made[64];
    int nmade = 0, e = 0;
    for (char *p = buf + 1;; p++) {
        if (*p && *p != '/')
            continue;
        char c = *p;
        *p = '\0';
        if (mkdir(buf, 0777) == 0) {
            if (nmade < 64)
                made[nmade++] = (size_t)(p - buf);
        } else if (errno != EEXIST) {
            e = errno;
            snprintf(failed, sizeof failed, "%s", buf);
        }
        *p = c;
        if (e || !c)
            break;
    }
    struct stat sb = {0};
    if (!e && (stat(buf, &sb) != 0 || !S_ISDIR(sb.st_mode))) {
        e = sb.st_mode ? EEXIST : errno;
        snprintf(failed, sizeof failed, "%s", buf);
    }
    if (!e)
        return GD_OK;
    for (int i = nmade - 1; i >= 0; i--) {
        buf[made[i]] = '\0';
        rmdir(buf);
    }
    return mkdir_failed(failed, e, err);
}

gd_status gd_atomic_open(gd_atomic_file *f, const char *dir, const char *name, gd_error *err)
{
    memset(f, 0, sizeof *f);
    snprintf(f->path, sizeof f->path, "%s/%s", dir, name);
    snprintf(f->tmp, sizeof f->tmp, "%s/.%s.tmp-XXXXXX", dir, name);
    int fd = mkstemp(f->tmp);
    if (fd < 0)
        return gd_error_set(err, GD_ERR_IO, "%s: cannot create a temporary file: %s", f->path, strerror(errno));
    fchmod(fd, 0644);
    f->fp = fdopen(fd, "w");
    if (!f->fp) {
        close(fd);
        unlink(f->tmp);
        return gd_error_set(err, GD_ERR_IO, "%s: fdopen: %s", f->path, strerror(errno));
    }
    return GD_OK;
}

gd_status gd_atomic_commit(gd_atomic_file *f, gd_error *err)
{
    if (!f->fp)
        return gd_error_set(err, GD_ERR_INTERNAL, "%s: not open", f->path);
    int bad = ferror(f->fp);
    bad |= fflush(f->fp) != 0;
    bad |= fsync(fileno(f->fp)) != 0;
    bad |= fclose(f->fp) != 0;
    f->fp = NULL;
    if (bad) {
        unlink(f->tmp);
        return gd_error_set(err, GD_ERR_IO, "%s: write failed: %s", f->path, strerror(errno));
    }
    if (rename(f->tmp, f->path) != 0) {
        int e = errno;
        unlink(f->tmp);
        return gd_error_set(err, GD_ERR_IO, "%s: rename failed: %s", f->path, strerror(e));
    }
    return GD_OK;
}

void gd_atomic_abort(gd_atomic_file *f)
{
    if (f->fp) {
        fclose(f->fp);
        f->fp = NULL;
        unlink(f->tmp);
    }
}
