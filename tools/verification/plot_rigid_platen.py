#!/usr/bin/python3
"""Load control through a rigid platen: Mandel's problem (centre pressure against the series,
midplane profiles) and confined creep (settlement against Terzaghi's degree of consolidation).

usage: plot_rigid_platen.py CSV_DIR FIG_DIR
Reads CSV_DIR/mandel/ and CSV_DIR/confined_creep/ (written by the RigidPlatenMandel.* and
RigidPlatenCreep.* tests under BIPHASIC_VERIFICATION_OUT); writes FIG_DIR/rigid_platen.png
(200 dpi) and FIG_DIR/rigid_platen.pdf. Prints the largest errors of every run.
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from verification_csv import fs, read, save  # noqa: E402

LABELS = {"bdf": "BDF (rtol 1e-6)", "backward_euler": "backward Euler",
          "axisymmetric_bdf": "axisymmetric, BDF",
          "axisymmetric_backward_euler": "axisymmetric, backward Euler",
          "tetrahedral_bdf": "tetrahedral column, BDF"}


def main():
    root, fig_dir = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    mandel, creep = root / "mandel", root / "confined_creep"
    if not mandel.is_dir() and not creep.is_dir():
        print("  no mandel/ or confined_creep/ results; skipped")
        return
    fig, (ax_c, ax_p, ax_s) = plt.subplots(1, 3, figsize=(fs.DOUBLE, 3.4))

    # (a) Mandel: centre pressure against T.
    if mandel.is_dir():
        base = None
        for run in ("bdf", "backward_euler"):
            path = mandel / f"{run}_centre.csv"
            if not path.is_file():
                continue
            rows = [r for r in read(path) if r["T"] > 0]
            base = base or rows
            ax_c.plot([r["T"] for r in rows], [r["p_computed"] for r in rows], lw=1,
                      ls="-" if run == "bdf" else "--", label=LABELS[run])
            worst = max(abs(r["p_computed"] - r["p_series"]) for r in rows if r["T"] >= 0.01)
            print(f"  mandel {run}: max |p_h(0) - p(0)|/sigma0 over T >= 0.01: {worst:.2e}")
        if base:
            ax_c.plot([r["T"] for r in base], [r["p_series"] for r in base], "k:", lw=1.5,
                      label="series")
        ax_c.axhline(0.5, color="gray", lw=0.6)
        ax_c.set_xscale("log")
        ax_c.set_xlabel("T = c t / a² [–]")
        ax_c.set_ylabel("centre pressure p / σ₀ [–]")
        ax_c.set_title("Mandel, centre")
        ax_c.legend()

        # (b) Mandel: midplane profiles at the checked times, BDF run.
        path = mandel / "bdf_profiles.csv"
        if path.is_file():
            rows = read(path)
            times = sorted({r["T"] for r in rows})
            colours = plt.cm.viridis([i / max(1, len(times) - 1) for i in range(len(times))])
            for T, colour in zip(times, colours):
                sel = sorted((r for r in rows if r["T"] == T), key=lambda r: r["x_over_a"])
                ax_p.plot([r["x_over_a"] for r in sel], [r["p_series"] for r in sel], "-",
                          color=colour, lw=1, label=f"T = {T:g}")
                ax_p.plot([r["x_over_a"] for r in sel], [r["p_computed"] for r in sel], "o",
                          ms=2, color=colour)
            ax_p.set_xlabel("x / a [–]")
            ax_p.set_ylabel("pressure p / σ₀ [–]")
            ax_p.set_title("Mandel, midplane")
            fig.legend(*ax_p.get_legend_handles_labels(), loc="lower center", ncol=len(times),
                       handlelength=1.2, columnspacing=1.0,
                       title="(b) at T: series (lines), BDF (dots)")

    # (c) Confined creep: settlement against T.
    if creep.is_dir():
        series = None
        for path in sorted(creep.glob("*.csv")):
            rows = [r for r in read(path) if r["T"] > 0]
            series = series or rows
            ax_s.plot([r["T"] for r in rows], [r["settlement_computed"] for r in rows], lw=1,
                      label=LABELS.get(path.stem, path.stem))
            worst = max(abs(r["settlement_computed"] - r["settlement_series"]) for r in rows)
            print(f"  creep {path.stem}: max |s_h - s|/s_final: {worst:.2e}")
        if series:
            ax_s.plot([r["T"] for r in series], [r["settlement_series"] for r in series], "k:",
                      lw=1.5, label="Terzaghi U(T)")
        ax_s.set_xscale("log")
        ax_s.set_xlabel("T = c t / H² [–]")
        ax_s.set_ylabel("settlement / (q H / H_A) [–]")
        ax_s.set_title("confined creep")
        ax_s.legend(loc="upper left", borderaxespad=0.2)
    fs.letters([ax_c, ax_p, ax_s])
    fig.tight_layout(rect=(0, 0.16 if fig.legends else 0, 1, 1))
    save(fig, fig_dir, "rigid_platen", tight=False)


if __name__ == "__main__":
    main()
