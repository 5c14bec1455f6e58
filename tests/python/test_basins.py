"""The basins of attraction from Python (docs/python.md section 3, docs/basins.md) against the
command line: the picture and the fractions of the Kahraman & Singh oscillator at Omega 0.65
(cases/basins/ks-hysteresis.ini) and its fractions over the speed (cases/basins/ks-fractions.ini),
both shortened; the picture as a 2-D array (Result.grid) against basins.csv read cell by cell and
the picture's counts in summary.json; the counts of the fractions against their samples; the
progress of the initial states and a stop from the progress callback, which leaves the previous
result in place."""
import csv
import os

import numpy as np
import pytest

import geardyn
from conftest import TIMES, cli_run, load, same_file, state

PICTURE = ('cases/basins/ks-hysteresis.ini',
           [('basins.resolution', 24), ('basins.resolution_y', 20), ('basins.samples', 300), ('output.plots', 'off')])
FRACTIONS = ('cases/basins/ks-fractions.ini',
             [('basins.points', 3), ('basins.samples', 200), ('output.plots', 'off')])


def _same_as_cli(rel, sets):
    rc, _, err = cli_run(rel, sets, 'cli')
    assert rc == 0, err
    r = geardyn.run(load(rel, sets), threads=1)
    assert r.analysis == 'basins'
    for name, data in r.raw.items():
        with open(os.path.join('cli', name), 'rb') as f:
            assert same_file(name, data, f.read()), name
    assert geardyn.read('cli').equals(r, ignore=TIMES)
    return r


def test_picture(work):
    r = _same_as_cli(*PICTURE)
    assert {'basins', 'attractors', 'fractions', 'attractor_points'} <= set(r.tables)
    x, y, label = r.grid()
    pic = r.summary['results']['picture']
    assert label.shape == (20, 24) and list(pic['cells']) == [24, 20]
    assert np.all(np.diff(x) > 0) and np.all(np.diff(y) > 0)
    # cell by cell, as the command line's basins.csv has it
    with open(os.path.join('cli', 'basins.csv'), newline='') as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 24 * 20
    xn, yn = r['basins'].dtype.names[2:4]
    for row in rows:
        i, j = int(row['i']), int(row['j'])
        assert label[j, i] == float(row['label'])
        assert x[i] == float(row[xn]) and y[j] == float(row[yn])
    _, _, outcome = r.grid('outcome')
    assert outcome.dtype.kind == 'U' and outcome[0, 0] == rows[0]['outcome']
    # the picture's counts of summary.json are the array's
    assert pic['labels'], 'no attractor found in the picture'
    for lab in pic['labels']:
        cells = int(np.sum(r.grid('attractor')[2] == lab['attractor']))
        assert cells == lab['cells'], lab
    assert sum(lab['cells'] for lab in pic['labels']) + int(np.sum(label < 0)) == label.size
    # the fractions: every sample counted once
    fr = r['fractions']
    assert np.all(fr['samples'] == 300) and fr['count'].sum() == 300


def test_fractions_over_speed(work):
    r = _same_as_cli(*FRACTIONS)
    fr = r['fractions']
    speeds = np.unique(fr['speed_rpm'])
    assert len(speeds) == 3
    for s in speeds:
        at = fr[fr['speed_rpm'] == s]
        assert at['count'].sum() == 200 and np.all(at['samples'] == 200)
        assert abs(at['fraction'].sum() - 1) < 1e-9
    assert set(np.unique(r['attractors']['speed_rpm'])) == set(speeds)


def test_progress_and_stop(work):
    rel, sets = FRACTIONS
    sets = sets + [('basins.samples', 2000)]
    seen = []

    def note(done, total, unit):
        seen.append((done, total, unit))

    geardyn.run(load(rel, sets), out='prev', threads=1, progress=note)
    counted = [p for p in seen if p != (0, 0, '')]   # (0, 0, ''): before the run counts anything
    assert counted, 'no progress reported during a basins run: %r' % seen
    assert {u for _, _, u in counted} == {'initial states'}
    assert all(t > 0 and 0 <= d <= t for d, t, _ in counted)
    before = state('prev')
    with pytest.raises(geardyn.Interrupted):
        geardyn.run(load(rel, sets), out='prev', threads=1, progress=lambda d, t, u: d > 0)
    assert state('prev') == before
