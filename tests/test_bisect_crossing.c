/* The bisection of the gated root finding's crossing check (gd_sim_bisect_crossing, two halvings a
 * round with the points of both possible second halvings evaluated together) against the plain
 * bisection, one halving at a time, written here as the definition: p(lo) on the held side, p(hi)
 * past it, the midpoint 0.5 (lo + hi), 48 halvings. The result places the end of the step ARKODE
 * redoes to locate a contact, so it must be the same to the bit, not only close: over random
 * cubics with one sign change and with three (where the two searches could end at different
 * roots if a decision differed), steep and flat ones, held side +1 and -1, every result is
 * compared bit for bit, and the cases with three sign changes are counted (they must occur). */
#include "dynamics/sim_internal.h"
#include "tap.h"

#include <gsl/gsl_rng.h>
#include <string.h>

/* p(x) of the cubic Hermite, as sim_events.c writes it for one point */
static double hermite(double g0, double d0, double g1, double d1, double x)
{
    double h00 = (1 + 2 * x) * (1 - x) * (1 - x), h10 = x * (1 - x) * (1 - x);
    double h01 = x * x * (3 - 2 * x), h11 = x * x * (x - 1);
    return g0 * h00 + d0 * h10 + g1 * h01 + d1 * h11;
}

static double bisect_plain(double g0, double d0, double g1, double d1, double held)
{
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 48; it++) {
        double x = 0.5 * (lo + hi);
        if (hermite(g0, d0, g1, d1, x) * held < 0)
            hi = x;
        else
            lo = x;
    }
    return hi;
}

/* sign changes of p on a fine grid */
static int sign_changes(double g0, double d0, double g1, double d1)
{
    int n = 0;
    double prev = hermite(g0, d0, g1, d1, 0.0);
    for (int i = 1; i <= 1000; i++) {
        double p = hermite(g0, d0, g1, d1, i / 1000.0);
        n += (p > 0) != (prev > 0);
        prev = p;
    }
    return n;
}

int main(void)
{
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 22);
    long cases = 0, same = 0, three = 0;
    double worst = 0.0;
    for (int i = 0; i < 200000; i++) {
        double held = gsl_rng_uniform(r) < 0.5 ? 1.0 : -1.0;
        /* g0 on the held side (or on the boundary), g1 past it; rates up to 30 times the values,
         * so that p turns back and crosses three times in some */
        double scale = pow(10.0, -12.0 + 12.0 * gsl_rng_uniform(r));
        double g0 = held * scale * gsl_rng_uniform(r) * (i % 50 == 0 ? 0.0 : 1.0);
        double g1 = -held * scale * (1e-6 + gsl_rng_uniform(r));
        double d0 = scale * 30.0 * (2.0 * gsl_rng_uniform(r) - 1.0);
        double d1 = scale * 30.0 * (2.0 * gsl_rng_uniform(r) - 1.0);
        double a = gd_sim_bisect_crossing(g0, d0, g1, d1, held), b = bisect_plain(g0, d0, g1, d1, held);
        cases++;
        same += memcmp(&a, &b, sizeof a) == 0;
        if (fabs(a - b) > worst)
            worst = fabs(a - b);
        three += sign_changes(g0, d0, g1, d1) >= 3;
    }
    tap_ok(same == cases, "the two bisections give the same bits in %ld of %ld cases (largest difference %.3g)", same,
           cases, worst);
    tap_ok(three > 1000, "%ld of the cubics change sign three times in the step (> 1000)", three);
    gsl_rng_free(r);
    return tap_done();
}
