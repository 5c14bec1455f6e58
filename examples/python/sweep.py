#!/usr/bin/env python3
"""The paper's speed sweep (cases/paper/sweep-speed.ini) before and after the flank modification
([modification] apply off and on): two sweeps from Python, their sweep tables compared point by
point, and the RMS mesh acceleration against speed drawn for both (docs/python.md).

    PYTHONPATH=build/python python3 examples/python/sweep.py [POINTS] [PICTURE]

POINTS defaults to 9 (100 to 8000 rpm, upwards; 100 transient mesh periods extended up to 300
while the section settles, 20 recorded); PICTURE to sweep-python.png (with matplotlib)."""
import os
import sys

import numpy as np

import geardyn

HERE = os.path.dirname(os.path.abspath(__file__))
points = int(sys.argv[1]) if len(sys.argv) > 1 else 9
picture = sys.argv[2] if len(sys.argv) > 2 else 'sweep-python.png'

base = geardyn.Case.load(os.path.join(HERE, '..', '..', 'cases', 'paper', 'sweep-speed.ini'))
base.update({'sweep.points': points, 'sweep.direction': 'up', 'run.lyapunov_exponents': 0,
             'run.transient_periods': 100, 'run.transient_max_periods': 300, 'run.record_periods': 20})
sweeps = {}
for apply in (False, True):
    c = base.copy()
    c.set('modification.apply', apply)
    sweeps[apply] = geardyn.run(c)['sweep']

before, after = sweeps[False], sweeps[True]
speed = before['parameter']
assert np.array_equal(speed, after['parameter'])
print('%10s %14s %14s %8s   %s' % ('speed_rpm', 'before_mps2', 'after_mps2', 'ratio', 'motion before / after'))
for i in range(len(speed)):
    print('%10.6g %14.6g %14.6g %8.3f   %s / %s' % (speed[i], before['rms_accel_mps2'][i], after['rms_accel_mps2'][i],
                                                  after['rms_accel_mps2'][i] / before['rms_accel_mps2'][i],
                                                  before['motion'][i], after['motion'][i]))
print('peak_before_mps2 = %.6g' % before['rms_accel_mps2'].max())
print('peak_after_mps2 = %.6g' % after['rms_accel_mps2'].max())
print('points_lower_after = %d of %d' % (int(np.sum(after['rms_accel_mps2'] < before['rms_accel_mps2'])), len(speed)))

try:
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
except ImportError:
    print('# matplotlib is not installed: no picture (apt-get install python3-matplotlib)')
    sys.exit(0)
fig, a = plt.subplots(figsize=(9, 5))
a.plot(speed, before['rms_accel_mps2'], 'o-', label='before modification (apply = off)')
a.plot(speed, after['rms_accel_mps2'], 's-', label="after modification (the paper's Table 2)")
a.set(xlabel='input speed (rpm)', ylabel='RMS mesh acceleration (m/s$^2$)',
      title='%s\n%d points upwards, 20 recorded mesh periods each' % (base['scene.title'], points))
a.grid(alpha=0.3)
a.legend()
fig.tight_layout()
fig.savefig(picture, dpi=90)
print('picture = %s' % picture)
