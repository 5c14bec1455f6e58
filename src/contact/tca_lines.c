/* The contact lines of one position for LTCA (formulation (b), docs/ltca.md): the position's
 * contact by tca_scan, then in every grid slice of every pair within max_gap of it the exact slice
 * minimum, with the curvatures and directions of both flanks there. */
#include "tca_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Contact lines: per pair and slice within max_gap, the exact slice minimum (t->lines), with the grid
 * value each point's prefilter tested (t->lines_pre). */
static gd_status lines_within(gd_tca *t, int half, double phi1, double max_gap, gd_error *err)
{
    double gstar;
    gd_status st = tca_scan(t, half, phi1, 0, NULL, &gstar, err);
    if (st != GD_OK)
        return st;
    /* the grid buffers now hold the pairs of this position (tca_scan filled them) */
    const tca_half *H = &t->h[half];
    int nn = t->nprof * t->nface, np = t->nprof;
    double phi2 = tca_phi2_nominal(t, phi1);
    double phi2_actual = phi2 - gstar;
    double s = H->f2.rb * H->f2.cos_bb;
    int lo, hi;
    tca_pair_range(t, half, phi1, &lo, &hi);
    if (hi - lo + 1 > t->maxpairs)
        hi = lo + t->maxpairs - 1;
    t->nlines = 0;
    int iters = 0;
    for (int m = lo; m <= hi; m++) {
        tca_pose P;
        tca_pose_at(t, half, phi1, phi2, m, &P);
        const double *gv = t->gbuf + (size_t)(m - lo) * nn;
        const unsigned char *fv = t->fbuf + (size_t)(m - lo) * nn;
        for (int j = 0; j < t->nface; j++) {
            int ib = -1;
            for (int i = 0; i < np; i++)
                if (fv[(size_t)j * np + i] == 0 && (ib < 0 || gv[(size_t)j * np + i] < gv[(size_t)j * np + ib]))
                    ib = i;
            if (ib < 0)
                continue;
            const double pre = (gv[(size_t)j * np + ib] - gstar) * s;
            if (!tca_lines_prefilter(pre, max_gap))
                continue;
            tca_cand c;
            st = tca_slice_min(t, half, &P, j, ib, gv, fv, &c, &iters, err);
            if (st != GD_OK)
                return st;
            if (!c.ok || !tca_lines_keep(pre, (c.g - gstar) * s, max_gap))
                continue;
            if (t->nlines == t->cap_lines) {
                int cap = t->cap_lines ? 2 * t->cap_lines : 256;
                gd_tca_line_point *nl = realloc(t->lines, (size_t)cap * sizeof *nl);
                double *np2 = nl ? realloc(t->lines_pre, (size_t)cap * sizeof *np2) : NULL;
                if (nl)
                    t->lines = nl;
                if (!np2)
                    return gd_error_set(err, GD_ERR_NOMEM, "TCA: out of memory for the contact lines");
                t->lines_pre = np2;
                t->cap_lines = cap;
            }
            t->lines_pre[t->nlines] = pre;
            gd_tca_line_point *lp = &t->lines[t->nlines++];
            memset(lp, 0, sizeof *lp);
            lp->pair = m;
            lp->slice = j;
            lp->u1 = c.u;
            lp->z1 = c.z;
            lp->gap = (c.g - gstar) * s;
            lp->gap_nominal = c.g * s;
            lp->edge = c.bits;
            gd_flank_eval e;
            gd_flank_eval_at(&H->f1, c.u, c.z, 2, &e);
            double n[3], k[2], dir[2][3];
            gd_flank_normal(&e, n);
            gd_flank_curvature(&e, k, dir);
            tca_fixed_point(t, half, phi1, m, e.r, lp->pos);
            tca_fixed_vector(t, phi1, m, n, lp->normal);
            for (int a = 0; a < 2; a++) {
                lp->k1[a] = k[a];
                tca_fixed_vector(t, phi1, m, dir[a], lp->dir1[a]);
            }
            tca_local L;
            tca_local_eval(t, half, &P, c.u, c.z, 0, &L);
            double rb2 = H->f2.rb;
            lp->u2 = sqrt(fmax(L.R * L.R - rb2 * rb2, 0)) / rb2;
            lp->z2 = L.Z;
            gd_flank_eval e2;
            gd_flank_eval_at(&H->f2, lp->u2, lp->z2, 2, &e2);
            gd_flank_curvature(&e2, k, dir);
            for (int a = 0; a < 2; a++) {
                lp->k2[a] = k[a];
                tca_gear_to_fixed(t, half, phi2_actual, m, dir[a], 0, lp->dir2[a]);
            }
        }
    }
    return GD_OK;
}

/* The lines within max_gap: from the memo (tca_lines_memo.c) when it holds them within a wider
 * window; else computed within twice max_gap (the prefilter's margin of 50 um, far wider than a gap
 * window of a few micrometres, makes the extra slice minima few), kept in the memo, and the subset
 * within max_gap taken: the points, values and order the computation within max_gap gives. */
gd_status tca_lines(gd_tca *t, int half, double phi1, double max_gap, gd_error *err)
{
    int got = tca_memo_get(t, half, phi1, max_gap, err);
    if (got)
        return got > 0 ? GD_OK : GD_ERR_NOMEM;
    const int memo = tca_memo_active(t) && isfinite(max_gap) && max_gap > 0;
    gd_status st = lines_within(t, half, phi1, memo ? 2.0 * max_gap : max_gap, err);
    if (st != GD_OK || !memo)
        return st;
    tca_memo_put(t, half, phi1, 2.0 * max_gap, t->lines, t->lines_pre, t->nlines);
    int k = 0;
    for (int i = 0; i < t->nlines; i++)
        if (tca_lines_keep(t->lines_pre[i], t->lines[i].gap, max_gap))
            t->lines[k++] = t->lines[i];
    t->nlines = k;
    return GD_OK;
}
