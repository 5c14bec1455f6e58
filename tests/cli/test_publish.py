#!/usr/bin/env python3
"""A run's set of files is published in one step (docs/robustness.md).

* A reader process opens DIR again and again, reads summary.json and every file it lists through
  that directory's fd, while runs of two cases (sets A and B: overlapping names, different
  contents, B without time_history.csv) alternate into DIR. Every snapshot must be set A or set B
  (sha256 of every file against sets computed beforehand in separate directories): never a mix,
  never a part. A listed file missing from a directory that DIR no longer is (the reader was
  overtaken by the next publication, which removes the swapped-out tree) is retried, not
  accepted; a file missing from the directory DIR still is fails.
* The user's entries (a file, a symbolic link, a hidden file, a directory with its inode) are
  still in DIR afterwards; no stage is left beside DIR.
* The lock (through the library, ctypes): after publication DIR is another inode and still
  locked until the run is closed; the swapped-out directory is retired.
* What a SIGKILL leaves (built by hand): an unpublished stage beside DIR is dropped; a previous
  tree swapped out but not yet removed gives the user's entries back to DIR.
* The fallback (--out . inside a temporary directory) still publishes a whole set, keeps the
  user's files, says so on stderr, and leaves no stage.
* A run that fails in a directory it made leaves no directory.

  test_publish.py LIBGEARDYN   (GEARDYN names the executable, GEARDYN_SOURCE the source tree)
"""
import ctypes
import fcntl
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_faults import fsize  # noqa: E402  (one copy of each helper)

G = os.environ.get('GEARDYN', 'geardyn')
SRC = os.environ.get('GEARDYN_SOURCE', '.')
QUICK = os.path.join(SRC, 'cases', 'quickstart.ini')
SMALL = ['--quiet', '--set', 'run.record_periods=5', '--set', 'output.event_log=off', '--set', 'output.plots=off']
CASE_A = SMALL
CASE_B = SMALL + ['--set', 'operating.speed_rpm=3000', '--set', 'output.time_history=off']
n_tap = 0
failed = 0


def ok(cond, msg):
    global n_tap, failed
    n_tap += 1
    if not cond:
        failed += 1
    print(('ok' if cond else 'not ok') + ' %d - %s' % (n_tap, msg))
    sys.stdout.flush()


def run(args, **kw):
    p = subprocess.run([G, 'run', QUICK] + args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, **kw)
    return p.returncode, p.stderr.decode('utf-8', 'replace')


def speed(summary):
    return summary['case']['parameters']['operating']['speed_rpm']['value']


def read_at(fd, name):
    with os.fdopen(os.open(name, os.O_RDONLY, dir_fd=fd), 'rb') as fp:
        return fp.read()


def the_set_fd(fd):
    """The files summary.json lists (summary.json itself apart: it holds the run's times), their
    sha256, and the case's speed, read through the directory fd."""
    s = json.loads(read_at(fd, 'summary.json'))
    files = {n: hashlib.sha256(read_at(fd, n)).hexdigest() for n in s['files'] if n != 'summary.json'}
    return {'speed': speed(s), 'files': files}


def the_set(d):
    fd = os.open(d, os.O_RDONLY | os.O_DIRECTORY)
    try:
        return the_set_fd(fd)
    finally:
        os.close(fd)


def reader(d, sets_path, stop):
    """Reader mode: snapshots of d until stop exists; prints a JSON report."""
    sets = json.load(open(sets_path))
    seen = {'A': 0, 'B': 0}
    retried, bad = 0, []
    while not os.path.exists(stop):
        try:
            fd = os.open(d, os.O_RDONLY | os.O_DIRECTORY)
        except OSError as e:
            bad.append('cannot open DIR: %s' % e)
            continue
        try:
            snap = the_set_fd(fd)
        except FileNotFoundError as e:
            if os.fstat(fd).st_ino != os.stat(d).st_ino:
                retried += 1
            else:
                bad.append('part: %s missing from DIR' % e.filename)
            snap = None
        except ValueError as e:
            bad.append('summary.json unreadable: %s' % e)
            snap = None
        os.close(fd)
        if snap is None:
            continue
        which = [k for k in ('A', 'B') if sets[k] == snap]
        if which:
            seen[which[0]] += 1
        elif len(bad) < 20:
            bad.append('a mix: speed %s, files %s' % (snap['speed'], sorted(
                n + ('' if any(sets[k]['files'].get(n) == h for k in 'AB') else '(foreign content)')
                for n, h in snap['files'].items())))
    print(json.dumps({'seen': seen, 'retried': retried, 'bad': bad}))


def user_entries(d):
    with open(os.path.join(d, 'notes.txt'), 'w') as f:
        f.write('my notes\n')
    with open(os.path.join(d, '.hidden'), 'w') as f:
        f.write('hidden\n')
    os.mkdir(os.path.join(d, 'mine'))
    with open(os.path.join(d, 'mine', 'f.txt'), 'w') as f:
        f.write('mine\n')
    os.symlink('notes.txt', os.path.join(d, 'link'))
    return os.stat(os.path.join(d, 'mine')).st_ino


def user_entries_kept(d, ino):
    try:
        return (open(os.path.join(d, 'notes.txt')).read() == 'my notes\n'
                and open(os.path.join(d, '.hidden')).read() == 'hidden\n'
                and open(os.path.join(d, 'mine', 'f.txt')).read() == 'mine\n'
                and os.stat(os.path.join(d, 'mine')).st_ino == ino
                and os.readlink(os.path.join(d, 'link')) == 'notes.txt')
    except OSError:
        return False


def exactly(d, want, user=('notes.txt', '.hidden', 'mine', 'link')):
    """DIR holds the set want whole (summary.json's list, each file's sha256) and nothing but the
    user's entries besides."""
    try:
        have = the_set(d)
        listed = json.load(open(os.path.join(d, 'summary.json')))['files']
    except (OSError, ValueError, KeyError):
        return False
    rest = set(os.listdir(d)) - {n.rstrip('/') for n in listed} - set(user)
    return have == want and not rest


def leftovers(d):
    """Stages beside d and temporaries in it."""
    parent, name = os.path.split(d)
    return sorted([n for n in os.listdir(parent) if n.startswith('.' + name + '.')]
                  + [n for n in os.listdir(d) if n.startswith(('.staging', '.plot-', '.geardyn'))])


def alternate(tmp, sets):
    d = os.path.join(tmp, 'out', 'res')
    rc, err = run(['--out', d] + CASE_A)
    ino = user_entries(d)
    sets_path = os.path.join(tmp, 'sets.json')
    json.dump(sets, open(sets_path, 'w'))
    stop = os.path.join(tmp, 'stop')
    rd = subprocess.Popen([sys.executable, os.path.abspath(__file__), '--reader', d, sets_path, stop],
                          stdout=subprocess.PIPE)
    time.sleep(0.2)
    rcs = []
    for k in range(20):
        rcs.append(run(['--out', d] + (CASE_B if k % 2 == 0 else CASE_A))[0])
    open(stop, 'w').close()
    rep = json.loads(rd.communicate(timeout=120)[0])
    ok(all(r == 0 for r in rcs), '20 runs alternating two cases into one directory: exit %s' % rcs)
    ok(not rep['bad'] and rep['seen']['A'] > 0 and rep['seen']['B'] > 0,
       'the reader saw set A %d times, set B %d times, retried %d overtaken directories, and never a mix or '
       'a part: %s' % (rep['seen']['A'], rep['seen']['B'], rep['retried'], rep['bad'][:5]))
    ok(user_entries_kept(d, ino), 'the user\'s file, hidden file, symbolic link and directory (same inode) '
       'are still in DIR: %s' % sorted(os.listdir(d)))
    ok(exactly(d, sets['A']) and leftovers(d) == [],
       'DIR holds the last set (A) whole and nothing else but the user\'s entries, no stage beside it (%s)'
       % leftovers(d))
    return d, ino


def sanitized(lib_path):
    """Whether the library links the address sanitizer, whose runtime must come first in a process:
    python cannot load it (the ASan build of scripts/test.sh)."""
    with open(lib_path, 'rb') as f:
        return b'libasan.so' in f.read()


def lock(lib_path, tmp):
    global n_tap
    if sanitized(lib_path):
        for what in ('the library stages beside DIR and publishes in one step',
                     'after the exchange DIR is another inode and a second run is still refused',
                     'the swapped-out directory is removed; the next run locks the directory DIR is now'):
            n_tap += 1
            print('ok %d - %s # SKIP the library is built with ASan, which python cannot load' % (n_tap, what))
        return
    lib = ctypes.CDLL(lib_path)
    libc = ctypes.CDLL(None)
    lib.gd_run_dir_stage.restype = ctypes.c_char_p
    fallback = getattr(lib, 'gd_run_dir_fallback', None)
    if fallback:
        fallback.restype = ctypes.c_char_p
    err = ctypes.create_string_buffer(8192)
    d = os.path.join(tmp, 'locked')
    os.mkdir(d)
    before = os.open(d, os.O_RDONLY | os.O_DIRECTORY)   # a run that opened DIR and waits for the lock
    r1, r2, fp = ctypes.c_void_p(), ctypes.c_void_p(), ctypes.c_void_p()
    st = lib.gd_run_dir_open(d.encode(), ctypes.byref(r1), err)
    st = st or lib.gd_run_dir_create(r1, b'summary.json', ctypes.byref(fp), err)
    libc.fputs(b'{"files": ["summary.json"]}\n', fp)
    st = st or lib.gd_run_dir_commit(r1, fp, err)
    stage = lib.gd_run_dir_stage(r1).decode()
    st = st or lib.gd_run_dir_publish(r1, err)
    ok(st == 0 and stage == os.path.join(tmp, '.locked.geardyn-stage') and fallback and fallback(r1) is None,
       'the library stages beside DIR (%s) and publishes in one step' % stage)
    lib.gd_run_dir_open(d.encode(), ctypes.byref(r2), err)
    st2 = lib.gd_run_dir_make(r2, err)
    msg = err.raw[4:].split(b'\0')[0].decode()
    replaced = os.fstat(before).st_ino != os.stat(d).st_ino
    ok(st2 != 0 and 'another geardyn run' in msg and replaced,
       'after the exchange DIR is another inode (%s) and a second run is still refused: %s' % (replaced, msg))
    lib.gd_run_dir_close(r2)
    lib.gd_run_dir_close(r1)
    fcntl.flock(before, fcntl.LOCK_EX | fcntl.LOCK_NB)   # the swapped-out directory: free, and retired
    retired = os.fstat(before).st_nlink == 0
    os.close(before)
    r3 = ctypes.c_void_p()
    lib.gd_run_dir_open(d.encode(), ctypes.byref(r3), err)
    st3 = lib.gd_run_dir_make(r3, err)
    probe = os.open(d, os.O_RDONLY | os.O_DIRECTORY)
    try:
        fcntl.flock(probe, fcntl.LOCK_EX | fcntl.LOCK_NB)
        held = False
    except BlockingIOError:
        held = True
    os.close(probe)
    lib.gd_run_dir_close(r3)
    ok(retired and st3 == 0 and held, 'the swapped-out directory is removed (%s); the next run locks the '
       'directory DIR is now (%s)' % (retired, held))


def stale(tmp, sets, setdirs):
    d = os.path.join(tmp, 'stale', 'res')
    rc, err = run(['--out', d] + CASE_A)
    ino = user_entries(d)
    stage = os.path.join(tmp, 'stale', '.res.geardyn-stage')
    # killed before the exchange: a stage with its marker and a whole unpublished set of case B
    shutil.copytree(setdirs['B'], stage)
    open(os.path.join(stage, '.geardyn-unpublished'), 'w').close()
    rc, err = run(['--out', d] + CASE_A)
    ok(rc == 0 and exactly(d, sets['A']) and user_entries_kept(d, ino) and leftovers(d) == [],
       'an unpublished stage a killed run left is dropped: exit %d, set A whole, user\'s entries kept, left %s'
       % (rc, leftovers(d)))
    # killed between the exchange and the end: DIR is the new set (B) with the marker, the previous
    # tree (A) at the stage's name still holds the user's directory and a file added meanwhile
    shutil.rmtree(stage, ignore_errors=True)   # (what the step before left if it failed)
    shutil.copytree(d, stage, symlinks=True)
    shutil.rmtree(d)
    shutil.copytree(setdirs['B'], d)
    open(os.path.join(d, '.geardyn-unpublished'), 'w').close()
    for n in ('notes.txt', '.hidden', 'link'):
        os.link(os.path.join(stage, n), os.path.join(d, n), follow_symlinks=False)
    with open(os.path.join(stage, 'late.txt'), 'w') as f:
        f.write('late\n')
    ino = os.stat(os.path.join(stage, 'mine')).st_ino
    rc, err = run(['--out', d] + CASE_B)
    ok(rc == 0 and exactly(d, sets['B'], ('notes.txt', '.hidden', 'mine', 'link', 'late.txt'))
       and user_entries_kept(d, ino) and leftovers(d) == [],
       'a swapped-out tree a killed run left gives the user\'s entries back and goes: exit %d, left %s, DIR %s'
       % (rc, leftovers(d), sorted(os.listdir(d))))


def fallback(tmp, sets):
    here = os.path.join(tmp, 'here')
    os.mkdir(here)
    rc, err = run(['--out', '.'] + CASE_A, cwd=here)
    with open(os.path.join(here, 'notes.txt'), 'w') as f:
        f.write('my notes\n')
    loud = [a for a in CASE_B if a != '--quiet']
    for out, why, want in (('.', "no name of its own", 'B'), (here, 'it is the working directory', 'A')):
        rc, err = run(['--out', out] + (loud if want == 'B' else [a for a in CASE_A if a != '--quiet']), cwd=here)
        ok(rc == 0 and exactly(here, sets[want], ('notes.txt',)) and leftovers(here) == []
           and 'not published in one step: ' in err and why in err,
           '--out %s from within DIR publishes a whole set one file at a time and says why: exit %d, left %s, %s'
           % (out if out == '.' else 'DIR', rc, leftovers(here), err.strip().splitlines()[-1:]))


def failed_run(tmp):
    d = os.path.join(tmp, 'new')
    rc, err = run(['--out', d] + CASE_A, preexec_fn=fsize(1000))
    ok(rc == 1 and not os.path.exists(d) and not os.path.exists(os.path.join(tmp, '.new.geardyn-stage')),
       'a run that fails in a directory it made leaves neither the directory nor a stage: exit %d' % rc)


def main():
    if len(sys.argv) == 5 and sys.argv[1] == '--reader':
        reader(*sys.argv[2:])
        return 0
    tmp = tempfile.mkdtemp(prefix='geardyn-publish-')
    sets, setdirs = {}, {}
    for k, args in (('A', CASE_A), ('B', CASE_B)):
        setdirs[k] = os.path.join(tmp, 'set' + k)
        rc, err = run(['--out', setdirs[k]] + args)
        sets[k] = the_set(setdirs[k])
    common = set(sets['A']['files']) & set(sets['B']['files'])
    ok(common and all(sets['A']['files'][n] != sets['B']['files'][n] for n in common)
       and set(sets['A']['files']) != set(sets['B']['files']),
       'sets A and B share %d names, every one with other contents, and differ in their names' % len(common))
    alternate(tmp, sets)
    lock(sys.argv[1], tmp)
    stale(tmp, sets, setdirs)
    fallback(tmp, sets)
    failed_run(tmp)
    print('1..%d' % n_tap)
    shutil.rmtree(tmp, ignore_errors=True)
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
