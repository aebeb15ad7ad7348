#!/usr/bin/python3
"""L² errors of the manufactured-solution study against the mesh size, log-log, with reference
slopes 3 (P2 displacement) and 2 (P1 pressure).

usage: plot_mms.py CSV [CSV ...] OUT.png [--title TITLE]
Writes OUT.png (200 dpi) and OUT.pdf beside it.
CSV: a table written by the test_mms tests into $BIPHASIC_VERIFICATION_OUT/mms/ (columns h,
error_u_l2, error_p_l2, ...). Several tables share the axes, labelled by their file names.
"""
import argparse
import pathlib
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import figure_style as fs  # noqa: E402


def read_table(path):
    data = np.genfromtxt(path, delimiter=",", names=True)
    return np.atleast_1d(data["h"]), np.atleast_1d(data["error_u_l2"]), np.atleast_1d(
        data["error_p_l2"])


def reference(ax, h, e, slope, label):
    """A line of the given slope through the finest point, a little below it."""
    y = 0.5 * e[-1] * (h / h[-1]) ** slope
    ax.loglog(h, y, "k--" if slope == 3 else "k:", linewidth=1, label=label)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("tables", nargs="+", help="CSV tables, then the PNG to write")
    parser.add_argument("--title", default="Manufactured solution on the unit cube")
    args = parser.parse_args()
    if len(args.tables) < 2:
        parser.error("give at least one CSV table and the output PNG")
    *tables, out = args.tables
    if len(tables) == 1 and pathlib.Path(tables[0]).is_dir():
        # called by plot_verification.py as `plot_mms.py CSV_DIR FIG_DIR`: this figure is drawn
        # from chosen tables instead (docs/verification_mms.md)
        print("  takes CSV tables (docs/verification_mms.md); skipped")
        return

    fs.apply()
    fig, ax = plt.subplots(figsize=(fs.SINGLE, 3.2 + 0.17 * 2 * len(tables)))
    markers = ["o", "s", "^", "D", "v"]
    h_all = None
    for i, path in enumerate(tables):
        h, eu, ep = read_table(path)
        name = (pathlib.Path(path).stem.removeprefix("convergence").replace("_", " ")
                .replace("fine", "").strip() or "default")
        m = markers[i % len(markers)]
        suffix = f" ({name})" if len(tables) > 1 else ""
        ax.loglog(h, eu, "-" + m, color="tab:blue", label=f"displacement ‖u − u_h‖{suffix}")
        ax.loglog(h, ep, "-" + m, color="tab:red", label=f"pressure ‖p − p_h‖{suffix}")
        if i == 0:
            h_all, eu0, ep0 = h, eu, ep
    reference(ax, h_all, eu0, 3, "slope 3")
    reference(ax, h_all, ep0, 2, "slope 2")
    ax.set_xlabel("cell size h [mm]")
    ax.set_ylabel("L² error at t = 1 s")
    ax.set_title(args.title)
    ax.grid(True, which="both", alpha=0.3)
    fs.plain_log_ticks(ax.xaxis)  # h spans about a decade: 0.1, 0.2, 0.3, 0.5
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2))
    for path in fs.save(fig, out):
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
