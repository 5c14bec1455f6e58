#!/usr/bin/env bash
# Install what is missing, build geardyn with Open MPI and -Werror and run the whole suite there
# (its MPI tests run 2 ranks; the guide runs its MPI block), check that every exported symbol has
# the gd_ prefix, build the command line once more against Debian's SUNDIALS package and check that
# every shipped case gives the same outputs as with the release build of SUNDIALS
# (scripts/compare-outputs.sh), build without MPI with ASan+UBSan and run the suites of the
# library and the command line there (and the Python module's run of every analysis), build the
# libFuzzer harnesses with clang and fuzz each for a minute (scripts/fuzz.sh), and end with the line
# "N passed, N failed". On two cores it takes about 27 minutes (CI's budget is 30).
set -uo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh || { echo "0 passed, 1 failed"; exit 1; }
jobs=$(nproc 2>/dev/null || echo 2)
passed=0; failed=0

count_log() { # count meson test results of a build directory
    local log="$1/meson-logs/testlog.json"
    [ -f "$log" ] || { failed=$((failed + 1)); return; }
    read -r p f < <(python3 - "$log" <<'PY'
import json, sys
p = f = 0
for line in open(sys.argv[1]):
    line = line.strip()
    if not line:
        continue
    r = json.loads(line).get("result", "")
    if r in ("OK", "EXPECTEDFAIL", "SKIP"):
        p += 1
    else:
        f += 1
print(p, f)
PY
)
    passed=$((passed + p)); failed=$((failed + f))
}

build_and_test() { # dir, meson options...
    local dir=$1; shift
    if [ -d "$dir/meson-info" ]; then meson setup --reconfigure "$dir" "$@" >/dev/null
    else meson setup "$dir" "$@" >/dev/null; fi || { echo "meson setup $dir failed"; failed=$((failed + 1)); return 1; }
    ninja -C "$dir" || { echo "build $dir failed"; failed=$((failed + 1)); return 1; }
    local names=() # EXCLUDE: a regex of test names left out of the suites TEST_ARGS selects
    if [ -n "${EXCLUDE:-}" ]; then
        mapfile -t names < <(meson test -C "$dir" --list "${TEST_ARGS[@]}" 2>/dev/null | sed -n 's/^.* \/ //p' |
            grep -vxE "$EXCLUDE")
    fi
    meson test -C "$dir" --print-errorlogs --num-processes "$jobs" "${TEST_ARGS[@]}" "${names[@]}"
    count_log "$dir"
}

TEST_ARGS=()
echo "== build with Open MPI (-Dmpi=enabled) and -Werror and run the suite (its MPI tests run 2 ranks;"
echo "   the guide runs its MPI block)"
build_and_test build-ci -Dwerror=true -Dbuildtype=debugoptimized -Dmpi=enabled

echo "== exported symbols of libgeardyn all carry the gd_ prefix"
lib=$(ls build-ci/src/libgeardyn.so* 2>/dev/null | head -1)
if [ -n "$lib" ]; then
    bad=$(nm -D --defined-only "$lib" | awk '$2 ~ /^[TDBRVW]$/ {print $3}' | grep -v '^gd_' || true)
    if [ -z "$bad" ]; then echo "ok: $(nm -D --defined-only "$lib" | awk '$2 ~ /^[TDBR]$/' | wc -l) symbols"; passed=$((passed + 1))
    else echo "symbols without the gd_ prefix:"; echo "$bad"; failed=$((failed + 1)); fi
else
    echo "libgeardyn not built"; failed=$((failed + 1))
fi

echo "== the release build of SUNDIALS (.deps/, scripts/sundials-release.sh) gives the same outputs"
echo "   as Debian's package on every shipped case"
if build-ci/src/cli/geardyn --version | grep -q 'release build'; then
    if { [ -d build-sys/meson-info ] || meson setup build-sys -Dsundials=system -Dwerror=true \
            -Dbuildtype=debugoptimized >/dev/null; } && ninja -C build-sys src/cli/geardyn >/dev/null; then
        rm -rf build-sys/compare
        if bash scripts/compare-outputs.sh "$(pwd)/build-sys/src/cli/geardyn" "$(pwd)/build-ci/src/cli/geardyn" \
                build-sys/compare | grep -v " same ("; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
    else
        echo "build-sys (-Dsundials=system) failed"; failed=$((failed + 1))
    fi
else
    echo "skipped: build-ci links $(build-ci/src/cli/geardyn --version | tail -1)"
fi

echo "== build without MPI, with ASan+UBSan, and run the suites of the library and the command line"
echo "   again, and the Python module's run of every analysis (the other Python tests, the guide and"
echo "   the examples call the same library functions as these). Left out there: faults, publish,"
echo "   dynamic_objective, optimize_robust, envelope_ns and envelope_bta, 12 minutes under the"
echo "   sanitizers, whose library code optimize_cli, optimize_objectives, run, guards, envelope and"
echo "   envelope_cli run (envelope_ns and envelope_bta: the paper's pair's curves and a regime map)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
TEST_ARGS=(--timeout-multiplier 4 --no-suite python --no-suite docs --no-suite examples)
EXCLUDE='faults|publish|dynamic_objective|optimize_robust|envelope_ns|envelope_bta'
if build_and_test build-asan -Db_sanitize=address,undefined -Db_lundef=false -Dbuildtype=debugoptimized \
        -Dwerror=true -Dmpi=disabled; then
    meson test -C build-asan --print-errorlogs --timeout-multiplier 4 python_runs
    count_log build-asan
fi
unset ASAN_OPTIONS UBSAN_OPTIONS EXCLUDE

echo "== fuzzing (clang, libFuzzer + ASan + UBSan): replay each harness's corpus, then fuzz it for 60 s"
echo "   (scripts/fuzz.sh; a crash leaves its input in build-fuzz/fuzz-artifacts/)"
if command -v clang >/dev/null; then
    if { [ -d build-fuzz/meson-info ] || CC=clang meson setup build-fuzz -Dfuzz=true -Db_lundef=false \
            -Dbuildtype=debugoptimized -Dwerror=true >/dev/null; } &&
            ninja -C build-fuzz tests/fuzz/fuzz_case tests/fuzz/fuzz_eventlog >/dev/null; then
        for h in case eventlog; do
            if bash scripts/fuzz.sh build-fuzz 60 "$h"; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
        done
    else
        echo "build-fuzz (-Dfuzz=true, CC=clang) failed"; failed=$((failed + 1))
    fi
else
    echo "clang is not installed (scripts/deps.sh installs it)"; failed=$((failed + 1))
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
