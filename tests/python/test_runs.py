"""Every analysis of the library's table (geardyn.analyses(): a row added later is tested here
without a line of its own) run from Python on a shipped case, shortened as scripts/compare-outputs.sh
shortens it, against the command line on the same case:

* in memory (geardyn.run(case)): the bytes of every file the run returns are those of the command
  line's files, but the times (compare-outputs.sh's JSON_SKIP and CSV_SKIP);
* with out (geardyn.run(case, out=DIR)): DIR holds the command line's files, byte for byte but the
  times, and geardyn.read(DIR) is the result run returned, every table bit for bit;
* geardyn.read of the command line's directory equals that result but the times.

The shipped case of an analysis is the one whose estimated cost (case.check()) is least, ties by
name; the pictures are off on both sides (test_pictures.py compares them)."""
import os

import pytest

import geardyn
from conftest import TIMES, cli_run, listing, load, same_file, shipped_cases, shortening


def _cases_by_analysis():
    by = {}
    for rel in shipped_cases():
        sets = shortening(rel) + [('output.plots', 'off')]
        c = load(rel if os.path.exists(rel) else os.path.join(os.environ['GEARDYN_SOURCE'], rel), sets)
        by.setdefault(c['scene.analysis'], []).append((c.check()['cost']['seconds'] or 0.0, rel, sets))
    return {a: sorted(v)[0][1:] for a, v in by.items()}


CHOSEN = _cases_by_analysis()


@pytest.mark.parametrize('analysis', list(geardyn.analyses()))
def test_same_as_command_line(analysis, work):
    assert analysis in CHOSEN, 'no shipped case runs the analysis %s (cases/ needs one)' % analysis
    rel, sets = CHOSEN[analysis]
    rc, _, err = cli_run(rel, sets, 'cli')
    assert rc == 0, err
    # in memory
    r = geardyn.run(load(rel, sets), threads=1)
    assert r.analysis == analysis and r.directory is None
    cli_files = listing('cli')
    assert set(r.raw) == {f for f in cli_files if not geardyn._result.is_picture(f)}
    for name, data in r.raw.items():
        with open(os.path.join('cli', name), 'rb') as f:
            assert same_file(name, data, f.read()), name
    # with out
    r2 = geardyn.run(load(rel, sets), out='py', threads=1)
    assert r2.directory == 'py' and listing('py') == cli_files
    for name in cli_files:
        with open(os.path.join('py', name), 'rb') as f, open(os.path.join('cli', name), 'rb') as g:
            mine = f.read()
            assert same_file(name, mine, g.read()), name
            assert mine == r2.raw[name], name   # what run returned is what it wrote
    assert geardyn.read('py') == r2
    assert geardyn.read('cli').equals(r2, ignore=TIMES)
    assert r.equals(r2, ignore=TIMES)
    assert r2.tables and all(t.dtype.names for t in r2.tables.values())
