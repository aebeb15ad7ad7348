#!/usr/bin/python3
"""Creep curve of a run with rigid platens: each platen's displacement against time, from the
run's platens.csv, and (with --strain H) the strain displacement / H.

usage: tools/plot_platens.py RUN_DIR [-o FIGURE_BASENAME] [--strain H] [--title TEXT]

Writes FIGURE_BASENAME.png (200 dpi) and FIGURE_BASENAME.pdf (default RUN_DIR/platens).
"""
import argparse
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import figure_style as fs  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run_dir")
    ap.add_argument("-o", "--output", help="figure path without extension")
    ap.add_argument("--strain", type=float, help="height [mm]: plot displacement / height too")
    ap.add_argument("--title", default="")
    args = ap.parse_args()
    run = pathlib.Path(args.run_dir)
    path = run / "platens.csv"
    if not path.is_file():
        sys.exit(f"{path}: no such file (the run has no rigid_platen condition?)")
    series = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            t, w = float(row["t"]), float(row["displacement"])
            series.setdefault(row["platen"], ([], []))
            series[row["platen"]][0].append(t)
            series[row["platen"]][1].append(w)
    fs.apply()
    fig, ax = plt.subplots(figsize=(fs.SINGLE, 2.6))
    for name, (t, w) in series.items():
        settle = [-x * 1e3 for x in w]  # µm, positive down
        ax.plot(t, settle, "o-", ms=2.5, lw=1, label=f"platen '{name}'")
    ax.set_xlabel("time t [s]")
    ax.set_ylabel("settlement −w [µm]")
    if args.strain:
        right = ax.secondary_yaxis("right", functions=(lambda s: s / (10 * args.strain),
                                                       lambda e: e * 10 * args.strain))
        right.set_ylabel("strain [%]")
    if args.title:
        ax.set_title(args.title)
    if len(series) > 1:
        ax.legend()
    base = pathlib.Path(args.output) if args.output else run / "platens"
    for path in fs.save(fig, base):
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
