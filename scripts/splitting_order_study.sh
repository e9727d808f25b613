#!/bin/sh
# The sub-flow order study behind kernel::split_order (splitting; argument 4:
# split_order4, splitting4's base map), see splitting_kernel.hpp. Arguments
# `max` (worst error over t = 1..10 s) and `csv` (one row per case) too.
# See src/bench/studies/splitting_order_study.cpp; built as the target
# tumble_splitting_order_study of a bench build (scripts/test.sh makes one).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$root/build/release}
cmake --build "$build" --target tumble_splitting_order_study -j2 >/dev/null
"$build/src/bench/tumble_splitting_order_study" "$@"
