#!/usr/bin/python3
"""Run a parameter study: every combination of the sweeps in a study file, on both cores,
skipping runs already done, into one tidy CSV table (one row per run).

usage: tools/study.py STUDY.toml [-o DIR] [--jobs N] [--dry-run] [--retry-failed]
                      [--skip-reference-check]

A study file (TOML, see docs/studies.md):

    title = "Time-step sensitivity, mesh 1"
    base = "../paper/mesh1_k1e-3_gls.toml"     # relative to the study file
    set = { "output.fields" = false }          # overrides for every run (optional)
    reference = "reference_axisymmetric.toml"  # optional: reference case for the discrepancy
    reference_check = "reference.toml"         # optional: a second reference, for a cross-check

    [[sweep]]                                  # a study is the union of its sweeps
    name = "be"
    set = { "time.integrator" = "backward_euler" }
    vary = { "time.dt" = [0.64, 3.2, 6.4, 8, 32], "stabilisation.type" = ["gls", "none"] }

Keys of `set` and `vary` are case-file keys (anything `biphasic run --set` takes), or:
  mesh           the paper's mesh 1-4 (mesh.lc = 1.3, 0.98, 0.73, 0.57 mm)
  loading.rate   platen speed [um/s]; with loading.strain, sets the ramp, the platen
  loading.strain final compressive strain [-]   displacement and time.t_end
  time.steps     run this many steps of time.dt only (time.t_end = steps * dt), e.g. 1 for the
                 first-step overshoot of a stability map

Each run writes to DIR/runs/<sweep>/<parameters>/ (summary.json, line.csv, log.txt) and the
table to DIR/runs.csv. Reference solutions (one per physical problem: material, loading rate
and strain) are computed once from the reference case and cached in results/references/
(shared by studies; BIPHASIC_REFERENCE_CACHE=DIR puts the cache elsewhere). The run's physical
parameters (every material.* key, loading.rate, loading.strain) are applied to the reference;
before any run, the runner checks that the reference then describes the run's physical problem
(geometry, material, the conditions on top, bottom and lateral faces and their load histories,
the probe line), across models (a 3-D quarter cylinder against an axisymmetric section), and
stops naming every difference otherwise. With reference_check, the rows also hold the
discrepancy against the second reference (discrepancy_check, discrepancy_check_max);
--skip-reference-check leaves it out. BIPHASIC_BIN=PATH runs another build.
"""
import argparse
import bisect
import copy
import csv
import functools
import hashlib
import itertools
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import time
import math
import tomllib

ROOT = pathlib.Path(__file__).resolve().parent.parent
BIN = pathlib.Path(os.environ.get("BIPHASIC_BIN", ROOT / "build" / "biphasic"))
REFERENCE_CACHE = pathlib.Path(os.environ.get("BIPHASIC_REFERENCE_CACHE",
                                              ROOT / "results" / "references"))
PAPER_MESH_LC = {1: 1.3, 2: 0.98, 3: 0.73, 4: 0.57}
# Parameters that define the physical problem (the reference depends on them only): every
# material key (the same in every model) and the derived loading keys.
LOADING_KEYS = ("loading.rate", "loading.strain")
SECTION_MODELS = ("axisymmetric", "plane_strain")
# The quarter cylinder's symmetry planes: what the axis of an axisymmetric section implies.
QUARTER_SYMMETRY = ("symmetry_x", "symmetry_y")


def is_physical(key):
    return key.startswith("material.") or key in LOADING_KEYS


class StudyError(Exception):
    pass


def toml_value(v):
    """A value as `--set` takes it (TOML syntax)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    return repr(v)


def slug(params):
    text = ",".join(f"{k.split('.')[-1]}={params[k]}" for k in sorted(params))
    text = re.sub(r"[^A-Za-z0-9_.,=+-]", "_", text) or "base"
    if len(text) > 100:
        text = text[:80] + "_" + hashlib.sha1(text.encode()).hexdigest()[:10]
    return text


class BaseCase:
    """What the runner needs to know of the base case to translate derived parameters."""

    def __init__(self, path):
        self.path = path
        try:
            self.toml = tomllib.loads(path.read_text())
        except (OSError, tomllib.TOMLDecodeError) as e:
            raise StudyError(f"{path}: {e}")
        mesh = self.toml.get("mesh", {})
        self.model = self.toml.get("model", "three_dimensional")
        if self.model in SECTION_MODELS:
            self.height = float(mesh.get("section", {}).get("height", 8.0))
        else:
            self.height = float(mesh.get("height", 8.0))
        self.top = None
        for i, bc in enumerate(self.toml.get("boundary", [])):
            if bc.get("name") == "top" and bc.get("type") == "displacement":
                self.top = (i, bc)
        self.t_end = float(self.toml.get("time", {}).get("t_end", 32.0))

    def loading_overrides(self, rate_um_s, strain, where):
        if self.top is None:
            raise StudyError(f"{where}: loading.rate/strain need a displacement condition on 'top' "
                             f"in the base case {self.path}")
        index, bc = self.top
        curve = bc.get("curve")
        if not curve:
            raise StudyError(f"{where}: the top displacement in {self.path} has no load curve")
        if rate_um_s <= 0 or strain <= 0:
            raise StudyError(f"{where}: loading.rate = {rate_um_s} and loading.strain = {strain} "
                             "must be > 0")
        depth = strain * self.height  # mm
        t_end = depth / (rate_um_s * 1e-3)
        return {f"boundary[{index}].value": -depth, f"curves.{curve}": [[0.0, 0.0], [t_end, 1.0]],
                "time.t_end": t_end}

    def default_loading(self):
        """(rate [um/s], strain) of the base case."""
        index, bc = self.top if self.top else (None, {"value": -0.08})
        depth = -float(bc.get("value", -0.08))
        return depth / self.t_end * 1e3, depth / self.height


def expand(params, base, where):
    """Case-file overrides for one run's parameters (derived ones translated)."""
    out = {}
    rate, strain = base.default_loading()
    loading = False
    steps = None
    for key, value in params.items():
        if key == "mesh":
            if value not in PAPER_MESH_LC:
                raise StudyError(f"{where}: mesh = {value!r}: the paper's meshes are 1, 2, 3, 4")
            out["mesh.lc"] = PAPER_MESH_LC[value]
        elif key == "loading.rate":
            rate, loading = float(value), True
        elif key == "loading.strain":
            strain, loading = float(value), True
        elif key == "time.steps":
            if not isinstance(value, int) or value < 1:
                raise StudyError(f"{where}: time.steps = {value!r} must be an integer >= 1")
            steps = value
        else:
            out[key] = value
    if loading:
        out.update(base.loading_overrides(rate, strain, where))
    if steps is not None:
        dt = float(out.get("time.dt", base.toml.get("time", {}).get("dt", 6.4)))
        out["time.t_end"] = steps * dt
    return out


def load_study(path):
    try:
        study = tomllib.loads(path.read_text())
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise StudyError(f"{path}: {e}")
    for key in study:
        if key not in ("title", "base", "set", "reference", "reference_check", "sweep", "output",
                       "columns"):
            raise StudyError(f"{path}: unknown key '{key}' (title, base, set, reference, "
                             "reference_check, sweep, output, columns)")
    columns = study.get("columns")
    if columns is not None and (not isinstance(columns, list) or not columns
                                or not all(isinstance(c, str) for c in columns)):
        raise StudyError(f"{path}: columns = {columns!r}: a non-empty list of column names")
    if "base" not in study:
        raise StudyError(f"{path}: 'base' (the base case file) is missing")
    base = BaseCase((path.parent / study["base"]).resolve())
    if not base.path.is_file():
        raise StudyError(f"{path}: base = '{study['base']}': no such file ({base.path})")
    sweeps = study.get("sweep", [])
    if not sweeps:
        raise StudyError(f"{path}: no [[sweep]] tables")
    runs = []
    names = set()
    for i, sw in enumerate(sweeps):
        where = f"{path}: sweep[{i}]"
        for key in sw:
            if key not in ("name", "set", "vary"):
                raise StudyError(f"{where}: unknown key '{key}' (name, set, vary)")
        name = sw.get("name", f"sweep{i}")
        if name in names:
            raise StudyError(f"{where}: name = '{name}' is used twice")
        names.add(name)
        vary = sw.get("vary", {})
        for key, values in vary.items():
            if not isinstance(values, list) or not values:
                raise StudyError(f"{where}: vary.{key} must be a non-empty list")
        keys = list(vary)
        for combo in itertools.product(*(vary[k] for k in keys)):
            params = dict(zip(keys, combo))
            fixed = {**study.get("set", {}), **sw.get("set", {}), **params}
            runs.append({"sweep": name, "params": params, "fixed": fixed,
                         "overrides": expand(fixed, base, where),
                         "dir": f"{name}/{slug(params)}"})
    references = {}
    for key in ("reference", "reference_check"):
        if key in study:
            ref_path = (path.parent / study[key]).resolve()
            if not ref_path.is_file():
                raise StudyError(f"{path}: {key} = '{study[key]}': no such file")
            references[key] = BaseCase(ref_path)
    if "reference_check" in references and "reference" not in references:
        raise StudyError(f"{path}: reference_check needs a reference")
    return study, base, runs, references


def set_args(overrides):
    args = []
    for k, v in overrides.items():
        args += ["--set", f"{k}={toml_value(v)}"]
    return args


def validate(base, runs):
    """Checks every run's configuration with `biphasic check` before any work starts."""
    for run in runs:
        cmd = [str(BIN), "check", str(base.path)] + set_args(run["overrides"])
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            raise StudyError(f"run {run['dir']}: {(r.stderr or r.stdout).strip()}")


# ---- the physical problem of a case ---------------------------------------------------------

@functools.lru_cache(maxsize=None)
def schema_defaults():
    """{key: default} of the case file's plain keys, read from `biphasic schema`."""
    if not BIN.is_file():
        raise StudyError(f"{BIN} not found; build first (tools/build.sh)")
    r = subprocess.run([str(BIN), "schema"], capture_output=True, text=True)
    if r.returncode != 0:
        raise StudyError(f"{BIN} schema: {(r.stderr or r.stdout).strip()}")
    out = {}
    for line in r.stdout.splitlines():
        m = re.match(r"\| `([a-z_.]+)` \| [^|]* \| `([^`]*)` \|", line)
        if m:
            try:
                out[m.group(1)] = tomllib.loads(f"v = {m.group(2)}")["v"]
            except tomllib.TOMLDecodeError:
                pass
    return out


def with_overrides(toml, overrides):
    """A case-file dict with `--set` overrides (KEY = a.b, a[i].b) applied."""
    cfg = copy.deepcopy(toml)
    for key, value in overrides.items():
        node = cfg
        parts = key.split(".")
        for i, part in enumerate(parts):
            last = i == len(parts) - 1
            m = re.fullmatch(r"(\w+)\[(\d+)\]", part)
            if m:
                items = node.setdefault(m.group(1), [])
                index = int(m.group(2))
                while len(items) <= index:
                    items.append({})
                if last:
                    items[index] = value
                else:
                    node = items[index]
            elif last:
                node[part] = value
            else:
                node = node.setdefault(part, {})
    return cfg


def _num(v):
    return float(f"{float(v):.12g}")


def _plain(v):
    """Numbers rounded to 12 digits (a case file's 1e-3 and a summary's 0.001 alike)."""
    if isinstance(v, bool) or isinstance(v, str):
        return v
    if isinstance(v, (int, float)):
        return _num(v)
    if isinstance(v, (list, tuple)):
        return tuple(_plain(x) for x in v)
    if isinstance(v, dict):
        return tuple(sorted((k, _plain(x)) for k, x in v.items()))
    return v


def physical_problem(cfg):
    """The physical problem a configuration describes (a case file with its overrides, or the
    resolved configuration of a summary.json), in terms a 3-D quarter cylinder and an
    axisymmetric section share: {item: value}. Items: the body (a cylinder (radius, height) for
    both), the material (every key, defaults filled in), each condition with its name, type,
    component ('axial' for z in 3-D and y in a section) and load history (the curve's points
    scaled by the value), body force, fluid source, regions, and the probe line's ends as
    (r, axial). The quarter cylinder's symmetry conditions on symmetry_x and symmetry_y are what
    the axis of the axisymmetric section holds: they are part of its body, not conditions."""
    defaults = schema_defaults()
    model = cfg.get("model", defaults.get("model", "three_dimensional"))
    section = model in SECTION_MODELS
    mesh = cfg.get("mesh", {})
    source = mesh.get("source", defaults.get("mesh.source", "quarter_cylinder"))
    bcs = cfg.get("boundary", [])
    symmetry = {b.get("name") for b in bcs if b.get("type") == "symmetry"}
    if model == "axisymmetric" and source == "section":
        sec = mesh.get("section", {})
        body = ("cylinder", _num(sec.get("width", defaults.get("mesh.section.width", 18.0))),
                _num(sec.get("height", defaults.get("mesh.section.height", 8.0))))
    elif not section and source == "quarter_cylinder" and set(QUARTER_SYMMETRY) <= symmetry:
        body = ("cylinder", _num(mesh.get("radius", defaults.get("mesh.radius", 18.0))),
                _num(mesh.get("height", defaults.get("mesh.height", 8.0))))
    elif not section and source == "quarter_cylinder":
        body = ("quarter cylinder without symmetry conditions on symmetry_x and symmetry_y",)
    elif source == "section":
        sec = mesh.get("section", {})
        body = (model, "rectangle", _num(sec.get("width", defaults.get("mesh.section.width"))),
                _num(sec.get("height", defaults.get("mesh.section.height"))))
    elif source == "column":
        col = mesh.get("column", {})
        body = (model, "column") + tuple(_num(col.get(k, defaults.get(f"mesh.column.{k}")))
                                         for k in ("width", "depth", "height"))
    else:  # a mesh file, or another generator: the same only if the same source and file
        body = (model, source, mesh.get("file", ""))
    out = {"body": body}
    material = {k.split(".", 1)[1]: v for k, v in defaults.items() if k.startswith("material.")}
    material.update(cfg.get("material", {}))
    for k, v in material.items():
        out[f"material.{k}"] = _plain(v)
    curves = cfg.get("curves", {})
    axial = "y" if section else "z"
    conditions = []
    for b in bcs:
        name, kind = b.get("name"), b.get("type")
        if not section and kind == "symmetry" and name in QUARTER_SYMMETRY:
            continue
        comp = b.get("component")
        if comp == axial:
            comp = "axial"
        value = b.get("value", b.get("vector"))
        curve = b.get("curve", "")
        if curve and value is not None:
            points = curves.get(curve)
            scaled = ((lambda y: tuple(_num(v * y) for v in value)) if isinstance(value, list)
                      else (lambda y: _num(value * y)))
            history = (tuple((_num(tp), scaled(y)) for tp, y in points)
                       if points is not None else f"curve '{curve}' missing")
        else:
            history = _plain(value)
        conditions.append((name, kind, comp or "", history))
    for name, kind, comp, history in sorted(conditions, key=repr):
        key = f"condition {kind} on '{name}'" + (f" ({comp})" if comp else "")
        out[key] = out.get(key, ()) + (history,)
    force = cfg.get("body_force", {})
    for c in ("x", "y", "z"):
        f = str(force.get(c, "0")).strip()
        if f != "0":
            out[f"body_force.{'axial' if c == axial else c} ({model})"] = f
    source_term = str(cfg.get("fluid_source", {}).get("value", "0")).strip()
    if source_term != "0":
        out[f"fluid_source.value ({model})"] = source_term
    if cfg.get("region"):
        out["regions"] = _plain(cfg["region"])
    output = cfg.get("output", {})
    ends = []
    for key in ("line_start", "line_end"):
        x, y, z = output.get(key, defaults.get(f"output.{key}", [0.0, 0.0, 0.0]))
        ends.append((_num(x), _num(y)) if section else (_num(math.hypot(x, y)), _num(z)))
    out["probe line (r, axial)"] = tuple(ends)
    return out


def physical_differences(run_cfg, ref_cfg):
    """What differs between the physical problems of a run and of its reference (empty: the
    same problem)."""
    a, b = physical_problem(run_cfg), physical_problem(ref_cfg)
    missing = "(none)"
    return [f"{k}: run {a.get(k, missing)}, reference {b.get(k, missing)}"
            for k in sorted(set(a) | set(b), key=str) if a.get(k, missing) != b.get(k, missing)]


def check_reference(run, base, reference, label):
    """Stops the study if the reference, with the run's physical parameters applied, does not
    describe the run's physical problem."""
    physical, overrides = reference_overrides(run, base, reference)
    run_cfg = with_overrides(base.toml, run["overrides"])
    ref_cfg = with_overrides(reference.toml, overrides)
    diff = physical_differences(run_cfg, ref_cfg)
    if diff:
        raise StudyError(f"run {run['dir']}: the {label} {reference.path.name} does not "
                         "describe the run's physical problem (a physical parameter of the run "
                         "cannot be applied to it): " + "; ".join(diff))


# ---- measures ------------------------------------------------------------------------------

def axial_column(line_csv):
    """The line.csv column of the axial coordinate: y in a section model (x = r, y = z), else
    z. The model is read from the run's summary.json next to the file."""
    try:
        model = json.loads((pathlib.Path(line_csv).parent / "summary.json").read_text())["model"]
    except (OSError, ValueError, KeyError):
        model = "three_dimensional"
    return "y" if model in SECTION_MODELS else "z"


@functools.lru_cache(maxsize=None)
def read_line(path):
    """{t: (z list, p list)} from a line.csv, z the axial coordinate (cached: a reference serves
    many runs; callers do not modify the result)."""
    out = {}
    axial = axial_column(path)
    with open(path) as f:
        for row in csv.DictReader(f):
            t = round(float(row["t"]), 9)
            out.setdefault(t, ([], []))
            out[t][0].append(float(row[axial]))
            out[t][1].append(float(row["p"]))
    for t, (z, p) in out.items():
        order = sorted(range(len(z)), key=lambda i: z[i])
        out[t] = ([z[i] for i in order], [p[i] for i in order])
    return out


def interpolate(x, xs, ys):
    """Piecewise-linear ys(x) on sorted xs (constant beyond the ends)."""
    if x <= xs[0]:
        return ys[0]
    i = bisect.bisect_left(xs, x)
    if i >= len(xs):
        return ys[-1]
    w = (x - xs[i - 1]) / (xs[i] - xs[i - 1]) if xs[i] > xs[i - 1] else 0.0
    return ys[i - 1] + w * (ys[i] - ys[i - 1])


def vertices(z, p):
    """The pressure nodes (P1 vertices) among the line's P2 nodes: the line runs along element
    edges, so its 2n + 1 nodes alternate vertex, mid-edge node, vertex."""
    if len(z) % 2 == 1:
        return z[::2], p[::2]
    return z, p


def discrepancy(run_line, ref_line):
    """max |p_h − p_ref| / max_line |p_ref| over the run's pressure nodes on the line (the
    nodal values the paper compares), at each output time the two share (t > 0)."""
    out = {}
    for t, (z, p) in run_line.items():
        z, p = vertices(z, p)
        match = [tr for tr in ref_line if abs(tr - t) < 1e-6 * max(1.0, abs(t))]
        if t <= 0 or not match:
            continue
        zr, pr = ref_line[match[0]]
        scale = max(abs(v) for v in pr)
        if scale == 0:
            continue
        out[t] = max(abs(pv - interpolate(zv, zr, pr)) for zv, pv in zip(z, p)) / scale
    return out


def midheight_error(run_line, ref_line):
    """|p_h − p_ref| / |p_ref| at mid-height of the line at the last output time shared with
    the reference: the accuracy away from the drained faces."""
    for t in sorted(run_line, reverse=True):
        match = [tr for tr in ref_line if abs(tr - t) < 1e-6 * max(1.0, abs(t))]
        if t <= 0 or not match:
            continue
        z, p = run_line[t]
        zr, pr = ref_line[match[0]]
        mid = 0.5 * (z[0] + z[-1])
        ref = interpolate(mid, zr, pr)
        return abs(interpolate(mid, z, p) - ref) / abs(ref) if ref else None
    return None


AXES = {"x": 0, "y": 1, "z": 2}


def curve_extremes(points, t_end):
    """(largest |value|, largest |slope|) of a piecewise-linear curve over [0, t_end]."""
    if not points:
        return 1.0, 0.0
    ts = [0.0] + [t for t, _ in points if 0.0 < t < t_end] + [t_end]

    def value(t):
        if t <= points[0][0]:
            return points[0][1]
        for (t0, v0), (t1, v1) in zip(points, points[1:]):
            if t <= t1:
                return v0 + (v1 - v0) * (t - t0) / (t1 - t0)
        return points[-1][1]
    top = max(abs(value(t)) for t in ts)
    slope = 0.0
    for (t0, v0), (t1, v1) in zip(points, points[1:]):
        if t1 > 0.0 and t0 < t_end and t1 > t0:
            slope = max(slope, abs(v1 - v0) / (t1 - t0))
    return top, slope


def loading_of(summary):
    """How the run is loaded, from its own geometry and conditions: {"loading": text,
    "strain": final compressive strain (largest displacement over the body's extent along it;
    for a rigid platen its measured final displacement), "loading_rate_um_s": the fastest
    platen speed the curve prescribes}; None where the run does not say (no displacement
    condition, or no bounds in an old summary)."""
    cfg = summary["configuration"]
    bounds = summary["mesh"].get("bounds")
    out = {"loading": None, "strain": None, "loading_rate_um_s": None}
    if not bounds:
        return out
    extent = [hi - lo for lo, hi in zip(bounds["min"], bounds["max"])]
    t_end = cfg["time"]["t_end"]
    best = None
    for b in cfg["boundary"]:
        if b["type"] not in ("displacement", "rigid_platen") or b.get("component") not in AXES:
            continue
        c = AXES[b["component"]]
        if extent[c] <= 0:
            continue
        top, slope = curve_extremes(cfg.get("curves", {}).get(b.get("curve", ""), []), t_end)
        if b["type"] == "rigid_platen":
            outs = [o for o in summary["outputs"] if o.get("platens", {}).get(b["name"])]
            if not outs:
                continue
            depth, rate = abs(outs[-1]["platens"][b["name"]]["displacement"]), None
        else:
            depth, rate = abs(b["value"]) * top, abs(b["value"]) * slope * 1e3
        if depth > 0 and (best is None or depth > best[0]):
            best = (depth, {"loading": f"{b['type']} {b['component']} on '{b['name']}'",
                            "strain": depth / extent[c],
                            "loading_rate_um_s": rate})
    return best[1] if best else out


def reaction_columns(last):
    """The last output's reactions and platen records as columns: reaction_<name>_<x|y|z> [N],
    platen_<name>_displacement [mm], platen_<name>_force [N]."""
    cols = {}
    for name, force in (last.get("reactions") or {}).items():
        for axis, value in zip("xyz", force):
            cols[f"reaction_{name}_{axis}"] = value
    for name, rec in (last.get("platens") or {}).items():
        cols[f"platen_{name}_displacement"] = rec["displacement"]
        cols[f"platen_{name}_force"] = rec["force"]
    return cols


def row_for(run, run_dir, study_name, reference_infos, rss_gb):
    """One table row; reference_infos: {"reference" or "reference_check": (dir, label)}."""
    s = json.loads((run_dir / "summary.json").read_text())
    cfg, c, tm = s["configuration"], s["counters"], s["timings"]
    outs = [o for o in s["outputs"] if o["t"] > 0]
    last = outs[-1] if outs else {}

    def peak(key):
        vals = [o[key] for o in outs if o.get(key) is not None]
        return max(vals) if vals else None

    t_end = cfg["time"]["t_end"]
    loading = loading_of(s)
    line = s.get("line", {})
    line_elements = (line.get("nodes", 1) - 1) // 2  # P2 elements along a line of mesh nodes
    line_length = (math.dist(line["start"], line["end"]) if "start" in line and "end" in line
                   else None)
    row = {
        "study": study_name, "sweep": run["sweep"], "run": run["dir"], "status": s["status"],
        **{f"param:{k}": v for k, v in run["params"].items()},
        "mesh_lc": cfg["mesh"].get("lc"), "mesh_layers": cfg["mesh"].get("layers", 0),
        "unknowns": s["mesh"]["unknowns"],
        "tetrahedra": s["mesh"].get("tetrahedra", s["mesh"].get("triangles")),
        "h_line": line_length / line_elements if line_length and line_elements > 0 else None,
        "permeability": cfg["material"]["permeability"],
        "lambda": cfg["material"]["lambda"], "mu": cfg["material"]["mu"],
        "stabilisation": cfg["stabilisation"]["type"], "integrator": cfg["time"]["integrator"],
        "dt": cfg["time"]["dt"], "bdf_rtol": cfg["time"]["bdf"]["rtol"],
        **loading, "t_end": t_end,
        "linear_solver": cfg["linear_solver"]["type"],
        "p_mid": last.get("p_mid"), "overshoot": last.get("overshoot"),
        "overshoot_max": peak("overshoot"), "undershoot": last.get("undershoot"),
        "undershoot_max": peak("undershoot"), "oscillation": last.get("oscillation"),
        "oscillation_max": peak("oscillation"),
        "discrepancy": None, "discrepancy_max": None, "midheight_error": None, "reference": None,
        **({"discrepancy_check": None, "discrepancy_check_max": None, "reference_check": None}
           if "reference_check" in reference_infos else {}),
        "wall_s": tm["wall"], "peak_rss_gb": rss_gb,
        "steps": c["steps"], "newton_iterations": c["newton_iterations"],
        "residual_evaluations": c["residual_evaluations"],
        "jacobian_evaluations": c["jacobian_evaluations"],
        "factorizations": c["factorizations"], "linear_solves": c["linear_solves"],
        "error_test_failures": c.get("error_test_failures"),
        "nonlinear_failures": c.get("nonlinear_failures"),
        **reaction_columns(last),
    }
    for which, (ref_dir, label) in reference_infos.items():
        if not (run_dir / "line.csv").is_file():
            continue
        # The resolved configurations of both: the reference must be the run's problem.
        ref_cfg = json.loads((ref_dir / "summary.json").read_text())["configuration"]
        diff = physical_differences(cfg, ref_cfg)
        if diff:
            row["reference_mismatch"] = f"{which}: " + "; ".join(diff)
            continue
        run_line, ref_line = read_line(run_dir / "line.csv"), read_line(ref_dir / "line.csv")
        d = discrepancy(run_line, ref_line)
        if not d:
            continue
        final = max(d)
        if which == "reference":
            row["discrepancy"] = d[final]
            row["discrepancy_max"] = max(d.values())
            row["midheight_error"] = midheight_error(run_line, ref_line)
            row["reference"] = label
        else:
            row["discrepancy_check"] = d[final]
            row["discrepancy_check_max"] = max(d.values())
            row["reference_check"] = label
    return row


# ---- references ----------------------------------------------------------------------------

def reference_overrides(run, base, reference):
    """The physical parameters of a run, applied to the reference case."""
    # A material key set to the reference's own value changes nothing: left out, so that the
    # same physical problem always has the same cache key (one reference, computed once).
    own = reference.toml.get("material", {})
    physical = {k: v for k, v in run["fixed"].items()
                if is_physical(k) and not (k.startswith("material.") and own.get(k[9:]) == v)}
    rate, strain = base.default_loading()
    physical.setdefault("loading.rate", round(rate, 12))
    physical.setdefault("loading.strain", round(strain, 12))
    return physical, expand(physical, reference, f"reference {reference.path}")


def reference_key(reference, physical):
    text = reference.path.read_text() + json.dumps(physical, sort_keys=True)
    return hashlib.sha1(text.encode()).hexdigest()[:12]


def reference_label(reference, physical, ref_dir):
    s = json.loads((ref_dir / "summary.json").read_text())
    k = s["configuration"]["material"]["permeability"]
    where = ref_dir.relative_to(ROOT) if ref_dir.is_relative_to(ROOT) else ref_dir
    return (f"{reference.path.name} ({s['model']}, k={k}, {s['mesh']['unknowns']} unknowns, "
            f"{s['configuration']['time']['integrator']}) {where}")


# ---- running -------------------------------------------------------------------------------

def completed(run_dir, overrides):
    try:
        stamp = json.loads((run_dir / "run.json").read_text())
        status = json.loads((run_dir / "summary.json").read_text())["status"]
    except (OSError, ValueError, KeyError):
        return None
    if stamp.get("overrides") != overrides:
        return None
    return status


class Pool:
    """Runs `biphasic run` jobs side by side, one core each, with progress and ETA."""

    def __init__(self, jobs, total):
        self.jobs, self.total = jobs, total
        self.running = {}  # pid -> (proc, label, start, on_done, log)
        self.done = 0
        self.walls = []
        self.t0 = time.time()

    def start(self, cmd, run_dir, label, on_done):
        while len(self.running) >= self.jobs:
            self.wait_one()
        run_dir.mkdir(parents=True, exist_ok=True)
        log = open(run_dir / "log.txt", "w")
        env = dict(os.environ, OMP_NUM_THREADS=str(max(1, (os.cpu_count() or 2) // self.jobs)))
        if self.jobs > 1:
            env["OPENBLAS_NUM_THREADS"] = "1"
        proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, env=env)
        self.running[proc.pid] = (proc, label, time.time(), on_done, log)

    def wait_one(self):
        pid, status, usage = os.wait4(-1, 0)
        if pid not in self.running:
            return
        proc, label, start, on_done, log = self.running.pop(pid)
        log.close()
        proc.returncode = os.waitstatus_to_exitcode(status)
        wall = time.time() - start
        self.walls.append(wall)
        self.done += 1
        on_done(proc.returncode, usage.ru_maxrss / 1024 / 1024)
        left = self.total - self.done - len(self.running)
        mean = sum(self.walls) / len(self.walls)
        eta = mean * (left + len(self.running) / 2) / self.jobs
        state = "ok" if proc.returncode == 0 else f"FAILED (exit {proc.returncode})"
        print(f"[{self.done}/{self.total} done, {len(self.running)} running, {left} left, "
              f"ETA {eta / 60:.1f} min] {label}: {state} in {wall:.1f} s", flush=True)

    def drain(self):
        while self.running:
            self.wait_one()


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("study", type=pathlib.Path)
    ap.add_argument("-o", "--output", type=pathlib.Path, default=None)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--dry-run", action="store_true", help="list the runs and stop")
    ap.add_argument("--retry-failed", action="store_true", help="rerun runs that failed before")
    ap.add_argument("--skip-reference-check", action="store_true",
                    help="do not compute or measure against the study's reference_check")
    args = ap.parse_args()
    try:
        study, base, runs, references = load_study(args.study.resolve())
        if args.skip_reference_check:
            references.pop("reference_check", None)
        # Every run's physical problem must reach each reference (pure Python, before any run).
        for which, reference in references.items():
            for r in runs:
                check_reference(r, base, reference, which.replace("_", " "))
    except StudyError as e:
        sys.exit(f"study: {e}")
    name = args.study.stem
    out = args.output or pathlib.Path(study.get("output", ROOT / "results" / "studies" / name))
    out = out if out.is_absolute() else (ROOT / out)
    if not BIN.is_file():
        sys.exit(f"study: {BIN} not found; build first (tools/build.sh)")
    print(f"study {name}: {study.get('title', '')} — {len(runs)} runs into {out}")
    if args.dry_run:
        for r in runs:
            print(f"  {r['dir']}: {' '.join(f'{k}={toml_value(v)}' for k, v in r['overrides'].items())}")
        return
    # References first (each once; cached across studies).
    refs = {}
    todo_refs = []
    for which, reference in references.items():
        for r in runs:
            physical, overrides = reference_overrides(r, base, reference)
            key = reference_key(reference, physical)
            r.setdefault("reference_keys", {})[which] = key
            if key in refs:
                continue
            ref_dir = REFERENCE_CACHE / key
            refs[key] = (ref_dir, physical, reference, overrides)
    try:
        validate(base, runs)
        for key, (ref_dir, physical, reference, overrides) in refs.items():
            validate(reference, [{"dir": f"reference {key}", "overrides": overrides}])
    except StudyError as e:
        sys.exit(f"study {args.study}: {e}")
    for key, (ref_dir, physical, reference, overrides) in refs.items():
        if completed(ref_dir, overrides) != "completed":
            todo_refs.append((key, ref_dir, reference, overrides))

    todo = [r for r in runs
            if completed(out / "runs" / r["dir"], r["overrides"]) not in
            (("completed",) if args.retry_failed else ("completed", "failed"))]
    print(f"{len(runs) - len(todo)} runs already done; {len(todo)} to run"
          + (f", {len(todo_refs)} reference solutions to compute first" if todo_refs else ""),
          flush=True)

    def stamp(run_dir, overrides):
        def on_done(code, peak_gb):
            (run_dir / "run.json").write_text(json.dumps(
                {"overrides": overrides, "exit_code": code, "peak_rss_gb": round(peak_gb, 4)},
                indent=1))
        return on_done

    if todo_refs:
        pool = Pool(args.jobs, len(todo_refs))
        for key, ref_dir, reference, overrides in todo_refs:
            if ref_dir.exists():
                shutil.rmtree(ref_dir)
            cmd = [str(BIN), "run", str(reference.path), "-o", str(ref_dir)] + \
                set_args(overrides)
            pool.start(cmd, ref_dir, f"reference {key}", stamp(ref_dir, overrides))
        pool.drain()

    pool = Pool(args.jobs, len(todo))
    for r in todo:
        run_dir = out / "runs" / r["dir"]
        if run_dir.exists():
            shutil.rmtree(run_dir)
        cmd = [str(BIN), "run", str(base.path), "-o", str(run_dir)] + \
            set_args(r["overrides"])
        pool.start(cmd, run_dir, r["dir"], stamp(run_dir, r["overrides"]))
    pool.drain()

    rows = []
    for r in runs:
        run_dir = out / "runs" / r["dir"]
        infos = {}
        for which, key in r.get("reference_keys", {}).items():
            ref_dir, physical, reference, _ = refs[key]
            if (ref_dir / "summary.json").is_file():
                infos[which] = (ref_dir, reference_label(reference, physical, ref_dir))
        try:
            peak = json.loads((run_dir / "run.json").read_text()).get("peak_rss_gb")
            rows.append(row_for(r, run_dir, name, infos, peak))
        except (OSError, ValueError, KeyError) as e:
            rows.append({"study": name, "sweep": r["sweep"], "run": r["dir"], "status": "missing",
                         **{f"param:{k}": v for k, v in r["params"].items()}})
            print(f"  {r['dir']}: no results ({e})", file=sys.stderr)
    columns = []
    for row in rows:
        for k in row:
            if k not in columns:
                columns.append(k)
    if study.get("columns"):
        unknown = [c for c in study["columns"] if c not in columns]
        if unknown:
            raise StudyError(f"{args.study}: columns: no column {', '.join(unknown)} in the table "
                             f"(available: {', '.join(columns)})")
        columns = list(study["columns"])
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "runs.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        for row in rows:
            w.writerow({k: ("" if row.get(k) is None else row.get(k)) for k in columns})
    failed = [row["run"] for row in rows if row.get("status") != "completed"]
    print(f"table: {out / 'runs.csv'} ({len(rows)} rows"
          + (f"; not completed: {', '.join(failed)}" if failed else "") + ")")
    mismatched = [row for row in rows if row.get("reference_mismatch")]
    for row in mismatched:
        print(f"  {row['run']}: not measured, the reference is another problem: "
              f"{row['reference_mismatch']}", file=sys.stderr)
    if failed or mismatched:
        sys.exit(1)


if __name__ == "__main__":
    main()
