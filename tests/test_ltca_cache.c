/* The LTCA cache of the dynamic model's excitations (gd_excitation.h, src/excitation/):
 *  1. the key: gd_ltca_cache_key is the FNV-1a hash of exactly the bytes gd_ltca_cache_key_bytes
 *     gives; the bytes ignore the speed and follow the torque and the positions;
 *  2. repeated identical cases: one computation, the same excitation, one reference each;
 *  3. entries are told apart by their full key: with every hash forced equal, two cases are still
 *     two entries with their own excitations, each found again;
 *  4. a held excitation is never freed: 20 other cases through the cache (16 slots) leave it
 *     intact and cached; with 20 held at once the cache grows instead of freeing one;
 *  5. every reference released: the count is back at zero (run it under valgrind or ASan for
 *     the memory side);
 *  6. gd_case_resolve and gd_model_build (stiffness = ltca, impact = on) hold no reference
 *     after they return;
 *  7. threads asking for the same new case at once: one computation. */
#include "ltca_util.h"
#include "excitation/ltca_cache.h"
#include "geardyn/gd_excitation.h"
#include "geardyn/gd_scene.h"

#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>

/* a fast LTCA: one helical half, two positions a cycle (about 0.05 s) */
static int small_case(gd_case *c, double torque_nm, double speed_rpm)
{
    char t[64], s[64];
    snprintf(t, sizeof t, "operating.torque_nm=%.17g", torque_nm);
    snprintf(s, sizeof s, "operating.speed_rpm=%.17g", speed_rpm);
    return lt_case(c, 0, "gear.arrangement=helical", "solver.ltca_positions_per_cycle=2", t, s, NULL);
}

static uint64_t fnv1a(const unsigned char *p, size_t n)
{
    uint64_t h = 14695981039346656037ull;
    for (size_t i = 0; i < n; i++) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

static uint64_t same_hash(const gd_case *c, int npos)
{
    (void)c, (void)npos;
    return 42;
}

/* a copy of what the dynamic model reads, to see that a held excitation is left alone */
typedef struct snapshot {
    int halves, npos;
    double k0[2], lte[2], k_mean;
    uint64_t key;
} snapshot;

static snapshot snap(const gd_ltca_excitation *x)
{
    snapshot s = {x->halves, x->npos, {x->k[0][0], x->k[0][1]}, {x->lte_arcsec[0], x->lte_arcsec[1]}, x->k_mean[0], x->key};
    return s;
}

static int same(snapshot a, snapshot b) { return memcmp(&a, &b, sizeof a) == 0; }

static void key_bytes(void)
{
    gd_case a, b, d;
    if (small_case(&a, 300, 1000) || small_case(&b, 300, 4000) || small_case(&d, 310, 1000))
        return;
    size_t n = gd_ltca_cache_key_bytes(&a, 0, NULL, 0);
    unsigned char *ka = malloc(n), *kb = malloc(n), *kd = malloc(n);
    size_t nb = gd_ltca_cache_key_bytes(&b, 0, kb, n), nd = gd_ltca_cache_key_bytes(&d, 0, kd, n);
    tap_ok(n > 100 && gd_ltca_cache_key_bytes(&a, 0, ka, n) == n, "key bytes: %zu of them, the size asked first", n);
    tap_ok(fnv1a(ka, n) == gd_ltca_cache_key(&a, 0), "gd_ltca_cache_key is FNV-1a of the key bytes (%016llx)",
           (unsigned long long)gd_ltca_cache_key(&a, 0));
    tap_ok(nb == n && memcmp(ka, kb, n) == 0, "key bytes: the same at another speed");
    tap_ok(nd == n && memcmp(ka, kd, n) != 0, "key bytes: differ with the torque");
    tap_ok(gd_ltca_cache_key_bytes(&a, 4, kd, n) == n && memcmp(ka, kd, n) != 0,
           "key bytes: differ with the positions (4 instead of the case's 2)");
    unsigned char few[8] = {0};
    tap_ok(gd_ltca_cache_key_bytes(&a, 0, few, sizeof few) == n && memcmp(few, "geardyn-", 8) == 0,
           "key bytes: a short buffer gets what fits, the count is still the whole");
    free(ka), free(kb), free(kd);
    gd_case_free(&a), gd_case_free(&b), gd_case_free(&d);
}

static void repeated(void)
{
    gd_case a, b;
    if (small_case(&a, 320, 1000) || small_case(&b, 320, 3000))
        return;
    gd_error e = {0};
    long n0 = gd_ltca_cache_computations(), r0 = gd_ltca_cache_references();
    const gd_ltca_excitation *x1 = NULL, *x2 = NULL, *x3 = NULL;
    gd_ltca_excitation_cached(&a, &x1, &e);
    gd_ltca_excitation_cached(&a, &x2, &e);
    gd_ltca_excitation_cached(&b, &x3, &e);
    tap_ok(x1 && x1 == x2 && x2 == x3 && gd_ltca_cache_computations() - n0 == 1,
           "the same case three times (two speeds): one computation (%ld), one excitation (%s)",
           gd_ltca_cache_computations() - n0, e.msg);
    tap_ok(gd_ltca_cache_references() - r0 == 3, "three references held (%ld)", gd_ltca_cache_references() - r0);
    gd_ltca_excitation_release(x1);
    gd_ltca_excitation_release(x2);
    gd_ltca_excitation_release(x3);
    gd_ltca_excitation_release(NULL);
    tap_ok(gd_ltca_cache_references() == r0, "released: back to %ld", r0);
    gd_ltca_excitation_cached(&a, &x1, &e);
    tap_ok(x1 == x2 && gd_ltca_cache_computations() - n0 == 1, "still cached after the release: no computation");
    gd_ltca_excitation_release(x1);
    gd_ltca_excitation_release(x1); /* once too often: ignored */
    tap_ok(gd_ltca_cache_references() == r0, "a release too many changes nothing (%ld)", gd_ltca_cache_references());
    gd_case_free(&a), gd_case_free(&b);
}

static void collisions(void)
{
    gd_ltca_cache_set_hash(same_hash);
    gd_case a, b;
    if (small_case(&a, 300, 1000) || small_case(&b, 310, 1000))
        return;
    gd_error e = {0};
    gd_ltca_excitation ra = {0}, rb = {0};
    gd_ltca_excitation_compute(&a, 2, &ra, &e);
    gd_ltca_excitation_compute(&b, 2, &rb, &e);
    long n0 = gd_ltca_cache_computations();
    const gd_ltca_excitation *xa = NULL, *xb = NULL, *xa2 = NULL, *xb2 = NULL;
    gd_ltca_excitation_cached(&a, &xa, &e);
    gd_ltca_excitation_cached(&b, &xb, &e);
    tap_ok(xa && xb && xa != xb && gd_ltca_cache_computations() - n0 == 2,
           "every hash forced equal: two cases are two entries, two computations (%ld)", gd_ltca_cache_computations() - n0);
    tap_ok(xa && xb && ra.k[0] && rb.k[0] && xa->k[0][0] == ra.k[0][0] && xb->k[0][0] == rb.k[0][0] &&
               ra.k[0][0] != rb.k[0][0],
           "each has its own stiffness (%.6g and %.6g N/m)", xa ? xa->k[0][0] : 0, xb ? xb->k[0][0] : 0);
    gd_ltca_excitation_cached(&a, &xa2, &e);
    gd_ltca_excitation_cached(&b, &xb2, &e);
    tap_ok(xa2 == xa && xb2 == xb && gd_ltca_cache_computations() - n0 == 2,
           "and each is found again by its full key, not confused with the other");
    gd_ltca_excitation_release(xa), gd_ltca_excitation_release(xa2);
    gd_ltca_excitation_release(xb), gd_ltca_excitation_release(xb2);
    gd_ltca_excitation_free(&ra), gd_ltca_excitation_free(&rb);
    gd_case_free(&a), gd_case_free(&b);
    gd_ltca_cache_set_hash(NULL);
}

static void held(void)
{
    gd_case a;
    if (small_case(&a, 330, 1000))
        return;
    gd_error e = {0};
    const gd_ltca_excitation *xa = NULL;
    if (gd_ltca_excitation_cached(&a, &xa, &e) != GD_OK) {
        tap_ok(0, "held: %s", e.msg);
        return;
    }
    snapshot before = snap(xa);
    long n0 = gd_ltca_cache_computations(), r0 = gd_ltca_cache_references();
    int slots0 = 0, slots = 0, bad = 0;
    gd_ltca_cache_entries(&slots0);
    for (int i = 0; i < 20; i++) {
        gd_case c;
        if (small_case(&c, 400 + 10 * i, 1000))
            return;
        const gd_ltca_excitation *x = NULL;
        bad |= gd_ltca_excitation_cached(&c, &x, &e) != GD_OK || x == xa;
        gd_ltca_excitation_release(x);
        gd_case_free(&c);
    }
    int entries = gd_ltca_cache_entries(&slots);
    tap_ok(!bad && gd_ltca_cache_computations() - n0 == 20, "20 other cases through the cache: 20 computations (%ld)",
           gd_ltca_cache_computations() - n0);
    tap_ok(entries <= 16 && slots == slots0, "the cache kept its size (%d entries, %d slots) with one held", entries,
           slots);
    tap_ok(same(snap(xa), before), "the held excitation is intact (k %.6g N/m)", xa->k[0][0]);
    const gd_ltca_excitation *again = NULL;
    gd_ltca_excitation_cached(&a, &again, &e);
    tap_ok(again == xa && gd_ltca_cache_computations() - n0 == 20,
           "and still cached: the oldest entry, but held, was not the one evicted");
    gd_ltca_excitation_release(again);
    gd_ltca_excitation_release(xa);
    tap_ok(gd_ltca_cache_references() == r0 - 1, "released: %ld references", gd_ltca_cache_references());

    /* 20 held at once: the cache grows rather than free one of them */
    enum { H = 20 };
    const gd_ltca_excitation *x[H] = {0};
    snapshot s[H];
    n0 = gd_ltca_cache_computations();
    for (int i = 0; i < H; i++) {
        gd_case c;
        if (small_case(&c, 600 + 10 * i, 1000))
            return;
        if (gd_ltca_excitation_cached(&c, &x[i], &e) == GD_OK)
            s[i] = snap(x[i]);
        else
            bad = 1;
        gd_case_free(&c);
    }
    entries = gd_ltca_cache_entries(&slots);
    int intact = !bad;
    for (int i = 0; i < H && intact; i++)
        intact = same(snap(x[i]), s[i]) && (i == 0 || x[i] != x[i - 1]);
    tap_ok(intact && gd_ltca_cache_computations() - n0 == H && entries >= H && slots >= H,
           "%d held at once: all distinct and intact, the cache grew to %d entries (%d slots)", H, entries, slots);
    for (int i = 0; i < H; i++)
        gd_ltca_excitation_release(x[i]);
    tap_ok(gd_ltca_cache_references() == 0, "all released: no reference left (%ld)", gd_ltca_cache_references());
    gd_case c;
    if (small_case(&c, 900, 1000))
        return;
    const gd_ltca_excitation *y = NULL;
    gd_ltca_excitation_cached(&c, &y, &e);
    gd_ltca_excitation_release(y);
    tap_ok(gd_ltca_cache_entries(NULL) == entries, "once nobody holds them, a new case takes an old one's slot (%d entries)",
           gd_ltca_cache_entries(NULL));
    gd_case_free(&c);
    gd_case_free(&a);
}

/* the library's own users of the cache give their references back */
static void library_users(void)
{
    long n0 = gd_ltca_cache_computations(), r0 = gd_ltca_cache_references();
    gd_case c;
    if (lt_case(&c, 0, "gear.arrangement=helical", "solver.ltca_positions_per_cycle=2", "operating.torque_nm=1100",
                "scene.analysis=response", "excitation.stiffness=ltca", "excitation.impact=on", NULL))
        return;
    tap_ok(gd_ltca_cache_references() == r0, "gd_case_resolve (stiffness = ltca) holds no reference after it (%ld)",
           gd_ltca_cache_references() - r0);
    gd_model m;
    gd_error e = {0};
    gd_status st = gd_model_build(&c, &m, &e);
    tap_ok(st == GD_OK && gd_ltca_cache_references() == r0 && gd_ltca_cache_computations() - n0 == 1,
           "gd_model_build (stiffness = ltca, impact = on) neither: %ld held, %ld computation(s) for both (%s)",
           gd_ltca_cache_references() - r0, gd_ltca_cache_computations() - n0, e.msg);
    gd_case_free(&c);
}

/* ---- threads -------------------------------------------------------------------------------- */

static gd_case shared;
static const gd_ltca_excitation *got[4];

static void *ask(void *arg)
{
    int i = (int)(intptr_t)arg;
    gd_error e = {0};
    gd_ltca_excitation_cached(&shared, &got[i], &e);
    return NULL;
}

static void threads(void)
{
    if (small_case(&shared, 1000, 1000))
        return;
    long n0 = gd_ltca_cache_computations(), r0 = gd_ltca_cache_references();
    pthread_t th[4];
    for (int i = 0; i < 4; i++)
        pthread_create(&th[i], NULL, ask, (void *)(intptr_t)i);
    for (int i = 0; i < 4; i++)
        pthread_join(th[i], NULL);
    tap_ok(got[0] && got[0] == got[1] && got[1] == got[2] && got[2] == got[3] && gd_ltca_cache_computations() - n0 == 1,
           "four threads ask for the same new case at once: one computation (%ld), one excitation",
           gd_ltca_cache_computations() - n0);
    for (int i = 0; i < 4; i++)
        gd_ltca_excitation_release(got[i]);
    tap_ok(gd_ltca_cache_references() == r0, "and four releases (%ld left)", gd_ltca_cache_references() - r0);
    gd_case_free(&shared);
}

int main(void)
{
    key_bytes();
    repeated();
    collisions();
    held();
    library_users();
    threads();
    return tap_done();
}
