/* The clocks behind the timings results report (wall_s, cpu_s). Internal: no GD_API. */
#ifndef GD_CORE_CLOCK_H
#define GD_CORE_CLOCK_H

/* Seconds on CLOCK_MONOTONIC: the wall time between two calls. */
double gd_clock_wall_s(void);
/* Seconds of CPU time of the calling thread (CLOCK_THREAD_CPUTIME_ID): the cost of a
 * single-threaded run, not inflated by other load on the machine. */
double gd_clock_thread_cpu_s(void);

#endif
