"""Stopping a run from Python (docs/python.md section 4): Ctrl-C (SIGINT, KeyboardInterrupt) during a
sweep reaches the library's stop hook through gd_job_stop; the run stops within a second of the
signal and KeyboardInterrupt is raised; the output directory keeps the previous result and the
sweep's journal (.sweep.journal, for resume=True), as the command line leaves it after the same
signal; a new directory holds the journal only, as the command line leaves it (test_resume.py
resumes them). A progress callback that returns true stops a run the same way (Interrupted)."""
import os
import shutil
import signal
import subprocess
import threading
import time

import pytest

import geardyn
from conftest import GEARDYN, SRC, beside, load, state

KS = os.path.join(SRC, 'tests', 'cli', 'ks-sweep.ini')   # 80 speeds up and down, K&S oscillator
LONG = [('run.transient_periods', 1000), ('run.record_periods', 200), ('output.plots', 'off')]
SHORT = [('sweep.points', 3), ('output.plots', 'off')]


def _interrupt_when(cond, sent):
    """A thread that sends SIGINT to this process once cond() holds, noting when."""
    def body():
        while not cond():
            time.sleep(0.005)
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)
    t = threading.Thread(target=body, daemon=True)
    t.start()
    return t


def _ctrl_c_sweep(out, progress=True):
    """A long sweep into out, SIGINT once two points are done (or after 1 s without a callback):
    the seconds from the signal to KeyboardInterrupt."""
    done, sent = [0], []
    started = time.monotonic()
    cb = (lambda d, total, unit: done.__setitem__(0, d)) if progress else None
    cond = (lambda: done[0] >= 2) if progress else (lambda: time.monotonic() - started > 1.0)
    t = _interrupt_when(cond, sent)
    with pytest.raises(KeyboardInterrupt):
        geardyn.run(load(KS, LONG), out=out, threads=1, progress=cb)
    latency = time.monotonic() - sent[0]
    t.join()
    return latency


@pytest.mark.parametrize('progress', [True, False], ids=['with a progress callback', 'without'])
def test_ctrl_c_stops_a_sweep_and_keeps_the_previous_result(work, progress):
    geardyn.run(load(KS, SHORT), out='d', threads=1)
    before = state('d')
    latency = _ctrl_c_sweep('d', progress)
    print('stopped %.3f s after SIGINT' % latency)
    assert latency < 1.0
    assert state('d') == (before[0], ['.sweep.journal']) and beside('d') == []
    # the command line, interrupted in its sweep into a copy of the same previous result
    shutil.copytree('d', 'c')
    os.unlink(os.path.join('c', '.sweep.journal'))   # the previous result, not the stopped sweep's journal
    args = [GEARDYN, 'run', KS, '--out', 'c', '--quiet', '--threads', '1']
    for k, v in LONG:
        args += ['--set', '%s=%s' % (k, v)]
    p = subprocess.Popen(args, stderr=subprocess.PIPE)
    journal = os.path.join('c', '.sweep.journal')
    while not (os.path.exists(journal) and open(journal).read().count('\n') >= 3) and p.poll() is None:
        time.sleep(0.005)
    p.send_signal(signal.SIGINT)
    err = p.communicate(timeout=60)[1].decode()
    assert p.returncode == 128 + signal.SIGINT, err
    files, dots = state('c')
    assert files == before[0] and dots == ['.sweep.journal'] and beside('c') == []


def test_ctrl_c_leaves_a_new_directory_with_the_journal_only(work):
    _ctrl_c_sweep('new')
    assert state('new') == ({}, ['.sweep.journal']) and beside('new') == []


def test_progress_callback_stops_a_run(work):
    geardyn.run(load(KS, SHORT), out='d', threads=1)
    before = state('d')
    seen = []

    def progress(done, total, unit):
        seen.append((done, total, unit))
        return done >= 2
    with pytest.raises(geardyn.Interrupted):
        geardyn.run(load(KS, LONG), out='d', threads=1, progress=progress)
    assert state('d') == (before[0], ['.sweep.journal']) and beside('d') == []
    assert seen and all(u == 'points' and t == 160 for d, t, u in seen)


def test_ctrl_c_stops_a_response(work):
    rel = os.path.join(SRC, 'cases', 'guide', 'herringbone.ini')
    geardyn.run(load(rel, [('run.record_periods', 5), ('output.plots', 'off')]), out='d', threads=1)
    before = state('d')
    done, sent = [0], []
    t = _interrupt_when(lambda: done[0] >= 50, sent)
    with pytest.raises(KeyboardInterrupt):
        geardyn.run(load(rel, [('output.plots', 'off')]), out='d', progress=lambda d, total, unit: done.__setitem__(0, d))
    assert time.monotonic() - sent[0] < 1.0
    t.join()
    assert state('d') == before and beside('d') == []
