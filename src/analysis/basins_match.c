/* The attractors of the basins followed over the parameter's values (gd_basins_match, docs/basins.md
 * section 5): at every value after the first, each attractor of the value before is continued by
 * shooting to this value and matched to the periodic attractor it is there; one that is not (a
 * non-periodic one, or an orbit that ended at a fold) is mapped as seeds through a mapper holding
 * this value's attractors, and goes with the attractor its points go to (a new one, the sample
 * missed, joins with no states). The continuation's stable orbits at the value are seeds too. Seeds
 * count nothing: the fractions are those of the sample alone, whatever the matching. */
#include "basins_internal.h"
#include "geardyn/gd_scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The attractors a of prev continued to this value's model ms: the index of cur's attractor it is. */
static int continued(const gd_basin_mapper *mp, const gd_model *ms, const gd_solver_opts *o, const gd_basin_opts *bo,
                     const gd_attractor *a, int *ids, gd_status *st, gd_error *err)
{
    if (a->kind != GD_ATT_PERIODIC)
        return -1;
    gd_po_opts po = bo->po;
    po.nper = a->period;
    po.multiple = 1;
    gd_po orbit;
    gd_error e1 = {0};
    gd_status s2 = gd_po_solve(ms, o, &po, a->pts, &orbit, &e1);
    if (s2 == GD_ERR_NOMEM) {
        *st = s2;
        *err = e1;
        return -1;
    }
    if (s2 != GD_OK || !orbit.stable)
        return -1;
    const gd_attractor *cur;
    int nc = gd_basin_mapper_attractors(mp, &cur);
    for (int j = 0; j < nc; j++) {
        if (ids[j] >= 0 || cur[j].kind != GD_ATT_PERIODIC || cur[j].period != orbit.nper)
            continue;
        int same = 1;
        for (int q = 0; q < orbit.nper && same; q++) {
            double best = INFINITY;
            for (int r = 0; r < cur[j].npts; r++)
                best = fmin(best, gd_basin_state_distance(orbit.y[q], cur[j].pts + (size_t)r * ms->n, ms->n));
            same = best <= 100.0 * bo->same_tol;
        }
        if (same)
            return j;
    }
    return -1;
}

GD_API gd_status gd_basins_match(const gd_case *c, const gd_basins_known *known, const gd_basins_hooks *h,
                                 gd_basins_result *res, gd_error *err)
{
    gd_case cc;
    gd_status st = gd_case_copy(&cc, c, err);
    if (st != GD_OK)
        return st;
    cc.analysis = GD_ANALYSIS_RESPONSE;
    gd_solver_opts o;
    gd_solver_opts_from_case(c, &o);
    gd_basin_opts bo;
    gd_basins_opts_of(c, h, &bo);
    int next_id = 0;
    for (int k = 0; k < res->npoints && st == GD_OK; k++) {
        gd_basins_point *p = &res->pt[k];
        if (!p->done) {
            st = gd_error_set(err, GD_ERR_INTERNAL, "the basins at %s = %.10g were not computed", c->bas_parameter,
                              p->value);
            break;
        }
        gd_model m;
        double base[GD_MAX_STATE];
        gd_basin_section sec;
        gd_basin_mapper *mp = NULL;
        st = gd_basins_model_at(&cc, c, p->value, &m, base, err);
        if (st == GD_OK)
            st = gd_basins_section_at(c, &m, base, &sec, err);
        if (st == GD_OK)
            st = gd_basin_mapper_create(&m, &o, &sec, &bo, &mp, err);
        for (int a = 0; a < p->natt && st == GD_OK; a++) {
            int idx;
            st = gd_basin_mapper_add(mp, &p->att[a], &idx, err);
        }
        /* ids of the mapper's attractors: room for those the seeds may add */
        int cap = p->natt + 16, *ids = malloc(sizeof(int) * (size_t)cap);
        if (st == GD_OK && !ids)
            st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for the attractors' ids");
        for (int j = 0; ids && j < cap; j++)
            ids[j] = -1;
        if (k > 0 && st == GD_OK) {
            const gd_basins_point *q = &res->pt[k - 1];
            int *matched = calloc((size_t)(q->natt > 0 ? q->natt : 1), sizeof(int));
            if (!matched)
                st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for the matching");
            /* the previous value's periodic attractors continued by shooting */
            for (int a = 0; a < q->natt && st == GD_OK; a++) {
                int j = continued(mp, &m, &o, &bo, &q->att[a], ids, &st, err);
                if (j >= 0) {
                    ids[j] = q->id[a];
                    matched[a] = 1;
                }
            }
            /* the others: where their points go (up to 5 of them, the first label that is an attractor) */
            for (int a = 0; a < q->natt && st == GD_OK; a++) {
                if (matched[a])
                    continue;
                const gd_attractor *qa = &q->att[a];
                int npick = qa->npts < 5 ? qa->npts : 5;
                for (int s = 0; s < npick && st == GD_OK; s++) {
                    int lab, before = 0;
                    const gd_attractor *cur;
                    before = gd_basin_mapper_attractors(mp, &cur);
                    st = gd_basin_map(mp, qa->pts + (size_t)(s * (qa->npts / npick)) * m.n, 1, 0, 1, &lab, err);
                    if (st != GD_OK || lab < 0)
                        continue;
                    if (lab >= cap) { /* more attractors than room: grow */
                        int nc2 = 2 * cap + lab;
                        int *ni = realloc(ids, sizeof(int) * (size_t)nc2);
                        if (!ni) {
                            st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for the attractors' ids");
                            break;
                        }
                        for (int j = cap; j < nc2; j++)
                            ni[j] = -1;
                        ids = ni;
                        cap = nc2;
                    }
                    (void)before;
                    if (ids[lab] < 0)
                        ids[lab] = q->id[a];
                    break;
                }
            }
            free(matched);
        }
        /* the continuation's stable orbits at this value: seeds */
        if (st == GD_OK && known) {
            int failed = 0;
            st = gd_basins_orbits_at(c, &cc, known, p->value, &o, &bo, p, &failed, err);
            if (st == GD_OK)
                st = gd_basins_seed_orbits(mp, p, err);
        }
        if (st == GD_OK)
            st = gd_basins_point_take(p, mp, err);
        if (st == GD_OK && p->natt > cap) {
            int *ni = realloc(ids, sizeof(int) * (size_t)p->natt);
            if (!ni)
                st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for the attractors' ids");
            else {
                for (int j = cap; j < p->natt; j++)
                    ni[j] = -1;
                ids = ni;
            }
        }
        for (int j = 0; j < p->natt && st == GD_OK; j++)
            p->id[j] = ids[j] >= 0 ? ids[j] : next_id++;
        /* an id continued into one attractor only: the first keeps it */
        for (int j = 0; j < p->natt && st == GD_OK; j++)
            for (int i = 0; i < j; i++)
                if (p->id[i] == p->id[j])
                    p->id[j] = next_id++;
        free(ids);
        gd_basin_mapper_free(mp);
    }
    res->nids = next_id;
    gd_case_free(&cc);
    return st;
}
