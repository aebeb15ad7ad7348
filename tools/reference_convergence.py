#!/usr/bin/python3
"""Measure how converged a reference solution is: run one case at a ladder of refinements in
space (and time tolerance) and compare the pressure along the probe line of each level with the
finest, with the discrepancy measure of the studies (docs/results.md): at every output time,
max |p_h - p_ref| over the line, divided by max |p_ref| on it.

usage: tools/reference_convergence.py [CASE] [--levels NRxNZ:RTOL[:RATIO],...] [-o DIR]
                                     [--dt S] [--line-points N] [--set KEY=VALUE ...]

Defaults: cases/studies/reference_axisymmetric.toml and the levels 2x96:1e-6, 4x192:1e-7,
8x384:1e-8, 16x768:1e-9 (each halving the cells in both directions and tightening the BDF
tolerance tenfold; RATIO, if given, sets the level's mesh.section.grading_ratio, else the
case's), outputs every 0.32 s (the studies' output interval) and 4001 evenly spaced samples of
the line (one every 2 um over the 8 mm axis), the same for every level, so that the measure
involves no interpolation between the levels' meshes and resolves the thin layers at the
drained faces at the first outputs. --line-points 0 samples each level at its own mesh nodes
instead (the measure then takes the P1 vertices, every other node, as the studies do).

Prints one row per level: its unknowns and wall time, the discrepancy against the finest level
at t = 32 s (the last output), its maximum over t <= 1 s and over the whole run (from the first
output on), and the same against the next finer level (what "one more refinement changes"
means). Writes DIR/convergence.csv (one row per level) and DIR/changes.csv (the change against
the next finer level at every output time). --set passes overrides to every run.
"""
import argparse
import bisect
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
    """Piecewise-linear ys(x) on sorted xs (constant beyond the ends)."""
    if x <= xs[0]:
        return ys[0]
    i = bisect.bisect_left(xs, x)
    if i >= len(xs):
        return ys[-1]
    w = (x - xs[i - 1]) / (xs[i] - xs[i - 1]) if xs[i] > xs[i - 1] else 0.0
    return ys[i - 1] + w * (ys[i] - ys[i - 1])


def discrepancy(line, ref, vertices_only=True):
    """{t: max |p - p_ref| / max |p_ref|} over the line's pressure nodes (every other P2 node of
    a line sampled at the mesh nodes), or over every sample with vertices_only=False (a line of
    evenly spaced interpolated points)."""
    out = {}
    for t, (s, p) in line.items():
        if t <= 0 or t not in ref:
            continue
        if vertices_only and len(s) % 2 == 1:
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
    ap.add_argument("case", nargs="?",
                    default=str(ROOT / "cases/studies/reference_axisymmetric.toml"))
    ap.add_argument("--levels", default="2x96:1e-6,4x192:1e-7,8x384:1e-8,16x768:1e-9")
    ap.add_argument("--dt", type=float, default=0.32, help="output interval [s]")
    ap.add_argument("--line-points", type=int, default=4001,
                    help="evenly spaced samples of the line for every level (0: mesh nodes)")
    ap.add_argument("-o", "--output", default=str(ROOT / "results/reference_convergence"))
    ap.add_argument("--set", action="append", default=[], help="override for every run")
    args = ap.parse_args()
    out = pathlib.Path(args.output)
    out.mkdir(parents=True, exist_ok=True)

    levels = []
    for spec in args.levels.split(","):
        parts = spec.split(":")
        if len(parts) not in (2, 3):
            sys.exit(f"reference_convergence: level '{spec}': expected NRxNZ:RTOL[:RATIO]")
        nr, nz = (int(v) for v in parts[0].split("x"))
        levels.append((nr, nz, float(parts[1]), float(parts[2]) if len(parts) == 3 else None))
    runs = []
    for nr, nz, rtol, ratio in levels:
        run_dir = out / (f"nr{nr}_nz{nz}_rtol{rtol:g}" + (f"_ratio{ratio:g}" if ratio else ""))
        sets = [f"mesh.section.nr={nr}", f"mesh.section.nz={nz}", f"time.bdf.rtol={rtol}",
                f"time.dt={args.dt}", f"output.line_points={args.line_points}"]
        if ratio:
            sets.append(f"mesh.section.grading_ratio={ratio}")
        sets += args.set
        stamp = run_dir / "sets.json"
        done = run_dir / "summary.json"
        if not done.is_file() or json.loads(done.read_text()).get("status") != "completed" or \
                not stamp.is_file() or json.loads(stamp.read_text()) != sets:
            cmd = [str(BIN), "run", args.case, "-o", str(run_dir), "--overwrite", "--quiet"]
            for extra in sets:
                cmd += ["--set", extra]
            print(" ".join(cmd), file=sys.stderr, flush=True)
            subprocess.run(cmd, check=True)
            stamp.write_text(json.dumps(sets))
        s = json.loads(done.read_text())
        runs.append({"nr": nr, "nz": nz, "rtol": rtol, "unknowns": s["mesh"]["unknowns"],
                     "ratio": s["configuration"]["mesh"]["section"]["grading_ratio"],
                     "wall_s": s["timings"]["wall"], "line": read_line(run_dir / "line.csv")})

    finest = runs[-1]["line"]
    vertices_only = args.line_points == 0
    rows = []
    changes = {}
    for i, r in enumerate(runs):
        vs_finest = (summary_of(discrepancy(r["line"], finest, vertices_only))
                     if i + 1 < len(runs) else (0, 0, 0))
        d_next = (discrepancy(r["line"], runs[i + 1]["line"], vertices_only)
                  if i + 1 < len(runs) else {})
        vs_next = summary_of(d_next) if d_next else (float("nan"),) * 3
        for t, v in d_next.items():
            changes.setdefault(t, {})[f"{r['nr']}x{r['nz']}"] = v
        rows.append({"nr": r["nr"], "nz": r["nz"], "rtol": r["rtol"], "ratio": r["ratio"],
                     "unknowns": r["unknowns"],
                     "wall_s": round(r["wall_s"], 2),
                     "finest_t32": vs_finest[0], "finest_t_le_1": vs_finest[1],
                     "finest_max": vs_finest[2],
                     "next_t32": vs_next[0], "next_t_le_1": vs_next[1], "next_max": vs_next[2]})
    with open(out / "convergence.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    with open(out / "changes.csv", "w", newline="") as f:
        names = [f"{r['nr']}x{r['nz']}" for r in runs[:-1]]
        w = csv.writer(f)
        w.writerow(["t"] + [f"change_{n}" for n in names])
        for t in sorted(changes):
            w.writerow([t] + [changes[t].get(n, "") for n in names])
    print("| cells | rtol | ratio | unknowns | wall [s] | vs finest: t = 32 s | t <= 1 s |"
          " max over t | vs next: t = 32 s | t <= 1 s | max over t |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    pct = lambda v: "n/a" if v != v else f"{100 * v:.3g} %"
    for r in rows:
        print(f"| {r['nr']} x {r['nz']} | {r['rtol']:g} | {r['ratio']:g} | {r['unknowns']} | "
              f"{r['wall_s']} | "
              f"{pct(r['finest_t32'])} | {pct(r['finest_t_le_1'])} | {pct(r['finest_max'])} | "
              f"{pct(r['next_t32'])} | {pct(r['next_t_le_1'])} | {pct(r['next_max'])} |")


if __name__ == "__main__":
    main()
