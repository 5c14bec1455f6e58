#!/usr/bin/env bash
# Replay the fuzzing corpus and fuzz for a bounded time.
#
#   scripts/fuzz.sh BUILD_DIR [SECONDS]
#
# BUILD_DIR is a build configured for fuzzing:
#   CC=clang meson setup BUILD_DIR -Dfuzz=true -Db_lundef=false && ninja -C BUILD_DIR tests/fuzz/fuzz_case
# First every input of tests/fuzz/case/ (seeds and every crash ever found), every shipped case of
# cases/ and every file of the bad-input corpus tests/bad-input/ is run once; then libFuzzer
# mutates them for SECONDS (default 60) into a scratch corpus
# that is thrown away, so the repository is never written. Prints the executions and the coverage
# reached; exits 1 on a crash, a leak or a sanitizer report, leaving the input that caused it in
# BUILD_DIR/fuzz-artifacts/ (add it to tests/fuzz/case/ with the fix, so that it is replayed for ever).
set -u
build=${1:?usage: scripts/fuzz.sh BUILD_DIR [SECONDS]}
seconds=${2:-60}
src=$(cd "$(dirname "$0")/.." && pwd)
exe=$build/tests/fuzz/fuzz_case
[ -x "$exe" ] || { echo "fuzz.sh: $exe not built (see the comment at the top of this script)" >&2; exit 2; }
art=$build/fuzz-artifacts
mkdir -p "$art"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

echo "# replay: tests/fuzz/case, cases, tests/bad-input"
if ! "$exe" -runs=0 -artifact_prefix="$art/" "$src/tests/fuzz/case" "$src/cases" "$src/tests/bad-input" > "$scratch/replay.log" 2>&1; then
    tail -40 "$scratch/replay.log"
    echo "fuzz.sh: the corpus replay failed" >&2
    exit 1
fi
grep -E "INITED|DONE" "$scratch/replay.log" | tail -1

# a dictionary of the schema's words (sections, keys, choices), so that mutations reach the checks
# behind the key lookup; made from the schema's source each time, so it cannot go stale
{ grep -oE '"[][a-z0-9_|.-]+"' "$src/src/case/case_schema.c" | tr -d '"' | tr '|' '\n'
  printf '%s\n' '[' ']' ' = ' '%%' ; } | sort -u | grep -v '^$' | sed 's/.*/"&"/' > "$scratch/case.dict"

echo "# fuzzing for $seconds s"
mkdir "$scratch/corpus"
"$exe" -max_total_time="$seconds" -max_len=4096 -dict="$scratch/case.dict" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$art/" "$scratch/corpus" "$src/tests/fuzz/case" "$src/cases" "$src/tests/bad-input" \
    > "$scratch/fuzz.log" 2>&1
rc=$?
grep -E "^#[0-9]+[[:space:]]+(INITED|DONE)" "$scratch/fuzz.log" | tail -2
grep -E "^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)" "$scratch/fuzz.log"
if [ $rc -ne 0 ]; then
    grep -E "ERROR|SUMMARY|runtime error|Test unit written" "$scratch/fuzz.log" | head -20
    echo "fuzz.sh: libFuzzer found a failure (exit $rc); the input is in $art/" >&2
    exit 1
fi
