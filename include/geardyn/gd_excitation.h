/* The excitations the dynamic model takes from LTCA (docs/ltca.md section 8, docs/model.md 8.4):
 * the mesh stiffness of each half and the mesh-in impact, computed once per distinct LTCA input
 * and kept in a process-wide cache (thread-safe), so that a sweep over speed or clearance
 * computes LTCA once. */
#ifndef GD_EXCITATION_H
#define GD_EXCITATION_H

#include "geardyn/gd_ltca.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The LTCA excitation of the pair (set->positions_per_cycle), from the cache or computed: a
 * reference the caller must give back with gd_ltca_excitation_release once it no longer reads *out
 * (the pointer stays valid until then). Entries are found by the full bytes of their inputs
 * (gd_ltca_cache_key_bytes), not by the hash alone. The cache keeps 16 excitations nobody holds
 * (the least recently used goes first) and never frees a held one: while more are held at once it
 * grows. On failure *out is NULL and there is nothing to release. */
GD_API gd_status gd_ltca_excitation_cached(const gd_pair *pair, const gd_ltca_settings *set,
                                           const gd_ltca_excitation **out, gd_error *err);
/* Give back a reference from gd_ltca_excitation_cached (NULL: nothing). The excitation stays
 * cached for the next caller with the same inputs until the cache needs its slot. */
GD_API void gd_ltca_excitation_release(const gd_ltca_excitation *x);
/* How many LTCA excitations the cache has computed so far (for tests and statistics). */
GD_API long gd_ltca_cache_computations(void);

/* The mesh-in impact force of one half by energy balance (paper Eq. 15-16): the relative normal
 * velocity v_s, the equivalent mass m (kg; the normal equivalent mass m_n of a half, as v_s is
 * along the normal) and the contact law F = c delta^n through the LTCA secant point (delta_m,
 * k_s delta_m): 1/2 m v^2 = c delta^(n+1)/(n+1), F_s = c delta_s^n; n = 1 gives
 * F_s = v_s sqrt(m k_s). Also the rise time: the time to the largest compression of the
 * linearised contact, (pi/2) sqrt(m / k_s) (the paper's form of the pulse lasts it, at most a
 * quarter of the mesh period; the contact form lasts m v_s / F_s: docs/model.md section 8.4). */
GD_API void gd_impact_force(double v_s, double m, double k_s, double delta_m, double n, double *force_n,
                            double *duration_s);

#ifdef __cplusplus
}
#endif
#endif
