/* The clocks behind the timings results report (src/core/clock.h). */
#include "clock.h"

#include <time.h>

static double seconds(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double gd_clock_wall_s(void) { return seconds(CLOCK_MONOTONIC); }

double gd_clock_thread_cpu_s(void) { return seconds(CLOCK_THREAD_CPUTIME_ID); }
