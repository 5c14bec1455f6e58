#!/usr/bin/env bash
# MPI (builds with -Dmpi=enabled): `mpirun -n 2 geardyn run` of the basins over a parameter spreads
# its values over the ranks (value k on rank k mod 2), rank 0 gathers their points, matches the
# attractors over the values and writes the same files as a serial run (the tables byte for byte,
# summary.json but its times); the basins at one value run on rank 0 alone. TAP output.
set -u
G=${GEARDYN:?}
SRC=${GEARDYN_SOURCE:?}
command -v mpirun > /dev/null || { echo "1..0 # SKIP mpirun not installed"; exit 0; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=0; bad=0
ok() { # status message (one line: TAP)
    local m=${2//$'\n'/ | }
    n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $m"; else echo "not ok $n - $m"; bad=$((bad + 1)); fi
}
MPI=(mpirun --oversubscribe -n 2)
[ "$(id -u)" = 0 ] && MPI+=(--allow-run-as-root)
export OMPI_MCA_plm=isolated OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_rmaps_base_oversubscribe=1

same_summary() { # the two summary.json without their times and threads
    python3 - "$1/summary.json" "$2/summary.json" <<'PY'
import json, sys
def strip(o):
    if isinstance(o, dict):
        return {k: strip(v) for k, v in o.items() if k not in ("cpu_s", "wall_s", "threads", "geardyn_version")}
    if isinstance(o, list):
        return [strip(v) for v in o]
    return o
a, b = (strip(json.load(open(p))) for p in sys.argv[1:3])
sys.exit(0 if a == b else 1)
PY
}

run_pair() { # name, case, extra arguments...
    local name=$1 case=$2; shift 2
    "$G" run "$case" --out "$work/$name-serial" --quiet --threads 1 "$@" > "$work/serial.txt" 2>&1
    ok $? "$name: serial run exits 0 ($(head -c 300 "$work/serial.txt"))"
    timeout 600 "${MPI[@]}" "$G" run "$case" --out "$work/$name-mpi" --quiet --threads 1 "$@" > "$work/mpi.txt" 2>&1
    ok $? "$name: mpirun -n 2 exits 0 ($(head -c 400 "$work/mpi.txt"))"
    local f
    for f in $(cd "$work/$name-serial" && ls *.csv); do
        cmp -s "$work/$name-serial/$f" "$work/$name-mpi/$f"; ok $? "$name: $f the same on 2 ranks as serially"
    done
    same_summary "$work/$name-serial" "$work/$name-mpi"; ok $? "$name: summary.json the same but its times"
}
run_pair fractions "$SRC/cases/basins/ks-fractions.ini" --set basins.points=5 --set basins.samples=300 \
    --set output.plots=off
run_pair picture "$SRC/cases/basins/ks-hysteresis.ini" --set basins.resolution=30 --set basins.samples=200 \
    --set output.plots=off
echo "1..$n"
[ $bad -eq 0 ]
