#!/usr/bin/env bash
# The command line end to end: check, run (files, stable summary.json keys, atomicity),
# events. TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok

"$G" --version | grep -q "^geardyn [0-9]"; ok $? "--version"
"$G" --help | grep -q "geardyn run CASE"; ok $? "--help"

"$G" check "$SRC/cases/quickstart.ini" --set operating.speed_rpm=3000 > "$work/check.txt"; ok $? "check exits 0"
grep -Eq "^speed_rpm = 3000 rpm +; --set #1" "$work/check.txt"; ok $? "check shows the --set source"
grep -Eq "^teeth_pinion = 30 +; file line" "$work/check.txt"; ok $? "check shows the file source"
grep -Eq "^pinion_mass_kg = [0-9.]+ kg +; derived" "$work/check.txt"; ok $? "check shows derived values"
grep -Eq "^poisson_ratio = 0.3 +; default" "$work/check.txt"; ok $? "check shows defaults"
grep -Eq "^contact_ratio_transverse = 1\.[0-9]+" "$work/check.txt"; ok $? "check shows derived geometry"

# the operating point has no default; every other physical value taken from a default is listed by
# check and at the start of a run, as far as the analysis and model use it
printf '[gear]\narrangement = spur\nhelix_angle_deg = 0\nface_width_pinion_mm = 20\nface_width_gear_mm = 20\n[scene]\nmodel = torsional\n' > "$work/bare.ini"
"$G" check "$work/bare.ini" > /dev/null 2> "$work/bare.err"; rc=$?
[ $rc -eq 2 ] && grep -q "bare.ini: operating.speed_rpm: missing" "$work/bare.err"
ok $? "a response without its operating point exits 2 naming the key ($(cat "$work/bare.err"))"
"$G" check "$work/bare.ini" --set scene.analysis=tca > /dev/null 2>&1; ok $? "a TCA needs no operating point"
printf '[operating]\nspeed_rpm = 3000\ntorque_nm = 100\n' >> "$work/bare.ini"
"$G" check "$work/bare.ini" > "$work/bare.txt"; ok $? "with it, check exits 0"
assumed() { sed -n '/^# physical values the case does not give/,/^$/p' "$1"; }
assumed "$work/bare.txt" | grep -q "\[clearance\] backlash_um = 10\b" &&
    assumed "$work/bare.txt" | grep -q "ste_amplitude_um = 10\b" && assumed "$work/bare.txt" | grep -q "mesh_damping_ratio = 0.02" &&
    assumed "$work/bare.txt" | grep -q "density_kg_per_m3 = 7850" && assumed "$work/bare.txt" | grep -q "bore_diameter_pinion_mm = 0"
ok $? "check lists the backlash, STE, damping and bodies taken from defaults"
! assumed "$work/bare.txt" | grep -Eq "bearing_clearance_um|radial_stiffness|helix_angle_deg|groove_width|speed_rpm|torque_nm|modification|misalignment"
ok $? "and nothing the torsional spur response does not use ($(assumed "$work/bare.txt" | tr '\n' ' '))"
"$G" check "$work/bare.ini" --set scene.model=bta --set clearance.backlash_um=10 > "$work/bare2.txt"
assumed "$work/bare2.txt" | grep -q "bearing_clearance_um = 5" && ! assumed "$work/bare2.txt" | grep -q "backlash_um"
ok $? "with bta the bearing clearance joins the list; a key given leaves it"
"$G" check "$work/bare.ini" --set scene.analysis=ltca > "$work/bare3.txt"
assumed "$work/bare3.txt" | grep -q "\[misalignment\] axis_in_plane_arcmin = 0" && ! assumed "$work/bare3.txt" | grep -q "backlash_um"
ok $? "an LTCA lists the alignment it assumes, not the backlash"
"$G" run "$work/bare.ini" --out "$work/bare" --set run.transient_periods=20 --set run.record_periods=10 > /dev/null 2> "$work/bare.run"
head -1 "$work/bare.run" | grep -q "^geardyn: physical values the case does not give" && grep -q "^geardyn:   \[clearance\] backlash_um = 10" "$work/bare.run"
ok $? "a run lists them on its first lines ($(head -3 "$work/bare.run" | tr '\n' ' '))"
"$G" run "$work/bare.ini" --out "$work/bare" --quiet --set run.transient_periods=20 --set run.record_periods=10 > /dev/null 2> "$work/bare.q"
[ ! -s "$work/bare.q" ]; ok $? "--quiet prints none of it"

out="$work/run"
"$G" run "$SRC/cases/quickstart.ini" --out "$out" --quiet --set scene.model=torsional-lr \
    --set run.transient_periods=50 --set run.record_periods=20 > "$work/run.txt" 2>&1
ok $? "run exits 0 ($(head -c 300 "$work/run.txt"))"
for f in summary.json poincare.csv time_history.csv events.csv variable.csv variable_poincare.csv spectrum.csv; do
    [ -s "$out/$f" ]; ok $? "run wrote $f"
done
ls -a "$out" | grep -q '\.tmp'; [ $? -ne 0 ]; ok $? "no temporary files left"
python3 - "$out/summary.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
keys = ["solver.method", "solver.steps", "solver.rhs_evals", "solver.events", "solver.wall_s",
        "results.rms_accel_mps2", "results.motion", "results.poincare_distinct", "results.impact_regime"]
missing = []
for k in keys:
    o = d
    for part in k.split("."):
        if not isinstance(o, dict) or part not in o:
            missing.append(k); break
        o = o[part]
r = d["results"]
assert not missing, missing
assert r["motion"] == "not-periodic" or r["motion"].startswith("period-"), r["motion"]
assert r["impact_regime"] in ("no-impact", "single-sided", "double-sided"), r["impact_regime"]
for s in ("left", "right", "combined"):
    assert r["rms_accel_mps2"][s] > 0
assert d["case"]["parameters"]["scene"]["model"]["value"] == "torsional-lr"
assert d["case"]["parameters"]["scene"]["model"]["source"] == "--set #1"
assert d["solver"]["events"] == sum(d["solver"]["events_by_kind"].values())
PY
ok $? "summary.json has the stable keys with valid values"
head -1 "$out/time_history.csv" | grep -q "^t_s,period,lambda_L_um,lambda_dot_L_mps,accel_L_mps2"; ok $? "time history header with units"
rows=$(($(wc -l < "$out/time_history.csv") - 1)); [ "$rows" -eq $((20 * 64)) ]; ok $? "time history has record x samples rows ($rows)"
prow=$(($(wc -l < "$out/poincare.csv") - 1)); [ "$prow" -eq 21 ]; ok $? "poincare has record + 1 rows ($prow)"

head -1 "$out/spectrum.csv" | grep -q "^frequency_hz,order,amplitude_um$"; ok $? "spectrum header"
python3 - "$out/spectrum.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
best = max(rows[1:], key=lambda r: float(r["amplitude_um"]))
assert abs(float(best["order"]) - 1.0) < 1e-9, best  # the mesh frequency dominates
PY
ok $? "the spectrum's largest line is the mesh frequency (order 1)"
"$G" run "$SRC/cases/quickstart.ini" --out "$work/run3" --quiet --set scene.model=torsional-lr \
    --set run.transient_periods=20 --set run.record_periods=10 --set output.response_variable=qR > /dev/null 2>&1
ok $? "a degree of freedom as the response variable"
head -1 "$work/run3/variable.csv" | grep -q "^t_s,qR_um,qR_rate_mps$"; ok $? "variable.csv names it"
"$G" events "$out/events.csv" --recorded --csv "$work/ev.csv" > "$work/ev.txt"; ok $? "events exits 0"
grep -q "impact regime:" "$work/ev.txt"; ok $? "events prints the impact regime"
regime=$(python3 -c "import json;print(json.load(open('$out/summary.json'))['results']['impact_regime'])")
grep -q "impact regime: $regime" "$work/ev.txt"; ok $? "events regime agrees with the run ($regime)"
sel=$(grep -o "[0-9]* selected" "$work/ev.txt" | cut -d' ' -f1)
[ $(($(wc -l < "$work/ev.csv") - 1)) -eq "$sel" ]; ok $? "events --csv wrote the selected rows ($sel)"
"$G" events "$out/events.csv" --clearance mesh-L --kind contact > "$work/ev2.txt"; ok $? "events filter"
grep -Eq "^mesh-R" "$work/ev2.txt"; [ $? -ne 0 ]; ok $? "events filter keeps one clearance"
"$G" events "$SRC/cases/quickstart.ini" > /dev/null 2>&1; rc=$?; [ $rc -eq 2 ]; ok $? "events refuses a non-log (exit $rc)"

# without gnuplot: a note, not an error, and no pictures
env PATH=/nonexistent "$G" run "$SRC/cases/quickstart.ini" --out "$work/nogp" --set scene.model=torsional \
    --set run.transient_periods=10 --set run.record_periods=5 > "$work/nogp.txt" 2>&1; rc=$?
[ $rc -eq 0 ]; ok $? "without gnuplot the run still succeeds (exit $rc)"
grep -q "note: gnuplot is not installed" "$work/nogp.txt"; ok $? "and notes it ($(tail -c 200 "$work/nogp.txt" | tr "\n" " "))"
ls "$work/nogp" | grep -q "png\|svg"; [ $? -ne 0 ]; ok $? "and draws nothing"

# [solver] keys reach the integrator: with fixed_step = on the steps are the period's share (a
# 13-stage table at 40 steps per period takes at least 40 x 30 steps; adaptive it takes fewer)
for fs in on off; do
    "$G" run "$SRC/cases/quickstart.ini" --out "$work/fs_$fs" --quiet --set scene.model=torsional \
        --set run.transient_periods=20 --set run.record_periods=10 --set solver.fixed_step=$fs \
        --set solver.steps_per_period=40 > /dev/null 2>&1
done
python3 - "$work/fs_on/summary.json" "$work/fs_off/summary.json" <<'PY'
import json, sys
on, off = (json.load(open(f))["solver"] for f in sys.argv[1:3])
assert on["steps"] >= 40 * 30 and off["steps"] < 40 * 30, (on["steps"], off["steps"])
PY
ok $? "solver.fixed_step = on fixes the step at the period over steps_per_period"

# a failure at run time leaves nothing behind: zero torque and no damping never re-engages
out2="$work/run2"
"$G" run "$SRC/cases/quickstart.ini" --out "$out2" --quiet --set scene.model=torsional --set operating.torque_nm=0 \
  --set excitation.ste_amplitude_um=0 --set damping.mesh_damping_ratio=0.3 --set run.initial_condition=zero \
  --set clearance.backlash_um=20 --set run.transient_periods=3000 > "$work/run2.txt" 2>&1; rc=$?
[ $rc -eq 1 ]; ok $? "endless separation stops with status 1 (got $rc: $(cat "$work/run2.txt"))"
grep -q "separated for" "$work/run2.txt"; ok $? "endless separation is explained"
[ -z "$(ls -A "$out2" 2>/dev/null)" ]; ok $? "failed run leaves no files"

echo "1..$n"
[ $bad -eq 0 ]
