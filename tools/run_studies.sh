#!/usr/bin/env bash
# Runs the studies of cases/studies/ (tools/study.py: both cores, runs already done are
# skipped, reference solutions cached in results/references/), then draws every figure into
# docs/figures/results/ and the tables of docs/results.md (tools/results_tables.py).
# usage: tools/run_studies.sh [SET]
#   SET = main (default; about 60 minutes on 2 cores from scratch): time_step, work_precision,
#         remedies, paper_figures, stability_map_mesh1..3 (each under 20 minutes)
#   SET = all: main + paper_figures_mesh4 (≈10 min), stability_map_mesh4 (≈20 min) and
#         reference_check (≈15 min: the 3-D cross-check reference refined)
#   SET = plots: only redraw figures and tables from the runs already done
# The studies gls_fixed_tau, gls_length and gls_quadrature are run by tools/study.py on their
# own (--skip-reference-check); their figures are drawn here when their tables exist.
# Every study is measured against its default (axisymmetric) reference; only the studies in
# `checked` also compute the 3-D cross-check reference (≈105 s per physical parameter set) and
# fill discrepancy_check; the others run with --skip-reference-check.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
set_name=${1:-main}
py=/usr/bin/python3
studies=(time_step work_precision remedies paper_figures stability_map_mesh1 stability_map_mesh2
         stability_map_mesh3)
[[ $set_name == all ]] && studies+=(paper_figures_mesh4 stability_map_mesh4 reference_check)
checked=" time_step work_precision remedies "
if [[ $set_name != plots ]]; then
  "$root/tools/build.sh"
  for s in "${studies[@]}"; do
    skip=()
    [[ $checked == *" $s "* ]] || skip=(--skip-reference-check)
    $py "$root/tools/study.py" "$root/cases/studies/$s.toml" "${skip[@]}"
  done
fi
res="$root/results/studies"
fig="$root/docs/figures/results"
have() { [[ -f "$res/$1/runs.csv" ]]; }
have time_step && $py "$root/tools/plot_study.py" sensitivity "$res/time_step" -o "$fig"
have work_precision && $py "$root/tools/plot_study.py" work "$res/work_precision" -o "$fig"
have remedies && $py "$root/tools/plot_study.py" remedies "$res/remedies" -o "$fig"
paper=()
for s in paper_figures paper_figures_mesh4; do have $s && paper+=("$res/$s"); done
((${#paper[@]})) && $py "$root/tools/plot_study.py" paper "${paper[@]}" -o "$fig"
maps=()
for m in 1 2 3 4; do have stability_map_mesh$m && maps+=("$res/stability_map_mesh$m"); done
((${#maps[@]})) && $py "$root/tools/plot_study.py" stability "${maps[@]}" -o "$fig"
have gls_fixed_tau && $py "$root/tools/plot_study.py" fixed_tau "$res/gls_fixed_tau" -o "$fig"
have gls_length && $py "$root/tools/plot_study.py" length "$res/gls_length" -o "$fig"
have gls_quadrature && $py "$root/tools/plot_study.py" quadrature "$res/gls_quadrature" -o "$fig"
# The scene (mesh 2, conditions, loading) from one run that writes its mesh; `plots` redraws it
# only when that run exists.
scene="$root/results/scene_mesh2"
if [[ $set_name != plots || -f $scene/summary.json ]]; then
  $py "$root/tools/plot_scene.py" "$scene" -o "$fig/scene_mesh2.png"
fi
$py "$root/tools/results_tables.py" "$res" > "$root/docs/results_tables.md"
echo "figures: $fig; tables: docs/results_tables.md"
