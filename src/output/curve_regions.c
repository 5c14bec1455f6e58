/* The regions of the plane of a continuation's curves named from what the run computed, without a
 * regime map (docs/continuation.md section 8, "Regions"): the one-parameter branches lie on the line
 * parameter2 = the case's value, and every bifurcation of every branch on that line (fold, period
 * doubling, Neimark-Sacker point, branch point, contact change) cuts it into intervals. Between two
 * consecutive cuts every branch's orbits keep their period, stability and contact events, so the
 * stable orbits over an interval are known exactly from the branch points there: their period and
 * their meshes' impact regime (in contact, single-sided, double-sided, as a sweep's). An interval
 * is named by those stable orbits; one where a branch's points disagree (a change the run did not
 * locate) or that no stable orbit covers is left unnamed. Where the label goes is the picture's
 * (plot_curves.c); regions.csv writes what is named, where, and from which branch points. */
#include "output_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

typedef struct motion {
    int nper, regime, count;
    unsigned bearings;           /* the clearances other than the meshes' with contact events on the orbit */
} motion;

/* The clearances that are not a mesh's (bearings) with events on orbit o. */
static unsigned bearing_events(const gd_contin_result *res, const gd_po *o)
{
    unsigned b = 0;
    for (int j = 0; j < res->nclear && j < 32; j++)
        if (strncmp(res->clear_name[j], "mesh", 4) != 0 && o->events[j] > 0)
            b |= 1u << j;
    return b;
}

/* The words of a motion: "in contact", "single-sided (period 2)", "double-sided; bearing
 * impacts 1L 2L" (no comma: regions.csv quotes nothing). */
static void motion_words(const gd_contin_result *res, const motion *m, char *out, size_t len)
{
    static const char *const words[3] = {"in contact", "single-sided", "double-sided"};
    size_t n = (size_t)snprintf(out, len, "%s", words[m->regime]);
    if (m->nper != 1 && n < len)
        n += (size_t)snprintf(out + n, len - n, " (period %d)", m->nper);
    for (int j = 0, first = 1; j < res->nclear && j < 32 && n < len; j++)
        if (m->bearings & (1u << j)) {
            const char *w = res->clear_name[j];
            if (strncmp(w, "bearing-", 8) == 0)
                w += 8;
            n += (size_t)snprintf(out + n, len - n, "%s%s", first ? "; bearing impacts " : " ", w);
            first = 0;
        }
}

static int cmp_motion(const void *a, const void *b)
{
    const motion *x = a, *y = b;
    return x->regime != y->regime ? x->regime - y->regime
           : x->nper != y->nper   ? x->nper - y->nper
                                  : (x->bearings > y->bearings) - (x->bearings < y->bearings);
}

/* The stable orbits of every branch over parameter pm (the middle of an interval): into mo (their
 * distinct motions, counted), the evidence into ev. Returns 1 when known, 0 when a branch's two
 * points around pm disagree in stability or regime (unnamed), -1 when no branch covers pm. */
static int orbits_at(const gd_contin_result *res, double pm, motion *mo, int *nmo, char *ev, size_t evlen)
{
    int covered = 0, n = 0;
    size_t k = 0;
    ev[0] = 0;
    for (int b = 0; b < res->nbranches; b++) {
        const gd_contin_branch *br = &res->branch[b];
        for (int i = 0; i + 1 < br->br.npoints; i++) {
            double a = br->br.pt[i].orbit.p, c = br->br.pt[i + 1].orbit.p;
            if (!(pm >= fmin(a, c) && pm <= fmax(a, c)))
                continue;
            /* the bifurcations between the two points: the motion at pm is the point's on its side of
             * them, unknown when pm lies between two of them */
            int before = 0, after = 0;
            for (int q = 0; q < br->br.nbif; q++)
                if (br->br.bif[q].after == i + 1) {
                    double t = (br->br.bif[q].p - a) / (c - a), u = (pm - a) / (c - a);
                    if (t < u)
                        before++;
                    else
                        after++;
                }
            if (before > 0 && after > 0)
                return 0;
            int i0 = before > 0 ? i + 1 : i, i1 = after > 0 ? i : i + 1;
            covered = 1;
            if (!br->meas)
                return 0;
            int s0 = br->br.pt[i0].orbit.stable, s1 = br->br.pt[i1].orbit.stable;
            int r0 = br->meas[i0].impact_regime, r1 = br->meas[i1].impact_regime;
            unsigned e0 = bearing_events(res, &br->br.pt[i0].orbit), e1 = bearing_events(res, &br->br.pt[i1].orbit);
            if (s0 != s1 || r0 != r1 || r0 < 0 || r0 > 2 || e0 != e1)
                return 0;
            if (k < evlen && i0 == i1)
                k += (size_t)snprintf(ev + k, evlen - k, "%sbranch %d point %d at %.8g", k ? "; " : "", b, i0,
                                      gd_contin_value(res, br->br.pt[i0].orbit.p));
            else if (k < evlen)
                k += (size_t)snprintf(ev + k, evlen - k, "%sbranch %d points %d-%d at %.8g to %.8g", k ? "; " : "", b,
                                      i0, i1, gd_contin_value(res, br->br.pt[i0].orbit.p),
                                      gd_contin_value(res, br->br.pt[i1].orbit.p));
            if (k < evlen)
                k += (size_t)snprintf(ev + k, evlen - k, ": %s %s period %d%s", s0 ? "stable" : "unstable",
                                      gd_impact_regime_name(r0), br->nper, e0 ? " bearing events" : "");
            if (!s0)
                continue;
            int j = 0;
            while (j < n && !(mo[j].nper == br->nper && mo[j].regime == r0 && mo[j].bearings == e0))
                j++;
            if (j == n) {
                if (n == 8)
                    continue;
                mo[n++] = (motion){br->nper, r0, 0, e0};
            }
            mo[j].count++;
        }
    }
    *nmo = n;
    return covered ? 1 : -1;
}

void gd_contin_regions_name(const gd_contin_result *res, double from, double to, double value2, gd_curve_regions *rg)
{
    memset(rg, 0, sizeof *rg);
    /* the cuts: the range's ends and every bifurcation of every branch (key units) */
    int ncut = 2;
    for (int b = 0; b < res->nbranches; b++)
        ncut += res->branch[b].br.nbif;
    double *cut = malloc(sizeof(double) * (size_t)ncut);
    if (!cut)
        return;
    int k = 0;
    cut[k++] = fmin(from, to);
    cut[k++] = fmax(from, to);
    for (int b = 0; b < res->nbranches; b++)
        for (int i = 0; i < res->branch[b].br.nbif; i++)
            cut[k++] = gd_contin_value(res, res->branch[b].br.bif[i].p);
    qsort(cut, (size_t)k, sizeof *cut, cmp_double);
    double tiny = 1e-9 * (cut[k - 1] - cut[0]);
    for (int i = 0; i + 1 < k && rg->n < GD_REGIONS_MAX; i++) {
        double a = fmax(cut[i], fmin(from, to)), c = fmin(cut[i + 1], fmax(from, to));
        if (c - a <= tiny)
            continue;
        motion mo[8];
        int nmo = 0;
        char ev[sizeof rg->r[0].evidence];
        double pm = 0.5 * (a + c) / res->scale;
        if (orbits_at(res, pm, mo, &nmo, ev, sizeof ev) != 1 || nmo == 0)
            continue;
        qsort(mo, (size_t)nmo, sizeof *mo, cmp_motion);
        gd_curve_region r = {0};
        size_t n = 0, q = 0;
        for (int j = 0; j < nmo; j++) {
            char w[160];
            motion_words(res, &mo[j], w, sizeof w);
            if (n < sizeof r.label)
                n += (size_t)snprintf(r.label + n, sizeof r.label - n, "%s%s", j ? " or " : "", w);
            /* no count of orbits in the words: two branches switched to at one period doubling, both
             * ways, may follow one orbit and its image shifted by a mesh period */
            if (q < sizeof r.orbits)
            {
                q += (size_t)snprintf(r.orbits + q, sizeof r.orbits - q, "%s%d:%s:%d:", j ? ";" : "", mo[j].nper,
                                      gd_impact_regime_name(mo[j].regime), mo[j].count);
                for (int cl = 0, first = 1; cl < res->nclear && cl < 32 && q < sizeof r.orbits; cl++)
                    if (mo[j].bearings & (1u << cl)) {
                        q += (size_t)snprintf(r.orbits + q, sizeof r.orbits - q, "%s%s", first ? "" : "+",
                                              res->clear_name[cl]);
                        first = 0;
                    }
            }
        }
        r.from = a;
        r.to = c;
        r.x = 0.5 * (a + c);
        r.y = value2;
        snprintf(r.evidence, sizeof r.evidence, "%s", ev);
        /* an interval of the same name as the one before, with no curve between them: one region */
        if (rg->n > 0 && strcmp(rg->r[rg->n - 1].label, r.label) == 0 && fabs(rg->r[rg->n - 1].to - a) <= tiny) {
            int curve_here = 0;
            for (int v = 0; v < res->ncurves; v++)
                if (res->curve[v].cv.npoints > 0 &&
                    fabs(gd_contin_value(res, res->curve[v].cv.pt[0].orbit.p) - a) <= 1e-6 * (cut[k - 1] - cut[0]))
                    curve_here = 1;
            if (!curve_here) {
                gd_curve_region *p = &rg->r[rg->n - 1];
                p->to = c;
                p->x = 0.5 * (p->from + c);
                size_t m = strlen(p->evidence);
                if (m + 3 < sizeof p->evidence)
                    snprintf(p->evidence + m, sizeof p->evidence - m, "; %s", ev);
                continue;
            }
        }
        rg->r[rg->n++] = r;
    }
    free(cut);
}

gd_status gd_contin_write_regions(gd_run_dir *d, const gd_contin_result *res, const gd_curve_regions *rg,
                                  gd_error *err)
{
    FILE *fp;
    gd_status st = gd_run_dir_create(d, "regions.csv", &fp, err);
    if (st != GD_OK)
        return st;
    const char *d1 = strchr(res->parameter, '.'), *d2 = strchr(res->parameter2, '.');
    const char *c1 = d1 ? d1 + 1 : res->parameter, *c2 = d2 ? d2 + 1 : res->parameter2;
    fprintf(fp, "region,label,%s,%s,continuation_p,continuation_p2,drawn,from_%s,to_%s,orbits,evidence\n", c1, c2, c1,
            c1);
    for (int i = 0; i < rg->n; i++) {
        const gd_curve_region *r = &rg->r[i];
        fprintf(fp, "%d,%s,%.10g,%.10g,%.12g,%.12g,%d,%.10g,%.10g,%s,%s\n", i, r->label, r->x, r->y, r->x / res->scale,
                r->y / res->scale2, r->drawn, r->from, r->to, r->orbits, r->evidence);
    }
    return gd_run_dir_commit(d, fp, err);
}
