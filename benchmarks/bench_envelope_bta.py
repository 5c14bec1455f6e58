#!/usr/bin/env python3
"""The envelope of the paper's pair (docs/continuation.md section 8, "The paper's pair"): every curve the
period-1 branch at 500 N m starts in the plane 3000 to 5500 rpm by 25 to 4800 N m (the paper's load range,
10 to 2000 kW at 4000 rpm; cases/continuation/paper-curves-torque.ini), its CPU time (the process,
getrusage of the child) against the regime map that places the same boundaries to 1 % of each range: a
sweep (both directions) of 101 x 101 points over the same plane. That map is timed on a coarse grid
(N1 x N2 points, both directions) and its CPU per point scaled to 101 x 101 points (each row's LTCA at
its torque is a small part of a row's CPU). The target is a tenth of the map's CPU.

The coarse map is also compared with the curves (tests/cli/envelope_jumps.py): every jump of the map (two
neighbouring speeds of one chain, up or down, at one torque, in different motion classes: period-n,
quasi-periodic, chaotic, not-periodic) is checked to lie on a curve to within the map's grid spacing, i.e.
some curve passes through the rectangle of the two points widened by one grid spacing in speed and in
torque. The jumps not on a curve are listed with their classes (the test of this on the (speed, backlash)
plane: tests/cli/test_envelope_bta.sh).

  bench_envelope_bta.py GEARDYN SOURCE [N1 N2] [modified|unmodified] [-- section.key=value ...]
  bench_envelope_bta.py --check CURVES.csv SWEEP.csv     (the comparison only, on finished runs)

Not a test: it times runs (tens of minutes of CPU).
"""
import csv
import json
import os
import resource
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tests', 'cli'))
import envelope_jumps  # noqa: E402  (the curves against the map's jumps, shared with tests/cli/test_envelope_bta.sh)

S1, S2, T1, T2 = 3000.0, 5500.0, 25.0, 4800.0  # the plane: rpm, N m


def run(geardyn, args, out):
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([geardyn, 'run'] + args + ['--out', out, '--quiet', '--threads', '1', '--set', 'output.plots=off'],
                   check=True, stdout=subprocess.DEVNULL)
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(out, 'summary.json')) as f:
        return r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime, json.load(f)


def check(curves_csv, sweep_csv):
    """every boundary of the map (sweep.csv of a regular grid) on a curve of curves.csv within one grid spacing"""
    k2 = next(csv.reader(open(curves_csv)))[7]
    for what, key in (('jumps of the map (the motion class changes between neighbouring speeds of a chain)',
                       envelope_jumps.motion),
                      ('changes of the mesh\'s impact regime (no-impact, single-, double-sided)',
                       lambda x: x['impact_regime'])):
        js, (h1, h2) = envelope_jumps.jumps(curves_csv, sweep_csv, key)
        missed = [j for j in js if not j['near']]
        print('%s: %d; a curve crosses the row between the two points: %d; a curve passes within one grid spacing '
              '(%.4g rpm, %.4g in %s) of them: %d' % (what, len(js), sum(j['crossed'] for j in js), h1, h2, k2,
                                                       len(js) - len(missed)))
        for j in missed:
            print('  not on a curve: %s at %s = %.6g, %.0f rpm %s -> %.0f rpm %s'
                  % (j['direction'], k2, j['p2'], j['p1a'], j['ka'], j['p1b'], j['kb']))


def main(argv):
    if argv[1] == '--check':  # the comparison only, on finished runs: --check CURVES.csv SWEEP.csv
        check(argv[2], argv[3])
        return 0
    geardyn, src = argv[1], argv[2]
    rest = argv[3:]
    extra = []  # after '--': section.key=value set on both runs (a quick look: -- continuation.curve_max_points=3)
    if '--' in rest:
        extra = [x for kv in rest[rest.index('--') + 1:] for x in ('--set', kv)]
        rest = rest[:rest.index('--')]
    variant = [a for a in rest if a in ('modified', 'unmodified')]
    nums = [int(a) for a in rest if a.isdigit()]
    n1, n2 = nums[:2] if len(nums) >= 2 else (11, 5)
    mod = (['--set', 'modification.apply=off'] if variant == ['unmodified'] else []) + extra
    case = os.path.join(src, 'cases', 'continuation', 'paper-curves-torque.ini')
    with tempfile.TemporaryDirectory() as tmp:
        cpu_e, s = run(geardyn, [case] + mod, os.path.join(tmp, 'env'))
        r = s['results']
        curves = r.get('curves', [])
        points = sum(c.get('points', 0) for c in curves)
        print('envelope of the paper\'s pair (%s), 3000-5500 rpm x 25-4800 N m: %d curves, %d points, %d curve '
              'corrections; CPU %.1f s (summary.json: cpu_s %.1f, curve_cpu_s %.1f)'
              % (variant[0] if variant else 'modified', len(curves), points, r['curve_corrections'], cpu_e, r['cpu_s'],
                 r['curve_cpu_s']))
        for c in curves:
            print('  %-28s %-4s %3d points: %s' % (c['kind'] + (' of ' + c['clearance'] if c.get('clearance') else ''),
                                                 c['direction'], c['points'], c['end']))
        mp = os.path.join(tmp, 'map')
        cpu_m, m = run(geardyn, [case] + mod + [
            '--set', 'scene.analysis=sweep', '--set', 'sweep.parameter=operating.speed_rpm',
            '--set', 'sweep.from=%g' % S1, '--set', 'sweep.to=%g' % S2, '--set', 'sweep.points=%d' % n1,
            '--set', 'sweep.parameter2=operating.torque_nm', '--set', 'sweep.from2=%g' % T1, '--set', 'sweep.to2=%g' % T2,
            '--set', 'sweep.points2=%d' % n2, '--set', 'sweep.mode=continuation', '--set', 'sweep.direction=both',
            '--set', 'run.transient_max_periods=3000', '--set', 'run.record_periods=100',
            '--set', 'run.lyapunov_exponents=0'], mp)
        full = cpu_m / (n1 * n2) * 101 * 101
        print('the regime map, %d x %d points both ways: CPU %.1f s, %.2f s per grid point; scaled to 101 x 101 '
              '(each boundary to 1 %% of each range): %.0f s; the envelope is %.3f of it (target < 0.1: %s)'
              % (n1, n2, cpu_m, cpu_m / (n1 * n2), full, cpu_e / full, 'met' if cpu_e < 0.1 * full else 'NOT met'))
        check(os.path.join(tmp, 'env', 'curves.csv'), os.path.join(mp, 'sweep.csv'))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
