#!/usr/bin/env bash
# Replay the fuzzing corpora and fuzz each harness for a bounded time.
#
#   scripts/fuzz.sh BUILD_DIR [SECONDS] [HARNESS ...]
#
# BUILD_DIR is a build configured for fuzzing:
#   CC=clang meson setup BUILD_DIR -Dfuzz=true -Db_lundef=false && ninja -C BUILD_DIR
# The harnesses (default: both) are tests/fuzz/fuzz_case.c (case loading, --set, scene
# resolution, model build) and tests/fuzz/fuzz_eventlog.c (the event-log reader). For each, first
# every input of its corpus is run once (case: tests/fuzz/case/, every shipped case of cases/ and
# every file of the bad-input corpus tests/bad-input/; eventlog: tests/fuzz/eventlog/), seeds and
# every crash ever found; then libFuzzer mutates them for SECONDS (default 60) into a scratch
# corpus that is thrown away, so the repository is never written. Prints the executions and the
# coverage reached; exits 1 on a crash, a leak or a sanitizer report, leaving the input that
# caused it in BUILD_DIR/fuzz-artifacts/ (add it to the harness's corpus with the fix, so that it
# is replayed for ever).
set -u
build=${1:?usage: scripts/fuzz.sh BUILD_DIR [SECONDS] [HARNESS ...]}
seconds=${2:-60}
shift $(($# < 2 ? $# : 2))
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(case eventlog)
src=$(cd "$(dirname "$0")/.." && pwd)
art=$build/fuzz-artifacts
mkdir -p "$art"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

# a dictionary per harness, made from the sources each time so that it cannot go stale: the
# schema's words (sections, keys, choices) for cases; the header, clearance and kind names for logs
dictionary() {
    case $1 in
    case) { grep -oE '"[][a-z0-9_|.-]+"' "$src/src/case/case_schema.c" | tr -d '"' | tr '|' '\n'
            printf '%s\n' '[' ']' ' = ' '%%'; } ;;
    eventlog) { grep -oE '"t_s,[a-z_,]+"' "$src/src/output/eventlog.c" | tr -d '"' | tr ',' '\n'
                printf '%s\n' mesh-L mesh-R bearing-1L bearing-2R contact separation back-contact \
                    back-separation , nan inf 1e308; } ;;
    esac | sort -u | grep -v '^$' | sed 's/.*/"&"/' > "$scratch/$1.dict"
}

corpora() {
    case $1 in
    case) echo "$src/tests/fuzz/case $src/cases $src/tests/bad-input" ;;
    eventlog) echo "$src/tests/fuzz/eventlog" ;;
    esac
}

bad=0
for h in "${harnesses[@]}"; do
    exe=$build/tests/fuzz/fuzz_$h
    [ -x "$exe" ] || { echo "fuzz.sh: $exe not built (see the comment at the top of this script)" >&2; exit 2; }
    read -r -a dirs <<< "$(corpora "$h")"
    echo "# $h: replay of ${dirs[*]#"$src/"}"
    if ! "$exe" -runs=0 -artifact_prefix="$art/" "${dirs[@]}" > "$scratch/replay.log" 2>&1; then
        tail -40 "$scratch/replay.log"
        echo "fuzz.sh: $h: the corpus replay failed" >&2
        bad=1
        continue
    fi
    grep -E "INITED|DONE" "$scratch/replay.log" | tail -1
    dictionary "$h"
    echo "# $h: fuzzing for $seconds s"
    mkdir -p "$scratch/corpus-$h"
    "$exe" -max_total_time="$seconds" -max_len=4096 -dict="$scratch/$h.dict" -timeout=10 -rss_limit_mb=2048 \
        -print_final_stats=1 -artifact_prefix="$art/" "$scratch/corpus-$h" "${dirs[@]}" > "$scratch/fuzz.log" 2>&1
    rc=$?
    grep -E "^#[0-9]+[[:space:]]+(INITED|DONE)" "$scratch/fuzz.log" | tail -2
    grep -E "^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)" "$scratch/fuzz.log"
    if [ $rc -ne 0 ]; then
        grep -E "ERROR|SUMMARY|runtime error|Test unit written" "$scratch/fuzz.log" | head -20
        echo "fuzz.sh: $h: libFuzzer found a failure (exit $rc); the input is in $art/" >&2
        bad=1
    fi
done
exit $bad
