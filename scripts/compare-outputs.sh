#!/usr/bin/env bash
# Run every shipped case (cases/**/*.ini) with two geardyn binaries and compare the outputs,
# to prove that a change of the source tree did not change behaviour.
#
#   bash scripts/compare-outputs.sh OLD_BINARY NEW_BINARY [WORKDIR]
#
# Each binary runs in its own directory WORKDIR/old, WORKDIR/new (default WORKDIR: a new
# directory under /tmp), which holds a symlink `cases` to the repository's cases/, as
# `geardyn run cases/X.ini --out out/X --quiet --threads T` plus the case's shortening below.
# Both runs therefore see the same relative paths, which geardyn writes into summary.json
# (case.path); gnuplot runs in the run's stage and names each plotted data file by its bare name
# in the SVGs (<title> of the data set).
#
# Compared, for every file the runs leave (hidden files included):
#   * exit status, stdout and stderr of the two runs (a failure must be the same failure);
#   * *.json: parsed with every number kept as its literal text and the key order kept, then
#     equal after deleting, at any depth, the keys in JSON_SKIP (times and the version);
#   * *.csv: byte for byte, except a CSV whose header holds a column of CSV_SKIP (CPU and
#     wall times: work-precision and optimiser outputs): parsed, those columns dropped, the
#     remaining cells compared as text;
#   * .sweep.journal (present only after an interrupted sweep): line by line with the version
#     and CRC of the header and the wall_s field and CRC of each point record masked;
#   * everything else (PNG, SVG, ...): byte for byte. gnuplot embeds no date, version of
#     geardyn or path (data files by their bare names), so the pictures are reproducible,
#     except PIC_SKIP: work_precision.png/.svg plot the errors against the measured CPU time.
#
# WORKDIR/hashes.txt lists a SHA-256 prefix of every old output (to compare two runs by hand).
# Environment: THREADS (default 1) is passed as --threads to both binaries; PARALLEL=1 (the
# default) runs the old and the new binary of a case side by side (2 cores), 0 one after the
# other. Prints one line per case, the total time and "N same, M differ"; the exit status is 0
# only when every case compares equal.
set -u -o pipefail

# ---- per-case shortening: case path glob -> extra --set section.key=value (first match wins;
#      the same for both binaries). Cases without an entry run as shipped.
SHORTEN=(
  # work-precision scenes (52 s each as shipped): three families (two for the implicit scene
  # plus a DIRK), rtol 1e-3..1e-6, RK4 and the order study to 64 steps/period, one repeat,
  # a short transient and window.
  'cases/accuracy/stiff-supports.ini'
  'workprecision.families=rk4,erk4,dirk3 workprecision.rtol_tightest=1e-6 workprecision.rk4_steps_max=64 workprecision.order_steps_max=64 workprecision.repeats=1 workprecision.horizon_periods=5 run.transient_periods=100 run.record_periods=10'
  'cases/accuracy/*.ini'
  'workprecision.families=rk4,erk4,erk8 workprecision.rtol_tightest=1e-6 workprecision.rk4_steps_max=64 workprecision.order_steps_max=64 workprecision.repeats=1 workprecision.horizon_periods=5 run.transient_periods=100 run.record_periods=10'
  # sweeps (25 points up and down, 300+100 periods): 4 points up and down, 100 (extended up to
  # 300 while the section converges) + 20 periods.
  'cases/paper/sweep-*.ini'
  'sweep.points=4 run.transient_periods=100 run.transient_max_periods=300 run.record_periods=20'
  # local analyses (1500..3000 + 200 periods, about 3 s each): 300..600 + 100 periods.
  'cases/paper/local-*.ini'
  'run.transient_periods=300 run.transient_max_periods=600 run.record_periods=100'
  # ALO (100 iterations x 30 ants of LTCA): 3 iterations x 10 ants, coarse LTCA grid.
  'cases/paper/optimize-alo.ini'
  'optimize.iterations=3 optimize.population=10 solver.ltca_positions_per_cycle=8 solver.ltca_face_slices=7'
  # ALO on the dynamic objective (30 iterations x 20 ants, each three LTCAs and continuations over
  # 3000-5500 rpm): 2 iterations x 4 ants.
  'cases/paper/optimize-dynamic.ini'
  'optimize.iterations=2 optimize.population=4'
  # optimiser comparison on the gear (9 optimisers x 10 runs x 400 LTCA): 2 runs x 40, coarse LTCA.
  'cases/paper/compare-optimizers.ini'
  'optimize.runs=2 optimize.budget_evals=40 optimize.population=10 solver.ltca_positions_per_cycle=8 solver.ltca_face_slices=7'
  # two-objective optimisers on the gear (4 optimisers x 5 runs x 120 evaluations of an LTCA and a
  # continuation over 3000-5500 rpm): 2 runs x 8, 2 subproblems, coarse LTCA.
  'cases/paper/compare-two-objectives-gear.ini'
  'optimize.runs=2 optimize.budget_evals=8 optimize.population=4 optimize.scalar_grid=2 solver.ltca_positions_per_cycle=8 solver.ltca_face_slices=7'
  # optimiser comparison on the test functions (5 functions x d = 6, 10; 15 runs x 10000): all
  # five functions at d = 6 only, 2 runs x 500. Its two gnuplot pictures cost about the square
  # of the number of problems (each panel rereads the whole CSV per optimiser): 29 s with 10
  # problems, 6 s with 5.
  'cases/optimize/compare-test-functions.ini'
  'optimize.dimension=6 optimize.runs=2 optimize.budget_evals=500'
  # basins (a 200 x 200 picture and 10 000 states; 13 values of 2 000 states; 100 x 100 of the bta
  # model): a 50 x 50 picture and 1 000 states; 4 values of 300 states; 10 x 10 and 100 states.
  'cases/basins/paper-*.ini'
  'basins.resolution=10 basins.samples=100'
  'cases/basins/*fractions*.ini'
  'basins.points=4 basins.samples=300'
  'cases/basins/*.ini'
  'basins.resolution=50 basins.samples=1000'
  # a continuation drawn over another case's sweep, whose results a fresh tree lacks: without them.
  'cases/guide/*-continuation.ini'
  'continuation.overlay_sweep='
  # the paper's pair's curves in two parameters (10-20 min of CPU in (speed, torque): an LTCA at every
  # new torque): the branch to 3600 rpm and 3 points per curve.
  'cases/continuation/paper-curves-*.ini'
  'continuation.to=3600 continuation.curve_max_points=3'
)

# Allowed to differ. JSON keys (any depth): geardyn_version; wall_s (solver/optimiser/LTCA/TCA/
# work-precision wall times), cpu_s and us_per_period (work-precision cost; cpu_s and cpu_s_in_loop
# also the flanks' CPU an optimisation over load and speed reports after it), wall_mean_s and
# wall_total_s (optimiser comparison), curve_cpu_s (the continuation's curves in two parameters); and `cheapest` of work-precision's cheapest_at_target[],
# the label of the run with the least measured CPU time among those meeting an error target: it
# is chosen by timing and changes between two runs of the same binary (its target, cpu_s and
# us_per_period beside it are skipped anyway; target and event_times_too stay compared).
JSON_SKIP='geardyn_version wall_s cpu_s cpu_s_in_loop us_per_period wall_mean_s wall_total_s cheapest curve_cpu_s'
CSV_SKIP='cpu_s us_per_period wall_s wall_mean_s wall_total_s'
PIC_SKIP='work_precision.png work_precision.svg'

if [ $# -lt 2 ] || [ $# -gt 3 ]; then
  echo "usage: bash scripts/compare-outputs.sh OLD_BINARY NEW_BINARY [WORKDIR]" >&2
  exit 2
fi
absbin() {
  local p
  case "$1" in
    */*) p="$(cd "$(dirname "$1")" 2>/dev/null && pwd)/$(basename "$1")" ;;
    *) p="$(command -v "$1" || true)" ;;
  esac
  if [ -z "$p" ] || [ ! -x "$p" ]; then echo "compare-outputs: not an executable: $1" >&2; exit 2; fi
  printf '%s\n' "$p"
}
OLD="$(absbin "$1")" || exit 2
NEW="$(absbin "$2")" || exit 2
cd "$(dirname "$0")/.." || exit 2
REPO="$(pwd)"
WORK="${3:-$(mktemp -d /tmp/geardyn-compare.XXXXXX)}"
mkdir -p "$WORK" && WORK="$(cd "$WORK" && pwd)" || exit 2
THREADS="${THREADS:-1}"
PARALLEL="${PARALLEL:-1}"
command -v python3 >/dev/null || { echo "compare-outputs: python3 is needed" >&2; exit 2; }

for side in old new; do
  mkdir -p "$WORK/$side/log"
  ln -sfn "$REPO/cases" "$WORK/$side/cases"
done

mapfile -t CASES < <(find cases -name '*.ini' -type f | LC_ALL=C sort)
if [ ${#CASES[@]} -eq 0 ]; then echo "compare-outputs: no cases under $REPO/cases" >&2; exit 2; fi

shortening() {   # the extra --set arguments of case $1, one per line
  local i
  for ((i = 0; i < ${#SHORTEN[@]}; i += 2)); do
    # shellcheck disable=SC2053
    if [[ "$1" == ${SHORTEN[i]} ]]; then
      local kv
      for kv in ${SHORTEN[i + 1]}; do printf -- '--set\n%s\n' "$kv"; done
      return
    fi
  done
}

run_one() {   # side binary case outrel logname extra-args...
  local side="$1" bin="$2" case="$3" out="$4" log="$5"
  shift 5
  rm -rf "${WORK:?}/$side/$out"
  mkdir -p "$WORK/$side/$(dirname "$out")"
  (cd "$WORK/$side" && "$bin" run "$case" "$@" --threads "$THREADS" --out "$out" --quiet \
     >"log/$log.stdout" 2>"log/$log.stderr"; echo $? >"log/$log.rc")
}

read -r -d '' COMPARE_PY <<'PY'
import csv, hashlib, io, json, os, sys

old, new, oldlog, newlog, log = sys.argv[1:6]
json_skip = set(sys.argv[6].split())
csv_skip = set(sys.argv[7].split())
pic_skip = set(sys.argv[8].split())

def listing(root):
    out = set()
    if os.path.isdir(root):
        for d, _, fs in os.walk(root):
            for f in fs:
                out.add(os.path.relpath(os.path.join(d, f), root))
    return out

def read(p):
    with open(p, 'rb') as f:
        return f.read()

def json_norm(b):
    def strip(o):
        if isinstance(o, list) and o and isinstance(o[0], tuple) and o[0][0] == '\0obj':
            return [(k, strip(v)) for k, v in o[1:] if k not in json_skip]
        if isinstance(o, list):
            return [strip(x) for x in o]
        return o
    lit = lambda s: ('\0num', s)
    o = json.loads(b.decode('utf-8'), object_pairs_hook=lambda kv: [('\0obj', None)] + kv,
                   parse_float=lit, parse_int=lit, parse_constant=lit)
    return strip(o)

def csv_norm(b):
    text = b.decode('utf-8')
    first = text.split('\n', 1)[0].rstrip('\r').split(',')
    if not csv_skip.intersection(first):
        return b
    rows = list(csv.reader(io.StringIO(text, newline='')))
    keep = [i for i, h in enumerate(rows[0]) if h not in csv_skip]
    return [[r[i] if i < len(r) else None for i in keep] + ([len(r)] if len(r) != len(rows[0]) else [])
            for r in rows]

def journal_norm(b):
    out = []
    for line in b.decode('utf-8', 'replace').split('\n'):
        t = line.split(' ')
        if t and t[0] == 'GDSWEEP' and len(t) > 2:
            t[2] = '<version>'
        if t and t[0] == 'P' and len(t) > 23:
            t[23] = '<wall_s>'   # gd_sweep_record_format: P slot chain pos branch status motion ... events transient wall_s
        if t and t[-1].startswith('*'):
            t[-1] = '<crc>'
        out.append(t)
    return out

def same(rel, a, b):
    if a == b:
        return True
    name = os.path.basename(rel)
    try:
        if name.endswith('.json'):
            return json_norm(a) == json_norm(b)
        if name.endswith('.csv'):
            return csv_norm(a) == csv_norm(b)
        if name == '.sweep.journal':
            return journal_norm(a) == journal_norm(b)
    except (ValueError, UnicodeDecodeError, IndexError):
        return False
    return False

diff, skipped = [], []
for what in ('rc', 'stdout', 'stderr'):
    if read(os.path.join(oldlog + '.' + what)) != read(os.path.join(newlog + '.' + what)):
        diff.append(what)
lo, ln = listing(old), listing(new)
for rel in sorted(lo | ln):
    if rel not in ln:
        diff.append(rel + ' (missing in new)')
    elif rel not in lo:
        diff.append(rel + ' (only in new)')
    elif os.path.basename(rel) in pic_skip:
        a, b = read(os.path.join(old, rel)), read(os.path.join(new, rel))
        if a != b:
            skipped.append(rel)
    elif not same(rel, read(os.path.join(old, rel)), read(os.path.join(new, rel))):
        diff.append(rel)
with open(log, 'a') as f:
    for rel in sorted(lo | ln):
        p = os.path.join(old, rel) if rel in lo else os.path.join(new, rel)
        f.write('%s %s\n' % (hashlib.sha256(read(p)).hexdigest()[:16], rel))
note = ' (not compared, CPU-time axes: %s)' % ', '.join(skipped) if skipped else ''
rc = read(oldlog + '.rc').decode().strip()
failed = ' [both exit %s]' % rc if rc != '0' and 'rc' not in diff else ''
print(('DIFFERS: ' + ', '.join(diff) if diff else 'same') + failed + note)
sys.exit(1 if diff else 0)
PY

echo "old: $OLD"
echo "new: $NEW"
echo "cases: $REPO/cases (${#CASES[@]}), work: $WORK, --threads $THREADS, parallel $PARALLEL"
: >"$WORK/hashes.txt"
nsame=0
ndiff=0
t_start=$SECONDS
for case in "${CASES[@]}"; do
  rel="${case#cases/}"
  rel="${rel%.ini}"
  out="out/$rel"
  log="${rel//\//__}"
  mapfile -t extra < <(shortening "$case")
  t0=${EPOCHREALTIME/[.,]/}
  if [ "$PARALLEL" = 1 ]; then
    run_one old "$OLD" "$case" "$out" "$log" "${extra[@]}" &
    run_one new "$NEW" "$case" "$out" "$log" "${extra[@]}" &
    wait
  else
    run_one old "$OLD" "$case" "$out" "$log" "${extra[@]}"
    run_one new "$NEW" "$case" "$out" "$log" "${extra[@]}"
  fi
  t1=${EPOCHREALTIME/[.,]/}
  if verdict="$(python3 -c "$COMPARE_PY" "$WORK/old/$out" "$WORK/new/$out" "$WORK/old/log/$log" \
                "$WORK/new/log/$log" "$WORK/hashes.txt" "$JSON_SKIP" "$CSV_SKIP" "$PIC_SKIP")"; then
    nsame=$((nsame + 1))
  else
    ndiff=$((ndiff + 1))
  fi
  dt=$(((t1 - t0) / 100000))
  printf '%-46s %s (%d.%d s)\n' "$case" "$verdict" $((dt / 10)) $((dt % 10))
done
echo "total time: $((SECONDS - t_start)) s"
echo "$nsame same, $ndiff differ"
[ "$ndiff" -eq 0 ]
