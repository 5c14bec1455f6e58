/* geardyn events: summarise, filter and export an event log. */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int parse_time(const char *opt, const char *s, double *v)
{
    char *end;
    *v = strtod(s, &end);
    if (*end || !isfinite(*v)) {
        fprintf(stderr, "geardyn: %s: '%s' is not a time in seconds\n", opt, s);
        return 2;
    }
    return 0;
}

/* Parse LOG [--from T] [--to T] [--clearance C] [--kind K] [--recorded] [--csv FILE]; returns 0
 * or the exit status. */
static int parse_events_args(int argc, char **argv, gd_eventlog_filter *f, const char **path, const char **csv)
{
    *f = gd_eventlog_filter_all();
    *path = NULL;
    *csv = NULL;
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        int need = strcmp(s, "--from") == 0 || strcmp(s, "--to") == 0 || strcmp(s, "--clearance") == 0 ||
                   strcmp(s, "--kind") == 0 || strcmp(s, "--csv") == 0;
        if (need && i + 1 >= argc) {
            fprintf(stderr, "geardyn: %s needs a value\n", s);
            return 2;
        }
        if (strcmp(s, "--from") == 0) {
            if (parse_time(s, argv[++i], &f->t_from_s)) return 2;
        } else if (strcmp(s, "--to") == 0) {
            if (parse_time(s, argv[++i], &f->t_to_s)) return 2;
        } else if (strcmp(s, "--clearance") == 0) {
            snprintf(f->clearance, sizeof f->clearance, "%s", argv[++i]);
        } else if (strcmp(s, "--kind") == 0) {
            const char *k = argv[++i];
            int ok = 0;
            for (int j = 0; j < GD_EV_NKINDS; j++)
                ok |= strcmp(k, gd_event_kind_name(j)) == 0;
            if (!ok) {
                fprintf(stderr, "geardyn: --kind: '%s' (valid: contact, separation, back-contact, back-separation)\n", k);
                return 2;
            }
            snprintf(f->kind, sizeof f->kind, "%s", k);
        } else if (strcmp(s, "--csv") == 0) {
            *csv = argv[++i];
        } else if (strcmp(s, "--recorded") == 0) {
            f->recorded_only = 1;
        } else if (s[0] == '-') {
            fprintf(stderr, "geardyn: unknown option '%s' (see geardyn --help)\n", s);
            return 2;
        } else if (!*path) {
            *path = s;
        } else {
            fprintf(stderr, "geardyn: more than one event log\n");
            return 2;
        }
    }
    if (!*path) {
        fprintf(stderr, "geardyn: no event log given (see geardyn --help)\n");
        return 2;
    }
    return 0;
}

/* Open the --csv file atomically through a run directory (its directory and name from the path);
 * the directory must exist: an export is one file, not a run of its own. */
static gd_status open_csv(const char *csv, gd_run_dir **d, FILE **fp, gd_error *err)
{
    char dir[1200], name[256];
    const char *slash = strrchr(csv, '/');
    if (slash) {
        snprintf(dir, sizeof dir, "%.*s", (int)(slash - csv), csv);
        snprintf(name, sizeof name, "%s", slash + 1);
        if (!dir[0])
            snprintf(dir, sizeof dir, "/");
    } else {
        snprintf(dir, sizeof dir, ".");
        snprintf(name, sizeof name, "%s", csv);
    }
    struct stat sb;
    if (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode))
        return gd_error_set(err, GD_ERR_IO, "%s: cannot create a temporary file: %s", csv,
                            strerror(stat(dir, &sb) != 0 ? errno : ENOTDIR));
    gd_status st = gd_run_dir_open(dir, d, err);
    if (st == GD_OK)
        st = gd_run_dir_create(*d, name, fp, err);
    return st;
}

/* The table of events per clearance and the impact regimes. */
static void print_summary(const char *path, const gd_eventlog_summary *sum, const char *csv)
{
    printf("event log %s: %ld events, %ld selected", path, sum->rows, sum->selected);
    if (sum->selected)
        printf(" between t = %.9g s and %.9g s", sum->t_first_s, sum->t_last_s);
    printf("\n\n%-12s %9s %11s %13s %16s   %s\n", "clearance", "contact", "separation", "back-contact",
           "back-separation", "impact velocity |v| m/s (min / mean / rms / max)");
    for (int c = 0; c < sum->nclear; c++) {
        printf("%-12s %9ld %11ld %13ld %16ld", sum->clear_name[c], sum->count[c][0], sum->count[c][1],
               sum->count[c][2], sum->count[c][3]);
        long nc = sum->ncontacts[c];
        if (nc)
            printf("   %.4g / %.4g / %.4g / %.4g", sum->vmin[c], sum->vsum[c] / nc, sqrt(sum->vsum2[c] / nc),
                   sum->vmax[c]);
        printf("\n");
    }
    int any_mesh = 0, worst = 0;
    for (int c = 0; c < sum->nclear; c++)
        if (strncmp(sum->clear_name[c], "mesh", 4) == 0) {
            if (!any_mesh)
                printf("\nimpact regime (from the selected events):\n");
            any_mesh = 1;
            printf("  %-10s %s\n", sum->clear_name[c], gd_impact_regime_name(sum->regime[c]));
            if (sum->regime[c] > worst)
                worst = sum->regime[c];
        }
    printf("%simpact regime: %s\n", any_mesh ? "  " : "\n", gd_impact_regime_name(worst));
    if (csv)
        printf("\n%ld rows written to %s\n", sum->selected, csv);
}

int cmd_events(int argc, char **argv)
{
    gd_eventlog_filter f;
    const char *path, *csv;
    int rc = parse_events_args(argc, argv, &f, &path, &csv);
    if (rc)
        return rc;
    gd_error err = {0};
    gd_eventlog_summary sum;
    gd_run_dir *d = NULL;
    FILE *fp = NULL;
    gd_status st = csv ? open_csv(csv, &d, &fp, &err) : GD_OK;
    if (st == GD_OK)
        st = gd_eventlog_summarise(path, &f, fp, &sum, &err);
    if (st == GD_OK && fp)
        st = gd_run_dir_commit(d, fp, &err);
    if (st == GD_OK && d)
        st = gd_run_dir_publish(d, &err);
    gd_run_dir_close(d);
    if (st != GD_OK)
        return cli_fail(&err);
    print_summary(path, &sum, csv);
    return 0;
}
