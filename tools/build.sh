#!/usr/bin/env bash
# Installs missing dependencies, then configures and builds into build/ (Release).
# Usage: tools/build.sh [extra cmake -D options]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/install_deps.sh"
werror=OFF
if [[ "${CI:-}" == "true" ]]; then werror=ON; fi
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DBIPHASIC_WERROR=$werror "$@" >/dev/null
cmake --build "$root/build" -j "$(nproc)"
