/* One value's point of the basins as a line of text and back (gd_basins_record_format, _parse): what a
 * process that computed some of the parameter's values sends to the one that matches them and writes
 * the files (the command line's MPI ranks). Reals are written with 17 significant digits, so that a
 * point read back is the point computed, bit for bit. */
#include "geardyn/gd_basins.h"

#include "../core/strbuf.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void put_reals(gd_strbuf *b, const double *x, int n)
{
    for (int i = 0; i < n; i++)
        gd_strbuf_printf(b, " %.17g", x[i]);
}

GD_API gd_status gd_basins_record_format(const gd_basins_result *res, int k, char **line, size_t *len, gd_error *err)
{
    *line = NULL;
    *len = 0;
    if (k < 0 || k >= res->npoints || !res->pt[k].done)
        return gd_error_set(err, GD_ERR_INPUT, "no computed point %d of the basins to format", k);
    const gd_basins_point *p = &res->pt[k];
    const int n = res->n;
    gd_strbuf b = {0};
    gd_strbuf_printf(&b, "basins %d %.17g %ld %ld %.17g %d %d", k, p->value, p->samples, p->periods, p->cpu_s, p->natt, p->norbits);
    for (int s = 0; s < GD_BASIN_NSPECIAL; s++)
        gd_strbuf_printf(&b, " %ld", p->special[s]);
    for (int a = 0; a < p->natt; a++) {
        const gd_attractor *t = &p->att[a];
        const gd_po *o = &t->orbit;
        gd_strbuf_printf(&b, " A %d %d %d %.17g %d %.17g %.17g %ld %d", t->kind, t->period, t->seeded, t->mle_per_period,
            t->impact_regime, t->x_min, t->x_max, p->count[a], t->npts);
        put_reals(&b, t->pts, t->npts * n);
        gd_strbuf_printf(&b, " %d %d %d %.17g", o->n, o->nper, o->nseg, o->p);
        put_reals(&b, o->mu_re, o->n);
        put_reals(&b, o->mu_im, o->n);
        gd_strbuf_printf(&b, " %.17g %d %d %.17g", o->mu_max, o->stable, o->iterations, o->residual);
        for (int c = 0; c < GD_MAX_CLEAR; c++)
            gd_strbuf_printf(&b, " %ld", o->events[c]);
        for (int s = 0; s < o->nseg; s++)
            put_reals(&b, o->y[s], o->n);
    }
    for (int r = 0; r < p->norbits; r++) {
        const gd_basins_orbit *ob = &p->orbits[r];
        gd_strbuf_printf(&b, " R %d %d %d %.17g", ob->branch, ob->period, ob->stable, ob->mu_max);
        for (int q = 0; q < ob->period; q++) {
            put_reals(&b, ob->pts[q], n);
            gd_strbuf_printf(&b, " %.17g %.17g", ob->u[q], ob->v[q]);
        }
    }
    gd_strbuf_printf(&b, "\n");
    if (b.bad) {
        free(b.p);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory for a basins record");
    }
    *line = b.p;
    *len = b.n;
    return GD_OK;
}

/* ---- reading ---- */

typedef struct rd {
    const char *p, *end;
    int bad;
} rd;

static const char *token(rd *r, size_t *tl)
{
    while (r->p < r->end && (*r->p == ' ' || *r->p == '\n'))
        r->p++;
    const char *s = r->p;
    while (r->p < r->end && *r->p != ' ' && *r->p != '\n')
        r->p++;
    *tl = (size_t)(r->p - s);
    if (*tl == 0 || *tl > 63)
        r->bad = 1;
    return s;
}

static double get_real(rd *r)
{
    size_t tl;
    const char *s = token(r, &tl);
    if (r->bad)
        return NAN;
    char t[64], *e;
    memcpy(t, s, tl);
    t[tl] = 0;
    double v = strtod(t, &e);
    if (*e)
        r->bad = 1;
    return v;
}

static long get_long(rd *r)
{
    size_t tl;
    const char *s = token(r, &tl);
    if (r->bad)
        return 0;
    char t[64], *e;
    memcpy(t, s, tl);
    t[tl] = 0;
    long v = strtol(t, &e, 10);
    if (*e)
        r->bad = 1;
    return v;
}

static void expect(rd *r, const char *word)
{
    size_t tl;
    const char *s = token(r, &tl);
    if (r->bad || tl != strlen(word) || memcmp(s, word, tl) != 0)
        r->bad = 1;
}

static void get_reals(rd *r, double *x, int n)
{
    for (int i = 0; i < n && !r->bad; i++)
        x[i] = get_real(r);
}

GD_API gd_status gd_basins_record_parse(gd_basins_result *res, const char *line, size_t len, gd_error *err)
{
    rd r = {line, line + len, 0};
    expect(&r, "basins");
    int k = (int)get_long(&r);
    if (r.bad || k < 0 || k >= res->npoints)
        return gd_error_set(err, GD_ERR_INPUT, "a basins record of no point of this run (%d of %d)", k, res->npoints);
    const int n = res->n;
    gd_basins_point q;
    memset(&q, 0, sizeof q);
    q.value = get_real(&r);
    q.samples = get_long(&r);
    q.periods = get_long(&r);
    q.cpu_s = get_real(&r);
    q.natt = (int)get_long(&r);
    q.norbits = (int)get_long(&r);
    for (int s = 0; s < GD_BASIN_NSPECIAL; s++)
        q.special[s] = get_long(&r);
    if (r.bad || q.natt < 0 || q.natt > 100000 || q.norbits < 0 || q.norbits > 100000)
        return gd_error_set(err, GD_ERR_INPUT, "a basins record with a bad head");
    q.att = calloc((size_t)(q.natt > 0 ? q.natt : 1), sizeof *q.att);
    q.count = calloc((size_t)(q.natt > 0 ? q.natt : 1), sizeof *q.count);
    q.id = calloc((size_t)(q.natt > 0 ? q.natt : 1), sizeof *q.id);
    q.orbits = q.norbits ? calloc((size_t)q.norbits, sizeof *q.orbits) : NULL;
    gd_status st = q.att && q.count && q.id && (q.orbits || !q.norbits) ? GD_OK
                 : gd_error_set(err, GD_ERR_NOMEM, "out of memory for a basins record");
    for (int a = 0; a < q.natt && st == GD_OK && !r.bad; a++) {
        gd_attractor *t = &q.att[a];
        gd_po *o = &t->orbit;
        expect(&r, "A");
        t->kind = (int)get_long(&r);
        t->period = (int)get_long(&r);
        t->seeded = (int)get_long(&r);
        t->mle_per_period = get_real(&r);
        t->impact_regime = (int)get_long(&r);
        t->x_min = get_real(&r);
        t->x_max = get_real(&r);
        q.count[a] = get_long(&r);
        t->npts = (int)get_long(&r);
        q.id[a] = a;
        if (r.bad || t->npts < 0 || t->npts > 100000000) {
            r.bad = 1;
            break;
        }
        t->pts = malloc(sizeof(double) * (size_t)(t->npts > 0 ? t->npts : 1) * (size_t)n);
        if (!t->pts) {
            st = gd_error_set(err, GD_ERR_NOMEM, "out of memory for a basins record");
            break;
        }
        get_reals(&r, t->pts, t->npts * n);
        o->n = (int)get_long(&r);
        o->nper = (int)get_long(&r);
        o->nseg = (int)get_long(&r);
        o->p = get_real(&r);
        if (r.bad || o->n < 0 || o->n > GD_MAX_STATE || o->nseg < 0 || o->nseg > GD_PO_MAX_PERIODS) {
            r.bad = 1;
            break;
        }
        get_reals(&r, o->mu_re, o->n);
        get_reals(&r, o->mu_im, o->n);
        o->mu_max = get_real(&r);
        o->stable = (int)get_long(&r);
        o->iterations = (int)get_long(&r);
        o->residual = get_real(&r);
        for (int c = 0; c < GD_MAX_CLEAR; c++)
            o->events[c] = get_long(&r);
        for (int s = 0; s < o->nseg; s++)
            get_reals(&r, o->y[s], o->n);
        snprintf(t->name, sizeof t->name, "%s", "");
        if (t->kind == GD_ATT_PERIODIC)
            snprintf(t->name, sizeof t->name, "period-%d", t->period);
        else
            snprintf(t->name, sizeof t->name, "%s", gd_attractor_kind_name(t->kind));
    }
    for (int i = 0; i < q.norbits && st == GD_OK && !r.bad; i++) {
        gd_basins_orbit *ob = &q.orbits[i];
        expect(&r, "R");
        ob->branch = (int)get_long(&r);
        ob->period = (int)get_long(&r);
        ob->stable = (int)get_long(&r);
        ob->mu_max = get_real(&r);
        if (ob->period < 1 || ob->period > GD_PO_MAX_PERIODS) {
            r.bad = 1;
            break;
        }
        for (int j = 0; j < ob->period && !r.bad; j++) {
            get_reals(&r, ob->pts[j], n);
            ob->u[j] = get_real(&r);
            ob->v[j] = get_real(&r);
        }
    }
    if (st == GD_OK && r.bad)
        st = gd_error_set(err, GD_ERR_INPUT, "a basins record that does not read back (point %d)", k);
    if (st != GD_OK) {
        for (int a = 0; q.att && a < q.natt; a++)
            free(q.att[a].pts);
        free(q.att), free(q.count), free(q.id), free(q.orbits);
        return st;
    }
    gd_basins_point *p = &res->pt[k];
    for (int a = 0; a < p->natt; a++)
        free(p->att[a].pts);
    free(p->att), free(p->count), free(p->id), free(p->orbits);
    q.done = 1;
    *p = q;
    return GD_OK;
}
