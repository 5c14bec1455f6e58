/* A string growing in memory (strbuf.h). */
#include "strbuf.h"

#include <stdio.h>
#include <stdlib.h>

void gd_strbuf_vprintf(gd_strbuf *b, const char *fmt, va_list ap)
{
    if (b->bad)
        return;
    for (;;) {
        va_list aq;
        va_copy(aq, ap);
        int k = vsnprintf(b->p ? b->p + b->n : NULL, b->p ? b->cap - b->n : 0, fmt, aq);
        va_end(aq);
        if (k < 0) {
            b->bad = 1;
            return;
        }
        if (b->p && b->n + (size_t)k < b->cap) {
            b->n += (size_t)k;
            return;
        }
        size_t cap = b->cap ? 2 * b->cap : 4096;
        while (cap < b->n + (size_t)k + 1)
            cap *= 2;
        char *q = realloc(b->p, cap);
        if (!q) {
            b->bad = 1;
            return;
        }
        b->p = q;
        b->cap = cap;
    }
}

void gd_strbuf_printf(gd_strbuf *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    gd_strbuf_vprintf(b, fmt, ap);
    va_end(ap);
}
