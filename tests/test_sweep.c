/* Sweeps (gd_sweep.h) on the Kahraman & Singh oscillator (torsional model, F_m 0.1, F_a 0.1,
 * zeta 0.05, alpha 0.2; cases/validation/kahraman-singh.ini), swept over the mesh frequency
 * ratio Omega = speed / 3183.0989 rpm:
 *  - the grid: endpoints exact, linear and log values, "up" is increasing whatever the order
 *    of from and to;
 *  - continuation: point k of a chain starts from the final state of point k-1 (checked
 *    against the same chain run by hand through gd_response_run), independent points all
 *    start from the initial condition;
 *  - both branches are present, and the softening jump of the oscillator shows as two
 *    different branches: for Omega in about [0.68, 0.78] the up branch stays on the
 *    no-impact orbit while the down branch keeps the single-sided impact orbit;
 *  - 1 and 2 threads give bit-identical points; the completion callback is never run by
 *    two threads at once; a sweep stopped half way and run again gives the same points;
 *  - records round-trip bit for bit, a damaged record is refused, and a journal with a
 *    torn last line and a gap in a chain is read back correctly;
 *  - bad [sweep] keys are refused with the key named. */
#include "geardyn/gd_sweep.h"
#include "geardyn/gd_analysis.h"
#include "geardyn/gd_output.h"
#include "physics_util.h"
#include "tap.h"

#include <stdatomic.h>
#include <unistd.h>

#define RPM_PER_OMEGA 3183.0988618379

static const char *ks[] = {
    "scene.analysis=sweep", "scene.model=torsional", "scene.error_excitation=on", "gear.helix_angle_deg=0",
    "gear.equivalent_mass_kg=1", "operating.torque_nm=14.095389311789", "clearance.backlash_um=20",
    "excitation.stiffness=harmonic", "excitation.mesh_stiffness_n_per_m=1e8", "excitation.stiffness_harmonics=0.2",
    "excitation.ste_amplitude_um=1", "excitation.ste_phase_deg=90", "damping.mesh_damping_ratio=0.05",
    "solver.characteristic_length_um=10", "run.transient_periods=200", "run.record_periods=20",
    "sweep.parameter=operating.speed_rpm", NULL};

/* The oscillator with the sweep keys of extra (NULL-terminated) and Omega from w0 to w1. */
static void ks_case(gd_case *c, double w0, double w1, int points, const char *const *extra)
{
    const char *sets[64];
    char from[64], to[64], pts[64];
    int n = 0;
    for (int i = 0; ks[i]; i++)
        sets[n++] = ks[i];
    snprintf(from, sizeof from, "sweep.from=%.12g", w0 * RPM_PER_OMEGA);
    snprintf(to, sizeof to, "sweep.to=%.12g", w1 * RPM_PER_OMEGA);
    snprintf(pts, sizeof pts, "sweep.points=%d", points);
    sets[n++] = from;
    sets[n++] = to;
    sets[n++] = pts;
    for (int i = 0; extra && extra[i]; i++)
        sets[n++] = extra[i];
    sets[n] = NULL;
    pu_case(c, sets);
}

typedef struct cb_state {
    atomic_int inside, overlap, calls, stop_after;
} cb_state;

static gd_status on_done(void *user, const gd_sweep_plan *p, const gd_sweep_point *pt, gd_error *err)
{
    cb_state *s = user;
    (void)p, (void)pt, (void)err;
    if (atomic_fetch_add(&s->inside, 1) != 0)
        atomic_store(&s->overlap, 1);
    usleep(2000); /* widen the window in which a second thread could enter */
    atomic_fetch_add(&s->calls, 1);
    atomic_fetch_sub(&s->inside, 1);
    return GD_OK;
}

static int stop_now(void *user)
{
    cb_state *s = user;
    int k = atomic_load(&s->stop_after);
    return k > 0 && atomic_load(&s->calls) >= k;
}

static void run_sweep(const gd_case *c, const gd_sweep_plan *p, gd_sweep_point *pts, int threads, cb_state *cb)
{
    gd_sweep_opts o;
    gd_sweep_opts_default(&o);
    o.threads = threads;
    o.point_done = on_done;
    o.should_stop = stop_now;
    o.user = cb;
    gd_error e = {0};
    PU_CHECK(gd_sweep_run(c, p, pts, &o, &e), &e);
}

/* Bitwise equality of two point results. */
static int same_point(const gd_sweep_plan *p, const gd_sweep_point *a, const gd_sweep_point *b)
{
    if (a->status != b->status || strcmp(a->motion, b->motion) != 0 || a->period_n != b->period_n ||
        a->poincare_distinct != b->poincare_distinct || a->npoincare != b->npoincare || a->steps != b->steps ||
        a->rhs_evals != b->rhs_evals || a->events != b->events)
        return 0;
    if (memcmp(a->rms_accel_mps2, b->rms_accel_mps2, sizeof a->rms_accel_mps2) != 0 ||
        memcmp(a->dynamic_load_factor, b->dynamic_load_factor, sizeof a->dynamic_load_factor) != 0 ||
        memcmp(a->impact_regime, b->impact_regime, sizeof a->impact_regime) != 0)
        return 0;
    if (memcmp(&a->mle_per_period, &b->mle_per_period, sizeof(double)) != 0 ||
        memcmp(a->y_final, b->y_final, sizeof(double) * (size_t)p->n) != 0 ||
        memcmp(a->md_final.mode, b->md_final.mode, sizeof(int) * (size_t)p->nclear) != 0)
        return 0;
    return a->npoincare == 0 ||
           memcmp(a->poincare, b->poincare, sizeof(double) * (size_t)(a->npoincare * p->nresp)) == 0;
}

static int same_all(const gd_sweep_plan *p, const gd_sweep_point *a, const gd_sweep_point *b)
{
    for (int s = 0; s < p->nslots; s++)
        if (!same_point(p, &a[s], &b[s]))
            return 0;
    return 1;
}

typedef struct hand_pc {
    const gd_model *m;
    double lam[64];
    long n;
} hand_pc;

static int hand_poincare(void *user, long period, double t_s, const double *y)
{
    hand_pc *h = user;
    (void)period;
    gd_modes md;
    memset(&md, 0, sizeof md);
    double x, xd;
    gd_model_clearance(h->m, h->m->mesh_clear[0], t_s * h->m->omega_n, y, &md, &x, &xd);
    if (h->n < 64)
        h->lam[h->n] = x;
    h->n++;
    return 0;
}

/* Run the chain of plan chain ch by hand (its own case copies, gd_response_run, the state
 * carried over when continuing) and compare with the sweep's points. */
static void check_chain_by_hand(const gd_case *base, const gd_sweep_plan *p, const gd_sweep_point *pts, int ch,
                                int continuation, const char *label)
{
    const gd_sweep_chain *cc = &p->chains[ch];
    double y_prev[GD_MAX_STATE];
    gd_modes md_prev;
    int ok_state = 1, ok_rms = 1, ok_pc = 1;
    for (int k = 0; k < cc->count; k++) {
        const gd_sweep_point *pt = &pts[cc->first + k];
        gd_case c;
        gd_error e = {0};
        PU_CHECK(gd_case_copy(&c, base, &e), &e);
        c.analysis = GD_ANALYSIS_RESPONSE;
        PU_CHECK(gd_case_set_number(&c, "operating.speed_rpm", pt->value[0], &e), &e);
        PU_CHECK(gd_case_resolve(&c, &e), &e);
        gd_model m;
        pu_build(&c, &m);
        gd_response_opts o;
        gd_response_opts_default(&o);
        double y0[GD_MAX_STATE];
        gd_modes md0;
        if (continuation && k > 0) {
            memcpy(y0, y_prev, sizeof y0);
            md0 = md_prev;
            PU_CHECK(gd_model_consistent_modes(&m, 0.0, y0, &md0, &e), &e);
            o.y0 = y0;
            o.md0 = &md0;
        }
        hand_pc h = {&m, {0}, 0};
        gd_response_hooks hooks = {NULL, hand_poincare, NULL, NULL};
        gd_response_result r;
        PU_CHECK(gd_response_run(&c, &m, &o, &hooks, &h, &r, &e), &e);
        ok_state &= memcmp(r.y_final, pt->y_final, sizeof(double) * (size_t)m.n) == 0;
        ok_rms &= memcmp(r.rms_accel_mps2, pt->rms_accel_mps2, sizeof r.rms_accel_mps2) == 0 &&
                  strcmp(r.motion, pt->motion) == 0 &&
                  memcmp(r.dynamic_load_factor, pt->dynamic_load_factor, sizeof r.dynamic_load_factor) == 0;
        for (long q = 0; q < h.n && q < 64; q++)
            ok_pc &= h.lam[q] == pt->poincare[q * p->nresp + 0];
        memcpy(y_prev, r.y_final, sizeof y_prev);
        md_prev = r.md_final;
        gd_case_free(&c);
    }
    tap_ok(ok_state, "%s: final states equal the chain run by hand (bitwise)", label);
    tap_ok(ok_rms, "%s: RMS accelerations, dynamic load factors and motion equal the chain run by hand", label);
    tap_ok(ok_pc, "%s: Poincare samples of lambda_L equal the chain run by hand", label);
}

static void expect_bad(const char *const *extra, const char *needle, const char *label)
{
    gd_case c;
    gd_error e = {0};
    PU_CHECK(gd_case_init(&c, &e), &e);
    c.speed_rpm = 4000, c.torque_nm = 500; /* the paper's operating point: a case must give one */
    const char *sets[64];
    int n = 0;
    for (int i = 0; ks[i]; i++)
        sets[n++] = ks[i];
    for (int i = 0; extra[i]; i++)
        sets[n++] = extra[i];
    gd_status st = GD_OK;
    for (int i = 0; i < n && st == GD_OK; i++)
        st = gd_case_set(&c, sets[i], i, &e);
    if (st == GD_OK)
        st = gd_case_resolve(&c, &e);
    tap_ok(st == GD_ERR_INPUT && strstr(e.msg, needle) != NULL, "%s: refused (%s)", label, e.msg);
    gd_case_free(&c);
}

int main(void)
{
    gd_error e = {0};
    cb_state cb;

    /* the grid */
    {
        gd_case c;
        const char *ex[] = {"sweep.spacing=log", NULL};
        ks_case(&c, 1.0, 0.5, 3, ex);
        gd_sweep_plan p;
        PU_CHECK(gd_sweep_plan_create(&c, &p, &e), &e);
        tap_ok(p.values[0][0] == c.sweep_from && p.values[0][2] == c.sweep_to, "grid: endpoints exact");
        TAP_REL(p.values[0][1], sqrt(c.sweep_from * c.sweep_to), 1e-14, "grid: log spacing gives the geometric mean");
        tap_ok(p.nchains == 2 && p.nslots == 6 && p.chains[0].branch == GD_BRANCH_UP &&
                   p.chains[1].branch == GD_BRANCH_DOWN,
               "plan: direction both gives an up and a down chain of 3 points");
        gd_sweep_point *pts;
        PU_CHECK(gd_sweep_points_create(&p, &pts, &e), &e);
        tap_ok(pts[0].value[0] < pts[1].value[0] && pts[1].value[0] < pts[2].value[0] &&
                   pts[3].value[0] > pts[4].value[0] && pts[4].value[0] > pts[5].value[0],
               "plan: up walks increasing values even when from > to, down decreasing");
        /* hysteresis needs two different motions: the up and down points of the middle value with
         * equal RMS accelerations, one classed period-1, the other not-periodic while still converging
         * to the same point, are one motion; with the down point's samples elsewhere, or its RMS
         * acceleration 10 % higher, they are two */
        for (int variant = 0; variant < 4; variant++) {
            for (int k = 0; k < 6; k++) {
                gd_sweep_point *q = &pts[k];
                q->status = GD_POINT_DONE;
                q->rms_accel_mps2[2] = 2094.41964;
                snprintf(q->motion, sizeof q->motion, "period-1");
                free(q->poincare);
                q->npoincare = 41;
                q->poincare = malloc(sizeof(double) * (size_t)(q->npoincare * p.nresp));
                for (long j = 0; j < q->npoincare * p.nresp; j++)
                    q->poincare[j] = 53.07373812;
            }
            gd_sweep_point *down = &pts[4]; /* the down chain's middle point */
            tap_ok(down->value[0] == pts[1].value[0], "the down chain's second point is the middle value");
            if (variant >= 1) { /* still converging: 2e-6 at the start of the window, 4e-8 at its middle */
                snprintf(down->motion, sizeof down->motion, "not-periodic");
                for (long j = 0; j < down->npoincare; j++)
                    for (int r = 0; r < p.nresp; r++)
                        down->poincare[j * p.nresp + r] += 2e-6 * exp(-0.2 * (double)j) * cos(1.3 * (double)j);
            }
            if (variant == 2)
                for (long j = 0; j < down->npoincare * p.nresp; j++)
                    down->poincare[j] += 0.05; /* another orbit with the same RMS */
            if (variant == 3)
                down->rms_accel_mps2[2] *= 1.1;
            gd_sweep_interval *iv;
            int niv;
            PU_CHECK(gd_sweep_hysteresis(&p, pts, &iv, &niv, &e), &e);
            static const char *what[] = {"one motion, one class", "one motion classed twice (one converging)",
                                         "two orbits, two classes, equal RMS", "RMS 10 % apart"};
            int want = variant >= 2;
            tap_ok(niv == want && (!want || (iv[0].from == 1 && iv[0].to == 1)), "hysteresis, %s: %d interval%s",
                   what[variant], niv, niv == 1 ? "" : "s");
            free(iv);
        }
        gd_sweep_points_free(&p, pts);
        gd_sweep_plan_free(&p);
        gd_case_free(&c);
    }

    /* continuation, both directions, 1 and 2 threads */
    gd_case c;
    ks_case(&c, 0.6, 0.8, 5, NULL);
    gd_sweep_plan p;
    PU_CHECK(gd_sweep_plan_create(&c, &p, &e), &e);
    gd_sweep_point *p1, *p2;
    PU_CHECK(gd_sweep_points_create(&p, &p1, &e), &e);
    PU_CHECK(gd_sweep_points_create(&p, &p2, &e), &e);
    memset(&cb, 0, sizeof cb);
    run_sweep(&c, &p, p1, 1, &cb);
    tap_ok(gd_sweep_pending(&p, p1) == 0 && atomic_load(&cb.calls) == p.nslots,
           "continuation: every point done, one completion call each (%d)", atomic_load(&cb.calls));
    int nup = 0, ndown = 0;
    for (int s = 0; s < p.nslots; s++) {
        nup += p1[s].branch == GD_BRANCH_UP && p1[s].status == GD_POINT_DONE;
        ndown += p1[s].branch == GD_BRANCH_DOWN && p1[s].status == GD_POINT_DONE;
    }
    tap_ok(nup == 5 && ndown == 5, "both branches present (%d up, %d down)", nup, ndown);
    check_chain_by_hand(&c, &p, p1, 0, 1, "continuation up");
    check_chain_by_hand(&c, &p, p1, 1, 1, "continuation down");
    /* the softening jump: at Omega 0.70 and 0.75 the branches differ */
    for (int i = 2; i <= 3; i++) {
        const gd_sweep_point *u = NULL, *d = NULL;
        for (int s = 0; s < p.nslots; s++)
            if (p1[s].idx[0] == i)
                *(p1[s].branch == GD_BRANCH_UP ? &u : &d) = &p1[s];
        double w = u->value[0] / RPM_PER_OMEGA;
        tap_ok(u->impact_regime[2] == GD_IMPACT_NONE && d->impact_regime[2] == GD_IMPACT_SINGLE,
               "hysteresis at Omega %.2f: up branch without impacts, down branch with single-sided impacts (%s, %s)",
               w, gd_impact_regime_name(u->impact_regime[2]), gd_impact_regime_name(d->impact_regime[2]));
        tap_ok(d->rms_accel_mps2[2] > 3 * u->rms_accel_mps2[2],
               "hysteresis at Omega %.2f: RMS acceleration down %.4g m/s^2 > 3 x up %.4g m/s^2", w,
               d->rms_accel_mps2[2], u->rms_accel_mps2[2]);
    }
    memset(&cb, 0, sizeof cb);
    run_sweep(&c, &p, p2, 2, &cb);
    tap_ok(same_all(&p, p1, p2), "1 and 2 threads give bit-identical points (continuation)");
    tap_ok(!atomic_load(&cb.overlap), "the completion callback never runs on two threads at once");

    /* stopped half way, then run again: the same points */
    {
        gd_sweep_point *p3;
        PU_CHECK(gd_sweep_points_create(&p, &p3, &e), &e);
        memset(&cb, 0, sizeof cb);
        atomic_store(&cb.stop_after, 3);
        gd_sweep_opts o;
        gd_sweep_opts_default(&o);
        o.threads = 2;
        o.point_done = on_done;
        o.should_stop = stop_now;
        o.user = &cb;
        gd_status st = gd_sweep_run(&c, &p, p3, &o, &e);
        int pend = gd_sweep_pending(&p, p3);
        tap_ok(st == GD_ERR_INTERRUPTED && pend > 0 && pend < p.nslots,
               "should_stop interrupts the sweep (%s, %d pending)", gd_status_name(st), pend);
        int ok = 1;
        for (int s = 0; s < p.nslots; s++)
            if (p3[s].status != GD_POINT_PENDING)
                ok &= same_point(&p, &p1[s], &p3[s]);
        tap_ok(ok, "the points finished before the stop are the uninterrupted ones");
        /* a continuation chain is resumed after its last done point */
        memset(&cb, 0, sizeof cb);
        run_sweep(&c, &p, p3, 1, &cb);
        tap_ok(same_all(&p, p1, p3) && atomic_load(&cb.calls) == pend,
               "running again finishes only the %d pending points, identical to an uninterrupted sweep", pend);
        gd_sweep_points_free(&p, p3);
    }

    /* records and the journal */
    {
        gd_sweep_point *q;
        PU_CHECK(gd_sweep_points_create(&p, &q, &e), &e);
        int ok = 1;
        for (int s = 0; s < p.nslots; s++) {
            char *line;
            size_t len;
            int slot = -1;
            PU_CHECK(gd_sweep_record_format(&p, &p1[s], &line, &len, &e), &e);
            ok &= line[len - 1] == '\n' && memchr(line, '\n', len - 1) == NULL;
            PU_CHECK(gd_sweep_record_parse(&p, line, len, q, &slot, &e), &e);
            ok &= slot == s;
            free(line);
        }
        tap_ok(ok && same_all(&p, p1, q), "records round-trip bit for bit");
        char *line;
        size_t len;
        int slot;
        PU_CHECK(gd_sweep_record_format(&p, &p1[2], &line, &len, &e), &e);
        char *bad = strdup(line);
        char *dig = strchr(bad + 20, '7');
        if (dig)
            *dig = '8';
        tap_ok(gd_sweep_record_parse(&p, bad, len, q, &slot, &e) == GD_ERR_INPUT, "a changed digit is refused");
        tap_ok(gd_sweep_record_parse(&p, line, len / 2, q, &slot, &e) == GD_ERR_INPUT, "a torn record is refused");
        free(bad);
        free(line);
        /* journal: header, up chain points 0, 1, 3, 4 (2 missing), down chain 0, and a torn line */
        char path[] = "/tmp/gd-test-sweep-XXXXXX";
        int fd = mkstemp(path);
        FILE *f = fdopen(fd, "w");
        char header[300];
        gd_sweep_journal_header(&p, header, sizeof header);
        fputs(header, f);
        int order[] = {0, 5, 1, 3, 4};
        for (int i = 0; i < 5; i++) {
            PU_CHECK(gd_sweep_record_format(&p, &p1[order[i]], &line, &len, &e), &e);
            fwrite(line, 1, len, f);
            free(line);
        }
        PU_CHECK(gd_sweep_record_format(&p, &p1[6], &line, &len, &e), &e);
        fwrite(line, 1, len / 3, f); /* torn by a kill */
        free(line);
        fclose(f);
        gd_sweep_point *r;
        PU_CHECK(gd_sweep_points_create(&p, &r, &e), &e);
        char *text;
        size_t tl;
        int loaded, ignored;
        PU_CHECK(gd_sweep_journal_load(path, &p, r, &text, &tl, &loaded, &ignored, &e), &e);
        tap_ok(loaded == 3 && ignored == 3, "journal: 3 points kept (up 0, 1 and down 0), the torn line and the up "
               "points after the gap dropped (loaded %d, ignored %d)", loaded, ignored);
        tap_ok(r[0].status == GD_POINT_DONE && r[1].status == GD_POINT_DONE && r[3].status == GD_POINT_PENDING &&
                   r[5].status == GD_POINT_DONE && same_point(&p, &p1[0], &r[0]) && same_point(&p, &p1[5], &r[5]),
               "journal: the kept points are the recorded ones");
        tap_ok(tl > strlen(header) && memcmp(text, header, strlen(header)) == 0 && text[tl - 1] == '\n',
               "journal: the text to write back starts with the header and ends with a whole line");
        free(text);
        /* another sweep's journal is refused */
        gd_sweep_plan p4 = p;
        p4.fingerprint ^= 1;
        tap_ok(gd_sweep_journal_load(path, &p4, r, &text, &tl, &loaded, &ignored, &e) == GD_ERR_INPUT &&
                   strstr(e.msg, "another sweep"),
               "journal of another sweep refused (%s)", e.msg);
        unlink(path);
        gd_sweep_points_free(&p, r);
        gd_sweep_points_free(&p, q);
    }
    gd_sweep_points_free(&p, p1);
    gd_sweep_points_free(&p, p2);
    gd_sweep_plan_free(&p);
    gd_case_free(&c);

    /* independent points: every point from the initial condition */
    {
        const char *ex[] = {"sweep.mode=independent", NULL};
        ks_case(&c, 0.6, 0.8, 5, ex);
        PU_CHECK(gd_sweep_plan_create(&c, &p, &e), &e);
        tap_ok(p.nslots == 5 && p.nchains == 5, "independent: one slot per value (%d)", p.nslots);
        PU_CHECK(gd_sweep_points_create(&p, &p1, &e), &e);
        PU_CHECK(gd_sweep_points_create(&p, &p2, &e), &e);
        memset(&cb, 0, sizeof cb);
        run_sweep(&c, &p, p1, 1, &cb);
        int ok = 1;
        for (int ch = 0; ch < p.nchains; ch++)
            ok &= p.chains[ch].branch == GD_BRANCH_INDEPENDENT;
        tap_ok(ok, "independent: the direction is 'independent'");
        for (int ch = 0; ch < p.nchains; ch += 2)
            check_chain_by_hand(&c, &p, p1, ch, 0, "independent");
        memset(&cb, 0, sizeof cb);
        run_sweep(&c, &p, p2, 2, &cb);
        tap_ok(same_all(&p, p1, p2), "1 and 2 threads give bit-identical points (independent)");
        gd_sweep_points_free(&p, p1);
        gd_sweep_points_free(&p, p2);
        gd_sweep_plan_free(&p);
        gd_case_free(&c);
    }

    /* a regime map: rows of parameter2, up and down in each */
    {
        const char *ex[] = {"sweep.parameter2=clearance.backlash_um", "sweep.from2=10", "sweep.to2=30",
                            "sweep.points2=3", NULL};
        ks_case(&c, 0.6, 0.8, 4, ex);
        PU_CHECK(gd_sweep_plan_create(&c, &p, &e), &e);
        tap_ok(p.naxes == 2 && p.nchains == 6 && p.nslots == 24 && p.chains[2].row == 1 &&
                   p.chains[2].branch == GD_BRANCH_UP,
               "map: one up and one down chain per row of parameter2 (%d chains, %d points)", p.nchains, p.nslots);
        gd_sweep_point *pts;
        PU_CHECK(gd_sweep_points_create(&p, &pts, &e), &e);
        gd_case pc;
        gd_model pm;
        PU_CHECK(gd_sweep_point_case(&c, &p, 9, &pc, &pm, &e), &e);
        tap_ok(pc.backlash_um == 20 && pc.speed_rpm == pts[9].value[0] && pts[9].value[1] == 20,
               "map: a point's case has both swept values (%g um, %g rpm)", pc.backlash_um, pc.speed_rpm);
        gd_case_free(&pc);
        gd_sweep_points_free(&p, pts);
        gd_sweep_plan_free(&p);
        gd_case_free(&c);
    }

    /* bad input */
    {
        const char *a[] = {"sweep.from=1000", "sweep.to=2000", "sweep.parameter=operating.speed_rmp", NULL};
        expect_bad(a, "did you mean operating.speed_rpm", "unknown swept key");
        const char *b[] = {"sweep.from=1000", "sweep.to=200000", NULL};
        expect_bad(b, "sweep.to: operating.speed_rpm = 200000 is out of range", "value out of the key's range");
        const char *d[] = {"sweep.from=0", "sweep.to=2000", "sweep.spacing=log", NULL};
        expect_bad(d, "sweep.spacing: log spacing", "log spacing through zero");
        const char *f[] = {"sweep.to=2000", NULL};
        expect_bad(f, "sweep.from: missing", "missing from");
        const char *g[] = {"sweep.from=1000", "sweep.to=2000", "sweep.parameter=scene.model", NULL};
        expect_bad(g, "not a numeric", "enumerated key");
        const char *h[] = {"sweep.from=1000", "sweep.to=2000", "sweep.parameter2=operating.speed_rpm",
                           "sweep.from2=1", "sweep.to2=2", NULL};
        expect_bad(h, "already sweep.parameter", "parameter2 equal to parameter");
        const char *k[] = {"sweep.from=1000", "sweep.to=2000", "sweep.from2=1", NULL};
        expect_bad(k, "given without sweep.parameter2", "from2 without parameter2");
        const char *r[] = {"sweep.from=1000", "sweep.to=2000", "sweep.response=lambda_L, x1L", NULL};
        expect_bad(r, "unknown response 'x1L'", "response not in the model");
        const char *t[] = {"sweep.from=1000", "sweep.to=2000", "sweep.parameter=operating.power_kw", NULL};
        gd_case bc;
        PU_CHECK(gd_case_init(&bc, &e), &e);
        bc.speed_rpm = 4000, bc.torque_nm = 500; /* the paper's operating point: a case must give one */
        gd_status st = GD_OK;
        for (int i = 0; ks[i] && st == GD_OK; i++)
            st = gd_case_set(&bc, ks[i], i, &e);
        for (int i = 0; t[i] && st == GD_OK; i++)
            st = gd_case_set(&bc, t[i], 50 + i, &e);
        if (st == GD_OK)
            st = gd_case_resolve(&bc, &e);
        gd_sweep_plan bp;
        if (st == GD_OK)
            st = gd_sweep_plan_create(&bc, &bp, &e);
        tap_ok(st == GD_ERR_INPUT && strstr(e.msg, "power_kw") != NULL,
               "sweeping power with the torque given is refused before any point runs (%s)", e.msg);
        gd_case_free(&bc);
    }
    return tap_done();
}
