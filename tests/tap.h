/* Minimal TAP output for meson (protocol: 'tap'): one line per check with the value,
 * the expected value and the tolerance, in the manner of GSL's test/results.c. */
#ifndef GD_TAP_H
#define GD_TAP_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

static int tap_n = 0, tap_failed = 0;

static inline void tap_ok(int ok, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static inline void tap_ok(int ok, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    printf("%s %d - ", ok ? "ok" : "not ok", ++tap_n);
    vprintf(fmt, ap);
    printf("\n");
    va_end(ap);
    if (!ok)
        tap_failed++;
    fflush(stdout);
}

/* |value - expected| <= tol (absolute) */
#define TAP_CLOSE(value, expected, tol, name)                                                                      \
    do {                                                                                                           \
        double v_ = (value), e_ = (expected), t_ = (tol);                                                          \
        tap_ok(isfinite(v_) && fabs(v_ - e_) <= t_, "%s: %.15g vs %.15g (|diff| %.3g, tol %.3g)", name, v_, e_,     \
               fabs(v_ - e_), t_);                                                                                 \
    } while (0)

/* |value - expected| <= rtol |expected| */
#define TAP_REL(value, expected, rtol, name)                                                                       \
    do {                                                                                                           \
        double v_ = (value), e_ = (expected), t_ = (rtol);                                                         \
        double r_ = fabs(v_ - e_) / fmax(fabs(e_), 1e-300);                                                        \
        tap_ok(isfinite(v_) && r_ <= t_, "%s: %.15g vs %.15g (rel %.3g, tol %.3g)", name, v_, e_, r_, t_);         \
    } while (0)

static inline int tap_done(void)
{
    printf("1..%d\n", tap_n);
    return tap_failed ? 1 : 0;
}

#endif
