#!/usr/bin/env python3
"""Time error of runs against a time-converged reference run on the same mesh.

    tools/time_error.py REFERENCE RUN [RUN ...] [--json]

For each RUN (an output folder of `biphasic run`), over the output times it shares with
REFERENCE:
  pressure: max over times and probe-line nodes of |p - p_ref|, divided by max |p_ref|;
  reaction: max over times of |F_z - F_z,ref| of the first boundary in reactions.csv, divided by
            max |F_z,ref| (when both runs wrote reactions.csv); reaction_end: the same at the last
            shared time only;
  displacement: max over times and probe-line nodes of |u_z - u_z,ref|, divided by max |u_z,ref|.
--every T keeps only the shared output times that are multiples of T (compare runs with
different output intervals at the same instants).
Both runs must use the same mesh (same probe-line nodes): the difference is then the time
discretisation's error plus the reference's own (state it).
"""
import argparse
import csv
import json
import os
import sys


def read_line(run, column="p"):
    """{t: [column at each node, in file order]} from line.csv."""
    out = {}
    with open(os.path.join(run, "line.csv")) as f:
        for row in csv.DictReader(f):
            out.setdefault(round(float(row["t"]), 9), []).append(float(row[column]))
    return out


def on_grid(t, every):
    """t is a multiple of every (to 1e-6 relative)."""
    if not every:
        return True
    k = round(t / every)
    return k >= 1 and abs(t - k * every) <= 1e-6 * max(1.0, abs(t))


def read_reaction(run):
    """{t: F_z} of the first boundary in reactions.csv, or None."""
    path = os.path.join(run, "reactions.csv")
    if not os.path.exists(path):
        return None
    out, first = {}, None
    with open(path) as f:
        for row in csv.DictReader(f):
            first = first or row["boundary"]
            if row["boundary"] == first:
                out[round(float(row["t"]), 9)] = float(row["Fz"])
    return out


def counters(run):
    try:
        with open(os.path.join(run, "summary.json")) as f:
            s = json.load(f)
        return s.get("counters", {}), s.get("timings", {})
    except (OSError, ValueError):
        return {}, {}


def time_error(ref, run, every=None):
    pr, pu = read_line(ref), read_line(run)
    times = sorted(t for t in set(pr) & set(pu) - {0.0} if on_grid(t, every))
    if not times:
        raise SystemExit(f"{run}: no output time in common with {ref}")
    for t in times:
        if len(pr[t]) != len(pu[t]):
            raise SystemExit(f"{run}: probe line differs from the reference's (another mesh?)")
    scale = max(abs(p) for t in times for p in pr[t]) or 1.0
    e_p = max(abs(a - b) for t in times for a, b in zip(pu[t], pr[t])) / scale
    ur, uu = read_line(ref, "uz"), read_line(run, "uz")
    uscale = max(abs(u) for t in times for u in ur[t]) or 1.0
    e_u = max(abs(a - b) for t in times for a, b in zip(uu[t], ur[t])) / uscale
    fr, fu = read_reaction(ref), read_reaction(run)
    e_f = e_f_end = None
    if fr and fu:
        ft = sorted(t for t in set(fr) & set(fu) - {0.0} if on_grid(t, every))
        fscale = max(abs(fr[t]) for t in ft) or 1.0
        e_f = max(abs(fu[t] - fr[t]) for t in ft) / fscale
        e_f_end = abs(fu[ft[-1]] - fr[ft[-1]]) / fscale
    return {"pressure": e_p, "reaction": e_f, "reaction_end": e_f_end, "displacement": e_u, "times": len(times),
            "first_time": times[0], "last_time": times[-1]}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("reference")
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--json", action="store_true", help="one JSON object per run")
    ap.add_argument("--every", type=float, default=None,
                    help="compare only at shared output times that are multiples of this [s]")
    args = ap.parse_args()
    for run in args.runs:
        e = time_error(args.reference, run, args.every)
        c, t = counters(run)
        e.update(run=run, factorizations=c.get("factorizations"), steps=c.get("steps"),
                 error_test_failures=c.get("error_test_failures"), wall=t.get("wall"))
        if args.json:
            print(json.dumps(e))
        else:
            rf = "-" if e["reaction"] is None else f"{e['reaction']:.2e}"
            print(f"{run}: pressure {e['pressure']:.2e}  reaction {rf}  displacement "
                  f"{e['displacement']:.2e}  steps {e['steps']}  "
                  f"factorisations {e['factorizations']}  error-test failures "
                  f"{e['error_test_failures']}  wall {e['wall']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
