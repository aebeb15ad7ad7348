#!/usr/bin/python3
"""Terzaghi consolidation: computed pressure isochrones and settlement against the series.

usage: plot_terzaghi.py CSV_DIR FIG_DIR   (reads CSV_DIR/terzaghi/, writes FIG_DIR/terzaghi.png
at 200 dpi and FIG_DIR/terzaghi.pdf)
Also prints the error table of every run (max |p_h - p|/q and max |U_h - U| over the tabulated
depths and times).
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from verification_csv import fs, label, print_errors, read, save  # noqa: E402


def main():
    csv_dir, fig_dir = pathlib.Path(sys.argv[1]) / "terzaghi", pathlib.Path(sys.argv[2])
    if not csv_dir.is_dir():
        print("  no terzaghi/ results; skipped")
        return
    runs = sorted(p.name[: -len("_profiles.csv")] for p in csv_dir.glob("*_profiles.csv"))
    fig, (ax_p, ax_u, ax_1) = plt.subplots(1, 3, figsize=(fs.DOUBLE, 3.6))

    # (a) Isochrones: the series on the finest BDF run's nodes, computed values as markers.
    bdf = [r for r in runs if r.startswith("bdf_")]
    finest = max(bdf, key=lambda r: int(r.split("nz")[1])) if bdf else runs[-1]
    shown = [r for r in (bdf[:1] + ["be_nz20_dt5"]) if r in runs]
    series = read(csv_dir / f"{finest}_profiles.csv")
    times = sorted({r["T"] for r in series})
    colours = plt.cm.viridis([i / max(1, len(times) - 1) for i in range(len(times))])
    for T, colour in zip(times, colours):
        rows = sorted((r for r in series if r["T"] == T), key=lambda r: r["zeta_over_H"])
        ax_p.plot([r["p_series"] for r in rows], [r["zeta_over_H"] for r in rows], color=colour,
                  label=f"T = {T:g}")
        for run, marker in zip(shown, "os"):
            pts = [r for r in read(csv_dir / f"{run}_profiles.csv") if r["T"] == T]
            ax_p.plot([r["p_computed"] for r in pts], [r["zeta_over_H"] for r in pts], marker,
                      color=colour, ms=3, mfc="none" if marker == "s" else colour)
    ax_p.invert_yaxis()
    ax_p.set_xlabel("pressure p / q [–]")
    ax_p.set_ylabel("depth below the drained face ζ / H [–]")
    ax_p.set_title("isochrones")
    ax_p.legend(loc="lower left", handlelength=1.0, borderaxespad=0.2)
    print("  (a): series (lines), " + ", ".join(
        f"{label(r)} ({m})" for r, m in zip(shown, ["dots", "open squares"])))

    # (b) Settlement error against time.
    for run in runs:
        rows = [r for r in read(csv_dir / f"{run}_settlement.csv") if r["T"] > 0]
        ax_u.plot([r["T"] for r in rows], [abs(r["U_computed"] - r["U_series"]) for r in rows],
                  "-", lw=1, label=label(run))
    ax_u.set_xscale("log")
    ax_u.set_yscale("log")
    ax_u.set_xlabel("time factor T = c t / H² [–]")
    ax_u.set_ylabel("settlement error |U_h − U| [–]")
    ax_u.set_title("settlement, U = s / (q H / H_A)")

    # (c) The first backward-Euler step (r = 0.01): undrained body, oscillation at the drained face.
    first = csv_dir / "first_step.csv"
    if first.exists():
        rows = sorted(read(first), key=lambda r: r["zeta_over_H"])
        ax_1.plot([r["p_computed"] for r in rows], [r["zeta_over_H"] for r in rows], "o-", ms=3)
        ax_1.axvline(1.0, color="k", lw=0.8, ls="--")
        ax_1.invert_yaxis()
        ax_1.set_xlabel("pressure p / q [–]")
        ax_1.set_ylabel("ζ / H [–]")
        ax_1.set_title("first step, r = c Δt / h² = 0.01")
    fs.letters([ax_p, ax_u, ax_1])
    handles, labels = ax_u.get_legend_handles_labels()
    # the markers of (a)
    for run, marker in zip(shown, "os"):
        handles += ax_p.plot([], [], marker, color="k", ms=3, mfc="none" if marker == "s" else "k")
        labels.append(f"(a) {'dots' if marker == 'o' else 'squares'}: {label(run)}")
    fig.legend(handles, labels, loc="lower center", ncol=3)
    fig.tight_layout(rect=(0, (0.16 * ((len(labels) + 2) // 3) + 0.08) / 3.6, 1, 1))
    save(fig, fig_dir, "terzaghi", tight=False)
    print_errors(csv_dir, [("max_pressure_error", "max |p_h - p|/q"),
                              ("max_settlement_error", "max |U_h - U|")])

if __name__ == "__main__":
    main()
