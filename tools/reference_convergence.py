#!/usr/bin/python3
"""Measure how converged a reference solution is: run one case at a ladder of refinements in
space (and time tolerance) and compare the pressure along the probe line of each level with the
finest, with the discrepancy measure of the studies (docs/results.md): at every output time,
max |p_h - p_ref| over the level's pressure nodes on the line, divided by max |p_ref| on it.

usage: tools/reference_convergence.py [CASE] [--levels NRxNZ:RTOL,...] [-o DIR] [--dt S]
                                     [--set KEY=VALUE ...]

Defaults: cases/paper/axisymmetric_reference.toml, the levels 36x24:1e-6, 72x48:1e-7,
144x96:1e-8 (each halving the cells in both directions and tightening the BDF tolerance
tenfold), outputs every 0.32 s (the studies' output interval). Prints one row per level: its
unknowns and wall time, the discrepancy against the finest level at t = 32 s, its maximum over
t <= 1 s and over the whole run (from the first output on), and the same against the next finer
level (what "one more refinement changes" means). Writes DIR/convergence.csv. --set passes
overrides to every run; with output.line_points = n every level samples the same n points (the
measure then carries no interpolation between the levels' nodes).
"""
import argparse
import csv
import json
import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
BIN = pathlib.Path(os.environ.get("BIPHASIC_BIN", ROOT / "build" / "biphasic"))


def read_line(path):
    """{t: (s list, p list)} from a line.csv, sorted by arc length s."""
    out = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            t = round(float(row["t"]), 9)
            out.setdefault(t, ([], []))
            out[t][0].append(float(row["s"]))
            out[t][1].append(float(row["p"]))
    for t, (s, p) in out.items():
        order = sorted(range(len(s)), key=lambda i: s[i])
        out[t] = ([s[i] for i in order], [p[i] for i in order])
    return out


def interpolate(x, xs, ys):
    if x <= xs[0]:
        return ys[0]
    for i in range(1, len(xs)):
        if x <= xs[i]:
            w = (x - xs[i - 1]) / (xs[i] - xs[i - 1]) if xs[i] > xs[i - 1] else 0.0
            return ys[i - 1] + w * (ys[i] - ys[i - 1])
    return ys[-1]


def discrepancy(line, ref):
    """{t: max |p - p_ref| / max |p_ref|} over the line's pressure nodes (every other P2 node)."""
    out = {}
    for t, (s, p) in line.items():
        if t <= 0 or t not in ref:
            continue
        if len(s) % 2 == 1:
            s, p = s[::2], p[::2]
        sr, pr = ref[t]
        scale = max(abs(v) for v in pr)
        if scale > 0:
            out[t] = max(abs(pv - interpolate(sv, sr, pr)) for sv, pv in zip(s, p)) / scale
    return out


def summary_of(d):
    late = d[max(d)] if d else float("nan")
    early = max((v for t, v in d.items() if t <= 1.0 + 1e-9), default=float("nan"))
    return late, early, max(d.values(), default=float("nan"))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("case", nargs="?", default=str(ROOT / "cases/paper/axisymmetric_reference.toml"))
    ap.add_argument("--levels", default="36x24:1e-6,72x48:1e-7,144x96:1e-8")
    ap.add_argument("--dt", type=float, default=0.32, help="output interval [s]")
    ap.add_argument("-o", "--output", default=str(ROOT / "results/reference_convergence"))
    ap.add_argument("--set", action="append", default=[], help="override for every run")
    args = ap.parse_args()
    out = pathlib.Path(args.output)
    out.mkdir(parents=True, exist_ok=True)

    levels = []
    for spec in args.levels.split(","):
        cells, rtol = spec.split(":")
        nr, nz = (int(v) for v in cells.split("x"))
        levels.append((nr, nz, float(rtol)))
    runs = []
    for nr, nz, rtol in levels:
        run_dir = out / f"nr{nr}_nz{nz}_rtol{rtol:g}"
        if not (run_dir / "summary.json").is_file() or \
                json.loads((run_dir / "summary.json").read_text()).get("status") != "completed":
            cmd = [str(BIN), "run", args.case, "-o", str(run_dir), "--overwrite", "--quiet",
                   "--set", f"mesh.section.nr={nr}", "--set", f"mesh.section.nz={nz}",
                   "--set", f"time.bdf.rtol={rtol}", "--set", f"time.dt={args.dt}"]
            for extra in args.set:
                cmd += ["--set", extra]
            print(" ".join(cmd), file=sys.stderr, flush=True)
            subprocess.run(cmd, check=True)
        s = json.loads((run_dir / "summary.json").read_text())
        runs.append({"nr": nr, "nz": nz, "rtol": rtol, "unknowns": s["mesh"]["unknowns"],
                     "wall_s": s["timings"]["wall"], "line": read_line(run_dir / "line.csv")})

    finest = runs[-1]["line"]
    rows = []
    for i, r in enumerate(runs):
        vs_finest = summary_of(discrepancy(r["line"], finest)) if i + 1 < len(runs) else (0, 0, 0)
        vs_next = (summary_of(discrepancy(r["line"], runs[i + 1]["line"]))
                   if i + 1 < len(runs) else (float("nan"),) * 3)
        rows.append({"nr": r["nr"], "nz": r["nz"], "rtol": r["rtol"], "unknowns": r["unknowns"],
                     "wall_s": round(r["wall_s"], 2),
                     "finest_t32": vs_finest[0], "finest_t_le_1": vs_finest[1],
                     "finest_max": vs_finest[2],
                     "next_t32": vs_next[0], "next_t_le_1": vs_next[1], "next_max": vs_next[2]})
    with open(out / "convergence.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print("| cells | rtol | unknowns | wall [s] | vs finest: t = 32 s | t <= 1 s | max over t |"
          " vs next: t = 32 s | t <= 1 s | max over t |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    pct = lambda v: "n/a" if v != v else f"{100 * v:.3g} %"
    for r in rows:
        print(f"| {r['nr']} x {r['nz']} | {r['rtol']:g} | {r['unknowns']} | {r['wall_s']} | "
              f"{pct(r['finest_t32'])} | {pct(r['finest_t_le_1'])} | {pct(r['finest_max'])} | "
              f"{pct(r['next_t32'])} | {pct(r['next_t_le_1'])} | {pct(r['next_max'])} |")


if __name__ == "__main__":
    main()
