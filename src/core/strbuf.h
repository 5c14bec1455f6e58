/* A string growing in memory (a gnuplot script, a journal record): gd_strbuf_printf appends to p
 * (n characters, NUL terminated); when memory runs out bad is set and nothing more is appended.
 * Start from {0}; free(p) when done. Internal: no GD_API. */
#ifndef GD_CORE_STRBUF_H
#define GD_CORE_STRBUF_H

#include <stdarg.h>
#include <stddef.h>

typedef struct gd_strbuf {
    char *p;
    size_t n, cap;
    int bad;
} gd_strbuf;

void gd_strbuf_printf(gd_strbuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void gd_strbuf_vprintf(gd_strbuf *b, const char *fmt, va_list ap) __attribute__((format(printf, 2, 0)));

#endif
