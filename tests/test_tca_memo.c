/* The memo of contact lines (src/contact/tca_lines_memo.c): a memoised result is the computed one to
 * the bit, on the paper's pair with its installation errors and modification.
 *  1. lines: at eight positions of both halves, the lines within a window w from the memo (after the
 *     lines within 3 w were computed and kept) are, point for point and byte for byte, those a
 *     workspace with the memo off computes within w; the lines within 3 w after those within w
 *     (a miss: computed again, wider) too;
 *  2. the whole LTCA with the mesh-in impact at 520 N m, run after one at 500 N m filled the memo, is
 *     byte for byte the LTCA at 520 N m with the memo off (LTE, stiffness, loads, every point, the
 *     mesh-in impacts), and the memo served it (hits counted);
 *  3. off means off: no hits while it is off. */
#include "ltca_util.h"
#include "pair_util.h"
#include "contact/tca_internal.h"

#include <stdlib.h>

static int same_lines(const gd_tca_line_point *a, int na, const gd_tca_line_point *b, int nb)
{
    return na == nb && (na == 0 || memcmp(a, b, (size_t)na * sizeof *a) == 0);
}

/* the lines of position phi1 within w: a copy (the workspace's buffer is reused) */
static gd_tca_line_point *lines(gd_tca *t, int h, double phi1, double w, int *n)
{
    gd_error e = {0};
    const gd_tca_line_point *p;
    if (gd_tca_lines_at(t, h, phi1, w, &p, n, &e) != GD_OK) {
        tap_ok(0, "lines at %.9g within %.3g um: %s", phi1, w * 1e6, e.msg);
        *n = -1;
        return NULL;
    }
    gd_tca_line_point *c = malloc((size_t)(*n > 0 ? *n : 1) * sizeof *c);
    memcpy(c, p, (size_t)*n * sizeof *c);
    return c;
}

static void memo_lines(const gd_case *c)
{
    gd_error e = {0};
    const gd_ltca_settings ls = gd_ltca_settings_from_case(c);
    const gd_tca_settings ts = {.profile_points = ls.profile_points, .face_points = ls.face_slices,
                                .refine = ls.refine};
    gd_tca *t;
    if (gd_tca_create(PAIR_OF(c), &ts, &t, &e) != GD_OK) {
        tap_ok(0, "TCA workspace: %s", e.msg);
        return;
    }
    const double w = 6e-6, tau = 2 * M_PI / c->teeth_pinion;
    int worst_hit = 1, worst_miss = 1, npts = 0, fewer = 0;
    for (int k = 0; k < 8; k++)
        for (int h = 0; h < gd_tca_halves(t); h++) {
            const double phi1 = tau * k / 8;
            int n0, n1, nm, nw, nw0;
            gd_tca_memo_enable(0);
            gd_tca_line_point *ref = lines(t, h, phi1, w, &n0), *refw = lines(t, h, phi1, 3 * w, &nw0);
            gd_tca_memo_enable(1);
            gd_tca_line_point *wide = lines(t, h, phi1, 3 * w, &nw); /* computed within 6 w, kept */
            long hits = gd_tca_memo_hits();
            gd_tca_line_point *m = lines(t, h, phi1, w, &nm);      /* from the memo */
            worst_hit &= gd_tca_memo_hits() == hits + 1 && same_lines(m, nm, ref, n0) && same_lines(wide, nw, refw, nw0);
            gd_tca_memo_enable(1);                                  /* emptied */
            gd_tca_line_point *a = lines(t, h, phi1, w, &n1), *b = lines(t, h, phi1, 7 * w, &nw);
            gd_tca_memo_enable(0);
            gd_tca_line_point *refb = lines(t, h, phi1, 7 * w, &nw0);
            worst_miss &= same_lines(a, n1, ref, n0) && same_lines(b, nw, refb, nw0);
            npts += n0;
            fewer += n0 < nw0;
            free(ref), free(refw), free(wide), free(m), free(a), free(b), free(refb);
        }
    tap_ok(worst_hit, "lines from the memo within 6 um are those computed within 6 um, byte for byte (8 positions, "
           "both halves, %d points); those within 18 um too", npts);
    tap_ok(worst_miss, "lines within 42 um after those within 6 um (computed again, wider) are those computed within "
           "42 um");
    tap_ok(fewer > 0, "the windows differ: %d of the 16 position-halves have more points within 42 um than within "
           "6 um", fewer);
    gd_tca_free(t);
}

static int same_result(const gd_ltca_result *a, const gd_ltca_result *b)
{
    const int N = a->npos, H = a->halves;
    int ok = a->npos == b->npos && a->halves == b->halves && a->first[N] == b->first[N];
    ok = ok && !memcmp(a->lte_arcsec, b->lte_arcsec, (size_t)N * sizeof(double));
    for (int h = 0; h < H && ok; h++)
        ok = !memcmp(a->stiffness[h], b->stiffness[h], (size_t)N * sizeof(double)) &&
             !memcmp(a->load[h], b->load[h], (size_t)N * sizeof(double)) &&
             !memcmp(a->max_pressure[h], b->max_pressure[h], (size_t)N * sizeof(double)) &&
             !memcmp(&a->impact[h], &b->impact[h], sizeof a->impact[h]);
    return ok && !memcmp(a->points, b->points, (size_t)a->first[N] * sizeof *a->points);
}

static void memo_ltca(gd_case *c)
{
    gd_error e = {0};
    gd_ltca_settings s = *LTCA_SET_OF(c);
    gd_ltca_result off, on, first;
    enum { N = 16 };
    gd_tca_memo_enable(0);
    s.torque_nm = 520;
    if (gd_ltca_run_opts(PAIR_OF(c), &s, N, 1, &off, &e) != GD_OK) {
        tap_ok(0, "LTCA, memo off: %s", e.msg);
        return;
    }
    tap_ok(gd_tca_memo_hits() == 0, "memo off: no hits (%ld)", gd_tca_memo_hits());
    gd_tca_memo_enable(1);
    s.torque_nm = 500;
    if (gd_ltca_run_opts(PAIR_OF(c), &s, N, 1, &first, &e) != GD_OK) {
        tap_ok(0, "LTCA at 500 N m, memo on: %s", e.msg);
        return;
    }
    const long h0 = gd_tca_memo_hits();
    s.torque_nm = 520;
    if (gd_ltca_run_opts(PAIR_OF(c), &s, N, 1, &on, &e) != GD_OK) {
        tap_ok(0, "LTCA at 520 N m, memo on: %s", e.msg);
        return;
    }
    const long h1 = gd_tca_memo_hits() - h0;
    tap_ok(same_result(&on, &off), "LTCA at 520 N m after one at 500 N m, memo on: byte for byte the LTCA with the "
           "memo off (LTE, stiffness, loads, pressures, %d points, mesh-in impacts at phase %.6f and %.6f)",
           on.first[N], on.impact[0].phase, on.impact[1].phase);
    tap_ok(h1 >= 2 * N, "and the memo served it: %ld hits (at least the 2 x %d positions)", h1, N);
    gd_ltca_result_free(&off);
    gd_ltca_result_free(&on);
    gd_ltca_result_free(&first);
}

int main(void)
{
    gd_case c;
    if (lt_case(&c, LT_MIS | LT_MOD, NULL))
        return tap_done();
    memo_lines(&c);
    memo_ltca(&c);
    gd_tca_memo_enable(1);
    gd_case_free(&c);
    return tap_done();
}
