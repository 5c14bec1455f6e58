"""geardyn from Python: the nonlinear dynamics of gear pairs, through libgeardyn (docs/python.md).

    import geardyn
    case = geardyn.Case.load('cases/quickstart.ini')
    case.set('operating.speed_rpm', 3000)
    r = geardyn.run(case)                       # or geardyn.run(case, out='results/q')
    r.summary['results']['rms_accel_mps2']      # summary.json as a dict
    th = r['time_history']                      # a numpy structured array: th['t_s'], th['dte_L_um']

Every analysis of the library's table runs (geardyn.analyses()); geardyn.read(dir) opens a
finished run's directory into the same Result; geardyn.events(path, ...) reads an event log with
the filters of geardyn events; geardyn.keys() is the schema of the case keys."""
from . import _lib
from ._case import Case, Key, keys
from ._errors import CaseError, Error, Interrupted
from ._result import Result, events, parse_table, read
from ._run import openmp, run, set_threads, threads

__all__ = ['Case', 'CaseError', 'Error', 'Interrupted', 'Key', 'Result', 'analyses', 'events', 'keys',
           'library', 'openmp', 'parse_table', 'read', 'run', 'set_threads', 'threads']


def analyses():
    """The analyses of the library's table, {name: one line saying what it computes}, in the order
    of the schema's scene.analysis (every value that has a row)."""
    spec = _lib.lib.gd_case_find_key(b'scene', b'analysis').contents
    out = {}
    for i, name in enumerate(_lib.text(spec.choices).split('|')):
        row = _lib.lib.gd_analysis_find(i)
        if row:
            out[_lib.text(row.contents.name)] = _lib.text(row.contents.what)
    return out


def library():
    """The path of the libgeardyn this module uses."""
    return _lib.library_path()
