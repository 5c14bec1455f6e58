"""A case: libgeardyn's gd_case behind an opaque pointer, loaded, read and changed through the
library's own schema and checks (gd_case_load, gd_case_load_text, gd_case_set)."""
import json
import math
import os

from . import _lib
from ._errors import CaseError, raise_for, schema_range

_lib_ = _lib.lib
_INDEX = {'%s.%s' % (_lib.text(k.section), _lib.text(k.key)): i for i, k in enumerate(_lib.SCHEMA)}


class Key:
    """One key of the schema (geardyn keys): name 'section.key', type (as geardyn keys names it),
    unit, valid (the valid values as text), low and high (numbers; open_low/open_high: the bound
    excluded), choices (choice and on/off keys), default (None when derived from other keys) and
    help."""
    __slots__ = ('name', 'section', 'key', 'type', 'unit', 'valid', 'low', 'high', 'open_low', 'open_high',
                 'choices', 'default', 'help')

    def __repr__(self):
        return '<geardyn.Key %s%s: %s, valid %s, default %r>' % (
            self.name, ' (%s)' % self.unit if self.unit else '', self.type, self.valid, self.default)


def _check(code, err):
    if code != 0:
        raise_for(code, err)


def _spec(name):
    """(index, gd_keyspec) of 'section.key'; an unknown key raises the library's message."""
    i = _INDEX.get(name) if isinstance(name, str) else None
    if i is None:
        err = _lib.Error_t()
        v = _lib.c_double()
        code = _lib_.gd_case_get_number(None, str(name).encode('utf-8'), _lib.byref(v), _lib.byref(err))
        raise_for(code or _lib.GD_ERR_INPUT, err)
    return i, _lib.SCHEMA[i]


def _format_value(value, ktype):
    """value as the text of a case file (or --set)."""
    if isinstance(value, bool):
        return 'on' if value else 'off'
    if isinstance(value, float):
        return repr(float(value))  # the shortest text that reads back to the same double
    if isinstance(value, (list, tuple)) or (ktype == 'list of numbers' and hasattr(value, '__iter__')
                                            and not isinstance(value, str)):
        return ', '.join(repr(float(v)) for v in value)
    if hasattr(value, 'item') and not isinstance(value, str):  # numpy scalars
        return _format_value(value.item(), ktype)
    return str(value)


class Case:
    """A case of geardyn: Case() has every default, Case.load(path) reads a case file,
    Case.from_text(text) the text of one; case.set(key, value) and case[key] = value change a key
    as --set does; case[key] reads it; case.check() is geardyn check; geardyn.run(case) runs it."""

    def __init__(self, _ptr=None, _sets=0, _path=''):
        if _ptr is None:
            err = _lib.Error_t()
            _ptr = _lib_.gd_case_new(_lib.byref(err))
            if not _ptr:
                raise_for(err.code or 3, err)
        self._ptr = _ptr
        self._sets = _sets
        self._path = _path

    def __del__(self):
        ptr, self._ptr = getattr(self, '_ptr', None), None
        if ptr and _lib_ is not None:
            _lib_.gd_case_delete(ptr)

    @classmethod
    def load(cls, path):
        """Read the case file path over the defaults (every line checked as geardyn run checks it)."""
        c = cls()
        err = _lib.Error_t()
        _check(_lib_.gd_case_load(c._ptr, os.fsencode(path), _lib.byref(err)), err)
        c._path = os.fsdecode(path)
        return c

    @classmethod
    def from_text(cls, text, name='<text>'):
        """Read the text of a case file (str or bytes); name stands for the file in messages."""
        data = text.encode('utf-8') if isinstance(text, str) else bytes(text)
        c = cls()
        err = _lib.Error_t()
        _check(_lib_.gd_case_load_text(c._ptr, data, len(data), name.encode('utf-8'), _lib.byref(err)), err)
        c._path = name
        return c

    def copy(self):
        err = _lib.Error_t()
        p = _lib_.gd_case_dup(self._ptr, _lib.byref(err))
        if not p:
            raise_for(err.code or 3, err)
        return Case(p, self._sets, self._path)

    __copy__ = copy

    def set(self, key, value):
        """Set key ('section.key') to value as `--set section.key=value` does: a number, a string, a
        bool for on/off keys, a sequence of numbers for a list; the library parses and checks it
        (CaseError with its message, naming the set '--set #N' in the order of this case's sets)."""
        i = _INDEX.get(key)  # an unknown key is the library's to refuse, as --set's
        text = _format_value(value, _lib.KEY_TYPES[_lib.SCHEMA[i].type] if i is not None else None)
        err = _lib.Error_t()
        self._sets += 1
        _check(_lib_.gd_case_set(self._ptr, ('%s=%s' % (key, text)).encode('utf-8'), self._sets - 1,
                                 _lib.byref(err)), err)
        return self

    __setitem__ = set

    def update(self, values=(), **kw):
        """set() each key of a mapping (or of key=value pairs)."""
        for k, v in dict(values, **kw).items():
            self.set(k, v)
        return self

    def __getitem__(self, key):
        """The value of key: float, int, bool (on/off), str (choices, text) or a list of floats."""
        i, k = _spec(key)
        t = _lib.KEY_TYPES[k.type]
        err = _lib.Error_t()
        if t in ('number', 'integer'):
            v = _lib.c_double()
            _check(_lib_.gd_case_get_number(self._ptr, key.encode(), _lib.byref(v), _lib.byref(err)), err)
            return int(v.value) if t == 'integer' else v.value
        if t == 'list of numbers':
            buf = (_lib.c_double * 256)()
            n = _lib.c_int()
            _check(_lib_.gd_case_get_list(self._ptr, key.encode(), buf, 256, _lib.byref(n), _lib.byref(err)), err)
            return [buf[j] for j in range(min(n.value, 256))]
        s = self._formatted(i)
        return s == 'on' if t == 'on/off' else s

    def get(self, key, default=None):
        try:
            return self[key]
        except CaseError:
            return default

    def _formatted(self, i):
        buf = _lib.ctypes.create_string_buffer(4096)
        _lib_.gd_case_format_value(self._ptr, i, buf, len(buf))
        return buf.value.decode('utf-8')

    def source(self, key):
        """Where the value of key comes from: ('default', None), ('file', line), ('set', n),
        ('derived', None) (derived values are filled by check() and run())."""
        i, _ = _spec(key)
        line = _lib.c_int()
        s = _lib.SOURCES[_lib_.gd_case_source(self._ptr, i, _lib.byref(line))]
        return s, (line.value if s in ('file', 'set') else None)

    def keys(self):
        return list(_INDEX)

    def __iter__(self):
        return iter(_INDEX)

    def __contains__(self, key):
        return key in _INDEX

    def items(self):
        return [(k, self[k]) for k in _INDEX]

    @property
    def path(self):
        """The case file it was read from (or the name given to from_text), '' for none."""
        return self._path

    @property
    def analysis(self):
        return self['scene.analysis']

    def check(self):
        """geardyn check: the case resolved (without LTCA, as check does), its derived values, its
        model's modes and the estimated cost of its run, as a dict ('case', 'derived', 'cost');
        CaseError as geardyn check refuses it."""
        err = _lib.Error_t()
        out = _lib.c_void_p()
        _check(_lib_.gd_case_check_json(self._ptr, _lib.byref(out), _lib.byref(err)), err)
        try:
            return json.loads(_lib.ctypes.string_at(out.value).decode('utf-8'))
        finally:
            _lib_.gd_free(out)

    def run(self, out=None, **kw):
        """geardyn.run(self, out, ...)."""
        from ._run import run
        return run(self, out, **kw)

    def __repr__(self):
        return '<geardyn.Case %s%s>' % (self['scene.analysis'], ' from %s' % self.path if self.path else '')


def keys():
    """The schema: every key a case may set, in the order of geardyn keys, as {name: Key}."""
    defaults = Case()
    out = {}
    for name, i in _INDEX.items():
        k = _lib.SCHEMA[i]
        e = Key()
        e.name, e.section, e.key = name, _lib.text(k.section), _lib.text(k.key)
        e.type, e.unit, e.help = _lib.KEY_TYPES[k.type], _lib.text(k.unit), _lib.text(k.help)
        e.valid = schema_range(k)
        numeric = e.type in ('number', 'integer', 'list of numbers')
        e.low, e.high = (k.min, k.max) if numeric else (None, None)
        e.open_low, e.open_high = (bool(k.min_open), bool(k.max_open)) if numeric else (False, False)
        e.choices = _lib.text(k.choices).split('|') if e.type in ('choice', 'on/off') else None
        derived = (e.type == 'number' and math.isnan(k.default)) or defaults.source(name)[0] == 'derived'
        e.default = None if derived else defaults[name]
        out[name] = e
    return out
