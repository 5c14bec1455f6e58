#!/usr/bin/env python3
"""The envelope of Kahraman & Singh's oscillator (docs/continuation.md section 8, "Cost"): every curve
the one-parameter branch at F_a 0.1 starts in the plane Omega 0.5 to 1.5, F_a 0.01 to 0.3
(cases/continuation/kahraman-singh-curves.ini with parameter2 from 0.1 to 3 um: folds, period
doublings and grazings, each followed both ways, through the cusp), best of the repeats: the CPU
time of the whole run (the process, getrusage of the child), the run's own cpu_s and curve_cpu_s
(summary.json), curves, points, corrections. The target is under 5 s CPU. With "map", the brute-force
regime map of the same plane in the same run: a sweep (both directions) of 101 x 101 points, each
boundary placed to 1 % of each range, its CPU time once.

  bench_envelope.py GEARDYN SOURCE [repeats] [map]

Not a test: it times runs.
"""
import json
import os
import resource
import subprocess
import sys
import tempfile

RPM_PER_OMEGA = 3183.0988618379


def run(geardyn, args, out):
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([geardyn, 'run'] + args + ['--out', out, '--quiet', '--set', 'output.plots=off'], check=True,
                   stdout=subprocess.DEVNULL)
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(out, 'summary.json')) as f:
        return r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime, json.load(f)


def main(argv):
    geardyn, src = argv[1], argv[2]
    repeats = int(argv[3]) if len(argv) > 3 else 3
    case = os.path.join(src, 'cases', 'continuation', 'kahraman-singh-curves.ini')
    box = ['--set', 'continuation.parameter2_from=0.1', '--set', 'continuation.parameter2_to=3']
    best = None
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(repeats):
            cpu, s = run(geardyn, [case] + box, os.path.join(tmp, 'env%d' % i))
            if best is None or cpu < best[0]:
                best = (cpu, s)
        cpu, s = best
        r = s['results']
        curves = r.get('curves', [])
        points = sum(c.get('points', 0) for c in curves)
        print('envelope of Kahraman & Singh, Omega 0.5-1.5 x F_a 0.01-0.3: %d curves, %d points, %d curve corrections; '
              'CPU %.3f s (summary.json: cpu_s %.3f, curve_cpu_s %.3f; best of %d); target < 5 s: %s'
              % (len(curves), points, r['curve_corrections'], cpu, r['cpu_s'], r['curve_cpu_s'], repeats,
                 'met' if cpu < 5.0 else 'NOT met'))
        for c in curves:
            print('  %-16s %-4s %3d points: %s' % (c.get('kind'), c.get('direction'), c.get('points', 0), c.get('end')))
        if 'map' in argv[3:]:
            cpu_m, m = run(geardyn, [case, '--set', 'scene.analysis=sweep', '--set', 'sweep.parameter=operating.speed_rpm',
                                     '--set', 'sweep.from=%.10f' % (0.5 * RPM_PER_OMEGA), '--set',
                                     'sweep.to=%.10f' % (1.5 * RPM_PER_OMEGA), '--set', 'sweep.points=101', '--set',
                                     'sweep.parameter2=excitation.ste_amplitude_um', '--set', 'sweep.from2=0.1', '--set',
                                     'sweep.to2=3', '--set', 'sweep.points2=101'], os.path.join(tmp, 'map'))
            print('the regime map of the same plane, 101 x 101 points both ways: CPU %.1f s, %.0f times the envelope'
                  % (cpu_m, cpu_m / cpu))
    return 0 if cpu < 5.0 else 1


if __name__ == '__main__':
    sys.exit(main(sys.argv))
