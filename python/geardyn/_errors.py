"""The exceptions of the module: the library's status and message, and for bad input the key, the
file and line (or the --set number) and the valid range read from the message, whose form the
library keeps for every refusal: `FILE:LINE: section.key: problem (valid: ...)`."""
import re

from . import _lib


class Error(Exception):
    """A run or a call of libgeardyn failed: status (its gd_status name, e.g. 'GD_ERR_SOLVER'), code
    (the number) and message (the library's, as the command line prints it after 'geardyn: ')."""

    def __init__(self, code, message):
        super().__init__(message)
        self.code = code
        self.status = _lib.STATUS[code] if 0 <= code < len(_lib.STATUS) else str(code)
        self.message = message


class CaseError(Error, ValueError):
    """Bad input (status GD_ERR_INPUT or GD_ERR_GEOMETRY: the command line's exit status 2). key is
    'section.key' (or '[section]', or None), file and line where the value came from (file None and
    where '--set #N' for a Case.set), valid the valid values (from the message, else the schema's
    range), message the library's text, unchanged."""

    def __init__(self, code, message):
        super().__init__(code, message)
        self.key, self.file, self.line, self.where, self.valid = _parse(message)


class Interrupted(Error):
    """The run was stopped by its progress callback (GD_ERR_INTERRUPTED); nothing was published."""


_KEY = re.compile(r'^(\[[^\]]*\]|[A-Za-z_][A-Za-z0-9_]*\.[A-Za-z0-9_]+)$')
_BARE = re.compile(r'^[A-Za-z_][A-Za-z0-9_]*$')
_FILELINE = re.compile(r'^(.*):(\d+)$')
_SET = re.compile(r'^--set #\d+$')
_UNKNOWN_IN = re.compile(r'^unknown key in \[([^\]]+)\]')


def _valid_clause(msg):
    """The text of the last '(valid: ...)' clause: up to the message's last ')' (a range inside it
    may be half open: '(0, 100000]')."""
    i = msg.rfind('(valid: ')
    if i < 0:
        return None
    j = msg.rfind(')')
    return msg[i + len('(valid: '):j if j > i else len(msg)]


def schema_range(k):
    """The valid values of a schema entry, as geardyn keys writes them."""
    t = _lib.KEY_TYPES[k.type]
    if t in ('number', 'integer', 'list of numbers'):
        return '%s%.6g, %.6g%s' % ('(' if k.min_open else '[', k.min, k.max, ')' if k.max_open else ']')
    if t in ('choice', 'on/off'):
        return ', '.join(_lib.text(k.choices).split('|'))
    return 'any text'


def _parse(msg):
    parts = msg.split(': ')
    key = file = line = where = None
    i = 0
    if parts and _SET.match(parts[0]):
        where, i = parts[0], 1
    elif parts and _FILELINE.match(parts[0]) and len(parts) > 1:
        m = _FILELINE.match(parts[0])
        file, line, where, i = m.group(1), int(m.group(2)), parts[0], 1
    elif len(parts) > 1 and not _KEY.match(parts[0]):
        file = where = parts[0]
        i = 1
    if i < len(parts) - 1 or (i < len(parts) and _KEY.match(parts[i])):
        tok = parts[i]
        if _KEY.match(tok):
            key = tok
        elif where is not None and _BARE.match(tok):
            m = _UNKNOWN_IN.match(parts[i + 1]) if i + 1 < len(parts) else None
            key = '%s.%s' % (m.group(1), tok) if m else tok
    valid = _valid_clause(msg)
    if valid is None and key and '.' in key and not key.startswith('['):
        sec, _, k = key.partition('.')
        spec = _lib.lib.gd_case_find_key(sec.encode(), k.encode())
        if spec:
            valid = schema_range(spec.contents)
    return key, file, line, where, valid


def raise_for(code, err):
    """Raise the exception of a failed call (code, the gd_error it filled)."""
    msg = err.msg.decode('utf-8', 'replace')
    if code in (_lib.GD_ERR_INPUT, _lib.GD_ERR_GEOMETRY):
        raise CaseError(code, msg)
    if code == _lib.GD_ERR_INTERRUPTED:
        raise Interrupted(code, msg)
    raise Error(code, msg)
