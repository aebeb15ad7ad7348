#!/usr/bin/python3
"""Unconfined compression between impermeable frictionless platens (Armstrong, Lai & Mow 1984):
platen force and centre pressure against the series for a short ramp.

usage: plot_unconfined_compression.py CSV_DIR FIG_DIR
(reads CSV_DIR/unconfined_compression/, writes FIG_DIR/unconfined_compression.png at 200 dpi
and FIG_DIR/unconfined_compression.pdf) and prints
the error table of every run (max errors over tau >= 0.01).
"""
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from verification_csv import fs, label, print_errors, read, save  # noqa: E402


def lc_of(run):
    """The element size of a run labelled like bdf_lc0.15."""
    return float(run.split("lc")[1].split("_")[0])


def main():
    csv_dir = pathlib.Path(sys.argv[1]) / "unconfined_compression"
    fig_dir = pathlib.Path(sys.argv[2])
    if not csv_dir.is_dir():
        print("  no unconfined_compression/ results; skipped")
        return
    runs = sorted((p.stem for p in csv_dir.glob("*.csv") if not p.stem.endswith("_errors")),
                  key=lc_of, reverse=True)
    fig, (ax_f, ax_p, ax_e) = plt.subplots(1, 3, figsize=(fs.DOUBLE, 3.2))
    base = [r for r in read(csv_dir / f"{runs[-1]}.csv") if r["tau"] > 0]
    tau = [r["tau"] for r in base]
    ax_f.plot(tau, [r["force_series"] for r in base], "k-", lw=2, label="series")
    ax_p.plot(tau, [r["pressure_series"] for r in base], "k-", lw=2, label="series")
    for run, marker, colour in zip(runs, "o^sv", ["C0", "C1", "C2", "C3"]):
        rows = [r for r in read(csv_dir / f"{run}.csv") if r["tau"] > 0]
        # About 30 markers spread evenly in log τ.
        lo, hi = math.log(rows[0]["tau"]), math.log(rows[-1]["tau"])
        picks = {min(range(len(rows)), key=lambda i: abs(math.log(rows[i]["tau"]) - x))
                 for x in (lo + (hi - lo) * k / 29 for k in range(30))}
        shown = [rows[i] for i in sorted(picks)]
        ax_f.plot([r["tau"] for r in shown], [r["force_computed"] for r in shown], marker, ms=4,
                  mfc="none", color=colour, label=label(run))
        ax_p.plot([r["tau"] for r in shown], [r["pressure_computed"] for r in shown], marker,
                  ms=4, mfc="none", color=colour, label=label(run))
        ax_e.plot([r["tau"] for r in rows],
                  [abs(r["force_computed"] - r["force_series"]) for r in rows], "-", lw=1,
                  color=colour)
        ax_e.plot([r["tau"] for r in rows],
                  [abs(r["pressure_computed"] - r["pressure_series"]) for r in rows], "--",
                  lw=1, color=colour)
    ax_e.plot([], [], "k-", lw=1, label="force")
    ax_e.plot([], [], "k--", lw=1, label="centre pressure")
    for ax in (ax_f, ax_p, ax_e):
        ax.set_xscale("log")
        ax.set_xlabel("τ = c t / a² [–]")
    ax_f.legend(loc="lower left")
    ax_e.legend()
    ax_f.set_ylabel("platen force F / (π a² ε₀ E) [–]")
    ax_f.set_title("platen force")
    ax_p.axhline(1.0, color="gray", lw=0.8, ls=":")
    ax_p.set_ylabel("centre pressure p(0, h/2) / (μ ε₀) [–]")
    ax_p.set_title("pressure at the centre")
    ax_e.axvline(0.01, color="gray", lw=0.8, ls=":")
    ax_e.set_yscale("log")
    ax_e.set_ylabel("|computed − series| (scaled as in a, b) [–]")
    ax_e.set_title("errors, compared from τ = 0.01")
    fig.suptitle("ramp over τ₀ = 1.1e-3, ν = 0.1")
    fs.letters([ax_f, ax_p, ax_e])
    save(fig, fig_dir, "unconfined_compression")
    print_errors(csv_dir, [("max_force_error", "max |F_h - F|/(pi a^2 eps0 E)"),
                              ("max_pressure_error", "max |p_h - p|/(mu eps0)"),
                              ("peak_pressure", "peak p/(mu eps0)"),
                              ("series_peak_pressure", "series peak")])


if __name__ == "__main__":
    main()
