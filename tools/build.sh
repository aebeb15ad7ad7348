#!/usr/bin/env bash
# Installs missing dependencies, then configures and builds into build/ (Release).
# Usage: tools/build.sh [extra cmake -D options]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/install_deps.sh"
# CI builds with warnings as errors; otherwise the build keeps whatever it was configured with.
extra=()
if [[ "${CI:-}" == "true" ]]; then extra+=(-DBIPHASIC_WERROR=ON); fi
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release "${extra[@]}" "$@" >/dev/null
cmake --build "$root/build" -j "$(nproc)"
