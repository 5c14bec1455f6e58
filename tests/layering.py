#!/usr/bin/env python3
"""Layering of libgeardyn and the command line (TAP; python3 standard library only).

Every '#include "..."' (and '#include <geardyn/...>') line of every .c/.h file under src/ and of
every public header in include/geardyn/ is mapped to the layer of the file it names: a public
header by PUBLIC below, an internal header by the folder under src/ it lives in (relative includes
such as "../case/case_keys.h" are resolved the way the compiler does: beside the including file
first, then include/, then src/). A file may include headers of its own layer and of the layers
below it (ALLOWED); a public header may include only public headers of its own layer or below.

One TAP line per folder (src/<layer>/ and include/geardyn/): 'ok' when none of its includes
points upwards, otherwise one 'not ok' line per offending include naming file:line, the include
and the two layers.

  layering.py [--root DIR] [--public-headers NAME...] [--exports LIB --nm NM]
  layering.py --self-test

--self-test       check the checker: on a tiny fake tree (a temporary directory) every kind of
                  upward include must give its 'not ok' line, and the same tree without them
                  must pass.

--root            the source tree to check (default: the one this script is in); a small fake
                  tree proves the check can fail.
--public-headers  the header list the build installs and tests (include/geardyn/meson.build):
                  one more TAP line checks that it, the directory and PUBLIC agree.
--exports LIB     instead of the layers, one TAP line: the dynamic symbols LIB exports (read
                  with NM) are exactly the functions declared GD_API in the public headers; the
                  tests link the internal static library, so this proves the shared library's API.
"""
import os
import re
import subprocess
import sys

# The layers, lowest first; a folder under src/ is a layer.
LAYERS = ['core', 'case', 'geometry', 'contact', 'excitation', 'dynamics', 'scene',
          'optimisation', 'analysis', 'output', 'plot', 'run', 'cli']

# The allowed arrows: what each layer may include (itself and the layers below it).
ALLOWED = {
    'core':         {'core'},
    'case':         {'core', 'case'},
    'geometry':     {'core', 'case', 'geometry'},
    'contact':      {'core', 'case', 'geometry', 'contact'},
    'excitation':   {'core', 'case', 'geometry', 'contact', 'excitation'},
    # the dynamics sees no gear: it integrates whatever model the scene built
    'dynamics':     {'core', 'case', 'dynamics'},
    'scene':        {'core', 'case', 'geometry', 'contact', 'excitation', 'dynamics', 'scene'},
    # the optimisers and their objectives: the LTCA of a modified flank, never the dynamics
    'optimisation': {'core', 'case', 'geometry', 'contact', 'optimisation'},
    'analysis':     {'core', 'case', 'geometry', 'contact', 'excitation', 'dynamics', 'scene',
                     'optimisation', 'analysis'},
    'output':       {'core', 'case', 'geometry', 'contact', 'excitation', 'dynamics', 'scene',
                     'optimisation', 'analysis', 'output'},
    # the pictures: gnuplot scripts of an analysis's results, handed to the caller's drawer
    'plot':         {'core', 'case', 'geometry', 'contact', 'excitation', 'dynamics', 'scene',
                     'optimisation', 'analysis', 'output', 'plot'},
    # the table of analyses: each row runs an analysis and writes its files through output
    'run':          {'core', 'case', 'geometry', 'contact', 'excitation', 'dynamics', 'scene',
                     'optimisation', 'analysis', 'output', 'plot', 'run'},
    'cli':          {'core', 'case', 'geometry', 'contact', 'excitation', 'dynamics', 'scene',
                     'optimisation', 'analysis', 'output', 'plot', 'run', 'cli'},
}

# The layer of each public header. ANY: includable from every layer (a generated constant header).
ANY = '*'
PUBLIC = {
    'gd_error.h': 'core',
    'gd_case.h': 'case',
    'gd_pair.h': 'geometry', 'gd_geometry.h': 'geometry', 'gd_flank.h': 'geometry',
    'gd_contact.h': 'contact', 'gd_compliance.h': 'contact', 'gd_tca.h': 'contact',
    'gd_ltca.h': 'contact',
    'gd_excitation.h': 'excitation',
    'gd_model.h': 'dynamics', 'gd_modal.h': 'dynamics', 'gd_sim.h': 'dynamics',
    'gd_scene.h': 'scene',
    'gd_optimize.h': 'optimisation',
    'gd_analysis.h': 'run', 'gd_job.h': 'run', 'gd_response.h': 'analysis', 'gd_sweep.h': 'analysis',
    'gd_workprec.h': 'analysis', 'gd_spectrum.h': 'analysis', 'gd_periodic.h': 'analysis',
    'gd_continuation.h': 'analysis', 'gd_envelope.h': 'analysis',
    'gd_continuation.h': 'analysis', 'gd_dynobj.h': 'analysis', 'gd_optpost.h': 'analysis',
    'gd_basins.h': 'analysis',
    'gd_output.h': 'output',
    'geardyn.h': 'cli',            # the umbrella: the command line only
    'gd_version.h': ANY,           # generated from gd_version.h.in
}

INCLUDE_RE = re.compile(r'^\s*#\s*include\s*(?:"([^"]+)"|<(geardyn/[^>]+)>)')


class Tap:
    def __init__(self):
        self.n = 0
        self.failed = 0

    def line(self, ok, text):
        self.n += 1
        self.failed += not ok
        print(f'{"ok" if ok else "not ok"} {self.n} - {text}')

    def diag(self, text):
        for t in text.splitlines():
            print(f'# {t}')

    def done(self):
        print(f'1..{self.n}')
        return 1 if self.failed else 0


def layer_of(path, root):
    """(layer, kind) of an existing file, kind 'public' or 'internal'; layer None if unknown."""
    rel = os.path.relpath(path, root).replace(os.sep, '/')
    if rel.startswith('include/geardyn/'):
        return PUBLIC.get(rel[len('include/geardyn/'):]), 'public'
    if rel.startswith('src/'):
        parts = rel.split('/')
        return (parts[1] if len(parts) > 2 and parts[1] in ALLOWED else None), 'internal'
    return None, 'outside'


def resolve(inc, including, root):
    """The file '#include "inc"' in file 'including' names, or None (not in the tree)."""
    for base in (os.path.dirname(including), os.path.join(root, 'include'), os.path.join(root, 'src')):
        p = os.path.normpath(os.path.join(base, inc))
        if os.path.isfile(p):
            return p
    return None


def check_file(path, layer, public_file, root):
    """Upward (or otherwise forbidden) includes of one file: list of messages."""
    bad = []
    rel = os.path.relpath(path, root)
    with open(path, encoding='utf-8', errors='replace') as f:
        for lineno, text in enumerate(f, 1):
            m = INCLUDE_RE.match(text)
            if not m:
                continue
            inc = m.group(1) or m.group(2)
            where = f'{rel}:{lineno}: #include "{inc}"'
            target = resolve(inc, path, root)
            if target is None:
                name = inc[len('geardyn/'):] if inc.startswith('geardyn/') else None
                if name is not None and PUBLIC.get(name) == ANY:
                    continue            # generated into the build directory
                bad.append(f'{where}: not found in src/ or include/, layer unknown')
                continue
            to, kind = layer_of(target, root)
            if kind == 'public' and PUBLIC.get(os.path.basename(target)) == ANY:
                continue
            if to is None:
                bad.append(f'{where}: {os.path.relpath(target, root)} has no layer (not in the tables)')
            elif public_file and kind != 'public':
                bad.append(f'{where}: public header ({layer}) includes an internal header ({to})')
            elif to not in ALLOWED[layer]:
                bad.append(f'{where}: {to} is above {layer}')
    return bad


def sources(folder):
    out = []
    for d, dirs, files in os.walk(folder):
        dirs.sort()
        out += [os.path.join(d, f) for f in sorted(files) if f.endswith(('.c', '.h'))]
    return out


def check_exports(lib, nm, root, tap):
    declared = set()
    for name in sorted(os.listdir(os.path.join(root, 'include', 'geardyn'))):
        if not name.endswith('.h'):
            continue
        with open(os.path.join(root, 'include', 'geardyn', name), encoding='utf-8') as f:
            t = f.read()
        t = re.sub(r'/\*.*?\*/', ' ', t, flags=re.S)
        t = re.sub(r'//[^\n]*', ' ', t)
        t = re.sub(r'^\s*#.*$', ' ', t, flags=re.M)
        declared |= {m.group(1) for m in re.finditer(r'\bGD_API\b[^;{}()]*?\b(\w+)\s*\(', t)}
    out = subprocess.run([nm, '-D', '--defined-only', lib], capture_output=True, text=True, check=True)
    exported = {f[2] for f in (l.split() for l in out.stdout.splitlines())
                if len(f) == 3 and f[1] in 'TDBRVWi'}
    missing, extra = sorted(declared - exported), sorted(exported - declared)
    tap.line(not missing and not extra,
             f'{os.path.basename(lib)} exports exactly the {len(declared)} functions declared GD_API '
             f'({len(exported)} exported)')
    if missing:
        tap.diag('declared GD_API but not exported: ' + ' '.join(missing))
    if extra:
        tap.diag('exported but not declared GD_API in include/geardyn: ' + ' '.join(extra))


def self_test():
    """The checker fails on upward includes and passes without them (fake trees in /tmp)."""
    import tempfile
    files = {
        'include/geardyn/gd_error.h': '',
        'include/geardyn/gd_case.h': '#include "geardyn/gd_error.h"\n',
        'include/geardyn/gd_model.h': '#include "geardyn/gd_case.h"\n#include "geardyn/gd_version.h"\n',
        'include/geardyn/gd_output.h': '#include "geardyn/gd_model.h"\n',
        'src/core/error.c': '#include "geardyn/gd_error.h"\n',
        'src/case/case_keys.h': '#include "geardyn/gd_case.h"\n',
        'src/case/case_load.c': '#include "case_keys.h"\n',
        'src/dynamics/rhs_plan.h': '#include "../case/case_keys.h"\n',
        'src/dynamics/simulate.c': '#include "rhs_plan.h"\n#include "case/case_keys.h"\n'
                                   '#include "geardyn/gd_model.h"\n',
        'src/output/json_util.h': '#include "geardyn/gd_model.h"\n',
        'src/output/eventlog.c': '#include "json_util.h"\n#include <geardyn/gd_output.h>\n',
    }
    upward = {  # file: (added line, what its 'not ok' line must say)
        'src/dynamics/simulate.c': ('#include "geardyn/gd_output.h"',
                                    'simulate.c:4: #include "geardyn/gd_output.h": output is above dynamics'),
        'src/case/case_load.c': ('#include "../dynamics/rhs_plan.h"',
                                 'case_load.c:2: #include "../dynamics/rhs_plan.h": dynamics is above case'),
        'src/core/error.c': ('#include <geardyn/gd_case.h>',
                             'error.c:2: #include "geardyn/gd_case.h": case is above core'),
        'src/dynamics/rhs_plan.h': ('#include "output/json_util.h"',
                                    'rhs_plan.h:2: #include "output/json_util.h": output is above dynamics'),
        'include/geardyn/gd_case.h': ('#include "geardyn/gd_model.h"',
                                      'gd_case.h:2: #include "geardyn/gd_model.h": dynamics is above case'),
        'include/geardyn/gd_model.h': ('#include "../../src/dynamics/rhs_plan.h"',
                                       'public header (dynamics) includes an internal header'),
    }
    tap = Tap()
    for bad in (False, True):
        with tempfile.TemporaryDirectory(prefix='geardyn-layering-') as tmp:
            for rel, text in files.items():
                if bad and rel in upward:
                    text += upward[rel][0] + '\n'
                os.makedirs(os.path.dirname(os.path.join(tmp, rel)), exist_ok=True)
                with open(os.path.join(tmp, rel), 'w', encoding='utf-8') as f:
                    f.write(text)
            r = subprocess.run([sys.executable, os.path.abspath(__file__), '--root', tmp],
                               capture_output=True, text=True)
        if not bad:
            tap.line(r.returncode == 0 and 'not ok' not in r.stdout, 'a fake tree without upward includes passes')
            if r.returncode != 0:
                tap.diag(r.stdout)
            continue
        tap.line(r.returncode == 1, 'the fake tree with upward includes fails')
        fails = [l for l in r.stdout.splitlines() if l.startswith('not ok')]
        for rel, (_, expect) in upward.items():
            tap.line(any(expect in l for l in fails), f'{rel}: {upward[rel][0]} is reported ({expect})')
        tap.line(len(fails) == len(upward), f'{len(fails)} not ok lines for the {len(upward)} upward includes')
        if len(fails) != len(upward):
            tap.diag(r.stdout)
    return tap.done()


def main(argv):
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    listed, lib, nm = None, None, 'nm'
    if argv == ['--self-test']:
        return self_test()
    i = 0
    while i < len(argv):
        a = argv[i]
        if a == '--root':
            root, i = os.path.abspath(argv[i + 1]), i + 2
        elif a == '--exports':
            lib, i = argv[i + 1], i + 2
        elif a == '--nm':
            nm, i = argv[i + 1], i + 2
        elif a == '--public-headers':
            listed, i = [], i + 1
            while i < len(argv) and not argv[i].startswith('--'):
                listed.append(argv[i])
                i += 1
        else:
            print(f'Bail out! unknown argument {a}')
            return 2
    tap = Tap()
    if lib is not None:
        check_exports(lib, nm, root, tap)
        return tap.done()
    src = os.path.join(root, 'src')

    # src/<layer>/: one line per folder, lowest first; folders that are no layer are errors
    folders = sorted(d for d in os.listdir(src) if os.path.isdir(os.path.join(src, d)))
    for d in [l for l in LAYERS if l in folders] + [d for d in folders if d not in ALLOWED]:
        files = sources(os.path.join(src, d))
        if d not in ALLOWED:
            if files:
                tap.line(False, f'src/{d}/: not a layer ({len(files)} files); add it to LAYERS and ALLOWED')
            continue
        bad = [b for f in files for b in check_file(f, d, False, root)]
        for b in bad:
            tap.line(False, b)
        if not bad:
            tap.line(True, f'src/{d}/ ({d}): {len(files)} files, no include from above')
    loose = [f for f in sorted(os.listdir(src)) if f.endswith(('.c', '.h'))]
    if loose:
        tap.line(False, 'src/: files outside every layer folder: ' + ' '.join(loose))

    # include/geardyn/: public headers include public headers of their layer or below only
    pub = os.path.join(root, 'include', 'geardyn')
    headers = sorted(f for f in os.listdir(pub) if f.endswith('.h'))
    bad = []
    for h in headers:
        layer = PUBLIC.get(h)
        if layer is None:
            bad.append(f'include/geardyn/{h}: not in the PUBLIC table, layer unknown')
        elif layer != ANY:
            bad += check_file(os.path.join(pub, h), layer, True, root)
    for b in bad:
        tap.line(False, b)
    if not bad:
        tap.line(True, f'include/geardyn/: {len(headers)} public headers, none includes from above')

    if listed is not None:
        on_disk = set(headers) | {'gd_version.h'}          # gd_version.h: generated
        table = set(PUBLIC)
        named = set(listed) | {'gd_version.h'}
        ok = named == on_disk == table
        tap.line(ok, 'public_header_names (include/geardyn/meson.build), include/geardyn/*.h and the '
                     'PUBLIC table list the same headers')
        if not ok:
            tap.diag(f'only in the meson list: {sorted(named - on_disk)}; missing from it: '
                     f'{sorted(on_disk - named)}; not in PUBLIC: {sorted(on_disk - table)}; '
                     f'in PUBLIC only: {sorted(table - on_disk)}')

    return tap.done()


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
