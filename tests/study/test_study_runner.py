#!/usr/bin/python3
"""End-to-end test of tools/study.py on cases/studies/quick.toml (a few seconds).

Asserts: every run completes and lands in the table with its parameters and counters; the
discrepancy against the (coarse) axisymmetric reference and against the 3-D cross-check
reference is computed, small where the solution is smooth, and the two agree; the axisymmetric
reference was solved with the runs' loading and permeability; GLS lowers the overshoot of the
unstabilised runs; a second invocation skips every run; --skip-reference-check drops the
cross-check; a figure is drawn from the table; the physical problems of a 3-D run and of the
axisymmetric reference compare equal, and differ when they should; bad study files, and a
physical override that cannot reach the reference, are refused before any run, naming the
file and the key. usage: test_study_runner.py WORK_DIR
"""
import csv
import json
import math
import os
import pathlib
import shutil
import subprocess
import sys
import tomllib

ROOT = pathlib.Path(__file__).resolve().parents[2]
STUDY = ROOT / "tools" / "study.py"
sys.path.insert(0, str(ROOT / "tools"))
import study  # noqa: E402
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
        check("reference_quick_axisymmetric.toml (axisymmetric" in x["reference"],
              f"{x['run']} names its reference: {x['reference']}")
        check("reference_quick.toml (three_dimensional" in x["reference_check"],
              f"{x['run']} names its cross-check reference: {x['reference_check']}")
        dc = float(x["discrepancy_check"]) if x["discrepancy_check"] else math.nan
        check(0 < dc < 0.5, f"{x['run']} discrepancy against the cross-check {dc} in (0, 0.5)")
        # Both references resolve the same problem: the run's error dominates their difference
        # (the coarse 3-D one is itself some 5 % of max p off at the end).
        check(abs(d - dc) < 0.4 * max(d, dc), f"{x['run']}: discrepancy {d} against the "
              f"axisymmetric reference, {dc} against the 3-D one")
    # The axisymmetric reference got the runs' loading (0.2 % strain at 2.5 um/s) and k.
    ref_dir = pathlib.Path(rows[0]["reference"].split()[-1])
    ref_dir = ref_dir if ref_dir.is_absolute() else ROOT / ref_dir
    s = json.loads((ref_dir / "summary.json").read_text())
    c = s["configuration"]
    top = next(b for b in c["boundary"] if b["name"] == "top" and b["type"] == "displacement")
    check(s["model"] == "axisymmetric" and s["status"] == "completed", "axisymmetric reference ran")
    check(math.isclose(top["value"], -0.016, rel_tol=1e-9) and top["component"] == "y",
          f"reference platen displacement {top}")
    check(math.isclose(c["time"]["t_end"], 6.4, rel_tol=1e-9), "reference t_end 6.4 s")
    check(c["curves"][top["curve"]] == [[0.0, 0.0], [6.4, 1.0]], f"reference ramp {c['curves']}")
    check(math.isclose(c["material"]["permeability"], 1e-3), "reference permeability")
    for dt in (3.2, 6.4):
        none, gls = by[(dt, "none")], by[(dt, "gls")]
        check(float(gls["overshoot_max"]) < float(none["overshoot_max"]),
              f"dt {dt}: GLS overshoot {gls['overshoot_max']} < none {none['overshoot_max']}")
        for col in ("discrepancy", "discrepancy_check"):
            check(float(gls[col]) < float(none[col]),
                  f"dt {dt}: GLS {col} {gls[col]} < none {none[col]} (both references agree)")
    # Again: nothing to run, same table.
    r = run([str(ROOT / "cases" / "studies" / "quick.toml"), "-o", str(out)], env)
    check(r.returncode == 0 and "4 runs already done; 0 to run" in r.stdout,
          f"second invocation skips the runs: {r.stdout}")
    check(len(list(csv.DictReader(open(out / "runs.csv")))) == 4, "table kept")
    r = run([str(ROOT / "cases" / "studies" / "quick.toml"), "-o", str(out),
             "--skip-reference-check"], env)
    rows = list(csv.DictReader(open(out / "runs.csv")))
    check(r.returncode == 0 and "discrepancy_check" not in rows[0] and
          all(x["discrepancy"] for x in rows), f"--skip-reference-check: {r.stderr}")
    # The physical problem of a 3-D run and of the axisymmetric reference, directly.
    base = tomllib.loads((ROOT / "cases" / "paper" / "mesh1_k1e-3_gls.toml").read_text())
    axi = tomllib.loads((ROOT / "cases" / "studies" / "reference_axisymmetric.toml").read_text())
    check(study.physical_differences(base, axi) == [], "3-D paper case and axisymmetric "
          f"reference: same problem, got {study.physical_differences(base, axi)}")
    for what, overrides in (("permeability", {"material.permeability": 1e-2}),
                            ("platen displacement", {"boundary[0].value": -0.16}),
                            ("ramp", {"curves.ramp": [[0.0, 0.0], [64.0, 1.0]]}),
                            ("radius", {"mesh.radius": 9.0}),
                            ("a symmetry plane", {"boundary[2].type": "pressure",
                                                  "boundary[2].value": 0.0}),
                            ("a sealed lateral face drained", {"boundary[6]": {
                                "name": "lateral", "type": "pressure", "value": 0.0}}),
                            ("the probe line", {"output.line_end": [0.0, 0.0, 4.0]})):
        diff = study.physical_differences(study.with_overrides(base, overrides), axi)
        check(len(diff) >= 1, f"{what} changed: the problems differ")
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
    # A physical override the reference cannot take (a pressure on the drained top, by index in
    # the 3-D case): refused before any run, naming the condition and the reference.
    bad.write_text(f'base = "{ROOT}/cases/paper/mesh1_k1e-3_gls.toml"\n'
                   f'reference = "{ROOT}/cases/studies/reference_quick_axisymmetric.toml"\n'
                   '[[sweep]]\nvary = { "boundary[4].value" = [0.01] }\n')
    r = run([str(bad), "-o", str(work / "bad")], env)
    check(r.returncode != 0 and "reference_quick_axisymmetric.toml" in r.stderr and
          "condition pressure on 'top'" in r.stderr, f"unreachable override named: {r.stderr}")
    check(not (work / "bad" / "runs").exists(), "no run started for an unreachable override")

    # A geometry other than the paper's: a 1 mm confined column (10 % over 100 s), stopped at
    # 20 s. Strain and rate come from the column's own extent and curve; the reactions are
    # columns; `columns` chooses and orders the table.
    wanted = ["run", "status", "loading", "strain", "loading_rate_um_s", "reaction_top_z",
              "reaction_bottom_z"]
    column = work / "column.toml"
    column.write_text(
        f'base = "{ROOT}/cases/verification/confined_compression/confined_compression.toml"\n'
        'set = { "time.t_end" = 20.0, "time.dt" = 10.0 }\n'
        f'columns = {json.dumps(wanted)}\n'
        '[[sweep]]\nname = "k"\nvary = { "material.permeability" = [1e-3, 2e-3] }\n')
    r = run([str(column), "-o", str(work / "column")], env)
    check(r.returncode == 0, f"column study: {r.stdout} {r.stderr}")
    with open(work / "column" / "runs.csv") as f:
        header = next(csv.reader(f))
    check(header == wanted, f"columns as listed: {header}")
    for x in csv.DictReader(open(work / "column" / "runs.csv")):
        check(x["loading"] == "displacement z on 'top'", f"loading named: {x['loading']}")
        check(math.isclose(float(x["strain"]), 0.02, rel_tol=1e-9),
              f"strain of the 1 mm column at 20 s: {x['strain']}")
        check(math.isclose(float(x["loading_rate_um_s"]), 1.0, rel_tol=1e-9),
              f"rate 0.1 mm / 100 s: {x['loading_rate_um_s']}")
        top, bottom = float(x["reaction_top_z"]), float(x["reaction_bottom_z"])
        check(top < 0 and math.isclose(top, -bottom, rel_tol=1e-6),
              f"platen reactions balance: {top}, {bottom}")
    column.write_text(column.read_text().replace('"reaction_bottom_z"', '"reaction_botom_z"'))
    r = run([str(column), "-o", str(work / "column")], env)
    check(r.returncode != 0 and "reaction_botom_z" in r.stderr and "reaction_bottom_z" in r.stderr,
          f"an unknown column is named with the available ones: {r.stderr}")
    if failures:
        sys.exit(f"{len(failures)} check(s) failed")
    print("all checks passed")


if __name__ == "__main__":
    main()
