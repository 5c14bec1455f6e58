"""Two or more explicit tables side by side at equal tolerances (docs/accuracy.md section 4.5).

Usage: compare_tables.py GEARDYN_EXE
  env TABLES (comma-separated ARKODE table names; default Fehlberg 7(8) and Verner 8(7)),
      RTOLS (default 1e-6..1e-10), SCENES (labels below; default all), EXTRA (more --set values)
For every scene: a reference (order 8, rtol 1e-13, largest step 0.002 period, samples on step
ends), then each table at each rtol with atol = rtol/100, from the static state. Prints RHS
evaluations and wall time per mesh period and the Poincare and RMS errors (the metric of
compare_geardyn_scipy.py)."""
import os, sys, tempfile
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import scipy_gear as sg
import compare_geardyn_scipy as C
exe = os.path.abspath(sys.argv[1])
tables = os.environ.get("TABLES", "ARKODE_FEHLBERG_13_7_8,ARKODE_VERNER_13_7_8").split(',')
scenes = [("tors", os.path.join(ROOT, "cases/quickstart.ini"), ["scene.model=torsional"], 100),
          ("bta7000", os.path.join(ROOT, "cases/accuracy/period1-7000rpm.ini"), [], 20),
          ("bta2000", os.path.join(ROOT, "cases/accuracy/periodn-2000rpm.ini"), [], 20),
          ("bta500", os.path.join(ROOT, "cases/accuracy/period1-7000rpm.ini"), ["operating.speed_rpm=500"], 10),
          ("chaotic1500", os.path.join(ROOT, "cases/accuracy/chaotic-1500rpm.ini"), [], 10),
          ("rattle4000", os.path.join(ROOT, "cases/accuracy/rattle-4000rpm.ini"), [], 20),
          ("stiff", os.path.join(ROOT, "cases/accuracy/stiff-supports.ini"), [], 20)]
only = os.environ.get("SCENES")
rt = [float(x) for x in os.environ.get("RTOLS", "1e-6,1e-7,1e-8,1e-9,1e-10").split(',')]
atolr = os.environ.get("ATOL", "ratio")
tmp = tempfile.mkdtemp(prefix="gd_tables_")
for lab, case, extra, per in scenes:
    if only and lab not in only.split(','): continue
    base = extra + ["run.record_periods=%d" % per]
    ref = C.geardyn_run(exe, case, base + ["solver.order=8", "solver.rtol=1e-13", "solver.atol=1e-15", "solver.max_step_fraction=0.002", "solver.exact_samples=on"], os.path.join(tmp, "ref"))
    for r in rt:
        line = []
        for t in tables:
            at = r/100 if atolr == "ratio" else float(atolr)
            g = C.geardyn_run(exe, case, base + ["solver.table=%s" % t, "solver.rtol=%g" % r, "solver.atol=%g" % at] + os.environ.get("EXTRA","").split(), os.path.join(tmp, "g"), repeats=3)
            err = sg.poincare_error(g["pts"], ref["pts"]); rerr = abs(g["rms"] - ref["rms"]) / ref["rms"]
            line.append("%s: %6.1f us rhs %6.0f P %.1e R %.1e" % (t.replace("ARKODE_", ""), 1e6*g["wall_s"]/per, g["rhs"]/per, err, rerr))
        print(lab, "%g" % r, " | ".join(line)); sys.stdout.flush()
