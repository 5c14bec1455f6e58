/* A process-wide memo of the contact lines of one position (tca_lines): the lines of a pair's
 * position depend on its geometry, the half, the pinion angle and the gap window only, not on the
 * load, so the LTCA runs of one pair at many torques (a continuation in torque: every corrector
 * iterate and every difference in the torque is a new LTCA) solve the same slice minima again. An
 * entry keeps the lines of (pair, half, phi1) within a window W with each point's grid value that
 * tca_lines' prefilter tested; a query within a window w <= W is the subset that tca_lines itself
 * would have computed at w (the same prefilter, the same test on the gap, the same order), so a
 * memoised result is the computed one to the bit, whatever the memo held before and however many
 * threads share it. Bounded: the least recently used entries go beyond MEMO_ENTRIES or MEMO_BYTES. */
#include "tca_internal.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#define MEMO_ENTRIES 2048
#define MEMO_BYTES ((size_t)64 << 20)

typedef struct memo_entry {
    unsigned char *key; /* the pair's key bytes (tca_memo_key) */
    size_t key_len;
    int half;
    double phi1, window;
    gd_tca_line_point *pts;
    double *pre; /* per point: the grid value tca_lines' prefilter tested */
    int n;
    size_t bytes;
    unsigned long used;
} memo_entry;

static pthread_mutex_t memo_lock = PTHREAD_MUTEX_INITIALIZER;
static memo_entry memo[MEMO_ENTRIES];
static int memo_n;
static size_t memo_bytes;
static unsigned long memo_tick;
static int memo_on = 1;
static long memo_hits;

static void entry_free(memo_entry *e)
{
    memo_bytes -= e->bytes;
    free(e->key);
    free(e->pts);
    free(e->pre);
    memset(e, 0, sizeof *e);
}

/* e out of the table (under the lock): the last entry takes its place */
static void drop(memo_entry *e)
{
    entry_free(e);
    memo_entry *last = &memo[memo_n - 1];
    if (e != last) {
        *e = *last;
        memset(last, 0, sizeof *last);
    }
    memo_n--;
}

/* the entry of (t's pair, half, phi1), else NULL (under the lock) */
static memo_entry *find(const gd_tca *t, int half, double phi1)
{
    for (int i = 0; i < memo_n; i++) {
        memo_entry *e = &memo[i];
        if (e->half == half && e->phi1 == phi1 && e->key_len == t->memo_len && !memcmp(e->key, t->memo_key, t->memo_len))
            return e;
    }
    return NULL;
}

int tca_memo_active(const gd_tca *t)
{
    if (!t->memo_key)
        return 0;
    pthread_mutex_lock(&memo_lock);
    int on = memo_on;
    pthread_mutex_unlock(&memo_lock);
    return on;
}

int tca_memo_get(gd_tca *t, int half, double phi1, double max_gap, gd_error *err)
{
    if (!t->memo_key)
        return 0;
    pthread_mutex_lock(&memo_lock);
    memo_entry *e = memo_on ? find(t, half, phi1) : NULL;
    if (!e || !(e->window >= max_gap)) {
        pthread_mutex_unlock(&memo_lock);
        return 0;
    }
    if (t->cap_lines < e->n) { /* (the prefilter's values keep the lines' capacity for tca_lines) */
        gd_tca_line_point *nl = realloc(t->lines, (size_t)e->n * sizeof *nl);
        double *np = nl ? realloc(t->lines_pre, (size_t)e->n * sizeof *np) : NULL;
        if (nl)
            t->lines = nl;
        if (!np) {
            pthread_mutex_unlock(&memo_lock);
            gd_error_set(err, GD_ERR_NOMEM, "TCA: out of memory for the contact lines");
            return -1;
        }
        t->lines_pre = np;
        t->cap_lines = e->n;
    }
    t->nlines = 0;
    for (int i = 0; i < e->n; i++)
        if (tca_lines_keep(e->pre[i], e->pts[i].gap, max_gap))
            t->lines[t->nlines++] = e->pts[i];
    e->used = ++memo_tick;
    memo_hits++;
    pthread_mutex_unlock(&memo_lock);
    return 1;
}

void tca_memo_put(const gd_tca *t, int half, double phi1, double window, const gd_tca_line_point *pts,
                  const double *pre, int n)
{
    if (!t->memo_key)
        return;
    const size_t bytes = t->memo_len + (size_t)n * (sizeof *pts + sizeof *pre);
    unsigned char *key = malloc(t->memo_len);
    gd_tca_line_point *p = malloc((size_t)(n > 0 ? n : 1) * sizeof *p);
    double *q = malloc((size_t)(n > 0 ? n : 1) * sizeof *q);
    if (key && p && q && bytes <= MEMO_BYTES / 4) { /* a memo is an economy: without room, none is kept */
        memcpy(key, t->memo_key, t->memo_len);
        memcpy(p, pts, (size_t)n * sizeof *p);
        memcpy(q, pre, (size_t)n * sizeof *q);
        pthread_mutex_lock(&memo_lock);
        memo_entry *e = memo_on ? find(t, half, phi1) : NULL;
        if (memo_on && !(e && e->window >= window)) { /* (another thread may have put a wider one) */
            if (e) /* replaced by the wider one */
                drop(e);
            while (memo_n > 0 && (memo_n == MEMO_ENTRIES || memo_bytes + bytes > MEMO_BYTES)) {
                int lru = 0;
                for (int i = 1; i < memo_n; i++)
                    if (memo[i].used < memo[lru].used)
                        lru = i;
                drop(&memo[lru]);
            }
            memo[memo_n++] = (memo_entry){key, t->memo_len, half, phi1, window, p, q, n, bytes, ++memo_tick};
            memo_bytes += bytes;
            key = NULL;
            p = NULL;
            q = NULL;
        }
        pthread_mutex_unlock(&memo_lock);
    }
    free(key);
    free(p);
    free(q);
}

void gd_tca_memo_enable(int on)
{
    pthread_mutex_lock(&memo_lock);
    memo_on = on;
    for (int i = 0; i < memo_n; i++)
        entry_free(&memo[i]);
    memo_n = 0;
    memo_hits = 0;
    pthread_mutex_unlock(&memo_lock);
}

long gd_tca_memo_hits(void)
{
    pthread_mutex_lock(&memo_lock);
    long h = memo_hits;
    pthread_mutex_unlock(&memo_lock);
    return h;
}
