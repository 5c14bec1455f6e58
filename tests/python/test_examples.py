"""The Python examples of examples/python/ are tests (like the C examples, tests/test_examples.py):
each runs as a user runs it, in a directory of its own, and what it prints is checked against a value
computed another way, by the command line:

  response.py      the RMS mesh acceleration and motion of cases/guide/spur.ini (shortened) equal
                   those of `geardyn run` on the same case; the RMS the example sums from the
                   samples it received agrees with the library's to the 9 digits the samples carry.
  sweep.py         the first point of each sweep (up from 100 rpm: a response from the case's
                   initial state) equals `geardyn run` of that response, before and after the
                   modification; the modification lowers the largest RMS acceleration (the paper's
                   finding, section 6).
  continuation.py  every bifurcation it prints is a row of the command line's bifurcations.csv.
  basins.py        each attractor's fraction, standard error and Wilson interval, its cells of the
                   picture (counted by the example in the 2-D array) and the basin entropy are those
                   of `geardyn run` on the same case (attractors.csv, summary.json).

With matplotlib installed each draws its picture (a whole PNG); without, it says so and ends well."""
import csv
import importlib.util
import json
import os
import subprocess
import sys

import pytest

from conftest import SRC, cli

EXAMPLES = os.path.join(SRC, 'examples', 'python')
MATPLOTLIB = importlib.util.find_spec('matplotlib') is not None


def example(name, *args):
    p = subprocess.run([sys.executable, os.path.join(EXAMPLES, name)] + [str(a) for a in args],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    vals = {'table': p.stdout.splitlines()}
    for line in p.stdout.splitlines():
        if ' = ' in line and not line.startswith('#'):
            k, v = line.split(' = ', 1)
            vals.setdefault(k.strip(), []).append(v.strip())
    if MATPLOTLIB:
        with open(vals['picture'][0], 'rb') as f:
            b = f.read()
        assert b[:8] == b'\x89PNG\r\n\x1a\n' and b[-12:] == b'\0\0\0\0IEND\xaeB`\x82'
    else:
        assert 'matplotlib is not installed' in p.stdout
    return vals


def cli_summary(case, sets):
    args = ['run', case, '--out', 'cli', '--quiet']
    for k, v in sets:
        args += ['--set', '%s=%s' % (k, v)]
    rc, _, err = cli(args)
    assert rc == 0, err
    with open(os.path.join('cli', 'summary.json')) as f:
        return json.load(f)


def test_response(work):
    v = example('response.py')
    s = cli_summary(os.path.join(SRC, 'cases', 'guide', 'spur.ini'),
                    [('run.transient_periods', 100), ('run.record_periods', 20), ('output.plots', 'off')])
    rms = s['results']['rms_accel_mps2']['left']
    assert float(v['rms_accel_mps2'][0]) == pytest.approx(rms, rel=1e-8)
    assert float(v['rms_accel_samples_mps2'][0]) == pytest.approx(rms, rel=1e-7)
    assert v['motion'][0] == s['results']['motion']
    assert int(v['samples'][0]) == 20 * s['case']['parameters']['output']['samples_per_period']['value']


def test_sweep(work):
    v = example('sweep.py', 5)
    assert float(v['peak_after_mps2'][0]) < float(v['peak_before_mps2'][0])
    first = v['table'][1].split()      # speed, before, after, ratio: the point at 100 rpm
    assert float(first[0]) == 100
    for col, apply in ((1, 'off'), (2, 'on')):
        s = cli_summary(os.path.join(SRC, 'cases', 'paper', 'sweep-speed.ini'),
                        [('scene.analysis', 'response'), ('operating.speed_rpm', 100), ('modification.apply', apply),
                         ('run.lyapunov_exponents', 0), ('run.transient_periods', 100),
                         ('run.transient_max_periods', 300), ('run.record_periods', 20), ('output.plots', 'off')])
        assert float(first[col]) == pytest.approx(s['results']['rms_accel_mps2']['combined'], rel=1e-5), apply


def test_continuation(work):
    v = example('continuation.py')
    rc, _, err = cli(['run', os.path.join(SRC, 'cases', 'continuation', 'kahraman-singh.ini'), '--out', 'cli', '--quiet',
                      '--set', 'output.plots=off'])
    assert rc == 0, err
    with open(os.path.join('cli', 'bifurcations.csv')) as f:
        rows = [ln.split(',') for ln in f.read().splitlines()[1:]]
    want = ['branch %s, period-%s, %s at speed_rpm = %.9g rpm' % (r[0], r[1], r[2], float(r[3])) for r in rows]
    assert v['bifurcation'] == want and len(want) >= 4
    assert int(v['branches'][0]) >= 2


def test_basins(work):
    v = example('basins.py', 30)
    s = cli_summary(os.path.join(SRC, 'cases', 'basins', 'ks-hysteresis.ini'),
                    [('basins.resolution', 30), ('basins.samples', 2000), ('output.plots', 'off')])
    assert v['cells'] == ['30 x 30']
    with open(os.path.join('cli', 'attractors.csv')) as f:
        rows = list(csv.DictReader(f))
    cells = {lab['attractor']: lab['cells'] for lab in s['results']['picture']['labels']}
    want = ['%s, %s, %s, fraction %.4f +- %.4f, wilson [%.4f, %.4f], picture cells %d'
            % (r['index'], r['name'], r['impact_regime'], float(r['fraction']), float(r['standard_error']),
               float(r['wilson_lo']), float(r['wilson_hi']), cells.get(int(r['attractor']), 0)) for r in rows]
    assert v['attractor'] == want and len(want) == 2
    assert v['basin_entropy'] == ['%.6f' % s['results']['picture']['basin_entropy']['S_b']]
