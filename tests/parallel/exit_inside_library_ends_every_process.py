#!/usr/bin/env python3
"""A process that ends through exit() inside a library (here MUMPS' analysis, as a Fortran
runtime error there does) must end the whole run (ctest label mpi): mpiexec returns a non-zero
status well within the time limit, instead of the other processes waiting forever, and the
ending process is named once. Usage:
  exit_inside_library_ends_every_process.py BIPHASIC MPIEXEC N CASE PRELOAD RANK [--set ...]
PRELOAD is the library that makes process RANK exit (exit_in_library.cpp).
"""
import os
import subprocess
import sys
import tempfile
import time

LIMIT = 120  # [s]; mesh 1 reaches its first analysis in a few seconds


def main():
    biphasic, mpiexec, processes, case, preload, rank = sys.argv[1:7]
    extra = sys.argv[7:]
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [mpiexec, "--oversubscribe", "-n", processes, "-x", "LD_PRELOAD=" + preload,
               "-x", "BIPHASIC_TEST_EXIT_RANK=" + rank, biphasic, "run", case,
               "-o", os.path.join(tmp, "out"), "--quiet"] + extra
        start = time.monotonic()
        try:
            run = subprocess.run(cmd, capture_output=True, text=True, timeout=LIMIT)
        except subprocess.TimeoutExpired as e:
            print(f"FAIL: the run still waited after {LIMIT} s (process {rank} had exited)")
            print((e.stderr or b"").decode(errors="replace")[-2000:])
            return 1
        took = time.monotonic() - start
    said = run.stdout + run.stderr
    print(f"exit status {run.returncode} after {took:.1f} s")
    print(said.strip()[-3000:])
    failures = []
    if "exit_in_library: process " + rank not in said:
        failures.append("the preloaded library never made the process exit (was it loaded?)")
    if run.returncode == 0:
        failures.append("exit status 0")
    expected = f"error: process {rank} ended inside a library call"
    if said.count(expected) != 1:
        failures.append(f"'{expected}' printed {said.count(expected)} times, not once")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
