#!/usr/bin/env bash
# Quick start 2: install everything (tests, benchmarks, peers, fuzz compiler),
# build everything, run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh test
cmake --preset release -DTUMBLE_BUILD_TESTS=ON -DTUMBLE_BUILD_BENCH=ON >/dev/null
cmake --build --preset release
ctest --preset release "$@"
