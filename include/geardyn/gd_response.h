/* The `response` analysis: one operating point, a transient, a recorded window, and what
 * a user reads off it (RMS mesh acceleration, dynamic transmission error, Poincare
 * section, motion class, impact regime). */
#ifndef GD_RESPONSE_H
#define GD_RESPONSE_H

#include "geardyn/gd_modal.h"
#include "geardyn/gd_sim.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum gd_impact_regime { GD_IMPACT_NONE = 0, GD_IMPACT_SINGLE = 1, GD_IMPACT_DOUBLE = 2 } gd_impact_regime;
GD_API const char *gd_impact_regime_name(int regime);

/* One uniform time-history sample of the recorded window, physical units. */
typedef struct gd_sample {
    double t_s;
    long period;
    double lambda_um[2];     /* relative mesh displacement along the tooth normal (incl. error), L and R */
    double lambda_dot_mps[2];
    double accel_mps2[2];    /* relative mesh acceleration */
    double dte_um[2];        /* dynamic transmission error r_b1 th1 - r_b2 th2 along the transverse line of action */
    double force_n[2];       /* normal mesh force */
    const double *y;         /* dimensionless state */
} gd_sample;

typedef struct gd_response_hooks {
    int (*sample)(void *user, const gd_sample *s);
    int (*poincare)(void *user, long period, double t_s, const double *y);
    int (*event)(void *user, const gd_event *ev, int recording);
    int (*progress)(void *user, long period, long total);
} gd_response_hooks;

typedef struct gd_response_result {
    double rms_accel_mps2[3];    /* left, right, combined ((a_L + a_R)/2) */
    double dte_mean_um[2], dte_rms_um[2], dte_pp_um[2]; /* RMS about the mean */
    double lambda_min_um[2], lambda_max_um[2];
    /* the largest normal mesh force of the window's samples (as force_n of a sample), and the dynamic
     * load factor: that force over the static mesh force of the mesh (gd_model.static_load_n; ISO
     * 6336-1's K_v is its design value), NaN at zero load */
    double force_max_n[2], dynamic_load_factor[2];
    int period_n;                /* n for period-n, 0 when not periodic */
    char motion[32];             /* "period-n", "quasi-periodic", "chaotic" or "not-periodic" (gd_motion_classify) */
    int poincare_distinct;
    long poincare_count;
    int impact_regime[3];        /* left, right, combined */
    long record_events, record_events_by_kind[GD_EV_NKINDS];
    int n_lyapunov;              /* exponents computed (0: none) */
    double lyapunov[GD_MAX_STATE]; /* per unit dimensionless time, largest first */
    double mle_per_period, mle_per_s;
    double y_final[GD_MAX_STATE]; /* state and modes at the end (continuation of sweeps) */
    gd_modes md_final;
    long transient_periods;      /* mesh periods run before the window (more than run.transient_periods when
                                  * run.transient_max_periods extended it) */
    double wall_s;
    gd_sim_stats stats;
} gd_response_result;

/* The local analysis of a response ([output] response_variable): the variable's uniform samples
 * of the recorded window, its Poincare points and its amplitude spectrum (Hann window). */
typedef struct gd_local {
    int kind, index;         /* internal: which variable */
    char name[32];           /* as [output] response_variable names it */
    double *t, *x, *xd;      /* uniform samples: s, um, m/s */
    size_t n, cap;
    double *px, *pxd;        /* Poincare points: um, m/s */
    size_t np, pcap;
    double *freq_hz, *amp_um; /* the spectrum, n/2 + 1 lines */
    size_t nfreq;
    double spec_amax;        /* largest spectral amplitude */
} gd_local;

/* The result of the response row of the table of analyses (gd_analysis.h). */
typedef struct gd_response_outcome {
    gd_model model;          /* the model the case built */
    gd_modal modes;          /* its modes (gd_scene_modes; modes.failed says why there are none) */
    gd_response_result res;
    gd_local local;          /* [output] response_variable: samples, Poincare points, spectrum */
} gd_response_outcome;

/* Options that are not in the case (tests set them; the CLI uses the defaults). */
typedef struct gd_response_opts {
    double periodicity_tol;      /* relative tolerance for equal Poincare points (0: run.periodicity_tol) */
    int max_period;              /* largest n tested (default 64) */
    const double *y0;            /* initial state (NULL: from [run] initial_condition) */
    const gd_modes *md0;
} gd_response_opts;

GD_API void gd_response_opts_default(gd_response_opts *o);
GD_API gd_status gd_response_run(const gd_case *c, const gd_model *m, const gd_response_opts *opts,
                                 const gd_response_hooks *hooks, void *user, gd_response_result *res, gd_error *err);

/* Motion class from a sequence of Poincare points (npts x n, row-major). Distances are the largest
 * component difference over the size of the orbit, 1 + the largest |component| of any point (one
 * scale for every component: in the model's units positions and rates are commensurate, and the
 * integration error of a small component is a share of the whole state's). The period is the
 * smallest p <= max_period for which every two points p apart in the settled part of the window,
 * its last half (at least 2p + 1 points), are within tol: an orbit still converging at the start
 * of the window (a weakly damped mode decaying) is classed by the orbit it converges to. 0: none. */
GD_API int gd_poincare_period(const double *pts, long npts, int n, double tol, int max_period);
/* Distinct points of the whole window (within tol, the same distance). */
GD_API int gd_poincare_distinct(const double *pts, long npts, int n, double tol);
/* The motion class from the Poincare period (0: none found) and the largest Lyapunov
 * exponent per mesh period (when have_mle): period-n when the section repeats; else
 * chaotic when mle > threshold, quasi-periodic when |mle| <= threshold, and
 * not-periodic when mle < -threshold (a transient not yet died out, or a period above
 * the largest tested) or when no exponent was computed. */
GD_API void gd_motion_classify(int period_n, int have_mle, double mle_per_period, double threshold, char *out,
                               size_t len);

/* Initial state of a run: static deflection or rest. */
GD_API gd_status gd_initial_state(const gd_case *c, const gd_model *m, double *y, gd_modes *md, gd_error *err);

#ifdef __cplusplus
}
#endif
#endif
