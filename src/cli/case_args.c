/* Arguments shared by `run` and `check`, and loading the case they name. */
#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int cli_parse_case_args(int argc, char **argv, cli_case_args *a, int allow_out)
{
    memset(a, 0, sizeof *a);
    a->check_only = !allow_out;
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (strcmp(s, "--set") == 0 || strcmp(s, "-s") == 0) {
            if (i + 1 >= argc || argv[i + 1][0] == '-') {  /* an assignment starts with its section */
                fprintf(stderr, "geardyn: %s needs section.key=value%s%s%s\n", s, i + 1 < argc ? " (got the option '" : "",
                        i + 1 < argc ? argv[i + 1] : "", i + 1 < argc ? "')" : "");
                return 2;
            }
            if (a->nsets == CLI_MAX_SETS) {
                fprintf(stderr, "geardyn: more than %d --set options\n", CLI_MAX_SETS);
                return 2;
            }
            a->sets[a->nsets++] = argv[++i];
        } else if (strncmp(s, "--set=", 6) == 0) {
            if (a->nsets == CLI_MAX_SETS) {
                fprintf(stderr, "geardyn: more than %d --set options\n", CLI_MAX_SETS);
                return 2;
            }
            a->sets[a->nsets++] = s + 6;
        } else if (allow_out && strcmp(s, "--out") == 0) {
            if (i + 1 >= argc || (argv[i + 1][0] == '-' && argv[i + 1][1] == '-')) {
                fprintf(stderr, "geardyn: --out needs a directory%s%s%s\n", i + 1 < argc ? " (got the option '" : "",
                        i + 1 < argc ? argv[i + 1] : "", i + 1 < argc ? "')" : "");
                return 2;
            }
            a->out_dir = argv[++i];
        } else if (allow_out && strcmp(s, "--quiet") == 0) {
            a->quiet = 1;
        } else if (allow_out && strcmp(s, "--resume") == 0) {
            a->resume = 1;
        } else if (allow_out && (strcmp(s, "--threads") == 0 || strncmp(s, "--threads=", 10) == 0)) {
            const char *v = s[9] == '=' ? s + 10 : i + 1 < argc ? argv[++i] : NULL;
            char *end = NULL;
            long t = v ? strtol(v, &end, 10) : 0;
            if (!v || !*v || *end || t < 1 || t > 4096) {
                fprintf(stderr, "geardyn: --threads needs a whole number from 1 to 4096%s%s%s\n", v ? " (got '" : "",
                        v ? v : "", v ? "')" : "");
                return 2;
            }
            a->threads = (int)t;
        } else if (s[0] == '-' && s[1] != '\0') {
            fprintf(stderr, "geardyn: unknown option '%s' (see geardyn --help)\n", s);
            return 2;
        } else if (!a->case_path) {
            a->case_path = s;
        } else {
            fprintf(stderr, "geardyn: more than one case file ('%s' and '%s')\n", a->case_path, s);
            return 2;
        }
    }
    if (!a->case_path) {
        fprintf(stderr, "geardyn: no case file given (see geardyn --help)\n");
        return 2;
    }
    return 0;
}

/* results/NAME for a case file NAME.ini */
static void default_out_dir(const char *case_path, char *out, size_t len)
{
    const char *base = strrchr(case_path, '/');
    base = base ? base + 1 : case_path;
    size_t l = strlen(base);
    if (l > 4 && strcmp(base + l - 4, ".ini") == 0)
        l -= 4;
    snprintf(out, len, "results/%.*s", (int)l, base);
}

int cli_load_case(cli_case_args *a, gd_case *c)
{
    gd_error err = {0};
    if (gd_case_init(c, &err) != GD_OK)
        return cli_fail(&err);
    if (gd_case_load(c, a->case_path, &err) != GD_OK)
        return cli_fail(&err);
    for (int i = 0; i < a->nsets; i++)
        if (gd_case_set(c, a->sets[i], i, &err) != GD_OK)
            return cli_fail(&err);
    if (a->out_dir)
        snprintf(a->dir, sizeof a->dir, "%s", a->out_dir);
    else if (c->directory[0])
        snprintf(a->dir, sizeof a->dir, "%s", c->directory);
    else
        default_out_dir(a->case_path, a->dir, sizeof a->dir);
    if (!a->check_only)
        c->stop = (gd_stop_hook){cli_should_stop, NULL}; /* the LTCA of the resolution */
    /* every check before any work (check shows the case as probed, without LTCA) */
    if (gd_case_prepare(c, a->check_only, cli_threads(a->threads), &a->cost, &err) != GD_OK)
        return cli_signal_caught() ? cli_interrupted(a->dir) : cli_fail(&err);
    if (!a->check_only && !a->quiet && a->cost.step_amplification > 1.0 + 1e-9 && c->analysis != GD_ANALYSIS_WORK_PRECISION)
        fprintf(stderr,
                "geardyn: note: solver.steps_per_period = %d is outside the stability region of the fixed-step method on "
                "the model's %.5g Hz mode (|R(h lambda)| = %.3g per step): the results will be round-off grown every "
                "step; stable from %ld steps per mesh period (docs/accuracy.md section 1)\n",
                c->steps_per_period, a->cost.step_mode_hz, a->cost.step_amplification, a->cost.stable_steps_per_period);
    return 0;
}

int cli_open_case(int argc, char **argv, int allow_out, cli_case_args *a, gd_case *c)
{
    int rc = cli_parse_case_args(argc, argv, a, allow_out);
    if (rc)
        return rc;
    rc = cli_load_case(a, c);
    if (rc)
        gd_case_free(c);
    return rc;
}

int cli_threads(int requested) { return requested > 0 ? requested : gd_threads_default(); }

void cli_print_defaulted(FILE *f, const gd_case *c, const char *prefix)
{
    size_t n, idx[256];
    const gd_keyspec *s = gd_case_schema(&n);
    size_t count = gd_case_defaulted_keys(c, idx, sizeof idx / sizeof idx[0]);
    if (count > sizeof idx / sizeof idx[0])
        count = sizeof idx / sizeof idx[0];
    if (count == 0)
        return;
    fprintf(f, "%sphysical values the case does not give, taken from the defaults:\n", prefix);
    const char *sec = NULL;
    size_t col = 0;
    for (size_t j = 0; j < count; j++) {
        const gd_keyspec *k = &s[idx[j]];
        char val[256], item[320];
        gd_case_format_value(c, idx[j], val, sizeof val);
        snprintf(item, sizeof item, "%s = %s", k->key, val);
        if (!sec || strcmp(sec, k->section) != 0) {
            if (sec)
                fputc('\n', f);
            sec = k->section;
            col = (size_t)fprintf(f, "%s  [%s] %s", prefix, sec, item);
        } else if (col + strlen(item) + 2 > 110) {
            col = (size_t)fprintf(f, ",\n%s      %s", prefix, item) - 2;
        } else {
            col += (size_t)fprintf(f, ", %s", item);
        }
    }
    fputc('\n', f);
}
