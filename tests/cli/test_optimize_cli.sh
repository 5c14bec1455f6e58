#!/usr/bin/env bash
# geardyn run for analysis = optimize and compare-optimizers (docs/optimisation.md): check shows the
# [optimize] keys; optimize writes the optimum, convergence, summary.json (and for the gear the LTE
# beside the unmodified pair and Table 2, and the optimum's LTCA and TCA outputs); the comparison
# output is complete for a small budget (files, CSV columns and rows, summary.json keys) and is
# identical with 1 and 2 threads except the wall-time columns. TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok

# ---- check ----------------------------------------------------------------------------------------
"$G" check "$SRC/cases/paper/optimize-alo.ini" > "$work/check.txt"; ok $? "check exits 0 on optimize-alo.ini"
grep -Eq "^\[optimize\]" "$work/check.txt"; ok $? "check shows [optimize]"
grep -Eq "^iterations = 100 +; file line" "$work/check.txt"; ok $? "check shows optimize.iterations from the file"
grep -Eq "^budget_evals = 3030 +; derived" "$work/check.txt"; ok $? "check shows the derived budget 30 x 101"
grep -Eq "^lead_unmodified_length_max_mm = 38 mm +; file line" "$work/check.txt"; ok $? "check shows a bound with its unit"
"$G" check "$SRC/cases/paper/compare-optimizers.ini" > /dev/null; ok $? "check exits 0 on compare-optimizers.ini"
"$G" check "$SRC/cases/optimize/compare-test-functions.ini" > /dev/null; ok $? "check exits 0 on compare-test-functions.ini"

# ---- optimize: a test function ----------------------------------------------------------------------
cat > "$work/sphere.ini" <<'EOF'
[scene]
analysis = optimize
[optimize]
algorithm = alo
objective = sphere
dimension = 3
iterations = 60
population = 10
shift = 0.5
runs = 2
EOF
out="$work/opt-sphere"
"$G" run "$work/sphere.ini" --out "$out" --quiet > "$work/run.txt" 2>&1; ok $? "optimize sphere exits 0 ($(head -c 300 "$work/run.txt"))"
for f in summary.json optimum.csv convergence.csv; do [ -s "$out/$f" ]; ok $? "optimize sphere: wrote $f"; done
head -1 "$out/optimum.csv" | grep -q "^variable,symbol,unit,value,lower,upper,minimiser$"; ok $? "optimum.csv header"
[ "$(($(wc -l < "$out/optimum.csv") - 1))" -eq 3 ]; ok $? "optimum.csv: 3 variables"
head -1 "$out/convergence.csv" | grep -q "^run,seed_offset,evaluation,f,best_f$"; ok $? "convergence.csv header"
[ "$(($(wc -l < "$out/convergence.csv") - 1))" -eq $((2 * 610)) ]; ok $? "convergence.csv: 2 runs x 610 evaluations"
python3 - "$out/summary.json" <<'PY'
import json, sys, math
d = json.load(open(sys.argv[1]))
assert d["analysis"] == "optimize"
r = d["results"]
for k in ("objective_value", "optimum", "bounds", "evaluations", "found_at_evaluation", "best_run", "run_values",
          "true_minimiser", "distance_to_minimiser"):
    assert k in r, "missing results." + k
assert r["evaluations"] == 610 and len(r["run_values"]) == 2
assert r["objective_value"] == min(r["run_values"])
o = r["true_minimiser"]; x = r["optimum"]
assert abs(math.dist(o, [x["x1"], x["x2"], x["x3"]]) - r["distance_to_minimiser"]) < 1e-9
assert r["objective_value"] < 1e-3, r["objective_value"]
assert d["settings"]["alo_iterations"] == 60 and d["settings"]["budget_evals"] == 610
PY
ok $? "optimize sphere: summary.json keys and values"

# ---- optimize: the gear problem, a tiny budget ------------------------------------------------------
out="$work/opt-gear"
"$G" run "$SRC/cases/paper/optimize-alo.ini" --out "$out" --quiet --set optimize.iterations=2 \
    --set optimize.population=4 --set solver.ltca_positions_per_cycle=8 > "$work/run.txt" 2>&1
ok $? "optimize gear (12 evaluations) exits 0 ($(head -c 300 "$work/run.txt"))"
for f in summary.json optimum.csv convergence.csv lte.csv optimum/summary.json optimum/load_distribution.csv \
         optimum/lte.csv optimum-tca/summary.json optimum-tca/contact_path.csv; do
    [ -s "$out/$f" ]; ok $? "optimize gear: wrote $f"
done
ls -a "$out" "$out/optimum" | grep -Eq '\.tmp|\.plot-'; [ $? -ne 0 ]; ok $? "optimize gear: no temporary files left"
head -1 "$out/optimum.csv" | grep -q "^variable,symbol,unit,value,lower,upper,case_value,effect,paper_table2$"; ok $? "optimum.csv header (gear, the paper's pair: Table 2 beside the case's own value)"
cut -d, -f2 "$out/optimum.csv" | tr '\n' ' ' | grep -q "^symbol y1 y2 y3 y4 y5 y6 y7 $"; ok $? "optimum.csv rows y1..y7"
head -1 "$out/lte.csv" | grep -q "^phi1_deg,lte_unmodified_arcsec,lte_case_arcsec,lte_optimum_arcsec,lte_paper_table2_arcsec$"; ok $? "lte.csv header"
[ "$(($(wc -l < "$out/lte.csv") - 1))" -eq 8 ]; ok $? "lte.csv: 8 positions"
python3 - "$out" <<'PY'
import json, sys, csv
out = sys.argv[1]
d = json.load(open(out + "/summary.json"))
r = d["results"]
lte = r["lte_pp_arcsec"]
for k in ("unmodified", "case", "optimum", "paper_table2"):
    assert 0 < lte[k] < 10, lte
assert lte["optimum"] == r["objective_value"], (lte, r["objective_value"])
assert lte["case"] == lte["unmodified"], lte   # optimize-alo.ini has no [modification]
assert set(r["optimum_vs_case"]) == {"y1", "y2", "y3", "y4", "y5", "y7"}
assert r["optimum_vs_case"]["y7"]["paper_table2"] == 35 and r["optimum_vs_case"]["y7"]["case"] == 0
assert r["paper"]["lte_pp_table2_arcsec"] == 1.157
assert r["evaluations"] == 12
# the optimum's own LTCA: the same amplitude, the optimum as its [modification] (derived)
o = json.load(open(out + "/optimum/summary.json"))
assert abs(o["results"]["lte_pp_arcsec"] - lte["optimum"]) < 1e-12
m = o["case"]["parameters"]["modification"]
assert m["root_relief_amount_um"]["source"] == "derived"
assert abs(m["root_relief_amount_um"]["value"] - r["optimum"]["root_relief_amount_um"]) < 1e-12
assert m["lead_relief_outer_um"]["value"] == m["lead_relief_inner_um"]["value"]
# the LTE columns are the three LTCA runs: their amplitudes
rows = list(csv.DictReader(open(out + "/lte.csv")))
for k, col in (("unmodified", "lte_unmodified_arcsec"), ("case", "lte_case_arcsec"), ("optimum", "lte_optimum_arcsec"),
               ("paper_table2", "lte_paper_table2_arcsec")):
    v = [float(x[col]) for x in rows]
    assert abs(max(v) - min(v) - lte[k]) < 1e-8, (k, max(v) - min(v), lte[k])
PY
ok $? "optimize gear: summary.json keys, LTE amplitudes consistent with lte.csv and optimum/"

# ---- compare-optimizers: a small budget, complete output, 1 and 2 threads ---------------------------
cat > "$work/cmp.ini" <<'EOF'
[scene]
analysis = compare-optimizers
[optimize]
objective = sphere, rastrigin
dimension = 2, 3
runs = 3
budget_evals = 150
population = 10
shift = 0.5
ecdf_targets = 11
target = 1e-6
EOF
for t in 1 2; do
    "$G" run "$work/cmp.ini" --out "$work/cmp$t" --quiet --threads $t > "$work/run.txt" 2>&1
    ok $? "compare, $t thread(s), exits 0 ($(head -c 300 "$work/run.txt"))"
done
out="$work/cmp2"
for f in runs.csv statistics.csv convergence.csv ecdf.csv best_points.csv summary.json; do
    [ -s "$out/$f" ]; ok $? "compare: wrote $f"
done
if command -v gnuplot > /dev/null; then
    for f in convergence.png convergence.svg ecdf.png ecdf.svg; do [ -s "$out/$f" ]; ok $? "compare: drew $f"; done
fi
ls -a "$out" | grep -Eq '\.tmp|\.plot-'; [ $? -ne 0 ]; ok $? "compare: no temporary files left"
head -1 "$out/runs.csv" | grep -q "^objective,dimension,optimizer,run,seed,final_f,final_delta_f,evaluations,evals_to_target,starts,wall_s$"
ok $? "runs.csv columns"
head -1 "$out/statistics.csv" | grep -q "^objective,dimension,optimizer,runs,budget_evals,f_ref,target,best,q1,median,q3,iqr,worst,mean,successes,success_rate,evals_to_target_median,ert_evals,wall_mean_s,wall_total_s$"
ok $? "statistics.csv columns"
head -1 "$out/convergence.csv" | grep -q "^objective,dimension,optimizer,evaluations,q1_delta_f,median_delta_f,q3_delta_f$"; ok $? "convergence.csv columns"
head -1 "$out/ecdf.csv" | grep -q "^objective,dimension,optimizer,evaluations,fraction$"; ok $? "ecdf.csv columns"
head -1 "$out/best_points.csv" | grep -q "^objective,dimension,optimizer,run,variable,unit,value$"; ok $? "best_points.csv columns"
# 4 problems x 9 optimisers x 3 runs
[ "$(($(wc -l < "$out/runs.csv") - 1))" -eq 108 ]; ok $? "runs.csv: 4 problems x 9 optimisers x 3 runs"
[ "$(($(wc -l < "$out/statistics.csv") - 1))" -eq 36 ]; ok $? "statistics.csv: 4 x 9 rows"
[ "$(($(wc -l < "$out/best_points.csv") - 1))" -eq $((9 * 3 * (2 + 2 + 3 + 3))) ]; ok $? "best_points.csv: one row per variable of every run"
python3 - "$out" <<'PY'
import json, sys, csv
out = sys.argv[1]
d = json.load(open(out + "/summary.json"))
assert d["analysis"] == "compare-optimizers"
s = d["settings"]
assert s["runs"] == 3 and s["budget_evals"] == 150 and len(s["optimizers"]) == 9
assert len(d["problems"]) == 4
algs = s["optimizers"]
runs = list(csv.DictReader(open(out + "/runs.csv")))
for p in d["problems"]:
    for k in ("objective", "dimension", "shift", "f_ref", "target", "ecdf_targets", "optimizers"):
        assert k in p, k
    assert p["f_ref"] == 0 and len(p["ecdf_targets"]) == 11 and abs(p["ecdf_targets"][-1] - 1e-6) < 1e-18
    assert set(p["optimizers"]) == set(algs)
    for a, st in p["optimizers"].items():
        for k in ("best", "q1", "median", "q3", "iqr", "worst", "success_rate", "evals_to_target_median", "ert_evals",
                  "wall_mean_s"):
            assert k in st, k
        mine = [float(r["final_f"]) for r in runs if r["objective"] == p["objective"]
                and int(r["dimension"]) == p["dimension"] and r["optimizer"] == a]
        assert len(mine) == 3 and abs(min(mine) - st["best"]) <= 1e-12 * (1 + abs(st["best"]))
        assert st["q1"] <= st["median"] <= st["q3"]
        ok = [float(r["final_f"]) <= 1e-6 for r in runs if r["objective"] == p["objective"]
              and int(r["dimension"]) == p["dimension"] and r["optimizer"] == a]
        assert abs(sum(ok) / 3 - st["success_rate"]) < 1e-12
for r in runs:
    assert int(r["evaluations"]) <= 150
    e = int(r["evals_to_target"])
    assert (e == -1) == (float(r["final_f"]) > 1e-6), r
for a in algs:
    assert 0 <= d["ecdf_pooled"][a]["at_budget"] <= 1
# the ECDF is non-decreasing in the evaluations and the pooled rows are there
rows = list(csv.DictReader(open(out + "/ecdf.csv")))
assert any(r["objective"] == "all" for r in rows)
prev = {}
for r in rows:
    key = (r["objective"], r["dimension"], r["optimizer"])
    f = float(r["fraction"])
    assert f >= prev.get(key, 0) - 1e-15
    prev[key] = f
PY
ok $? "compare: summary.json keys, statistics consistent with runs.csv, ECDF non-decreasing"
# 1 and 2 threads: identical outputs except the wall times
cmp <(cut -d, -f1-10 "$work/cmp1/runs.csv") <(cut -d, -f1-10 "$work/cmp2/runs.csv"); ok $? "runs.csv identical with 1 and 2 threads (without wall_s)"
cmp <(cut -d, -f1-18 "$work/cmp1/statistics.csv") <(cut -d, -f1-18 "$work/cmp2/statistics.csv"); ok $? "statistics.csv identical (without the wall columns)"
for f in convergence.csv ecdf.csv best_points.csv; do cmp "$work/cmp1/$f" "$work/cmp2/$f"; ok $? "$f identical with 1 and 2 threads"; done
python3 - "$work/cmp1/summary.json" "$work/cmp2/summary.json" <<'PY'
import json, sys
def strip(o):
    if isinstance(o, dict):
        return {k: strip(v) for k, v in o.items() if "wall" not in k and k != "threads"}
    if isinstance(o, list):
        return [strip(v) for v in o]
    return o
a, b = (strip(json.load(open(p))) for p in sys.argv[1:3])
assert a == b
PY
ok $? "summary.json identical with 1 and 2 threads (without wall times and the thread count)"

# ---- compare-optimizers on the gear problem: a tiny budget --------------------------------------------
out="$work/cmp-gear"
"$G" run "$SRC/cases/paper/compare-optimizers.ini" --out "$out" --quiet --set optimize.optimizers=alo,ln_cobyla,random \
    --set optimize.runs=2 --set optimize.budget_evals=8 --set optimize.population=4 \
    --set solver.ltca_positions_per_cycle=8 --set output.plots=off > "$work/run.txt" 2>&1
ok $? "compare on gear-lte (3 optimisers x 2 runs x 8 evaluations) exits 0 ($(head -c 300 "$work/run.txt"))"
python3 - "$out" <<'PY'
import json, sys, csv
out = sys.argv[1]
d = json.load(open(out + "/summary.json"))
p = d["problems"][0]
assert p["objective"] == "gear-lte" and p["dimension"] == 6
runs = list(csv.DictReader(open(out + "/runs.csv")))
assert len(runs) == 6
assert p["f_ref"] == min(float(r["final_f"]) for r in runs)   # the best found: no known minimum
assert p["f_ref_is"] == "the best value found by any run"
pts = list(csv.DictReader(open(out + "/best_points.csv")))
assert {r["variable"] for r in pts} == {"root_relief_amount_um", "root_relief_length_mm", "tip_relief_amount_um",
                                         "tip_relief_length_mm", "lead_relief_inner_um", "lead_unmodified_length_mm"}
PY
ok $? "compare on gear-lte: f_ref is the best run, best points named by their [modification] keys"

# ---- optimize: the objectives over load and speed on a spur pair ------------------------------------
{ cat "$SRC/tests/cli/spur-optimize.ini"; cat <<'EOF'; } > "$work/spur-range.ini"
[optimize]
algorithm = random
objective = gear-lte-range
variables = y3, y4
torques_nm = 60, 120
torque_weights = 3, 1
lte_range_combine = mean
budget_evals = 8
population = 4
EOF
"$G" check "$work/spur-range.ini" > "$work/check.txt"; ok $? "check exits 0 on a gear-lte-range case"
grep -Eq "^speed_from_rpm = none +; default, ignored: only optimize.objective = gear-dynamic uses it" \
    "$work/check.txt"; ok $? "check: the keys of gear-dynamic are ignored by gear-lte-range"
out="$work/opt-range"
"$G" run "$work/spur-range.ini" --out "$out" --quiet > "$work/run.txt" 2>&1
ok $? "optimize gear-lte-range exits 0 ($(head -c 300 "$work/run.txt"))"
python3 - "$out/summary.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))["results"]
assert r["objective_unit"] == "arcsec"
of = r["objective_of"]
for flank in ("unmodified", "case", "optimum"):
    t = of[flank]["torques"]
    assert [x["torque_nm"] for x in t] == [60, 120]
    mean = (3 * t[0]["lte_pp_arcsec"] + t[1]["lte_pp_arcsec"]) / 4
    assert abs(of[flank]["value"] - mean) <= 1e-9 * mean, (flank, of[flank]["value"], mean)
# the optimum evaluated again is the best value of the run
assert abs(of["optimum"]["value"] - r["objective_value"]) <= 1e-9 * r["objective_value"]
# at the case's torque the LTE table's amplitude is the objective's at 120 N m
assert abs(r["lte_pp_arcsec"]["optimum"] - of["optimum"]["torques"][1]["lte_pp_arcsec"]) <= 1e-9 * r["lte_pp_arcsec"]["optimum"]
PY
ok $? "gear-lte-range: each flank's value is the duty-weighted mean of its torques', the optimum's the run's best"
python3 - "$out" <<'PY'
import csv, json, os, sys
out = sys.argv[1]
r = json.load(open(os.path.join(out, "summary.json")))["results"]
rows = list(csv.DictReader(open(os.path.join(out, "lte_over_torque.csv"))))
assert list(rows[0]) == ["torque_nm", "objective_torque", "lte_unmodified_arcsec", "lte_case_arcsec", "lte_optimum_arcsec"]
assert not os.path.exists(os.path.join(out, "response_over_speed.csv")) and "objective_on_bta" not in r
t = [float(x["torque_nm"]) for x in rows]
assert len(rows) == 22 and t == sorted(t) and abs(t[0] - 12) < 1e-9 and abs(t[-1] - 180) < 1e-9, t
assert [float(x["torque_nm"]) for x in rows if x["objective_torque"] == "1"] == [60, 120]
h = r["lte_over_torque"]
for flank in ("unmodified", "case", "optimum"):
    at = {float(x["torque_nm"]): float(x["lte_%s_arcsec" % flank]) for x in rows}
    # the Harris map at the objective's torques: its values (summary.json's 12 digits; the same
    # numbers bit for bit in test dynamic_objective)
    for each in r["objective_of"][flank]["torques"]:
        assert abs(at[each["torque_nm"]] - each["lte_pp_arcsec"]) <= 1e-11 * each["lte_pp_arcsec"], (flank, each)
    assert all(abs(a - at[x]) <= 1e-11 * a for a, x in zip(h[flank]["lte_pp_arcsec"], t))
    assert abs(h[flank]["least_lte_pp_arcsec"] - min(at.values())) <= 1e-11 * min(at.values())
PY
ok $? "gear-lte-range: lte_over_torque.csv, 20 torques from 12 to 180 N m and the objective's 60 and 120, there the objective's amplitudes"

# the Harris map's grid from the case, and the three flanks' contact patterns
out="$work/opt-range-grid"
"$G" run "$work/spur-range.ini" --out "$out" --quiet --set optimize.harris_torques=5 \
    --set optimize.harris_torque_from_nm=40 --set optimize.harris_torque_to_nm=240 > "$work/run.txt" 2>&1
ok $? "optimize gear-lte-range with the Harris map's grid exits 0 ($(head -c 300 "$work/run.txt"))"
python3 - "$out" "$work/opt-range" <<'PY'
import csv, json, os, sys
out, before = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(os.path.join(out, "lte_over_torque.csv"))))
t = [float(x["torque_nm"]) for x in rows]
# 40, 90, 140, 190, 240 N m and the objective's 60 and 120
assert t == [40, 60, 90, 120, 140, 190, 240], t
assert [x["objective_torque"] for x in rows] == ["0", "1", "0", "1", "0", "0", "0"], rows
# the same flanks at the objective's torques as with the default grid, bit for bit
b = {x["torque_nm"]: x for x in csv.DictReader(open(os.path.join(before, "lte_over_torque.csv")))}
for x in rows:
    if x["objective_torque"] == "1":
        assert all(x[k] == b[x["torque_nm"]][k] for k in x), (x, b[x["torque_nm"]])
# each flank's own LTCA and TCA: its LTE amplitude at the case's torque is the LTE table's, and its
# [modification] is the flank's
r = json.load(open(os.path.join(out, "summary.json")))["results"]
for flank, sub in (("unmodified", "unmodified"), ("case", "case"), ("optimum", "optimum")):
    for f in ("load_distribution.csv", "lte.csv", "summary.json"):
        assert os.path.isfile(os.path.join(out, sub, f)), (sub, f)
    for f in ("contact_path.csv", "gte.csv", "summary.json"):
        assert os.path.isfile(os.path.join(out, sub + "-tca", f)), (sub, f)
    s = json.load(open(os.path.join(out, sub, "summary.json")))
    a = s["results"]["lte_pp_arcsec"]
    assert abs(a - r["lte_pp_arcsec"][flank]) <= 1e-9 * a, (flank, a, r["lte_pp_arcsec"][flank])
    tip = s["case"]["parameters"]["modification"]["tip_relief_amount_um"]["value"]
    want = {"unmodified": 0, "case": 10, "optimum": r["optimum"]["tip_relief_amount_um"]}[flank]
    assert abs(tip - want) <= 1e-12 * max(1, want), (flank, tip, want)
PY
ok $? "gear-lte-range: the Harris map on the case's grid of 5 torques from 40 to 240 N m and the objective's, and the three flanks' LTCA and TCA in unmodified/, case/, optimum/ and their -tca/"

out="$work/opt-dynamic"
"$G" run "$work/spur-range.ini" --out "$out" --quiet --set optimize.objective=gear-dynamic \
    --set optimize.torques_nm=120 --set optimize.torque_weights=1 --set optimize.speed_from_rpm=3500 \
    --set optimize.speed_to_rpm=4500 --set optimize.budget_evals=4 --set optimize.population=2 > "$work/run.txt" 2>&1
ok $? "optimize gear-dynamic exits 0 ($(head -c 300 "$work/run.txt"))"
python3 - "$out/summary.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
r = d["results"]
assert d["settings"]["objective"] == "gear-dynamic"
assert r["objective_unit"] == "m/s^2"
of = r["objective_of"]
for flank in ("unmodified", "case", "optimum"):
    t = of[flank]["torques"]
    assert len(t) == 1 and t[0]["torque_nm"] == 120 and t[0]["peak"] == of[flank]["value"] > 0
    assert t[0]["method"] in ("continuation", "continuation+sweep", "sweep")
assert abs(of["optimum"]["value"] - r["objective_value"]) <= 1e-9 * r["objective_value"]
assert r["objective_value"] <= max(r["run_values"])
PY
ok $? "gear-dynamic: the objective of the three flanks, each with its method, the optimum's the run's best"
python3 - "$out" <<'PY'
import csv, json, os, sys
out = sys.argv[1]
r = json.load(open(os.path.join(out, "summary.json")))["results"]
rows = list(csv.DictReader(open(os.path.join(out, "response_over_speed.csv"))))
assert list(rows[0]) == ["model", "flank", "torque_nm", "point", "speed_rpm", "rms_accel_mps2", "stable", "source",
                         "period_n"]
assert {x["model"] for x in rows} == {"torsional", "bta"}
for flank in ("unmodified", "case", "optimum"):
    on_bta = [x for x in rows if x["flank"] == flank and x["model"] == "bta"]
    peak = max(float(x["rms_accel_mps2"]) for x in on_bta if x["stable"] == "1")
    assert abs(peak - r["objective_on_bta"][flank]["value"]) <= 1e-11 * peak, (flank, peak)
    mine = [x for x in rows if x["flank"] == flank and x["model"] == "torsional"]
    assert mine and all(x["torque_nm"] == "120" for x in mine)
    assert all(3500 - 1e-6 <= float(x["speed_rpm"]) <= 4500 + 1e-6 for x in mine)
    assert {x["source"] for x in mine} <= {"branch", "swept", "refined"} and mine[0]["source"] == "branch"
    # the curve's largest stable value is the objective the run reported (to summary.json's 12 digits)
    peak = max(float(x["rms_accel_mps2"]) for x in mine if x["stable"] == "1")
    assert abs(peak - r["objective_of"][flank]["value"]) <= 1e-11 * peak, (flank, peak)
    assert r["response_over_speed"][flank]["value"] == r["objective_of"][flank]["value"]
b = r["objective_on_bta"]
assert b["model_in_loop"] == "torsional" and b["model"] == "bta"
vals = {f: b[f]["value"] for f in ("unmodified", "case", "optimum")}
assert all(v > 0 for v in vals.values()) and vals != {f: r["objective_of"][f]["value"] for f in vals}
assert b["ranking"] == sorted(vals, key=lambda f: vals[f])
loop = {f: r["objective_of"][f]["value"] for f in vals}
assert b["ranking_in_loop"] == sorted(loop, key=lambda f: loop[f])
assert b["same_ranking"] == (b["ranking"] == b["ranking_in_loop"])
at = [x for x in csv.DictReader(open(os.path.join(out, "lte_over_torque.csv"))) if x["objective_torque"] == "1"]
assert len(at) == 1 and float(at[0]["torque_nm"]) == 120
for flank in ("unmodified", "case", "optimum"):   # the LTE table's amplitudes at the case's 120 N m
    v = float(at[0]["lte_%s_arcsec" % flank])
    assert abs(v - r["lte_pp_arcsec"][flank]) <= 1e-9 * v, (flank, v, r["lte_pp_arcsec"][flank])
PY
ok $? "gear-dynamic: the response curves' largest stable values are the objective, the flanks on bta ranked, the Harris map at 120 N m the LTE table's"
"$G" run "$work/spur-range.ini" --out "$out-2" --quiet --threads 1 --set optimize.objective=gear-dynamic \
    --set optimize.torques_nm=120 --set optimize.torque_weights=1 --set optimize.speed_from_rpm=3500 \
    --set optimize.speed_to_rpm=4500 --set optimize.budget_evals=4 --set optimize.population=2 > "$work/run.txt" 2>&1 &&
cmp -s "$out/response_over_speed.csv" "$out-2/response_over_speed.csv" &&
cmp -s "$out/lte_over_torque.csv" "$out-2/lte_over_torque.csv"
ok $? "gear-dynamic: response_over_speed.csv and lte_over_torque.csv the same with 1 and 2 threads"

# progress on a terminal (script(1) gives the run one): the evaluations of all the runs with the time left,
# ending at the whole budget; none when stderr is not a terminal
if command -v script > /dev/null; then
    # 200 evaluations on the case's own LTCA grid (a second or more: 80 on a coarse grid end within the
    # first quarter of a second, before any line but the last)
    script -qec "\"$G\" run \"$SRC/cases/paper/optimize-alo.ini\" --out \"$work/tty\" --set optimize.iterations=9 \
        --set optimize.population=10 --set optimize.runs=2 --set output.plots=off" /dev/null < /dev/null |
        tr '\r' '\n' > "$work/tty.txt"
    grep -q "^geardyn: optimize [0-9]*/200 evaluations ([0-9]*%), .* per s, about [0-9]* s left" "$work/tty.txt" &&
        grep -q "^geardyn: optimize 200/200 evaluations (100%)" "$work/tty.txt" &&
        "$G" run "$SRC/cases/paper/optimize-alo.ini" --out "$work/notty" --set optimize.iterations=3 \
            --set optimize.population=10 --set solver.ltca_positions_per_cycle=8 --set solver.ltca_face_slices=7 \
            --set output.plots=off > /dev/null 2> "$work/notty.txt" &&
        ! grep -q "evaluations (" "$work/notty.txt"
    ok $? "progress on a terminal: evaluations of both runs with the time left, to 200/200"
else
    ok 0 "# SKIP script(1) is not installed"
fi

# ---- gear-dynamic on a herringbone: each half's RMS mesh acceleration, the larger ------------------
# The paper's pair with its case's flank (geardyn's LTE optimum), 5400-5500 rpm at 500 N m: the
# objective of that flank is the larger of the two halves' RMS mesh accelerations of a response run
# at its peak speed, not the combined one (their mean's RMS, which cancels where the halves vibrate
# in antiphase), on a coarser LTCA grid than the case's.
out="$work/herringbone-dyn"
"$G" run "$SRC/cases/paper/optimize-dynamic.ini" --out "$out" --quiet --set optimize.algorithm=random \
    --set optimize.iterations=1 --set optimize.population=2 --set optimize.torques_nm=500 \
    --set optimize.speed_from_rpm=5400 --set optimize.speed_to_rpm=5500 --set optimize.harris_torques=2 \
    --set solver.ltca_positions_per_cycle=16 --set solver.ltca_face_slices=11 --set output.plots=off \
    > "$work/run.txt" 2>&1
ok $? "optimize gear-dynamic on the paper's herringbone exits 0 ($(head -c 300 "$work/run.txt"))"
speed=$(python3 - "$out" <<'PY'
import csv, json, os, sys
out = sys.argv[1]
peak = json.load(open(os.path.join(out, "summary.json")))["results"]["objective_of"]["case"]["torques"][0]["peak"]
rows = [r for r in csv.DictReader(open(os.path.join(out, "response_over_speed.csv")))
        if r["model"] == "torsional-lr" and r["flank"] == "case" and r["stable"] == "1"]
best = max(rows, key=lambda r: float(r["rms_accel_mps2"]))
assert abs(float(best["rms_accel_mps2"]) - peak) <= 1e-9 * peak, (best, peak)
print(best["speed_rpm"], peak)
PY
)
ok $? "the case flank's peak lies on its response curve ($speed)"
set -- $speed
"$G" run "$SRC/cases/paper/optimize-dynamic.ini" --out "$out-response" --quiet --set scene.analysis=response \
    --set scene.model=torsional-lr --set operating.speed_rpm="$1" --set solver.ltca_positions_per_cycle=16 \
    --set solver.ltca_face_slices=11 --set output.plots=off > "$work/run.txt" 2>&1 &&
    python3 - "$out-response/summary.json" "$2" <<'PY'
import json, sys
a = json.load(open(sys.argv[1]))["results"]["rms_accel_mps2"]
peak = float(sys.argv[2])
half = max(a["left"], a["right"])
assert abs(half - peak) <= 1e-3 * peak, (a, peak)        # the larger of the halves'
assert a["combined"] < 0.9 * half, a                      # which here the combined is not
PY
ok $? "gear-dynamic on a herringbone: the peak is the larger half's RMS mesh acceleration of a response run at its speed, not the combined"

echo "1..$n"
[ $bad -eq 0 ]
