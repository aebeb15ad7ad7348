"""Shared by the plot_*.py scripts: reading the verification CSVs, saving a figure, and printing
a run's error table."""
import csv


def read(path):
    """Rows of a CSV as dicts, numbers as floats (the `run`, `overrides` and `stabilisation`
    columns stay text)."""
    text = ("run", "overrides", "stabilisation")
    with open(path) as f:
        return [{k: (v if k in text else float(v)) for k, v in r.items()}
                for r in csv.DictReader(f)]


def save(fig, fig_dir, name):
    """Writes FIG_DIR/<name>.png."""
    fig.tight_layout()
    out = fig_dir / f"{name}.png"
    fig.savefig(out, dpi=120)
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
