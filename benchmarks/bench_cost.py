#!/usr/bin/env python3
"""The estimated cost of a run (`geardyn check`: time and files) against the run itself, on every
shipped case (cases/**/*.ini): the CPU time of `geardyn run` (the process, its threads and its
gnuplot children) against the estimated CPU time, the wall time against the estimated wall time
(on an idle machine; a loaded one stretches it), and the bytes the run's directory holds against
the estimated bytes. The estimate should be within a factor of 3 of the CPU time and of the bytes
(docs/performance.md, "The cost estimate"); the wall time is reported with the load average.

  bench_cost.py GEARDYN SOURCE [--threads N] [--only SUBSTRING ...] [--skip SUBSTRING ...] [--json FILE]

Not a test: it times runs (minutes; compare-optimizers alone takes a quarter of an hour). Exit 1
when a case is off by more than the factor.
"""
import glob
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
import time

FACTOR = 3.0


def overlay(case):
    """A continuation that overlays a sweep's results runs without them (they are another case's)."""
    with open(case) as f:
        return ['--set', 'continuation.overlay_sweep='] if re.search(r'^overlay_sweep\s*=', f.read(), re.M) else []


def estimate(g, case):
    out = subprocess.run([g, 'check', case] + overlay(case), capture_output=True, text=True)
    if out.returncode != 0:
        return None
    est = {}
    for line in out.stdout.splitlines():
        m = re.match(r'time_class = (\S+(?: or more)?)\s+; about (\S+) s', line)
        if m:
            est['class'] = m.group(1)
            est['wall_s'] = float(m.group(2))
            cpu = re.search(r'\((\S+) s(?: \([^)]*\))? of CPU\)', line)
            est['cpu_s'] = float(cpu.group(1)) if cpu else est['wall_s']
        m = re.match(r'disk_bytes = (\S+)', line)
        if m:
            est['disk_bytes'] = float(m.group(1))
    return est


def du(d):
    total = 0
    for root, _, names in os.walk(d):
        for n in names:
            total += os.lstat(os.path.join(root, n)).st_size
    return total


def measure(g, case, out, threads):
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    args = [g, 'run', case, '--out', out, '--quiet'] + overlay(case)
    if threads:
        args += ['--threads', str(threads)]
    p = subprocess.run(args, capture_output=True, text=True)
    wall = time.monotonic() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    return p.returncode, wall, cpu, du(out), p.stderr.strip()[-300:]


def ratio(a, b):
    if not (a > 0 and b > 0):
        return float('inf') if a != b else 1.0
    return max(a / b, b / a)


def main(argv):
    g, src = argv[1], argv[2]
    threads, only, skip, jpath = 0, [], [], None
    i = 3
    while i < len(argv):
        if argv[i] == '--threads':
            threads = int(argv[i + 1]); i += 2
        elif argv[i] == '--only':
            only.append(argv[i + 1]); i += 2
        elif argv[i] == '--skip':
            skip.append(argv[i + 1]); i += 2
        elif argv[i] == '--json':
            jpath = argv[i + 1]; i += 2
        else:
            sys.exit('bench_cost.py: unknown argument %s' % argv[i])
    cases = sorted(glob.glob(os.path.join(src, 'cases', '*.ini')) + glob.glob(os.path.join(src, 'cases', '*', '*.ini')))
    cases = [c for c in cases if (not only or any(o in c for o in only)) and not any(s in c for s in skip)]
    tmp = tempfile.mkdtemp(prefix='geardyn-bench-cost-')
    rows, bad = [], 0
    print('load average at the start: %.1f %.1f %.1f' % os.getloadavg())
    print('%-40s %8s %8s %8s %8s %6s %10s %10s %6s' % ('case', 'est wall', 'wall', 'est CPU', 'CPU', 'x CPU',
                                                    'est bytes', 'bytes', 'x'))
    for case in cases:
        name = os.path.relpath(case, os.path.join(src, 'cases'))
        est = estimate(g, case)
        if est is None:
            print('%-40s check refused it' % name)
            bad += 1
            continue
        out = os.path.join(tmp, name.replace('/', '-')[:-4])
        rc, wall, cpu, size, err = measure(g, case, out, threads)
        subprocess.run(['rm', '-rf', out])
        if rc != 0:
            print('%-40s run failed (exit %d): %s' % (name, rc, err))
            bad += 1
            continue
        xt = ratio(est['cpu_s'], cpu)
        xd = ratio(est['disk_bytes'], size)
        off = xt > FACTOR or xd > FACTOR
        bad += off
        print('%-40s %8.3g %8.3g %8.3g %8.3g %6.2f %10.3g %10.3g %6.2f%s' % (name, est['wall_s'], wall, est['cpu_s'], cpu,
              xt, est['disk_bytes'], size, xd, '  OFF' if off else ''))
        sys.stdout.flush()
        rows.append({'case': name, 'estimate': est, 'wall_s': wall, 'cpu_s': cpu, 'bytes': size,
                     'cpu_factor': xt, 'disk_factor': xd, 'load': os.getloadavg()[0]})
    subprocess.run(['rm', '-rf', tmp])
    print('load average at the end: %.1f %.1f %.1f' % os.getloadavg())
    print('%d of %d cases within a factor of %g in CPU time and in bytes; largest factors %.2f and %.2f' % (
        len(rows) - sum(r['cpu_factor'] > FACTOR or r['disk_factor'] > FACTOR for r in rows), len(cases), FACTOR,
        max([r['cpu_factor'] for r in rows] or [0]), max([r['disk_factor'] for r in rows] or [0])))
    if jpath:
        with open(jpath, 'w') as f:
            json.dump(rows, f, indent=1)
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
