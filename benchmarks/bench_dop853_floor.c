/* Benchmark: geardyn's one-degree-of-freedom scene against a plain C loop that integrates the same
 * equation, coded by hand, with Hairer's DOP853 (Dormand & Prince's 8(5,3) pair with its seventh-order
 * dense output; Hairer, Norsett & Wanner, Solving Ordinary Differential Equations I, 2nd ed.,
 * Springer 1993, section II.10; the method's published coefficients) and Hairer's step control
 * (the error of the 5th- and 3rd-order embedded solutions combined as err5^2 / sqrt(err5^2 + 0.01
 * err3^2), the step factor err^(1/8) / 0.9 bounded to [1/6, 1/0.333], no growth after a rejected
 * step), and locates the same events on its dense output: the ends of the backlash dead zone of
 * the held contact mode, by the Illinois method on the interpolant to 1e-12 of the step, the state
 * there taken from the interpolant and the step restarted from it with the mode flipped. Stop times
 * at the mesh period's ends, where the Poincare points are taken.
 *
 * The scene: Kahraman & Singh's oscillator as geardyn's torsional model of
 * cases/validation/kahraman-singh.ini (zeta 0.05, F_m 0.1, F_a 0.1, alpha 0.2, Omega 1.2: a
 * single-sided impacting period-1 orbit, two events per period); the loop reads the model's numbers
 * (mass, load, dead zone, stiffness and error harmonics) from the built gd_model and evaluates
 *     q'' = (F0 - w (k s(t) f(w q - e(t)) + c (w q' - e'(t)))) / m,
 *     s(t) = 1 + a cos(Omega t + phi), e(t) = e_m + e_r sin(Omega t + phi_e).
 * Both start from the static state; each run's Poincare points are compared with geardyn's at rtol
 * 1e-13 (largest step 0.002 period; gd_workprec_poincare_error). Both run at rtol 1e-6 to 1e-11
 * (atol rtol / 100); the figure of merit is geardyn's time per period against the loop's at the same
 * error, interpolated log-log between the loop's tolerances.
 *
 * Usage: bench_dop853_floor [repeats [periods [rtol]]]   (defaults 3, 2000, every rtol; GEARDYN_SOURCE the
 * source tree). Instruction counts, deterministic on a busy machine:
 *   valgrind --tool=callgrind --toggle-collect=floor_periods bench_dop853_floor 1 500 1e-8
 *   valgrind --tool=callgrind --toggle-collect=geardyn_periods bench_dop853_floor 1 500 1e-8 */
#include "geardyn/geardyn.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* ---- DOP853's coefficients ---- */
static const double C[16] = {0.0, 0.526001519587677318785587544488e-01, 0.789002279381515978178381316732e-01,
                             0.118350341907227396726757197510, 0.281649658092772603273242802490,
                             0.333333333333333333333333333333, 0.25, 0.307692307692307692307692307692,
                             0.651282051282051282051282051282, 0.6, 0.857142857142857142857142857142, 1.0, 1.0, 0.1, 0.2,
                             0.777777777777777777777777777778};
static double A[16][16];
static double E3[12], E5[12], D[4][16];

static void coefficients(void)
{
    A[1][0] = 5.26001519587677318785587544488e-2;
    A[2][0] = 1.97250569845378994544595329183e-2, A[2][1] = 5.91751709536136983633785987549e-2;
    A[3][0] = 2.95875854768068491816892993775e-2, A[3][2] = 8.87627564304205475450678981324e-2;
    A[4][0] = 2.41365134159266685502369798665e-1, A[4][2] = -8.84549479328286085344864962717e-1;
    A[4][3] = 9.24834003261792003115737966543e-1;
    A[5][0] = 3.7037037037037037037037037037e-2, A[5][3] = 1.70828608729473871279604482173e-1;
    A[5][4] = 1.25467687566822425016691814123e-1;
    A[6][0] = 3.7109375e-2, A[6][3] = 1.70252211019544039314978060272e-1, A[6][4] = 6.02165389804559606850219397283e-2;
    A[6][5] = -1.7578125e-2;
    A[7][0] = 3.70920001185047927108779319836e-2, A[7][3] = 1.70383925712239993810214054705e-1;
    A[7][4] = 1.07262030446373284651809199168e-1, A[7][5] = -1.53194377486244017527936158236e-2;
    A[7][6] = 8.27378916381402288758473766002e-3;
    A[8][0] = 6.24110958716075717114429577812e-1, A[8][3] = -3.36089262944694129406857109825;
    A[8][4] = -8.68219346841726006818189891453e-1, A[8][5] = 2.75920996994467083049415600797e1;
    A[8][6] = 2.01540675504778934086186788979e1, A[8][7] = -4.34898841810699588477366255144e1;
    A[9][0] = 4.77662536438264365890433908527e-1, A[9][3] = -2.48811461997166764192642586468;
    A[9][4] = -5.90290826836842996371446475743e-1, A[9][5] = 2.12300514481811942347288949897e1;
    A[9][6] = 1.52792336328824235832596922938e1, A[9][7] = -3.32882109689848629194453265587e1;
    A[9][8] = -2.03312017085086261358222928593e-2;
    A[10][0] = -9.3714243008598732571704021658e-1, A[10][3] = 5.18637242884406370830023853209;
    A[10][4] = 1.09143734899672957818500254654, A[10][5] = -8.14978701074692612513997267357;
    A[10][6] = -1.85200656599969598641566180701e1, A[10][7] = 2.27394870993505042818970056734e1;
    A[10][8] = 2.49360555267965238987089396762, A[10][9] = -3.0467644718982195003823669022;
    A[11][0] = 2.27331014751653820792359768449, A[11][3] = -1.05344954667372501984066689879e1;
    A[11][4] = -2.00087205822486249909675718444, A[11][5] = -1.79589318631187989172765950534e1;
    A[11][6] = 2.79488845294199600508499808837e1, A[11][7] = -2.85899827713502369474065508674;
    A[11][8] = -8.87285693353062954433549289258, A[11][9] = 1.23605671757943030647266201528e1;
    A[11][10] = 6.43392746015763530355970484046e-1;
    A[12][0] = 5.42937341165687622380535766363e-2, A[12][5] = 4.45031289275240888144113950566;
    A[12][6] = 1.89151789931450038304281599044, A[12][7] = -5.8012039600105847814672114227;
    A[12][8] = 3.1116436695781989440891606237e-1, A[12][9] = -1.52160949662516078556178806805e-1;
    A[12][10] = 2.01365400804030348374776537501e-1, A[12][11] = 4.47106157277725905176885569043e-2;
    A[13][0] = 5.61675022830479523392909219681e-2, A[13][6] = 2.53500210216624811088794765333e-1;
    A[13][7] = -2.46239037470802489917441475441e-1, A[13][8] = -1.24191423263816360469010140626e-1;
    A[13][9] = 1.5329179827876569731206322685e-1, A[13][10] = 8.20105229563468988491666602057e-3;
    A[13][11] = 7.56789766054569976138603589584e-3, A[13][12] = -8.298e-3;
    A[14][0] = 3.18346481635021405060768473261e-2, A[14][5] = 2.83009096723667755288322961402e-2;
    A[14][6] = 5.35419883074385676223797384372e-2, A[14][7] = -5.49237485713909884646569340306e-2;
    A[14][10] = -1.08347328697249322858509316994e-4, A[14][11] = 3.82571090835658412954920192323e-4;
    A[14][12] = -3.40465008687404560802977114492e-4, A[14][13] = 1.41312443674632500278074618366e-1;
    A[15][0] = -4.28896301583791923408573538692e-1, A[15][5] = -4.69762141536116384314449447206;
    A[15][6] = 7.68342119606259904184240953878, A[15][7] = 4.06898981839711007970213554331;
    A[15][8] = 3.56727187455281109270669543021e-1, A[15][12] = -1.39902416515901462129418009734e-3;
    A[15][13] = 2.9475147891527723389556272149, A[15][14] = -9.15095847217987001081870187138;
    for (int j = 0; j < 12; j++)
        E3[j] = A[12][j];
    E3[0] -= 0.244094488188976377952755905512;
    E3[8] -= 0.733846688281611857341361741547;
    E3[11] -= 0.220588235294117647058823529412e-1;
    E5[0] = 0.1312004499419488073250102996e-1, E5[5] = -0.1225156446376204440720569753e1;
    E5[6] = -0.4957589496572501915214079952, E5[7] = 0.1664377182454986536961530415e1;
    E5[8] = -0.3503288487499736816886487290, E5[9] = 0.3341791187130174790297318841;
    E5[10] = 0.8192320648511571246570742613e-1, E5[11] = -0.2235530786388629525884427845e-1;
    static const double d[4][16] = {
        {-0.84289382761090128651353491142e1, 0, 0, 0, 0, 0.56671495351937776962531783590, -0.30689499459498916912797304727e1,
         0.23846676565120698287728149680e1, 0.21170345824450282767155149946e1, -0.87139158377797299206789907490,
         0.22404374302607882758541771650e1, 0.63157877876946881815570249290, -0.88990336451333310820698117400e-1,
         0.18148505520854727256656404962e2, -0.91946323924783554000451984436e1, -0.44360363875948939664310572000e1},
        {0.10427508642579134603413151009e2, 0, 0, 0, 0, 0.24228349177525818288430175319e3, 0.16520045171727028198505394887e3,
         -0.37454675472269020279518312152e3, -0.22113666853125306036270938578e2, 0.77334326684722638389603898808e1,
         -0.30674084731089398182061213626e2, -0.93321305264302278729567221706e1, 0.15697238121770843886131091075e2,
         -0.31139403219565177677282850411e2, -0.93529243588444783865713862664e1, 0.35816841486394083752465898540e2},
        {0.19985053242002433820987653617e2, 0, 0, 0, 0, -0.38703730874935176555105901742e3, -0.18917813819516756882830838328e3,
         0.52780815920542364900561016686e3, -0.11573902539959630126141871134e2, 0.68812326946963000169666922661e1,
         -0.10006050966910838403183860980e1, 0.77771377980534432092869265740, -0.27782057523535084065932004339e1,
         -0.60196695231264120758267380846e2, 0.84320405506677161018159903784e2, 0.11992291136182789328035130030e2},
        {-0.25693933462703749003312586129e2, 0, 0, 0, 0, -0.15418974869023643374053993627e3, -0.23152937917604549567536039109e3,
         0.35763911791061412378285349910e3, 0.93405324183624310003907691704e2, -0.37458323136451633156875139351e2,
         0.10409964950896230045147246184e3, 0.29840293426660503123344363579e2, -0.43533456590011143754432175058e2,
         0.96324553959188282948394950600e2, -0.39177261675615439165231486172e2, -0.14972683625798562581422125276e3}};
    memcpy(D, d, sizeof D);
}

/* ---- the equation, coded by hand ---- */

typedef struct ks {
    double inv_m, F0, w, h, k, c, Omega, phase, a, phi, e_m, e_r, e_phi;
    int mode;                /* -1, 0, +1: the held contact mode */
    long nrhs;
} ks;

static inline void excitation(const ks *p, double t, double *e, double *ed, double *s)
{
    double th = p->Omega * t + p->phase;
    double se, ce;
    sincos(th + p->e_phi, &se, &ce);
    *e = p->e_m + p->e_r * se;
    *ed = p->e_r * p->Omega * ce;
    *s = 1.0 + p->a * cos(th + p->phi);
}

static inline void rhs(ks *p, double t, const double *y, double *yd)
{
    double e, ed, s;
    excitation(p, t, &e, &ed, &s);
    double x = p->w * y[0] - e, xd = p->w * y[1] - ed;
    double f = p->c * xd;
    if (p->mode > 0)
        f += p->k * s * (x - p->h);
    else if (p->mode < 0)
        f += p->k * s * (x + p->h);
    yd[0] = y[1];
    yd[1] = p->inv_m * (p->F0 - p->w * f);
    p->nrhs++;
}

/* the clearance coordinate at (t, y) */
static inline double coord(const ks *p, double t, const double *y)
{
    double e, ed, s;
    excitation(p, t, &e, &ed, &s);
    return p->w * y[0] - e;
}

/* ---- the loop ---- */

typedef struct dop {
    ks *p;
    double rtol, atol;
    double rc[8][2];         /* the dense output of the last step */
    double t_old, h_old;
    long steps, rejects, events;
} dop;

static void dense(const dop *d, double t, double *y)
{
    double s = (t - d->t_old) / d->h_old, s1 = 1.0 - s;
    for (int i = 0; i < 2; i++)
        y[i] = d->rc[0][i] +
               s * (d->rc[1][i] +
                    s1 * (d->rc[2][i] + s * (d->rc[3][i] + s1 * (d->rc[4][i] + s * (d->rc[5][i] + s1 * (d->rc[6][i] +
                                                                                                   s * d->rc[7][i]))))));
}

/* the root function of the held mode's boundary that the step crossed at its end (-1: none) */
static double gfun(const dop *d, double t, const double *y, int which)
{
    double x = coord(d->p, t, y);
    return which ? x + d->p->h : x - d->p->h;
}

/* One period from t0 to t1 with y (in and out), k1 = f(t0, y) in *k1 on entry when fsal, h the step
 * to try (in and out). */
static void period(dop *d, double t0, double t1, double *y, double *h)
{
    ks *p = d->p;
    double t = t0, k[16][2], y1[2], yt[2];
    rhs(p, t, y, k[0]);
    int reject = 0;
    double facold = 1e-4;
    while (t < t1) {
        double hh = *h;
        int last = 0;
        if (t + hh >= t1 - 1e-12 * fabs(t1)) {
            hh = t1 - t;
            last = 1;
        }
        for (int s = 1; s < 12; s++) {
            for (int i = 0; i < 2; i++) {
                double acc = 0.0;
                for (int j = 0; j < s; j++)
                    acc += A[s][j] * k[j][i];
                yt[i] = y[i] + hh * acc;
            }
            rhs(p, t + C[s] * hh, yt, k[s]);
        }
        double err3 = 0.0, err5 = 0.0;
        for (int i = 0; i < 2; i++) {
            double b = 0.0, e3 = 0.0, e5 = 0.0;
            for (int j = 0; j < 12; j++) {
                b += A[12][j] * k[j][i];
                e3 += E3[j] * k[j][i];
                e5 += E5[j] * k[j][i];
            }
            y1[i] = y[i] + hh * b;
            double sk = d->atol + d->rtol * fmax(fabs(y[i]), fabs(y1[i]));
            err3 += (e3 / sk) * (e3 / sk);
            err5 += (e5 / sk) * (e5 / sk);
        }
        double deno = err5 + 0.01 * err3;
        double err = deno > 0 ? fabs(hh) * err5 / sqrt(deno * 2.0) : 0.0;
        double fac11 = pow(err, 0.125), fac = fmax(1.0 / 6.0, fmin(1.0 / 0.333, fac11 / 0.9));
        double hnew = hh / fac;
        if (err > 1.0) { /* rejected */
            *h = hh / fmin(1.0 / 0.333, fac11 / 0.9);
            reject = 1;
            d->rejects++;
            continue;
        }
        facold = fmax(err, 1e-4);
        (void)facold;
        d->steps++;
        /* the dense output of the step: three more stages */
        double k13[2];
        rhs(p, t + hh, y1, k13);
        memcpy(k[12], k13, sizeof k13);
        for (int s = 13; s < 16; s++) {
            for (int i = 0; i < 2; i++) {
                double acc = 0.0;
                for (int j = 0; j < s; j++)
                    acc += A[s][j] * k[j][i];
                yt[i] = y[i] + hh * acc;
            }
            rhs(p, t + C[s] * hh, yt, k[s]);
        }
        for (int i = 0; i < 2; i++) {
            double ydiff = y1[i] - y[i], bspl = hh * k[0][i] - ydiff;
            d->rc[0][i] = y[i];
            d->rc[1][i] = ydiff;
            d->rc[2][i] = bspl;
            d->rc[3][i] = ydiff - hh * k13[i] - bspl;
            for (int q = 0; q < 4; q++) {
                double acc = 0.0;
                for (int j = 0; j < 16; j++)
                    acc += D[q][j] * k[j][i];
                d->rc[4 + q][i] = hh * acc;
            }
        }
        d->t_old = t;
        d->h_old = hh;
        /* an event of the held mode: x - h leaves the side of mode +1 or 0, x + h that of mode 0 or -1 */
        double t_ev = INFINITY;
        int which = -1;
        for (int wch = 0; wch < 2; wch++) {
            int held_above = wch == 0 ? p->mode > 0 : p->mode >= 0; /* the mode's side of the boundary */
            double g1 = gfun(d, t + hh, y1, wch);
            if ((g1 > 0) == held_above)
                continue;
            /* Illinois on the interpolant from the step's start */
            double a = t, b = t + hh, ga = gfun(d, a, y, wch), gb = g1, yy[2];
            int side = 0;
            for (int it = 0; it < 100 && b - a > 1e-12 * hh; it++) {
                double c = b - gb * (b - a) / (gb - ga);
                dense(d, c, yy);
                double gc = gfun(d, c, yy, wch);
                if ((gc > 0) == (gb > 0)) {
                    b = c, gb = gc;
                    if (side == -1)
                        ga *= 0.5;
                    side = -1;
                } else {
                    a = c, ga = gc;
                    if (side == 1)
                        gb *= 0.5;
                    side = 1;
                }
            }
            if (b < t_ev) {
                t_ev = b;
                which = wch;
            }
        }
        if (which >= 0) { /* restart from the interpolant at the event, the mode flipped */
            dense(d, t_ev, y);
            double g = gfun(d, t_ev, y, which);
            p->mode = which == 0 ? (g > 0 ? 1 : 0) : (g > 0 ? 0 : -1);
            if (which == 0 && p->mode == 0 && gfun(d, t_ev, y, 1) < 0)
                p->mode = -1;
            t = t_ev;
            d->events++;
            rhs(p, t, y, k[0]);
            *h = fmin(hnew, t1 - t > 0 ? t1 - t : hnew);
            reject = 0;
            continue;
        }
        if (reject)
            hnew = fmin(hnew, hh);
        reject = 0;
        memcpy(y, y1, sizeof y1);
        memcpy(k[0], k13, sizeof k13);
        t = last ? t1 : t + hh;
        if (!last)
            *h = hnew;
        else
            *h = fmax(*h, hnew);
    }
}

static double err_of(const double *a, const double *b, long npts, int n)
{
    return gd_workprec_poincare_error(a, b, npts, n);
}

/* the timed runs, each a function of its own (callgrind --toggle-collect=floor_periods or
 * geardyn_periods counts one of them) */
static __attribute__((noinline)) void floor_periods(dop *d, double T, long periods, double *y, double *pts)
{
    double h = T * 0.01;
    memcpy(pts, y, sizeof(double) * 2);
    for (long k = 0; k < periods; k++) {
        period(d, k * T, (k + 1) * T, y, &h);
        memcpy(pts + (k + 1) * 2, y, sizeof(double) * 2);
    }
}

static __attribute__((noinline)) int geardyn_periods(const gd_model *m, const gd_solver_opts *o, const double *y0,
                                                     const gd_modes *md0, long periods, double *pts, gd_sim_stats *ss)
{
    gd_error e = {0};
    gd_sim *s;
    if (gd_sim_create(m, o, y0, md0, &s, &e) != GD_OK)
        return 1;
    memcpy(pts, y0, sizeof(double) * 2);
    for (long k = 0; k < periods; k++) {
        if (gd_sim_period(s, &e) != GD_OK) {
            gd_sim_free(s);
            return 1;
        }
        memcpy(pts + (k + 1) * 2, gd_sim_state(s), sizeof(double) * 2);
    }
    gd_sim_get_stats(s, ss);
    gd_sim_free(s);
    return 0;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 3;
    long periods = argc > 2 ? atol(argv[2]) : 2000;
    double rtol_only = argc > 3 ? atof(argv[3]) : 0.0;
    coefficients();
    const char *src = getenv("GEARDYN_SOURCE");
    char path[4096];
    snprintf(path, sizeof path, "%s/cases/validation/kahraman-singh.ini", src ? src : ".");
    gd_case c;
    gd_error e = {0};
    gd_case_init(&c, &e);
    gd_model m;
    if (gd_case_load(&c, path, &e) != GD_OK || gd_case_resolve(&c, &e) != GD_OK || gd_model_build(&c, &m, &e) != GD_OK) {
        fprintf(stderr, "%s\n", e.msg);
        return 1;
    }
    const gd_clearance *cl = &m.clear[0];
    const gd_mesh_excitation *x = &m.mesh[0];
    if (m.custom || m.ndof != 1 || m.nk || m.nc || m.nclear != 1 || cl->nw != 1 || m.nmesh != 1 ||
        x->kind != GD_STIFF_HARMONIC || x->nh > 1 || x->mean != 1.0 || x->nimp > 0 || cl->damp_contact_only) {
        fprintf(stderr, "the scene is not the one-degree-of-freedom oscillator this loop codes\n");
        return 1;
    }
    ks p = {m.inv_mass[0], m.F0[0], cl->wval[0], cl->h, cl->k, cl->c, m.Omega, x->phase, x->nh ? x->a[0] : 0.0,
            x->nh ? x->phi[0] : 0.0, x->e_m, x->e_r, x->e_phi, 0, 0};
    double y0[GD_MAX_STATE];
    gd_modes md0;
    gd_initial_state(&c, &m, y0, &md0, &e);
    size_t sz = (size_t)(periods + 1) * (size_t)m.n;
    double *ref = malloc(sizeof(double) * sz), *pts = malloc(sizeof(double) * sz);
    gd_solver_opts o;
    gd_solver_opts_from_case(&c, &o);
    o.rtol = 1e-13;
    o.atol = 1e-15;
    o.max_step_fraction = 0.002;
    gd_sim *s;
    if (gd_sim_create(&m, &o, y0, &md0, &s, &e) != GD_OK)
        return 1;
    memcpy(ref, y0, sizeof(double) * 2); /* the reference */
    for (long k = 0; k < periods; k++) {
        if (gd_sim_period(s, &e) != GD_OK)
            return 1;
        memcpy(ref + (k + 1) * 2, gd_sim_state(s), sizeof(double) * 2);
    }
    gd_sim_free(s);
    printf("geardyn %s on %s: Kahraman & Singh (cases/validation/kahraman-singh.ini), %ld mesh periods, best of %d\n"
           "DOP853 in a plain C loop (the equation coded by hand) against geardyn's torsional model (ERK order 8)\n",
           GD_VERSION_STRING, GD_SUNDIALS_BUILD, periods, repeats);
    enum { NT = 6 };
    double rt[NT], fl_us[NT], fl_err[NT], gd_us[NT], gd_err[NT];
    for (int q = 0; q < NT; q++) {
        rt[q] = pow(10.0, -6.0 - q);
        if (rtol_only > 0 && fabs(rt[q] / rtol_only - 1) > 1e-6) {
            fl_us[q] = gd_us[q] = fl_err[q] = gd_err[q] = NAN;
            continue;
        }
        fl_us[q] = gd_us[q] = INFINITY;
        long frhs = 0, fsteps = 0, fev = 0, grhs = 0, gsteps = 0, gev = 0;
        for (int r = 0; r < repeats; r++) {
            /* the loop */
            ks pp = p;
            pp.mode = md0.mode[0];
            dop d = {&pp, rt[q], rt[q] / 100, {{0}}, 0, 0, 0, 0, 0};
            double y[2] = {y0[0], y0[1]};
            double t0 = now();
            floor_periods(&d, m.period, periods, y, pts);
            fl_us[q] = fmin(fl_us[q], 1e6 * (now() - t0) / periods);
            fl_err[q] = err_of(pts, ref, periods + 1, 2);
            frhs = pp.nrhs, fsteps = d.steps, fev = d.events;
            /* geardyn */
            gd_solver_opts_from_case(&c, &o);
            o.rtol = rt[q];
            o.atol = rt[q] / 100;
            t0 = now();
            gd_sim_stats ss;
            if (geardyn_periods(&m, &o, y0, &md0, periods, pts, &ss))
                return 1;
            gd_us[q] = fmin(gd_us[q], 1e6 * (now() - t0) / periods);
            grhs = ss.rhs_evals, gsteps = ss.steps, gev = ss.events;
            gd_err[q] = err_of(pts, ref, periods + 1, 2);
        }
        printf("  rtol %.0e  DOP853 loop %7.3f us/period %6.1f RHS %5.1f steps %4.2f events, error %.3g   |   "
               "geardyn %7.3f us/period %6.1f RHS %5.1f steps %4.2f events, error %.3g\n", rt[q], fl_us[q],
               (double)frhs / periods, (double)fsteps / periods, (double)fev / periods, fl_err[q], gd_us[q],
               (double)grhs / periods, (double)gsteps / periods, (double)gev / periods, gd_err[q]);
    }
    /* geardyn's time against the loop's at geardyn's error (log-log between the loop's tolerances) */
    printf("at matched accuracy (the loop's time interpolated at geardyn's error):\n");
    for (int q = 0; q < NT; q++) {
        double ge = gd_err[q], t = NAN;
        for (int j = 0; j + 1 < NT; j++) {
            double e1 = fl_err[j], e2 = fl_err[j + 1];
            if ((ge <= e1 && ge >= e2) || (ge >= e1 && ge <= e2)) {
                double s2 = (log(ge) - log(e1)) / (log(e2) - log(e1));
                t = exp(log(fl_us[j]) + s2 * (log(fl_us[j + 1]) - log(fl_us[j])));
                break;
            }
        }
        printf("  geardyn rtol %.0e: error %.3g, %.3f us/period; the loop at that error %.3f us/period: ratio %.2f\n",
               rt[q], ge, gd_us[q], t, gd_us[q] / t);
    }
    free(ref);
    free(pts);
    gd_case_free(&c);
    return 0;
}
