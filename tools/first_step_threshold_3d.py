#!/usr/bin/env python3
"""Least stabilisation that keeps the first backward-Euler step monotone on a tetrahedral column.

    tools/first_step_threshold_3d.py [--biphasic build/biphasic] [--tolerance 1e-3] [--out CSV]

The three-dimensional counterpart of tools/first_step_threshold.py (docs/formulation.md, "The
first step's monotonicity on the 1-D column"). It runs `biphasic run` on
cases/verification/oscillation/oscillation.toml: a column of 10 cubic cells (a = 0.1 mm, each
split into six tetrahedra), c = k H_A = 1e-3 mm^2/s, a step load q on the drained top, one
backward-Euler step of dt = r a^2 / c from rest. The overshoot is max p / q - 1 over every vertex
(the four vertical edges of the column hold all of them; each is sampled by a probe). For each
r it bisects (in log scale) for the least stabilisation.scale that brings the overshoot to the
tolerance, for the paper's GLS and for the flux perturbation, with the element length h the
circumradius (the paper's choice, 0.866 a here) and the shortest edge (a), and prints the
result in the 1-D column's units, layer thickness a:

    GLS:   gamma = c_e / (a^2 / (4k)) = scale (h/a)^2     1-D least value: max(0, 2/3 - 4r)
    flux:  b     = beta H_A / a^2    = scale (h/a)^2 / 4  1-D least value: max(0, 1/6 - r)

A scale of 1e4 that still leaves the overshoot above the tolerance is reported as "> 1e4".
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile

CASE = "cases/verification/oscillation/oscillation.toml"
A = 0.1          # cell size [mm]
C = 1e-3         # consolidation coefficient k (lambda + 2 mu) [mm^2/s]
Q = 1e-4         # step load [MPa]
EDGES = [(0.0, 0.0), (A, 0.0), (0.0, A), (A, A)]
LENGTH_RATIO = {"circumradius": math.sqrt(3.0) / 2.0, "shortest_edge": 1.0}


def write_case(path):
    """The verification case with a probe along each vertical edge of the column."""
    with open(CASE) as f:
        text = f.read()
    for i, (x, y) in enumerate(EDGES):
        text += (f"\n[[probe]]\nname = \"edge{i}\"\nstart = [{x}, {y}, 0.0]\n"
                 f"end = [{x}, {y}, 1.0]\n")
    with open(path, "w") as f:
        f.write(text)


def overshoot(biphasic, case, work, r, stabilisation, length, scale):
    """max p / q - 1 over the column's vertices after the first step."""
    dt = r * A * A / C
    out = os.path.join(work, "run")
    cmd = [biphasic, "run", case, "-o", out, "--overwrite", "--quiet",
           "--set", "output.fields=[]", "--set", f"time.dt={dt!r}", "--set", f"time.t_end={dt!r}",
           "--set", f'stabilisation.type="{stabilisation}"']
    if stabilisation != "none":
        cmd += ["--set", f'stabilisation.length="{length}"', "--set",
                f"stabilisation.scale={scale!r}"]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    p_max = -math.inf
    for i in range(len(EDGES)):
        with open(os.path.join(out, f"probe_edge{i}.csv")) as f:
            rows = [row for row in csv.DictReader(f) if abs(float(row["t"]) - dt) <= 1e-9 * dt]
        p_max = max(p_max, max(float(row["p"]) for row in rows))
    return p_max / Q - 1.0


def least_scale(run, tolerance, lo=1e-4, hi=1e4):
    """The least scale in [lo, hi] with run(scale) <= tolerance (bisection in log scale, the
    overshoot falling with the scale); 0 if the unstabilised step already meets it; inf if hi
    does not."""
    if run(lo) <= tolerance:
        return 0.0
    if run(hi) > tolerance:
        return math.inf
    for _ in range(40):
        mid = math.sqrt(lo * hi)
        if run(mid) <= tolerance:
            hi = mid
        else:
            lo = mid
        if hi / lo < 1.0 + 1e-3:
            break
    return hi


def text(x):
    return "> 1e4" if math.isinf(x) else f"{x:.4g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--biphasic", default="build/biphasic")
    ap.add_argument("--tolerance", type=float, default=1e-3)
    ap.add_argument("--out", help="also write the table as CSV")
    args = ap.parse_args()
    r_values = [1e-3, 1e-2, 0.05, 0.1, 1.0 / 6.0, 0.25, 0.3, 0.4, 0.5]
    rows = []
    with tempfile.TemporaryDirectory() as work:
        case = os.path.join(work, "column.toml")
        write_case(case)
        for r in r_values:
            none = overshoot(args.biphasic, case, work, r, "none", "circumradius", 1.0)
            row = {"r": r, "overshoot_none": none}
            for length, ratio in LENGTH_RATIO.items():
                for stabilisation, unit in (("gls", ratio ** 2), ("flux_perturbation", ratio ** 2 / 4)):
                    s = least_scale(lambda scale: overshoot(args.biphasic, case, work, r,
                                                            stabilisation, length, scale),
                                    args.tolerance)
                    paper = overshoot(args.biphasic, case, work, r, stabilisation, length, 1.0)
                    row[f"{stabilisation}_{length}"] = s * unit
                    row[f"{stabilisation}_{length}_paper_overshoot"] = paper
            rows.append(row)
            print(f"r = {r:.4g} done", file=sys.stderr, flush=True)
    print(f"Least coefficient for an overshoot <= {args.tolerance:g}, in the 1-D units (layer "
          "thickness a); the paper's coefficients are gamma = 0.75, b = 0.1875 with h = "
          "circumradius and gamma = 1, b = 0.25 with h = shortest edge.\n")
    print("| r | overshoot, none | GLS gamma (h = circumradius) | GLS gamma (h = shortest edge) "
          "| 1-D: 2/3 - 4r | flux b (h = circumradius) | flux b (h = shortest edge) | 1-D: 1/6 - r "
          "| overshoot with the paper's GLS / flux (circumradius) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for row in rows:
        r = row["r"]
        print(f"| {r:.4g} | {row['overshoot_none']:.3g} | {text(row['gls_circumradius'])} | "
              f"{text(row['gls_shortest_edge'])} | {max(0.0, 2 / 3 - 4 * r):.4g} | "
              f"{text(row['flux_perturbation_circumradius'])} | "
              f"{text(row['flux_perturbation_shortest_edge'])} | {max(0.0, 1 / 6 - r):.4g} | "
              f"{row['gls_circumradius_paper_overshoot']:.3g} / "
              f"{row['flux_perturbation_circumradius_paper_overshoot']:.3g} |")
    if args.out:
        with open(args.out, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
