/* The amplitude spectrum reads the amplitude of sinusoids on bins, finds their frequencies,
 * ignores the mean, and does so for lengths that are not powers of two; and on a linear gear
 * response it shows the forced amplitude at the mesh frequency (order 1). */
#include "analysis_util.h"
#include "tap.h"

#include <stdlib.h>

typedef struct acc { double *v; size_t k; } acc;

static int hook(void *u, const gd_sample *s)
{
    acc *a = u;
    a->v[a->k++] = s->lambda_um[0];
    return 0;
}

int main(void)
{
    size_t n = 3000; /* 2^3 3 5^3: mixed radix */
    double dt = 1e-4, f1 = 50 * (1.0 / (n * dt)), f2 = 137 * (1.0 / (n * dt));
    double *x = malloc(sizeof(double) * n), *fr = malloc(sizeof(double) * (n / 2 + 1)),
           *am = malloc(sizeof(double) * (n / 2 + 1));
    for (size_t i = 0; i < n; i++)
        x[i] = 7.0 + 2.5 * sin(2 * M_PI * f1 * i * dt + 0.3) + 0.4 * cos(2 * M_PI * f2 * i * dt);
    gd_error e = {0};
    tap_ok(gd_amplitude_spectrum(x, n, dt, fr, am, &e) == GD_OK, "spectrum of 3000 samples (%s)", e.msg);
    TAP_CLOSE(fr[50], f1, 1e-9, "bin 50 is at f1");
    TAP_REL(am[50], 2.5, 1e-12, "amplitude of the first sinusoid");
    TAP_REL(am[137], 0.4, 1e-12, "amplitude of the second sinusoid");
    TAP_CLOSE(am[0], 0.0, 1e-12, "the mean is removed");
    size_t kmax = 1;
    for (size_t k = 1; k <= n / 2; k++)
        if (am[k] > am[kmax])
            kmax = k;
    tap_ok(kmax == 50, "the largest line is the first sinusoid (bin %zu)", kmax);
    TAP_CLOSE(am[300], 0.0, 1e-12, "far from the lines the Hann window leaves nothing");

    /* linear gear response: the mesh deflection oscillates at the mesh frequency with the
     * closed-form amplitude |X| = e_r Omega^2 / |1 - Omega^2 + 2 i zeta Omega| */
    gd_case c;
    gd_model m;
    const char *extra[] = {"run.transient_periods=300", "run.record_periods=50", "output.samples_per_period=64",
                           "solver.rtol=1e-10", "solver.atol=1e-12", NULL};
    double Om = 0.8, zeta = 0.1, er = 0.5;
    au_ks_case(&c, &m, 0.0, zeta, 20.0, er, Om, extra);
    size_t ns = 50 * 64;
    double *lam = malloc(sizeof(double) * ns);
    acc a = {lam, 0};
    gd_response_hooks h = {0};
    h.sample = hook;
    gd_response_result r;
    if (gd_response_run(&c, &m, NULL, &h, &a, &r, &e) != GD_OK)
        au_die(&e);
    double *fr2 = malloc(sizeof(double) * (ns / 2 + 1)), *am2 = malloc(sizeof(double) * (ns / 2 + 1));
    gd_amplitude_spectrum(lam, ns, (1.0 / m.mesh_freq_hz) / 64, fr2, am2, &e);
    double X = er * Om * Om / sqrt(pow(1 - Om * Om, 2) + pow(2 * zeta * Om, 2));
    TAP_CLOSE(fr2[50], m.mesh_freq_hz, 1e-6 * m.mesh_freq_hz, "order 1 (bin 50 of 50 periods) is the mesh frequency");
    TAP_REL(am2[50], X * m.bc_m * 1e6, 1e-6, "mesh-frequency amplitude of the deflection = closed form (um)");
    TAP_CLOSE(am2[100] / am2[50], 0.0, 1e-6, "no second harmonic in a linear response");
    free(x);
    free(fr);
    free(am);
    free(lam);
    free(fr2);
    free(am2);
    gd_case_free(&c);
    return tap_done();
}

