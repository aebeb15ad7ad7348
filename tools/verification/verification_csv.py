"""Shared by the plot_*.py scripts: reading the verification CSVs, human labels for the runs,
saving a figure (PNG at 200 dpi beside a vector PDF, print style of tools/figure_style.py) and
printing a run's error table."""
import csv
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import figure_style as fs  # noqa: E402

fs.apply()

WORDS = {"bdf": "BDF", "be": "backward Euler", "backward": "backward Euler",
         "holmes": "Holmes–Mow", "gls": "GLS", "none": "no stabilisation",
         "axisymmetric": "axisymmetric", "tetrahedral": "tetrahedral column",
         "step": "step load", "ramp": "ramped load"}


def label(run):
    """A run's folder/file name as words: bdf_nz20 -> "BDF, 20 layers", be_nz20_dt5 ->
    "backward Euler, 20 layers, Δt = 5 s", be_lc0.15_dt1 -> "backward Euler, mesh size 0.15,
    Δt = 1 s", holmes_mow_bdf_nz20 -> "Holmes–Mow, BDF, 20 layers"."""
    parts = []
    for tok in run.split("_"):
        if tok in ("euler", "mow"):
            continue
        m = re.fullmatch(r"(nz|lc|dt|r)([0-9.eE+-]+)", tok)
        if m:
            key, v = m.groups()
            parts.append({"nz": f"{v} layers", "lc": f"mesh size {v}", "dt": f"Δt = {v} s",
                          "r": f"r = {v}"}[key])
        else:
            parts.append(WORDS.get(tok, tok))
    return ", ".join(parts)


def read(path):
    """Rows of a CSV as dicts, numbers as floats (the `run`, `overrides` and `stabilisation`
    columns stay text)."""
    text = ("run", "overrides", "stabilisation")
    with open(path) as f:
        return [{k: (v if k in text else float(v)) for k, v in r.items()}
                for r in csv.DictReader(f)]


def save(fig, fig_dir, name, tight=True):
    """Writes FIG_DIR/<name>.png (200 dpi) and FIG_DIR/<name>.pdf (tight: lay out first)."""
    for out in fs.save(fig, pathlib.Path(fig_dir) / name, tight=tight):
        print(f"  wrote {out}")


def print_errors(csv_dir, columns):
    """The rows of every *_errors.csv in csv_dir as a Markdown table: run, unknowns, steps and
    `columns` (pairs of column name and heading)."""
    print("  | run | unknowns | steps | " + " | ".join(h for _, h in columns) + " |")
    print("  |" + " --- |" * (3 + len(columns)))
    for path in sorted(csv_dir.glob("*_errors.csv")):
        for r in read(path):
            cells = [f"{r[c]:.2e}" for c, _ in columns]
            print(f"  | {r['run']} | {r['unknowns']:.0f} | {r['steps']:.0f} | "
                  + " | ".join(cells) + " |")
