#!/usr/bin/env bash
# Bad input: every class of error gives one clear message "file:line: key: problem (valid: ...)",
# exit status 2, and writes nothing. TAP output.
set -u
G=${GEARDYN:?}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=0; bad=0
ok() { n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; bad=$((bad + 1)); fi; }

# case CONTENT EXPECTED_REGEX NAME
check_bad() {
    local content=$1 expect=$2 name=$3
    local f="$work/case.ini" out="$work/out-$n"
    printf '%s\n' "$content" > "$f"
    "$G" run "$f" --out "$out" --quiet > "$work/stdout" 2> "$work/stderr"
    local rc=$?
    local msg; msg=$(cat "$work/stderr")
    [ $rc -eq 2 ]; ok $? "$name: exit status 2 (got $rc)"
    echo "$msg" | grep -Eq -- "$expect"; ok $? "$name: message matches /$expect/ (got: $msg)"
    [ "$(echo "$msg" | wc -l)" -eq 1 ]; ok $? "$name: one line"
    [ ! -e "$out" ]; ok $? "$name: nothing written"
}

check_bad "[operating]
speed_rmp = 4000" "case.ini:2: speed_rmp: unknown key in \[operating\], did you mean operating.speed_rpm\? \(valid: .*speed_rpm" "unknown key with suggestion"
check_bad "[operatin]
speed_rpm = 4000" "case.ini:1: \[operatin\]: unknown section, did you mean \[operating\]\? \(valid: .*\[scene\]" "unknown section"
check_bad "[operating]
speed_rpm = fast" "case.ini:2: operating.speed_rpm: not a number: 'fast' \(valid: a finite number in \(0, 100000\] rpm\)" "wrong type"
check_bad "[clearance]
backlash_um = -3" "case.ini:2: clearance.backlash_um: out of range: '-3' \(valid: a finite number in \[0, 5000\] um\)" "out of range"
check_bad "[damping]
mesh_damping_ratio = nan" "case.ini:2: damping.mesh_damping_ratio: not finite: 'nan' \(valid: " "NaN"
check_bad "[operating]
torque_nm = inf" "case.ini:2: operating.torque_nm: not finite: 'inf'" "infinity"
check_bad "[scene]
model = bta3" "case.ini:2: scene.model: unknown choice 'bta3' \(valid: one of torsional,torsional-lr,bta\)" "bad choice"
check_bad "[run]
record_periods = 2.5" "case.ini:2: run.record_periods: not a whole number: '2.5' \(valid: a whole number in \[1, " "fractional integer"
check_bad "[operating]
speed_rpm = 4000
speed_rpm = 3000" "case.ini:3: operating.speed_rpm: given twice \(first at line 2\)" "duplicate key"
check_bad "[operating]
torque_nm = 500
power_kw = 200" "case.ini:3: operating.power_kw: give torque_nm or power_kw, not both" "conflicting keys"
check_bad "[gear]
teeth_pinion = 8
profile_shift_pinion = 0
[operating]
speed_rpm = 4000
torque_nm = 500" "case.ini:2: gear.teeth_pinion: pinion: undercut: z = 8 with profile shift 0 is undercut \\(needs x >= " "impossible geometry: undercut"
check_bad "[gear]
teeth_pinion = 12
helix_angle_deg = 0
profile_shift_pinion = 1.2
[operating]
speed_rpm = 4000
torque_nm = 500" "case.ini:4: gear.profile_shift_pinion: pinion: pointed tip: normal tip thickness .* \\(reduce profile shift or addendum\\)" "impossible geometry: pointed tip"
check_bad "[scene]
analysis = optimise" "case.ini:2: scene.analysis: unknown choice 'optimise' \\(valid: one of response,sweep,tca,ltca,optimize,compare-optimizers,work-precision,continuation,basins\\)" "unknown analysis"
# [optimize] (docs/optimisation.md)
check_bad "[scene]
analysis = compare-optimizers
[optimize]
optimizers = alo, gn_direct, ln_bobyqa
[operating]
torque_nm = 500" "case.ini:4: optimize.optimizers: unknown optimiser 'gn_direct' \\(valid: alo, gn_direct_l, .*random, moalo, weighted-sum, eps-constraint\\)" "optimize: unknown optimiser"
check_bad "[scene]
analysis = optimize
[optimize]
objective = sphere, rastrigin" "case.ini:4: optimize.objective: 2 objectives for optimize \\(valid: one of gear-lte, sphere, " "optimize: a list of objectives for optimize"
check_bad "[scene]
analysis = optimize
[optimize]
objective = sphere
dimension = 2.5" "case.ini:5: optimize.dimension: 2.5 \\(valid: whole numbers from 1 to 1000\\)" "optimize: fractional dimension"
check_bad "[scene]
analysis = optimize
[optimize]
tip_relief_length_min_mm = 5
tip_relief_length_max_mm = 3
[operating]
torque_nm = 500" "case.ini:5: optimize.tip_relief_length_max_mm: the bounds of tip_relief_length_mm are \\[5, 3\\] \\(valid: the lower bound below the upper\\)" "optimize: bounds in the wrong order"
check_bad "[scene]
analysis = optimize
[optimize]
lead_unmodified_length_max_mm = 45
[operating]
torque_nm = 500" "case.ini:4: optimize.lead_unmodified_length_max_mm: the box holds a modification that does not fit on the pinion .*modification.lead_unmodified_length_mm: 45 mm is longer than the pinion face of one half 40 mm" "optimize: a box larger than the flank"
check_bad "[scene]
analysis = optimize
[optimize]
population = 30
budget_evals = 50
[operating]
torque_nm = 500" "case.ini:5: optimize.budget_evals: a budget of 50 evaluations for ALO with 30 ants \\(valid: at least two populations, 60\\)" "optimize: budget below two ALO populations"
check_bad "[scene]
analysis = optimize
[optimize]
iterations = 10
budget_evals = 500
[operating]
torque_nm = 500" "case.ini:5: optimize.budget_evals: give iterations or budget_evals, not both" "optimize: iterations and budget"
check_bad "[scene]
analysis = optimize
[optimize]
shift = 0.3
[operating]
torque_nm = 500" "case.ini:4: optimize.shift: 0.3 for gear-lte \\(valid: 0; " "optimize: shift of the gear problem"
check_bad "[scene]
model = torsional
[output]
response_variable = y1L
[operating]
speed_rpm = 4000
torque_nm = 500" "case.ini:4: output.response_variable: 'y1L' is not a variable of this model \\(valid: lambda_L, dte_L, q\\)" "response variable of another model"
check_bad "[run]
transient_periods = 500
transient_max_periods = 400" "case.ini:3: run.transient_max_periods: 400 is below run.transient_periods = 500 \\(valid: 0, or at least transient_periods\\)" "adaptive transient shorter than the fixed one"
check_bad "this is not ini" "case.ini:1: syntax error" "syntax error"

# missing file
"$G" run "$work/nope.ini" --out "$work/nope" --quiet 2> "$work/stderr"; rc=$?
[ $rc -eq 2 ]; ok $? "missing file: exit 2 (got $rc)"
grep -q "nope.ini: cannot open case file" "$work/stderr"; ok $? "missing file: message ($(cat "$work/stderr"))"
[ ! -e "$work/nope" ]; ok $? "missing file: nothing written"

# --set errors name the option
printf '[scene]\nmodel = torsional\n' > "$work/ok.ini"
"$G" check "$work/ok.ini" --set operating.speed_rpm=-1 2> "$work/stderr" > /dev/null; rc=$?
[ $rc -eq 2 ] && grep -q -- "--set #1: operating.speed_rpm: out of range: '-1'" "$work/stderr"; ok $? "--set out of range ($(cat "$work/stderr"))"
"$G" check "$work/ok.ini" --set operating.sped_rpm=1 2> "$work/stderr" > /dev/null; rc=$?
[ $rc -eq 2 ] && grep -q "did you mean operating.speed_rpm" "$work/stderr"; ok $? "--set unknown key ($(cat "$work/stderr"))"
"$G" run 2> /dev/null; rc=$?; [ $rc -eq 2 ]; ok $? "no case file: exit 2"
"$G" frobnicate 2> /dev/null; rc=$?; [ $rc -eq 2 ]; ok $? "unknown command: exit 2"
"$G" run "$work/ok.ini" --bogus 2> /dev/null; rc=$?; [ $rc -eq 2 ]; ok $? "unknown option: exit 2"

echo "1..$n"
[ $bad -eq 0 ]
