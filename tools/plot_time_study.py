#!/usr/bin/python3
"""Figures of the time studies (tools/time_study.py) from their CSV tables alone.

usage: tools/plot_time_study.py CSV [CSV ...] [-o DIR] [--second reaction|displacement]

For a time-error table (columns error_pressure, ...), writes per scene:
  time_<scene>_pressure.png    pressure time error against wall time, factorisations and Newton
                               iterations; one curve per method, one column per stabilisation
  time_<scene>_<second>.png    time error of the platen reaction (or of the settlement u_z)
                               against wall time and Newton iterations
For a failure table (column divisor): failure_<scene>.png, the largest converging fixed step
against the applied strain, with and without stabilisation.
PNG at 200 dpi into DIR (default: docs/figures/integrators).
"""
import argparse
import collections
import csv
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
METHODS = [  # (method column, legend, style)
    ("backward_euler", "backward Euler, fixed Δt", dict(color="tab:blue", marker="o", ls="-")),
    ("adaptive_backward_euler", "adaptive backward Euler (IDA at order 1)",
     dict(color="tab:orange", marker="s", ls="--")),
    ("bdf", "BDF (IDA, orders 1–5)", dict(color="tab:green", marker="^", ls="-.")),
]
STAB = {"gls": "GLS", "flux_perturbation": "flux perturbation", "none": "no stabilisation"}
COST = {"wall_s": "wall time [s]", "factorizations": "factorisations",
        "newton_iterations": "Newton iterations", "steps": "time steps"}
MEASURE = {"pressure": "time error of the line pressure [-]",
           "reaction": "time error of the platen reaction [-]",
           "displacement": "time error of the settlement u_z [-]"}
SCENE = {"paper_mesh1": "paper's reference loading, mesh 1 (1 % strain)",
         "paper_mesh2": "paper's reference loading, mesh 2 (1 % strain)",
         "confined_compression": "ramp confined compression (Mow et al.)",
         "terzaghi": "Terzaghi consolidation (load ramped over 1 s)",
         "paper_mesh1_strain": "paper's loading, mesh 1"}


def num(row, key):
    try:
        return float(row.get(key, ""))
    except (TypeError, ValueError):
        return math.nan


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def group_key(row):
    """The study's combination without the stabilisation (e.g. the strain)."""
    return tuple(sorted((k, v) for k, v in row.items()
                        if k.startswith("param:") and k != "param:stabilisation.type"))


def panel_letter(ax, i):
    ax.text(-0.02, 1.02, f"({chr(ord('a') + i)})", transform=ax.transAxes, fontsize=11,
            fontweight="bold", ha="right", va="bottom")


def time_error_figure(rows, measure, costs, out, name, title):
    stabs = [s for s in STAB if any(r["stabilisation"] == s for r in rows)]
    fig, axes = plt.subplots(len(costs), len(stabs), figsize=(4.2 * len(stabs), 3.4 * len(costs)),
                             squeeze=False, sharey=True)
    col = f"error_{measure}"
    letter = 0
    for j, stab in enumerate(stabs):
        sr = [r for r in rows if r["stabilisation"] == stab]
        check = [num(r, col) for r in sr if r["method"] == "reference_check"]
        for i, cost in enumerate(costs):
            ax = axes[i][j]
            for method, label, style in METHODS:
                pts = sorted((num(r, cost), num(r, col)) for r in sr
                             if r["method"] == method and r["status"] == "completed")
                pts = [(x, y) for x, y in pts if x > 0 and y > 0 and not math.isnan(x + y)]
                if pts:
                    ax.plot(*zip(*pts), label=label, ms=5, lw=1.2, **style)
                failed = [r for r in sr if r["method"] == method and r["status"] != "completed"]
                if failed and i == 0 and j == 0:
                    pass
            if check and check[0] > 0:
                ax.axhline(check[0], color="grey", lw=0.8, ls=":",
                           label="reference check (rtol 1e-7 vs 1e-8)")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.grid(True, which="major", alpha=0.3)
            ax.set_xlabel(COST[cost])
            if j == 0:
                ax.set_ylabel(MEASURE[measure])
            if i == 0:
                ax.set_title(STAB[stab])
            panel_letter(ax, letter)
            letter += 1
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=len(labels), frameon=False,
               bbox_to_anchor=(0.5, 0.0))
    fig.suptitle(title)
    fig.tight_layout(rect=(0, 0.05, 1, 0.97))
    path = out / name
    fig.savefig(path, dpi=200)
    plt.close(fig)
    print(path)


def failure_figure(rows, out, name):
    fig, ax = plt.subplots(figsize=(5.6, 4.2))
    styles = {"gls": dict(color="tab:blue", marker="o"), "none": dict(color="tab:red", marker="s"),
              "flux_perturbation": dict(color="tab:purple", marker="^")}
    by = collections.defaultdict(dict)
    t_end = {}
    for r in rows:
        strain = num(r, "param:loading.strain")
        dt = num(r, "largest_converged_dt")
        by[r["stabilisation"]][strain] = dt
        t_end[strain] = num(r, "t_end")
    for stab, d in by.items():
        xs = sorted(d)
        ok = [(100 * x, d[x]) for x in xs if not math.isnan(d[x])]
        if ok:
            ax.plot(*zip(*ok), label=STAB[stab], lw=1.3, ms=6, **styles.get(stab, {}))
        for x in xs:
            if math.isnan(d[x]):
                ax.plot(100 * x, min(v for v in d.values() if not math.isnan(v)) / 2, "x",
                        color=styles.get(stab, {}).get("color", "k"))
    xs = sorted(t_end)
    ax.plot([100 * x for x in xs], [t_end[x] for x in xs], color="grey", ls=":", lw=1,
            label="t_end (the whole load in one step)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("applied compressive strain [%]")
    ax.set_ylabel("largest converging Δt [s]")
    ax.set_title("Backward Euler without cut-back, mesh 1, 2.5 µm/s", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(frameon=False, fontsize=9)
    fig.tight_layout()
    path = out / name
    fig.savefig(path, dpi=200)
    plt.close(fig)
    print(path)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv", nargs="+", type=pathlib.Path)
    ap.add_argument("-o", "--output", type=pathlib.Path, default=ROOT / "docs/figures/integrators")
    ap.add_argument("--second", choices=["reaction", "displacement"], default=None,
                    help="second measure (default: reaction, or displacement when no reaction)")
    args = ap.parse_args()
    args.output.mkdir(parents=True, exist_ok=True)
    for path in args.csv:
        rows = read(path)
        if not rows:
            continue
        scene = rows[0]["scene"]
        if "divisor" in rows[0]:
            failure_figure(rows, args.output, f"failure_{scene}.png")
            continue
        groups = collections.defaultdict(list)
        for r in rows:
            groups[group_key(r)].append(r)
        for key, gr in groups.items():
            suffix = "".join(f"_{k.split('.')[-1]}{v}" for k, v in key)
            label = SCENE.get(scene, scene) + "".join(
                f", {k.split(':')[-1]} = {v}" for k, v in key)
            second = args.second or ("reaction" if any(r.get("error_reaction") for r in gr)
                                     else "displacement")
            time_error_figure(gr, "pressure", ["wall_s", "factorizations", "newton_iterations"],
                              args.output, f"time_{scene}{suffix}_pressure.png",
                              f"Time error of the pressure against cost: {label}")
            time_error_figure(gr, second, ["wall_s", "newton_iterations"], args.output,
                              f"time_{scene}{suffix}_{second}.png",
                              f"Time error of the {'platen reaction' if second == 'reaction' else 'settlement'}"
                              f" against cost: {label}")


if __name__ == "__main__":
    main()
