#!/usr/bin/python3
"""Markdown tables of the studies' headline numbers (from each study's runs.csv), for
docs/results.md: written to stdout by tools/run_studies.sh into docs/results_tables.md.

usage: tools/results_tables.py RESULTS_STUDIES_DIR
"""
import csv
import json
import math
import pathlib
import sys

MESH = {1.3: "1", 0.98: "2", 0.73: "3", 0.57: "4"}


def rows_of(root, study):
    path = pathlib.Path(root) / study / "runs.csv"
    if not path.is_file():
        return []
    return [r for r in csv.DictReader(open(path)) if r.get("status") == "completed"]


def f(r, k):
    try:
        return float(r[k])
    except (KeyError, TypeError, ValueError):
        return math.nan


def pct(v):
    return "–" if math.isnan(v) else f"{100 * v:.1f}"


def mesh_of(r):
    if int(f(r, "mesh_layers") or 0) > 0:
        return f"swept {int(f(r, 'mesh_layers'))} layers"
    lc = f(r, "mesh_lc")
    return next((m for v, m in MESH.items() if math.isclose(v, lc)), f"lc {lc:g}")


def method(r):
    if r["integrator"] == "backward_euler":
        return f"BE Δt {f(r, 'dt'):g} s"
    return f"BDF rtol {f(r, 'bdf_rtol'):g}"


def stab(r):
    return "GLS" if r["stabilisation"] == "gls" else "none"


def has(rows, key):
    """Whether any row holds a value in column key (say discrepancy_check, present only when the
    study was run with its reference_check)."""
    return any(not math.isnan(f(r, key)) for r in rows)


CHECK = "against the 3-D cross-check [%]"


def table(header, lines):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in line) + " |" for line in lines]
    return "\n".join(out) + "\n"


def time_step(root):
    rows = rows_of(root, "time_step")
    if not rows:
        return ""
    check = has(rows, "discrepancy_check")
    lines = []
    for r in rows:
        lines.append([r["sweep"], method(r), f"{f(r, 'loading_rate_um_s'):g}", stab(r),
                      pct(f(r, "overshoot_max")), f"{f(r, 'oscillation_max'):.3f}",
                      pct(f(r, "discrepancy")), pct(f(r, "discrepancy_max"))] +
                     ([pct(f(r, "discrepancy_check"))] if check else []) +
                     [pct(f(r, "midheight_error")), r["steps"],
                      r["factorizations"], f"{f(r, 'wall_s'):.1f}"])
    return ("### Time step and loading rate (mesh 2, k = 1e-3)\n\n" + table(
        ["sweep", "method", "rate [µm/s]", "stab.", "max overshoot [%]", "max oscillation",
         "discrepancy at end [%]", "max discrepancy over time [%]"] +
        ([f"discrepancy at end {CHECK}"] if check else []) +
        ["mid-height error [%]", "steps", "factorisations", "wall [s]"], lines))


def work(root):
    rows = rows_of(root, "work_precision")
    if not rows:
        return ""
    check = has(rows, "discrepancy_check")
    lines = []
    for r in sorted(rows, key=lambda r: (mesh_of(r), r["integrator"], r["stabilisation"], f(r, "wall_s"))):
        lines.append([mesh_of(r), method(r), stab(r), pct(f(r, "discrepancy")),
                      pct(f(r, "discrepancy_max"))] +
                     ([pct(f(r, "discrepancy_check"))] if check else []) +
                     [r["steps"], r["factorizations"], r["residual_evaluations"],
                      f"{f(r, 'wall_s'):.1f}"])
    best = []
    for target in (0.05, 0.02, 0.01):
        ok = [r for r in rows if f(r, "discrepancy") <= target]
        if ok:
            r = min(ok, key=lambda r: f(r, "wall_s"))
            best.append([f"{100 * target:g} %", mesh_of(r), method(r), stab(r),
                         pct(f(r, "discrepancy")), f"{f(r, 'wall_s'):.1f}"])
        else:
            best.append([f"{100 * target:g} %", "none reached", "", "", "", ""])
    return ("### Work–precision (k = 1e-3, discrepancy at t = 32 s)\n\n" +
            table(["target", "mesh", "cheapest method", "stab.", "discrepancy [%]", "wall [s]"], best) +
            "\n" + table(["mesh", "method", "stab.", "discrepancy [%]",
                          "max discrepancy over time [%]"] +
                          ([f"discrepancy {CHECK}"] if check else []) +
                          ["steps", "factorisations", "residuals", "wall [s]"], lines))


def stability(root):
    out = []
    onset = []
    for m in (1, 2, 3, 4):
        rows = rows_of(root, f"stability_map_mesh{m}")
        if not rows:
            continue
        h = f(rows[0], "h_line")
        for s in ("none", "gls"):
            sel = [r for r in rows if r["stabilisation"] == s]
            ks = sorted({f(r, "permeability") for r in sel}, reverse=True)
            dts = sorted({f(r, "dt") for r in sel})
            grid = {(f(r, "permeability"), f(r, "dt")): f(r, "overshoot") for r in sel}
            lines = [[f"{k:g}"] + [pct(grid.get((k, d), math.nan)) for d in dts] for k in ks]
            out.append(f"Mesh {m} (h = {h:.2f} mm on the axis), {stab(sel[0]) if sel else s}: "
                       "first-step overshoot [%]\n\n" +
                       table(["k \\ Δt [s]"] + [f"{d:g}" for d in dts], lines))
            # Onset: the largest r = c dt / h^2 with an overshoot above 1 %.
            lam_mu = f(sel[0], "lambda") + 2 * f(sel[0], "mu")
            osc = [(k * lam_mu * d / h ** 2, grid[(k, d)]) for (k, d) in grid if grid[(k, d)] > 0.01]
            calm = [(k * lam_mu * d / h ** 2, grid[(k, d)]) for (k, d) in grid if grid[(k, d)] <= 0.01]
            onset.append([m, f"{h:.2f}", stab(sel[0]),
                          f"{max(r for r, _ in osc):.3g}" if osc else "–",
                          f"{min(r for r, _ in calm):.3g}" if calm else "–"])
    if not out:
        return ""
    return ("### Stability maps (first backward-Euler step)\n\n" +
            table(["mesh", "h [mm]", "stab.", "largest c Δt/h² with overshoot > 1 %",
                   "smallest c Δt/h² with overshoot ≤ 1 %"], onset) + "\n" + "\n".join(out))


def generic(root, study, title):
    rows = rows_of(root, study)
    if not rows:
        return ""
    check = has(rows, "discrepancy_check")
    lines = []
    for r in rows:
        lines.append([r["sweep"], mesh_of(r), r["unknowns"], f"{f(r, 'permeability'):g}", stab(r),
                      f"{100 * f(r, 'strain'):g}", method(r), pct(f(r, "overshoot")),
                      pct(f(r, "discrepancy")), pct(f(r, "discrepancy_max"))] +
                     ([pct(f(r, "discrepancy_check"))] if check else []) +
                     [pct(f(r, "midheight_error")), f"{f(r, 'p_mid') * 1e3:.4f}",
                      f"{f(r, 'wall_s'):.1f}"])
    return (f"### {title}\n\n" + table(
        ["sweep", "mesh", "unknowns", "k", "stab.", "strain [%]", "method", "overshoot at end [%]",
         "discrepancy at end [%]", "max discrepancy over time [%]"] +
        ([f"discrepancy at end {CHECK}"] if check else []) +
        ["mid-height error [%]", "p_mid [kPa]", "wall [s]"], lines))


def references(root):
    cache = pathlib.Path(root).parent / "references"
    used = set()  # the references the studies' tables name (the cache may hold stale ones)
    for table_path in pathlib.Path(root).glob("*/runs.csv"):
        for r in csv.DictReader(open(table_path)):
            for col in ("reference", "reference_check"):
                if r.get(col):
                    used.add(pathlib.Path(r[col].split()[-1]).name)
    lines = []
    for d in sorted(cache.glob("*/summary.json")):
        if d.parent.name not in used:
            continue
        s = json.loads(d.read_text())
        c = s["configuration"]
        if s.get("status") != "completed":
            continue
        top = next(b for b in c["boundary"] if b["name"] == "top" and b["type"] == "displacement")
        if s.get("model") == "axisymmetric":
            sec = c["mesh"]["section"]
            height = sec["height"]
            mesh = (f"axisymmetric section {sec['nr']} x {sec['nz']} "
                    f"(graded {sec['grading_ratio']:g}:1 toward {', '.join(sec['grading_curves'])})")
        else:
            height = c["mesh"]["height"]
            mesh = (f"swept, {c['mesh']['layers']} layers (ratio "
                    f"{c['mesh']['layer_grading_ratio']:g}), lc {c['mesh']['lc']:g}")
        lines.append([d.parent.name, f"{c['material']['permeability']:g}",
                      f"{-top['value'] / c['time']['t_end'] * 1e3:g}",
                      f"{-100 * top['value'] / height:g}", mesh,
                      s["mesh"]["unknowns"], f"BDF rtol {c['time']['bdf']['rtol']:g}",
                      s["counters"]["steps"], f"{s['timings']['wall']:.0f}"])
    if not lines:
        return ""
    return ("### Reference solutions (results/references/)\n\n" + table(
        ["key", "k", "rate [µm/s]", "strain [%]", "mesh", "unknowns", "integrator", "steps",
         "wall [s]"], lines))


def main():
    root = sys.argv[1]
    print("<!-- Generated by tools/results_tables.py from results/studies/*/runs.csv. -->\n")
    print("# Study tables\n")
    for part in (references(root), time_step(root), work(root), stability(root),
                 generic(root, "paper_figures", "The paper's figures (meshes 1–3)"),
                 generic(root, "paper_figures_mesh4", "The paper's figures (mesh 4)"),
                 generic(root, "remedies", "Remedies (k = 1e-3, BE Δt = 6.4 s)")):
        if part:
            print(part)


if __name__ == "__main__":
    main()
