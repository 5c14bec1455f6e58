#!/usr/bin/env python3
"""A continuation from Python: the periodic orbits of the Kahraman & Singh oscillator
(cases/continuation/kahraman-singh.ini) followed in speed, stable and unstable, with the
bifurcations located on them (docs/continuation.md), read from the branch and bifurcations
tables; the branches drawn with the bifurcations marked (docs/python.md).

    PYTHONPATH=build/python python3 examples/python/continuation.py [CASE] [PICTURE]

PICTURE defaults to continuation-python.png (with matplotlib)."""
import os
import sys

import numpy as np

import geardyn

HERE = os.path.dirname(os.path.abspath(__file__))
case_path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, '..', '..', 'cases', 'continuation',
                                                                  'kahraman-singh.ini')
picture = sys.argv[2] if len(sys.argv) > 2 else 'continuation-python.png'

r = geardyn.run(geardyn.Case.load(case_path))
branch, bif = r['branch'], r['bifurcations']
res = r.summary['results']
col = res['parameter'].split('.')[1]          # the continued key's column: speed_rpm
y = 'lambda_max_L_um'                        # the largest mesh deflection of the orbit

print('parameter = %s' % res['parameter'])
print('branches = %d' % len(res['branches']))
print('points = %d' % len(branch))
print('stable_points = %d' % int(np.sum(branch['stable'] == 1)))
for b in bif:
    print('bifurcation = branch %d, period-%d, %s at %s = %.9g %s' % (b['branch'], b['period_n'], b['kind'], col,
                                                                      b[col], res['unit']))

try:
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
except ImportError:
    print('# matplotlib is not installed: no picture (apt-get install python3-matplotlib)')
    sys.exit(0)
fig, a = plt.subplots(figsize=(11, 6))
colours = plt.get_cmap('tab10').colors
for k in np.unique(branch['branch']).astype(int):
    b = branch[branch['branch'] == k]
    c = colours[k % len(colours)]
    # each step between two points drawn solid when both ends are stable, dashed otherwise; the
    # runs of equal style share their end points, so that the line is unbroken
    step_stable = (b['stable'][:-1] == 1) & (b['stable'][1:] == 1)
    start = 0
    for i in range(1, len(step_stable) + 1):
        if i == len(step_stable) or step_stable[i] != step_stable[start]:
            a.plot(b[col][start:i + 1], b[y][start:i + 1], '-' if step_stable[start] else '--', color=c,
                   lw=1.8 if step_stable[start] else 1.0)
            start = i
    a.plot([], [], '-', color=c, label='branch %d: period-%d' % (k, int(b['period_n'][0])))
a.plot([], [], 'k-', lw=1.8, label='stable')
a.plot([], [], 'k--', lw=1.0, label='unstable')
marks = {'fold': ('s', '#d62728'), 'period-doubling': ('D', '#ff7f0e'), 'neimark-sacker': ('^', '#17becf'),
         'contact-change': ('o', '#7f7f7f'), 'branch-point': ('*', '#9467bd')}
for kind in np.unique(bif['kind']):
    b = bif[bif['kind'] == kind]
    m, c = marks.get(kind, ('x', 'k'))
    a.plot(b[col], b[y], m, color=c, ms=8, mfc='none', mew=1.6, ls='none', label=kind)
a.set(xlabel='%s (%s)' % (res['parameter'], res['unit']), ylabel='largest mesh deflection of the orbit (um)',
      title=r.summary['case']['parameters']['scene']['title']['value'])
a.grid(alpha=0.3)
a.legend(fontsize=9, loc='upper left', bbox_to_anchor=(1.01, 1.0))
fig.tight_layout()
fig.savefig(picture, dpi=90)
print('picture = %s' % picture)
