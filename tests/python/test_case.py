"""Cases from Python (docs/python.md section 2): the schema is geardyn keys', a key reads back what
was set to the bit, a case from text is the case from its file, check() is geardyn check, and every
bad input of the corpus (tests/bad-input/*.txt) that the library refuses raises CaseError (or Error)
with exactly the command line's message, writing nothing."""
import math
import os
import re
import shlex
import sys

import pytest

import geardyn
from conftest import SRC, cli, load, shipped_cases

sys.path.insert(0, os.path.join(SRC, 'tests', 'cli'))
import test_bad_corpus as corpus  # noqa: E402  (its parser and the set-up of each case)

KEY_LINE = re.compile(r'^(\S+?)(?: \((.*)\))?: (.*?); (?:valid )?(.*); default (.*)$')


def test_keys_are_the_schema():
    rc, out, err = cli(['keys'])
    assert rc == 0, err
    lines = [ln for ln in out.splitlines() if ln and not ln.startswith((' ', '['))]
    keys = geardyn.keys()
    assert [KEY_LINE.match(ln).group(1) for ln in lines] == list(keys)
    for ln in lines:
        name, unit, ktype, valid, default = KEY_LINE.match(ln).groups()
        k = keys[name]
        assert (k.unit or None, k.type, k.valid) == (unit, ktype, valid), ln
        if default == 'derived':
            assert k.default is None, ln
        elif k.type in ('number', 'integer'):
            assert float(default) == pytest.approx(k.default, rel=1e-9), ln
        elif k.type == 'on/off':
            assert k.default == (default == 'on'), ln
        elif k.type == 'list of numbers':
            assert k.default == [], ln
        elif default != 'empty':
            assert k.default == default, ln


def test_set_and_read_back():
    c = geardyn.Case.load('%s/cases/quickstart.ini' % SRC)
    assert c['operating.speed_rpm'] == 4000.0 and c.source('operating.speed_rpm')[0] == 'file'
    x = 1234.5678901234567
    c.set('operating.speed_rpm', x)
    assert c['operating.speed_rpm'] == x and c.source('operating.speed_rpm') == ('set', 1)
    c['run.record_periods'] = 7
    assert c['run.record_periods'] == 7 and isinstance(c['run.record_periods'], int)
    c.set('output.plots', False)
    assert c['output.plots'] is False
    c.set('scene.model', 'torsional')
    assert c['scene.model'] == 'torsional'
    h = [0.1, 1 / 3]
    c.set('excitation.stiffness_harmonics', h)
    assert c['excitation.stiffness_harmonics'] == h
    c.set('scene.title', 'a title, with = signs')
    assert c['scene.title'] == 'a title, with = signs'
    d = c.copy()
    d.set('operating.speed_rpm', 1000)
    assert (c['operating.speed_rpm'], d['operating.speed_rpm']) == (x, 1000.0)


def test_bad_key_and_value_raise_case_error():
    c = geardyn.Case()
    with pytest.raises(geardyn.CaseError) as e:
        c.set('operating.speed_rmp', 3)
    assert (e.value.key, e.value.where) == ('operating.speed_rmp', '--set #1')
    rc, _, err = cli(['check', '%s/cases/quickstart.ini' % SRC, '--set', 'operating.speed_rmp=3'])
    assert rc == 2 and str(e.value) == err[len('geardyn: '):].rstrip('\n')
    assert str(e.value).startswith('--set #1: speed_rmp: unknown key in [operating], did you mean operating.speed_rpm?')
    with pytest.raises(geardyn.CaseError) as e:
        c.set('operating.speed_rpm', -5)
    assert e.value.key == 'operating.speed_rpm' and e.value.valid == 'a finite number in (0, 100000] rpm'
    assert e.value.status == 'GD_ERR_INPUT' and e.value.file is None
    with pytest.raises(geardyn.CaseError) as e:
        c.set('operating.speed_rpm', math.nan)
    assert "not finite: 'nan'" in str(e.value)
    with pytest.raises(geardyn.CaseError) as e:
        geardyn.Case.from_text('[operating]\nspeed_rpm = 4000\ntorque_nm = -1\n', name='mine.ini')
    assert (e.value.file, e.value.line, e.value.key) == ('mine.ini', 3, 'operating.torque_nm')
    assert e.value.valid.startswith('a finite number in')
    with pytest.raises(geardyn.CaseError):
        c['operating.sped_rpm']


@pytest.mark.parametrize('rel', shipped_cases())
def test_from_text_is_load(rel):
    a = geardyn.Case.load(os.path.join(SRC, rel))
    with open(os.path.join(SRC, rel), 'rb') as f:
        b = geardyn.Case.from_text(f.read(), name=os.path.join(SRC, rel))
    for k in a:
        x, y = a[k], b[k]
        assert x == y or (x != x and y != y), k   # nan: a derived value not yet resolved
        assert a.source(k) == b.source(k), k


def _check_lines(out):
    vals = {}
    for ln in out.splitlines():
        m = re.match(r'^(\w+) = (\S+)', ln)
        if m:
            vals[m.group(1)] = m.group(2)
    return vals


@pytest.mark.parametrize('rel, sets', [('cases/quickstart.ini', []), ('cases/guide/spur.ini', [('operating.speed_rpm', 2500)]),
                                       ('cases/paper/ltca-modified.ini', [])])
def test_check_is_geardyn_check(rel, sets):
    c = load(os.path.join(SRC, rel), sets)
    k = c.check()
    rc, out, err = cli(['check', os.path.join(SRC, rel)] + sum([['--set', '%s=%s' % kv] for kv in sets], []))
    assert rc == 0, err
    v = _check_lines(out)
    model = k['derived']['model']
    for name in ('mesh_frequency_hz', 'natural_frequency_hz', 'frequency_ratio', 'static_mesh_force_n',
                 'static_deflection_um', 'normal_equivalent_mass_kg'):
        if model[name] is None:   # check prints no line for what the analysis has no speed or torque for
            assert name not in v, name
        else:
            assert '%.6g' % model[name] == v[name], name
    assert model['degrees_of_freedom'] == int(v['degrees_of_freedom'])
    geo = k['derived']['geometry']
    for name in ('transverse_module_mm', 'centre_distance_mm', 'contact_ratio_transverse', 'contact_ratio_overlap'):
        assert '%.6g' % geo[name] == v[name], name
    assert k['cost']['time_class'] == v['time_class']
    assert '%.3g' % k['cost']['memory_bytes'] == v['memory_bytes']
    speed = k['case']['parameters']['operating']['speed_rpm']['value']   # JSON null: a key unset (NaN)
    assert speed == c['operating.speed_rpm'] or (speed is None and math.isnan(c['operating.speed_rpm']))
    assert c.source('excitation.mesh_stiffness_n_per_m')[0] != 'derived'  # the case itself is not resolved


# ---- the bad-input corpus ----

CASES = []
for _name in sorted(os.listdir(os.path.join(SRC, 'tests', 'bad-input'))):
    if _name.endswith('.txt'):
        CASES += corpus.parse(os.path.join(SRC, 'tests', 'bad-input', _name))


def _python_call(args):
    """The Python call that does what the command line args do, or None when they are refused by the
    command line's own argument parsing (which Python has not: keyword arguments instead)."""
    if not args:
        return None
    cmd, rest = args[0], args[1:]
    if cmd in ('run', 'check'):
        path, sets, out, i = None, [], None, 0
        while i < len(rest):
            a = rest[i]
            if a in ('--set', '-s'):
                if i + 1 >= len(rest) or rest[i + 1].startswith('-'):
                    return None
                sets.append(rest[i + 1])
                i += 2
            elif a.startswith('--set='):
                sets.append(a[6:])
                i += 1
            elif a == '--out' and cmd == 'run':
                if i + 1 >= len(rest) or rest[i + 1].startswith('--'):
                    return None
                out = rest[i + 1]
                i += 2
            elif a == '--quiet' and cmd == 'run':
                i += 1
            elif a.startswith('-') or path is not None:
                return None
            else:
                path = a
                i += 1
        if path is None:
            return None

        def call():
            c = geardyn.Case.load(path)
            for s in sets:  # the --set text as it is: section.key=value
                key, _, value = s.partition('=')
                if '=' not in s or '.' not in key:
                    c._sets += 1
                    err = geardyn._lib.Error_t()
                    code = geardyn._lib.lib.gd_case_set(c._ptr, s.encode(), c._sets - 1, geardyn._lib.byref(err))
                    if code:
                        geardyn._errors.raise_for(code, err)
                    continue
                c.set(key, value)
            if cmd == 'check':
                c.check()
            else:
                geardyn.run(c, out=out or c['output.directory'] or
                            os.path.join('results', os.path.basename(path)[:-4] if path.endswith('.ini') else
                                         os.path.basename(path)))
        return call
    if cmd == 'events':
        path, kw, i = None, {}, 0
        while i < len(rest):
            a = rest[i]
            if a in ('--from', '--to', '--clearance', '--kind'):
                if i + 1 >= len(rest):
                    return None
                v = rest[i + 1]
                if a in ('--from', '--to'):
                    try:
                        float(v)
                    except ValueError:
                        return None
                    kw['t_' + a[2:]] = float(v)
                elif a == '--kind':
                    if v not in geardyn._result.KINDS:
                        return None
                    kw['kind'] = v
                else:
                    kw['clearance'] = v
                i += 2
            elif a == '--recorded':
                kw['recorded'] = True
                i += 1
            elif a.startswith('-') or path is not None:
                return None   # --csv: the command line's export
            else:
                path = a
                i += 1
        return None if path is None else (lambda: geardyn.events(path, **kw))
    return None


@pytest.mark.parametrize('c', CASES, ids=['%s: %s' % (c['src'], c['name']) for c in CASES])
def test_bad_input_as_command_line(c, tmp_path, monkeypatch):
    work = str(tmp_path / 'w')
    path = corpus.prepare(c, work)
    args = corpus.args_of(c, path, work)
    call = _python_call(args)
    if call is None:
        pytest.skip('refused by the command line\'s argument parsing: %s' % ' '.join(shlex.quote(a) for a in args))
    monkeypatch.chdir(work)
    before = corpus.snapshot(work)
    rc, _, err = cli(args, cwd=work, stdin=corpus.subprocess.DEVNULL, timeout=20)
    assert rc == c['status'] and corpus.snapshot(work) == before
    assert err.startswith('geardyn: ')
    message = err[len('geardyn: '):].rstrip('\n')
    with pytest.raises(geardyn.Error) as e:
        call()
    assert str(e.value) == message
    assert isinstance(e.value, geardyn.CaseError) == (rc == 2)
    m = re.match(r'^(.*):(\d+): ([a-z_0-9]+\.[a-z_0-9]+): ', message)
    if m:   # where and what, read from the message
        assert (e.value.file, e.value.line, e.value.key) == (m.group(1), int(m.group(2)), m.group(3))
    if '(valid: ' in message:
        assert e.value.valid and e.value.valid in message
    assert corpus.snapshot(work) == before, 'nothing written'
    if c['status'] == 2 and c.get('path') is None and args[0] in ('run', 'check') and 'bytes' in c:
        with pytest.raises(geardyn.CaseError) as t:    # the same bytes as text: the same refusal
            with open(path, 'rb') as f:
                geardyn.Case.from_text(f.read(), name=path)
            raise geardyn.CaseError(1, message)         # the file is refused later (its keys)
        assert str(t.value) == message


def test_cost_of_gear_objectives(work):
    """check()'s estimate of an optimisation counts what one evaluation of its objective computes:
    gear-lte-range an LTCA per torque, gear-dynamic per torque an LTCA and the orbits followed over
    the speed range (several times the LTCA's cost: docs/optimisation.md section 12 measured 0.5 s
    of CPU for an evaluation of three torques), in proportion to the evaluations of the budget, the
    torques and the speed range."""
    base = [('output.plots', 'off')]

    def seconds(sets):
        return load('cases/paper/optimize-dynamic.ini', base + sets).check()['cost']['seconds']
    lte = seconds([('optimize.objective', 'gear-lte')])
    lte_range = seconds([('optimize.objective', 'gear-lte-range')])
    dyn = seconds([])
    dyn_one = seconds([('optimize.torques_nm', '500')])
    dyn_long = seconds([('optimize.iterations', 61)])
    dyn_wide = seconds([('optimize.speed_to_rpm', 8000)])
    assert lte_range == pytest.approx(3 * lte, rel=0.2)
    assert dyn > 3 * lte_range
    assert dyn == pytest.approx(3 * dyn_one, rel=0.2)
    assert dyn_long == pytest.approx(2 * dyn, rel=0.1)
    assert 1.3 * dyn < dyn_wide <= 2 * dyn   # twice the orbits, each of fewer steps at higher speed
    # two objectives at once: each evaluation computes both, the LTE and the dynamic response
    two = seconds([('optimize.objective', 'gear-lte'), ('optimize.objective2', 'gear-dynamic'),
                   ('optimize.algorithm', 'moalo')])
    assert two > 0.8 * dyn and two > 3 * lte
