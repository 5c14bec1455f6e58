/* The errors of a work-precision run against the reference where users look (the Poincare points
 * over the window and over the short horizon, the RMS acceleration, the event times), the orders
 * fitted to the order study, and the cheapest run that reaches a target (docs/accuracy.md). */
#include "wp_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

GD_API double gd_workprec_poincare_error(const double *a, const double *b, long npts, int n)
{
    if (npts <= 0)
        return NAN;
    double worst = 0;
    for (int i = 0; i < n; i++) {
        double sc = 0;
        for (long k = 0; k < npts; k++)
            sc = fmax(sc, fabs(b[k * n + i]));
        sc += 1.0;
        for (long k = 0; k < npts; k++) {
            double d = fabs(a[k * n + i] - b[k * n + i]) / sc;
            if (!(d <= worst)) /* also catches NaN */
                worst = isnan(d) ? INFINITY : d;
        }
    }
    return worst;
}

static int ev_cmp(const void *pa, const void *pb)
{
    const wp_ev *a = pa, *b = pb;
    if (a->clearance != b->clearance)
        return a->clearance - b->clearance;
    if (a->kind != b->kind)
        return a->kind - b->kind;
    return (a->t > b->t) - (a->t < b->t);
}

/* Largest |t - t_ref| (mesh periods, capped at 1) over the reference events before t_end, to
 * the nearest event of the same clearance and kind; 0 when there are no reference events. */
static double event_error(const wp_trace *ref, const wp_trace *tr, double t_end, double period, gd_error *err,
                          gd_status *st)
{
    *st = GD_OK;
    if (ref->nev == 0)
        return tr->nev == 0 ? 0.0 : 1.0;
    wp_ev *s = NULL;
    if (tr->nev > 0) {
        s = malloc(sizeof *s * (size_t)tr->nev);
        if (!s) {
            *st = gd_error_set(err, GD_ERR_NOMEM, "out of memory matching events");
            return NAN;
        }
        memcpy(s, tr->ev, sizeof *s * (size_t)tr->nev);
        qsort(s, (size_t)tr->nev, sizeof *s, ev_cmp);
    }
    double worst = 0;
    for (long i = 0; i < ref->nev; i++) {
        const wp_ev *r = &ref->ev[i];
        if (r->t > t_end)
            continue;
        /* lower bound of (clearance, kind, t) */
        long lo = 0, hi = tr->nev;
        while (lo < hi) {
            long mid = (lo + hi) / 2;
            if (ev_cmp(&s[mid], r) < 0)
                lo = mid + 1;
            else
                hi = mid;
        }
        double best = INFINITY;
        for (long j = lo - 1; j <= lo; j++)
            if (j >= 0 && j < tr->nev && s[j].clearance == r->clearance && s[j].kind == r->kind)
                best = fmin(best, fabs(s[j].t - r->t));
        worst = fmax(worst, fmin(1.0, best / period));
    }
    free(s);
    return worst;
}

void wp_fill_run(gd_wp_run *r, const wp_trace *tr, const wp_trace *ref, long periods, long horizon, int chaotic,
                 double period, int n, gd_error *err, gd_status *st)
{
    *st = GD_OK;
    r->status = tr->status;
    snprintf(r->message, sizeof r->message, "%s", tr->msg);
    r->periods = periods;
    r->rhs_evals = tr->stats.rhs_evals;
    r->steps = tr->stats.steps;
    r->step_attempts = tr->stats.step_attempts;
    r->root_evals = tr->stats.root_evals;
    r->jac_evals = tr->stats.jac_evals;
    r->events = tr->stats.events;
    r->flipflop_events = tr->flipflops;
    r->ref_events = 0;
    for (long i = 0; i < ref->nev; i++)
        r->ref_events += !chaotic || ref->ev[i].t <= horizon * period;
    r->err_poincare = r->err_short = r->err_rms = r->err_events = r->err_mle = NAN;
    r->rms_accel_mps2 = r->mle_per_period = NAN;
    if (!tr->complete)
        return;
    r->rms_accel_mps2 = tr->rms;
    r->err_poincare = gd_workprec_poincare_error(tr->pts, ref->pts, periods + 1, n);
    long h = horizon < periods ? horizon : periods;
    r->err_short = gd_workprec_poincare_error(tr->pts, ref->pts, h + 1, n);
    if (isfinite(tr->rms) && isfinite(ref->rms))
        r->err_rms = fabs(tr->rms - ref->rms) / fmax(fabs(ref->rms), 1e-300);
    double t_end = (chaotic ? (double)h : (double)periods) * period;
    r->err_events = event_error(ref, tr, t_end, period, err, st);
}

static double slope(const gd_wp_order *o, int from, int to)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0, nn = to - from + 1;
    for (int i = from; i <= to; i++) {
        double xv = log((double)o->steps[i]), yv = log(o->err[i]);
        sx += xv;
        sy += yv;
        sxx += xv * xv;
        sxy += xv * yv;
    }
    return -(nn * sxy - sx * sy) / (nn * sxx - sx * sx);
}

/* The valid levels (error between 100 x floor and 1e-2: above the reference floor, past the
 * unstable or pre-asymptotic start) and the orders fitted over them (gd_wp_order). */
void wp_fit_order(gd_wp_order *o, double floor_)
{
    o->order = o->order_range = NAN;
    o->fit_from = o->fit_to = o->range_from = -1;
    int best_from = -1, best_len = 0;
    for (int i = 0; i < o->nlevels;) {
        if (!(isfinite(o->err[i]) && o->err[i] > 100.0 * floor_ && o->err[i] < 1e-2)) {
            i++;
            continue;
        }
        int j = i;
        while (j < o->nlevels && isfinite(o->err[j]) && o->err[j] > 100.0 * floor_ && o->err[j] < 1e-2)
            j++;
        if (j - i > best_len) {
            best_len = j - i;
            best_from = i;
        }
        i = j;
    }
    if (best_len < 2)
        return;
    int last = best_from + best_len - 1;
    o->range_from = best_from;
    o->order_range = slope(o, best_from, last);
    o->fit_to = last;
    o->fit_from = best_len > 3 ? last - 2 : best_from;
    o->order = slope(o, o->fit_from, last);
}

GD_API int gd_workprec_cheapest(const gd_wp_result *res, double target, int with_events)
{
    int best = -1;
    for (int i = 0; i < res->nruns; i++) {
        const gd_wp_run *r = &res->runs[i];
        if (r->status != GD_WP_OK)
            continue;
        int ok = res->ref.chaotic ? r->err_short <= target : r->err_poincare <= target && r->err_rms <= target;
        if (with_events)
            ok = ok && r->err_events <= target;
        if (ok && (best < 0 || r->cpu_s < res->runs[best].cpu_s))
            best = i;
    }
    return best;
}
