/* The `work-precision` analysis on the command line (docs/accuracy.md): the grid as it runs,
 * the work-precision diagrams (work_precision.png/.svg) and the summary lines. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void fmt_err(char *buf, size_t len, double v)
{
    if (isfinite(v))
        snprintf(buf, len, "%.2e", v);
    else
        snprintf(buf, len, "-");
}

int cli_workprec_start(void *user, const char *what, const char *label, int index, int total)
{
    cli_progress *o = user;
    if (o->quiet)
        return 0;
    if (strcmp(what, "grid") != 0 && strcmp(what, "order") != 0)
        printf("  %s: %s\n", what, label);
    else if (o->tty)
        fprintf(stderr, "\rgeardyn: %s %d/%d: %-40s", what, index + 1, total, label);
    fflush(stdout);
    return 0;
}

int cli_workprec_done(void *user, const char *what, const gd_wp_run *r, const gd_wp_result *res)
{
    cli_progress *o = user;
    if (o->quiet || strcmp(what, "grid") != 0)
        return 0;
    if (o->tty)
        fprintf(stderr, "\r%80s\r", "");
    char a[16], b[16], c[16], d[16];
    fmt_err(a, sizeof a, res->ref.chaotic ? r->err_short : r->err_poincare);
    fmt_err(b, sizeof b, r->err_rms);
    fmt_err(c, sizeof c, r->err_events);
    fmt_err(d, sizeof d, r->err_mle);
    if (r->status == GD_WP_OK)
        printf("  %-22s %8.3f s %9.1f RHS/period %7ld events   %s %s  rms %s  events %s%s%s\n", r->label, r->cpu_s,
               (double)r->rhs_evals / (double)r->periods, r->events, res->ref.chaotic ? "short" : "poincare", a, b, c,
               isfinite(r->err_mle) ? "  mle " : "", isfinite(r->err_mle) ? d : "");
    else
        printf("  %-22s %s%s%s\n", r->label, gd_wp_status_name(r->status), r->message[0] ? ": " : "", r->message);
    fflush(stdout);
    return 0;
}

void cli_workprec_announce(const char *dir, const gd_case *c)
{
    printf("%s: work-precision of %s, %d transient + %d recorded mesh periods\n", dir, c->title[0] ? c->title : c->path,
           c->transient_periods, c->record_periods);
}

void cli_workprec_after_run(const cli_progress *p, gd_status st)
{
    (void)st;
    if (p->tty)
        fprintf(stderr, "\r%80s\r", "");
}

void cli_workprec_report(const cli_case_args *a, const char *dir, const gd_case *c, const void *result)
{
    (void)dir;
    const gd_wp_result *res = &((const gd_workprec_outcome *)result)->res;
    if (!res->ref.converged)
        fprintf(stderr, "geardyn: warning: the reference has not converged: it differs from its check (%s) by %.3g, "
                "above workprecision.reference_max_error = %g; errors below that are not resolved\n",
                res->ref.check_method, res->ref.chaotic ? res->ref.check_short : res->ref.check_poincare,
                c->wp_reference_max_error);
    if (a->quiet)
        return;
    printf("reference %s: %s (%s), RMS %.6g m/s^2, %ld events; check %s differs by %.3g (Poincare), %.3g "
           "(short horizon), %.3g (RMS)\n",
           res->ref.method, res->ref.motion, res->ref.chaotic ? "chaotic" : "periodic", res->ref.rms_accel_mps2,
           res->ref.events, res->ref.check_method, res->ref.check_poincare, res->ref.check_short, res->ref.check_rms);
    if (res->norders > 0) {
        printf("convergence order of the Poincare points (fixed steps, first %ld periods):\n", res->horizon_periods);
        for (int i = 0; i < res->norders; i++) {
            const gd_wp_order *O = &res->orders[i];
            printf("  %-14s nominal %d, measured %s", res->families[O->family].name, O->nominal,
                   isfinite(O->order) ? "" : "-");
            if (isfinite(O->order))
                printf("%.2f (steps %d to %d); %.2f over steps %d to %d", O->order, O->steps[O->fit_from],
                       O->steps[O->fit_to], O->order_range, O->steps[O->range_from], O->steps[O->fit_to]);
            printf("\n");
        }
    }
    static const double targets[] = {1e-3, 1e-6, 1e-8};
    for (int ev = 0; ev < 2; ev++)
        for (int k = 0; k < 3; k++) {
            int i = gd_workprec_cheapest(res, targets[k], ev);
            printf("cheapest at error %.0e%s: ", targets[k], ev ? " with the event times too" : "");
            if (i >= 0)
                printf("%s, %.1f us per mesh period\n", res->runs[i].label,
                       1e6 * res->runs[i].cpu_s / (double)res->runs[i].periods);
            else
                printf("none reached it\n");
        }
    printf("  %.1f s in all\n", res->wall_s);
}
