/* Amplitude spectrum: Hann window and GSL's mixed-radix real FFT (any length). */
#include "geardyn/gd_spectrum.h"
#include "../core/gsl_quiet.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fft_real.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

GD_API gd_status gd_amplitude_spectrum(const double *x, size_t n, double dt, double *freq, double *amp,
                                       gd_error *err)
{
    gd_gsl_quiet(); /* GSL reports errors by return code (src/core/gsl_quiet.c) */
    if (n < 2 || !(dt > 0))
        return gd_error_set(err, GD_ERR_INPUT, "spectrum: need at least 2 samples and a positive step");
    double *w = malloc(sizeof(double) * n);
    gsl_fft_real_wavetable *tab = gsl_fft_real_wavetable_alloc(n);
    gsl_fft_real_workspace *ws = gsl_fft_real_workspace_alloc(n);
    gd_status st = GD_OK;
    if (!w || !tab || !ws) {
        st = gd_error_set(err, GD_ERR_NOMEM, "spectrum: out of memory for %zu samples", n);
        goto done;
    }
    double mean = 0, gain = 0;
    for (size_t i = 0; i < n; i++)
        mean += x[i];
    mean /= (double)n;
    for (size_t i = 0; i < n; i++) {
        double h = 0.5 - 0.5 * cos(2.0 * M_PI * (double)i / (double)n); /* periodic Hann */
        w[i] = (x[i] - mean) * h;
        gain += h;
    }
    int rc = gsl_fft_real_transform(w, 1, n, tab, ws);
    if (rc != GSL_SUCCESS) {
        st = gd_error_set(err, GD_ERR_GSL, "spectrum: gsl_fft_real_transform: %s", gsl_strerror(rc));
        goto done;
    }
    /* GSL's half-complex order: w[0] = Re X0, then (Re Xk, Im Xk) pairs, and Re X_{n/2} last
     * when n is even */
    for (size_t k = 0; k <= n / 2; k++) {
        double re, im;
        if (k == 0) {
            re = w[0];
            im = 0;
        } else if (2 * k == n) {
            re = w[n - 1];
            im = 0;
        } else {
            re = w[2 * k - 1];
            im = w[2 * k];
        }
        double a = sqrt(re * re + im * im) / gain;
        amp[k] = (k == 0 || 2 * k == n) ? a : 2.0 * a;
        freq[k] = (double)k / ((double)n * dt);
    }
done:
    free(w);
    gsl_fft_real_wavetable_free(tab);
    gsl_fft_real_workspace_free(ws);
    return st;
}
