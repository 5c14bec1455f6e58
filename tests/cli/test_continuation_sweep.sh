#!/usr/bin/env bash
# continuation.start = sweep (docs/continuation.md section 7): a sweep of Kahraman & Singh's
# oscillator (cases/continuation/kahraman-singh.ini as a sweep in the speed, Omega 0.5 to 1.5 in
# steps of 0.05, up and down) writes states.csv, every point's final state at mesh phase 0; a
# continuation started from its point at Omega 1 lands on the orbit that start = attractor finds
# there (states to 1e-8); in the hysteresis interval (Omega 0.65) the up point starts the
# non-impacting orbit and the down point the impacting one, as each branch of the sweep was; the
# period-4 point at Omega 1.5 starts a period-4 orbit (its period taken from the sweep) whose
# mesh deflection at phase 0 is one of the sweep's four Poincare values there, and so is that of
# the period-4 branch the cascade of the plain continuation reaches from Omega 0.5. A directory
# that is missing, not a sweep, a sweep of another model or in another key is refused with exit 2
# naming the key, and nothing is written. TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok
KS="$SRC/cases/continuation/kahraman-singh.ini"
SWEEP=(--set scene.analysis=sweep --set sweep.parameter=operating.speed_rpm --set sweep.from=1591.5494309189
       --set sweep.to=4774.6482927569 --set sweep.points=21 --set run.record_periods=50
       --set run.lyapunov_exponents=0 --set output.plots=off)
QUICK=(--set output.plots=off --set continuation.max_points=3 --set continuation.branch_switching=off)

"$G" run "$KS" --out "$work/sweep" --quiet "${SWEEP[@]}" > "$work/sweep.txt" 2>&1
ok $? "the sweep runs ($(head -c 200 "$work/sweep.txt"))"
python3 - "$work/sweep" <<'PY'
import csv, json, sys
d = sys.argv[1]
rows = list(csv.DictReader(open(d + "/states.csv")))
s = json.load(open(d + "/summary.json"))
assert s["files"] == ["sweep.csv", "bifurcation.csv", "states.csv", "summary.json"], s["files"]
assert list(rows[0].keys()) == ["speed_rpm", "direction", "period_n", "status", "q", "q_dot"], list(rows[0].keys())
sw = list(csv.DictReader(open(d + "/sweep.csv")))
assert [(r["direction"], r["period_n"]) for r in rows] == [(r["direction"], r["period_n"]) for r in sw]
assert all("%.12g" % float(a["speed_rpm"]) == b["parameter"] for a, b in zip(rows, sw))
PY
ok $? "states.csv: one row per point of sweep.csv, same order, values and periods; listed in summary.json"

# Omega 1 (3183.09886184 rpm as the sweep's tables print it): from the up point and from the attractor
V=3183.09886184
"$G" run "$KS" --out "$work/from-sweep" --quiet "${QUICK[@]}" --set continuation.start=sweep \
    --set continuation.start_sweep="$work/sweep" --set continuation.start_value=$V > "$work/c1.txt" 2>&1
ok $? "start = sweep runs ($(head -c 200 "$work/c1.txt"))"
"$G" run "$KS" --out "$work/from-attr" --quiet "${QUICK[@]}" --set continuation.start_value=$V > "$work/c2.txt" 2>&1
ok $? "start = attractor at the same value runs"
cmp_start() { # dir1 dir2 tolerance: the first orbit of branch 0 (value and state) of both
python3 - "$1" "$2" "$3" <<'PY'
import csv, sys
a, b = (list(csv.DictReader(open(d + "/branch.csv")))[0] for d in sys.argv[1:3])
tol = float(sys.argv[3])
d = max(abs(float(a[k]) - float(b[k])) for k in ("q", "q_dot"))
print("%.2g" % d)
sys.exit(0 if a["speed_rpm"] == b["speed_rpm"] and a["period_n"] == b["period_n"] and d < tol else 1)
PY
}
dd=$(cmp_start "$work/from-sweep" "$work/from-attr" 1e-8); ok $? "the sweep's point at Omega 1 starts the attractor's orbit (|dy| $dd < 1e-8)"
grep -q "\"start_sweep_point\": \"sweep $work/sweep, up, speed_rpm = 3183.098862\"" "$work/from-sweep/summary.json"
ok $? "summary.json names the sweep's point"
python3 - "$work" <<'PY'
import csv, sys
o = list(csv.DictReader(open(sys.argv[1] + "/from-sweep/branch.csv")))[0]
s = [r for r in csv.DictReader(open(sys.argv[1] + "/sweep/sweep.csv")) if r["parameter"] == "3183.09886184" and r["direction"] == "up"][0]
a, b = float(o["dynamic_load_factor"]), float(s["dynamic_load_factor"])
print("# dynamic load factor: orbit", a, "sweep", b)
sys.exit(0 if a > 1 and abs(a - b) < 1e-6 * a else 1)
PY
ok $? "the orbit's dynamic load factor is the sweep point's there (same samples of one period)"

# the hysteresis interval: Omega 0.65, up on the orbit without impacts, down on the impacting one
V=2069.01426019
for dir in up down; do
    "$G" run "$KS" --out "$work/h-$dir" --quiet "${QUICK[@]}" --set continuation.start=sweep \
        --set continuation.start_sweep="$work/sweep" --set continuation.start_sweep_direction=$dir \
        --set continuation.start_value=$V > "$work/h.txt" 2>&1
    ok $? "start = sweep, $dir point at Omega 0.65 runs"
done
python3 - "$work" <<'PY'
import csv, sys
up, down = (list(csv.DictReader(open("%s/h-%s/branch.csv" % (sys.argv[1], d))))[0] for d in ("up", "down"))
sys.exit(0 if int(up["events_mesh"]) == 0 and int(down["events_mesh"]) > 0 and up["stable"] == down["stable"] == "1"
         and abs(float(up["q"]) - float(down["q"])) > 1e-3 else 1)
PY
ok $? "at Omega 0.65 the up point starts the stable orbit without impacts, the down point the stable impacting one"

# the period-4 point at Omega 1.5, and the cascade from Omega 0.5
V=4774.6482927569
"$G" run "$KS" --out "$work/p4" --quiet "${QUICK[@]}" --set continuation.start=sweep --set continuation.direction=down \
    --set continuation.start_sweep="$work/sweep" --set continuation.start_value=$V > "$work/p4.txt" 2>&1
ok $? "start = sweep at the period-4 point runs ($(head -c 200 "$work/p4.txt"))"
"$G" run "$KS" --out "$work/cascade" --quiet --set output.plots=off > "$work/cascade.txt" 2>&1
ok $? "the plain continuation from Omega 0.5 runs"
python3 - "$work" <<'PY'
import csv, json, sys
w = sys.argv[1]
p4 = list(csv.DictReader(open(w + "/p4/branch.csv")))[0]
s = json.load(open(w + "/p4/summary.json"))["results"]
lam = sorted({round(float(r["lambda_L"]), 6) for r in csv.DictReader(open(w + "/sweep/bifurcation.csv"))
              if r["direction"] == "up" and r["parameter"] == "4774.64829276"})
casc = [r for r in csv.DictReader(open(w + "/cascade/branch.csv")) if r["period_n"] == "4"
        and abs(float(r["continuation_p"]) - 1.5) < 1e-12]
near = lambda x: min(abs(float(x) - l) for l in lam)
print("# sweep's lambda_L at Omega 1.5:", lam, "start:", p4["lambda_L"], "cascade:", [r["lambda_L"] for r in casc])
ok = (s["start_period_n"] == 4 and s["start_period_found"] and p4["period_n"] == "4" and len(lam) == 4
      and near(p4["lambda_L"]) < 1e-6 and casc and all(near(r["lambda_L"]) < 1e-6 for r in casc))
sys.exit(0 if ok else 1)
PY
ok $? "Omega 1.5: the sweep's period-4 point and the cascade's period-4 branch have one of its 4 Poincare values"

# refusals: exit 2, the key named, nothing written
refuse() { # pattern, then --set arguments
    local pat=$1 o="$work/bad"
    shift
    rm -rf "$o"
    "$G" run "$KS" --out "$o" --quiet --set continuation.start=sweep "$@" > "$work/bad.txt" 2>&1
    local rc=$?
    [ $rc -eq 2 ] && grep -Eq -e "$pat" "$work/bad.txt" && [ ! -e "$o" ]
    ok $? "refused with exit 2: $pat (rc $rc: $(head -c 300 "$work/bad.txt"))"
}
"$G" run "$KS" --out "$work/other-model" --quiet "${SWEEP[@]}" --set clearance.backlash_um=25 > /dev/null 2>&1
"$G" run "$KS" --out "$work/other-key" --quiet "${SWEEP[@]}" --set sweep.parameter=clearance.backlash_um \
    --set sweep.from=10 --set sweep.to=30 --set sweep.points=3 > /dev/null 2>&1
refuse "continuation.start_sweep: $work/none/summary.json" --set continuation.start_sweep="$work/none"
refuse "continuation.start_sweep: $work/from-attr holds the output of continuation, not of a sweep" \
    --set continuation.start_sweep="$work/from-attr"
refuse "continuation.start_sweep: the sweep in $work/other-model is of another model: clearance.backlash_um = 25 there, 20 here" \
    --set continuation.start_sweep="$work/other-model"
refuse "continuation.start_sweep: the sweep in $work/other-key varies clearance.backlash_um" \
    --set continuation.start_sweep="$work/other-key"
refuse "continuation.start_sweep_direction: .* has no finished independent point" \
    --set continuation.start_sweep="$work/sweep" --set continuation.start_sweep_direction=independent
refuse "continuation.start_sweep: the sweep's down point at 4456.338407 is not periodic" \
    --set continuation.start_sweep="$work/sweep" --set continuation.start_sweep_direction=down \
    --set continuation.start_value=4456.3384
sed 's/"states.csv",//' "$work/sweep/summary.json" > "$work/s.json"
mkdir -p "$work/nostates" && cp "$work/s.json" "$work/nostates/summary.json"
refuse "continuation.start_sweep: the sweep in $work/nostates has no states.csv" \
    --set continuation.start_sweep="$work/nostates"
echo "1..$n"
[ $bad -eq 0 ]
