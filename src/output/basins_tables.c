/* The files of the basins (include/geardyn/gd_basins.h, docs/basins.md section 6): basins.csv (the
 * picture's cells), attractors.csv, fractions.csv, attractor_points.csv, continuation_orbits.csv and
 * summary.json. Writers only: every number is the result's. */
#include "output_internal.h"
#include "json_util.h"

#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static void num(FILE *fp, double v)
{
    if (isfinite(v))
        fprintf(fp, ",%.10g", v);
    else
        fprintf(fp, ",NaN");
}

/* The parameter's column: the key's name without its section ("speed_rpm"), or none. */
static const char *key_column(const gd_basins_result *res)
{
    const char *dot = strchr(res->parameter, '.');
    return res->parameter[0] ? (dot ? dot + 1 : res->parameter) : NULL;
}

static void value_head(FILE *fp, const gd_basins_result *res)
{
    if (key_column(res))
        fprintf(fp, "%s,", key_column(res));
}

static void value_cell(FILE *fp, const gd_basins_result *res, const gd_basins_point *p)
{
    if (key_column(res))
        fprintf(fp, "%.12g,", p->value);
}

/* The outcome of a label at point p: the attractor's name or the label's. */
static const char *outcome(const gd_basins_point *p, int label)
{
    return label >= 0 ? (label < p->natt ? p->att[label].name : "?") : gd_basin_label_name(label);
}

static gd_status write_cells(gd_run_dir *d, const gd_basins_result *res, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "basins.csv", &fp, err);
    if (st != GD_OK)
        return st;
    const gd_basins_point *p = &res->pt[0];
    const gd_basin_section *s = &res->sec;
    double du = (s->hi[0] - s->lo[0]) / res->nx, dv = (s->hi[1] - s->lo[1]) / res->ny;
    fprintf(fp, "i,j,%s,%s,label,attractor,outcome\n", res->column[0], res->column[1]);
    for (int j = 0; j < res->ny; j++)
        for (int i = 0; i < res->nx; i++) {
            int l = res->grid[(size_t)j * res->nx + i];
            fprintf(fp, "%d,%d,%.10g,%.10g,%d,%d,%s\n", i, j, s->lo[0] + (i + 0.5) * du, s->lo[1] + (j + 0.5) * dv, l,
                    l >= 0 && l < p->natt ? p->id[l] : l, outcome(p, l));
        }
    return gd_run_dir_commit(d, fp, err);
}

static gd_status write_attractors(gd_run_dir *d, const gd_basins_result *res, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "attractors.csv", &fp, err);
    if (st != GD_OK)
        return st;
    const int n = res->n;
    value_head(fp, res);
    fprintf(fp, "attractor,index,name,kind,period_n,seeded,count,samples,fraction,standard_error,wilson_lo,wilson_hi,"
                "mu_max,mle_per_period,impact_regime,lambda_min_L_half_backlash,lambda_max_L_half_backlash,"
                "lambda_min_L_um,lambda_max_L_um,%s,%s", res->column[0], res->column[1]);
    for (int j = 0; j < n; j++)
        fprintf(fp, ",mu%d_re,mu%d_im", j + 1, j + 1);
    for (int j = 0; j < n; j++)
        fprintf(fp, ",%s", res->state_name[j]);
    fputc('\n', fp);
    for (int k = 0; k < res->npoints; k++) {
        const gd_basins_point *p = &res->pt[k];
        for (int a = 0; a < p->natt; a++) {
            const gd_attractor *t = &p->att[a];
            gd_basin_fraction f;
            gd_basins_fraction(res, k, a, &f);
            double u, v;
            gd_basin_section_coords(&res->sec, t->pts, &u, &v);
            value_cell(fp, res, p);
            fprintf(fp, "%d,%d,%s,%s,%d,%d,%ld,%ld", p->id[a], a, t->name, gd_attractor_kind_name(t->kind), t->period,
                    t->seeded, p->count[a], p->samples);
            num(fp, f.p);
            num(fp, f.se);
            num(fp, f.wilson_lo);
            num(fp, f.wilson_hi);
            num(fp, t->kind == GD_ATT_PERIODIC ? t->orbit.mu_max : NAN);
            num(fp, t->mle_per_period);
            fprintf(fp, ",%s", t->impact_regime >= 0 ? gd_impact_regime_name(t->impact_regime) : "NaN");
            num(fp, t->x_min / res->half_gap);
            num(fp, t->x_max / res->half_gap);
            num(fp, t->x_min * res->length_um);
            num(fp, t->x_max * res->length_um);
            num(fp, u);
            num(fp, v);
            for (int j = 0; j < n; j++) {
                num(fp, t->kind == GD_ATT_PERIODIC ? t->orbit.mu_re[j] : NAN);
                num(fp, t->kind == GD_ATT_PERIODIC ? t->orbit.mu_im[j] : NAN);
            }
            for (int j = 0; j < n; j++)
                fprintf(fp, ",%.17g", t->pts[j]);
            fputc('\n', fp);
        }
    }
    return gd_run_dir_commit(d, fp, err);
}

static gd_status write_fractions(gd_run_dir *d, const gd_basins_result *res, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "fractions.csv", &fp, err);
    if (st != GD_OK)
        return st;
    value_head(fp, res);
    fprintf(fp, "attractor,outcome,seeded,count,samples,fraction,standard_error,wilson_lo,wilson_hi\n");
    for (int k = 0; k < res->npoints; k++) {
        const gd_basins_point *p = &res->pt[k];
        for (int l = 0; l < p->natt + GD_BASIN_NSPECIAL; l++) {
            int label = l < p->natt ? l : -(l - p->natt) - 1;
            gd_basin_fraction f;
            gd_basins_fraction(res, k, label, &f);
            value_cell(fp, res, p);
            fprintf(fp, "%d,%s,%d,%ld,%ld", label >= 0 ? p->id[label] : label, outcome(p, label),
                    label >= 0 ? p->att[label].seeded : 0, f.count, f.total);
            num(fp, f.p);
            num(fp, f.se);
            num(fp, f.wilson_lo);
            num(fp, f.wilson_hi);
            fputc('\n', fp);
        }
    }
    return gd_run_dir_commit(d, fp, err);
}

static gd_status write_points(gd_run_dir *d, const gd_basins_result *res, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "attractor_points.csv", &fp, err);
    if (st != GD_OK)
        return st;
    value_head(fp, res);
    fprintf(fp, "attractor,point,%s,%s\n", res->column[0], res->column[1]);
    for (int k = 0; k < res->npoints; k++) {
        const gd_basins_point *p = &res->pt[k];
        for (int a = 0; a < p->natt; a++)
            for (int q = 0; q < p->att[a].npts; q++) {
                double u, v;
                gd_basin_section_coords(&res->sec, p->att[a].pts + (size_t)q * res->n, &u, &v);
                value_cell(fp, res, p);
                fprintf(fp, "%d,%d,%.10g,%.10g\n", p->id[a], q, u, v);
            }
    }
    return gd_run_dir_commit(d, fp, err);
}

static gd_status write_orbits(gd_run_dir *d, const gd_basins_result *res, gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "continuation_orbits.csv", &fp, err);
    if (st != GD_OK)
        return st;
    value_head(fp, res);
    fprintf(fp, "branch,period_n,stable,mu_max,point,%s,%s\n", res->column[0], res->column[1]);
    for (int k = 0; k < res->npoints; k++) {
        const gd_basins_point *p = &res->pt[k];
        for (int r = 0; r < p->norbits; r++)
            for (int q = 0; q < p->orbits[r].period; q++) {
                value_cell(fp, res, p);
                fprintf(fp, "%d,%d,%d,%.10g,%d,%.10g,%.10g\n", p->orbits[r].branch, p->orbits[r].period,
                        p->orbits[r].stable, p->orbits[r].mu_max, q, p->orbits[r].u[q], p->orbits[r].v[q]);
            }
    }
    return gd_run_dir_commit(d, fp, err);
}

gd_status gd_basins_write_tables(gd_run_dir *d, const gd_case *c, const gd_basins_result *res, gd_error *err)
{
    gd_status st = res->grid ? write_cells(d, res, err) : GD_OK;
    if (st == GD_OK)
        st = write_attractors(d, res, err);
    if (st == GD_OK && c->bas_samples > 0)
        st = write_fractions(d, res, err);
    if (st == GD_OK)
        st = write_points(d, res, err);
    if (st == GD_OK && c->bas_continuation[0])
        st = write_orbits(d, res, err);
    return st;
}

static json_t *fraction_json(const gd_basin_fraction *f)
{
    return json_pack("{s:I, s:o, s:o, s:[o, o]}", "count", (json_int_t)f->count, "fraction", gd_json_num(f->p),
                     "standard_error", gd_json_num(f->se), "wilson", gd_json_num(f->wilson_lo),
                     gd_json_num(f->wilson_hi));
}

static json_t *point_json(const gd_case *c, const gd_basins_result *res, int k)
{
    const gd_basins_point *p = &res->pt[k];
    json_t *o = json_object();
    if (res->parameter[0])
        json_object_set_new(o, "value", gd_json_num(p->value));
    json_object_set_new(o, "samples", json_integer(p->samples));
    json_t *atts = json_array();
    for (int a = 0; a < p->natt; a++) {
        const gd_attractor *t = &p->att[a];
        json_t *q = json_object();
        json_object_set_new(q, "attractor", json_integer(p->id[a]));
        json_object_set_new(q, "name", json_string(t->name));
        json_object_set_new(q, "kind", json_string(gd_attractor_kind_name(t->kind)));
        json_object_set_new(q, "period_n", json_integer(t->period));
        json_object_set_new(q, "seeded", json_boolean(t->seeded));
        if (c->bas_samples > 0) {
            gd_basin_fraction f;
            gd_basins_fraction(res, k, a, &f);
            json_object_set_new(q, "sample", fraction_json(&f));
        }
        json_object_set_new(q, "mu_max", gd_json_num(t->kind == GD_ATT_PERIODIC ? t->orbit.mu_max : NAN));
        json_object_set_new(q, "mle_per_period", gd_json_num(t->mle_per_period));
        json_object_set_new(q, "impact_regime", t->impact_regime >= 0 ? json_string(gd_impact_regime_name(t->impact_regime))
                                                                      : json_null());
        json_object_set_new(q, "lambda_min_L_half_backlash", gd_json_num(t->x_min / res->half_gap));
        json_object_set_new(q, "lambda_max_L_half_backlash", gd_json_num(t->x_max / res->half_gap));
        json_array_append_new(atts, q);
    }
    json_object_set_new(o, "attractors", atts);
    json_t *other = json_object();
    for (int l = -1; l >= -GD_BASIN_NSPECIAL && c->bas_samples > 0; l--) {
        gd_basin_fraction f;
        gd_basins_fraction(res, k, l, &f);
        json_object_set_new(other, gd_basin_label_name(l), fraction_json(&f));
    }
    json_object_set_new(o, "other_outcomes", other);
    json_t *orbits = json_array();
    for (int r = 0; r < p->norbits; r++)
        json_array_append_new(orbits, json_pack("{s:i, s:i, s:b, s:o}", "branch", p->orbits[r].branch, "period_n",
                                                p->orbits[r].period, "stable", p->orbits[r].stable, "mu_max",
                                                gd_json_num(p->orbits[r].mu_max)));
    json_object_set_new(o, "continuation_orbits", orbits);
    json_object_set_new(o, "mesh_periods", json_integer(p->periods));
    json_object_set_new(o, "cpu_s", gd_json_num(p->cpu_s));
    return o;
}

static json_t *picture_json(const gd_basins_result *res)
{
    const gd_basins_point *p = &res->pt[0];
    long total = (long)res->nx * res->ny;
    json_t *o = json_object();
    json_object_set_new(o, "cells", json_pack("[i, i]", res->nx, res->ny));
    const gd_basin_entropy *e = &res->entropy;
    json_object_set_new(o, "basin_entropy", json_pack("{s:i, s:I, s:I, s:o, s:o, s:o, s:b}", "box_cells", e->box,
                                                      "boxes", (json_int_t)e->boxes, "boundary_boxes",
                                                      (json_int_t)e->boundary_boxes, "S_b", gd_json_num(e->sb), "S_bb",
                                                      gd_json_num(e->sbb), "ln2", gd_json_num(log(2.0)),
                                                      "fractal_boundary", e->fractal));
    json_t *labels = json_array();
    for (int l = 0; l < p->natt + GD_BASIN_NSPECIAL; l++) {
        int label = l < p->natt ? l : -(l - p->natt) - 1;
        if (res->grid_cells[l] == 0 && label < 0)
            continue;
        json_array_append_new(labels, json_pack("{s:i, s:s, s:I, s:o, s:I, s:o}", "attractor",
                                                label >= 0 ? p->id[label] : label, "outcome", outcome(p, label), "cells",
                                                (json_int_t)res->grid_cells[l], "share",
                                                gd_json_num((double)res->grid_cells[l] / (double)total),
                                                "boundary_cells", (json_int_t)res->grid_boundary[l], "boundary_share",
                                                gd_json_num((double)res->grid_boundary[l] / (double)total)));
    }
    json_object_set_new(o, "labels", labels);
    return o;
}

gd_status gd_summary_write_basins(gd_run_dir *d, const gd_case *c, const gd_modal *modes, const gd_basins_result *res,
                                  gd_error *err)
{
    json_t *root = gd_json_root(c, "basins", "scene", "model");
    json_object_set_new(root, "derived", json_pack("{s:o}", "modal", gd_modal_json(c, modes)));
    json_t *r = json_object();
    json_object_set_new(r, "parameter", res->parameter[0] ? json_string(res->parameter) : json_null());
    json_object_set_new(r, "unit", json_string(res->unit));
    const gd_basin_section *s = &res->sec;
    json_object_set_new(r, "section", json_pack("{s:[s, s], s:[s, s], s:[o, o], s:[o, o], s:[i, i], s:o}", "coordinates",
                                                res->coord[0], res->coord[1], "columns", res->column[0], res->column[1],
                                                "x_range", gd_json_num(s->lo[0]), gd_json_num(s->hi[0]), "y_range",
                                                gd_json_num(s->lo[1]), gd_json_num(s->hi[1]), "cells", s->cells[0],
                                                s->cells[1], "phase_deg", gd_json_num(res->phase_deg)));
    json_object_set_new(r, "samples", json_integer(c->bas_samples));
    json_object_set_new(r, "seed", json_integer(c->bas_seed));
    json_object_set_new(r, "wilson_z", gd_json_num(res->z));
    json_object_set_new(r, "picture", res->grid ? picture_json(res) : json_null());
    json_t *pts = json_array();
    long periods = 0;
    double cpu = 0;
    for (int k = 0; k < res->npoints; k++) {
        json_array_append_new(pts, point_json(c, res, k));
        periods += res->pt[k].periods;
        cpu += res->pt[k].cpu_s;
    }
    json_object_set_new(r, res->parameter[0] ? "values" : "at_case_values", res->parameter[0] ? pts : json_incref(json_array_get(pts, 0)));
    if (!res->parameter[0])
        json_decref(pts);
    json_object_set_new(r, "attractor_ids", json_integer(res->nids));
    json_t *notes = json_array();
    for (int i = 0; i < res->nnotes; i++)
        json_array_append_new(notes, json_string(res->notes[i]));
    json_object_set_new(r, "notes", notes);
    json_object_set_new(r, "mesh_periods", json_integer(periods));
    json_object_set_new(r, "cpu_s", gd_json_num(cpu));
    json_object_set_new(r, "wall_s", gd_json_num(res->wall_s));
    json_object_set_new(r, "threads", json_integer(res->threads));
    json_object_set_new(root, "results", r);
    return gd_json_write_summary(d, root, err);
}
