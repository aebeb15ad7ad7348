#!/usr/bin/python3
"""First-step pressure overshoot against r = c Δt / h², with and without stabilisation.

usage: plot_oscillation.py CSV_DIR FIG_DIR
(reads CSV_DIR/oscillation/overshoot_nz*.csv, writes FIG_DIR/oscillation.png at 200 dpi and
FIG_DIR/oscillation.pdf) and prints the
overshoot table and the thresholds.
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from verification_csv import fs, read, save  # noqa: E402

# 1D P2/P1, backward Euler, first step (docs/verification.md, section 3).
ONE_D = {0.01: 0.2415, 0.05: 0.156, 0.1: 0.0774}
LABELS = {"none": "no stabilisation", "gls": "GLS", "flux_perturbation": "flux perturbation"}


def main():
    csv_dir = pathlib.Path(sys.argv[1]) / "oscillation"
    fig_dir = pathlib.Path(sys.argv[2])
    files = sorted(csv_dir.glob("overshoot_nz*.csv"))
    if not files:
        print("  no oscillation/ results; skipped")
        return
    fig, ax = plt.subplots(figsize=(fs.DOUBLE, 3.2))
    floor = 1e-5
    path = files[0]  # the curve depends on r alone: other nz give the same values
    nz = path.stem.split("nz")[1]
    rows = read(path)
    styles = {"none": dict(color="C3", marker="o", ms=3),
              "gls": dict(color="C0", marker="s", ms=7, mfc="none"),
              "flux_perturbation": dict(color="C2", marker=".", ms=4, ls="--")}
    for name, style in styles.items():
        sel = [r for r in rows if r["stabilisation"] == name]
        r_values = [r["r"] for r in sel]
        ax.plot(r_values, [max(floor, r["overshoot"]) for r in sel], **style,
                label=f"{LABELS[name]}: max over the vertices")
        if name == "none":
            ax.plot(r_values, [max(floor, r["level_mean_overshoot"]) for r in sel], ":",
                    color="C3", label="no stabilisation: layers' mean pressure")
            if "line_oscillation" in sel[0]:
                ax.plot(r_values, [max(floor, r["line_oscillation"]) for r in sel], "-.",
                        color="C1", label="no stabilisation: oscillation measure, probe edge")
    ax.plot(list(ONE_D), list(ONE_D.values()), "kx", ms=8, label="1D P2/P1 (notes)")
    ax.axvline(1 / 6, color="k", lw=0.8, ls=":", label="1D threshold r = 1/6")
    ax.axhline(1e-3, color="gray", lw=0.8, ls="--", label="0.1 % level")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(floor, 1.5)
    ax.set_xlabel("r = c Δt / h² [–]")
    ax.set_ylabel("first-step overshoot (max p − q) / q [–]")
    ax.set_title(f"step load, first backward-Euler step, {nz} layers")
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0))
    save(fig, fig_dir, "oscillation")

    by = {(r["r"], r["stabilisation"]): r for r in rows}
    print(f"  {files[0].name}: | r | none | none, layer mean | none, edge oscillation | GLS "
          "| flux perturbation | 1D |")
    for r in sorted({k[0] for k in by}):
        cells = [by[(r, "none")]["overshoot"], by[(r, "none")]["level_mean_overshoot"],
                 by[(r, "none")].get("line_oscillation", float("nan")),
                 by[(r, "gls")]["overshoot"], by[(r, "flux_perturbation")]["overshoot"]]
        print(f"  | {r:.4g} | " + " | ".join(f"{c:.3g}" for c in cells) +
              f" | {ONE_D.get(round(r, 6), '')} |")
    for path in sorted(csv_dir.glob("thresholds_nz*.csv")):
        for r in read(path):
            print(f"  {path.stem}: {r['stabilisation']}: vanishes above r = "
                  f"{r['r_vanishes']:.4g} (layer mean {r['r_vanishes_level_mean']:.4g})")


if __name__ == "__main__":
    main()
