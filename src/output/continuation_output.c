/* The files of a continuation (include/geardyn/gd_continuation.h): branch.csv (every branch point),
 * bifurcations.csv (every located bifurcation) and summary.json. Writers only: nothing computed. */
#include "output_internal.h"
#include "json_util.h"

#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* The key's name without its section ("speed_rpm"): the parameter's column. */
static const char *key_column(const gd_contin_result *res)
{
    const char *dot = strchr(res->parameter, '.');
    return dot ? dot + 1 : res->parameter;
}

static void num(FILE *fp, double v)
{
    if (isfinite(v))
        fprintf(fp, ",%.10g", v);
    else
        fprintf(fp, ",NaN");
}

static void measure_header(FILE *fp)
{
    fprintf(fp, ",rms_accel_mps2,rms_accel_L_mps2,rms_accel_R_mps2,lambda_min_L_um,lambda_max_L_um,"
                "lambda_min_R_um,lambda_max_R_um,lambda_L,dynamic_load_factor,dynamic_load_factor_L,"
                "dynamic_load_factor_R");
}

static void measure_row(FILE *fp, const gd_contin_result *res, const gd_contin_measure *m)
{
    num(fp, m->rms_accel_mps2[2]);
    num(fp, m->rms_accel_mps2[0]);
    num(fp, res->nmesh > 1 ? m->rms_accel_mps2[1] : NAN);
    num(fp, m->lambda_min_um[0]);
    num(fp, m->lambda_max_um[0]);
    num(fp, res->nmesh > 1 ? m->lambda_min_um[1] : NAN);
    num(fp, res->nmesh > 1 ? m->lambda_max_um[1] : NAN);
    num(fp, m->lambda_poincare);
    num(fp, res->nmesh > 1 ? fmax(m->dynamic_load_factor[0], m->dynamic_load_factor[1]) : m->dynamic_load_factor[0]);
    num(fp, m->dynamic_load_factor[0]);
    num(fp, res->nmesh > 1 ? m->dynamic_load_factor[1] : NAN);
}

static gd_status write_branch(gd_run_dir *d, const gd_contin_result *res, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "branch.csv", &fp, err);
    if (st != GD_OK)
        return st;
    fprintf(fp, "branch,period_n,point,%s,continuation_p,stable,mu_max", key_column(res));
    for (int j = 0; j < res->n; j++)
        fprintf(fp, ",mu%d_re,mu%d_im", j + 1, j + 1);
    measure_header(fp);
    for (int j = 0; j < res->nclear; j++)
        fprintf(fp, ",events_%s", res->clear_name[j]);
    fprintf(fp, ",newton_iterations,residual,ds");
    for (int j = 0; j < res->n; j++)
        fprintf(fp, ",%s", res->state_name[j]);
    fputc('\n', fp);
    for (int b = 0; b < res->nbranches; b++) {
        const gd_contin_branch *br = &res->branch[b];
        for (int i = 0; i < br->br.npoints; i++) {
            const gd_cont_point *pt = &br->br.pt[i];
            const gd_po *o = &pt->orbit;
            fprintf(fp, "%d,%d,%d,%.12g,%.12g,%d,%.10g", b, br->nper, i, gd_contin_value(res, o->p), o->p,
                    o->stable, o->mu_max);
            for (int j = 0; j < res->n; j++)
                fprintf(fp, ",%.10g,%.10g", o->mu_re[j], o->mu_im[j]);
            measure_row(fp, res, &br->meas[i]);
            for (int j = 0; j < res->nclear; j++)
                fprintf(fp, ",%ld", o->events[j]);
            fprintf(fp, ",%d,%.3g,%.6g", o->iterations, o->residual, pt->ds);
            for (int j = 0; j < res->n; j++)
                fprintf(fp, ",%.17g", o->y[0][j]);
            fputc('\n', fp);
        }
    }
    return gd_run_dir_commit(d, fp, err);
}

static gd_status write_bifurcations(gd_run_dir *d, const gd_contin_result *res, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "bifurcations.csv", &fp, err);
    if (st != GD_OK)
        return st;
    const char *k = key_column(res);
    fprintf(fp, "branch,period_n,kind,%s,%s_lo,%s_hi,continuation_p,mu_re,mu_im,clearance", k, k, k);
    measure_header(fp);
    for (int j = 0; j < res->n; j++)
        fprintf(fp, ",%s", res->state_name[j]);
    fprintf(fp, ",location\n");
    for (int b = 0; b < res->nbranches; b++) {
        const gd_contin_branch *br = &res->branch[b];
        for (int i = 0; i < br->br.nbif; i++) {
            const gd_bifurcation *bf = &br->br.bif[i];
            fprintf(fp, "%d,%d,%s,%.12g,%.12g,%.12g,%.12g,%.10g,%.10g,%s", b, br->nper, gd_bif_kind_name(bf->kind),
                    gd_contin_value(res, bf->p), gd_contin_value(res, bf->p_lo), gd_contin_value(res, bf->p_hi), bf->p,
                    bf->mu_re, bf->mu_im, bf->clearance >= 0 ? res->clear_name[bf->clearance] : "");
            measure_row(fp, res, &br->bif_meas[i]);
            for (int j = 0; j < res->n; j++)
                fprintf(fp, ",%.12g", bf->y[j]);
            fprintf(fp, ",%s\n", gd_bif_location_name(bf->location));
        }
    }
    return gd_run_dir_commit(d, fp, err);
}

gd_status gd_contin_write_tables(gd_run_dir *d, const gd_contin_result *res, gd_error *err)
{
    gd_status st = write_branch(d, res, err);
    return st == GD_OK ? write_bifurcations(d, res, err) : st;
}

static const char *end_name(int end)
{
    static const char *names[] = {"bound", "budget", "step", "closed", "half-period", "period-doubling"};
    return end >= 0 && end <= GD_END_DOUBLING ? names[end] : "?";
}

static json_t *branch_json(const gd_contin_result *res, int b)
{
    const gd_contin_branch *br = &res->branch[b];
    json_t *o = json_object();
    int stable = 0;
    for (int i = 0; i < br->br.npoints; i++)
        stable += br->br.pt[i].orbit.stable;
    json_object_set_new(o, "branch", json_integer(b));
    json_object_set_new(o, "period_n", json_integer(br->nper));
    json_object_set_new(o, "direction", json_string(br->direction > 0 ? "up" : "down"));
    json_object_set_new(o, "switched_from_branch", br->parent >= 0 ? json_integer(br->parent) : json_null());
    json_object_set_new(o, "points", json_integer(br->br.npoints));
    json_object_set_new(o, "stable_points", json_integer(stable));
    json_object_set_new(o, "first", gd_json_num(gd_contin_value(res, br->br.pt[0].orbit.p)));
    json_object_set_new(o, "last", gd_json_num(gd_contin_value(res, br->br.pt[br->br.npoints - 1].orbit.p)));
    json_object_set_new(o, "end", json_string(end_name(br->br.end)));
    json_object_set_new(o, "end_reason", json_string(br->end_reason));
    json_object_set_new(o, "born_at", br->parent >= 0 ? gd_json_num(gd_contin_value(res, br->born_p)) : json_null());
    json_object_set_new(o, "joins_doubling", br->joins >= 0 ? json_pack("{s:i, s:o}", "branch", br->joins, "value",
                                                                        gd_json_num(gd_contin_value(res, br->joins_p)))
                                                            : json_null());
    json_object_set_new(o, "state_scale", gd_json_num(br->br.y_scale));
    json_object_set_new(o, "parameter_scale", gd_json_num(br->br.p_scale));
    json_object_set_new(o, "newton_tol", gd_json_num(br->br.tol));
    json_object_set_new(o, "locate_tol", gd_json_num(br->br.locate_tol));
    json_object_set_new(o, "corrections", json_integer(br->br.corrections));
    json_object_set_new(o, "newton_iterations", json_integer(br->br.newton_iterations));
    json_t *bifs = json_array();
    for (int i = 0; i < br->br.nbif; i++) {
        const gd_bifurcation *bf = &br->br.bif[i];
        json_t *q = json_object();
        json_object_set_new(q, "kind", json_string(gd_bif_kind_name(bf->kind)));
        json_object_set_new(q, "value", gd_json_num(gd_contin_value(res, bf->p)));
        json_object_set_new(q, "bracket", json_pack("[o, o]", gd_json_num(gd_contin_value(res, bf->p_lo)),
                                                    gd_json_num(gd_contin_value(res, bf->p_hi))));
        json_object_set_new(q, "multiplier", json_pack("[o, o]", gd_json_num(bf->mu_re), gd_json_num(bf->mu_im)));
        json_object_set_new(q, "clearance", bf->clearance >= 0 ? json_string(res->clear_name[bf->clearance])
                                                                : json_null());
        json_object_set_new(q, "location", json_string(gd_bif_location_name(bf->location)));
        json_array_append_new(bifs, q);
    }
    json_object_set_new(o, "bifurcations", bifs);
    return o;
}

gd_status gd_contin_write_summary(gd_run_dir *d, const gd_case *c, const gd_modal *modes, const gd_contin_result *res,
                                  gd_error *err)
{
    json_t *root = gd_json_root(c, "continuation", "scene", "model");
    json_object_set_new(root, "derived", json_pack("{s:o}", "modal", gd_modal_json(c, modes)));
    json_t *r = json_object();
    json_object_set_new(r, "parameter", json_string(res->parameter));
    json_object_set_new(r, "unit", json_string(res->unit));
    json_object_set_new(r, "scale", gd_json_num(res->scale));
    json_object_set_new(r, "start_value", gd_json_num(res->start_value));
    json_object_set_new(r, "start_period_n", json_integer(res->nper_start));
    json_object_set_new(r, "start_period_found", json_boolean(res->period_found));
    json_object_set_new(r, "start_sweep_point", res->start_source[0] ? json_string(res->start_source) : json_null());
    json_t *brs = json_array();
    for (int b = 0; b < res->nbranches; b++)
        json_array_append_new(brs, branch_json(res, b));
    json_object_set_new(r, "branches", brs);
    json_t *notes = json_array();
    for (int i = 0; i < res->nnotes; i++)
        json_array_append_new(notes, json_string(res->notes[i]));
    json_object_set_new(r, "notes", notes);
    json_object_set_new(r, "notes_dropped", json_integer(res->notes_dropped));
    json_object_set_new(r, "corrections", json_integer(res->corrections));
    json_object_set_new(r, "newton_iterations", json_integer(res->newton_iterations));
    json_object_set_new(r, "newton_iterations_per_correction",
                        gd_json_num(res->corrections ? (double)res->newton_iterations / (double)res->corrections : NAN));
    json_object_set_new(r, "cpu_s", gd_json_num(res->cpu_s));
    json_object_set_new(root, "results", r);
    return gd_json_write_summary(d, root, err);
}
