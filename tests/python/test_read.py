"""geardyn.read(dir) of every shipped case's output equals the result geardyn.run returned for it
(docs/python.md section 3): each case of cases/ run into a directory, shortened as
scripts/compare-outputs.sh shortens it and, where that leaves a run of more than half a second
(check()'s estimate), to 3 sweep points and 100 + 20 mesh periods; a continuation to 2 branches of
at most 40 points; the pictures off. Equal means equal summaries and every table bit for bit."""
import os

import pytest

import geardyn
from conftest import load, shipped_cases, shortening

QUICK = [('run.transient_periods', 100), ('run.transient_max_periods', 0), ('run.record_periods', 20)]


def short(rel):
    sets = shortening(rel) + [('output.plots', 'off')]
    c = load(rel, sets)
    if c['scene.analysis'] == 'continuation':
        sets += [('continuation.max_points', min(c['continuation.max_points'], 40)),
                 ('continuation.max_branches', min(c['continuation.max_branches'], 2))]
        c = load(rel, sets)
    if (c.check()['cost']['seconds'] or 0) > 0.5:
        extra = [(k, v) for k, v in QUICK if c[k] > v or k == 'run.transient_max_periods']
        if c['scene.analysis'] == 'sweep':
            extra.append(('sweep.points', 3))
        sets += extra
        c = load(rel, sets)
    return c


@pytest.mark.parametrize('rel', shipped_cases())
def test_read_is_run(rel, work):
    r = geardyn.run(short(rel), out='out')
    assert geardyn.read('out') == r
    assert geardyn.read(os.path.abspath('out')) == r
