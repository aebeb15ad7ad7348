#!/usr/bin/python3
"""The worked example cases/examples/cartilage_plug/ end to end, short variant: the gmsh script
makes a coarse plug mesh with its named groups, both cases check on it, the creep case runs two
outputs (its platen settles the undrained amount sigma H / (3 mu) at once, then creeps; its
reaction is the load), the relaxation case runs its first outputs, and the plot script draws the
creep curve.

usage: test_cartilage_plug_example.py SCRATCH_DIR (BIPHASIC_BIN = the program)
"""
import csv
import json
import os
import pathlib
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = os.environ["BIPHASIC_BIN"]
PY = "/usr/bin/python3"
EXAMPLE = ROOT / "cases/examples/cartilage_plug"


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{' '.join(map(str, cmd))} exited {r.returncode}:\n{r.stdout}\n{r.stderr}")
    return r.stdout


def main():
    scratch = pathlib.Path(sys.argv[1])
    shutil.rmtree(scratch, ignore_errors=True)
    scratch.mkdir(parents=True)
    mesh = scratch / "plug.msh"
    print(run([PY, ROOT / "tools/examples/cartilage_plug_mesh.py", mesh, "--lc", "0.3"]).strip())
    text = mesh.read_text()
    for name in ("bottom", "top", "lateral", "symmetry_x", "symmetry_y", "cartilage"):
        assert f'"{name}"' in text, f"physical group {name} missing from the mesh"
    use_mesh = ["--set", f"mesh.file=\"{mesh}\""]
    for case in ("unconfined_creep.toml", "confined_relaxation.toml"):
        run([BIN, "check", EXAMPLE / case] + use_mesh)

    creep = scratch / "creep"
    run([BIN, "run", EXAMPLE / "unconfined_creep.toml", "-o", creep, "--quiet",
         "--set", "time.t_end=120", "--set", "output.fields=false"] + use_mesh)
    with open(creep / "platens.csv") as f:
        rows = list(csv.DictReader(f))
    w = {float(r["t"]): float(r["displacement"]) for r in rows}
    assert sorted(w) == [0.0, 60.0, 120.0], sorted(w)
    undrained = 0.05 * 1.5 / (3 * 0.27)  # sigma H / (3 mu) [mm], incompressible at t = 0+
    assert 0.95 * undrained < -w[60.0] < 1.08 * undrained, (w, undrained)
    assert -w[120.0] > -w[60.0], f"no creep: {w}"
    summary = json.loads((creep / "summary.json").read_text())
    assert summary["status"] == "completed"
    force = summary["outputs"][-1]["platens"]["top"]["force"]
    top = summary["outputs"][-1]["reactions"]["top"][2]
    bottom = summary["outputs"][-1]["reactions"]["bottom"][2]
    assert abs(top - force) < 1e-8 * abs(force), (top, force)
    assert abs(top + bottom) < 1e-6 * abs(force), (top, bottom)
    print(f"creep: settlement {-w[60.0]:.4f} mm at 60 s (undrained {undrained:.4f}), "
          f"{-w[120.0]:.4f} mm at 120 s")

    relax = scratch / "relaxation"
    run([BIN, "run", EXAMPLE / "confined_relaxation.toml", "-o", relax, "--quiet",
         "--set", "time.t_end=40"] + use_mesh)
    summary = json.loads((relax / "summary.json").read_text())
    assert summary["status"] == "completed"
    assert summary["outputs"][-1]["reactions"]["top"][2] < 0  # the platen pushes down
    assert (relax / "fields.xdmf").is_file() and (relax / "fields.h5").is_file()

    run([PY, ROOT / "tools/plot_platens.py", creep, "--strain", "1.5", "-o", scratch / "creep"])
    for ext in ("png", "pdf"):
        assert (scratch / f"creep.{ext}").stat().st_size > 1000, ext
    print("ok")


if __name__ == "__main__":
    main()
