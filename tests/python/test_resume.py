"""A sweep's journal and its resumption from Python (docs/python.md section 4): geardyn.run(case,
out) journals every finished point into out/.sweep.journal as geardyn run does (the library's
gd_sweep_journal); a sweep stopped by its progress callback leaves the journal geardyn run leaves,
record for record (but each point's wall time and the CRC that covers it); resume=True continues
it, and so does geardyn run --resume, and a sweep the command line was interrupted in resumes from
Python: every time the files are those of an uninterrupted run, and the note is geardyn run's."""
import os
import shutil
import signal
import subprocess
import time

import pytest

import geardyn
from conftest import GEARDYN, SRC, cli, listing, load, same_file, state

KS = os.path.join(SRC, 'tests', 'cli', 'ks-sweep.ini')   # the K&S oscillator, up and down
SETS = [('sweep.points', 6), ('run.transient_periods', 20000), ('run.record_periods', 20), ('output.plots', 'off')]
# 20000 transient periods: about 0.4 s a point, several times the 0.1 s between the progress calls,
# so that the stop comes while the point after the K-th runs (a faster sweep could end first)
K = 3                                                   # points done when the sweep is stopped


def _set_args():
    a = []
    for k, v in SETS:
        a += ['--set', '%s=%s' % (k, v)]
    return a


def _journal(d):
    """The journal's lines, split, each point's wall time and the CRCs masked (as
    scripts/compare-outputs.sh compares journals), the header first, the records by slot."""
    with open(os.path.join(d, '.sweep.journal')) as f:
        lines = [ln.split(' ') for ln in f.read().split('\n') if ln]
    for t in lines:
        if t[0] == 'GDSWEEP':
            t[2] = '<version>'
        if t[0] == 'P':
            t[23] = '<wall_s>'   # gd_sweep_record_format: ... events transient_periods wall_s
        t[-1] = '<crc>'
    return lines[0], {int(t[1]): t for t in lines[1:]}


def _stop_python(d):
    with pytest.raises(geardyn.Interrupted):
        geardyn.run(load(KS, SETS), out=d, threads=1, progress=lambda done, total, unit: done >= K)


def _stop_cli(d):
    """geardyn run into d, SIGINT once K points are journalled."""
    p = subprocess.Popen([GEARDYN, 'run', KS, '--out', d, '--quiet', '--threads', '1'] + _set_args(),
                         stderr=subprocess.PIPE)
    journal = os.path.join(d, '.sweep.journal')
    while not (os.path.exists(journal) and open(journal).read().count('\n') >= K + 1) and p.poll() is None:
        time.sleep(0.002)
    p.send_signal(signal.SIGINT)
    err = p.communicate(timeout=60)[1].decode()
    assert p.returncode == 128 + signal.SIGINT, err


def _same_files(a, b):
    assert listing(a) == listing(b)
    for name in listing(a):
        with open(os.path.join(a, name), 'rb') as f, open(os.path.join(b, name), 'rb') as g:
            assert same_file(name, f.read(), g.read()), name


@pytest.fixture
def whole(work):
    """An uninterrupted sweep: 'whole' by the command line."""
    rc, _, err = cli(['run', KS, '--out', 'whole', '--quiet', '--threads', '1'] + _set_args())
    assert rc == 0, err
    return 'whole'


def test_a_stopped_sweep_leaves_the_journal_of_the_command_line(whole):
    _stop_python('py')
    _stop_cli('c')
    assert state('py') == ({}, ['.sweep.journal']) == state('c')
    head_py, rec_py = _journal('py')
    head_c, rec_c = _journal('c')
    assert head_py == head_c
    assert len(rec_py) >= K and len(rec_c) >= K
    for slot in set(rec_py) & set(rec_c):
        assert rec_py[slot] == rec_c[slot], slot
    # the records are the points of the uninterrupted run: a resume from the journal gives its files
    # (below); here: no final file was written
    assert not [n for n in os.listdir('py') if not n.startswith('.')]


def test_resume_from_python(whole):
    _stop_python('py')
    r = geardyn.run(load(KS, SETS), out='py', threads=1, resume=True)
    assert r.notes[0].startswith('resuming: ') and r.notes[0].endswith(' of 12 points already done')
    assert int(r.notes[0].split()[1]) >= K
    _same_files('py', whole)
    assert state('py')[1] == []                       # the journal is gone once the files are published


def test_resume_from_the_command_line_of_a_python_sweep(whole):
    _stop_python('py')
    rc, _, err = cli(['run', KS, '--out', 'py', '--resume', '--threads', '1'] + _set_args())
    assert rc == 0, err
    assert 'geardyn: resuming: ' in err
    _same_files('py', whole)
    assert state('py')[1] == []


def test_resume_from_python_of_a_command_line_sweep(whole):
    _stop_cli('c')
    shutil.copytree('c', 'c2')
    r = geardyn.run(load(KS, SETS), out='c', threads=1, resume=True)
    _same_files('c', whole)
    assert state('c')[1] == []
    # the note is geardyn run --resume's
    rc, _, err = cli(['run', KS, '--out', 'c2', '--resume', '--threads', '1'] + _set_args())
    assert rc == 0, err
    line = next(ln for ln in err.splitlines() if ln.startswith('geardyn: resuming: '))
    assert r.notes == [line[len('geardyn: '):]]
    _same_files('c2', whole)


def test_resume_without_a_journal_says_so(work):
    r = geardyn.run(load(KS, SETS), out='fresh', threads=1, resume=True)
    rc, _, err = cli(['run', KS, '--out', 'fresh2', '--resume', '--threads', '1'] + _set_args())
    assert rc == 0, err
    assert r.notes == ['no journal in fresh: the sweep starts from the beginning']
    assert 'geardyn: note: no journal in fresh2: the sweep starts from the beginning' in err
    _same_files('fresh', 'fresh2')
    with pytest.raises(ValueError):
        geardyn.run(load(KS, SETS), resume=True)
