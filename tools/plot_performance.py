#!/usr/bin/python3
"""Cost against problem size from tools/bench_runs.sh output (runs.csv): wall time,
factorisation time and peak memory per linear solver, log-log, with the fitted growth exponent.

usage: plot_performance.py runs.csv [-o performance.png]
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("-o", "--output", default="performance.png")
    args = ap.parse_args()
    rows = list(csv.DictReader(open(args.csv)))
    solvers = sorted({r["solver"] for r in rows})
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    quantities = [("wall_s", "whole run, wall [s]"), ("factorization_s", "one factorisation [s]"),
                  ("peak_rss_gb", "peak memory [GB]")]
    for ax, (key, label) in zip(axes, quantities):
        for solver in solvers:
            pts = sorted((float(r["unknowns"]), float(r[key])) for r in rows if r["solver"] == solver)
            n = np.array([p[0] for p in pts])
            v = np.array([p[1] for p in pts])
            text = solver
            if len(n) >= 2:
                slope = np.polyfit(np.log(n), np.log(v), 1)[0]
                text += f" (~ n^{slope:.2f})"
            ax.loglog(n, v, "o-", label=text)
        ax.set_xlabel("unknowns n")
        ax.set_ylabel(label)
        ax.grid(which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Reference loading (k = 1e-3, GLS, 5 backward-Euler steps), 2 cores")
    fig.tight_layout()
    fig.savefig(args.output, dpi=130)
    print(args.output)


if __name__ == "__main__":
    main()
