#!/usr/bin/env python3
"""The regions a continuation's curves picture names without a regime map (regions.csv,
docs/continuation.md section 8, "Regions named from the run") against an independent computation:
time integration. For each region of the Kahraman & Singh planes (cases/continuation/
kahraman-singh-curves.ini and kahraman-singh-cusp.ini) two sweeps of the response in the first
parameter at the region's value of the second, one up from the range's start and one down from its
end, each ending on the region's point, so that each follows the motion its side of any hysteresis
carries there: the set of motions the two find at that point (the period of the Poincare section
and the meshes' impact regime: in contact, single-sided, double-sided) must be exactly the set the
region names. The cases also have ranges of the first parameter the run leaves unnamed (beyond a
period doubling with no branch of the doubled orbit); none of them may be named. TAP; python3
standard library only.

  test_regions.py        (GEARDYN names the executable, GEARDYN_SOURCE the source tree)
"""
import csv
import os
import subprocess
import sys
import tempfile

from tap import ok, plan  # tests/cli/tap.py

G = os.environ.get('GEARDYN', 'geardyn')
SRC = os.environ.get('GEARDYN_SOURCE', '.')


def run(case, out, sets):
    args = [G, 'run', os.path.join(SRC, case), '--out', out, '--quiet', '--threads', '1']
    for s in sets:
        args += ['--set', s]
    p = subprocess.run(args, capture_output=True, text=True)
    return p.returncode, p.stderr.strip()


def sweep_end(case, out, key1, key2, y, frm, to, direction, x):
    """The motion a sweep in key1 at key2 = y, from frm to to in direction, finds at its last point
    (x): (period, impact regime), or None."""
    sets = ['scene.analysis=sweep', 'sweep.parameter=' + key1, 'sweep.from=%.10g' % frm, 'sweep.to=%.10g' % to,
            'sweep.points=25', 'sweep.direction=' + direction, '%s=%.10g' % (key2, y),
            'run.transient_periods=400', 'run.record_periods=64', 'run.lyapunov_exponents=0', 'output.plots=off']
    rc, err = run(case, out, sets)
    if rc != 0:
        print('# sweep failed: %s' % err[:300])
        return None
    rows = list(csv.DictReader(open(os.path.join(out, 'sweep.csv'), encoding='utf-8')))
    last = min(rows, key=lambda r: abs(float(r['parameter']) - x))
    if abs(float(last['parameter']) - x) > 1e-6 * abs(x):
        return None
    motion = last['motion']
    period = int(motion[len('period-'):]) if motion.startswith('period-') else 0
    return period, last['impact_regime']


def main():
    work = tempfile.mkdtemp(prefix='geardyn-regions-')
    cases = [('cases/continuation/kahraman-singh-curves.ini', 'curves', (3904.7, 4774.6)),
             ('cases/continuation/kahraman-singh-cusp.ini', 'cusp', None)]
    for case, name, unnamed in cases:
        out = os.path.join(work, name)
        rc, err = run(case, out, ['output.plots=off'])
        ok(rc == 0 and os.path.exists(os.path.join(out, 'regions.csv')), '%s: the run writes regions.csv (%s)' %
           (name, err[:200] or 'ok'))
        if rc != 0:
            continue
        rows = list(csv.DictReader(open(os.path.join(out, 'regions.csv'), encoding='utf-8')))
        hdr = list(rows[0].keys()) if rows else []
        key1, key2 = 'operating.speed_rpm', 'excitation.ste_amplitude_um'
        c1, c2 = key1.split('.')[1], key2.split('.')[1]
        ok(len(rows) >= 2 and hdr[:4] == ['region', 'label', c1, c2],
           '%s: %d regions named, columns %s' % (name, len(rows), ','.join(hdr[:11])))
        lo, hi = 1591.5494309189, 4774.6482927569
        if name == 'cusp':
            lo, hi = 2546.4790894703, 3819.7186342055
        for r in rows:
            x, y = float(r[c1]), float(r[c2])
            want = set()
            for o in r['orbits'].split(';'):
                per, regime = o.split(':')[:2]
                want.add((int(per), regime))
            got = set()
            for direction, frm, to in (('up', lo, x), ('down', x, hi)):
                m = sweep_end(case, os.path.join(work, '%s-%s-%s' % (name, r['region'], direction)), key1, key2, y,
                              frm, to, direction, x)
                if m is not None:
                    got.add(m)
            ok(got == want, '%s: region %s %r at %s = %.6g, %s = %.6g: the sweeps up and down find %s, the region '
               'names %s' % (name, r['region'], r['label'], c1, x, c2, y, sorted(got), sorted(want)))
        if unnamed:
            inside = [r for r in rows if unnamed[0] < float(r[c1]) < unnamed[1]]
            ok(not inside, '%s: %s %.6g to %.6g (beyond the period doubling: no branch of the doubled orbit) is '
               'not named (%s)' % (name, c1, unnamed[0], unnamed[1], [r['label'] for r in inside]))
    return plan()


if __name__ == '__main__':
    sys.exit(main())
