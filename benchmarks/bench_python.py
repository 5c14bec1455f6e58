#!/usr/bin/env python3
"""The Python module's figures (docs/python.md): not a test (tests time nothing).

  memory    RSS of the process over 1000 short response runs (cases/validation/kahraman-singh.ini,
            10 + 5 mesh periods), after runs 1, 100, 500 and 1000
  stop      the time from SIGINT to KeyboardInterrupt during a sweep (tests/cli/ks-sweep.ini with
            1000 + 200 mesh periods a point), over N trials, each once two points are done
  threads   two responses (cases/guide/herringbone.ini at 3000 and 3500 rpm, 1 OpenMP thread each)
            one after the other, then in two Python threads at once: wall and CPU times, the speed-up
            and the CPU seconds the process used per wall second (above 1: both runs computed at once)
  overhead  the cost of a run from Python against the command line's: N short responses
            (cases/validation/kahraman-singh.ini, 10 + 5 mesh periods, pictures off), each as
            `geardyn run --out DIR` in a process of its own, as geardyn.run(case) in memory and as
            geardyn.run(case, out=DIR): the median wall time of each

  PYTHONPATH=build/python GEARDYN_SOURCE=. python3 benchmarks/bench_python.py [memory] [stop N] [threads N] [overhead N]
  meson test -C build --benchmark -v python"""
import os
import signal
import statistics
import sys
import threading
import time

import geardyn

SRC = os.environ.get('GEARDYN_SOURCE', os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))


def load(rel, sets):
    c = geardyn.Case.load(os.path.join(SRC, rel))
    for k, v in sets:
        c.set(k, v)
    return c


def rss_kb():
    with open('/proc/self/status') as f:
        return next(int(ln.split()[1]) for ln in f if ln.startswith('VmRSS:'))


def load_average():
    return os.getloadavg()[0]


def memory():
    c = load('cases/validation/kahraman-singh.ini',
             [('run.transient_periods', 10), ('run.record_periods', 5), ('output.plots', 'off')])
    t0 = time.monotonic()
    marks = {}
    for i in range(1, 1001):
        geardyn.run(c, threads=1)
        if i in (1, 100, 500, 1000):
            marks[i] = rss_kb()
    dt = time.monotonic() - t0
    print('memory: RSS after run 1: %d kB, 100: %d kB, 500: %d kB, 1000: %d kB (1000 - 100: %+d kB); '
          '%.1f ms a run, load %.1f' % (marks[1], marks[100], marks[500], marks[1000], marks[1000] - marks[100],
                                      dt, load_average()))


def stop(trials):
    case = load('tests/cli/ks-sweep.ini', [('run.transient_periods', 1000), ('run.record_periods', 200),
                                           ('output.plots', 'off')])
    lat = []
    for _ in range(trials):
        done, sent = [0], []

        def body():
            while done[0] < 2:
                time.sleep(0.002)
            sent.append(time.monotonic())
            os.kill(os.getpid(), signal.SIGINT)
        t = threading.Thread(target=body)
        t.start()
        try:
            geardyn.run(case, threads=1, progress=lambda d, total, unit: done.__setitem__(0, d))
        except KeyboardInterrupt:
            lat.append(time.monotonic() - sent[0])
        t.join()
    print('stop: SIGINT to KeyboardInterrupt during a sweep, %d trials: min %.1f ms, median %.1f ms, max %.1f ms; '
          'load %.1f' % (trials, 1e3 * min(lat), 1e3 * statistics.median(lat), 1e3 * max(lat), load_average()))


def cpu_s():
    t = os.times()
    return t.user + t.system


def two_threads(trials):
    cases = [load('cases/guide/herringbone.ini', [('operating.speed_rpm', s), ('output.plots', 'off')])
             for s in (3000, 3500)]
    for _ in range(trials):
        t0, c0 = time.monotonic(), cpu_s()
        for c in cases:
            geardyn.run(c, threads=1)
        seq, seq_cpu = time.monotonic() - t0, cpu_s() - c0
        ts = [threading.Thread(target=geardyn.run, args=(c,), kwargs={'threads': 1}) for c in cases]
        t0, c0 = time.monotonic(), cpu_s()
        for t in ts:
            t.start()
        for t in ts:
            t.join()
        par, par_cpu = time.monotonic() - t0, cpu_s() - c0
        print('threads: two responses one after the other %.2f s (%.2f s CPU), in two Python threads %.2f s '
              '(%.2f s CPU, %.2f CPU seconds a second): speed-up %.2f (%d cores, load %.1f)' %
              (seq, seq_cpu, par, par_cpu, par_cpu / par, seq / par, os.cpu_count(), load_average()))


def overhead(trials):
    import subprocess
    import tempfile
    exe = os.environ.get('GEARDYN', os.path.join(SRC, 'build', 'src', 'cli', 'geardyn'))
    rel = 'cases/validation/kahraman-singh.ini'
    sets = [('run.transient_periods', 10), ('run.record_periods', 5), ('output.plots', 'off')]
    c = load(rel, sets)
    cmd = [exe, 'run', os.path.join(SRC, rel), '--quiet', '--threads', '1']
    for k, v in sets:
        cmd += ['--set', '%s=%s' % (k, v)]
    t_cli, t_mem, t_dir = [], [], []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(trials):
            t0 = time.monotonic()
            subprocess.run(cmd + ['--out', os.path.join(tmp, 'cli')], check=True)
            t_cli.append(time.monotonic() - t0)
            t0 = time.monotonic()
            geardyn.run(c, threads=1)
            t_mem.append(time.monotonic() - t0)
            t0 = time.monotonic()
            geardyn.run(c, out=os.path.join(tmp, 'py'), threads=1)
            t_dir.append(time.monotonic() - t0)
    med = statistics.median
    print('overhead: a short response (%d trials, median): geardyn run --out %.1f ms, geardyn.run in memory %.1f ms, '
          'geardyn.run(out=) %.1f ms; load %.1f' % (trials, 1e3 * med(t_cli), 1e3 * med(t_mem), 1e3 * med(t_dir),
                                                    load_average()))


def main(argv):
    what = argv or ['memory', 'stop', '10', 'threads', '3', 'overhead', '20']
    i = 0
    while i < len(what):
        w = what[i]
        n = int(what[i + 1]) if i + 1 < len(what) and what[i + 1].isdigit() else None
        if w == 'memory':
            memory()
        elif w == 'stop':
            stop(n or 10)
        elif w == 'threads':
            two_threads(n or 3)
        elif w == 'overhead':
            overhead(n or 20)
        else:
            raise SystemExit('bench_python.py: unknown %r (memory, stop N, threads N, overhead N)' % w)
        i += 2 if n is not None else 1


if __name__ == '__main__':
    main(sys.argv[1:])
