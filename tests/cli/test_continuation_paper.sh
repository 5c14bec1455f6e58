#!/usr/bin/env bash
# The paper's speed sweep against its continuation (docs/continuation.md, docs/paper-reproduction.md):
# a coarse brute-force sweep of cases/paper/sweep-speed.ini from 3000 to 5500 rpm (11 speeds, up and
# down) and cases/continuation/paper-speed.ini (the period-1 orbit followed over the same range, the
# sweep drawn over it).
# 1. Every grid interval where a direction of the sweep jumps onto or off the period-1 orbit, and
#    every hysteresis interval (up and down differ), contains a bifurcation of the period-1 branch
#    located by continuation (fold, grazing, period doubling or Neimark-Sacker).
# 2. Every change of stability along the branch lies at a located fold, period doubling or
#    Neimark-Sacker point; where the sweep is period-1 the branch is stable there (its points either side are stable).
# 3. At those speeds the branch's orbit (Newton from the branch's state interpolated to the speed,
#    start = state) has the sweep's RMS mesh acceleration to 1e-6 relative.
# TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok
PS="$SRC/cases/continuation/paper-speed.ini"

"$G" run "$SRC/cases/paper/sweep-speed.ini" --out "$work/sweep" --quiet --set sweep.from=3000 --set sweep.to=5500 \
    --set sweep.points=11 --set run.lyapunov_exponents=0 --set output.plots=off > "$work/sweep.txt" 2>&1
ok $? "the coarse sweep runs ($(head -c 300 "$work/sweep.txt"))"
"$G" run "$PS" --out "$work/cont" --quiet --set continuation.overlay_sweep="$work/sweep" > "$work/cont.txt" 2>&1
ok $? "the continuation runs with the sweep as overlay ($(head -c 300 "$work/cont.txt"))"

# 1 and 2; the speeds of check 3 with the branch state interpolated there
python3 - "$work" > "$work/checks.txt" <<'PY'
import csv, sys
w = sys.argv[1]
sw = list(csv.DictReader(open(w + "/sweep/sweep.csv")))
br = [r for r in csv.DictReader(open(w + "/cont/branch.csv")) if r["branch"] == "0"]
bf = [r for r in csv.DictReader(open(w + "/cont/bifurcations.csv")) if r["branch"] == "0"]
names = list(br[0].keys())[list(br[0].keys()).index("ds") + 1:]
def ok(c, msg):
    print(("PASS " if c else "FAIL ") + msg)
up = {float(r["parameter"]): r for r in sw if r["direction"] == "up"}
dn = {float(r["parameter"]): r for r in sw if r["direction"] == "down"}
v = sorted(up)
bif = [(float(b["speed_rpm"]), b["kind"]) for b in bf]
def inside(a, b):
    return [k + " %.2f" % p for p, k in bif if a <= p <= b]
p1 = lambda r: r["period_n"] == "1"
intervals = []
for d, s in (("up", up), ("down", dn)):
    for a, b in zip(v, v[1:]):
        if p1(s[a]) != p1(s[b]):
            intervals.append(("%s sweep on/off the period-1 orbit" % d, a, b))
for i, x in enumerate(v):
    same = up[x]["motion"] == dn[x]["motion"] and \
        abs(float(up[x]["rms_accel_mps2"]) - float(dn[x]["rms_accel_mps2"])) <= 1e-3 * float(up[x]["rms_accel_mps2"])
    if not same and p1(up[x]) != p1(dn[x]):
        intervals.append(("hysteresis at %g" % x, v[max(i - 1, 0)], v[min(i + 1, len(v) - 1)]))
ok(len(intervals) >= 2, "the sweep jumps on or off the period-1 orbit at least twice (%d)" % len(intervals))
for what, a, b in intervals:
    f = inside(a, b)
    ok(len(f) > 0, "%s, %g .. %g rpm: contains %s" % (what, a, b, ", ".join(f) or "no bifurcation"))
# every change of stability along the branch lies at a located fold, period doubling or Neimark-Sacker point
changes, missed = 0, []
for a, b in zip(br, br[1:]):
    if a["stable"] != b["stable"]:
        changes += 1
        pa, pb = sorted((float(a["speed_rpm"]), float(b["speed_rpm"])))
        if not [k for p, k in bif if pa <= p <= pb and k in ("fold", "period-doubling", "neimark-sacker")]:
            missed.append("%.2f .. %.2f" % (pa, pb))
ok(changes >= 3 and not missed, "each of the %d changes of stability along the branch brackets a located fold, period "
   "doubling or Neimark-Sacker point (missed: %s)" % (changes, ", ".join(missed) or "none"))
sp = [(float(r["speed_rpm"]), r) for r in br]
sp.sort(key=lambda t: t[0])
checks = []
for x in v:
    if not (p1(up[x]) and p1(dn[x])):
        continue
    lo = max([t for t in sp if t[0] <= x], key=lambda t: t[0], default=None)
    hi = min([t for t in sp if t[0] >= x], key=lambda t: t[0], default=None)
    stable = lo is not None and hi is not None and lo[1]["stable"] == "1" and hi[1]["stable"] == "1"
    ok(stable, "the sweep is period-1 at %g rpm, the branch stable there (%s)" % (x, "yes" if stable else "no"))
    if stable:
        f = 0.0 if hi[0] == lo[0] else (x - lo[0]) / (hi[0] - lo[0])
        y = [float(lo[1][k]) + f * (float(hi[1][k]) - float(lo[1][k])) for k in names]
        checks.append("%.10g %s %s" % (x, up[x]["rms_accel_mps2"], ",".join("%.17g" % q for q in y)))
open(w + "/points.txt", "w").write("\n".join(checks) + "\n")
PY
ok $? "the tables read"
while IFS= read -r line; do
    case "$line" in
        PASS\ *) ok 0 "${line#PASS }" ;;
        *) ok 1 "${line#FAIL }" ;;
    esac
done < "$work/checks.txt"

# 3. the orbit at each speed from the branch state, against the sweep's RMS
count=0
while read -r speed rms state; do
    [ -n "$speed" ] || continue
    o="$work/at-$speed"
    "$G" run "$PS" --out "$o" --quiet --set continuation.start=state --set continuation.state="$state" \
        --set continuation.start_value="$speed" --set continuation.max_points=2 --set output.plots=off \
        > "$work/at.txt" 2>&1
    rc=$?
    python3 -c "
import csv, sys
p0 = next(csv.DictReader(open('$o/branch.csv')))
s, r = float(p0['speed_rpm']), float(p0['rms_accel_mps2']); rms = $rms
d = abs(r - rms) / rms
print('%.4g rpm: RMS %.9g by shooting, %.9g by the sweep, relative difference %.2g' % (s, r, rms, d))
sys.exit(0 if abs(s - $speed) < 1e-6 and d < 1e-6 else 1)" > "$work/cmp.txt" 2>&1
    ok $(( rc | $? )) "$(cat "$work/cmp.txt")"
    count=$((count + 1))
done < "$work/points.txt"
[ $count -ge 3 ]; ok $? "at least 3 speeds compared ($count)"
echo "1..$n"
[ $bad -eq 0 ]
