#!/usr/bin/env bash
# geardyn run on the paper's LTCA cases: files, stable summary.json keys with valid values, no
# temporary files left, check shows the new keys, a fixed pinion reports unequal load shares, a
# case without load is refused with exit 2. TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok

"$G" check "$SRC/cases/paper/ltca-modified.ini" > "$work/check.txt"; ok $? "check exits 0 on ltca-modified.ini"
grep -Eq "^pinion_axial = floating +; file line" "$work/check.txt"; ok $? "check shows [support] pinion_axial"
grep -Eq "^ltca_face_slices = 21 +; file line" "$work/check.txt"; ok $? "check shows [solver] ltca_face_slices"

for case in ltca-unmodified ltca-modified; do
    out="$work/$case"
    "$G" run "$SRC/cases/paper/$case.ini" --out "$out" --quiet --set solver.ltca_positions_per_cycle=16 \
        > "$work/run.txt" 2>&1
    ok $? "run $case exits 0 ($(head -c 300 "$work/run.txt"))"
    for f in summary.json lte.csv load_distribution.csv pair_loads.csv; do
        [ -s "$out/$f" ]; ok $? "$case: wrote $f"
    done
    ls -a "$out" | grep -Eq '\.tmp|\.plot-'; [ $? -ne 0 ]; ok $? "$case: no temporary files left"
    python3 - "$out/summary.json" "$case" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
case = sys.argv[2]
r = d["results"]
for k in ("lte_pp_arcsec", "mean_mesh_stiffness_n_per_m.left", "mean_mesh_stiffness_n_per_m.right",
          "load_share.left", "load_share.right", "max_contact_pressure_mpa.left", "edge_loading.left",
          "mesh_in.left.relative_normal_velocity_per_pinion_speed_m"):
    o = r
    for part in k.split("."):
        assert isinstance(o, dict) and part in o, "missing results." + k
        o = o[part]
assert d["analysis"] == "ltca"
assert 0.1 < r["lte_pp_arcsec"] < 10, r["lte_pp_arcsec"]
for h in ("left", "right"):
    assert 1e8 < r["mean_mesh_stiffness_n_per_m"][h] < 5e9, r["mean_mesh_stiffness_n_per_m"]
    assert abs(r["load_share"][h] - 0.5) < 1e-3, r["load_share"]
edge = case == "ltca-unmodified"
assert r["edge_loading"]["left"] is edge and r["edge_loading"]["right"] is edge, r["edge_loading"]
s = d["solver"]
assert s["max_load_balance_error"] < 1e-9 and s["max_penetration_m"] < 1e-12 and s["min_load_n"] >= 0, s
assert s["pinion_axial"] == "floating" and s["positions"] == 16
assert d["case"]["parameters"]["solver"]["ltca_positions_per_cycle"]["source"] == "--set #1"
PY
    ok $? "$case: summary.json has the stable keys with valid values"
    head -1 "$out/lte.csv" | grep -q "^phi1_deg,lte_arcsec,axial_shift_um,gte_left_arcsec"; ok $? "$case: lte.csv header"
    rows=$(($(wc -l < "$out/lte.csv") - 1)); [ "$rows" -eq 16 ]; ok $? "$case: lte.csv has 16 rows ($rows)"
    head -1 "$out/pair_loads.csv" | grep -q "^position,phi1_deg,half,pair,load_n,share_of_half"; ok $? "$case: pair_loads.csv header"
done

# edge loading (docs/ltca.md section 5) both ways: the aligned pairs of unmodified flanks (the guide's
# spur pair, whose line load is uniform to its face ends, and the paper's herringbone without its
# misalignment, whose helical lines carry more near the root, wherever they end) raise none; the
# spur pair with its gear axis tilted 10' across the plane loads one face end at every position, at
# several times its line's mean
edge_case() { # name case extra-set...
    local name=$1 case=$2; shift 2
    "$G" run "$SRC/cases/$case.ini" --out "$work/edge-$name" --quiet --set scene.analysis=ltca --set output.plots=off \
        --set solver.ltca_positions_per_cycle=16 "$@" > /dev/null 2>&1
}
edge_case spur guide/spur
edge_case spur-tilted guide/spur --set misalignment.axis_cross_plane_arcmin=10
edge_case paper-aligned paper/ltca-unmodified --set misalignment.axis_in_plane_arcmin=0 \
    --set misalignment.axis_cross_plane_arcmin=0 --set misalignment.centre_distance_error_mm=0
python3 - "$work" <<'PY'
import json, sys
r = {n: json.load(open("%s/edge-%s/summary.json" % (sys.argv[1], n)))["results"]
     for n in ("spur", "spur-tilted", "paper-aligned")}
for n in ("spur", "paper-aligned"):
    assert r[n]["edge_loading"]["left"] is False and r[n]["edge_positions"]["left"] == 0, (n, r[n]["edge_loading"])
    assert not [k for k in r[n]["edge_kinds"]["left"] if "end" in k], r[n]["edge_kinds"]
assert abs(r["spur"]["edge_line_load_ratio_max"]["left"] - 1) < 1e-3, r["spur"]["edge_line_load_ratio_max"]
t = r["spur-tilted"]
assert t["edge_loading"]["left"] is True and t["edge_positions"]["left"] == 16, t["edge_positions"]
assert t["edge_line_load_ratio_max"]["left"] > 2 and "pinion_end_hi" in t["edge_kinds"]["left"], t
print("# spur: edge load ratio", r["spur"]["edge_line_load_ratio_max"]["left"], "tip contacts", r["spur"]["tip_contact_positions"]["left"], "tilted: edge load ratio",
      t["edge_line_load_ratio_max"]["left"])
PY
ok $? "edge loading: none on the aligned unmodified pairs, at every position of the tilted spur pair"

# one key switches a case to the unmodified pair: modification.apply = off must give exactly the
# LTCA of the case without a [modification] section (every amount resolves to 0)
out="$work/apply-off"
"$G" run "$SRC/cases/paper/ltca-modified.ini" --out "$out" --quiet --set solver.ltca_positions_per_cycle=16 \
    --set modification.apply=off --set output.plots=off > "$work/run.txt" 2>&1
ok $? "ltca-modified with modification.apply=off exits 0"
python3 - "$out/summary.json" "$work/ltca-unmodified/summary.json" "$work/ltca-modified/summary.json" <<'PY'
import json, sys
off, unmod, mod = (json.load(open(f)) for f in sys.argv[1:4])
keys = lambda d: (d["results"]["lte_pp_arcsec"], d["results"]["mean_mesh_stiffness_n_per_m"]["left"],
                  d["results"]["mean_mesh_stiffness_n_per_m"]["right"])
assert keys(off) == keys(unmod), (keys(off), keys(unmod))
assert keys(off) != keys(mod), (keys(off), keys(mod))
p = off["case"]["parameters"]["modification"]
assert p["tip_relief_amount_um"]["value"] == 0 and p["tip_relief_amount_um"]["source"] == "derived", p
PY
ok $? "modification.apply=off reproduces the unmodified pair exactly"

# a fixed pinion with the paper's errors: the tilt leaves one half open; the summary says so
out="$work/fixed"
"$G" run "$SRC/cases/paper/ltca-unmodified.ini" --out "$out" --quiet --set support.pinion_axial=fixed \
    --set solver.ltca_positions_per_cycle=8 --set output.plots=off > "$work/run.txt" 2>&1
ok $? "fixed pinion run exits 0"
python3 - "$out/summary.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))["results"]
assert r["load_share"]["left"] < 0.01 and r["load_share"]["right"] > 0.99, r["load_share"]
assert abs(r["load_share_difference"] + 1) < 0.02, r["load_share_difference"]
PY
ok $? "fixed pinion: load shares left/right reported unequal"

bad_case="$work/bad.ini"
printf '[scene]\nanalysis = ltca\n[operating]\ntorque_nm = 0\n' > "$bad_case"
"$G" run "$bad_case" --out "$work/bad" --quiet 2> "$work/stderr"; rc=$?
[ $rc -eq 2 ]; ok $? "no load: exit 2 (got $rc)"
grep -Eq "bad.ini:4: operating.torque_nm: .*\(valid: > 0" "$work/stderr"; ok $? "the message names file, line and key ($(cat "$work/stderr"))"
[ ! -e "$work/bad" ]; ok $? "nothing written"

echo "1..$n"
[ $bad -eq 0 ]
