#!/usr/bin/python3
"""End-to-end test of tools/study.py on cases/studies/quick.toml (a few seconds).

Asserts: every run completes and lands in the table with its parameters and counters; the
discrepancy against the (coarse) reference is computed and small where the solution is smooth;
GLS lowers the overshoot of the unstabilised runs; a second invocation skips every run; a
figure is drawn from the table; bad study files are refused before any run, naming the file
and the key. usage: test_study_runner.py WORK_DIR
"""
import csv
import math
import os
import pathlib
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
STUDY = ROOT / "tools" / "study.py"
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def run(args, env):
    return subprocess.run([sys.executable, str(STUDY)] + args, capture_output=True, text=True,
                          env=env)


def main():
    work = pathlib.Path(sys.argv[1])
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    env = dict(os.environ, BIPHASIC_REFERENCE_CACHE=str(work / "references"))
    out = work / "quick"
    r = run([str(ROOT / "cases" / "studies" / "quick.toml"), "-o", str(out), "--jobs", "2"], env)
    print(r.stdout, r.stderr)
    check(r.returncode == 0, f"study exit code {r.returncode}")
    rows = list(csv.DictReader(open(out / "runs.csv")))
    check(len(rows) == 4, f"4 rows, got {len(rows)}")
    by = {(float(x["dt"]), x["stabilisation"]): x for x in rows}
    for x in rows:
        check(x["status"] == "completed", f"{x['run']} completed")
        check(math.isclose(float(x["strain"]), 0.002, rel_tol=1e-9), f"{x['run']} strain 0.2 %")
        check(math.isclose(float(x["t_end"]), 6.4, rel_tol=1e-9), f"{x['run']} t_end 6.4 s")
        check(int(x["steps"]) == round(6.4 / float(x["dt"])), f"{x['run']} steps")
        check(int(x["factorizations"]) >= 1 and float(x["wall_s"]) > 0, f"{x['run']} counters")
        d = float(x["discrepancy"]) if x["discrepancy"] else math.nan
        check(0 < d < 0.5, f"{x['run']} discrepancy {d} in (0, 0.5)")
        check("reference_quick.toml" in x["reference"], f"{x['run']} names its reference")
    for dt in (3.2, 6.4):
        none, gls = by[(dt, "none")], by[(dt, "gls")]
        check(float(gls["overshoot_max"]) < float(none["overshoot_max"]),
              f"dt {dt}: GLS overshoot {gls['overshoot_max']} < none {none['overshoot_max']}")
    # Again: nothing to run, same table.
    r = run([str(ROOT / "cases" / "studies" / "quick.toml"), "-o", str(out)], env)
    check(r.returncode == 0 and "4 runs already done; 0 to run" in r.stdout,
          f"second invocation skips the runs: {r.stdout}")
    check(len(list(csv.DictReader(open(out / "runs.csv")))) == 4, "table kept")
    # A figure from the table.
    p = subprocess.run(["/usr/bin/python3", str(ROOT / "tools" / "plot_study.py"), "work", str(out),
                        "-o", str(work / "figures")], capture_output=True, text=True)
    check(p.returncode == 0 and (work / "figures" / "work_precision_wall.png").is_file(),
          f"work-precision figure: {p.stderr}")
    # Bad study files: clear errors before any run.
    bad = work / "bad.toml"
    bad.write_text(f'base = "{ROOT}/cases/paper/mesh1_k1e-3_gls.toml"\n'
                   '[[sweep]]\nvary = { "material.permeabilty" = [1e-3] }\n')
    r = run([str(bad), "-o", str(work / "bad")], env)
    check(r.returncode != 0 and "material.permeabilty" in r.stderr and "bad.toml" in r.stderr,
          f"misspelt key named: {r.stderr}")
    check(not (work / "bad" / "runs").exists(), "no run started for a bad study")
    bad.write_text('[[sweep]]\nvary = { "time.dt" = [1.0] }\n')
    r = run([str(bad)], env)
    check(r.returncode != 0 and "'base'" in r.stderr, f"missing base named: {r.stderr}")
    bad.write_text(f'base = "{ROOT}/cases/paper/mesh1_k1e-3_gls.toml"\n'
                   '[[sweep]]\nvary = { "mesh" = [5] }\n')
    r = run([str(bad)], env)
    check(r.returncode != 0 and "mesh = 5" in r.stderr, f"unknown paper mesh named: {r.stderr}")
    if failures:
        sys.exit(f"{len(failures)} check(s) failed")
    print("all checks passed")


if __name__ == "__main__":
    main()
