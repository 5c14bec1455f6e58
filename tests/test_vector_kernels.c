/* geardyn's serial vector kernels (src/dynamics/compat/vector_kernels.c) give the same bits as SUNDIALS'
 * own serial kernels, operation by operation and on whole runs.
 *
 * 1. Every overridden operation on seeded random data, for every special case the library
 *    takes (coefficients +1, -1, 0, a = b, a = -b, general) and every aliasing of the output
 *    with an input: the result of a vector with geardyn's table and of a vector with the
 *    library's is compared with memcmp. These cases differ in rounding (c (x + y) is not
 *    c x + c y) or in the data they read (an output that is also a later input), so a kernel
 *    that takes a different path fails here.
 * 2. Whole runs of the bta model through gd_sim (ERK orders 5 and 8 with located events, the
 *    tangent vectors of the Lyapunov exponents, fixed-step RK4, DIRK with its Newton solves):
 *    with solver.vector_kernels = sundials and = geardyn the period-end states, the exponents
 *    and every counter (steps, RHS evaluations, events) are identical. */
#include "geardyn/geardyn.h"
#include "tap.h"
#include "dynamics/compat/sundials_compat.h"
#include "dynamics/compat/vector_kernels.h"

#include <gsl/gsl_rng.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_context.h>

static gsl_rng *rng;

static void fill(N_Vector v, int with_zeros)
{
    double *d = N_VGetArrayPointer(v);
    for (sunindextype i = 0; i < N_VGetLength(v); i++) {
        double u = gsl_rng_uniform(rng);
        d[i] = (u - 0.5) * pow(10.0, 6.0 * gsl_rng_uniform(rng) - 3.0);
        if (with_zeros && u < 0.1)
            d[i] = 0.0;
    }
}

/* the pair of vectors for one comparison: library's table (lib) and geardyn's (gd) */
#define NV 10
typedef struct {
    N_Vector lib[NV], gd[NV];
    int n;
} vset;

static void vset_new(vset *s, int n, SUNContext ctx)
{
    s->n = n;
    for (int i = 0; i < NV; i++) {
        s->lib[i] = N_VNew_Serial(n, ctx);
        s->gd[i] = N_VNew_Serial(n, ctx);
        N_VEnableFusedOps_Serial(s->lib[i], SUNTRUE);
        N_VEnableFusedOps_Serial(s->gd[i], SUNTRUE);
        if (gd_vector_use_compiled_ops(s->gd[i]) != 0)
            tap_ok(0, "gd_vector_use_compiled_ops refused a serial vector");
    }
}

static void vset_free(vset *s)
{
    for (int i = 0; i < NV; i++) {
        N_VDestroy(s->lib[i]);
        N_VDestroy(s->gd[i]);
    }
}

/* fresh random contents, the same in both sets */
static void vset_fill(vset *s)
{
    for (int i = 0; i < NV; i++) {
        fill(s->lib[i], i % 3 == 2);
        memcpy(N_VGetArrayPointer(s->gd[i]), N_VGetArrayPointer(s->lib[i]), sizeof(double) * (size_t)s->n);
    }
}

static int vset_same(const vset *s)
{
    for (int i = 0; i < NV; i++)
        if (memcmp(N_VGetArrayPointer(s->lib[i]), N_VGetArrayPointer(s->gd[i]), sizeof(double) * (size_t)s->n))
            return 0;
    return 1;
}

static int same_double(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

static const double coef[] = {1.0, -1.0, 0.0, 0.7, -0.7, 1.3, 2.5e-3};
#define NCOEF ((int)(sizeof coef / sizeof coef[0]))

static void op_by_op(SUNContext ctx, const char *width)
{
    /* up to 20: each number of four-wide blocks with 0 to 3 single elements (the short sum in one
     * pass); 40 and 57: the 20-, 16- and 4-wide blocks and single elements */
    const int lens[] = {1, 2, 3, 4, 7, 8, 12, 15, 16, 19, 20, 40, 57};
    int bad[16] = {0}, count[16] = {0};
    const char *names[16] = {"linearsum", "scale", "linearcombination", "scaleaddmulti", "const", "prod", "div",
                             "abs", "inv", "addconst", "dotprod", "maxnorm", "wrmsnorm", "wsqrsumlocal", "min"};
    for (int li = 0; li < (int)(sizeof lens / sizeof lens[0]); li++) {
        vset s;
        vset_new(&s, lens[li], ctx);
        /* linear sum: every coefficient pair, output distinct, = x, = y */
        for (int ia = 0; ia < NCOEF; ia++)
            for (int ib = 0; ib < NCOEF; ib++)
                for (int al = 0; al < 3; al++) {
                    vset_fill(&s);
                    for (int k = 0; k < 2; k++) {
                        N_Vector *v = k ? s.gd : s.lib;
                        N_Vector z = al == 0 ? v[2] : al == 1 ? v[0] : v[1];
                        N_VLinearSum(coef[ia], v[0], coef[ib], v[1], z);
                    }
                    bad[0] += !vset_same(&s), count[0]++;
                    vset_fill(&s); /* a = b and a = -b with a general value */
                    for (int k = 0; k < 2; k++) {
                        N_Vector *v = k ? s.gd : s.lib;
                        N_Vector z = al == 0 ? v[2] : al == 1 ? v[0] : v[1];
                        N_VLinearSum(coef[ia], v[0], ib % 2 ? -coef[ia] : coef[ia], v[1], z);
                    }
                    bad[0] += !vset_same(&s), count[0]++;
                }
        /* scale */
        for (int ic = 0; ic < NCOEF; ic++)
            for (int al = 0; al < 2; al++) {
                vset_fill(&s);
                for (int k = 0; k < 2; k++) {
                    N_Vector *v = k ? s.gd : s.lib;
                    N_VScale(coef[ic], v[0], al ? v[0] : v[1]);
                }
                bad[1] += !vset_same(&s), count[1]++;
            }
        /* linear combination: 1 to 9 vectors, first coefficient from the set, output distinct,
         * = X[0], or = a later X[k] (the library's vector-outer order shows there) */
        for (int nv = 1; nv <= 9; nv++)
            for (int ic = 0; ic < NCOEF; ic++)
                for (int al = 0; al < 3; al++) {
                    vset_fill(&s);
                    double c[9];
                    c[0] = coef[ic];
                    for (int i = 1; i < nv; i++) c[i] = coef[(ic + 3 * i) % NCOEF] * (1.0 + 0.1 * i);
                    for (int k = 0; k < 2; k++) {
                        N_Vector *v = k ? s.gd : s.lib;
                        N_Vector X[9];
                        for (int i = 0; i < nv; i++) X[i] = v[i];
                        N_Vector z = al == 0 ? v[9] : al == 1 ? v[0] : v[nv > 1 ? nv - 1 : 0];
                        N_VLinearCombination(nv, c, X, z);
                    }
                    bad[2] += !vset_same(&s), count[2]++;
                }
        /* scale-add-multi: 1 to 4 outputs, Y = Z or distinct */
        for (int nv = 1; nv <= 4; nv++)
            for (int ic = 0; ic < NCOEF; ic++)
                for (int al = 0; al < 2; al++) {
                    vset_fill(&s);
                    double a[4];
                    for (int i = 0; i < nv; i++) a[i] = coef[(ic + i) % NCOEF];
                    for (int k = 0; k < 2; k++) {
                        N_Vector *v = k ? s.gd : s.lib;
                        N_Vector Y[4], Z[4];
                        for (int i = 0; i < nv; i++) Y[i] = v[1 + i], Z[i] = v[5 + i];
                        N_VScaleAddMulti(nv, a, v[0], Y, al ? Y : Z);
                    }
                    bad[3] += !vset_same(&s), count[3]++;
                }
        /* the element-wise operations and the reductions */
        for (int rep = 0; rep < 20; rep++) {
            vset_fill(&s);
            double cst = coef[rep % NCOEF] * 3.7;
            double r[2][5];
            for (int k = 0; k < 2; k++) {
                N_Vector *v = k ? s.gd : s.lib;
                N_VConst(cst, v[3]);
                N_VProd(v[0], v[1], v[4]);
                N_VDiv(v[0], v[1], v[5]);
                N_VAbs(v[2], v[6]);
                N_VInv(v[1], v[7]);
                N_VAddConst(v[0], cst, v[8]);
                r[k][0] = N_VDotProd(v[0], v[1]);
                r[k][1] = N_VMaxNorm(v[2]);
                r[k][2] = N_VWrmsNorm(v[0], v[1]);
                r[k][3] = N_VWSqrSumLocal(v[0], v[1]);
                r[k][4] = N_VMin(v[2]);
            }
            for (int q = 4; q < 10; q++) count[q]++;
            bad[4] += !vset_same(&s); /* all six element-wise outputs at once */
            for (int q = 0; q < 5; q++) bad[10 + q] += !same_double(r[0][q], r[1][q]), count[10 + q]++;
        }
        vset_free(&s);
    }
    for (int q = 0; q < 15; q++) {
        if (q >= 5 && q <= 9)
            continue; /* counted with 'const' (one comparison of all element-wise outputs) */
        tap_ok(count[q] > 0 && bad[q] == 0, "%s%s (%s): %d of %d cases bit-identical to SUNDIALS' serial kernel",
               names[q], q == 4 ? " prod div abs inv addconst" : "", width, count[q] - bad[q], count[q]);
    }
}

typedef struct {
    double y[64 * GD_MAX_STATE];
    double lyap[4];
    gd_sim_stats st;
    int nper, n, nlyap;
} run_out;

static void run(const char *const *sets, int nsets, const char *kernels, int periods, int tangents, run_out *out)
{
    gd_case c;
    gd_error err = {0};
    gd_case_init(&c, &err);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    const char *base[] = {"operating.speed_rpm=4000", "operating.torque_nm=500", "clearance.backlash_um=10",
                          "clearance.bearing_clearance_um=5", "excitation.ste_amplitude_um=10"};
    for (int i = 0; i < 5; i++) gd_case_set(&c, base[i], i, &err);
    for (int i = 0; i < nsets; i++) gd_case_set(&c, sets[i], 5 + i, &err);
    char kv[64];
    snprintf(kv, sizeof kv, "solver.vector_kernels=%s", kernels);
    memset(out, 0, sizeof *out);
    if (gd_case_set(&c, kv, 20, &err) != GD_OK || gd_case_resolve(&c, &err) != GD_OK) {
        tap_ok(0, "case: %s", err.msg);
        gd_case_free(&c);
        return;
    }
    gd_model m;
    double y0[GD_MAX_STATE];
    gd_modes md;
    gd_solver_opts o;
    gd_sim *s = NULL;
    int ok = gd_model_build(&c, &m, &err) == GD_OK && gd_model_static_state(&m, y0, &md, &err) == GD_OK;
    gd_solver_opts_from_case(&c, &o);
    if (!ok) {
        tap_ok(0, "model: %s", err.msg);
        gd_case_free(&c);
        return;
    }
    o.n_tangent = tangents;
    if (gd_sim_create(&m, &o, y0, &md, &s, &err) != GD_OK) {
        tap_ok(0, "sim: %s", err.msg);
        gd_case_free(&c);
        return;
    }
    out->n = m.n;
    if (tangents)
        gd_sim_lyapunov_start(s);
    for (int p = 0; p < periods && p < 64; p++) {
        if (gd_sim_period(s, &err) != GD_OK) {
            tap_ok(0, "run: %s", err.msg);
            break;
        }
        memcpy(out->y + (size_t)p * (size_t)m.n, gd_sim_state(s), sizeof(double) * (size_t)m.n);
        out->nper = p + 1;
    }
    if (tangents) {
        double el;
        out->nlyap = gd_sim_lyapunov(s, out->lyap, &el);
    }
    gd_sim_get_stats(s, &out->st);
    gd_sim_free(s);
    gd_case_free(&c);
}

static void whole_runs(void)
{
    static const struct {
        const char *label;
        const char *sets[3];
        int nsets, periods, tangents;
    } cases[] = {
        {"ERK order 5, events located", {"solver.order=5"}, 1, 30, 0},
        {"ERK order 8, events located", {"solver.order=8"}, 1, 30, 0},
        {"ERK order 5 with 2 tangent vectors (Lyapunov)", {"solver.order=5"}, 1, 20, 2},
        {"fixed-step RK4", {"solver.method=rk4", "solver.steps_per_period=128"}, 2, 20, 0},
        {"DIRK order 3", {"solver.method=dirk", "solver.order=3", "solver.rtol=1e-6"}, 3, 3, 0},
    };
    static run_out a, b;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        run(cases[i].sets, cases[i].nsets, "sundials", cases[i].periods, cases[i].tangents, &a);
        run(cases[i].sets, cases[i].nsets, "geardyn", cases[i].periods, cases[i].tangents, &b);
        int same = a.nper == cases[i].periods && b.nper == a.nper && a.n == b.n &&
                   !memcmp(a.y, b.y, sizeof(double) * (size_t)(a.nper * a.n)) && a.nlyap == b.nlyap &&
                   !memcmp(a.lyap, b.lyap, sizeof a.lyap) && a.st.steps == b.st.steps &&
                   a.st.rhs_evals == b.st.rhs_evals && a.st.events == b.st.events;
        tap_ok(same, "%s: %d period-end states%s, %ld steps, %ld RHS evaluations, %ld events identical with "
                     "SUNDIALS' and geardyn's vector kernels", cases[i].label, a.nper,
               cases[i].tangents ? " and the exponents" : "", b.st.steps, b.st.rhs_evals, b.st.events);
        tap_ok(b.st.events > 0, "%s: the run has events (%ld), so their location is covered", cases[i].label,
               b.st.events);
    }
}

/* The error weights in one pass (gd_vector_error_weights, what the explicit methods give ARKODE)
 * against ARKODE's own sequence on the library's kernels (arkEwtSetSS: abs, scale, add a constant,
 * the N_VMin test when atol is 0, invert): the same bits, and the same refusal. */
static void error_weights(SUNContext ctx)
{
    const int lens[] = {1, 2, 3, 7, 20, 57};
    const double tols[][2] = {{1e-8, 1e-10}, {1e-3, 1e-16}, {1e-12, 1.0}, {1e-6, 0.0}, {0.0, 0.0}};
    int bad = 0, count = 0, refusals = 0;
    for (int li = 0; li < (int)(sizeof lens / sizeof lens[0]); li++) {
        N_Vector y = N_VNew_Serial(lens[li], ctx), t = N_VNew_Serial(lens[li], ctx);
        N_Vector w1 = N_VNew_Serial(lens[li], ctx), w2 = N_VNew_Serial(lens[li], ctx);
        for (int rep = 0; rep < 40; rep++)
            for (int k = 0; k < (int)(sizeof tols / sizeof tols[0]); k++) {
                fill(y, rep % 2);
                double rtol = tols[k][0], atol = tols[k][1];
                N_VAbs(y, t);
                N_VScale(rtol, t, t);
                N_VAddConst(t, atol, t);
                int lib = atol == 0.0 && N_VMin(t) <= 0.0 ? -1 : 0;
                if (lib == 0)
                    N_VInv(t, w1);
                int gd = gd_vector_error_weights(y, w2, rtol, atol);
                refusals += lib != 0;
                bad += gd != lib || (lib == 0 && memcmp(N_VGetArrayPointer(w1), N_VGetArrayPointer(w2),
                                                        sizeof(double) * (size_t)lens[li]));
                count++;
            }
        N_VDestroy(y), N_VDestroy(t), N_VDestroy(w1), N_VDestroy(w2);
    }
    tap_ok(bad == 0 && refusals > 0 && refusals < count,
           "error weights in one pass: %d of %d cases bit-identical to ARKODE's sequence of library kernels "
           "(%d refused by both, atol 0 with a zero component)", count - bad, count, refusals);
}

int main(void)
{
    rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 20261122);
    SUNContext ctx;
    if (SUNContext_Create(GD_SUN_COMM_NULL, &ctx) != 0) {
        tap_ok(0, "SUNContext_Create");
        return 1;
    }
    /* the linear combination two lanes wide (SSE2), then as the runs use it (AVX where the
     * processor has it) */
    gd_vector_kernels_wide(0);
    op_by_op(ctx, "two lanes");
    if (gd_vector_kernels_wide(1))
        op_by_op(ctx, "four lanes, AVX");
    error_weights(ctx);
    SUNContext_Free(&ctx);
    gsl_rng_free(rng);
    whole_runs();
    printf("1..%d\n", tap_n);
    return tap_failed ? 1 : 0;
}
