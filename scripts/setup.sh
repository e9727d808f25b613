#!/usr/bin/env bash
# Installs the Debian 12 packages tumble needs (only those missing). Safe to run
# again. `setup.sh render`: what building `tumble` and rendering need (the
# demo). `setup.sh test`: that plus what the tests, benchmarks, peers and
# fuzzers need.
set -euo pipefail
cd "$(dirname "$0")/.."

RENDER_PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libboost-dev                     # core: linear algebra, elliptic functions
  libtomlplusplus-dev libcli11-dev               # scenes, command line
  libosmesa6-dev libegl-dev libegl-mesa0 libglm-dev  # headless GL (OSMesa / EGL), camera maths
  libstb-dev libdeflate-dev fonts-dejavu-core    # PNG in/out, text overlay
  nlohmann-json3-dev                             # JSON (manifest, golden sidecars, info --json)
  libassimp-dev                                  # mesh shapes (OBJ, STL, PLY, ...)
  zlib1g-dev                                     # named by Debian's assimp CMake package, not among its dependencies
  ffmpeg                                         # videos (run as a program)
)
TEST_PACKAGES=(
  libgtest-dev libgmock-dev libbenchmark-dev     # tests, microbenchmarks
  assimp-testmodels                              # tests: real and malformed meshes
  openscad                                       # scenes/: regenerates the shipped STL from .scad
  gnuplot-nox                                    # `tumble bench` charts (run as a program)
  parallel                                       # tests: shards rendered by GNU Parallel, then assembled
  libbullet-dev libode-dev                       # optional peers for `tumble bench`
  clang-14 clang libclang-rt-14-dev              # CI: libFuzzer targets (fuzz preset)
  python3-dev pybind11-dev python3-numpy         # the Python module (python/)
  python3-pytest python3-nbclient python3-ipykernel python3-matplotlib  # its tests, the notebook
  jupyter-notebook                               # `jupyter notebook`, as docs/python.md says
  libtinygltf-dev                                # `tumble export --gltf`
  chromium                                       # tests: three.js plays the glTF export (tools/gltf_viewer)
)

case "${1:-test}" in
  render) PACKAGES=("${RENDER_PACKAGES[@]}") ;;
  test) PACKAGES=("${RENDER_PACKAGES[@]}" "${TEST_PACKAGES[@]}") ;;
  *) echo "usage: $0 [render|test]" >&2; exit 2 ;;
esac

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

# The Khronos glTF validator (npm gltf-validator, pinned in tools/npm) for the
# glTF export test: node and npm from Debian when missing, then a local install.
if [ "${1:-test}" = test ]; then
  if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    echo "setup: installing nodejs npm"
    SUDO=""
    [ "$(id -u)" -eq 0 ] || SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends nodejs npm
  fi
  if [ ! -f tools/npm/node_modules/gltf-validator/package.json ] || [ ! -f tools/npm/node_modules/three/package.json ]; then
    echo "setup: npm install (tools/npm: gltf-validator, three)"
    npm ci --prefix tools/npm --no-audit --no-fund --loglevel=error
  fi
fi
