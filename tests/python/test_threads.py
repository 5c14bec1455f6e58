"""The GIL is released during a run (docs/python.md section 5): two runs in two Python threads
proceed at the same time, each seen in progress (0 < done < total) while the other is, which a
binding that held the GIL through the run would never show (one thread's run would block every
other thread, its progress callback included); and each gives what it gives alone, bit for bit.
The thread count and OpenMP settings are reachable."""
import os
import threading
import time

import geardyn
from conftest import SRC, TIMES, load

CASE = os.path.join(SRC, 'cases', 'guide', 'herringbone.ini')
SETS = [('output.plots', 'off')]


def test_two_threads_run_in_parallel():
    seen = {0: [], 1: []}
    results = {}

    def one(k):
        def progress(done, total, unit):
            seen[k].append((time.monotonic(), 0 < done < total))
        results[k] = geardyn.run(load(CASE, SETS + [('operating.speed_rpm', 3000 + 500 * k)]), threads=1,
                                 progress=progress)
    ts = [threading.Thread(target=one, args=(k,)) for k in (0, 1)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    spans = []
    for k in (0, 1):
        times = [t for t, running in seen[k] if running]
        assert times, 'run %d was never seen in progress' % k
        spans.append((times[0], times[-1]))
    assert max(s[0] for s in spans) < min(s[1] for s in spans), 'the two runs did not overlap: %s' % spans
    for k in (0, 1):
        alone = geardyn.run(load(CASE, SETS + [('operating.speed_rpm', 3000 + 500 * k)]), threads=1)
        assert alone.equals(results[k], ignore=TIMES)


def test_threads_and_openmp():
    o = geardyn.openmp()
    assert o['default_threads'] >= 1 and o['threads'] == geardyn.threads()
    try:
        geardyn.set_threads(3)
        assert geardyn.threads() == 3 and geardyn.openmp()['threads'] == 3
    finally:
        geardyn.set_threads(0)
    assert geardyn.threads() == o['default_threads']
    if os.environ.get('OMP_NUM_THREADS'):
        assert o['default_threads'] == int(os.environ['OMP_NUM_THREADS'].split(',')[0])
