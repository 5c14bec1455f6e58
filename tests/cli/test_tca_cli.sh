#!/usr/bin/env bash
# geardyn run on the paper's TCA cases: files, stable summary.json keys, no temporary files left,
# check shows the new sections, a modification that does not fit is refused with exit 2. TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok

"$G" check "$SRC/cases/paper/tca-modified.ini" > "$work/check.txt"; ok $? "check exits 0 on tca-modified.ini"
grep -Eq "^tip_relief_amount_um = 35 um +; file line" "$work/check.txt"; ok $? "check shows [modification] keys"
grep -Eq "^centre_distance_error_mm = 0.1 mm +; file line" "$work/check.txt"; ok $? "check shows [misalignment] keys"
grep -Eq "^start_of_active_profile_radius_mm = " "$work/check.txt"; ok $? "check shows the start of active profile"

for case in tca-unmodified tca-modified; do
    out="$work/$case"
    "$G" run "$SRC/cases/paper/$case.ini" --out "$out" --quiet --set solver.tca_positions_per_cycle=16 \
        --set solver.tca_formulation=both > "$work/run.txt" 2>&1
    ok $? "run $case exits 0 ($(head -c 300 "$work/run.txt"))"
    for f in summary.json gte.csv contact_path.csv separation_left.csv separation_right.csv; do
        [ -s "$out/$f" ]; ok $? "$case: wrote $f"
    done
    ls -a "$out" | grep -Eq '\.tmp|\.plot-'; [ $? -ne 0 ]; ok $? "$case: no temporary files left"
    python3 - "$out/summary.json" "$case" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
case = sys.argv[2]
r = d["results"]
for k in ("gte_pp_arcsec.left", "gte_pp_arcsec.right", "edge_contact.left", "edge_contact.right",
          "contact_ratio_transverse", "contact_ratio_overlap", "operating_pressure_angle_deg"):
    o = r
    for part in k.split("."):
        assert isinstance(o, dict) and part in o, "missing results." + k
        o = o[part]
assert d["analysis"] == "tca"
assert r["gte_pp_arcsec"]["left"] > 0.1 and r["gte_pp_arcsec"]["right"] > 0.1, r["gte_pp_arcsec"]
assert 1.2 < r["contact_ratio_transverse"] < 1.5 and 1.3 < r["contact_ratio_overlap"] < 1.5
assert 23.4 < r["operating_pressure_angle_deg"] < 23.7, r["operating_pressure_angle_deg"]
edge = case == "tca-unmodified"
assert r["edge_contact"]["left"] is edge and r["edge_contact"]["right"] is edge, r["edge_contact"]
cmp = r["formulation_comparison"]
assert cmp["positions_compared"] == cmp["positions"] and cmp["max_difference_arcsec"] < 1e-3, cmp
assert d["case"]["parameters"]["solver"]["tca_positions_per_cycle"]["source"] == "--set #1"
PY
    ok $? "$case: summary.json has the stable keys with valid values"
    head -1 "$out/gte.csv" | grep -q "^phi1_deg,gte_left_arcsec,te_left_arcsec"; ok $? "$case: gte.csv header with units"
    rows=$(($(wc -l < "$out/gte.csv") - 1)); [ "$rows" -eq 32 ]; ok $? "$case: gte.csv has 2 cycles x 16 rows ($rows)"
done

bad_case="$work/bad.ini"
printf '[scene]\nanalysis = tca\n[modification]\ntip_relief_amount_um = 35\ntip_relief_length_mm = 30\n' > "$bad_case"
"$G" run "$bad_case" --out "$work/bad" --quiet 2> "$work/stderr"; rc=$?
[ $rc -eq 2 ]; ok $? "a tip relief longer than the profile: exit 2 (got $rc)"
grep -Eq "bad.ini:5: modification.tip_relief_length_mm: .*do not fit on the active profile.*\(valid: " "$work/stderr"
ok $? "the message names file, line and key ($(cat "$work/stderr"))"
[ ! -e "$work/bad" ]; ok $? "nothing written"

echo "1..$n"
[ $bad -eq 0 ]
