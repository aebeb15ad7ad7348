#!/usr/bin/env python3
"""ParaView reads the field output.

Runs a column stretched homogeneously (F = diag(1, 1, 1.2), uniform pore pressure) with every
field quantity selected, then loads fields.xdmf with both of ParaView's XDMF readers (the XDMF
2 reader "XDMFReader" and the XDMF 3 reader "Xdmf3ReaderS", through pvbatch) and checks the
arrays: names, point or cell data, tuples, components, and the values of the last output
against the Neo-Hookean closed form. Exits 77 (skipped) if pvbatch is not installed.

Usage: paraview_reads_fields.py WORK_DIR  (BIPHASIC_BIN names the solver)
"""
import math
import os
import shutil
import subprocess
import sys

MU, LAMBDA, PRESSURE, STRETCH, HEIGHT = 0.5, 0.3, 0.05, 1.2, 2.0
FIELDS = ["displacement", "pressure", "stress", "effective_stress", "J", "flux", "permeability"]
SKIPPED = 77


def column_case():
    lines = [
        "format_version = 1",
        '[mesh]\nsource = "column"',
        f"[mesh.column]\nwidth = 1.0\ndepth = 1.5\nheight = {HEIGHT}\nnz = 2",
        f"[material]\nmu = {MU}\nlambda = {LAMBDA}\npermeability = 1e-3",
        "[curves]\nramp = [[0.0, 0.0], [1.0, 1.0]]",
        '[[boundary]]\nname = "top"\ntype = "displacement"\ncomponent = "z"\n'
        f'value = {(STRETCH - 1.0) * HEIGHT}\ncurve = "ramp"',
        '[[boundary]]\nname = "bottom"\ntype = "displacement"\ncomponent = "z"\nvalue = 0',
    ]
    for face in ["x0", "x1", "y0", "y1"]:
        lines.append(f'[[boundary]]\nname = "{face}"\ntype = "symmetry"')
    for face in ["top", "bottom", "x0", "x1", "y0", "y1"]:
        lines.append(f'[[boundary]]\nname = "{face}"\ntype = "pressure"\nvalue = {PRESSURE}')
    lines.append("[time]\nt_end = 1.0\ndt = 0.5")
    lines.append('[linear_solver]\ntype = "klu"\nordering = "amd"')
    quoted = ", ".join(f'"{f}"' for f in FIELDS)
    lines.append(f"[output]\nline = false\nfields = [{quoted}]")
    return "\n".join(lines) + "\n"


def expected_stress(effective):
    """Cauchy stress of F = diag(1, 1, s), row by row (9 components)."""
    s = STRETCH
    lateral = LAMBDA * math.log(s) / s - (0.0 if effective else PRESSURE)
    axial = MU / s * (s * s - 1.0) + lateral
    return [lateral, 0, 0, 0, lateral, 0, 0, 0, axial]


def check_reader(name, reader, failures):
    """Checks one reader's output at t = 1 s; appends what is wrong to `failures`."""
    from paraview import servermanager

    reader.UpdatePipeline(1.0)
    data = servermanager.Fetch(reader)
    if data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    cells, points = data.GetNumberOfCells(), data.GetNumberOfPoints()
    expected_arrays = {
        "displacement": ("point", 3, None),
        "pressure": ("point", 1, None),
        "stress": ("cell", 9, expected_stress(False)),
        "effective_stress": ("cell", 9, expected_stress(True)),
        "J": ("cell", 1, [STRETCH]),
        "flux": ("cell", 3, [0.0, 0.0, 0.0]),
        "permeability": ("cell", 1, [1e-3]),
    }
    for array, (centre, components, values) in expected_arrays.items():
        attributes = data.GetPointData() if centre == "point" else data.GetCellData()
        a = attributes.GetArray(array)
        if a is None:
            failures.append(f"{name}: no {centre} array {array}")
            continue
        tuples = points if centre == "point" else cells
        if a.GetNumberOfTuples() != tuples or a.GetNumberOfComponents() != components:
            failures.append(f"{name}: {array} is {a.GetNumberOfTuples()} x "
                            f"{a.GetNumberOfComponents()}, expected {tuples} x {components}")
            continue
        for i in range(tuples if values else 0):
            got = a.GetTuple(i)
            if any(abs(g - v) > 1e-9 for g, v in zip(got, values)):
                failures.append(f"{name}: {array} of cell {i} is {got}, expected {values}")
                break
    print(f"{name}: {cells} cells, {points} points, times {list(reader.TimestepValues)}")


def load(xdmf):
    """Inside pvbatch: both readers, every array."""
    from paraview import simple

    failures = []
    check_reader("XDMFReader", simple.XDMFReader(FileNames=[xdmf]), failures)
    check_reader("Xdmf3ReaderS", simple.Xdmf3ReaderS(FileName=[xdmf]), failures)
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--load":
        return load(sys.argv[2])
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    pvbatch = shutil.which("pvbatch")
    if pvbatch is None:
        print("pvbatch not found (Debian: paraview and python3-paraview): skipped")
        return SKIPPED
    work = sys.argv[1]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    case = os.path.join(work, "column.toml")
    with open(case, "w") as f:
        f.write(column_case())
    out = os.path.join(work, "run")
    subprocess.run([os.environ["BIPHASIC_BIN"], "run", case, "-o", out, "--quiet"], check=True)
    xdmf = os.path.join(out, "fields.xdmf")
    return subprocess.run([pvbatch, "--force-offscreen-rendering", os.path.abspath(__file__),
                           "--load", xdmf]).returncode


if __name__ == "__main__":
    sys.exit(main())
