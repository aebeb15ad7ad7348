#!/usr/bin/env python3
"""`mpiexec -n N biphasic run CASE --restart DIR` against an uninterrupted run (ctest label mpi).

Three runs of CASE with reactions on "top" and "bottom": (a) N processes to the case's t_end;
(b) N processes to T_STOP, then continued with --restart on N processes; (c) a copy of (b)'s
first part continued on one process (the checkpoint is written in the one-process layout).
line.csv and reactions.csv of (b) and (c) must have the rows of (a), agreeing to 1e-8 of each
column's largest value (the parallel MUMPS varies from run to run in the last digits), and
their summaries must be completed with one restart recorded. A restart with another case's
checkpoint (material.mu changed) must end every process with exit status 1, print the error
once and leave the folder's files as they were. With --compare-fields EXE, fields.h5 of (b)
and (c) must agree with (a)'s too (compare_fields.cpp). Usage:
restart_matches_uninterrupted.py BIPHASIC MPIEXEC N CASE T_STOP [--compare-fields EXE]
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

from run_matches_serial import largest_difference, read_csv


def compare_csv(reference, run, name, keys, failures):
    """Row by row: the same times (to rounding: a segment ends exactly at its t_end) and the
    same rows, the values to 1e-8 of each column's largest."""
    a, b = read_csv(os.path.join(reference, name)), read_csv(os.path.join(run, name))
    label = f"{os.path.basename(run)}/{name}"
    if len(a) != len(b) or not a:
        failures.append(f"{label}: {len(b)} rows, the uninterrupted run has {len(a)}")
        return
    t_scale = max(abs(float(r["t"])) for r in a) or 1.0
    for i, (x, y) in enumerate(zip(a, b)):
        if abs(float(x["t"]) - float(y["t"])) > 1e-9 * t_scale or any(
                x[k] != y[k] for k in x if k not in keys and k != "t"):
            failures.append(f"{label}: row {i + 1} is {y}, the uninterrupted run's {x}")
            return
    d = largest_difference(a, b, keys)
    print(f"{label}: {len(b)} rows, largest difference {d:.2e} of the largest value")
    if not d <= 1e-8:
        failures.append(f"{label} differs by {d:.2e}")


def check_summary(run, failures):
    with open(os.path.join(run, "summary.json")) as f:
        s = json.load(f)
    restarts = s.get("restarts", [])
    if s.get("status") != "completed" or len(restarts) != 1:
        failures.append(f"{os.path.basename(run)}/summary.json: status {s.get('status')}, "
                        f"{len(restarts)} restarts")


def main():
    biphasic, mpiexec, processes, case, t_stop = sys.argv[1:6]
    extra = sys.argv[6:]
    compare_fields = extra[1] if extra[:1] == ["--compare-fields"] else None
    overrides = ["--set", 'output.reactions=["top","bottom"]']
    mpi = [mpiexec, "--oversubscribe", "-n", processes, biphasic, "run", case, "--quiet"]
    serial = [biphasic, "run", case, "--quiet"]
    with tempfile.TemporaryDirectory() as tmp:
        a, b, c = (os.path.join(tmp, name) for name in ("uninterrupted", "restarted", "on_one"))
        subprocess.run(mpi + ["-o", a] + overrides, check=True)
        subprocess.run(mpi + ["-o", b] + overrides + ["--set", f"time.t_end={t_stop}"],
                       check=True)
        shutil.copytree(b, c)
        subprocess.run(mpi + ["--restart", b] + overrides, check=True)
        subprocess.run(serial + ["--restart", c] + overrides, check=True)

        failures = []
        for run in (b, c):
            compare_csv(a, run, "line.csv", ["ux", "uy", "uz", "p"], failures)
            compare_csv(a, run, "reactions.csv", ["Fx", "Fy", "Fz"], failures)
            check_summary(run, failures)
            if compare_fields:
                fields = subprocess.run([compare_fields, os.path.join(a, "fields.h5"),
                                         os.path.join(run, "fields.h5"), "1e-8"])
                if fields.returncode != 0:
                    failures.append(f"{os.path.basename(run)}/fields.h5 differs (see above)")

        # Another case's checkpoint: refused on every process before anything is written.
        files = ("summary.json", "line.csv", "reactions.csv", "checkpoint.bin")
        before = {}
        for name in files:
            with open(os.path.join(b, name), "rb") as f:
                before[name] = f.read()
        refused = subprocess.run(mpi + ["--restart", b] + overrides +
                                 ["--set", "material.mu=0.6"], capture_output=True, text=True)
        said = (refused.stdout + refused.stderr).count("belongs to another case")
        if refused.returncode != 1 or said != 1:
            failures.append(f"another case's checkpoint: exit {refused.returncode}, message "
                            f"printed {said} times")
        for name in files:
            with open(os.path.join(b, name), "rb") as f:
                if f.read() != before[name]:
                    failures.append(f"the refused restart changed {name}")
        for f in failures:
            print("FAIL:", f)
        return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
