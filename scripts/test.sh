#!/usr/bin/env bash
# Quick start 2: install everything (tests, benchmarks, peers, Python module,
# fuzz compiler), build everything, run the whole test suite. The Python module
# is built whenever pybind11 and Python's headers are installed, whatever an
# earlier configure (the demo's, without tests) left in the cache.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh test
fresh=()
[ -f build/release/CMakeCache.txt ] || { fresh=(-DCMAKE_UNITY_BUILD=ON); export CMAKE_GENERATOR=Ninja; }  # as in demo.sh
log=$(mktemp)
trap 'rm -f "$log"' EXIT
cmake --preset release -DTUMBLE_BUILD_TESTS=ON -DTUMBLE_BUILD_BENCH=ON -DTUMBLE_BUILD_PYTHON=AUTO "${fresh[@]}" >"$log"
no_python=$(sed -n 's/^-- tumble: Python module OFF: //p' "$log")
say_no_python() {
  [ -z "$no_python" ] && return 0
  echo "############################################################################" >&2
  echo "## test.sh: NO PYTHON MODULE in this build: $no_python" >&2
  echo "## import tumble, python_tests and the notebook test are left out." >&2
  echo "############################################################################" >&2
}
say_no_python
cmake --build --preset release
status=0
ctest --preset release "$@" || status=$?
say_no_python
exit "$status"
