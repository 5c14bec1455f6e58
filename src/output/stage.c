/* The lock of a run's output directory, its stage and the publication of the staged set
 * (stage.h; what a reader can rely on: docs/robustness.md). */
#include "stage.h"

#include "output_internal.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <jansson.h>
#include <stdio.h> /* renameat2 (glibc 2.28, _GNU_SOURCE) */
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

/* In a stage from its creation: a tree at the stage's name holding it was never published (its
 * files are the killed run's); one without it is a previous result a killed run had swapped out. */
#define MARKER ".geardyn-unpublished"
#define STAGE_SUFFIX ".geardyn-stage"
#define LOCK_TRIES 16

static int remove_entry(const char *p, const struct stat *sb, int flag, struct FTW *f)
{
    (void)sb, (void)flag, (void)f;
    remove(p);
    return 0;
}

/* rm -r path; nothing when it is absent */
static void remove_tree(const char *path)
{
    struct stat sb;
    if (lstat(path, &sb) != 0)
        return;
    if (S_ISDIR(sb.st_mode))
        nftw(path, remove_entry, 16, FTW_DEPTH | FTW_PHYS | FTW_MOUNT); /* never into a mount */
    else
        unlink(path);
}

/* A directory stream of its own on the directory dfd (a dup would share dfd's position). */
static DIR *open_stream(int dfd)
{
    int fd = openat(dfd, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    DIR *dp = fd >= 0 ? fdopendir(fd) : NULL;
    if (!dp && fd >= 0)
        close(fd);
    return dp;
}

static int same_inode(const struct stat *a, const struct stat *b)
{
    return a->st_dev == b->st_dev && a->st_ino == b->st_ino;
}

/* Open and lock DIR (made when absent). A run that published over DIR while this one waited for
 * the lock leaves it holding the directory that was swapped out: open the path again. */
static gd_status lock_dir(gd_stage *s, gd_error *err)
{
    for (int k = 0; k < LOCK_TRIES; k++) {
        struct stat a, b;
        if (k == 0 && stat(s->dir, &a) != 0)
            s->made_dir = 1;
        gd_status st = gd_mkdir_p(s->dir, err);
        if (st != GD_OK)
            return st;
        int fd = open(s->dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        if (fd < 0)
            return gd_error_set(err, GD_ERR_IO, "%s: cannot open: %s", s->dir, strerror(errno));
        if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
            int e = errno;
            close(fd);
            if (e == EWOULDBLOCK)
                return gd_error_set(err, GD_ERR_IO, "%s: another geardyn run is writing into this directory (wait "
                                    "for it to end, or choose another --out)", s->dir);
            return gd_error_set(err, GD_ERR_IO, "%s: cannot lock: %s", s->dir, strerror(e));
        }
        if (fstat(fd, &a) == 0 && stat(s->dir, &b) == 0 && same_inode(&a, &b)) {
            s->dir_fd = fd;
            return GD_OK;
        }
        close(fd);
    }
    return gd_error_set(err, GD_ERR_IO, "%s: replaced by other runs %d times while this run tried to lock it",
                        s->dir, LOCK_TRIES);
}

/* DIR's parent and name (trailing slashes dropped, a symbolic link resolved); 0 when DIR has no
 * name of its own in a parent ("/", ".", ".."). */
static int split_dir(gd_stage *s)
{
    char buf[GD_PATH_MAX];
    struct stat sb;
    if (lstat(s->dir, &sb) == 0 && S_ISLNK(sb.st_mode)) {
        char *r = realpath(s->dir, NULL);
        if (!r || strlen(r) >= sizeof buf) {
            free(r);
            return 0;
        }
        snprintf(buf, sizeof buf, "%s", r);
        free(r);
    } else {
        snprintf(buf, sizeof buf, "%s", s->dir);
    }
    size_t n = strlen(buf);
    while (n > 1 && buf[n - 1] == '/')
        buf[--n] = '\0';
    char *slash = strrchr(buf, '/');
    const char *name = slash ? slash + 1 : buf;
    if (!name[0] || strcmp(name, ".") == 0 || strcmp(name, "..") == 0 || strlen(name) >= sizeof s->name)
        return 0;
    snprintf(s->name, sizeof s->name, "%s", name);
    if (!slash)
        snprintf(s->parent, sizeof s->parent, ".");
    else if (slash == buf)
        snprintf(s->parent, sizeof s->parent, "/");
    else
        snprintf(s->parent, sizeof s->parent, "%.*s", (int)(slash - buf), buf);
    snprintf(s->sname, sizeof s->sname, ".%s" STAGE_SUFFIX, s->name);
    return 1;
}

/* The previous result's list: the "files" of summary.json in the directory dfd (NULL: none). */
static json_t *listed_files(int dfd)
{
    int fd = openat(dfd, "summary.json", O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return NULL;
    FILE *fp = fdopen(fd, "r");
    if (!fp) {
        close(fd);
        return NULL;
    }
    json_t *root = json_loadf(fp, 0, NULL);
    fclose(fp);
    return root;
}

/* name is summary.json, one of the files root lists (a directory listed as "name/"), or a name
 * that only a run makes (the marker): it belongs to a result, not to the user. */
static int of_result(json_t *root, const char *name)
{
    if (strcmp(name, "summary.json") == 0 || strcmp(name, MARKER) == 0)
        return 1;
    size_t i, n = strlen(name);
    json_t *v;
    json_array_foreach(root ? json_object_get(root, "files") : NULL, i, v) {
        const char *f = json_string_value(v);
        if (f && strncmp(f, name, n) == 0 && (f[n] == '\0' || (f[n] == '/' && f[n + 1] == '\0')))
            return 1;
    }
    return 0;
}

static int exists_at(int dfd, const char *name)
{
    struct stat sb;
    return fstatat(dfd, name, &sb, AT_SYMLINK_NOFOLLOW) == 0;
}

/* Every entry of the tree from that is not its result's (of_result) and that to lacks is renamed
 * into to; with link, the entries that are not directories are hard-linked instead (a symbolic
 * link as itself) and directories are left. Returns how many entries could not be moved (-1: the
 * tree cannot be read): from must then be kept. */
static int carry_over(int from, int to, int link)
{
    DIR *dp = open_stream(from);
    if (!dp)
        return -1;
    json_t *root = listed_files(from);
    int failed = 0;
    struct dirent *e;
    while ((e = readdir(dp)) != NULL) {
        const char *n = e->d_name;
        if (strcmp(n, ".") == 0 || strcmp(n, "..") == 0 || of_result(root, n) || exists_at(to, n))
            continue;
        struct stat sb;
        if (!link)
            failed += renameat(from, n, to, n) != 0;
        else if (fstatat(from, n, &sb, AT_SYMLINK_NOFOLLOW) == 0 && !S_ISDIR(sb.st_mode))
            linkat(from, n, to, n, 0); /* refused (another user's file, protected_hardlinks): renamed after */
    }
    closedir(dp);
    json_decref(root);
    return failed;
}

/* The path of the stage beside DIR (".NAME.geardyn-stage" for a DIR given as "NAME"). */
static void beside_path(const gd_stage *s, char *buf, size_t n)
{
    if (strcmp(s->parent, ".") == 0)
        snprintf(buf, n, "%s", s->sname);
    else
        snprintf(buf, n, "%s/%s", s->parent, s->sname);
}

/* What a killed run left in the parent and in DIR (the lock is held: no run is using them). A
 * tree at the stage's name without the marker is the previous result a killed run had swapped
 * out: the user's entries still in it go back to DIR before it is removed. */
static void remove_stale(gd_stage *s)
{
    if (s->parent_fd >= 0) {
        int fd = openat(s->parent_fd, s->sname, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (fd >= 0) {
            int kept = !exists_at(fd, MARKER) && carry_over(fd, s->dir_fd, 0) != 0;
            close(fd);
            char p[sizeof s->path];
            beside_path(s, p, sizeof p);
            if (!kept)
                remove_tree(p);
        }
    }
    unlinkat(s->dir_fd, MARKER, 0);
    DIR *dp = open_stream(s->dir_fd);
    if (!dp)
        return;
    struct dirent *e;
    while ((e = readdir(dp)) != NULL)
        if (strncmp(e->d_name, ".staging", 8) == 0 || strncmp(e->d_name, ".plot-", 6) == 0) {
            char p[GD_PATH_MAX + 300];
            snprintf(p, sizeof p, "%s/%s", s->dir, e->d_name);
            remove_tree(p);
        }
    closedir(dp);
}

/* "" when the set can be published by an exchange beside DIR, else why not. */
static void why_not_exchange(gd_stage *s, int named)
{
    struct stat d, p, cwd;
    const char *why = NULL;
    if (!named)
        why = "it has no name of its own in a parent directory ('.', '..' or '/')";
    else if (s->parent_fd < 0)
        why = "its parent directory cannot be opened";
    else if (fstat(s->dir_fd, &d) != 0 || fstat(s->parent_fd, &p) != 0)
        why = "it cannot be examined";
    else if (d.st_dev != p.st_dev)
        why = "it is a mount point";
    else if (stat(".", &cwd) == 0 && same_inode(&d, &cwd))
        why = "it is the working directory";
    if (!why && !exists_at(s->dir_fd, "summary.json")) {
        DIR *dp = open_stream(s->dir_fd);
        struct dirent *e;
        while (dp && !why && (e = readdir(dp)) != NULL)
            if (e->d_name[0] != '.')
                why = "it holds files but no summary.json (not a geardyn result)";
        if (dp)
            closedir(dp);
    }
    snprintf(s->fallback, sizeof s->fallback, "%s", why ? why : "");
}

/* The stage beside DIR: marked unpublished before anything goes in, DIR's permissions. */
static int make_beside(gd_stage *s)
{
    if (mkdirat(s->parent_fd, s->sname, 0700) != 0) {
        snprintf(s->fallback, sizeof s->fallback, "its parent directory refuses a stage beside it (%s)",
                 strerror(errno));
        return 0;
    }
    s->stage_fd = openat(s->parent_fd, s->sname, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    int m = s->stage_fd >= 0 ? openat(s->stage_fd, MARKER, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600) : -1;
    struct stat sb;
    if (m < 0 || fstat(s->dir_fd, &sb) != 0 || fchmod(s->stage_fd, sb.st_mode & 07777) != 0) {
        snprintf(s->fallback, sizeof s->fallback, "a stage beside it cannot be prepared (%s)", strerror(errno));
        if (m >= 0)
            close(m);
        if (s->stage_fd >= 0)
            close(s->stage_fd);
        s->stage_fd = -1;
        beside_path(s, s->path, sizeof s->path);
        remove_tree(s->path);
        return 0;
    }
    close(m);
    beside_path(s, s->path, sizeof s->path);
    flock(s->stage_fd, LOCK_EX | LOCK_NB); /* new: nobody else has it; DIR after the exchange */
    return 1;
}

gd_status gd_stage_make(gd_stage *s, const char *dir, gd_error *err)
{
    memset(s, 0, sizeof *s);
    s->dir_fd = s->stage_fd = s->parent_fd = -1;
    snprintf(s->dir, sizeof s->dir, "%s", dir);
    int named = split_dir(s);
    size_t n = strlen(s->name), k = strlen(STAGE_SUFFIX);
    if (named && s->name[0] == '.' && n > k && strcmp(s->name + n - k, STAGE_SUFFIX) == 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: names ending in '%s' are the stages of other output "
                            "directories (valid: another name)", dir, STAGE_SUFFIX);
    gd_status st = lock_dir(s, err);
    if (st != GD_OK)
        return st;
    if (named)
        s->parent_fd = open(s->parent, O_PATH | O_DIRECTORY | O_CLOEXEC);
    remove_stale(s);
    why_not_exchange(s, named);
    if (!s->fallback[0] && make_beside(s))
        return GD_OK;
    snprintf(s->path, sizeof s->path, "%s/.staging", s->dir);
    if (mkdir(s->path, 0777) != 0)
        return gd_error_set(err, GD_ERR_IO, "%s: cannot create: %s", s->path, strerror(errno));
    s->stage_fd = open(s->path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (s->stage_fd < 0)
        return gd_error_set(err, GD_ERR_IO, "%s: cannot open: %s", s->path, strerror(errno));
    return GD_OK;
}

/* The previous summary.json and the files it lists that the new set lacks go first, so that DIR
 * never holds two sets under one summary.json. */
static void remove_previous(const gd_stage *s, const char *const *files, int nfiles)
{
    char p[GD_PATH_MAX + 300];
    json_t *root = listed_files(s->dir_fd);
    size_t i;
    json_t *v;
    json_array_foreach(root ? json_object_get(root, "files") : NULL, i, v) {
        const char *name = json_string_value(v);
        int keep = !name || !name[0] || name[0] == '.' || strstr(name, "..") || name[0] == '/';
        for (int j = 0; j < nfiles && !keep; j++)
            keep = strcmp(files[j], name) == 0;
        if (keep)
            continue;
        snprintf(p, sizeof p, "%s/%s", s->dir, name);
        remove_tree(p);
    }
    json_decref(root);
    unlinkat(s->dir_fd, "summary.json", 0);
}

/* Move one file (or directory, "name/") of the stage into place; a directory of the previous
 * result is first moved into the stage, which goes at the end. */
static gd_status move_into_place(const gd_stage *s, const char *name, gd_error *err)
{
    char from[sizeof s->path + 300], to[GD_PATH_MAX + 300], old[sizeof s->path + 300];
    size_t l = strlen(name);
    int isdir = l > 0 && name[l - 1] == '/', len = (int)(isdir ? l - 1 : l);
    snprintf(from, sizeof from, "%s/%.*s", s->path, len, name);
    snprintf(to, sizeof to, "%s/%.*s", s->dir, len, name);
    if (isdir) {
        snprintf(old, sizeof old, "%s/.previous-%.*s", s->path, len, name);
        rename(to, old);
    }
    if (rename(from, to) != 0)
        return gd_error_set(err, GD_ERR_IO, "%s: cannot move into place: %s", to, strerror(errno));
    return GD_OK;
}

/* The fallback, and a set without summary.json (an export): one rename per file, summary.json
 * last. A reader listing DIR meanwhile can see part of the set. */
static gd_status rename_series(const gd_stage *s, const char *const *files, int nfiles, int summary, gd_error *err)
{
    if (summary)
        remove_previous(s, files, nfiles);
    gd_status st = GD_OK;
    for (int i = 0; i < nfiles && st == GD_OK; i++)
        if (strcmp(files[i], "summary.json") != 0)
            st = move_into_place(s, files[i], err);
    if (st == GD_OK && summary)
        st = move_into_place(s, "summary.json", err);
    if (st == GD_OK)
        fsync(s->dir_fd);
    return st;
}

static void fsync_path(const char *path)
{
    int fd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        fsync(fd);
        close(fd);
    }
}

/* One step: the user's entries of DIR are hard-linked into the stage, the stage and DIR are
 * exchanged, the user's entries the links did not take (directories) follow into the new DIR,
 * and the previous tree (now at the stage's name) is removed. */
static gd_status exchange(gd_stage *s, const char *const *files, int nfiles, gd_error *err)
{
    carry_over(s->dir_fd, s->stage_fd, 1);
    fsync(s->stage_fd);
    if (renameat2(s->parent_fd, s->sname, s->parent_fd, s->name, RENAME_EXCHANGE) != 0) {
        int e = errno;
        if (e != EINVAL && e != ENOSYS && e != EXDEV && e != EBUSY && e != ENOTSUP)
            return gd_error_set(err, GD_ERR_IO, "%s: cannot exchange with its stage %s: %s", s->dir, s->path,
                                strerror(e));
        snprintf(s->fallback, sizeof s->fallback, "its filesystem cannot exchange two directories (%s)",
                 strerror(e));
        return rename_series(s, files, nfiles, 1, err);
    }
    int t = s->dir_fd; /* the new DIR is the stage's inode; the previous tree is at the stage's name */
    s->dir_fd = s->stage_fd;
    s->stage_fd = t;
    unlinkat(s->dir_fd, MARKER, 0);
    s->keep_old = carry_over(s->stage_fd, s->dir_fd, 0) != 0;
    fsync_path(s->parent);
    return GD_OK;
}

gd_status gd_stage_publish(gd_stage *s, const char *const *files, int nfiles, gd_error *err)
{
    int summary = 0;
    for (int i = 0; i < nfiles; i++)
        summary |= strcmp(files[i], "summary.json") == 0;
    gd_status st = summary && !s->fallback[0] ? exchange(s, files, nfiles, err)
                                              : rename_series(s, files, nfiles, summary, err);
    if (!s->keep_old)
        remove_tree(s->path);
    return st;
}

void gd_stage_close(gd_stage *s, int published)
{
    if (s->stage_fd >= 0 && !published)
        remove_tree(s->path);
    if (s->made_dir && !published && s->dir_fd >= 0)
        rmdir(s->dir); /* only when empty: an interrupted sweep keeps its journal */
    if (s->stage_fd >= 0)
        close(s->stage_fd);
    if (s->dir_fd >= 0)
        close(s->dir_fd); /* and the locks */
    if (s->parent_fd >= 0)
        close(s->parent_fd);
    s->stage_fd = s->dir_fd = s->parent_fd = -1;
}
