#!/usr/bin/env bash
# continuation.parameter2 on the command line (docs/continuation.md section 8):
# cases/continuation/kahraman-singh-curves.ini (Kahraman & Singh, constant stiffness, zeta 0.05,
# F_m 0.1; Omega 0.5 to 1.5 through operating.speed_rpm, F_a 0.05 to 0.2 through
# excitation.ste_amplitude_um, 10 um per unit of F_a) writes curves.csv and the curves in
# summary.json: from the branch's grazing, two folds and period doubling at F_a 0.1, eight curves
# (each both ways), every one ending on the box; the grazing curve on its closed form
# F_a Omega^2 = F_m sqrt((1 - Omega^2)^2 + (2 zeta Omega)^2) to 1e-8 at every point; on every fold
# and period-doubling point tr M = +-(1 + det M) with det M = exp(-4 pi zeta / Omega) (one degree of
# freedom, Liouville) to 1e-8; the curves pass through the branch's bifurcations; with gnuplot,
# curves.png and curves.svg are drawn and listed. Bad keys are
# refused with exit 2 naming file, line and key, and nothing is written. TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok
KS="$SRC/cases/continuation/kahraman-singh-curves.ini"

"$G" check "$KS" > "$work/check.txt"; ok $? "check exits 0 on kahraman-singh-curves.ini"
grep -Eq "^parameter2 = excitation.ste_amplitude_um +; file line" "$work/check.txt"; ok $? "check lists continuation.parameter2"

out="$work/ks"
"$G" run "$KS" --out "$out" --quiet --set output.plots=on > "$work/run.txt" 2>&1
ok $? "run exits 0 ($(head -c 300 "$work/run.txt"))"
for f in branch.csv bifurcations.csv curves.csv summary.json; do
    [ -s "$out/$f" ]; ok $? "wrote $f"
done
if command -v gnuplot > /dev/null; then
    [ -s "$out/curves.png" ] && [ -s "$out/curves.svg" ] && grep -q '"curves.png"' "$out/summary.json"
    ok $? "the curves' picture drawn (PNG, SVG) and listed"
fi
python3 - "$out" > "$work/checks.txt" <<'PY'
import csv, json, math, sys
d = sys.argv[1]
scale, fa_um = 3183.0988618379, 10.0  # rpm per unit of Omega, um per unit of F_a (the case's comment)
zeta, fm = 0.05, 0.1
cv = list(csv.DictReader(open(d + "/curves.csv")))
bf = list(csv.DictReader(open(d + "/bifurcations.csv")))
s = json.load(open(d + "/summary.json"))["results"]
def ok(c, msg):
    print(("PASS " if c else "FAIL ") + msg)
curves = s["curves"]
kinds = sorted(c["kind"] for c in curves)
ok(kinds == ["fold"] * 4 + ["grazing"] * 2 + ["period-doubling"] * 2, "eight curves: two grazing, four fold, two "
   "period-doubling (%s)" % kinds)
ok(all(c["end"] == "bound" for c in curves), "every curve ends on the box (%s)" % [c["end"] for c in curves])
ok(s["parameter2"] == "excitation.ste_amplitude_um" and s["unit2"] == "um", "summary.json names parameter2 and its unit")
worst, worst_l, worst_mu, n = 0.0, 0.0, 0.0, 0
for r in cv:
    om, fa = float(r["speed_rpm"]) / scale, float(r["ste_amplitude_um"]) / fa_um
    if r["kind"] == "grazing":
        worst = max(worst, abs(fa * om * om - fm * math.sqrt((1 - om * om) ** 2 + (2 * zeta * om) ** 2)))
        continue
    m1, m2 = complex(float(r["mu1_re"]), float(r["mu1_im"])), complex(float(r["mu2_re"]), float(r["mu2_im"]))
    tr, det = (m1 + m2).real, (m1 * m2).real
    sg = 1 if r["kind"] == "fold" else -1
    worst_l = max(worst_l, abs(tr - sg * (1 + det)), abs(det - math.exp(-4 * math.pi * zeta / om)))
    worst_mu = max(worst_mu, min(abs(m1 - sg), abs(m2 - sg)))
    n += 1
ok(worst < 1e-8, "grazing curve on F_a Omega^2 = F_m sqrt((1 - Omega^2)^2 + (2 zeta Omega)^2) (worst %.2g)" % worst)
ok(n > 50 and worst_l < 1e-8, "%d fold and period-doubling points: tr M = +-(1 + det M), det M = exp(-4 pi zeta / "
   "Omega) (worst %.2g)" % (n, worst_l))
ok(worst_mu < 5e-8, "a multiplier at +1 (fold) or -1 (period doubling) at every point to 5e-8 (continuation.newton_tol 1e-9; worst %.2g)" % worst_mu)
# each curve's first point is its bifurcation of branch 0, at the case's F_a
for c in curves:
    b = [x for x in bf if x["branch"] == "0" and abs(float(x["speed_rpm"]) - c["first"][0]) < 1e-6 * scale]
    ok(len(b) == 1 and abs(c["first"][1] - 1.0) < 1e-12, "curve %d (%s %s) starts at the %s of branch 0 at %.6f rpm"
       % (c["curve"], c["kind"], c["direction"], b[0]["kind"] if b else "?", c["first"][0]))
print("# curves:", [(c["kind"], c["direction"], c["points"], round(c["last"][0], 3), c["last"][1]) for c in curves])
PY
cat "$work/checks.txt" | grep '^#'
while read -r verdict msg; do
    [ "$verdict" = PASS ]; ok $? "$msg"
done < <(grep -E '^(PASS|FAIL)' "$work/checks.txt")

# refusals: exit 2, file:line and key named, nothing written
refuse() { # key=value, pattern of the message[, another key=value]
    local o="$work/bad"
    rm -rf "$o"
    "$G" run "$KS" --out "$o" --quiet --set "$1" ${3:+--set "$3"} > "$work/bad.txt" 2>&1
    local rc=$?
    [ $rc -eq 2 ] && grep -Eq -e "$2" "$work/bad.txt" && [ ! -e "$o" ]
    ok $? "--set $1 refused with exit 2 (rc $rc: $(head -c 200 "$work/bad.txt"))"
}
refuse continuation.parameter2=operating.speed_rpm "continuation.parameter2: 'operating.speed_rpm' is continuation.parameter too"
refuse continuation.parameter2=gear.teeth_pinion "continuation.parameter2: 'gear.teeth_pinion' is not a real-valued"
refuse continuation.parameter2=continuation.from "continuation.parameter2: 'continuation.from' is not a real-valued"
refuse continuation.parameter2_to=0.4 "continuation.parameter2_to: 0.4 is not above parameter2_from"
refuse continuation.parameter2_from=-1 "continuation.parameter2_from: excitation.ste_amplitude_um = -1 is out of range"
refuse continuation.parameter2_from=1.5 "continuation.parameter2: the case's excitation.ste_amplitude_um = 1 lies outside"
refuse continuation.parameter2= "continuation.parameter2_from: given without continuation.parameter2"
refuse continuation.curve_max_points=1 "continuation.curve_max_points"
echo "1..$n"
[ $bad -eq 0 ]
