#!/usr/bin/python3
"""Figures of the time studies (tools/time_study.py) from their CSV tables alone.

usage: tools/plot_time_study.py CSV [CSV ...] [-o DIR] [--second reaction|displacement]

For a time-error table (columns error_pressure, ...), writes per scene:
  time_<scene>_pressure.png    pressure time error against wall time, factorisations and Newton
                               iterations; one curve per method, one column per stabilisation
  time_<scene>_<second>.png    time error of the platen reaction (or of the settlement u_z)
                               against wall time and Newton iterations
For a failure table (column divisor): the largest converging fixed step
against the applied strain, with and without stabilisation (<scene>.png).
PNG at 200 dpi with a PDF beside each into DIR (default: docs/figures/integrators).
--markdown prints the tables of docs/integrators.md instead: every run, and for each scene and
stabilisation the cheapest run of each method whose pressure time error is <= 1e-3 and 1e-4.
"""
import argparse
import collections
import csv
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

import figure_style as fs  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
METHODS = [  # (method column, legend, style)
    ("backward_euler", "backward Euler, fixed Δt", dict(color="tab:blue", marker="o", ls="-")),
    ("adaptive_backward_euler", "adaptive backward Euler (IDA at order 1)",
     dict(color="tab:orange", marker="s", ls="--")),
    ("bdf", "BDF (IDA, orders 1–5)", dict(color="tab:green", marker="^", ls="-.")),
]
STAB = {"gls": "GLS", "flux_perturbation": "flux perturbation", "none": "no stabilisation"}
COST = {"wall_s": "wall time [s]", "factorizations": "factorisations [–]",
        "newton_iterations": "Newton iterations [–]", "steps": "time steps [–]"}
MEASURE = {"pressure": "time error of the line pressure [-]",
           "reaction": "time error of the platen reaction [-]",
           "displacement": "time error of the settlement u_z [-]"}
SHORT = {"pressure": "pressure", "reaction": "reaction", "displacement": "settlement"}
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
    fs.panel_label(ax, chr(ord("a") + i))


def time_error_figure(rows, measure, costs, out, name, title):
    stabs = [s for s in STAB if any(r["stabilisation"] == s for r in rows)]
    fig, axes = plt.subplots(len(costs), len(stabs), figsize=(fs.DOUBLE, 2.1 * len(costs) + 1.0),
                             squeeze=False, sharey=True)
    col = f"error_{measure}"
    letter = 0
    for j, stab in enumerate(stabs):
        sr = [r for r in rows if r["stabilisation"] == stab]
        check = [num(r, col) for r in sr if r["method"] == "reference_check"]
        for i, cost in enumerate(costs):
            ax = axes[i][j]
            for method, label, style in METHODS:
                # joined in the order of the method's parameter (coarse step / loose tolerance first)
                pts = [(num(r, cost), num(r, col)) for r in
                       sorted(sr, key=lambda r: -num(r, "value"))
                       if r["method"] == method and r["status"] == "completed"]
                pts = [(x, y) for x, y in pts if x > 0 and y > 0 and not math.isnan(x + y)]
                if pts:
                    ax.plot(*zip(*pts), label=label, ms=5, lw=1.2, **style)
                cut = [(num(r, cost), num(r, col)) for r in sr if r["method"] == method
                       and r["status"] == "completed" and num(r, "cutbacks") > 0]
                if cut:  # steps cut back (failed Newton / inverted element): open markers
                    ax.plot(*zip(*cut), ls="none", marker=style["marker"], ms=5, mfc="white",
                            mec=style["color"], label="backward Euler: some steps cut back")
            # The check is drawn where it informs (within three decades of the smallest run
            # error); a check at round-off (both references took the same steps) would only
            # stretch the axis.
            data_min = min((num(r, col) for r in sr if r["method"] not in
                            ("reference", "reference_check") and num(r, col) > 0),
                           default=0.0)
            if check and check[0] > 0 and check[0] > 1e-3 * data_min:
                ax.axhline(check[0], color="grey", lw=0.8, ls=":",
                           label="reference check (rtol 1e-7 vs 1e-8)")
            if cost == "factorizations":  # a handful: linear axis, integer ticks
                ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
                ax.set_xlim(left=0)
            else:
                ax.set_xscale("log")
                lo, hi = ax.get_xlim()
                subs = (1.0, 2.0, 5.0) if hi / lo < 300 else (1.0,)  # wide ranges: decades only
                ax.xaxis.set_major_locator(matplotlib.ticker.LogLocator(subs=subs))
                ax.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda x, _: f"{x:g}"))
                ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
            ax.set_yscale("log")
            ax.grid(True, which="major", alpha=0.3)
            ax.set_xlabel(COST[cost])
            if j == 0:
                ax.set_ylabel(f"time error, {SHORT[measure]} [–]")
            if i == 0:
                ax.set_title(STAB[stab])
            panel_letter(ax, letter)
            letter += 1
    handles, labels = axes[0][0].get_legend_handles_labels()
    for ax in axes.flat:  # the union of the panels' entries, in order
        for h, lab in zip(*ax.get_legend_handles_labels()):
            if lab not in labels:
                handles.append(h)
                labels.append(lab)
    ncol = 3 if len(stabs) >= 3 else 2
    fig.legend(handles, labels, loc="lower center", ncol=ncol, frameon=False,
               bbox_to_anchor=(0.5, 0.0))
    fig.suptitle(title)
    nrows = -(-len(labels) // ncol)
    height = fig.get_size_inches()[1]
    fig.tight_layout(rect=(0, (0.16 * nrows + 0.1) / height, 1, 1 - 0.3 / height))
    for path in fs.save(fig, out / name, tight=False):
        print(path)


def failure_figure(rows, out, name):
    """(a) largest converging step against strain; (b) the platen's strain increment per step at
    that step. A combination whose coarsest step (t_end) converged is a lower bound (arrow)."""
    fig, axes = plt.subplots(1, 2, figsize=(fs.DOUBLE, 3.3))
    styles = {"gls": dict(color="tab:blue", marker="o", ms=10, mfc="none", mew=1.6, ls="-"),
              "none": dict(color="tab:red", marker="s", ms=5, ls="--"),
              "flux_perturbation": dict(color="tab:purple", marker="^", ms=6, ls=":")}
    by = collections.defaultdict(dict)
    t_end, height = {}, {}
    for r in rows:
        strain = num(r, "param:loading.strain")
        by[r["stabilisation"]][strain] = num(r, "largest_converged_dt")
        t_end[strain] = num(r, "t_end")
    for stab, d in by.items():
        xs = [x for x in sorted(d) if not math.isnan(d[x])]
        for ax, f in ((axes[0], lambda x: d[x]), (axes[1], lambda x: 100 * x * d[x] / t_end[x])):
            ys = [f(x) for x in xs]
            ax.plot([100 * x for x in xs], ys, label=STAB[stab], lw=1.3, **styles.get(stab, {}))
            for x, y in zip(xs, ys):
                if abs(d[x] - t_end[x]) < 1e-9 * t_end[x]:
                    ax.annotate("", xy=(100 * x, y * 1.6), xytext=(100 * x, y),
                                arrowprops=dict(arrowstyle="->", color="grey"))
        failed = [x for x in sorted(d) if math.isnan(d[x])]
        for x in failed:
            axes[0].plot(100 * x, 1, "x", color=styles.get(stab, {}).get("color", "k"))
    xs = sorted(t_end)
    axes[0].plot([100 * x for x in xs], [t_end[x] for x in xs], color="grey", ls=":", lw=1,
                 label="t_end (the whole load in one step)")
    axes[0].set_ylabel("largest converging Δt [s]")
    axes[1].set_ylabel("platen strain per step at that Δt [%]")
    for i, ax in enumerate(axes):
        ax.set_xscale("log")
        ax.set_yscale("log" if i == 0 else "linear")
        if i == 1:
            ax.set_ylim(bottom=0)
        ax.set_xlabel("applied compressive strain [%]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
        fs.plain_log_ticks(ax.xaxis)
        if i == 0:
            fs.plain_log_ticks(ax.yaxis)
        panel_letter(ax, i)
    fig.suptitle("Backward Euler without cut-back, mesh 1, k = 1e-3, 2.5 µm/s\n"
                 "(Δt = t_end / N, N = 1, 2, 3, 4, 6, 8, 12, 16; arrow: t_end itself converged)")
    for path in fs.save(fig, out / name):
        print(path)


def param_text(r):
    if r["method"] == "backward_euler":
        return f"Δt {float(r['value']):g} s"
    if r["method"].startswith("reference"):
        return f"rtol {float(r['bdf_rtol']):g}"
    return f"rtol {float(r['value']):g}"


def fmt(x, digits=2):
    return "—" if math.isnan(x) else f"{x:.{digits}e}"


def wall_at(runs, target, cost="wall_s"):
    """Wall time at the target pressure error, interpolated log-log between the two runs of a
    method (in parameter order) that bracket it; ('<=', wall) of the cheapest run when even the
    coarsest run is below the target; None when no run reaches it."""
    runs = sorted(runs, key=lambda r: -num(r, "value"))
    pts = [(num(r, "error_pressure"), num(r, cost)) for r in runs]
    pts = [(e, w) for e, w in pts if e > 0 and w > 0]
    if not pts or min(e for e, _ in pts) > target:
        return None
    if pts[0][0] <= target:
        return "≤", min(w for e, w in pts if e <= target)
    for (e0, w0), (e1, w1) in zip(pts, pts[1:]):
        if e0 > target >= e1:
            f = math.log(target / e0) / math.log(e1 / e0)
            return "≈", math.exp(math.log(w0) + f * math.log(w1 / w0))
    return "≤", min(w for e, w in pts if e <= target)


def markdown(path):
    rows = read(path)
    if not rows:
        return
    scene = rows[0]["scene"]
    if "divisor" in rows[0]:
        print(f"\n**{scene}**: every attempt (dt = t_end / N, coarsest first)\n")
        print("| stabilisation | strain | N | Δt [s] | status | Newton | wall [s] | message |")
        print("|---|---|---|---|---|---|---|---|")
        for r in rows:
            msg = (r.get("message") or "").replace("|", "/")[:110]
            print(f"| {STAB[r['stabilisation']]} | {100 * num(r, 'param:loading.strain'):g} % | "
                  f"{r['divisor']} | {num(r, 'dt'):g} | {r['status']} | {r['newton_iterations']} | "
                  f"{num(r, 'wall_s'):.1f} | {msg} |")
        return
    groups = collections.defaultdict(list)
    for r in rows:
        groups[group_key(r)].append(r)
    for key, gr in groups.items():
        label = SCENE.get(scene, scene) + "".join(f", {k.split(':')[-1]} = {v}" for k, v in key)
        print(f"\n**{label}**: every run\n")
        print("| stabilisation | method | parameter | e_p | e_F (max) | e_F (end) | e_u | wall [s] "
              "| factorisations | steps | Newton | error-test failures | status |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for r in gr:
            name = "reference" if r["method"] == "reference" else (
                "reference check" if r["method"] == "reference_check" else
                dict((m, lab) for m, lab, _ in METHODS)[r["method"]])
            print(f"| {STAB[r['stabilisation']]} | {name} | {param_text(r)} | "
                  f"{fmt(num(r, 'error_pressure'))} | {fmt(num(r, 'error_reaction'))} | "
                  f"{fmt(num(r, 'error_reaction_end'))} | {fmt(num(r, 'error_displacement'))} | "
                  f"{num(r, 'wall_s'):.3g} | {r['factorizations']} | {r['steps']} | "
                  f"{r['newton_iterations']} | {r['error_test_failures'] or '—'} | {r['status']} |")
        at = [k for k in gr[0] if k.startswith("overshoot@")]
        if at:
            print(f"\n**{label}**: overshoot (max_line p − p_mid) / p_mid at the first "
                  "output and at fixed times\n")
            print("| stabilisation | method | parameter | first output t [s] | overshoot there | "
                  + " | ".join(f"overshoot at t = {k.split('@')[1]} s" for k in at) + " |")
            print("|---|---|---|---|---|" + "---|" * len(at))
            for r in gr:
                name = "reference" if r["method"] == "reference" else (
                    "reference check" if r["method"] == "reference_check" else
                    dict((m, lab) for m, lab, _ in METHODS)[r["method"]])
                cells = [fmt(num(r, k), 4) if not math.isnan(num(r, k)) else "—" for k in at]
                print(f"| {STAB[r['stabilisation']]} | {name} | {param_text(r)} | "
                      f"{num(r, 't_first'):g} | {num(r, 'overshoot_first'):.5f} | "
                      + " | ".join(c if c == "—" else f"{num(r, k):.5f}" for c, k in zip(cells, at))
                      + " |")
        print(f"\n**{label}**: cheapest run (wall) reaching a pressure time error\n")
        print("| stabilisation | target | backward Euler, fixed Δt | adaptive backward Euler | "
              "BDF (IDA, orders 1–5) | BE / BDF at the target: wall; Newton (log-log interpolated; ≥: "
              "BDF's loosest run is already below the target) |")
        print("|---|---|---|---|---|---|")
        for stab in STAB:
            sr = [r for r in gr if r["stabilisation"] == stab and r["status"] == "completed"]
            if not sr:
                continue
            for target in (1e-3, 1e-4):
                cells, walls = [], {}
                for method, _, _ in METHODS:
                    ok = [r for r in sr if r["method"] == method
                          and num(r, "error_pressure") <= target]
                    if not ok:
                        cells.append("not reached")
                        continue
                    best = min(ok, key=lambda r: num(r, "wall_s"))
                    walls[method] = num(best, "wall_s")
                    cells.append(f"{walls[method]:.3g} s ({param_text(best)}: e_p "
                                 f"{num(best, 'error_pressure'):.1e}, {best['factorizations']} fact., "
                                 f"{best['steps']} steps, {best['newton_iterations']} Newton)")
                ratio = []
                for cost, unit in (("wall_s", " s"), ("newton_iterations", " Newton")):
                    be = wall_at([r for r in sr if r["method"] == "backward_euler"], target, cost)
                    bdf = wall_at([r for r in sr if r["method"] == "bdf"], target, cost)
                    if be and bdf:
                        ratio.append(f"{be[1]:.3g}{unit} / {bdf[1]:.3g}{unit} = "
                                     f"{'≥ ' if bdf[0] == '≤' and be[0] == '≈' else ''}"
                                     f"{be[1] / bdf[1]:.2g}")
                ratio = "; ".join(ratio) or "—"
                print(f"| {STAB[stab]} | {target:g} | " + " | ".join(cells) + f" | {ratio} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv", nargs="+", type=pathlib.Path)
    ap.add_argument("-o", "--output", type=pathlib.Path, default=ROOT / "docs/figures/integrators")
    ap.add_argument("--second", choices=["reaction", "displacement"], default=None,
                    help="second measure (default: reaction, or displacement when no reaction)")
    ap.add_argument("--markdown", action="store_true", help="print Markdown tables, no figures")
    args = ap.parse_args()
    if args.markdown:
        for path in args.csv:
            markdown(path)
        return
    args.output.mkdir(parents=True, exist_ok=True)
    fs.apply()
    for path in args.csv:
        rows = read(path)
        if not rows:
            continue
        scene = rows[0]["scene"]
        if "divisor" in rows[0]:
            failure_figure(rows, args.output, f"{scene}.png")
            continue
        groups = collections.defaultdict(list)
        for r in rows:
            groups[group_key(r)].append(r)
        for key, gr in groups.items():
            suffix = "".join(f"_{k.split('.')[-1]}{v}" for k, v in key)
            label = SCENE.get(scene, scene) + "".join(
                f", {k.split(':')[-1]} = {v}" for k, v in key)
            # Terzaghi: the bottom reaction equals the load at every instant; use the settlement
            second = args.second or ("displacement" if scene == "terzaghi" or
                                     not any(r.get("error_reaction") for r in gr) else "reaction")
            time_error_figure(gr, "pressure", ["wall_s", "factorizations", "newton_iterations"],
                              args.output, f"time_{scene}{suffix}_pressure.png",
                              f"Time error of the pressure against cost: {label}")
            time_error_figure(gr, second, ["wall_s", "newton_iterations"], args.output,
                              f"time_{scene}{suffix}_{second}.png",
                              f"Time error of the {'platen reaction' if second == 'reaction' else 'settlement'}"
                              f" against cost: {label}")


if __name__ == "__main__":
    main()
