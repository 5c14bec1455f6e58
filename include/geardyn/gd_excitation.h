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

/* The LTCA excitation of the case (its ltca_positions_per_cycle), from the cache or computed. The
 * pointer stays valid for the life of the process. */
GD_API gd_status gd_ltca_excitation_cached(const gd_case *c, const gd_ltca_excitation **out, gd_error *err);
/* How many LTCA excitations the cache has computed so far (for tests and statistics). */
GD_API long gd_ltca_cache_computations(void);

/* The mesh-in impact force of one half by energy balance (paper Eq. 15-16): the relative normal
 * velocity v_s, the equivalent mass m (kg) and the contact law F = c delta^n through the LTCA
 * secant point (delta_m, k_s delta_m): 1/2 m v^2 = c delta^(n+1)/(n+1), F_s = c delta_s^n; n = 1
 * gives F_s = v_s sqrt(m k_s). Also the duration of the pulse: the time to the largest
 * compression of the linearised contact, (pi/2) sqrt(m / k_s) (gd_model_apply_ltca caps it at a
 * quarter of the mesh period). */
GD_API void gd_impact_force(double v_s, double m, double k_s, double delta_m, double n, double *force_n,
                            double *duration_s);

#ifdef __cplusplus
}
#endif
#endif
