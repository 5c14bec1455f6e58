#!/usr/bin/env bash
# analysis = basins on the command line (docs/basins.md): cases/basins/ks-hysteresis.ini (Kahraman &
# Singh at Omega 0.65, shortened) writes basins.csv, attractors.csv, fractions.csv,
# attractor_points.csv, summary.json and the picture; the same files with 1 and 2 threads; two
# attractors (one with impacts, one without) whose fractions add up with the other outcomes to the
# sample; the picture's cells and the summary agree. With the continuation of the same oscillator
# (cases/continuation/kahraman-singh.ini) named: its three orbits through Omega 0.65 marked, the two
# stable ones the attractors. cases/basins/ks-fractions.ini (shortened) over Omega: fractions that
# add up at every value, the attractor ids followed, the picture of the fractions beside the
# continuation's branches. check estimates the cost. TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok
KS="$SRC/cases/basins/ks-hysteresis.ini"
KF="$SRC/cases/basins/ks-fractions.ini"
SMALL=(--set basins.resolution=50 --set basins.samples=1000)

"$G" check "$KS" > "$work/check.txt"; ok $? "check exits 0 on ks-hysteresis.ini"
grep -Eq "^resolution = 200 +; file line" "$work/check.txt"; ok $? "check lists basins.resolution"
grep -Eq "^integration = 5e\+04 runs of 20 mesh periods" "$work/check.txt"; ok $? "check estimates 50 000 runs"

for t in 1 2; do
    "$G" run "$KS" "${SMALL[@]}" --out "$work/t$t" --threads $t --quiet > "$work/run$t.txt" 2>&1
    ok $? "run with $t thread(s) exits 0 ($(head -c 300 "$work/run$t.txt"))"
done
for f in basins.csv attractors.csv fractions.csv attractor_points.csv; do
    cmp -s "$work/t1/$f" "$work/t2/$f"; ok $? "$f: the same with 1 and 2 threads"
done
for f in basins.png basins.svg summary.json; do
    [ -s "$work/t1/$f" ]; ok $? "wrote $f"
done
python3 - "$work/t1" > "$work/checks.txt" <<'PY'
import csv, json, sys
d = sys.argv[1]
def ok(c, msg):
    print(("PASS " if c else "FAIL ") + msg)
cells = list(csv.DictReader(open(d + "/basins.csv")))
att = list(csv.DictReader(open(d + "/attractors.csv")))
fr = list(csv.DictReader(open(d + "/fractions.csv")))
s = json.load(open(d + "/summary.json"))
ok(len(cells) == 2500, "basins.csv: 50 x 50 cells (%d)" % len(cells))
ok(len(att) == 2 and sorted(a["impact_regime"] for a in att) == ["no-impact", "single-sided"],
   "two attractors, one without impacts, one single-sided (%s)" % [a["impact_regime"] for a in att])
ok(all(a["period_n"] == "1" and float(a["mu_max"]) < 1 for a in att), "both of period 1 and stable")
ok(sum(int(f["count"]) for f in fr) == 1000, "fractions.csv: the counts add up to the sample")
ok(abs(sum(float(f["fraction"]) for f in fr) - 1) < 1e-12, "the fractions add up to 1")
for f in fr:
    p, lo, hi = float(f["fraction"]), float(f["wilson_lo"]), float(f["wilson_hi"])
    ok(lo <= p <= hi, "%s: %.4f inside its Wilson interval [%.4f, %.4f]" % (f["outcome"], p, lo, hi))
labels = s["results"]["picture"]["labels"]
for l in labels:
    n = sum(1 for c in cells if int(c["attractor"]) == l["attractor"])
    ok(n == l["cells"], "summary.json: attractor %d holds %d cells of the picture (basins.csv: %d)" % (l["attractor"], l["cells"], n))
e = s["results"]["picture"]["basin_entropy"]
ok(0 < e["S_b"] <= e["S_bb"] and e["fractal_boundary"] == (e["S_bb"] > 0.6931471805599453),
   "basin entropy S_b %.4f <= S_bb %.4f, the fractal test S_bb > ln 2 (%s)" % (e["S_b"], e["S_bb"], e["fractal_boundary"]))
ok(set(s["files"]) >= {"basins.csv", "attractors.csv", "fractions.csv", "attractor_points.csv", "basins.png",
                       "basins.svg", "summary.json"}, "summary.json lists the files")
PY
while read -r st msg; do [ "$st" = PASS ]; ok $? "$msg"; done < "$work/checks.txt"

# with the continuation of the same oscillator: its orbits marked and seeding
"$G" run "$SRC/cases/continuation/kahraman-singh.ini" --out "$work/cont" --quiet --set continuation.branch_switching=off \
    --set continuation.to=2546.4790894703 --set output.plots=off > "$work/cont.txt" 2>&1
ok $? "the continuation of the oscillator exits 0"
"$G" run "$KS" "${SMALL[@]}" --out "$work/withcont" --set basins.continuation="$work/cont" > "$work/wc.txt" 2>&1
ok $? "run with basins.continuation exits 0 ($(head -c 300 "$work/wc.txt"))"
python3 - "$work/withcont" > "$work/checks2.txt" <<'PY'
import csv, sys
d = sys.argv[1]
def ok(c, msg):
    print(("PASS " if c else "FAIL ") + msg)
orb = list(csv.DictReader(open(d + "/continuation_orbits.csv")))
att = list(csv.DictReader(open(d + "/attractors.csv")))
ok(len(orb) == 3 and sorted(o["stable"] for o in orb) == ["0", "1", "1"],
   "three orbits of the continuation through Omega 0.65, two stable (%s)" % [o["stable"] for o in orb])
cols = [c for c in att[0].keys() if c.startswith("lambda_L_half")][0], [c for c in att[0].keys() if c.startswith("lambda_dot_L")][0]
for o in orb:
    if o["stable"] != "1":
        continue
    near = [a for a in att if abs(float(a[cols[0]]) - float(o[cols[0]])) < 1e-6 and abs(float(a[cols[1]]) - float(o[cols[1]])) < 1e-6]
    ok(len(near) == 1, "the stable orbit at (%s, %s) is an attractor" % (o[cols[0]], o[cols[1]]))
ok(len(att) == 2 and all(a["seeded"] == "0" for a in att), "no attractor found from the seeds only")
PY
while read -r st msg; do [ "$st" = PASS ]; ok $? "$msg"; done < "$work/checks2.txt"
grep -q "continuation's orbit, branch 0, period 1, unstable" "$work/wc.txt"; ok $? "the lines name the unstable orbit"

# over Omega
"$G" run "$KF" --out "$work/frac" --set basins.points=5 --set basins.samples=300 --set basins.continuation="$work/cont" \
    > "$work/f.txt" 2>&1
ok $? "the fractions over Omega exit 0 ($(head -c 300 "$work/f.txt"))"
for f in fractions.csv attractors.csv fractions.png fractions.svg summary.json; do
    [ -s "$work/frac/$f" ]; ok $? "over Omega: wrote $f"
done
python3 - "$work/frac" > "$work/checks3.txt" <<'PY'
import csv, json, sys, collections
d = sys.argv[1]
def ok(c, msg):
    print(("PASS " if c else "FAIL ") + msg)
fr = list(csv.DictReader(open(d + "/fractions.csv")))
by = collections.defaultdict(list)
for f in fr:
    by[f["speed_rpm"]].append(f)
ok(len(by) == 5, "five values of the speed (%d)" % len(by))
for v, rows in sorted(by.items(), key=lambda x: float(x[0])):
    ok(sum(int(r["count"]) for r in rows) == 300, "speed %s rpm: the counts add up to the sample" % v)
att = list(csv.DictReader(open(d + "/attractors.csv")))
ids = sorted(set(a["attractor"] for a in att))
ok(ids == ["0", "1"], "two attractor ids over the range: the orbit without impacts and the impacting one (%s)" % ids)
s = json.load(open(d + "/summary.json"))
ok(s["results"]["parameter"] == "operating.speed_rpm" and len(s["results"]["values"]) == 5, "summary.json: five values")
PY
while read -r st msg; do [ "$st" = PASS ]; ok $? "$msg"; done < "$work/checks3.txt"
echo "1..$n"
[ $bad -eq 0 ]
