/* ISO 6336-1 (method B) mean mesh stiffness, the default for mesh_stiffness_n_per_m. */
#include "geardyn/gd_geometry.h"

#include <math.h>

GD_API double gd_iso6336_mesh_stiffness(const gd_pair *pair, const gd_geometry *g)
{
    static const double C[9] = {0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182};
    /* ISO 6336-1 virtual numbers of teeth z_n = z / (cos^2 beta_b cos beta) (as ISO/TR 6336-30's
     * worked example gives them; z / cos^3 beta, the usual approximation, is 0.5 % stiffer here) */
    double cbn = cos(g->beta_b) * cos(g->beta_b) * cos(g->beta);
    double zn1 = g->z[0] / cbn, zn2 = g->z[1] / cbn, x1 = g->x[0], x2 = g->x[1];
    double q = C[0] + C[1] / zn1 + C[2] / zn2 + C[3] * x1 + C[4] * x1 / zn1 + C[5] * x2 + C[6] * x2 / zn2 +
               C[7] * x1 * x1 + C[8] * x2 * x2;                     /* mm um / N */
    double cth = 1.0 / q;                                          /* N / (mm um) */
    /* basic rack factor C_B = [1 + 0.5 (1.2 - h_fP/m_n)] [1 - 0.02 (20 deg - alpha_n)], with the
     * rack dedendum h_fP/m_n taken as the dedendum coefficient (0.975 for 1.25 and 20 deg) */
    double cb = (1.0 + 0.5 * (1.2 - pair->dedendum_coefficient)) * (1.0 - 0.02 * (20.0 - g->alpha_n * 180.0 / M_PI));
    /* C_M = 0.8 (solid blanks), C_R = 1; the reduction of c' below 100 N/mm line load is not
     * applied: a dynamic model needs the stiffness at every load, and a power sweep must not
     * change the pair silently (docs/model.md) */
    double cprime = cth * 0.8 * 1.0 * cb * cos(g->beta);
    double cga = cprime * (0.75 * g->eps_alpha + 0.25);
    if (g->eps_alpha < 1.2)
        cga *= 0.9;
    double k_transverse = cga * (g->b_contact * 1e3) * 1e6;          /* N/(mm um) * mm -> N/um -> N/m */
    return k_transverse / (cos(g->beta_b) * cos(g->beta_b));
}
