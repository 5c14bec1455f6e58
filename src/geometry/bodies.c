/* Default masses, inertias and groove-shaft stiffness of the gear bodies from the geometry and the
 * blank (rim, web, hub; docs/model.md section 9.2). */
#include "geardyn/gd_geometry.h"
#include "geardyn/gd_case.h" /* the enum of the arrangement */

#include <math.h>

/* Mass and polar inertia of the annulus ri..ro (m) of axial length len (m), added to *m and *j. */
static void annulus(double rho, double ro, double ri, double len, double *m, double *j)
{
    *m += rho * M_PI * (ro * ro - ri * ri) * len;
    *j += 0.5 * rho * M_PI * (pow(ro, 4) - pow(ri, 4)) * len;
}

GD_API void gd_body_blank(const gd_pair *pair, const gd_geometry *g, int which, gd_blank *b)
{
    const int w = which;
    double bore = w == 0 ? pair->bore_diameter_pinion_mm : pair->bore_diameter_gear_mm;
    double rim = w == 0 ? pair->rim_inner_diameter_pinion_mm : pair->rim_inner_diameter_gear_mm;
    double web = w == 0 ? pair->web_thickness_pinion_mm : pair->web_thickness_gear_mm;
    double hub = w == 0 ? pair->hub_diameter_pinion_mm : pair->hub_diameter_gear_mm;
    double hub_len = w == 0 ? pair->hub_length_pinion_mm : pair->hub_length_gear_mm;
    int herringbone = pair->arrangement == GD_ARR_HERRINGBONE;
    b->r_bore = 0.5e-3 * bore;
    b->r_hub = hub > 0 ? 0.5e-3 * hub : b->r_bore;
    b->r_rim = rim > 0 ? 0.5e-3 * rim : b->r_hub;
    b->web = rim > 0 ? 1e-3 * web : 0.0;
    b->groove = herringbone ? 1e-3 * pair->groove_width_mm : 0.0;
    b->width = herringbone ? 2.0 * g->b[w] + b->groove : g->b[w];
    b->hub_length = hub > 0 ? (isfinite(hub_len) ? 1e-3 * hub_len : b->width) : 0.0;
}

GD_API void gd_body_of_mesh(const gd_pair *pair, const gd_geometry *g, int which, double *mass_kg, double *inertia_kgm2)
{
    /* a herringbone half carries half of the groove, the web and the hub; a single pair all of its body */
    double rho = pair->density_kg_per_m3, share = pair->arrangement == GD_ARR_HERRINGBONE ? 0.5 : 1.0;
    gd_blank b;
    gd_body_blank(pair, g, which, &b);
    double m = 0, j = 0, mw = 0, jw = 0;
    annulus(rho, g->r[which], b.r_rim, g->b[which], &m, &j);       /* the teeth and the rim under them */
    annulus(rho, g->rf[which], b.r_rim, 0.5 * b.groove, &m, &j);   /* the rim under half the groove */
    annulus(rho, b.r_rim, b.r_hub, b.web, &mw, &jw);                /* the web */
    annulus(rho, b.r_hub, b.r_bore, b.hub_length, &mw, &jw);        /* the hub */
    *mass_kg = m + share * mw;
    *inertia_kgm2 = j + share * jw;
}

GD_API double gd_groove_shaft_stiffness(const gd_pair *pair, const gd_geometry *g, int which)
{
    double rbore = 0.5e-3 * (which == 0 ? pair->bore_diameter_pinion_mm : pair->bore_diameter_gear_mm);
    double area = M_PI * (g->rf[which] * g->rf[which] - rbore * rbore);
    double len = fmax(pair->groove_width_mm * 1e-3, 1e-3); /* a groove of zero width: a 1 mm neck */
    return pair->youngs_modulus_gpa * 1e9 * area / len;
}
