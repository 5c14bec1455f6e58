/* A run for a program that cannot fill gd_run_env (include/geardyn/gd_job.h): the hooks of the
 * environment count the progress and ask one stop flag, and the run directory keeps its files. */
#include "rows.h"
#include "geardyn/gd_job.h"

#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

struct gd_job {
    gd_case c;
    char dir[GD_PATH_MAX];
    int disk;
    int threads;
    int ran;
    atomic_int stop;
    atomic_long done, total;
    _Atomic(const char *) unit;
    gd_run_dir *out;          /* after a successful run: its files */
    gd_draw_fn draw;          /* the caller's drawer of the pictures (NULL: none) */
    void *draw_user;
    char *notes;              /* the run's notes, one a line */
    int resume;               /* a sweep: continue the journal of an interrupted one */
    gd_sweep_journal *journal; /* a sweep's, in a directory on disk */
    size_t nnotes_len;
};

static void count(gd_job *j, const char *unit, long done, long total)
{
    atomic_store(&j->unit, unit);
    atomic_store(&j->total, total);
    atomic_store(&j->done, done);
}

static int should_stop(void *user)
{
    gd_job *j = user;
    return atomic_load(&j->stop);
}

static int on_progress(void *user, long done, long total)
{
    count(user, "mesh periods", done, total);
    return should_stop(user);
}

static void on_note(void *user, int kind, const char *text);

/* A sweep into a directory keeps the journal geardyn run keeps (resumed with j->resume); its note
 * joins the run's notes ("note: " of geardyn run's line off). */
static gd_status on_sweep_start(void *user, const gd_sweep_plan *p, gd_sweep_point *pts, gd_run_dir *out,
                                gd_error *err)
{
    gd_job *j = user;
    if (j->disk) {
        gd_status st = gd_sweep_journal_open(out, p, pts, j->resume, &j->journal, err);
        if (st != GD_OK)
            return st;
        const char *note = gd_sweep_journal_note(j->journal);
        if (note[0])
            on_note(j, 0, strncmp(note, "note: ", 6) == 0 ? note + 6 : note);
    }
    count(user, "points", p->nslots - gd_sweep_pending(p, pts), p->nslots);
    return GD_OK;
}

static gd_status on_sweep_point(void *user, const gd_sweep_plan *p, const gd_sweep_point *pt, gd_error *err)
{
    gd_job *j = user;
    gd_status st = j->journal ? gd_sweep_journal_point(j->journal, p, pt, err) : GD_OK;
    if (st == GD_OK)
        atomic_fetch_add(&j->done, 1);
    return st;
}

static int on_wp_start(void *user, const char *what, const char *label, int index, int total)
{
    (void)label;
    count(user, what, index, total);
    return should_stop(user);
}

static int on_wp_done(void *user, const char *what, const gd_wp_run *run, const gd_wp_result *res)
{
    (void)what, (void)run, (void)res;
    gd_job *j = user;
    atomic_fetch_add(&j->done, 1);
    return should_stop(user);
}

static void on_optimize_run(void *user, int run, int runs, unsigned long seed, const gd_opt_result *r)
{
    (void)seed, (void)r;
    count(user, "runs", run + 1, runs);
}

static int on_branch(void *user, int done, int planned)
{
    count(user, "branches", done, planned);
    return should_stop(user);
}

static int on_basins(void *user, long done, long total)
{
    count(user, "initial states", done, total);
    return should_stop(user);
}

static void on_problem(void *user, const struct gd_compare_entry *q, const gd_opt_compare_settings *s)
{
    (void)q, (void)s;
    gd_job *j = user;
    atomic_store(&j->unit, "problems");
    atomic_fetch_add(&j->done, 1);
}

static gd_status on_draw(void *user, const char *dir, const char *script, const char *const *names, int nnames,
                         gd_error *err)
{
    gd_job *j = user;
    return j->draw(j->draw_user, dir, script, names, nnames, err);
}

/* A note joins the run's notes (a note already there is not repeated: an analysis run inside
 * another, optimize's optimum, may say the same). */
static void on_note(void *user, int kind, const char *text)
{
    (void)kind;
    gd_job *j = user;
    char line[GD_ERROR_MSG_MAX + 256];
    snprintf(line, sizeof line, "%s", text); /* one line: a newline of gnuplot's message as a space, none at the end */
    size_t n = strlen(line);
    while (n > 0 && (line[n - 1] == '\n' || line[n - 1] == ' '))
        line[--n] = '\0';
    for (char *c = line; *c; c++)
        if (*c == '\n')
            *c = ' ';
    text = line;
    for (const char *p = j->notes; p && *p;) {
        const char *e = strchr(p, '\n');
        if ((size_t)(e - p) == n && memcmp(p, text, n) == 0)
            return;
        p = e + 1;
    }
    char *q = realloc(j->notes, j->nnotes_len + n + 2);
    if (!q)
        return; /* a note lost for want of memory loses nothing of the run */
    memcpy(q + j->nnotes_len, text, n);
    j->nnotes_len += n;
    q[j->nnotes_len++] = '\n';
    q[j->nnotes_len] = '\0';
    j->notes = q;
}

GD_API gd_status gd_job_new(const gd_case *c, const char *dir, int threads, gd_job **job, gd_error *err)
{
    *job = NULL;
    if (dir && strlen(dir) >= GD_PATH_MAX)
        return gd_error_set(err, GD_ERR_INPUT, "%s: output directory path too long (valid: < %d characters)", dir,
                            GD_PATH_MAX);
    gd_job *j = calloc(1, sizeof *j);
    if (!j)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    gd_status st = gd_case_copy(&j->c, c, err);
    if (st != GD_OK) {
        free(j);
        return st;
    }
    if (dir) {
        snprintf(j->dir, sizeof j->dir, "%s", dir);
        j->disk = 1;
    }
    j->threads = threads;
    atomic_init(&j->stop, 0);
    atomic_init(&j->done, 0);
    atomic_init(&j->total, 0);
    atomic_init(&j->unit, "");
    *job = j;
    return GD_OK;
}

GD_API gd_status gd_job_run(gd_job *j, gd_error *err)
{
    if (j->ran)
        return gd_error_set(err, GD_ERR_INTERNAL, "a job runs once");
    j->ran = 1;
    if (atomic_load(&j->stop))
        return gd_error_set(err, GD_ERR_INTERRUPTED, "stopped before the run");
    j->c.stop = (gd_stop_hook){should_stop, j}; /* the LTCA of the resolution */
    gd_status st = gd_case_prepare(&j->c, 0, j->threads, NULL, err);
    if (st != GD_OK)
        return st;
    const gd_analysis_type *a = gd_analysis_find(j->c.analysis); /* gd_case_resolve refused a case without one */
    gd_run_dir *out = NULL;
    st = j->disk ? gd_run_dir_open(j->dir, &out, err) : gd_run_dir_open_memory("(memory)", &out, err);
    if (st != GD_OK)
        return st;
    gd_run_dir_keep(out);
    gd_run_env env = {0};
    env.user = j;
    env.threads = j->threads;
    env.progress = on_progress;
    env.should_stop = should_stop;
    env.sweep_start = on_sweep_start;
    env.sweep_point = on_sweep_point;
    env.workprec.start = on_wp_start;
    env.workprec.done = on_wp_done;
    env.optimize_run = on_optimize_run;
    env.continuation_branch = on_branch;
    env.compare_problem = on_problem;
    env.basins_progress = on_basins;
    env.draw = j->draw ? on_draw : NULL;
    env.note = on_note;
    st = gd_analysis_run_dir(a, &j->c, &env, out, err);
    gd_sweep_journal_close(j->journal, st == GD_OK); /* kept for a resume unless the files are published */
    j->journal = NULL;
    if (st != GD_OK) {
        gd_run_dir_close(out);
        return st;
    }
    j->out = out;
    return GD_OK;
}

GD_API void gd_job_set_draw(gd_job *j, gd_draw_fn draw, void *user)
{
    j->draw = draw;
    j->draw_user = user;
}

GD_API void gd_job_set_resume(gd_job *j, int resume) { j->resume = resume; }

GD_API const char *gd_job_notes(const gd_job *j) { return j->notes ? j->notes : ""; }

GD_API void gd_job_stop(gd_job *j) { atomic_store(&j->stop, 1); }

GD_API const char *gd_job_progress(const gd_job *j, long *done, long *total)
{
    gd_job *m = (gd_job *)j; /* atomics are read through a non-const pointer */
    if (done)
        *done = atomic_load(&m->done);
    if (total)
        *total = atomic_load(&m->total);
    return atomic_load(&m->unit);
}

GD_API const char *gd_job_file(const gd_job *j, const char *name, size_t *len)
{
    return j->out ? gd_run_dir_data(j->out, name, len) : NULL;
}

GD_API void gd_job_free(gd_job *j)
{
    if (!j)
        return;
    gd_run_dir_close(j->out);
    gd_case_free(&j->c);
    free(j->notes);
    free(j);
}
