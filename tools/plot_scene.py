#!/usr/bin/python3
"""The paper's scene from a run's own output: the mesh, the boundary conditions and the loading.

usage: tools/plot_scene.py [RUN_DIR] [-o OUT] [--case CASE.toml] [--biphasic PATH]

RUN_DIR (default results/scene_mesh2) is the folder of a run that wrote its generated mesh
(`mesh.write_msh`, gmsh .msh 4.1 ASCII) beside its summary.json. When RUN_DIR holds no such
run, it is made first with

    build/biphasic run CASE.toml -o RUN_DIR --set mesh.write_msh=mesh.msh --set output.fields=false

(CASE default cases/paper/mesh2_k1e-3_gls.toml: mesh 2 of the paper, under a minute).

Writes OUT (default docs/figures/results/scene_mesh2.png, 200 dpi) with a vector PDF beside it:
  (a) the boundary triangles of the mesh in a 3-D view, coloured by boundary, with the probe line;
  (b) the meridian section with the boundary conditions, each written out from the run's
      resolved configuration (summary.json): displacement and pressure conditions, symmetry
      planes, and the faces with no condition (traction-free and sealed);
  (c) the prescribed platen displacement against time (curve × value) with the output times.
Everything drawn is read from the run: the mesh from the .msh file, the rest from summary.json.
"""
import argparse
import json
import math
import pathlib
import subprocess
import sys

import numpy as np

import figure_style as fs

import matplotlib.pyplot as plt  # noqa: E402  (figure_style selects the Agg backend)
from matplotlib import patches  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
DEFAULT_CASE = ROOT / "cases" / "paper" / "mesh2_k1e-3_gls.toml"
COLOURS = {"top": "#7fb3d5", "bottom": "#7fb3d5", "lateral": "#d5d8dc",
           "symmetry_x": "#f7dc6f", "symmetry_y": "#f5cba7"}


# ---- reading ---------------------------------------------------------------------------------

def read_msh(path):
    """Nodes and boundary triangles of a gmsh .msh 4.1 ASCII file: (coords {tag: xyz},
    {physical surface name: [(n0, n1, n2), ...]}) with the corner nodes of each triangle
    (3- or 6-node triangles)."""
    lines = pathlib.Path(path).read_text().splitlines()

    def section(name):
        return lines.index(f"${name}") + 1

    if lines[section("MeshFormat")].split()[:2] != ["4.1", "0"]:
        raise SystemExit(f"{path}: not a gmsh 4.1 ASCII file")
    names = {}
    i = section("PhysicalNames")
    for line in lines[i + 1:i + 1 + int(lines[i])]:
        dim, tag, name = line.split(maxsplit=2)
        names[(int(dim), int(tag))] = name.strip('"')
    # Entities: the physical tags of each surface
    i = section("Entities")
    counts = [int(v) for v in lines[i].split()]
    surface_phys = {}
    row = i + 1 + counts[0] + counts[1]
    for line in lines[row:row + counts[2]]:
        v = line.split()
        nphys = int(v[7])
        surface_phys[int(v[0])] = [int(p) for p in v[8:8 + nphys]]
    # Nodes
    i = section("Nodes")
    blocks = int(lines[i].split()[0])
    coords, j = {}, i + 1
    for _ in range(blocks):
        n = int(lines[j].split()[3])
        tags = [int(t) for t in lines[j + 1:j + 1 + n]]
        for k, t in enumerate(tags):
            coords[t] = [float(x) for x in lines[j + 1 + n + k].split()]
        j += 1 + 2 * n
    # Elements: triangles (type 2: 3 nodes, type 9: 6 nodes) on surfaces
    i = section("Elements")
    blocks = int(lines[i].split()[0])
    faces, j = {}, i + 1
    for _ in range(blocks):
        dim, entity, etype, n = (int(v) for v in lines[j].split())
        if dim == 2 and etype in (2, 9):
            for phys in surface_phys.get(entity, []):
                name = names.get((2, phys), f"surface {phys}")
                faces.setdefault(name, []).extend(
                    tuple(int(v) for v in line.split()[1:4]) for line in lines[j + 1:j + 1 + n])
        j += 1 + n
    return coords, faces


def make_run(run_dir, case, biphasic):
    cmd = [str(biphasic), "run", str(case), "-o", str(run_dir), "--overwrite", "--quiet",
           "--set", "mesh.write_msh=mesh.msh", "--set", "output.fields=false"]
    print("running:", " ".join(cmd), file=sys.stderr)
    subprocess.run(cmd, check=True)


# ---- the conditions in words -------------------------------------------------------------------

def conditions(config):
    """{boundary name: [text, ...]} from the resolved configuration."""
    out = {}
    for b in config["boundary"]:
        kind, name = b["type"], b["name"]
        if kind == "displacement":
            value = b["value"]
            text = f"u_{b['component']} = {value:g} mm"
            if value == 0:
                text = f"u_{b['component']} = 0"
            elif b.get("curve"):
                text = f"u_{b['component']} = {value:g} mm × {b['curve']}(t)"
        elif kind == "pressure":
            value = b["value"]
            text = "p = 0 (drained)" if value == 0 and not b.get("curve") else f"p = {value:g} MPa"
        elif kind == "symmetry":
            text = "symmetry: u_n = 0, no flux"
        else:
            text = kind.replace("_", " ")
        out.setdefault(name, []).append(text)
    return {n: [w.replace("= -", "= −") for w in ws] for n, ws in out.items()}


def plane_of(coords, tris):
    """'x = 0' (etc.) when every node of the triangles has one coordinate constant, else None."""
    pts = np.array([coords[n] for t in tris for n in t])
    for k, axis in enumerate("xyz"):
        if np.ptp(pts[:, k]) < 1e-6 * max(np.ptp(pts), 1.0):
            return axis, float(pts[0, k])
    return None


# ---- drawing ---------------------------------------------------------------------------------

def mesh_panel(ax, coords, faces, line, elev=24.0, azim=-128.0):
    """The boundary triangles facing the viewer, shaded by a light from the viewer's upper
    left (back faces are culled: the body is convex, so what is left does not overlap).
    Returns the names of the boundaries drawn."""
    drawn = []
    eye = np.array([math.cos(math.radians(elev)) * math.cos(math.radians(azim)),
                    math.cos(math.radians(elev)) * math.sin(math.radians(azim)),
                    math.sin(math.radians(elev))])
    light = eye + np.array([0.0, 0.0, 0.8])
    light /= np.linalg.norm(light)
    everything = np.array(list(coords.values()))
    centre = everything.mean(axis=0)
    for name, tris in faces.items():
        xyz = np.array([[coords[n] for n in t] for t in tris])
        normal = np.cross(xyz[:, 1] - xyz[:, 0], xyz[:, 2] - xyz[:, 0])
        normal /= np.linalg.norm(normal, axis=1)[:, None]
        outward = np.sign(np.einsum("ij,ij->i", normal, xyz.mean(axis=1) - centre))
        normal *= np.where(outward == 0, 1, outward)[:, None]
        keep = normal @ eye > 1e-3
        if not keep.any():
            continue
        drawn.append(name)
        base = np.array(plt.matplotlib.colors.to_rgb(COLOURS.get(name, "#cccccc")))
        shade = 0.55 + 0.45 * np.clip(normal[keep] @ light, 0, 1)
        ax.add_collection3d(Poly3DCollection(
            xyz[keep], facecolors=np.clip(base[None, :] * shade[:, None], 0, 1),
            edgecolors="#2c3e50", linewidths=0.15, zorder=1))
    (x0, y0, z0), (x1, y1, z1) = line
    ax.plot([x0, x1], [y0, y1], [z0, z1], color="tab:red", lw=2.2, zorder=5, solid_capstyle="butt")
    lo, hi = everything.min(axis=0), everything.max(axis=0)
    ax.set_xlim(lo[0], hi[0]), ax.set_ylim(lo[1], hi[1]), ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect(hi - lo, zoom=1.1)
    ax.view_init(elev=elev, azim=azim)
    ax.set_xlabel("x [mm]", labelpad=-4), ax.set_ylabel("y [mm]", labelpad=-4)
    ax.set_zlabel("z [mm]", labelpad=-6)
    ax.set_xticks([0, 9, 18]), ax.set_yticks([0, 9, 18]), ax.set_zticks([0, 8])
    ax.tick_params(pad=-2)
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.pane.set_visible(False)
        axis._axinfo["grid"]["linewidth"] = 0.3
    ax.computed_zorder = False
    return drawn


def section_panel(ax, config, conds, planes, line_nodes):
    """The meridian section r–z with platens, axis, lateral face and the conditions, drawn to
    scale, the words beside it."""
    R, H = config["mesh"]["radius"], config["mesh"]["height"]
    t = 0.12 * H  # platen thickness in the drawing
    ax.add_patch(patches.Rectangle((0, 0), R, H, fc="#eaf2f8", ec="k", lw=0.8))
    for z in (H, -t):
        ax.add_patch(patches.Rectangle((0, z), 1.06 * R, t, fc="#aeb6bf", ec="k", lw=0.6,
                                       hatch="////"))
    ax.annotate("", xy=(0.5 * R, H + 1.05 * t), xytext=(0.5 * R, H + 2.6 * t),
                arrowprops=dict(arrowstyle="-|>", lw=1.0, color="k"))
    ax.plot([0, 0], [-2.0 * t, H + 2.0 * t], "k-.", lw=0.6)
    ax.plot([0, 0], [0, H], color="tab:red", lw=2.6, solid_capstyle="butt", zorder=3)

    def words(name, default="no condition: traction-free, sealed (no flux)"):
        return ", ".join(conds.get(name, [default]))

    def free(name):
        """The displacement components a face leaves free (a frictionless platen)."""
        fixed = {b["component"] for b in config["boundary"]
                 if b["name"] == name and b["type"] == "displacement"}
        rest = [c for c in "xyz" if c not in fixed]
        return f"; u_{', u_'.join(rest)} free (frictionless)" if fixed and rest else ""

    ax.text(0.5 * R + 0.6, H + 1.9 * t, f"top platen: {words('top')}{free('top')}",
            va="center", ha="left", fontsize=8)
    ax.text(0.5 * R + 0.6, -1.6 * t, f"bottom platen: {words('bottom')}{free('bottom')}",
            va="top", ha="left", fontsize=8)
    ax.annotate("", xy=(1.06 * R + 1.2, 0), xytext=(1.06 * R + 1.2, H),
                arrowprops=dict(arrowstyle="<|-|>", lw=0.6, color="k", shrinkA=0, shrinkB=0))
    ax.text(1.06 * R + 1.6, 0.5 * H, f"H = {H:g} mm", va="center", ha="left", fontsize=8)
    ax.annotate("", xy=(0.15, 0.5 * H), xytext=(R, 0.5 * H),
                arrowprops=dict(arrowstyle="<|-|>", lw=0.6, color="k", shrinkA=0, shrinkB=0))
    ax.text(0.5 * R, 0.5 * H + 0.15, f"R = {R:g} mm", va="bottom", ha="center", fontsize=8)
    ax.text(1.06 * R + 6.5, 0.5 * H, f"lateral face r = {R:g} mm:\n"
            + words("lateral").replace(": ", ":\n", 1), va="center", ha="left", fontsize=8)

    def plane(name):
        axis, value = planes[name]
        return f"{axis} = {0.0 if abs(value) < 1e-9 else value:g}"

    sym = ", ".join(plane(n) for n in sorted(planes))
    ax.text(-0.8, 0.72 * H, f"axis r = 0\nsymmetry planes\n{sym}:\n"
            + (words(sorted(planes)[0]).split(": ", 1)[-1] if planes else ""),
            va="center", ha="right", fontsize=8)
    ax.text(-0.8, 0.18 * H, f"probe line: p on the axis,\nz = 0 … {H:g} mm ({line_nodes} nodes)",
            color="tab:red", va="center", ha="right", fontsize=8)
    ax.set_xlim(-0.75 * R, 1.75 * R), ax.set_ylim(-2.6 * t, H + 2.6 * t)
    ax.set_aspect("equal")
    ax.axis("off")


def loading_panel(ax, config, outputs, bounds):
    """The loading displacement (curve × value) against time, the output times on it, and the
    compressive strain on the right axis."""
    moving = [b for b in config["boundary"] if b["type"] == "displacement" and b.get("curve")]
    t_end = config["time"]["t_end"]
    for b in moving:
        pts = sorted(config["curves"][b["curve"]])
        ts = [p[0] for p in pts if p[0] <= t_end] + ([t_end] if pts[-1][0] < t_end else [])
        u = [b["value"] * np.interp(t, [p[0] for p in pts], [p[1] for p in pts]) for t in ts]
        ax.plot(ts, [1e3 * v for v in u], "-", color="k",
                label=f"{b['name']}: u_{b['component']} = {b['value']:g} mm × {b['curve']}(t)"
                .replace("= -", "= −"))
        to = [o["t"] for o in outputs if o["t"] > 0]
        uo = [1e3 * b["value"] * np.interp(t, [p[0] for p in pts], [p[1] for p in pts]) for t in to]
        ax.plot(to, uo, "o", color="tab:blue", ms=4, clip_on=False, label=f"outputs (Δt = {config['time']['dt']:g} s)")
        k = "xyz".index(b["component"])
        extent = bounds["max"][k] - bounds["min"][k]
        sec = ax.secondary_yaxis("right", functions=(lambda v, e=extent: -v / (1e3 * e) * 100,
                                                     lambda s, e=extent: -s * 1e3 * e / 100))
        sec.set_ylabel("compressive strain [%]")
    ax.set_xlabel("time t [s]"), ax.set_ylabel("platen displacement [µm]")
    ax.set_xlim(0, t_end)
    ax.grid(alpha=0.3)
    ax.legend(loc="lower left")


def loading_title(config):
    """'loading: ramp at 2.5 µm/s to 1 % strain' from the moving condition's curve."""
    for b in config["boundary"]:
        if b["type"] == "displacement" and b.get("curve"):
            pts = sorted(config["curves"][b["curve"]])
            rates = {round(abs(b["value"] * (q[1] - p[1]) / (q[0] - p[0])), 12)
                     for p, q in zip(pts, pts[1:]) if q[0] > p[0]}
            up_to = "up to " if len(rates) > 1 else ""
            return f"loading: the {b['name']} platen at {up_to}{1e3 * max(rates):g} µm/s"
    return "loading"


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run_dir", nargs="?", default=str(ROOT / "results" / "scene_mesh2"))
    ap.add_argument("-o", "--output", default=str(ROOT / "docs" / "figures" / "results" / "scene_mesh2.png"))
    ap.add_argument("--case", default=str(DEFAULT_CASE), help="case run when RUN_DIR has no mesh")
    ap.add_argument("--biphasic", default=str(ROOT / "build" / "biphasic"))
    args = ap.parse_args()
    run = pathlib.Path(args.run_dir)
    summary_path = run / "summary.json"
    summary = json.loads(summary_path.read_text()) if summary_path.is_file() else None
    msh = run / summary["configuration"]["mesh"]["write_msh"] if summary and \
        summary["configuration"]["mesh"].get("write_msh") else None
    if summary is None or summary.get("status") != "completed" or msh is None or not msh.is_file():
        make_run(run, args.case, args.biphasic)
        summary = json.loads(summary_path.read_text())
        msh = run / summary["configuration"]["mesh"]["write_msh"]
    config = summary["configuration"]
    coords, faces = read_msh(msh)
    planes = {n: plane_of(coords, faces[n]) for n in faces
              if any(b["name"] == n and b["type"] == "symmetry" for b in config["boundary"])}
    line = (summary["line"]["start"], summary["line"]["end"])

    fs.apply()
    fig = plt.figure(figsize=(fs.DOUBLE, 5.6))
    a = fig.add_axes((0.0, 0.43, 0.50, 0.53), projection="3d")
    c = fig.add_axes((0.60, 0.50, 0.31, 0.40))
    b = fig.add_axes((0.06, 0.02, 0.90, 0.33))
    drawn = mesh_panel(a, coords, faces, line)
    m = summary["mesh"]
    a.text2D(0.5, 0.98, f"mesh: lc = {config['mesh']['lc']:g} mm, {m['tetrahedra']} tetrahedra,\n"
             f"{m['unknowns']} unknowns (P2 displacement, P1 pressure)", transform=a.transAxes,
             ha="center", va="top", fontsize=8)
    groups = {}
    for n in sorted(drawn):
        groups.setdefault(COLOURS.get(n, "#cccccc"), []).append(n.replace("_", " "))
    handles = [patches.Patch(fc=col, ec="#2c3e50", lw=0.4, label=" / ".join(ns))
               for col, ns in groups.items()]
    handles.append(plt.Line2D([], [], color="tab:red", lw=2.2, label="probe line (axis)"))
    fig.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.25, 0.445), ncol=3,
               handlelength=1.4, columnspacing=1.0)
    section_panel(b, config, conditions(config), planes, summary["line"]["nodes"])
    loading_panel(c, config, summary["outputs"], m["bounds"])
    c.set_title(loading_title(config))
    a.text2D(0.02, 0.98, "(a)", transform=a.transAxes, fontsize=9, fontweight="bold",
             ha="left", va="top")
    fs.panel_label(b, "b", x=0.0, y=0.95)
    fs.panel_label(c, "c")
    mat = config["material"]
    fig.suptitle(f"{pathlib.Path(config['case_file']).name}: quarter cylinder R = "
                 f"{config['mesh']['radius']:g} mm, H = {config['mesh']['height']:g} mm; "
                 f"λ = {mat['lambda']:g} MPa, μ = {mat['mu']:g} MPa, "
                 f"k = {mat['permeability']:g} mm⁴/(N s)", y=1.0)
    for path in fs.save(fig, args.output, tight=False):
        print(path)


if __name__ == "__main__":
    main()
