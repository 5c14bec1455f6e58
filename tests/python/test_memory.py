"""1000 short response runs in a loop do not grow the process (docs/python.md section 6): the
library frees every result, the job its copy of the case and the files it kept, and the module
keeps nothing of a run it has returned. RSS (VmRSS of /proc/self/status) after run 1000 exceeds
RSS after run 100 (the warm-up: Python's and glibc's pools, OpenMP's threads) by less than 2 MB,
where a run's files alone are about 100 kB (a lost run's files would add 90 MB)."""
import os

import pytest

import geardyn
from conftest import SRC, load

ASAN = 'libasan' in os.environ.get('LD_PRELOAD', '')


def rss_kb():
    with open('/proc/self/status') as f:
        for line in f:
            if line.startswith('VmRSS:'):
                return int(line.split()[1])


@pytest.mark.skipif(ASAN, reason="AddressSanitizer's quarantine keeps freed memory: RSS says nothing there")
def test_thousand_runs_do_not_grow():
    c = load(os.path.join(SRC, 'cases', 'validation', 'kahraman-singh.ini'),
             [('run.transient_periods', 10), ('run.record_periods', 5), ('output.plots', 'off')])
    rss, size = {}, 0
    for i in range(1, 1001):
        r = geardyn.run(c, threads=1)
        if i in (100, 1000):
            rss[i] = rss_kb()
            size = sum(len(b) for b in r.raw.values())
    growth = rss[1000] - rss[100]
    print('RSS %d kB after 100 runs, %d kB after 1000 (+%d kB); a run returns %d kB of files' %
          (rss[100], rss[1000], growth, size // 1024))
    assert size > 50000
    assert growth < 2048
