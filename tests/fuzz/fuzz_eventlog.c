/* libFuzzer harness: the event-log reader of `geardyn events` (gd_eventlog_summarise) on any
 * bytes, once with no filter and the selected rows copied out, once with a filter on a time
 * window, a clearance and a kind taken from the input's first byte. Every call may refuse its
 * input; none may crash, leak or read out of bounds (built with -fsanitize=fuzzer,address,
 * undefined: meson option fuzz, scripts/fuzz.sh). Seeds: tests/fuzz/eventlog/. */
#include "geardyn/geardyn.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char log_path[64];

static int write_log(const uint8_t *data, size_t size)
{
    if (!log_path[0]) {
        snprintf(log_path, sizeof log_path, "/tmp/geardyn-fuzz-events-XXXXXX");
        int fd = mkstemp(log_path);
        if (fd < 0)
            return -1;
        close(fd);
    }
    FILE *fp = fopen(log_path, "wb");
    if (!fp)
        return -1;
    size_t w = fwrite(data, 1, size, fp);
    return fclose(fp) == 0 && w == size ? 0 : -1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (write_log(data, size) != 0)
        return 0;
    static FILE *sink;
    if (!sink)
        sink = fopen("/dev/null", "w");
    gd_error err = {0};
    gd_eventlog_summary sum;
    gd_eventlog_filter all = {-INFINITY, INFINITY, "", "", 0};
    (void)gd_eventlog_summarise(log_path, &all, sink, &sum, &err);
    static const char *clear[] = {"", "mesh-L", "mesh-R", "bearing-1L"};
    static const char *kind[] = {"", "contact", "separation", "back-contact"};
    unsigned b = size ? data[0] : 0;
    gd_eventlog_filter f = {1e-4 * (b & 7), (b & 8) ? 1e-3 : INFINITY, "", "", (int)(b >> 7)};
    snprintf(f.clearance, sizeof f.clearance, "%s", clear[(b >> 4) & 3]);
    snprintf(f.kind, sizeof f.kind, "%s", kind[(b >> 2) & 3]);
    err.msg[0] = '\0';
    (void)gd_eventlog_summarise(log_path, &f, NULL, &sum, &err);
    return 0;
}
