#!/usr/bin/python3
"""A quarter of a cylindrical cartilage plug, meshed by gmsh with named physical groups: the
worked example of cases/examples/cartilage_plug/ (README there).

usage: tools/examples/cartilage_plug_mesh.py [OUT.msh] [--radius R] [--height H] [--lc LC]

Defaults: a plug 3 mm across (R = 1.5 mm) and 1.5 mm thick, element size 0.15 mm, written to
cases/examples/cartilage_plug/cartilage_plug.msh. The quarter x, y >= 0 of the plug, 10-node
tetrahedra (curved on the lateral face), gmsh format 4.1. Physical groups, the names a case file
refers to:
  surfaces  bottom (z = 0), top (z = H), lateral (r = R), symmetry_x (x = 0), symmetry_y (y = 0)
  volume    cartilage
Needs gmsh's Python module (Debian: python3-gmsh).
"""
import argparse
import math
import pathlib

import gmsh

ROOT = pathlib.Path(__file__).resolve().parents[2]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", nargs="?",
                    default=str(ROOT / "cases/examples/cartilage_plug/cartilage_plug.msh"))
    ap.add_argument("--radius", type=float, default=1.5, help="plug radius [mm]")
    ap.add_argument("--height", type=float, default=1.5, help="plug thickness [mm]")
    ap.add_argument("--lc", type=float, default=0.15, help="element size [mm]")
    args = ap.parse_args()
    R, H = args.radius, args.height

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("cartilage_plug")
    # A quarter cylinder: the OpenCASCADE kernel's cylinder with an opening angle of 90 degrees
    # starts at the x axis and turns toward y, so it fills x, y >= 0.
    occ = gmsh.model.occ
    occ.addCylinder(0, 0, 0, 0, 0, H, R, angle=math.pi / 2)
    occ.synchronize()

    # Name each face by where it lies (its centre of mass).
    faces = {"bottom": [], "top": [], "lateral": [], "symmetry_x": [], "symmetry_y": []}
    tol = 1e-6 * max(R, H)
    for dim, tag in gmsh.model.getEntities(2):
        x, y, z = gmsh.model.occ.getCenterOfMass(dim, tag)
        if abs(z) < tol:
            faces["bottom"].append(tag)
        elif abs(z - H) < tol:
            faces["top"].append(tag)
        elif abs(x) < tol:
            faces["symmetry_x"].append(tag)
        elif abs(y) < tol:
            faces["symmetry_y"].append(tag)
        else:
            faces["lateral"].append(tag)
    for name, tags in faces.items():
        if len(tags) != 1:
            raise SystemExit(f"expected one {name} face, found {len(tags)}")
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, tags), name)
    volumes = [tag for _, tag in gmsh.model.getEntities(3)]
    gmsh.model.setPhysicalName(3, gmsh.model.addPhysicalGroup(3, volumes), "cartilage")

    gmsh.option.setNumber("Mesh.MeshSizeMin", args.lc)
    gmsh.option.setNumber("Mesh.MeshSizeMax", args.lc)
    gmsh.model.mesh.generate(3)
    gmsh.model.mesh.setOrder(2)  # 10-node tetrahedra, curved along the lateral face
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    out = pathlib.Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    gmsh.write(str(out))
    tets = sum(len(t) for t in gmsh.model.mesh.getElements(3)[1])
    gmsh.finalize()
    print(f"wrote {out}: {tets} tetrahedra, R = {R} mm, H = {H} mm, lc = {args.lc} mm")


if __name__ == "__main__":
    main()
