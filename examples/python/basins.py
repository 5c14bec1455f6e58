#!/usr/bin/env python3
"""Basins of attraction from Python: the Kahraman & Singh oscillator at Omega 0.65
(cases/basins/ks-hysteresis.ini), where a single-sided impacting orbit and a no-impact orbit are
both stable (docs/basins.md): which one a start settles on, over the plane of the mesh deflection
and its velocity, read as a 2-D array (Result.grid) from basins.csv; each attractor's fraction of
random starts with its standard error and Wilson interval; the picture drawn with the attractors'
points on it (docs/python.md).

    PYTHONPATH=build/python python3 examples/python/basins.py [RESOLUTION] [PICTURE]

RESOLUTION (cells a side, default 80) shortens the picture; PICTURE defaults to basins-python.png
(with matplotlib)."""
import os
import sys

import numpy as np

import geardyn

HERE = os.path.dirname(os.path.abspath(__file__))
resolution = int(sys.argv[1]) if len(sys.argv) > 1 else 80
picture = sys.argv[2] if len(sys.argv) > 2 else 'basins-python.png'

case = geardyn.Case.load(os.path.join(HERE, '..', '..', 'cases', 'basins', 'ks-hysteresis.ini'))
case.set('basins.resolution', resolution)
case.set('basins.samples', 2000)
r = geardyn.run(case)
x, y, label = r.grid()                       # label[j, i]: the attractor's index, < 0 no attractor
xname, yname = r['basins'].dtype.names[2:4]
att = r['attractors']
pts = r['attractor_points']

print('cells = %d x %d' % (len(x), len(y)))
for a in att:
    k = int(a['index'])
    print('attractor = %d, %s, %s, fraction %.4f +- %.4f, wilson [%.4f, %.4f], picture cells %d'
          % (k, a['name'], a['impact_regime'], a['fraction'], a['standard_error'], a['wilson_lo'], a['wilson_hi'],
             int(np.sum(label == k))))
print('basin_entropy = %.6f' % r.summary['results']['picture']['basin_entropy']['S_b'])

try:
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap
except ImportError:
    print('# matplotlib is not installed: no picture (apt-get install python3-matplotlib)')
    sys.exit(0)
fig, ax = plt.subplots(figsize=(8, 7.5))
colours = ['#1f77b4', '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b']
n = max(len(att), 1)
shown = np.ma.masked_less(label, 0)          # cells of no attractor (diverged, ...) left white
ax.pcolormesh(x, y, shown, cmap=ListedColormap(colours[:n]), vmin=-0.5, vmax=n - 0.5, shading='nearest')
from matplotlib.patches import Patch
handles = []
for a in att:
    k = int(a['index'])
    c = colours[k % len(colours)]
    p = pts[pts['attractor'] == a['attractor']]
    # the attractor's points, white on its own basin's colour
    ax.plot(p[xname], p[yname], 'os^D'[k % 4], ms=10, mfc='white', mec='k', mew=1.6, ls='none')
    handles.append(Patch(color=c, label='basin of %s, %s: %.1f %% of starts' % (a['name'], a['impact_regime'],
                                                                              100 * a['fraction'])))
    handles.append(plt.Line2D([], [], marker='os^D'[k % 4], ms=9, mfc='white', mec='k', mew=1.6, ls='none',
                              label='its point on the section'))
ax.legend(handles=handles, fontsize=9, loc='upper center', bbox_to_anchor=(0.5, -0.1), ncol=2)
ax.set(xlabel=xname, ylabel=yname, title=r.summary['case']['parameters']['scene']['title']['value'])
fig.tight_layout()
fig.savefig(picture, dpi=90)
print('picture = %s' % picture)
