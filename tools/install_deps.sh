#!/usr/bin/env bash
# Installs the Debian 12 packages the project builds and runs with, when any is missing.
# Run as root (or with sudo available). Safe to run repeatedly. Extra package names given as
# arguments are installed too (the CI fuzz stage adds clang and libclang-rt-14-dev).
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libsundials-dev libsuitesparse-dev libmetis-dev libeigen3-dev
  libgmsh-dev libhdf5-dev libhdf5-openmpi-dev libtomlplusplus-dev nlohmann-json3-dev
  libumfpack5 libmumps-seq-dev libopenblas0-pthread libhypre-dev libopenmpi-dev
  libpetsc-real-dev libmumps-dev openmpi-bin
  libgtest-dev python3 python3-numpy python3-matplotlib python3-jsonschema python3-gmsh time
  "$@"
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  exit 0
fi
echo "install_deps: installing ${missing[*]}"
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO=sudo; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
