#!/usr/bin/python3
"""Cryer's sphere: centre pressure against the series, profiles along the radius, and the two
line measures (overshoot, oscillation) through the Mandel-Cryer rise.

usage: plot_cryer.py CSV_DIR FIG_DIR   (reads CSV_DIR/cryer/, writes FIG_DIR/cryer.png at
200 dpi and FIG_DIR/cryer.pdf)
Also prints the error table of every run (max |p_h(0) - p(0)|/P0 over T >= 0.01, the peak and
its time against the series', the oscillation measure, the overshoot at the peak).
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from verification_csv import fs, label, print_errors, read, save  # noqa: E402


def lc_of(run):
    """The element size of a run labelled like be_lc0.15_dt1."""
    return float(run.split("lc")[1].split("_")[0])


def main():
    csv_dir, fig_dir = pathlib.Path(sys.argv[1]) / "cryer", pathlib.Path(sys.argv[2])
    if not csv_dir.is_dir():
        print("  no cryer/ results; skipped")
        return
    runs = sorted((p.name[: -len("_centre.csv")] for p in csv_dir.glob("*_centre.csv")),
                  key=lc_of, reverse=True)
    finest = runs[-1]
    fig, ((ax_c, ax_r), (ax_m, ax_1)) = plt.subplots(2, 2, figsize=(fs.DOUBLE, 5.6))

    # (a) Centre pressure against T: the series and every run.
    base = read(csv_dir / f"{finest}_centre.csv")
    ax_c.plot([r["T"] for r in base], [r["p_series"] for r in base], "k-", lw=2, label="series")
    for run in runs:
        rows = read(csv_dir / f"{run}_centre.csv")
        ax_c.plot([r["T"] for r in rows], [r["p_computed"] for r in rows], lw=1, label=label(run))
    ax_c.axhline(1.0, color="gray", lw=0.8, ls=":")
    ax_c.set_xlabel("time factor T = c t / R² [–]")
    ax_c.set_ylabel("centre pressure p(0, T) / P₀ [–]")
    ax_c.set_title("centre pressure, Mandel–Cryer rise (ν = 0.2)")
    ax_c.legend()

    # (b) Profiles along the radius (centre to drained surface), finest run.
    rows = read(csv_dir / f"{finest}_profiles.csv")
    times = sorted({r["T"] for r in rows})
    for T, colour in zip(times, plt.cm.viridis([i / max(1, len(times) - 1)
                                                for i in range(len(times))])):
        sel = sorted((r for r in rows if r["T"] == T), key=lambda r: r["r_over_R"])
        ax_r.plot([r["r_over_R"] for r in sel], [r["p_series"] for r in sel], "-", color=colour,
                  label=f"T = {T:g}")
        ax_r.plot([r["r_over_R"] for r in sel], [r["p_computed"] for r in sel], "o", ms=3,
                  color=colour)
    ax_r.set_xlabel("radius r / R on the edge y = z = 0 [–]")
    ax_r.set_ylabel("pressure p / P₀ [–]")
    ax_r.set_title("profiles: series (lines), finest mesh (dots)")
    ax_r.legend(ncol=2, handlelength=1.0, columnspacing=0.8)

    # (c) The line measures of the summary along the radius.
    for run, colour in zip(runs, ["C0", "C1", "C2", "C3"]):
        rows = [r for r in read(csv_dir / f"{run}_centre.csv") if r["T"] > 0]
        ax_m.plot([r["T"] for r in rows], [max(r["overshoot"], 1e-6) for r in rows], "--",
                  color=colour, lw=1)
        ax_m.plot([r["T"] for r in rows], [max(r["oscillation"], 1e-6) for r in rows], "-",
                  color=colour, lw=1, label=label(run))
    ax_m.plot([], [], "k--", lw=1, label="overshoot (max p − p_mid) / p_mid")
    ax_m.plot([], [], "k-", lw=1, label="oscillation (non-monotonicity)")
    ax_m.set_yscale("log")
    ax_m.set_ylim(1e-6, 2)
    ax_m.set_xlabel("time factor T = c t / R² [–]")
    ax_m.set_ylabel("measure along the radius [–]\n(floored at 1e-6)")
    ax_m.set_title("line measures: oscillation 0 from T ≈ 0.03")
    ax_m.legend(loc="lower left")

    # (d) The first backward-Euler step of Δt = 0.01 s (T = 1e-5).
    for path in sorted(csv_dir.glob("first_step_*.csv")):
        rows = sorted(read(path), key=lambda r: r["r_over_R"])
        ax_1.plot([r["r_over_R"] for r in rows], [r["p_computed"] for r in rows], "o-", ms=3,
                  label=label(path.stem[len("first_step_"):]))
    ax_1.axhline(1.0, color="k", lw=0.8, ls="--")
    ax_1.set_xlabel("radius r / R [–]")
    ax_1.set_ylabel("pressure p / P₀ [–]")
    ax_1.set_title("first backward-Euler step, T = 1e-5\n(series: p = P₀ but in a 0.003 R layer)",
                   fontsize=8)
    ax_1.legend()
    fs.letters([ax_c, ax_r, ax_m, ax_1])
    save(fig, fig_dir, "cryer")
    print_errors(csv_dir, [("max_centre_error", "max |p_h(0) - p(0)|/P0, T >= 0.01"),
                              ("peak", "peak"), ("peak_T", "at T"),
                              ("series_peak", "series peak"), ("series_peak_T", "at T"),
                              ("max_oscillation", "oscillation, T >= 0.01"),
                              ("max_oscillation_after_rise", "oscillation, T >= 0.04"),
                              ("overshoot_at_peak", "overshoot at the peak")])


if __name__ == "__main__":
    main()
