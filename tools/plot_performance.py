#!/usr/bin/python3
"""Cost against problem size from tools/bench_runs.sh output (runs.csv): wall time,
factorisation time and peak memory per linear solver, log-log, with the fitted growth exponent.

usage: plot_performance.py runs.csv [-o performance.png]
Writes the PNG (200 dpi) and a PDF beside it.
"""
import argparse
import csv

import matplotlib
import matplotlib.ticker

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import figure_style as fs  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("-o", "--output", default="performance.png")
    args = ap.parse_args()
    rows = list(csv.DictReader(open(args.csv)))
    solvers = sorted({r["solver"] for r in rows})
    fs.apply()
    fig, axes = plt.subplots(1, 3, figsize=(fs.DOUBLE, 2.9))
    quantities = [("wall_s", "whole run, wall [s]"), ("factorization_s", "one factorisation [s]"),
                  ("peak_rss_gb", "peak memory [GB]")]
    for ax, (key, label) in zip(axes, quantities):
        for solver in solvers:
            pts = sorted((float(r["unknowns"]), float(r[key])) for r in rows if r["solver"] == solver)
            n = np.array([p[0] for p in pts])
            v = np.array([p[1] for p in pts])
            line, = ax.loglog(n, v, "o-", label=solver.upper())
            if len(n) >= 2:  # the fitted growth exponent beside the curve's midpoint
                slope = np.polyfit(np.log(n), np.log(v), 1)[0]
                i = len(n) // 2
                ax.annotate(f"∝ n^{slope:.2f}", (n[i], v[i]), xytext=(4, -4),
                            textcoords="offset points", ha="left", va="top",
                            color=line.get_color())
        ax.set_xlabel("unknowns n [–]")
        ax.set_ylabel(label)
        ax.grid(which="both", alpha=0.3)
        fs.plain_log_ticks(ax.yaxis)
        ax.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:,.0f}"))
        ax.xaxis.set_minor_formatter(matplotlib.ticker.FuncFormatter(
            lambda v, _: f"{v:,.0f}" if round(v / 10 ** np.floor(np.log10(v))) in (3,) else ""))
    fs.letters(axes)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=len(labels))
    fig.tight_layout(rect=(0, 0.08, 1, 0.93))
    fig.suptitle("Reference loading (k = 1e-3, GLS, 5 backward-Euler steps), 2 cores")
    for path in fs.save(fig, args.output, tight=False):
        print(path)


if __name__ == "__main__":
    main()
