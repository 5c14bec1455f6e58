"""Running an analysis: gd_job (include/geardyn/gd_job.h) in a thread of its own, the calling
thread waiting in Python, where Ctrl-C (KeyboardInterrupt) and the progress callback are seen and
turned into gd_job_stop, the library's stop hook of the run."""
import json
import os
import signal
import threading

from . import _draw, _lib
from ._case import Case
from ._errors import Error, raise_for
from ._result import Result

_lib_ = _lib.lib
_threads = 0          # set_threads: the module's default (0: the library's, gd_threads_default)
POLL_S = 0.1          # the progress callback is called at most this often
_ASYNC_SIGNALS = {getattr(signal, n) for n in ('SIGINT', 'SIGTERM', 'SIGHUP', 'SIGQUIT', 'SIGALRM', 'SIGUSR1',
                                                'SIGUSR2', 'SIGCHLD', 'SIGWINCH') if hasattr(signal, n)}


def set_threads(n):
    """The threads of every run that does not give threads= (0: the library's default: OpenMP's,
    from OMP_NUM_THREADS or the processors)."""
    global _threads
    n = int(n)
    if n < 0 or n > 4096:
        raise ValueError('threads: %d (valid: 0 for the default, or 1 to 4096)' % n)
    _threads = n


def threads():
    """The threads a run uses when it is given none."""
    return _threads or _lib_.gd_threads_default()


def openmp():
    """libgeardyn's OpenMP: version (yyyymm, 0 without OpenMP), default_threads (what a run uses
    with threads 0: OMP_NUM_THREADS, else the processors; read by OpenMP when the library was
    loaded, so set OMP_* in the environment before importing geardyn), threads (this module's
    default, set_threads) and the OMP_* variables of this process."""
    return {'version': _lib_.gd_openmp_version(), 'default_threads': _lib_.gd_threads_default(),
            'threads': threads(), 'environment': {k: v for k, v in os.environ.items() if k.startswith(('OMP_', 'GOMP_'))}}


class _Job:
    def __init__(self, case, out, nthreads, resume=False):
        err = _lib.Error_t()
        self.ptr = _lib.c_void_p()
        code = _lib_.gd_job_new(case._ptr, os.fsencode(out) if out is not None else None, nthreads,
                                _lib.byref(self.ptr), _lib.byref(err))
        if code != 0:
            raise_for(code, err)
        self.code = None
        self.err = _lib.Error_t()
        self.finished = threading.Event()
        self.stopping = threading.Event()
        if resume:
            _lib_.gd_job_set_resume(self.ptr, 1)
        if out is not None:  # pictures are files of a directory: a run in memory draws none
            self.drawer = _draw.drawer(self.stopping.is_set)  # kept alive while the run goes on
            _lib_.gd_job_set_draw(self.ptr, _lib.ctypes.cast(self.drawer, _lib.c_void_p), None)

    def stop(self):
        self.stopping.set()
        _lib_.gd_job_stop(self.ptr)

    def notes(self):
        return [n for n in _lib.text(_lib_.gd_job_notes(self.ptr)).split('\n') if n]

    def body(self):
        # signals go to the waiting thread (Python's handlers run there), never interrupt a system
        # call of the run; the threads the library starts inherit the mask
        signal.pthread_sigmask(signal.SIG_BLOCK, _ASYNC_SIGNALS)
        try:
            self.code = _lib_.gd_job_run(self.ptr, _lib.byref(self.err))  # the GIL is released meanwhile
        finally:
            self.finished.set()

    def progress(self):
        done, total = _lib.c_long(), _lib.c_long()
        unit = _lib_.gd_job_progress(self.ptr, _lib.byref(done), _lib.byref(total))
        return done.value, total.value, _lib.text(unit)

    def files(self):
        """Every file of the run: summary.json, the files it lists, those of its sub-directories."""
        out = {}

        def get(name):
            n = _lib.c_size_t()
            p = _lib_.gd_job_file(self.ptr, name.encode('utf-8'), _lib.byref(n))
            return None if p is None else _lib.ctypes.string_at(p, n.value)

        def walk(prefix):
            s = get(prefix + 'summary.json')
            if s is None:
                return
            out[prefix + 'summary.json'] = s
            for name in json.loads(s.decode('utf-8')).get('files', []):
                if name.endswith('/'):
                    walk(prefix + name)
                elif name != 'summary.json':
                    b = get(prefix + name)
                    if b is not None:
                        out[prefix + name] = b
        walk('')
        return out

    def free(self):
        if self.ptr:
            _lib_.gd_job_free(self.ptr)
            self.ptr = None


def run(case, out=None, *, threads=None, progress=None, resume=False):
    """Run the analysis of case ([scene] analysis; a Case or the path of a case file) and return its
    Result: the files geardyn run writes, parsed, computed in memory; with out, also written and
    published into the directory out exactly as geardyn run --out out does, its pictures drawn by
    gnuplot when output.plots is on and gnuplot is installed (a failed or interrupted run leaves
    the previous result there, or nothing). Result.notes says why pictures are missing, in the
    words of geardyn run's notes.

    A sweep into out keeps the journal out/.sweep.journal as geardyn run does (a record per point
    as it finishes, synced); a stopped sweep leaves it there, and resume=True continues it as
    geardyn run --resume does: the points it holds are not run again and the files are those of an
    uninterrupted run (Result.notes: "resuming: K of N points already done", or "no journal in
    out: the sweep starts from the beginning").

    threads: OpenMP threads of the run (default: set_threads, else the library's). progress: called
    as progress(done, total, unit) from this thread about every POLL_S s while the run goes on
    (total 0: not known); a true return stops the run (Interrupted). Ctrl-C stops the run through
    the library's stop hook within a unit of work (a mesh period, a contact position, ...) and
    raises KeyboardInterrupt once it has stopped. The run itself holds no GIL: runs in two Python
    threads proceed in parallel.

    Bad input raises CaseError with the message of geardyn run, before anything is written."""
    if not isinstance(case, Case):
        case = Case.load(case)
    n = _threads if threads is None else int(threads)
    if n < 0:
        raise ValueError('threads: %d (valid: 0 for the default, or a positive number)' % n)
    if resume and out is None:
        raise ValueError('resume: a sweep resumes in the directory it was interrupted in (give out)')
    job = _Job(case, out, n, bool(resume))
    worker = threading.Thread(target=job.body, name='geardyn run', daemon=True)
    try:
        try:
            worker.start()
            _wait(job, progress)
        except BaseException:
            if worker.ident is not None:
                _stop_and_wait(job)
            raise
        if job.code != 0:
            raise_for(job.code, job.err)
        files = job.files()
        notes = job.notes()
    finally:
        job.free()
    return Result(files, os.fspath(out) if out is not None else None, notes)


def _wait(job, progress):
    """Wait for the run, calling progress; its true return stops the job. (The wait is on an Event
    the worker sets, not on Thread.join: Python 3.11's join, interrupted by KeyboardInterrupt, may
    take a running thread for finished.)"""
    last = None
    while not job.finished.wait(POLL_S if progress else None):
        p = job.progress()
        if p != last:
            last = p
            if progress(*p):
                job.stop()
                progress = None
    if progress:
        p = job.progress()
        if p != last:
            progress(*p)


def _stop_and_wait(job):
    """Ctrl-C (or an exception of the progress callback): the library's stop hook, and the run
    waited for, since it must end before it is freed, even through a second Ctrl-C."""
    job.stop()
    while not job.finished.is_set():
        try:
            job.finished.wait()
        except KeyboardInterrupt:
            pass
