#!/usr/bin/env python3
"""Fault injection without privileges: a full disk (RLIMIT_FSIZE, SIGXFSZ ignored) at several
sizes and SIGINT / SIGTERM / SIGHUP at several moments of a response run, a sweep, an
optimisation and basins, and SIGKILL then --resume for the sweep. Early signals in the long computations that
are not integrations (an optimisation, a large LTCA and TCA, an optimiser comparison, a
continuation of one branch, a work-precision study, basins): each ends the process with 128 + the signal within half the run's own
length, measured in the same test, leaving nothing in a new directory or the previous result. Each trial runs into a directory that holds
a previous result and proves that afterwards it holds either that result unchanged (sha256 of
every file) or a whole new set (exactly the files its summary.json lists, every picture whole),
and no temporaries (but the sweep's journal after an interrupted sweep). Also: a second run into
a locked directory, a second signal, what a killed run left, the previous set's files a new set
lacks. No stage is left beside the directory (PARENT/.NAME.geardyn-stage). TAP; python3 standard
library only.

  test_faults.py        (GEARDYN names the executable, GEARDYN_SOURCE the source tree)
"""
import hashlib
import json
import os
import resource
import signal
import subprocess
import sys
import tempfile
import time

G = os.environ.get('GEARDYN', 'geardyn')
SRC = os.environ.get('GEARDYN_SOURCE', '.')
n_tap = 0
failed = 0
outcomes = {}


def ok(cond, msg):
    global n_tap, failed
    n_tap += 1
    if not cond:
        failed += 1
    print(('ok' if cond else 'not ok') + ' %d - %s' % (n_tap, msg))
    sys.stdout.flush()


with open(os.path.join(SRC, "tests", "cli", "ks-sweep.ini")) as _f:
    SWEEP = _f.read()  # record_periods 30, plots on, 80 points each way


def state(d):
    """sha256 of every file under d (relative names), '.'-names at the top apart."""
    files, dots = {}, []
    if not os.path.isdir(d):
        return files, dots
    for name in os.listdir(d):
        if name.startswith('.'):
            dots.append(name)
    for root, dirs, names in os.walk(d):
        rel = os.path.relpath(root, d)
        if rel != '.' and rel.split(os.sep)[0].startswith('.'):
            continue
        for n in names:
            p = os.path.join(root, n)
            r = os.path.normpath(os.path.join(rel, n))
            if r.startswith('.'):
                continue
            with open(p, 'rb') as f:
                files[r] = hashlib.sha256(f.read()).hexdigest()
    return files, sorted(dots)


def beside(d):
    """Stages left beside d (PARENT/.NAME.geardyn-stage)."""
    parent, name = os.path.split(d)
    return sorted(n for n in os.listdir(parent) if n.startswith('.' + name + '.'))


def picture_whole(p):
    with open(p, 'rb') as f:
        b = f.read()
    if p.endswith('.png'):
        return b[:8] == b'\x89PNG\r\n\x1a\n' and b[-12:] == b'\0\0\0\0IEND\xaeB`\x82'
    return b.rstrip().endswith(b'</svg>')


def whole_set(d):
    """The top-level names are exactly summary.json's list (sub-directories likewise), pictures whole."""
    try:
        listed = json.load(open(os.path.join(d, 'summary.json')))['files']
    except (OSError, ValueError, KeyError):
        return False
    have = sorted(n for n in os.listdir(d) if not n.startswith('.'))
    want = sorted(n.rstrip('/') for n in listed)
    if have != want:
        return False
    for n in listed:
        p = os.path.join(d, n.rstrip('/'))
        if n.endswith('/') and not whole_set(p):
            return False
        if p.endswith(('.png', '.svg')) and not picture_whole(p):
            return False
    return True


def fsize(limit):
    def pre():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
    return pre


def run(args, pre=None, sig=None, at=0.0, second=False):
    p = subprocess.Popen([G, 'run'] + args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                         preexec_fn=pre)
    if sig:
        time.sleep(at)
        try:
            if second:
                # SIGINT and sig pending together (the process stopped meanwhile), so that the
                # second reaches the handler before the run has acted on the first, which it
                # would within a millisecond; two of one signal would merge into one
                p.send_signal(signal.SIGSTOP)
                p.send_signal(signal.SIGINT)
                p.send_signal(sig)
                p.send_signal(signal.SIGCONT)
            else:
                p.send_signal(sig)
        except ProcessLookupError:
            pass
    err = p.communicate(timeout=600)[1].decode('utf-8', 'replace')
    return p.returncode, err


def trial(kind, d, args, what, before, pre=None, sig=None, at=0.0, journal_ok=False):
    rc, err = run(args, pre, sig, at)
    files, dots = state(d)
    allowed = ['.sweep.journal'] if journal_ok and rc != 0 else []
    clean = all(x in allowed for x in dots) and beside(d) == []
    if rc == 0:
        outcome = 'new'
        good = whole_set(d) and clean
    else:
        outcome = 'kept'
        good = files == before and clean
        if sig and sig != signal.SIGKILL:
            good = good and rc == 128 + sig and ('interrupted' in err)
        elif not sig:
            good = good and rc == 1
    outcomes.setdefault(kind, {}).setdefault(outcome, 0)
    outcomes[kind][outcome] += 1
    ok(good, '%s, %s: exit %d, %s (%d files, left %s) %s' % (kind, what, rc, 'whole new set' if rc == 0
       else 'previous result unchanged', len(files), dots + beside(d), err.strip().splitlines()[-1:] if rc else ''))
    return rc, files


def timed(args):
    t0 = time.monotonic()
    rc, err = run(args)
    return rc, time.monotonic() - t0, err


def series(kind, d, args, sizes, moments, journal_ok=False):
    rc, dur, err = timed(args)
    ok(rc == 0 and whole_set(d), '%s: the previous result (%.2f s) %s' % (kind, dur, err.strip()[-200:]))
    before, _ = state(d)
    for sz in sizes:
        rc, files = trial(kind, d, args, 'file size limit %d bytes' % sz, before, pre=fsize(sz),
                          journal_ok=journal_ok)
        before = files
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        for frac in moments:
            rc, files = trial(kind, d, args, '%s at %.0f%% of its time' % (sig.name, 100 * frac), before, sig=sig,
                              at=frac * dur, journal_ok=journal_ok)
            before = files
    return dur


def early_stops(kind, tmp, case, sets, frac=0.2):
    """The run's own length D (uninterrupted, its result the previous one), then a signal at frac D:
    SIGINT into a new directory, SIGTERM and SIGHUP into the previous result. Each must end the
    process with 128 + the signal before D / 2 (an analysis that asks for signals only at its end
    runs the whole D) and leave nothing, or the previous result unchanged."""
    def args(out):
        a = [os.path.join(SRC, case), '--out', out, '--quiet', '--set', 'output.plots=off']
        for x in sets:
            a += ['--set', x]
        return a
    d = os.path.join(tmp, kind + '-early')
    rc, dur, err = timed(args(d))
    ok(rc == 0 and whole_set(d), '%s: the uninterrupted run takes %.2f s %s' % (kind, dur, err.strip()[-200:]))
    before, _ = state(d)
    for sig, out in ((signal.SIGINT, d + '-new'), (signal.SIGTERM, d), (signal.SIGHUP, d)):
        t0 = time.monotonic()
        rc, err = run(args(out), sig=sig, at=frac * dur)
        took = time.monotonic() - t0
        files, dots = state(out)
        kept = files == before if out == d else not os.path.exists(out) or (files == {} and dots == [])
        # the line names what the directory holds: its previous result, or none
        says = 'keeps its previous result' if out == d else 'holds no result'
        good = rc == 128 + sig and took < 0.5 * dur and kept and dots == [] and 'interrupted' in err and says in err
        outcomes.setdefault(kind, {}).setdefault('stopped early', 0)
        outcomes[kind]['stopped early'] += good
        ok(good, '%s, %s at %.0f%% of its %.2f s: exit %d after %.2f s (%.0f%%), %s, left %s, says "%s"' %
           (kind, sig.name, 100 * frac, dur, rc, took, 100 * took / dur,
            'previous result unchanged' if out == d and kept else 'nothing left' if kept else 'FILES CHANGED', dots,
            err.strip().splitlines()[-1] if err.strip() else ''))


def main():
    tmp = tempfile.mkdtemp(prefix='geardyn-faults-')
    quick = os.path.join(SRC, 'cases', 'quickstart.ini')
    # response: small tables, so that a limit between the tables and the pictures truncates a picture
    r = os.path.join(tmp, 'response')
    rargs = [quick, '--out', r, '--quiet', '--set', 'run.record_periods=5', '--set', 'output.event_log=off']
    series('response', r, rargs, [1000, 40000, 90000, 150000], [0.1, 0.5, 0.9])

    s = os.path.join(tmp, 'sweep')
    sc = os.path.join(tmp, 'ks.ini')
    with open(sc, 'w') as f:
        f.write(SWEEP)
    sargs = [sc, '--out', s, '--quiet', '--threads', '2']
    dur = series('sweep', s, sargs, [300, 5000, 60000], [0.2, 0.6, 0.97], journal_ok=True)
    before, _ = state(s)
    for frac in (0.3, 0.7):
        rc, err = run(sargs, sig=signal.SIGKILL, at=frac * dur)
        files, dots = state(s)
        ok((rc == -9 and files == before) or (rc == 0 and whole_set(s)), 'sweep, SIGKILL at %.0f%%: exit %d, '
           '%s, left %s' % (100 * frac, rc, 'whole new set' if rc == 0 else 'previous result unchanged', dots))
        rc, err = run(sargs + ['--resume'])
        files, dots = state(s)
        ok(rc == 0 and whole_set(s) and dots == [] and beside(s) == [], 'sweep, --resume after SIGKILL: exit %d, '
           'whole new set, left %s' % (rc, dots + beside(s)))
        outcomes['sweep']['kill+resume'] = outcomes['sweep'].get('kill+resume', 0) + 1
        before = files

    o = os.path.join(tmp, 'optimize')
    oargs = [os.path.join(SRC, 'cases', 'paper', 'optimize-alo.ini'), '--out', o, '--quiet', '--set',
             'optimize.iterations=2', '--set', 'optimize.population=4', '--set', 'solver.ltca_positions_per_cycle=8']
    series('optimize', o, oargs, [500, 5000, 60000], [0.2, 0.6, 0.95])

    # early signals in the computations that poll a stop hook per position, evaluation or period
    early_stops('optimize', tmp, 'cases/paper/optimize-alo.ini',
                ['optimize.iterations=14', 'optimize.population=6', 'solver.ltca_positions_per_cycle=8'])
    early_stops('ltca', tmp, 'cases/paper/ltca-modified.ini', ['solver.ltca_positions_per_cycle=1500'])
    early_stops('tca', tmp, 'cases/paper/tca-modified.ini', ['solver.tca_positions_per_cycle=2500'])
    early_stops('compare-optimizers', tmp, 'cases/paper/compare-optimizers.ini',
                ['optimize.runs=2', 'optimize.budget_evals=40', 'optimize.population=10',
                 'solver.ltca_positions_per_cycle=8'])
    early_stops('continuation', tmp, 'cases/continuation/paper-speed.ini', [])  # one branch: a stop between points
    # basins: a small picture and sample (a full disk, signals), then a larger one stopped early (the stop hook
    # is asked every mesh period of every trajectory)
    b = os.path.join(tmp, 'basins')
    bargs = [os.path.join(SRC, 'cases', 'basins', 'ks-hysteresis.ini'), '--out', b, '--quiet', '--set',
             'basins.resolution=30', '--set', 'basins.samples=200']
    series('basins', b, bargs, [300, 60000], [0.5])
    early_stops('basins', tmp, 'cases/basins/ks-hysteresis.ini', ['basins.resolution=80', 'basins.samples=500'])
    early_stops('work-precision', tmp, 'cases/accuracy/period1-7000rpm.ini',
                ['workprecision.families=rk4,erk4,erk8', 'workprecision.rtol_tightest=1e-7',
                 'workprecision.rk4_steps_max=64', 'workprecision.order_steps_max=64', 'workprecision.repeats=1',
                 'workprecision.horizon_periods=5', 'run.transient_periods=100', 'run.record_periods=200'])

    # a second run into a directory being written is refused, the first one ends well
    p = subprocess.Popen([G, 'run'] + rargs, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(0.3)
    rc, err = run(rargs)
    p.wait()
    ok(rc == 1 and 'another geardyn run is writing into this directory' in err and p.returncode == 0
       and whole_set(r), 'a second run into a locked directory: exit %d, %s' % (rc, err.strip()))
    # a second signal ends the run at once (exit 128 + the one handled last: either); what it left
    # is removed by the next run. One thread, so that the two handlers run one after the other.
    before, _ = state(o)
    rc, err = run(oargs + ['--threads', '1'], sig=signal.SIGTERM, at=0.3, second=True)
    ok(rc in (130, 143) and 'second signal' in err and state(o)[0] == before,
       'SIGINT and a second signal, SIGTERM: exit %d, previous result unchanged: %s' %
       (rc, err.strip().splitlines()[-1:]))
    rc, err = run(oargs)
    ok(rc == 0 and state(o)[1] == [] and beside(o) == [] and whole_set(o),
       'the next run removes what it left (left %s)' % (state(o)[1] + beside(o)))
    # a killed run's stages (beside DIR, and DIR/.staging where DIR cannot be exchanged) and
    # gnuplot script are removed by the next run
    stage = os.path.join(tmp, '.response.geardyn-stage')
    os.mkdir(stage)
    open(os.path.join(stage, '.geardyn-unpublished'), 'w').close()
    open(os.path.join(stage, 'time_history.csv'), 'w').close()
    os.mkdir(os.path.join(r, '.staging'))
    open(os.path.join(r, '.staging', 'time_history.csv'), 'w').close()
    open(os.path.join(r, '.plot-abcdef'), 'w').close()
    rc, err = run(rargs)
    ok(rc == 0 and state(r)[1] == [] and beside(r) == [] and whole_set(r), 'stale stages and a .plot- file are '
       'removed by the next run (left %s)' % (state(r)[1] + beside(r)))
    # the files of the previous set that the new one lacks go (the local analysis's tables)
    rc, err = run(rargs + ['--set', 'output.plots=off', '--set', 'output.time_history=off'])
    ok(rc == 0 and whole_set(r) and not os.path.exists(os.path.join(r, 'time_history.csv'))
       and not os.path.exists(os.path.join(r, 'response.png')),
       'a new set without time_history.csv and pictures: the previous ones are gone (%s)' %
       sorted(os.listdir(r)))
    # an output path that fails further on (a file in the way) leaves none of the directories made
    open(os.path.join(tmp, 'afile'), 'w').close()
    bad = os.path.join(tmp, 'made', '..', 'afile', 'z')
    rc, err = run([quick, '--out', bad, '--quiet'])
    ok(rc == 2 and not os.path.exists(os.path.join(tmp, 'made')) and 'cannot be a directory' in err,
       'an output path through a file: exit %d, no leading directory left: %s' % (rc, err.strip()))
    print('# outcomes: ' + json.dumps(outcomes, sort_keys=True))
    print('1..%d' % n_tap)
    subprocess.run(['rm', '-rf', tmp])
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
