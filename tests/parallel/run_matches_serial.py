#!/usr/bin/env python3
"""`mpiexec -n N biphasic run CASE` against `biphasic run CASE` on one process (ctest label mpi),
three-dimensional or two-dimensional.

The line probe (every row, u and p) and the reactions (every output) must agree to 1e-8 of
their largest value, with the same Newton iterations step by step; with rigid platens, so must
platens.csv's displacements, its forces and the summary's platen record be the same; the summary must record
the processes and their partition; a case refused on several processes (KLU) must end every
process with exit status 1 and one message. With --compare-fields EXE, every field of the two
runs' fields.h5 (displacement, pressure and the cell fields each process recovers for its own
elements, written into one file by all processes) must agree to 1e-8 of its largest value as
well, checked by EXE (compare_fields.cpp), with the mesh and output times equal and fields.xdmf
the same text. With --factorizations-may-differ, the factorisation counts are printed but
not compared: a BDF run's consistent start repeats its correction until the momentum residual is
below 1e-12 of the force scale, a round-off level where a platen's force row (a sum over its
face) lands on either side depending on the order of the sums. --parallel-set KEY=VALUE goes to
the run on N processes only (a solver one process does not have); other extra arguments
(--set ...) go to both runs. Usage:
run_matches_serial.py BIPHASIC MPIEXEC N CASE [--compare-fields EXE] [--factorizations-may-differ]
                      [--parallel-set KEY=VALUE ...] [--set ...]
"""
import csv
import json
import os
import subprocess
import sys
import tempfile


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def largest_difference(a, b, keys):
    worst = 0.0
    for key in keys:
        scale = max(abs(float(r[key])) for r in a) or 1.0
        diff = max(abs(float(x[key]) - float(y[key])) for x, y in zip(a, b))
        worst = max(worst, diff / scale)
    return worst


def main():
    biphasic, mpiexec, processes, case = sys.argv[1:5]
    extra = sys.argv[5:]
    compare_fields = None
    counted = ("shift_corrected_solves", "factorizations")
    parallel_only = []
    while extra[:1] in (["--compare-fields"], ["--factorizations-may-differ"], ["--parallel-set"]):
        if extra[0] == "--compare-fields":
            compare_fields, extra = extra[1], extra[2:]
        elif extra[0] == "--parallel-set":
            parallel_only, extra = parallel_only + ["--set", extra[1]], extra[2:]
        else:
            counted, extra = ("shift_corrected_solves",), extra[1:]
    overrides = ["--set", 'output.reactions=["top", "bottom"]'] + extra
    with tempfile.TemporaryDirectory() as tmp:
        serial, parallel = os.path.join(tmp, "serial"), os.path.join(tmp, "parallel")
        subprocess.run([biphasic, "run", case, "-o", serial, "--quiet"] + overrides, check=True)
        subprocess.run([mpiexec, "--oversubscribe", "-n", processes, biphasic, "run", case, "-o",
                        parallel] + overrides + parallel_only, check=True)
        failures = []
        a, b = read_csv(os.path.join(serial, "line.csv")), read_csv(os.path.join(parallel, "line.csv"))
        if len(a) != len(b):
            failures.append(f"line.csv: {len(a)} rows on one process, {len(b)} on {processes}")
        else:
            d = largest_difference(a, b, ["ux", "uy", "uz", "p"])
            print(f"line.csv: largest difference {d:.2e} of the largest value")
            if not d <= 1e-8:
                failures.append(f"line.csv differs by {d:.2e}")
        a = read_csv(os.path.join(serial, "reactions.csv"))
        b = read_csv(os.path.join(parallel, "reactions.csv"))
        if len(a) != len(b) or len(a) == 0:
            failures.append(f"reactions.csv: {len(a)} rows on one process, {len(b)} on {processes}")
        else:
            d = largest_difference(a, b, ["Fx", "Fy", "Fz"])
            print(f"reactions.csv: largest difference {d:.2e} of the largest value")
            if not d <= 1e-8:
                failures.append(f"reactions.csv differs by {d:.2e}")
        if os.path.exists(os.path.join(serial, "platens.csv")):
            a = read_csv(os.path.join(serial, "platens.csv"))
            b = read_csv(os.path.join(parallel, "platens.csv"))
            if len(a) != len(b) or [r["platen"] for r in a] != [r["platen"] for r in b]:
                failures.append(f"platens.csv: {len(a)} rows on one process, {len(b)} on {processes}")
            else:
                d = largest_difference(a, b, ["displacement"])
                print(f"platens.csv: largest difference {d:.2e} of the largest displacement")
                if not d <= 1e-8:
                    failures.append(f"platens.csv differs by {d:.2e}")
                if [r["force"] for r in a] != [r["force"] for r in b]:
                    failures.append("platens.csv: the forces differ")
        if compare_fields:
            fields = subprocess.run([compare_fields, os.path.join(serial, "fields.h5"),
                                     os.path.join(parallel, "fields.h5"), "1e-8"])
            if fields.returncode != 0:
                failures.append("fields.h5 differs (see above)")
            # The index names the same datasets at the same times, whoever wrote their rows.
            with open(os.path.join(serial, "fields.xdmf")) as f1, \
                    open(os.path.join(parallel, "fields.xdmf")) as f2:
                if f1.read() != f2.read():
                    failures.append("fields.xdmf differs from one process's")
        with open(os.path.join(serial, "summary.json")) as f:
            s = json.load(f)
        with open(os.path.join(parallel, "summary.json")) as f:
            p = json.load(f)
        if s.get("platens") != p.get("platens"):
            failures.append(f"summary platens: {s.get('platens')} on one process, "
                            f"{p.get('platens')} on {processes}")
        newton_s = [x["newton_iterations"] for x in s["steps"]]
        newton_p = [x["newton_iterations"] for x in p["steps"]]
        if newton_s != newton_p:
            failures.append(f"Newton iterations {newton_s} on one process, {newton_p} on {processes}")
        # BDF: IDA's shift-corrected solves happen at the same steps on one and on N processes.
        for key in ("shift_corrected_solves", "factorizations"):
            a_count, b_count = s["counters"].get(key), p["counters"].get(key)
            print(f"{key}: {a_count} on one process, {b_count} on {processes}")
            if key in counted and a_count != b_count:
                failures.append(f"{key}: {a_count} on one process, {b_count} on {processes}")
        # The linear solver's counters are reported as in one process.
        for key in ("symbolic_analyses", "refinement_steps", "precision_fallbacks"):
            if key not in p["counters"]:
                failures.append(f"summary counters: no {key} on {processes} processes")
        if p.get("status") != "completed" or p["parallel"]["processes"] != int(processes):
            failures.append("summary: status or process count wrong")
        elements = p["mesh"].get("tetrahedra", p["mesh"].get("triangles"))
        if sum(p["parallel"]["owned_elements"]) != elements or s.get("model") != p.get("model"):
            failures.append("summary: owned elements do not add up to the mesh, or another model")
        # Input refused before any work: exit status 1, the message printed once (process 0).
        refused = subprocess.run([mpiexec, "--oversubscribe", "-n", processes, biphasic, "run",
                                  case, "-o", os.path.join(tmp, "refused"), "--set",
                                  'linear_solver.type="klu"'], capture_output=True, text=True)
        said = (refused.stdout + refused.stderr).count("error: linear_solver.type")
        if refused.returncode != 1 or said != 1:
            failures.append(f"a refused case: exit {refused.returncode}, message printed {said} times")
        for f in failures:
            print("FAIL:", f)
        return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
