"""The result of a run: summary.json as a dict and every CSV table as a numpy structured array,
parsed from the run's files (the bytes geardyn run writes), whether they come from a run in
memory (geardyn.run) or from a finished run's directory (geardyn.read). The tables are read from
their headers: a column whose cells are numbers (nan and inf included) or empty (a value the
run has not: nan) is float64, any other column str, and so is a column with no value at all;
nothing here knows the columns of an analysis."""
import csv
import errno
import io
import json
import os

import numpy as np

from . import _lib
from ._errors import Error, raise_for


def parse_table(data):
    """A CSV file of geardyn (bytes) as a structured array named by its header."""
    text = data.decode('utf-8')
    rows = list(csv.reader(io.StringIO(text, newline='')))
    if not rows:
        return np.zeros(0, dtype=[])
    header = rows[0]
    body = rows[1:]
    width = len(header)
    for r, row in enumerate(body, 2):
        if len(row) != width:
            raise Error(_lib.GD_ERR_INPUT, 'line %d: %d fields under a header of %d' % (r, len(row), width))
    names, seen = [], {}
    for h in header:  # a repeated name (none is written today) gets a suffix rather than failing
        n = h if h not in seen else '%s_%d' % (h, seen[h])
        seen[h] = seen.get(h, 0) + 1
        names.append(n)
    columns = []
    for j in range(width):
        cells = [row[j] for row in body]
        try:
            if not any(cells):
                raise ValueError('no value: a column of text')
            col = np.array([float(c) if c else np.nan for c in cells], dtype=np.float64)
        except ValueError:
            col = np.array(cells, dtype=str)
        columns.append(col)
    dtype = [(n, c.dtype) for n, c in zip(names, columns)]
    out = np.empty(len(body), dtype=dtype)
    for n, c in zip(names, columns):
        out[n] = c
    return out


PICTURES = ('.png', '.svg', '.pdf', '.eps')


def is_picture(name):
    """A picture the command line drew (gnuplot): listed, not read."""
    return name.lower().endswith(PICTURES)


def _same_table(a, b, ignore=()):
    if a.dtype.names != b.dtype.names or a.shape != b.shape:
        return False
    for n in a.dtype.names:
        if n in ignore:
            continue
        x, y = a[n], b[n]
        if x.dtype.kind == 'f' or y.dtype.kind == 'f':
            if x.dtype != y.dtype or not np.array_equal(x.view(np.uint64), y.view(np.uint64)):
                return False  # bit for bit: nan and -0 included
        elif not np.array_equal(x, y):
            return False
    return True


class Result:
    """A run's results. summary: summary.json as a dict; tables: {name: structured array} of every
    CSV file (name without .csv: 'time_history', 'sweep', 'branch', ...); json: the other JSON files;
    subruns: {name: Result} of the run's sub-directories (optimize: 'optimum', 'optimum-tca');
    files: the files summary.json lists, in its order; pictures: those that are pictures (drawn with
    gnuplot into the directory of a run with out=, as geardyn run draws them; not read); other:
    files of any other kind; notes: the run's notes (no pictures and why, pictures not drawn and
    why: the lines geardyn run prints as "geardyn: note: ..."; [] for a directory read);
    raw: {name: bytes} of every file read (all but the pictures);
    directory: where it was read from or written to (None for a run in memory). result[name] is a
    table ('time_history' or 'time_history.csv'), a sub-run's table ('optimum/lte') or a sub-run."""

    def __init__(self, files, directory=None, notes=()):
        self.directory = directory
        self.notes = list(notes)
        self.raw = dict(files)
        try:
            self.summary = json.loads(files['summary.json'].decode('utf-8'))
        except KeyError:
            raise Error(_lib.GD_ERR_INPUT, '%s: no summary.json (not a finished run of geardyn)' %
                        (directory or 'the run')) from None
        self.analysis = self.summary.get('analysis')
        self.files = list(self.summary.get('files', []))
        self.tables, self.json, self.subruns, self.pictures, self.other = {}, {}, {}, [], []
        for name in self.files:
            if name.endswith('/'):
                sub = name[:-1]
                pre = sub + '/'
                self.subruns[sub] = Result({k[len(pre):]: v for k, v in files.items() if k.startswith(pre)},
                                           os.path.join(directory, sub) if directory else None)
            elif name.endswith('.csv'):
                self.tables[name[:-4]] = parse_table(files[name])
            elif name.endswith('.json') and name != 'summary.json':
                self.json[name] = json.loads(files[name].decode('utf-8'))
            elif is_picture(name):
                self.pictures.append(name)
            elif name != 'summary.json':
                self.other.append(name)   # a file of another kind: its bytes are in raw

    def __getitem__(self, name):
        if '/' in name:
            sub, _, rest = name.partition('/')
            return self.subruns[sub][rest] if rest else self.subruns[sub]
        if name in self.subruns:
            return self.subruns[name]
        return self.tables[name[:-4] if name.endswith('.csv') else name]

    def __contains__(self, name):
        try:
            self[name]
            return True
        except KeyError:
            return False

    def keys(self):
        return list(self.tables)

    def grid(self, column='label', table='basins'):
        """A table of cells (columns i and j, then the cell centre's two coordinates, as basins.csv
        is) as a picture: (x, y, values), x the nx centres along i, y the ny centres along j,
        values[j, i] the column's value of cell (i, j), an array of shape (ny, nx) (nan, or '' for a
        column of text, where a cell has no row). result.grid() is the basins' labels;
        result.grid('outcome') their names. The names of the coordinates are
        result[table].dtype.names[2:4]."""
        t = self[table]
        names = t.dtype.names
        if not names or names[:2] != ('i', 'j') or len(names) < 4:
            raise KeyError('%s: not a table of cells (columns i, j, x, y, ...)' % table)
        i, j = t['i'].astype(np.intp), t['j'].astype(np.intp)
        nx = int(i.max()) + 1 if len(t) else 0
        ny = int(j.max()) + 1 if len(t) else 0
        col = t[column]
        values = np.full((ny, nx), np.nan) if col.dtype.kind == 'f' else np.full((ny, nx), '', dtype=col.dtype)
        values[j, i] = col
        x, y = np.full(nx, np.nan), np.full(ny, np.nan)
        x[i], y[j] = t[names[2]], t[names[3]]
        return x, y, values

    def equals(self, other, ignore=()):
        """Equal summaries and pictures, every table and sub-run equal bit for bit; but the keys of
        summary.json (at any depth) and the columns named in ignore (times: two runs of one case
        differ in nothing else)."""
        def strip(o):
            if isinstance(o, dict):
                return {k: strip(v) for k, v in o.items() if k not in ignore}
            if isinstance(o, list):
                return [strip(v) for v in o]
            return o
        return (isinstance(other, Result) and strip(self.summary) == strip(other.summary)
                and self.json == other.json and self.pictures == other.pictures
                and self.other == other.other and all(self.raw.get(n) == other.raw.get(n) for n in self.other)
                and set(self.tables) == set(other.tables)
                and all(_same_table(self.tables[k], other.tables[k], ignore) for k in self.tables)
                and set(self.subruns) == set(other.subruns)
                and all(self.subruns[k].equals(other.subruns[k], ignore) for k in self.subruns))

    def __eq__(self, other):
        return self.equals(other)

    __hash__ = None

    def __repr__(self):
        return '<geardyn.Result %s: %s%s>' % (self.analysis, ', '.join(self.tables) or 'no tables',
                                               '; ' + ', '.join(s + '/' for s in self.subruns) if self.subruns else '')


def _read_files(fd, prefix, out):
    """summary.json and every file it lists, through the directory's descriptor fd."""
    def rd(name):
        f = os.open(name, os.O_RDONLY | os.O_CLOEXEC, dir_fd=fd)
        with os.fdopen(f, 'rb') as fp:
            return fp.read()
    s = rd('summary.json')
    out[prefix + 'summary.json'] = s
    for name in json.loads(s.decode('utf-8')).get('files', []):
        if name.endswith('/'):
            sub = os.open(name[:-1], os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC, dir_fd=fd)
            try:
                _read_files(sub, prefix + name, out)
            finally:
                os.close(sub)
        elif name != 'summary.json' and not is_picture(name):
            out[prefix + name] = rd(name)


def read(directory):
    """A finished run's directory (any analysis, written by geardyn run or geardyn.run) as a
    Result. Every file is read through one handle of the directory, so that a run published into
    it meanwhile (an exchange of the whole directory) cannot mix two sets: the read starts again."""
    directory = os.fspath(directory)
    for attempt in range(5):
        fd = os.open(directory, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)
        try:
            files = {}
            _read_files(fd, '', files)
            return Result(files, directory)
        except FileNotFoundError as e:
            if e.filename == 'summary.json' or attempt == 4:
                raise Error(_lib.GD_ERR_INPUT, '%s: %s: no such file (not a finished run of geardyn)' %
                            (directory, e.filename)) from None
            # the directory was exchanged under us by a new publication: read the new one
        finally:
            os.close(fd)


KINDS = ('contact', 'separation', 'back-contact', 'back-separation')


def events(path, t_from=None, t_to=None, clearance=None, kind=None, recorded=False):
    """The event log path (an events.csv, or a run directory holding one) as a structured array,
    with the filters of geardyn events: the rows with t_from <= t_s <= t_to, of one clearance
    ('mesh-L', 'bearing-1R', ...), of one kind (contact, separation, back-contact,
    back-separation), of the recorded window only. The library reads and checks the log
    (gd_eventlog_select): CaseError for a file that is not an event log, a clearance it lacks, or
    a time window that selects nothing (the message names t_from and t_to as geardyn events' --from
    and --to)."""
    path = os.fspath(path)
    if os.path.isdir(path) and os.path.isfile(os.path.join(path, 'events.csv')):
        path = os.path.join(path, 'events.csv')
    if kind is not None and kind not in KINDS:
        raise ValueError("kind: '%s' (valid: %s)" % (kind, ', '.join(KINDS)))
    f = _lib.EventlogFilter()
    f.t_from_s = float('-inf') if t_from is None else float(t_from)
    f.t_to_s = float('inf') if t_to is None else float(t_to)
    f.clearance = (clearance or '').encode('utf-8')[:31]
    f.kind = (kind or '').encode('utf-8')
    f.recorded_only = 1 if recorded else 0
    err = _lib.Error_t()
    buf = _lib.c_void_p()
    n = _lib.c_size_t()
    code = _lib.lib.gd_eventlog_select(os.fsencode(path), _lib.byref(f), _lib.byref(buf), _lib.byref(n), None,
                                       _lib.byref(err))
    if code != 0:
        raise_for(code, err)
    try:
        data = _lib.ctypes.string_at(buf.value, n.value)
    finally:
        _lib.lib.gd_free(buf)
    return parse_table(data)
