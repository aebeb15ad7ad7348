#!/usr/bin/python3
"""Time error against cost: runs of several time integrators measured against a
time-converged reference ON THE SAME MESH, or the largest step at which backward Euler converges.

usage: tools/time_study.py STUDY.toml [-o DIR] [--jobs N] [--dry-run] [--retry-failed]

A time study (kind = "time_error", the default; see docs/integrators.md):

    title = "Paper's reference loading, mesh 1"
    scene = "paper_mesh1"                       # label in the CSV and the figures
    base = "../paper/mesh1_k1e-3_gls.toml"      # relative to the study file
    set = { "output.fields" = false, "output.reactions" = ["top"] }
    vary = { "stabilisation.type" = ["gls", "none"] }   # one reference per combination
    compare_every = 8.0       # time errors over the output times that are multiples of this [s]
    be_output_interval = 8.0  # optional: backward Euler writes outputs only every 8 s
                              # (output.every = 8 s / dt), as the IDA runs do
    overshoot_at = [0.8, 8.0] # also record the overshoot at these output times
    csv = "docs/figures/integrators/time_paper_mesh1.csv"   # copy of the table (repo-relative)

    [reference]               # the time-converged reference, on top of set and vary
    set = { "time.integrator" = "bdf", "time.bdf.rtol" = 1e-8, "time.bdf.max_order" = 5,
            "time.dt" = 0.08 }
    check = { "time.bdf.rtol" = 1e-7 }   # a second run: its distance to the reference is stated

    [[method]]                # a method is a sweep of one integrator
    name = "backward_euler"
    set = { "time.integrator" = "backward_euler" }
    vary = { "time.dt" = [8.0, 4.0, 2.0, 0.8, 0.4, 0.16, 0.08] }

A failure study (kind = "failure"): for each combination of `vary`, backward Euler runs at
dt = t_end / N for N in `divisors`, coarsest first, until one completes (put
"time.newton.max_cutbacks" = 0 in `set` so that a failed Newton solve stops the run):

    kind = "failure"
    base = "../paper/mesh1_k1e-3_gls.toml"
    set = { "output.fields" = false, "time.newton.max_cutbacks" = 0 }
    vary = { "stabilisation.type" = ["gls", "none"], "loading.strain" = [0.01, 0.1] }
    divisors = [1, 2, 4, 8, 16, 32, 64]

Keys are case-file keys or the derived keys of tools/study.py (mesh, loading.rate,
loading.strain, time.steps). Runs go into DIR/runs/<combination>/<method>/<parameters>/ (default
DIR = results/time_studies/<study>); a run already done with the same overrides is not rerun.
The table (one row per run, with the time errors of tools/time_error.py and the solver's
counters) goes to DIR/runs.csv and to `csv`.
"""
import argparse
import concurrent.futures
import csv
import importlib.util
import itertools
import json
import os
import pathlib
import shutil
import subprocess
import sys
import time
import tomllib

ROOT = pathlib.Path(__file__).resolve().parent.parent


def _load(name):
    spec = importlib.util.spec_from_file_location(name, ROOT / "tools" / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


study = _load("study")
time_error = _load("time_error")
StudyError = study.StudyError

TOP_KEYS = {"kind", "title", "scene", "base", "set", "vary", "compare_every", "overshoot_at",
            "csv", "reference", "method", "divisors", "output", "be_output_interval"}


def combos(vary):
    keys = list(vary)
    for values in itertools.product(*(vary[k] for k in keys)):
        yield dict(zip(keys, values))


def load(path):
    try:
        s = tomllib.loads(path.read_text())
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise StudyError(f"{path}: {e}")
    for key in s:
        if key not in TOP_KEYS:
            raise StudyError(f"{path}: unknown key '{key}' ({', '.join(sorted(TOP_KEYS))})")
    if "base" not in s:
        raise StudyError(f"{path}: 'base' (the base case file) is missing")
    base = study.BaseCase((path.parent / s["base"]).resolve())
    if not base.path.is_file():
        raise StudyError(f"{path}: base = '{s['base']}': no such file ({base.path})")
    kind = s.get("kind", "time_error")
    if kind not in ("time_error", "failure"):
        raise StudyError(f"{path}: kind = '{kind}': 'time_error' or 'failure'")
    for key, values in s.get("vary", {}).items():
        if not isinstance(values, list) or not values:
            raise StudyError(f"{path}: vary.{key} must be a non-empty list")
    if kind == "time_error":
        if "reference" not in s or "set" not in s["reference"]:
            raise StudyError(f"{path}: [reference] with its 'set' is missing")
        if not s.get("method"):
            raise StudyError(f"{path}: no [[method]] tables")
    elif not s.get("divisors"):
        raise StudyError(f"{path}: 'divisors' is missing")
    return s, base, kind


def plan(s, base, path):
    """[(group params, [run dict])]: per combination of `vary`, its reference, check and runs."""
    groups = []
    for params in combos(s.get("vary", {})):
        gname = study.slug(params)
        where = f"{path}: {gname}"
        common = {**s.get("set", {}), **params}
        runs = []
        if "reference" in s:
            ref = {**common, **s["reference"]["set"]}
            runs.append({"method": "reference", "value": None,
                         "overrides": study.expand(ref, base, where), "dir": f"{gname}/reference"})
            if "check" in s["reference"]:
                chk = {**ref, **s["reference"]["check"]}
                runs.append({"method": "reference_check", "value": None,
                             "overrides": study.expand(chk, base, where),
                             "dir": f"{gname}/reference_check"})
        for m in s.get("method", []):
            vary = m.get("vary", {})
            if len(vary) != 1:
                raise StudyError(f"{where}: method '{m.get('name')}' must vary exactly one key")
            (key, values), = vary.items()
            for v in values:
                fixed = {**common, **m.get("set", {}), key: v}
                overrides = study.expand(fixed, base, where)
                interval = s.get("be_output_interval")
                if interval and overrides.get("time.integrator") == "backward_euler":
                    # write outputs only every `interval` seconds (writing every small step
                    # would dominate the wall time of a small problem)
                    overrides["output.every"] = max(1, round(interval / float(overrides["time.dt"])))
                runs.append({"method": m["name"], "key": key, "value": v,
                             "overrides": overrides,
                             "dir": f"{gname}/{m['name']}/{study.slug({key: v})}"})
        groups.append((params, runs))
    return groups


def run_one(base, run, out, retry_failed):
    """Runs one case (unless done); returns (status, measured wall)."""
    run_dir = out / "runs" / run["dir"]
    status = study.completed(run_dir, run["overrides"])
    if status == "completed" or (status == "failed" and not retry_failed):
        return status, None
    if run_dir.exists():
        shutil.rmtree(run_dir)
    run_dir.mkdir(parents=True)
    cmd = [str(study.BIN), "run", str(base.path), "-o", str(run_dir)] + \
        study.set_args(run["overrides"])
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    t0 = time.time()
    with open(run_dir / "log.txt", "w") as log:
        code = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, env=env).returncode
    wall = time.time() - t0
    (run_dir / "run.json").write_text(json.dumps(
        {"overrides": run["overrides"], "exit_code": code, "wall_measured": round(wall, 3)},
        indent=1))
    return study.completed(run_dir, run["overrides"]) or "no summary", wall


def summary(run_dir):
    try:
        return json.loads((run_dir / "summary.json").read_text())
    except (OSError, ValueError):
        return None


def failure_message(run_dir, s):
    if s and s.get("message"):
        return s["message"]
    try:
        lines = [ln.strip() for ln in (run_dir / "log.txt").read_text().splitlines() if ln.strip()]
    except OSError:
        return ""
    for ln in reversed(lines):
        if any(w in ln.lower() for w in ("error", "fail", "diverg", "invert", "converge")):
            return ln[:200]
    return lines[-1][:200] if lines else ""


def base_row(s_toml, group, run, run_dir):
    s = summary(run_dir)
    row = {"scene": s_toml.get("scene", ""), **{f"param:{k}": v for k, v in group.items()},
           "method": run["method"], "value": run["value"], "run": run["dir"],
           "status": s["status"] if s else "missing"}
    if not s:
        row["message"] = failure_message(run_dir, s)
        return row, None
    cfg, c, tm = s["configuration"], s["counters"], s["timings"]
    row.update({
        "stabilisation": cfg["stabilisation"]["type"], "integrator": cfg["time"]["integrator"],
        "dt": cfg["time"]["dt"], "bdf_rtol": cfg["time"]["bdf"]["rtol"],
        "t_end": cfg["time"]["t_end"], "unknowns": s["mesh"]["unknowns"],
        "wall_s": tm.get("wall"), "steps": c.get("steps"),
        "newton_iterations": c.get("newton_iterations"),
        "residual_evaluations": c.get("residual_evaluations"),
        "jacobian_evaluations": c.get("jacobian_evaluations"),
        "factorizations": c.get("factorizations"), "linear_solves": c.get("linear_solves"),
        "error_test_failures": c.get("error_test_failures"),
        "nonlinear_failures": c.get("nonlinear_failures"), "cutbacks": c.get("cutbacks"),
    })
    if row["status"] != "completed":
        row["message"] = failure_message(run_dir, s)
    return row, s


def time_error_rows(s_toml, base, groups, out):
    rows = []
    every = s_toml.get("compare_every")
    for group, runs in groups:
        ref_dir = out / "runs" / runs[0]["dir"]
        ref_ok = (summary(ref_dir) or {}).get("status") == "completed"
        for run in runs:
            run_dir = out / "runs" / run["dir"]
            row, s = base_row(s_toml, group, run, run_dir)
            if s:
                outs = [o for o in s.get("outputs", []) if o["t"] > 0]
                if outs:
                    row["t_first"] = outs[0]["t"]
                    row["overshoot_first"] = outs[0].get("overshoot")
                    row["overshoot_last"] = outs[-1].get("overshoot")
                    row["overshoot_max"] = max((o.get("overshoot") or 0.0) for o in outs)
                for t in s_toml.get("overshoot_at", []):
                    hit = [o for o in outs if abs(o["t"] - t) <= 1e-6 * max(1.0, t)]
                    row[f"overshoot@{t:g}"] = hit[0].get("overshoot") if hit else None
            if ref_ok and run["method"] != "reference" and (run_dir / "line.csv").is_file():
                try:
                    e = time_error.time_error(str(ref_dir), str(run_dir), every)
                    row.update({"error_pressure": e["pressure"], "error_reaction": e["reaction"],
                                "error_reaction_end": e["reaction_end"],
                                "error_displacement": e["displacement"],
                                "compared_times": e["times"]})
                except SystemExit as err:
                    row["message"] = str(err)
            rows.append(row)
    return rows


def write_table(rows, out, csv_path):
    columns = []
    for row in rows:
        for k in row:
            if k not in columns:
                columns.append(k)
    out.mkdir(parents=True, exist_ok=True)
    for p in [out / "runs.csv"] + ([csv_path] if csv_path else []):
        p.parent.mkdir(parents=True, exist_ok=True)
        with open(p, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=columns)
            w.writeheader()
            for row in rows:
                w.writerow({k: ("" if row.get(k) is None else row.get(k)) for k in columns})
        print(f"table: {p} ({len(rows)} rows)")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("study", type=pathlib.Path)
    ap.add_argument("-o", "--output", type=pathlib.Path, default=None)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--dry-run", action="store_true")
    ap.add_argument("--retry-failed", action="store_true")
    args = ap.parse_args()
    path = args.study.resolve()
    try:
        s, base, kind = load(path)
        out = args.output or ROOT / s.get("output", f"results/time_studies/{path.stem}")
        out = out if out.is_absolute() else ROOT / out
        csv_path = ROOT / s["csv"] if s.get("csv") else None
        if kind == "time_error":
            groups = plan(s, base, path)
        else:
            groups = []
            for params in combos(s.get("vary", {})):
                fixed = {**s.get("set", {}), **params}
                t_end = float(study.expand(fixed, base, str(path)).get("time.t_end", base.t_end))
                runs = []
                for n in s["divisors"]:
                    dt = t_end / n
                    runs.append({"method": "backward_euler", "key": "time.dt", "value": dt,
                                 "divisor": n,
                                 "overrides": study.expand({**fixed, "time.dt": dt}, base, str(path)),
                                 "dir": f"{study.slug(params)}/N={n}"})
                groups.append((params, runs))
    except StudyError as e:
        sys.exit(f"time_study: {e}")
    total = sum(len(r) for _, r in groups)
    print(f"time study {path.stem} ({kind}): {s.get('title', '')} — {total} runs into {out}")
    if args.dry_run:
        for _, runs in groups:
            for r in runs:
                print(f"  {r['dir']}: " + " ".join(f"{k}={study.toml_value(v)}"
                                                   for k, v in r["overrides"].items()))
        return
    if not study.BIN.is_file():
        sys.exit(f"time_study: {study.BIN} not found; build first")
    try:
        study.validate(base, [r for _, runs in groups for r in runs])
    except StudyError as e:
        sys.exit(f"time_study {path}: {e}")

    done = [0]
    t0 = time.time()

    def report(run, status, wall):
        done[0] += 1
        how = "done before" if wall is None else f"{wall:.1f} s"
        print(f"[{done[0]}/{total}, {(time.time() - t0) / 60:.1f} min] {run['dir']}: {status} "
              f"({how})", flush=True)

    def chain(runs):
        """Failure study: coarsest step first, stop at the first that completes."""
        for run in runs:
            status, wall = run_one(base, run, out, args.retry_failed)
            report(run, status, wall)
            if status == "completed":
                break

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        if kind == "failure":
            futures = [pool.submit(chain, runs) for _, runs in groups]
        else:
            # references first (the longest runs), then the rest
            order = [r for _, runs in groups for r in runs if r["method"].startswith("reference")]
            order += [r for _, runs in groups for r in runs if not r["method"].startswith("reference")]
            futures = [pool.submit(lambda r=r: report(r, *run_one(base, r, out, args.retry_failed)))
                       for r in order]
        for f in futures:
            f.result()

    if kind == "time_error":
        rows = time_error_rows(s, base, groups, out)
    else:
        rows = []
        for group, runs in groups:
            largest = None
            for run in runs:
                run_dir = out / "runs" / run["dir"]
                if not (run_dir / "run.json").is_file():
                    continue  # not tried: a coarser step converged
                row, _ = base_row(s, group, run, run_dir)
                row["divisor"] = run["divisor"]
                rows.append(row)
                if row["status"] == "completed":
                    largest = run["value"]
                    break  # finer steps (left over from an earlier list of divisors) not listed
            for row in rows:
                if row["run"].startswith(study.slug(group) + "/"):
                    row["largest_converged_dt"] = largest
    write_table(rows, out, csv_path)


if __name__ == "__main__":
    main()
