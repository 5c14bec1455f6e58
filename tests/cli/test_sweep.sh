#!/usr/bin/env bash
# analysis = sweep on the command line (Kahraman & Singh oscillator, torsional model, a few
# seconds): the stable columns of sweep.csv and bifurcation.csv, the same files with 1 and 2
# threads, kill -9 mid-sweep then --resume and SIGINT / SIGTERM then --resume give the files
# of an uninterrupted sweep and lose no finished point, pictures, and bad [sweep] input
# (exit 2, one file:line message, nothing written). TAP output.
set -u
set -m # background jobs keep SIGINT (job control puts them in their own process group)
G=${GEARDYN:?}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=0; bad=0
ok() { # status message (one line: TAP)
    local m=${2//$'\n'/ | }
    n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $m"; else echo "not ok $n - $m"; bad=$((bad + 1)); fi
}

# 160 points per direction: a sweep of more than a second with 2 threads, so that the kill tests
# below stop it mid-way (with 80, a sweep on SUNDIALS 7.5 could end before the poll saw its records)
POINTS=160
REC=30
ks_case() { # the oscillator, Omega from 0.5 to 1.5 (jump between about 0.68 and 0.78)
    sed -e "s/^record_periods = .*/record_periods = $REC/" -e "s/^plots = .*/plots = off/" \
        -e "s/^points = .*/points = $POINTS/" "${GEARDYN_SOURCE:?}/tests/cli/ks-sweep.ini"
}
case="$work/ks.ini"
ks_case > "$case"
files=(sweep.csv bifurcation.csv states.csv summary.json)
same_files() { # dir dir
    local f
    for f in "${files[@]}"; do cmp -s "$1/$f" "$2/$f" || return 1; done
}
journal_lines() { # complete records in a journal (a torn last line does not count)
    python3 - "$1" <<'PY'
import sys
data = open(sys.argv[1], "rb").read()
print(sum(1 for l in data.split(b"\n")[:-1] if l.startswith(b"P ")))
PY
}
wait_lines() { # journal, count, pid: wait until the journal has count records (at most 60 s)
    # polled with grep, not journal_lines: a python start per poll let a short sweep finish
    # unseen (a record being written may count here; the tests count with journal_lines)
    local i
    for i in $(seq 1 6000); do
        [ -f "$1" ] && [ "$(grep -c '^P ' "$1")" -ge "$2" ] && return 0
        kill -0 "$3" 2>/dev/null || return 1
        sleep 0.01
    done
    return 1
}

ref="$work/ref"
"$G" run "$case" --out "$ref" --quiet --threads 1 > "$work/ref.txt" 2>&1; ok $? "sweep exits 0 ($(head -c 300 "$work/ref.txt"))"
head -1 "$ref/sweep.csv" | grep -q "^parameter,direction,rms_accel_mps2,mle,motion,impact_regime"
ok $? "sweep.csv has the stable columns ($(head -1 "$ref/sweep.csv"))"
[ "$(head -1 "$ref/bifurcation.csv")" = "parameter,direction,lambda_L" ]  # the torsional model: one mesh
ok $? "bifurcation.csv has the stable columns ($(head -1 "$ref/bifurcation.csv"))"
rows=$(($(wc -l < "$ref/sweep.csv") - 1)); [ "$rows" -eq $((2 * POINTS)) ]; ok $? "sweep.csv: one row per point and direction ($rows)"
brows=$(($(wc -l < "$ref/bifurcation.csv") - 1)); [ "$brows" -eq $((2 * POINTS * (REC + 1))) ]
ok $? "bifurcation.csv: record_periods + 1 Poincare samples per point ($brows)"
[ -z "$(ls -A "$ref" | grep -v -e '^sweep.csv$' -e '^bifurcation.csv$' -e '^states.csv$' -e '^summary.json$')" ]
ok $? "only the final files are left (no journal, no temporary files): $(ls -A "$ref" | tr '\n' ' ')"
python3 - "$ref" $((2 * POINTS)) <<'PY'
import csv, json, sys
d = sys.argv[1]
s = json.load(open(d + "/summary.json"))
assert s["analysis"] == "sweep"
assert s["sweep"]["parameter"]["name"] == "operating.speed_rpm" and s["sweep"]["parameter"]["unit"] == "rpm"
assert s["results"]["points_done"] == int(sys.argv[2]) and s["results"]["points_failed"] == 0
rows = list(csv.DictReader(open(d + "/sweep.csv")))
assert {r["direction"] for r in rows} == {"up", "down"}
for r in rows:
    assert r["motion"] == "quasi-periodic" or r["motion"] == "chaotic" or r["motion"].startswith("period-") or r["motion"] == "not-periodic", r
    assert r["impact_regime"] in ("no-impact", "single-sided", "double-sided"), r
    float(r["rms_accel_mps2"]); float(r["mle"])
# the jump: somewhere between Omega 0.68 and 0.78 (2160 and 2480 rpm) the branches differ
hy = s["results"]["hysteresis"]
assert any(h["from"] < 2480 and h["to"] > 2160 for h in hy), hy
up = {r["parameter"]: r for r in rows if r["direction"] == "up"}
dn = {r["parameter"]: r for r in rows if r["direction"] == "down"}
assert any(up[k]["impact_regime"] == "no-impact" and dn[k]["impact_regime"] == "single-sided" for k in up)
PY
ok $? "summary.json: stable keys, both branches, the hysteresis of the jump"

# 1 and 2 threads
"$G" run "$case" --out "$work/t2" --quiet --threads 2 > /dev/null 2>&1; ok $? "sweep with 2 threads exits 0"
same_files "$ref" "$work/t2"; ok $? "1 and 2 threads give identical files"
"$G" run "$case" --out "$work/ind1" --quiet --threads 1 --set sweep.mode=independent --set sweep.points=12 >/dev/null 2>&1 &&
"$G" run "$case" --out "$work/ind2" --quiet --threads 2 --set sweep.mode=independent --set sweep.points=12 >/dev/null 2>&1
ok $? "independent sweeps with 1 and 2 threads exit 0"
same_files "$work/ind1" "$work/ind2"; ok $? "independent points: 1 and 2 threads give identical files"
cut -d, -f2 "$work/ind1/sweep.csv" | tail -n +2 | sort -u | grep -qx independent; ok $? "independent points are marked 'independent'"

# the summary lines: the largest RMS acceleration and dynamic load factor, each with its branch, and
# whether it lies on an end of the range; the same in summary.json; the factor in sweep.csv per mesh
for range in "1591.5 4774.6" "1591.5 2300"; do
    set -- $range
    "$G" run "$case" --out "$work/sum-$1-$2" --threads 2 --set sweep.points=12 --set sweep.to=$2 > "$work/sum.txt" 2> /dev/null
    python3 - "$work/sum-$1-$2" "$work/sum.txt" <<'PY'
import csv, json, re, sys
d, out = sys.argv[1], open(sys.argv[2]).read()
s = json.load(open(d + "/summary.json"))["results"]
rows = [r for r in csv.DictReader(open(d + "/sweep.csv")) if r["status"] == "done"]
values = sorted(float(r["parameter"]) for r in rows)
for key, col, label in (("rms_accel_mps2", "rms_accel_mps2", "largest RMS mesh acceleration"),
                        ("dynamic_load_factor", "dynamic_load_factor", "largest dynamic load factor")):
    best = max(rows, key=lambda r: float(r[col]))
    e = s[key]
    assert abs(e["max"] - float(best[col])) <= 1e-8 * e["max"] and e["max_direction"] == best["direction"], (e, best)
    line = [l for l in out.splitlines() if l.strip().startswith(label)][0]
    assert "(%s branch)" % best["direction"] in line, line
    at_end = float(best["parameter"]) in (values[0], values[-1])
    assert ("an end of the swept range" in line) == at_end, (line, at_end)
    print("# " + line.strip())
for r in rows:  # the Kahraman & Singh oscillator has one mesh: no right mesh's column
    assert "dynamic_load_factor_R" not in r and float(r["dynamic_load_factor"]) == float(r["dynamic_load_factor_L"]) >= 0
PY
    ok $? "summary lines name the branch and the end of the range ($1 to $2 rpm): $(grep largest "$work/sum.txt" | tr '\n' ' ')"
done

# kill -9 mid-sweep, a torn line, --resume
k="$work/kill"
"$G" run "$case" --out "$k" --quiet --threads 2 > /dev/null 2>&1 &
pid=$!
wait_lines "$k/.sweep.journal" 8 $pid; started=$?
kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null; rc=$?
[ $started -eq 0 ] && [ $rc -eq 137 ]; ok $? "sweep killed with SIGKILL mid-way (exit $rc)"
[ ! -e "$k/sweep.csv" ]; ok $? "nothing but the journal is written before the end"
done_before=$(journal_lines "$k/.sweep.journal")
printf 'P 7 0 7 0 1 period-1 1 1 0 1 1 152.0' >> "$k/.sweep.journal" # a record torn by the kill
"$G" run "$case" --out "$k" --resume --threads 2 > "$work/resume.txt" 2>&1; ok $? "--resume exits 0 ($(head -c 300 "$work/resume.txt"))"
grep -q "resuming: $done_before of $((2 * POINTS)) points already done (a torn or unusable journal line was dropped)" "$work/resume.txt"
ok $? "--resume keeps every finished point ($done_before) and drops the torn line: $(grep resuming "$work/resume.txt")"
same_files "$ref" "$k"; ok $? "killed and resumed: files identical to the uninterrupted sweep"
[ ! -e "$k/.sweep.journal" ]; ok $? "the journal is removed at the end"

# SIGINT: finish nothing more, a consistent journal, exit 130, then --resume
for sig in INT TERM; do
    i="$work/sig$sig"
    "$G" run "$case" --out "$i" --quiet --threads 2 > "$work/sig.txt" 2>&1 &
    pid=$!
    wait_lines "$i/.sweep.journal" 6 $pid; started=$?
    kill -$sig $pid 2>/dev/null; wait $pid; rc=$?
    want=$([ $sig = INT ] && echo 130 || echo 143)
    [ $started -eq 0 ] && [ $rc -eq "$want" ]; ok $? "SIG$sig stops the sweep with exit $want (got $rc)"
    grep -q "interrupted (SIG$sig).*--resume" "$work/sig.txt"; ok $? "SIG$sig: the message says to use --resume ($(cat "$work/sig.txt"))"
    [ "$(tail -c 1 "$i/.sweep.journal" | od -An -c | tr -d ' ')" = '\n' ]; ok $? "SIG$sig: the journal ends with a whole record"
    kept=$(journal_lines "$i/.sweep.journal")
    "$G" run "$case" --out "$i" --resume --threads 1 > "$work/resume.txt" 2>&1; ok $? "SIG$sig: --resume exits 0"
    grep -q "resuming: $kept of " "$work/resume.txt"; ok $? "SIG$sig: --resume starts from the $kept journaled points"
    same_files "$ref" "$i"; ok $? "SIG$sig: resumed files identical to the uninterrupted sweep"
done

# --resume of another sweep's journal is refused; without --resume a new sweep starts over
o="$work/other"
"$G" run "$case" --out "$o" --quiet --set sweep.points=6 > /dev/null 2>&1 &
pid=$!; wait_lines "$o/.sweep.journal" 1 $pid; kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
if [ -e "$o/.sweep.journal" ]; then
    "$G" run "$case" --out "$o" --quiet --set sweep.points=7 --resume > /dev/null 2> "$work/other.txt"; rc=$?
    [ $rc -eq 2 ] && grep -q "written for another sweep" "$work/other.txt"; ok $? "--resume refuses another sweep's journal (exit $rc: $(cat "$work/other.txt"))"
else
    ok 0 "--resume refuses another sweep's journal (skipped: the small sweep finished first)"
fi

# pictures (when gnuplot is installed)
if command -v gnuplot > /dev/null; then
    p="$work/pic"
    "$G" run "$case" --out "$p" --quiet --set output.plots=on --set sweep.points=6 --set run.transient_periods=20 > /dev/null 2>&1
    [ -s "$p/bifurcation.png" ] && [ -s "$p/bifurcation.svg" ] && grep -q '"bifurcation.png"' "$p/summary.json"
    ok $? "bifurcation diagram drawn (PNG, SVG) and listed"
    m="$work/map"
    "$G" run "$case" --out "$m" --quiet --set output.plots=on --set sweep.points=4 --set run.transient_periods=20 \
        --set sweep.parameter2=clearance.backlash_um --set sweep.from2=10 --set sweep.to2=30 --set sweep.points2=3 > "$work/map.txt" 2>&1
    [ -s "$m/regime_map.png" ] && [ -s "$m/regime_map.svg" ] && [ $(($(wc -l < "$m/sweep.csv") - 1)) -eq 24 ] &&
        head -1 "$m/sweep.csv" | grep -q "^parameter,direction,rms_accel_mps2,mle,motion,impact_regime,parameter2"
    ok $? "two-parameter sweep: 24 points, parameter2 column, regime map drawn ($(head -c 200 "$work/map.txt"))"
else
    ok 0 "pictures (skipped: gnuplot not installed)"
fi

# bad [sweep] input: exit 2, one message naming file:line, nothing written; the case without its
# [sweep] gives the speed that the sweep gave (a sweep of another key needs it)
ks_base() { ks_case | sed '/^\[sweep\]/,$d'; printf '[operating]\nspeed_rpm = 3000\n'; }
check_bad() { # sweep-section-lines expected-regex name
    local f="$work/bad.ini" out="$work/bad-$n"
    ks_base > "$f"
    printf '[sweep]\n%s\n' "$1" >> "$f"
    "$G" run "$f" --out "$out" --quiet > "$work/stdout" 2> "$work/stderr"
    local rc=$? msg; msg=$(cat "$work/stderr")
    [ $rc -eq 2 ]; ok $? "$3: exit status 2 (got $rc)"
    echo "$msg" | grep -Eq -- "$2"; ok $? "$3: message matches /$2/ (got: $msg)"
    [ "$(echo "$msg" | wc -l)" -eq 1 ] && [ ! -e "$out" ]; ok $? "$3: one line, nothing written"
}
L=$(($(ks_base | wc -l) + 1)) # line of [sweep]
check_bad "parameter = operating.speed_rmp
from = 100
to = 200" "bad.ini:$((L + 1)): sweep.parameter: 'operating.speed_rmp' is not a numeric case key: .*did you mean operating.speed_rpm" "unknown swept key"
check_bad "parameter = operating.speed_rpm
from = 100
to = 200000" "bad.ini:$((L + 3)): sweep.to: operating.speed_rpm = 200000 is out of range \(valid: a number in \(0, 100000\] rpm\)" "value out of range"
check_bad "parameter = clearance.backlash_um
from = 0
to = 50
spacing = log" "bad.ini:$((L + 4)): sweep.spacing: log spacing from 0 to 50 \(valid: positive" "log spacing through zero"
check_bad "parameter = operating.speed_rpm
to = 2000" "bad.ini:$((L + 1)): sweep.from: missing \(valid: the first value of operating.speed_rpm, a number in \(0, 100000\] rpm\)" "missing from"
check_bad "parameter = scene.model
from = 1
to = 2" "bad.ini:$((L + 1)): sweep.parameter: 'scene.model' is not a numeric case key" "enumerated key"
check_bad "parameter = operating.speed_rpm
from = 1000
to = 2000
mode = sideways" "bad.ini:$((L + 4)): sweep.mode: unknown choice 'sideways' \(valid: one of continuation,independent\)" "bad mode"
check_bad "parameter = operating.speed_rpm
from = 1000
to = 2000
from2 = 3" "bad.ini:$((L + 4)): sweep.from2: given without sweep.parameter2" "from2 without parameter2"
check_bad "parameter = operating.speed_rpm
from = 1000
to = 2000
response = lambda_L, x1L" "bad.ini:$((L + 4)): sweep.response: unknown response 'x1L'" "unknown response"
"$G" run "$case" --out "$work/thr" --threads 0 > /dev/null 2> "$work/stderr"; rc=$?
[ $rc -eq 2 ] && grep -q -- "--threads needs a whole number" "$work/stderr"; ok $? "--threads 0 refused with exit 2"

echo "1..$n"
[ $bad -eq 0 ]
