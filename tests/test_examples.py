#!/usr/bin/env python3
"""The C examples of examples/ are tests: each is run and what it prints is checked against a value
computed another way, mostly by the command line ($GEARDYN, summary.json), which reaches the same
physics through the table of analyses and its writers:

  response EXE  examples/response.c on cases/guide/spur.ini (shortened): the RMS acceleration,
                motion class, impact regime and step count equal those of `geardyn run` on the
                same case, and the RMS the example sums from the samples it receives equals the
                library's (two computations from the same samples).
  sweep EXE     examples/sweep.c on cases/guide/spur-sweep.ini, independent points: every point
                equals a `geardyn run` of the response at its speed (an independent sweep point is
                a response run from the case's initial state), and the sweep's standard files are
                in its directory.
  ltca EXE      examples/ltca.c (the spur pair written in C): its mean, smallest and largest mesh
                stiffness equal those of `geardyn run cases/guide/spur.ini --set
                scene.analysis=ltca` (the pair built in C is the case's pair), and the mean is
                within 20 % of ISO 6336-1 (docs/ltca.md section 6).
  basins EXE    examples/basins_duffing.c, the forced Duffing oscillator as a custom system, 10 000
                random initial states each: the twin-well case (two attractors, Attractors.jl's test
                suite: 0.511 and 0.489 of 1000 states) and the five-attractor case (bSTAB's reference:
                0.2027, 0.495, 0.0288, 0.0257, 0.2478 of 10 000 states): every fraction within three
                combined standard errors of its reference, the number of attractors exact, no state
                left without an attractor.

Standard library only; TAP output."""
import json
import os
import subprocess
import sys
import tempfile

GEARDYN = os.environ["GEARDYN"]
SRC = os.environ["GEARDYN_SOURCE"]
SHORT = ["run.transient_periods=100", "run.record_periods=20"]
n_checks = 0
failed = 0


def ok(cond, what):
    global n_checks, failed
    n_checks += 1
    if not cond:
        failed += 1
    print(("ok" if cond else "not ok") + " %d - %s" % (n_checks, what))


def close(got, want, rel, what):
    ok(abs(got - want) <= rel * abs(want), "%s: %.12g against %.12g (relative tolerance %g)" % (what, got, want, rel))


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        print("Bail out! %s: exit %d: %s" % (" ".join(cmd), p.returncode, p.stderr.strip()))
        sys.exit(1)
    return p.stdout


def printed(out):
    """The `name = value` lines of an example."""
    vals = {}
    for line in out.splitlines():
        if " = " in line and not line.startswith("#"):
            k, v = line.split(" = ", 1)
            vals[k.strip()] = v.strip()
    return vals


def cli_summary(case, sets, out):
    cmd = [GEARDYN, "run", case, "--out", out]
    for s in sets:
        cmd += ["--set", s]
    run(cmd)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def response(exe, tmp):
    case = os.path.join(SRC, "cases/guide/spur.ini")
    ex = printed(run([exe, case] + SHORT))
    s = cli_summary(case, SHORT, os.path.join(tmp, "cli-response"))
    r = s["results"]
    close(float(ex["rms_accel_mps2"]), r["rms_accel_mps2"]["combined"], 1e-10, "response: RMS acceleration = geardyn run's")
    ok(ex["motion"] == r["motion"], "response: motion %s = geardyn run's %s" % (ex["motion"], r["motion"]))
    ok(ex["impact_regime"] == r["impact_regime"],
       "response: impact regime %s = geardyn run's %s" % (ex["impact_regime"], r["impact_regime"]))
    ok(int(ex["steps"]) == s["solver"]["steps"], "response: %s steps = geardyn run's %d" % (ex["steps"], s["solver"]["steps"]))
    per = s["case"]["parameters"]["output"]["samples_per_period"]["value"]
    ok(int(ex["samples"]) == 20 * per, "response: the sample hook saw %s samples (20 recorded periods x %d)" % (ex["samples"], per))
    close(float(ex["rms_accel_left_from_samples_mps2"]), float(ex["rms_accel_left_mps2"]), 1e-12,
          "response: RMS summed by the example's sample hook = the library's")


def sweep(exe, tmp):
    case = os.path.join(SRC, "cases/guide/spur-sweep.ini")
    out = os.path.join(tmp, "example-sweep")
    sets = ["sweep.mode=independent", "sweep.direction=up", "sweep.points=4", "sweep.from=1000", "sweep.to=4000"] + SHORT
    lines = [l.split() for l in run([exe, case, out] + sets).splitlines() if l and not l.startswith("#")]
    ok(len(lines) == 4, "sweep: %d points printed (4)" % len(lines))
    for speed, branch, rms, motion, regime, steps in lines:
        s = cli_summary(os.path.join(SRC, "cases/guide/spur.ini"), ["operating.speed_rpm=" + speed] + SHORT,
                        os.path.join(tmp, "cli-" + speed))
        r = s["results"]
        close(float(rms), r["rms_accel_mps2"]["combined"], 1e-10, "sweep: %s rpm: RMS acceleration = the response run's" % speed)
        ok(motion == r["motion"] and regime == r["impact_regime"] and int(steps) == s["solver"]["steps"],
           "sweep: %s rpm: %s, %s, %s steps = the response run's %s, %s, %d" %
           (speed, motion, regime, steps, r["motion"], r["impact_regime"], s["solver"]["steps"]))
    with open(os.path.join(out, "summary.json")) as f:
        files = json.load(f)["files"]
    ok(sorted(files) == ["bifurcation.csv", "states.csv", "summary.json", "sweep.csv"] and files[-1] == "summary.json",
       "sweep: summary.json lists the sweep's tables, then itself: %s" % ", ".join(files))


def ltca(exe, tmp):
    ex = printed(run([exe]))
    s = cli_summary(os.path.join(SRC, "cases/guide/spur.ini"), ["scene.analysis=ltca"], os.path.join(tmp, "cli-ltca"))
    r = s["results"]
    for k, key in (("mean", "mean_mesh_stiffness_n_per_m"), ("min", "min_mesh_stiffness_n_per_m"),
                   ("max", "max_mesh_stiffness_n_per_m")):
        close(float(ex["stiffness_%s_n_per_m" % k]), r[key]["left"], 1e-10,
              "ltca: %s mesh stiffness of the pair written in C = geardyn run's on the case" % k)
    close(float(ex["lte_pp_arcsec"]), r["lte_pp_arcsec"], 1e-10, "ltca: LTE peak-to-peak = geardyn run's")
    close(float(ex["stiffness_mean_n_per_m"]), float(ex["iso6336_stiffness_n_per_m"]), 0.2,
          "ltca: mean mesh stiffness within 20 % of ISO 6336-1")


def basins(exe, tmp):
    for system, nref in (("twin", 2), ("five", 5)):
        ex = printed(run([exe, system, "10000"]))
        ok(int(ex["attractors"]) == nref, "basins %s: %s attractors (reference %d)" % (system, ex["attractors"], nref))
        other = sum(int(ex[k]) for k in ("diverged", "left-box", "iteration-cap", "integration-failed"))
        ok(other == 0, "basins %s: every state reached an attractor (%d did not)" % (system, other))
        seen = set()
        for r in range(nref):
            val = ex["fraction_%d" % r].split(";")[0].split()
            p, se, ref, ref_se = (float(x) for x in val[:4])
            comb = (se * se + ref_se * ref_se) ** 0.5
            ok(abs(p - ref) <= 3 * comb, "basins %s: fraction %.4f +- %.4f against the reference %.4f +- %.4f "
               "(%.2f combined standard errors; at most 3)" % (system, p, se, ref, ref_se, abs(p - ref) / comb))
            seen.add(ex["fraction_%d" % r].split("attractor ")[1].split(",")[0])
        ok(len(seen) == nref, "basins %s: each reference value on its own attractor (%s)" % (system, sorted(seen)))


def main():
    which, exe = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        {"response": response, "sweep": sweep, "ltca": ltca, "basins": basins}[which](exe, tmp)
    print("1..%d" % n_checks)
    return 0


if __name__ == "__main__":
    sys.exit(main())
