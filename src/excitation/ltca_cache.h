/* Internals of the LTCA cache (ltca_excitation.c) for the tests. */
#ifndef GD_LTCA_CACHE_H
#define GD_LTCA_CACHE_H

#include "geardyn/gd_ltca.h"

/* Replace the hash the cache files its entries under (NULL: gd_ltca_cache_key again), so that a
 * test can make every key collide and see that only the full key bytes tell entries apart. Call it
 * while no reference is held (the entries filed under the old hash are dropped). */
__attribute__((visibility("hidden"))) void gd_ltca_cache_set_hash(
    uint64_t (*hash)(const gd_pair *pair, const gd_ltca_settings *set, int npos));
/* References handed out by gd_ltca_excitation_cached and not yet released, over all entries. */
__attribute__((visibility("hidden"))) long gd_ltca_cache_references(void);
/* Entries in the cache now, and the slots it has (16, more only while more are held at once). */
__attribute__((visibility("hidden"))) int gd_ltca_cache_entries(int *slots);

#endif
