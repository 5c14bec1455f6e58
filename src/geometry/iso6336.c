/* ISO 6336-1 (method B) mean mesh stiffness, the default for mesh_stiffness_n_per_m. */
#include "geardyn/gd_geometry.h"

#include <math.h>

GD_API void gd_iso6336_mesh_stiffness_terms(const gd_pair *pair, const gd_geometry *g, gd_iso6336_terms *t)
{
    static const double C[9] = {0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182};
    /* ISO 6336-1 virtual numbers of teeth z_n = z / (cos^2 beta_b cos beta) (as ISO/TR 6336-30's
     * worked example gives them; z / cos^3 beta, the usual approximation, is 0.5 % stiffer here) */
    double cbn = cos(g->beta_b) * cos(g->beta_b) * cos(g->beta);
    double zn1 = g->z[0] / cbn, zn2 = g->z[1] / cbn, x1 = g->x[0], x2 = g->x[1];
    t->zn[0] = zn1;
    t->zn[1] = zn2;
    t->q_prime = C[0] + C[1] / zn1 + C[2] / zn2 + C[3] * x1 + C[4] * x1 / zn1 + C[5] * x2 + C[6] * x2 / zn2 +
                 C[7] * x1 * x1 + C[8] * x2 * x2;                  /* mm um / N */
    t->c_th = 1.0 / t->q_prime;                                    /* N / (mm um) */
    /* basic rack factor C_B = [1 + 0.5 (1.2 - h_fP/m_n)] [1 - 0.02 (20 deg - alpha_n)], with the
     * rack dedendum h_fP/m_n taken as the dedendum coefficient (0.975 for 1.25 and 20 deg) */
    t->c_b = (1.0 + 0.5 * (1.2 - pair->dedendum_coefficient)) * (1.0 - 0.02 * (20.0 - g->alpha_n * 180.0 / M_PI));
    /* C_M = 0.8 (solid blanks), C_R = 1; the reduction of c' below 100 N/mm line load is not
     * applied: a dynamic model needs the stiffness at every load, and a power sweep must not
     * change the pair silently (docs/model.md) */
    t->c_m = 0.8;
    t->c_r = 1.0;
    t->cos_beta = cos(g->beta);
    t->c_prime = t->c_th * t->c_m * t->c_r * t->c_b * t->cos_beta;
    t->eps_alpha = g->eps_alpha;
    t->eps_factor = (0.75 * g->eps_alpha + 0.25) * (g->eps_alpha < 1.2 ? 0.9 : 1.0);
    t->c_gamma_alpha = t->c_prime * (0.75 * g->eps_alpha + 0.25);
    if (g->eps_alpha < 1.2)
        t->c_gamma_alpha *= 0.9;
    t->face_width_mm = g->b_contact * 1e3;
    t->cos2_beta_b = cos(g->beta_b) * cos(g->beta_b);
    double k_transverse = t->c_gamma_alpha * t->face_width_mm * 1e6; /* N/(mm um) * mm -> N/um -> N/m */
    t->k_n_per_m = k_transverse / t->cos2_beta_b;
}

GD_API double gd_iso6336_mesh_stiffness(const gd_pair *pair, const gd_geometry *g)
{
    gd_iso6336_terms t;
    gd_iso6336_mesh_stiffness_terms(pair, g, &t);
    return t.k_n_per_m;
}
