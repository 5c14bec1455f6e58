/* FNV-1a, 64 bits: the fingerprints that name a computation (the sweep journal's, the LTCA
 * cache key). Values are part of files on disk: a change invalidates every stored journal and
 * cache entry. Internal: no GD_API. */
#ifndef GD_CORE_HASH_H
#define GD_CORE_HASH_H

#include <stddef.h>
#include <stdint.h>

#define GD_FNV1A_OFFSET_BASIS 14695981039346656037ULL

/* h folded with len bytes of data; start from GD_FNV1A_OFFSET_BASIS. */
uint64_t gd_fnv1a(uint64_t h, const void *data, size_t len);
/* The same over the characters of a string (without its terminating NUL). */
uint64_t gd_fnv1a_str(uint64_t h, const char *s);

#endif
