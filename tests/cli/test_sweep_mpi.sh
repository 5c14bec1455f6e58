#!/usr/bin/env bash
# MPI (builds with -Dmpi=enabled): `mpirun -n 2 geardyn run sweep.ini` writes the same files as
# a serial run: continuation (the up and down chains on two ranks), independent points (spread
# over the ranks), a regime map (rows over ranks, two threads each); a serial sweep killed
# half way is finished by two ranks with --resume. TAP output.
set -u
G=${GEARDYN:?}
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
# containers: no ssh launcher, no cross-memory attach
export OMPI_MCA_plm=isolated OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_rmaps_base_oversubscribe=1

sed -e "s/^record_periods = .*/record_periods = 20/" -e "s/^plots = .*/plots = off/" -e "s/^points = .*/points = 40/" \
    "${GEARDYN_SOURCE:?}/tests/cli/ks-sweep.ini" > "$work/ks.ini"
files=(sweep.csv bifurcation.csv states.csv summary.json)
same_files() {
    local f
    for f in "${files[@]}"; do cmp -s "$1/$f" "$2/$f" || return 1; done
}

run_pair() { # name, extra arguments...
    local name=$1; shift
    "$G" run "$work/ks.ini" --out "$work/$name-serial" --quiet "$@" > "$work/serial.txt" 2>&1
    ok $? "$name: serial run exits 0"
    timeout 300 "${MPI[@]}" "$G" run "$work/ks.ini" --out "$work/$name-mpi" --quiet "$@" > "$work/mpi.txt" 2>&1
    ok $? "$name: mpirun -n 2 exits 0 ($(head -c 400 "$work/mpi.txt"))"
    same_files "$work/$name-serial" "$work/$name-mpi"; ok $? "$name: 2 ranks give the files of the serial run"
    [ ! -e "$work/$name-mpi/.sweep.journal" ]; ok $? "$name: no journal left"
}
run_pair continuation --threads 1
run_pair independent --set sweep.mode=independent --set sweep.points=16
run_pair map --threads 2 --set sweep.points=8 --set sweep.parameter2=clearance.backlash_um --set sweep.from2=10 \
    --set sweep.to2=30 --set sweep.points2=3

# a serial sweep killed half way, finished by two ranks
k="$work/kill"
"$G" run "$work/ks.ini" --out "$k" --quiet --threads 1 > /dev/null 2>&1 &
pid=$!
for i in $(seq 1 3000); do
    [ -f "$k/.sweep.journal" ] && [ "$(grep -c '^P ' "$k/.sweep.journal")" -ge 6 ] && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.02
done
kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null; rc=$?
[ $rc -eq 137 ]; ok $? "serial sweep killed mid-way (exit $rc)"
timeout 300 "${MPI[@]}" "$G" run "$work/ks.ini" --out "$k" --resume --threads 1 > "$work/resume.txt" 2>&1
ok $? "mpirun -n 2 --resume exits 0 ($(head -c 300 "$work/resume.txt"))"
grep -q "resuming: [1-9][0-9]* of 80 points already done" "$work/resume.txt"; ok $? "the ranks resume from the journal"
same_files "$work/continuation-serial" "$k"; ok $? "killed serial, resumed on 2 ranks: files identical to the serial run"

echo "1..$n"
[ $bad -eq 0 ]
