#!/usr/bin/python3
"""Figures of the verification benchmarks from their computed-vs-analytic CSVs.

usage: plot_verification.py CSV_DIR FIG_DIR
CSV_DIR is what the verification tests wrote under BIPHASIC_VERIFICATION_OUT (one folder per
benchmark). Runs every tools/verification/plot_*.py as `plot_X.py CSV_DIR FIG_DIR`; each draws
FIG_DIR/<benchmark>.png from CSV_DIR/<benchmark>/ and skips quietly when that folder is missing.
"""
import pathlib
import subprocess
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    csv_dir, fig_dir = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    fig_dir.mkdir(parents=True, exist_ok=True)
    scripts = sorted((pathlib.Path(__file__).parent / "verification").glob("plot_*.py"))
    failed = []
    for script in scripts:
        print(f"{script.name}:", flush=True)
        if subprocess.run([sys.executable, str(script), str(csv_dir), str(fig_dir)]).returncode:
            failed.append(script.name)
    if failed:
        sys.exit("failed: " + ", ".join(failed))


if __name__ == "__main__":
    main()
