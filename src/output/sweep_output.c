/* Sweep records (journal lines, MPI messages), the journal read back for --resume, and the
 * final tables and summary.json, written in slot order. */
#include "output_internal.h"
#include "geardyn/gd_sweep.h"
#include "geardyn/gd_version.h"
#include "json_util.h"
#include "../case/case_keys.h"
#include "../analysis/analysis_internal.h"

#include <errno.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- records ---- */

static uint32_t crc32_of(const char *s, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= (unsigned char)s[i];
        for (int k = 0; k < 8; k++)
            c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return ~c;
}

/* body + " *crc32\n", malloc'd */
static char *seal(const char *body, size_t n, size_t *len)
{
    char *out = malloc(n + 12);
    if (!out)
        return NULL;
    memcpy(out, body, n);
    snprintf(out + n, 12, " *%08x\n", (unsigned)crc32_of(body, n));
    *len = n + 11;
    return out;
}

/* The body of a sealed line (without its '\n'), or 0 when the seal is missing or wrong. */
static size_t unseal(const char *line, size_t len)
{
    if (len > 0 && line[len - 1] == '\n')
        len--;
    if (len < 11)
        return 0;
    const char *star = line + len - 10;
    if (star[0] != ' ' || star[1] != '*')
        return 0;
    uint32_t v = 0;
    for (int i = 2; i < 10; i++) {
        char ch = star[i];
        int d = ch >= '0' && ch <= '9' ? ch - '0' : ch >= 'a' && ch <= 'f' ? ch - 'a' + 10 : -1;
        if (d < 0)
            return 0;
        v = v * 16u + (uint32_t)d;
    }
    size_t body = (size_t)(star - line);
    return crc32_of(line, body) == v ? body : 0;
}

GD_API void gd_sweep_journal_header(const gd_sweep_plan *p, char *buf, size_t len)
{
    char body[256];
    int n = snprintf(body, sizeof body, "GDSWEEP 3 %s %016llx %d %d %ld", GD_VERSION_STRING,
                     (unsigned long long)p->fingerprint, p->nslots, p->nresp, p->npoincare);
    snprintf(buf, len, "%s *%08x\n", body, (unsigned)crc32_of(body, (size_t)n));
}

GD_API gd_status gd_sweep_record_format(const gd_sweep_plan *p, const gd_sweep_point *pt, char **line, size_t *len,
                                        gd_error *err)
{
    char *buf = NULL;
    size_t sz = 0;
    FILE *f = open_memstream(&buf, &sz);
    if (!f)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory formatting a sweep record");
    fprintf(f, "P %d %d %d %d %d %s %d %d %d %d %d", pt->slot, pt->chain, pt->pos, pt->branch, pt->status,
            pt->motion[0] ? pt->motion : "-", pt->period_n, pt->poincare_distinct, pt->impact_regime[0],
            pt->impact_regime[1], pt->impact_regime[2]);
    for (int i = 0; i < 3; i++)
        fprintf(f, " %.17g", pt->rms_accel_mps2[i]);
    fprintf(f, " %.17g %.17g", pt->dynamic_load_factor[0], pt->dynamic_load_factor[1]);
    fprintf(f, " %.17g %.17g %ld %ld %ld %ld %.17g", pt->mle_per_period, pt->mle_per_s, pt->steps, pt->rhs_evals,
            pt->events, pt->transient_periods, pt->wall_s);
    fprintf(f, " %d", p->n);
    for (int i = 0; i < p->n; i++)
        fprintf(f, " %.17g", pt->y_final[i]);
    fprintf(f, " %d", p->nclear);
    for (int i = 0; i < p->nclear; i++)
        fprintf(f, " %d", pt->md_final.mode[i]);
    fprintf(f, " %d", p->nmesh);
    for (int i = 0; i < p->nmesh; i++)
        fprintf(f, " %d", pt->md_final.rect_level[i]);
    fprintf(f, " %d %ld %d", pt->md_final.from_state, pt->npoincare, p->nresp);
    for (long i = 0; i < pt->npoincare * p->nresp; i++)
        fprintf(f, " %.17g", pt->poincare[i]);
    char msg[sizeof pt->error];
    snprintf(msg, sizeof msg, "%s", pt->error[0] ? pt->error : "-");
    for (char *q = msg; *q; q++)
        if (*q == '\n' || *q == '\r')
            *q = ' ';
    fprintf(f, " %d %s", pt->error_code, msg);
    if (fclose(f) != 0 || !buf) {
        free(buf);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory formatting a sweep record");
    }
    *line = seal(buf, sz, len);
    free(buf);
    if (!*line)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory formatting a sweep record");
    return GD_OK;
}

typedef struct tok {
    char *q;
    int bad;
} tok;

static long t_long(tok *t)
{
    if (t->bad)
        return 0;
    char *end;
    errno = 0;
    long v = strtol(t->q, &end, 10);
    if (end == t->q || errno || (*end != ' ' && *end != '\0')) {
        t->bad = 1;
        return 0;
    }
    t->q = *end ? end + 1 : end;
    return v;
}

static double t_double(tok *t)
{
    if (t->bad)
        return 0;
    char *end;
    double v = strtod(t->q, &end);
    if (end == t->q || (*end != ' ' && *end != '\0')) {
        t->bad = 1;
        return 0;
    }
    t->q = *end ? end + 1 : end;
    return v;
}

static void t_word(tok *t, char *out, size_t cap)
{
    if (t->bad)
        return;
    size_t l = strcspn(t->q, " ");
    if (l == 0 || l >= cap) {
        t->bad = 1;
        return;
    }
    memcpy(out, t->q, l);
    out[l] = '\0';
    t->q += l + (t->q[l] ? 1 : 0);
}

GD_API gd_status gd_sweep_record_parse(const gd_sweep_plan *p, const char *line, size_t len, gd_sweep_point *pts,
                                       int *slot, gd_error *err)
{
    size_t body = unseal(line, len);
    if (!body)
        return gd_error_set(err, GD_ERR_INPUT, "sweep record: torn or corrupt (checksum)");
    char *b = malloc(body + 1);
    double *pc = NULL;
    if (!b)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory reading a sweep record");
    memcpy(b, line, body);
    b[body] = '\0';
    gd_sweep_point pt;
    memset(&pt, 0, sizeof pt);
    tok t = {b, 0};
    char w[64];
    t_word(&t, w, sizeof w);
    if (t.bad || strcmp(w, "P") != 0)
        goto bad;
    pt.slot = (int)t_long(&t);
    if (t.bad || pt.slot < 0 || pt.slot >= p->nslots)
        goto bad;
    const int *si = &p->slot_info[4 * pt.slot];
    pt.chain = (int)t_long(&t);
    pt.pos = (int)t_long(&t);
    pt.branch = (int)t_long(&t);
    pt.status = (int)t_long(&t);
    if (t.bad || pt.chain != si[0] || pt.pos != si[1] || pt.branch != p->chains[si[0]].branch ||
        (pt.status != GD_POINT_DONE && pt.status != GD_POINT_FAILED))
        goto bad;
    t_word(&t, pt.motion, sizeof pt.motion);
    if (strcmp(pt.motion, "-") == 0)
        pt.motion[0] = '\0';
    pt.period_n = (int)t_long(&t);
    pt.poincare_distinct = (int)t_long(&t);
    for (int i = 0; i < 3; i++)
        pt.impact_regime[i] = (int)t_long(&t);
    for (int i = 0; i < 3; i++)
        pt.rms_accel_mps2[i] = t_double(&t);
    for (int i = 0; i < 2; i++)
        pt.dynamic_load_factor[i] = t_double(&t);
    pt.mle_per_period = t_double(&t);
    pt.mle_per_s = t_double(&t);
    pt.steps = t_long(&t);
    pt.rhs_evals = t_long(&t);
    pt.events = t_long(&t);
    pt.transient_periods = t_long(&t);
    pt.wall_s = t_double(&t);
    if (t_long(&t) != p->n || t.bad)
        goto bad;
    for (int i = 0; i < p->n; i++)
        pt.y_final[i] = t_double(&t);
    if (t_long(&t) != p->nclear || t.bad)
        goto bad;
    for (int i = 0; i < p->nclear; i++) {
        pt.md_final.mode[i] = (int)t_long(&t);
        if (pt.md_final.mode[i] < -1 || pt.md_final.mode[i] > 1)
            goto bad;
    }
    if (t_long(&t) != p->nmesh || t.bad)
        goto bad;
    for (int i = 0; i < p->nmesh; i++)
        pt.md_final.rect_level[i] = (int)t_long(&t);
    pt.md_final.from_state = (int)t_long(&t);
    pt.npoincare = t_long(&t);
    if (t.bad || pt.npoincare != (pt.status == GD_POINT_DONE ? p->npoincare : 0) || t_long(&t) != p->nresp)
        goto bad;
    if (pt.npoincare > 0) {
        pc = malloc(sizeof(double) * (size_t)pt.npoincare * (size_t)p->nresp);
        if (!pc) {
            free(b);
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory reading a sweep record");
        }
        for (long i = 0; i < pt.npoincare * p->nresp; i++)
            pc[i] = t_double(&t);
    }
    pt.error_code = (int)t_long(&t);
    if (t.bad || !*t.q)
        goto bad;
    snprintf(pt.error, sizeof pt.error, "%s", strcmp(t.q, "-") == 0 ? "" : t.q);
    /* the plan's fields */
    gd_sweep_point *dst = &pts[pt.slot];
    pt.idx[0] = dst->idx[0];
    pt.idx[1] = dst->idx[1];
    pt.value[0] = dst->value[0];
    pt.value[1] = dst->value[1];
    pt.poincare = pc;
    gd_sweep_point_clear(dst);
    *dst = pt;
    *slot = pt.slot;
    free(b);
    return GD_OK;
bad:
    free(b);
    free(pc);
    return gd_error_set(err, GD_ERR_INPUT, "sweep record: malformed or of another sweep");
}

/* ---- the journal ---- */

static gd_status read_all(const char *path, char **data, size_t *len, int *missing, gd_error *err)
{
    *data = NULL;
    *len = 0;
    *missing = 0;
    FILE *f = fopen(path, "rb");
    if (!f) {
        if (errno == ENOENT) {
            *missing = 1;
            return GD_OK;
        }
        return gd_error_set(err, GD_ERR_IO, "%s: cannot read: %s", path, strerror(errno));
    }
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap + 1);
    while (buf) {
        if (n == cap) {
            char *nb = realloc(buf, 2 * cap + 1);
            if (!nb) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap *= 2;
        }
        size_t r = fread(buf + n, 1, cap - n, f);
        n += r;
        if (r == 0)
            break;
    }
    int bad = ferror(f);
    fclose(f);
    if (!buf)
        return gd_error_set(err, GD_ERR_NOMEM, "%s: out of memory reading the journal", path);
    if (bad) {
        free(buf);
        return gd_error_set(err, GD_ERR_IO, "%s: read error", path);
    }
    buf[n] = '\0';
    *data = buf;
    *len = n;
    return GD_OK;
}

/* Check the header line of the journal data against this sweep's; *pos gets the offset of
 * the first record. A torn header means nothing was recorded (one ignored line). */
static gd_status journal_check_header(const char *path, const char *data, size_t len, const char *header, size_t hl,
                                      size_t *pos, int *ignored, gd_error *err)
{
    *pos = 0;
    if (len == 0)
        return GD_OK;
    const char *nl = memchr(data, '\n', len);
    if (!nl) { /* torn header: nothing was recorded */
        *ignored = 1;
        *pos = len;
        return GD_OK;
    }
    size_t l0 = (size_t)(nl - data) + 1;
    if (l0 != hl || memcmp(data, header, hl) != 0) {
        int ours = unseal(data, l0) != 0 && strncmp(data, "GDSWEEP ", 8) == 0;
        return gd_error_set(err, GD_ERR_INPUT, "%s: %s; run without --resume to start the sweep over", path,
                            ours ? "written for another sweep (the case, the sweep or geardyn changed)"
                                 : "not a sweep journal, or its header is corrupt");
    }
    *pos = l0;
    return GD_OK;
}

/* Parse the records from pos on into pts; off[slot] gets the offset + 1 of the line kept
 * for each slot (the first intact one). Torn, corrupt, foreign and repeated lines are
 * counted in *ignored; only running out of memory is an error. */
static gd_status journal_parse_records(const gd_sweep_plan *p, const char *data, size_t len, size_t pos,
                                       gd_sweep_point *pts, long *off, int *ignored, gd_error *err)
{
    while (pos < len) {
        const char *nl = memchr(data + pos, '\n', len - pos);
        if (!nl) { /* the last line, torn by a kill */
            (*ignored)++;
            break;
        }
        size_t l = (size_t)(nl - (data + pos)) + 1;
        int slot = -1;
        gd_error e2 = {0};
        if (l > 1 && data[pos] == 'P') {
            /* a second record of a slot (never written twice; keep the first) */
            long sl = -1;
            if (sscanf(data + pos, "P %ld", &sl) == 1 && sl >= 0 && sl < p->nslots && off[sl]) {
                (*ignored)++;
                pos += l;
                continue;
            }
            gd_status st = gd_sweep_record_parse(p, data + pos, l, pts, &slot, &e2);
            if (st == GD_ERR_NOMEM) {
                *err = e2;
                return st;
            }
        }
        if (slot >= 0)
            off[slot] = (long)pos + 1;
        else
            (*ignored)++;
        pos += l;
    }
    return GD_OK;
}

/* A continuation chain needs every point before the ones it keeps: forget the points after
 * a missing one. */
static void journal_drop_after_gaps(const gd_sweep_plan *p, gd_sweep_point *pts, long *off, int *ignored)
{
    if (p->mode != GD_SWEEP_CONTINUATION)
        return;
    for (int c = 0; c < p->nchains; c++) {
        int gap = 0;
        for (int k = 0; k < p->chains[c].count; k++) {
            int s = p->chains[c].first + k;
            if (!off[s])
                gap = 1;
            else if (gap) {
                gd_sweep_point_clear(&pts[s]);
                off[s] = 0;
                (*ignored)++;
            }
        }
    }
}

/* The journal as it should be: the header and the kept lines, in their order in the file
 * (malloc'd into *text, NUL-terminated), or NULL when out of memory. */
static char *journal_kept_text(const gd_sweep_plan *p, const char *header, size_t hl, const char *data, size_t len,
                               const long *off, size_t *text_len)
{
    char *out = malloc(hl + len + 1);
    if (!out)
        return NULL;
    memcpy(out, header, hl);
    size_t ol = hl;
    /* walk the file again to keep the original order */
    size_t pos = 0;
    while (pos < len) {
        const char *nl = memchr(data + pos, '\n', len - pos);
        if (!nl)
            break;
        size_t l = (size_t)(nl - (data + pos)) + 1;
        long sl = -1;
        if (data[pos] == 'P' && sscanf(data + pos, "P %ld", &sl) == 1 && sl >= 0 && sl < p->nslots &&
            off[sl] == (long)pos + 1) {
            memcpy(out + ol, data + pos, l);
            ol += l;
        }
        pos += l;
    }
    out[ol] = '\0';
    *text_len = ol;
    return out;
}

GD_API gd_status gd_sweep_journal_load(const char *path, const gd_sweep_plan *p, gd_sweep_point *pts, char **text,
                                       size_t *text_len, int *loaded, int *ignored, gd_error *err)
{
    char header[300];
    gd_sweep_journal_header(p, header, sizeof header);
    size_t hl = strlen(header);
    *loaded = *ignored = 0;
    *text = NULL;
    *text_len = 0;
    char *data;
    size_t len;
    int missing;
    gd_status st = read_all(path, &data, &len, &missing, err);
    if (st != GD_OK)
        return st;
    long *off = calloc((size_t)p->nslots, sizeof(long)); /* offset + 1 of the kept line of each slot */
    if (!off) {
        free(data);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory reading the journal");
    }
    size_t pos = 0;
    if (!missing)
        st = journal_check_header(path, data, len, header, hl, &pos, ignored, err);
    if (st == GD_OK)
        st = journal_parse_records(p, data, len, pos, pts, off, ignored, err);
    if (st != GD_OK) {
        free(data);
        free(off);
        return st;
    }
    journal_drop_after_gaps(p, pts, off, ignored);
    char *out = journal_kept_text(p, header, hl, data, len, off, text_len);
    free(data);
    if (!out) {
        free(off);
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory reading the journal");
    }
    for (int s = 0; s < p->nslots; s++)
        if (off[s])
            (*loaded)++;
    free(off);
    *text = out;
    return GD_OK;
}

/* ---- tables ---- */

static void fmt_num(FILE *f, const char *fmt, double v)
{
    if (isfinite(v))
        fprintf(f, fmt, v);
    else
        fputs("nan", f);
}

static void csv_text(FILE *f, const char *s)
{
    if (!strpbrk(s, ",\"\n")) {
        fputs(s, f);
        return;
    }
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"')
            fputc('"', f);
        fputc(*s == '\n' ? ' ' : *s, f);
    }
    fputc('"', f);
}

gd_status gd_sweep_write_tables(gd_run_dir *d, const gd_sweep_plan *p, const gd_sweep_point *pts, gd_error *err)
{
    FILE *sw, *bf;
    gd_status st = gd_run_dir_create(d, "sweep.csv", &sw, err);
    if (st != GD_OK)
        return st;
    if ((st = gd_run_dir_create(d, "bifurcation.csv", &bf, err)) != GD_OK) {
        gd_run_dir_discard(d, sw);
        return st;
    }
    int map = p->naxes > 1;
    fprintf(sw, "parameter,direction,rms_accel_mps2,mle,motion,impact_regime%s,period_n,poincare_distinct,"
                   "rms_accel_L_mps2,rms_accel_R_mps2,impact_regime_L,impact_regime_R,mle_per_s,transient_periods,"
                   "dynamic_load_factor,dynamic_load_factor_L,dynamic_load_factor_R,status,error\n",
            map ? ",parameter2" : "");
    fprintf(bf, "parameter,direction%s", map ? ",parameter2" : "");
    for (int r = 0; r < p->nresp; r++)
        fprintf(bf, ",%s", p->resp[r].name);
    fputc('\n', bf);
    for (int s = 0; s < p->nslots; s++) {
        const gd_sweep_point *pt = &pts[s];
        const char *dirn = gd_sweep_branch_name(pt->branch);
        char v1[40], v2[40] = "";
        snprintf(v1, sizeof v1, "%.12g", pt->value[0]);
        if (map)
            snprintf(v2, sizeof v2, ",%.12g", pt->value[1]);
        int done = pt->status == GD_POINT_DONE;
        fprintf(sw, "%s,%s,", v1, dirn);
        fmt_num(sw, "%.9g", done ? pt->rms_accel_mps2[2] : NAN);
        fputc(',', sw);
        fmt_num(sw, "%.9g", done ? pt->mle_per_period : NAN);
        fprintf(sw, ",%s,%s%s,%d,%d,", pt->status == GD_POINT_PENDING ? "pending" : pt->motion,
                done ? gd_impact_regime_name(pt->impact_regime[2]) : "", v2, pt->period_n, pt->poincare_distinct);
        fmt_num(sw, "%.9g", done ? pt->rms_accel_mps2[0] : NAN);
        fputc(',', sw);
        fmt_num(sw, "%.9g", done ? pt->rms_accel_mps2[1] : NAN);
        fprintf(sw, ",%s,%s,", done ? gd_impact_regime_name(pt->impact_regime[0]) : "",
                done ? gd_impact_regime_name(pt->impact_regime[1]) : "");
        fmt_num(sw, "%.9g", done ? pt->mle_per_s : NAN);
        if (done)
            fprintf(sw, ",%ld", pt->transient_periods);
        else
            fputc(',', sw);
        for (int i = -1; i < 2; i++) { /* the larger of the meshes, then each */
            fputc(',', sw);
            fmt_num(sw, "%.9g", !done ? NAN : i >= 0 ? pt->dynamic_load_factor[i] : gd_sweep_point_dlf(pt));
        }
        fprintf(sw, ",%s,", done ? "done" : pt->status == GD_POINT_FAILED ? "failed" : "pending");
        csv_text(sw, pt->error);
        fputc('\n', sw);
        for (long k = 0; k < pt->npoincare; k++) {
            fprintf(bf, "%s,%s%s", v1, dirn, v2);
            for (int r = 0; r < p->nresp; r++) {
                fputc(',', bf);
                fmt_num(bf, "%.10g", pt->poincare[k * p->nresp + r]);
            }
            fputc('\n', bf);
        }
    }
    st = gd_run_dir_commit(d, sw, err);
    if (st == GD_OK)
        st = gd_run_dir_commit(d, bf, err);
    else
        gd_run_dir_discard(d, bf);
    return st;
}

/* ---- summary.json ---- */

static json_t *axis_json(const gd_case *c, const gd_sweep_plan *p, int a)
{
    json_t *o = json_object();
    json_object_set_new(o, "name", json_string(p->parameter[a]));
    json_object_set_new(o, "unit", json_string(p->unit[a]));
    json_object_set_new(o, "from", gd_json_num(a ? c->sweep_from2 : c->sweep_from));
    json_object_set_new(o, "to", gd_json_num(a ? c->sweep_to2 : c->sweep_to));
    json_object_set_new(o, "points", json_integer(p->npoints[a]));
    json_object_set_new(o, "spacing", json_string(p->spacing[a] == GD_SWEEP_LOG ? "log" : "linear"));
    json_t *v = json_array();
    for (int i = 0; i < p->npoints[a]; i++)
        json_array_append_new(v, gd_json_num(p->values[a][i]));
    json_object_set_new(o, "values", v);
    return o;
}

/* The smallest and largest value over the points, and where the largest is. */
typedef struct extremes {
    double min, max, max_at, max_at2;
    int max_branch;
} extremes;

static void extremes_add(extremes *e, double v, const gd_sweep_point *pt)
{
    if (v < e->min)
        e->min = v;
    if (v > e->max) {
        e->max = v;
        e->max_at = pt->value[0];
        e->max_at2 = pt->value[1];
        e->max_branch = pt->branch;
    }
}

static json_t *extremes_json(const extremes *e, int naxes)
{
    json_t *o = json_object();
    json_object_set_new(o, "min", gd_json_num(e->min));
    json_object_set_new(o, "max", gd_json_num(e->max));
    json_object_set_new(o, "max_at", gd_json_num(e->max_at));
    json_object_set_new(o, "max_direction", isfinite(e->max) ? json_string(gd_sweep_branch_name(e->max_branch))
                                                              : json_null());
    if (naxes > 1)
        json_object_set_new(o, "max_at_parameter2", gd_json_num(e->max_at2));
    return o;
}

static void count_in(json_t *obj, const char *key)
{
    json_t *v = json_object_get(obj, key);
    json_object_set_new(obj, key, json_integer(v ? json_integer_value(v) + 1 : 1));
}

/* The "sweep" object: the axes, mode, direction and responses of the plan. */
static json_t *sweep_json(const gd_case *c, const gd_sweep_plan *p)
{
    json_t *sw = json_object();
    json_object_set_new(sw, "parameter", axis_json(c, p, 0));
    json_object_set_new(sw, "parameter2", p->naxes > 1 ? axis_json(c, p, 1) : json_null());
    json_object_set_new(sw, "mode", json_string(p->mode == GD_SWEEP_CONTINUATION ? "continuation" : "independent"));
    char dirn[16];
    gd_case_key_choice("sweep", "direction", p->direction, dirn, sizeof dirn);
    json_object_set_new(sw, "direction", p->mode == GD_SWEEP_CONTINUATION ? json_string(dirn) : json_null());
    json_t *rs = json_array();
    for (int r = 0; r < p->nresp; r++)
        json_array_append_new(rs, json_string(p->resp[r].name));
    json_object_set_new(sw, "responses", rs);
    json_object_set_new(sw, "responses_unit", json_string("dimensionless: lengths over solver.characteristic_length_um, "
                                                          "rates over that length times the natural frequency"));
    json_object_set_new(sw, "poincare_samples_per_point", json_integer(p->npoincare));
    json_object_set_new(sw, "points", json_integer(p->nslots));
    json_object_set_new(sw, "mle_unit", json_string("per mesh period"));
    return sw;
}

/* The failed point pt as an entry of results.failed. */
static json_t *failed_json(const gd_sweep_plan *p, const gd_sweep_point *pt)
{
    json_t *f = json_object();
    json_object_set_new(f, "parameter", gd_json_num(pt->value[0]));
    if (p->naxes > 1)
        json_object_set_new(f, "parameter2", gd_json_num(pt->value[1]));
    json_object_set_new(f, "direction", json_string(gd_sweep_branch_name(pt->branch)));
    json_object_set_new(f, "error", json_string(gd_status_name(pt->error_code)));
    json_object_set_new(f, "message", json_string(pt->error));
    return f;
}

/* The tallies over every point, in slot order: counts, extremes and solver totals. */
typedef struct tally {
    json_t *motion, *impact, *failed;
    long ndone, nfail, npend, steps, rhs, events, positive;
    extremes rms, mle, dlf;
} tally;

static void tally_points(const gd_sweep_plan *p, const gd_sweep_point *pts, tally *t)
{
    t->motion = json_object();
    t->impact = json_object();
    t->failed = json_array();
    t->ndone = t->nfail = t->npend = t->steps = t->rhs = t->events = t->positive = 0;
    t->rms = (extremes){INFINITY, -INFINITY, NAN, NAN, 0};
    t->mle = (extremes){INFINITY, -INFINITY, NAN, NAN, 0};
    t->dlf = (extremes){INFINITY, -INFINITY, NAN, NAN, 0};
    for (int s = 0; s < p->nslots; s++) {
        const gd_sweep_point *pt = &pts[s];
        t->steps += pt->steps;
        t->rhs += pt->rhs_evals;
        t->events += pt->events;
        if (pt->status == GD_POINT_PENDING) {
            t->npend++;
            continue;
        }
        if (pt->status == GD_POINT_FAILED) {
            t->nfail++;
            count_in(t->motion, "failed");
            json_array_append_new(t->failed, failed_json(p, pt));
            continue;
        }
        t->ndone++;
        count_in(t->motion, pt->motion);
        count_in(t->impact, gd_impact_regime_name(pt->impact_regime[2]));
        double l = pt->mle_per_period;
        extremes_add(&t->rms, pt->rms_accel_mps2[2], pt);
        if (isfinite(gd_sweep_point_dlf(pt)))
            extremes_add(&t->dlf, gd_sweep_point_dlf(pt), pt);
        if (isfinite(l)) {
            extremes_add(&t->mle, l, pt);
            t->positive += l > 0;
        }
    }
}

/* results.branches (one-parameter continuation): where the motion class changes, in chain order. */
static json_t *branches_json(const gd_sweep_plan *p, const gd_sweep_point *pts)
{
    json_t *brs = json_array();
    for (int ch = 0; ch < p->nchains; ch++) {
        const gd_sweep_chain *cc = &p->chains[ch];
        json_t *b = json_object(), *tr = json_array();
        json_object_set_new(b, "direction", json_string(gd_sweep_branch_name(cc->branch)));
        for (int k = 1; k < cc->count; k++) {
            const gd_sweep_point *a = &pts[cc->first + k - 1], *q = &pts[cc->first + k];
            if (a->status == GD_POINT_PENDING || q->status == GD_POINT_PENDING || strcmp(a->motion, q->motion) == 0)
                continue;
            json_t *t = json_object();
            json_object_set_new(t, "between", json_pack("[o,o]", gd_json_num(a->value[0]), gd_json_num(q->value[0])));
            json_object_set_new(t, "from", json_string(a->motion));
            json_object_set_new(t, "to", json_string(q->motion));
            json_array_append_new(tr, t);
        }
        json_object_set_new(b, "motion_changes", tr);
        json_array_append_new(brs, b);
    }
    return brs;
}

/* results.hysteresis: the intervals of gd_sweep_hysteresis. */
static json_t *hysteresis_json(const gd_sweep_plan *p, const gd_sweep_interval *iv, int niv)
{
    json_t *hy = json_array();
    for (int j = 0; j < niv; j++) {
        json_t *h = json_object();
        json_object_set_new(h, "from", gd_json_num(p->values[0][iv[j].from]));
        json_object_set_new(h, "to", gd_json_num(p->values[0][iv[j].to]));
        json_object_set_new(h, "points", json_integer(iv[j].points));
        if (p->naxes > 1)
            json_object_set_new(h, "parameter2", gd_json_num(p->values[1][iv[j].row]));
        json_array_append_new(hy, h);
    }
    return hy;
}

/* The "results" object. */
static gd_status results_json(const gd_sweep_plan *p, const gd_sweep_point *pts, const tally *t, json_t **out,
                              gd_error *err)
{
    json_t *res = json_object();
    json_object_set_new(res, "points_done", json_integer(t->ndone));
    json_object_set_new(res, "points_failed", json_integer(t->nfail));
    json_object_set_new(res, "points_pending", json_integer(t->npend));
    json_object_set_new(res, "motion_counts", t->motion);
    json_object_set_new(res, "impact_regime_counts", t->impact);
    json_object_set_new(res, "rms_accel_mps2", extremes_json(&t->rms, p->naxes));
    json_object_set_new(res, "dynamic_load_factor", extremes_json(&t->dlf, p->naxes));
    json_t *la = extremes_json(&t->mle, p->naxes);
    json_object_set_new(la, "positive_points", json_integer(t->positive));
    json_object_set_new(res, "mle_per_period", la);
    json_object_set_new(res, "failed", t->failed);
    if (p->naxes == 1 && p->mode == GD_SWEEP_CONTINUATION)
        json_object_set_new(res, "branches", branches_json(p, pts));
    if (p->mode == GD_SWEEP_CONTINUATION && p->direction == GD_SWEEP_BOTH) {
        gd_sweep_interval *iv;
        int niv;
        gd_status st = gd_sweep_hysteresis(p, pts, &iv, &niv, err);
        if (st != GD_OK) {
            json_decref(res);
            return st;
        }
        json_object_set_new(res, "hysteresis", hysteresis_json(p, iv, niv));
        free(iv);
    }
    *out = res;
    return GD_OK;
}

gd_status gd_sweep_write_summary(gd_run_dir *d, const gd_case *c, const gd_modal *modes, const gd_sweep_plan *p,
                                 const gd_sweep_point *pts, gd_error *err)
{
    tally t;
    tally_points(p, pts, &t);
    json_t *res;
    gd_status st = results_json(p, pts, &t, &res, err);
    if (st != GD_OK)
        return st;
    json_t *root = gd_json_root(c, "sweep", "scene", "model");
    json_object_set_new(root, "sweep", sweep_json(c, p));
    json_object_set_new(root, "derived", json_pack("{s:o}", "modal", gd_modal_json(c, modes)));
    json_object_set_new(root, "results", res);
    json_t *sol = json_object();
    json_object_set_new(sol, "steps", json_integer(t.steps));
    json_object_set_new(sol, "rhs_evals", json_integer(t.rhs));
    json_object_set_new(sol, "events", json_integer(t.events));
    json_object_set_new(root, "solver", sol);
    return gd_json_write_summary(d, root, err);
}
