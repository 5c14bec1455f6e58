/* LTCA excitations of the dynamic model: a process-wide cache of LTCA runs keyed by their inputs,
 * and the impact force by energy balance. */
#include "geardyn/gd_excitation.h"

#include "ltca_cache.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

/* Entries kept when nobody holds them; more slots are added only while more than this many
 * excitations are held at once (each held one must stay), and the extra slots then stay. */
#define CACHE_SIZE 16

/* One cached LTCA. Filed under a 64-bit hash of its inputs, but identified by the inputs
 * themselves (gd_ltca_cache_key_bytes): two inputs whose hashes collide are not confused. refs
 * counts the references handed out and not released; only an entry with none is evicted. */
typedef struct entry {
    gd_ltca_excitation *x;
    uint64_t hash;
    unsigned char *key;
    size_t key_len;
    long refs;
    unsigned long used; /* tick of the last hand-out: the least recently used unheld entry goes */
} entry;

static pthread_mutex_t cache_lock = PTHREAD_MUTEX_INITIALIZER;
static entry *cache;
static int cache_n, cache_slots;
static unsigned long tick;
static long computations, references;
static uint64_t (*cache_hash)(const gd_pair *pair, const gd_ltca_settings *set, int npos) = gd_ltca_cache_key;

static void entry_free(entry *e)
{
    gd_ltca_excitation_free(e->x);
    free(e->x);
    free(e->key);
    memset(e, 0, sizeof *e);
}

GD_API long gd_ltca_cache_computations(void)
{
    pthread_mutex_lock(&cache_lock);
    long n = computations;
    pthread_mutex_unlock(&cache_lock);
    return n;
}

void gd_ltca_cache_set_hash(uint64_t (*hash)(const gd_pair *pair, const gd_ltca_settings *set, int npos))
{
    pthread_mutex_lock(&cache_lock);
    cache_hash = hash ? hash : gd_ltca_cache_key;
    /* entries filed under the old hash would never be found again: drop those nobody holds */
    int n = 0;
    for (int i = 0; i < cache_n; i++) {
        if (cache[i].refs == 0)
            entry_free(&cache[i]);
        else
            cache[n++] = cache[i];
    }
    cache_n = n;
    pthread_mutex_unlock(&cache_lock);
}

long gd_ltca_cache_references(void)
{
    pthread_mutex_lock(&cache_lock);
    long n = references;
    pthread_mutex_unlock(&cache_lock);
    return n;
}

int gd_ltca_cache_entries(int *slots)
{
    pthread_mutex_lock(&cache_lock);
    int n = cache_n;
    if (slots)
        *slots = cache_slots;
    pthread_mutex_unlock(&cache_lock);
    return n;
}

/* A slot for a new entry (under the lock): a free one while there are fewer than CACHE_SIZE
 * entries, else the least recently used entry nobody holds (freed), else a new slot. NULL: out of
 * memory. */
static entry *slot_for_new(void)
{
    if (cache_n >= CACHE_SIZE) {
        entry *lru = NULL;
        for (int i = 0; i < cache_n; i++)
            if (cache[i].refs == 0 && (!lru || cache[i].used < lru->used))
                lru = &cache[i];
        if (lru) {
            entry_free(lru);
            return lru;
        }
    }
    if (cache_n == cache_slots) {
        int n = cache_slots ? 2 * cache_slots : CACHE_SIZE;
        entry *grown = realloc(cache, sizeof *grown * (size_t)n);
        if (!grown)
            return NULL;
        cache = grown;
        cache_slots = n;
    }
    entry *e = &cache[cache_n++];
    memset(e, 0, sizeof *e);
    return e;
}

GD_API gd_status gd_ltca_excitation_cached(const gd_pair *pair, const gd_ltca_settings *set,
                                           const gd_ltca_excitation **out, gd_error *err)
{
    *out = NULL;
    int npos = set->positions_per_cycle;
    size_t key_len = gd_ltca_cache_key_bytes(pair, set, npos, NULL, 0);
    unsigned char *key = malloc(key_len);
    if (!key)
        return gd_error_set(err, GD_ERR_NOMEM, "LTCA cache: out of memory");
    gd_ltca_cache_key_bytes(pair, set, npos, key, key_len);
    gd_status st = GD_OK;
    pthread_mutex_lock(&cache_lock);
    uint64_t hash = cache_hash(pair, set, npos);
    for (int i = 0; i < cache_n; i++) {
        entry *e = &cache[i];
        if (e->hash == hash && e->key_len == key_len && memcmp(e->key, key, key_len) == 0) {
            e->refs++;
            references++;
            e->used = ++tick;
            *out = e->x;
            pthread_mutex_unlock(&cache_lock);
            free(key);
            return GD_OK;
        }
    }
    /* computed under the lock: threads that need the same LTCA wait for it instead of repeating it */
    gd_ltca_excitation *x = calloc(1, sizeof *x);
    if (!x) {
        st = gd_error_set(err, GD_ERR_NOMEM, "LTCA cache: out of memory");
    } else if ((st = gd_ltca_excitation_compute(pair, set, npos, x, err)) != GD_OK) {
        free(x);
        x = NULL;
        gd_error_prefix(err, "LTCA for the dynamic model");
    } else {
        entry *e = slot_for_new();
        if (!e) {
            gd_ltca_excitation_free(x);
            free(x);
            x = NULL;
            st = gd_error_set(err, GD_ERR_NOMEM, "LTCA cache: out of memory");
        } else {
            *e = (entry){.x = x, .hash = hash, .key = key, .key_len = key_len, .refs = 1, .used = ++tick};
            key = NULL; /* the entry's now */
            references++;
            computations++;
            *out = x;
        }
    }
    pthread_mutex_unlock(&cache_lock);
    free(key);
    return st;
}

GD_API void gd_ltca_excitation_release(const gd_ltca_excitation *x)
{
    if (!x)
        return;
    pthread_mutex_lock(&cache_lock);
    for (int i = 0; i < cache_n; i++)
        if (cache[i].x == x) {
            if (cache[i].refs > 0) { /* a release too many is ignored */
                cache[i].refs--;
                references--;
            }
            break;
        }
    pthread_mutex_unlock(&cache_lock);
}

GD_API void gd_impact_force(double v_s, double m, double k_s, double delta_m, double n, double *force_n,
                            double *duration_s)
{
    v_s = fabs(v_s);
    if (fabs(n - 1.0) < 1e-12 || !(delta_m > 0)) {
        *force_n = v_s * sqrt(m * k_s);
    } else {
        double c = k_s * pow(delta_m, 1.0 - n); /* F = c delta^n through (delta_m, k_s delta_m) */
        double delta_s = pow((n + 1.0) * m * v_s * v_s / (2.0 * c), 1.0 / (n + 1.0));
        *force_n = c * pow(delta_s, n);
    }
    *duration_s = 0.5 * M_PI * sqrt(m / k_s);
}
