#!/usr/bin/env python3
"""Wall time and peak memory per process of cases run on 1 process and on N processes.

Runs each case with `biphasic run` (one process; the sequential MUMPS) and with
`mpirun -n N biphasic run` (the parallel MUMPS), both with the case's linear solver settings
(by default the mesh's nested-dissection order and mixed precision), one run at a time, and prints a Markdown table from the runs' own summary.json
files (docs/parallel.md, *Measured*). Usage:

  tools/parallel_scaling.py [--processes 2] [--out results/parallel_scaling] CASE...
"""
import argparse
import json
import os
import subprocess
import sys


def run(cmd, env):
    print("+", " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, env=env, stdout=subprocess.DEVNULL)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("cases", nargs="+")
    ap.add_argument("--processes", type=int, default=2)
    ap.add_argument("--out", default="results/parallel_scaling")
    ap.add_argument("--biphasic", default="build/biphasic")
    ap.add_argument("--set", action="append", default=[], help="key=value for every run")
    args = ap.parse_args()
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    sets = sum((["--set", s] for s in args.set), [])
    rows = []
    for case in args.cases:
        stem = os.path.splitext(os.path.basename(case))[0]
        one = os.path.join(args.out, stem + "_np1")
        many = os.path.join(args.out, f"{stem}_np{args.processes}")
        os.makedirs(args.out, exist_ok=True)
        rss = os.path.join(args.out, stem + "_np1.maxrss")
        # The one-process summary has no memory record: GNU time's maximum resident set [KB].
        run(["/usr/bin/time", "-f", "%M", "-o", rss, args.biphasic, "run", case, "-o", one,
             "--overwrite", "--quiet"] + sets, env)
        run(["mpirun", "--oversubscribe", "-n", str(args.processes), args.biphasic, "run", case,
             "-o", many, "--overwrite", "--quiet"] + sets, env)
        with open(os.path.join(one, "summary.json")) as f:
            s1 = json.load(f)
        with open(os.path.join(many, "summary.json")) as f:
            sn = json.load(f)
        with open(rss) as f:
            s1["peak_gb"] = float(f.read().split()[-1]) / 1024**2
        rows.append((stem, s1, sn))
    n = args.processes
    print(f"\n| case | unknowns | wall, 1 process [s] | wall, {n} processes [s] | "
          f"peak memory, 1 process [GB] | peak memory per process, {n} processes [GB] | "
          f"factorisation, 1 / {n} [s] | Newton iterations, 1 / {n} |")
    print("|---|---|---|---|---|---|---|---|")
    for stem, s1, sn in rows:
        mem1 = s1["peak_gb"]
        memn = ", ".join(f"{m:.2f}" for m in sn["parallel"]["peak_memory_gb"])
        print(f"| {stem} | {sn['mesh']['unknowns']} | {s1['timings']['wall']:.1f} | "
              f"{sn['timings']['wall']:.1f} | {mem1:.2f} | {memn} | "
              f"{s1['timings']['factorization']:.1f} / {sn['timings']['factorization']:.1f} | "
              f"{s1['counters']['newton_iterations']} / {sn['counters']['newton_iterations']} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
