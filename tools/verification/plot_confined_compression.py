#!/usr/bin/python3
"""Ramp confined compression: platen stress against the finite-strain and linear solutions.

usage: plot_confined_compression.py CSV_DIR FIG_DIR
(reads CSV_DIR/confined_compression/, writes FIG_DIR/confined_compression.png at 200 dpi and
FIG_DIR/confined_compression.pdf; with Holmes–Mow runs also confined_compression_holmes_mow.*)
and prints the
error table of every run.
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from verification_csv import fs, label, print_errors, read, save  # noqa: E402


def plot(csv_dir, fig_dir, runs, title, reference_label, name):
    """Stress and relative error of `runs`, which share one reference, into FIG_DIR/name.png."""
    fig, (ax_s, ax_e) = plt.subplots(1, 2, figsize=(fs.DOUBLE, 3.2))
    base = read(csv_dir / f"{runs[0]}.csv")
    t = [r["t"] for r in base]
    ax_s.plot(t, [-r["stress_neo_hookean"] for r in base], "k-", label=reference_label)
    ax_s.plot(t, [-r["stress_linear"] for r in base], "k--", label="linear (Mow et al. 1980), k = k₀")
    for run, marker in zip(runs, "o^sv"):
        rows = read(csv_dir / f"{run}.csv")
        rows = rows[:: max(1, len(rows) // 60)]
        ax_s.plot([r["t"] for r in rows], [-r["stress_computed"] for r in rows], marker, ms=3,
                  mfc="none", label=label(run))
        rows = read(csv_dir / f"{run}.csv")
        ax_e.plot([r["t"] for r in rows],
                  [abs(r["stress_computed"] / r["stress_neo_hookean"] - 1) for r in rows],
                  label=label(run))
    ax_s.set_xlabel("time t [s]")
    ax_s.set_ylabel("compressive platen stress −P_zz [MPa]")
    ax_s.set_title("platen stress")
    fig.suptitle(title)
    ax_s.legend()
    ax_e.axhline(5e-3, color="r", lw=0.8, ls="--", label="asserted bound 0.5 %")
    ax_e.set_yscale("log")
    ax_e.set_xlabel("time t [s]")
    ax_e.set_ylabel("relative error |σ_h / σ_ref − 1| [–]")
    ax_e.set_title("error against the finite-strain reference")
    ax_e.legend(loc="upper right")
    fs.letters([ax_s, ax_e])
    save(fig, fig_dir, name)


def main():
    csv_dir = pathlib.Path(sys.argv[1]) / "confined_compression"
    fig_dir = pathlib.Path(sys.argv[2])
    if not csv_dir.is_dir():
        print("  no confined_compression/ results; skipped")
        return
    runs = sorted(p.stem for p in csv_dir.glob("*.csv") if not p.stem.endswith("_errors"))
    # runs against the Neo-Hookean column solution (a two-region column has its own layered
    # reference column and is not drawn here)
    runs = [r for r in runs if "stress_neo_hookean" in read(csv_dir / f"{r}.csv")[0]]
    constant = [r for r in runs if not r.startswith("holmes_mow")]
    holmes_mow = [r for r in runs if r.startswith("holmes_mow")]
    if constant:
        plot(csv_dir, fig_dir, constant,
             "10 % ramp over 100 s, then hold (μ = 0.5, λ = 0, k = 1e-3, h = 1)",
             "Neo-Hookean, finite strain", "confined_compression")
    if holmes_mow:
        plot(csv_dir, fig_dir, holmes_mow,
             "the same with Holmes–Mow k(J): k₀ = 1e-3, φ₀ = 0.2, κ = 1, M = 4",
             "Neo-Hookean, finite strain, Holmes–Mow k", "confined_compression_holmes_mow")
    print_errors(csv_dir, [("max_relative_error", "max relative error"),
                              ("max_top_bottom_imbalance", "top/bottom imbalance")])


if __name__ == "__main__":
    main()
