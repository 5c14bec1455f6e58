# Sourced by the command-line tests (bash): the executable G ($GEARDYN), the source tree SRC
# ($GEARDYN_SOURCE), a scratch directory work removed on exit, and ok STATUS MESSAGE, which prints
# one TAP line and counts the checks (n) and the failures (bad).
set -u
G=${GEARDYN:?}
SRC=${GEARDYN_SOURCE:?}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=0; bad=0
ok() { # status message (one TAP line: a message's newlines become " | ")
    local m=${2//$'\n'/ | }
    n=$((n + 1)); if [ "$1" = 0 ]; then echo "ok $n - $m"; else echo "not ok $n - $m"; bad=$((bad + 1)); fi
}
