/* The Ant Lion Optimizer (docs/optimisation.md section 4): its ratio schedule; the floor it reaches
 * on the sphere, unshifted and shifted; that it depends on the objective only through the order of
 * the values (rank roulette: valid for any sign of f, unlike the reference code's 1/f weights);
 * bitwise reproducibility for a seed; identical runs with 1 and 2 threads; its evaluation count.
 * TAP output. */
#include "geardyn/geardyn.h"
#include "tap.h"

#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif

static gd_status sphere_eval(void *state, const double *y, double *f, gd_error *err)
{
    (void)err;
    const gd_opt_testfn *t = state;
    *f = gd_opt_function_value(GD_OBJ_SPHERE, t->dim, t->optimum, y);
    return GD_OK;
}

/* sqrt(sphere) - 10: negative near the minimum, a strictly increasing function of the sphere */
static gd_status shifted_root_eval(void *state, const double *y, double *f, gd_error *err)
{
    double s;
    sphere_eval(state, y, &s, err);
    *f = sqrt(s) - 10.0;
    return GD_OK;
}

/* the sphere with a workload that varies from point to point, so that two threads finish their
 * evaluations out of order; each state counts its evaluations */
typedef struct busy_user {
    gd_opt_testfn *t;
    atomic_long per_state[8];
    atomic_int next;
    atomic_int entered;      /* states that have started evaluating */
    int expect;              /* the first evaluation of a state waits (up to 5 s) until this many have started */
} busy_user;
typedef struct busy_state {
    busy_user *u;
    int id;
    long count;
} busy_state;

static gd_status busy_alloc(void *user, void **state, gd_error *err)
{
    busy_state *s = calloc(1, sizeof *s);
    if (!s)
        return gd_error_set(err, GD_ERR_NOMEM, "out of memory");
    s->u = user;
    s->id = atomic_fetch_add(&s->u->next, 1) % 8;
    *state = s;
    return GD_OK;
}

static void busy_free(void *state)
{
    busy_state *s = state;
    atomic_fetch_add(&s->u->per_state[s->id], s->count);
    free(s);
}

static gd_status busy_eval(void *state, const double *y, double *f, gd_error *err)
{
    busy_state *s = state;
    if (s->count == 0) {
        /* hold this thread's first evaluation until the others have started one: with 2 threads both
         * must then evaluate, however the machine schedules them */
        atomic_fetch_add(&s->u->entered, 1);
        for (int k = 0; k < 5000 && atomic_load(&s->u->entered) < s->u->expect; k++)
            nanosleep(&(struct timespec){0, 1000000}, NULL);
    }
    sphere_eval(s->u->t, y, f, err);
    volatile double acc = 0;
    int n = 2000 + (int)(fabs(y[0]) * 1000.0) % 20000;
    for (int i = 0; i < n; i++)
        acc += sqrt((double)i);
    s->count++;
    return GD_OK;
}

static int run(const gd_opt_problem *p, unsigned long seed, int pop, long budget, int threads, gd_opt_result *r)
{
    gd_opt_settings s;
    gd_opt_settings_default(&s);
    s.algorithm = GD_OPT_ALO;
    s.seed = seed;
    s.population = pop;
    s.budget = budget;
    s.threads = threads;
    s.keep_history = 1;
    gd_error e = {0};
    if (gd_opt_run(p, &s, r, &e) != GD_OK) {
        tap_ok(0, "ALO run: %s", e.msg);
        return 1;
    }
    return 0;
}

static int same_run(const gd_opt_result *a, const gd_opt_result *b)
{
    return a->evaluations == b->evaluations && a->f == b->f && a->best_at == b->best_at &&
           memcmp(a->y, b->y, sizeof(double) * (size_t)a->dim) == 0 &&
           memcmp(a->f_history, b->f_history, sizeof(double) * (size_t)a->evaluations) == 0;
}

int main(void)
{
    gd_error e = {0};
    /* the ratio schedule I(t) = 1 + 10^w t/T (Mirjalili 2015, Eq. 2.10-2.11; w = 2..6 past 10, 50, 75, 90, 95 %) */
    TAP_CLOSE(gd_alo_ratio(10, 100), 1.0, 0, "I(t = 0.10 T) = 1 (no shrink in the first tenth)");
    TAP_CLOSE(gd_alo_ratio(11, 100), 1.0 + 1e2 * 0.11, 1e-12, "I(0.11 T) = 1 + 10^2 0.11");
    TAP_CLOSE(gd_alo_ratio(50, 100), 1.0 + 1e2 * 0.50, 1e-12, "I(0.50 T) = 1 + 10^2 0.5 (w = 3 only above 0.5 T)");
    TAP_CLOSE(gd_alo_ratio(51, 100), 1.0 + 1e3 * 0.51, 1e-12, "I(0.51 T) = 1 + 10^3 0.51");
    TAP_CLOSE(gd_alo_ratio(76, 100), 1.0 + 1e4 * 0.76, 1e-9, "I(0.76 T) = 1 + 10^4 0.76");
    TAP_CLOSE(gd_alo_ratio(91, 100), 1.0 + 1e5 * 0.91, 1e-9, "I(0.91 T) = 1 + 10^5 0.91");
    TAP_CLOSE(gd_alo_ratio(100, 100), 1.0 + 1e6, 1e-6, "I(T) = 1 + 10^6");
    tap_ok(gd_alo_iterations(3030, 30) == 100 && gd_alo_iterations(3059, 30) == 100 && gd_alo_iterations(59, 30) == 0,
           "iterations for a budget: N (T + 1) <= budget (3030 -> 100, 3059 -> 100, 59 -> 0)");

    /* the floor on the sphere: d = 10, box [-100, 100], 30 ants, 500 iterations. The last walks
     * sample a box of half-width h / I(T) = 100 / (1 + 10^6) around the elite, so the attainable
     * value is of the order d (h / I(T))^2 = 1e-7: required below it (3 seeds, unshifted and
     * shifted by up to half the box). */
    double floor_ = 10.0 * pow(100.0 / gd_alo_ratio(500, 500), 2);
    for (int shifted = 0; shifted < 2; shifted++)
        for (unsigned long seed = 1; seed <= 3; seed++) {
            gd_opt_testfn t;
            if (gd_opt_testfn_init(&t, GD_OBJ_SPHERE, 10, shifted ? 0.5 : 0.0, 100 + seed, &e) != GD_OK) {
                tap_ok(0, "test function: %s", e.msg);
                continue;
            }
            gd_opt_problem p;
            gd_opt_testfn_problem(&t, &p);
            gd_opt_result r;
            if (run(&p, seed, 30, 30L * 501, 1, &r) == 0) {
                double dist = 0;
                for (int i = 0; i < 10; i++)
                    dist = fmax(dist, fabs(r.y[i] - t.optimum[i]));
                tap_ok(r.f < floor_ && r.evaluations == 30L * 501,
                       "sphere d = 10%s, seed %lu: f = %.3g below d (h/I_T)^2 = %.3g after %ld = 30 x 501 evaluations "
                       "(largest |y - o| %.2g)", shifted ? " shifted" : "", seed, r.f, floor_, r.evaluations, dist);
                gd_opt_result_free(&r);
            }
            gd_opt_testfn_free(&t);
        }

    gd_opt_testfn t;
    gd_opt_testfn_init(&t, GD_OBJ_SPHERE, 4, 0.5, 7, &e);
    gd_opt_problem p;
    gd_opt_testfn_problem(&t, &p);
    p.eval = sphere_eval;

    /* reproducible for a seed, bit for bit; another seed differs */
    {
        gd_opt_result a, b, c;
        if (run(&p, 42, 12, 12L * 81, 1, &a) == 0 && run(&p, 42, 12, 12L * 81, 1, &b) == 0 &&
            run(&p, 43, 12, 12L * 81, 1, &c) == 0) {
            tap_ok(same_run(&a, &b), "seed 42 twice: every evaluation and the optimum identical bit for bit");
            tap_ok(!same_run(&a, &c), "seed 43 gives another run (f %.3g vs %.3g)", c.f, a.f);
            gd_opt_result_free(&a);
            gd_opt_result_free(&b);
            gd_opt_result_free(&c);
        }
    }
    /* depends on f only through the order of the values: sqrt(sphere) - 10 (negative near the
     * minimum, where 1/f roulette weights are undefined) gives the same points */
    {
        gd_opt_problem q = p;
        q.eval = shifted_root_eval;
        gd_opt_result a, b;
        if (run(&p, 5, 12, 12L * 81, 1, &a) == 0 && run(&q, 5, 12, 12L * 81, 1, &b) == 0) {
            int same = a.evaluations == b.evaluations && memcmp(a.y, b.y, sizeof(double) * 4) == 0;
            long k = 0;
            for (; same && k < a.evaluations; k++)
                same = b.f_history[k] == sqrt(a.f_history[k]) - 10.0;
            tap_ok(same, "ALO on sqrt(f) - 10 visits the points of ALO on f (%ld evaluations compared; best %.6g = "
                   "sqrt(%.3g) - 10): the roulette uses ranks", k, b.f, a.f);
            gd_opt_result_free(&a);
            gd_opt_result_free(&b);
        }
    }
    /* 1 and 2 threads: the same run, bit for bit, with 2 threads really evaluating (each state counts) */
    {
        busy_user u;
        memset(&u, 0, sizeof u);
        u.t = &t;
        u.expect = 1;
        gd_opt_problem q = p;
        q.eval = busy_eval;
        q.state_alloc = busy_alloc;
        q.state_free = busy_free;
        q.user = &u;
        gd_opt_result a, b, c;
#ifdef _OPENMP
        omp_set_num_threads(1);
#endif
        int bad = run(&q, 9, 16, 16L * 41, 0, &a);
        long one = atomic_load(&u.per_state[0]);
        memset(&u, 0, sizeof u);
        u.t = &t;
        u.expect = 2;
#ifdef _OPENMP
        omp_set_num_threads(2);
#endif
        bad |= run(&q, 9, 16, 16L * 41, 0, &b);
        long s0 = atomic_load(&u.per_state[0]), s1 = atomic_load(&u.per_state[1]);
        atomic_store(&u.entered, 0);
        bad |= run(&q, 9, 16, 16L * 41, 2, &c);
        if (!bad) {
            tap_ok(one == a.evaluations, "1 thread: one state made all %ld evaluations (%ld)", a.evaluations, one);
#ifdef _OPENMP
            tap_ok(s0 > 0 && s1 > 0 && s0 + s1 == b.evaluations, "2 threads: both states evaluated (%ld + %ld = %ld)", s0,
                   s1, b.evaluations);
#endif
            tap_ok(same_run(&a, &b), "omp_set_num_threads(1) and (2): every evaluation and the optimum identical");
            tap_ok(same_run(&a, &c), "settings.threads = 2: identical as well");
            gd_opt_result_free(&a);
            gd_opt_result_free(&b);
            gd_opt_result_free(&c);
        }
    }
    /* the evaluation count: N (T + 1) of a budget that is not a multiple of N, counted by the objective */
    {
        busy_user u;
        memset(&u, 0, sizeof u);
        u.t = &t;
        gd_opt_problem q = p;
        q.eval = busy_eval;
        q.state_alloc = busy_alloc;
        q.state_free = busy_free;
        q.user = &u;
        gd_opt_result a;
        if (run(&q, 3, 30, 1000, 2, &a) == 0) {
            long counted = 0;
            for (int i = 0; i < 8; i++)
                counted += atomic_load(&u.per_state[i]);
            tap_ok(a.evaluations == 990 && counted == 990 && a.iterations == 32,
                   "budget 1000, 30 ants: T = 32 iterations, %ld evaluations reported, %ld counted by the objective "
                   "(30 x 33 = 990)", a.evaluations, counted);
            gd_opt_result_free(&a);
        }
    }
    gd_opt_testfn_free(&t);
    return tap_done();
}
