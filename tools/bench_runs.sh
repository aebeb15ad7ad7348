#!/usr/bin/env bash
# Whole runs of the paper's reference loading (k = 1e-3, GLS, 5 steps) with each linear solver,
# timed with /usr/bin/time for the peak memory. Writes OUT/runs.csv (and one run folder each);
# tools/plot_performance.py OUT/runs.csv draws cost against unknowns.
# usage: tools/bench_runs.sh OUT "mumps:1,2,3,4 umfpack:1,2,3 klu:1,2" [key=value ...]
# Extra key=value arguments are passed to every run as --set (e.g. stabilisation.type=none);
# each run's folder and CSV row carry them in the "variant" column.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-results/bench}
plan=${2:-"mumps:1,2,3,4 umfpack:1,2,3 klu:1"}
shift $(( $# < 2 ? $# : 2 ))
extra=()
for kv in "$@"; do extra+=(--set "$kv"); done
variant=$(IFS=' '; echo "$*")
tag=${variant//[^A-Za-z0-9_.]/_}
bin="$root/build/biphasic"
mkdir -p "$out"
csv="$out/runs${tag:+_$tag}.csv"
echo "solver,mesh,unknowns,wall_s,peak_rss_gb,factorization_s,analysis_s,solve_s,assembly_s,newton_iterations,factorizations,fill,krylov_iterations,max_krylov_iterations,variant" > "$csv"
for entry in $plan; do
  solver=${entry%%:*}
  for mesh in ${entry#*:}; do
    mesh=${mesh//,/ }
    for m in $mesh; do
      dir="$out/${solver}_mesh$m${tag:+_$tag}"
      /usr/bin/time -f "%M" -o "$dir.rss" "$bin" run "$root/cases/paper/mesh${m}_k1e-3_gls.toml" -o "$dir" --overwrite \
        --set linear_solver.type="$solver" "${extra[@]}" --quiet
      /usr/bin/python3 - "$dir" "$solver" "$m" "$(cat "$dir.rss")" "$variant" >> "$csv" <<'PY'
import json, sys
d, solver, mesh, rss, variant = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), sys.argv[5]
s = json.load(open(d + "/summary.json"))
t, c = s["timings"], s["counters"]
print(f"{solver},{mesh},{s['mesh']['unknowns']},{t['wall']:.3f},{rss / 1024 / 1024:.3f},{t['factorization']:.3f},"
      f"{t['symbolic_analysis']:.3f},{t['linear_solve']:.3f},{t['residual_assembly'] + t['jacobian_assembly']:.3f},"
      f"{c['newton_iterations']},{c['factorizations']},{c['fill_ratio']:.2f},"
      f"{c.get('krylov_iterations', 0)},{c.get('max_krylov_iterations', 0)},{variant}")
PY
      tail -n 1 "$csv"
    done
  done
done
