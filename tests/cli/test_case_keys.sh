#!/usr/bin/env bash
# docs/case-keys.md is exactly what `geardyn keys --markdown` prints: a key added to the schema
# without regenerating the page fails here. Regenerate with
#   build/src/cli/geardyn keys --markdown > docs/case-keys.md
# TAP output.
set -u
G=${GEARDYN:?}
SRC=${GEARDYN_SOURCE:?}
echo "1..3"
"$G" keys --markdown > "${TMPDIR:-/tmp}/case-keys.$$.md"
rc=$?
[ $rc -eq 0 ] && echo "ok 1 - geardyn keys --markdown" || echo "not ok 1 - geardyn keys --markdown exits $rc"
if diff -u "$SRC/docs/case-keys.md" "${TMPDIR:-/tmp}/case-keys.$$.md" >&2; then
    echo "ok 2 - docs/case-keys.md matches the schema"
else
    echo "not ok 2 - docs/case-keys.md differs from geardyn keys --markdown (regenerate it)"
fi
# every key of the schema has a row: count the keys the plain listing prints
nkeys=$("$G" keys | grep -c '^[a-z]*\.[a-z0-9_]*[ :]')
nrows=$(grep -c '^| `' "$SRC/docs/case-keys.md")
[ "$nkeys" -gt 100 ] && [ "$nkeys" -eq "$nrows" ] && echo "ok 3 - $nrows rows, one per key" \
    || echo "not ok 3 - $nkeys keys in the schema, $nrows rows in docs/case-keys.md"
rm -f "${TMPDIR:-/tmp}/case-keys.$$.md"
