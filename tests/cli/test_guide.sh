#!/usr/bin/env bash
# Every command of docs/guide.md runs, and prints what the guide says it prints: each fenced `sh`
# block is run with bash -e in a scratch directory that has the source tree's cases/ and
# `geardyn` on its PATH, and every line of an `output` block that follows it must appear in its
# output (times and thread counts masked; `text` blocks are not compared). The runs are the
# guide's own, not shortened: about 20 s on 2 cores. The `bash` blocks of the guide (installing
# and building) are not run: this test runs on the build they make. A block that calls mpirun is
# skipped when geardyn was built without MPI or mpirun is missing. The Python blocks run as the
# guide says, from a source tree with its build in build/ (PYTHONPATH=build/python): build/ is this
# build, examples/ the source tree's, and python3 the interpreter meson found with numpy
# ($GEARDYN_PYTHON); without one (no numpy, or a build with ASan) they are skipped. TAP output.
set -u
G=${GEARDYN:?}
SRC=${GEARDYN_SOURCE:?}
guide="$SRC/docs/guide.md"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/bin" "$work/blocks"
ln -s "$SRC/cases" "$work/cases"
ln -s "$SRC/examples" "$work/examples"
ln -s "$G" "$work/bin/geardyn"
ln -s "$(cd "$(dirname "$G")/../.." && pwd)" "$work/build"   # G is BUILD/src/cli/geardyn
[ -n "${GEARDYN_PYTHON:-}" ] && ln -s "$GEARDYN_PYTHON" "$work/bin/python3"

# the sh blocks, one file each, and the output block after each (NN.out)
awk -v dir="$work/blocks" '
    /^```sh[[:space:]]*$/ { n++; f = sprintf("%s/%02d.sh", dir, n); inblock = 1; next }
    /^```output[[:space:]]*$/ && n { f = sprintf("%s/%02d.out", dir, n); inblock = 1; next }
    /^```/ && inblock { inblock = 0; close(f); next }
    /^```/ { inother = !inother; next }
    inblock { print > f }
' "$guide"
# times and thread counts vary from run to run
mask() { sed -E 's/[0-9]+(\.[0-9]+)? (s|us)\b/T \2/g; s/[0-9]+ threads?/N threads/g'; }
blocks=("$work"/blocks/*.sh)
[ -e "${blocks[0]}" ] || { echo "1..1"; echo "not ok 1 - no sh block found in docs/guide.md"; exit 0; }
echo "1..$((${#blocks[@]} + 1))"
mpi=0
if "$G" --version | grep -q "MPI on" && command -v mpirun > /dev/null; then mpi=1; fi
# the guide's mpirun as the test machine can run it: as root (containers) and on one node
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_plm=isolated \
    OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_rmaps_base_oversubscribe=1
n=0
for b in "${blocks[@]}"; do
    n=$((n + 1))
    first=$(grep -m1 . "$b")
    if grep -q '^mpirun' "$b" && [ $mpi = 0 ]; then
        echo "ok $n - $first # SKIP geardyn built without MPI or mpirun missing"
        continue
    fi
    if grep -q 'python3' "$b" && [ -z "${GEARDYN_PYTHON:-}" ]; then
        echo "ok $n - $first # SKIP no python3 for the module (no numpy, or a build with ASan)"
        continue
    fi
    if ! (cd "$work" && PATH="$work/bin:$PATH" bash -e -o pipefail "$b") > "$work/out" 2>&1; then
        echo "not ok $n - $first"
        sed 's/^/# /' "$work/out" | tail -20
        continue
    fi
    missing=""
    if [ -f "${b%.sh}.out" ]; then
        mask < "$work/out" > "$work/out.masked"
        while IFS= read -r line; do
            grep -qxF -- "$line" "$work/out.masked" || missing="$missing
# missing: $line"
        done < <(mask < "${b%.sh}.out")
    fi
    if [ -z "$missing" ]; then
        echo "ok $n - $first"
    else
        echo "not ok $n - $first: the output differs from the guide's$missing"
        sed 's/^/# got: /' "$work/out" | head -20
    fi
done
# every case the guide names exists, and every case of cases/guide/ is used by the guide
bad=""
for c in $(grep -o 'cases/guide/[a-z0-9-]*\.ini' "$guide" | sort -u); do [ -f "$SRC/$c" ] || bad="$bad $c"; done
for c in "$SRC"/cases/guide/*.ini; do grep -q "cases/guide/$(basename "$c")" "$guide" || bad="$bad unused:$(basename "$c")"; done
n=$((n + 1))
[ -z "$bad" ] && echo "ok $n - the guide's cases are cases/guide/*.ini, all used" || echo "not ok $n - cases:$bad"
