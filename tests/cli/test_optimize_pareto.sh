#!/usr/bin/env bash
# Two objectives at once from a case (docs/optimisation.md section 13): optimize on ZDT1 and ZDT2
# (MOALO, weighted sums, epsilon-constraints, random search) and on the gear's LTE and dynamic
# response. Every row of pareto.csv is non-dominated among all the run's evaluations and every
# evaluation is dominated by or equal to a row (the front is complete); the hypervolume recomputed
# from pareto.csv is summary.json's and the last of evaluations.csv; MOALO's front on ZDT1 is within
# 5 % of the true front's hypervolume; 1 and 2 threads give the same front. TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok

check_front() { # DIR
python3 - "$1" <<'PY'
import csv, json, sys
d = sys.argv[1]
s = json.load(open(d + "/summary.json"))
r, st = s["results"], s["settings"]
c0, c1 = st["objective_columns"]
ref = st["hv_reference"]
front = [(float(x[c0]), float(x[c1])) for x in csv.DictReader(open(d + "/pareto.csv"))]
ev = [x for x in csv.DictReader(open(d + "/evaluations.csv")) if int(x["run"]) == r["best_run"]]
pts = [(float(x[c0]), float(x[c1])) for x in ev]
assert len(front) == r["front_points"] > 0 and len(ev) == r["evaluations"]
dom = lambda a, b: a[0] <= b[0] and a[1] <= b[1] and a != b
for p in front:  # non-dominated among every evaluation, and one of them
    assert not any(dom(q, p) for q in pts), p
    assert p in pts, p
for q in pts:  # complete: every evaluation is dominated by or equal to a point of the front
    assert any(p == q or dom(p, q) for p in front), q
assert front == sorted(front)
# the hypervolume within the reference point, recomputed (a staircase of boxes)
hv, prev = 0.0, ref[1]
for p in front:
    if p[0] < ref[0] and p[1] < prev:
        hv += (ref[0] - p[0]) * (prev - p[1])
        prev = p[1]
assert abs(hv - r["hypervolume"]) <= 1e-9 * max(hv, 1e-300), (hv, r["hypervolume"])
assert abs(float(ev[-1]["hypervolume"]) - r["hypervolume"]) <= 1e-9 * max(hv, 1e-300)
hvs = [float(x["hypervolume"]) for x in ev]
assert all(b >= a for a, b in zip(hvs, hvs[1:]))  # never falls
print(len(front), hv)
PY
}

# ---- ZDT1 by MOALO: the shipped case -----------------------------------------------------------
"$G" run "$SRC/cases/optimize/pareto-zdt1.ini" --out "$work/z1" --threads 1 > "$work/z1.txt" 2>&1
ok $? "optimize pareto-zdt1.ini exits 0 ($(head -c 300 "$work/z1.txt"))"
for f in pareto.csv evaluations.csv summary.json; do
    [ -s "$work/z1/$f" ]; ok $? "pareto-zdt1 writes $f"
done
head -1 "$work/z1/pareto.csv" | grep -qx "point,x1,x2,x3,x4,x5,f1,f2"; ok $? "pareto.csv: the variables and both objectives"
check_front "$work/z1" > /dev/null; ok $? "ZDT1, MOALO: the front non-dominated and complete among the evaluations, its hypervolume recomputed"
python3 - "$work/z1/summary.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))["results"]
assert abs(r["true_front_hypervolume"] - (1.1 ** 2 - 1 / 3)) < 1e-12
assert 0 < r["hypervolume_gap_percent"] < 5, r["hypervolume_gap_percent"]
PY
ok $? "ZDT1, MOALO with 5050 evaluations: within 5 % of the true front's hypervolume (1.1^2 - 1/3)"
grep -q "non-dominated points, hypervolume" "$work/z1.txt"; ok $? "the console reports the front and its hypervolume"
"$G" run "$SRC/cases/optimize/pareto-zdt1.ini" --out "$work/z2" --threads 2 --quiet > /dev/null 2>&1
cmp -s "$work/z1/pareto.csv" "$work/z2/pareto.csv" && cmp -s "$work/z1/evaluations.csv" "$work/z2/evaluations.csv"
ok $? "ZDT1, MOALO: the same front and evaluations with 1 and 2 threads"

# ---- ZDT2 by the others -------------------------------------------------------------------------
for alg in weighted-sum eps-constraint random; do
    "$G" run "$SRC/cases/optimize/pareto-zdt1.ini" --out "$work/z-$alg" --quiet --set optimize.objective=zdt2 \
        --set optimize.algorithm=$alg --set optimize.iterations=19 --set optimize.runs=2 > "$work/z-$alg.txt" 2>&1
    ok $? "optimize zdt2 by $alg exits 0 ($(head -c 300 "$work/z-$alg.txt"))"
    check_front "$work/z-$alg" > /dev/null; ok $? "ZDT2, $alg: the front non-dominated and complete, its hypervolume recomputed"
done
python3 - "$work/z-random/summary.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))["results"]
assert len(r["run_hypervolumes"]) == 2 and r["hypervolume"] == max(r["run_hypervolumes"])
assert r["best_run"] == 1 + r["run_hypervolumes"].index(r["hypervolume"])
PY
ok $? "two runs: the one with the larger hypervolume is kept"

# check: compare-optimizers uses the keys of MOALO and of the scalarisations when its list names them
"$G" check "$SRC/cases/optimize/compare-two-objectives.ini" > "$work/check2.txt" 2>&1 &&
    grep -Eq "^scalar_grid = 8 +; default$" "$work/check2.txt" && grep -Eq "^archive = 100 +; default$" "$work/check2.txt" &&
    "$G" check "$SRC/cases/paper/compare-optimizers.ini" > "$work/check1.txt" 2>&1 &&
    grep -Eq "^archive = 100 +; default, ignored: only optimize.optimizers with moalo uses it" "$work/check1.txt" &&
    grep -Eq "^scalar_grid = 8 +; default, ignored: only optimize.optimizers with weighted-sum or eps-constraint" "$work/check1.txt"
ok $? "check: compare-optimizers' scalar_grid and archive used when optimizers names them, ignored when not"

# ---- the gear: the LTE and the dynamic response --------------------------------------------------
{ cat "$SRC/tests/cli/spur-optimize.ini"; cat <<'EOF'; } > "$work/spur.ini"
[optimize]
algorithm = moalo
objective = gear-lte
objective2 = gear-dynamic
variables = y3, y4
torques_nm = 120
speed_from_rpm = 3500
speed_to_rpm = 4500
budget_evals = 8
population = 4
EOF
"$G" run "$work/spur.ini" --out "$work/g" > "$work/g.txt" 2>&1
ok $? "optimize gear-lte and gear-dynamic by MOALO exits 0 ($(head -c 300 "$work/g.txt"))"
head -1 "$work/g/pareto.csv" | grep -qx "point,tip_relief_amount_um,tip_relief_length_mm,lte_pp_arcsec,rms_accel_max_mps2"
ok $? "pareto.csv: the design variables and both objectives in their units"
check_front "$work/g" > /dev/null; ok $? "the gear: the front non-dominated and complete among the evaluations, its hypervolume recomputed"
python3 - "$work/g/summary.json" "$work/g/pareto.csv" <<'PY'
import csv, json, sys
s = json.load(open(sys.argv[1]))
r, st = s["results"], s["settings"]
assert st["objectives"] == ["gear-lte", "gear-dynamic"]
un = r["flanks"]["unmodified"]
for c, ref in zip(st["objective_columns"], st["hv_reference"]):
    assert abs(1.1 * un[c] - ref) <= 1e-9 * ref, (c, un[c], ref)
assert st["hv_reference_is"] == "1.1 times the unmodified flank's objectives"
for x in csv.DictReader(open(sys.argv[2])):
    assert 0 <= float(x["tip_relief_amount_um"]) and 0 < float(x["tip_relief_length_mm"])
PY
ok $? "the gear: the reference point is 1.1 times the unmodified flank's objectives"
grep -q "unmodified: lte_pp_arcsec" "$work/g.txt"; ok $? "the console reports the unmodified flank beside the front"

# ---- the comparison of two-objective optimisers (the shipped case, shortened) ---------------------
cmp_sets="--set optimize.runs=3 --set optimize.budget_evals=1010"
"$G" run "$SRC/cases/optimize/compare-two-objectives.ini" --out "$work/c1" --threads 1 $cmp_sets > "$work/c1.txt" 2>&1
ok $? "compare-optimizers on zdt1, zdt2 by moalo, weighted-sum, eps-constraint, random exits 0 ($(head -c 300 "$work/c1.txt"))"
"$G" run "$SRC/cases/optimize/compare-two-objectives.ini" --out "$work/c2" --threads 2 --quiet $cmp_sets > /dev/null 2>&1
ok $? "... and with 2 threads"
for f in runs.csv statistics.csv convergence.csv ecdf.csv; do
    python3 - "$work/c1/$f" "$work/c2/$f" <<'PY'
import csv, sys
a, b = (list(csv.DictReader(open(f))) for f in sys.argv[1:])
strip = lambda rows: [{k: v for k, v in r.items() if not k.startswith("wall")} for r in rows]
assert strip(a) == strip(b) and len(a) > 0
PY
    ok $? "compare, two objectives: $f the same with 1 and 2 threads (but the wall times)"
done
python3 - "$work/c1" "$work/z1/summary.json" <<'PY'
import csv, json, sys
d = sys.argv[1]
s = json.load(open(d + "/summary.json"))
box = 1.1 * 1.1
for p in s["problems"]:
    assert p["objectives"] == 2 and p["hv_reference"] == [1.1, 1.1]
    true = box - 1 / 3 if p["objective"] == "zdt1" else box - 2 / 3
    assert abs(box - p["f_ref"] - true) < 1e-12, p["f_ref"]  # the reference: the true front's hypervolume
runs = list(csv.DictReader(open(d + "/runs.csv")))
assert len(runs) == 2 * 4 * 3
for r in runs:
    hv = box - float(r["final_f"])
    assert -1e-12 <= hv <= (box - 1 / 3 if r["objective"] == "zdt1" else box - 2 / 3) + 1e-12, r
PY
ok $? "compare, two objectives: each run's value is the reference box less its hypervolume, the reference the true front's"
"$G" run "$SRC/cases/optimize/pareto-zdt1.ini" --out "$work/z1010" --quiet --set optimize.iterations=19 > /dev/null 2>&1
python3 - "$work/c1/runs.csv" "$work/z1010/summary.json" <<'PY'
import csv, json, sys
hv = json.load(open(sys.argv[2]))["results"]["hypervolume"]
r = [x for x in csv.DictReader(open(sys.argv[1])) if x["objective"] == "zdt1" and x["optimizer"] == "moalo" and x["run"] == "1"][0]
assert r["seed"] == "1"
assert abs((1.21 - float(r["final_f"])) - hv) <= 1e-9, (1.21 - float(r["final_f"]), hv)
PY
ok $? "compare, two objectives: MOALO's run of seed 1 has the hypervolume of optimize's run of seed 1 (1010 evaluations)"

echo "1..$n"
[ $bad -eq 0 ]
