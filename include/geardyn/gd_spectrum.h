/* Amplitude spectra of uniformly sampled signals (GSL mixed-radix real FFT, Hann window). */
#ifndef GD_SPECTRUM_H
#define GD_SPECTRUM_H

#include <stddef.h>

#include "geardyn/gd_error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Single-sided amplitude spectrum of x[0..n) sampled every dt seconds, after removing the
 * mean and applying a Hann window, scaled so that a sinusoid of amplitude A on a bin reads A
 * (coherent gain corrected). freq[k] = k / (n dt), amp[k] for k = 0 .. n/2 (n/2 + 1 values;
 * both arrays sized by the caller). */
GD_API gd_status gd_amplitude_spectrum(const double *x, size_t n, double dt, double *freq, double *amp,
                                       gd_error *err);

#ifdef __cplusplus
}
#endif
#endif
