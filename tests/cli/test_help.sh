#!/usr/bin/env bash
# geardyn help COMMAND and geardyn COMMAND --help print the same text; the man page holds every
# command and renders without a warning; a wrong command is refused with status 2. TAP output.
set -u
G=${GEARDYN:?}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
cmds="run check events keys help"
n=0
ok() { n=$((n + 1)); if [ "$1" -eq 0 ]; then echo "ok $n - $2"; else echo "not ok $n - $2"; fi; }
for c in $cmds; do
    "$G" help "$c" > "$T/help" 2>&1; r1=$?
    "$G" "$c" --help > "$T/opt" 2>&1; r2=$?
    [ $r1 -eq 0 ] && [ $r2 -eq 0 ] && cmp -s "$T/help" "$T/opt" && grep -q "^usage: geardyn $c " "$T/help"
    ok $? "help $c and $c --help print the same usage"
    "$G" --help | grep -q "^  geardyn $c "; ok $? "--help lists $c"
done
"$G" help --man > "$T/geardyn.1"; ok $? "help --man"
for c in $cmds; do grep -q "^\.SS \"$c\"" "$T/geardyn.1"; ok $? "the man page has $c"; done
if command -v groff > /dev/null; then
    warn=$(groff -man -Tutf8 -ww -z "$T/geardyn.1" 2>&1)
    [ -z "$warn" ]; ok $? "the man page renders without warnings${warn:+: $warn}"
else
    echo "ok $((n + 1)) - # SKIP groff not installed"; n=$((n + 1))
fi
"$G" help nosuch > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "help of an unknown command: status 2"
"$G" nosuch > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "an unknown command: status 2"
"$G" keys --bogus > /dev/null 2>&1; [ $? -eq 2 ]; ok $? "keys with an unknown option: status 2"
echo "1..$n"
