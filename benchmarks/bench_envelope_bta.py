#!/usr/bin/env python3
"""The envelope of the paper's pair (docs/continuation.md section 8, "The paper's pair"): every curve the
period-1 branch at 500 N m starts in the plane 3000 to 5500 rpm by 25 to 4800 N m (the paper's load range,
10 to 2000 kW at 4000 rpm; cases/continuation/paper-curves-torque.ini), its CPU time (the process,
getrusage of the child) against the regime map that places the same boundaries to 1 % of each range: a
sweep (both directions) of 101 x 101 points over the same plane. That map is timed on a coarse grid
(N1 x N2 points, both directions) and its CPU per point scaled to 101 x 101 points (each row's LTCA at
its torque is a small part of a row's CPU). The target is a tenth of the map's CPU.

The coarse map is also the brute-force check: every jump of the map (two neighbouring speeds of one
chain, up or down, at one torque, in different motion classes: period-n, quasi-periodic, chaotic,
not-periodic) must lie on a curve to within the map's grid spacing, i.e. some curve passes through the
rectangle of the two points widened by one grid spacing in speed and in torque. The jumps not on a curve
are listed with their classes.

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

S1, S2, T1, T2 = 3000.0, 5500.0, 25.0, 4800.0  # the plane: rpm, N m


def run(geardyn, args, out):
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([geardyn, 'run'] + args + ['--out', out, '--quiet', '--threads', '1', '--set', 'output.plots=off'],
                   check=True, stdout=subprocess.DEVNULL)
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(out, 'summary.json')) as f:
        return r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime, json.load(f)


def polylines(path):
    """the curves of curves.csv: {curve: (kind, [(speed, second key), ...])} (the second key: its 8th column)"""
    cv = {}
    rd = csv.DictReader(open(path))
    k2 = rd.fieldnames[7]
    for r in rd:
        cv.setdefault(r['curve'], (r['kind'] + ('' if r['clearance'] in ('', '-') else ' of ' + r['clearance']), []))
        cv[r['curve']][1].append((float(r['speed_rpm']), float(r[k2])))
    return cv


def through(poly, x0, x1, y0, y1):
    """whether the polyline passes through the rectangle [x0, x1] x [y0, y1]"""
    for (a, b), (c, d) in zip(poly, poly[1:] or poly):
        for k in range(101):
            x, y = a + (c - a) * k / 100, b + (d - b) * k / 100
            if x0 <= x <= x1 and y0 <= y <= y1:
                return True
    return False


def crosses(poly, x0, x1, y):
    """whether the polyline crosses the segment [x0, x1] x {y}"""
    for (a, b), (c, d) in zip(poly, poly[1:]):
        if (b - y) * (d - y) <= 0 and b != d:
            x = a + (c - a) * (y - b) / (d - b)
            if x0 <= x <= x1:
                return True
    return False


def check(curves_csv, sweep_csv):
    """every boundary of the map (sweep.csv of a regular grid) on a curve of curves.csv within one grid spacing"""
    cv = polylines(curves_csv)
    k2 = next(csv.reader(open(curves_csv)))[7]
    rows = list(csv.DictReader(open(sweep_csv)))
    g1 = sorted({float(x['parameter']) for x in rows})
    g2 = sorted({float(x['parameter2']) for x in rows})
    h1, h2 = (g1[-1] - g1[0]) / (len(g1) - 1), (g2[-1] - g2[0]) / (len(g2) - 1)
    chains = {}
    for x in rows:
        chains.setdefault((x['direction'], float(x['parameter2'])), []).append(x)
    def boundaries(key):
        n, strict, missed = 0, 0, []
        for (d, tq), ch in sorted(chains.items()):
            ch.sort(key=lambda x: float(x['parameter']))
            for a, b in zip(ch, ch[1:]):
                ka, kb = key(a), key(b)
                if ka == kb:
                    continue
                n += 1
                sa, sb = float(a['parameter']), float(b['parameter'])
                strict += any(crosses(poly, min(sa, sb), max(sa, sb), tq) for kind, poly in cv.values())
                if not any(through(poly, min(sa, sb) - h1, max(sa, sb) + h1, tq - h2, tq + h2)
                           for kind, poly in cv.values()):
                    missed.append('%s at %s = %.6g, %.0f rpm %s -> %.0f rpm %s' % (d, k2, tq, sa, ka, sb, kb))
        return n, strict, missed

    motion = lambda x: 'period-%s' % x['period_n'] if x['motion'].startswith('period') else x['motion']
    for what, key in (('jumps of the map (the motion class changes between neighbouring speeds of a chain)', motion),
                      ('changes of the mesh\'s impact regime (no-impact, single-, double-sided)',
                       lambda x: x['impact_regime'])):
        n, strict, missed = boundaries(key)
        print('%s: %d; a curve crosses the row between the two points: %d; a curve passes within one grid spacing '
              '(%.4g rpm, %.4g in %s) of them: %d' % (what, n, strict, h1, h2, k2, n - len(missed)))
        for m_ in missed:
            print('  not on a curve: ' + m_)


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
