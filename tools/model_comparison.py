#!/usr/bin/python3
"""Model no more than the scene needs: the paper's scene (k = 1e-3, 1 % strain at 2.5 um/s)
solved by the three-dimensional quarter cylinders and by the axisymmetric model, each run's
axis pressure measured against one reference with the discrepancy of docs/results.md
(max |p_h - p_ref| over the run's pressure nodes on the axis / max |p_ref|), at t = 32 s and
over all outputs from the first on, with its unknowns and wall time.

usage: tools/model_comparison.py --reference DIR [-o DIR] [--only NAME,...] [--skip-3d]

DIR of --reference is a run of the scene with outputs every 0.32 s (for instance the finest
level of tools/reference_convergence.py). The runs (names in the table):
  3d_mesh{1..4}_{nogls,gls}   cases/paper/mesh{n}_k1e-3_*.toml (backward Euler, dt = 6.4 s)
  3d_swept                    cases/studies/reference.toml (swept, graded; BDF rtol 1e-5)
  axi_mesh{1..4}_{nogls,gls}  the axisymmetric model at the axis resolution of mesh n
                              (cells of lc in r and z), backward Euler, dt = 6.4 s
  axi_graded_{NZ}_{be,bdf}    the axisymmetric model graded 30:1 toward the platens with NZ
                              cells over the height and NZ cells across, backward Euler
                              (dt = 6.4 s) or BDF (rtol 1e-5, outputs every 0.32 s)
Writes DIR/comparison.csv and prints a Markdown table.
"""
import argparse
import csv
import json
import os
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from reference_convergence import discrepancy, read_line  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
BIN = pathlib.Path(os.environ.get("BIPHASIC_BIN", ROOT / "build" / "biphasic"))
LC = {1: 1.3, 2: 0.98, 3: 0.73, 4: 0.57}
AXI = ROOT / "cases/paper/axisymmetric_k1e-3_nogls.toml"


def runs():
    out = []
    for n in (1, 2, 3, 4):
        for st in ("nogls", "gls"):
            out.append((f"3d_mesh{n}_{st}", ROOT / f"cases/paper/mesh{n}_k1e-3_{st}.toml",
                        ["output.fields=false"]))
    out.append(("3d_swept", ROOT / "cases/studies/reference.toml", ["output.fields=false"]))
    for n in (1, 2, 3, 4):
        nr, nz = round(18.0 / LC[n]), round(8.0 / LC[n])
        for st, t in (("nogls", "none"), ("gls", "gls")):
            out.append((f"axi_mesh{n}_{st}", AXI,
                        [f"mesh.section.nr={nr}", f"mesh.section.nz={nz}",
                         f"stabilisation.type=\"{t}\"", "output.fields=false"]))
    for nz in (8, 12, 16, 24, 32, 48):
        common = [f"mesh.section.nr={nz}", f"mesh.section.nz={nz}",
                  "mesh.section.grading_curves=[\"bottom\",\"top\"]",
                  "mesh.section.grading_ratio=30", "output.fields=false"]
        out.append((f"axi_graded_{nz}_be", AXI, common))
        out.append((f"axi_graded_{nz}_bdf", AXI, common + [
            "time.integrator=\"bdf\"", "time.dt=0.32", "time.bdf.rtol=1e-5",
            "linear_solver.type=\"klu\""]))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--reference", required=True)
    ap.add_argument("-o", "--output", default=str(ROOT / "results/model_comparison"))
    ap.add_argument("--only", default="", help="comma-separated run names (default: all)")
    ap.add_argument("--skip-3d", action="store_true")
    args = ap.parse_args()
    out = pathlib.Path(args.output)
    out.mkdir(parents=True, exist_ok=True)
    ref = read_line(pathlib.Path(args.reference) / "line.csv")
    only = set(filter(None, args.only.split(",")))
    rows = []
    for name, case, sets in runs():
        if (only and name not in only) or (args.skip_3d and name.startswith("3d")):
            continue
        run_dir = out / name
        summary = run_dir / "summary.json"
        if not summary.is_file() or json.loads(summary.read_text()).get("status") != "completed":
            cmd = [str(BIN), "run", str(case), "-o", str(run_dir), "--overwrite", "--quiet"]
            for s in sets:
                cmd += ["--set", s]
            print(" ".join(cmd), file=sys.stderr, flush=True)
            subprocess.run(cmd, check=True)
        s = json.loads(summary.read_text())
        d = discrepancy(read_line(run_dir / "line.csv"), ref)
        rows.append({"run": name, "unknowns": s["mesh"]["unknowns"],
                     "wall_s": round(s["timings"]["wall"], 3),
                     "discrepancy_t32": d[max(d)] if d else None,
                     "discrepancy_max": max(d.values()) if d else None})
    with open(out / "comparison.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print("| run | unknowns | wall [s] | discrepancy t = 32 s | max over t |")
    print("|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['run']} | {r['unknowns']} | {r['wall_s']} | "
              f"{100 * r['discrepancy_t32']:.3g} % | {100 * r['discrepancy_max']:.3g} % |")


if __name__ == "__main__":
    main()
