#!/usr/bin/env python3
"""A response from Python and its four panels drawn from the arrays: the time history, the phase
portrait and the Poincare section of the response variable, and its spectrum, as geardyn run's
response.png shows them (docs/python.md, docs/guide.md section 14).

    PYTHONPATH=build/python python3 examples/python/response.py [CASE] [PICTURE]

CASE defaults to cases/guide/spur.ini (1500 rpm), run with 100 transient and 20 recorded mesh
periods; PICTURE to response-python.png (drawn only when matplotlib is installed)."""
import os
import sys

import numpy as np

import geardyn

HERE = os.path.dirname(os.path.abspath(__file__))
case_path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, '..', '..', 'cases', 'guide', 'spur.ini')
picture = sys.argv[2] if len(sys.argv) > 2 else 'response-python.png'

case = geardyn.Case.load(case_path)
case.update({'run.transient_periods': 100, 'run.record_periods': 20})
r = geardyn.run(case)

res = r.summary['results']
th = r['time_history']            # every sample of the recorded window
v = r['variable']                 # the response variable ([output] response_variable) and its rate
pc = r['variable_poincare']       # its values at every mesh period
sp = r['spectrum']                # its amplitude spectrum
name = r.summary['case']['parameters']['output']['response_variable']['value']
xcol, vcol = v.dtype.names[1], v.dtype.names[2]
mesh_hz = r.summary['derived']['model']['mesh_frequency_hz']

# the RMS mesh acceleration of the samples (printed to 9 digits) against the library's (all of them)
rms_samples = float(np.sqrt(np.mean(th['accel_L_mps2'] ** 2)))
k = 1 + int(np.argmax(sp['amplitude_um'][1:]))   # the largest line but the mean
print('case = %s' % case_path)
print('rms_accel_mps2 = %.9g' % res['rms_accel_mps2']['left'])
print('rms_accel_samples_mps2 = %.9g' % rms_samples)
print('motion = %s' % res['motion'])
print('samples = %d' % len(th))
print('poincare_points = %d' % len(pc))
print('largest_line_order = %.6g' % sp['order'][k])
print('largest_line_um = %.6g' % sp['amplitude_um'][k])

try:
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
except ImportError:
    print('# matplotlib is not installed: no picture (apt-get install python3-matplotlib)')
    sys.exit(0)

fig, ax = plt.subplots(2, 2, figsize=(12, 8.5))
mle = res['mle_per_period']
fig.suptitle('%s: %s, %s%s' % (name, res['motion'], res['impact_regime'],
                               ', largest Lyapunov exponent %.4g per mesh period' % mle if mle is not None else ''))
a = ax[0, 0]
a.plot(v['t_s'] * 1e3, v[xcol], lw=0.8, color='#9400d3')
a.set(xlabel='t (ms)', ylabel='%s (um)' % name, title='time history (last %d mesh periods)' % case['run.record_periods'])
a.set_xlim(v['t_s'][0] * 1e3, v['t_s'][-1] * 1e3)
a = ax[0, 1]
a.plot(v[xcol], v[vcol], lw=0.6, color='#4682b4')
a.plot(pc[pc.dtype.names[0]], pc[pc.dtype.names[1]], 'o', color='#d62728', ms=4)
a.set(xlabel='%s (um)' % name, ylabel='rate (m/s)', title='phase portrait')
a = ax[1, 0]
keep = (sp['order'] > 0) & (sp['order'] <= 10)
a.vlines(sp['order'][keep], 1e-300, sp['amplitude_um'][keep], lw=0.8, color='#9400d3')
a.set_yscale('log')
a.set_ylim(sp['amplitude_um'][keep].max() * 1e-6, sp['amplitude_um'][keep].max() * 4)
a.set(xlabel='order of the mesh frequency (%.4g Hz)' % mesh_hz, ylabel='amplitude (um)',
      title='amplitude spectrum (Hann window)')
a = ax[1, 1]
a.plot(pc[pc.dtype.names[0]], pc[pc.dtype.names[1]], 'o', color='#d62728', ms=4)
a.set_xlim(ax[0, 1].get_xlim())   # the phase portrait's window: a period-n orbit shows n points
a.set_ylim(ax[0, 1].get_ylim())
a.set(xlabel='%s (um)' % name, ylabel='rate (m/s)',
      title='Poincare section (%d distinct point%s)' % (res['poincare_distinct'], '' if res['poincare_distinct'] == 1 else 's'))
for a in ax.flat:
    a.grid(alpha=0.3, ls=':')
fig.tight_layout()
fig.savefig(picture, dpi=90)
print('picture = %s' % picture)
