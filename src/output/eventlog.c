/* The event log: writing one CSV row per located event, and reading, filtering and
 * summarising a log for `geardyn events`. */
#include "output_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define EVENTLOG_HEADER "t_s,period,phase,clearance,kind,direction,rel_velocity_mps,x_um,recording,located"

void gd_eventlog_header(FILE *fp) { fprintf(fp, "%s\n", EVENTLOG_HEADER); }

void gd_eventlog_row(FILE *fp, const gd_model *m, const gd_event *ev, int recording)
{
    double ph = ev->t / m->period;
    ph -= floor(ph);
    fprintf(fp, "%.15g,%ld,%.9f,%s,%s,%d,%.9g,%.9g,%d,%d\n", ev->t / m->omega_n, ev->period, ph,
            m->clear[ev->clearance].name, gd_event_kind_name(ev->kind), ev->direction,
            ev->xdot * m->bc_m * m->omega_n, ev->x * m->bc_m * 1e6, recording, ev->located);
}

static int kind_index(const char *k)
{
    for (int i = 0; i < GD_EV_NKINDS; i++)
        if (strcmp(k, gd_event_kind_name(i)) == 0)
            return i;
    return -1;
}

/* The event log opened for reading if it is a regular file: a FIFO (opened without waiting for a
 * writer), a device or a directory is refused. */
static FILE *open_regular(const char *path, gd_error *err)
{
    struct stat sb;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0 || fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode)) {
        if (fd < 0)
            gd_error_set(err, GD_ERR_INPUT, "%s: cannot open event log: %s", path, strerror(errno));
        else
            gd_error_set(err, GD_ERR_INPUT, "%s: is %s, not an event log (valid: the events.csv of a run)", path,
                         S_ISDIR(sb.st_mode) ? "a directory" : "not a regular file");
        if (fd >= 0)
            close(fd);
        return NULL;
    }
    FILE *fp = fdopen(fd, "r");
    if (!fp) {
        gd_error_set(err, GD_ERR_INPUT, "%s: cannot open event log: %s", path, strerror(errno));
        close(fd);
    }
    return fp;
}

/* The clearance a filter names must be one of the log's (a misspelt name would select nothing
 * and look like a clearance without events). */
static gd_status check_filter_clearance(const char *path, const char *want, char seen[][24], int nseen,
                                        gd_error *err)
{
    char valid[16 * 26] = "";
    for (int c = 0; c < nseen; c++) {
        if (strcmp(seen[c], want) == 0)
            return GD_OK;
        size_t used = strlen(valid);
        snprintf(valid + used, sizeof valid - used, "%s%s", c ? ", " : "", seen[c]);
    }
    return gd_error_set(err, GD_ERR_INPUT, "%s: clearance '%s' is not in this event log (valid: %s)", path, want,
                        nseen ? valid : "none, the log has no events");
}

static void note_clearance(char seen[][24], int *nseen, const char *name)
{
    for (int c = 0; c < *nseen; c++)
        if (strcmp(seen[c], name) == 0)
            return;
    if (*nseen < 16)
        snprintf(seen[(*nseen)++], 24, "%s", name);
}

GD_API gd_eventlog_filter gd_eventlog_filter_all(void)
{
    return (gd_eventlog_filter){.t_from_s = -INFINITY, .t_to_s = INFINITY};
}

/* A time window that leaves the log's events outside is a usage error: say what the log holds
 * (the options' names are geardyn events'; the Python module's t_from and t_to are the same). */
static gd_status check_window(const char *path, const gd_eventlog_filter *f, const gd_eventlog_summary *sum,
                              gd_error *err)
{
    if (isinf(f->t_from_s) && isinf(f->t_to_s))
        return GD_OK;
    if (sum->rows == 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: the log holds no events, a time window selects nothing", path);
    const char *opt = f->t_from_s > sum->log_t_max_s ? "--from" : f->t_to_s < sum->log_t_min_s ? "--to" : NULL;
    if (!opt)
        return GD_OK;
    return gd_error_set(err, GD_ERR_INPUT,
                        "%s %.9g: %s the log's %s event (%s holds %ld events from t = %.9g s to %.9g s, "
                        "mesh periods %ld to %ld; valid: a window that meets them)",
                        opt, opt[2] == 'f' ? f->t_from_s : f->t_to_s, opt[2] == 'f' ? "after" : "before",
                        opt[2] == 'f' ? "last" : "first", path, sum->rows, sum->log_t_min_s, sum->log_t_max_s,
                        sum->log_period_min, sum->log_period_max);
}

GD_API gd_status gd_eventlog_summarise(const char *path, const gd_eventlog_filter *flt, FILE *out_csv,
                                       gd_eventlog_summary *sum, gd_error *err)
{
    memset(sum, 0, sizeof *sum);
    if (!(flt->t_from_s < flt->t_to_s))
        return gd_error_set(err, GD_ERR_INPUT, "--from %.9g --to %.9g selects nothing (valid: --from before --to)",
                            flt->t_from_s, flt->t_to_s);
    FILE *fp = open_regular(path, err);
    if (!fp)
        return GD_ERR_INPUT;
    char line[1024], seen[16][24];
    long lineno = 0;
    int nseen = 0;
    gd_status st = GD_OK;
    if (!fgets(line, sizeof line, fp) || strncmp(line, EVENTLOG_HEADER, strlen(EVENTLOG_HEADER)) != 0) {
        fclose(fp);
        return gd_error_set(err, GD_ERR_INPUT, "%s:1: not a geardyn event log (expected the header '%s')", path,
                            EVENTLOG_HEADER);
    }
    lineno = 1;
    if (out_csv)
        fprintf(out_csv, "%s\n", EVENTLOG_HEADER);
    sum->t_first_s = sum->log_t_min_s = INFINITY;
    sum->t_last_s = sum->log_t_max_s = -INFINITY;
    while (fgets(line, sizeof line, fp)) {
        lineno++;
        char copy[1024];
        snprintf(copy, sizeof copy, "%s", line);
        char *f[10];
        int nf = 0;
        char *save = NULL;
        for (char *tok = strtok_r(copy, ",\n", &save); tok && nf < 10; tok = strtok_r(NULL, ",\n", &save))
            f[nf++] = tok;
        if (nf != 10) {
            st = gd_error_set(err, GD_ERR_INPUT, "%s:%ld: expected 10 fields, found %d", path, lineno, nf);
            break;
        }
        char *end;
        double t = strtod(f[0], &end);
        double v = strtod(f[6], NULL);
        int kind = kind_index(f[4]);
        int rec = atoi(f[8]);
        if (*end || !isfinite(t) || kind < 0) {
            st = gd_error_set(err, GD_ERR_INPUT, "%s:%ld: malformed row", path, lineno);
            break;
        }
        long period = strtol(f[1], NULL, 10);
        if (sum->rows == 0 || t < sum->log_t_min_s) {
            sum->log_t_min_s = t;
            sum->log_period_min = period;
        }
        if (sum->rows == 0 || t > sum->log_t_max_s) {
            sum->log_t_max_s = t;
            sum->log_period_max = period;
        }
        sum->rows++;
        note_clearance(seen, &nseen, f[3]);
        if (t < flt->t_from_s || t > flt->t_to_s)
            continue;
        if (flt->clearance[0] && strcmp(flt->clearance, f[3]) != 0)
            continue;
        if (flt->kind[0] && strcmp(flt->kind, f[4]) != 0)
            continue;
        if (flt->recorded_only && !rec)
            continue;
        sum->selected++;
        if (out_csv)
            fputs(line, out_csv);
        int c;
        for (c = 0; c < sum->nclear; c++)
            if (strcmp(sum->clear_name[c], f[3]) == 0)
                break;
        if (c == sum->nclear) {
            if (sum->nclear == 16) {
                st = gd_error_set(err, GD_ERR_INPUT, "%s:%ld: more than 16 clearances", path, lineno);
                break;
            }
            snprintf(sum->clear_name[c], sizeof sum->clear_name[c], "%s", f[3]);
            sum->vmin[c] = INFINITY;
            sum->nclear++;
        }
        sum->count[c][kind]++;
        if (kind == GD_EV_CONTACT || kind == GD_EV_BACK_CONTACT) {
            double a = fabs(v);
            sum->ncontacts[c]++;
            sum->vmin[c] = fmin(sum->vmin[c], a);
            sum->vmax[c] = fmax(sum->vmax[c], a);
            sum->vsum[c] += a;
            sum->vsum2[c] += a * a;
        }
        sum->t_first_s = fmin(sum->t_first_s, t);
        sum->t_last_s = fmax(sum->t_last_s, t);
    }
    if (st == GD_OK && ferror(fp))
        st = gd_error_set(err, GD_ERR_IO, "%s: read error", path);
    fclose(fp);
    if (st == GD_OK && flt->clearance[0])
        st = check_filter_clearance(path, flt->clearance, seen, nseen, err);
    for (int c = 0; c < sum->nclear; c++)
        sum->regime[c] = sum->count[c][GD_EV_BACK_CONTACT] ? GD_IMPACT_DOUBLE
                       : sum->count[c][GD_EV_SEPARATION] ? GD_IMPACT_SINGLE : GD_IMPACT_NONE;
    if (st == GD_OK)
        st = check_window(path, flt, sum, err);
    return st;
}

GD_API gd_status gd_eventlog_select(const char *path, const gd_eventlog_filter *flt, char **csv, size_t *len,
                                    gd_eventlog_summary *sum, gd_error *err)
{
    *csv = NULL;
    *len = 0;
    gd_eventlog_filter all;
    if (!flt) {
        memset(&all, 0, sizeof all);
        all.t_from_s = -INFINITY;
        all.t_to_s = INFINITY;
        flt = &all;
    }
    gd_eventlog_summary own;
    char *buf = NULL;
    size_t n = 0;
    FILE *fp = open_memstream(&buf, &n);
    if (!fp)
        return gd_error_set(err, GD_ERR_NOMEM, "%s: out of memory for the selected events", path);
    gd_status st = gd_eventlog_summarise(path, flt, fp, sum ? sum : &own, err);
    if (fclose(fp) != 0 && st == GD_OK)
        st = gd_error_set(err, GD_ERR_NOMEM, "%s: out of memory for the selected events", path);
    if (st != GD_OK) {
        free(buf);
        return st;
    }
    *csv = buf;
    *len = n;
    return GD_OK;
}
