/* Poincare-section analysis and the motion class: the period of a sequence of stroboscopic
 * points (in the settled part of the window), the number of distinct points (relative tolerance
 * on the size of the orbit), and the class from the period and the largest Lyapunov exponent. */
#include "geardyn/gd_response.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The size of the orbit: 1 + the largest |component| of any point. */
static double orbit_scale(const double *pts, long npts, int n)
{
    double s = 0;
    for (long k = 0; k < npts * n; k++)
        s = fmax(s, fabs(pts[k]));
    return 1.0 + s;
}

/* max over components of |a_i - b_i|, over the orbit's size */
static double dist(const double *a, const double *b, double scale, int n)
{
    double d = 0;
    for (int i = 0; i < n; i++)
        d = fmax(d, fabs(a[i] - b[i]));
    return d / scale;
}

GD_API int gd_poincare_period(const double *pts, long npts, int n, double tol, int max_period)
{
    double scale = orbit_scale(pts, npts, n);
    for (int p = 1; p <= max_period; p++) {
        if (npts < 2 * p + 1)
            break;
        long k0 = npts / 2; /* the settled part: the last half, at least 2p + 1 points */
        if (npts - k0 < 2 * p + 1)
            k0 = npts - (2 * p + 1);
        int ok = 1;
        for (long k = k0; k + p < npts && ok; k++)
            if (dist(pts + k * n, pts + (k + p) * n, scale, n) > tol)
                ok = 0;
        if (ok)
            return p;
    }
    return 0;
}

GD_API int gd_poincare_distinct(const double *pts, long npts, int n, double tol)
{
    double scale = orbit_scale(pts, npts, n);
    long *rep = malloc(sizeof(long) * (size_t)(npts > 0 ? npts : 1));
    if (!rep)
        return -1;
    int nrep = 0;
    for (long k = 0; k < npts; k++) {
        int found = 0;
        for (int r = 0; r < nrep && !found; r++)
            if (dist(pts + k * n, pts + rep[r] * n, scale, n) <= tol)
                found = 1;
        if (!found)
            rep[nrep++] = k;
    }
    free(rep);
    return nrep;
}

GD_API void gd_motion_classify(int period_n, int have_mle, double mle_per_period, double threshold, char *out,
                               size_t len)
{
    if (period_n > 0)
        snprintf(out, len, "period-%d", period_n);
    else if (have_mle && isfinite(mle_per_period) && mle_per_period > threshold)
        snprintf(out, len, "chaotic");
    else if (have_mle && isfinite(mle_per_period) && fabs(mle_per_period) <= threshold)
        snprintf(out, len, "quasi-periodic");
    else
        snprintf(out, len, "not-periodic");
}
