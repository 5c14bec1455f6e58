#!/usr/bin/env bash
# The guards stop a run with a clear status instead of hanging or drifting: more events per mesh
# period than allowed (chattering), and teeth separated for good at zero load. TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok

# the quickstart scene has about 20 contact events per mesh period: a limit of 3 must stop it
"$G" run "$SRC/cases/quickstart.ini" --out "$work/chatter" --quiet --set solver.max_events_per_period=3 \
    --set run.transient_periods=10 --set run.record_periods=5 > "$work/out.txt" 2>&1; rc=$?
[ $rc -eq 1 ]; ok $? "too many events per period: exit status 1 (got $rc)"
grep -q "chattering: more than 3 events in mesh period" "$work/out.txt"; ok $? "and says so: $(cat "$work/out.txt")"
[ -z "$(ls -A "$work/chatter" 2>/dev/null)" ]; ok $? "and leaves no files"
# with the limit at its default the same run completes
"$G" run "$SRC/cases/quickstart.ini" --out "$work/fine" --quiet --set run.transient_periods=10 \
    --set run.record_periods=5 > /dev/null 2>&1; ok $? "the same run completes with the default limit"

# a light-load rattle that the root finder follows event by event completes (no false alarm)
"$G" run "$SRC/cases/quickstart.ini" --out "$work/rattle" --quiet --set scene.model=torsional-lr \
    --set operating.torque_nm=5 --set run.transient_periods=50 --set run.record_periods=50 > "$work/r.txt" 2>&1
ok $? "light-load rattle completes ($(head -c 200 "$work/r.txt"))"
python3 -c "import json,sys; d=json.load(open('$work/rattle/summary.json')); sys.exit(0 if d['results']['impact_regime']=='double-sided' else 1)"
ok $? "and it is a double-sided rattle"

echo "1..$n"
[ $bad -eq 0 ]
