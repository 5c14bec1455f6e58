#!/usr/bin/env bash
# The robust variant of the gear objectives from a case (optimize.robust, docs/optimisation.md section
# 12): with 1 and 2 threads the same Monte Carlo sample and the same values; the robust objective of
# each flank is the quantile of its sample's values in robust.csv (recomputed here); the sample lies
# within its ranges; the nominal objective is the objective without robust; gear-lte, gear-lte-range
# and gear-dynamic. TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok

{ cat "$SRC/tests/cli/spur-optimize.ini"; cat <<'EOF'; } > "$work/spur.ini"
[optimize]
algorithm = random
objective = gear-lte-range
variables = y3, y4
torques_nm = 60, 120
lte_range_combine = max
budget_evals = 8
population = 4
robust = on
robust_samples = 7
robust_quantile = 0.8
robust_misalignment_tilt_arcmin = 0.4
robust_misalignment_centre_distance_mm = 0.03
robust_deviation_um = 1.5
robust_deviation_mm = 0.25
EOF

# the checks of one run's files: the quantile of robust.csv, the ranges, the summary's numbers
check_run() { # DIR QUANTILE
python3 - "$1" "$2" <<'PY'
import csv, json, sys

def quantile(v, q):  # linear between the order statistics (Hyndman & Fan's type 7, GSL's)
    v = sorted(v)
    h = q * (len(v) - 1)
    i = int(h)
    return v[-1] if i + 1 >= len(v) else v[i] + (h - i) * (v[i + 1] - v[i])

d, q = sys.argv[1], float(sys.argv[2])
s = json.load(open(d + "/summary.json"))
r = s["results"]
rb = r["robust"]
rows = list(csv.DictReader(open(d + "/robust.csv")))
n = rb["samples"]
assert len(rows) == 3 * n, len(rows)
unit = [k for k in rows[0] if k.startswith("objective_")][0]
ranges = {"axis_in_plane_deviation_arcmin": rb["misalignment_tilt_arcmin"],
          "axis_cross_plane_deviation_arcmin": rb["misalignment_tilt_arcmin"],
          "centre_distance_deviation_mm": rb["misalignment_centre_distance_mm"],
          "tip_relief_amount_deviation_um": rb["deviation_um"],
          "tip_relief_length_deviation_mm": rb["deviation_mm"]}
for flank in ("unmodified", "case", "optimum"):
    fr = [x for x in rows if x["flank"] == flank]
    assert [int(x["sample"]) for x in fr] == list(range(1, n + 1))
    for k, h in ranges.items():
        v = [float(x[k]) for x in fr]
        assert all(abs(x) <= h for x in v) and (n < 5 or max(v) - min(v) > 0.2 * h), (k, v, h)
    # the same sample for every flank
    for x, y in zip(fr, [x for x in rows if x["flank"] == "unmodified"]):
        assert all(x[k] == y[k] for k in ranges)
    qq = quantile([float(x[unit]) for x in fr], q)
    assert abs(qq - rb[flank]["robust"]) <= 1e-9 * abs(qq), (flank, qq, rb[flank]["robust"])
    assert abs(r["objective_of"][flank]["value"] - rb[flank]["robust"]) <= 1e-12 * abs(qq)
    assert rb[flank]["nominal"] > 0
# the run minimised the robust value: its best is the optimum's robust value
assert abs(rb["optimum"]["robust"] - r["objective_value"]) <= 1e-9 * r["objective_value"]
assert rb["quantile"] == q
PY
}

out1="$work/t1"; out2="$work/t2"
"$G" run "$work/spur.ini" --out "$out1" --threads 1 > "$work/run1.txt" 2>&1
ok $? "optimize gear-lte-range robust exits 0 with 1 thread ($(head -c 300 "$work/run1.txt"))"
"$G" run "$work/spur.ini" --out "$out2" --threads 2 > "$work/run2.txt" 2>&1
ok $? "... and with 2 threads"
grep -Eq "^    robust:  unmodified [0-9.]+, the case's modification [0-9.]+, optimum [0-9.]+ arcsec" "$work/run1.txt"
ok $? "the console reports the robust objective of the three flanks"
grep -Eq "^    nominal: unmodified [0-9.]+, the case's modification [0-9.]+, optimum [0-9.]+ arcsec" "$work/run1.txt"
ok $? "the console reports the nominal objective of the three flanks"
cmp -s "$out1/robust.csv" "$out2/robust.csv"; ok $? "1 and 2 threads: the same sample and the same values (robust.csv)"
cmp -s "$out1/convergence.csv" "$out2/convergence.csv"; ok $? "1 and 2 threads: the same evaluations (convergence.csv)"
python3 - "$out1/summary.json" "$out2/summary.json" <<'PY'
import json, sys
a, b = (json.load(open(f))["results"] for f in sys.argv[1:])
assert a["robust"] == b["robust"] and a["objective_of"] == b["objective_of"]
PY
ok $? "1 and 2 threads: the same results.robust and objective_of in summary.json"
check_run "$out1" 0.8; ok $? "gear-lte-range: each flank's robust value is the 0.8 quantile of its values in robust.csv, the sample within its ranges"

# the nominal values are those of the objective without robust
out3="$work/t3"
"$G" run "$work/spur.ini" --out "$out3" --quiet --set optimize.robust=off > "$work/run3.txt" 2>&1
ok $? "the same case without robust exits 0"
python3 - "$out1/summary.json" "$out3/summary.json" <<'PY'
import json, sys
a, b = (json.load(open(f))["results"] for f in sys.argv[1:])
for flank in ("unmodified", "case"):
    assert abs(a["robust"][flank]["nominal"] - b["objective_of"][flank]["value"]) <= 1e-12 * b["objective_of"][flank]["value"]
    assert a["objective_of"][flank]["torques"] == b["objective_of"][flank]["torques"]
assert "robust" not in b
PY
ok $? "gear-lte-range: the nominal value and the torques' amplitudes of the unmodified and the case's flank are those without robust"
[ ! -e "$out3/robust.csv" ]; ok $? "without robust no robust.csv"

out4="$work/t4"
"$G" run "$work/spur.ini" --out "$out4" --quiet --set optimize.objective=gear-lte --set optimize.robust_quantile=1 \
    > "$work/run4.txt" 2>&1
ok $? "optimize gear-lte robust exits 0"
check_run "$out4" 1.0; ok $? "gear-lte: the robust value is the largest of the sample (quantile 1)"
python3 - "$out4/summary.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))["results"]
# the nominal value of gear-lte is the LTE table's amplitude at the case's torque
for flank in ("unmodified", "case", "optimum"):
    assert abs(r["robust"][flank]["nominal"] - r["lte_pp_arcsec"][flank]) <= 1e-9 * r["lte_pp_arcsec"][flank]
PY
ok $? "gear-lte: the nominal value of each flank is its LTE amplitude of the LTE table"

# gear-lte takes the case's one torque: the weights of gear-lte-range (ignored) do not enter its mean
out6="$work/t6"
"$G" run "$work/spur.ini" --out "$out6" --quiet --set optimize.objective=gear-lte --set optimize.lte_range_combine=mean \
    --set optimize.torque_weights=0,0 --set optimize.budget_evals=2 --set optimize.population=2 > "$work/run6.txt" 2>&1
ok $? "optimize gear-lte robust with the ignored weights 0, 0 exits 0 ($(head -c 300 "$work/run6.txt"))"
python3 - "$out6/summary.json" <<'PY'
import json, math, sys
rb = json.load(open(sys.argv[1]))["results"]["robust"]
for flank in ("unmodified", "case", "optimum"):
    assert math.isfinite(rb[flank]["robust"]) and rb[flank]["robust"] > 0, rb
PY
ok $? "gear-lte robust: the ignored torque weights leave every value finite"

out5="$work/t5"
"$G" run "$work/spur.ini" --out "$out5" --quiet --set optimize.objective=gear-dynamic --set optimize.torques_nm=120 \
    --set optimize.speed_from_rpm=3500 --set optimize.speed_to_rpm=4500 --set optimize.budget_evals=2 \
    --set optimize.population=2 --set optimize.robust_samples=2 --set optimize.robust_quantile=0.5 > "$work/run5.txt" 2>&1
ok $? "optimize gear-dynamic robust exits 0 ($(head -c 300 "$work/run5.txt"))"
check_run "$out5" 0.5; ok $? "gear-dynamic: the robust value is the median of the sample's values"

echo "1..$n"
[ $bad -eq 0 ]
