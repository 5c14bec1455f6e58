#!/usr/bin/env bash
# Neimark-Sacker curves of a gear pair from a case file (docs/continuation.md section 8): the paper's
# pair on bta, unmodified, in (speed, backlash) (cases/continuation/paper-curves-backlash.ini with
# modification.apply=off), the curves started from rows of the branch's bifurcations.csv at 10 um
# (continuation.curve_start) in the box 9.5 to 25 um.
# - On every point of the Neimark-Sacker curve from 4932.23 rpm a complex pair of the monodromy's
#   eigenvalues (computed by the Floquet routine from the corrected orbit) lies on the unit circle,
#   and its cos theta is the curve's unknown kappa (the bordered system on M^2 - 2 kappa M + I),
#   both to 1e-6: two independent computations of the same pair (not at the point where the curve
#   ends on a grazing, where the monodromy jumps).
# - Consistency: the curve followed down ends on the bound 9.5 um at the speed where a one-parameter
#   continuation at 9.5 um locates its Neimark-Sacker point, to 1e-8 relative.
# - Grazing-Neimark-Sacker: followed up, the curve ends where the period-1 orbit first touches
#   bearing 1L's clearance, located; the grazing curve of that clearance, started from another row
#   (the contact change at 4571.34 rpm) and followed up, locates a grazing-Neimark-Sacker point (a
#   complex pair crossing the unit circle on it) at the same place, to 1e-6 relative in both keys: the
#   same codimension-two point from two independent continuations. The multiplier reported there is
#   the pair on the unit circle.
# - The 1:3 resonance on the curve (kappa = -1/2) is reported with its multiplier at -1/2 + i sqrt(3)/2.
# TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok
CASE="$SRC/cases/continuation/paper-curves-backlash.ini"
grep -v '^parameter2' "$CASE" > "$work/branch.ini"
UN=(--set modification.apply=off --set output.plots=off --quiet)

"$G" run "$work/branch.ini" "${UN[@]}" --out "$work/a" > "$work/a.txt" 2>&1
ok $? "the branch at 10 um ($(head -c 300 "$work/a.txt"))"
"$G" run "$work/branch.ini" "${UN[@]}" --set clearance.backlash_um=9.5 --out "$work/d" > "$work/d.txt" 2>&1
ok $? "the branch at 9.5 um ($(head -c 300 "$work/d.txt"))"
row_of() { # the data row of bifurcations.csv (1-based) of kind $2 nearest speed $3
    python3 - "$1" "$2" "$3" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
best = min((i for i, r in enumerate(rows) if r["kind"] == sys.argv[2]),
           key=lambda i: abs(float(rows[i]["speed_rpm"]) - float(sys.argv[3])))
print(best + 1)
PY
}
ns_row=$(row_of "$work/a/bifurcations.csv" neimark-sacker 4932.23)
gr_row=$(row_of "$work/a/bifurcations.csv" contact-change 4571.34)
BOX=(--set continuation.parameter2_from=9.5 --set continuation.parameter2_to=25
     --set continuation.curve_start="$work/a/bifurcations.csv")
"$G" run "$CASE" "${UN[@]}" "${BOX[@]}" --set continuation.curve_start_row="$ns_row" --out "$work/ns" > "$work/ns.txt" 2>&1
ok $? "the Neimark-Sacker curve from row $ns_row ($(head -c 300 "$work/ns.txt"))"
"$G" run "$CASE" "${UN[@]}" "${BOX[@]}" --set continuation.curve_start_row="$gr_row" --out "$work/gr" > "$work/gr.txt" 2>&1
ok $? "the grazing curve from row $gr_row ($(head -c 300 "$work/gr.txt"))"

python3 - "$work" > "$work/checks.txt" <<'PY'
import csv, json, math, sys
w = sys.argv[1]
def ok(c, msg):
    print(("PASS " if c else "FAIL ") + msg)
def rows(p):
    return list(csv.DictReader(open(p)))
cv, c2 = rows(w + "/ns/curves.csv"), rows(w + "/ns/codim2.csv")
s = json.load(open(w + "/ns/summary.json"))["results"]
ok([c["kind"] for c in s["curves"]] == ["neimark-sacker"] * 2, "two Neimark-Sacker curves, down and up (%s)"
   % [c["kind"] for c in s["curves"]])
# the pair on the unit circle, its cos theta the curve's kappa
# (not at the point that ends the curve on a grazing: the monodromy jumps there, a saltation matrix
# appearing with the touch, so the Floquet routine's M and the bordered system's differ by the jump)
worst_m, worst_k, npts = 0.0, 0.0, 0
n = sum(1 for k in cv[0] if k.startswith("mu") and k.endswith("_re"))
ends = {c["direction"]: c["end"] for c in s["curves"]}
last_pt = {r["direction"]: r["point"] for r in cv}
for r in cv:
    if ends.get(r["direction"]) == "contact" and r["point"] == last_pt[r["direction"]]:
        continue
    mus = [complex(float(r["mu%d_re" % j]), float(r["mu%d_im" % j])) for j in range(1, n + 1)]
    pair = min((m for m in mus if m.imag > 0), key=lambda m: abs(abs(m) - 1))
    worst_m = max(worst_m, abs(abs(pair) - 1))
    worst_k = max(worst_k, abs(pair.real / abs(pair) - float(r["kappa"])))
    npts += 1
ok(npts > 20 and worst_m < 1e-6 and worst_k < 1e-6, "%d points: a complex pair on the unit circle (worst ||mu| - 1| "
   "%.2g) at cos theta = kappa (worst %.2g), to 1e-6" % (npts, worst_m, worst_k))
# consistency with the one-parameter run at 9.5 um
down = [r for r in cv if r["direction"] == "down"]
last = down[-1]
d = [float(r["speed_rpm"]) for r in rows(w + "/d/bifurcations.csv") if r["kind"] == "neimark-sacker"]
near = min(d, key=lambda v: abs(v - float(last["speed_rpm"]))) if d else float("nan")
rel = abs(near - float(last["speed_rpm"])) / near
ok(ends.get("down") == "bound" and float(last["backlash_um"]) == 9.5 and rel < 1e-8,
   "down: ends on the bound 9.5 um at %.8f rpm, the branch at 9.5 um's Neimark-Sacker point %.8f rpm (rel %.2g)"
   % (float(last["speed_rpm"]), near, rel))
# the grazing-Neimark-Sacker point from both curves
g1 = [r for r in c2 if r["kind"] == "grazing-neimark-sacker"]
g2 = [r for r in rows(w + "/gr/codim2.csv") if r["kind"] == "grazing-neimark-sacker"]
ok(ends.get("up") == "contact" and len(g1) == 1 and g1[0]["clearance"] == "bearing-1L" and g1[0]["location"] == "located"
   and g1[0]["ends_curve"] == "1", "up: ends on the grazing of bearing-1L, located (%s)"
   % [(r["clearance"], r["location"]) for r in g1])
if g1 and g2:
    a = g1[0]
    b = min(g2, key=lambda r: abs(float(r["speed_rpm"]) - float(a["speed_rpm"])))
    rs = abs(float(a["speed_rpm"]) - float(b["speed_rpm"])) / float(b["speed_rpm"])
    rb = abs(float(a["backlash_um"]) - float(b["backlash_um"])) / float(b["backlash_um"])
    ok(b["location"] == "located" and rs < 1e-6 and rb < 1e-6, "the same point on the grazing curve: (%.6f rpm, "
       "%.7f um) against (%.6f rpm, %.7f um), rel %.2g and %.2g" % (float(a["speed_rpm"]), float(a["backlash_um"]),
       float(b["speed_rpm"]), float(b["backlash_um"]), rs, rb))
    m = complex(float(a["mu_re"]), float(a["mu_im"]))
    ok(abs(abs(m) - 1) < 1e-5 and abs(m.real - float(b["mu_re"])) < 1e-5,
       "its multiplier the pair on the unit circle: %.7f%+.7fi, the grazing curve's %.7f%+.7fi"
       % (m.real, m.imag, float(b["mu_re"]), float(b["mu_im"])))
else:
    ok(False, "a grazing-Neimark-Sacker point from both curves (%d, %d)" % (len(g1), len(g2)))
r3 = [r for r in c2 if r["kind"] == "resonance-1:3"]
ok(len(r3) == 1 and abs(float(r3[0]["mu_re"]) + 0.5) < 1e-6 and abs(float(r3[0]["mu_im"]) - math.sqrt(3) / 2) < 1e-6,
   "the 1:3 resonance at mu = -1/2 + i sqrt(3)/2 (%s)" % [(r["mu_re"], r["mu_im"], r["speed_rpm"]) for r in r3])
PY
grep '^#' "$work/checks.txt"
while read -r verdict msg; do
    [ "$verdict" = PASS ]; ok $? "$msg"
done < <(grep -E '^(PASS|FAIL)' "$work/checks.txt")
echo "1..$n"
[ "$bad" = 0 ]
