#!/usr/bin/env python3
"""The SVG pictures name their data files by bare names: gnuplot writes the name of every plotted
data file into the SVG (the <title> of the data set), and the pictures are drawn in the run's
stage, so a picture must not name the stage or any absolute path. Runs a representative set of
shipped cases (one per kind of picture, shortened with --set) with an absolute --out (and the
TCA also with a relative one), then for every SVG of every run (subdirectories included: the
optimum/ and optimum-tca/ of an optimisation): each <title> that names a data file ('name' ...)
names a file without a directory, and the text holds neither the working directory, nor the
output directory, nor the name of a stage directory left behind. TAP; python3 standard library.

  test_svg_names.py            (GEARDYN names the executable, GEARDYN_SOURCE the source tree)
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

# case, --set assignments: every kind of picture (response, the local analysis's four panels,
# sweep, tca, ltca, optimize with optimum/ and optimum-tca/, compare, work-precision, continuation, basins)
CASES = [
    ('cases/quickstart.ini', ['run.transient_periods=50', 'run.record_periods=20']),
    ('cases/paper/local-speed-7000rpm.ini', ['run.transient_periods=100', 'run.transient_max_periods=100',
                                             'run.record_periods=40']),
    ('cases/paper/sweep-speed.ini', ['sweep.points=3', 'run.transient_periods=50', 'run.transient_max_periods=50',
                                     'run.record_periods=10']),
    ('cases/paper/tca-modified.ini', []),
    ('cases/paper/ltca-modified.ini', ['solver.ltca_positions_per_cycle=8', 'solver.ltca_face_slices=7']),
    ('cases/paper/optimize-alo.ini', ['optimize.iterations=1', 'optimize.population=4',
                                      'solver.ltca_positions_per_cycle=6', 'solver.ltca_face_slices=5']),
    ('cases/optimize/compare-test-functions.ini', ['optimize.dimension=6', 'optimize.runs=2',
                                                   'optimize.budget_evals=100', 'optimize.objective=sphere,rastrigin']),
    ('cases/optimize/pareto-zdt1.ini', ['optimize.iterations=5']),
    ('cases/accuracy/period1-7000rpm.ini', ['workprecision.families=rk4,erk4', 'workprecision.rtol_tightest=1e-5',
                                            'workprecision.rk4_steps_max=32', 'workprecision.order_steps_max=32',
                                            'workprecision.repeats=1', 'workprecision.horizon_periods=5',
                                            'run.transient_periods=50', 'run.record_periods=10']),
    ('cases/continuation/kahraman-singh.ini', []),
    ('cases/basins/ks-hysteresis.ini', ['basins.resolution=30', 'basins.samples=200']),
    ('cases/basins/ks-fractions.ini', ['basins.points=3', 'basins.samples=100']),
]

TITLE = re.compile(r'<title>(.*?)</title>', re.S)


def svgs(d):
    for root, _, files in os.walk(d):
        for n in sorted(files):
            if n.endswith('.svg'):
                yield os.path.join(root, n)


def problems(svg, forbidden):
    """What is wrong with one SVG: a data file named with a directory, or a forbidden text."""
    text = open(svg, encoding='utf-8', errors='replace').read()
    bad = []
    for t in TITLE.findall(text):
        m = re.match(r"\s*'([^']*)'", t)
        if m and '/' in m.group(1):
            bad.append('a data set titled %r' % t[:120])
    for f in forbidden:
        if f in text:
            bad.append('the text %r' % f)
    return bad, text.count('<title>')


def main():
    exe = os.environ['GEARDYN']
    src = os.environ.get('GEARDYN_SOURCE', os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
    if shutil.which('gnuplot') is None:
        print('1..0 # SKIP gnuplot is not installed')
        return 0
    work = tempfile.mkdtemp(prefix='geardyn-svg-')
    runs = [(c, s, os.path.join(work, 'abs', os.path.splitext(os.path.basename(c))[0])) for c, s in CASES]
    runs.append(('cases/paper/tca-modified.ini', [], os.path.join('rel', 'tca-modified')))
    print('1..%d' % len(runs))
    failed = 0
    for i, (case, sets, out) in enumerate(runs, 1):
        args = [exe, 'run', os.path.join(src, case), '--out', out, '--quiet', '--threads', '1']
        for s in sets:
            args += ['--set', s]
        p = subprocess.run(args, cwd=work, stdin=subprocess.DEVNULL, capture_output=True, timeout=240)
        outdir = os.path.join(work, out)
        names = list(svgs(outdir))
        # the output directory and the working directory as they could appear: absolute, as
        # given, and the stage directory geardyn used (any directory it left is a stage)
        forbidden = [work, os.path.realpath(work), out + '/', '.staging']
        bad = []
        for svg in names:
            b, _ = problems(svg, forbidden)
            bad += ['%s: %s' % (os.path.relpath(svg, outdir), x) for x in b]
        why = []
        if p.returncode != 0:
            why.append('exit %d: %s' % (p.returncode, p.stderr.decode('utf-8', 'replace')[:300]))
        if not names:
            why.append('no SVG drawn')
        why += bad[:4]
        ok = not why
        failed += not ok
        print('%s %d - %s: %d SVGs name their data files without a directory%s' %
              ('ok' if ok else 'not ok', i, case + (' (relative --out)' if not os.path.isabs(out) else ''),
               len(names), '' if ok else ': ' + '; '.join(why)))
    shutil.rmtree(work, ignore_errors=True)
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
