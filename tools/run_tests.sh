#!/usr/bin/env bash
# Quick start 2: installs what is missing, builds (warnings are errors under CI=true), and runs
# the default test suite (everything but the tests labelled `slow`). Extra arguments go to ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/build.sh"
cd "$root/build"
ctest -LE slow --output-on-failure -j "$(nproc)" "$@"
