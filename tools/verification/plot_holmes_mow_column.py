#!/usr/bin/python3
"""Holmes-Mow solid, drained column: platen stress against the closed-form P_zz.

usage: plot_holmes_mow_column.py CSV_DIR FIG_DIR
(reads CSV_DIR/holmes_mow_column/{uniaxial,confined}.csv, writes
FIG_DIR/holmes_mow_column.png at 200 dpi and FIG_DIR/holmes_mow_column.pdf) and prints the largest relative error of each run.
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from verification_csv import fs, read, save  # noqa: E402


def main():
    csv_dir = pathlib.Path(sys.argv[1]) / "holmes_mow_column"
    fig_dir = pathlib.Path(sys.argv[2])
    if not csv_dir.is_dir():
        print("  no holmes_mow_column/ results; skipped")
        return
    fig, (ax_s, ax_e) = plt.subplots(1, 2, figsize=(fs.DOUBLE, 2.9))
    for run, marker in (("uniaxial", "o"), ("confined", "s")):
        path = csv_dir / f"{run}.csv"
        if not path.is_file():
            continue
        rows = read(path)
        strain = [1 - r["stretch"] for r in rows]
        ax_s.plot(strain, [-r["stress_reference"] for r in rows], "k-", lw=0.8)
        ax_s.plot(strain, [-r["stress_computed"] for r in rows], marker, mfc="none",
                  label=f"{run}: finite elements")
        errors = [abs(r["stress_computed"] / r["stress_reference"] - 1) for r in rows]
        ax_e.plot(strain, errors, marker + "-", mfc="none", label=run)
        print(f"  {run}: max relative error {max(errors):.2e}")
    ax_s.plot([], [], "k-", lw=0.8, label="closed form")
    ax_s.set_xlabel("compressive strain 1 − λ₁ [–]")
    ax_s.set_ylabel("platen stress −P_zz [MPa]")
    ax_s.set_title("Holmes–Mow, E = 0.8 MPa, ν = 0.3, β = 0.6")
    ax_s.legend()
    ax_e.set_yscale("log")
    ax_e.set_xlabel("compressive strain 1 − λ₁ [–]")
    ax_e.set_ylabel("relative error |P_FE / P_zz − 1| [–]")
    ax_e.set_title("relative error of the platen stress")
    ax_e.legend()
    fs.letters([ax_s, ax_e])
    save(fig, fig_dir, "holmes_mow_column")


if __name__ == "__main__":
    main()
