"""What the tests of the Python module share (tests/python/, docs/python.md): the command line
($GEARDYN) and the source tree ($GEARDYN_SOURCE) as the other tests name them, a working directory
holding a link `cases` to the shipped cases (so that the command line and the module give a case
the same relative path, which summary.json records), the shortening of each shipped case and the
times that may differ between two runs, both read from scripts/compare-outputs.sh (the one table
of them), and the comparison of two runs' files."""
import csv
import fnmatch
import glob
import hashlib
import io
import json
import os
import shlex
import subprocess

import pytest

import geardyn

GEARDYN = os.environ['GEARDYN']
SRC = os.environ['GEARDYN_SOURCE']


def _compare_outputs():
    with open(os.path.join(SRC, 'scripts', 'compare-outputs.sh')) as f:
        s = f.read()
    body = s[s.index('SHORTEN=(') + len('SHORTEN=('):]
    body = body[:body.index('\n)')]
    toks = shlex.split(body, comments=True)
    shorten = [(pat, [tuple(kv.split('=', 1)) for kv in sets.split()]) for pat, sets in zip(toks[0::2], toks[1::2])]

    def var(name):
        line = next(ln for ln in s.splitlines() if ln.startswith(name + '='))
        return set(shlex.split(line[len(name) + 1:])[0].split())
    return shorten, var('JSON_SKIP'), var('CSV_SKIP')


SHORTEN, JSON_SKIP, CSV_SKIP = _compare_outputs()
TIMES = JSON_SKIP | CSV_SKIP   # keys of summary.json and columns of the tables that hold times


def shipped_cases():
    """Every shipped case, as 'cases/...ini' relative to the source tree."""
    return sorted(os.path.relpath(p, SRC) for p in glob.glob(os.path.join(SRC, 'cases', '**', '*.ini'),
                                                               recursive=True))


def shortening(rel):
    """The --set pairs compare-outputs.sh runs the case rel with."""
    for pat, sets in SHORTEN:
        if fnmatch.fnmatch(rel, pat):
            return list(sets)
    return []


def load(rel, sets=()):
    c = geardyn.Case.load(rel)
    for k, v in sets:
        c.set(k, v)
    return c


def cli(args, cwd=None, **kw):
    """geardyn ARGS: (exit status, stdout, stderr)."""
    p = subprocess.run([GEARDYN] + list(args), cwd=cwd, capture_output=True, **kw)
    return p.returncode, p.stdout.decode('utf-8', 'replace'), p.stderr.decode('utf-8', 'replace')


def cli_run(rel, sets, out, threads=1, cwd=None):
    args = ['run', rel]
    for k, v in sets:
        args += ['--set', '%s=%s' % (k, v)]
    return cli(args + ['--out', out, '--quiet', '--threads', str(threads)], cwd=cwd)


def listing(root):
    out = set()
    for d, _, fs in os.walk(root):
        for f in fs:
            out.add(os.path.relpath(os.path.join(d, f), root))
    return out


def state(d):
    """sha256 of every file under d but its top-level '.'-names, and those names."""
    files, dots = {}, []
    if not os.path.isdir(d):
        return None, []
    for rel in listing(d):
        if rel.startswith('.'):
            if os.sep not in rel:
                dots.append(rel)
            continue
        with open(os.path.join(d, rel), 'rb') as f:
            files[rel] = hashlib.sha256(f.read()).hexdigest()
    return files, sorted(dots)


def beside(d):
    """What a run left beside d (its stage PARENT/.NAME.geardyn-stage)."""
    parent, name = os.path.split(os.path.abspath(d))
    return sorted(n for n in os.listdir(parent) if n.startswith('.' + name + '.'))


def _json_norm(b):
    def strip(o):
        if isinstance(o, dict):
            return [(k, strip(v)) for k, v in o.items() if k not in JSON_SKIP]
        if isinstance(o, list):
            return [strip(x) for x in o]
        return o
    lit = lambda t: ('num', t)  # noqa: E731  (numbers compared as their text)
    return strip(json.loads(b.decode('utf-8'), object_pairs_hook=dict, parse_float=lit, parse_int=lit,
                            parse_constant=lit))


def _csv_norm(b):
    rows = list(csv.reader(io.StringIO(b.decode('utf-8'), newline='')))
    keep = [i for i, h in enumerate(rows[0]) if h not in CSV_SKIP] if rows else []
    return [[r[i] for i in keep] for r in rows]


def same_file(name, a, b):
    """Two runs' bytes of one file are the same, but the times (scripts/compare-outputs.sh)."""
    if a == b:
        return True
    if name.endswith('.json'):
        return _json_norm(a) == _json_norm(b)
    if name.endswith('.csv'):
        return _csv_norm(a) == _csv_norm(b)
    return False


@pytest.fixture
def work(tmp_path, monkeypatch):
    """A fresh working directory with the link cases -> the shipped cases."""
    os.symlink(os.path.join(SRC, 'cases'), tmp_path / 'cases')
    monkeypatch.chdir(tmp_path)
    return tmp_path
