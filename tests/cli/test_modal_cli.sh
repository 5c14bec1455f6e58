#!/usr/bin/env bash
# The natural frequencies on the command line (docs/model.md section 9.7): check's section of modes
# and resonance speeds (the spur pair's one mode at sqrt(k/m), the paper's herringbone's symmetric and
# antisymmetric modes, a floating spur pinion's rigid-body mode kept out, ISO 6336-1's stiffness named
# as the estimate with stiffness = ltca), and derived.modal in summary.json of a response (with ISO's
# and with LTCA's stiffness: the frequency of the torsional mode moves with the square root of the
# stiffness), a sweep and a continuation, equal to what check prints. TAP output.
. "${GEARDYN_SOURCE:?}/tests/cli/tap.sh" # G, SRC, work, ok

spur="$SRC/cases/guide/spur.ini"
"$G" check "$spur" > "$work/check.txt"; ok $? "check exits 0 on the spur pair"
grep -q "^# natural frequencies (docs/model.md section 9.7)" "$work/check.txt"; ok $? "check has the section of modes"
grep -Eq "^modes = 1 +; rigid-body modes excluded: 0" "$work/check.txt"; ok $? "spur torsional: one mode"
grep -Eq "^ +1 +5641.08 +13538.6 +6769.3 +4512.87 +3384.65 +100.00 +mesh 100 %" "$work/check.txt"
ok $? "spur torsional: 5641.08 Hz = sqrt(k_m/m_n)/2 pi, main resonance 13538.6 rpm and 1/2, 1/3, 1/4 of it"
grep -q "^# mesh stiffness: 6.1569e+08 N/m, the mean over a mesh cycle (ISO 6336-1)" "$work/check.txt"
ok $? "spur: the stiffness of the linearisation and where it comes from"

"$G" check "$spur" --set excitation.stiffness=ltca > "$work/check-ltca.txt"
grep -q "^# mesh stiffness: ISO 6336-1's 6.1569e+08 N/m, an estimate: with stiffness = ltca the run takes LTCA's" \
    "$work/check-ltca.txt"; ok $? "stiffness = ltca: check names ISO 6336-1's value as the estimate"

"$G" check "$SRC/cases/guide/herringbone.ini" > "$work/check-hb.txt"
grep -Eq "^modes = 10 +;" "$work/check-hb.txt"; ok $? "herringbone bta: ten modes"
[ "$(grep -Ec '^ +[0-9]+ .* symmetric ' "$work/check-hb.txt")" = 5 ] &&
    [ "$(grep -Ec '^ +[0-9]+ .* antisymmetric ' "$work/check-hb.txt")" = 5 ]
ok $? "herringbone bta: five symmetric and five antisymmetric modes"
grep -Eq "^ +7 +2239.48 +4478.97 .* symmetric +mesh-L 38.1 %, mesh-R 38.1 %" "$work/check-hb.txt"
ok $? "herringbone bta: mode 7 at 2239.48 Hz, 4478.97 rpm, symmetric, 38.1 % in each mesh"

"$G" check "$spur" --set scene.model=bta --set support.axial_stiffness_pinion_n_per_m=0 > "$work/check-fl.txt"
grep -Eq "^modes = 4 +; rigid-body modes excluded: 1" "$work/check-fl.txt" &&
    grep -q "^# rigid-body mode 1 (zero frequency, nothing holds it): z1 1$" "$work/check-fl.txt"
ok $? "spur bta with a floating pinion: its axial motion is a rigid-body mode, kept out"

# summary.json of a response, a sweep and a continuation
short="--set run.transient_periods=5 --set run.record_periods=2 --quiet"
# shellcheck disable=SC2086
"$G" run "$spur" --out "$work/resp" $short > /dev/null 2>&1; ok $? "response run"
# shellcheck disable=SC2086
"$G" run "$spur" --out "$work/resp-ltca" $short --set excitation.stiffness=ltca > /dev/null 2>&1
ok $? "response run with stiffness = ltca"
# shellcheck disable=SC2086
"$G" run "$SRC/cases/guide/spur-sweep.ini" --out "$work/sweep" $short --set sweep.points=3 > /dev/null 2>&1
ok $? "sweep run"
"$G" run "$SRC/cases/continuation/kahraman-singh.ini" --out "$work/cont" --quiet > /dev/null 2>&1
ok $? "continuation run"
python3 - "$work" <<'PY'
import json, math, sys
w = sys.argv[1]
def modal(d):
    return json.load(open(f"{w}/{d}/summary.json"))["derived"]["modal"]
failed = 0
def check(cond, msg):
    global failed
    failed += not cond
    print(("# ok: " if cond else "# FAILED: ") + msg)
r = modal("resp")
m = r["modes"][0]
check(len(r["modes"]) == 1 and abs(m["frequency_hz"] - 5641.08258) < 1e-4 and r["mesh_stiffness_source"] == "iso6336",
      "response: derived.modal has check's mode, from ISO 6336-1's stiffness")
check(abs(m["resonance_rpm"]["main"] - 13538.598) < 1e-2 and abs(m["resonance_rpm"]["1/3"] * 3 - m["resonance_rpm"]["main"]) < 1e-9,
      "response: the resonance speeds, main and superharmonic")
check(m["strain_energy_share"] == {"mesh": 1.0} and m["shape"] == {"q": 1.0} and r["rigid_body_modes"] == [],
      "response: all the strain energy in the mesh, shape q = 1")
l = modal("resp-ltca")
k_iso, k_ltca = r["mesh_stiffness_n_per_m"][0], l["mesh_stiffness_n_per_m"][0]
k_model = json.load(open(f"{w}/resp-ltca/summary.json"))["derived"]["model"]["mesh_stiffness_n_per_m"]
check(l["mesh_stiffness_source"] == "ltca" and abs(k_ltca / k_model - 1) < 1e-12 and abs(k_ltca / k_iso - 1) > 0.01,
      f"stiffness = ltca: the linearisation takes LTCA's mean {k_ltca:.6g} N/m, not ISO's {k_iso:.6g}")
check(abs(l["modes"][0]["frequency_hz"] / m["frequency_hz"] - math.sqrt(k_ltca / k_iso)) < 1e-12,
      "stiffness = ltca: the torsional frequency moves with the square root of the stiffness")
s = modal("sweep")
check(abs(s["modes"][0]["frequency_hz"] - m["frequency_hz"]) < 1e-9, "sweep: derived.modal, the same mode")
c = modal("cont")
check(abs(c["modes"][0]["resonance_rpm"]["main"] - 3183.0988618) < 1e-6,
      "continuation (Kahraman & Singh): the main resonance at Omega = 1, 3183.0989 rpm")
sys.exit(1 if failed else 0)
PY
ok $? "derived.modal of a response (ISO and LTCA stiffness), a sweep and a continuation"

echo "1..$n"
[ "$bad" = 0 ]
