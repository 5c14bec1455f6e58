#!/usr/bin/env python3
"""The tables write the columns that exist: a model with one mesh (a spur or single-helical pair,
the one-coordinate torsional model of a herringbone) has no right mesh, so no table of a response,
a sweep or a continuation has a right-mesh column (_R) nor a column that is NaN in every row; its
summary.json gives null for the right mesh. A model with two meshes (the herringbone's bta) writes
both, and they differ. TAP; python3 standard library only.

  test_columns.py        (GEARDYN names the executable, GEARDYN_SOURCE the source tree)
"""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile

from tap import ok, plan  # tests/cli/tap.py

G = os.environ.get('GEARDYN', 'geardyn')
SRC = os.environ.get('GEARDYN_SOURCE', '.')
SHORT = ['run.transient_periods=20', 'run.record_periods=10', 'output.plots=off']


def run(case, out, sets):
    args = [G, 'run', os.path.join(SRC, case), '--out', out, '--quiet']
    for s in sets:
        args += ['--set', s]
    p = subprocess.run(args, capture_output=True, text=True)
    return p.returncode, p.stderr.strip()


def tables(d):
    for root, _, names in os.walk(d):
        for n in sorted(names):
            if n.endswith('.csv'):
                p = os.path.join(root, n)
                rows = list(csv.reader(open(p)))
                yield os.path.relpath(p, d), rows[0], rows[1:]


RIGHT = re.compile(r'(^|_)R($|_)')


def one_mesh(what, case, sets):
    with tempfile.TemporaryDirectory() as tmp:
        d = os.path.join(tmp, 'out')
        rc, err = run(case, d, sets)
        ok(rc == 0, '%s: runs (%s)' % (what, err[-200:]))
        if rc:
            return
        for name, head, body in tables(d):
            right = [h for h in head if RIGHT.search(h)]
            nan = [h for i, h in enumerate(head) if h != 'error' and body and
                   all(i < len(r) and r[i].strip().lower() in ('nan', '-nan') for r in body)]
            ok(not right and not nan, '%s, %s: no right-mesh column (%s), none all NaN (%s)' % (what, name, right, nan))
        s = json.load(open(os.path.join(d, 'summary.json')))
        res = s['results']
        rights = [k for k, v in res.items() if isinstance(v, dict) and v.get('right', None) is not None]
        ok(not rights, '%s: summary.json has no right mesh (%s)' % (what, rights))


def two_meshes():
    with tempfile.TemporaryDirectory() as tmp:
        d = os.path.join(tmp, 'out')
        rc, err = run('cases/quickstart.ini', d, SHORT + ['excitation.half_phase_deg=90'])
        ok(rc == 0, 'two meshes: runs (%s)' % err[-200:])
        if rc:
            return
        th = list(csv.DictReader(open(os.path.join(d, 'time_history.csv'))))
        pc = list(csv.DictReader(open(os.path.join(d, 'poincare.csv'))))
        ok(all(c in th[0] for c in ('lambda_R_um', 'lambda_dot_R_mps', 'accel_R_mps2', 'dte_R_um', 'force_R_n'))
           and any(r['lambda_L_um'] != r['lambda_R_um'] for r in th), 'two meshes: time_history.csv has the right mesh')
        ok('lambda_R' in pc[0] and 'lambda_dot_R' in pc[0], 'two meshes: poincare.csv has the right mesh')
        res = json.load(open(os.path.join(d, 'summary.json')))['results']
        ok(res['rms_accel_mps2']['right'] > 0, 'two meshes: summary.json gives the right mesh')


def main():
    one_mesh('spur response', 'cases/guide/spur.ini', SHORT)
    one_mesh('helical response', 'cases/guide/helical.ini', SHORT)
    one_mesh('torsional response of a herringbone', 'cases/quickstart.ini', SHORT + ['scene.model=torsional'])
    one_mesh('spur sweep', 'cases/guide/spur-sweep.ini', SHORT + ['sweep.points=3'])
    one_mesh('torsional sweep of a herringbone', 'cases/paper/sweep-speed.ini',
             SHORT + ['scene.model=torsional', 'sweep.points=3', 'run.transient_max_periods=20'])
    one_mesh('continuation of a one-coordinate model', 'cases/continuation/kahraman-singh.ini',
             ['output.plots=off', 'continuation.to=2500', 'continuation.branch_switching=off'])
    two_meshes()
    return plan()


if __name__ == '__main__':
    sys.exit(main())
