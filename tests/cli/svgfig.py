"""A gnuplot SVG read back as a figure: its panels (frames), the plots drawn in each (their data
points, curves, markers, fills and key entries), the texts with their extents, and the checks a
reader's eye makes of a figure (tests/cli/test_pictures.py runs them on every picture of every
shipped case). Python standard library only.

What gnuplot's SVG terminal writes and this module relies on:
  * every plot is a <g id="gnuplot_plot_N"> (in a multiplot "gnuplot_plot_Nx", x the panel's letter)
    whose <title> is the plot's key entry when it has one; its key text is a <text> inside it and
    its key sample (a short line or one marker) sits beside that text;
  * a panel's frame is a closed black rectangle (the border) drawn outside the plot groups;
  * texts are <g transform="translate(x,y) [rotate(a)]" font-size=.. text-anchor=..><text>, the
    point being the baseline's anchor; sub- and superscripts are <tspan>s with a dy.
Text extents use the advance widths of the font gnuplot draws with (DejaVu Sans when installed,
read from its TrueType tables), so that two labels that touch are seen to touch.
"""
import math
import os
import re
import struct
import subprocess
import xml.etree.ElementTree as ET

SVG = '{http://www.w3.org/2000/svg}'
XLINK = '{http://www.w3.org/1999/xlink}'


# ---------------------------------------------------------------- font metrics

class Font:
    """Advance widths (in em) of a TrueType font's characters: cmap format 4, hhea, hmtx."""

    def __init__(self, path=None):
        self.widths = {}
        self.default = 0.6
        if path is None:
            try:
                path = subprocess.run(['fc-match', '-f', '%{file}', 'sans'], capture_output=True,
                                      text=True, timeout=20).stdout.strip()
            except (OSError, subprocess.SubprocessError):
                path = ''
        try:
            self._load(path)
        except (OSError, struct.error, KeyError, ValueError):
            self.widths = {}

    def _load(self, path):
        data = open(path, 'rb').read()
        ntab = struct.unpack('>H', data[4:6])[0]
        tabs = {}
        for i in range(ntab):
            tag, _, off, ln = struct.unpack('>4sIII', data[12 + 16 * i:28 + 16 * i])
            tabs[tag.decode('latin-1')] = (off, ln)
        upem = struct.unpack('>H', data[tabs['head'][0] + 18:tabs['head'][0] + 20])[0]
        nhm = struct.unpack('>H', data[tabs['hhea'][0] + 34:tabs['hhea'][0] + 36])[0]
        hm = tabs['hmtx'][0]
        adv = [struct.unpack('>H', data[hm + 4 * i:hm + 4 * i + 2])[0] for i in range(nhm)]
        co = tabs['cmap'][0]
        n = struct.unpack('>H', data[co + 2:co + 4])[0]
        sub = None
        for i in range(n):
            pid, eid, off = struct.unpack('>HHI', data[co + 4 + 8 * i:co + 12 + 8 * i])
            fmt = struct.unpack('>H', data[co + off:co + off + 2])[0]
            if fmt == 4 and (pid, eid) in ((3, 1), (0, 3), (0, 4), (3, 10)):
                sub = co + off
                break
        if sub is None:
            return
        segx2 = struct.unpack('>H', data[sub + 6:sub + 8])[0]
        seg = segx2 // 2
        ends = struct.unpack('>%dH' % seg, data[sub + 14:sub + 14 + segx2])
        starts = struct.unpack('>%dH' % seg, data[sub + 16 + segx2:sub + 16 + 2 * segx2])
        deltas = struct.unpack('>%dh' % seg, data[sub + 16 + 2 * segx2:sub + 16 + 3 * segx2])
        ro_at = sub + 16 + 3 * segx2
        offs = struct.unpack('>%dH' % seg, data[ro_at:ro_at + segx2])
        for s in range(seg):
            for c in range(starts[s], min(ends[s], 0x2400) + 1):
                if offs[s] == 0:
                    g = (c + deltas[s]) & 0xFFFF
                else:
                    p = ro_at + 2 * s + offs[s] + 2 * (c - starts[s])
                    g = struct.unpack('>H', data[p:p + 2])[0]
                    if g:
                        g = (g + deltas[s]) & 0xFFFF
                if g:
                    self.widths[chr(c)] = adv[min(g, nhm - 1)] / upem

    def width(self, s, size):
        return sum(self.widths.get(ch, self.default) for ch in s) * size


FONT = Font()


# ---------------------------------------------------------------- geometry helpers

def parse_transform(t):
    """translate(x,y) [rotate(a)] [scale(s)] of gnuplot's SVG: (x, y, angle, scale)."""
    x = y = a = 0.0
    s = 1.0
    for name, args in re.findall(r'(\w+)\(([^)]*)\)', t or ''):
        v = [float(u) for u in re.split(r'[ ,]+', args.strip()) if u]
        if name == 'translate':
            x, y = v[0], v[1] if len(v) > 1 else 0.0
        elif name == 'rotate':
            a = v[0]
        elif name == 'scale':
            s = v[0]
    return x, y, a, s


def parse_path(d):
    """The subpaths of an SVG path (absolute and relative M, L, H, V, Z): [(points, closed)]."""
    subs, cur, x, y, start = [], None, 0.0, 0.0, (0.0, 0.0)
    for cmd, args in re.findall(r'([MmLlHhVvZz])([^MmLlHhVvZz]*)', d or ''):
        nums = [float(u) for u in re.findall(r'-?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?|-?\.\d+', args)]
        if cmd in 'Zz':
            if cur is not None:
                subs.append((cur, True))
                x, y = start
            cur = None
            continue
        if cmd in 'Mm':
            if cur is not None:
                subs.append((cur, False))
            pairs = list(zip(nums[0::2], nums[1::2]))
            for i, (a, b) in enumerate(pairs):
                if cmd == 'm':
                    x, y = x + a, y + b
                else:
                    x, y = a, b
                if i == 0:
                    cur, start = [(x, y)], (x, y)
                else:
                    cur.append((x, y))
        elif cmd in 'Ll':
            for a, b in zip(nums[0::2], nums[1::2]):
                x, y = (x + a, y + b) if cmd == 'l' else (a, b)
                cur.append((x, y))
        elif cmd in 'Hh':
            for a in nums:
                x = x + a if cmd == 'h' else a
                cur.append((x, y))
        elif cmd in 'Vv':
            for b in nums:
                y = y + b if cmd == 'v' else b
                cur.append((x, y))
    if cur is not None:
        subs.append((cur, False))
    return subs


def parse_colour(c, inherited=None):
    if c is None or c == 'currentColor':
        return inherited
    c = c.strip()
    m = re.match(r'rgb\(\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*\)', c)
    if m:
        return tuple(int(u) for u in m.groups())
    m = re.match(r'#([0-9a-fA-F]{6})$', c)
    if m:
        return tuple(int(m.group(1)[i:i + 2], 16) for i in (0, 2, 4))
    named = {'black': (0, 0, 0), 'white': (255, 255, 255), 'gray': (190, 190, 190), 'grey': (190, 190, 190),
             'lightgrey': (211, 211, 211)}
    if c in named:
        return named[c]
    return None if c == 'none' else (0, 0, 0)


class Box:
    def __init__(self, x0, y0, x1, y1):
        self.x0, self.y0, self.x1, self.y1 = min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1)

    @property
    def w(self):
        return self.x1 - self.x0

    @property
    def h(self):
        return self.y1 - self.y0

    def inside(self, x, y, tol=0.0):
        return self.x0 + tol < x < self.x1 - tol and self.y0 + tol < y < self.y1 - tol

    def contains(self, x, y, tol=0.0):
        return self.x0 - tol <= x <= self.x1 + tol and self.y0 - tol <= y <= self.y1 + tol

    def overlaps(self, o, shrink=0.0):
        return (self.x0 + shrink < o.x1 - shrink and o.x0 + shrink < self.x1 - shrink and
                self.y0 + shrink < o.y1 - shrink and o.y0 + shrink < self.y1 - shrink)

    def grow(self, d):
        return Box(self.x0 - d, self.y0 - d, self.x1 + d, self.y1 + d)

    def union(self, o):
        return Box(min(self.x0, o.x0), min(self.y0, o.y0), max(self.x1, o.x1), max(self.y1, o.y1))

    def __repr__(self):
        return '[%.0f..%.0f x %.0f..%.0f]' % (self.x0, self.x1, self.y0, self.y1)


def segment_hits_box(a, b, box):
    """Whether the segment a-b meets the inside of box (Liang-Barsky)."""
    (x0, y0), (x1, y1) = a, b
    dx, dy = x1 - x0, y1 - y0
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, x0 - box.x0), (dx, box.x1 - x0), (-dy, y0 - box.y0), (dy, box.y1 - y0)):
        if p == 0:
            if q <= 0:
                return False
        else:
            r = q / p
            if p < 0:
                t0 = max(t0, r)
            else:
                t1 = min(t1, r)
            if t0 >= t1:
                return False
    return True


# ---------------------------------------------------------------- the figure

class Text:
    def __init__(self, x, y, angle, size, anchor, s, plot, sizes):
        self.x, self.y, self.angle, self.size, self.anchor, self.s, self.plot = x, y, angle, size, anchor, s, plot
        w = sum(FONT.width(part, sz) for part, sz in sizes)
        asc, desc = 0.76 * size, 0.24 * size
        off = {'start': 0.0, 'middle': -0.5, 'end': -1.0}.get(anchor, 0.0) * w
        if abs(angle % 360 - 270) < 1 or abs(angle % 360 - 90) < 1:
            # rotated by -90 (or 90): the text runs upwards (downwards) from its anchor
            sgn = -1 if abs(angle % 360 - 270) < 1 else 1
            a0, a1 = y + sgn * off, y + sgn * (off + w)
            self.box = Box(x - asc, min(a0, a1), x + desc, max(a0, a1)) if sgn < 0 else \
                Box(x - desc, min(a0, a1), x + asc, max(a0, a1))
            self.rotated = True
        else:
            self.box = Box(x + off, y - asc, x + off + w, y + desc)
            self.rotated = False
        self.number = parse_number(s)

    def __repr__(self):
        return '%r at (%.0f, %.0f)' % (self.s, self.x, self.y)


def parse_number(s):
    """The value of a tick label ('2500', '-0.25', '1e-05', '10^-5' of '10^{%L}'), else None."""
    t = s.strip().replace('\u2212', '-').replace(' ', '')
    m = re.match(r'^10\^(-?\d+)$', t)
    if m:
        return 10.0 ** int(m.group(1))
    m = re.match(r'^(-?\d+(?:\.\d+)?)x10\^(-?\d+)$', t)
    if m:
        return float(m.group(1)) * 10.0 ** int(m.group(2))
    if re.match(r'^-?(\d+(\.\d*)?|\.\d+)([eE][-+]?\d+)?$', t):
        return float(t)
    return None


def significant_digits(s):
    """Significant digits of a tick label as written (trailing zeros of an integer not counted)."""
    t = s.strip().replace('\u2212', '-').lstrip('-')
    if '^' in t:
        t = t.split('x10^')[0] if 'x10^' in t else '1'
    t = re.split(r'[eE]', t)[0]
    digits = t.replace('.', '').lstrip('0')
    if '.' not in t:
        digits = digits.rstrip('0')
    return len(digits)


def png_colours(href):
    """The colours (r, g, b) of an image embedded as a PNG (data:image/png;base64): 8-bit RGB or RGBA,
    not interlaced, as gnuplot writes them; an empty set for anything else."""
    import base64
    import zlib
    m = re.match(r'data:image/png;base64,(.*)$', href.strip(), re.S)
    if not m:
        return set()
    try:
        data = base64.b64decode(re.sub(r'\s+', '', m.group(1)))
        pos, idat, hdr = 8, b'', None
        while pos < len(data):
            n, kind = struct.unpack('>I4s', data[pos:pos + 8])
            body = data[pos + 8:pos + 8 + n]
            if kind == b'IHDR':
                hdr = struct.unpack('>IIBBBBB', body)
            elif kind == b'IDAT':
                idat += body
            pos += 12 + n
        w, h, depth, ctype, _, _, interlace = hdr
        if depth != 8 or ctype not in (2, 6) or interlace:
            return set()
        bpp = 3 if ctype == 2 else 4
        raw = zlib.decompress(idat)
        stride = w * bpp
        prev = bytearray(stride)
        out = set()
        for r in range(h):
            f = raw[r * (stride + 1)]
            line = bytearray(raw[r * (stride + 1) + 1:(r + 1) * (stride + 1)])
            for i in range(stride):
                a = line[i - bpp] if i >= bpp else 0
                b = prev[i]
                c = prev[i - bpp] if i >= bpp else 0
                if f == 1:
                    line[i] = (line[i] + a) & 255
                elif f == 2:
                    line[i] = (line[i] + b) & 255
                elif f == 3:
                    line[i] = (line[i] + (a + b) // 2) & 255
                elif f == 4:
                    pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                    line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
            for i in range(0, stride, bpp):
                if bpp == 3 or line[i + 3] > 0:
                    out.add((line[i], line[i + 1], line[i + 2]))
            prev = line
        return out
    except (ValueError, TypeError, struct.error, zlib.error):
        return set()


class Element:
    """A drawn element of a plot: a path (subpaths), markers (use), an image or a filled area."""

    def __init__(self, kind, subpaths, colour, dash, width, marker=None, fill=None, opacity=1.0):
        self.kind, self.subpaths, self.colour, self.dash, self.width = kind, subpaths, colour, dash, width
        self.marker, self.fill, self.opacity = marker, fill, opacity
        self.colours = set()       # an image's colours

    def points(self):
        for pts, _ in self.subpaths:
            for p in pts:
                yield p


class Plot:
    def __init__(self, pid):
        self.id = pid
        m = re.match(r'gnuplot_plot_(\d+)([a-z]*)$', pid)
        self.panel_key = m.group(2) if m else ''
        self.title = None
        self.elements = []         # the data drawn
        self.key_texts = []        # the key entry's text(s)
        self.key_samples = []      # the key entry's sample
        self.labels = []           # texts drawn as data ('with labels')
        self.order = 0

    def data_points(self):
        for e in self.elements:
            yield from e.points()

    def style(self):
        """(colour, dash, marker) of the plot: what tells it apart in a key."""
        for e in self.key_samples + self.elements:
            return (e.colour if e.kind != 'fill' else e.fill, e.dash or '', e.marker or '')
        return None

    def look(self):
        """(colour, dash, marker shape) of the plot as its key shows it: a line's dash and a
        marker's shape together (style() gives the first sample's alone)."""
        els = self.key_samples or self.elements
        if not els:
            return None
        e = els[0]
        colour = e.colour if e.kind != 'fill' else e.fill
        dash = next((x.dash or '' for x in els if x.kind == 'path'), '')
        marker = next(((x.marker or '').split('@')[0] for x in els if x.kind == 'use'), '')
        return colour, dash, marker


class Panel:
    def __init__(self, key, frame):
        self.key, self.frame, self.plots = key, frame, []
        self.xlabel = self.ylabel = self.x2label = self.y2label = self.title = None
        self.ticks = {'left': [], 'right': [], 'bottom': [], 'top': []}


class Figure:
    def __init__(self, path):
        self.path = path
        self.name = os.path.basename(path)
        tree = ET.parse(path)
        root = tree.getroot()
        vb = [float(v) for v in (root.get('viewBox') or '0 0 0 0').split()]
        self.width, self.height = vb[2], vb[3]
        self.texts = []            # every text
        self.loose = []            # elements drawn outside plot groups: (element, order)
        self.plots = {}
        self._order = 0
        self._walk(root, {'color': None, 'stroke': None, 'fill': None, 'font-size': '11', 'text-anchor': 'start',
                          'stroke-dasharray': None, 'stroke-width': '1', 'fill-opacity': '1'}, None, None)
        self._panels()

    # -- reading
    def _walk(self, el, inh, plot, xf):
        tag = el.tag.replace(SVG, '')
        if tag in ('defs', 'title', 'desc', 'filter'):
            if tag == 'title' and plot is not None and plot.title is None:
                t = (el.text or '').strip()
                plot.title = None if re.match(r'^gnuplot_plot_\w+$', t) else t
            return
        a = dict(inh)
        for k in ('color', 'stroke', 'fill', 'font-size', 'text-anchor', 'stroke-dasharray', 'stroke-width',
                  'fill-opacity'):
            if el.get(k) is not None:
                a[k] = el.get(k)
        if tag in ('g', 'svg'):
            gid = el.get('id') or ''
            if gid.startswith('gnuplot_plot_'):
                plot = self.plots.get(gid)
                if plot is None:
                    plot = self.plots[gid] = Plot(gid)
                    plot.order = self._order
                self._order += 1
            tr = el.get('transform')
            if tr and el.find(SVG + 'text') is not None:
                self._text(el, a, plot, tr)
                return
            for ch in el:
                self._walk(ch, a, plot, xf)
            return
        self._order += 1
        colour = parse_colour(el.get('stroke'), parse_colour(a.get('stroke'), parse_colour(a.get('color'))))
        if tag == 'path':
            fill = el.get('fill')
            fillc = parse_colour(fill, parse_colour(a.get('color'))) if fill and fill != 'none' else None
            op = float(el.get('fill-opacity') or a.get('fill-opacity') or 1)
            e = Element('fill' if fillc else 'path', parse_path(el.get('d')), colour,
                        el.get('stroke-dasharray') or a.get('stroke-dasharray'),
                        float(el.get('stroke-width') or a.get('stroke-width') or 1), fill=fillc, opacity=op)
            if el.get('class') == 'gridline':
                return
            self._add(e, plot)
        elif tag == 'use':
            x, y, _, s = parse_transform(el.get('transform'))
            href = el.get(XLINK + 'href') or el.get('href') or ''
            c = parse_colour(el.get('color'), parse_colour(a.get('color')))
            e = Element('use', [([(x, y)], False)], c, None, 1.0, marker=href.lstrip('#') + '@%.2f' % s)
            e.size = s
            self._add(e, plot)
        elif tag == 'image':
            x, y = float(el.get('x', 0)), float(el.get('y', 0))
            w, h = float(el.get('width', 0)), float(el.get('height', 0))
            e = Element('image', [([(x, y), (x + w, y), (x + w, y + h), (x, y + h)], True)], None, None, 0)
            href = el.get(XLINK + 'href') or el.get('href') or ''
            e.colours = png_colours(href)
            self._add(e, plot)
        elif tag in ('polygon', 'polyline'):
            nums = [float(u) for u in re.findall(r'-?\d+(?:\.\d+)?', el.get('points') or '')]
            pts = list(zip(nums[0::2], nums[1::2]))
            fill = el.get('fill')
            fillc = parse_colour(fill, parse_colour(a.get('color'))) if fill and fill != 'none' else None
            e = Element('fill' if fillc else 'path', [(pts, tag == 'polygon')], colour, None, 1.0, fill=fillc,
                        opacity=float(el.get('fill-opacity') or a.get('fill-opacity') or 1))
            self._add(e, plot)
        elif tag == 'rect':
            return

    def _add(self, e, plot):
        e.order = self._order
        if plot is None:
            self.loose.append(e)
        else:
            plot.elements.append(e)

    def _text(self, g, a, plot, tr):
        x, y, ang, _ = parse_transform(tr)
        size = float(a.get('font-size') or 11)
        txt = g.find(SVG + 'text')
        parts = []
        if txt.text and txt.text.strip('\n\t'):
            parts.append((txt.text, size))
        s = txt.text or ''
        for ts in txt.iter(SVG + 'tspan'):
            sz = float(ts.get('font-size') or size)
            piece = ts.text or ''
            dy = ts.get('dy')
            if dy is not None and dy.replace('px', '').strip().startswith('-') and sz < size and piece:
                piece = '^' + piece
            s += piece
            parts.append((ts.text or '', sz))
            if ts.tail:
                s += ts.tail
                parts.append((ts.tail, size))
        t = Text(x, y, ang, size, a.get('text-anchor') or 'start', s.strip('\n\t'), plot, parts)
        t.order = self._order
        self._order += 1
        self.texts.append(t)
        if plot is not None:
            plot.labels.append(t)

    # -- structure
    def _panels(self):
        # frames: closed axis-parallel black rectangles outside the plots, large enough for a graph
        rects = []
        for e in self.loose:
            if e.kind != 'path' or e.colour not in ((0, 0, 0),):
                continue
            for pts, closed in e.subpaths:
                if not closed and not (len(pts) == 5 and pts[0] == pts[-1]):
                    continue
                xs, ys = {round(p[0], 1) for p in pts}, {round(p[1], 1) for p in pts}
                if len(pts) in (4, 5) and len(xs) == 2 and len(ys) == 2:
                    b = Box(min(xs), min(ys), max(xs), max(ys))
                    if b.w > 60 and b.h > 40:
                        rects.append(b)
        uniq = []
        for b in rects:
            if not any(abs(b.x0 - u.x0) < 0.5 and abs(b.y0 - u.y0) < 0.5 and abs(b.w - u.w) < 0.5 and
                       abs(b.h - u.h) < 0.5 for u in uniq):
                uniq.append(b)
        self.frames = uniq
        # key entries of each plot: its titled text and the sample beside it
        for p in self.plots.values():
            self._split_key(p)
        groups = {}
        for p in sorted(self.plots.values(), key=lambda q: q.order):
            groups.setdefault(p.panel_key, []).append(p)
        self.panels = []
        for key, plots in groups.items():
            pts = [q for p in plots for q in p.data_points()]
            best, bestn = None, -1
            for b in self.frames:
                n = sum(1 for (x, y) in pts if b.contains(x, y, 1.0))
                if n > bestn or (n == bestn and best is not None and b.w * b.h > best.w * best.h):
                    best, bestn = b, n
            if not pts:
                best = None
            panel = Panel(key, best)
            panel.plots = plots
            self.panels.append(panel)
        self._classify_texts()

    def _split_key(self, p):
        """The key entries of plot p: each text of its group with a sample beside it (or the
        plot's title), the sample taken out of the data."""
        for t in list(p.labels):
            if not t.s.strip():
                p.labels.remove(t)
                continue
            if self._take_sample(p, t) or (p.title and t.s.strip() == p.title.strip()):
                p.labels.remove(t)
                p.key_texts.append(t)
                t.key = True

    def _take_sample(self, p, t):
        # the sample: one short level line, one marker or one small filled box level with the text,
        # just beside it
        found = False
        if True:
            cy = t.y - 0.32 * t.size
            win = Box(t.box.x0 - 120, cy - 0.6 * t.size, t.box.x1 + 120, cy + 0.6 * t.size)
            taken = set()
            for e in p.elements:
                keep = []
                for pts, closed in e.subpaths:
                    xs, ys = [q[0] for q in pts], [q[1] for q in pts]
                    bb = Box(min(xs), min(ys), max(xs), max(ys))
                    kind = e.kind
                    ok = kind not in taken and win.contains(bb.x0, bb.y0) and win.contains(bb.x1, bb.y1) \
                        and not bb.overlaps(t.box)
                    if ok and kind == 'path':
                        ok = len(pts) == 2 and bb.h < 0.5 and bb.w > 5
                    elif ok and kind == 'fill':
                        ok = closed and bb.w < 60 and bb.h < 1.2 * t.size
                    elif ok and kind != 'use':
                        ok = False
                    if ok:
                        found = True
                        taken.add(kind)
                        p.key_samples.append(Element(kind, [(pts, closed)], e.colour, e.dash, e.width,
                                                     e.marker, e.fill, e.opacity))
                    else:
                        keep.append((pts, closed))
                e.subpaths = keep
            p.elements = [e for e in p.elements if e.subpaths]
        return found

    def _classify_texts(self):
        for t in self.texts:
            t.role = 'label' if t.plot is not None and not getattr(t, 'key', False) else \
                ('key' if getattr(t, 'key', False) else 'other')
        framed = [pn for pn in self.panels if pn.frame is not None]
        for t in self.texts:
            if t.role != 'other':
                continue
            # the panel whose frame is nearest
            best, bd = None, 1e18
            for pn in framed:
                f = pn.frame
                dx = max(f.x0 - t.x, 0, t.x - f.x1)
                dy = max(f.y0 - t.y, 0, t.y - f.y1)
                d = dx * dx + dy * dy
                if d < bd:
                    best, bd = pn, d
            t.panel = best
            if best is None:
                continue
            f = best.frame
            if t.number is not None and not t.rotated:
                if t.x < f.x0 - 1 and f.y0 - 8 <= t.y <= f.y1 + 12 and t.anchor == 'end':
                    best.ticks['left'].append(t)
                    t.role = 'tick'
                elif t.x > f.x1 + 1 and f.y0 - 8 <= t.y <= f.y1 + 12 and t.anchor == 'start':
                    best.ticks['right'].append(t)
                    t.role = 'tick'
                elif t.y > f.y1 and t.y < f.y1 + 3.2 * t.size and f.x0 - 30 <= t.x <= f.x1 + 30:
                    best.ticks['bottom'].append(t)
                    t.role = 'tick'
                elif t.y < f.y0 and t.y > f.y0 - 2.0 * t.size and f.x0 - 30 <= t.x <= f.x1 + 30:
                    best.ticks['top'].append(t)
                    t.role = 'tick'
        for pn in framed:
            f = pn.frame
            mine = [t for t in self.texts if t.role == 'other' and getattr(t, 'panel', None) is pn and
                    t.number is None and t.s.strip()]
            left = [t for t in mine if t.rotated and t.x < f.x0 and f.y0 - 20 <= t.y <= f.y1 + 20]
            right = [t for t in mine if t.rotated and t.x > f.x1 and f.y0 - 20 <= t.y <= f.y1 + 20]
            below = [t for t in mine if not t.rotated and t.y > f.y1 and abs(t.x - (f.x0 + f.x1) / 2) < 0.2 * f.w]
            above = [t for t in mine if not t.rotated and t.y < f.y0 and abs(t.x - (f.x0 + f.x1) / 2) < 0.2 * f.w]
            if left:
                pn.ylabel = max(left, key=lambda t: t.x)
                pn.ylabel.role = 'axis'
            if right:
                pn.y2label = min(right, key=lambda t: t.x)
                pn.y2label.role = 'axis'
            if below:
                pn.xlabel = min(below, key=lambda t: t.y)
                pn.xlabel.role = 'axis'
            above.sort(key=lambda t: -t.y)
            if above and pn.ticks['top']:
                pn.x2label = above.pop(0)
                pn.x2label.role = 'axis'
            if above:
                pn.title = above[0]
                pn.title.role = 'title'

    # -- queries
    def axis_labels(self):
        out = []
        for pn in self.panels:
            for t in (pn.xlabel, pn.ylabel, pn.x2label, pn.y2label):
                if t is not None and t not in out:
                    out.append(t)
        return out


# ---------------------------------------------------------------- colour

def srgb_to_linear(c):
    c = c / 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def linear_to_srgb(c):
    c = min(max(c, 0.0), 1.0)
    return 255.0 * (12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055)


def luminance(rgb):
    r, g, b = (srgb_to_linear(v) for v in rgb)
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def contrast_on_white(rgb):
    return 1.05 / (luminance(rgb) + 0.05)


# Vienot, Brettel & Mollon (1999): dichromat simulation in linear RGB
CVD = {
    'protan': ((0.11238, 0.88762, 0.0), (0.11238, 0.88762, 0.0), (0.00401, -0.00401, 1.0)),
    'deutan': ((0.29275, 0.70725, 0.0), (0.29275, 0.70725, 0.0), (-0.02234, 0.02234, 1.0)),
}


def simulate(rgb, kind):
    if kind == 'normal':
        return rgb
    lin = [srgb_to_linear(v) for v in rgb]
    m = CVD[kind]
    return tuple(linear_to_srgb(sum(m[i][j] * lin[j] for j in range(3))) for i in range(3))


def lab(rgb):
    r, g, b = (srgb_to_linear(v) for v in rgb)
    x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047
    y = 0.2126 * r + 0.7152 * g + 0.0722 * b
    z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883
    f = lambda t: t ** (1 / 3) if t > 0.008856 else 7.787 * t + 16 / 116
    return 116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))


def delta_e(c1, c2):
    """The smallest CIE76 colour difference of two colours seen with normal vision, protanopia and
    deuteranopia."""
    best = 1e9
    for k in ('normal', 'protan', 'deutan'):
        a, b = lab(simulate(c1, k)), lab(simulate(c2, k))
        best = min(best, math.sqrt(sum((u - v) ** 2 for u, v in zip(a, b))))
    return best
