#!/usr/bin/env bash
# analysis = continuation on the command line (docs/continuation.md): cases/continuation/kahraman-singh.ini
# (Kahraman & Singh, constant stiffness, Omega 0.5 to 1.5 through operating.speed_rpm) writes
# branch.csv, bifurcations.csv, summary.json and the picture; the branch from Omega 0.5 has the
# grazing, the two folds and the period doubling where tests/test_continuation.c finds them with the
# library directly (to 1e-8 in Omega: the locate tolerance is 1e-8 in arclength; the grazing against
# its closed form 1/sqrt(1.99)); its stable points have |mu_max| < 1; the period-2 branch switched to at
# the period doubling starts there, period-doubles again where the library test finds it, and the
# period-4 branch born there runs to the bound; each switched branch is followed back to its doubling;
# max_branches bounds their number; end_reason says the bound in rpm; to Omega 2, each curve of doubled
# orbits joining two period doublings is followed once and names both; a user's spur pair runs on the
# default settings. Bad [continuation] settings are
# refused with exit 2 naming file, line and key, and
# nothing is written. TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok
KS="$SRC/cases/continuation/kahraman-singh.ini"

"$G" check "$KS" > "$work/check.txt"; ok $? "check exits 0 on kahraman-singh.ini"
grep -Eq "^parameter = operating.speed_rpm +; file line" "$work/check.txt"; ok $? "check lists continuation.parameter"
grep -Eq "^locate_tol = 1e-08 +; file line" "$work/check.txt"; ok $? "check lists continuation.locate_tol"

out="$work/ks"
"$G" run "$KS" --out "$out" --quiet > "$work/run.txt" 2>&1; ok $? "run exits 0 ($(head -c 300 "$work/run.txt"))"
# the progress on stderr: one line per count of branches followed, never the same line twice (both
# directions from the middle, then the switchings at the doublings, which add two branches)
"$G" run "$KS" --out "$work/ks-progress" --set output.plots=off --set continuation.direction=both \
    --set continuation.max_branches=4 > /dev/null 2> "$work/progress.txt"
grep "continuation:" "$work/progress.txt" > "$work/progress2.txt"
[ -s "$work/progress2.txt" ] && [ -z "$(sort "$work/progress2.txt" | uniq -d)" ] && tail -1 "$work/progress2.txt" | grep -q "4 of 4 branches"
ok $? "progress: each line once, ending at 4 of 4 branches ($(tr '\n' ' ' < "$work/progress2.txt"))"
for f in branch.csv bifurcations.csv summary.json; do
    [ -s "$out/$f" ]; ok $? "wrote $f"
done
ls -a "$out" | grep -Eq '\.tmp'; [ $? -ne 0 ]; ok $? "no temporary files left"
python3 - "$out" > "$work/checks.txt" <<'PY'
import csv, json, sys
d = sys.argv[1]
scale = 3183.0988618379  # rpm per unit of Omega (the case's comment)
br = list(csv.DictReader(open(d + "/branch.csv")))
bf = list(csv.DictReader(open(d + "/bifurcations.csv")))
s = json.load(open(d + "/summary.json"))
def ok(c, msg):
    print(("PASS " if c else "FAIL ") + msg)
# the values tests/test_continuation.c prints for alpha 0 (docs/continuation.md section 4)
expect = [("contact-change", 1.99 ** -0.5), ("fold", 0.7313611271), ("fold", 0.5853315696),
          ("period-doubling", 1.2267006347)]
b0 = [b for b in bf if b["branch"] == "0"]
ok([b["kind"] for b in b0] == [k for k, _ in expect], "branch 0: grazing, fold, fold, period doubling in this "
   "order (%s)" % [b["kind"] for b in b0])
for (k, om), b in zip(expect, b0):
    got = float(b["speed_rpm"]) / scale
    ok(abs(got - om) < 1e-8, "%s at Omega %.10f (library test %.10f, |d| %.2g)" % (k, got, om, abs(got - om)))
    ok(abs(float(b["continuation_p"]) - got) < 1e-9, "%s: continuation_p is Omega" % k)
pd = [b for b in b0 if b["kind"] == "period-doubling"]
ok(pd and abs(float(pd[0]["mu_re"]) + 1) < 1e-4, "the period doubling's multiplier is -1")
ok(b0 and b0[0]["clearance"] == "mesh", "the grazing names the clearance 'mesh'")
p0 = [r for r in br if r["branch"] == "0"]
ok(abs(float(p0[0]["speed_rpm"]) / scale - 0.5) < 1e-12 and abs(float(p0[-1]["speed_rpm"]) / scale - 1.5) < 1e-9,
   "branch 0 runs from Omega 0.5 to the bound 1.5")
ok(all((r["stable"] == "1") == (float(r["mu_max"]) < 1) for r in br), "stable exactly where |mu_max| < 1")
below = []
for r in p0:  # the points from the start up to the grazing
    if float(r["speed_rpm"]) / scale >= 0.7088:
        break
    below.append(r)
ok(len(below) > 5 and all(int(r["events_mesh"]) == 0 for r in below), "no mesh event below the grazing (%d points)"
   % len(below))
ok(all(float(r["lambda_min_L_um"]) >= 10 - 1e-6 for r in below),
   "below the grazing the teeth never separate: lambda_min_L >= b = 10 um")
b1 = [r for r in br if r["branch"] == "1"]
ok(b1 and b1[0]["period_n"] == "2" and abs(float(b1[0]["speed_rpm"]) / scale - 1.2267) < 0.02,
   "branch 1: period 2, switched to near the period doubling")
sb = s["results"]["branches"]
ok(s["analysis"] == "continuation" and sb[0]["end"] == "bound" and
   "branch.csv" in s["files"] and "summary.json" in s["files"], "summary.json: the first branch to its bound, "
   "the files")
# the end in the key's unit: the bound 1.5 as rpm, and p
ok("operating.speed_rpm = 4774.648293 rpm" in sb[0]["end_reason"] and "p = 1.5" in sb[0]["end_reason"],
   "end_reason in rpm and p (%s)" % sb[0]["end_reason"])
# the cascade: period 1 -> 2 at Omega 1.2267, 2 -> 4 on the switched branch at 1.4004 (the library test's
# 1.4003789567); each switched branch followed away from its doubling and back to it
ok([(b["period_n"], b["direction"], b["switched_from_branch"]) for b in sb] ==
   [(1, "up", None), (2, "up", 0), (2, "down", 0), (4, "up", 1), (4, "down", 1)],
   "five branches: 1; 2 up and back from branch 0; 4 up and back from branch 1 (%s)"
   % [(b["period_n"], b["direction"], b["switched_from_branch"]) for b in sb])
pd1 = [b for b in bf if b["branch"] == "1" and b["kind"] == "period-doubling"]
ok(len(pd1) == 1 and abs(float(pd1[0]["speed_rpm"]) / scale - 1.4003789567) < 1e-7,
   "branch 1 (period 2) period-doubles at Omega 1.4003789567 (%s)" % [b["speed_rpm"] for b in pd1])
for b, born in ((2, 1.2267006331), (4, 1.4003789567)):
    ok(len(sb) > b and sb[b]["end"] == "period-doubling" and abs(sb[b]["last"] / scale - born) < 0.01
       and abs(sb[b]["last"] / scale - born) > 0, "branch %d ends back at the doubling at Omega %.4f (last %.6f)"
       % (b, born, sb[b]["last"] / scale if len(sb) > b else 0))
b3 = [r for r in br if r["branch"] == "3"]
ok(b3 and all(r["period_n"] == "4" for r in b3) and abs(float(b3[-1]["speed_rpm"]) / scale - 1.5) < 1e-9,
   "branch 3: period 4 up to the bound 1.5")
PY
ok $? "branch.csv, bifurcations.csv and summary.json read"
while IFS= read -r line; do
    case "$line" in
        PASS\ *) ok 0 "${line#PASS }" ;;
        *) ok 1 "${line#FAIL }" ;;
    esac
done < "$work/checks.txt"

# refusals: exit 2, file:line and key named, nothing written
refuse() { # key=value, pattern of the message[, another key=value]
    local o="$work/bad"
    rm -rf "$o"
    "$G" run "$KS" --out "$o" --quiet --set "$1" ${3:+--set "$3"} > "$work/bad.txt" 2>&1
    local rc=$?
    [ $rc -eq 2 ] && grep -Eq -e "$2" "$work/bad.txt" && [ ! -e "$o" ]
    ok $? "--set $1 refused with exit 2 (rc $rc: $(head -c 200 "$work/bad.txt"))"
}
refuse continuation.parameter=gear.teeth_pinion "continuation.parameter: 'gear.teeth_pinion' is not a real-valued"
refuse continuation.parameter=operating.nothing "continuation.parameter: 'operating.nothing'"
refuse continuation.to=1000 "--set #1: continuation.to: 1000 is not above from"
refuse continuation.from=-5 "continuation.from: operating.speed_rpm = -5 is out of range"
refuse continuation.ds=0.2 "continuation.ds: 0.2 is outside \[ds_min, ds_max\]"
refuse continuation.period=17 "continuation.period"
refuse continuation.direction=sideways "continuation.direction"
refuse continuation.start_value=9000 "continuation.start_value: 9000 is outside the bounds"
refuse continuation.newton_tol=1e-13 "continuation.newton_tol: 1e-13 is below solver.atol = 1e-12, the absolute error"
refuse continuation.overlay_sweep=/nonexistent "continuation.overlay_sweep: no /nonexistent/sweep.csv" \
    continuation.response=rms_accel
refuse continuation.overlay_sweep=/nonexistent "continuation.overlay_sweep: a sweep has no deflection extremes"
refuse continuation.start=state "continuation.state: '' \(valid: with start = state"
refuse continuation.state=1,2 "continuation.state: given with start = attractor"
refuse continuation.max_branches=0 "continuation.max_branches"
refuse continuation.start_sweep=/tmp "continuation.start_sweep: given with start = attractor"
refuse continuation.start=sweep "continuation.start_sweep: missing"
# max_branches bounds the cascade: 3 branches, the doubling on branch 1 not switched, said in notes
"$G" run "$KS" --out "$work/mb" --quiet --set continuation.max_branches=3 --set output.plots=off > "$work/mb.txt" 2>&1
ok $? "max_branches = 3 runs"
python3 -c '
import json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))["results"]
assert len(s["branches"]) == 3, len(s["branches"])
assert any("max_branches" in n for n in s["notes"]), s["notes"]
' "$work/mb"
ok $? "max_branches = 3: three branches, a note for the doubling not switched"
# to Omega 2: the period-2 orbits form one curve between the period doublings of the period-1 branch at
# Omega 1.2267 and 1.9527 (branch 1 from the first to the second, branch 2 back to the first): it is followed
# once, and the doubling at 1.9527 is named as the one it joins, not switched at again; the same for the
# period-4 curve between the doublings of branch 1 at 1.4004 and 1.8462, and the period-8 one between those
# of the period-4 branch; no branch ends on the point budget
"$G" run "$KS" --out "$work/o2" --quiet --set continuation.to=6366.1977236758 --set continuation.max_points=400 \
    --set continuation.max_branches=7 --set output.plots=off > "$work/o2.txt" 2>&1
ok $? "continuation to Omega 2 runs"
python3 -c '
import json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))["results"]
b = s["branches"]
scale = 3183.0988618379
ends = [x["end"] for x in b]
assert "budget" not in ends, ends
def born(x): return x["born_at"] / scale if x["born_at"] is not None else None
def joins(x): return (x["joins_doubling"]["branch"], x["joins_doubling"]["value"] / scale) if x["joins_doubling"] else None
p2 = [x for x in b if x["period_n"] == 2]
assert len(p2) == 2, [(x["period_n"], born(x)) for x in b]
assert all(abs(born(x) - 1.2267006347) < 1e-8 for x in p2), [born(x) for x in p2]
j = sorted(joins(x) for x in p2)
assert j[0][0] == 0 and abs(j[0][1] - 1.2267006347) < 1e-8 and j[1][0] == 0 and abs(j[1][1] - 1.9526847) < 1e-6, j
p4 = [x for x in b if x["period_n"] == 4]
assert len(p4) == 2 and all(joins(x) and joins(x)[0] == p2[0]["branch"] for x in p4), [joins(x) for x in p4]
assert sorted(round(joins(x)[1], 4) for x in p4) == [1.4004, 1.8462], [joins(x) for x in p4]
import csv
rows = list(csv.DictReader(open(sys.argv[1] + "/bifurcations.csv")))
for x in b:
    if joins(x):
        near = [r for r in rows if int(r["branch"]) == x["branch"] and r["kind"] == "fold" and
                abs(float(r["continuation_p"]) - joins(x)[1]) < 1e-3]
        assert not near, ("a fold listed at the doubling a branch joins", x["branch"], near)
print("# branches:", [(x["period_n"], x["direction"], born(x), joins(x), x["end"]) for x in b])
' "$work/o2"
ok $? "to Omega 2: each curve of doubled orbits followed once, from the doubling it was born at to the one it joins (both named), none on the budget"
# a user's spur pair (the NASA Glenn spur rig pair: 28/28 teeth, module 3.175 mm, 20 deg, face 6.35 mm, 72 N m,
# backlash 127 um) in rpm, with every [continuation] setting at its default: it runs, from the attractor at
# 9000 rpm both ways to the bounds 2000 and 16000 rpm, through the folds of its softening resonance (where a
# brute-force sweep of the same pair jumps: up between 9700 and 9800 rpm, down between 6500 and 6400), and no
# branch uses up its point budget
cat > "$work/spur.ini" <<'INI'
[scene]
analysis = continuation
model = torsional
[gear]
arrangement = spur
normal_module_mm = 3.175
teeth_pinion = 28
teeth_gear = 28
helix_angle_deg = 0
normal_pressure_angle_deg = 20
face_width_pinion_mm = 6.35
face_width_gear_mm = 6.35
[operating]
speed_rpm = 5000
torque_nm = 72
[clearance]
backlash_um = 127
[continuation]
parameter = operating.speed_rpm
from = 2000
to = 16000
INI
"$G" run "$work/spur.ini" --out "$work/spur" --quiet --set output.plots=off > "$work/spur.txt" 2>&1
ok $? "a spur pair in rpm with the default [continuation] settings runs ($(head -c 300 "$work/spur.txt"))"
python3 -c '
import csv, json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))["results"]
b = s["branches"]
f = [float(x["speed_rpm"]) for x in csv.DictReader(open(sys.argv[1] + "/bifurcations.csv")) if x["kind"] == "fold"]
assert [x["end"] for x in b] == ["bound", "bound"], [(x["end"], x["points"]) for x in b]
assert sorted([b[0]["last"], b[1]["last"]]) == [2000, 16000], [x["last"] for x in b]
assert max(x["points"] for x in b) < 400, [x["points"] for x in b]
assert any(9700 < v < 9800 for v in f) and any(6400 < v < 6500 for v in f), f
print("# points", [x["points"] for x in b], "folds", f)
' "$work/spur"
ok $? "the spur pair: both branches to their bounds within the budget, the folds where a sweep jumps"
# the same pair in the bta model: down from 9000 rpm the branch passes a branch point onto a closed curve
# of orbits (between folds at 6322 and 8436 rpm) that does not hold its first point; it ends once round
# that curve, back at a point it passed, not on the point budget
sed 's/^model = torsional/model = bta/' "$work/spur.ini" > "$work/spur-bta.ini"
"$G" run "$work/spur-bta.ini" --out "$work/spur-bta" --quiet --set output.plots=off \
    --set continuation.branch_switching=off > "$work/spur-bta.txt" 2>&1
ok $? "the spur pair in the bta model runs on the default settings ($(head -c 300 "$work/spur-bta.txt"))"
python3 -c '
import json, sys
b = json.load(open(sys.argv[1] + "/summary.json"))["results"]["branches"]
assert b[0]["end"] == "closed" and "back at the orbit of its point" in b[0]["end_reason"], b[0]["end_reason"]
assert b[0]["points"] < 400 and b[1]["end"] == "bound", [(x["end"], x["points"]) for x in b]
print("#", b[0]["points"], "points:", b[0]["end_reason"])
' "$work/spur-bta"
ok $? "the spur pair in the bta model: the branch down ends once round the closed curve it entered, within the budget"

# in the file: the message names its line
sed 's/^to = .*/to = 1000/' "$KS" > "$work/bad.ini"
line=$(grep -n '^to = 1000' "$work/bad.ini" | cut -d: -f1)
"$G" run "$work/bad.ini" --out "$work/bad2" --quiet > "$work/bad.txt" 2>&1
rc=$?
[ $rc -eq 2 ] && grep -q "bad.ini:$line: continuation.to: 1000 is not above from" "$work/bad.txt" && [ ! -e "$work/bad2" ]
ok $? "to = 1000 in the file refused at its line $line (rc $rc: $(head -c 200 "$work/bad.txt"))"
# the NASA Glenn spur pair (docs/guide.md): its period-2 orbits form a curve between the period doublings
# of the period-1 branch at 6365.78 and 6592.91 rpm. Switched at the first, the orbit is found 1 % of the
# range above it, where the branch bends sharply: the way back down must reach the doubling it was born at,
# not jump onto the branch's way up (where the parameter's reversal would be reported as a fold with no
# multiplier at 1, a complex pair 0.38 + 0.39i)
"$G" run "$SRC/cases/guide/nasa-grc-spur-continuation.ini" --out "$work/nasa" --quiet --set output.plots=off \
    --set continuation.overlay_sweep= > "$work/nasa.txt" 2>&1
python3 -c '
import csv, json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))["results"]
p2 = [x for x in s["branches"] if x["period_n"] == 2 and x["born_at"] is not None and abs(x["born_at"] - 6365.78) < 0.01]
assert len(p2) == 2, [(x["period_n"], x["born_at"]) for x in s["branches"]]
ends = sorted((x["end"], round(x["joins_doubling"]["value"], 2)) for x in p2)
assert ends == [("period-doubling", 6365.78), ("period-doubling", 6592.91)], ends
ids = {x["branch"] for x in p2}
rows = [r for r in csv.DictReader(open(sys.argv[1] + "/bifurcations.csv")) if int(r["branch"]) in ids]
assert not [r for r in rows if r["kind"] in ("fold", "branch-point")], rows
' "$work/nasa"
ok $? "NASA Glenn pair: the period-2 branch followed from its doubling at 6365.78 rpm both ways to a doubling (the one it was born at and 6592.91 rpm), no fold on it"

echo "1..$n"
[ $bad -eq 0 ]
