#!/usr/bin/env bash
# Quick start 1: install what the render needs, build only `tumble` (no tests,
# no benchmarks), render the default demo into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh render
cmake --preset release -DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_BENCH=OFF >/dev/null
cmake --build --preset release --target tumble
./build/release/src/app/tumble render scenes/dzhanibekov.toml "$@"
