/* Default masses, inertias and groove-shaft stiffness of the gear bodies from the geometry. */
#include "geardyn/gd_geometry.h"
#include "geardyn/gd_case.h" /* the enum of the arrangement */

#include <math.h>

GD_API void gd_body_of_mesh(const gd_pair *pair, const gd_geometry *g, int which, double *mass_kg, double *inertia_kgm2)
{
    /* a herringbone half carries half of the groove; a single pair has none */
    double rho = pair->density_kg_per_m3;
    double rbore = 0.5e-3 * (which == 0 ? pair->bore_diameter_pinion_mm : pair->bore_diameter_gear_mm);
    double r = g->r[which], rf = g->rf[which];
    double b = g->b[which];
    double half_groove = pair->arrangement == GD_ARR_HERRINGBONE ? 0.5e-3 * pair->groove_width_mm : 0.0;
    double m_teeth = rho * M_PI * (r * r - rbore * rbore) * b;
    double m_groove = rho * M_PI * (rf * rf - rbore * rbore) * half_groove;
    double i_teeth = 0.5 * rho * M_PI * (pow(r, 4) - pow(rbore, 4)) * b;
    double i_groove = 0.5 * rho * M_PI * (pow(rf, 4) - pow(rbore, 4)) * half_groove;
    *mass_kg = m_teeth + m_groove;
    *inertia_kgm2 = i_teeth + i_groove;
}

GD_API double gd_groove_shaft_stiffness(const gd_pair *pair, const gd_geometry *g, int which)
{
    double rbore = 0.5e-3 * (which == 0 ? pair->bore_diameter_pinion_mm : pair->bore_diameter_gear_mm);
    double area = M_PI * (g->rf[which] * g->rf[which] - rbore * rbore);
    double len = fmax(pair->groove_width_mm * 1e-3, 1e-3); /* a groove of zero width: a 1 mm neck */
    return pair->youngs_modulus_gpa * 1e9 * area / len;
}
