#!/usr/bin/python3
"""Markdown table of runs from their summary.json: mesh size, cost counters, wall time and the
line measures at the last output time (or --time T).

usage: summarize_runs.py RUN_DIR [RUN_DIR ...] [--time T]
"""
import argparse
import json
import pathlib


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--time", type=float, default=None)
    args = ap.parse_args()
    print("| run | unknowns | k | stabilisation | integrator | steps | Newton | residuals | Jacobians "
          "| factorisations | factorisation [s] | wall [s] | t [s] | p_mid [MPa] | overshoot | undershoot |")
    print("|" + "---|" * 16)
    for run in args.runs:
        s = json.load(open(pathlib.Path(run) / "summary.json"))
        cfg, c, tm = s["configuration"], s["counters"], s["timings"]
        outs = s["outputs"]
        o = outs[-1] if args.time is None else min(outs, key=lambda x: abs(x["t"] - args.time))
        fmt = lambda v: "–" if v is None else f"{v:.4f}"
        tcfg = cfg["time"]
        integrator = (f"BDF rtol {tcfg['bdf']['rtol']:g}" if tcfg["integrator"] == "bdf"
                      else f"BE dt {tcfg['dt']:g}")
        print(f"| {pathlib.Path(run).name} | {s['mesh']['unknowns']} | {cfg['material']['permeability']:g} "
              f"| {cfg['stabilisation']['type']} | {integrator} | {c['steps']} | {c['newton_iterations']} "
              f"| {c['residual_evaluations']} | {c['jacobian_evaluations']} | {c['factorizations']} "
              f"| {tm['factorization']:.1f} | {tm['wall']:.1f} | {o['t']:g} | {o['p_mid']:.4e} "
              f"| {fmt(o['overshoot'])} | {fmt(o['undershoot'])} |")


if __name__ == "__main__":
    main()
