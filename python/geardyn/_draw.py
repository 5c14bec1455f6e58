"""The drawer of a run's pictures (gd_draw_fn, include/geardyn/gd_output.h): gnuplot run on the
library's script in the run's stage, as the command line's src/cli/gnuplot.c does. The script
writes each picture NAME as .NAME.png.tmp and .NAME.svg.tmp; when gnuplot succeeded and every
picture is whole (a PNG to its IEND chunk, an SVG to its </svg>) they move into place, else the
run gets the command line's note; the temporary files go either way. gnuplot gets SIGKILL when
the thread that started it ends (PR_SET_PDEATHSIG: the run's thread waits for it, so only when the
process dies), and is killed when the run is stopped (Ctrl-C, the progress callback)."""
import ctypes
import os
import shutil
import subprocess
import tempfile

from . import _lib

DRAW_FN = ctypes.CFUNCTYPE(_lib.c_int, _lib.c_void_p, _lib.c_char_p, _lib.c_char_p, _lib.POINTER(_lib.c_char_p),
                           _lib.c_int, _lib.POINTER(_lib.Error_t))
GD_ERR_IO = 4
NOT_INSTALLED = 'gnuplot is not installed: no pictures (apt-get install gnuplot-nox)'
POLL_S = 0.02         # how often a drawing asks whether the run is stopped
_PR_SET_PDEATHSIG = 1
_SIGKILL = 9

try:
    _libc = ctypes.CDLL(None, use_errno=True)
    _prctl = _libc.prctl
    _prctl.argtypes = [ctypes.c_int, ctypes.c_ulong, ctypes.c_ulong, ctypes.c_ulong, ctypes.c_ulong]
    _prctl.restype = ctypes.c_int
except (OSError, AttributeError):  # not Linux: gnuplot is still killed when the run stops
    _prctl = None


class Failed(Exception):
    def __init__(self, code, msg):
        super().__init__(msg)
        self.code = code


def _child(parent):
    """In gnuplot's process before the exec: die with the thread that started it."""
    def setup():
        if _prctl is not None and (_prctl(_PR_SET_PDEATHSIG, _SIGKILL, 0, 0, 0) != 0 or os.getppid() != parent):
            os._exit(127)
    return setup


def _whole(path, png):
    try:
        with open(path, 'rb') as f:
            head = f.read(8)
            f.seek(0, os.SEEK_END)
            size = f.tell()
            if size < 16:
                return False
            f.seek(size - 16)
            tail = f.read(16)
    except OSError:
        return False
    if png:
        return head == b'\x89PNG\r\n\x1a\n' and tail[4:] == b'\0\0\0\0IEND\xae\x42\x60\x82'
    return tail.rstrip(b'\n\r ').endswith(b'</svg>')


def _run(exe, d, script, stopped):
    fd, spath = tempfile.mkstemp(prefix='.plot-', dir=d)
    logpath = spath + '.log'
    try:
        with os.fdopen(fd, 'w', encoding='utf-8') as f:
            f.write(script)
        with open(logpath, 'wb') as log:
            try:
                p = subprocess.Popen([exe, os.path.basename(spath)], cwd=d, stdin=subprocess.DEVNULL,
                                     stdout=subprocess.DEVNULL, stderr=log, close_fds=True,
                                     preexec_fn=_child(os.getpid()))
            except OSError as e:
                raise Failed(GD_ERR_IO, 'cannot start gnuplot: %s' % e.strerror) from None
            while True:
                try:
                    rc = p.wait(POLL_S)
                    break
                except subprocess.TimeoutExpired:
                    if stopped():
                        p.kill()
                        p.wait()
                        raise Failed(_lib.GD_ERR_INTERRUPTED, 'interrupted') from None
        if rc != 0:
            with open(logpath, 'rb') as log:
                msg = log.read(399).decode('utf-8', 'replace')
            raise Failed(GD_ERR_IO, 'gnuplot failed: ' + msg)
    finally:
        for q in (spath, logpath):
            try:
                os.unlink(q)
            except OSError:
                pass


def draw(d, script, names, stopped):
    """gd_gnuplot_draw: gnuplot on script in d, the pictures names moved into place when whole."""
    exe = shutil.which('gnuplot')
    if exe is None:
        raise Failed(GD_ERR_IO, NOT_INSTALLED)
    tmps = [(os.path.join(d, '.%s%s.tmp' % (n, e)), os.path.join(d, n + e), e == '.png')
            for n in names for e in ('.png', '.svg')]
    try:
        _run(exe, d, script, stopped)
        for tmp, _, png in tmps:
            if not _whole(tmp, png):
                raise Failed(GD_ERR_IO, '%s: gnuplot wrote no whole picture (a full disk?)' %
                             os.path.basename(tmp)[1:-4])
        for tmp, fin, _ in tmps:
            try:
                os.rename(tmp, fin)
            except OSError:
                raise Failed(GD_ERR_IO, '%s: cannot rename the picture' % fin) from None
    finally:
        for tmp, _, _ in tmps:
            try:
                os.unlink(tmp)
            except OSError:
                pass


def drawer(stopped):
    """The ctypes callback of a run (keep a reference while the run goes on): stopped() says
    whether the run was asked to stop."""
    def callback(user, d, script, names, nnames, err):
        try:
            if script is None:
                if shutil.which('gnuplot') is None:
                    raise Failed(GD_ERR_IO, NOT_INSTALLED)
                return 0
            draw(os.fsdecode(d), script.decode('utf-8'), [names[i].decode('utf-8') for i in range(nnames)], stopped)
            return 0
        except Failed as e:
            code, msg = e.code, str(e)
        except BaseException as e:  # nothing may escape into the library
            code, msg = GD_ERR_IO, 'the drawer failed: %r' % e
        err.contents.code = code
        err.contents.msg = msg.encode('utf-8')[:_lib.GD_ERROR_MSG_MAX - 1]
        return code
    return DRAW_FN(callback)
