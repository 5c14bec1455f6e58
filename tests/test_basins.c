/* Basins of attraction (gd_basins.h, docs/basins.md section 8).
 *
 * 1. A fraction's standard error is sqrt(p (1 - p) / N) and the ends of its Wilson interval are the
 *    two roots of (p_hat - p)^2 = z^2 p (1 - p) / N (to 1e-12).
 * 2. Basin entropy on grids whose boxes have known label counts: one label (S_b = S_bb = 0), a
 *    boundary through the middle of a column of boxes (S_bb = ln 2 exactly, not > ln 2), a
 *    checkerboard of cells (S_b = S_bb = ln 2), four labels in every box (ln 4 > ln 2: fractal); the
 *    boundary cells of a square.
 * 3. A system with known basins, x' = x - x^3, y' = -y (time 1 per map): every initial state with
 *    x > 0 goes to (1, 0) and with x < 0 to (-1, 0), on a grid and on a random sample, each cell and
 *    sample checked; both attractors period 1 with the multipliers exp(-2) and exp(-1) of the
 *    linearisation (to 1e-7). The outcomes that are no attractor: y' = y diverges (every state), y'
 *    = 0.3 drifts out of the box (left-box), x' = 1e-4 drifts too slowly for 40 periods (the
 *    iteration cap), and the rotation x' = y, y' = -x (no period commensurate with the map's)
 *    is a non-periodic attractor with a largest Lyapunov exponent of 0 to 1e-3: quasi-periodic.
 * 4. The section of a gear model: a state's coordinates are its mesh deflection and rate over h
 *    at t = 0 (gd_model_clearance, to 1e-14), proj . dir is the identity; a model shifted to mesh
 *    phase phi maps as the model from phi / Omega (to 1e-8).
 * 5. Kahraman & Singh (zeta 0.05, F_m 0.1, F_a 0.1, constant stiffness) in its hysteresis interval,
 *    Omega 0.65: the continuation from Omega 0.5 crosses 0.65 three times; the basins of a 60 x 60
 *    picture and 1000 random states have exactly two attractors, the two stable orbits of the
 *    continuation there (to 1e-6), and the unstable orbit lies on their boundary: its state moved by
 *    +-1e-4 along its unstable eigenvector goes to one attractor on one side and the other on the
 *    other side (brute force, 600 periods). Outside the interval, Omega 0.5 and 0.8, one attractor
 *    with fraction 1.
 * 6. The same labels, attractors and fractions with 1 and 2 threads.
 * 7. Grid refinement (40 x 40 against 80 x 80): each attractor's share of the grid changes by less
 *    than its boundary's share of the coarse grid's cells.
 * 8. The analysis of a case over a parameter (Omega 0.55 to 0.75, 5 values): the orbit without
 *    impacts keeps its id from 0.55 to 0.7, the impacting one its own from 0.6 to 0.75; records of
 *    every point read back bit for bit. */
#include "analysis_util.h"
#include "tap.h"
#include "geardyn/gd_basins.h"
#include "geardyn/gd_periodic.h"

#include <gsl/gsl_eigen.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- 1, 2 ---- */

static void test_fractions(void)
{
    static const long cnt[] = {0, 3, 311, 500, 999};
    for (int i = 0; i < 5; i++) {
        gd_basin_fraction f;
        long N = 1000;
        double z = 1.96;
        gd_basin_fraction_of(cnt[i], N, z, &f);
        double ph = (double)cnt[i] / N;
        TAP_CLOSE(f.se, sqrt(ph * (1 - ph) / N), 1e-15, "standard error");
        double r_lo = (ph - f.wilson_lo) * (ph - f.wilson_lo) - z * z * f.wilson_lo * (1 - f.wilson_lo) / N;
        double r_hi = (ph - f.wilson_hi) * (ph - f.wilson_hi) - z * z * f.wilson_hi * (1 - f.wilson_hi) / N;
        tap_ok(fabs(r_lo) < 1e-12 && fabs(r_hi) < 1e-12 && f.wilson_lo <= ph && ph <= f.wilson_hi,
               "Wilson interval of %ld/%ld: [%.6f, %.6f] are roots (residuals %.2g, %.2g)", cnt[i], N, f.wilson_lo,
               f.wilson_hi, r_lo, r_hi);
    }
}

static void test_entropy(void)
{
    enum { NX = 20, NY = 10 };
    int g[NX * NY];
    gd_basin_entropy e;
    gd_error err = {0};
    for (int k = 0; k < NX * NY; k++)
        g[k] = 3;
    gd_basin_entropy_of(g, NX, NY, 5, &e, &err);
    tap_ok(e.sb == 0 && e.sbb == 0 && e.boundary_boxes == 0 && e.boxes == 8, "one label: S_b 0, no boundary box");
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++)
            g[j * NX + i] = i < 12 ? 0 : 1; /* a boundary inside the third column of boxes: 2 of 5 and 3 of 5 */
    gd_basin_entropy_of(g, NX, NY, 5, &e, &err);
    double s = -(0.4 * log(0.4) + 0.6 * log(0.6));
    TAP_CLOSE(e.sbb, s, 1e-15, "a straight boundary: S_bb of the boxes it crosses");
    TAP_CLOSE(e.sb, s * 2 / 8, 1e-15, "a straight boundary: S_b");
    tap_ok(!e.fractal && e.boundary_boxes == 2, "a straight boundary is not fractal (%ld boundary boxes)",
           e.boundary_boxes);
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++)
            g[j * NX + i] = (i + j) % 2;
    gd_basin_entropy_of(g, NX, NY, 2, &e, &err);
    TAP_CLOSE(e.sbb, log(2.0), 1e-15, "checkerboard: S_bb = ln 2");
    tap_ok(!e.fractal, "S_bb = ln 2 is not above ln 2");
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++)
            g[j * NX + i] = 2 * (j % 2) + i % 2 - 2; /* -2, -1, 0, 1: labels that are no attractor count too */
    gd_basin_entropy_of(g, NX, NY, 2, &e, &err);
    TAP_CLOSE(e.sbb, log(4.0), 1e-14, "four labels in every box: S_bb = ln 4");
    tap_ok(e.fractal, "ln 4 > ln 2: fractal");
    for (int k = 0; k < NX * NY; k++)
        g[k] = 0;
    for (int j = 2; j < 6; j++)
        for (int i = 3; i < 9; i++)
            g[j * NX + i] = 1;
    long b, c;
    gd_basin_boundary_cells(g, NX, NY, 1, &b, &c);
    tap_ok(b == 2 * 6 + 2 * 2 && c == 24, "a 6 x 4 square: %ld cells, %ld on its boundary", c, b);
    tap_ok(gd_basin_entropy_of(g, NX, NY, 11, &e, &err) == GD_ERR_INPUT, "boxes larger than the grid refused");
}

/* ---- 3 ---- */

static int sys_kind;

static void rhs(double t, const double *y, double *yd, void *ctx)
{
    (void)t, (void)ctx;
    switch (sys_kind) {
    case 0: yd[0] = y[0] - y[0] * y[0] * y[0], yd[1] = -y[1]; break;
    case 1: yd[0] = y[0] - y[0] * y[0] * y[0], yd[1] = y[1]; break;
    case 2: yd[0] = y[0] - y[0] * y[0] * y[0], yd[1] = 0.3; break;
    case 3: yd[0] = 1e-4, yd[1] = 0; break;
    default: yd[0] = y[1], yd[1] = -y[0]; break;
    }
}

static void tangent(double t, const double *y, const double *v, double *out, void *ctx)
{
    (void)t, (void)ctx;
    switch (sys_kind) {
    case 0: out[0] = (1 - 3 * y[0] * y[0]) * v[0], out[1] = -v[1]; break;
    case 1: out[0] = (1 - 3 * y[0] * y[0]) * v[0], out[1] = v[1]; break;
    case 2: out[0] = (1 - 3 * y[0] * y[0]) * v[0], out[1] = 0; break;
    case 3: out[0] = 0, out[1] = 0; break;
    default: out[0] = v[1], out[1] = -v[0]; break;
    }
}

static gd_solver_opts plain_opts(double rtol)
{
    gd_solver_opts o;
    memset(&o, 0, sizeof o);
    o.method = GD_METHOD_ERK;
    o.order = 8;
    o.rtol = rtol;
    o.atol = rtol * 1e-2;
    o.root_finding = 1;
    o.refine_events = 1;
    o.max_step_fraction = 0.1;
    o.max_events_per_period = 10000;
    o.max_separated_periods = 1000;
    return o;
}

static gd_basin_mapper *custom_mapper(int kind, gd_model *m, const gd_basin_opts *bo, int cells)
{
    static gd_custom_system sys = {2, rhs, tangent, NULL, NULL};
    sys_kind = kind;
    gd_model_custom(m, &sys, 1.0);
    gd_solver_opts o = plain_opts(1e-10);
    gd_basin_section sec;
    gd_error e = {0};
    const double base[2] = {0, 0};
    gd_basin_mapper *mp = NULL;
    if (gd_basin_section_plane(&sec, 2, base, 0, 1, -1.0, 2.0, -1.0, 1.0, cells, cells, &e) != GD_OK ||
        gd_basin_mapper_create(m, &o, &sec, bo, &mp, &e) != GD_OK)
        au_die(&e);
    return mp;
}

static void test_known_basins(void)
{
    gd_model m;
    gd_basin_opts bo;
    gd_basin_opts_default(&bo);
    gd_error e = {0};
    enum { C = 30, N = 2000 };
    gd_basin_mapper *mp = custom_mapper(0, &m, &bo, C);
    int lab[C * C], slab[N];
    if (gd_basin_map_grid(mp, lab, &e) != GD_OK)
        au_die(&e);
    const gd_attractor *att;
    int na = gd_basin_mapper_attractors(mp, &att);
    int plus = -1, minus = -1;
    for (int a = 0; a < na; a++)
        if (att[a].kind == GD_ATT_PERIODIC && att[a].period == 1)
            *(att[a].pts[0] > 0 ? &plus : &minus) = a;
    tap_ok(na == 2 && plus >= 0 && minus >= 0, "x' = x - x^3, y' = -y: two attractors of period 1 (%d)", na);
    if (plus < 0 || minus < 0)
        return;
    TAP_CLOSE(att[plus].pts[0], 1.0, 1e-8, "attractor at x = 1");
    TAP_CLOSE(att[minus].pts[0], -1.0, 1e-8, "attractor at x = -1");
    TAP_CLOSE(att[plus].orbit.mu_re[0], exp(-1.0), 1e-7, "its multipliers: exp(-1)");
    TAP_CLOSE(att[plus].orbit.mu_re[1], exp(-2.0), 1e-7, "and exp(-2)");
    int bad = 0;
    for (int j = 0; j < C; j++)
        for (int i = 0; i < C; i++) {
            double x = -1.0 + (i + 0.5) * 3.0 / C;
            bad += lab[j * C + i] != (x > 0 ? plus : minus);
        }
    tap_ok(bad == 0, "every cell of the %d x %d grid to the attractor on its side of x = 0 (%d wrong)", C, C, bad);
    double *y0 = malloc(sizeof(double) * 2 * N);
    srand(7);
    for (int k = 0; k < N; k++) {
        y0[2 * k] = -1.0 + 3.0 * rand() / (RAND_MAX + 1.0);
        y0[2 * k + 1] = -1.0 + 2.0 * rand() / (RAND_MAX + 1.0);
    }
    if (gd_basin_map(mp, y0, N, 1, 0, slab, &e) != GD_OK)
        au_die(&e);
    bad = 0;
    for (int k = 0; k < N; k++)
        bad += slab[k] != (y0[2 * k] > 0 ? plus : minus);
    tap_ok(bad == 0, "every state of a random sample of %d likewise (%d wrong)", N, bad);
    gd_basin_mapper_free(mp);

    static const struct { int kind, label; const char *what; } other[] = {
        {1, GD_BASIN_DIVERGED, "y' = y: diverged"}, {2, GD_BASIN_LEFT_BOX, "y' = 0.3: left the box"},
        {3, GD_BASIN_CAP, "x' = 1e-4: the iteration cap"}};
    for (int q = 0; q < 3; q++) {
        gd_basin_opts_default(&bo);
        if (other[q].kind == 1)
            bo.consecutive_lost_steps = 1000000; /* (so that it diverges before it is lost) */
        bo.max_periods = other[q].kind == 3 ? 40 : 2000;
        bo.consecutive_recurrences = other[q].kind == 3 ? 1000 : 100;
        mp = custom_mapper(other[q].kind, &m, &bo, 10);
        int l[100];
        if (gd_basin_map_grid(mp, l, &e) != GD_OK)
            au_die(&e);
        int wrong = 0;
        for (int k = 0; k < 100; k++) {
            double yy = -1.0 + ((k / 10) + 0.5) * 0.2;
            if (other[q].kind == 1 && fabs(yy) < 1e-12)
                continue;
            wrong += l[k] != other[q].label;
        }
        tap_ok(wrong == 0 && gd_basin_mapper_attractors(mp, &att) == 0, "%s (every cell labelled %s; %d not)",
               other[q].what, gd_basin_label_name(other[q].label), wrong);
        gd_basin_mapper_free(mp);
    }
    gd_basin_opts_default(&bo);
    bo.lyapunov_periods = 2000;
    mp = custom_mapper(4, &m, &bo, 40);
    double start[2] = {0.55, 0.0};
    int l1;
    if (gd_basin_map(mp, start, 1, 1, 0, &l1, &e) != GD_OK)
        au_die(&e);
    na = gd_basin_mapper_attractors(mp, &att);
    tap_ok(na == 1 && l1 == 0 && att[0].kind == GD_ATT_QUASI_PERIODIC && fabs(att[0].mle_per_period) < 1e-3,
           "the rotation: one quasi-periodic attractor, largest Lyapunov exponent %.2g per period", na ? att[0].mle_per_period : NAN);
    gd_basin_mapper_free(mp);
    free(y0);
}

/* ---- 4 ---- */

static void test_section(void)
{
    gd_case c;
    gd_model m0, m;
    au_ks_case(&c, &m0, 0.0, 0.05, 0.1, 0.1, 0.65, NULL);
    gd_error e = {0};
    double base[GD_MAX_STATE];
    gd_modes md;
    if (gd_model_static_state(&m0, base, &md, &e) != GD_OK)
        au_die(&e);
    double phi = 1.1;
    gd_model_at_mesh_phase(&m0, phi, &m);
    gd_basin_section s;
    if (gd_basin_section_named(&s, &m, base, "lambda_L", "lambda_dot_L", -2, 3, -2, 2, 10, 10, &e) != GD_OK)
        au_die(&e);
    double y[GD_MAX_STATE] = {1.37, -0.42}, u, v, x, xd;
    gd_basin_section_coords(&s, y, &u, &v);
    memset(&md, 0, sizeof md);
    md.from_state = 1;
    gd_model_clearance(&m, m.mesh_clear[0], 0.0, y, &md, &x, &xd);
    double h = m.clear[m.mesh_clear[0]].h;
    TAP_CLOSE(u, x / h, 1e-14, "section coordinate 1: the mesh deflection over h at t = 0");
    TAP_CLOSE(v, xd / h, 1e-14, "section coordinate 2: its rate over h");
    gd_basin_section_state(&s, 0.3, -0.7, y);
    gd_basin_section_coords(&s, y, &u, &v);
    tap_ok(fabs(u - 0.3) < 1e-14 && fabs(v + 0.7) < 1e-14, "the state of (0.3, -0.7) has those coordinates");
    tap_ok(gd_basin_section_named(&s, &m, base, "lambda_R", "lambda_dot_L", -2, 3, -2, 2, 10, 10, &e) == GD_ERR_INPUT,
           "a torsional model has no lambda_R: %s", e.msg);
    tap_ok(gd_basin_section_named(&s, &m, base, "lambda_L", "q", -2, 3, -2, 2, 10, 10, &e) == GD_ERR_INPUT,
           "lambda_L and q move one component: refused (%s)", e.msg);
    /* the shifted model's map is the model's from phi / Omega */
    gd_solver_opts o = plain_opts(1e-11);
    double y0[2] = {1.2, 0.1}, y1[2], y2[2];
    if (gd_sim_period_map(&m, &o, y0, 1, y1, NULL, NULL, &e) != GD_OK)
        au_die(&e);
    /* the original model from t0 = phi / Omega: a simulation advanced to t0, then restarted there from y0 */
    gd_sim *sim;
    memset(&md, 0, sizeof md);
    if (gd_model_consistent_modes(&m0, 0.0, y0, &md, &e) != GD_OK || gd_sim_create(&m0, &o, y0, &md, &sim, &e) != GD_OK ||
        gd_sim_advance_to(sim, phi / m0.Omega, &e) != GD_OK || gd_sim_set_state(sim, y0, &e) != GD_OK ||
        gd_sim_advance_to(sim, phi / m0.Omega + m0.period, &e) != GD_OK)
        au_die(&e);
    memcpy(y2, gd_sim_state(sim), sizeof y2);
    gd_sim_free(sim);
    tap_ok(fabs(y1[0] - y2[0]) < 1e-8 && fabs(y1[1] - y2[1]) < 1e-8,
           "the model at mesh phase %.2f maps as the model from t = phase / Omega (%.2g, %.2g)", phi, y1[0] - y2[0],
           y1[1] - y2[1]);
    gd_case_free(&c);
}

/* ---- 5, 6, 7 ---- */

static gd_basin_mapper *ks_mapper(double Omega, int cells, int threads, gd_model *m, gd_solver_opts *o)
{
    gd_case c;
    gd_model m0;
    static const char *extra[] = {"solver.rtol=1e-10", "solver.atol=1e-12", NULL};
    au_ks_case(&c, &m0, 0.0, 0.05, 0.1, 0.1, Omega, extra);
    *m = m0;
    gd_solver_opts_from_case(&c, o);
    gd_error e = {0};
    double base[GD_MAX_STATE];
    gd_modes md;
    gd_basin_section s;
    gd_basin_opts bo;
    gd_basin_opts_default(&bo);
    bo.threads = threads;
    gd_basin_mapper *mp = NULL;
    if (gd_model_static_state(m, base, &md, &e) != GD_OK ||
        gd_basin_section_named(&s, m, base, "lambda_L", "lambda_dot_L", -2, 3, -2, 2, cells, cells, &e) != GD_OK ||
        gd_basin_mapper_create(m, o, &s, &bo, &mp, &e) != GD_OK)
        au_die(&e);
    gd_case_free(&c);
    return mp;
}

/* The sample of the K&S tests: N states uniform in the box. */
static double *ks_sample(int N, const gd_model *m)
{
    gd_error e = {0};
    double base[GD_MAX_STATE];
    gd_modes md;
    gd_basin_section s;
    if (gd_model_static_state(m, base, &md, &e) != GD_OK ||
        gd_basin_section_named(&s, m, base, "lambda_L", "lambda_dot_L", -2, 3, -2, 2, 10, 10, &e) != GD_OK)
        au_die(&e);
    double *y = malloc(sizeof(double) * (size_t)N * m->n);
    srand(11);
    for (int k = 0; k < N; k++)
        gd_basin_section_state(&s, -2 + 5.0 * rand() / (RAND_MAX + 1.0), -2 + 4.0 * rand() / (RAND_MAX + 1.0),
                               y + (size_t)k * m->n);
    return y;
}

/* The orbits of the K&S continuation (Omega 0.5 up to 0.8) through Omega: shooting from the branch
 * interpolated there. */
static int ks_orbits(const gd_model *m, const gd_solver_opts *o, double Omega, gd_po *orbits)
{
    gd_error e = {0};
    double y[GD_MAX_STATE];
    gd_modes md;
    gd_model m5;
    gd_model_at_mesh_frequency(0.5, &m5, (void *)m, &e);
    if (gd_model_static_state(&m5, y, &md, &e) != GD_OK || gd_sim_period_map(&m5, o, y, 300, y, NULL, NULL, &e) != GD_OK)
        au_die(&e);
    gd_cont_opts co;
    gd_cont_opts_default(&co);
    co.p_min = 0.5;
    co.p_max = 0.8;
    co.ds_max = 0.02;
    gd_po start;
    gd_branch br;
    if (gd_po_solve(&m5, o, &co.po, y, &start, &e) != GD_OK ||
        gd_continue(gd_model_at_mesh_frequency, (void *)m, o, &co, &start, &br, &e) != GD_OK)
        au_die(&e);
    int n = 0;
    for (int i = 0; i + 1 < br.npoints && n < 8; i++) {
        double a = br.pt[i].orbit.p, b = br.pt[i + 1].orbit.p;
        if (!(Omega >= fmin(a, b) && Omega <= fmax(a, b)))
            continue;
        double s = (Omega - a) / (b - a), y0[GD_MAX_STATE];
        for (int q = 0; q < m->n; q++)
            y0[q] = br.pt[i].orbit.y[0][q] + s * (br.pt[i + 1].orbit.y[0][q] - br.pt[i].orbit.y[0][q]);
        gd_model mo;
        gd_model_at_mesh_frequency(Omega, &mo, (void *)m, &e);
        if (gd_po_solve(&mo, o, &co.po, y0, &orbits[n], &e) == GD_OK)
            n++;
    }
    gd_branch_free(&br);
    return n;
}

static int ks_label_of(const gd_model *m, const gd_solver_opts *o, const double *y, const gd_attractor *att, int na)
{
    gd_error e = {0};
    double z[GD_MAX_STATE];
    memcpy(z, y, sizeof(double) * m->n);
    if (gd_sim_period_map(m, o, z, 600, z, NULL, NULL, &e) != GD_OK)
        return -9;
    for (int a = 0; a < na; a++)
        if (fabs(z[0] - att[a].pts[0]) < 1e-6 && fabs(z[1] - att[a].pts[1]) < 1e-6)
            return a;
    return -8;
}

static void test_ks_hysteresis(void)
{
    gd_model m;
    gd_solver_opts o;
    gd_error e = {0};
    enum { C = 60, N = 1000 };
    gd_basin_mapper *mp = ks_mapper(0.65, C, 0, &m, &o);
    int *lab = malloc(sizeof(int) * C * C), *slab = malloc(sizeof(int) * N);
    double *y0 = ks_sample(N, &m);
    if (gd_basin_map_grid(mp, lab, &e) != GD_OK || gd_basin_map(mp, y0, N, 1, 0, slab, &e) != GD_OK)
        au_die(&e);
    const gd_attractor *att;
    int na = gd_basin_mapper_attractors(mp, &att);
    gd_po orb[8];
    int no = ks_orbits(&m, &o, 0.65, orb), nstable = 0, upo = -1;
    for (int k = 0; k < no; k++) {
        nstable += orb[k].stable;
        if (!orb[k].stable)
            upo = k;
    }
    tap_ok(no == 3 && nstable == 2 && upo >= 0, "the continuation through Omega 0.65: %d orbits, %d stable", no, nstable);
    int found = 0;
    for (int k = 0; k < no; k++) {
        if (!orb[k].stable)
            continue;
        for (int a = 0; a < na; a++)
            if (att[a].kind == GD_ATT_PERIODIC && att[a].period == 1 &&
                fabs(att[a].pts[0] - orb[k].y[0][0]) < 1e-6 && fabs(att[a].pts[1] - orb[k].y[0][1]) < 1e-6)
                found++;
    }
    long cnt[2] = {0, 0}, other = 0;
    for (int k = 0; k < N; k++)
        if (slab[k] == 0 || slab[k] == 1)
            cnt[slab[k]]++;
        else
            other++;
    tap_ok(na == 2 && found == 2 && other == 0,
           "Omega 0.65: exactly two attractors, the continuation's stable orbits (%d of %d matched); fractions %.3f "
           "and %.3f, %ld other outcomes", found, na, cnt[0] / (double)N, cnt[1] / (double)N, other);
    if (upo >= 0 && na == 2) {
        /* the unstable eigenvector of the orbit's monodromy */
        gsl_matrix *M = gsl_matrix_alloc(2, 2);
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++)
                gsl_matrix_set(M, i, j, orb[upo].M[i * 2 + j]);
        gsl_vector_complex *ev = gsl_vector_complex_alloc(2);
        gsl_matrix_complex *V = gsl_matrix_complex_alloc(2, 2);
        gsl_eigen_nonsymmv_workspace *w = gsl_eigen_nonsymmv_alloc(2);
        gsl_eigen_nonsymmv(M, ev, V, w);
        int k = fabs(GSL_REAL(gsl_vector_complex_get(ev, 0))) > fabs(GSL_REAL(gsl_vector_complex_get(ev, 1))) ? 0 : 1;
        double v[2] = {GSL_REAL(gsl_matrix_complex_get(V, 0, k)), GSL_REAL(gsl_matrix_complex_get(V, 1, k))};
        double yp[2], ym[2];
        for (int q = 0; q < 2; q++) {
            yp[q] = orb[upo].y[0][q] + 1e-4 * v[q];
            ym[q] = orb[upo].y[0][q] - 1e-4 * v[q];
        }
        int lp = ks_label_of(&m, &o, yp, att, na), lm = ks_label_of(&m, &o, ym, att, na);
        tap_ok(lp >= 0 && lm >= 0 && lp != lm, "the unstable orbit (multiplier %.4f) lies on the basin boundary: "
               "+-1e-4 along its unstable direction go to attractors %d and %d", orb[upo].mu_re[0], lp, lm);
        /* and the picture's cell holding it borders both basins */
        double u, vv;
        gd_basin_section s;
        double base[GD_MAX_STATE];
        gd_modes md;
        gd_model_static_state(&m, base, &md, &e);
        gd_basin_section_named(&s, &m, base, "lambda_L", "lambda_dot_L", -2, 3, -2, 2, C, C, &e);
        gd_basin_section_coords(&s, orb[upo].y[0], &u, &vv);
        int ci = (int)floor((u + 2) / 5 * C), cj = (int)floor((vv + 2) / 4 * C), seen[2] = {0, 0};
        for (int dj = -1; dj <= 1; dj++)
            for (int di = -1; di <= 1; di++) {
                int l = lab[(cj + dj) * C + ci + di];
                if (l == 0 || l == 1)
                    seen[l] = 1;
            }
        tap_ok(seen[0] && seen[1], "the picture's cells around it hold both basins");
        gsl_eigen_nonsymmv_free(w);
        gsl_matrix_complex_free(V);
        gsl_vector_complex_free(ev);
        gsl_matrix_free(M);
    }
    gd_basin_mapper_free(mp);
    /* 6: the same with 1 and 2 threads */
    int *lab1 = malloc(sizeof(int) * C * C), *slab1 = malloc(sizeof(int) * N);
    gd_basin_mapper *m1 = ks_mapper(0.65, C, 1, &m, &o), *m2 = ks_mapper(0.65, C, 2, &m, &o);
    if (gd_basin_map_grid(m1, lab1, &e) != GD_OK || gd_basin_map(m1, y0, N, 1, 0, slab1, &e) != GD_OK ||
        gd_basin_map_grid(m2, lab, &e) != GD_OK || gd_basin_map(m2, y0, N, 1, 0, slab, &e) != GD_OK)
        au_die(&e);
    const gd_attractor *a1, *a2;
    int n1 = gd_basin_mapper_attractors(m1, &a1), n2 = gd_basin_mapper_attractors(m2, &a2), same = n1 == n2;
    for (int a = 0; a < n1 && same; a++)
        same = memcmp(a1[a].pts, a2[a].pts, sizeof(double) * (size_t)a1[a].npts * m.n) == 0;
    tap_ok(same && memcmp(lab1, lab, sizeof(int) * C * C) == 0 && memcmp(slab1, slab, sizeof(int) * N) == 0 &&
           gd_basin_mapper_periods(m1) == gd_basin_mapper_periods(m2),
           "1 and 2 threads: the same attractors (bit for bit), labels of the picture and the sample, %ld and %ld periods",
           gd_basin_mapper_periods(m1), gd_basin_mapper_periods(m2));
    gd_basin_mapper_free(m1);
    gd_basin_mapper_free(m2);
    free(lab1), free(slab1);
    /* outside the hysteresis interval */
    static const double outside[2] = {0.5, 0.8};
    for (int q = 0; q < 2; q++) {
        mp = ks_mapper(outside[q], 30, 0, &m, &o);
        if (gd_basin_map(mp, y0, N, 1, 0, slab, &e) != GD_OK)
            au_die(&e);
        na = gd_basin_mapper_attractors(mp, &att);
        long on0 = 0;
        for (int k = 0; k < N; k++)
            on0 += slab[k] == 0;
        tap_ok(na == 1 && on0 == N, "Omega %.1f, outside the interval: one attractor (%d, %s), fraction %.4f", outside[q],
               na, na ? att[0].name : "none", on0 / (double)N);
        gd_basin_mapper_free(mp);
    }
    free(lab), free(slab), free(y0);
}

static void test_refinement(void)
{
    gd_model m;
    gd_solver_opts o;
    gd_error e = {0};
    int *g1 = malloc(sizeof(int) * 40 * 40), *g2 = malloc(sizeof(int) * 80 * 80);
    gd_basin_mapper *m1 = ks_mapper(0.65, 40, 0, &m, &o), *m2 = ks_mapper(0.65, 80, 0, &m, &o);
    if (gd_basin_map_grid(m1, g1, &e) != GD_OK || gd_basin_map_grid(m2, g2, &e) != GD_OK)
        au_die(&e);
    const gd_attractor *a1, *a2;
    int n1 = gd_basin_mapper_attractors(m1, &a1), n2 = gd_basin_mapper_attractors(m2, &a2);
    tap_ok(n1 == 2 && n2 == 2, "refinement: two attractors on both grids");
    for (int a = 0; a < n1 && n2 == 2; a++) {
        int b = fabs(a1[a].pts[0] - a2[0].pts[0]) < 1e-6 ? 0 : 1; /* the same attractor on the fine grid */
        long bd1, c1, bd2, c2;
        gd_basin_boundary_cells(g1, 40, 40, a, &bd1, &c1);
        gd_basin_boundary_cells(g2, 80, 80, b, &bd2, &c2);
        double f1 = c1 / 1600.0, f2 = c2 / 6400.0, share = bd1 / 1600.0;
        tap_ok(fabs(f2 - f1) < share, "attractor %d: grid fraction %.4f (40 x 40) and %.4f (80 x 80) differ by %.4f, "
               "less than its boundary's share of the coarse grid %.4f", a, f1, f2, fabs(f2 - f1), share);
    }
    gd_basin_mapper_free(m1);
    gd_basin_mapper_free(m2);
    free(g1), free(g2);
}

/* ---- 8 ---- */

static void test_case_parameter(void)
{
    gd_case c;
    gd_model m;
    static const char *extra[] = {"scene.analysis=basins", "basins.picture=off", "basins.samples=300",
                                  "basins.resolution=60", "basins.x_from=-2", "basins.x_to=3", "basins.y_from=-2",
                                  "basins.y_to=2", "basins.points=5", NULL};
    au_ks_case(&c, &m, 0.0, 0.05, 0.1, 0.1, 0.65, extra);
    double rpm_per_Omega = c.speed_rpm / m.Omega;
    au_set(&c, "basins.parameter=operating.speed_rpm");
    au_num(&c, "basins.from", 0.55 * rpm_per_Omega);
    au_num(&c, "basins.to", 0.75 * rpm_per_Omega);
    gd_error e = {0};
    if (gd_case_resolve(&c, &e) != GD_OK)
        au_die(&e);
    gd_basins_result res;
    gd_basins_hooks h = {0};
    if (gd_basins_run(&c, NULL, &h, &res, &e) != GD_OK)
        au_die(&e);
    /* the orbit without impacts: the attractor whose largest mesh deflection is below the backlash's far side */
    int id_free = -2, id_imp = -2, ok = res.npoints == 5;
    for (int k = 0; k < res.npoints && ok; k++) {
        const gd_basins_point *p = &res.pt[k];
        double Om = p->value / rpm_per_Omega;
        int want = (Om < 0.58 || Om > 0.74) ? 1 : 2;
        ok = p->natt == want;
        for (int a = 0; a < p->natt && ok; a++) {
            int imp = p->att[a].impact_regime != GD_IMPACT_NONE && Om < 0.7; /* (no-impact orbit grazes at 0.709) */
            int *id = Om < 0.7 ? (imp ? &id_imp : &id_free) : NULL;
            if (id && *id == -2)
                *id = p->id[a];
            else if (id)
                ok = *id == p->id[a];
        }
        printf("# Omega %.3f: %d attractors, ids", Om, p->natt);
        for (int a = 0; a < p->natt; a++)
            printf(" %d (%s, %s)", p->id[a], p->att[a].name, gd_impact_regime_name(p->att[a].impact_regime));
        printf("\n");
    }
    tap_ok(ok && id_free >= 0 && id_imp >= 0 && id_free != id_imp,
           "over Omega 0.55 to 0.75: one attractor, then two with the ids they keep (%d without impacts, %d impacting), "
           "then one", id_free, id_imp);
    /* the impacting attractor keeps its id to 0.75 */
    const gd_basins_point *last = &res.pt[4];
    tap_ok(last->natt == 1 && last->id[0] == id_imp, "at Omega 0.75 the one attractor is the impacting one (id %d)",
           last->natt ? last->id[0] : -1);
    /* records read back bit for bit */
    gd_basins_result r2;
    memset(&r2, 0, sizeof r2);
    r2.npoints = res.npoints;
    r2.n = res.n;
    r2.pt = calloc((size_t)r2.npoints, sizeof *r2.pt);
    int same = 1;
    for (int k = 0; k < res.npoints; k++) {
        char *line;
        size_t len;
        if (gd_basins_record_format(&res, k, &line, &len, &e) != GD_OK ||
            gd_basins_record_parse(&r2, line, len, &e) != GD_OK)
            au_die(&e);
        free(line);
        const gd_basins_point *p = &res.pt[k], *q = &r2.pt[k];
        same &= p->natt == q->natt && p->samples == q->samples && memcmp(p->special, q->special, sizeof p->special) == 0 &&
                memcmp(&p->value, &q->value, sizeof p->value) == 0;
        for (int a = 0; a < p->natt && same; a++)
            same = p->count[a] == q->count[a] && p->att[a].npts == q->att[a].npts &&
                   memcmp(p->att[a].pts, q->att[a].pts, sizeof(double) * p->att[a].npts * res.n) == 0 &&
                   memcmp(p->att[a].orbit.mu_re, q->att[a].orbit.mu_re, sizeof(double) * res.n) == 0 &&
                   memcmp(&p->att[a].mle_per_period, &q->att[a].mle_per_period, sizeof(double)) == 0;
    }
    tap_ok(same, "every point's record reads back bit for bit");
    gd_basins_result_free(&r2);
    gd_basins_result_free(&res);
    gd_case_free(&c);
}

int main(void)
{
    test_fractions();
    test_entropy();
    test_known_basins();
    test_section();
    test_ks_hysteresis();
    test_refinement();
    test_case_parameter();
    return tap_done();
}
