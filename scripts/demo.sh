#!/usr/bin/env bash
# Quick start 1: install what the render needs, build only `tumble` (no tests,
# no benchmarks, no Python module), render the default demo into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh render
# A new build folder is a unity build (one compiler run per few files: the
# headers are parsed once, not once a file) made by Ninja (which compiles a
# library while the one below it is still being archived); an existing one
# keeps what it was configured with.
fresh=()
[ -f build/release/CMakeCache.txt ] || { fresh=(-DCMAKE_UNITY_BUILD=ON); export CMAKE_GENERATOR=Ninja; }
cmake --preset release -DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_BENCH=OFF "${fresh[@]}" >/dev/null
cmake --build --preset release --target tumble
./build/release/src/app/tumble render scenes/dzhanibekov.toml "$@"
