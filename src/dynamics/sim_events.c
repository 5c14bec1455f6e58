/* Events: root functions on both sides of every clearance (gated or not), location of the
 * crossings (refined with the method), contact-mode flips with their event records and the
 * saltation of the tangent vectors, the near-grazing watch, and the repair of held modes the
 * state has left. Called by the driver (simulate.c) after each step. */
#include "sim_internal.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <string.h>

GD_API const char *gd_event_kind_name(int kind)
{
    static const char *names[] = {"contact", "separation", "back-contact", "back-separation"};
    return kind >= 0 && kind < GD_EV_NKINDS ? names[kind] : "?";
}

/* A value of a root function exactly on its boundary (g = 0) counts as the side of the held mode:
 * ARKODE switches off a root function that is exactly zero where it restarts, and a crossing back
 * in the first step after an event on the boundary (a grazing separation) would go unseen. */
#define ON_BOUNDARY 1e-100

static int root_fn(sunrealtype t, N_Vector y, sunrealtype *g, void *user)
{
    gd_sim *s = user;
    double sn, cs;
    sim_phase_at(s, t, &sn, &cs);
    gd_model_roots_sc(&s->m, t, sn, cs, NV_DATA_S(y), g, &s->md);
    s->nroot_evals++;
    for (int i = 0; i < s->nroots; i++)
        if (g[i] == 0.0) {
            int mode = s->md.mode[i / 2]; /* g[2c] = x - h > 0 in mode +1; g[2c+1] = x + h < 0 in mode -1 */
            g[i] = (i % 2 == 0 ? mode > 0 : mode >= 0) ? ON_BOUNDARY : -ON_BOUNDARY;
        }
    /* a solution gone NaN or infinite inside a step (an unstable fixed step) would send
     * ARKODE's root search around for ever: fail the step instead */
    for (int i = 0; i < s->nroots; i++)
        if (!isfinite(g[i])) {
            s->nonfinite = 1;
            return -1;
        }
    return 0;
}

/* Root finding: ARKODE gets the root functions at the start (ungated), or only while it
 * locates a crossing (gated: gd_sim_arm_roots). */
gd_status gd_sim_roots_setup(gd_sim *s, gd_error *err)
{
    const gd_model *m = &s->m;
    const gd_solver_opts *o = &s->o;
    if (o->root_finding && m->nclear > 0) {
        s->nroots = 2 * m->nclear;
        s->gate = !o->ungated_roots && o->refine_events && !s->implicit && o->method != GD_METHOD_RK4 && !o->fixed_step;
        if (!s->gate) {
            CHECK(s->ops->root_init(s->mem, s->nroots, root_fn));
            CHECK(s->ops->set_no_inactive_root_warn(s->mem));
            s->armed = 1;
        }
    }
    return GD_OK;
}

typedef double v2 __attribute__((vector_size(16))); /* two lanes, each its own IEEE operations */

/* The cubic Hermite through (0, g0) and (1, g1) with end rates d0, d1 (rates times the step), at
 * two points x in [0, 1] at once: g0 h00 + d0 h10 + g1 h01 + d1 h11. */
static inline v2 hermite3_2(double g0, double d0, double g1, double d1, v2 x)
{
    v2 h00 = (1.0 + 2.0 * x) * (1.0 - x) * (1.0 - x), h10 = x * (1.0 - x) * (1.0 - x);
    v2 h01 = x * x * (3.0 - 2.0 * x), h11 = x * x * (x - 1.0);
    return g0 * h00 + d0 * h10 + g1 * h01 + d1 * h11;
}

/* the same at one point */
static inline double hermite3(double g0, double d0, double g1, double d1, double x)
{
    return hermite3_2(g0, d0, g1, d1, (v2){x, x})[0];
}

/* Cubic Hermite of g over a step (values g0, g1, rates d0, d1 times h): does it cross
 * zero and come back? Returns the fraction of the step at the far extremum, or -1. */
static double grazing_fraction(double g0, double g1, double d0, double d1)
{
    if ((g0 > 0) != (g1 > 0) || g0 == 0.0 || g1 == 0.0)
        return -1.0;
    /* most steps: p keeps the sign of g0 for a simple reason. h00 + h01 = 1 with both >= 0, and
     * s (1 - s)^2 and s^2 (1 - s) are at most 4/27 on [0, 1], so |p(s)| >= min(|g0|, |g1|) - 4/27
     * (the rate terms that point towards zero) */
    double sg = g0 > 0 ? 1.0 : -1.0;
    /* fmin and fmax written out (the values are finite: the step ended on a finite state), so
     * that this test, made for every side of every clearance at every step, calls no function */
    double a0 = sg * g0, a1 = sg * g1, r0 = -sg * d0, r1 = sg * d1;
    if ((a0 < a1 ? a0 : a1) > (4.0 / 27.0) * ((r0 > 0.0 ? r0 : 0.0) + (r1 > 0.0 ? r1 : 0.0)))
        return -1.0;
    /* p(s) = g0 h00 + d0 h10 + g1 h01 + d1 h11; p'(s) = A s^2 + B s + C */
    double A = 6 * g0 + 3 * d0 - 6 * g1 + 3 * d1;
    double B = -6 * g0 - 4 * d0 + 6 * g1 - 2 * d1;
    double C = d0;
    double roots[2];
    int nr = 0;
    if (fabs(A) < 1e-300) {
        if (fabs(B) > 1e-300)
            roots[nr++] = -C / B;
    } else {
        double disc = B * B - 4 * A * C;
        if (disc >= 0) {
            double sq = sqrt(disc);
            double q = -0.5 * (B + (B >= 0 ? sq : -sq));
            roots[nr++] = q / A;
            if (q != 0)
                roots[nr++] = C / q;
        }
    }
    for (int i = 0; i < nr; i++) {
        double x = roots[i];
        if (!(x > 0 && x < 1))
            continue;
        double p = hermite3(g0, d0, g1, d1, x);
        if ((p > 0) != (g0 > 0))
            return x;
    }
    return -1.0;
}

/* The clearance coordinates and rates at the current (t, y) (gd_sim_clearances_now); the sine and
 * cosine of Omega t from the cache (the step's last stage was at its end). */
void gd_sim_clearances_compute(gd_sim *s)
{
    double sn, cs;
    sim_phase_at(s, s->t, &sn, &cs);
    gd_model_clearances_sc(&s->m, s->t, sn, cs, NV_DATA_S(s->y), &s->md, s->cx, s->cv);
    s->cx_ok = 1;
}

/* One side g = x + off of a clearance for the grazing watch (values g0, g1 at the step's ends, rates
 * d0, d1 times the step dt): the earlier of best and the time of a touch hidden inside the step.
 * The test of grazing_fraction with both rates counted towards zero (reach, shared by the two
 * sides) comes first: where it holds, grazing_fraction's own (with a part of the rates, rounded
 * monotonically) holds too and returns -1, so the skip changes no result. */
static inline double graze_side(double g0, double g1, double d0, double d1, double reach, double t0, double dt,
                                double best)
{
    double a0 = fabs(g0), a1 = fabs(g1);
    if ((a0 < a1 ? a0 : a1) > reach)
        return best;
    double f = grazing_fraction(g0, g1, d0, d1);
    if (f > 0) {
        double tc = t0 + f * dt;
        if (best < 0 || tc < best)
            best = tc;
    }
    return best;
}

/* A touch hidden inside the step [t0, t1]? Returns the time to stop at, or -1. The clearances at
 * t0 are in cx0, cv0, those at t1 (the current state) in cx, cv. */
static double grazing_check(gd_sim *s, double t0, double t1)
{
    double best = -1.0;
    gd_sim_clearances_now(s);
    const double dt = t1 - t0;
    for (int c = 0; c < s->m.nclear; c++) {
        double x0 = s->cx0[c], x1 = s->cx[c], d0 = s->cv0[c] * dt, d1 = s->cv[c] * dt;
        double h = s->m.clear[c].h, reach = (4.0 / 27.0) * (fabs(d0) + fabs(d1));
        best = graze_side(x0 + -h, x1 + -h, d0, d1, reach, t0, dt, best); /* g = x - h */
        best = graze_side(x0 + h, x1 + h, d0, d1, reach, t0, dt, best);   /* g = x + h */
    }
    return best;
}

/* The near-grazing watch after a step [t0, t1] that located no root: a crossing and return hidden
 * inside the step (grazing_check) rewinds the step to t0 with the root functions on; *tg is then
 * the time of the suspected touch, where the redone steps are to stop (> 0), else no rewind. */
gd_status gd_sim_grazing_watch(gd_sim *s, double t0, double t1, double *tg, gd_error *err)
{
    s->t = t1;
    double tgz = grazing_check(s, t0, t1);
    *tg = tgz;
    if (tgz > 0) {
        s->grazing_suspects++;
        s->grazing_rewinds++;
        memcpy(NV_DATA_S(s->y), s->y_prev, sizeof(double) * (size_t)s->N);
        s->t = t0;
        memcpy(s->cx, s->cx0, sizeof s->cx);
        memcpy(s->cv, s->cv0, sizeof s->cv);
        s->cx_ok = 1;
        gd_status st = gd_sim_arm_roots(s, 1, err); /* the redone steps locate the touch */
        if (st == GD_OK)
            st = gd_sim_reset_at(s, t0, err);
        if (st != GD_OK)
            return st;
        if (s->o.method != GD_METHOD_RK4 && !s->o.fixed_step)
            s->ops->set_init_step(s->mem, 0.5 * (tgz - t0));
    }
    return GD_OK;
}

GD_API void gd_sim_watch_gaps(gd_sim *s, gd_gap_extrema *g)
{
    s->gaps = g;
    if (!g)
        return;
    memset(g, 0, sizeof *g);
    for (int c = 0; c < s->m.nclear; c++)
        g->h[c] = s->m.clear[c].h;
}

typedef struct gap_rate {
    gd_sim *s;
    int c;
    gd_status st;
    gd_error *err;
    double x; /* the coordinate at the last time evaluated */
} gap_rate;

/* the rate of clearance c on the dense output at absolute time t (GSL's gsl_function) */
static double gap_rate_at(double t, void *params)
{
    gap_rate *r = params;
    double y[GD_MAX_STATE], v = NAN;
    r->st = gd_sim_dense(r->s, t, y, r->err);
    if (r->st == GD_OK)
        gd_model_clearance(&r->s->m, r->c, t - (double)r->s->shift * r->s->m.period, y, &r->s->md, &r->x, &v);
    return v;
}

/* The extremum of clearance c in [ta, tb], where its rate changes sign (va its rate at ta), located by
 * GSL's Brent solver on the rate of the dense output and recorded in s->gaps. */
static gd_status gap_extremum(gd_sim *s, int c, double ta, double tb, double va, gd_error *err)
{
    gd_gap_extrema *g = s->gaps;
    gap_rate r = {s, c, GD_OK, err, 0.0};
    gsl_function F = {gap_rate_at, &r};
    gsl_root_fsolver *rs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!rs)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the gap watch");
    int rc = gsl_root_fsolver_set(rs, &F, ta, tb), conv = GSL_CONTINUE;
    for (int it = 0; it < 100 && rc == GSL_SUCCESS && conv == GSL_CONTINUE; it++) {
        rc = gsl_root_fsolver_iterate(rs);
        conv = gsl_root_test_interval(gsl_root_fsolver_x_lower(rs), gsl_root_fsolver_x_upper(rs),
                                      1e-13 * s->m.period, 0.0);
    }
    double tr = gsl_root_fsolver_root(rs);
    gsl_root_fsolver_free(rs);
    if (r.st != GD_OK)
        return r.st;
    if (rc != GSL_SUCCESS) /* (after 100 iterations the estimate stands: the coordinate is flat there) */
        return gd_error_set(err, GD_ERR_GSL, "the gap watch of %s: gsl_root_fsolver_brent: %s", s->m.clear[c].name,
                            gsl_strerror(rc));
    gap_rate_at(tr, &r);
    if (r.st != GD_OK)
        return r.st;
    if (g->n[c] == GD_GAP_EXTREMA_MAX) {
        g->dropped++;
        return GD_OK;
    }
    g->t[c][g->n[c]] = tr;
    g->x[c][g->n[c]] = r.x;
    g->kind[c][g->n[c]++] = va >= 0 ? 1 : -1;
    return GD_OK;
}

/* Where, as a fraction of the step, the cubic Hermite of the coordinate (values x0, x1, rates d0, d1
 * times the step) has the extremum of its rate between two interior zeros of it: a pair of extrema
 * inside the step although the rate has the same sign at both ends (how a pair is born). -1 for
 * none. */
static double pair_fraction(double x0, double x1, double d0, double d1)
{
    /* p'(u) = A u^2 + B u + C on [0, 1] */
    double A = 6 * x0 + 3 * d0 - 6 * x1 + 3 * d1, B = -6 * x0 - 4 * d0 + 6 * x1 - 2 * d1, C = d0;
    if (!(fabs(A) > 0))
        return -1.0;
    double disc = B * B - 4 * A * C;
    if (!(disc > 0))
        return -1.0;
    double sq = sqrt(disc), q = -0.5 * (B + (B >= 0 ? sq : -sq)), r1 = q / A, r2 = q != 0 ? C / q : -1.0;
    if (!(r1 > 0 && r1 < 1 && r2 > 0 && r2 < 1))
        return -1.0;
    return -B / (2 * A); /* the vertex of p', between the two zeros */
}

/* The gap watch over the step [t0, t1] (absolute): each clearance whose rate changes sign inside
 * it has an extremum there, located by GSL's Brent solver on the rate of the dense output (the
 * same values and rates at the step's ends as the grazing watch, with the septic interpolant in
 * between). Where the rate has the same sign at both ends, a pair of extrema may still lie inside
 * the step: when the cubic Hermite of the coordinate shows one, and the rate of the dense output
 * has the other sign at the Hermite rate's extremum, both halves of the step are searched. */
static gd_status gap_watch(gd_sim *s, double t0, double t1, gd_error *err)
{
    for (int c = 0; c < s->m.nclear; c++) {
        gap_rate r = {s, c, GD_OK, err, 0.0};
        double v0 = gap_rate_at(t0, &r), x0 = r.x, v1 = gap_rate_at(t1, &r), x1 = r.x;
        if (r.st != GD_OK)
            return r.st;
        gd_status st = GD_OK;
        if ((v0 >= 0) != (v1 >= 0)) {
            st = gap_extremum(s, c, t0, t1, v0, err);
        } else {
            double f = pair_fraction(x0, x1, v0 * (t1 - t0), v1 * (t1 - t0));
            if (f > 0) {
                double tm = t0 + f * (t1 - t0), vm = gap_rate_at(tm, &r);
                if (r.st != GD_OK)
                    return r.st;
                if ((vm >= 0) != (v0 >= 0)) {
                    st = gap_extremum(s, c, t0, tm, v0, err);
                    if (st == GD_OK)
                        st = gap_extremum(s, c, tm, t1, vm, err);
                }
            }
        }
        if (st != GD_OK)
            return st;
    }
    return GD_OK;
}

gd_status gd_sim_after_step(gd_sim *s, double t0, double t1, gd_error *err)
{
    if (s->gaps && t1 > t0) {
        gd_status st = gap_watch(s, t0, t1, err);
        if (st != GD_OK)
            return st;
    }
    if (s->step_hook && s->step_hook(s, t0, t1, s->hook_user))
        return gd_error_set(err, GD_ERR_INTERRUPTED, "stopped by the step hook");
    return GD_OK;
}

static int new_mode_for(int old, int r_hi, int r_lo)
{
    /* r_hi: crossing of x - h; r_lo: crossing of x + h (+1 up, -1 down, 0 none) */
    if (r_hi && r_lo)
        return r_hi > 0 ? 1 : -1;
    if (r_hi)
        return r_hi > 0 ? 1 : 0;
    if (r_lo)
        return r_lo < 0 ? -1 : 0;
    return old;
}

static int kind_of(int old, int nw)
{
    return nw == 1 ? GD_EV_CONTACT : nw == -1 ? GD_EV_BACK_CONTACT : old == 1 ? GD_EV_SEPARATION
                                                                          : GD_EV_BACK_SEPARATION;
}

static gd_status record_event(gd_sim *s, int c, int old, int nw, int direction, int located, gd_error *err)
{
    gd_event ev;
    ev.t = sim_abs_time(s, s->t);
    ev.period = s->period;
    ev.clearance = c;
    ev.old_mode = old;
    ev.new_mode = nw;
    ev.direction = direction;
    ev.located = located;
    ev.kind = kind_of(old, nw);
    gd_model_clearance(&s->m, c, s->t, NV_DATA_S(s->y), &s->md, &ev.x, &ev.xdot);
    s->events++;
    s->by_kind[ev.kind]++;
    s->by_clear[c]++;
    s->events_this_period++;
    if (s->event_hook && s->event_hook(s, &ev, s->hook_user))
        return gd_error_set(err, GD_ERR_INTERRUPTED, "stopped by the event hook");
    return GD_OK;
}

/* Tangent vectors across the switching surface of clearance c (mode about to become nw):
 * d+ = d + (f+ - f-) (n . d) / (n . f- + dg/dt), n = grad of g = w.x - e(t) -/+ h. With a
 * continuous dead-zone force and damping that acts always, f+ = f- and this is the identity;
 * damping in contact only makes the vector field jump. */
static void saltation(gd_sim *s, int c, int nw)
{
    const gd_model *m = &s->m;
    const int n = m->n, nd = m->ndof;
    double *y = NV_DATA_S(s->y);
    double fm[GD_MAX_STATE], fp[GD_MAX_STATE];
    gd_model_rhs(m, s->t, y, fm, &s->md);
    int old = s->md.mode[c];
    s->md.mode[c] = nw;
    gd_model_rhs(m, s->t, y, fp, &s->md);
    s->md.mode[c] = old;
    s->extra_rhs += 2;
    double x, xdot;
    gd_model_clearance(m, c, s->t, y, &s->md, &x, &xdot); /* n . f- + dg/dt */
    if (fabs(xdot) < 1e-300)
        return;
    const gd_clearance *cl = &m->clear[c];
    for (int v = 1; v <= s->k; v++) {
        double *d = y + v * n;
        double nd_ = 0;
        for (int q = 0; q < cl->nw; q++)
            nd_ += cl->wval[q] * d[cl->widx[q]];
        double f = nd_ / xdot;
        for (int i = nd; i < n; i++) /* only accelerations can jump */
            d[i] += (fp[i] - fm[i]) * f;
    }
}

/* Where the method itself crosses. ARKODE locates a root on its Hermite interpolant over the
 * step [t0, t1] (cubic by default: no RHS evaluation of its own), which is less accurate than
 * the method. The step is redone with the method from t0 to a little past that root,
 * tr + REFINE_MARGIN (t1 - t0), with root finding on: the crossing is then located again on the
 * interpolant of the redone step, whose end point is the method's solution and lies just past
 * the crossing, so the interpolation error at the root is smaller by about (margin / step)^2
 * and the state at the event has the method's accuracy. The roots found by the redone step
 * replace the first ones (they are the method's). If the interpolant's root was early by more
 * than the margin, the step goes on to t1; if the method does not cross in [t0, t1] at all, no
 * root is reported and the run goes on from t1. Each redone piece is one ARKODE step, and the
 * step hook runs for it on its interpolant. */
#define REFINE_MARGIN 1e-4

/* Give ARKODE the root functions (on) or take them away (gated root finding only). */
gd_status gd_sim_arm_roots(gd_sim *s, int on, gd_error *err)
{
    if (!s->gate || s->armed == on)
        return GD_OK;
    int flag = s->ops->root_init(s->mem, on ? s->nroots : 0, on ? root_fn : NULL);
    if (flag >= 0 && on)
        flag = s->ops->set_no_inactive_root_warn(s->mem);
    if (flag < 0)
        return gd_sim_sun_check(s, flag, "RootInit", err);
    s->armed = on;
    return GD_OK;
}

/* The bisection of the cubic Hermite p of a root function over the step's fraction [0, 1] (values
 * g0, g1, rates d0, d1 times the step) for a sign change: p(lo) on the held side (held = +1 or -1),
 * p(hi) past it, 48 halvings; returns hi. Two halvings a round: p at the midpoint and at the two
 * points the next halving may test are independent evaluations the processor overlaps, where one
 * halving at a time waits for each value before the next point is known. The points (the same
 * sums, halved) and the decisions are those of one halving at a time, and so is hi, to the bit. */
double gd_sim_bisect_crossing(double g0, double d0, double g1, double d1, double held)
{
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 48; it += 2) {
        double m = 0.5 * (lo + hi), ql = 0.5 * (lo + m), qh = 0.5 * (m + hi);
        double pm = hermite3(g0, d0, g1, d1, m);
        v2 pq = hermite3_2(g0, d0, g1, d1, (v2){ql, qh});
        /* p(m) past: hi = m, and the next point is 0.5 (lo + m) = ql; else lo = m, and it is
         * 0.5 (m + hi) = qh. The quarter [b[k], b[k + 1]] kept, chosen without a branch. */
        int past = pm * held < 0, past_l = pq[0] * held < 0, past_h = pq[1] * held < 0;
        int k = 3 - 2 * past - ((past & past_l) | ((!past) & past_h));
        double b[5] = {lo, ql, m, qh, hi};
        lo = b[k];
        hi = b[k + 1];
    }
    return hi;
}

/* Gated root finding, after a step [t0, t1] taken without the root functions: the time at which a
 * root function changed sign, by ARKODE's rule (a value exactly zero counts as the side of the held
 * mode, as in root_fn), estimated as the first zero of the cubic Hermite of g from the clearances
 * and rates at both ends; -1 when none changed sign. The estimate only places the end of the step
 * that ARKODE then redoes with its root finding on (refine_root_state), which locates the root. */
double gd_sim_crossing_in_step(gd_sim *s, double t0, double t1)
{
    double best = -1.0, dt = t1 - t0;
    gd_sim_clearances_now(s);
    for (int c = 0; c < s->m.nclear; c++) {
        int mode = s->md.mode[c];
        double h = s->m.clear[c].h, x0 = s->cx0[c], x1 = s->cx[c];
        /* a sign change of x - h or x + h needs the two ends on different sides of h or -h (the
         * rounded sums keep the signs of the exact ones): with both strictly in one of the three
         * regions a half gap h >= 0 makes, neither side can report one (most steps) */
        if (h >= 0.0 && ((x0 > h && x1 > h) || (x0 < -h && x1 < -h) || (x0 > -h && x0 < h && x1 > -h && x1 < h)))
            continue;
        for (int side = 0; side < 2; side++) { /* g = x - h (side 0), x + h (side 1) */
            double off = side ? h : -h;
            double held = side == 0 ? (mode > 0 ? 1.0 : -1.0) : (mode >= 0 ? 1.0 : -1.0);
            double g0 = s->cx0[c] + off, g1 = s->cx[c] + off;
            if (!(g1 * held < 0) || g0 * held < 0)
                continue;
            double hi = gd_sim_bisect_crossing(g0, s->cv0[c] * dt, g1, s->cv[c] * dt, held);
            /* a root in the step's first instant (a second clearance crossing just after one
             * handled at t0) still gets a piece of step for ARKODE to find it in (hi > 0: fmax
             * written out) */
            double tc = t0 + (hi > 1e-9 ? hi : 1e-9) * dt;
            if (best < 0 || tc < best)
                best = tc;
        }
    }
    return best;
}

static gd_status refine_root_state(gd_sim *s, double t0, double tr, gd_error *err)
{
    double t1 = tr;
    if (s->ops->get_current_time(s->mem, &t1) < 0 || !(t1 >= tr))
        t1 = tr;
    if (!(tr > t0))
        return GD_OK;
    int fixed = s->o.method == GD_METHOD_RK4 || s->o.fixed_step;
    double target = fmin(t1, tr + REFINE_MARGIN * (t1 - t0)), ta = t0;
    s->h_resume = t1 - t0;
    memcpy(NV_DATA_S(s->y), s->y_prev, sizeof(double) * (size_t)s->N);
    gd_status ast = gd_sim_arm_roots(s, 1, err);
    if (ast != GD_OK)
        return ast;
    int flag = s->ops->reset(s->mem, t0, s->y), found = 0;
    if (flag >= 0)
        flag = fixed ? s->ops->set_fixed_step(s->mem, target - t0) : s->ops->set_init_step(s->mem, target - t0);
    s->resets++;
    while (flag >= 0) {
        flag = s->ops->set_stop_time(s->mem, target);
        double t2 = ta;
        if (flag >= 0)
            flag = s->ops->evolve(s->mem, target, s->y, &t2, ARK_ONE_STEP);
        if (flag < 0)
            break;
        s->t_step0 = ta;
        s->t = t2;
        s->cx_ok = 0;
        gd_status hst = gd_sim_after_step(s, sim_abs_time(s, ta), sim_abs_time(s, t2), err);
        if (hst != GD_OK)
            return hst;
        if (flag == ARK_ROOT_RETURN) {
            flag = s->ops->get_root_info(s->mem, s->rootsfound);
            found = 1;
            break;
        }
        if (!(t2 < t1))
            break; /* the method did not cross in this step */
        if (!(t2 < target)) { /* the crossing lies beyond the margin: on to the end of the step */
            target = t1;
            if (fixed)
                flag = s->ops->set_fixed_step(s->mem, t1 - t2);
        }
        ta = t2;
    }
    if (fixed && flag >= 0) {
        int f2 = s->ops->set_fixed_step(s->mem, s->m.period / s->o.steps_per_period);
        if (f2 < 0)
            flag = f2;
    }
    if (flag < 0)
        return gd_sim_sun_check(s, flag, "refining the state at an event", err);
    if (!found)
        memset(s->rootsfound, 0, sizeof s->rootsfound);
    return GD_OK;
}

static gd_status handle_roots(gd_sim *s, gd_error *err)
{
    for (int c = 0; c < s->m.nclear; c++) {
        int r_hi = s->rootsfound[2 * c], r_lo = s->rootsfound[2 * c + 1];
        if (!r_hi && !r_lo)
            continue;
        int old = s->md.mode[c];
        int nw = new_mode_for(old, r_hi, r_lo);
        if (nw == old)
            continue;
        if (s->k > 0)
            saltation(s, c, nw);
        s->md.mode[c] = nw;
        gd_status st = record_event(s, c, old, nw, (r_hi ? r_hi : r_lo) > 0 ? 1 : -1, 1, err);
        if (st != GD_OK)
            return st;
    }
    /* Another clearance may have crossed within the root tolerance of this one (two halves
     * that touch together, up to rounding) or once the state was refined: a coordinate past
     * a boundary its held mode does not allow switches here and now, or ARKODE, restarting
     * with the root function already past zero, would never see that crossing. */
    gd_sim_clearances_now(s);
    for (int c = 0; c < s->m.nclear; c++) {
        if (s->rootsfound[2 * c] || s->rootsfound[2 * c + 1])
            continue;
        double x = s->cx[c], xd = s->cv[c];
        int old = s->md.mode[c], nw = model_mode_of(&s->m, c, x);
        if (nw == old)
            continue;
        if (s->k > 0)
            saltation(s, c, nw);
        s->md.mode[c] = nw;
        gd_status st = record_event(s, c, old, nw, xd >= 0 ? 1 : -1, 1, err);
        if (st != GD_OK)
            return st;
    }
    if (s->events_this_period > s->o.max_events_per_period)
        return gd_error_set(err, GD_ERR_CHATTER,
                            "chattering: more than %d events in mesh period %ld (t = %.9g periods) without progress; "
                            "raise solver.max_events_per_period or look at the event log",
                            s->o.max_events_per_period, s->period, sim_abs_time(s, s->t) / s->m.period);
    return gd_sim_reset_at(s, s->t, err);
}

/* The roots of the step [t0, tret] that ended with flag: ARKODE's (ARK_ROOT_RETURN; refined with the
 * method when refine), or, with gated root finding, the crossing the step-end check found near tc
 * (> 0), which ARKODE locates on the redone step. *handled: the modes were switched here. */
gd_status gd_sim_roots_after_step(gd_sim *s, int flag, int refine, double t0, double tret, double tc, int *handled,
                                  gd_error *err)
{
    int hd = 0;
    *handled = 0;
    if (flag == ARK_ROOT_RETURN) {
        int f2 = s->ops->get_root_info(s->mem, s->rootsfound);
        if (f2 < 0)
            return gd_sim_sun_check(s, f2, "GetRootInfo", err);
        if (refine) { /* the hook runs on the redone pieces */
            gd_status st = refine_root_state(s, t0, tret, err);
            if (st != GD_OK)
                return st;
        }
        gd_status st = handle_roots(s, err);
        if (st != GD_OK)
            return st;
        *handled = 1;
    } else if (tc > 0) { /* ARKODE redoes the step with its root finding on and locates it */
        memset(s->rootsfound, 0, sizeof s->rootsfound);
        gd_status st = refine_root_state(s, t0, tc, err);
        if (st != GD_OK)
            return st;
        for (int i = 0; i < s->nroots; i++)
            hd |= s->rootsfound[i] != 0;
        if (hd) {
            st = handle_roots(s, err);
            if (st != GD_OK)
                return st;
            *handled = 1;
        }
    }
    return GD_OK;
}

/* Root finding on, after a step that ended without a root: a held mode the state has left by
 * more than 1e-6 (1 + h) is a crossing the root finding could not see. It happens at a grazing
 * contact: a separation located exactly on the boundary restarts its root function at exactly
 * zero, ARKODE deactivates it, and a return to contact within the first instants of the next
 * step is never reported; the teeth would then pass through each other without force. The mode
 * is switched at the step end and the event logged as not located (located = 0). The threshold
 * is far above the distance (about 1e-8) a refined event state may lie on the old side of its
 * boundary, and far below any physical length. */
gd_status gd_sim_repair_held_modes(gd_sim *s, gd_error *err)
{
    int changed = 0;
    gd_sim_clearances_now(s);
    for (int c = 0; c < s->m.nclear; c++) {
        double x = s->cx[c], h = s->m.clear[c].h;
        int old = s->md.mode[c], nw = model_mode_of(&s->m, c, x);
        if (nw == old)
            continue;
        /* distance past the boundary of the region the held mode allows */
        double past = old > 0 ? h - x : old < 0 ? x + h : fabs(x) - h;
        if (!(past > 1e-6 * (1.0 + fabs(h))))
            continue;
        if (s->k > 0)
            saltation(s, c, nw);
        s->md.mode[c] = nw;
        changed = 1;
        gd_status st = record_event(s, c, old, nw, nw > old ? 1 : -1, 0, err);
        if (st != GD_OK)
            return st;
    }
    return changed ? gd_sim_reset_at(s, s->t, err) : GD_OK;
}

/* Root finding off: the modes follow the state; a change between two step ends is
 * reported as an event at the step end (not located, as a fixed-step user would see it). */
gd_status gd_sim_modes_from_state(gd_sim *s, gd_error *err)
{
    const double *y = NV_DATA_S(s->y);
    for (int c = 0; c < s->m.nclear; c++) {
        double x, v;
        gd_model_clearance(&s->m, c, s->t, y, &s->md, &x, &v);
        int nw = model_mode_of(&s->m, c, x), old = s->md.mode[c];
        if (nw == old)
            continue;
        s->md.mode[c] = nw;
        gd_status st = record_event(s, c, old, nw, nw > old ? 1 : -1, 0, err);
        if (st != GD_OK)
            return st;
    }
    if (s->events_this_period > s->o.max_events_per_period)
        return gd_error_set(err, GD_ERR_CHATTER, "chattering: more than %d events in mesh period %ld",
                            s->o.max_events_per_period, s->period);
    return GD_OK;
}

