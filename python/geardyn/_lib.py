"""libgeardyn through ctypes: the library's path, the few structures that cross, the prototypes.

Only opaque pointers, numbers, text and three small public structures (gd_error, gd_keyspec,
gd_eventlog_filter) cross the boundary; a run goes through gd_job (include/geardyn/gd_job.h), so
that nothing here depends on the layout of gd_case or gd_run_env. ctypes releases the GIL around
every call into the library (docs/python.md says why ctypes and not CFFI)."""
import ctypes
import os

try:
    from . import _config
except ImportError:  # the source tree's copy: python/geardyn has no _config.py, the build's has
    _config = None

c_int, c_long, c_size_t, c_double = ctypes.c_int, ctypes.c_long, ctypes.c_size_t, ctypes.c_double
c_char_p, c_void_p = ctypes.c_char_p, ctypes.c_void_p
POINTER, byref = ctypes.POINTER, ctypes.byref

GD_ERROR_MSG_MAX = 1024
STATUS = ['GD_OK', 'GD_ERR_INPUT', 'GD_ERR_GEOMETRY', 'GD_ERR_NOMEM', 'GD_ERR_IO', 'GD_ERR_SOLVER', 'GD_ERR_GSL',
          'GD_ERR_NLOPT', 'GD_ERR_CHATTER', 'GD_ERR_PHYSICS', 'GD_ERR_INTERNAL', 'GD_ERR_INTERRUPTED']
GD_ERR_INPUT, GD_ERR_GEOMETRY, GD_ERR_INTERRUPTED = 1, 2, 11
KEY_TYPES = ['number', 'integer', 'choice', 'on/off', 'text', 'list of numbers']  # gd_keytype, as geardyn keys names them
SOURCES = ['default', 'file', 'set', 'derived']                                  # gd_source


class Error_t(ctypes.Structure):
    _fields_ = [('code', c_int), ('msg', ctypes.c_char * GD_ERROR_MSG_MAX)]


class Keyspec(ctypes.Structure):
    _fields_ = [('section', c_char_p), ('key', c_char_p), ('type', c_int), ('unit', c_char_p),
                ('offset', c_size_t), ('count_offset', c_size_t), ('min', c_double), ('max', c_double),
                ('min_open', c_int), ('max_open', c_int), ('default', c_double), ('choices', c_char_p),
                ('help', c_char_p)]


class AnalysisHead(ctypes.Structure):
    """The first fields of a row of the table of analyses (gd_analysis_type): id, name, what. Only
    read through gd_analysis_find's pointer, so the rest of the row may grow."""
    _fields_ = [('id', c_int), ('name', c_char_p), ('what', c_char_p)]


class EventlogFilter(ctypes.Structure):
    _fields_ = [('t_from_s', c_double), ('t_to_s', c_double), ('clearance', ctypes.c_char * 32),
                ('kind', ctypes.c_char * 32), ('recorded_only', c_int)]


def library_path():
    """GEARDYN_LIBRARY when set, else the library this package was built or installed with."""
    path = os.environ.get('GEARDYN_LIBRARY') or (_config.LIBRARY if _config else None)
    if not path:
        raise ImportError('geardyn: this is the source tree\'s copy of the module, which does not know where '
                          'libgeardyn is: use the build tree\'s (PYTHONPATH=build/python) or the installed one, '
                          'or set GEARDYN_LIBRARY to the library')
    return path


def _load():
    path = library_path()
    try:
        return ctypes.CDLL(path)
    except OSError as e:
        hint = ''
        if 'ASan runtime' in str(e) or 'libasan' in str(e):
            hint = ' (a library built with AddressSanitizer loads only with its runtime preloaded: ' \
                   'LD_PRELOAD=$(gcc -print-file-name=libasan.so))'
        raise ImportError('geardyn: cannot load libgeardyn %s: %s%s' % (path, e, hint)) from None


lib = _load()

_PROTOTYPES = [
    # name, result, arguments
    ('gd_status_name', c_char_p, [c_int]),
    ('gd_free', None, [c_void_p]),
    ('gd_case_schema', POINTER(Keyspec), [POINTER(c_size_t)]),
    ('gd_case_find_key', POINTER(Keyspec), [c_char_p, c_char_p]),
    ('gd_case_new', c_void_p, [POINTER(Error_t)]),
    ('gd_case_dup', c_void_p, [c_void_p, POINTER(Error_t)]),
    ('gd_case_delete', None, [c_void_p]),
    ('gd_case_load', c_int, [c_void_p, c_char_p, POINTER(Error_t)]),
    ('gd_case_load_text', c_int, [c_void_p, c_char_p, c_size_t, c_char_p, POINTER(Error_t)]),
    ('gd_case_set', c_int, [c_void_p, c_char_p, c_int, POINTER(Error_t)]),
    ('gd_case_get_number', c_int, [c_void_p, c_char_p, POINTER(c_double), POINTER(Error_t)]),
    ('gd_case_get_list', c_int, [c_void_p, c_char_p, POINTER(c_double), c_int, POINTER(c_int), POINTER(Error_t)]),
    ('gd_case_format_value', None, [c_void_p, c_size_t, c_char_p, c_size_t]),
    ('gd_case_source', c_int, [c_void_p, c_size_t, POINTER(c_int)]),
    ('gd_case_check_json', c_int, [c_void_p, POINTER(c_void_p), POINTER(Error_t)]),
    ('gd_analysis_find', POINTER(AnalysisHead), [c_int]),
    ('gd_threads_default', c_int, []),
    ('gd_openmp_version', c_int, []),
    ('gd_job_new', c_int, [c_void_p, c_char_p, c_int, POINTER(c_void_p), POINTER(Error_t)]),
    ('gd_job_run', c_int, [c_void_p, POINTER(Error_t)]),
    ('gd_job_stop', None, [c_void_p]),
    ('gd_job_progress', c_char_p, [c_void_p, POINTER(c_long), POINTER(c_long)]),
    ('gd_job_file', c_void_p, [c_void_p, c_char_p, POINTER(c_size_t)]),
    ('gd_job_free', None, [c_void_p]),
    ('gd_job_set_draw', None, [c_void_p, c_void_p, c_void_p]),
    ('gd_job_notes', c_char_p, [c_void_p]),
    ('gd_job_set_resume', None, [c_void_p, c_int]),
    ('gd_eventlog_select', c_int, [c_char_p, POINTER(EventlogFilter), POINTER(c_void_p), POINTER(c_size_t),
                                   c_void_p, POINTER(Error_t)]),
]
for _name, _res, _args in _PROTOTYPES:
    _f = getattr(lib, _name)
    _f.restype = _res
    _f.argtypes = _args


def _schema():
    n = c_size_t()
    s = lib.gd_case_schema(byref(n))
    keys = [s[i] for i in range(n.value)]
    # the stride of the mirror above must be the library's: gd_case_find_key of the last entry
    # points where our array says it is
    last = keys[-1]
    found = lib.gd_case_find_key(last.section, last.key)
    if ctypes.addressof(found.contents) != ctypes.addressof(last):
        raise ImportError('geardyn: libgeardyn %s has another gd_keyspec than this module (rebuild both)' %
                          library_path())
    return keys


SCHEMA = _schema()


def text(b):
    return b.decode('utf-8') if b is not None else None
