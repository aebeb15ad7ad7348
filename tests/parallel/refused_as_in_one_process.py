#!/usr/bin/env python3
"""A case one process refuses before any work must be refused alike on N processes (ctest label
mpi): exit status 1 on both, the error printed once by the N-process run, and its problem lines
(those after "error:") the same as one process prints. Extra arguments (--set ...) go to both
runs. Usage: refused_as_in_one_process.py BIPHASIC MPIEXEC N CASE [--set ...] EXPECTED
where EXPECTED is a piece of text the message must contain.
"""
import os
import subprocess
import sys
import tempfile


def problems(text):
    """The indented lines right after "error:" that list the problems (mpiexec's own notes,
    which follow, are left out)."""
    lines, out = text.splitlines(), []
    start = next((k for k, line in enumerate(lines) if "error:" in line), len(lines))
    for line in lines[start + 1:]:
        if not line.startswith("  "):
            break
        out.append(line.strip())
    return out


def main():
    biphasic, mpiexec, processes, case = sys.argv[1:5]
    extra, expected = sys.argv[5:-1], sys.argv[-1]
    with tempfile.TemporaryDirectory() as tmp:
        one = subprocess.run([biphasic, "run", case, "-o", os.path.join(tmp, "one"), "--quiet"]
                             + extra, capture_output=True, text=True)
        many = subprocess.run([mpiexec, "--oversubscribe", "-n", processes, biphasic, "run", case,
                               "-o", os.path.join(tmp, "many"), "--quiet"] + extra,
                              capture_output=True, text=True)
    said = many.stdout + many.stderr
    print("one process:", one.returncode, one.stderr.strip())
    print(f"{processes} processes:", many.returncode, said.strip())
    failures = []
    if one.returncode != 1 or many.returncode != 1:
        failures.append(f"exit status {one.returncode} on one process, {many.returncode} on "
                        f"{processes}; both should be 1")
    if said.count("error:") != 1:
        failures.append(f"the error is printed {said.count('error:')} times")
    if expected not in one.stderr or expected not in said:
        failures.append(f"the message does not say '{expected}'")
    if problems(one.stderr) != problems(said):
        failures.append("the problems listed differ from one process's")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
