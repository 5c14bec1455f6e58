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
for f in branch.csv bifurcations.csv curves.csv codim2.csv summary.json; do
    [ -s "$out/$f" ]; ok $? "wrote $f"
done
grep -q '"codim2.csv"' "$out/summary.json"; ok $? "codim2.csv listed in summary.json's files"
if command -v gnuplot > /dev/null; then
    [ -s "$out/curves.png" ] && [ -s "$out/curves.svg" ] && grep -q '"curves.png"' "$out/summary.json"
    ok $? "the curves' picture drawn (PNG, SVG) and listed"
fi
python3 - "$out" > "$work/checks.txt" <<'PY'
import csv, json, math, re, sys
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
# the end reasons in the keys' names and units: the bound's key and value, the other key's value
rx = re.compile(r"^ended on the bound (continuation\.parameter2_to = 2 um at operating\.speed_rpm = [0-9.]+ rpm"
                r"|continuation\.parameter2_from = 0\.5 um at operating\.speed_rpm = [0-9.]+ rpm"
                r"|continuation\.from = 1591\.5494\d* rpm at excitation\.ste_amplitude_um = [0-9.]+ um"
                r"|continuation\.to = 4774\.6482\d* rpm at excitation\.ste_amplitude_um = [0-9.]+ um)$")
bad = [c["end_reason"] for c in curves if not rx.match(c["end_reason"])]
ok(not bad, "every end reason names the bound and the other key in their units (%s)" % bad[:2])
for c in curves:
    oth = float(c["end_reason"].rsplit(" = ", 1)[1].split()[0]) if c["end"] == "bound" else float("nan")
    k = 0 if "at operating.speed_rpm" in c["end_reason"] else 1
    ok(abs(oth - c["last"][k]) <= 1e-9 * abs(c["last"][k]), "curve %d's end reason gives its last point (%s)"
       % (c["curve"], c["end_reason"]))
c2 = list(csv.DictReader(open(d + "/codim2.csv")))
ok(len(c2) == sum(len(c["codim2"]) for c in curves) == 0, "no codimension-two point in this box (%d rows)" % len(c2))
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

# one curve from a row of an earlier run's bifurcations.csv (continuation.curve_start): row 2, the
# upper fold, gives its two curves only, the same as the run of every curve gives from that fold
"$G" run "$KS" --out "$work/row" --quiet --set output.plots=off --set continuation.curve_start="$out/bifurcations.csv" \
    --set continuation.curve_start_row=2 > "$work/row.txt" 2>&1
ok $? "a start from row 2 of bifurcations.csv runs ($(head -c 300 "$work/row.txt"))"
python3 - "$out" "$work/row" > "$work/row-checks.txt" <<'PY'
import json, sys
a = json.load(open(sys.argv[1] + "/summary.json"))["results"]
b = json.load(open(sys.argv[2] + "/summary.json"))["results"]
bf = [c for c in a["curves"] if c["kind"] == "fold" and abs(c["first"][0] - b["curves"][0]["first"][0]) < 1e-6]
print(("PASS " if len(b["curves"]) == 2 and all(c["kind"] == "fold" and c["from_branch"] is None for c in b["curves"])
       and "row 2: fold at speed_rpm = " in (b["curve_start"] or "") else "FAIL ") +
      "only the fold's two curves (%s; %s)" % ([(c["kind"], c["direction"]) for c in b["curves"]], b["curve_start"]))
same = len(bf) == 2 and all(x["direction"] == y["direction"] and x["points"] == y["points"] and
                            all(abs(u - v) <= 1e-9 * abs(v) for u, v in zip(x["last"], y["last"]))
                            for x, y in zip(bf, b["curves"]))
print(("PASS " if same else "FAIL ") + "they end where the all-curves run's curves of that fold end, to 1e-9 (%s)"
      % [c["last"] for c in b["curves"]])
PY
while read -r verdict msg; do
    [ "$verdict" = PASS ]; ok $? "$msg"
done < "$work/row-checks.txt"

# the cusp (cases/continuation/kahraman-singh-cusp.ini): both fold curves from the branch at F_a 0.02
# pass it, codim2.csv reports it from each, at the same point; one-parameter continuations in Omega
# at F_a 1 % above it find two folds (their hysteresis 0.5 rpm wide) near its Omega, 1 % below none
# (with steps a tenth of the case's, that would see them); and the folds' separation s at F_a 1 %
# and 2 % above it extrapolate (s^(2/3) linear in F_a, the cusp's normal form) to its F_a.
CU="$SRC/cases/continuation/kahraman-singh-cusp.ini"
"$G" run "$CU" --out "$work/cusp" --quiet --set output.plots=off > "$work/cusp.txt" 2>&1
ok $? "the cusp case runs ($(head -c 300 "$work/cusp.txt"))"
python3 - "$work/cusp/codim2.csv" > "$work/cusp-at.txt" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
cp = [r for r in rows if r["kind"] == "cusp"]
om = [float(r["speed_rpm"]) / 3183.0988618379 for r in cp]
fa = [float(r["ste_amplitude_um"]) / 10.0 for r in cp]
good = (len(rows) == len(cp) == 2 and all(r["curve_kind"] == "fold" and r["label"] == "CP" and r["test"] == "test_cusp"
        and r["location"] == "located" for r in cp) and abs(om[0] - om[1]) < 1e-8 * om[0] and abs(fa[0] - fa[1]) < 1e-8 * fa[0])
print("%d %.12g %.12g %s" % (good, om[0] if om else 0, fa[0] if fa else 0, [(r["kind"], r["curve"]) for r in rows]))
PY
read -r good om_c fa_c rest < "$work/cusp-at.txt"
[ "$good" = 1 ]; ok $? "codim2.csv: the cusp, from both fold curves, at the same point to 1e-8 (Omega $om_c, F_a $fa_c; $rest)"
KS1="$SRC/cases/continuation/kahraman-singh.ini"
one() { # F_a, output, ds
    "$G" run "$KS1" --out "$2" --quiet --set output.plots=off --set continuation.branch_switching=off \
        --set operating.speed_rpm=2546.4790894703 --set continuation.from=2546.4790894703 \
        --set continuation.to=3819.7186342055 --set excitation.ste_amplitude_um="$1" --set continuation.ds="$3" \
        --set continuation.ds_max="$3"
}
for f in 1.01 1.02 0.99; do
    one "$(python3 -c "print(10 * $fa_c * $f)")" "$work/one-$f" $([ $f = 0.99 ] && echo 0.005 || echo 0.05)
    ok $? "one-parameter run at F_a = $f x the cusp's"
done
python3 - "$work" "$om_c" "$fa_c" <<'PY' > "$work/cusp-checks.txt"
import csv, sys
w, om_c, fa_c = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
def folds(f):
    return sorted(float(r["speed_rpm"]) / 3183.0988618379 for r in csv.DictReader(open("%s/one-%s/bifurcations.csv" % (w, f)))
                  if r["kind"] == "fold" and r["location"] == "located")
a, b, c = folds("1.01"), folds("1.02"), folds("0.99")
print(("PASS " if len(a) == 2 and abs(0.5 * (a[0] + a[1]) - om_c) < 2e-3 else "FAIL ") +
      "F_a 1 %% above the cusp: two folds near its Omega %.6f (%s)" % (om_c, a))
print(("PASS " if len(b) == 2 else "FAIL ") + "F_a 2 %% above: two folds (%s)" % b)
print(("PASS " if len(c) == 0 else "FAIL ") + "F_a 1 %% below the cusp: no fold (%s)" % c)
if len(a) == 2 and len(b) == 2:
    s1, s2 = (a[1] - a[0]) ** (2 / 3), (b[1] - b[0]) ** (2 / 3)
    f0 = 1.01 * fa_c - s1 * (0.01 * fa_c) / (s2 - s1)
    print(("PASS " if abs(f0 - fa_c) < 1e-3 * fa_c else "FAIL ") + "the folds' separation extrapolates to the cusp's "
          "F_a: %.8f against %.8f" % (f0, fa_c))
PY
while read -r verdict msg; do
    [ "$verdict" = PASS ]; ok $? "$msg"
done < "$work/cusp-checks.txt"

# the (Omega, F_m) plane (cases/continuation/kahraman-singh-mean-force.ini: F_a 0.1, F_m 0.02 to 1.1
# through operating.torque_nm, 140.95389311789 N m per unit of F_m): every grazing-curve point on
# the closed form F_a Omega^2 = F_m sqrt((1 - Omega^2)^2 + (2 zeta Omega)^2) to 1e-8; and while the
# orbit stays off the back flank the oscillator's equation is homogeneous in the deflection from the
# contact boundary (the piecewise-linear force k max(x - 1, 0)), so its curves depend on F_a / F_m
# only: the cusp this plane locates is the cusp of the (Omega, F_a) plane at F_m 0.1 (the cusp case
# above), F_a,cusp / 0.1 = 0.1 / F_m,cusp, to 1e-8 in both
MF="$SRC/cases/continuation/kahraman-singh-mean-force.ini"
"$G" run "$MF" --out "$work/mf" --quiet --set output.plots=off > "$work/mf.txt" 2>&1
ok $? "the (Omega, F_m) case runs ($(head -c 300 "$work/mf.txt"))"
python3 - "$work/mf" "$work/cusp/codim2.csv" > "$work/mf-checks.txt" <<'PY'
import csv, json, math, sys
d = sys.argv[1]
scale, fm_nm = 3183.0988618379, 140.95389311789  # rpm per unit of Omega, N m per unit of F_m
zeta, fa = 0.05, 0.1
cv = list(csv.DictReader(open(d + "/curves.csv")))
s = json.load(open(d + "/summary.json"))["results"]
def ok(c, msg):
    print(("PASS " if c else "FAIL ") + msg)
ok(s["parameter2"] == "operating.torque_nm" and s["unit2"] == "N m", "summary.json names parameter2 operating.torque_nm, N m")
g = [r for r in cv if r["kind"] == "grazing"]
worst = max((abs(fa * om * om - fm * math.sqrt((1 - om * om) ** 2 + (2 * zeta * om) ** 2))
             for om, fm in ((float(r["speed_rpm"]) / scale, float(r["torque_nm"]) / fm_nm) for r in g)), default=1)
ok(len(g) > 50 and worst < 1e-8, "(Omega, F_m): %d grazing-curve points on F_a Omega^2 = F_m sqrt((1 - Omega^2)^2 + "
   "(2 zeta Omega)^2) (worst %.2g)" % (len(g), worst))
top = max(float(r["torque_nm"]) / fm_nm for r in g) if g else 0
peak = fa / (2 * zeta * math.sqrt(1 - zeta * zeta))  # at Omega^2 = 1 / (1 - 2 zeta^2)
ok(abs(top - peak) < 1e-3, "the grazing curve's largest F_m %.6f near its peak F_a / (2 zeta sqrt(1 - zeta^2)) = %.6f"
   % (top, peak))
kinds = sorted(c["kind"] for c in s["curves"])
ok(kinds == ["fold"] * 4 + ["grazing"] * 2 + ["period-doubling"] * 2, "eight curves (%s)" % kinds)
mine = [r for r in csv.DictReader(open(d + "/codim2.csv")) if r["kind"] == "cusp"]
theirs = [r for r in csv.DictReader(open(sys.argv[2])) if r["kind"] == "cusp"]
ok(len(mine) == 2, "the cusp, from both fold curves (%d rows)" % len(mine))
if mine and theirs:
    om_t, fa_t = float(theirs[0]["speed_rpm"]) / scale, float(theirs[0]["ste_amplitude_um"]) / 10.0
    for r in mine:
        om, fm = float(r["speed_rpm"]) / scale, float(r["torque_nm"]) / fm_nm
        e_om, e_r = abs(om - om_t) / om_t, abs(fa / fm - fa_t / 0.1) / (fa_t / 0.1)
        ok(e_om < 1e-8 and e_r < 1e-8, "curve %s's cusp (Omega %.10f, F_m %.10f) is the (Omega, F_a) plane's (Omega "
           "%.10f, F_a %.10f) with F_a / F_m alike: %.2g in Omega, %.2g in F_a / F_m" % (r["curve"], om, fm, om_t, fa_t,
                                                                                      e_om, e_r))
print("# (Omega, F_m) curves:", [(c["kind"], c["direction"], c["points"], round(c["last"][0], 3), c["last"][1])
                                 for c in s["curves"]])
PY
grep '^#' "$work/mf-checks.txt"
while read -r verdict msg; do
    [ "$verdict" = PASS ]; ok $? "$msg"
done < <(grep -E '^(PASS|FAIL)' "$work/mf-checks.txt")

# convergence: every codimension-two point of the curve cases (the cusp, from both fold curves; the
# curves of kahraman-singh-curves.ini locate none) moves by less than 1e-7 relative in both
# parameters between solver.rtol 1e-9 and 1e-11 (atol 1e-12 and the case's newton_tol 1e-9)
for r in 1e-9 1e-11; do
    "$G" run "$CU" --out "$work/cusp-$r" --quiet --set output.plots=off --set solver.rtol=$r > "$work/cusp-$r.txt" 2>&1
    ok $? "the cusp case runs at solver.rtol = $r"
done
python3 - "$work/cusp-1e-9/codim2.csv" "$work/cusp-1e-11/codim2.csv" "$out/codim2.csv" <<'PY' > "$work/conv.txt"
import csv, sys
a, b, ks = (list(csv.DictReader(open(f))) for f in sys.argv[1:])
print(("PASS " if len(a) == len(b) == 2 else "FAIL ") + "the cusp from both fold curves at both tolerances (%d, %d rows)"
      % (len(a), len(b)))
for ra, rb in zip(a, b):
    d = [abs(float(ra[k]) - float(rb[k])) / abs(float(rb[k])) for k in ("speed_rpm", "ste_amplitude_um")]
    same = ra["kind"] == rb["kind"] and ra["curve"] == rb["curve"]
    print(("PASS " if same and max(d) < 1e-7 else "FAIL ") + "curve %s's %s moves %.2g in Omega, %.2g in F_a (relative) "
          "from rtol 1e-9 to 1e-11" % (rb["curve"], rb["kind"], d[0], d[1]))
print(("PASS " if len(ks) == 0 else "FAIL ") + "kahraman-singh-curves.ini locates no codimension-two point (%d)" % len(ks))
PY
while read -r verdict msg; do
    [ "$verdict" = PASS ]; ok $? "$msg"
done < "$work/conv.txt"

# a fold curve ending on a grazing curve (grazing-fold, GF): Kahraman & Singh at F_a 0.5 (5 um), Omega
# 0.3 to 0.6, F_a 0.3 to 0.6. The fold curve from the fold at 1223.63 rpm, followed down in F_a, runs
# into the grazing curve from the contact change at 1560.51 rpm, whose fold test changes sign there:
# codim2.csv locates the GF on the grazing curve, and the fold curve's last point (its corrector fails
# at the grazing, where the fold orbit's contact events change) lies on it to 1e-5 relative in both
# parameters (the two curves' intersection, by two independent continuations)
"$G" run "$KS" --out "$work/gf" --quiet --set output.plots=off --set excitation.ste_amplitude_um=5 \
    --set operating.speed_rpm=954.93 --set continuation.from=954.93 --set continuation.to=1909.86 \
    --set continuation.parameter2_from=3 --set continuation.parameter2_to=6 --set continuation.curve_max_points=100 \
    > "$work/gf.txt" 2>&1
ok $? "the (Omega, F_a) plane at F_a 0.3 to 0.6 runs ($(head -c 300 "$work/gf.txt"))"
python3 - "$work/gf" <<'PY' > "$work/gf-checks.txt"
import csv, sys
d = sys.argv[1]
last = {}
for r in csv.DictReader(open(d + "/curves.csv")):
    last[r["curve"]] = r
gf = [r for r in csv.DictReader(open(d + "/codim2.csv"))
      if r["curve_kind"] == "grazing" and r["kind"] == "grazing-fold" and r["location"] == "located"]
best = None
for g in gf:
    for c, r in last.items():
        if r["kind"] != "fold":
            continue
        e = max(abs(float(r[k]) - float(g[k])) / abs(float(g[k])) for k in ("speed_rpm", "ste_amplitude_um"))
        if best is None or e < best[0]:
            best = (e, g, c, r)
print(("PASS " if gf else "FAIL ") + "codim2.csv: %d grazing-fold points located on grazing curves" % len(gf))
if best:
    e, g, c, r = best
    print(("PASS " if e < 1e-5 else "FAIL ") + "the GF of grazing curve %s at (%s rpm, %s um) is where fold curve %s ends "
          "(%s rpm, %s um): %.2g relative" % (g["curve"], g["speed_rpm"], g["ste_amplitude_um"], c, r["speed_rpm"],
                                              r["ste_amplitude_um"], e))
PY
while read -r verdict msg; do
    [ "$verdict" = PASS ]; ok $? "$msg"
done < "$work/gf-checks.txt"

# a bound of the box on the edge of the key's range: in (Omega, zeta) with parameter2_from = 0 (zeta
# below 0 is refused by the case) the curves followed down in zeta end on the bound zeta = 0, the
# grazing curve where F_a Omega^2 = F_m |1 - Omega^2| (F_a = F_m: Omega^2 = 1/2), to 1e-8; not on a
# model out of its range a step short of it
"$G" run "$KS" --out "$work/z0" --quiet --set output.plots=off --set continuation.parameter2=damping.mesh_damping_ratio \
    --set continuation.parameter2_from=0 --set continuation.parameter2_to=0.1 > "$work/z0.txt" 2>&1
ok $? "the (Omega, zeta) plane down to zeta 0 runs ($(head -c 300 "$work/z0.txt"))"
python3 - "$work/z0" <<'PY' > "$work/z0-checks.txt"
import csv, json, math, sys
d = sys.argv[1]
curves = json.load(open(d + "/summary.json"))["results"]["curves"]
down = [c for c in curves if c["direction"] == "down" and "continuation.from =" not in c["end_reason"]]  # not the lower fold's
ends = [(c["kind"], c["end"], c["end_reason"][:80]) for c in down]
print(("PASS " if len(down) == 3 and all(c["end"] == "bound" and "continuation.parameter2_from = 0 at" in c["end_reason"]
                                          for c in down) else "FAIL ")
      + "the grazing, upper fold and period-doubling curves down in zeta end on the bound zeta = 0 (%s)" % ends)
last = {}
for r in csv.DictReader(open(d + "/curves.csv")):
    if r["direction"] == "down" and r["kind"] == "grazing":
        last = r
om = float(last["speed_rpm"]) / 3183.0988618379
e = abs(om - math.sqrt(0.5)) / math.sqrt(0.5)
print(("PASS " if float(last["mesh_damping_ratio"]) == 0 and e < 1e-8 else "FAIL ")
      + "the grazing curve's end at zeta %s, Omega %.10f: 1/sqrt(2) to %.2g" % (last["mesh_damping_ratio"], om, e))
PY
while read -r verdict msg; do
    [ "$verdict" = PASS ]; ok $? "$msg"
done < "$work/z0-checks.txt"

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
# a row that is not a bifurcation of this case with a curve: refused before any work
refuse continuation.curve_start="$out/bifurcations.csv" "continuation.curve_start_row: 9, but .*bifurcations.csv has 4 rows \(valid: 1 to 4\)" continuation.curve_start_row=9
refuse continuation.curve_start="$work/cusp/bifurcations.csv" "continuation.curve_start: the continuation in .*cusp is of another model: excitation.ste_amplitude_um = 0.2 there, 1 here"
mkdir -p "$work/ns" && cp "$out/summary.json" "$work/ns/" && sed '2s/,contact-change,/,branch-point,/' "$out/bifurcations.csv" > "$work/ns/bifurcations.csv"
refuse continuation.curve_start="$work/ns/bifurcations.csv" "continuation.curve_start_row: row 1 of .*is a branch-point, which has no curve"
refuse continuation.curve_start="$work/no-such/bifurcations.csv" "continuation.curve_start: .*no-such/bifurcations.csv: No such file"
refuse continuation.curve_start="$out/bifurcations.csv" "continuation.curve_start: given without continuation.parameter2" continuation.parameter2=
# continuation.curve_kinds: the kinds named are followed, the others not; the curves followed are the
# same curves as in the run of every kind (first and last points to 1e-12)
"$G" run "$KS" --out "$work/kinds" --quiet --set output.plots=off --set "continuation.curve_kinds=grazing, fold" \
    > "$work/kinds.txt" 2>&1
ok $? "curve_kinds = grazing, fold runs ($(head -c 300 "$work/kinds.txt"))"
python3 - "$out" "$work/kinds" > "$work/kinds-checks.txt" <<'PY'
import json, sys
full, part = (json.load(open(d + "/summary.json"))["results"]["curves"] for d in sys.argv[1:3])
print(("PASS " if sorted(c["kind"] for c in part) == ["fold"] * 4 + ["grazing"] * 2 else "FAIL ")
      + "curve_kinds = grazing, fold: the four fold and two grazing curves only (%s)" % [c["kind"] for c in part])
same = [c for c in full if c["kind"] in ("fold", "grazing")]
d = max(abs(a[k][i] - b[k][i]) / max(1.0, abs(a[k][i])) for a, b in zip(same, part) for k in ("first", "last")
        for i in (0, 1)) if len(same) == len(part) else float("inf")
print(("PASS " if d < 1e-12 else "FAIL ") + "and they are the run's own curves: first and last points to %.2g" % d)
PY
while read -r verdict msg; do
    [ "$verdict" = PASS ]; ok $? "$msg"
done < "$work/kinds-checks.txt"
refuse continuation.curve_kinds=cusp "continuation.curve_kinds: 'cusp' is not a kind of curve, or is named twice \(valid: a comma-separated list of fold, period-doubling, neimark-sacker, grazing, each once\)"
refuse "continuation.curve_kinds=fold, fold" "continuation.curve_kinds: 'fold' is not a kind of curve, or is named twice"
refuse "continuation.curve_kinds=," "continuation.curve_kinds: ',' names no kind"
refuse continuation.curve_kinds=fold "continuation.curve_kinds: given without continuation.parameter2" continuation.parameter2=
refuse continuation.curve_start="$out/bifurcations.csv" "continuation.curve_kinds: 'fold' leaves out the grazing of row 1 of .*bifurcations.csv" continuation.curve_kinds=fold

# the picture's overlays: a regime map of the same plane (a sweep with parameter2, 4 x 3 points both
# ways) under the curves, and an earlier run's curves in the same keys beside them (the cusp case's:
# another range of the same keys) are taken and drawn; a map of another model, curves in other keys,
# a one-parameter run's output, are refused before any work (without parameter2: tests/bad-input/19-continuation-overlays.txt)
"$G" run "$KS" --out "$work/map" --quiet --set output.plots=off --set scene.analysis=sweep \
    --set sweep.parameter=operating.speed_rpm --set sweep.from=1591.5494309189 --set sweep.to=4774.6482927569 \
    --set sweep.points=4 --set sweep.parameter2=excitation.ste_amplitude_um --set sweep.from2=0.5 --set sweep.to2=2 \
    --set sweep.points2=3 --set sweep.direction=both --set run.lyapunov_exponents=0 > "$work/map.txt" 2>&1
ok $? "a regime map of the plane runs ($(head -c 300 "$work/map.txt"))"
"$G" run "$KS" --out "$work/over" --quiet --set output.plots=on --set continuation.overlay_map="$work/map" \
    --set continuation.overlay_curves="$work/cusp" > "$work/over.txt" 2>&1
ok $? "the curves over the map and beside the cusp case's curves run ($(head -c 300 "$work/over.txt"))"
if command -v gnuplot > /dev/null; then
    [ -s "$work/over/curves.png" ] && grep -q "over the regime map map" "$work/over/curves.svg" &&
        grep -q "thin grey: the curves of cusp" "$work/over/curves.svg"
    ok $? "curves.png drawn over the map, the cusp case's curves named in its key"
fi
refuse continuation.overlay_map="$work/map" "continuation.overlay_map: the sweep in .*map is of another model: damping.mesh_damping_ratio = 0.05 there, 0.07 here \(valid: a sweep of this case, which may differ in operating.speed_rpm and excitation.ste_amplitude_um only\)" damping.mesh_damping_ratio=0.07
refuse continuation.overlay_map="$work/one-1.01" "continuation.overlay_map: .*one-1.01 holds the output of continuation, not of a sweep"
refuse continuation.overlay_curves="$work/mf" "continuation.overlay_curves: the continuation in .*mf followed curves in operating.speed_rpm and operating.torque_nm \(valid: curves in continuation.parameter = operating.speed_rpm and parameter2 = excitation.ste_amplitude_um\)"
refuse continuation.overlay_curves="$work/one-1.01" "continuation.overlay_curves: the continuation in .*one-1.01 followed no curves"
echo "1..$n"
[ $bad -eq 0 ]
