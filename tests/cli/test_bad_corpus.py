#!/usr/bin/env python3
"""The bad-input corpus (tests/bad-input/*.txt): every case is run in a directory of its own and
must exit with its expected status, say its message fragment on stderr, and write nothing (no new
file anywhere under its directory, which is also the working directory, so a default output
directory would be seen). TAP, one line per case; python3 standard library only.

A corpus file holds cases, each:

    === name
    expect: STATUS | fragment of the message (a plain substring)
    cmd: run CASE --out OUT --quiet      (optional; this is the default)
    path: dir | fifo | device | big | missing  (optional: CASE is that instead of the case file;
                                          big: 1.1 MB of comments)
    bytes: text with \\xNN, \\r, \\n, \\t escapes (optional: the case file's bytes, no body)
    file NAME: text with escapes          (optional, repeatable: another file beside the case)
    ---
    the case file, verbatim (until the next '===')

In cmd, CASE is the case file (or what path: makes it), OUT a fresh directory name, DIR the
case's own directory. A case may run at most 20 s (a hang is a failure).

  test_bad_corpus.py [CORPUS_DIR]      (GEARDYN names the executable)
"""
import codecs
import os
import shlex
import subprocess
import sys
import tempfile


def unescape(text):
    return codecs.escape_decode(text.encode('utf-8'))[0]


def parse(path):
    cases, cur, body = [], None, False
    with open(path, encoding='utf-8') as f:
        for raw in f:
            line = raw.rstrip('\n')
            if line.startswith('=== '):
                cur = {'name': line[4:].strip(), 'cmd': 'run CASE --out OUT --quiet', 'files': {},
                       'lines': [], 'src': os.path.basename(path)}
                cases.append(cur)
                body = False
            elif cur is None or (not body and (line.startswith('#') or not line.strip())):
                continue
            elif body:
                cur['lines'].append(line)
            elif line == '---':
                body = True
            else:
                key, _, val = line.partition(':')
                key, val = key.strip(), val.strip()
                if key == 'expect':
                    status, _, frag = val.partition('|')
                    cur['status'], cur['frag'] = int(status), frag.strip()
                elif key.startswith('file '):
                    cur['files'][key[5:].strip()] = unescape(val)
                elif key in ('cmd', 'path', 'bytes'):
                    cur[key] = val
                else:
                    raise SystemExit('%s: %s: unknown field %r' % (path, cur['name'], key))
    for c in cases:
        if 'status' not in c:
            raise SystemExit('%s: %s: no expect: line' % (path, c['name']))
    return cases


def snapshot(d):
    out = set()
    for root, dirs, files in os.walk(d):
        for n in dirs + files:
            out.add(os.path.relpath(os.path.join(root, n), d))
    return out


def prepare(c, work):
    """The case's directory work made, its case file and other files written; returns the path
    that CASE stands for (also tests/python/test_case.py's)."""
    os.makedirs(work)
    case = os.path.join(work, 'case.ini')
    data = unescape(c['bytes']) if 'bytes' in c else ('\n'.join(c['lines']) + '\n').encode('utf-8')
    with open(case, 'wb') as f:
        f.write(data)
    for name, content in c['files'].items():
        with open(os.path.join(work, name), 'wb') as f:
            f.write(content)
    kind = c.get('path')
    if kind == 'dir':
        case = os.path.join(work, 'adir')
        os.mkdir(case)
    elif kind == 'fifo':
        case = os.path.join(work, 'afifo')
        os.mkfifo(case)
    elif kind == 'device':
        case = '/dev/zero'
    elif kind == 'big':
        case = os.path.join(work, 'big.ini')
        with open(case, 'w') as f:
            f.write('[scene]\n' + ('; ' + 'x' * 97 + '\n') * 11000)
    elif kind == 'missing':
        case = os.path.join(work, 'nothing-here.ini')
    return case


def args_of(c, case, work):
    """The command line of the case, CASE, OUT and DIR replaced."""
    return [a.replace('CASE', case).replace('OUT', os.path.join(work, 'out')).replace('DIR', work)
            for a in shlex.split(c['cmd'])]


def run_case(exe, c, work):
    case = prepare(c, work)
    before = snapshot(work)
    args = args_of(c, case, work)
    try:
        p = subprocess.run([exe] + args, cwd=work, stdin=subprocess.DEVNULL, capture_output=True, timeout=20)
        rc, err = p.returncode, p.stderr.decode('utf-8', 'replace')
    except subprocess.TimeoutExpired:
        rc, err = 'timeout', ''
    written = sorted(snapshot(work) - before)
    return rc, err, written


def main():
    exe = os.environ['GEARDYN']
    here = os.path.dirname(os.path.abspath(__file__))
    corpus = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, '..', 'bad-input')
    cases = []
    for name in sorted(os.listdir(corpus)):
        if name.endswith('.txt'):
            cases += parse(os.path.join(corpus, name))
    bad, clean2 = 0, 0
    with tempfile.TemporaryDirectory() as tmp:
        for i, c in enumerate(cases, 1):
            rc, err, written = run_case(exe, c, os.path.join(tmp, str(i)))
            problems = []
            if rc != c['status']:
                problems.append('exit %s, expected %d' % (rc, c['status']))
            if c['frag'] not in err:
                problems.append('message lacks %r' % c['frag'])
            if written:
                problems.append('wrote %s' % ', '.join(written[:5]))
            if rc == 2 and not written:
                clean2 += 1
            if problems:
                bad += 1
                print('not ok %d - %s: %s: %s (stderr: %s)' % (i, c['src'], c['name'], '; '.join(problems),
                                                              err.strip()[:400]))
            else:
                print('ok %d - %s: %s' % (i, c['src'], c['name']))
    print('# %d bad inputs, %d exit 2 with nothing written' % (len(cases), clean2))
    print('1..%d' % len(cases))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
