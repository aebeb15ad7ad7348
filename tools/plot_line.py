#!/usr/bin/python3
"""Pressure (and axial displacement) along the probe line from one or more runs' line.csv.

usage: plot_line.py RUN_DIR [RUN_DIR ...] [-o OUT.png] [--time T]
Writes OUT.png (200 dpi) and OUT.pdf.
One run: a curve per output time. Several runs: one curve per run at time T (default: the last
output time), labelled by the run's title, e.g. to compare with and without GLS.
"""
import argparse
import csv
import json
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import figure_style as fs  # noqa: E402

STAB = {"none": "no stabilisation", "gls": "GLS", "flux_perturbation": "flux perturbation"}


def read_line(run_dir):
    rows = list(csv.DictReader(open(pathlib.Path(run_dir) / "line.csv")))
    by_time = {}
    for r in rows:
        by_time.setdefault(float(r["t"]), []).append(r)
    return by_time


def title_of(run_dir, short=False):
    """The run's title, or (short) its folder name with permeability and stabilisation."""
    try:
        s = json.load(open(pathlib.Path(run_dir) / "summary.json"))
        cfg = s["configuration"]
        if short:
            stab = cfg["stabilisation"]["type"]
            text = f"k = {cfg['material']['permeability']:g} mm⁴/(N s), {STAB.get(stab, stab)}"
            time = cfg.get("time", {})
            if time.get("integrator") == "backward_euler" and "dt" in time:
                text += f", backward Euler Δt = {time['dt']:g} s"
            elif time.get("integrator"):
                text += f", {'BDF' if time['integrator'] == 'bdf' else time['integrator']}"
            return text
        return cfg.get("title") or str(run_dir)
    except (OSError, KeyError, ValueError):
        return str(run_dir)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+")
    ap.add_argument("-o", "--output", default="pressure_profiles.png")
    ap.add_argument("--time", type=float, default=None)
    args = ap.parse_args()

    fs.apply()
    fig, (axp, axu) = plt.subplots(1, 2, figsize=(fs.DOUBLE, 3.2), sharey=True)
    if len(args.runs) == 1:
        data = read_line(args.runs[0])
        for t in sorted(data):
            if t == 0.0:
                continue
            rows = data[t]
            axp.plot([float(r["p"]) for r in rows], [float(r["z"]) for r in rows], "o-", ms=3, label=f"t = {t:g} s")
            axu.plot([float(r["uz"]) for r in rows], [float(r["z"]) for r in rows], "-", label=f"t = {t:g} s")
        fig.suptitle(title_of(args.runs[0]))
    else:
        for run in args.runs:
            data = read_line(run)
            t = args.time if args.time is not None else max(data)
            t = min(data, key=lambda x: abs(x - t))
            rows = data[t]
            label = f"{title_of(run, short=True)} (t = {t:g} s)"
            axp.plot([float(r["p"]) for r in rows], [float(r["z"]) for r in rows], "o-", ms=3, label=label)
            axu.plot([float(r["uz"]) for r in rows], [float(r["z"]) for r in rows], "-", label=label)
    axp.set_xlabel("pressure p [MPa]")
    axp.set_ylabel("z on the reference line [mm]")
    axu.set_xlabel("axial displacement u_z [mm]")
    for ax in (axp, axu):
        ax.grid(alpha=0.3)
        ax.xaxis.set_major_locator(plt.MaxNLocator(5))
    fs.letters([axp, axu])
    # one legend for both panels (the same curves), below them
    handles, labels = axp.get_legend_handles_labels()
    ncol = 1 if len(args.runs) > 1 else min(4, len(labels))
    fig.legend(handles, labels, loc="lower center", ncol=ncol)
    rows_ = -(-len(labels) // ncol)
    fig.tight_layout(rect=(0, min(0.5, (0.16 * rows_ + 0.1) / 3.2), 1, 1))
    for path in fs.save(fig, args.output, tight=False):
        print(path)


if __name__ == "__main__":
    main()
