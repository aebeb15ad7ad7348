#!/usr/bin/env bash
# Quick start 1: installs what is missing, builds, and runs the paper's reference loading on
# mesh 1 with GLS (k = 1e-3, 5 steps of 6.4 s) into results/reference/, then plots the
# pressure along the axis. Extra arguments go to `biphasic run` (e.g. --set stabilisation.type=none).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/build.sh"
out="$root/results/reference"
"$root/build/biphasic" run "$root/cases/paper/mesh1_k1e-3_gls.toml" -o "$out" --overwrite "$@"
/usr/bin/python3 "$root/tools/plot_line.py" "$out" -o "$out/pressure_profiles.png" || true
echo "results: $out (line.csv, fields.xdmf for ParaView, summary.json, pressure_profiles.png)"
