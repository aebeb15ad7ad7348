#!/usr/bin/env bash
# Runs the verification benchmarks (ctest -L verification) with their computed-vs-analytic CSVs
# written to OUT_DIR (default results/verification), then draws the figures of
# docs/verification.md from them into FIG_DIR (default docs/figures/verification).
# Usage: tools/run_verification.sh [OUT_DIR [FIG_DIR]] [-- extra ctest arguments]
# Extra ctest arguments, e.g. `-- -LE slow` for the quick variants only (the default runs the
# slow ones too, whose finer meshes the figures show).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/results/verification
fig=$root/docs/figures/verification
if [[ $# -gt 0 && "$1" != "--" ]]; then out=$(realpath -m "$1"); shift; fi
if [[ $# -gt 0 && "$1" != "--" ]]; then fig=$(realpath -m "$1"); shift; fi
if [[ $# -gt 0 && "$1" == "--" ]]; then shift; fi
"$root/tools/build.sh"
rm -rf "$out"
mkdir -p "$out"
cd "$root/build"
BIPHASIC_VERIFICATION_OUT="$out" ctest -L verification --output-on-failure -j "$(nproc)" "$@"
/usr/bin/python3 "$root/tools/plot_verification.py" "$out" "$fig"
