/* LTCA excitations of the dynamic model: a process-wide cache of LTCA runs keyed by their inputs,
 * and the impact force by energy balance. */
#include "geardyn/gd_excitation.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#define CACHE_SIZE 16

static pthread_mutex_t cache_lock = PTHREAD_MUTEX_INITIALIZER;
static gd_ltca_excitation *cache[CACHE_SIZE];
static int cache_next;
static long computations;

GD_API long gd_ltca_cache_computations(void)
{
    pthread_mutex_lock(&cache_lock);
    long n = computations;
    pthread_mutex_unlock(&cache_lock);
    return n;
}

GD_API gd_status gd_ltca_excitation_cached(const gd_case *c, const gd_ltca_excitation **out, gd_error *err)
{
    uint64_t key = gd_ltca_cache_key(c, c->ltca_positions_per_cycle);
    gd_status st = GD_OK;
    pthread_mutex_lock(&cache_lock);
    for (int i = 0; i < CACHE_SIZE; i++)
        if (cache[i] && cache[i]->key == key) {
            *out = cache[i];
            pthread_mutex_unlock(&cache_lock);
            return GD_OK;
        }
    /* computed under the lock: threads that need the same LTCA wait for it instead of repeating it */
    gd_ltca_excitation *x = calloc(1, sizeof *x);
    if (!x) {
        st = gd_error_set(err, GD_ERR_NOMEM, "LTCA cache: out of memory");
    } else if ((st = gd_ltca_excitation_compute(c, c->ltca_positions_per_cycle, x, err)) != GD_OK) {
        free(x);
        gd_error_prefix(err, "LTCA for the dynamic model");
    } else {
        /* entries are never freed while the process runs (pointers handed out stay valid); the
         * ring overwrites the oldest only when all slots are taken */
        if (cache[cache_next]) {
            gd_ltca_excitation_free(cache[cache_next]);
            free(cache[cache_next]);
        }
        cache[cache_next] = x;
        cache_next = (cache_next + 1) % CACHE_SIZE;
        computations++;
        *out = x;
    }
    pthread_mutex_unlock(&cache_lock);
    return st;
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
