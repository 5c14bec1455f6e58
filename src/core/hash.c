/* FNV-1a, 64 bits (src/core/hash.h). */
#include "hash.h"

#include <string.h>

uint64_t gd_fnv1a(uint64_t h, const void *data, size_t len)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < len; i++) {
        h ^= p[i];
        h *= 1099511628211ULL;
    }
    return h;
}

uint64_t gd_fnv1a_str(uint64_t h, const char *s) { return gd_fnv1a(h, s, strlen(s)); }
