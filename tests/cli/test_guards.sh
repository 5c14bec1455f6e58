#!/usr/bin/env bash
# The guards stop a run with a clear status instead of hanging or drifting: more events per mesh
# period than allowed (chattering), teeth separated for good at zero load, a run estimated beyond
# run.max_time_s refused before any work, the estimate of a long run said when it starts. TAP output.
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

# a run that would never end is refused before any work, with the estimate and the key that
# limits it (the quickstart case with a largest step of 1e-12 mesh period: about 1e12 steps a period)
"$G" run "$SRC/cases/quickstart.ini" --out "$work/never" --set solver.max_step_fraction=1e-12 > "$work/n.txt" 2>&1; rc=$?
[ $rc -eq 2 ]; ok $? "a run estimated at a century: exit status 2 (got $rc)"
grep -q "run.max_time_s: the run is estimated at about .* years), from .* integration steps.*solver.max_step_fraction = 1e-12" \
    "$work/n.txt"; ok $? "and says the estimate, where it comes from and the key: $(head -c 400 "$work/n.txt")"
[ ! -e "$work/never" ]; ok $? "and writes nothing"
# raising the key lets it start; a run estimated above a minute says its estimate when it starts
# (a transient of 500 000 periods: about 1.5 minutes); it is stopped once it has said so
"$G" run "$SRC/cases/quickstart.ini" --out "$work/long" --set run.transient_periods=500000 \
    --set output.plots=off > "$work/l.txt" 2>&1 &
pid=$!
for i in $(seq 1 2000); do grep -q "estimated at" "$work/l.txt" && break; sleep 0.01; done
kill "$pid" 2> /dev/null; wait "$pid" 2> /dev/null
grep -q "^geardyn: this run is estimated at about .* (limit run.max_time_s = 8.64e+04 s)" "$work/l.txt"
ok $? "a run estimated above a minute says so when it starts: $(head -1 "$work/l.txt")"
"$G" run "$SRC/cases/quickstart.ini" --out "$work/short" --set run.transient_periods=10 --set run.record_periods=5 \
    --set output.plots=off > "$work/s.txt" 2>&1
! grep -q "estimated at" "$work/s.txt"; ok $? "a short run does not"

# a basins run is estimated from its initial states too (the picture's cells and the sample, each a
# trajectory of about 14 mesh periods on a one-coordinate model) and refused above the limit
"$G" run "$SRC/cases/basins/ks-hysteresis.ini" --out "$work/basins" --set run.max_time_s=2 > "$work/b.txt" 2>&1; rc=$?
[ $rc -eq 2 ]; ok $? "basins estimated above run.max_time_s = 2: exit status 2 (got $rc)"
grep -q "run.max_time_s: the run is estimated at about .* from .* integration steps: 5e+04 initial states (basins.resolution = 200, resolution_y = 200, picture = on, samples = 10000" \
    "$work/b.txt"; ok $? "and names its states and keys: $(head -c 400 "$work/b.txt")"
[ ! -e "$work/basins" ]; ok $? "and writes nothing"

# check prints no NaN: a key unset and not derived reads "none"; every shipped case has an estimate
nan=""; noest=""
for f in "$SRC"/cases/*.ini "$SRC"/cases/*/*.ini; do
    # a continuation that overlays a sweep's results needs them: checked without the overlay
    extra=(); grep -q "^overlay_sweep" "$f" && extra=(--set continuation.overlay_sweep=)
    "$G" check "$f" "${extra[@]}" > "$work/c.txt" 2>&1 || noest="$noest $f(exit $?)"
    grep -qi "\bnan\b" "$work/c.txt" && nan="$nan $f"
    grep -q "^time_class = .*; about .* s" "$work/c.txt" || noest="$noest $f"
done
[ -z "$nan" ]; ok $? "geardyn check prints no nan for any shipped case${nan:+:$nan}"
[ -z "$noest" ]; ok $? "and estimates every one's cost${noest:+:$noest}"

echo "1..$n"
[ $bad -eq 0 ]
