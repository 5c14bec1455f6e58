"""The curves of a continuation with parameter2 (curves.csv) against a regime map of the same plane (the
sweep.csv of a sweep with parameter2 over a regular grid, both directions; docs/continuation.md section 8,
"Against brute force"). A jump of the map is two neighbouring values of the first parameter along one
chain (one direction, one value of the second parameter) whose classes differ; it lies on a curve to
within the map's grid spacing when some curve passes through the rectangle of the two points widened by
one grid spacing in each parameter. Used by tests/cli/test_envelope_bta.sh and
benchmarks/bench_envelope_bta.py."""
import csv


def polylines(path):
    """the curves of curves.csv: {curve: (kind, [(first key, second key), ...])}; the first key is
    curves.csv's 7th column, the second its 8th"""
    cv = {}
    rd = csv.DictReader(open(path))
    k1, k2 = rd.fieldnames[6], rd.fieldnames[7]
    for r in rd:
        cv.setdefault(r['curve'], (r['kind'] + ('' if r['clearance'] in ('', '-') else ' of ' + r['clearance']), []))
        cv[r['curve']][1].append((float(r[k1]), float(r[k2])))
    return cv


def through(poly, x0, x1, y0, y1):
    """whether the polyline passes through the rectangle [x0, x1] x [y0, y1] (each segment sampled at 101
    points: the curves' steps are a small part of a grid spacing)"""
    for (a, b), (c, d) in zip(poly, poly[1:] or poly):
        for k in range(101):
            x, y = a + (c - a) * k / 100, b + (d - b) * k / 100
            if x0 <= x <= x1 and y0 <= y <= y1:
                return True
    return False


def crosses(poly, x0, x1, y):
    """whether the polyline crosses the segment [x0, x1] x {y}"""
    for (a, b), (c, d) in zip(poly, poly[1:]):
        if (b - y) * (d - y) <= 0 and b != d:
            x = a + (c - a) * (y - b) / (d - b)
            if x0 <= x <= x1:
                return True
    return False


def motion(row):
    """a sweep.csv row's class of motion: period-N, quasi-periodic, chaotic, not-periodic ..."""
    return 'period-%s' % row['period_n'] if row['motion'].startswith('period') else row['motion']


def grid(sweep_csv):
    """the rows of sweep.csv, the grid spacings (h1, h2) and the chains {(direction, second value): rows by the
    first parameter}"""
    rows = list(csv.DictReader(open(sweep_csv)))
    g1 = sorted({float(x['parameter']) for x in rows})
    g2 = sorted({float(x['parameter2']) for x in rows})
    h1, h2 = (g1[-1] - g1[0]) / (len(g1) - 1), (g2[-1] - g2[0]) / (len(g2) - 1)
    chains = {}
    for x in rows:
        chains.setdefault((x['direction'], float(x['parameter2'])), []).append(x)
    for ch in chains.values():
        ch.sort(key=lambda x: float(x['parameter']))
    return rows, (h1, h2), chains


def jumps(curves_csv, sweep_csv, key=motion):
    """every jump of the map in the classes key gives: a list of dicts with direction, p2, the two points
    p1a, p1b, their classes ka, kb, crossed (a curve crosses the row between them), near (a curve passes
    within one grid spacing), and the spacings (h1, h2)"""
    cv = polylines(curves_csv)
    rows, (h1, h2), chains = grid(sweep_csv)
    out = []
    for (d, y), ch in sorted(chains.items()):
        for a, b in zip(ch, ch[1:]):
            ka, kb = key(a), key(b)
            if ka == kb:
                continue
            sa, sb = float(a['parameter']), float(b['parameter'])
            lo, hi = min(sa, sb), max(sa, sb)
            out.append(dict(direction=d, p2=y, p1a=sa, p1b=sb, ka=ka, kb=kb,
                            crossed=any(crosses(poly, lo, hi, y) for kind, poly in cv.values()),
                            near=[kind for kind, poly in cv.values() if through(poly, lo - h1, hi + h1, y - h2, y + h2)]))
    return out, (h1, h2)
