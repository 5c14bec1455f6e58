"""The pictures of a run from Python (docs/python.md section 3): geardyn.run(case, out=DIR) draws
them as geardyn run --out DIR does, through the library's scripts and the module's drawer
(python/geardyn/_draw.py, gnuplot):

* for one shipped case of every analysis (the one test_runs.py runs, shortened as
  scripts/compare-outputs.sh shortens it, pictures on): the same set of files, every SVG and every
  table the same bytes (but the times, and the pictures compare-outputs.sh skips: PIC_SKIP), every
  PNG whole;
* the notes: without gnuplot, with a gnuplot that fails, the module's Result.notes are the lines
  geardyn run prints as "geardyn: note: ...";
* atomic: a run stopped while gnuplot draws (Ctrl-C) leaves the previous directory as it was, no
  stage, no temporary picture, and its gnuplot is gone."""
import os
import shlex
import signal
import stat
import threading
import time

import pytest

import geardyn
from conftest import GEARDYN, SRC, beside, cli, cli_run, listing, load, same_file, shortening, state
from test_runs import CHOSEN

GNUPLOT = __import__('shutil').which('gnuplot')
needs_gnuplot = pytest.mark.skipif(GNUPLOT is None, reason='gnuplot is not installed (apt-get install gnuplot-nox)')


def _pic_skip():
    with open(os.path.join(SRC, 'scripts', 'compare-outputs.sh')) as f:
        line = next(ln for ln in f.read().splitlines() if ln.startswith('PIC_SKIP='))
    return set(shlex.split(line[len('PIC_SKIP='):])[0].split())


PIC_SKIP = _pic_skip()


def _whole_png(path):
    with open(path, 'rb') as f:
        b = f.read()
    return b[:8] == b'\x89PNG\r\n\x1a\n' and b[-12:] == b'\0\0\0\0IEND\xae\x42\x60\x82'


@needs_gnuplot
@pytest.mark.parametrize('analysis', list(geardyn.analyses()))
def test_pictures_as_the_command_line(analysis, work):
    rel, sets = CHOSEN[analysis]
    sets = [kv for kv in sets if kv[0] != 'output.plots'] + [('output.plots', 'on')]
    rc, _, err = cli_run(rel, sets, 'cli')
    assert rc == 0, err
    r = geardyn.run(load(rel, sets), out='py', threads=1)
    files = listing('cli')
    assert listing('py') == files
    pics = [f for f in files if f.endswith(('.png', '.svg'))]
    assert pics, 'geardyn run drew no picture of %s' % rel
    drawn = list(r.pictures) + [sub + '/' + f for sub, rs in r.subruns.items() for f in rs.pictures]
    assert sorted(drawn) == sorted(pics) and r.notes == []
    # a run inside the run (optimize's optimum/ and optimum-tca/) draws its own pictures too
    for sub in {os.path.dirname(f) for f in files if os.sep in f}:
        assert any(os.path.dirname(f) == sub and f.endswith('.svg') for f in pics), sub
    for name in sorted(files):
        with open(os.path.join('py', name), 'rb') as f, open(os.path.join('cli', name), 'rb') as g:
            mine, theirs = f.read(), g.read()
        if name.endswith('.png'):
            assert _whole_png(os.path.join('py', name)), name
        elif os.path.basename(name) not in PIC_SKIP:
            assert same_file(name, mine, theirs), name
    assert [n for n in os.listdir('.') if n.startswith('.')] == []


def _fake_gnuplot(tmp_path, body):
    """A directory holding an executable 'gnuplot' (a shell script with body), for PATH."""
    d = tmp_path / 'bin'
    d.mkdir(exist_ok=True)
    p = d / 'gnuplot'
    p.write_text('#!/bin/sh\n' + body)
    p.chmod(p.stat().st_mode | stat.S_IXUSR)
    return str(d)


TCA = ('cases/paper/tca-modified.ini', [])


def _notes_of_cli(stderr):
    return [ln[len('geardyn: note: '):].rstrip() for ln in stderr.splitlines() if ln.startswith('geardyn: note: ')]


def test_without_gnuplot_the_notes_of_the_command_line(work, tmp_path, monkeypatch):
    empty = tmp_path / 'nothing'
    empty.mkdir()
    monkeypatch.setenv('PATH', str(empty))
    rc, _, err = cli(['run', TCA[0], '--out', 'cli'])
    assert rc == 0, err
    r = geardyn.run(load(*TCA), out='py')
    assert r.notes == _notes_of_cli(err) == ['gnuplot is not installed: no pictures (apt-get install gnuplot-nox)']
    assert listing('py') == listing('cli') and r.pictures == []
    # a run in memory has no directory to draw into: no pictures, no note
    assert geardyn.run(load(*TCA)).notes == []


def test_a_failing_gnuplot_gives_the_note_of_the_command_line(work, tmp_path, monkeypatch):
    monkeypatch.setenv('PATH', _fake_gnuplot(tmp_path, 'echo "line 3: no such terminal" >&2\nexit 1\n') + ':' +
                       os.environ['PATH'])
    rc, _, err = cli(['run', TCA[0], '--out', 'cli'])
    assert rc == 0, err
    r = geardyn.run(load(*TCA), out='py')
    assert r.notes == _notes_of_cli(err) == ['pictures not drawn: gnuplot failed: line 3: no such terminal']
    assert listing('py') == listing('cli') and r.pictures == []
    assert not [n for n in os.listdir('py') if n.endswith('.tmp')]


def test_a_truncated_picture_is_not_published(work, tmp_path, monkeypatch):
    """gnuplot exits 0 after a write that failed (a full disk): the picture is not whole."""
    real = GNUPLOT or '/usr/bin/gnuplot'
    body = ('"%s" "$@" || exit $?\n'
            'for f in .*.svg.tmp; do head -c 100 "$f" > "$f.cut" && mv "$f.cut" "$f"; done\n' % real)
    monkeypatch.setenv('PATH', _fake_gnuplot(tmp_path, body) + ':' + os.environ['PATH'])
    if GNUPLOT is None:
        pytest.skip('gnuplot is not installed')
    rc, _, err = cli(['run', TCA[0], '--out', 'cli'])
    r = geardyn.run(load(*TCA), out='py')
    assert r.notes == _notes_of_cli(err) == ['pictures not drawn: contact_pattern.svg: gnuplot wrote no whole '
                                             'picture (a full disk?)']
    assert listing('py') == listing('cli') and not any(f.endswith(('.png', '.svg', '.tmp')) for f in listing('py'))


@needs_gnuplot
def test_ctrl_c_while_drawing_keeps_the_previous_result(work, tmp_path, monkeypatch):
    geardyn.run(load(*TCA), out='d')
    before = state('d')
    assert any(f.endswith('.svg') for f in before[0])
    # a gnuplot that says it started (its pid) and draws for a minute
    pidfile = tmp_path / 'gnuplot.pid'
    monkeypatch.setenv('PATH', _fake_gnuplot(tmp_path, 'echo $$ > "%s"\nexec sleep 60\n' % pidfile) + ':' +
                       os.environ['PATH'])

    def interrupt():
        while not pidfile.exists() or not pidfile.read_text().strip():
            time.sleep(0.01)
        os.kill(os.getpid(), signal.SIGINT)
    t = threading.Thread(target=interrupt, daemon=True)
    t.start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        geardyn.run(load(TCA[0], [('solver.tca_positions_per_cycle', 16)]), out='d')
    t.join()
    assert time.monotonic() - started < 30     # not the minute of the drawing
    assert state('d') == before and beside('d') == []
    pid = int(pidfile.read_text())
    with pytest.raises(ProcessLookupError):
        os.kill(pid, 0)                         # gnuplot is gone (killed and reaped)
