#!/usr/bin/env python3
"""Every picture of every shipped case read back from its SVG and judged as a figure in a report
(tests/cli/svgfig.py reads the SVG; the checks are below). Each shipped case runs once, as shipped
or shortened with --set where it is long (the table SHORTEN says how; the shortenings keep what
the pictures show); the variants (VARIANTS) add the pictures no shipped case draws as written: a
regime map, TCA and LTCA of single pairs, other response variables, the paper's 25-point speed
sweep (its resonance off the Poincare panel's scale), a continuation with a sweep over it, curves over a
regime map and beside another case's curves.

The checks of every picture:
  frame     no drawn point on or beyond a panel's frame, unless a curve ends there because its
            range ends there (a time history over its own window), an impulse stands on its
            axis, or a map's cell fills to the range's end;
  span      the curves and markers of a panel span at least half of its x axis (the first start to the last end);
  band      no time series so dense (turning every 3 px or less) that it draws a solid band;
  units     every axis label names its quantity (two words at least) and ends in a unit, "(unit)",
            that the run's tables name (their column suffixes, summary.json's units) or is a
            count; "(-)" only for a dimensionless quantity;
  words     no key name, no underscore, no "lambda" spelt out, no number of an equation, figure
            or table of a paper the picture does not name, no "1 points", no word repeated in
            parentheses ("chaotic (chaotic)"), no value missing (": -") or without its unit;
            on a single pair no halves (left, right, half, λL);
  key       a legend covers no drawn point; every entry's series draws something a reader sees
            (more than a stub of 12 px, not all under plots drawn later); no legend of three or
            more entries repeated in several panels;
  texts     no two texts overlap, an axis title 0.6 of a character clear of its ticks; no key or
            label text runs over a frame;
  ticks     tick labels at round values (a step of 1, 2, 2.5 or 5 times a power of ten, every
            value a multiple of it; or 1, 2, 5 times the powers of ten on a log axis);
  colour    no line or marker too light for white (contrast below 1.7: yellow); the series of a
            panel, and the colours of a categorical key, told apart by colour (for colour-blind
            eyes too: CIE76 difference of at least 12 under protanopia and deuteranopia) or by
            dash or marker;
  type      no text smaller than 9 px; panels at least 280 x 160 px; no two panels of a picture
            with the same title; no empty slot in a grid of panels;
and the checks of a kind: response.png's spectrum shows its largest component with room to its
right and its phase portrait is a curve, not a polygon; time_history.png and phase.png draw
output.response_variable as response.png does; bifurcation.png draws every row of
bifurcation.csv and its Poincare panel is not squashed by one column; regime_map.png's axes stay
inside the swept ranges, its key names the classes that occur and its exponent's colour scale is
set by the bulk of the cells; gte.png of a pair whose GTE is round-off says so and draws it flat;
contact_pattern.png draws a path, not a scatter; continuation.png's markers each of their own
shape (a sweep's points are not bifurcations) and every row of bifurcations.csv drawn as a marker
of its kind (branch points too), a marker of lines or an outline drawn over one of another kind
(a branch point on its fold) 1.4 times its size so that both show; the optimiser comparison draws no overlapping
translucent bands; curves.png over a regime map names in its key exactly the map's classes of motion, every
region it names lies on cells of that motion's colour, and an earlier run's curves beside them are drawn
with their key entry.

The SVG is drawn with the PNG's font size in pixels (src/plot/figure.h), so its layout is the PNG's.

  test_pictures.py                 (GEARDYN names the executable, GEARDYN_SOURCE the source tree)
  test_pictures.py --keep DIR      runs and keeps the outputs in DIR
  test_pictures.py --check DIR     checks the pictures of outputs kept in DIR (no run)
  test_pictures.py --subset        one run per kind of picture (the sanitizer build of the suite:
                                   its memory checks are the same on every case)
TAP; python3 standard library.
"""
import csv
import glob
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import svgfig  # noqa: E402

# ---- the runs: every shipped case (cases/**/*.ini), shortened where long -------------------------
# (glob of the case, --set assignments, why). First match wins; a case without a match runs as
# shipped. The shortenings keep the motion each picture shows (a sweep's bands, a chaotic
# attractor) while cutting transients, windows, points and budgets.
SHORTEN = [
    # work-precision: three families (and their root-finding-off twins; all eight in one scene, so
    # that their colours and markers are told apart), rtol to 1e-6, RK4 and the order study to 64
    # steps a period, a short transient and window
    ('cases/accuracy/stiff-supports.ini', ['workprecision.families=rk4,erk4,dirk3', 'workprecision.rtol_tightest=1e-6',
                                           'workprecision.rk4_steps_max=64', 'workprecision.order_steps_max=64',
                                           'workprecision.repeats=1', 'workprecision.horizon_periods=5',
                                           'run.transient_periods=100', 'run.record_periods=10']),
    ('cases/accuracy/period1-7000rpm.ini', ['workprecision.families=rk4,erk2,erk3,erk4,erk5,erk6,erk7,erk8',
                                            'workprecision.rtol_tightest=1e-6',
                                            'workprecision.rk4_steps_max=64', 'workprecision.order_steps_max=64',
                                            'workprecision.repeats=1', 'workprecision.horizon_periods=5',
                                            'run.transient_periods=100', 'run.record_periods=10']),
    ('cases/accuracy/*.ini', ['workprecision.families=rk4,erk4,erk8', 'workprecision.rtol_tightest=1e-6',
                              'workprecision.rk4_steps_max=64', 'workprecision.order_steps_max=64',
                              'workprecision.repeats=1', 'workprecision.horizon_periods=5',
                              'run.transient_periods=100', 'run.record_periods=10']),
    # sweeps: 6 points up and down, 100 (up to 300 while the section converges) + 30 periods
    ('cases/paper/sweep-*.ini', ['sweep.points=6', 'run.transient_periods=100', 'run.transient_max_periods=300',
                                 'run.record_periods=30', 'run.lyapunov_exponents=0']),
    ('cases/guide/spur-sweep.ini', ['sweep.points=8', 'run.record_periods=40']),
    # local analyses: 300 (to 600) + 100 periods
    ('cases/paper/local-*.ini', ['run.transient_periods=300', 'run.transient_max_periods=600',
                                 'run.record_periods=100']),
    ('cases/quickstart.ini', ['run.transient_periods=300', 'run.record_periods=100']),
    ('cases/guide/herringbone.ini', ['run.transient_periods=300', 'run.record_periods=100']),
    # optimisation: 3 iterations of 10 ants, coarse LTCA
    ('cases/paper/optimize-alo.ini', ['optimize.iterations=3', 'optimize.population=10',
                                      'solver.ltca_positions_per_cycle=8', 'solver.ltca_face_slices=7']),
    # the dynamic objective (620 evaluations of three LTCAs and continuations): 2 iterations of 4 ants
    ('cases/paper/optimize-dynamic.ini', ['optimize.iterations=2', 'optimize.population=4']),
    ('cases/paper/compare-optimizers.ini', ['optimize.runs=2', 'optimize.budget_evals=40', 'optimize.population=10',
                                            'solver.ltca_positions_per_cycle=8', 'solver.ltca_face_slices=7']),
    ('cases/optimize/compare-test-functions.ini', ['optimize.dimension=6', 'optimize.runs=2',
                                                   'optimize.budget_evals=500']),
    # the paper's pair's curves: the backlash plane of the unmodified pair whole (its three Neimark-Sacker
    # points' curves among them; 35 s of CPU, the modified pair's nine 80 s); the torque plane (an LTCA at
    # every new torque: minutes whole) around the two bearing grazings at 3496 and 3510 rpm, 400-600 N m
    ('cases/continuation/paper-curves-backlash.ini', ['modification.apply=off']),
    ('cases/continuation/paper-curves-torque.ini', ['continuation.from=3300', 'continuation.to=3700',
                                                    'continuation.parameter2_from=400',
                                                    'continuation.parameter2_to=600']),
    # two objectives on the gear: 8 evaluations of 4 ants, coarse LTCA
    ('cases/paper/pareto-lte-dynamic.ini', ['optimize.iterations=1', 'optimize.population=4',
                                            'solver.ltca_positions_per_cycle=8', 'solver.ltca_face_slices=7']),
    # the two-objective optimisers on the gear: 2 runs of 8 evaluations, 2 subproblems, coarse LTCA
    ('cases/paper/compare-two-objectives-gear.ini', ['optimize.runs=2', 'optimize.budget_evals=8',
                                                     'optimize.population=4', 'optimize.scalar_grid=2',
                                                     'solver.ltca_positions_per_cycle=8',
                                                     'solver.ltca_face_slices=7']),
    # the NASA Glenn spur pair: the sweep every 1000 rpm with 40 recorded periods; the continuation
    # without the sweep its case names in results/ (the variant nasa-overlay draws it over)
    ('cases/guide/nasa-grc-spur-sweep.ini', ['sweep.points=15', 'run.record_periods=40']),
    ('cases/guide/nasa-grc-spur-continuation.ini', ['continuation.overlay_sweep=']),
    # basins: a coarser picture and smaller samples, five values of the parameter
    ('cases/basins/ks-hysteresis.ini', ['basins.resolution=60', 'basins.samples=300']),
    ('cases/basins/ks-fractions.ini', ['basins.points=5', 'basins.samples=200']),
    ('cases/basins/paper-4750rpm.ini', ['basins.resolution=12', 'basins.samples=40']),
]

# variants: pictures no shipped case draws as written: (name, case, --set, a run before it whose
# output directory, WORK/NAME-before, its --set may name as {before})
VARIANTS = [
    ('ks-overlay', 'cases/continuation/kahraman-singh.ini',
     ['continuation.response=rms_accel', 'continuation.overlay_sweep={before}'],
     ('cases/continuation/kahraman-singh.ini', ['scene.analysis=sweep', 'sweep.parameter=operating.speed_rpm',
                                                'sweep.from=1600', 'sweep.to=4700', 'sweep.points=24',
                                                'output.plots=off'])),
    ('speed-sweep-25', 'cases/paper/sweep-speed.ini',
     ['run.transient_periods=100', 'run.transient_max_periods=300', 'run.record_periods=30', 'run.lyapunov_exponents=0'],
     None),
    ('regime-map', 'cases/paper/sweep-speed.ini',
     ['sweep.from=3000', 'sweep.to=5500', 'sweep.points=5', 'sweep.parameter2=clearance.backlash_um', 'sweep.from2=0',
      'sweep.to2=40', 'sweep.points2=3', 'sweep.direction=up', 'run.transient_periods=100',
      'run.transient_max_periods=200', 'run.record_periods=30'], None),
    ('spur-tca', 'cases/guide/spur.ini', ['scene.analysis=tca'], None),
    ('helical-tca', 'cases/guide/helical.ini', ['scene.analysis=tca'], None),
    ('spur-ltca', 'cases/guide/spur.ini', ['scene.analysis=ltca', 'solver.ltca_positions_per_cycle=16'], None),
    ('herringbone-y1L', 'cases/quickstart.ini', ['run.transient_periods=300', 'run.record_periods=60',
                                                 'output.response_variable=y1L'], None),
    ('spur-dte', 'cases/guide/spur.ini', ['output.response_variable=dte_L'], None),
    # a continuation with branch points, and bifurcations located only to a bracket (the NASA Glenn
    # spur rig pair in the bta model, as tests/cli/test_continuation_cli.sh runs it)
    ('spur-branch-points', 'cases/guide/spur.ini',
     ['scene.analysis=continuation', 'scene.model=bta', 'scene.title=', 'gear.normal_module_mm=3.175',
      'gear.teeth_pinion=28', 'gear.teeth_gear=28', 'gear.profile_shift_pinion=0', 'gear.profile_shift_gear=0',
      'gear.face_width_pinion_mm=6.35', 'gear.face_width_gear_mm=6.35', 'gear.bore_diameter_pinion_mm=0',
      'gear.bore_diameter_gear_mm=0', 'operating.speed_rpm=5000', 'operating.torque_nm=72',
      'clearance.backlash_um=127', 'excitation.stiffness=harmonic', 'excitation.ste_amplitude_um=10',
      'continuation.parameter=operating.speed_rpm', 'continuation.from=2000', 'continuation.to=16000',
      'continuation.branch_switching=off'], None),
    ('nasa-overlay', 'cases/guide/nasa-grc-spur-continuation.ini', ['continuation.overlay_sweep={before}'],
     ('cases/guide/nasa-grc-spur-sweep.ini', ['sweep.points=15', 'run.record_periods=40', 'output.plots=off'])),
    # the basins with the continuation's orbits marked (basins.png) and its branches (fractions.png)
    ('ks-basins-continuation', 'cases/basins/ks-hysteresis.ini',
     ['basins.resolution=60', 'basins.samples=300', 'basins.continuation={before}'],
     ('cases/continuation/kahraman-singh.ini', ['output.plots=off'])),
    ('ks-fractions-continuation', 'cases/basins/ks-fractions.ini',
     ['basins.points=5', 'basins.samples=200', 'basins.continuation={before}'],
     ('cases/continuation/kahraman-singh.ini', ['output.plots=off'])),
    # curves that stay in the lower half of their box (F_a to 10 um; the period-doubling curve reaches
    # 5.2): the frame follows the curves
    ('ks-curves-tall-box', 'cases/continuation/kahraman-singh-curves.ini',
     ['continuation.parameter2_to=10', 'continuation.curve_kinds=grazing, period-doubling'], None),
    # the curves in (Omega, F_a) over a coarse regime map of the same plane ({before}), beside the
    # curves at another mesh damping ({before2}: the case before a modification)
    ('ks-curves-overlays', 'cases/continuation/kahraman-singh-curves.ini',
     ['continuation.overlay_map={before}', 'continuation.overlay_curves={before2}'],
     [('cases/continuation/kahraman-singh-curves.ini',
       ['scene.analysis=sweep', 'sweep.parameter=operating.speed_rpm', 'sweep.from=1591.5494309189',
        'sweep.to=4774.6482927569', 'sweep.points=11', 'sweep.parameter2=excitation.ste_amplitude_um',
        'sweep.from2=0.5', 'sweep.to2=2', 'sweep.points2=6', 'sweep.direction=both', 'run.lyapunov_exponents=0',
        'output.plots=off']),
      ('cases/continuation/kahraman-singh-curves.ini', ['damping.mesh_damping_ratio=0.07', 'output.plots=off'])]),
]

# the sanitizer build: one run per kind of picture
SUBSET = {'cases/quickstart.ini', 'cases/guide/spur.ini', 'cases/paper/sweep-speed.ini', 'cases/paper/tca-modified.ini',
          'cases/paper/ltca-modified.ini', 'cases/paper/optimize-alo.ini', 'cases/optimize/compare-test-functions.ini',
          'cases/accuracy/period1-7000rpm.ini', 'cases/continuation/paper-speed.ini', 'regime-map', 'spur-tca',
          'ks-basins-continuation', 'ks-fractions-continuation'}


def runs(src):
    out = []
    for path in sorted(glob.glob(os.path.join(src, 'cases', '**', '*.ini'), recursive=True)):
        rel = os.path.relpath(path, src)
        sets = []
        for pat, s in SHORTEN:
            if glob.fnmatch.fnmatch(rel, pat):
                sets = s
                break
        out.append((rel, rel, sets, None))
    for name, case, sets, before in VARIANTS:
        out.append((name, case, sets, before))
    return out


def out_name(name):
    return re.sub(r'[^A-Za-z0-9.-]+', '_', name.replace('cases/', '').replace('.ini', ''))


def run_one(exe, src, work, item):
    name, case, sets, before = item
    out = os.path.join(work, out_name(name))
    pre = out + '-before'
    befores = before if isinstance(before, list) else [before] if before else []
    for i, b in enumerate(befores):   # {before}, {before2}, ...: WORK/NAME-before, WORK/NAME-before2
        args = [exe, 'run', os.path.join(src, b[0]), '--out', pre + (str(i + 1) if i else ''), '--quiet',
                '--threads', '1']
        for s in b[1]:
            args += ['--set', s]
        p = subprocess.run(args, cwd=work, stdin=subprocess.DEVNULL, capture_output=True, timeout=900)
        if p.returncode != 0:
            return name, case, out, p.returncode, p.stderr.decode('utf-8', 'replace')
    args = [exe, 'run', os.path.join(src, case), '--out', out, '--quiet', '--threads', '1']
    for s in sets:
        args += ['--set', s.replace('{before2}', pre + '2').replace('{before}', pre)]
    p = subprocess.run(args, cwd=work, stdin=subprocess.DEVNULL, capture_output=True, timeout=900)
    return name, case, out, p.returncode, p.stderr.decode('utf-8', 'replace')


# ---- what a run's tables call units ----------------------------------------------------------------

SUFFIX_UNITS = [  # column suffix -> the unit as a picture writes it (and its scaled forms)
    ('_n_per_mm', ['N/mm']), ('_n_per_m', ['N/m', 'N/µm', 'MN/m', 'N/mm']), ('_mps2', ['m/s²']),
    ('_mps', ['m/s', 'mm/s']), ('_um', ['µm', 'mm', 'nm']), ('_mm', ['mm', 'µm']), ('_s', ['s', 'ms', 'µs']),
    ('_hz', ['Hz', 'kHz']), ('_rpm', ['rpm']), ('_kw', ['kW', 'MW']), ('_nm', ['N m', 'kN m']),
    ('_n', ['N', 'kN']), ('_mpa', ['MPa', 'GPa']), ('_arcsec', ['arcsec', 'µrad']), ('_deg', ['deg', '°']),
    ('_per_period', ['per mesh period']), ('_per_s', ['1/s']), ('_kg', ['kg']), ('_bytes', ['bytes', 'MB']),
    ('_periods', ['mesh periods']), ('_relative', ['-']), ('_half_backlash', ['half backlashes']),
    ('_half_backlash_per_tau', ['half backlashes per τ']),
]
SUMMARY_UNITS = {'um': ['µm', 'mm'], 'mm': ['mm'], 'rpm': ['rpm'], 'kW': ['kW'], 'N m': ['N m'], 'N/m': ['N/m', 'N/µm'],
                 'deg': ['deg', '°'], 'per mesh period': ['per mesh period'], 'arcsec': ['arcsec'],
                 'm/s^2': ['m/s²'], 'GPa': ['GPa'], 'arcmin': ['arcmin'], '': ['-'],
                 'arcsec m/s^2': ['arcsec m/s²'], 'arcsec um': ['arcsec µm']}
# words of a quantity with a dimension: its label may not say "(-)"
DIMENSIONAL = re.compile(r'deflection|displacement|acceleration|speed|power|backlash|clearance|torque|stiffness|'
                         r'load|pressure|\btime\b|frequency|amplitude|transmission error|velocity|rate\b|'
                         r'force|roll length|face position|angle|separation', re.I)
COUNT = re.compile(r'evaluations|\bsteps\b|number of|\bruns\b|\bpoints\b|per mesh period$|\border\b', re.I)


def run_units(outdir):
    units = {'-'}
    for csv in glob.glob(os.path.join(outdir, '**', '*.csv'), recursive=True):
        try:
            head = open(csv, encoding='utf-8').readline().strip().split(',')
        except (OSError, UnicodeDecodeError):
            continue
        for col in head:
            for suf, us in SUFFIX_UNITS:
                if col.endswith(suf) or col == suf[1:]:
                    units.update(us)
                    break
            if col in ('mle', 'mle_per_period'):
                units.add('per mesh period')
    # the units summary.json gives its results (not the case's keys: those are not columns)
    def walk(o):
        if isinstance(o, dict):
            for k, v in o.items():
                if k == 'case':
                    continue
                if (k == 'unit' or k.endswith('_unit')) and isinstance(v, str):
                    if v.startswith('dimensionless: lengths over solver.characteristic_length_um'):
                        units.update(['-', 'µm'])     # the unit of the lengths is that length, in µm
                    else:
                        units.update(SUMMARY_UNITS.get(v, [v]))
                else:
                    walk(v)
        elif isinstance(o, list):
            for v in o:
                walk(v)
    for sj in glob.glob(os.path.join(outdir, '**', 'summary.json'), recursive=True):
        try:
            walk(json.load(open(sj, encoding='utf-8')))
        except (OSError, ValueError):
            continue
    return units


def key_names(exe):
    p = subprocess.run([exe, 'keys'], capture_output=True, text=True, timeout=60)
    keys = set()
    for line in p.stdout.splitlines():
        m = re.match(r'^([a-z_]+)\.([a-z0-9_]+):', line)
        if m:
            keys.add(m.group(1) + '.' + m.group(2))
            if '_' in m.group(2):
                keys.add(m.group(2))
    return keys


# ---- the checks ------------------------------------------------------------------------------------

def fmt(p):
    return '(%.0f, %.0f)' % p


def check_frame(fig, bad):
    for pn in fig.panels:
        f = pn.frame
        if f is None:
            continue
        for p in pn.plots:
            for e in p.elements:
                if e.kind == 'image':
                    pts = list(e.points())
                    if any(not f.contains(x, y, 1.0) for x, y in pts):
                        bad.append('an image beyond the frame %r' % f)
                    continue
                for pts, closed in e.subpaths:
                    n = len(pts)
                    # a curve drawn over its own range: it starts or ends on that edge of the frame
                    ends = [pts[0], pts[-1]] if n > 2 else []
                    own_l = any(abs(x - f.x0) <= 0.6 and f.y0 < y < f.y1 for x, y in ends)
                    own_r = any(abs(x - f.x1) <= 0.6 and f.y0 < y < f.y1 for x, y in ends)
                    for i, (x, y) in enumerate(pts):
                        if f.inside(x, y, 0.6):
                            continue
                        on_y_edge = abs(y - f.y0) <= 0.6 or abs(y - f.y1) <= 0.6
                        inside_loose = f.contains(x, y, 0.6)
                        if e.kind == 'fill' and inside_loose:
                            continue    # an area filled to its range's end (a map's cell)
                        if e.kind == 'path' and inside_loose and not on_y_edge and \
                                ((own_l and x - f.x0 <= 0.6) or (own_r and f.x1 - x <= 0.6)):
                            continue    # a curve drawn over its own range, near the range's end
                        if e.kind == 'path' and inside_loose and n == 2 and on_y_edge and \
                                abs(pts[0][0] - pts[1][0]) < 0.01 and abs(y - f.y1) <= 0.6 and i == 0:
                            continue    # an impulse standing on the bottom of its axis
                        bad.append('frame: a point of %s at %s on or beyond the frame %r%s' %
                                   (p.title or p.id, fmt((x, y)), f, ' (a marker)' if e.kind == 'use' else ''))
                        break
                    else:
                        continue
                    break
                else:
                    continue
                break


def is_work_precision(pn):
    """A panel of a work-precision diagram, whose points sit where the machine's CPU times put them."""
    t = pn.title.s if pn.title else ''
    return t.startswith('Error of ')


def check_span(fig, bad):
    for pn in fig.panels:
        f = pn.frame
        if f is None:
            continue
        xs, marks = [], []
        for p in pn.plots:
            for e in p.elements:
                if e.kind == 'use':   # the markers of the points drawn
                    inside = [x for x, y in e.points() if f.contains(x, y, 1)]
                    if inside:
                        marks.append((min(inside), max(inside)))
                    continue
                if e.kind != 'path':
                    continue
                for pts, _ in e.subpaths:
                    inside = [x for x, y in pts if f.contains(x, y, 1)]
                    if len(inside) >= 2 and max(inside) - min(inside) > 1:   # a curve, not an impulse
                        xs.append((min(inside), max(inside)))
        if not xs:   # a panel of points only (a Poincaré section, a map): not judged here
            continue
        xs += [m for m in marks if is_work_precision(pn)]
        # from the leftmost curve's start or marker to the rightmost's end: the curves of a
        # work-precision panel cluster by CPU time, which the machine's load spreads, with gaps
        # between them, and a family of one point draws a marker and no curve
        cover = max(b for _, b in xs) - min(a for a, _ in xs)
        if cover < 0.5 * f.w:
            bad.append('span: the curves of panel %r span %.0f %% of its x axis' %
                       (pn.title.s if pn.title else pn.key, 100 * cover / f.w))


def check_units(fig, units, bad):
    for t in fig.axis_labels():
        s = t.s.strip()
        m = re.search(r'\(([^()]*)\)\s*$', s)
        if not m:
            if not COUNT.search(s):
                bad.append('units: the axis label %r has no unit' % s)
            continue
        u = m.group(1).strip()
        if len(s[:m.start()].split()) < 2:
            bad.append('units: %r does not say what quantity it is' % s)
        if u == '-':
            if DIMENSIONAL.search(s[:m.start()]) and not re.match(r'(order|ratio|fraction|(relative )?error|dynamic '
                                                                    r'load factor)\b', s):
                bad.append('units: %r says "(-)" for a quantity with a dimension' % s)
            continue
        if u not in units and not COUNT.search(s):
            bad.append('units: the unit of %r is not one of the tables\' (%s)' % (s, ', '.join(sorted(units))))


WORDS = [
    (re.compile(r'_'), 'an underscore'),
    (re.compile(r'\blambda', re.I), '"lambda" spelt out'),
    (re.compile(r'\b(Eq|Eqs|Fig|Figs|Table)\.?\s*\d', re.I), 'the number of an equation, figure or table'),
    (re.compile(r'(?<![\d.,])\b1 (distinct )?(points|runs|periods|problems|branches|variables|evaluations)\b'),
     'a plural after 1'),
    (re.compile(r'\(\s*\)'), 'empty parentheses'),
    (re.compile(r'\b(\w[\w-]*) \(\1\)'), 'a word repeated in parentheses'),
    (re.compile(r':\s*-\s*$'), 'a value missing ("-")'),
    (re.compile(r'\bmean [-\u2212]?\d[\d.]*\s*\)'), 'a value without its unit'),
]


def check_words(fig, keys, single, bad):
    seen = set()
    for t in fig.texts:
        s = t.s
        if not s.strip() or s in seen:
            continue
        seen.add(s)
        for rx, what in WORDS:
            if rx.search(s):
                bad.append('words: %s in %r' % (what, s))
        for k in keys:
            if '.' in k and k in s:
                bad.append('words: the key name %s in %r' % (k, s))
                break
        if single and re.search(r'\b(left|right)\b|\bhalf\b|\bhalves\b|\u03bb[LR]\b', s, re.I):
            bad.append('words: a half of a single pair in %r' % s)


def key_box(p):
    b = None
    for t in p.key_texts:
        b = t.box if b is None else b.union(t.box)
    for e in p.key_samples:
        for x, y in e.points():
            bb = svgfig.Box(x - 3, y - 3, x + 3, y + 3)
            b = bb if b is None else b.union(bb)
    return b


def check_key(fig, bad):
    allplots = sorted(fig.plots.values(), key=lambda q: q.order)
    for pn in fig.panels:
        keyed = [p for p in pn.plots if p.key_texts]
        if not keyed:
            continue
        boxes = [key_box(p) for p in keyed]
        kb = boxes[0]
        for b in boxes[1:]:
            kb = kb.union(b)
        kb = kb.grow(1)
        # a legend covers no drawn point of any panel
        hit = None
        for q in allplots:
            for e in q.elements:
                if e.kind == 'image':
                    continue
                for pts, closed in e.subpaths:
                    if any(kb.inside(x, y) for x, y in pts):
                        hit = q
                    elif e.kind == 'path' and any(segment_hits(pts[i], pts[i + 1], kb) for i in range(len(pts) - 1)):
                        hit = q
                    if hit:
                        break
                if hit:
                    break
            if hit:
                break
        if hit:
            bad.append('key: the legend %r of panel %r covers data of %s' %
                       (kb, pn.title.s if pn.title else pn.key, hit.title or hit.id))
    # every entry draws something visible: data of its own, or (a shared legend) a plot of its
    # style elsewhere; and not all of it under later plots
    for p in allplots:
        if not p.key_texts:
            continue
        st = p.style()
        own = list(p.data_points())
        if not own:
            # a key-only entry (the key of plots drawn without one): the plots of its colour (and,
            # for a line, its dash) that draw
            colour = st[0] if st else None
            same = [q for q in allplots if q is not p and list(q.data_points()) and
                    (q.style() == st or any((e.colour == colour and (e.kind != 'path' or (e.dash or '') == st[1]))
                                            or e.fill == colour or colour in e.colours for e in q.elements))]
            if not same:
                bad.append('key: the entry %r draws nothing' % p.key_texts[0].s)
                continue
            series = same
        else:
            # its plot and (a key shared by panels) the plots of its style elsewhere
            series = [p] + [q for q in allplots if q is not p and not q.key_texts and q.style() == st and
                            list(q.data_points())]
        # what the series draws: more than a few pixels, and not all under plots drawn after it
        pts = [xy for q in series for xy in q.data_points()]
        xs, ys = [x for x, _ in pts], [y for _, y in pts]
        marker = any(e.kind in ('use', 'fill', 'image') for q in series for e in q.elements)
        if not marker and math.hypot(max(xs) - min(xs), max(ys) - min(ys)) < 12:
            bad.append('key: the entry %r draws a stub of %.0f px, nothing a reader sees' %
                       (p.key_texts[0].s, math.hypot(max(xs) - min(xs), max(ys) - min(ys))))
        elif all(hidden_under_later(q, allplots) for q in series):
            bad.append('key: the entry %r is hidden under other plots' % p.key_texts[0].s)
    # no legend repeated over the panels
    keys = {}
    for pn in fig.panels:
        entries = tuple(t.s for p in pn.plots for t in p.key_texts)
        if len(entries) >= 3:
            keys[entries] = keys.get(entries, 0) + 1
    for entries, n in keys.items():
        if n > 1:
            bad.append('key: the legend (%s, ...) repeated in %d panels' % (entries[0], n))


def hidden_under_later(p, allplots):
    """Whether every drawn point of plot p lies under a plot drawn after it at least as wide
    (a dashed line leaves what is under it visible)."""
    st = p.style()
    later = [q for q in allplots if q.order > p.order and q.style() != st]
    cells = {}
    for q in later:
        for e in q.elements:
            if e.kind == 'path' and e.dash:
                continue
            r = e.width / 2 if e.kind == 'path' else (getattr(e, 'size', 1) if e.kind == 'use' else 0)
            for pts, _ in e.subpaths:
                for i in range(len(pts)):
                    (x0, y0) = pts[i]
                    (x1, y1) = pts[i + 1] if i + 1 < len(pts) and e.kind == 'path' else pts[i]
                    steps = max(1, int(math.hypot(x1 - x0, y1 - y0)))
                    for k in range(steps + 1):
                        c = (int(x0 + (x1 - x0) * k / steps), int(y0 + (y1 - y0) * k / steps))
                        if cells.get(c, -1) < r:
                            cells[c] = r
    mine = []
    for e in p.elements:
        r = e.width / 2 if e.kind == 'path' else (getattr(e, 'size', 1) if e.kind == 'use' else 0)
        mine += [((int(x), int(y)), r) for x, y in e.points()]
    return bool(cells) and bool(mine) and all(cells.get(c, -1) >= r - 0.25 for c, r in mine)


def segment_hits(a, b, box):
    return svgfig.segment_hits_box(a, b, box)


def check_texts(fig, bad):
    ts = [t for t in fig.texts if t.s.strip()]
    found = 0
    for i in range(len(ts)):
        for j in range(i + 1, len(ts)):
            a, b = ts[i], ts[j]
            # an axis title keeps 0.6 of a character clear of the tick labels beside it
            gap = 0.3 * a.size if (a.rotated and b.role == 'tick') or (b.rotated and a.role == 'tick') else 0
            if a.box.grow(gap).overlaps(b.box.grow(gap), shrink=0.3):
                if a.s == b.s and abs(a.x - b.x) < 0.5 and abs(a.y - b.y) < 0.5:
                    continue   # drawn twice at the same place (a key redrawn opaque)
                bad.append('texts: %r and %r overlap' % (a, b))
                found += 1
                if found > 3:
                    return


def check_texts_frames(fig, bad):
    """A text (a key's, a label's) that runs over a frame other than its own axes' labels."""
    for t in fig.texts:
        if not t.s.strip() or t.role in ('tick', 'axis', 'title'):
            continue
        for pn in fig.panels:
            f = pn.frame
            if f is None:
                continue
            b = t.box.grow(-0.5)
            crosses = (b.x0 < f.x0 < b.x1 or b.x0 < f.x1 < b.x1) and b.y1 > f.y0 and b.y0 < f.y1 or \
                      (b.y0 < f.y0 < b.y1 or b.y0 < f.y1 < b.y1) and b.x1 > f.x0 and b.x0 < f.x1
            if crosses:
                bad.append('texts: %r runs over the frame %r' % (t, f))
                return


def check_texts_inside(fig, bad):
    """Every text inside the picture (a key broken into columns ran off its right edge)."""
    for t in fig.texts:
        b = t.box.grow(-0.5)
        if t.s.strip() and fig.width > 0 and (b.x0 < 0 or b.y0 < 0 or b.x1 > fig.width or b.y1 > fig.height):
            bad.append('texts: %r runs off the picture (%g x %g)' % (t, fig.width, fig.height))
            return


def round_step(d):
    m = d / 10 ** math.floor(math.log10(d))
    return any(abs(m - r) < 1e-6 * r for r in (1, 2, 2.5, 5, 10))


def check_ticks(fig, bad):
    """Tick labels at round values: a round step (1, 2, 2.5 or 5 times a power of ten) and every
    value a multiple of it; or powers of ten (a log axis)."""
    for pn in fig.panels:
        for side, ts in pn.ticks.items():
            vals = sorted({t.number for t in ts if t.number is not None})
            if len(vals) < 2:
                continue
            if all(v > 0 and abs(math.log10(v) - round(math.log10(v))) < 1e-9 for v in vals):
                continue
            mant = lambda v: v / 10 ** math.floor(math.log10(v) + 1e-12)
            if all(v > 0 and any(abs(mant(v) - m) < 1e-6 for m in (1, 2, 2.5, 5)) for v in vals):
                continue    # 1, 2, 5 times the powers of ten: a log axis over a decade or two
            steps = [b - a for a, b in zip(vals, vals[1:])]
            d = min(steps)
            ok = d > 0 and round_step(d) and all(abs(v / d - round(v / d)) < 1e-6 for v in vals)
            if not ok:
                bad.append('ticks: %s tick labels %s are not at round values' %
                           (side, ', '.join(t.s.strip() for t in ts[:4])))


def significant_digits(s):
    return svgfig.significant_digits(s)


def check_colour(fig, bad):
    for p in fig.plots.values():
        for e in p.elements + p.key_samples:
            c = e.colour if e.kind in ('path', 'use') else None
            if c and e.kind == 'path' and e.width < 0.4:
                continue
            if c == (255, 255, 255) and e.kind == 'use':
                continue    # a white disc under a marker (errorbars): it erases, it is not a colour
            if c and svgfig.contrast_on_white(c) < 1.7:
                bad.append('colour: %s drawn in rgb%r, too light on white (contrast %.2f)' %
                           (p.title or (p.key_texts[0].s if p.key_texts else p.id), c, svgfig.contrast_on_white(c)))
                break
    for pn in fig.panels:
        keyed = [p for p in pn.plots if p.key_texts and p.look()]
        for i in range(len(keyed)):
            for j in range(i + 1, len(keyed)):
                (ca, da, ma), (cb, db, mb) = keyed[i].look(), keyed[j].look()
                if da != db or ma != mb or ca is None or cb is None:
                    continue
                de = svgfig.delta_e(ca, cb)
                if de < 12:
                    bad.append('colour: %r and %r differ only by colours too close for colour-blind eyes (%.1f)' %
                               (keyed[i].key_texts[0].s, keyed[j].key_texts[0].s, de))


def check_type(fig, bad):
    small = [t for t in fig.texts if t.s.strip() and t.size < 9]
    if small:
        bad.append('type: text of %.1f px (%r)' % (small[0].size, small[0].s))
    titles = {}
    for pn in fig.panels:
        f = pn.frame
        if f is not None and (f.w < 280 or f.h < 160):
            bad.append('type: a panel of %.0f x %.0f px' % (f.w, f.h))
        if pn.title is not None and pn.title.s.strip():
            titles[pn.title.s] = titles.get(pn.title.s, 0) + 1
    for s, n in titles.items():
        if n > 1:
            bad.append('type: %d panels titled %r' % (n, s))


def check_band(fig, bad):
    """A time series drawn so dense that it is a band: its extremes closer than 3 px apart."""
    for pn in fig.panels:
        for p in pn.plots:
            for e in p.elements:
                if e.kind != 'path':
                    continue
                for pts, _ in e.subpaths:
                    if len(pts) < 200:
                        continue
                    xs = [x for x, _ in pts]
                    if any(b < a - 0.01 for a, b in zip(xs, xs[1:])):
                        continue        # not a time series
                    ext = [pts[i][0] for i in range(1, len(pts) - 1)
                           if (pts[i][1] - pts[i - 1][1]) * (pts[i + 1][1] - pts[i][1]) < 0]
                    if len(ext) > 20:
                        gap = (ext[-1] - ext[0]) / (len(ext) - 1)
                        if gap < 3:
                            bad.append('band: %s turns every %.1f px, a solid band' % (p.title or p.id, gap))
                            return


def clusters(vals, tol):
    out = []
    for v in sorted(vals):
        if out and v - out[-1][-1] <= tol:
            out[-1].append(v)
        else:
            out.append([v])
    return [sum(c) / len(c) for c in out]


def check_slots(fig, bad):
    """A grid of panels with a slot where nothing is drawn."""
    fr = [pn.frame for pn in fig.panels if pn.frame is not None]
    if len(fr) < 2:
        return
    w = max(f.w for f in fr)
    h = max(f.h for f in fr)
    cols = clusters([(f.x0 + f.x1) / 2 for f in fr], 0.4 * w)
    rows = clusters([(f.y0 + f.y1) / 2 for f in fr], 0.4 * h)
    if len(cols) * len(rows) <= len(fr):
        return
    for cx in cols:
        for cy in rows:
            if any(abs((f.x0 + f.x1) / 2 - cx) < 0.4 * w and abs((f.y0 + f.y1) / 2 - cy) < 0.4 * h for f in fr):
                continue
            slot = svgfig.Box(cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
            used = any(slot.contains(t.x, t.y) for t in fig.texts if t.s.strip())
            if not used:
                bad.append('slots: an empty panel slot at %r' % slot)


def check_swatches(fig, bad):
    """The colours of a categorical key (key boxes, or a stepped colour box) told apart."""
    cols = []
    for p in fig.plots.values():
        for e in p.key_samples:
            if e.kind == 'fill' and e.fill and e.fill not in cols:
                cols.append(e.fill)
    # a colour box of classes (a stepped one, of few colours): the fills outside every frame, one
    # box a column of them
    boxes = {}
    for e in fig.loose:
        if e.kind == 'fill' and e.fill and e.fill != (255, 255, 255):
            pts = list(e.points())
            if pts and not any(pn.frame and pn.frame.contains(*pts[0]) for pn in fig.panels):
                b = boxes.setdefault(round(min(x for x, _ in pts) / 5), [])
                if e.fill not in b:
                    b.append(e.fill)
    for b in boxes.values():
        if 2 <= len(b) <= 20:
            cols += [c for c in b if c not in cols]
    for i in range(len(cols)):
        for j in range(i + 1, len(cols)):
            de = svgfig.delta_e(cols[i], cols[j])
            if de < 12:
                bad.append('colour: key colours rgb%r and rgb%r too close for colour-blind eyes (%.1f)' %
                           (cols[i], cols[j], de))
                return


def check_path_scatter(fig, bad):
    """Markers meant as a path (in drawing order) that jump about: a scatter."""
    for pn in fig.panels:
        if pn.frame is None:
            continue
        diag = math.hypot(pn.frame.w, pn.frame.h)
        for p in pn.plots:
            pts = [q for e in p.elements if e.kind == 'use' for q in e.points()]
            if len(pts) < 10:
                continue
            d = sorted(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(pts, pts[1:]))
            if d[len(d) // 2] > 0.1 * diag:
                bad.append('path: the markers of %s jump %.0f px a step (median): a scatter, not a path' %
                           (p.title or p.id, d[len(d) // 2]))


# ---- the checks of a kind ---------------------------------------------------------------------------

def panel_by_label(fig, rx):
    for pn in fig.panels:
        for t in (pn.title, pn.xlabel, pn.ylabel):
            if t is not None and re.search(rx, t.s, re.I):
                return pn
    return None


def check_response(fig, bad):
    spec = panel_by_label(fig, r'spectrum')
    if spec and spec.frame:
        f = spec.frame
        best, top = None, 1e18
        for p in spec.plots:
            for e in p.elements:
                for pts, _ in e.subpaths:
                    for x, y in pts:
                        if y < top:
                            best, top = (x, y), y
        if best and best[0] > f.x1 - 0.04 * f.w:
            bad.append('spectrum: its largest component at x = %.0f, at the right end of the axis %r' % (best[0], f))
    phase = panel_by_label(fig, r'phase portrait')
    if phase:
        turns = []
        for p in phase.plots:
            for e in p.elements:
                if e.kind != 'path':
                    continue
                for pts, _ in e.subpaths:
                    for i in range(1, len(pts) - 1):
                        ax, ay = pts[i][0] - pts[i - 1][0], pts[i][1] - pts[i - 1][1]
                        bx, by = pts[i + 1][0] - pts[i][0], pts[i + 1][1] - pts[i][1]
                        if math.hypot(ax, ay) > 1.5 and math.hypot(bx, by) > 1.5:
                            turns.append(abs(math.degrees(math.atan2(ax * by - ay * bx, ax * bx + ay * by))))
        if len(turns) > 20:
            turns.sort()
            med = turns[len(turns) // 2]
            if med > 20:
                bad.append('phase portrait: a polygon, %.0f degrees a vertex (median)' % med)


def ylabel_of(fig, rx):
    pn = panel_by_label(fig, rx)
    return pn.ylabel.s if pn and pn.ylabel else None


def check_bifurcation(fig, bad):
    pn = fig.panels[0] if fig.panels else None
    if pn is None or pn.frame is None:
        return
    cols = {}
    for p in pn.plots:
        for x, y in p.data_points():
            cols.setdefault(round(x), []).append(y)
    if len(cols) < 4:
        return
    ys = sorted((min(v), max(v), k) for k, v in cols.items())
    extent = lambda skip: (max(b for a, b, k in ys if k != skip) - min(a for a, b, k in ys if k != skip))
    worst = min(extent(k) for _, _, k in ys)
    if worst < 0.3 * pn.frame.h and extent(None) > 0.8 * pn.frame.h:
        bad.append('bifurcation: one column squashes the others into %.0f %% of the panel\'s height' %
                   (100 * worst / pn.frame.h))


def check_bifurcation_points(fig, outdir, bad):
    """Every row of bifurcation.csv drawn once in the top panel (inside the axis, or as the marker of
    a value beyond it)."""
    import csv
    try:
        rows = list(csv.reader(open(os.path.join(outdir, 'bifurcation.csv'), encoding='utf-8')))
    except OSError:
        return
    if len(rows) < 2 or len(rows[0]) < 3:
        return
    col = 3 if rows[0][2] == 'parameter2' else 2
    n = 0
    for r in rows[1:]:
        try:
            n += math.isfinite(float(r[col]))
        except (ValueError, IndexError):
            pass
    pn = fig.panels[0] if fig.panels else None
    if pn is None:
        return
    drawn = sum(1 for p in pn.plots for e in p.elements if e.kind == 'use' for _ in e.points())
    if drawn != n:
        bad.append('bifurcation: %d Poincaré points drawn of the %d in bifurcation.csv' % (drawn, n))


def check_regime_map(fig, summary, bad):
    sw = summary.get('sweep', {}) if summary else {}
    axes = [sw.get('parameter') or {}, sw.get('parameter2') or {}]
    for pn in fig.panels:
        for side, a in (('bottom', axes[0]), ('left', axes[1])):
            lo, hi = a.get('from'), a.get('to')
            if lo is None or hi is None:
                continue
            lo, hi = min(lo, hi), max(lo, hi)
            for t in pn.ticks[side]:
                if t.number is not None and not (lo - 1e-9 * abs(hi - lo) <= t.number <= hi + 1e-9 * abs(hi - lo)):
                    bad.append('regime map: the %s axis reaches %s outside the swept %g .. %g' %
                               (side, t.s.strip(), lo, hi))
                    break
    classes = set()
    res = summary.get('results', {}) if summary else {}
    for k in (res.get('motion_counts') or {}):
        classes.add(k)
    names = [t.s for pn in fig.panels for t in pn.ticks['right'] + [x for x in fig.texts if x.role == 'other']]
    listed = [s for s in names if re.search(r'period|chaotic|quasi|not periodic|failed|P\d', s)]
    if classes and len(set(listed)) > len(classes):
        bad.append('regime map: %d classes listed where %d occur' % (len(set(listed)), len(classes)))


def check_mle_scale(fig, outdir, bad):
    """The exponent's colour scale of a regime map set by the bulk of the cells, not by a few:
    its end (read off the colour box and its ticks) at most 1.5 times the 90th percentile of the
    exponent's magnitude over the points (sweep.csv)."""
    try:
        import csv
        vals = sorted(abs(float(r['mle'])) for r in csv.DictReader(open(os.path.join(outdir, 'sweep.csv')))
                      if r.get('mle') not in (None, '', 'nan', 'NaN'))
    except (OSError, ValueError, KeyError):
        return
    if len(vals) < 5:
        return
    p90 = vals[int(0.9 * (len(vals) - 1))]
    # the continuous colour box: a column of many colours outside the frames
    cols = {}
    for e in fig.loose:
        if e.kind == 'fill' and e.fill:
            pts = list(e.points())
            if pts and not any(pn.frame and pn.frame.contains(*pts[0]) for pn in fig.panels):
                cols.setdefault(round(min(x for x, _ in pts) / 5), []).append(e)
    for es in cols.values():
        if len({e.fill for e in es}) <= 20:
            continue
        pts = [q for e in es for q in e.points()]
        x1 = max(x for x, _ in pts)
        y0, y1 = min(y for _, y in pts), max(y for _, y in pts)
        ticks = [t for t in fig.texts if t.number is not None and x1 <= t.x <= x1 + 60 and y0 - 5 <= t.y <= y1 + 10]
        if len(ticks) < 2 or p90 <= 0:
            continue
        a, b = ticks[0], ticks[-1]
        if abs(b.y - a.y) < 1:
            continue
        slope = (b.number - a.number) / (b.y - a.y)
        # a tick label's baseline sits a third of the font below its value's position
        end = max(abs(a.number + slope * (y - (a.y - 0.32 * a.size))) for y in (y0, y1))
        if end > 1.5 * p90:
            bad.append('regime map: the colour scale of the exponent reaches %.3g, %.1f times the 90th percentile '
                       '%.3g of its magnitude: a few cells set it' % (end, end / p90, p90))


def check_flat(fig, bad):
    for pn in fig.panels:
        for side in ('left', 'right'):
            vals = sorted(t.number for t in pn.ticks[side] if t.number is not None)
            if len(vals) >= 2:
                step = min(b - a for a, b in zip(vals, vals[1:]))
                if 0 < step < 1e-6:
                    title = pn.title.s if pn.title else ''
                    bad.append('round-off: ticks %g apart on the %s axis of %r' % (step, side, title))


# the shapes of gnuplot's markers (an open and a filled one alike)
SHAPES = {'gpPt0': 'plus', 'gpPt1': 'cross', 'gpPt2': 'star', 'gpPt3': 'square', 'gpPt4': 'square',
          'gpPt5': 'circle', 'gpPt6': 'circle', 'gpPt7': 'triangle up', 'gpPt8': 'triangle up',
          'gpPt9': 'triangle down', 'gpPt10': 'triangle down', 'gpPt11': 'diamond', 'gpPt12': 'diamond',
          'gpPt13': 'pentagon', 'gpPt14': 'pentagon'}


def check_continuation(fig, bad):
    """Every kind of marker in the key of its own shape (a sweep's points are not bifurcations)."""
    marks = {}
    for p in fig.plots.values():
        for e in p.key_samples:
            if e.kind == 'use' and p.key_texts:
                shape = e.marker.split('@')[0]
                marks.setdefault(SHAPES.get(shape, shape), []).append(p.key_texts[0].s)
    for k, v in marks.items():
        if len(v) > 1:
            bad.append('continuation: %s drawn with the same shape of marker (%s)' % (' and '.join(repr(s) for s in v), k))


LINE_SHAPES = {'gpPt0', 'gpPt1', 'gpPt2'}
OPEN_SHAPES = {'gpPt3', 'gpPt5', 'gpPt7', 'gpPt9', 'gpPt11', 'gpPt13'}


def check_coincident_markers(fig, bad):
    """Two bifurcations of different kinds on one point (a branch point on its fold) both visible:
    a marker drawn in lines (plus, cross, star) or as an outline over another is at least 1.4 times
    its size (black lines on a black marker of the same size vanish; two filled shapes of different
    outline both show at their edges)."""
    marks = []
    for p in fig.plots.values():
        if not (p.key_texts and re.search(r'\([A-Z]+\)$', p.key_texts[0].s)):
            continue
        for e in p.elements:
            if e.kind == 'use':
                shape, _, scale = e.marker.partition('@')
                for x, y in e.points():
                    marks.append((p.order, p.key_texts[0].s, shape, float(scale or 1), x, y))
    for a in marks:
        for b in marks:
            if b[0] <= a[0] or a[1] == b[1] or math.hypot(a[4] - b[4], a[5] - b[5]) > 3:
                continue
            if b[2] in LINE_SHAPES | OPEN_SHAPES and b[3] < 1.4 * a[3]:
                bad.append('continuation: %r at (%.0f, %.0f) hides %r under it' % (b[1], b[4], b[5], a[1]))


BIF_MARKS = {'fold': 'F', 'period-doubling': 'PD', 'neimark-sacker': 'NS', 'contact-change': 'C', 'branch-point': 'BP'}


def check_continuation_points(fig, outdir, bad):
    """Every row of bifurcations.csv drawn, as a marker of its kind's key entry ('... (BP)')."""
    try:
        rows = list(csv.DictReader(open(os.path.join(outdir, 'bifurcations.csv'), encoding='utf-8')))
    except OSError:
        return
    want = {}
    for r in rows:
        want[r['kind']] = want.get(r['kind'], 0) + 1
    for kind, n in want.items():
        mark = BIF_MARKS.get(kind)
        plots = [p for p in fig.plots.values() if p.key_texts and p.key_texts[0].s.endswith('(%s)' % mark)]
        drawn = sum(1 for p in plots for e in p.elements if e.kind == 'use' for _ in e.points())
        if drawn != n:
            bad.append('continuation: %d %s in bifurcations.csv, %d drawn' % (n, kind, drawn))


def check_bands(fig, bad):
    for pn in fig.panels:
        fills = []
        for p in pn.plots:
            for e in p.elements:
                if e.kind == 'fill' and e.opacity < 1:
                    pts = list(e.points())
                    xs, ys = [x for x, _ in pts], [y for _, y in pts]
                    fills.append((p, svgfig.Box(min(xs), min(ys), max(xs), max(ys))))
        over = 0
        for i in range(len(fills)):
            for j in range(i + 1, len(fills)):
                if fills[i][0] is not fills[j][0] and fills[i][1].overlaps(fills[j][1], 2):
                    over += 1
        if over:
            bad.append('bands: %d pairs of translucent bands overlap in panel %r' %
                       (over, pn.title.s if pn.title else pn.key))
            return


REGIMES = ['in contact', 'single-sided', 'double-sided']
REGION_RGB = [(0xEE, 0xEE, 0xEE), (0xC6, 0xDF, 0xF4), (0xFB, 0xE6, 0xA8), (0xC4, 0xC4, 0xC4), (0x86, 0xB6, 0xE3),
              (0xE8, 0xBE, 0x5A)]
REGION_WORD = {'no-impact': 'in contact', 'single-sided': 'single-sided', 'double-sided': 'double-sided'}


def region_colour(name):
    """The background colour of a motion named in a region's label: 'single-sided, period 2'."""
    regime, _, motion = name.partition(', ')
    return REGION_RGB[REGIMES.index(regime) + (3 if motion else 0)]


def check_curves_overlays(fig, outdir, summary, bad):
    """curves.svg over a regime map (continuation.overlay_map): the key names every class of motion
    the map's cells have, and only those; every region named inside the frame lies on cells of its
    motion's colour (a name 'A or B': the cells split between the sweeps up and down); with
    continuation.overlay_curves, the earlier run's curves are drawn and the key says where that run
    differs."""
    cont = summary.get('case', {}).get('parameters', {}).get('continuation', {})
    mp = (cont.get('overlay_map') or {}).get('value') or ''
    oc = (cont.get('overlay_curves') or {}).get('value') or ''
    keytexts = [t.s for p in fig.plots.values() for t in p.key_texts]
    if mp:
        d = mp if os.path.isabs(mp) else os.path.join(os.path.dirname(outdir), mp)
        want = set()
        for r in csv.DictReader(open(os.path.join(d, 'sweep.csv'), encoding='utf-8')):
            if r['status'] == 'done' and r['impact_regime'] in REGION_WORD:
                want.add('%s, %s' % (REGION_WORD[r['impact_regime']],
                                     'period 1' if r['motion'] == 'period-1' else 'other motion'))
        got = {t for t in keytexts if re.match(r'^(in contact|single-sided|double-sided), ', t)}
        if got != want:
            bad.append('overlay: the key names the motions %s, the map has %s' % (sorted(got), sorted(want)))
        fills = [(e.fill, list(e.points())) for p in fig.plots.values() for e in p.elements
                 if e.kind == 'fill' and e.fill]
        rx = re.compile(r'^(in contact|single-sided|double-sided)(, [a-z0-9 -]+?)?( or (in contact|single-sided|'
                        r'double-sided)(, [a-z0-9 -]+?)?)?$')
        frame = fig.panels[0].frame if fig.panels else None
        named = [t for t in fig.texts if frame and frame.contains(t.x, t.y) and rx.match(t.s)]
        if not named:
            bad.append('overlay: no region of the map named inside the frame')
        for t in named:
            colours = {region_colour(n) for n in t.s.split(' or ')}
            cx, cy = (t.box.x0 + t.box.x1) / 2, (t.box.y0 + t.box.y1) / 2
            under = [f for f, pts in fills if pts and min(x for x, _ in pts) <= cx <= max(x for x, _ in pts) and
                     min(y for _, y in pts) <= cy <= max(y for _, y in pts)]
            if not under or under[-1] not in colours:
                bad.append('overlay: the region named %r lies on rgb%r, not on its colour' %
                           (t.s, under[-1] if under else None))
    if oc:
        grey = [p for p in fig.plots.values() if any(t.s.startswith('thin grey: ') for t in p.key_texts)]
        drawn = [e for p in fig.plots.values() for e in p.elements if e.kind == 'path' and e.colour == (128, 128, 128)]
        if len(grey) != 1 or not drawn:
            bad.append('overlay: the earlier curves are %s, their key entry %s' %
                       ('drawn' if drawn else 'not drawn', 'found' if len(grey) == 1 else 'missing'))


def axis_map(ticks, attr):
    """The linear map from data to pixels along an axis, fitted through its numbered ticks."""
    pts = [(t.number, getattr(t, attr)) for t in ticks if t.number is not None]
    if len(pts) < 2:
        return None
    (a0, p0), (a1, p1) = min(pts), max(pts)
    if a1 == a0:
        return None
    return lambda v: p0 + (v - a0) * (p1 - p0) / (a1 - a0)


def check_curves_fill(fig, summary, bad):
    """curves.svg without a regime map: what is drawn (curves, their points, the starts) spans at least
    half the frame each way, even where the curves stay in a corner of the box (the frame then follows
    them, not the box)."""
    cont = summary.get('case', {}).get('parameters', {}).get('continuation', {})
    if (cont.get('overlay_map') or {}).get('value'):
        return
    panel = fig.panels[0] if fig.panels else None
    if panel is None or panel.frame is None:
        return
    f = panel.frame
    pts = [(x, y) for p in fig.plots.values() for x, y in p.data_points() if f.contains(x, y, 1.0)]
    if not pts:
        bad.append('curves: nothing drawn inside the frame')
        return
    wx = (max(x for x, _ in pts) - min(x for x, _ in pts)) / f.w
    wy = (max(y for _, y in pts) - min(y for _, y in pts)) / f.h
    if wx < 0.5 or wy < 0.5:
        bad.append('curves: the data span %.0f %% of the frame across and %.0f %% up (at least 50 %% each)'
                   % (100 * wx, 100 * wy))


def check_curves_regions(fig, outdir, summary, bad):
    """curves.svg without a regime map: every region of regions.csv marked drawn is named there,
    its words (one line, or two split as written) centred on its row's point (to 2 px in x and
    half a line in y), inside the frame, crossing no curve; and every region's name inside the
    frame is a row of regions.csv (no region named that the run did not name)."""
    cont = summary.get('case', {}).get('parameters', {}).get('continuation', {})
    if (cont.get('overlay_map') or {}).get('value'):
        return
    path = os.path.join(outdir, 'regions.csv')
    if not os.path.exists(path):
        bad.append('regions: no regions.csv beside curves.svg')
        return
    rows = list(csv.DictReader(open(path, encoding='utf-8')))
    res = summary.get('results', {})
    c1, c2 = res.get('parameter', '').split('.')[-1], res.get('parameter2', '').split('.')[-1]
    panel = fig.panels[0] if fig.panels else None
    if panel is None or panel.frame is None:
        bad.append('regions: no frame')
        return
    fx, fy = axis_map(panel.ticks['bottom'], 'x'), axis_map(panel.ticks['left'], 'y')
    if fx is None or fy is None:
        bad.append('regions: the axes have no numbered ticks')
        return
    words = re.compile(r'^(in contact|single-sided|double-sided)\b')
    inside = [t for t in fig.texts if panel.frame.contains(t.x, t.y) and not t.rotated]
    paths = [e for p in fig.plots.values() for e in p.elements if e.kind == 'path']
    used = set()
    for r in rows:
        if r['drawn'] == '0':
            continue
        x, y = fx(float(r[c1])), fy(float(r[c2]))
        label = r['label']
        near = [t for t in inside if abs((t.box.x0 + t.box.x1) / 2 - x) < 2.0 and abs(t.y - y) < 2.5 * t.size]
        lines = sorted(near, key=lambda t: t.y)
        text = ' '.join(t.s for t in lines)
        if text != label:
            bad.append('regions: %r not named at its point (%.0f, %.0f): %r there' % (label, x, y, text))
            continue
        used.update(id(t) for t in lines)
        top, bot = min(t.box.y0 for t in lines), max(t.box.y1 for t in lines)
        if not top < y < bot:
            bad.append('regions: %r drawn beside its point, not on it (%.0f to %.0f, the point %.0f)' %
                       (label, top, bot, y))
        for t in lines:
            if not all(panel.frame.contains(px, py) for px in (t.box.x0, t.box.x1) for py in (t.box.y0, t.box.y1)):
                bad.append('regions: %r runs over the frame' % label)
            for e in paths:
                for pts, _ in e.subpaths:
                    if any(segment_hits(pts[i], pts[i + 1], t.box) for i in range(len(pts) - 1)):
                        bad.append('regions: %r crosses a curve' % label)
                        break
    for t in inside:
        if words.match(t.s) and id(t) not in used:
            bad.append('regions: %r named inside the frame, not a region of regions.csv' % t.s)


def check_picture(path, outdir, keys, single, summary):
    fig = svgfig.Figure(path)
    bad = []
    check_frame(fig, bad)
    check_span(fig, bad)
    check_units(fig, run_units(outdir), bad)
    check_words(fig, keys, single, bad)
    check_key(fig, bad)
    check_texts(fig, bad)
    check_texts_frames(fig, bad)
    check_texts_inside(fig, bad)
    check_ticks(fig, bad)
    check_colour(fig, bad)
    check_type(fig, bad)
    check_band(fig, bad)
    check_slots(fig, bad)
    check_swatches(fig, bad)
    name = fig.name
    if name == 'response.svg':
        check_response(fig, bad)
    if name in ('time_history.svg', 'phase.svg'):
        resp = os.path.join(os.path.dirname(path), 'response.svg')
        if os.path.exists(resp):
            r = svgfig.Figure(resp)
            want = ylabel_of(r, r'time history')
            if name == 'time_history.svg':
                got = fig.panels[0].ylabel.s if fig.panels and fig.panels[0].ylabel else None
            else:
                got = fig.panels[0].xlabel.s if fig.panels and fig.panels[0].xlabel else None
            norm = lambda x: re.sub(r' of the (left|right) half', '', re.sub(r'(?<=[\u03bb\dq])[LR](?=\b|/| )', '',
                                                                                 x or ''))
            if want is not None and norm(got) != norm(want):
                bad.append('variable: %s draws %r, response.svg %r' % (name, got, want))
    if name == 'bifurcation.svg':
        check_bifurcation(fig, bad)
        check_bifurcation_points(fig, os.path.dirname(path), bad)
    if name == 'regime_map.svg':
        check_regime_map(fig, summary, bad)
        check_mle_scale(fig, os.path.dirname(path), bad)
    if name in ('gte.svg', 'lte.svg', 'contact_pattern.svg'):
        check_flat(fig, bad)
    if name == 'contact_pattern.svg':
        check_path_scatter(fig, bad)
    if name == 'continuation.svg':
        check_continuation(fig, bad)
        check_continuation_points(fig, os.path.dirname(path), bad)
        check_coincident_markers(fig, bad)
    if name in ('convergence.svg', 'ecdf.svg'):
        check_bands(fig, bad)
    if name == 'curves.svg':
        check_curves_overlays(fig, outdir, summary, bad)
        check_curves_regions(fig, outdir, summary, bad)
        check_curves_fill(fig, summary, bad)
    return bad


def single_pair(outdir):
    try:
        s = json.load(open(os.path.join(outdir, 'summary.json'), encoding='utf-8'))
    except (OSError, ValueError):
        return False, {}
    text = json.dumps(s)
    return bool(re.search(r'"arrangement":\s*"(spur|helical)"', text)), s


def main():
    exe = os.environ.get('GEARDYN', 'geardyn')
    src = os.environ.get('GEARDYN_SOURCE', os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
    args = sys.argv[1:]
    keep = check_only = None
    subset = '--subset' in args
    args = [a for a in args if a != '--subset']
    if args[:1] == ['--keep']:
        keep = os.path.abspath(args[1])
    elif args[:1] == ['--check']:
        check_only = os.path.abspath(args[1])
    if shutil.which('gnuplot') is None and not check_only:
        print('1..0 # SKIP gnuplot is not installed')
        return 0
    items = runs(src)
    if subset:
        items = [it for it in items if it[0] in SUBSET]
    work = check_only or keep or tempfile.mkdtemp(prefix='geardyn-pictures-')
    os.makedirs(work, exist_ok=True)
    # the shipped continuation case may name a sweep to overlay: the docs' directory layout
    results = []
    if check_only:
        for name, case, sets, before in items:
            results.append((name, case, os.path.join(work, out_name(name)), 0, ''))
    else:
        jobs = int(os.environ.get('GEARDYN_PICTURES_JOBS', '2'))
        with ThreadPoolExecutor(max_workers=jobs) as ex:
            results = list(ex.map(lambda it: run_one(exe, src, work, it), items))
    keys = key_names(exe) if not check_only or shutil.which(exe) or os.path.exists(exe) else set()
    lines = []
    failed = 0
    for name, case, out, rc, err in results:
        svgs = sorted(glob.glob(os.path.join(out, '**', '*.svg'), recursive=True))
        if os.path.basename(out).endswith('-before'):
            continue
        if rc != 0 or not svgs or 'pictures not drawn' in err:   # gnuplot refused a script: some not drawn
            lines.append((False, '%s: %s' % (name, 'exit %d: %s' % (rc, err[:300]) if rc else
                                             'no SVG drawn' if not svgs else err.strip()[:300])))
            continue
        single, summary = single_pair(out)
        for svg in svgs:
            sub = os.path.dirname(svg)
            s1, sm = single_pair(sub) if sub != out else (single, summary)
            bad = check_picture(svg, sub, keys, s1, sm)
            rel = os.path.relpath(svg, out)
            lines.append((not bad, '%s: %s%s' % (name, rel, '' if not bad else ': ' + '; '.join(bad[:6]) +
                                                  (' (and %d more)' % (len(bad) - 6) if len(bad) > 6 else ''))))
    print('1..%d' % len(lines))
    for i, (ok, text) in enumerate(lines, 1):
        failed += not ok
        print('%s %d - %s' % ('ok' if ok else 'not ok', i, text))
    if not keep and not check_only:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
