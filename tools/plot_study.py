#!/usr/bin/python3
"""Figures from study tables (runs.csv written by tools/study.py) and the runs' line.csv.

usage: tools/plot_study.py KIND STUDY_DIR [STUDY_DIR ...] -o OUT_DIR

KIND:
  paper          the paper's figures (study paper_figures [+ paper_figures_mesh4])
  sensitivity    time step and loading rate, backward Euler and BDF (study time_step)
  work           work-precision: discrepancy at the end against wall time and linear solves
  stability      first-step overshoot over (k, dt) per mesh with the line c dt / h^2 = 1/6
  remedies       cost of accuracy: refinement, GLS, graded mesh (study remedies)
  fixed_tau      GLS with tau fixed at its dt = 6.4 s value against the paper's h^2/(4 k dt)
                 (study gls_fixed_tau)
  length         GLS element length h: circumradius, edges, volume diameter (study gls_length)
  quadrature     4 against 27 quadrature points: line pressure and their difference
                 (study gls_quadrature)

Each writes PNG files (200 dpi) with a vector PDF beside each into OUT_DIR and prints their names.
Figures are drawn at their printed width (7.2 in for two columns, 3.5 in for one).
"""
import argparse
import csv
import json
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import colors  # noqa: E402

import figure_style as fs  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
STAB = {"none": "no stabilisation", "gls": "GLS"}
plain_log_ticks = fs.plain_log_ticks


def read_rows(dirs):
    rows = []
    for d in dirs:
        with open(pathlib.Path(d) / "runs.csv") as f:
            for row in csv.DictReader(f):
                row["_dir"] = pathlib.Path(d) / "runs" / row["run"]
                row["_study"] = pathlib.Path(d)
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
    """The reference run a row was measured against. Its path in the table is relative to the
    checkout that ran the study: tried under this checkout, then under the one holding the
    study folder (<root>/results/studies/<study>), so that a study read from elsewhere finds
    its reference cache too."""
    label = row.get("reference", "")
    if not label:
        return None
    path = pathlib.Path(label.split()[-1])
    if path.is_absolute():
        return path
    candidates = [ROOT / path]
    study = row.get("_study")
    if study is not None and len(pathlib.Path(study).resolve().parents) > 2:
        candidates.append(pathlib.Path(study).resolve().parents[2] / path)
    return next((c for c in candidates if c.is_dir()), candidates[0])


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


def g(v):
    """A number as %g without the exponent's leading zero (1e-5, not 1e-05)."""
    return f"{v:g}".replace("e-0", "e-").replace("e+0", "e")


def mesh_label(row):
    lc = num(row, "mesh_lc")
    names = {1.3: "mesh 1", 0.98: "mesh 2", 0.73: "mesh 3", 0.57: "mesh 4"}
    layers = num(row, "mesh_layers")
    if layers > 0:
        layers = int(layers)
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
    ax.set_ylabel("pressure p [kPa]")
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend()


def save(fig, out, name, tight=True):
    """NAME (PNG, 200 dpi) and the same name as PDF into OUT."""
    for path in fs.save(fig, pathlib.Path(out) / name, tight=tight):
        print(path)


# ---- kinds ---------------------------------------------------------------------------------

def paper(rows, out):
    mesh2_k01 = [r for r in select(rows, sweep="permeability") if math.isclose(num(r, "permeability"), 0.1)]
    if mesh2_k01:
        r = mesh2_k01[0]
        z, p, uz = line_at(r["_dir"])
        fig, (a, b) = plt.subplots(1, 2, figsize=(fs.DOUBLE, 2.8))
        a.plot(z, [100 * e for e in axial_strain(z, uz)], ".-")
        a.set_xlabel("z on the axis [mm]"), a.set_ylabel("axial strain [%]"), a.grid(alpha=0.3)
        a.set_title("nodal axial strain")
        b.plot(z, [v * 1e3 for v in p], ".-")
        b.set_xlabel("z on the axis [mm]"), b.set_ylabel("pressure p [kPa]"), b.grid(alpha=0.3)
        b.set_title("pressure")
        fig.suptitle("on the axis: mesh 2, k = 0.1 mm⁴/(N s), 1 % strain, t = 32 s")
        fs.letters([a, b])
        save(fig, out, "paper_mesh2_k0.1_strain_pressure.png")
    perm = select(rows, sweep="permeability")
    if perm:
        fig, ax = plt.subplots(figsize=(fs.SINGLE, 2.8))
        pressure_panel(ax, sorted(perm, key=lambda r: -num(r, "permeability")),
                       lambda r: f"{num(r, 'permeability'):g}",
                       "permeability, mesh 2, no stabilisation", with_reference=False)
        ax.legend(title="k [mm⁴/(N s)]")
        save(fig, out, "paper_permeability.png")
    for sweep, ks, name in (("refine_nogls", (1e-2, 5e-3, 1e-3), "no stabilisation"),
                            ("refine_gls", (5e-3, 1e-3), "GLS")):
        runs = select(rows, sweep=sweep)
        if not runs:
            continue
        fig, axes = plt.subplots(1, len(ks), figsize=(fs.DOUBLE, 3.0), squeeze=False, sharey=True)
        for ax, k in zip(axes[0], ks):
            sel = sorted([r for r in runs if math.isclose(num(r, "permeability"), k)],
                         key=lambda r: num(r, "unknowns"))
            pressure_panel(ax, sel, lambda r: f"{mesh_label(r)} ({100 * num(r, 'discrepancy'):.1f} %)",
                           f"k = {k:g} mm⁴/(N s)")
            ax.legend(title="mesh (discrepancy)", handlelength=1.2)
        for ax in axes[0][1:]:
            ax.set_ylabel("")
        fig.suptitle(f"mesh refinement, {name}: pressure on the axis at t = 32 s")
        fs.letters(axes[0])
        save(fig, out, f"paper_{sweep}.png")
    strain = select(rows, sweep="strain")
    if strain:
        fig, axes = plt.subplots(1, 2, figsize=(fs.DOUBLE, 3.0), sharey=True)
        for ax, stab in zip(axes, ("none", "gls")):
            sel = sorted(select(strain, stabilisation=stab), key=lambda r: num(r, "strain"))
            for r in sel:
                z, p, _ = line_at(r["_dir"])
                pm = max(abs(v) for v in p) or 1.0
                ax.plot(z, [v / pm for v in p], ".-", ms=3,
                        label=f"{100 * num(r, 'strain'):g} % ({fs.percent(100 * num(r, 'overshoot'))} %)")
            ax.set_xlabel("z on the axis [mm]"), ax.grid(alpha=0.3)
            ax.set_title(STAB[stab])
            ax.legend(title="strain (overshoot)")
        axes[0].set_ylabel("p / max p [–]")
        fig.suptitle("higher strains, mesh 2, k = 1e-3 mm⁴/(N s): pressure on the axis at the end")
        fs.letters(axes)
        save(fig, out, "paper_higher_strains.png")


def sensitivity(rows, out):
    fig, axes = plt.subplots(2, 2, figsize=(fs.DOUBLE, 5.6), sharey="row")
    for col, stab in enumerate(("none", "gls")):
        be = sorted(select(rows, sweep="be_dt", stabilisation=stab), key=lambda r: num(r, "dt"))
        pressure_panel(axes[0][col], be, lambda r: f"Δt = {num(r, 'dt'):g} s "
                       f"({fs.sig(num(r, 'oscillation_max'))})",
                       f"backward Euler, t = 32 s, {STAB[stab]}")
        axes[0][col].legend(title="step (oscillation measure)")
        bdf = sorted(select(rows, sweep="bdf_rtol", stabilisation=stab), key=lambda r: -num(r, "bdf_rtol"))
        pressure_panel(axes[1][col], bdf, lambda r: f"rtol = {g(num(r, 'bdf_rtol'))} "
                       f"({fs.sig(num(r, 'oscillation_max'))})",
                       f"variable-order BDF, t = 32 s, {STAB[stab]}")
        axes[1][col].legend(title="tolerance (oscillation measure)")
    for ax in axes[:, 1]:
        ax.set_ylabel("")
    fs.letters(axes.flat)
    save(fig, out, "sensitivity_time_step.png")
    # The overshoot over time: where (and when) the oscillation lives.
    fig, axes = plt.subplots(1, 2, figsize=(fs.DOUBLE, 3.3), sharey=True)
    for ax, stab in zip(axes, ("none", "gls")):
        runs = sorted(select(rows, sweep="be_dt", stabilisation=stab), key=lambda r: num(r, "dt"))
        runs += sorted(select(rows, sweep="bdf_rtol", stabilisation=stab), key=lambda r: -num(r, "bdf_rtol"))
        for r in runs:
            outs = [o for o in json.loads((r["_dir"] / "summary.json").read_text())["outputs"]
                    if o["t"] > 0 and o.get("overshoot") is not None]
            be = r["integrator"] == "backward_euler"
            ax.plot([o["t"] for o in outs], [100 * o["overshoot"] for o in outs],
                    "o-" if be else "k--" if math.isclose(num(r, "bdf_rtol"), 1e-4) else ":",
                    ms=3, lw=1, label=(f"backward Euler, Δt = {num(r, 'dt'):g} s" if be
                                       else f"BDF, rtol = {g(num(r, 'bdf_rtol'))}"))
        ax.set_xlabel("time t [s]")
        ax.set_title(f"mesh 2, k = 1e-3, {STAB[stab]}")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("overshoot on the axis [% of p_mid]")
    fs.letters(axes)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=3)
    fig.tight_layout(rect=(0, 0.17, 1, 1))
    save(fig, out, "sensitivity_overshoot_over_time.png", tight=False)
    fig, axes = plt.subplots(1, 2, figsize=(fs.DOUBLE, 3.3), sharey=True)
    for ax, integ in zip(axes, ("be_rate", "bdf_rate")):
        rates = sorted({num(r, "loading_rate_um_s") for r in select(rows, sweep=integ)})
        for stab, style in (("none", "-"), ("gls", "--")):
            for r in sorted(select(rows, sweep=integ, stabilisation=stab),
                            key=lambda r: num(r, "loading_rate_um_s")):
                z, p, _ = line_at(r["_dir"])
                pm = max(p) or 1.0
                ax.plot(z, [v / pm for v in p], style,
                        color=f"C{rates.index(num(r, 'loading_rate_um_s'))}", label=f"{num(r, 'loading_rate_um_s'):g} µm/s, "
                        f"{STAB[stab]} ({fs.percent(100 * num(r, 'overshoot_max'))} %)")
        ax.set_xlabel("z on the axis [mm]"), ax.grid(alpha=0.3)
        ax.set_title("backward Euler, Δt = 6.4 s" if integ == "be_rate" else "BDF, rtol = 1e-4")
        ax.legend(title="rate, stabilisation (overshoot)", loc="lower center")
    axes[0].set_ylabel("p / max p at 1 % strain [–]")
    fs.letters(axes)
    save(fig, out, "sensitivity_loading_rate.png")


def work(rows, out):
    """Discrepancy and mid-height error at t = 32 s against two cost measures: wall time and
    linear solves (one back-substitution per Newton iteration). Factorisations are a poor
    cost axis here: backward Euler reuses one factorisation for the whole run at any Δt and
    BDF needs three at any rtol, so they are given in the legend instead; the end points of
    each backward-Euler curve are labelled with their Δt."""
    names = {"BE": "backward Euler", "BDF": "BDF"}
    groups = {}
    for r in rows:
        if r.get("status") != "completed":
            continue
        integ = "BE" if r["integrator"] == "backward_euler" else "BDF"
        groups.setdefault((mesh_label(r), integ, r["stabilisation"]), []).append(r)
    colours = {("mesh 1", "gls"): "tab:blue", ("mesh 1", "none"): "tab:orange",
               ("mesh 2", "gls"): "tab:green", ("mesh 2", "none"): "tab:red"}
    dts = sorted({num(r, "dt") for (_, i, _), rs in groups.items() if i == "BE" for r in rs})
    rtols = sorted({num(r, "bdf_rtol") for (_, i, _), rs in groups.items() if i == "BDF" for r in rs})
    along = "; ".join(t for t in (
        f"backward Euler Δt = {g(dts[-1])} … {g(dts[0])} s" if dts else "",
        f"BDF rtol = {g(rtols[-1])} … {g(rtols[0])}" if rtols else "") if t)
    for xkey, xlabel, name in (("wall_s", "wall time [s]", "work_precision_wall.png"),
                               ("linear_solves", "linear solves (Newton iterations) [–]",
                                "work_precision_solves.png")):
        fig, axes = plt.subplots(1, 2, figsize=(fs.DOUBLE, 3.9))
        for ax, letter, ykey, ylabel in (
                (axes[0], "a", "discrepancy", "discrepancy at t = 32 s [%]"),
                (axes[1], "b", "midheight_error", "mid-height error at t = 32 s [%]")):
            for (mesh, integ, stab), rs in sorted(groups.items()):
                # Along each curve the method's own parameter: BE from large to small dt,
                # BDF from loose to tight rtol.
                rs = sorted(rs, key=lambda r: -num(r, "dt") if integ == "BE" else -num(r, "bdf_rtol"))
                fact = sorted({int(num(r, "factorizations")) for r in rs})
                ftxt = "/".join(str(f) for f in fact)
                xs, ys = [num(r, xkey) for r in rs], [100 * num(r, ykey) for r in rs]
                ax.loglog(xs, ys, ("o-" if integ == "BE" else "s--"), ms=3.5, lw=1,
                          color=colours.get((mesh, stab), None),
                          label=f"{mesh}, {STAB.get(stab, stab)}, {names[integ]}, "
                                f"{ftxt} factorisation{'s' if fact != [1] else ''}")
                if integ == "BE" and mesh == "mesh 1" and stab == "none" and len(rs) > 1:
                    # the two ends of one backward-Euler curve, to read the direction of Δt
                    for r, x, y, ha in ((rs[0], xs[0], ys[0], "left"), (rs[-1], xs[-1], ys[-1], "right")):
                        ax.annotate(f"Δt = {num(r, 'dt'):g} s", (x, y), xytext=(0, -5),
                                    textcoords="offset points", ha=ha, va="top", fontsize=8,
                                    color=colours[(mesh, stab)])
            ax.set_xlabel(xlabel), ax.set_ylabel(ylabel)
            ax.margins(x=0.08, y=0.1)
            ax.grid(alpha=0.3, which="both")
            plain_log_ticks(ax.yaxis), plain_log_ticks(ax.xaxis)
            fs.panel_label(ax, letter)
        handles, labels = axes[0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="lower center", ncol=2,
                   title=f"along each curve: {along}" if along else None)
        fig.tight_layout(rect=(0, 0.25, 1, 1))
        save(fig, out, name, tight=False)


def stability(rows, out):
    """First-step overshoot on a (Δt, k) grid per mesh, one cell per run with its value, and
    where r = c Δt / h² = 1/6 falls in each row (c = k (λ + 2μ), h the element length on the
    axis). The grid is drawn by index, not on log axes, so that close Δt (6.4 and 8 s) do not
    overlap. Colours in bands (0.1, 1, 2, 5, 10 %: the 1 % band edge is the onset criterion of
    the tables); each cell prints its value to two significant figures ("<0.01" below)."""
    meshes = sorted({mesh_label(r) for r in rows})
    bounds = [0, 0.1, 1, 2, 5, 10, 15]
    cmap = plt.get_cmap("magma_r", len(bounds) + 1)
    norm = colors.BoundaryNorm(bounds, cmap.N, extend="max")
    for stab in ("none", "gls"):
        cols = min(len(meshes), 2)
        nrows = (len(meshes) + cols - 1) // cols
        fig, axes = plt.subplots(nrows, cols, figsize=(fs.DOUBLE, 2.55 * nrows + 0.55),
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
            im = ax.imshow(grid, origin="lower", cmap=cmap, norm=norm, aspect="auto")
            # Threshold Δt* = h² / (6 (λ + 2μ) k) per row, placed by log interpolation between
            # the columns; rows whose Δt* lies outside the grid get no point. Drawn under the
            # cell values, which sit on a light box.
            h, m = num(sel[0], "h_line"), num(sel[0], "lambda") + 2 * num(sel[0], "mu")
            pos = [math.log(v) for v in dts]
            xs, ys = [], []
            for a, k in enumerate(ks):
                d = math.log(h * h / (6 * m * k))
                j = next((j for j in range(len(dts) - 1) if pos[j] <= d <= pos[j + 1]), None)
                if j is not None:
                    xs.append(j + (d - pos[j]) / (pos[j + 1] - pos[j])), ys.append(a)
            ax.plot(xs, ys, "-", color="tab:cyan", lw=1.8, marker="|", ms=9, zorder=2,
                    label="c Δt / h² = 1/6")
            for a, row in enumerate(grid):
                for b, o in enumerate(row):
                    if math.isnan(o):
                        continue
                    ax.text(b, a, fs.percent(o), ha="center", va="center", fontsize=8, zorder=3,
                            bbox=dict(boxstyle="round,pad=0.12", fc="white", ec="none", alpha=0.75))
            ax.set_xticks(range(len(dts)), [f"{d:g}" for d in dts])
            ax.set_yticks(range(len(ks)), [f"{k:g}" for k in ks])
            ax.set_xlim(-0.5, len(dts) - 0.5), ax.set_ylim(-0.5, len(ks) - 0.5)
            ax.set_xlabel("Δt [s]")
            if i % cols == 0:
                ax.set_ylabel("k [mm⁴/(N s)]")
            ax.set_title(f"{mesh}, h = {h:.2f} mm on the axis")
            fs.panel_label(ax, "abcd"[i])
        fig.suptitle(f"First backward-Euler step, {STAB[stab]}: pressure overshoot [% of p_mid]; "
                     f"cyan line: c Δt / h² = 1/6, c = k (λ + 2μ)")
        if im is not None:
            cb = fig.colorbar(im, ax=flat, shrink=0.85, label="overshoot [%]", spacing="uniform")
            cb.set_ticks(bounds, labels=[f"{b:g}" for b in bounds])
        save(fig, out, f"stability_map_{stab}.png", tight=False)


def remedies(rows, out):
    """Discrepancy at t = 32 s against wall time for the three remedies (uniform refinement,
    GLS on the same meshes, a swept mesh graded toward the drained faces), each point labelled
    with its number of unknowns; further variants of the graded mesh (finer plane, more layers,
    smaller Δt, BDF, stronger grading) as single labelled points when the study has them."""
    fig, ax = plt.subplots(figsize=(fs.DOUBLE, 3.4))
    series = {
        "uniform refinement, no stabilisation": select(rows, sweep="uniform", stabilisation="none"),
        "uniform refinement, GLS": select(rows, sweep="uniform", stabilisation="gls"),
        "graded swept mesh, no stabilisation": select(rows, sweep="graded"),
    }
    for (label, rs), style in zip(series.items(), ("o-", "s-", "^-", "v-")):
        rs = [r for r in rs if r.get("status") == "completed"]
        rs.sort(key=lambda r: num(r, "unknowns"))
        if not rs:
            continue
        ax.plot([num(r, "wall_s") for r in rs], [100 * num(r, "discrepancy") for r in rs], style,
                label=label)
        for r in rs:
            ax.annotate(f"{num(r, 'unknowns') / 1e3:.0f}k", (num(r, "wall_s"), 100 * num(r, "discrepancy")),
                        fontsize=8, xytext=(3, 3), textcoords="offset points")
    variants = {
        "graded_plane": lambda r: f"finer cross-section (lc {num(r, 'mesh_lc'):g})",
        "graded_layers": lambda r: f"{int(num(r, 'mesh_layers'))} layers",
        "graded_dt": lambda r: f"Δt = {num(r, 'dt'):g} s",
        "graded_bdf": lambda r: f"BDF, rtol = {g(num(r, 'bdf_rtol'))}",
        "graded_ratio": lambda r: f"grading ratio {float(r.get('param:mesh.layer_grading_ratio') or 0):g}",
    }
    extra = [(r, f) for s, f in variants.items() for r in select(rows, sweep=s)
             if r.get("status") == "completed"]
    styles = [("v", "tab:purple"), ("D", "tab:brown"), ("P", "tab:pink"), ("X", "tab:olive"),
              ("<", "tab:cyan"), (">", "tab:gray"), ("*", "black"), ("h", "tab:purple")]
    for (r, f), (marker, colour) in zip(extra, styles * 2):
        ax.plot(num(r, "wall_s"), 100 * num(r, "discrepancy"), marker, color=colour, ms=5,
                ls="none", label=f"graded, {f(r)} ({num(r, 'unknowns') / 1e3:.0f}k)")
    ax.axhline(1.0, color="grey", lw=0.8, ls=":", label="1 % discrepancy")
    ax.set_xscale("log"), ax.set_yscale("log")
    ax.set_xlabel("wall time [s]"), ax.set_ylabel("discrepancy at t = 32 s [%]")
    ax.set_title("k = 1e-3, backward Euler Δt = 6.4 s unless stated\n(point labels: unknowns)")
    lo, hi = ax.get_xlim()
    ax.set_xlim(lo, hi * 1.6)  # room for the labels of the rightmost points
    ax.set_ylim(0.8, max(ax.get_ylim()[1], 14))
    ax.grid(alpha=0.3, which="both")
    plain_log_ticks(ax.xaxis), plain_log_ticks(ax.yaxis)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), ncol=1)
    save(fig, out, "remedies_cost_of_accuracy.png")


# ---- the paper's remaining experiments (studies gls_fixed_tau, gls_length, gls_quadrature) ----

def overshoot_over_time(run_dir):
    """(t, overshoot) at every output after t = 0, from the run's summary.json."""
    outs = [o for o in json.loads((pathlib.Path(run_dir) / "summary.json").read_text())["outputs"]
            if o["t"] > 0 and o.get("overshoot") is not None]
    return [o["t"] for o in outs], [o["overshoot"] for o in outs]


def fixed_tau(rows, out):
    """The paper's tau_GLS = h^2/(4 k dt) against tau fixed at its dt = 6.4 s value (the
    coefficient scaled by dt / 6.4 s): (a) the largest overshoot over the outputs and (b) the
    discrepancy at the end against dt; (c) the pressure on the axis at the end and (d) the
    overshoot over time of the fixed-tau runs. The fixed tau's run at dt = 6.4 s is the paper's
    run at that step (sweep paper_tau), drawn in both series."""
    done = [r for r in rows if r.get("status") == "completed"]
    paper_runs = sorted(select(done, sweep="paper_tau"), key=lambda r: num(r, "dt"))
    fixed = [r for r in done if r["sweep"].startswith("fixed_tau")]
    fixed += [r for r in paper_runs if math.isclose(num(r, "dt"), 6.4)]
    fixed.sort(key=lambda r: num(r, "dt"))
    series = (("paper's τ = h²/(4kΔt)", paper_runs, dict(color="tab:blue", marker="o", ls="-")),
              ("τ fixed at its Δt = 6.4 s value", fixed, dict(color="tab:red", marker="s", ls="--")))
    fig, axes = plt.subplots(2, 2, figsize=(fs.DOUBLE, 5.4))
    (a, b), (c, d) = axes
    for ax, key, ylabel in ((a, "overshoot_max", "largest overshoot over the outputs [%]"),
                            (b, "discrepancy", "discrepancy at t = 32 s [%]")):
        for label, rs, style in series:
            ax.plot([num(r, "dt") for r in rs], [100 * num(r, key) for r in rs], label=label,
                    **style)
        ax.axvline(6.4, color="grey", lw=0.8, ls=":")
        ax.set_xscale("log")
        ax.set_xlabel("time step Δt [s]"), ax.set_ylabel(ylabel)
        ax.set_ylim(bottom=-0.03 * ax.get_ylim()[1])  # markers at zero stay visible
        ax.grid(alpha=0.3, which="both")
        plain_log_ticks(ax.xaxis)
    a.text(6.4, a.get_ylim()[1] * 0.97, " the two τ agree", color="grey", fontsize=8,
           ha="left", va="top")
    a.set_title("overshoot")
    b.set_title("error next to the drained faces")
    a.legend(loc="center right")
    pressure_panel(c, fixed, lambda r: f"Δt = {num(r, 'dt'):g} s", "τ fixed: pressure at t = 32 s")
    c.legend(title="step", ncol=2)
    for i, r in enumerate(fixed):
        t, o = overshoot_over_time(r["_dir"])
        d.plot(t, [100 * v for v in o], "o-", ms=2.5, color=f"C{i}", clip_on=False)
    d.set_xlabel("time t [s]"), d.set_ylabel("overshoot on the axis [% of p_mid]")
    d.set_title("τ fixed: overshoot over time (steps as in c)")
    d.set_ylim(bottom=0)
    d.grid(alpha=0.3)
    fig.suptitle("GLS whose τ does not follow the time step: mesh 2, k = 1e-3 mm⁴/(N s), "
                 "backward Euler, 1 % strain")
    fs.letters(axes.flat)
    save(fig, out, "gls_fixed_tau.png")


LENGTHS = (  # (stabilisation.length, label), in the order of the coefficient's size on the
    # paper's meshes (h enters c_e = h²/(4k) squared; "none" is a zero coefficient)
    ("none", "none"), ("volume_diameter", "volume\ndiameter"), ("circumradius", "circum-\nradius"),
    ("shortest_edge", "shortest\nedge"), ("longest_edge", "longest\nedge"))


def length(rows, out):
    """GLS with each choice of the element length h against no stabilisation, on meshes 1-3 at
    each permeability: the largest overshoot over the outputs (log scale) and the discrepancy
    at the end, one line per mesh across the choices of h."""
    done = [r for r in rows if r.get("status") == "completed"]

    def choice(r):
        return "none" if r["stabilisation"] == "none" else r.get("param:stabilisation.length", "")

    ks = sorted({num(r, "permeability") for r in done})
    meshes = sorted({mesh_label(r) for r in done})
    fig, axes = plt.subplots(2, len(ks), figsize=(fs.DOUBLE, 5.2), squeeze=False, sharex=True)
    xs = range(len(LENGTHS))
    for j, k in enumerate(ks):
        for m, mesh in enumerate(meshes):
            sel = {choice(r): r for r in done
                   if math.isclose(num(r, "permeability"), k) and mesh_label(r) == mesh}
            for i, (key, ylabel) in enumerate((("overshoot_max", "largest overshoot [%]"),
                                              ("discrepancy", "discrepancy at t = 32 s [%]"))):
                ys = [100 * num(sel[n], key) if n in sel else math.nan for n, _ in LENGTHS]
                axes[i][j].plot(xs, ys, marker="osD"[m % 3], color=f"C{m}", label=mesh)
                axes[i][j].set_ylabel(ylabel if j == 0 else "")
        axes[0][j].set_title(f"k = {k:.0e} mm⁴/(N s)".replace("e-0", "e-"))
    for ax in axes.flat:
        ax.grid(alpha=0.3, which="both")
        ax.set_xticks(list(xs), [lab for _, lab in LENGTHS])
    for ax in axes[0]:
        ax.set_yscale("log")
        ax.set_ylim(5e-4, 20)
        plain_log_ticks(ax.yaxis, minor_subs=())
    top = max(ax.get_ylim()[1] for ax in axes[1])
    for ax in axes[1]:
        ax.set_ylim(0, top)
        ax.set_xlabel("h in c_e = h²/(4k), smallest to largest")
    axes[0][0].legend()
    fig.suptitle("GLS element length h, backward Euler Δt = 6.4 s, 1 % strain "
                 "(overshoot: largest over the outputs)")
    fs.letters(axes.flat)
    save(fig, out, "gls_length.png")


def quadrature(rows, out):
    """4 against 27 quadrature points: (a) the pressure on the axis at the end on mesh 2, with
    and without GLS, and the reference; (b) the difference between the two rules at every
    node of the line, relative to the largest pressure of the 4-point run, for every mesh and
    stabilisation (log scale; zero differences, at the drained nodes, are left out)."""
    done = [r for r in rows if r.get("status") == "completed" and r.get("sweep") == "points"]

    def points(r):
        return int(float(r.get("param:quadrature.points") or 0))

    pairs = {}
    for r in done:
        pairs.setdefault((mesh_label(r), r["stabilisation"]), {})[points(r)] = r
    pairs = {key: v for key, v in sorted(pairs.items()) if 4 in v and 27 in v}
    fig, (a, b) = plt.subplots(1, 2, figsize=(fs.DOUBLE, 3.2))
    shown = "mesh 2" if any(m == "mesh 2" for m, _ in pairs) else next(iter(pairs))[0]
    ref_row = None
    for i, ((mesh, stab), v) in enumerate(pairs.items()):
        if mesh != shown:
            continue
        z4, p4, _ = line_at(v[4]["_dir"])
        z27, p27, _ = line_at(v[27]["_dir"])
        colour = "tab:blue" if stab == "gls" else "tab:orange"
        a.plot(z4, [x * 1e3 for x in p4], "-", color=colour, lw=1.2, label=f"{STAB[stab]}, 4 points")
        a.plot(z27, [x * 1e3 for x in p27], "o", color=colour, mfc="none", ms=4.5, mew=0.8,
               label=f"{STAB[stab]}, 27 points")
        ref_row = v[4]
    ref = reference_dir(ref_row) if ref_row else None
    if ref and (ref / "line.csv").is_file():
        z, p, _ = line_at(ref, num(ref_row, "t_end"))
        a.plot(z, [x * 1e3 for x in p], "k--", lw=0.9, label="reference")
    a.set_xlabel("z on the axis [mm]"), a.set_ylabel("pressure p [kPa]")
    a.set_title(f"{shown}, t = 32 s")
    a.grid(alpha=0.3)
    a.legend(loc="lower center")
    for i, ((mesh, stab), v) in enumerate(pairs.items()):
        z4, p4, _ = line_at(v[4]["_dir"])
        z27, p27, _ = line_at(v[27]["_dir"])
        scale = max(abs(x) for x in p4) or 1.0
        pts = [(z, abs(q - p) / scale) for z, p, q, zz in zip(z4, p4, p27, z27)
               if math.isclose(z, zz, abs_tol=1e-9) and q != p]
        mesh_no = int(mesh.split()[-1]) - 1 if mesh.startswith("mesh ") else i
        b.semilogy([z for z, _ in pts], [d for _, d in pts],
                   "-" if stab == "gls" else "--", marker="osD"[mesh_no % 3], ms=3,
                   color=f"C{mesh_no}", label=f"{mesh}, {'GLS' if stab == 'gls' else 'none'}")
    b.set_xlabel("z on the axis [mm]"), b.set_ylabel("|p₂₇ − p₄| / max p₄ [–]")
    b.set_title("difference of the two rules, t = 32 s")
    b.grid(alpha=0.3)
    lo, hi = b.get_ylim()
    b.set_ylim(lo, hi * 3e3)  # room for the legend
    handles, labels = b.get_legend_handles_labels()
    order = sorted(range(len(labels)), key=lambda i: (labels[i].endswith("none"), labels[i]))
    b.legend([handles[i] for i in order], [labels[i] for i in order], ncol=2,
             loc="upper center", handlelength=2.4)
    fig.suptitle("quadrature: 4 points (degree 2) against 27 (degree 5), k = 1e-3 mm⁴/(N s), "
                 "backward Euler Δt = 6.4 s")
    fs.letters([a, b])
    save(fig, out, "gls_quadrature.png")


def one_point(rows, out):
    """The GLS term integrated with its full rule against the centroid alone (sweep
    gls_one_point of the quadrature study): the largest overshoot over the outputs (log scale)
    and the discrepancy at the end against the mesh, one line per permeability and rule."""
    done = [r for r in rows if r.get("status") == "completed" and r.get("sweep") == "gls_one_point"]
    ks = sorted({num(r, "permeability") for r in done})
    meshes = sorted({int(float(r["param:mesh"])) for r in done})
    fig, axes = plt.subplots(1, 2, figsize=(fs.DOUBLE, 2.8))
    for j, k in enumerate(ks):
        for rule, style in (("full", "-"), ("one_point", "--")):
            sel = {int(float(r["param:mesh"])): r for r in done
                   if math.isclose(num(r, "permeability"), k)
                   and r.get("param:stabilisation.gls_quadrature") == rule}
            label = f"k = {k:.0e}, {'4 points' if rule == 'full' else 'one point'}".replace(
                "e-0", "e-")
            for ax, key in zip(axes, ("overshoot_max", "discrepancy")):
                ys = [100 * num(sel[m], key) if m in sel else math.nan for m in meshes]
                ax.plot(meshes, ys, style, marker="os"[j % 2], color=f"C{j}", label=label,
                        fillstyle="full" if rule == "full" else "none")
    axes[0].set_yscale("log")
    axes[0].set_ylabel("largest overshoot [%]")
    axes[1].set_ylabel("discrepancy at t = 32 s [%]")
    axes[1].set_ylim(bottom=0)
    for ax in axes:
        ax.set_xticks(meshes, [f"mesh {m}" for m in meshes])
        ax.grid(alpha=0.3, which="both")
    axes[1].legend()
    fig.suptitle("The paper's GLS term with 4 points and with the centroid alone "
                 "(other terms: 4 points), Δt = 6.4 s, 1 % strain")
    fs.letters(axes.flat)
    save(fig, out, "gls_one_point.png")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kind", choices=["paper", "sensitivity", "work", "stability", "remedies",
                                     "fixed_tau", "length", "quadrature", "one_point"])
    ap.add_argument("studies", nargs="+")
    ap.add_argument("-o", "--output", default=str(ROOT / "docs" / "figures" / "results"))
    args = ap.parse_args()
    fs.apply()
    pathlib.Path(args.output).mkdir(parents=True, exist_ok=True)
    rows = read_rows(args.studies)
    globals()[args.kind](rows, args.output)


if __name__ == "__main__":
    main()
