#!/usr/bin/env bash
# analysis = work-precision on the command line (docs/accuracy.md): a small grid on the torsional
# model writes every table, the diagrams (when gnuplot is there), summary.json, atomically and
# complete; bad [workprecision] input is refused with the key and the valid values. TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok

cat > "$work/wp.ini" <<'INI'
[scene]
analysis = work-precision
model = torsional
title = test grid
[operating]
speed_rpm = 4000
torque_nm = 500
[run]
transient_periods = 300
record_periods = 20
[workprecision]
families = rk4,erk5,erk8
rk4_steps_min = 32
rk4_steps_max = 128
rtol_loosest = 1e-4
rtol_tightest = 1e-8
rtols_per_decade = 1
horizon_periods = 5
order_steps_min = 16
order_steps_max = 256
INI
"$G" check "$work/wp.ini" > /dev/null 2>&1; ok $? "geardyn check accepts a work-precision case"
"$G" run "$work/wp.ini" --out "$work/out" > "$work/out.txt" 2>&1; rc=$?
ok $rc "the small grid runs (exit status $rc)"
for f in work_precision.csv order_study.csv orders.csv summary.json; do
    [ -s "$work/out/$f" ]; ok $? "writes $f"
done
if command -v gnuplot > /dev/null; then
    [ -s "$work/out/work_precision.png" ] && [ -s "$work/out/work_precision.svg" ]; ok $? "draws work_precision.png and .svg"
else
    grep -q "gnuplot is not installed" "$work/out.txt"; ok $? "says that gnuplot is missing"
fi
[ -z "$(ls -A "$work/out" | grep -E '^\.|tmp')" ]; ok $? "no temporary file left behind"
# 3 families x 2 (root finding on and off): rk4 3 step counts, erk5 and erk8 5 tolerances each
rows=$(($(wc -l < "$work/out/work_precision.csv") - 1))
[ "$rows" -eq 26 ]; ok $? "work_precision.csv: 26 runs ($rows)"
python3 - "$work/out" <<'PY'; ok $? "summary.json complete: reference converged, every run finished with its errors, orders measured"
import json, sys, math
d = json.load(open(sys.argv[1] + "/summary.json"))
assert d["analysis"] == "work-precision"
r = d["reference"]
assert r["converged"] and r["check_difference"]["poincare"] < 1e-9, r
assert r["motion"] == "period-1" and r["scene_class"] == "periodic", r
assert len(d["runs"]) == 26
for u in d["runs"]:
    assert u["status"] == "ok", u
    for k in ("poincare", "rms_accel_relative", "event_times_periods", "short_horizon"):
        assert u["errors"][k] is not None and math.isfinite(u["errors"][k]), (u["label"], k)
    assert u["cpu_s"] > 0 and u["rhs_evals"] > 0 and u["steps"] > 0 and u["events"] >= 0
orders = {o["family"]: o["measured_order"] for o in d["orders"]}
assert abs(orders["rk4"] - 4) < 0.4, orders
# without event location the error jumps with where each contact falls in the grid: judge its
# order over the whole range of steps (the fit over the finest steps can land on a lucky pair)
span = {o["family"]: o["measured_order_over_range"] for o in d["orders"]}
assert span["rk4-noroot"] < orders["rk4"] - 0.5, (orders, span)
assert len(d["cheapest_at_target"]) == 12
assert "work_precision.csv" in d["files"] and "summary.json" in d["files"]
PY
grep -q "convergence order of the Poincare points" "$work/out.txt"; ok $? "prints the measured orders"
grep -q "cheapest at error 1e-06" "$work/out.txt"; ok $? "prints the cheapest setting per accuracy"

# bad input: the key and the valid values
"$G" check "$work/wp.ini" --set workprecision.families=rk4,erk9 > "$work/e1.txt" 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "workprecision.families: 'erk9'" "$work/e1.txt" && grep -q "valid orders of erk" "$work/e1.txt"
ok $? "erk9 refused (exit $rc): $(head -c 200 "$work/e1.txt")"
"$G" check "$work/wp.ini" --set workprecision.families=rk5 > "$work/e2.txt" 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "unknown family 'rk5'" "$work/e2.txt"; ok $? "unknown family refused (exit $rc)"
"$G" check "$work/wp.ini" --set workprecision.check_order=8 --set workprecision.reference_order=8 > "$work/e3.txt" 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "check_order" "$work/e3.txt"; ok $? "a check by the reference's own method refused (exit $rc)"
"$G" check "$work/wp.ini" --set workprecision.horizon_periods=50 > "$work/e4.txt" 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "horizon_periods: 50 longer than run.record_periods 20" "$work/e4.txt"
ok $? "a horizon longer than the window refused (exit $rc)"
"$G" check "$work/wp.ini" --set workprecision.rtol_tightest=1e-2 > "$work/e5.txt" 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "rtol_tightest" "$work/e5.txt"; ok $? "tolerances in the wrong order refused (exit $rc)"
# an interrupted or failed run leaves no partial files: a run whose reference cannot be computed
"$G" run "$work/wp.ini" --out "$work/fail" --set solver.max_events_per_period=1 --quiet > "$work/e6.txt" 2>&1; rc=$?
[ $rc -eq 1 ] && [ -z "$(ls -A "$work/fail" 2>/dev/null)" ]; ok $? "a failing transient stops with status 1 and no files (exit $rc)"

# check judges a fixed step against its method's stability region: the paper's pair (bta) at
# 2000 rpm has its groove modes at 19.4 kHz, so RK4 needs 43 steps per mesh period (h w <= 2 sqrt 2)
for spp in 32 64; do
    "$G" check "$SRC/cases/accuracy/periodn-2000rpm.ini" --set solver.method=rk4 --set solver.steps_per_period=$spp \
        > "$work/chk$spp.txt" 2>&1
done
grep -q "^stable_from_steps_per_period = 43   ; UNSTABLE" "$work/chk32.txt" &&
    grep -q "^stable_from_steps_per_period = 43$" "$work/chk64.txt"
ok $? "check: RK4 on the paper's pair at 2000 rpm unstable at 32 steps per period, stable at 64 (from 43)"
for spp in 16 32; do   # 4000 rpm: stable from 22 steps
    "$G" run "$SRC/cases/quickstart.ini" --out "$work/rk4-$spp" --set solver.method=rk4 --set solver.steps_per_period=$spp \
        --set run.transient_periods=20 --set run.record_periods=5 --set output.plots=off > "$work/rk4-$spp.txt" 2>&1
done
grep -q "note: solver.steps_per_period = 16 is outside the stability region.*stable from 22 steps" "$work/rk4-16.txt" &&
    ! grep -q "stability region" "$work/rk4-32.txt"
ok $? "run: a note when the fixed step is unstable (RK4 at 16 steps at 4000 rpm), none when stable (32)"
python3 - "$work/rk4-16/summary.json" "$work/rk4-32/summary.json" "$work/rk4-16.txt" <<'PY'
import json, re, sys
a = json.load(open(sys.argv[1]))["solver"]["fixed_step"]
b = json.load(open(sys.argv[2]))["solver"]["fixed_step"]
note = open(sys.argv[3]).read()
assert a["steps_per_period"] == 16 and a["stable"] is False and a["stable_from_steps_per_period"] == 22, a
assert b["steps_per_period"] == 32 and b["stable"] is True and b["stable_from_steps_per_period"] == 22, b
assert a["amplification"] > 1 >= b["amplification"] - 1e-9, (a, b)
# the same numbers as the note of the run
m = re.search(r"on the model's ([0-9.e+]+) Hz mode \(\|R\(h lambda\)\| = ([0-9.e+]+) per step\)", note)
assert m and abs(float(m.group(1)) - a["mode_hz"]) <= 1e-4 * a["mode_hz"], (m and m.groups(), a)
assert abs(float(m.group(2)) - a["amplification"]) <= 1e-2 * a["amplification"], (m.groups(), a)
PY
ok $? "run: summary.json's solver.fixed_step says whether the step is stable, from how many steps, as the note"
"$G" check "$SRC/cases/accuracy/periodn-2000rpm.ini" > "$work/chk-adaptive.txt" 2>&1
! grep -q "step_amplification" "$work/chk-adaptive.txt"; ok $? "check: an adaptive step is not judged"
"$G" run "$SRC/cases/quickstart.ini" --out "$work/adaptive" --set run.transient_periods=20 --set run.record_periods=5 \
    --set output.plots=off > /dev/null 2>&1 &&
    python3 -c "import json, sys; assert json.load(open(sys.argv[1]))['solver']['fixed_step'] is None" "$work/adaptive/summary.json"
ok $? "run: an adaptive step has no fixed_step in summary.json"

echo "1..$n"
[ $bad -eq 0 ]
