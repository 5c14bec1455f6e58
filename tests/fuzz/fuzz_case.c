/* libFuzzer harness: a case file and its --set assignments through loading, the case check, the
 * scene resolution, the analysis's own check, the model build and the run's cost estimate
 * (gd_case_load, gd_case_set, gd_case_resolve, gd_model_build, gd_run_cost_check).
 *
 * Input: the case file's bytes, then optionally a line "%%" followed by one --set assignment per
 * line. Every call may refuse its input; none may crash, leak or read out of bounds (built with
 * -fsanitize=fuzzer,address,undefined: meson option fuzz, scripts/fuzz.sh). LTCA is deferred as
 * in geardyn check (gd_case.ltca_deferred), so each input costs microseconds. */
#include "geardyn/geardyn.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char case_path[64];

/* The case part into the harness's file (gd_case_load reads a path, as the command line does). */
static int write_case(const uint8_t *data, size_t size)
{
    if (!case_path[0]) {
        snprintf(case_path, sizeof case_path, "/tmp/geardyn-fuzz-case-XXXXXX");
        int fd = mkstemp(case_path);
        if (fd < 0)
            return -1;
        close(fd);
    }
    FILE *fp = fopen(case_path, "wb");
    if (!fp)
        return -1;
    size_t w = fwrite(data, 1, size, fp);
    return fclose(fp) == 0 && w == size ? 0 : -1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char sep[] = "\n%%\n";
    size_t case_len = size;
    for (size_t i = 0; i + 4 <= size; i++)
        if (memcmp(data + i, sep, 4) == 0) {
            case_len = i + 1;
            break;
        }
    if (write_case(data, case_len) != 0)
        return 0;
    gd_error err = {0};
    gd_case c;
    if (gd_case_init(&c, &err) != GD_OK)
        return 0;
    c.ltca_deferred = 1;
    gd_status st = gd_case_load(&c, case_path, &err);
    /* the --set lines: NUL-terminated copies, at most CLI_MAX_SETS as the command line allows */
    size_t pos = case_len + 3;
    for (int k = 0; st == GD_OK && pos < size && k < 256; k++) {
        size_t end = pos;
        while (end < size && data[end] != '\n')
            end++;
        char *a = malloc(end - pos + 1);
        if (!a)
            break;
        memcpy(a, data + pos, end - pos);
        a[end - pos] = '\0';
        st = gd_case_set(&c, a, k, &err);
        free(a);
        pos = end + 1;
    }
    if (st == GD_OK)
        st = gd_case_resolve(&c, &err);
    gd_model m;
    if (st == GD_OK)
        st = gd_model_build(&c, &m, &err);
    if (st == GD_OK) {
        gd_run_cost cost;
        gd_run_cost_estimate(&c, &m, 2, &cost);
        gd_run_cost_check(&c, &m, &cost, &err);
    }
    gd_case_free(&c);
    return 0;
}
