#!/usr/bin/python3
"""Figures from study tables (runs.csv written by tools/study.py) and the runs' line.csv.

usage: tools/plot_study.py KIND STUDY_DIR [STUDY_DIR ...] -o OUT_DIR

KIND:
  paper          the paper's figures (study paper_figures [+ paper_figures_mesh4])
  sensitivity    time step and loading rate, backward Euler and BDF (study time_step)
  work           work-precision: discrepancy at the end against wall time and linear solves
  stability      first-step overshoot over (k, dt) per mesh with the line c dt / h^2 = 1/6
  remedies       cost of accuracy: refinement, GLS, graded mesh (study remedies)

Each writes PNG files into OUT_DIR and prints their names.
"""
import argparse
import csv
import json
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import ticker  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent


def read_rows(dirs):
    rows = []
    for d in dirs:
        with open(pathlib.Path(d) / "runs.csv") as f:
            for row in csv.DictReader(f):
                row["_dir"] = pathlib.Path(d) / "runs" / row["run"]
                rows.append(row)
    return rows


def num(row, key):
    v = row.get(key, "")
    try:
        return float(v)
    except (TypeError, ValueError):
        return math.nan


def line_at(run_dir, t=None):
    """(z, p, uz) on the line at time t (default: the last output); z and uz are the axial
    coordinate and displacement (y and uy of a section model such as the axisymmetric
    reference)."""
    data = {}
    try:
        model = json.loads((pathlib.Path(run_dir) / "summary.json").read_text())["model"]
    except (OSError, ValueError, KeyError):
        model = "three_dimensional"
    z, uz = ("y", "uy") if model in ("axisymmetric", "plane_strain") else ("z", "uz")
    with open(pathlib.Path(run_dir) / "line.csv") as f:
        for r in csv.DictReader(f):
            data.setdefault(float(r["t"]), []).append((float(r[z]), float(r["p"]), float(r[uz])))
    times = sorted(data)
    key = times[-1] if t is None else min(times, key=lambda x: abs(x - t))
    pts = sorted(data[key])
    return [p[0] for p in pts], [p[1] for p in pts], [p[2] for p in pts]


def axial_strain(z, uz):
    """Compressive axial strain −du_z/dz at the nodes (one-sided at the ends)."""
    out = []
    for i in range(len(z)):
        a, b = max(i - 1, 0), min(i + 1, len(z) - 1)
        out.append(-(uz[b] - uz[a]) / (z[b] - z[a]))
    return out


def reference_dir(row):
    label = row.get("reference", "")
    if not label:
        return None
    path = pathlib.Path(label.split()[-1])
    return path if path.is_absolute() else ROOT / path


def select(rows, **conds):
    out = []
    for r in rows:
        ok = True
        for k, v in conds.items():
            rv = r.get(k, "")
            if isinstance(v, float):
                ok = ok and rv != "" and math.isclose(float(rv), v, rel_tol=1e-9)
            else:
                ok = ok and rv == str(v)
        if ok:
            out.append(r)
    return out


def mesh_label(row):
    lc = num(row, "mesh_lc")
    names = {1.3: "mesh 1", 0.98: "mesh 2", 0.73: "mesh 3", 0.57: "mesh 4"}
    layers = int(num(row, "mesh_layers") or 0)
    if layers > 0:
        return f"swept, {layers} layers"
    return next((n for v, n in names.items() if math.isclose(v, lc)), f"lc {lc:g}")


def pressure_panel(ax, runs, label_of, title, with_reference=True):
    for r in runs:
        z, p, _ = line_at(r["_dir"])
        ax.plot(z, [v * 1e3 for v in p], marker=".", ms=3, lw=1, label=label_of(r))
    if with_reference and runs:
        ref = reference_dir(runs[0])
        if ref and (ref / "line.csv").is_file():
            z, p, _ = line_at(ref, num(runs[0], "t_end"))
            ax.plot(z, [v * 1e3 for v in p], "k--", lw=1, label="reference")
    ax.set_xlabel("z on the axis [mm]")
    ax.set_ylabel("pressure [kPa]")
    ax.set_title(title, fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)


def save(fig, out, name, tight=True):
    """PNG at 200 dpi (print-ready)."""
    path = pathlib.Path(out) / name
    if tight:
        fig.tight_layout()
    fig.savefig(path, dpi=200)
    plt.close(fig)
    print(path)


def kfmt(r):
    return f"k = {num(r, 'permeability'):g}"


# ---- kinds ---------------------------------------------------------------------------------

def paper(rows, out):
    mesh2_k01 = [r for r in select(rows, sweep="permeability") if math.isclose(num(r, "permeability"), 0.1)]
    if mesh2_k01:
        r = mesh2_k01[0]
        z, p, uz = line_at(r["_dir"])
        fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.6))
        a.plot(z, [100 * e for e in axial_strain(z, uz)], ".-")
        a.set_xlabel("z [mm]"), a.set_ylabel("axial strain [%]"), a.grid(alpha=0.3)
        a.set_title("nodal strain on the axis, mesh 2, k = 0.1, 1 % strain", fontsize=9)
        b.plot(z, [v * 1e3 for v in p], ".-")
        b.set_xlabel("z [mm]"), b.set_ylabel("pressure [kPa]"), b.grid(alpha=0.3)
        b.set_title("pressure on the axis", fontsize=9)
        save(fig, out, "paper_mesh2_k0.1_strain_pressure.png")
    perm = select(rows, sweep="permeability")
    if perm:
        fig, ax = plt.subplots(figsize=(6, 4))
        pressure_panel(ax, sorted(perm, key=lambda r: -num(r, "permeability")), kfmt,
                       "influence of permeability, mesh 2, no GLS", with_reference=False)
        save(fig, out, "paper_permeability.png")
    for sweep, ks, name in (("refine_nogls", (1e-2, 5e-3, 1e-3), "no GLS"),
                            ("refine_gls", (5e-3, 1e-3), "GLS")):
        runs = select(rows, sweep=sweep)
        if not runs:
            continue
        fig, axes = plt.subplots(1, len(ks), figsize=(4.2 * len(ks), 3.8), squeeze=False)
        for ax, k in zip(axes[0], ks):
            sel = sorted([r for r in runs if math.isclose(num(r, "permeability"), k)],
                         key=lambda r: num(r, "unknowns"))
            pressure_panel(ax, sel, lambda r: f"{mesh_label(r)} (disc. {100 * num(r, 'discrepancy'):.1f} %)",
                           f"mesh refinement, {name}, k = {k:g}")
        save(fig, out, f"paper_{sweep}.png")
    strain = select(rows, sweep="strain")
    if strain:
        fig, axes = plt.subplots(1, 2, figsize=(9, 3.8))
        for ax, stab in zip(axes, ("none", "gls")):
            sel = sorted(select(strain, stabilisation=stab), key=lambda r: num(r, "strain"))
            for r in sel:
                z, p, _ = line_at(r["_dir"])
                pm = max(abs(v) for v in p) or 1.0
                ax.plot(z, [v / pm for v in p], ".-", ms=3,
                        label=f"{100 * num(r, 'strain'):g} % (overshoot {100 * num(r, 'overshoot'):.1f} %)")
            ax.set_xlabel("z [mm]"), ax.set_ylabel("p / max p"), ax.grid(alpha=0.3)
            ax.set_title(f"higher strains, mesh 2, k = 1e-3, {'GLS' if stab == 'gls' else 'no GLS'}",
                         fontsize=9)
            ax.legend(fontsize=7)
        save(fig, out, "paper_higher_strains.png")


def sensitivity(rows, out):
    fig, axes = plt.subplots(2, 2, figsize=(10, 7.5))
    for col, stab in enumerate(("none", "gls")):
        be = sorted(select(rows, sweep="be_dt", stabilisation=stab), key=lambda r: num(r, "dt"))
        pressure_panel(axes[0][col], be, lambda r: f"BE dt = {num(r, 'dt'):g} s "
                       f"(osc. {num(r, 'oscillation_max'):.2f})",
                       f"backward Euler, t = 32 s, {'GLS' if stab == 'gls' else 'no GLS'}")
        bdf = sorted(select(rows, sweep="bdf_rtol", stabilisation=stab), key=lambda r: -num(r, "bdf_rtol"))
        pressure_panel(axes[1][col], bdf, lambda r: f"BDF rtol = {num(r, 'bdf_rtol'):g} "
                       f"(osc. {num(r, 'oscillation_max'):.2f})",
                       f"variable-order BDF, t = 32 s, {'GLS' if stab == 'gls' else 'no GLS'}")
    save(fig, out, "sensitivity_time_step.png")
    # The overshoot over time: where (and when) the oscillation lives.
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8), sharey=True)
    for ax, stab in zip(axes, ("none", "gls")):
        runs = sorted(select(rows, sweep="be_dt", stabilisation=stab), key=lambda r: num(r, "dt"))
        runs += sorted(select(rows, sweep="bdf_rtol", stabilisation=stab), key=lambda r: -num(r, "bdf_rtol"))
        for r in runs:
            outs = [o for o in json.loads((r["_dir"] / "summary.json").read_text())["outputs"]
                    if o["t"] > 0 and o.get("overshoot") is not None]
            be = r["integrator"] == "backward_euler"
            ax.plot([o["t"] for o in outs], [100 * o["overshoot"] for o in outs],
                    "o-" if be else "k--" if math.isclose(num(r, "bdf_rtol"), 1e-4) else ":",
                    ms=3, lw=1, label=(f"BE dt = {num(r, 'dt'):g} s" if be
                                       else f"BDF rtol {num(r, 'bdf_rtol'):g}"))
        ax.set_xlabel("t [s]"), ax.set_ylabel("overshoot on the axis [%]")
        ax.set_title(f"overshoot over time, mesh 2, k = 1e-3, {'GLS' if stab == 'gls' else 'no GLS'}",
                     fontsize=9)
        ax.grid(alpha=0.3), ax.legend(fontsize=7)
    save(fig, out, "sensitivity_overshoot_over_time.png")
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    for ax, integ in zip(axes, ("be_rate", "bdf_rate")):
        for stab, style in (("none", "-"), ("gls", "--")):
            for r in sorted(select(rows, sweep=integ, stabilisation=stab),
                            key=lambda r: num(r, "loading_rate_um_s")):
                z, p, _ = line_at(r["_dir"])
                pm = max(p) or 1.0
                ax.plot(z, [v / pm for v in p], style, label=f"{num(r, 'loading_rate_um_s'):g} um/s, "
                        f"{stab} (overshoot {100 * num(r, 'overshoot_max'):.1f} %)")
        ax.set_xlabel("z [mm]"), ax.set_ylabel("p / max p at 1 % strain"), ax.grid(alpha=0.3)
        ax.set_title("loading rate, " + ("backward Euler dt = 6.4 s" if integ == "be_rate"
                                         else "BDF rtol 1e-4"), fontsize=9)
        ax.legend(fontsize=6)
    save(fig, out, "sensitivity_loading_rate.png")


def work(rows, out):
    """Discrepancy and mid-height error at t = 32 s against two cost measures: wall time and
    linear solves (one back-substitution per Newton iteration). Factorisations are a poor
    cost axis here: backward Euler reuses one factorisation for the whole run at any Δt and
    BDF needs three at any rtol, so they are given in the legend instead."""
    names = {"BE": "backward Euler over Δt", "BDF": "BDF over rtol"}
    groups = {}
    for r in rows:
        if r.get("status") != "completed":
            continue
        integ = "BE" if r["integrator"] == "backward_euler" else "BDF"
        groups.setdefault((mesh_label(r), integ, r["stabilisation"]), []).append(r)
    colours = {("mesh 1", "gls"): "tab:blue", ("mesh 1", "none"): "tab:orange",
               ("mesh 2", "gls"): "tab:green", ("mesh 2", "none"): "tab:red"}
    for xkey, xlabel, name in (("wall_s", "wall time [s]", "work_precision_wall.png"),
                               ("linear_solves", "linear solves (Newton iterations)",
                                "work_precision_solves.png")):
        fig, axes = plt.subplots(1, 2, figsize=(7.2, 3.6))
        for ax, letter, ykey, ylabel in (
                (axes[0], "a", "discrepancy", "discrepancy at t = 32 s [%]"),
                (axes[1], "b", "midheight_error", "mid-height error at t = 32 s [%]")):
            for (mesh, integ, stab), rs in sorted(groups.items()):
                # Along each curve the method's own parameter: BE from large to small dt,
                # BDF from loose to tight rtol.
                rs = sorted(rs, key=lambda r: -num(r, "dt") if integ == "BE" else -num(r, "bdf_rtol"))
                fact = sorted({int(num(r, "factorizations")) for r in rs})
                ftxt = "/".join(str(f) for f in fact)
                ax.loglog([num(r, xkey) for r in rs], [100 * num(r, ykey) for r in rs],
                          ("o-" if integ == "BE" else "s--"), ms=3.5, lw=1,
                          color=colours.get((mesh, stab), None),
                          label=f"{mesh}, {'GLS' if stab == 'gls' else 'no stabilisation'}, "
                                f"{names[integ]} ({ftxt} fact.)")
            ax.set_xlabel(xlabel), ax.set_ylabel(ylabel)
            ax.grid(alpha=0.3, which="both")
            plain_log_ticks(ax.yaxis), plain_log_ticks(ax.xaxis)
            ax.tick_params(which="minor", labelsize=7)
            panel_letter(ax, letter)
        handles, labels = axes[0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="lower center", ncol=2, fontsize=7, frameon=False)
        fig.tight_layout(rect=(0, 0.2, 1, 1))
        save(fig, out, name, tight=False)


def panel_letter(ax, letter):
    ax.set_title(f"({letter})", loc="left", fontsize=10, fontweight="bold")


def plain_log_ticks(axis):
    """Tick labels as plain numbers (6, 8, 10) instead of 6×10⁰ on a log axis; minor ticks
    labelled at 2, 3, 5 per decade, or all of them when the axis spans less than a decade."""
    lo, hi = axis.get_view_interval()
    narrow = lo > 0 and hi / lo < 10
    axis.set_major_formatter(ticker.FuncFormatter(lambda v, _: f"{v:g}"))

    def minor(v, _):
        lead = round(v / 10 ** math.floor(math.log10(v)), 6) if v > 0 else 0
        return f"{v:g}" if narrow or lead in (2, 3, 5) else ""

    axis.set_minor_formatter(ticker.FuncFormatter(minor))


def stability(rows, out):
    """First-step overshoot on a (Δt, k) grid per mesh, one cell per run with its value, and
    where r = c Δt / h² = 1/6 falls in each row (c = k (λ + 2μ), h the element length on the
    axis). The grid is drawn by index, not on log axes, so that close Δt (6.4 and 8 s) do not
    overlap."""
    meshes = sorted({mesh_label(r) for r in rows})
    for stab in ("none", "gls"):
        cols = min(len(meshes), 2)
        nrows = (len(meshes) + cols - 1) // cols
        fig, axes = plt.subplots(nrows, cols, figsize=(3.8 * cols + 1.6, 3.0 * nrows + 0.9),
                                 squeeze=False, layout="constrained")
        flat = [a for row in axes for a in row]
        for ax in flat[len(meshes):]:
            ax.set_visible(False)
        im = None
        for i, (ax, mesh) in enumerate(zip(flat, meshes)):
            sel = [r for r in rows if mesh_label(r) == mesh and r["stabilisation"] == stab
                   and r.get("status") == "completed"]
            if not sel:
                continue
            dts = sorted({num(r, "dt") for r in sel})
            ks = sorted({num(r, "permeability") for r in sel})
            grid = [[math.nan] * len(dts) for _ in ks]
            for r in sel:
                grid[ks.index(num(r, "permeability"))][dts.index(num(r, "dt"))] = \
                    100 * num(r, "overshoot")
            im = ax.imshow(grid, origin="lower", cmap="magma_r", vmin=0, vmax=15, aspect="auto")
            for a, row in enumerate(grid):
                for b, o in enumerate(row):
                    if math.isnan(o):
                        continue
                    text = ("<0.01" if o < 0.01 else f"{o:.2f}" if o < 1 else
                            f"{o:.1f}" if o < 10 else f"{o:.0f}")
                    ax.text(b, a, text, ha="center", va="center", fontsize=7,
                            color="white" if o > 9 else "black")
            ax.set_xticks(range(len(dts)), [f"{d:g}" for d in dts])
            ax.set_yticks(range(len(ks)), [f"{k:g}" for k in ks])
            # Threshold Δt* = h² / (6 (λ + 2μ) k) per row, placed by log interpolation between
            # the columns; rows whose Δt* lies outside the grid get no point.
            h, m = num(sel[0], "h_line"), num(sel[0], "lambda") + 2 * num(sel[0], "mu")
            pos = [math.log(v) for v in dts]
            xs, ys = [], []
            for a, k in enumerate(ks):
                d = math.log(h * h / (6 * m * k))
                j = next((j for j in range(len(dts) - 1) if pos[j] <= d <= pos[j + 1]), None)
                if j is not None:
                    xs.append(j + (d - pos[j]) / (pos[j + 1] - pos[j])), ys.append(a)
            ax.plot(xs, ys, "c-", lw=2, marker="|", ms=10)
            ax.set_xlim(-0.5, len(dts) - 0.5), ax.set_ylim(-0.5, len(ks) - 0.5)
            ax.set_xlabel("Δt [s]")
            if i % cols == 0:
                ax.set_ylabel("k [mm⁴/(N s)]")
            ax.set_title(f"{mesh}, h = {h:.2f} mm on the axis", fontsize=9)
            panel_letter(ax, "abcd"[i])
        fig.suptitle(f"First backward-Euler step, {'GLS' if stab == 'gls' else 'no stabilisation'}:"
                     f" pressure overshoot [% of p_mid]\ncyan line: c Δt / h² = 1/6 with"
                     f" c = k (λ + 2μ)", fontsize=10)
        if im is not None:
            fig.colorbar(im, ax=flat, shrink=0.85, label="overshoot [%]")
        save(fig, out, f"stability_map_{stab}.png", tight=False)


def remedies(rows, out):
    fig, ax = plt.subplots(figsize=(7, 5))
    series = {
        "uniform refinement, no GLS": [r for r in select(rows, sweep="uniform", stabilisation="none")],
        "GLS, same meshes": [r for r in select(rows, sweep="uniform", stabilisation="gls")],
        "swept mesh graded toward the drained faces, no GLS": select(rows, sweep="graded"),
        "24 layers graded 30:1 and 100:1, no GLS": select(rows, sweep="graded_ratio"),
    }
    for (label, rs), style in zip(series.items(), ("o-", "s-", "^-", "v-")):
        rs = [r for r in rs if r.get("status") == "completed"]
        if not rs:
            continue
        rs.sort(key=lambda r: (num(r, "unknowns"), num(r, "wall_s")))
        ax.loglog([num(r, "wall_s") for r in rs], [100 * num(r, "discrepancy") for r in rs], style,
                  label=label)
        for r in rs:
            text = f"{num(r, 'unknowns') / 1e3:.0f}k"
            if r.get("sweep") == "graded_ratio":
                text += f", {num(r, 'param:mesh.layer_grading_ratio'):g}:1"
            ax.annotate(text, (num(r, "wall_s"), 100 * num(r, "discrepancy")),
                        fontsize=6, xytext=(3, 3), textcoords="offset points")
    ax.axhline(1.0, color="grey", lw=0.8)
    ax.set_xlabel("wall time [s]"), ax.set_ylabel("discrepancy at t = 32 s [%]")
    ax.set_title("cost of accuracy, k = 1e-3, backward Euler dt = 6.4 s (labels: unknowns)", fontsize=9)
    ax.grid(alpha=0.3, which="both"), ax.legend(fontsize=7)
    save(fig, out, "remedies_cost_of_accuracy.png")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kind", choices=["paper", "sensitivity", "work", "stability", "remedies"])
    ap.add_argument("studies", nargs="+")
    ap.add_argument("-o", "--output", default=str(ROOT / "docs" / "figures" / "results"))
    args = ap.parse_args()
    pathlib.Path(args.output).mkdir(parents=True, exist_ok=True)
    rows = read_rows(args.studies)
    globals()[args.kind](rows, args.output)


if __name__ == "__main__":
    main()
