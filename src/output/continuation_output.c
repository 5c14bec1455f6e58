/* The files of a continuation (include/geardyn/gd_continuation.h): branch.csv (every branch point),
 * bifurcations.csv (every located bifurcation), curves.csv (every point of the curves in two
 * parameters) and codim2.csv (their codimension-two points), with continuation.parameter2, and
 * summary.json. Writers only: nothing computed. */
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

/* The measures of an orbit; the right mesh's (_R) only in a model with two meshes. */
static void measure_header(FILE *fp, const gd_contin_result *res)
{
    int two = res->nmesh > 1;
    fprintf(fp, ",rms_accel_mps2,rms_accel_L_mps2%s,lambda_min_L_um,lambda_max_L_um%s,lambda_L,dynamic_load_factor,"
            "dynamic_load_factor_L%s", two ? ",rms_accel_R_mps2" : "", two ? ",lambda_min_R_um,lambda_max_R_um" : "",
            two ? ",dynamic_load_factor_R" : "");
}

static void measure_row(FILE *fp, const gd_contin_result *res, const gd_contin_measure *m)
{
    int two = res->nmesh > 1;
    num(fp, m->rms_accel_mps2[2]);
    num(fp, m->rms_accel_mps2[0]);
    if (two)
        num(fp, m->rms_accel_mps2[1]);
    num(fp, m->lambda_min_um[0]);
    num(fp, m->lambda_max_um[0]);
    if (two) {
        num(fp, m->lambda_min_um[1]);
        num(fp, m->lambda_max_um[1]);
    }
    num(fp, m->lambda_poincare);
    num(fp, two ? fmax(m->dynamic_load_factor[0], m->dynamic_load_factor[1]) : m->dynamic_load_factor[0]);
    num(fp, m->dynamic_load_factor[0]);
    if (two)
        num(fp, m->dynamic_load_factor[1]);
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
    measure_header(fp, res);
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
    measure_header(fp, res);
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

/* curves.csv: every point of every curve in (parameter, parameter2) */
static gd_status write_curves(gd_run_dir *d, const gd_contin_result *res, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "curves.csv", &fp, err);
    if (st != GD_OK)
        return st;
    const char *dot = strchr(res->parameter2, '.'), *k2 = dot ? dot + 1 : res->parameter2;
    fprintf(fp, "curve,kind,period_n,from_branch,direction,point,%s,%s,continuation_p,continuation_p2,clearance,"
            "graze_phase,stable,mu_max", key_column(res), k2);
    for (int j = 0; j < res->n; j++)
        fprintf(fp, ",mu%d_re,mu%d_im", j + 1, j + 1);
    fprintf(fp, ",test_fold,test_period_doubling,test_cusp,kappa");
    for (int j = 0; j < res->nclear; j++)
        fprintf(fp, ",events_%s", res->clear_name[j]);
    fprintf(fp, ",newton_iterations,residual,ds");
    for (int j = 0; j < res->n; j++)
        fprintf(fp, ",%s", res->state_name[j]);
    fprintf(fp, "\n");
    for (int ic = 0; ic < res->ncurves; ic++) {
        const gd_contin_curve *cu = &res->curve[ic];
        for (int i = 0; i < cu->cv.npoints; i++) {
            const gd_curve_point *pt = &cu->cv.pt[i];
            const gd_po *o = &pt->orbit;
            char fb[16] = "";
            if (cu->branch >= 0)
                snprintf(fb, sizeof fb, "%d", cu->branch);
            fprintf(fp, "%d,%s,%d,%s,%s,%d,%.12g,%.12g,%.12g,%.12g,%s", ic, gd_curve_kind_name(cu->cv.kind),
                    cu->cv.nper, fb, cu->direction > 0 ? "up" : "down", i, gd_contin_value(res, o->p),
                    pt->p2 * res->scale2, o->p, pt->p2,
                    cu->cv.clearance >= 0 ? res->clear_name[cu->cv.clearance] : "");
            num(fp, pt->t_graze);
            fprintf(fp, ",%d,%.10g", o->stable, o->mu_max);
            for (int j = 0; j < res->n; j++)
                fprintf(fp, ",%.10g,%.10g", o->mu_re[j], o->mu_im[j]);
            num(fp, pt->test[GD_CT_FOLD]);
            num(fp, pt->test[GD_CT_PD]);
            num(fp, pt->test[GD_CT_CUSP]);
            num(fp, pt->kappa);
            for (int j = 0; j < res->nclear; j++)
                fprintf(fp, ",%ld", o->events[j]);
            fprintf(fp, ",%d,%.3g,%.6g", o->iterations, o->residual, pt->ds);
            for (int j = 0; j < res->n; j++)
                fprintf(fp, ",%.17g", o->y[0][j]);
            fprintf(fp, "\n");
        }
    }
    return gd_run_dir_commit(d, fp, err);
}

/* The test function whose sign change located codimension-two point c2 of a curve of kind ck: a column
 * of curves.csv, kappa on a Neimark-Sacker curve, mu_modulus (|mu| - 1 of a complex pair) for a
 * Neimark-Sacker point met on a grazing curve, or where the orbit's contact events change (a grazing
 * met, ending the curve): gap_CLEARANCE (the distance of the extremum that crossed to its boundary) or
 * events_CLEARANCE (the counts of its events, bisected). */
static void c2_test(const gd_contin_result *res, int ck, const gd_codim2 *c2, char *buf, size_t n)
{
    const char *clr = c2->clearance >= 0 && c2->clearance < res->nclear ? res->clear_name[c2->clearance] : "";
    int met = c2->kind == GD_C2_DOUBLE_GRAZING ||
              (ck != GD_CURVE_GRAZING && c2->kind >= GD_C2_GRAZING_FOLD && c2->kind <= GD_C2_GRAZING_NS);
    if (met)
        snprintf(buf, n, "%s_%s", c2->location == GD_LOC_EVENTS ? "events" : "gap", clr);
    else if (c2->kind == GD_C2_CUSP)
        snprintf(buf, n, "test_cusp");
    else if (c2->kind == GD_C2_FOLD_FLIP)
        snprintf(buf, n, "%s", ck == GD_CURVE_FOLD ? "test_period_doubling" : "test_fold");
    else if (c2->kind >= GD_C2_R1 && c2->kind <= GD_C2_R4)
        snprintf(buf, n, "kappa");
    else if (c2->kind == GD_C2_GRAZING_FOLD)
        snprintf(buf, n, "test_fold");
    else if (c2->kind == GD_C2_GRAZING_PD)
        snprintf(buf, n, "test_period_doubling");
    else
        snprintf(buf, n, "mu_modulus");
}

/* codim2.csv: every codimension-two point located along the curves */
static gd_status write_codim2(gd_run_dir *d, const gd_contin_result *res, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "codim2.csv", &fp, err);
    if (st != GD_OK)
        return st;
    const char *dot = strchr(res->parameter2, '.'), *k2 = dot ? dot + 1 : res->parameter2, *k = key_column(res);
    fprintf(fp, "curve,curve_kind,period_n,kind,label,%s,%s,%s_lo,%s_lo,%s_hi,%s_hi,continuation_p,continuation_p2,"
            "test,clearance,mu_re,mu_im,location,ends_curve,point", k, k2, k, k2, k, k2);
    for (int j = 0; j < res->n; j++)
        fprintf(fp, ",%s", res->state_name[j]);
    fprintf(fp, "\n");
    for (int ic = 0; ic < res->ncurves; ic++) {
        const gd_curve *cv = &res->curve[ic].cv;
        for (int i = 0; i < cv->nc2; i++) {
            const gd_codim2 *c2 = &cv->c2[i];
            char test[64];
            c2_test(res, cv->kind, c2, test, sizeof test);
            fprintf(fp, "%d,%s,%d,%s,%s,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%s,%s", ic,
                    gd_curve_kind_name(cv->kind), cv->nper, gd_codim2_kind_name(c2->kind), gd_codim2_label(c2->kind),
                    gd_contin_value(res, c2->p1), c2->p2 * res->scale2, gd_contin_value(res, c2->p1_lo),
                    c2->p2_lo * res->scale2, gd_contin_value(res, c2->p1_hi), c2->p2_hi * res->scale2, c2->p1, c2->p2,
                    test, c2->clearance >= 0 && c2->clearance < res->nclear ? res->clear_name[c2->clearance] : "");
            num(fp, c2->mu_re);
            num(fp, c2->mu_im);
            fprintf(fp, ",%s,%d,%d", gd_bif_location_name(c2->location), c2->ends_curve, c2->point);
            for (int j = 0; j < res->n; j++)
                fprintf(fp, ",%.17g", c2->y[j]);
            fprintf(fp, "\n");
        }
    }
    return gd_run_dir_commit(d, fp, err);
}

gd_status gd_contin_write_tables(gd_run_dir *d, const gd_contin_result *res, gd_error *err)
{
    gd_status st = write_branch(d, res, err);
    if (st == GD_OK)
        st = write_bifurcations(d, res, err);
    if (st == GD_OK && res->parameter2[0])
        st = write_curves(d, res, err);
    return st == GD_OK && res->parameter2[0] ? write_codim2(d, res, err) : st;
}

static json_t *curve_json(const gd_contin_result *res, int ic)
{
    const gd_contin_curve *cu = &res->curve[ic];
    const gd_curve *cv = &cu->cv;
    const gd_curve_point *a = &cv->pt[0], *z = &cv->pt[cv->npoints - 1];
    json_t *o = json_object();
    json_object_set_new(o, "curve", json_integer(ic));
    json_object_set_new(o, "kind", json_string(gd_curve_kind_name(cv->kind)));
    json_object_set_new(o, "period_n", json_integer(cv->nper));
    json_object_set_new(o, "clearance", cv->clearance >= 0 ? json_string(res->clear_name[cv->clearance]) : json_null());
    json_object_set_new(o, "from_branch", cu->branch >= 0 ? json_integer(cu->branch) : json_null());
    json_object_set_new(o, "direction", json_string(cu->direction > 0 ? "up" : "down"));
    json_object_set_new(o, "points", json_integer(cv->npoints));
    json_object_set_new(o, "first", json_pack("[o, o]", gd_json_num(gd_contin_value(res, a->orbit.p)),
                                              gd_json_num(a->p2 * res->scale2)));
    json_object_set_new(o, "last", json_pack("[o, o]", gd_json_num(gd_contin_value(res, z->orbit.p)),
                                             gd_json_num(z->p2 * res->scale2)));
    json_object_set_new(o, "end", json_string(gd_curve_end_name(cv->end)));
    json_object_set_new(o, "end_reason", json_string(cv->end_reason));
    json_t *c2s = json_array();
    for (int i = 0; i < cv->nc2; i++) {
        const gd_codim2 *c2 = &cv->c2[i];
        char test[64];
        c2_test(res, cv->kind, c2, test, sizeof test);
        json_array_append_new(c2s, json_pack("{s:s, s:s, s:[o, o], s:s, s:o, s:s, s:b}", "kind",
                                             gd_codim2_kind_name(c2->kind), "label", gd_codim2_label(c2->kind), "at",
                                             gd_json_num(gd_contin_value(res, c2->p1)), gd_json_num(c2->p2 * res->scale2),
                                             "test", test, "clearance", c2->clearance >= 0 && c2->clearance < res->nclear
                                             ? json_string(res->clear_name[c2->clearance]) : json_null(),
                                             "location", gd_bif_location_name(c2->location), "ends_curve",
                                             c2->ends_curve));
    }
    json_object_set_new(o, "codim2", c2s);
    json_object_set_new(o, "corrections", json_integer(cv->corrections));
    json_object_set_new(o, "newton_iterations", json_integer(cv->newton_iterations));
    json_object_set_new(o, "newton_tol", gd_json_num(cv->tol));
    return o;
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
    if (res->parameter2[0]) {
        json_object_set_new(r, "parameter2", json_string(res->parameter2));
        json_object_set_new(r, "unit2", json_string(res->unit2));
        json_object_set_new(r, "scale2", gd_json_num(res->scale2));
        json_object_set_new(r, "curve_start", res->curve_start[0] ? json_string(res->curve_start) : json_null());
        json_t *cvs = json_array();
        for (int i = 0; i < res->ncurves; i++)
            json_array_append_new(cvs, curve_json(res, i));
        json_object_set_new(r, "curves", cvs);
        json_object_set_new(r, "curve_corrections", json_integer(res->curve_corrections));
        json_object_set_new(r, "curve_cpu_s", gd_json_num(res->curve_cpu_s));
    }
    json_object_set_new(root, "results", r);
    return gd_json_write_summary(d, root, err);
}
