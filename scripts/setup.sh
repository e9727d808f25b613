#!/usr/bin/env bash
# Installs the Debian 12 packages tumble needs (only those missing), then
# configures and builds the release preset. Safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  build-essential cmake pkg-config
  libeigen3-dev libboost-dev                     # core: linear algebra, elliptic functions
  libtomlplusplus-dev libcli11-dev               # scenes, command line
  libosmesa6-dev libegl-dev libegl-mesa0 libglm-dev  # headless GL (OSMesa / EGL), camera maths
  libstb-dev libdeflate-dev fonts-dejavu-core    # PNG in/out, text overlay
  libassimp-dev                                  # mesh shapes (OBJ, STL, PLY, ...)
  libgtest-dev libgmock-dev libbenchmark-dev     # tests, microbenchmarks
  assimp-testmodels                              # tests: real and malformed meshes
  openscad                                       # scenes/: regenerates the shipped STL from .scad
  ffmpeg gnuplot-nox                             # videos, charts (run as programs)
  libbullet-dev libode-dev                       # optional peers for `tumble bench`
  clang-14 clang libclang-rt-14-dev              # CI: libFuzzer targets (fuzz preset)
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake --preset release >/dev/null
cmake --build --preset release
