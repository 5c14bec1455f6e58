/* The curves of the `continuation` analysis (continuation.parameter2; docs/continuation.md section
 * 8): the keys checked, and every fold, period doubling, Neimark-Sacker point and grazing of the branches continued in
 * (parameter, parameter2) both ways by gd_curve_follow (gd_envelope.h), each bifurcation once, or
 * only the curve of one row of an earlier run's bifurcations.csv (continuation.curve_start, read by
 * src/output/curve_start.c); the end reasons in the keys' names and units. */
#include "geardyn/gd_continuation.h"
#include "../case/case_keys.h"
#include "analysis_internal.h"
#include "../core/clock.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WHERE(key) (gd_case_key_where(c, "continuation", key, w, sizeof w), w)

unsigned gd_contin_curve_kinds(const char *list, char *bad, size_t nbad)
{
    unsigned mask = 0;
    const char *s = list;
    bad[0] = 0;
    while (*s) {
        while (*s == ' ' || *s == ',')
            s++;
        if (!*s)
            break;
        size_t n = strcspn(s, ",");
        while (n > 0 && s[n - 1] == ' ')
            n--;
        int k = -1;
        for (int i = 0; i <= GD_CURVE_GRAZING && k < 0; i++)
            if (strlen(gd_curve_kind_name(i)) == n && strncmp(s, gd_curve_kind_name(i), n) == 0)
                k = i;
        if (k < 0 || (mask & (1u << k))) {
            snprintf(bad, nbad, "%.*s", (int)n, s);
            return 0;
        }
        mask |= 1u << k;
        s += n;
        while (*s == ' ')
            s++;
    }
    return mask;
}

gd_status gd_contin_check_curves(const gd_case *c, gd_error *err)
{
    char w[GD_PATH_MAX + 32], range[160], bad[128];
    if (!gd_contin_curve_kinds(c->cont_curve_kinds, bad, sizeof bad))
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_kinds: '%s' %s (valid: a comma-separated list "
                            "of fold, period-doubling, neimark-sacker, grazing, each once)", WHERE("curve_kinds"),
                            bad[0] ? bad : c->cont_curve_kinds,
                            bad[0] ? "is not a kind of curve, or is named twice" : "names no kind");
    static const char *bk[2] = {"parameter2_from", "parameter2_to"};
    const char *name = c->cont_parameter2;
    if (gd_case_key_given(c, "continuation", "curve_start_row") && !c->cont_curve_start[0])
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start_row: given without "
                            "continuation.curve_start (valid: name the bifurcations.csv whose row starts the curve, or "
                            "leave curve_start_row out)", WHERE("curve_start_row"));
    if (!name[0] && c->cont_curve_start[0])
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_start: given without continuation.parameter2 "
                            "(valid: set parameter2, the curve's second key, or leave curve_start out)",
                            WHERE("curve_start"));
    if (!name[0] && gd_case_key_given(c, "continuation", "curve_kinds"))
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.curve_kinds: given without continuation.parameter2 "
                            "(valid: set parameter2, the curves' second key, or leave curve_kinds out)",
                            WHERE("curve_kinds"));
    if (!name[0]) {
        for (int i = 0; i < 2; i++)
            if (gd_case_key_given(c, "continuation", bk[i]))
                return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.%s: given without continuation.parameter2 "
                                    "(valid: set parameter2, the curves' second key, or leave %s out)", WHERE(bk[i]),
                                    bk[i], bk[i]);
        return GD_OK;
    }
    const gd_keyspec *k = gd_case_key_dotted(name);
    if (!k || k->type != GD_KEY_DOUBLE || strcmp(k->section, "continuation") == 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.parameter2: '%s' is not a real-valued numeric key of "
                            "the case (valid: section.key of a number other than continuation.parameter, e.g. "
                            "excitation.ste_amplitude_um, operating.torque_nm)", WHERE("parameter2"), name);
    if (strcmp(name, c->cont_parameter) == 0)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.parameter2: '%s' is continuation.parameter too "
                            "(valid: a second, different numeric key)", WHERE("parameter2"), name);
    gd_case_key_range_text(k, range, sizeof range);
    double b[2] = {c->cont_from2, c->cont_to2};
    for (int i = 0; i < 2; i++) {
        if (!gd_case_key_given(c, "continuation", bk[i]))
            return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.%s: missing (valid: the %s bound of %s, %s)",
                                WHERE("parameter2"), bk[i], i ? "upper" : "lower", name, range);
        if (!gd_case_key_in_range(k, b[i]))
            return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.%s: %s = %.10g is out of range (valid: %s)",
                                WHERE(bk[i]), bk[i], name, b[i], range);
    }
    if (!(c->cont_from2 < c->cont_to2))
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.parameter2_to: %.10g is not above parameter2_from = "
                            "%.10g (valid: parameter2_from < parameter2_to)", WHERE("parameter2_to"), c->cont_to2,
                            c->cont_from2);
    double v;
    gd_error e2 = {0};
    if (gd_case_get_number(c, name, &v, &e2) != GD_OK)
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.parameter2: %s", WHERE("parameter2"), e2.msg);
    if (!(v >= c->cont_from2 && v <= c->cont_to2))
        return gd_error_set(err, GD_ERR_INPUT, "%s: continuation.parameter2: the case's %s = %.10g lies outside "
                            "[parameter2_from, parameter2_to] = [%.10g, %.10g] (valid: the one-parameter branches run "
                            "at the case's value, inside the bounds)", WHERE("parameter2"), name, v, c->cont_from2,
                            c->cont_to2);
    return GD_OK;
}

/* The curve kind of a bifurcation, or -1 when none is continued. */
static int curve_kind(const gd_bifurcation *bf)
{
    if (bf->location != GD_LOC_LOCATED)
        return -1;
    return bf->kind == GD_BIF_FOLD ? GD_CURVE_FOLD
         : bf->kind == GD_BIF_PERIOD_DOUBLING ? GD_CURVE_PERIOD_DOUBLING
         : bf->kind == GD_BIF_NEIMARK_SACKER ? GD_CURVE_NEIMARK_SACKER
         : bf->kind == GD_BIF_CONTACT_CHANGE && bf->clearance >= 0 ? GD_CURVE_GRAZING : -1;
}

/* Whether bifurcation i of branch ib was continued already: one of the same kind, period and clearance
 * at the same parameter on an earlier branch or earlier on this one. */
static int continued_before(const gd_contin_result *res, int ib, int i, double tol)
{
    const gd_bifurcation *bf = &res->branch[ib].br.bif[i];
    for (int b = 0; b <= ib; b++)
        for (int j = 0; j < (b < ib ? res->branch[b].br.nbif : i); j++) {
            const gd_bifurcation *o = &res->branch[b].br.bif[j];
            if (res->branch[b].nper == res->branch[ib].nper && o->kind == bf->kind && o->clearance == bf->clearance &&
                fabs(o->p - bf->p) <= tol)
                return 1;
        }
    return 0;
}

/* Whether an earlier curve of bifurcation bf's kind, period and clearance crossed the branches' line
 * p2 = v2 within tol of bf (a Neimark-Sacker curve with the pair at bf's angle, to 0.05 in cos theta):
 * then bf lies on that curve, followed both ways from its own start. The crossing's p1 by linear
 * interpolation. Asked for Neimark-Sacker points (two of a branch on one closed curve, the curve between
 * them followed once instead of twice); two folds of a branch on one fold curve through a cusp are each
 * followed, the cusp located from both. */
static int on_earlier_curve(const gd_contin_result *res, const gd_bifurcation *bf, int kind, int nper, double v2,
                            double tol, int *which)
{
    const double kappa = kind == GD_CURVE_NEIMARK_SACKER ? bf->mu_re / hypot(bf->mu_re, bf->mu_im) : NAN;
    for (int j = 0; j < res->ncurves; j++) {
        const gd_curve *cv = &res->curve[j].cv;
        if (cv->kind != kind || cv->nper != nper || (kind == GD_CURVE_GRAZING && cv->clearance != bf->clearance))
            continue;
        for (int i = 1; i + 1 < cv->npoints; i++) {
            const gd_curve_point *a = &cv->pt[i], *b = &cv->pt[i + 1];
            const double fa = a->p2 - v2, fb = b->p2 - v2;
            if (fa * fb > 0 || fa == fb)
                continue;
            const double t = fa / (fa - fb), p1 = a->orbit.p + t * (b->orbit.p - a->orbit.p);
            if (fabs(p1 - bf->p) > tol)
                continue;
            if (kind == GD_CURVE_NEIMARK_SACKER && !(fabs(a->kappa + t * (b->kappa - a->kappa) - kappa) < 0.05))
                continue;
            *which = j;
            return 1;
        }
    }
    return 0;
}

static void curve_note(gd_contin_result *res, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void curve_note(gd_contin_result *res, const char *fmt, ...)
{
    if (res->nnotes >= GD_CONTIN_NOTES) {
        res->notes_dropped++;
        return;
    }
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(res->notes[res->nnotes++], GD_ERROR_MSG_MAX, fmt, ap);
    va_end(ap);
}

/* Follow the curve of start both ways into res (from branch ib's bifurcation i, or -1, -1: a row); *st
 * set on an error that ends the run, a note on a curve not followed. */
static gd_status follow_both(gd_contin_result *res, gd_case_param2 *pp, const gd_solver_opts *o, gd_curve_opts *cvo,
                             const gd_curve_start *s, int ib, int i, const char *what, gd_error *err)
{
    gd_status st = GD_OK;
    for (int dir = -1; dir <= 1 && st == GD_OK; dir += 2) {
        gd_contin_curve *cc = realloc(res->curve, sizeof *cc * (size_t)(res->ncurves + 1));
        if (!cc)
            return gd_error_set(err, GD_ERR_NOMEM, "out of memory for the curves");
        res->curve = cc;
        gd_contin_curve *cu = &res->curve[res->ncurves];
        memset(cu, 0, sizeof *cu);
        cu->branch = ib;
        cu->bif = i;
        cu->direction = dir;
        cvo->direction = dir;
        gd_error e2 = {0};
        gd_status cs = gd_curve_follow(gd_model_at_case_keys, pp, o, cvo, s, &cu->cv, &e2);
        if (cs == GD_OK) {
            res->curve_corrections += cu->cv.corrections;
            res->ncurves++;
        } else if (cs == GD_ERR_NOMEM || cs == GD_ERR_INTERRUPTED) {
            st = gd_error_set(err, cs, "%s", e2.msg);
        } else {
            curve_note(res, "no %s curve from %s (%s): %s", gd_curve_kind_name(s->kind), what, dir > 0 ? "up" : "down",
                       e2.msg);
        }
    }
    return st;
}

gd_status gd_contin_curves(const gd_case *c, gd_case *work, const gd_solver_opts *o, const gd_cont_opts *co,
                           const gd_contin_curve_row *row, gd_contin_result *res, gd_error *err)
{
    if (!c->cont_parameter2[0])
        return GD_OK;
    double t0 = gd_clock_thread_cpu_s();
    snprintf(res->parameter2, sizeof res->parameter2, "%s", c->cont_parameter2);
    snprintf(res->unit2, sizeof res->unit2, "%s", gd_case_key_dotted(c->cont_parameter2)->unit);
    double v2;
    gd_status st = gd_case_get_number(work, res->parameter2, &v2, err);
    if (st != GD_OK)
        return st;
    double big = fmax(fabs(c->cont_from2), fabs(c->cont_to2));
    res->scale2 = big > 0 ? big : 1.0;
    gd_case_param2 pp = {work, res->parameter, res->parameter2, res->scale, res->scale2};
    gd_curve_opts cvo;
    gd_curve_opts_default(&cvo);
    cvo.po = co->po;
    cvo.p_min[0] = co->p_min;
    cvo.p_max[0] = co->p_max;
    cvo.p_min[1] = c->cont_from2 / res->scale2;
    cvo.p_max[1] = c->cont_to2 / res->scale2;
    cvo.ds = co->ds;
    cvo.ds_min = co->ds_min;
    cvo.ds_max = co->ds_max;
    cvo.dp_max[0] = co->dp_max;
    cvo.max_points = c->cont_curve_max_points;
    cvo.locate_tol = co->locate_tol;
    cvo.stop = co->stop;
    cvo.words.key[0] = res->parameter;
    cvo.words.key[1] = res->parameter2;
    cvo.words.unit[0] = res->unit;
    cvo.words.unit[1] = res->unit2;
    cvo.words.value_scale[0] = res->scale;
    cvo.words.value_scale[1] = res->scale2;
    cvo.words.bound_key[0][0] = "continuation.from"; /* p_min: from / scale, as the branches' */
    cvo.words.bound_key[0][1] = "continuation.to";
    cvo.words.bound_key[1][0] = "continuation.parameter2_from";
    cvo.words.bound_key[1][1] = "continuation.parameter2_to";
    const double tol = 1e-6 * (co->p_max - co->p_min);
    char bad[128];
    const unsigned kinds = gd_contin_curve_kinds(c->cont_curve_kinds, bad, sizeof bad);
    if (row) { /* only the curve of an earlier run's row */
        gd_curve_start s;
        memset(&s, 0, sizeof s);
        s.kind = row->kind;
        s.nper = row->nper;
        s.clearance = row->kind == GD_CURVE_GRAZING ? row->clearance : -1;
        s.p1 = row->value / res->scale;
        s.p2 = v2 / res->scale2;
        memcpy(s.y, row->y, sizeof s.y);
        snprintf(res->curve_start, sizeof res->curve_start, "%s", row->source);
        st = follow_both(res, &pp, o, &cvo, &s, -1, -1, row->source, err);
    }
    const int nb = row ? 0 : res->nbranches;
    for (int ib = 0; ib < nb && st == GD_OK; ib++)
        for (int i = 0; i < res->branch[ib].br.nbif && st == GD_OK; i++) {
            const gd_bifurcation *bf = &res->branch[ib].br.bif[i];
            int kind = curve_kind(bf);
            if (kind < 0 && bf->kind != GD_BIF_BRANCH_POINT)
                curve_note(res, "branch %d: the %s at %.10g is not continued in %s: its location ended %s", ib,
                           gd_bif_kind_name(bf->kind), gd_contin_value(res, bf->p), res->parameter2,
                           gd_bif_location_name(bf->location));
            if (kind < 0 || !(kinds & (1u << kind)) || continued_before(res, ib, i, tol))
                continue;
            int on = -1;
            if (kind == GD_CURVE_NEIMARK_SACKER &&
                on_earlier_curve(res, bf, kind, res->branch[ib].nper, v2 / res->scale2,
                                 5e-3 * (co->p_max - co->p_min), &on)) {
                curve_note(res, "branch %d: the %s at %.10g lies on curve %d (%s from the %s of branch %d at %.10g), "
                           "followed both ways from there: not followed again", ib, gd_bif_kind_name(bf->kind),
                           gd_contin_value(res, bf->p), on, res->curve[on].direction > 0 ? "up" : "down",
                           gd_bif_kind_name(res->branch[res->curve[on].branch].br.bif[res->curve[on].bif].kind),
                           res->curve[on].branch, gd_contin_value(res, res->curve[on].cv.pt[0].orbit.p));
                continue;
            }
            gd_curve_start s;
            memset(&s, 0, sizeof s);
            s.kind = kind;
            s.nper = res->branch[ib].nper;
            s.clearance = kind == GD_CURVE_GRAZING ? bf->clearance : -1;
            s.p1 = bf->p;
            s.p2 = v2 / res->scale2;
            memcpy(s.y, bf->y, sizeof s.y);
            char what[160];
            snprintf(what, sizeof what, "the %s of branch %d at %.10g", gd_bif_kind_name(bf->kind), ib,
                     gd_contin_value(res, bf->p));
            st = follow_both(res, &pp, o, &cvo, &s, ib, i, what, err);
        }
    /* the case as it was: the second key at its value */
    gd_error e3 = {0};
    gd_status rs = gd_case_set_number(work, res->parameter2, v2, &e3);
    if (st == GD_OK && rs != GD_OK)
        st = gd_error_set(err, rs, "%s", e3.msg);
    res->curve_cpu_s = gd_clock_thread_cpu_s() - t0;
    return st;
}
