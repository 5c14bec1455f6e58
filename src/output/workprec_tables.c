/* The tables of a work-precision run: every grid run (work_precision.csv), and when there is an
 * order study its runs (order_study.csv) and the measured orders (orders.csv). */
#include "output_internal.h"

#include <math.h>
#include <stdio.h>

static void csv_num(FILE *fp, double v)
{
    if (isfinite(v))
        fprintf(fp, ",%.6g", v);
    else
        fputs(",", fp);
}

static void write_run_row(FILE *fp, const gd_wp_result *res, const gd_wp_run *r)
{
    static const char *methods[] = {"erk", "dirk", "rk4"};
    const gd_wp_family *F = &res->families[r->family];
    fprintf(fp, "%s,%s,%s,%d,%d,%d", r->label, F->name, methods[F->method], F->order, F->root_finding, r->fixed_step);
    if (r->fixed_step)
        fprintf(fp, ",%d", r->steps_per_period);
    else
        fputs(",", fp);
    csv_num(fp, r->rtol);
    csv_num(fp, r->atol);
    fprintf(fp, ",%s", gd_wp_status_name(r->status));
    csv_num(fp, r->cpu_s);
    csv_num(fp, r->periods > 0 ? 1e6 * r->cpu_s / (double)r->periods : NAN);
    fprintf(fp, ",%ld", r->rhs_evals);
    csv_num(fp, r->periods > 0 ? (double)r->rhs_evals / (double)r->periods : NAN);
    fprintf(fp, ",%ld,%ld,%ld,%ld,%ld", r->steps, r->root_evals, r->events, r->flipflop_events, r->ref_events);
    csv_num(fp, r->rms_accel_mps2);
    csv_num(fp, r->mle_per_period);
    csv_num(fp, r->err_poincare);
    csv_num(fp, r->err_short);
    csv_num(fp, r->err_rms);
    csv_num(fp, r->err_events);
    csv_num(fp, r->err_mle);
    fputc('\n', fp);
}

static const char run_header[] =
    "label,family,method,order,root_finding,fixed_step,steps_per_period,rtol,atol,status,cpu_s,us_per_period,"
    "rhs_evals,rhs_evals_per_period,steps,root_evals,events,flipflop_events,reference_events,rms_accel_mps2,mle_per_period,"
    "err_poincare,err_short_horizon,err_rms_relative,err_event_times_periods,err_mle_per_period\n";

gd_status gd_workprec_write_tables(gd_run_dir *d, const gd_wp_result *res, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "work_precision.csv", &fp, err);
    if (st != GD_OK)
        return st;
    fputs(run_header, fp);
    for (int i = 0; i < res->nruns; i++)
        write_run_row(fp, res, &res->runs[i]);
    if ((st = gd_run_dir_commit(d, fp, err)) != GD_OK)
        return st;
    if (res->norders == 0)
        return GD_OK;
    if ((st = gd_run_dir_create(d, "order_study.csv", &fp, err)) != GD_OK)
        return st;
    fputs(run_header, fp);
    for (int i = 0; i < res->norder_runs; i++)
        write_run_row(fp, res, &res->order_runs[i]);
    if ((st = gd_run_dir_commit(d, fp, err)) != GD_OK)
        return st;
    if ((st = gd_run_dir_create(d, "orders.csv", &fp, err)) != GD_OK)
        return st;
    fputs("family,root_finding,nominal_order,measured_order,fitted_from_steps,fitted_to_steps,order_over_range,"
          "range_from_steps\n", fp);
    for (int i = 0; i < res->norders; i++) {
        const gd_wp_order *O = &res->orders[i];
        const gd_wp_family *F = &res->families[O->family];
        fprintf(fp, "%s,%d,%d", F->name, F->root_finding, O->nominal);
        csv_num(fp, O->order);
        if (O->fit_from >= 0)
            fprintf(fp, ",%d,%d", O->steps[O->fit_from], O->steps[O->fit_to]);
        else
            fputs(",,", fp);
        csv_num(fp, O->order_range);
        if (O->range_from >= 0)
            fprintf(fp, ",%d\n", O->steps[O->range_from]);
        else
            fputs(",\n", fp);
    }
    return gd_run_dir_commit(d, fp, err);
}

