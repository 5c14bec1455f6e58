/* Running gnuplot on a script, quietly, when it is installed. */
#include "gnuplot.h"

#include <stdio.h>

#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

static int find_gnuplot(char *out, size_t len)
{
    const char *path = getenv("PATH");
    if (!path)
        path = "/usr/bin:/bin";
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", path);
    char *save = NULL;
    for (char *d = strtok_r(buf, ":", &save); d; d = strtok_r(NULL, ":", &save)) {
        snprintf(out, len, "%s/gnuplot", d);
        if (access(out, X_OK) == 0)
            return 1;
    }
    return 0;
}

int gd_gnuplot_available(void)
{
    char p[4200];
    return find_gnuplot(p, sizeof p);
}

/* The gnuplot drawing now (0: none), for gd_gnuplot_end_running. */
static volatile sig_atomic_t running = 0;

void gd_gnuplot_end_running(void)
{
    pid_t pid = running;
    if (pid > 0) {
        kill(pid, SIGKILL);
        while (waitpid(pid, NULL, 0) < 0 && errno == EINTR)
            ;
    }
}

/* Start exe with argv in dir, stdin and stdout /dev/null, stderr into logpath; the child gets
 * SIGKILL when this process ends, however it ends (a SIGKILL too): a gnuplot drawing on into the
 * stage of a run that is gone would race the next run's removal of that stage. Signals are blocked
 * across the fork, so that the pid is recorded for gd_gnuplot_end_running before a handler can
 * ask for it. -1 and errno when it cannot start; the exec's failure shows as exit status 127. */
static pid_t spawn(const char *exe, char *const argv[], const char *dir, const char *logpath)
{
    sigset_t all, old;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &old);
    pid_t parent = getpid();
    pid_t pid = fork();
    if (pid == 0) { /* async-signal-safe calls only until the exec */
        int in = open("/dev/null", O_RDONLY | O_CLOEXEC), out = open("/dev/null", O_WRONLY | O_CLOEXEC),
            log = open(logpath, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent || in < 0 || out < 0 || log < 0 ||
            dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(log, 2) < 0 || chdir(dir) != 0)
            _exit(127);
        pthread_sigmask(SIG_SETMASK, &old, NULL);
        execve(exe, argv, environ);
        _exit(127);
    }
    int e = errno;
    if (pid > 0)
        running = pid;
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    errno = e;
    return pid;
}

gd_status gd_gnuplot_run(const char *dir, const char *script, gd_error *err)
{
    char exe[4200];
    if (!find_gnuplot(exe, sizeof exe))
        return gd_error_set(err, GD_ERR_IO, "gnuplot is not installed");
    char spath[1200], logpath[1200];
    snprintf(spath, sizeof spath, "%s/.plot-XXXXXX", dir);
    int fd = mkstemp(spath);
    if (fd < 0)
        return gd_error_set(err, GD_ERR_IO, "%s: cannot write a gnuplot script: %s", dir, strerror(errno));
    size_t len = strlen(script);
    if (write(fd, script, len) != (ssize_t)len) {
        close(fd);
        unlink(spath);
        return gd_error_set(err, GD_ERR_IO, "%s: cannot write a gnuplot script", dir);
    }
    close(fd);
    snprintf(logpath, sizeof logpath, "%s.log", spath);
    char *argv[] = {exe, strrchr(spath, '/') + 1, NULL}; /* the script by its name in dir */
    pid_t pid = spawn(exe, argv, dir, logpath);
    int rc = pid < 0 ? errno : 0;
    gd_status st = GD_OK;
    if (rc != 0) {
        st = gd_error_set(err, GD_ERR_IO, "cannot start gnuplot: %s", strerror(rc));
    } else {
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
            ;
        running = 0;
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            char msg[400] = "";
            FILE *lf = fopen(logpath, "r");
            if (lf) {
                size_t n = fread(msg, 1, sizeof msg - 1, lf);
                msg[n] = '\0';
                fclose(lf);
            }
            st = gd_error_set(err, GD_ERR_IO, "gnuplot failed: %s", msg);
        }
    }
    unlink(spath);
    unlink(logpath);
    return st;
}

/* A whole picture: a PNG from its signature to its IEND chunk, an SVG to its closing tag (gnuplot
 * exits 0 after a write that failed, on a full disk, leaving a truncated file). */
static int picture_whole(const char *path, int png)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    unsigned char head[8] = {0}, tail[16] = {0};
    size_t nh = fread(head, 1, sizeof head, f);
    long size = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    size_t nt = 0;
    if (size >= 16 && fseek(f, size - 16, SEEK_SET) == 0)
        nt = fread(tail, 1, sizeof tail, f);
    fclose(f);
    if (nh != sizeof head || nt != sizeof tail)
        return 0;
    if (png)
        return memcmp(head, "\x89PNG\r\n\x1a\n", 8) == 0 &&
               memcmp(tail + 4, "\0\0\0\0IEND\xae\x42\x60\x82", 12) == 0;
    int k = (int)sizeof tail;
    while (k > 0 && (tail[k - 1] == '\n' || tail[k - 1] == '\r' || tail[k - 1] == ' '))
        k--;
    return k >= 6 && memcmp(tail + k - 6, "</svg>", 6) == 0;
}

gd_status gd_gnuplot_draw(const char *dir, const char *script, const char *const *names, int nnames, gd_error *err)
{
    static const char *ext[2] = {".png", ".svg"};
    gd_status st = gd_gnuplot_run(dir, script, err);
    for (int i = 0; i < nnames && st == GD_OK; i++)
        for (int e = 0; e < 2 && st == GD_OK; e++) {
            char tmp[1400];
            snprintf(tmp, sizeof tmp, "%s/.%s%s.tmp", dir, names[i], ext[e]);
            if (!picture_whole(tmp, e == 0))
                st = gd_error_set(err, GD_ERR_IO, "%s%s: gnuplot wrote no whole picture (a full disk?)", names[i],
                                  ext[e]);
        }
    for (int i = 0; i < nnames; i++)
        for (int e = 0; e < 2; e++) {
            char tmp[1400], fin[1400];
            snprintf(tmp, sizeof tmp, "%s/.%s%s.tmp", dir, names[i], ext[e]);
            snprintf(fin, sizeof fin, "%s/%s%s", dir, names[i], ext[e]);
            if (st == GD_OK && rename(tmp, fin) != 0)
                st = gd_error_set(err, GD_ERR_IO, "%s: cannot rename the picture", fin);
            unlink(tmp);
        }
    return st;
}

gd_status cli_gnuplot_drawer(void *user, const char *dir, const char *script, const char *const *names, int nnames,
                             gd_error *err)
{
    (void)user;
    if (!script)
        return gd_gnuplot_available() ? GD_OK
                                      : gd_error_set(err, GD_ERR_IO, "gnuplot is not installed: no pictures "
                                                                     "(apt-get install gnuplot-nox)");
    return gd_gnuplot_draw(dir, script, names, nnames, err);
}
